//! The rig FMU's settings: every parameter and input value an instance holds, with the
//! checks of their setters and of initialization, shared by the model and the state format.

use super::variables::{default_load, rig_spec, Var, DEFAULT_ENVELOPE, DEFAULT_TOLERANCE};
use crate::pin_joint::variables::fidelity_of_code;
use fmi_layer::fmi2::logging::show;
use fmi_layer::fmi2::model::ModelResult;
use pinjoint::fidelity::{Envelope, Fidelity};
use pinjoint::params::PARAMS;
use pinjoint::rig::{Formulation, Inputs, Method, RigConfig, RIG_PARAMS};

/// Every value a host can set, as the model holds it (Booleans and Integers as f64).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Model and rig parameters (`cfg.rig.load` is unused: the load is the input).
    pub cfg: RigConfig,
    /// The `use_command_input` parameter: follow the `command_angle` input instead of the
    /// sine stroke.
    pub use_command_input: bool,
    /// Integer codes of `rig.formulation` and `rig.method`, checked at initialization.
    pub formulation: f64,
    /// Integer code of `rig.method` (0 dopri5, 1 dop853, 2 rk4), checked at initialization.
    pub method: f64,
    /// The `load` input (N): the radial load on the pin.
    pub load: f64,
    /// The `command_angle` input (rad), followed when `use_command_input` is true.
    pub command_angle: f64,
    /// Integer code of `fidelity`, checked when set and at initialization.
    pub fidelity: f64,
    /// The `tolerance` parameter: the relative error a table level may have against full.
    pub tolerance: f64,
    /// load_min, load_max (N), speed_min, speed_max (rad/s).
    pub envelope: [f64; 4],
    /// The `temperature` input (K), the lubricant temperature (`cfg.model.lubricant.temperature`
    /// is unused, as `cfg.rig.load` is).
    pub temperature: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            cfg: RigConfig::default(),
            use_command_input: false,
            formulation: 0.0,
            method: 0.0,
            load: default_load(),
            command_angle: 0.0,
            fidelity: 0.0,
            tolerance: DEFAULT_TOLERANCE,
            envelope: DEFAULT_ENVELOPE,
            temperature: pinjoint::params::DEFAULT_TEMPERATURE,
        }
    }
}

impl Settings {
    /// The value of table entry `v` (not an output).
    pub fn get(&self, v: Var) -> f64 {
        let rig = &self.cfg.rig;
        match v {
            Var::Load => self.load,
            Var::CommandAngle => self.command_angle,
            Var::Frequency => rig.frequency,
            Var::Amplitude => rig.amplitude,
            Var::UseCommandInput => f64::from(u8::from(self.use_command_input)),
            Var::Rig(i) => (RIG_PARAMS[i].get)(rig),
            Var::Formulation => self.formulation,
            Var::Method => self.method,
            Var::Model(i) => (PARAMS[i].get)(&self.cfg.model),
            Var::Fidelity => self.fidelity,
            Var::Tolerance => self.tolerance,
            Var::Envelope(k) => self.envelope[k],
            Var::Temperature => self.temperature,
            Var::Out(_) => unreachable!("outputs are not settings"),
        }
    }

    /// Store `x` as the value of table entry `v` (not an output; not checked here).
    pub fn set(&mut self, v: Var, x: f64) {
        let rig = &mut self.cfg.rig;
        match v {
            Var::Load => self.load = x,
            Var::CommandAngle => self.command_angle = x,
            Var::Frequency => rig.frequency = x,
            Var::Amplitude => rig.amplitude = x,
            Var::UseCommandInput => self.use_command_input = x != 0.0,
            Var::Rig(i) => (RIG_PARAMS[i].set)(rig, x),
            Var::Formulation => self.formulation = x,
            Var::Method => self.method = x,
            Var::Model(i) => (PARAMS[i].set)(&mut self.cfg.model, x),
            Var::Fidelity => self.fidelity = x,
            Var::Tolerance => self.tolerance = x,
            Var::Envelope(k) => self.envelope[k] = x,
            Var::Temperature => self.temperature = x,
            Var::Out(_) => unreachable!("the FMI layer never sets outputs"),
        }
    }

    /// The inputs as the simulator takes them.
    pub fn inputs(&self) -> Inputs {
        Inputs { load: Some(self.load), command_angle: self.use_command_input.then_some(self.command_angle) }
    }

    /// Check an input value (parameters are checked together by [`Settings::config`]).
    pub fn check_input(v: Var, x: f64) -> ModelResult<()> {
        match v {
            Var::Load if !x.is_finite() => Err(format!(
                "input load = {} N is invalid: it must be a finite number (a negative value is taken as its magnitude)",
                show(x)
            ).into()),
            Var::CommandAngle if !x.is_finite() => Err(format!("input command_angle = {} rad is not a finite number", show(x)).into()),
            Var::Temperature if !(x > pinjoint::params::MIN_TEMPERATURE && x <= pinjoint::params::MAX_TEMPERATURE) => Err(format!(
                "input temperature = {} K is out of range: it must be in ({}, {}] K",
                show(x),
                pinjoint::params::MIN_TEMPERATURE,
                pinjoint::params::MAX_TEMPERATURE
            ).into()),
            Var::Fidelity if x.fract() != 0.0 || fidelity_of_code(x as i32).is_none() => Err(fidelity_range(x).into()),
            _ => Ok(()),
        }
    }

    /// The validated configuration; an error names the parameter, its value and unit.
    pub fn config(&self) -> ModelResult<RigConfig> {
        // Every model parameter is checked as set, `lubricant.temperature` too (the input replaces it).
        self.cfg.model.validate().map_err(|e| e.to_string())?;
        let mut cfg = self.cfg;
        for key in ["frequency", "amplitude"] {
            let s = rig_spec(key);
            let x = (s.get)(&cfg.rig);
            if !(x.is_finite() && s.range.contains(x)) {
                return Err(format!("parameter {key} = {} {} is invalid: it must be a finite number {}", show(x), s.unit, s.range.describe()).into());
            }
        }
        cfg.rig.formulation = match self.formulation {
            0.0 => Formulation::Hybrid,
            1.0 => Formulation::Regularised,
            x => return Err(format!("parameter rig.formulation = {x} is invalid: it must be 0 (hybrid) or 1 (regularised)").into()),
        };
        cfg.rig.method = match self.method {
            0.0 => Method::Dopri5,
            1.0 => Method::Dop853,
            2.0 => Method::Rk4,
            x => return Err(format!("parameter rig.method = {x} is invalid: it must be 0 (Dopri5), 1 (Dop853) or 2 (RK4)").into()),
        };
        cfg.rig.load = self.load.abs();
        cfg.model.lubricant.temperature = self.temperature;
        cfg.validate().map_err(|e| e.to_string())?;
        Ok(cfg)
    }

    /// The validated fidelity settings: the level, the tolerance and the envelope. They are
    /// checked whatever the level (as PinJoint does), though `full` uses neither tolerance nor
    /// envelope. An error names the parameter, its value and unit.
    pub fn fidelity(&self) -> ModelResult<(Fidelity, f64, Envelope)> {
        let level = (self.fidelity.fract() == 0.0).then(|| fidelity_of_code(self.fidelity as i32)).flatten();
        let level = level.ok_or_else(|| fidelity_range(self.fidelity))?;
        let t = self.tolerance;
        if !(t.is_finite() && t > 0.0) {
            return Err(format!("parameter tolerance = {} (relative error, dimensionless) is invalid: it must be a finite number > 0", show(t)).into());
        }
        let env = crate::envelope_from_parameters(self.envelope)?;
        Ok((level, t, env))
    }
}

impl Settings {
    /// The fidelity settings as stored (code, tolerance, envelope), for comparisons.
    pub fn fidelity_key(&self) -> [f64; 6] {
        let [a, b, c, d] = self.envelope;
        [self.fidelity, self.tolerance, a, b, c, d]
    }
}

fn fidelity_range(x: f64) -> String {
    format!("parameter fidelity = {} is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)", show(x))
}
