//! The PinJoint model: library outputs at the inputs, the zero-velocity treatment of the
//! torque (the presliding state or the band, [`super::zero_velocity`]), and the dissipated
//! energy. Every variable is read, checked, stored and serialized through its row of
//! [`TABLE`].

use super::variables::{Values, STATE_VERSION, TABLE};
use super::zero_velocity::presliding_friction;
use crate::fidelity::{describe, envelope_text};
use crate::inputs::check_capacity;
use crate::table::rejected;
use fmi_layer::core::bytes::{ByteReader, ByteWriter};
use fmi_layer::core::interface::Interface;
use fmi_layer::core::logging::show;
use fmi_layer::core::model::{Model, ModelError, ModelResult};
use fmi_layer::core::variables::Causality;
use pinjoint::fidelity::Evaluator;
use pinjoint::zero_velocity::modes::{self, Mode};
use pinjoint::zero_velocity::wrap::increment;
use pinjoint::zero_velocity::ZeroVelocityModel;
use pinjoint::Joint;

pub use super::evaluate::{operating_point, outputs};
use super::evaluate::{derive, outputs_deferred};

/// Whether each row of [`TABLE`] reads a quantity the evaluator may leave pending
/// ([`pinjoint::fidelity::evaluation::DERIVED_COLUMNS`]).
static DERIVED_ROWS: std::sync::LazyLock<Vec<bool>> =
    std::sync::LazyLock::new(|| TABLE.rows().iter().map(|r| pinjoint::fidelity::evaluation::DERIVED_COLUMNS.contains(&r.var.name.as_str())).collect());

/// A PinJoint instance: the values of its variables and the evaluator built from them; it
/// implements the FMI layer's [`Model`].
#[derive(Debug, Clone, Default)]
pub struct PinJointModel {
    v: Values,
    /// Built from the parameters, the temperature input and the fidelity settings on first
    /// use (at exit of initialization); dropped when a parameter changes, moved to a new
    /// temperature input by [`Evaluator::set_temperature`].
    evaluator: Option<Evaluator>,
    /// For the host's log (fidelity chosen; first fallback; a validity excursion).
    message: Option<String>,
    /// The interface the host instantiated: under Model Exchange the host owns the presliding
    /// state; under Co-Simulation the model steps it.
    interface: Option<Interface>,
    /// Whether the inputs were outside the validity envelope at the last evaluation.
    validity: pinjoint::validity::Tracker,
    /// Initialization is over (exit of initialization mode, or a state restored after it).
    initialized: bool,
    /// The host set the angle in initialization mode: it is the reference.
    angle_in_init: bool,
}

impl PinJointModel {
    /// An instance at the start values of every variable (no evaluator built yet).
    pub fn new() -> Self {
        Self::default()
    }

    fn evaluator(&mut self) -> ModelResult<&mut Evaluator> {
        if let Some(ev) = self.evaluator.as_mut().filter(|e| e.temperature().to_bits() != self.v.temperature.to_bits()) {
            // A new temperature: the same evaluator moved there (bit for bit one built there;
            // at full a few logarithms, a table or boundary level is built again).
            ev.set_temperature(self.v.temperature).map_err(|e| ModelError::failed("", e))?;
        }
        if self.evaluator.is_none() {
            // Every parameter is checked as set, `lubricant.temperature` too (the input replaces it);
            // a changed parameter drops the evaluator, so this runs again after any change.
            self.v.zv.validate()?;
            self.v.params.validate().map_err(|e| ModelError::failed("", e))?;
            let params = self.effective_params();
            Joint::new(&params).map_err(|e| ModelError::failed("", e))?;
            let ev = self.v.fidelity.build(&params)?;
            self.message = Some(describe(&ev, ""));
            self.evaluator = Some(ev);
        }
        Ok(self.evaluator.as_mut().expect("just built"))
    }

    /// The parameters with the lubricant temperature taken from the `temperature` input.
    /// At the default input (293.15 K = the default reference) they equal the parameters,
    /// so the outputs are exactly the paper model's.
    fn effective_params(&self) -> pinjoint::Params {
        let mut p = self.v.params;
        p.lubricant.temperature = self.v.temperature;
        p
    }

    /// The zero-velocity model chosen. Its settings were validated when the evaluator was built
    /// (or the state restored); the full check runs here only for a code that is not a model.
    fn zero_velocity(&self) -> ModelResult<ZeroVelocityModel> {
        let code = self.v.zv.code;
        match ZeroVelocityModel::from_code(code as i64) {
            Some(m) if code.fract() == 0.0 => Ok(m),
            _ => self.v.zv.validate(),
        }
    }

    /// Whether the model steps the presliding state itself (Co-Simulation) and the angle's
    /// increments drive it (the host has set the angle since initialization).
    fn angle_drives(&self) -> bool {
        self.interface != Some(Interface::ModelExchange) && self.v.angle_driven == 1.0
    }

    /// The angle increment the outputs deflect the committed state by: modulo 2π, the
    /// equivalent closest to ω·h of the last step ([`pinjoint::zero_velocity::wrap`]).
    fn delta(&self) -> f64 {
        if self.angle_drives() { increment(self.v.angle - self.v.angle_ref, self.v.omega_ref * self.v.step) } else { 0.0 }
    }

    /// The Model Exchange mode (stick under Co-Simulation).
    fn mode(&self) -> Mode {
        Mode::from_code(self.v.mode).unwrap_or_default()
    }

    /// The sliding torque at the held inputs (0 unloaded or before an evaluation).
    fn bound(&self) -> f64 {
        self.v.out.point.map_or(0.0, |p| p.torque)
    }

    /// The evaluator in use (after initialization).
    pub fn current_evaluator(&self) -> Option<&Evaluator> {
        self.evaluator.as_ref()
    }
}

impl Model for PinJointModel {
    fn set_start_values(&mut self) {
        *self = PinJointModel::new();
    }

    fn set_interface(&mut self, interface: Interface) {
        self.interface = Some(interface);
    }

    fn get_real(&self, i: usize) -> f64 {
        TABLE.get(&self.v, i)
    }

    fn prepare_read(&mut self, i: usize) {
        if let Some(ev) = self.evaluator.as_ref().filter(|_| self.v.out.pending && DERIVED_ROWS.get(i).copied().unwrap_or(false)) {
            derive(ev, &mut self.v.out);
        }
    }

    fn check_real(&self, i: usize, x: f64) -> ModelResult<()> {
        // Beyond the asperity model's capacity the load is refused here, leaving the
        // instance and its outputs as they were.
        TABLE.check_input(i, x, self.evaluator.as_ref().map(|e| e.joint().capacity()))
    }

    fn set_real(&mut self, i: usize, x: f64) {
        // A parameter drops the evaluator (a new temperature input is seen at next use).
        let var = TABLE.set(&mut self.v, i, x);
        if var.causality == Causality::Parameter {
            self.evaluator = None;
        } else if var.name == "angle" {
            if !self.initialized {
                self.angle_in_init = true;
            } else {
                if self.v.angle_pending == 1.0 {
                    // The first angle after (re)initialization, none set in initialization
                    // mode: it is the reference, not a deflection from the start value.
                    self.v.angle_ref = x;
                    self.v.angle_pending = 0.0;
                }
                // Set after initialization: from now on the angle drives the presliding state.
                self.v.angle_driven = 1.0;
            }
        }
    }

    fn take_message(&mut self) -> Option<String> {
        self.message.take()
    }

    fn exit_initialization(&mut self, _start_time: f64) -> ModelResult<()> {
        self.evaluator()?;
        // The presliding state is committed at the initial angle; if the host set none, at
        // the first angle it sets.
        self.v.angle_ref = self.v.angle;
        self.v.angle_driven = 0.0;
        self.v.angle_pending = if self.angle_in_init { 0.0 } else { 1.0 };
        self.v.mode = 0.0;
        self.v.step = 0.0;
        self.v.omega_ref = 0.0;
        self.initialized = true;
        Ok(())
    }

    fn completed_integrator_step(&mut self) -> ModelResult<bool> {
        if self.zero_velocity()? != ZeroVelocityModel::Presliding || self.interface != Some(Interface::ModelExchange) {
            return Ok(false);
        }
        Ok(modes::event_due(&self.v.zv.law, self.mode(), self.v.tau, self.v.omega, self.bound()))
    }

    fn update_discrete_states(&mut self) -> ModelResult<bool> {
        if self.zero_velocity()? != ZeroVelocityModel::Presliding || self.interface != Some(Interface::ModelExchange) {
            return Ok(false);
        }
        let (mode, tau) = modes::update(&self.v.zv.law, self.mode(), self.v.tau, self.v.omega, self.bound());
        let changed = tau.to_bits() != self.v.tau.to_bits();
        (self.v.mode, self.v.tau) = (mode.code(), tau);
        Ok(changed)
    }

    fn compute_outputs(&mut self) -> ModelResult<()> {
        let (load, omega) = (self.v.load, self.v.omega);
        let (model, delta) = (self.zero_velocity()?, self.delta());
        self.evaluator()?;
        // Borrow the evaluator and the values apart (no copy of the values on the hot path).
        let ev = self.evaluator.as_mut().expect("built above");
        // What a table or the boundary level leaves of the operating point (Hertz, Sommerfeld,
        // h_min, the clearance's outputs) is computed when the host reads it (prepare_read).
        let (out, first_fallback) = outputs_deferred(ev, &self.v, model, delta)?;
        if first_fallback {
            let ev = self.evaluator.as_ref().expect("built above");
            self.message = Some(format!(
                "fidelity {}: load = {} N, angular_velocity = {} rad/s is outside the envelope ({}); \
                 the full solve answers there (said once)",
                ev.chosen(),
                show(load),
                show(omega),
                envelope_text(ev.envelope())
            ));
        }
        self.v.out = out;
        // The evaluator's joint has the parameters' edges already (no recomputation per step).
        let edges = self.evaluator.as_ref().expect("built above").joint().edges();
        let s = &self.v;
        let v = super::variables::validity_within(s, &edges);
        let excursion = || super::variables::excursion(s);
        crate::validity::note(&mut self.validity, v, excursion, "", &mut self.message);
        Ok(())
    }

    fn do_step(&mut self, _time: f64, step: f64) -> ModelResult<()> {
        let e = self.v.energy + self.v.out.friction.power_loss * step;
        if !e.is_finite() {
            return Err(ModelError::NotFinite(format!("dissipated_energy overflows ({e} J)")));
        }
        if self.zero_velocity()? == ZeroVelocityModel::Presliding {
            // The step and ω the next angle is read against (and the damping capped at).
            (self.v.step, self.v.omega_ref) = (step, self.v.omega);
            if self.angle_drives() {
                // Commit the presliding torque the outputs already hold at this angle.
                self.v.tau = self.v.out.friction.held;
                self.v.angle_ref = self.v.angle;
            } else {
                // The exact update over omega*h with the inputs held; the reference angle
                // follows the motion the state assumed.
                let bound = self.v.out.point.map_or(0.0, |p| p.torque);
                let travel = self.v.omega * step;
                let law = self.v.zv.law.at_step(step);
                self.v.tau = law.deflect(self.v.tau, travel, bound);
                self.v.angle_ref += travel;
                if !self.v.angle_ref.is_finite() {
                    return Err(ModelError::NotFinite(format!("presliding_reference_angle overflows ({} rad)", show(self.v.angle_ref))));
                }
                // The inputs are held: the operating point (and T) stand; only the friction moves.
                self.v.out.friction = if self.v.load == 0.0 { Default::default() } else { presliding_friction(&law, Mode::Stick, self.v.tau, self.v.omega, bound) };
            }
        }
        self.v.energy = e;
        Ok(())
    }

    fn jacobian(&mut self, unknowns: &[usize], knowns: &[usize], out: &mut [f64]) -> ModelResult<()> {
        let (model, delta) = (self.zero_velocity()?, self.delta());
        let v = self.v;
        let me = self.interface == Some(Interface::ModelExchange);
        super::partials::jacobian(self.evaluator()?, &v, model, delta, me, (unknowns, knowns), out)
    }

    fn serialize(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter::default();
        TABLE.write(STATE_VERSION, &self.v, &mut w);
        out.extend_from_slice(&w.buf);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let mut v = Values::default();
        let mut r = ByteReader::new(bytes);
        TABLE.read("PinJoint", STATE_VERSION, &mut r, &mut v)?;
        r.finish().map_err(rejected)?;
        // Every value passed its setter's check; now those of fmi2ExitInitializationMode
        // (parameters, band, fidelity settings, load capacity of the state's own joint),
        // before anything of this instance changes.
        let joint = Joint::new(&v.params).map_err(|e| ModelError::failed("state: ", e))?;
        v.zv.validate()?;
        v.fidelity.validate()?;
        check_capacity(v.load, joint.capacity())?;
        if Mode::from_code(v.mode).is_none() {
            return Err(ModelError::RejectedState(format!("presliding_mode = {} is not a mode (0, 1 or -1)", show(v.mode))));
        }
        // The same parameters keep the built evaluator (a table is not rebuilt on every restore).
        let same = v.params == self.v.params && v.fidelity == self.v.fidelity && v.zv == self.v.zv;
        let evaluator = if same { self.evaluator.take() } else { None };
        *self = PinJointModel { v, evaluator, message: None, interface: self.interface, validity: self.validity, initialized: true, angle_in_init: false };
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::error::Error;

    /// A parameter the library rejects: the host sees the library's message, and the
    /// error carries the library's typed error as its source.
    #[test]
    fn a_rejected_parameter_carries_the_library_error() {
        let mut m = PinJointModel::new();
        m.set_real(TABLE.index("geometry.pin_radius").unwrap(), -0.028);
        let e = m.exit_initialization(0.0).unwrap_err();
        assert!(e.to_string().starts_with("parameter geometry.pin_radius = -0.028 m "), "{e}");
        let source = e.source().and_then(|s| s.downcast_ref::<pinjoint::ParamError>());
        assert!(matches!(source, Some(pinjoint::ParamError::OutOfRange { .. })), "{source:?}");
    }

    /// A state whose Model Exchange mode is not 0, 1 or -1 is refused, nothing changed.
    #[test]
    fn a_state_with_a_bad_mode_is_refused() {
        let mut m = PinJointModel::new();
        let mode = TABLE.index("presliding_mode").unwrap();
        for bad in [2.0, 0.5, f64::NAN] {
            let mut v = Values::default();
            TABLE.set(&mut v, mode, bad);
            let mut w = ByteWriter::default();
            TABLE.write(STATE_VERSION, &v, &mut w);
            let e = m.deserialize(&w.buf).unwrap_err();
            assert!(matches!(e, ModelError::RejectedState(_) | ModelError::InvalidValue { .. }), "{bad}: {e}");
        }
        assert_eq!(m.v.mode, 0.0);
    }

    /// The first angle set after initialization is the reference when none was set in
    /// initialization mode; one set there is the reference itself.
    #[test]
    fn the_first_angle_is_the_reference_unless_set_in_initialization() {
        let angle = TABLE.index("angle").unwrap();
        let mut m = PinJointModel::new();
        m.exit_initialization(0.0).unwrap();
        m.set_real(angle, 1.4);
        m.compute_outputs().unwrap();
        assert_eq!(m.v.out.friction.torque, 0.0);
        assert_eq!((m.v.angle_ref, m.v.angle_pending, m.v.angle_driven), (1.4, 0.0, 1.0));
        let mut m = PinJointModel::new();
        m.set_real(angle, 0.0);
        m.exit_initialization(0.0).unwrap();
        m.set_real(angle, 1.4);
        m.compute_outputs().unwrap();
        let bound = m.v.out.point.unwrap().torque;
        assert_eq!(m.v.out.friction.torque, -bound);
    }

    /// A state with another layout version is rejected by name, nothing changed.
    #[test]
    fn a_foreign_state_is_rejected() {
        let mut m = PinJointModel::new();
        let mut bytes = Vec::new();
        m.serialize(&mut bytes);
        bytes[0] = STATE_VERSION + 2;
        let e = m.deserialize(&bytes).unwrap_err();
        assert!(matches!(e, ModelError::RejectedState(_)));
        assert_eq!(e.to_string(), format!("PinJoint state version {}; this FMU reads version {STATE_VERSION}", STATE_VERSION + 2));
        bytes[0] = STATE_VERSION;
        m.deserialize(&bytes).unwrap();
    }
}
