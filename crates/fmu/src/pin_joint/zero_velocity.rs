//! PinJoint's zero-velocity treatment: the `zero_velocity.*` parameters and the friction
//! outputs of both laws of [`pinjoint::zero_velocity`] (the band and the presliding state),
//! computed from the library's operating point.
//!
//! Which input drives the presliding state under Co-Simulation: the `angle` input's
//! increments, once the host has set the angle after initialization. Then the torque the host
//! reads after setting (angle, angular_velocity) is the elastic torque at that angle, the same
//! before and after `fmi2DoStep` (which commits it), and ∂torque/∂angle is the presliding
//! stiffness: a host that integrates its angle with symplectic Euler sees the spring at the
//! current position, and a linearly implicit host can take the spring implicitly through the
//! directional derivatives. A host that never sets the angle (it connects only the angular
//! velocity) drives the state by angular_velocity·h over each step, the exact solution of the
//! Model Exchange equation with the input held. Under Model Exchange the state is the host's
//! continuous state `presliding_torque` with derivative `der(presliding_torque)`; the angle is
//! not used.

use crate::declare::declare;
use crate::table::{Row, Rule};
use fmi_layer::core::model::{ModelError, ModelResult};
use fmi_layer::core::variables::{Causality, EnumType, Kind};
use pinjoint::zero_velocity::modes::{self, Mode};
use pinjoint::zero_velocity::presliding::{self, HostCoupling, Presliding};
use pinjoint::zero_velocity::{band, ZeroVelocityModel};

/// The `zero_velocity.model` parameter's choices.
pub static MODEL_TYPE: EnumType = EnumType {
    name: "ZeroVelocityModel",
    description: "Treatment of the friction torque at and near zero angular velocity",
    items: &[
        ("band", 0, "Stateless: the torque ramped linearly inside |omega| < zero_velocity.speed_band (creeps under a drive below breakaway)"),
        ("presliding", 1, "Presliding state (single-state elasto-plastic law): holds below breakaway, breaks away at the sliding torque, slides with the model's torque"),
    ],
};

/// The zero-velocity parameters of an instance, as the host set them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZeroVelocitySettings {
    /// Code of `zero_velocity.model` (0 band, 1 presliding).
    pub code: f64,
    /// `zero_velocity.speed_band` ω_b (rad/s).
    pub band: f64,
    /// `zero_velocity.presliding_angle`, `zero_velocity.elastic_limit`, `zero_velocity.damping_time`,
    /// `zero_velocity.host_inertia` (its `step` is 0: the model sets the host's step per evaluation).
    pub law: Presliding,
}

impl Default for ZeroVelocitySettings {
    fn default() -> Self {
        ZeroVelocitySettings { code: ZeroVelocityModel::default().code() as f64, band: band::DEFAULT_SPEED_BAND, law: Presliding::default() }
    }
}

impl ZeroVelocitySettings {
    /// The model chosen, every parameter checked (each whatever the model); an error names
    /// the parameter, its value and unit.
    pub fn validate(&self) -> ModelResult<ZeroVelocityModel> {
        let model = if self.code.fract() == 0.0 { ZeroVelocityModel::from_code(self.code as i64) } else { None };
        let model = model.ok_or_else(|| {
            let rule = Rule::Code(&MODEL_TYPE).broken_by(self.code, "").unwrap_or_default();
            ModelError::invalid("parameter", "zero_velocity.model", self.code, "", rule)
        })?;
        band::check_band(self.band).map_err(|e| ModelError::failed("", e))?;
        self.law.validate().map_err(|e| ModelError::failed("", e))?;
        Ok(model)
    }
}

/// The friction outputs of one evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Friction {
    /// Friction torque on the pin (N·m).
    pub torque: f64,
    /// Power dissipated (W).
    pub power_loss: f64,
    /// The presliding torque τ the outputs use (N·m): at the current angle (Co-Simulation),
    /// the host's state (Model Exchange); 0 for the band.
    pub held: f64,
    /// dτ/dt (N·m/s), the Model Exchange derivative; 0 for the band.
    pub rate: f64,
}

/// The presliding outputs at the held torque `tau` (N·m), ω and the sliding torque `bound`, in
/// the Model Exchange `mode` (always stick under Co-Simulation; [`modes`]).
pub fn presliding_friction(law: &Presliding, mode: Mode, tau: f64, omega: f64, bound: f64) -> Friction {
    Friction {
        torque: modes::torque(law, mode, tau, omega, bound),
        power_loss: modes::dissipation(law, mode, tau, omega, bound),
        held: tau,
        rate: modes::rate(law, mode, tau, omega, bound),
    }
}

/// The `zero_velocity.host_inertia` parameter row at value reference `vr`, state slot `slot`.
pub fn host_inertia_row<S: 'static>(vr: u32, slot: usize, at: fn(&S) -> &ZeroVelocitySettings, at_mut: fn(&mut S) -> &mut ZeroVelocitySettings) -> Row<S> {
    let mut v = declare(presliding::HOST_INERTIA_NAME, vr, Kind::Real, Causality::Parameter, Some("kg.m2"), None,
        "Inertia J of the host's body on the pin (kg.m2), 0 = not given (the default). When given, the presliding damping is c = 2 zeta sqrt(k J), \
         zeta = 0.7 (near critical: a heavy body settles within a few presliding periods, a resonant dither below breakaway does not walk) instead of \
         zero_velocity.damping_time k, capped under Co-Simulation for an explicit host at the last communication step h: \
         c <= 0.9 (J/h) min(1, 2 - h^2 k/J); in [0, 1e9]");
    v.start = Some(0.0);
    v.min = Some(0.0);
    v.max = Some(presliding::MAX_HOST_INERTIA);
    Row::new(v, move |s| at(s).law.host_inertia, move |s, x| at_mut(s).law.host_inertia = x, Rule::Any).at_slot(slot)
}

/// The `zero_velocity.host_coupling` parameter row (Integer: 0 sequential, 1 parallel) at
/// value reference `vr`, state slot `slot`.
pub fn host_coupling_row<S: 'static>(vr: u32, slot: usize, at: fn(&S) -> &ZeroVelocitySettings, at_mut: fn(&mut S) -> &mut ZeroVelocitySettings) -> Row<S> {
    let mut v = declare(presliding::HOST_COUPLING_NAME, vr, Kind::Integer, Causality::Parameter, None, None,
        "How the host couples the torque to its body: 0 = sequential (the default: the host sets angle and angular_velocity, steps the FMU and integrates its body with the torque of the same step, as fmpy loops and Simulink do), 1 = parallel (the master steps every FMU and then exchanges the values, so the body integrates the torque of the previous communication point, as libcosim/OSP and Ecos do). With 1 and zero_velocity.host_inertia = J given, the presliding stiffness is capped at J/(27 h^2) for that delayed loop (h the communication step), so a hold stays stable and free of chatter");
    v.start = Some(0.0);
    v.min = Some(0.0);
    v.max = Some(1.0);
    Row::new(v, move |s| at(s).law.coupling.code() as f64,
        move |s, x| at_mut(s).law.coupling = HostCoupling::from_code(x as i64).unwrap_or_default(), Rule::Closed(0.0, 1.0)).at_slot(slot)
}

/// The band outputs: `sliding` = T(P, |ω|), `edge` = T(P, ω_b) (evaluated only inside the band).
pub fn band_friction(omega: f64, width: f64, sliding: f64, edge: impl FnOnce() -> ModelResult<f64>) -> ModelResult<Friction> {
    let torque = if band::inside(omega, width) { band::torque(omega, width, sliding, edge()?) } else { band::torque(omega, width, sliding, 0.0) };
    Ok(Friction { torque, power_loss: (torque * omega).abs(), held: 0.0, rate: 0.0 })
}

/// The parameter rows `zero_velocity.model` and the three presliding parameters at value
/// references `vr`.. and state slots `slot`..; `at` finds the settings in the model's values.
pub fn rows<S: 'static>(vr: u32, slot: usize, at: fn(&S) -> &ZeroVelocitySettings, at_mut: fn(&mut S) -> &mut ZeroVelocitySettings) -> Vec<Row<S>> {
    let d = Presliding::default();
    let mut model = declare("zero_velocity.model", vr, Kind::Enumeration(&MODEL_TYPE), Causality::Parameter, None, None,
        "Zero-velocity treatment: 0 = band (stateless ramp inside zero_velocity.speed_band; a drive below breakaway creeps), \
         1 = presliding (default: a presliding state holds the joint below breakaway, breaks away at the sliding torque and slides with the model's torque)");
    model.start = Some(ZeroVelocityModel::default().code() as f64);
    model.min = Some(0.0);
    model.max = Some(1.0);
    let real = |name: &str, vr: u32, unit: Option<&'static str>, display: Option<&'static str>, start: f64, range: (Option<f64>, Option<f64>), text: &str| {
        let mut v = declare(name, vr, Kind::Real, Causality::Parameter, unit, display, text);
        v.start = Some(start);
        (v.min, v.max) = range;
        v
    };
    let rows = vec![
        Row::new(model, move |s| at(s).code, move |s, x| at_mut(s).code = x, Rule::Code(&MODEL_TYPE)),
        Row::new(
            real(presliding::ANGLE_NAME, vr + 1, Some("rad"), Some("deg"), d.angle, (None, Some(1.0)),
                "Presliding angle phi_s: the elastic deflection at which the presliding torque would reach the sliding torque (stiffness k = T/phi_s); in (0, 1] rad. \
                 The default 1.5e-3 rad (42 um at the pin surface) keeps explicit hosts stable at 10 ms steps for J >= 20 kg.m2 up to 60 kN"),
            move |s| at(s).law.angle,
            move |s, x| at_mut(s).law.angle = x,
            Rule::OpenClosed(0.0, 1.0),
        ),
        Row::new(
            real(presliding::ELASTIC_LIMIT_NAME, vr + 2, None, None, d.elastic_limit, (Some(0.0), None),
                "Elastic limit beta: fraction of the sliding torque up to which presliding is purely elastic (no drift under any drive below beta T); in [0, 1)"),
            move |s| at(s).law.elastic_limit,
            move |s, x| at_mut(s).law.elastic_limit = x,
            Rule::Any,
        ),
        Row::new(
            real(presliding::DAMPING_TIME_NAME, vr + 3, Some("s"), Some("ms"), d.damping_time, (Some(0.0), Some(1e3)),
                "Presliding damping time t_d: damping c = t_d k of the elastic deflection rate; in [0, 1000] s"),
            move |s| at(s).law.damping_time,
            move |s, x| at_mut(s).law.damping_time = x,
            Rule::Any,
        ),
    ];
    rows.into_iter().enumerate().map(|(k, r)| r.at_slot(slot + k)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_are_checked_by_name() {
        assert_eq!(ZeroVelocitySettings::default().validate().unwrap(), ZeroVelocityModel::Presliding);
        let bad = ZeroVelocitySettings { code: 2.0, ..Default::default() };
        assert_eq!(bad.validate().unwrap_err().to_string(), "parameter zero_velocity.model = 2 is out of range: it must be 0 (band) or 1 (presliding)");
        let bad = ZeroVelocitySettings { band: -1.0, ..Default::default() };
        assert!(bad.validate().unwrap_err().to_string().contains("zero_velocity.speed_band = -1 rad/s"));
        let mut bad = ZeroVelocitySettings::default();
        bad.law.elastic_limit = f64::NAN;
        assert!(bad.validate().unwrap_err().to_string().contains("zero_velocity.elastic_limit = NaN"));
    }
}
