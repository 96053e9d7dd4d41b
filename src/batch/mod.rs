//! Many presliding joints stepped together: a scene at scale (issue 30).
//!
//! A [`PreslidingBatch`] holds n joints, each exactly the scalar object of
//! [`crate::zero_velocity::PreslidingJoint`] (the law of Dupont, Hayward, Armstrong and
//! Altpeter, IEEE TAC 47(5), 2002, bounded by the sliding torque of eq. 11), and steps them
//! all in one call over struct-of-arrays inputs ([`Inputs`]: angle, angular velocity, load,
//! temperature), in parallel over rayon's threads, without allocating per call once the
//! temperatures settle. Each joint's sliding torque comes from its parameter set at its
//! temperature at the batch's fidelity level ([`model::Model`]): shared by default, per joint
//! when asked. Joints at one (parameter set, temperature) share one model ([`cache`]), so a
//! table level is built once for them all.
//!
//! Bit for bit the scalar law, by construction: each joint's state is a `PreslidingJoint`
//! driven by the same calls (`torque_at`, `commit`, `commit_step`) with the sliding torque from the same
//! functions as the scalar front ends (the cold complete solve at full, as the Python
//! `Presliding` object and the PinJoint FMU's step; the level inside its envelope at the
//! other levels, as the vectorised `Joint.evaluate`). The answer of one joint depends on its
//! own inputs and state alone, whatever the thread count or chunking. `tests/batch.rs`
//! checks this against n scalar objects over random scenes at every level.
//!
//! The host's conventions are the scalar joint's (see [`crate::zero_velocity::joint`]): each
//! joint's law carries its host inertia ([`PreslidingBatch::set_host_inertia`],
//! `Presliding::with_host_inertia`); a commit with the host's step
//! ([`PreslidingBatch::commit_step`], [`PreslidingBatch::step_with`]) is the scalar
//! `commit_step`, so the next angle is read modulo 2π against ω·h and the host-inertia damping
//! is capped at h; a joint may wait for its first angle ([`PreslidingBatch::set_last_steps`],
//! as `PreslidingJoint::unreferenced`).
//!
//! ```
//! use pinjoint::batch::{BatchParams, Inputs, PreslidingBatch, Settings};
//! use pinjoint::zero_velocity::Presliding;
//! use pinjoint::Params;
//! let n = 3;
//! let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), Settings::default()).unwrap();
//! let (angle, omega, load) = ([1e-4, 0.0, 0.1], [0.0, 0.0, 0.2], [20e3, 20e3, 20e3]);
//! let inputs = Inputs { angle: &angle, angular_velocity: &omega, load: &load, temperature: None };
//! let mut torque = vec![0.0; n];
//! b.step(&inputs, &mut torque).unwrap(); // the torque at the inputs, then commit
//! assert!(torque[0] < 0.0 && torque[1] == 0.0 && torque[2] < 0.0);
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod inputs;
pub mod model;
pub mod cache;
pub mod joints;
pub mod step;

pub use error::BatchError;
pub use inputs::Inputs;
pub use model::{Model, Settings};

use crate::joint::Joint;
use crate::params::Params;
use crate::zero_velocity::Presliding;
use cache::Models;
use joints::Joints;
use step::{Action, Bounds};

/// The parameter sets of a batch.
// One value per batch, built once: the size of the shared set costs nothing worth a Box.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum BatchParams {
    /// One set for every joint (the default).
    Shared(Params),
    /// One set per joint, in joint order.
    PerJoint(Vec<Params>),
}

/// n presliding joints stepped together (see the [module documentation](self)).
#[derive(Debug, Clone)]
pub struct PreslidingBatch {
    /// Each joint's presliding state.
    joints: Joints,
    /// Each joint's last sliding torque and its inputs (apart from the states: the pass that
    /// computes them reads no state).
    bounds: Bounds,
    /// Each joint's model slot (u32::MAX before its first call).
    slots: Vec<u32>,
    models: Models,
    per_joint: bool,
    law: Presliding,
    /// Per joint, kg·m² (each joint's law carries it); None: not set (0, not given).
    host_inertia: Option<Vec<f64>>,
    /// Each joint's model key in this call (a buffer kept between calls).
    keys: Vec<cache::Key>,
    /// Every joint holds its parameter set's model at the set's own temperature (the last
    /// call gave no temperatures).
    own_temperatures: bool,
}

impl PreslidingBatch {
    /// `n` joints at rest at angle 0, nothing held, with the presliding `law`, the parameter
    /// sets `params` (validated: a per-joint error names the joint) and the fidelity
    /// `settings`. The models are built at the first call (at the temperatures it gives).
    pub fn new(n: usize, params: BatchParams, law: Presliding, settings: Settings) -> Result<Self, BatchError> {
        if n == 0 {
            return Err(BatchError::Empty);
        }
        if n >= cache::FULL_BIT as usize {
            return Err(BatchError::TooMany(n));
        }
        law.validate().map_err(BatchError::Law)?;
        settings.validate()?;
        if matches!(settings.fidelity, crate::fidelity::Fidelity::Table | crate::fidelity::Fidelity::Auto) && settings.tolerance < crate::fidelity::FULL_ERROR_BOUND {
            return Err(BatchError::Fidelity(crate::fidelity::FidelityError::ToleranceBelowModelAccuracy { value: settings.tolerance, floor: crate::fidelity::FULL_ERROR_BOUND }));
        }
        let (sets, per_joint) = match params {
            BatchParams::Shared(p) => (vec![p], false),
            BatchParams::PerJoint(v) if v.len() == n => (v, true),
            BatchParams::PerJoint(v) => return Err(BatchError::ParamCount { expected: n, got: v.len() }),
        };
        let bases = sets.iter().enumerate().map(|(index, p)| Joint::new(p).map_err(|source| BatchError::Params { index, source })).collect::<Result<Vec<_>, _>>()?;
        Ok(PreslidingBatch {
            joints: Joints::new(law, n),
            bounds: Bounds::new(n),
            slots: vec![u32::MAX; n],
            models: Models::new(bases, settings),
            per_joint,
            law,
            host_inertia: None,
            keys: Vec::with_capacity(n),
            own_temperatures: false,
        })
    }

    /// The number of joints.
    pub fn len(&self) -> usize {
        self.joints.len()
    }

    /// Never true (a batch has at least one joint); for clippy's `len` rule.
    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// The presliding law every joint follows.
    pub fn law(&self) -> &Presliding {
        &self.law
    }

    /// The fidelity settings.
    pub fn settings(&self) -> &Settings {
        self.models.settings()
    }

    /// Whether each joint has its own parameter set.
    pub fn per_joint(&self) -> bool {
        self.per_joint
    }

    /// The parameter set of joint `i`.
    pub fn params(&self, i: usize) -> &Params {
        self.models.bases()[if self.per_joint { i } else { 0 }].params()
    }

    /// The models held now: one per parameter set and temperature in use, and up to
    /// [`cache::RETAINED`] no joint uses any more (kept for reuse).
    pub fn models_held(&self) -> usize {
        self.models.held()
    }

    /// The models held now with a table: at most [`cache::LEVELS_MAX`] (at the table and auto
    /// levels, joints beyond that many parameter sets and temperatures at once are answered by
    /// the complete solve, [`cache`]).
    pub fn tables_held(&self) -> usize {
        self.models.tables_held()
    }

    /// The host inertia per joint (kg·m²), when set.
    pub fn host_inertia(&self) -> Option<&[f64]> {
        self.host_inertia.as_deref()
    }

    /// Set the host inertia per joint (kg·m² in [0, 1e9], 0 = not given; one value per
    /// joint), or clear it (None: 0 for every joint). Joint i's law becomes
    /// `law.with_host_inertia(inertia[i])`: the presliding damping 2ζ√(k·J), capped at the
    /// host's step of the last commit (`Presliding::damping`). The states, the last steps and
    /// the pending first angles are kept. On an error nothing has changed.
    pub fn set_host_inertia(&mut self, inertia: Option<&[f64]>) -> Result<(), BatchError> {
        let n = self.len();
        if let Some(v) = inertia {
            inputs::check_length("host_inertia", v, n)?;
        }
        let j = |i: usize| inertia.map_or(0.0, |v| v[i]);
        for index in 0..n {
            self.law.with_host_inertia(j(index)).map_err(|_| BatchError::HostInertia { index, value: j(index) })?;
        }
        self.joints.set_inertia(inertia.map(<[f64]>::to_vec), 0.0);
        self.host_inertia = inertia.map(<[f64]>::to_vec);
        Ok(())
    }

    /// Joint `i`'s law (its host inertia, and its `step` the host's step of the last commit).
    pub fn joint_law(&self, i: usize) -> Presliding {
        *self.joints.get(i).law()
    }

    /// Every joint's step bookkeeping into `step` (s, the host's step of the last commit; 0
    /// before one or when not given), `omega` (rad/s, ω at that commit) and `unreferenced`
    /// (whether the joint waits for its first angle), one value per joint each: with
    /// [`PreslidingBatch::states`] everything a joint holds.
    pub fn last_steps(&self, step: &mut [f64], omega: &mut [f64], unreferenced: &mut [bool]) -> Result<(), BatchError> {
        let n = self.len();
        inputs::check_length("step", step, n)?;
        inputs::check_length("angular_velocity", omega, n)?;
        if unreferenced.len() != n {
            return Err(BatchError::Shape { argument: "unreferenced", expected: n, got: unreferenced.len() });
        }
        for (i, ((h, w), u)) in step.iter_mut().zip(omega).zip(unreferenced).enumerate() {
            let j = self.joints.get(i);
            ((*h, *w), *u) = (j.last_step(), j.is_unreferenced());
        }
        Ok(())
    }

    /// Restore the step bookkeeping ([`PreslidingBatch::last_steps`]; after
    /// [`PreslidingBatch::set_states`], which marks every joint referenced): `step` finite
    /// ≥ 0 (s), `omega` finite (rad/s). `unreferenced` all true with the states at rest is a
    /// batch of `PreslidingJoint::unreferenced` joints: each takes the first angle it is given
    /// as its reference. On an error nothing has changed.
    pub fn set_last_steps(&mut self, step: &[f64], omega: &[f64], unreferenced: &[bool]) -> Result<(), BatchError> {
        let n = self.len();
        inputs::check_length("step", step, n)?;
        inputs::check_length("angular_velocity", omega, n)?;
        if unreferenced.len() != n {
            return Err(BatchError::Shape { argument: "unreferenced", expected: n, got: unreferenced.len() });
        }
        for (i, (&h, &w)) in step.iter().zip(omega).enumerate() {
            step::check_step(i, h)?;
            inputs::finite("angular_velocity", i, w, "rad/s")?;
        }
        for (i, ((&h, &w), &u)) in step.iter().zip(omega).zip(unreferenced).enumerate() {
            let mut j = self.joints.get(i);
            j.set_last_step(h, w, u);
            self.joints.set(i, &j);
        }
        Ok(())
    }

    /// Joint `i`'s state: (presliding torque τ in N·m, reference angle in rad).
    pub fn state(&self, i: usize) -> (f64, f64) {
        let s = self.joints.get(i);
        (s.presliding_torque(), s.reference_angle())
    }

    /// Every joint's state into `torque` (N·m) and `angle` (rad), one value per joint each.
    pub fn states(&self, torque: &mut [f64], angle: &mut [f64]) -> Result<(), BatchError> {
        inputs::check_length("torque", torque, self.len())?;
        inputs::check_length("angle", angle, self.len())?;
        for (i, (t, a)) in torque.iter_mut().zip(angle).enumerate() {
            (*t, *a) = self.state(i);
        }
        Ok(())
    }

    /// Replace every joint's state: presliding torque (N·m) and reference angle (rad), one
    /// finite value per joint each.
    pub fn set_states(&mut self, torque: &[f64], angle: &[f64]) -> Result<(), BatchError> {
        inputs::check_length("presliding_torque", torque, self.len())?;
        inputs::check_length("angle", angle, self.len())?;
        for (i, (&t, &a)) in torque.iter().zip(angle).enumerate() {
            inputs::finite("presliding_torque", i, t, "N.m")?;
            inputs::finite("angle", i, a, "rad")?;
        }
        for (i, (&t, &a)) in torque.iter().zip(angle).enumerate() {
            let mut j = self.joints.get(i);
            j.set_state(t, a);
            self.joints.set(i, &j);
        }
        Ok(())
    }

    /// Point every joint at the model of its parameter set at its temperature. Without
    /// temperatures after a call without them, every joint already holds its set's model at
    /// the set's own temperature: nothing to do (no pass over the joints).
    fn assign(&mut self, temperature: Option<&[f64]>) -> Result<(), BatchError> {
        if temperature.is_none() && self.own_temperatures {
            return Ok(());
        }
        let PreslidingBatch { models, slots, keys, per_joint, .. } = self;
        let n = slots.len();
        keys.resize(n, (0, 0));
        for (i, k) in keys.iter_mut().enumerate() {
            *k = models.key_of(if *per_joint { i as u32 } else { 0 }, temperature.map(|t| t[i]));
        }
        // The table for the first LEVELS_MAX keys of this call, the complete solve beyond.
        models.budget(keys);
        // In parallel for a batch stepped in parallel, or from a thread already in a rayon
        // pool; a small batch's call from any other thread stays on it (no pool is woken,
        // and none is used: a process forked from one that used a pool has none of its
        // threads).
        let parallel = step::parallel(n, models.settings().fidelity) || rayon::current_thread_index().is_some();
        models.assign(slots, |i| keys[i], parallel)?;
        self.own_temperatures = temperature.is_none();
        Ok(())
    }

    fn run(&mut self, inputs: &Inputs, steps: Option<&[f64]>, action: Action, out: &mut [f64]) -> Result<(), BatchError> {
        inputs.check(self.len())?;
        if let Some(h) = steps {
            inputs::check_length("step", h, self.len())?;
        }
        if action != Action::Commit {
            inputs::check_length("output", out, self.len())?;
        }
        self.assign(inputs.temperature)?;
        let PreslidingBatch { joints, bounds, slots, models, .. } = self;
        if !step::parallel(joints.len(), models.settings().fidelity) {
            // On the calling thread (no pool).
            return step::run(joints, bounds, slots, models, inputs, steps, action, out);
        }
        // Both passes on one of the pool's threads: a caller outside the pool (a Python
        // thread) hands the call over once, not once a pass (each hand-over wakes threads).
        rayon::scope(|_| step::run(joints, bounds, slots, models, inputs, steps, action, out))
    }

    /// The friction torque on each pin (N·m) at the inputs into `out`, the states unchanged:
    /// joint i's `PreslidingJoint::torque_at(angle, ω, T)` with T its sliding torque.
    /// On an error (the lowest joint index's) no state has changed.
    pub fn torque(&mut self, inputs: &Inputs, out: &mut [f64]) -> Result<(), BatchError> {
        self.run(inputs, None, Action::Torque, out)
    }

    /// Commit every joint's state at its input angle (the FMU's step when the host sets the
    /// angle), the host's step not given: each joint's `PreslidingJoint::commit` (its last
    /// step kept). On an error no state has changed.
    pub fn commit(&mut self, inputs: &Inputs) -> Result<(), BatchError> {
        self.run(inputs, None, Action::Commit, &mut [])
    }

    /// Commit every joint's state at its input angle as a host step of `step` (s, finite ≥ 0,
    /// one per joint; 0: not known): each joint's `PreslidingJoint::commit_step`, so its next
    /// angle is read modulo 2π against ω·h and its host-inertia damping is capped at h. On an
    /// error no state has changed.
    pub fn commit_step(&mut self, inputs: &Inputs, step: &[f64]) -> Result<(), BatchError> {
        self.run(inputs, Some(step), Action::Commit, &mut [])
    }

    /// [`PreslidingBatch::torque`] then [`PreslidingBatch::commit`] at the same inputs, the
    /// sliding torque solved once: the explicit host's step.
    pub fn step(&mut self, inputs: &Inputs, out: &mut [f64]) -> Result<(), BatchError> {
        self.run(inputs, None, Action::Step, out)
    }

    /// [`PreslidingBatch::torque`] then [`PreslidingBatch::commit_step`] with the host's
    /// `step` (s, one per joint) at the same inputs, the sliding torque solved once.
    pub fn step_with(&mut self, inputs: &Inputs, step: &[f64], out: &mut [f64]) -> Result<(), BatchError> {
        self.run(inputs, Some(step), Action::Step, out)
    }

    /// Each joint's sliding torque T(P, |ω|) (N·m, ≥ 0) at `load` (N), `angular_velocity`
    /// (rad/s) and `temperature` (K; None: each parameter set's) into `out`: at ω = 0 the
    /// breakaway torque. The states are unchanged.
    pub fn sliding_torque(&mut self, load: &[f64], angular_velocity: &[f64], temperature: Option<&[f64]>, out: &mut [f64]) -> Result<(), BatchError> {
        let inputs = Inputs { angle: load, angular_velocity, load, temperature };
        inputs::check_length("load", load, self.len())?;
        self.run(&inputs, None, Action::Bound, out)
    }
}
