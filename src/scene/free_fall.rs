//! The free-fall extension: the leg's equation of motion about the trunnion, integrated by
//! semi-implicit (symplectic) Euler with the trunnion friction read before each step.
//!
//! Torques on the leg (positive = increasing φ, φ from the down-locked position):
//!
//! ```text
//!   T_g = −m g l sin φ                    gravity
//!   T_d = −c1 ω − c2 ω |ω|                the actuator throttled as a damper
//!   T_s = −T_l for φ < φ_e, else 0        the lock spring
//!   T_f = n_pins × (the joint's friction torque at φ, ω, P, T)
//!   J dω/dt = T_g + T_d + T_s + T_f
//! ```
//!
//! The pin load follows from the leg's dynamics: with the trunnion at the origin (x horizontal,
//! y up) and the centre of gravity at l(sin φ, −cos φ), its acceleration is
//! a_cg = l[α(cos φ, sin φ) + ω²(−sin φ, cos φ)], the reaction on the leg F = m a_cg + (0, m g),
//! and each pin carries P = share × |F|. α is that of the previous step (0 at the first),
//! lagged one step so the load is known before the friction torque that depends on it.
//!
//! Step n (t = n h): P_n from (φ_n, ω_n, α_{n−1}); the friction torque T_f,n at (φ_n, ω_n, P_n),
//! the joint's step committed; α_n = ΣT/J, ω_{n+1} = ω_n + h α_n, φ_{n+1} = φ_n + h ω_{n+1}.
//! The leg locks at the first step with φ_{n+1} ≤ 0, at the time interpolated linearly inside
//! the step.
//!
//! The lock margin (static, at the lock): the lock spring's torque about the lock links against
//! the breakaway torque of their pivots at the lock spring's load and the temperature,
//! lock_link_torque / (pivots × T_break) − 1. Positive: the lock engages.

use super::error::SceneError;
use super::params::FreeFallParams;
use super::trunnion::Trunnion;
use crate::fidelity::{Envelope, Level};
use crate::joint::Joint;
use crate::params::Params;

/// The angular velocity (rad/s) standing for ω → 0⁺ in the breakaway torque: far below any
/// speed at which the film carries load in the joint model.
pub const BREAKAWAY_SPEED: f64 = 1e-9;

/// One step of a run: the state at its start and what acted during it (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// t, s.
    pub time: f64,
    /// φ, rad (0 = down and locked).
    pub angle: f64,
    /// ω, rad/s (negative while the leg falls).
    pub angular_velocity: f64,
    /// P, the load on each trunnion pin, N.
    pub load: f64,
    /// T_f, the friction torque of all trunnion pins on the leg, N·m (opposing ω).
    pub friction_torque: f64,
}

/// What one run gave.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeFallOutcome {
    /// The joints' temperature, K.
    pub temperature: f64,
    /// Every step's [`Sample`]; the last is the lock (φ = 0 at the interpolated time, with the
    /// velocity, load and torque of the locking step) or the end of the run.
    pub series: Vec<Sample>,
    /// Whether the leg reached φ = 0 before the end time.
    pub locked: bool,
    /// Time from release to lock, s (+∞ if not locked).
    pub time_to_lock: f64,
    /// |ω| at the lock, rad/s (the locking step's ω_{n+1}); None if not locked.
    pub speed_at_lock: Option<f64>,
    /// lock_link_torque / (pivots × T_break) − 1 (dimensionless; positive: the lock engages).
    pub lock_margin: f64,
    /// T_break, the breakaway torque of one lock-link pivot at the lock spring's load, N·m.
    pub breakaway_torque: f64,
    /// The work of the trunnion friction against the leg's motion, −Σ T_f Δφ, J.
    pub friction_energy: f64,
    /// The level the trunnion's sliding torque ran at (None without trunnion pins).
    pub level: Option<Level>,
}

/// Each trunnion pin's load P (N) at angle `phi` (rad), angular velocity `omega` (rad/s) and
/// angular acceleration `alpha` (rad/s²).
pub fn pin_load(scene: &FreeFallParams, phi: f64, omega: f64, alpha: f64) -> f64 {
    let (s, c) = phi.sin_cos();
    let (m, l) = (scene.leg_mass, scene.cg_distance);
    let ax = l * (alpha * c - omega * omega * s);
    let ay = l * (alpha * s + omega * omega * c);
    scene.trunnion_load_share * (m * ax).hypot(m * (ay + scene.gravity))
}

/// The torques on the leg other than friction (N·m) at `phi` (rad) and `omega` (rad/s):
/// gravity, the damper and the lock spring.
pub fn applied_torque(scene: &FreeFallParams, phi: f64, omega: f64) -> f64 {
    let gravity = -scene.leg_mass * scene.gravity * scene.cg_distance * phi.sin();
    let damper = -scene.damper_linear * omega - scene.damper_quadratic * omega * omega.abs();
    let spring = if phi < scene.lock_spring_angle { -scene.lock_spring_torque } else { 0.0 };
    gravity + damper + spring
}

/// The envelope of loads and speeds the table and boundary fidelities are built over (outside it
/// they answer with the complete solve, so the envelope sets the cost, not the answer): per-pin
/// loads from a fifth to twice the leg's static share (at least 10 N to 100 N), speeds from
/// 1e-3 rad/s to a bound on |ω| (at least 0.1 rad/s): the smaller of the energy bound
/// ([`FreeFallParams::speed_bound`]) and the damper's terminal speed under the largest drive, c1 ω + c2 ω² = m g l + T_l (faster,
/// the damper alone outweighs every driving torque).
pub fn envelope(scene: &FreeFallParams) -> Envelope {
    let weight = scene.trunnion_load_share * scene.leg_mass * scene.gravity;
    let load_min = (0.2 * weight).max(10.0);
    let load_max = (2.0 * weight).max(10.0 * load_min);
    let mgl = scene.leg_mass * scene.gravity * scene.cg_distance;
    let energy = scene.speed_bound();
    let (c1, c2, drive) = (scene.damper_linear, scene.damper_quadratic, mgl + scene.lock_spring_torque);
    let terminal = if c2 > 0.0 {
        // The positive root of c2 ω² + c1 ω − drive = 0, written without cancellation.
        2.0 * drive / (c1 + (c1 * c1 + 4.0 * c2 * drive).sqrt())
    } else if c1 > 0.0 {
        drive / c1
    } else {
        f64::INFINITY
    };
    Envelope { load_min, load_max, speed_min: 1e-3, speed_max: energy.min(terminal).max(0.1) }
}

/// The joint of `params` at `temperature` (K): the parameters' own errors as
/// [`SceneError::Params`], the model's refusal of the temperature as [`SceneError::Temperature`].
pub fn joint_at(params: &Params, temperature: f64) -> Result<Joint, SceneError> {
    if !(temperature.is_finite() && temperature > 0.0) {
        return Err(SceneError::Invalid { name: "temperature", value: temperature, unit: "K", rule: "it must be a finite number > 0 K".into() });
    }
    let mut p = *params;
    p.lubricant.temperature = p.lubricant.reference_temperature;
    p.validate()?;
    p.lubricant.temperature = temperature;
    Joint::new(&p).map_err(|source| SceneError::Temperature { temperature, source })
}

/// The breakaway torque of one pin of `joint` at `load` (N): the sliding torque as ω → 0⁺, the
/// larger of the model's answer at rest (ω = 0) and at [`BREAKAWAY_SPEED`], so a model that
/// adds a yield torque at either counts it.
pub fn breakaway_torque(joint: &Joint, load: f64) -> Result<f64, SceneError> {
    let at = |w: f64| joint.evaluate(load, w).map(|op| op.torque).map_err(|source| SceneError::Breakaway { load, source });
    Ok(at(0.0)?.max(at(BREAKAWAY_SPEED)?))
}

/// The static margin `drive / resistance − 1`; without resistance +∞ (or 0 without drive either).
fn margin(drive: f64, resistance: f64) -> f64 {
    if resistance > 0.0 {
        drive / resistance - 1.0
    } else if drive > 0.0 {
        f64::INFINITY
    } else {
        0.0
    }
}

/// Run the scene with the joints at `temperature` (K) (the scene's own `temperature` is not
/// used: see [`FreeFallParams::run`]). The joint's parameters are `params` at that temperature.
///
/// Errors: an invalid scene ([`SceneError::Invalid`]), invalid joint parameters, a temperature
/// the joint model refuses ([`SceneError::Temperature`]: nothing is run), an operating point the
/// model has no answer at ([`SceneError::Joint`], with the time and state). The work is bounded
/// by [`super::params::MAX_STEPS`] steps.
pub fn simulate(scene: &FreeFallParams, params: &Params, temperature: f64) -> Result<FreeFallOutcome, SceneError> {
    scene.validate()?;
    let joint = joint_at(params, temperature)?;
    let breakaway = breakaway_torque(&joint, scene.lock_link_load)?;
    let lock_margin = margin(scene.lock_link_torque, f64::from(scene.lock_link_pivots) * breakaway);
    let mut trunnion = Trunnion::new(joint, scene.trunnion_joints, scene.fidelity, scene.tolerance, envelope(scene), scene.up_angle, scene.inertia, scene.step).map_err(SceneError::Fidelity)?;

    let h = scene.step;
    let steps = scene.steps();
    let mut series = Vec::with_capacity(steps + 1);
    let (mut phi, mut omega, mut alpha) = (scene.up_angle, 0.0_f64, 0.0_f64);
    let mut friction_energy = 0.0;
    let mut lock = None;
    for n in 0..steps {
        let t = n as f64 * h;
        let load = pin_load(scene, phi, omega, alpha);
        let friction = trunnion.step(phi, omega, load).map_err(|e| SceneError::at_point(e, t, phi, omega, load))?;
        alpha = (applied_torque(scene, phi, omega) + friction) / scene.inertia;
        let omega_next = omega + h * alpha;
        let phi_next = phi + h * omega_next;
        if !(phi_next.is_finite() && omega_next.is_finite()) {
            return Err(SceneError::NotFinite { time: t, angle: phi, omega, load, friction });
        }
        series.push(Sample { time: t, angle: phi, angular_velocity: omega, load, friction_torque: friction });
        if phi_next <= 0.0 {
            // Inside the step the angle is linear in time (ω_{n+1} over the step).
            let fraction = if phi > 0.0 { phi / (phi - phi_next) } else { 0.0 };
            friction_energy += friction * phi;
            let time = t + fraction * h;
            series.push(Sample { time, angle: 0.0, angular_velocity: omega_next, load, friction_torque: friction });
            lock = Some((time, omega_next.abs()));
            break;
        }
        friction_energy -= friction * (phi_next - phi);
        phi = phi_next;
        omega = omega_next;
        if n + 1 == steps {
            series.push(Sample { time: steps as f64 * h, angle: phi, angular_velocity: omega, load, friction_torque: friction });
        }
    }
    Ok(FreeFallOutcome {
        temperature,
        series,
        locked: lock.is_some(),
        time_to_lock: lock.map_or(f64::INFINITY, |l| l.0),
        speed_at_lock: lock.map(|l| l.1),
        lock_margin,
        breakaway_torque: breakaway,
        friction_energy,
        level: trunnion.level(),
    })
}

impl FreeFallParams {
    /// [`simulate`] at the scene's own `temperature`.
    pub fn run(&self, params: &Params) -> Result<FreeFallOutcome, SceneError> {
        simulate(self, params, self.temperature)
    }
}
