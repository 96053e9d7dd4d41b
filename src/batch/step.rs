//! The parallel passes of a call: the sliding torque of every joint (cached per joint, so
//! `torque` then `commit` at the same inputs solves once), then the presliding law of each.
//! Rayon chunks over the joints; nothing is allocated per call.

use super::cache::Models;
use super::error::BatchError;
use super::inputs::{finite, Inputs};
use crate::zero_velocity::PreslidingJoint;
use rayon::prelude::*;

/// Joints handed to one rayon task; below two chunks the work stays on the calling thread.
pub const CHUNK: usize = 512;

/// One joint: its presliding state and the last sliding torque computed for it.
#[derive(Debug, Clone, Copy)]
pub struct JointState {
    /// The scalar law's state.
    pub state: PreslidingJoint,
    /// Bits of the (load, angular velocity, temperature) of `bound`; load NaN: none yet.
    key: [u64; 3],
    /// The sliding torque at `key` (N·m).
    pub bound: f64,
}

impl JointState {
    /// At `state`, no sliding torque computed yet.
    pub fn new(state: PreslidingJoint) -> Self {
        JointState { state, key: [f64::NAN.to_bits(), 0, 0], bound: f64::NAN }
    }
}

/// What the second pass does with each joint's sliding torque.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// The friction torque at the inputs into the output; the state unchanged.
    Torque,
    /// Commit the state at the input angle.
    Commit,
    /// Both: the torque at the inputs, then commit.
    Step,
    /// The sliding torque itself into the output (no angle used).
    Bound,
}

/// A host step (s) that is a finite number ≥ 0, else [`BatchError::Step`] naming the joint.
#[inline]
pub fn check_step(index: usize, value: f64) -> Result<f64, BatchError> {
    if value.is_finite() && value >= 0.0 { Ok(value) } else { Err(BatchError::Step { index, value }) }
}

/// Joint `i`'s first bad input, checked in the order load, angular velocity, angle (when
/// `angle`), host step: the error of a joint whose inputs are not all finite (or whose step
/// is negative).
#[cold]
fn input_error(inp: &Inputs, steps: Option<&[f64]>, i: usize, angle: bool) -> BatchError {
    let check = || -> Result<(), BatchError> {
        finite("load", i, inp.load[i], "N")?;
        finite("angular_velocity", i, inp.angular_velocity[i], "rad/s")?;
        if angle {
            finite("angle", i, inp.angle[i], "rad")?;
        }
        if let Some(h) = steps {
            check_step(i, h[i])?;
        }
        Ok(())
    };
    check().expect_err("called for a joint with a bad input")
}

/// The first failing joint of a chunk starting at `offset`, if any.
fn bounds_chunk(joints: &mut [JointState], slots: &[u32], models: &Models, inp: &Inputs, steps: Option<&[f64]>, offset: usize, angle: bool) -> Option<(usize, BatchError)> {
    let end = offset + joints.len();
    let (loads, omegas) = (&inp.load[offset..end], &inp.angular_velocity[offset..end]);
    // The model of the previous joint's slot (most joints share one): looked up once a run.
    let mut current = (u32::MAX, None, 0);
    for (k, ((j, &slot), (&load, &omega))) in joints.iter_mut().zip(slots).zip(loads.iter().zip(omegas)).enumerate() {
        let i = offset + k;
        let good = load.is_finite() && omega.is_finite() && (!angle || inp.angle[i].is_finite()) && steps.is_none_or(|h| h[i].is_finite() && h[i] >= 0.0);
        if !good {
            return Some((i, input_error(inp, steps, i, angle)));
        }
        if slot != current.0 {
            current = (slot, Some(models.get(slot)), models.key(slot).1);
        }
        let key = [load.to_bits(), omega.to_bits(), current.2];
        if key != j.key {
            let model = current.1.expect("set above");
            match model.sliding_torque(load, omega) {
                Ok(t) => {
                    j.bound = t;
                    j.key = key;
                }
                Err(source) => return Some((i, BatchError::Model { index: i, source })),
            }
        }
    }
    None
}

/// Commit joint `i` at its input angle: `PreslidingJoint::commit`, or with the host's step
/// `PreslidingJoint::commit_step` (ω·h the next increment is read against, the damping cap).
#[inline]
fn commit(j: &mut JointState, inp: &Inputs, steps: Option<&[f64]>, i: usize) {
    match steps {
        Some(h) => j.state.commit_step(inp.angle[i], inp.angular_velocity[i], j.bound, h[i]),
        None => j.state.commit(inp.angle[i], j.bound),
    }
}

/// The law on a chunk (every bound computed).
fn law_chunk(joints: &mut [JointState], out: &mut [f64], inp: &Inputs, steps: Option<&[f64]>, offset: usize, action: Action) {
    for (k, j) in joints.iter_mut().enumerate() {
        let i = offset + k;
        match action {
            Action::Torque => out[k] = j.state.torque_at(inp.angle[i], inp.angular_velocity[i], j.bound),
            Action::Commit => commit(j, inp, steps, i),
            Action::Step => {
                // `torque_at` then `commit` (or `commit_step`) at one angle and bound, the held
                // torque computed once: `torque_at` is `law.torque(held_at(..), ..)`, and a
                // commit stores `held_at(..)` at the angle (`set_state`), plus the host's step
                // (`set_last_step`) for `commit_step`.
                let (angle, omega) = (inp.angle[i], inp.angular_velocity[i]);
                let held = j.state.held_at(angle, j.bound);
                out[k] = j.state.law().torque(held, omega, j.bound);
                j.state.set_state(held, angle);
                if let Some(h) = steps {
                    j.state.set_last_step(h[i], omega, false);
                }
            }
            Action::Bound => out[k] = j.bound,
        }
    }
}

/// Every joint's sliding torque at `inp` (the inputs' lengths and the slots already set),
/// then `action`; a commit with `steps` (one host step per joint, s, length checked) commits
/// each joint as `PreslidingJoint::commit_step`. On an error (the lowest joint index's) no
/// state has changed. `out` has one value per joint (unused by [`Action::Commit`]: it may be
/// empty then).
pub fn run(joints: &mut [JointState], slots: &[u32], models: &Models, inp: &Inputs, steps: Option<&[f64]>, action: Action, out: &mut [f64]) -> Result<(), BatchError> {
    let n = joints.len();
    let angle = action != Action::Bound;
    let err = if n < 2 * CHUNK {
        bounds_chunk(joints, slots, models, inp, steps, 0, angle)
    } else {
        joints
            .par_chunks_mut(CHUNK)
            .zip(slots.par_chunks(CHUNK))
            .enumerate()
            .filter_map(|(c, (j, s))| bounds_chunk(j, s, models, inp, steps, c * CHUNK, angle))
            .min_by_key(|(i, _)| *i)
    };
    if let Some((_, e)) = err {
        return Err(e);
    }
    let out_len = if action == Action::Commit { 0 } else { n };
    let out = &mut out[..out_len];
    if n < 2 * CHUNK {
        law_chunk(joints, out, inp, steps, 0, action);
    } else if action == Action::Commit {
        joints.par_chunks_mut(CHUNK).enumerate().for_each(|(c, j)| law_chunk(j, &mut [], inp, steps, c * CHUNK, action));
    } else {
        joints.par_chunks_mut(CHUNK).zip(out.par_chunks_mut(CHUNK)).enumerate().for_each(|(c, (j, o))| law_chunk(j, o, inp, steps, c * CHUNK, action));
    }
    Ok(())
}
