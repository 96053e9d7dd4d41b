//! The trunnion pins' friction: the joint model's sliding torque with the presliding state, the
//! one place the scene uses [`PreslidingJoint`] (so a change of its API touches this file only).
//!
//! Each pin turns with the leg (its angle is the leg's φ, its angular velocity ω) and carries the
//! same load P, so every pin gives the same friction torque: one presliding state stands for all
//! of them and the torque is multiplied by the number of pins. The sliding torque T(P, |ω|) is the
//! model's (eqs. 10–11) at the chosen fidelity; the presliding law (Dupont et al. 2002) with its
//! default settings turns it into the torque at rest and through a stop.

use crate::fidelity::{Envelope, Evaluator, Fidelity, FidelityError, Level};
use crate::joint::Joint;
use crate::zero_velocity::{Presliding, PreslidingJoint};

/// The friction of the trunnion pins of one leg.
#[derive(Debug, Clone)]
pub struct Trunnion {
    /// The sliding torque of one pin at the chosen fidelity (None: no pins, no friction).
    evaluator: Option<Evaluator>,
    /// The presliding state of one pin.
    state: PreslidingJoint,
    /// Number of pins.
    pins: f64,
    /// The host's step h (s), committed with every step (issue 29's host conventions).
    step: f64,
}

impl Trunnion {
    /// `pins` pins of `joint` at rest at `angle` (rad), the sliding torque at `fidelity` (held to
    /// `tolerance` over `envelope`, outside it the complete solve). With no pins nothing is built
    /// and the torque is 0.
    /// The presliding law is the default one with the host's inertia `inertia` (kg·m², the
    /// leg's J shared by the pins: each pin carries J / pins) and every step is committed as a
    /// host step of `step` s (docs/zero-velocity.md, host inertia).
    #[allow(clippy::too_many_arguments)]
    pub fn new(joint: Joint, pins: u32, fidelity: Fidelity, tolerance: f64, envelope: Envelope, angle: f64, inertia: f64, step: f64) -> Result<Self, FidelityError> {
        let per_pin = if pins == 0 { 0.0 } else { inertia / f64::from(pins) };
        // The scene's inertia is validated (1000–2000 kg·m² class; finite and > 0), so the law's
        // check (0 to 1e9 kg·m²) passes; the default law is kept should it not.
        let law = Presliding::default().with_host_inertia(per_pin).unwrap_or_default();
        let state = PreslidingJoint::new(law, angle);
        let evaluator = if pins == 0 { None } else { Some(Evaluator::with_joint(joint, fidelity, tolerance, envelope)?) };
        Ok(Trunnion { evaluator, state, pins: f64::from(pins), step })
    }

    /// The level the sliding torque runs at (None without pins).
    pub fn level(&self) -> Option<Level> {
        self.evaluator.as_ref().map(Evaluator::chosen)
    }

    /// The friction torque of all pins on the leg (N·m, opposing the motion) at the angle `angle`
    /// (rad), angular velocity `omega` (rad/s) and load per pin `load` (N), read before the step;
    /// then the step is committed (the state advances to `angle`).
    pub fn step(&mut self, angle: f64, omega: f64, load: f64) -> Result<f64, FidelityError> {
        let Some(ev) = self.evaluator.as_mut() else { return Ok(0.0) };
        // An unloaded pin (P = 0) holds nothing and slides without friction.
        let bound = if load == 0.0 { 0.0 } else { ev.evaluate(load, omega)?.torque };
        // `torque_at` then `commit_step`, the held torque computed once.
        let torque = self.state.step(angle, omega, bound, Some(self.step));
        // + 0.0: no −0 at rest.
        Ok(self.pins * torque + 0.0)
    }
}
