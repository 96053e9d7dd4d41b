//! The parallel passes of a call: the sliding torque of every joint (cached per joint, so
//! `torque` then `commit` at the same inputs solves once), then the presliding law of each.
//! Rayon chunks over the joints; nothing is allocated per call.

use super::cache::Models;
use super::error::BatchError;
use super::inputs::{finite, Inputs};
use super::model::Model;
use crate::fidelity::{Located, StribeckTable};
use super::joints::{self, Joints, State};
use crate::zero_velocity::{Presliding, PreslidingJoint};
use rayon::prelude::*;

/// Joints handed to one rayon task; below two chunks the work stays on the calling thread.
/// Each pass hands out single chunks (`with_max_len(1)`): rayon's adaptive split would
/// otherwise stop at a few long runs per thread, and a thread that starts late (woken for the
/// call) could not take over any of them, idling the others at the pass's end (measured
/// through Python, 10⁴ joints at table level on 2 cores: the per-call median 5–15 % lower in
/// three runs of four, equal in the fourth).
pub const CHUNK: usize = 512;

/// Whether a batch of `n` joints at `fidelity` is stepped in parallel, else on the calling
/// thread: at full from two chunks on; at the other levels (a table answers in ~40 ns a
/// joint) from eight, below which handing the call to the pool and joining its threads costs
/// more than the second core gives. Measured on 2 cores, a reversing scene at the table level
/// (examples of the bench's scenes): 2000 joints 42 ns a joint-step on the calling thread
/// against 56 ns in parallel, 4000 joints 45 against 43, 8000 joints 41 against 34; at full,
/// 2000 joints 917 against 520.
#[inline]
pub fn parallel(n: usize, fidelity: crate::fidelity::Fidelity) -> bool {
    n >= if fidelity == crate::fidelity::Fidelity::Full { 2 * CHUNK } else { 8 * CHUNK }
}

/// Each joint's last sliding torque and the inputs it was computed at, apart from the joints'
/// states (the first pass reads and writes these alone) and in two arrays (the second pass
/// reads the torques alone).
#[derive(Debug, Clone)]
pub struct Bounds {
    /// Per joint, the bits of the (load, angular velocity, temperature) of its `values` entry;
    /// load NaN: none yet.
    keys: Vec<[u64; 3]>,
    /// Per joint, the sliding torque at its key (N·m).
    values: Vec<f64>,
}

impl Bounds {
    /// No sliding torque computed yet, for `n` joints.
    pub fn new(n: usize) -> Self {
        Bounds { keys: vec![[0x7ff8_0000_0000_0000, 0, 0]; n], values: vec![f64::NAN; n] }
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

/// Whether a joint's inputs are all good: load, angular velocity and angle (when read)
/// finite, the host's step (when given) a finite number ≥ 0; [`input_error`] names the first
/// that is not.
#[inline(always)]
fn inputs_good(load: f64, omega: f64, angle: impl FnOnce() -> Option<f64>, step: impl FnOnce() -> Option<f64>) -> bool {
    load.is_finite() && omega.is_finite() && angle().is_none_or(f64::is_finite) && step().is_none_or(|h| h.is_finite() && h >= 0.0)
}

/// Joints located ahead of their answers in the bounds pass: the table cells of a block are
/// requested from memory together, then read (a table of thousands of cells does not fit a
/// core's cache, and each joint's point falls in its own cell).
pub const BLOCK: usize = 8;

/// The first failing joint of a chunk starting at `offset`, if any. In blocks of [`BLOCK`]
/// joints: the inputs are checked and each joint whose (load, ω, temperature) changed is
/// located in its model ([`Model::locate`]), then those are answered in order
/// ([`Model::sliding_torque_located`]); the error of the lowest joint index is the one
/// returned, as when each joint is checked then answered in turn.
#[allow(clippy::too_many_arguments)]
fn bounds_chunk(keys: &mut [[u64; 3]], values: &mut [f64], slots: &[u32], models: &Models, inp: &Inputs, steps: Option<&[f64]>, offset: usize, angle: bool) -> Option<(usize, BatchError)> {
    // One model for the whole chunk (the common case) at the table level: the table directly.
    // (All the slots equal to the first: a fold without an early exit, which vectorises.)
    if let Some(&slot) = slots.first()
        && slots.iter().fold(0, |differ, &s| differ | (s ^ slot)) == 0
    {
        let model = models.get(slot);
        if let Some(table) = model.torque_table() {
            return bounds_chunk_table(keys, values, model, table, models.key(slot).1, inp, steps, offset, angle);
        }
    }
    let end = offset + keys.len();
    let (loads, omegas) = (&inp.load[offset..end], &inp.angular_velocity[offset..end]);
    // The model of the previous joint's slot (most joints share one): looked up once a run.
    let mut current: (u32, Option<&Model>, u64) = (u32::MAX, None, 0);
    // The joints of a block to answer: index in the chunk, located point.
    let mut todo = [(0, Located::OUTSIDE); BLOCK];
    for first in (0..keys.len()).step_by(BLOCK) {
        let last = (first + BLOCK).min(keys.len());
        let (mut pending, mut bad) = (0, None);
        for k in first..last {
            let i = offset + k;
            let (load, omega) = (loads[k], omegas[k]);
            let good = inputs_good(load, omega, || angle.then(|| inp.angle[i]), || steps.map(|h| h[i]));
            if !good {
                bad = Some(i);
                break;
            }
            let slot = slots[k];
            if slot != current.0 {
                current = (slot, Some(models.get(slot)), models.key(slot).1);
            }
            // Compared word by word (an array built on the stack and compared whole is read back
            // wider than it was written: a stalled load).
            let old = &keys[k];
            if load.to_bits() != old[0] || omega.to_bits() != old[1] || current.2 != old[2] {
                todo[pending] = (k, current.1.expect("set above").locate(load, omega));
                pending += 1;
            }
        }
        for &(k, at) in &todo[..pending] {
            let (load, omega, slot) = (loads[k], omegas[k], slots[k]);
            if slot != current.0 {
                current = (slot, Some(models.get(slot)), models.key(slot).1);
            }
            match current.1.expect("set above").sliding_torque_located(load, omega, at) {
                Ok(value) => (keys[k], values[k]) = ([load.to_bits(), omega.to_bits(), current.2], value),
                Err(source) => return Some((offset + k, BatchError::Model { index: offset + k, source })),
            }
        }
        if let Some(i) = bad {
            return Some((i, input_error(inp, steps, i, angle)));
        }
    }
    None
}

/// [`bounds_chunk`] for a chunk whose joints all use `model`, at the table level
/// ([`Model::torque_table`]: `table`), key temperature bits `tkey`: the same answers and
/// errors, the table asked directly (the model's layers, which every joint would go through
/// in turn, only where the table gives no answer).
#[allow(clippy::too_many_arguments)]
fn bounds_chunk_table(keys: &mut [[u64; 3]], values: &mut [f64], model: &Model, table: &StribeckTable, tkey: u64, inp: &Inputs, steps: Option<&[f64]>, offset: usize, angle: bool) -> Option<(usize, BatchError)> {
    let end = offset + keys.len();
    let (loads, omegas, angles) = (&inp.load[offset..end], &inp.angular_velocity[offset..end], &inp.angle[offset..end]);
    let hs = steps.map(|h| &h[offset..end]);
    let mut todo = [(0, Located::OUTSIDE); BLOCK];
    for first in (0..keys.len()).step_by(BLOCK) {
        let last = (first + BLOCK).min(keys.len());
        let (mut pending, mut bad) = (0, None);
        for k in first..last {
            let (load, omega) = (loads[k], omegas[k]);
            let good = inputs_good(load, omega, || angle.then(|| angles[k]), || hs.map(|h| h[k]));
            if !good {
                bad = Some(offset + k);
                break;
            }
            let old = &keys[k];
            if load.to_bits() != old[0] || omega.to_bits() != old[1] || tkey != old[2] {
                todo[pending] = (k, table.locate_torque(load.abs(), omega));
                pending += 1;
            }
        }
        for &(k, at) in &todo[..pending] {
            let (load, omega) = (loads[k], omegas[k]);
            // The table's answer where the model would give it (Model::torque_table), else the
            // model's own (its errors included).
            let value = match table.torque_located(load.abs(), omega, at) {
                Some(t) => t,
                None => match model.sliding_torque(load, omega) {
                    Ok(t) => t,
                    Err(source) => return Some((offset + k, BatchError::Model { index: offset + k, source })),
                },
            };
            (keys[k], values[k]) = ([load.to_bits(), omega.to_bits(), tkey], value);
        }
        if let Some(i) = bad {
            return Some((i, input_error(inp, steps, i, angle)));
        }
    }
    None
}

/// The joints of a chunk: the law, their states and waiting flags, their host inertia when
/// set per joint.
struct Chunk<'a> {
    law: &'a Presliding,
    states: &'a mut [State],
    unreferenced: &'a mut [bool],
    inertia: Option<&'a [f64]>,
}

/// `f` on each joint of a chunk as the scalar object (its index in the chunk, the joint, its
/// bound), the joint stored back when `commits`. Generic over `f` and `inertia`, so that each
/// action's loop is compiled on its own (no choice made per joint).
#[inline(always)]
fn each(c: &mut Chunk, bounds: &[f64], commits: bool, inertia: impl Fn(usize) -> Option<f64>, mut f: impl FnMut(usize, &mut PreslidingJoint, f64)) {
    for (k, ((s, u), &bound)) in c.states.iter_mut().zip(c.unreferenced.iter_mut()).zip(bounds).enumerate() {
        let mut j = joints::joint(c.law, s, *u, inertia(k));
        f(k, &mut j, bound);
        if commits {
            joints::store(&j, s, u);
        }
    }
}

/// The law on a chunk (every bound computed).
fn law_chunk(c: Chunk, bounds: &[f64], out: &mut [f64], inp: &Inputs, steps: Option<&[f64]>, offset: usize, action: Action) {
    match c.inertia {
        None => law_with(c, bounds, out, inp, steps, offset, action, |_| None),
        Some(v) => law_with(c, bounds, out, inp, steps, offset, action, |k| Some(v[k])),
    }
}

/// [`law_chunk`] with the host inertia of the chunk's joint k given by `inertia`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn law_with(mut c: Chunk, bounds: &[f64], out: &mut [f64], inp: &Inputs, steps: Option<&[f64]>, offset: usize, action: Action, inertia: impl Fn(usize) -> Option<f64>) {
    let end = offset + bounds.len();
    let (angles, omegas) = (&inp.angle[offset..end], &inp.angular_velocity[offset..end]);
    match (action, steps) {
        (Action::Torque, _) => each(&mut c, bounds, false, inertia, |k, j, b| out[k] = j.torque_at(angles[k], omegas[k], b)),
        (Action::Commit, None) => each(&mut c, bounds, true, inertia, |k, j, b| j.commit(angles[k], b)),
        (Action::Commit, Some(h)) => {
            let h = &h[offset..end];
            each(&mut c, bounds, true, inertia, |k, j, b| j.commit_step(angles[k], omegas[k], b, h[k]));
        }
        (Action::Step, None) => each(&mut c, bounds, true, inertia, |k, j, b| out[k] = j.step(angles[k], omegas[k], b, None)),
        (Action::Step, Some(h)) => {
            let h = &h[offset..end];
            each(&mut c, bounds, true, inertia, |k, j, b| out[k] = j.step(angles[k], omegas[k], b, Some(h[k])));
        }
        (Action::Bound, _) => out.copy_from_slice(bounds),
    }
}

/// Every joint's sliding torque at `inp` (the inputs' lengths and the slots already set),
/// then `action`; a commit with `steps` (one host step per joint, s, length checked) commits
/// each joint as `PreslidingJoint::commit_step`. On an error (the lowest joint index's) no
/// state has changed. `out` has one value per joint (unused by [`Action::Commit`]: it may be
/// empty then).
#[allow(clippy::too_many_arguments)]
pub fn run(joints: &mut Joints, bounds: &mut Bounds, slots: &[u32], models: &Models, inp: &Inputs, steps: Option<&[f64]>, action: Action, out: &mut [f64]) -> Result<(), BatchError> {
    let n = joints.len();
    let angle = action != Action::Bound;
    let par = parallel(n, models.settings().fidelity);
    let err = if !par {
        bounds_chunk(&mut bounds.keys, &mut bounds.values, slots, models, inp, steps, 0, angle)
    } else {
        bounds
            .keys
            .par_chunks_mut(CHUNK)
            .zip(bounds.values.par_chunks_mut(CHUNK))
            .zip(slots.par_chunks(CHUNK))
            .enumerate()
            .with_max_len(1)
            .filter_map(|(c, ((k, v), s))| bounds_chunk(k, v, s, models, inp, steps, c * CHUNK, angle))
            .min_by_key(|(i, _)| *i)
    };
    if let Some((_, e)) = err {
        return Err(e);
    }
    let bounds = &bounds.values[..];
    let out_len = if action == Action::Commit { 0 } else { n };
    let out = &mut out[..out_len];
    let (law, states, unreferenced, inertia) = joints.parts_mut();
    if !par {
        law_chunk(Chunk { law, states, unreferenced, inertia }, bounds, out, inp, steps, 0, action);
    } else {
        let inertia_of = |c: usize| inertia.map(|v| &v[c * CHUNK..((c + 1) * CHUNK).min(n)]);
        let chunks = states.par_chunks_mut(CHUNK).zip(unreferenced.par_chunks_mut(CHUNK)).zip(bounds.par_chunks(CHUNK)).enumerate().with_max_len(1);
        if action == Action::Commit {
            chunks.for_each(|(c, ((states, unreferenced), b))| law_chunk(Chunk { law, states, unreferenced, inertia: inertia_of(c) }, b, &mut [], inp, steps, c * CHUNK, action));
        } else {
            chunks.zip(out.par_chunks_mut(CHUNK)).for_each(|((c, ((states, unreferenced), b)), o)| {
                law_chunk(Chunk { law, states, unreferenced, inertia: inertia_of(c) }, b, o, inp, steps, c * CHUNK, action);
            });
        }
    }
    Ok(())
}
