//! The rig's parameters: the `[rig]` section of a parameter file, beside the model's sections.
//!
//! # Actuator model and the reasoning for its defaults
//!
//! The paper gives no actuator data (section 4: a servo-hydraulic torsional actuator rated
//! 200 N·m, in angle control from a function generator, with an internal strain-gauge torque
//! transducer). The rig model is the smallest one that has the parts the paper describes:
//!
//! ```text
//! θ_cmd(t) = A·sin(2π f t)                                   command (function generator)
//! T_d      = clamp(K_p·(θ_cmd − θ) + K_d·(θ̇_cmd − ω), ±T_max)  position loop with a derivative term
//! τ_s·Ṫ_a  = T_d − T_a                                       first-order torque lag (servo-valve + oil)
//! J·ω̇      = T_a + T_f,    θ̇ = ω                             rotating inertia, T_f = friction on the pin
//! ```
//!
//! Without friction the loop's characteristic polynomial is `τ_s J s³ + J s² + K_d s + K_p`;
//! Routh–Hurwitz gives stability iff `K_d > τ_s·K_p`, which validation enforces.
//!
//! Defaults, and why:
//! - `inertia` J = 0.05 kg·m²: the hollow 300M pin (OD 56, ID 42, 200.5 mm, section 4.2) is
//!   1.0e-3 kg·m²; the rotor of a 200 N·m rotary vane actuator, its drive shaft, the torque
//!   transducer and the spline coupling are taken as ≈ 0.05 kg·m² (an estimate: no data given).
//! - `position_gain` K_p = 6000 N·m/rad (105 N·m per degree): the loop must supply the friction
//!   torque μ·R·P (≤ 67 N·m at 20 kN, 202 N·m at 60 kN) from the angle error, so the stroke lags
//!   the command by about T/K_p: 0.64° at 20 kN and 1.9° at 60 kN, 1 Hz ("a few degrees").
//! - `servo_time_constant` τ_s = 3 ms: the servo-valve and oil-column response of the torque
//!   loop (≈ 50 Hz bandwidth), the limited response the paper blames for the oscillation at
//!   1 Hz (section 5).
//! - `velocity_gain` K_d = 40 N·m·s/rad = 2.2·τ_s·K_p. The closed loop (no friction) then has a
//!   real pole at 27 Hz and a lightly damped pair at 78 Hz, ζ = 0.17. Each reversal (a step of
//!   2μ·R·P in the friction torque) rings that pair: at 1 Hz the joint breaks away while the
//!   command is already moving at speed and the recorded torque oscillates by about ±10 N·m
//!   for ≈ 60 ms after each reversal at 20 kN (Figure 13b); at 0.03 Hz the reversal is
//!   quasi-static and the torque is clean (Figure 11b). With K_d = 30 (ζ = 0.13) the ringing at
//!   60 kN, 1 Hz turns into sustained stick–slip over the whole stroke; 40 keeps a margin
//!   against the falling (Stribeck) friction, whose slope R·P·dμ/dω ≈ −6 N·m·s/rad at 60 kN
//!   acts as negative damping.
//! - `torque_limit` T_max = 400 N·m: twice the 200 N·m rating, so saturation is available but does not act
//!   in the paper's tests (a 60 kN stroke needs 202 N·m); set 200 to model the rating strictly.
//! - `breakaway_factor` = 1: static = kinetic boundary friction, the paper's model. Raise it
//!   (e.g. 1.1) to reproduce the slightly higher torque the experiments show at stroke ends.
//! - `regularisation_speed` ω_reg = 1e-3 rad/s, for the regularised formulation only:
//!   tanh(ω/ω_reg) > 0.99 above 2.6e-3 rad/s, 2 % of the 0.03 Hz peak speed (0.13 rad/s). The
//!   creep band is stiff: its time constant J·ω_reg/(μ_c R P) is 0.75 µs at 20 kN, so explicit
//!   integrators take steps of that size while the joint "sticks". That is the price the hybrid
//!   formulation avoids.
//! - Integration: Dopri5, rtol = 1e-8, atol = 1e-9 (the state mixes rad, rad/s, N·m and J; all
//!   are O(0.1–1e3)), RK4 step 1e-4 s, events located to 1e-10 s, internal segments of 0.05 s.

use crate::params::{ParamError, Range};
use serde::{Deserialize, Serialize};

/// How the friction at ω = 0 is modelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Formulation {
    /// Stick/slip hybrid system: slip phases with the friction torque −sign(ω)·μ(P,|ω|)·R·P,
    /// stick phases with ω = 0 while |T_a| ≤ breakaway torque, transitions located as events.
    #[default]
    Hybrid,
    /// One smooth ODE: friction torque −μ(P,|ω|)·R·P·tanh(ω/ω_reg). No events, stiff near ω = 0.
    Regularised,
}

/// The ODE integrator used for every phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Dormand–Prince 5(4), adaptive (`rtol`, `atol`).
    #[default]
    Dopri5,
    /// Dormand–Prince 8(5,3), adaptive (`rtol`, `atol`).
    Dop853,
    /// Classical Runge–Kutta 4, fixed step `rk4_step`.
    Rk4,
    /// Dormand–Prince 5(4), adaptive (`rtol`, `atol`), integrating in slip the deviation from
    /// the position loop's steady response to the sine command (an exact change of variables,
    /// `rig::steady`), in Lawson form: the loop linearised about the slip (the friction's
    /// secant slope in the speed included) is solved exactly by its matrix exponential, and
    /// Dopri5 integrates what the friction's departure from it, the saturation and the
    /// energy integrals add (`rig::lawson`: far fewer steps). The states between steps
    /// (samples, communication points, event location trials) are read from its continuous
    /// extension (exponential quadrature) instead of one re-integration step each: no
    /// right-hand-side evaluations for them. Stick phases and the regularised formulation
    /// use `ode_solvers`' Dopri5 with the same continuous output.
    Dopri5Dense,
}

/// Every rig constant (SI units). See the module documentation for the equations and defaults.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RigParams {
    /// A, command amplitude (rad). Default 40° (section 4.4).
    pub amplitude: f64,
    /// f, command frequency (Hz). Default 1 Hz (0.03, 0.3 and 1 Hz in the paper).
    pub frequency: f64,
    /// P, radial load on the pin (N), used when no load input is given. Default 20 kN.
    pub load: f64,
    /// J, rotating inertia (kg·m²).
    pub inertia: f64,
    /// K_p, position gain (N·m/rad).
    pub position_gain: f64,
    /// K_d, velocity (derivative) gain (N·m·s/rad); must exceed τ_s·K_p.
    pub velocity_gain: f64,
    /// τ_s, servo torque lag time constant (s).
    pub servo_time_constant: f64,
    /// T_max, saturation of the torque demand (N·m).
    pub torque_limit: f64,
    /// Breakaway torque / (μ_c R P) (≥ 1).
    pub breakaway_factor: f64,
    /// ω_reg, speed scale of the regularised formulation (rad/s).
    pub regularisation_speed: f64,
    /// Relative tolerance of Dopri5/Dop853.
    pub rtol: f64,
    /// Absolute tolerance of Dopri5/Dop853 (same number for every state component).
    pub atol: f64,
    /// Step of the fixed-step RK4 integrator (s).
    pub rk4_step: f64,
    /// Event times (ω = 0 reversals, breakaway) are located to this width (s).
    pub event_tolerance: f64,
    /// Length of the internal integration segments (s); they end on multiples of it.
    pub segment_length: f64,
    /// How stick at reversal is modelled: hybrid events or a regularised ODE.
    pub formulation: Formulation,
    /// The integrator of the slip phases (or of the regularised ODE).
    pub method: Method,
}

impl Default for RigParams {
    fn default() -> Self {
        Self {
            amplitude: 40f64.to_radians(),
            frequency: 1.0,
            load: 20e3,
            inertia: 0.05,
            position_gain: 6000.0,
            velocity_gain: 40.0,
            servo_time_constant: 0.003,
            torque_limit: 400.0,
            breakaway_factor: 1.0,
            regularisation_speed: 1e-3,
            rtol: 1e-8,
            atol: 1e-9,
            rk4_step: 1e-4,
            event_tolerance: 1e-10,
            segment_length: 0.05,
            formulation: Formulation::Hybrid,
            method: Method::Dopri5,
        }
    }
}

/// One numeric `[rig]` key: name, unit, admissible range, accessors (for messages, FMU parameters).
#[derive(Clone, Copy)]
pub struct RigParamSpec {
    /// The key in the `[rig]` section.
    pub key: &'static str,
    /// SI unit of the value.
    pub unit: &'static str,
    /// Admissible values; anything else is a validation error naming the key.
    pub range: Range,
    /// One line for messages, the FMU's description and `pinjoint params --rig`.
    pub description: &'static str,
    /// Reads the value from a [`RigParams`].
    pub get: fn(&RigParams) -> f64,
    /// Writes the value into a [`RigParams`].
    pub set: fn(&mut RigParams, f64),
}

impl RigParamSpec {
    /// `rig.key`, the name in messages.
    pub fn name(&self) -> String {
        format!("rig.{}", self.key)
    }
}

macro_rules! rspec {
    ($key:ident, $unit:expr, $range:expr, $desc:expr) => {
        RigParamSpec {
            key: stringify!($key),
            unit: $unit,
            range: $range,
            description: $desc,
            get: |p: &RigParams| p.$key,
            set: |p: &mut RigParams, v: f64| p.$key = v,
        }
    };
}

/// Largest gains offered: K_p ≤ 1e6 N·m/rad, K_d ≤ 1e4 N·m·s/rad. With J ≥ 1e-3 kg·m² and
/// τ_s ≥ 1e-3 s the fastest closed-loop mode, |s| ≈ √(K_d/(τ_s J)) ≤ 1e5 rad/s, keeps explicit
/// steps above ≈ 3e-5 s.
pub const MAX_POSITION_GAIN: f64 = 1e6;
/// Largest derivative gain K_d offered (N·m·s/rad); see [`MAX_POSITION_GAIN`].
pub const MAX_VELOCITY_GAIN: f64 = 1e4;

/// Every numeric `[rig]` parameter.
pub static RIG_PARAMS: [RigParamSpec; 15] = [
    rspec!(amplitude, "rad", Range::NonNegative, "Command amplitude A"),
    rspec!(frequency, "Hz", Range::Positive, "Command frequency f"),
    rspec!(load, "N", Range::NonNegative, "Radial load P when no load input is given"),
    rspec!(inertia, "kg.m2", Range::HalfOpen(1e-3, 10.0), "Rotating inertia J"),
    rspec!(position_gain, "N.m/rad", Range::OpenClosed(0.0, MAX_POSITION_GAIN), "Position gain K_p"),
    rspec!(velocity_gain, "N.m.s/rad", Range::OpenClosed(0.0, MAX_VELOCITY_GAIN), "Velocity gain K_d (> tau_s K_p)"),
    rspec!(servo_time_constant, "s", Range::HalfOpen(1e-3, 1.0), "Servo torque lag tau_s"),
    rspec!(torque_limit, "N.m", Range::Positive, "Saturation of the torque demand T_max"),
    rspec!(breakaway_factor, "1", Range::HalfOpen(1.0, 100.0), "Breakaway torque / (mu_c R P)"),
    rspec!(regularisation_speed, "rad/s", Range::Positive, "Speed scale of the regularised formulation"),
    rspec!(rtol, "1", Range::OpenClosed(1e-14, 1e-2), "Relative tolerance (Dopri5, Dop853)"),
    rspec!(atol, "1", Range::OpenClosed(1e-16, 1e-2), "Absolute tolerance (Dopri5, Dop853)"),
    rspec!(rk4_step, "s", Range::OpenClosed(1e-8, 0.01), "RK4 step"),
    rspec!(event_tolerance, "s", Range::OpenClosed(1e-14, 1e-4), "Event location tolerance"),
    rspec!(segment_length, "s", Range::OpenClosed(1e-4, 10.0), "Internal segment length"),
];

impl RigParams {
    /// Check every value (the error names `rig.key`, the value and the unit).
    pub fn validate(&self) -> Result<(), ParamError> {
        for s in RIG_PARAMS.iter() {
            let v = (s.get)(self);
            if !v.is_finite() {
                return Err(ParamError::NotFinite { name: s.name(), value: v, unit: s.unit });
            }
            if !s.range.contains(v) {
                return Err(ParamError::OutOfRange { name: s.name(), value: v, unit: s.unit, range: s.range.describe() });
            }
        }
        let bound = self.servo_time_constant * self.position_gain;
        if self.velocity_gain <= bound {
            return Err(ParamError::OutOfRange {
                name: "rig.velocity_gain".into(),
                value: self.velocity_gain,
                unit: "N.m.s/rad",
                range: format!(
                    "> rig.servo_time_constant * rig.position_gain = {bound} (Routh-Hurwitz stability of the position loop)"
                ),
            });
        }
        Ok(())
    }

    /// Stroke period 1/f (s).
    pub fn period(&self) -> f64 {
        1.0 / self.frequency
    }
}
