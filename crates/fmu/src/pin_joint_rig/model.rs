//! The PinJointRig co-simulation model: the rig simulator [`RigSim`] behind the
//! FMI layer. It integrates internally across communication steps (its own
//! segments and events, independent of the host's grid); a communication step only
//! moves the simulator's clock and samples it.
//!
//! Time: the rig's clock is the FMU time minus the start time, so the stroke
//! A sin(2 pi f (t - t_start)) starts at rest on the command at the start time.
//! Inputs are held over each step; setting an input to a new value restarts the
//! integration at the current time (see [`pinjoint::rig::sim`]).
//!
//! Fidelity: `fidelity` (0 full, 1 table, 2 boundary, 3 auto), `tolerance` and the envelope
//! are checked at fmi2ExitInitializationMode and, unless full, applied with
//! [`RigSim::set_fidelity`]; the log says once which level was built (what auto picked) and
//! its measured bound, and once when a friction evaluation first fell outside the envelope.
//! At full (the default) the simulator is built exactly as without these parameters.

use super::settings::Settings;
use super::state::{decode, encode};
use super::variables::{Outputs, Values, TABLE};
use crate::fidelity::{describe, envelope_text};
use crate::inputs::check_capacity;
use fmi_layer::core::logging::show;
use fmi_layer::core::model::{Model, ModelError, ModelResult};
use fmi_layer::core::variables::Causality;
use pinjoint::fidelity::{Evaluator, Fidelity};
use pinjoint::rig::RigSim;
use std::sync::Arc;

/// Whether the variable `name` is one of the fidelity settings (a change logs the first
/// fallback again).
fn is_fidelity_setting(name: &str) -> bool {
    name == "fidelity" || name == "tolerance" || name.starts_with("envelope.")
}

/// A PinJointRig instance: the settings, the start time, the rig simulator and the last
/// outputs; it implements the FMI layer's [`Model`].
#[derive(Debug, Clone, Default)]
pub struct RigModel {
    /// The settings and the outputs of the last sample.
    pub(super) v: Values,
    /// The experiment's start time: the rig's clock is t - start_time.
    pub(super) start_time: f64,
    /// The simulator, built at fmi2ExitInitializationMode (or for outputs read
    /// during initialization); dropped when a parameter changes.
    pub(super) sim: Option<RigSim>,
    /// For the host's log ([`Model::take_message`]): the level built; the first fallback.
    message: Option<String>,
    /// Whether the first evaluation outside the envelope has been logged (once per instance
    /// and fidelity setting; kept across a restore with the same settings).
    fallback_logged: bool,
    /// Whether the last sample was outside the validity envelope (one log per excursion).
    validity: pinjoint::validity::Tracker,
}

impl RigModel {
    /// An instance at the start values of every variable (no simulator built yet).
    pub fn new() -> Self {
        Self::default()
    }

    /// A model with these settings and, if given, a simulator resumed from `state`; `reuse`
    /// is a fidelity level already built, used if it matches the settings (not rebuilt).
    pub(super) fn restored(
        settings: Settings,
        start_time: f64,
        state: Option<pinjoint::rig::RigState>,
        reuse: Option<Arc<Evaluator>>,
    ) -> ModelResult<Self> {
        let mut m = RigModel { v: Values { settings, ..Values::default() }, start_time, ..RigModel::new() };
        // The parameter file's and exit-initialization's checks, for a state taken at any time.
        m.v.settings.config()?;
        m.v.settings.fidelity()?;
        if let Some(st) = state {
            let mut sim = m.build(reuse)?;
            sim.set_state(&st).map_err(|e| ModelError::failed("", e))?;
            m.sim = Some(sim);
        }
        Ok(m)
    }

    /// The simulator for the settings, at their fidelity. At `full` it is exactly
    /// [`RigSim::new`]; otherwise [`RigSim::set_fidelity`], or `reuse` when it is the same
    /// level, tolerance and envelope built for the same model parameters.
    fn build(&self, reuse: Option<Arc<Evaluator>>) -> ModelResult<RigSim> {
        let cfg = self.v.settings.config()?;
        let (level, tolerance, envelope) = self.v.settings.fidelity()?;
        let mut sim = RigSim::new(&cfg).map_err(|e| ModelError::failed("", e))?;
        if level != Fidelity::Full {
            let same = |e: &Evaluator| {
                e.requested() == level && e.tolerance() == tolerance && *e.envelope() == envelope && e.joint().params() == &cfg.model
            };
            match reuse.filter(|e| same(e)) {
                Some(ev) => sim.share_fidelity(ev).map_err(|e| ModelError::failed("", e))?,
                None => {
                    sim.set_fidelity(level, tolerance, envelope).map_err(|e| ModelError::failed(format!("fidelity {level}: "), e))?;
                }
            }
        }
        Ok(sim)
    }

    fn sim(&mut self) -> ModelResult<&mut RigSim> {
        if self.sim.is_none() {
            self.sim = Some(self.build(None)?);
        }
        Ok(self.sim.as_mut().expect("just built"))
    }

    /// The simulator in use (after initialization).
    pub fn simulator(&self) -> Option<&RigSim> {
        self.sim.as_ref()
    }

    /// Say once when a friction evaluation first fell outside the envelope.
    fn note_fallback(&mut self) {
        if self.fallback_logged {
            return;
        }
        let Some(sim) = self.sim.as_ref() else { return };
        let (Some(ev), n) = (sim.fidelity(), sim.stats().fallbacks) else { return };
        if n == 0 {
            return;
        }
        self.message = Some(format!(
            "fidelity {}: by t = {} s (rig clock) a friction evaluation fell outside the envelope ({}; \
             e.g. speeds below {} rad/s around a reversal); the full solve answers there (said once)",
            ev.chosen(),
            show(sim.time()),
            envelope_text(ev.envelope()),
            ev.envelope().speed_min
        ));
        self.fallback_logged = true;
    }

    /// Apply the held inputs at the current time and sample. A changed `temperature` input
    /// moves the simulator's friction model there ([`RigSim::set_temperature`]: as a rig
    /// built at that temperature resumed from the current state).
    fn refresh(&mut self, rig_time: Option<f64>) -> ModelResult<()> {
        let inputs = self.v.settings.inputs();
        let t = self.v.settings.temperature;
        if let Some(sim) = self.sim.as_mut().filter(|s| s.joint().params().lubricant.temperature.to_bits() != t.to_bits()) {
            sim.set_temperature(t).map_err(|e| ModelError::failed("", e))?;
        }
        let sim = self.sim()?;
        let t = rig_time.unwrap_or(sim.time()).max(sim.time());
        sim.advance_to(t, &inputs).map_err(|e| ModelError::failed("", e))?;
        let s = sim.sample().map_err(|e| ModelError::failed("", e))?;
        self.note_fallback();
        let joint = self.sim.as_ref().expect("built above").joint();
        // Checked once, by the FMI layer (finite and within their declared min/max).
        self.v.out = Outputs::of(s, joint);
        let context = format!(" at t = {} s (rig clock)", show(s.time));
        let v = super::variables::validity(&self.v);
        let values = &self.v;
        crate::validity::note(&mut self.validity, v, || super::variables::excursion(values), &context, &mut self.message);
        Ok(())
    }
}

impl Model for RigModel {
    fn set_start_values(&mut self) {
        *self = RigModel::new();
    }

    fn get_real(&self, i: usize) -> f64 {
        TABLE.get(&self.v, i)
    }

    fn check_real(&self, i: usize, x: f64) -> ModelResult<()> {
        // Beyond the asperity model's capacity the load is refused here, leaving the
        // simulation as it was.
        TABLE.check_input(i, x, self.sim.as_ref().map(|s| s.joint().capacity()))
    }

    fn set_real(&mut self, i: usize, x: f64) {
        let var = TABLE.set(&mut self.v, i, x);
        // The temperature input is applied at the next refresh (RigSim::set_temperature: the
        // simulator's friction model moves there, its state is kept); parameters drop the simulator.
        if var.causality == Causality::Parameter {
            self.sim = None;
        }
        if is_fidelity_setting(&var.name) {
            self.fallback_logged = false;
        }
    }

    fn take_message(&mut self) -> Option<String> {
        self.message.take()
    }

    fn exit_initialization(&mut self, start_time: f64) -> ModelResult<()> {
        self.start_time = start_time;
        // A level built for outputs read during initialization is reused, not rebuilt.
        let reuse = self.sim.as_ref().and_then(RigSim::shared_fidelity);
        let sim = self.build(reuse)?;
        check_capacity(self.v.settings.load, sim.joint().capacity())?;
        self.message = sim.fidelity().map(|ev| describe(ev, "; outside it the full solve answers"));
        self.sim = Some(sim);
        Ok(())
    }

    fn compute_outputs(&mut self) -> ModelResult<()> {
        self.refresh(None)
    }

    fn do_step(&mut self, time: f64, step: f64) -> ModelResult<()> {
        self.refresh(Some(time + step - self.start_time))
    }

    fn serialize(&self, out: &mut Vec<u8>) {
        encode(&self.v.settings, self.start_time, self.sim.as_ref().map(pinjoint::rig::RigSim::state), out);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let (settings, start_time, state) = decode(bytes)?;
        let reuse = self.sim.as_ref().and_then(RigSim::shared_fidelity);
        let mut m = RigModel::restored(settings, start_time, state, reuse)?;
        m.fallback_logged = self.fallback_logged && m.v.settings.fidelity == self.v.settings.fidelity;
        m.validity = self.validity;
        *self = m;
        Ok(())
    }
}
