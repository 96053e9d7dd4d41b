//! The batch's joints, kept compactly: the law's parameters once, and per joint what a
//! [`PreslidingJoint`] holds beyond them: τ, θ_ref, ω and the host's step of the last commit
//! (32 bytes), whether it waits for its first angle, and its host inertia when set per joint.
//! The scalar object is 72 bytes, most of it the law repeated; a step of 10⁴ joints streams
//! the states through the cache, so the pass over them reads less than half as much.
//!
//! A joint is rebuilt as the scalar [`PreslidingJoint`] to be stepped ([`joint`]) and its
//! parts stored back ([`store`]): the law is the scalar object's, bit for bit.

use crate::zero_velocity::{Presliding, PreslidingJoint};

/// One joint's state beyond the shared law.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C)]
pub struct State {
    /// τ, the presliding torque at the reference angle (N·m).
    pub torque: f64,
    /// θ_ref (rad).
    pub angle: f64,
    /// ω at the last commit (rad/s).
    pub omega: f64,
    /// The host's step of the last commit (s; 0: not known).
    pub step: f64,
}

/// Joint `s` of a batch whose law is `law` (its host inertia `inertia` when set per joint,
/// else the law's): the scalar object.
#[inline(always)]
pub fn joint(law: &Presliding, s: &State, unreferenced: bool, inertia: Option<f64>) -> PreslidingJoint {
    let law = Presliding { host_inertia: inertia.unwrap_or(law.host_inertia), step: s.step, ..*law };
    PreslidingJoint::from_parts(law, s.torque, s.angle, s.omega, unreferenced)
}

/// Store joint `j`'s state into `s` and `unreferenced` (its law's parameters are the batch's,
/// and its host inertia is kept apart: neither changes in a step).
#[inline(always)]
pub fn store(j: &PreslidingJoint, s: &mut State, unreferenced: &mut bool) {
    let (law, torque, angle, omega, unref) = j.parts();
    *s = State { torque, angle, omega, step: law.step };
    *unreferenced = unref;
}

/// n joints: the law once, the states per joint.
#[derive(Debug, Clone)]
pub struct Joints {
    /// The law of every joint; its `host_inertia` that of every joint unless set per joint
    /// (`inertia`); its `step` unused (per joint, in `states`).
    law: Presliding,
    /// Per joint.
    states: Vec<State>,
    /// Per joint: waits for its first angle.
    unreferenced: Vec<bool>,
    /// Per joint host inertia (kg·m²), when set.
    inertia: Option<Vec<f64>>,
}

impl Joints {
    /// `n` joints as `PreslidingJoint::new(law, 0.0)`.
    pub fn new(law: Presliding, n: usize) -> Self {
        let s = State { torque: 0.0, angle: 0.0, omega: 0.0, step: law.step };
        Joints { law, states: vec![s; n], unreferenced: vec![false; n], inertia: None }
    }

    /// The number of joints.
    pub fn len(&self) -> usize {
        self.states.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.states.is_empty()
    }

    /// Joint `i` as the scalar object.
    pub fn get(&self, i: usize) -> PreslidingJoint {
        joint(&self.law, &self.states[i], self.unreferenced[i], self.inertia.as_ref().map(|v| v[i]))
    }

    /// Replace joint `i`'s state by `j`'s (its law's host inertia and step included: `j`'s law
    /// otherwise is the batch's).
    pub fn set(&mut self, i: usize, j: &PreslidingJoint) {
        store(j, &mut self.states[i], &mut self.unreferenced[i]);
        let h = j.law().host_inertia;
        if let Some(v) = &mut self.inertia {
            v[i] = h;
        } else {
            debug_assert!(h.to_bits() == self.law.host_inertia.to_bits(), "a joint's host inertia is the batch's");
        }
    }

    /// Every joint's host inertia `inertia[i]` (kg·m², checked by the caller), or the law's
    /// own `shared` for every joint (None); the states unchanged.
    pub fn set_inertia(&mut self, inertia: Option<Vec<f64>>, shared: f64) {
        self.law.host_inertia = shared;
        self.inertia = inertia;
    }

    /// The law, the states, the waiting flags and the per-joint host inertia, for the passes
    /// over the joints.
    pub fn parts_mut(&mut self) -> (&Presliding, &mut [State], &mut [bool], Option<&[f64]>) {
        (&self.law, &mut self.states, &mut self.unreferenced, self.inertia.as_deref())
    }
}
