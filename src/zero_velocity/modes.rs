//! The presliding law under Model Exchange: stick and slip modes, so that no fixed-step
//! explicit integrator meets the law's stiffness.
//!
//! The Model Exchange equation of the state is dτ/dt = k·ω·g ([`Presliding::rate`]). Beyond the
//! elastic limit g = (T − u)/((1 − β)·T), so the state relaxes towards the bound with the
//! eigenvalue −|ω|/((1 − β)·φ_s): at 1 rad/s and the defaults −13 000 s⁻¹. An explicit
//! integrator steps past its stability limit there (Euler: |ω|·h > 2·(1 − β)·φ_s, 0.15 mrad at
//! 1 ms), and the state oscillates with growing amplitude until it overflows. Three changes
//! keep it bounded and non-stiff for any integrator, and exact in sliding:
//!
//! 1. **Monotone stick rate.** In stick the rate is k·ω·clamp(g, 0, 1): the state moves only
//!    in the direction of ω and by at most the elastic k·|ω| per unit time, so any explicit
//!    stage (Euler, each Runge–Kutta stage) takes it at most one elastic increment past the
//!    bound, never back through it. A state beyond the bound (the load fell, or the step
//!    overshot) stays there; the output is clamped at the bound.
//! 2. **Slip mode.** When the state reaches the bound along the motion, s·τ ≥ (1 − ε)·T with
//!    s = sign(ω) and ε = [`SLIP_FRACTION`]·(1 − β), the joint slides: the mode becomes slip s,
//!    the state is not integrated (rate 0) and the torque is that of the state s·T, which is
//!    the model's −s·T(P, |ω|) bit for bit while s·ω > 0 (and the elastic response from the
//!    bound, with its damping, against it).
//! 3. **Events.** The mode changes, and the state is projected onto the bound, only in the
//!    host's event mode ([`update`]). The model asks for an event at the end of an integrator
//!    step ([`event_due`], `fmi2CompletedIntegratorStep`'s `enterEventMode`: a step event)
//!    when a stick state reached or passed the bound, or a slip's ω stopped or reversed. At
//!    the reversal the state restarts in stick at s·T, unloading elastically.
//!
//! A host that does not honour step events stays in stick: bounded (1.), and exact in steady
//! sliding (the output is clamped at the bound), with one difference from the Co-Simulation
//! law: a state left beyond the bound (a load drop, a fast step) is not projected back, so
//! a reversal unloads from it (the output stays at the bound until the excess is unloaded).
//!
//! The stick equations are Lipschitz in τ (the kinks at β·T and T are not jumps), so BDF and
//! CVode take them as before; between events the right-hand side is continuous.

use super::jet::Scalar;
use super::presliding::Presliding;

/// ε/(1 − β): the slip mode starts when g = (T − u)/((1 − β)·T) falls to 0.01 (the state within
/// 1 % of the transition's span of the bound, 4.6 transition lengths (1 − β)·φ_s past the
/// elastic limit). At that point the stick torque with its damping is already the bound for
/// |ω| ≥ (1 − β)·φ_s/t_d (7.5e-3 rad/s with the defaults); below that the switch changes the
/// torque by at most 0.01·(1 − β)·T (0.05 % of T).
pub const SLIP_FRACTION: f64 = 0.01;

/// Whether the sliding torque `bound` is not > 0 (0, negative or NaN): an unloaded joint.
#[inline]
fn unloaded(bound: f64) -> bool {
    bound.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
}

/// The mode of the Model Exchange state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// The presliding state is integrated (elastic and elasto-plastic).
    #[default]
    Stick,
    /// Sliding in the direction of the sign (+1 or −1): the torque is the sliding torque.
    Slip(i8),
}

impl Mode {
    /// Its code (the FMU's `presliding_mode`): 0 stick, +1 slip in +ω, −1 slip in −ω.
    pub fn code(self) -> f64 {
        match self {
            Mode::Stick => 0.0,
            Mode::Slip(s) => f64::from(s.signum()),
        }
    }

    /// The mode of `code` (0, 1 or −1), if it is one.
    pub fn from_code(code: f64) -> Option<Self> {
        if code == 0.0 {
            Some(Mode::Stick)
        } else if code == 1.0 {
            Some(Mode::Slip(1))
        } else if code == -1.0 {
            Some(Mode::Slip(-1))
        } else {
            None
        }
    }

    /// The state the outputs use: τ in stick, s·T in slip.
    #[inline]
    fn held<S: Scalar>(self, tau: S, bound: S) -> S {
        match self {
            Mode::Stick => tau,
            Mode::Slip(s) => if s > 0 { bound } else { -bound },
        }
    }
}

/// dτ/dt (N·m/s): in stick k·ω·clamp(g, 0, 1) (g in the direction of ω; a state beyond the bound
/// behind the motion unloads elastically, g = 1); 0 in slip and when unloaded.
#[inline]
pub fn rate<S: Scalar>(law: &Presliding, mode: Mode, tau: S, omega: S, bound: S) -> S {
    if mode != Mode::Stick || unloaded(bound.re()) {
        return S::c(0.0);
    }
    // At rest g is taken in the unloading direction: the value is 0, ∂/∂ω the elastic k.
    let g = law.fraction(tau, law.direction(tau, omega), bound);
    let g = if g.re() < 0.0 { S::c(0.0) } else if g.re() > 1.0 { S::c(1.0) } else { g };
    law.stiffness(bound) * omega * g
}

/// The friction torque on the pin (N·m): [`Presliding::torque`] at the state of the mode.
#[inline]
pub fn torque<S: Scalar>(law: &Presliding, mode: Mode, tau: S, omega: S, bound: S) -> S {
    law.torque(mode.held(tau, bound), omega, bound)
}

/// The power dissipated (W): [`Presliding::dissipation`] at the state of the mode.
#[inline]
pub fn dissipation<S: Scalar>(law: &Presliding, mode: Mode, tau: S, omega: S, bound: S) -> S {
    law.dissipation(mode.held(tau, bound), omega, bound)
}

/// Whether the slip condition s·τ ≥ (1 − ε)·T holds, s = sign(ω) (0 at rest: no).
fn reaches_bound(law: &Presliding, tau: f64, omega: f64, bound: f64) -> bool {
    let s = if omega > 0.0 { 1.0 } else if omega < 0.0 { -1.0 } else { return false };
    s * tau >= (1.0 - SLIP_FRACTION * (1.0 - law.elastic_limit)) * bound
}

/// Whether an event is due at the end of an integrator step: in stick, the state beyond the
/// bound or reaching it along the motion; in slip s, s·ω ≤ 0 (stopped or reversed) or the joint
/// unloaded. A state [`update`] leaves is never due again at the same values.
pub fn event_due(law: &Presliding, mode: Mode, tau: f64, omega: f64, bound: f64) -> bool {
    let loaded = bound > 0.0;
    match mode {
        Mode::Stick => loaded && (tau.abs() > bound || reaches_bound(law, tau, omega, bound)),
        Mode::Slip(s) => !loaded || f64::from(s) * omega <= 0.0,
    }
}

/// The event update (the host's event mode): the state projected onto [−T, T]; slip s when it
/// reaches the bound along the motion (τ ← s·T), a slip that stopped or reversed back to stick
/// at s·T. Unloaded: stick at 0. Returns the new mode and state.
pub fn update(law: &Presliding, mode: Mode, tau: f64, omega: f64, bound: f64) -> (Mode, f64) {
    if unloaded(bound) {
        return (Mode::Stick, 0.0);
    }
    let tau = match mode {
        Mode::Stick => tau.clamp(-bound, bound),
        Mode::Slip(s) => f64::from(s) * bound,
    };
    if reaches_bound(law, tau, omega, bound) {
        let s: i8 = if omega > 0.0 { 1 } else { -1 };
        (Mode::Slip(s), f64::from(s) * bound)
    } else {
        (Mode::Stick, tau)
    }
}
