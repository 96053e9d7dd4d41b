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
use super::variables::{Output, Var, LAYOUT};
use pinjoint::fidelity::{Evaluator, Fidelity};
use fmi_layer::fmi2::logging::show;
use fmi_layer::fmi2::model::{Model, ModelResult};
use pinjoint::rig::{RigSim, Sample};
use std::sync::Arc;


/// What the log says about the level built: what was asked, what runs (auto's pick), the
/// measured bound, the tolerance and the envelope.
fn describe(ev: &Evaluator) -> String {
    let e = ev.envelope();
    format!(
        "fidelity {} -> {}: measured error bound {:e} (tolerance {:e}) over load {}..{} N, |omega| {}..{} rad/s; \
         outside it the full solve answers",
        ev.requested(),
        ev.chosen(),
        ev.error_bound(),
        ev.tolerance(),
        e.load_min,
        e.load_max,
        e.speed_min,
        e.speed_max
    )
}

/// The outputs as the FMU reports them: the sample, with the core's film quantities
/// set to 0 at zero load (no contact) where the library has NaN.
pub fn outputs(s: &Sample) -> ModelResult<[f64; Output::ALL.len()]> {
    let contact = s.load > 0.0;
    let out = Output::ALL.map(|o| match o {
        Output::Angle => s.angle,
        Output::AngularVelocity => s.angular_velocity,
        Output::Torque => s.torque,
        Output::FrictionTorque => s.friction_torque,
        Output::FrictionCoefficient => s.friction_coefficient,
        Output::FilmThickness => if contact { s.film_thickness } else { 0.0 },
        Output::FluidLoadFraction => if contact { s.fluid_load_fraction } else { 0.0 },
        Output::Stuck => f64::from(u8::from(s.stuck)),
        Output::CommandedAngle => s.command_angle,
        Output::ActuatorWork => s.actuator_work,
        Output::FrictionDissipation => s.friction_dissipation,
        Output::KineticEnergy => s.kinetic_energy,
        // Filled in by `with_min_film` (they need the joint).
        Output::MinFilmThickness | Output::MinLambdaRatio => 0.0,
    });
    if let Some((o, v)) = Output::ALL.iter().zip(out).find(|(_, v)| !v.is_finite()) {
        let name = &super::INFO.variables[LAYOUT.iter().position(|x| *x == Var::Out(*o)).expect("in the table")].name;
        return Err(format!(
            "the rig gives {name} = {} at t = {} s (load {} N, angle {} rad, speed {} rad/s)",
            show(v),
            show(s.time),
            show(s.load),
            show(s.angle),
            show(s.angular_velocity)
        ).into());
    }
    Ok(out)
}

/// [`outputs`] with h_min and λ_min from `joint` ([`pinjoint::Joint::min_film`]) at the sample's
/// load, speed, film and fluid share; 0 at zero load (no contact).
pub fn with_min_film(mut out: [f64; Output::ALL.len()], s: &Sample, joint: &pinjoint::Joint) -> [f64; Output::ALL.len()] {
    if s.load > 0.0 {
        let h_min = joint.min_film(s.load, s.angular_velocity, s.film_thickness, s.fluid_load_fraction);
        if h_min.is_finite() {
            out[Output::MinFilmThickness as usize] = h_min;
            out[Output::MinLambdaRatio as usize] = h_min / joint.composite_roughness();
        }
    }
    out
}

/// A PinJointRig instance: the settings, the start time, the rig simulator and the last
/// outputs; it implements the FMI layer's [`Model`].
#[derive(Debug, Clone)]
pub struct RigModel {
    pub(super) settings: Settings,
    /// The experiment's start time: the rig's clock is t - start_time.
    pub(super) start_time: f64,
    /// The simulator, built at fmi2ExitInitializationMode (or for outputs read
    /// during initialization); dropped when a parameter changes.
    pub(super) sim: Option<RigSim>,
    out: [f64; Output::ALL.len()],
    /// For the host's log ([`Model::take_message`]): the level built; the first fallback.
    message: Option<String>,
    /// Whether the first evaluation outside the envelope has been logged (once per instance
    /// and fidelity setting; kept across a restore with the same settings).
    fallback_logged: bool,
}

impl RigModel {
    /// An instance at the start values of every variable (no simulator built yet).
    pub fn new() -> Self {
        RigModel {
            settings: Settings::default(),
            start_time: 0.0,
            sim: None,
            out: [0.0; Output::ALL.len()],
            message: None,
            fallback_logged: false,
        }
    }

    /// A model with these settings and, if given, a simulator resumed from `state`; `reuse`
    /// is a fidelity level already built, used if it matches the settings (not rebuilt).
    pub(super) fn restored(
        settings: Settings,
        start_time: f64,
        state: Option<pinjoint::rig::RigState>,
        reuse: Option<Arc<Evaluator>>,
    ) -> ModelResult<Self> {
        let mut m = RigModel { settings, start_time, ..RigModel::new() };
        // The parameter file's and exit-initialization's checks, for a state taken at any time.
        m.settings.config()?;
        m.settings.fidelity()?;
        if let Some(st) = state {
            let mut sim = m.build(reuse)?;
            sim.set_state(&st).map_err(|e| e.to_string())?;
            m.sim = Some(sim);
        }
        Ok(m)
    }

    /// The simulator for the settings, at their fidelity. At `full` it is exactly
    /// [`RigSim::new`]; otherwise [`RigSim::set_fidelity`], or `reuse` when it is the same
    /// level, tolerance and envelope built for the same model parameters.
    fn build(&self, reuse: Option<Arc<Evaluator>>) -> ModelResult<RigSim> {
        let cfg = self.settings.config()?;
        let (level, tolerance, envelope) = self.settings.fidelity()?;
        let mut sim = RigSim::new(&cfg).map_err(|e| e.to_string())?;
        if level != Fidelity::Full {
            let same = |e: &Evaluator| {
                e.requested() == level && e.tolerance() == tolerance && *e.envelope() == envelope && e.joint().params() == &cfg.model
            };
            match reuse.filter(|e| same(e)) {
                Some(ev) => sim.share_fidelity(ev).map_err(|e| e.to_string())?,
                None => {
                    sim.set_fidelity(level, tolerance, envelope).map_err(|e| format!("fidelity {level}: {e}"))?;
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
        let e = ev.envelope();
        self.message = Some(format!(
            "fidelity {}: by t = {} s (rig clock) a friction evaluation fell outside the envelope (load {}..{} N, |omega| {}..{} rad/s; \
             e.g. speeds below {} rad/s around a reversal); the full solve answers there (said once)",
            ev.chosen(),
            show(sim.time()),
            e.load_min,
            e.load_max,
            e.speed_min,
            e.speed_max,
            e.speed_min
        ));
        self.fallback_logged = true;
    }

    /// Apply the held inputs at the current time and sample. A changed `temperature` input
    /// rebuilds the simulator's friction model and resumes from the current state.
    fn refresh(&mut self, rig_time: Option<f64>) -> ModelResult<()> {
        let inputs = self.settings.inputs();
        let stale = self.sim.as_ref().is_some_and(|s| s.joint().params().lubricant.temperature.to_bits() != self.settings.temperature.to_bits());
        if stale {
            let state = self.sim.as_ref().map(RigSim::state).expect("checked above");
            let mut sim = self.build(None)?;
            sim.set_state(&state).map_err(|e| e.to_string())?;
            self.sim = Some(sim);
        }
        let sim = self.sim()?;
        let t = rig_time.unwrap_or(sim.time()).max(sim.time());
        sim.advance_to(t, &inputs).map_err(|e| e.to_string())?;
        let s = sim.sample().map_err(|e| e.to_string())?;
        self.note_fallback();
        let joint = self.sim.as_ref().expect("built above").joint();
        self.out = with_min_film(outputs(&s)?, &s, joint);
        Ok(())
    }
}

impl Default for RigModel {
    fn default() -> Self {
        Self::new()
    }
}

impl Model for RigModel {
    fn set_start_values(&mut self) {
        *self = RigModel::new();
    }

    fn get_real(&self, i: usize) -> f64 {
        match LAYOUT[i] {
            Var::Out(o) => self.out[o as usize],
            v => self.settings.get(v),
        }
    }

    fn check_real(&self, i: usize, x: f64) -> ModelResult<()> {
        Settings::check_input(LAYOUT[i], x)?;
        // Beyond the asperity model's capacity (pinjoint::Joint::capacity) the load is refused
        // here, leaving the simulation as it was.
        match (LAYOUT[i], &self.sim) {
            (Var::Load, Some(sim)) => check_capacity(x, sim.joint().capacity()),
            _ => Ok(()),
        }
    }

    fn set_real(&mut self, i: usize, x: f64) {
        let v = LAYOUT[i];
        self.settings.set(v, x);
        // The temperature input is applied at the next refresh (rebuilding the friction model
        // and keeping the simulator's state); parameters drop the simulator.
        if !matches!(v, Var::Load | Var::CommandAngle | Var::Temperature) {
            self.sim = None;
        }
        if matches!(v, Var::Fidelity | Var::Tolerance | Var::Envelope(_)) {
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
        check_capacity(self.settings.load, sim.joint().capacity())?;
        self.message = sim.fidelity().map(describe);
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
        encode(&self.settings, self.start_time, self.sim.as_ref().map(pinjoint::rig::RigSim::state), out);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let (settings, start_time, state) = decode(bytes)?;
        let reuse = self.sim.as_ref().and_then(RigSim::shared_fidelity);
        let mut m = RigModel::restored(settings, start_time, state, reuse)?;
        m.fallback_logged = self.fallback_logged && m.settings.fidelity_key() == self.settings.fidelity_key();
        *self = m;
        Ok(())
    }
}

/// A load at or beyond the joint's asperity capacity is an error naming both.
fn check_capacity(load: f64, capacity: f64) -> ModelResult<()> {
    if load.abs() >= capacity {
        Err(format!(
            "input load = {} N is beyond the asperity model's capacity of {} N for these parameters",
            show(load),
            show(capacity)
        ).into())
    } else {
        Ok(())
    }
}
