//! The rig FMU's settings: every parameter and input value an instance holds, with the
//! checks of initialization (each value's own check is its row's, [`super::variables::TABLE`]).

use crate::fidelity::FidelitySettings;
use fmi_layer::core::model::{ModelError, ModelResult};
use pinjoint::fidelity::{Envelope, Fidelity};
use pinjoint::rig::params::{RigParamSpec, RIG_PARAMS};
use pinjoint::rig::{Formulation, Inputs, Method, RigConfig};

/// The row of [`RIG_PARAMS`] with `key`.
pub fn rig_spec(key: &str) -> &'static RigParamSpec {
    RIG_PARAMS.iter().find(|s| s.key == key).expect("a [rig] key")
}

/// Every value a host can set, as the model holds it (Booleans and Integers as f64).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Model and rig parameters (`cfg.rig.load` is unused: the load is the input).
    pub cfg: RigConfig,
    /// The `use_command_input` parameter: follow the `command_angle` input instead of the
    /// sine stroke.
    pub use_command_input: bool,
    /// Integer code of `rig.formulation` (0 hybrid, 1 regularised), checked at initialization.
    pub formulation: f64,
    /// Integer code of `rig.method` (0 dopri5, 1 dop853, 2 rk4, 3 dopri5-dense), checked at initialization.
    pub method: f64,
    /// The `load` input (N): the radial load on the pin.
    pub load: f64,
    /// The `command_angle` input (rad), followed when `use_command_input` is true.
    pub command_angle: f64,
    /// `fidelity`, `tolerance` and the envelope.
    pub fidelity: FidelitySettings,
    /// The `temperature` input (K), the lubricant temperature (`cfg.model.lubricant.temperature`
    /// is unused, as `cfg.rig.load` is).
    pub temperature: f64,
}

impl Settings {
    /// The inputs as the simulator takes them.
    pub fn inputs(&self) -> Inputs {
        Inputs { load: Some(self.load), command_angle: self.use_command_input.then_some(self.command_angle) }
    }

    /// The validated configuration; an error names the parameter, its value and unit.
    pub fn config(&self) -> ModelResult<RigConfig> {
        // Every model parameter is checked as set, `lubricant.temperature` too (the input replaces it).
        self.cfg.model.validate().map_err(|e| ModelError::failed("", e))?;
        let mut cfg = self.cfg;
        for key in ["frequency", "amplitude"] {
            let s = rig_spec(key);
            let x = (s.get)(&cfg.rig);
            if !(x.is_finite() && s.range.contains(x)) {
                return Err(ModelError::invalid("parameter", key, x, s.unit, format!("is invalid: it must be a finite number {}", s.range.describe())));
            }
        }
        cfg.rig.formulation = match self.formulation {
            0.0 => Formulation::Hybrid,
            1.0 => Formulation::Regularised,
            x => return Err(ModelError::invalid("parameter", "rig.formulation", x, "", "is invalid: it must be 0 (hybrid) or 1 (regularised)")),
        };
        cfg.rig.method = match self.method {
            0.0 => Method::Dopri5,
            1.0 => Method::Dop853,
            2.0 => Method::Rk4,
            3.0 => Method::Dopri5Dense,
            x => return Err(ModelError::invalid("parameter", "rig.method", x, "", "is invalid: it must be 0 (Dopri5), 1 (Dop853), 2 (RK4) or 3 (Dopri5 dense)")),
        };
        cfg.rig.load = self.load.abs();
        cfg.model.lubricant.temperature = self.temperature;
        cfg.validate().map_err(|e| ModelError::failed("", e))?;
        Ok(cfg)
    }

    /// The validated fidelity settings: the level, the tolerance and the envelope
    /// ([`FidelitySettings::validate`]).
    pub fn fidelity(&self) -> ModelResult<(Fidelity, f64, Envelope)> {
        self.fidelity.validate()
    }
}
