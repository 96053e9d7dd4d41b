//! The presliding joint as a stateful object: the law of [`super::presliding`] with its state,
//! stepped the way the FMU steps it. The FMU (Co-Simulation and Model Exchange) and the
//! Python package hold one of these, so every front end applies the same law to the same
//! numbers.
//!
//! The state is the presliding torque τ committed at a reference angle θ_ref. Between
//! commits the torque at an angle θ is the law's exact update over the increment θ − θ_ref
//! ([`PreslidingJoint::torque_at`]); [`PreslidingJoint::commit`] makes it the new state.
//! A host that does not track the angle drives the state with ω·h instead
//! ([`PreslidingJoint::advance`]). Under Model Exchange the host's integrator owns τ and
//! integrates [`super::modes::rate`].
//!
//! The host's conventions, in one place for every front end:
//! - **Angles modulo 2π.** The increment θ − θ_ref is the 2π-equivalent closest to ω·h, ω the
//!   angular velocity and h the step of the last commit ([`super::wrap::increment`]); a host
//!   that wraps its angle into (−π, π] gets the same torque as one that does not.
//! - **The first angle.** A joint made by [`PreslidingJoint::unreferenced`] takes the first
//!   angle it sees as its reference: no deflection at the first step.
//! - **The host's step** of the last commit also caps the host-inertia damping
//!   ([`Presliding::damping`]).

use super::jet::{Jet, Scalar};
use super::presliding::Presliding;

/// The sliding torque T and its partials with respect to the angular velocity and the load,
/// as the law's bound: a [`Jet`] over (angle, angular velocity, load), ∂T/∂angle = 0.
pub fn bound_jet(torque: f64, dtorque_domega: f64, dtorque_dload: f64) -> Jet {
    Jet::with(torque, [0.0, dtorque_domega, dtorque_dload])
}

/// Central differences of the sliding torque `bound(load, omega)` (N·m) with respect to ω
/// and P, for the directional derivatives: steps 1e-6 of |ω| (at least 1e-9 rad/s) and of |P|
/// (at least 1e-3 N). T depends on |ω| and |P|, so at ω = 0 or P = 0 the symmetric difference
/// gives 0. Returns (T, ∂T/∂ω, ∂T/∂P).
pub fn bound_partials<E>(mut bound: impl FnMut(f64, f64) -> Result<f64, E>, load: f64, omega: f64) -> Result<(f64, f64, f64), E> {
    let t = bound(load, omega)?;
    let hw = (1e-6 * omega.abs()).max(1e-9);
    let hp = (1e-6 * load.abs()).max(1e-3);
    let dw = (bound(load, omega + hw)? - bound(load, omega - hw)?) / (2.0 * hw);
    let dp = (bound(load + hp, omega)? - bound(load - hp, omega)?) / (2.0 * hp);
    Ok((t, dw, dp))
}

/// The presliding state of one joint and its law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreslidingJoint {
    /// The law; its `step` is the host's step of the last commit (0 before one).
    law: Presliding,
    /// τ, the presliding torque at the reference angle (N·m).
    torque: f64,
    /// θ_ref (rad).
    angle: f64,
    /// ω at the last commit (rad/s): ω·h is the increment the next angle is read against.
    omega: f64,
    /// No reference yet: the first angle seen becomes it.
    unreferenced: bool,
}

impl PreslidingJoint {
    /// At rest at `angle` (rad), nothing held.
    pub fn new(law: Presliding, angle: f64) -> Self {
        PreslidingJoint { law, torque: 0.0, angle, omega: 0.0, unreferenced: false }
    }

    /// At rest, nothing held, with no reference angle yet: the first angle given to
    /// [`PreslidingJoint::torque_at`], [`PreslidingJoint::held_at`] or a commit is the reference
    /// (no deflection there).
    pub fn unreferenced(law: Presliding) -> Self {
        PreslidingJoint { unreferenced: true, ..PreslidingJoint::new(law, 0.0) }
    }

    /// With a committed presliding torque `torque` (N·m) at the reference angle `angle` (rad).
    pub fn at_state(law: Presliding, torque: f64, angle: f64) -> Self {
        PreslidingJoint { law, torque, angle, omega: 0.0, unreferenced: false }
    }

    /// The joint from its parts, as [`PreslidingJoint::parts`] gives them: the law (its host
    /// inertia, its `step` the host's step of the last commit), τ (N·m), θ_ref (rad), ω at the
    /// last commit (rad/s) and whether it waits for its first angle. For a store that keeps
    /// many joints compactly (`pinjoint::batch`): parts taken from a joint give it back
    /// exactly.
    #[cfg(feature = "batch")]
    #[inline]
    pub(crate) fn from_parts(law: Presliding, torque: f64, angle: f64, omega: f64, unreferenced: bool) -> Self {
        PreslidingJoint { law, torque, angle, omega, unreferenced }
    }

    /// The joint's parts (see [`PreslidingJoint::from_parts`]).
    #[cfg(feature = "batch")]
    #[inline]
    pub(crate) fn parts(&self) -> (Presliding, f64, f64, f64, bool) {
        (self.law, self.torque, self.angle, self.omega, self.unreferenced)
    }

    /// The law (its `step` the host's step of the last commit).
    #[inline]
    pub fn law(&self) -> &Presliding {
        &self.law
    }

    /// Whether the joint still waits for its first angle ([`PreslidingJoint::unreferenced`]).
    pub fn is_unreferenced(&self) -> bool {
        self.unreferenced
    }

    /// The host's step of the last commit (s; 0 before one) and ω there (rad/s).
    pub fn last_step(&self) -> (f64, f64) {
        (self.law.step, self.omega)
    }

    /// Restore the step bookkeeping ([`PreslidingJoint::last_step`]) and whether the joint
    /// waits for its first angle (e.g. from a stored state).
    #[inline(always)]
    pub fn set_last_step(&mut self, step: f64, omega: f64, unreferenced: bool) {
        self.law = self.law.at_step(step);
        self.omega = if omega.is_finite() { omega } else { 0.0 };
        self.unreferenced = unreferenced;
    }

    /// The increment from the reference to `angle` (rad): modulo 2π, the equivalent closest to
    /// ω·h of the last commit ([`super::wrap::increment`]); 0 while unreferenced.
    #[inline(always)]
    pub fn increment(&self, angle: f64) -> f64 {
        if self.unreferenced {
            return 0.0;
        }
        super::wrap::increment(angle - self.angle, self.omega * self.law.step)
    }

    /// The committed presliding torque τ (N·m).
    pub fn presliding_torque(&self) -> f64 {
        self.torque
    }

    /// The reference angle θ_ref (rad) at which τ was committed.
    pub fn reference_angle(&self) -> f64 {
        self.angle
    }

    /// Replace the state (e.g. from a stored FMU state, or a Model Exchange host's τ); the
    /// joint has a reference from then on.
    #[inline(always)]
    pub fn set_state(&mut self, torque: f64, angle: f64) {
        self.torque = torque;
        self.angle = angle;
        self.unreferenced = false;
    }

    /// The presliding torque τ at `angle` (rad) with the sliding torque `bound` (N·m): the
    /// exact update over the increment θ − θ_ref ([`PreslidingJoint::increment`]).
    #[inline(always)]
    pub fn held_at(&self, angle: f64, bound: f64) -> f64 {
        self.law.deflect(self.torque, self.increment(angle), bound)
    }

    /// The friction torque on the pin (N·m) at `angle` (rad) and `omega` (rad/s) with the
    /// sliding torque `bound` = T(P, |ω|) (N·m), without changing the state.
    #[inline(always)]
    pub fn torque_at(&self, angle: f64, omega: f64, bound: f64) -> f64 {
        self.law.torque(self.held_at(angle, bound), omega, bound)
    }

    /// Commit the state at `angle`: τ ← τ at `angle`, θ_ref ← `angle`.
    #[inline(always)]
    pub fn commit(&mut self, angle: f64, bound: f64) {
        self.torque = self.held_at(angle, bound);
        self.angle = angle;
        self.unreferenced = false;
    }

    /// Commit at `angle` as a host step of `step` s at `omega` rad/s: as
    /// [`PreslidingJoint::commit`], and ω·h becomes the increment the next angle is read
    /// against (`step` 0 or not a finite number > 0: not known, the nearest equivalent to 0).
    #[inline(always)]
    pub fn commit_step(&mut self, angle: f64, omega: f64, bound: f64, step: f64) {
        self.commit(angle, bound);
        self.set_last_step(step, omega, false);
    }

    /// [`PreslidingJoint::torque_at`] then [`PreslidingJoint::commit`] (`step` None) or
    /// [`PreslidingJoint::commit_step`] (the host's step `step`, s) at one angle and bound,
    /// the held torque computed once: the friction torque at (`angle`, `omega`) with the
    /// sliding torque `bound`, the state committed there. Bit for bit the two calls.
    #[inline(always)]
    pub fn step(&mut self, angle: f64, omega: f64, bound: f64, step: Option<f64>) -> f64 {
        // `torque_at` is `law.torque(held_at(..), ..)`; a commit stores `held_at(..)` at the
        // angle (what `set_state` does), `commit_step` then `set_last_step`.
        let held = self.held_at(angle, bound);
        let torque = self.law.torque(held, omega, bound);
        self.set_state(held, angle);
        if let Some(h) = step {
            self.set_last_step(h, omega, false);
        }
        torque
    }

    /// Drive the state by ω·h (for a host that does not set the angle): τ ← the update over
    /// `omega`·`step`; θ_ref unchanged.
    pub fn advance(&mut self, omega: f64, step: f64, bound: f64) {
        self.torque = self.law.deflect(self.torque, omega * step, bound);
    }

    /// The friction torque at (`angle`, `omega`) and its partial derivatives with respect to
    /// (angle, angular velocity, load), `bound` carrying T and its partials ([`bound_jet`]).
    /// The angle partial is the tangent stiffness in the direction of motion
    /// ([`tangent_held`]).
    pub fn torque_partials(&self, angle: f64, omega: f64, bound: Jet) -> Jet {
        let tau = tangent_held(&self.law, self.torque, self.increment(angle), omega, bound);
        self.law.torque(tau, Jet::var(omega, 1), bound)
    }
}

/// The presliding torque held after the increment `delta` from the committed `tau`, as a jet
/// over (angle, angular velocity, load). Its ω and P partials are exact (through the bound);
/// its angle partial is the law's tangent dτ/dΔ = k·g at the held torque in the direction of
/// motion: that of `omega`, else of `delta`, else (at rest, nothing moving) the unloading
/// direction (from a state beyond a bound that fell, the bound: the output is clamped there). This
/// is the derivative a linearly implicit host needs for its next increment,
/// which moves the way ω does: the law is one-sided (a sliding joint is stiff against a
/// reversal, not along its motion), and for an increment in the direction of ω it is the exact
/// partial derivative of the held torque.
pub fn tangent_held(law: &Presliding, tau: f64, delta: f64, omega: f64, bound: Jet) -> Jet {
    let mut held = law.deflect(Jet::c(tau), Jet::c(delta), bound);
    let dir = if omega != 0.0 {
        omega
    } else if delta != 0.0 {
        delta
    } else if held.v > 0.0 {
        -1.0
    } else {
        1.0
    };
    if held.v.abs() > bound.v && dir * held.v < 0.0 {
        // Beyond the bound (it fell with a change of ω or P since the state was committed):
        // the output is the bound itself, and against it the joint unloads elastically.
        let s = held.v.signum();
        held = Jet::with(s * bound.v, [0.0, s * bound.d[1], s * bound.d[2]]);
    }
    held.d[0] = (law.stiffness(Jet::c(bound.v)) * law.fraction(Jet::c(held.v), dir, Jet::c(bound.v))).v.max(0.0);
    held
}

/// Model Exchange: the friction torque and dτ/dt at the state `tau` (N·m), with their partial
/// derivatives with respect to (τ, angular velocity, load); `bound` is T with its partials
/// in the last two slots (its first, ∂T/∂τ, is 0).
pub fn state_partials(law: &Presliding, tau: f64, omega: f64, bound: Jet) -> (Jet, Jet) {
    let x = Jet::var(tau, 0);
    let w = Jet::var(omega, 1);
    (law.torque(x, w, bound), law.rate(x, w, bound))
}
