//! An independent check of the batch (issue 30) with scenes the other tests have not seen.
//!
//! The reference is written here from the scalar pieces alone, per joint:
//! * the presliding state is a `PreslidingJoint` built as the Python `Presliding` object builds
//!   it (`Presliding::with_host_inertia`, `PreslidingJoint::new` / `unreferenced`), driven by
//!   `torque_at`, `commit`, `commit_step`;
//! * the sliding torque is computed twice, by two scalar front ends' routes to a temperature:
//!   a `Joint` (and level) built fresh with `lubricant.temperature` = T (what a Python
//!   `Presliding(params at T)` / `Joint(params at T, fidelity)` computes), and an `Evaluator`
//!   that follows the temperatures one call after another by `set_temperature` (what the
//!   PinJoint FMU does with its temperature input). The batch must equal both, bit for bit.
//!
//! The scenes: every fidelity level, per-joint parameter sets (μ_c, viscosity, grease),
//! per-joint temperatures that change between calls (the cold day's −54 °C, −55 °C, hot
//! days), joints at rest (ω = ±0), unloaded joints (±0 N), negative loads, reversals, angles
//! that jump by whole turns, host steps (`step_with`, `commit_step`), host inertia per joint,
//! joints waiting for their first angle, torque-then-commit against step, and n across the
//! rayon chunking threshold (2·512). Errors in the middle of a chunk must leave every state
//! (and the step bookkeeping) as it was, and the batch must step on correctly afterwards.

use pinjoint::batch::{BatchError, BatchParams, Inputs, PreslidingBatch, Settings};
use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};
use pinjoint::zero_velocity::{Presliding, PreslidingJoint};
use pinjoint::{Joint, ModelError, Params};
use std::alloc::{GlobalAlloc, Layout, System};
use std::collections::HashMap;
use std::f64::consts::TAU;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Counts the allocations of the measuring thread and of rayon's threads while `COUNTING` is
/// set (the "no allocation per step", measured). The tests of this file take `SERIAL`
/// so that no other test allocates meanwhile; the test harness's own thread, which reports the
/// test before (and allocates doing so) while the next one may already be measuring, is not
/// counted (it once made a count of 16 under load).
struct Counting;

static COUNTING: AtomicBool = AtomicBool::new(false);
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);
static SERIAL: Mutex<()> = Mutex::new(());

thread_local! {
    /// Set on the thread that measures (a constant initialiser and no destructor: reading it
    /// from the allocator allocates nothing).
    static MEASURING: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether an allocation now is counted: counting, and on the measuring thread or one of
/// rayon's (the batch's parallel passes).
fn counted() -> bool {
    COUNTING.load(Ordering::Relaxed) && (MEASURING.with(std::cell::Cell::get) || rayon::current_thread_index().is_some())
}

/// Count the allocations of this thread and rayon's (`on`), or stop counting.
fn count(on: bool) {
    MEASURING.with(|m| m.set(on));
    COUNTING.store(on, Ordering::SeqCst);
}

// SAFETY: forwards to the system allocator; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if counted() {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if counted() {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// This file's tests one at a time (the allocation count sees every thread).
fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// SplitMix64: a small fixed-seed generator (the scenes are reproducible from the seed).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

const COLD_DAY: f64 = 273.15 - 54.0;
const COLDEST: f64 = 218.15;

fn settings(fidelity: Fidelity) -> Settings {
    Settings { fidelity, tolerance: 5e-4, envelope: Envelope::new(4e3, 50e3, 0.02, 8.0).unwrap() }
}

/// A fresh joint (and level) per (parameter set, temperature's bits): what a Python
/// `Presliding`/`Joint` built with `lubricant.temperature` = T computes with.
type Fresh = HashMap<(usize, u64), Result<(Joint, Option<Evaluator>), String>>;

/// The sliding torque of one joint, the two scalar routes.
struct ScalarBound {
    set: usize,
    params: Params,
    settings: Settings,
    /// The FMU's route: this joint's evaluator, moved from temperature to temperature.
    moving: Option<Evaluator>,
}

impl ScalarBound {
    fn new(set: usize, params: Params, settings: Settings) -> Self {
        ScalarBound { set, params, settings, moving: None }
    }

    fn temperature(&self, t: Option<f64>) -> f64 {
        t.unwrap_or(self.params.lubricant.temperature)
    }

    /// Whether the model (and level) can be built at `t`: Err with a description if not.
    fn prepare(&mut self, fresh: &mut Fresh, t: Option<f64>) -> Result<(), String> {
        let t = self.temperature(t);
        let (params, s) = (self.params, self.settings);
        let built = fresh
            .entry((self.set, t.to_bits()))
            .or_insert_with(|| {
                let mut p = params;
                p.lubricant.temperature = t;
                let joint = Joint::new(&p).map_err(|e| format!("joint: {e}"))?;
                let level = if s.fidelity == Fidelity::Full { None } else { Some(Evaluator::new(&p, s.fidelity, s.tolerance, s.envelope).map_err(|e| format!("level: {e}"))?) };
                Ok((joint, level))
            })
            .as_ref()
            .map(|_| ())
            .map_err(Clone::clone);
        if built.is_ok() {
            // The FMU's route: built once at the parameters' own temperature, then moved.
            if self.moving.is_none() {
                self.moving = Some(Evaluator::new(&self.params, s.fidelity, s.tolerance, s.envelope).map_err(|e| format!("moving level: {e}"))?);
            }
            let ev = self.moving.as_mut().unwrap();
            if let Err(e) = ev.set_temperature(t) {
                panic!("the fresh route builds at {t} K but set_temperature refuses: {e}");
            }
        }
        built
    }

    /// Both routes' sliding torque at the prepared temperature `t`; they must agree bit for
    /// bit (else the test fails here, naming the point). `tabled`: whether this joint's key is
    /// among the call's first LEVELS_MAX at the table and auto levels ([`tabled`]); beyond
    /// them the complete solve answers.
    fn bound(&self, fresh: &Fresh, t: Option<f64>, load: f64, omega: f64, tabled: bool) -> Result<f64, ModelError> {
        let t = self.temperature(t);
        let (joint, level) = fresh[&(self.set, t.to_bits())].as_ref().expect("prepared");
        let level = if tabled || !matches!(self.settings.fidelity, Fidelity::Table | Fidelity::Auto) { level.as_ref() } else { None };
        let answer = |joint: &Joint, level: Option<&Evaluator>| -> Result<f64, ModelError> {
            // As python/src/presliding.rs: capacity, an unloaded joint, then the model.
            if load.abs() >= joint.capacity() {
                return Err(ModelError::BeyondCapacity { load: load.abs(), capacity: joint.capacity() });
            }
            if load == 0.0 {
                return Ok(0.0);
            }
            if let Some(e) = level.and_then(|ev| ev.evaluate_inside(load, omega)) {
                return Ok(e.torque);
            }
            joint.evaluate(load, omega).map(|op| op.torque)
        };
        let a = answer(joint, level);
        let ev = self.moving.as_ref().expect("prepared");
        assert_eq!(ev.temperature().to_bits(), t.to_bits());
        let level = (self.settings.fidelity != Fidelity::Full && (tabled || self.settings.fidelity == Fidelity::Boundary)).then_some(ev);
        let b = answer(ev.joint(), level);
        match (&a, &b) {
            (Ok(x), Ok(y)) => assert_eq!(x.to_bits(), y.to_bits(), "fresh {x} != moved {y} at T = {t} K, P = {load} N, ω = {omega} rad/s"),
            _ => assert_eq!(a, b, "at T = {t} K, P = {load} N, ω = {omega} rad/s"),
        }
        a
    }
}

/// Whether each joint's (parameter set, temperature) key is among the first LEVELS_MAX
/// distinct ones of the call in joint order: those joints a table answers at the table and
/// auto levels, the others the complete solve (the batch's bound on tables, written out here
/// from its definition).
fn tabled(scalar: &[ScalarBound], t: Option<&[f64]>) -> Vec<bool> {
    let mut top: Vec<(usize, u64)> = Vec::new();
    scalar
        .iter()
        .enumerate()
        .map(|(i, sb)| {
            let k = (sb.set, sb.temperature(t.map(|t| t[i])).to_bits());
            if top.contains(&k) {
                true
            } else if top.len() < pinjoint::batch::cache::LEVELS_MAX {
                top.push(k);
                true
            } else {
                false
            }
        })
        .collect()
}

/// A joint's parameters, drawn: μ_c, the oil's viscosity, the grease's yield stress and
/// consistency, or the defaults.
fn draw_params(r: &mut Rng) -> Params {
    draw_params_from(r, Params::default())
}

/// [`draw_params`] about `base`.
fn draw_params_from(r: &mut Rng, base: Params) -> Params {
    let mut p = base;
    if r.chance(0.8) {
        p.friction.boundary_friction_coefficient = r.range(0.07, 0.17);
    }
    if r.chance(0.5) {
        p.lubricant.viscosity *= r.range(0.6, 1.0);
    }
    if r.chance(0.5) {
        p.grease.yield_stress *= r.range(0.5, 2.0);
        p.grease.consistency *= r.range(0.5, 2.0);
    }
    p
}

fn draw_temperature(r: &mut Rng, cold: f64) -> f64 {
    match r.below(7) {
        0 => COLD_DAY.max(cold),
        1 => COLDEST.max(cold),
        2 => 343.15,
        3 => 293.15,
        4 => 253.15_f64.max(cold),
        _ => r.range(cold, 350.0),
    }
}

/// What the host does with one step's inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Call {
    /// torque, then commit at the same inputs (with or without the step).
    TorqueCommit,
    /// step (with or without the step).
    Step,
    /// torque, then commit at other loads and temperatures.
    TorqueOtherCommit,
    /// torque alone.
    Torque,
    /// The sliding torques.
    Sliding,
}

/// What a scene's calls did.
#[derive(Debug, Default, Clone, Copy)]
struct Stats {
    /// Calls compared bit for bit with every joint answering.
    good: usize,
    /// Calls refused for a temperature or a level (the reference refused too, same joint).
    temperature: usize,
    /// Calls refused for a model error (same joint, same error).
    model: usize,
    /// Joint-calls at −54 °C or colder compared bit for bit.
    cold: usize,
}

impl std::ops::AddAssign for Stats {
    fn add_assign(&mut self, o: Stats) {
        self.good += o.good;
        self.temperature += o.temperature;
        self.model += o.model;
        self.cold += o.cold;
    }
}

struct Scene {
    n: usize,
    fidelity: Fidelity,
    per_joint: bool,
    steps: usize,
    /// The coldest temperature drawn (K); None: no temperatures given.
    cold: Option<f64>,
    host: bool,
    unreferenced: bool,
    /// Some joints' parameters are the paper's model (from −35 °C: colder is refused, and
    /// its table cannot be built where its film passes the clearance).
    paper: bool,
}

/// Run a drawn scene on two batches (one commits by torque+commit, the other by step, each
/// where the call allows) and on the reference; every output, state and step record bit
/// for bit. Returns what the calls did.
fn run_scene(seed: u64, sc: &Scene) -> Stats {
    let mut r = Rng(seed);
    let n = sc.n;
    let s = settings(sc.fidelity);
    let law = Presliding::new(r.range(5e-4, 3e-3), r.range(0.8, 0.97), r.range(1e-3, 3e-2)).unwrap();
    let draw = |r: &mut Rng| if sc.paper && r.chance(0.5) { draw_params_from(r, Params::paper()) } else { draw_params(r) };
    let sets: Vec<Params> = if sc.per_joint { (0..n).map(|_| draw(&mut r)).collect() } else { vec![draw(&mut r)] };
    let bp = if sc.per_joint { BatchParams::PerJoint(sets.clone()) } else { BatchParams::Shared(sets[0]) };
    let mut a = PreslidingBatch::new(n, bp.clone(), law, s).unwrap();
    let mut b = PreslidingBatch::new(n, bp, law, s).unwrap();
    let inertia: Option<Vec<f64>> = sc.host.then(|| (0..n).map(|_| if r.chance(0.2) { 0.0 } else { 10f64.powf(r.range(-2.0, 4.0)) }).collect());
    for x in [&mut a, &mut b] {
        if sc.unreferenced {
            x.set_last_steps(&vec![0.0; n], &vec![0.0; n], &vec![true; n]).unwrap();
        }
        x.set_host_inertia(inertia.as_deref()).unwrap();
    }
    let mut refs: Vec<PreslidingJoint> = (0..n)
        .map(|i| {
            let l = law.with_host_inertia(inertia.as_ref().map_or(0.0, |v| v[i])).unwrap();
            if sc.unreferenced { PreslidingJoint::unreferenced(l) } else { PreslidingJoint::new(l, 0.0) }
        })
        .collect();
    let set = |i: usize| if sc.per_joint { i } else { 0 };
    // One scalar bound per joint (the FMU's evaluator is per joint); fresh joints per set.
    let mut scalar: Vec<ScalarBound> = (0..n).map(|i| ScalarBound::new(set(i), sets[set(i)], s)).collect();
    let mut fresh = Fresh::new();

    // Each joint's true motion: angle, ω; and a load level.
    let mut theta: Vec<f64> = (0..n).map(|_| if r.chance(0.3) { r.range(-10.0, 10.0) } else { 0.0 }).collect();
    let mut omega: Vec<f64> = (0..n).map(|_| r.range(-2.0, 2.0)).collect();
    let mut load: Vec<f64> = (0..n).map(|_| r.range(2e3, 6e4)).collect();
    let capacity: Vec<f64> = (0..n).map(|i| Joint::new(&sets[set(i)]).unwrap().capacity()).collect();
    let mut stats = Stats::default();
    let (mut out_a, mut out_b) = (vec![0.0; n], vec![0.0; n]);
    for _ in 0..sc.steps {
        let h = if r.chance(0.2) { 0.0 } else { 10f64.powf(r.range(-4.0, -1.7)) };
        // A third of the steps hold every load and speed (a joint at rest, a steady slide):
        // only the angles and the temperatures move.
        let hold = r.chance(0.33);
        for i in 0..n {
            if hold {
                theta[i] += omega[i] * h;
                continue;
            }
            match r.below(10) {
                0 => omega[i] = 0.0,
                1 => omega[i] = -0.0,
                2 => omega[i] = -omega[i],                     // a reversal
                3 => omega[i] = r.range(-1e-3, 1e-3),          // creeping
                4 => omega[i] = r.range(-6.0, 6.0),
                _ => omega[i] += r.range(-0.3, 0.3),
            }
            theta[i] += omega[i] * h + if omega[i] == 0.0 { r.range(-2e-4, 2e-4) } else { 0.0 };
            match r.below(12) {
                // Rarely, about the asperity model's capacity (an error beyond it).
                _ if r.chance(0.03 / n as f64) => load[i] = capacity[i] * r.range(0.99, 1.01) * if r.chance(0.5) { -1.0 } else { 1.0 },
                0 => load[i] = 0.0,
                1 => load[i] = -0.0,
                2 => load[i] = -r.range(1e3, 6e4),
                3 => load[i] = r.range(1.0, 100.0),
                4 => load[i] = r.range(4.5e3, 5.5e3),
                _ => load[i] = r.range(5e2, 6.5e4),
            }
        }
        // The angle the host reports: as is, wrapped into (−π, π], or off by whole turns.
        let reported: Vec<f64> = theta
            .iter()
            .map(|&x| match r.below(4) {
                0 => {
                    let w = (x + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
                    if w == -std::f64::consts::PI { std::f64::consts::PI } else { w }
                }
                1 => x + TAU * (r.below(7) as f64 - 3.0),
                _ => x,
            })
            .collect();
        let temps: Option<Vec<f64>> = match sc.cold {
            Some(c) if r.chance(0.7) => {
                let common = r.chance(0.3).then(|| draw_temperature(&mut r, c));
                Some((0..n).map(|_| common.unwrap_or_else(|| draw_temperature(&mut r, c))).collect())
            }
            _ => None,
        };
        let with_step = r.chance(0.6);
        let steps: Vec<f64> = (0..n).map(|_| if r.chance(0.1) { 0.0 } else { h }).collect();
        let call = match r.below(10) {
            0..=3 => Call::TorqueCommit,
            4..=6 => Call::Step,
            7 => Call::TorqueOtherCommit,
            8 => Call::Torque,
            _ => Call::Sliding,
        };
        let t = temps.as_deref();
        let inputs = Inputs { angle: &reported, angular_velocity: &omega, load: &load, temperature: t };

        // The reference's answers: the first level/temperature error, else the first model error.
        let prepare = |scalar: &mut Vec<ScalarBound>, fresh: &mut Fresh, t: Option<&[f64]>| -> Option<usize> {
            // Every joint (an error in one does not stop the others' evaluators moving: the
            // batch moves none of them on an error, but the reference is rebuilt each call).
            let bad: Vec<usize> = (0..n).filter(|&i| scalar[i].prepare(fresh, t.map(|t| t[i])).is_err()).collect();
            bad.first().copied()
        };
        let bounds_of = |scalar: &Vec<ScalarBound>, fresh: &Fresh, t: Option<&[f64]>, load: &[f64]| -> Result<Vec<f64>, (usize, ModelError)> {
            let tab = tabled(scalar, t);
            (0..n).map(|i| scalar[i].bound(fresh, t.map(|t| t[i]), load[i], omega[i], tab[i]).map_err(|e| (i, e))).collect()
        };
        let states_of = |x: &PreslidingBatch| {
            let (mut tq, mut an, mut hh, mut ww, mut uu) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![false; n]);
            x.states(&mut tq, &mut an).unwrap();
            x.last_steps(&mut hh, &mut ww, &mut uu).unwrap();
            (tq.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), an.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), hh.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), ww.iter().map(|v| v.to_bits()).collect::<Vec<_>>(), uu)
        };
        let before = states_of(&a);
        let bad_t = prepare(&mut scalar, &mut fresh, t);
        let want = if bad_t.is_some() { None } else { Some(bounds_of(&scalar, &fresh, t, &load)) };

        // Batch a: torque (or sliding torque); batch b: step where a commits the same inputs.
        let ra = if call == Call::Sliding { a.sliding_torque(&load, &omega, t, &mut out_a) } else { a.torque(&inputs, &mut out_a) };
        let rb = match (call, with_step) {
            (Call::TorqueCommit, true) => b.step_with(&inputs, &steps, &mut out_b),
            (Call::TorqueCommit, false) => b.step(&inputs, &mut out_b),
            (Call::Sliding, _) => b.sliding_torque(&load, &omega, t, &mut out_b),
            _ => b.torque(&inputs, &mut out_b),
        };
        match (&want, bad_t) {
            (None, Some(i)) => {
                for (name, res) in [("a", &ra), ("b", &rb)] {
                    match res {
                        Err(BatchError::Temperature { index, .. }) | Err(BatchError::Level { index, .. }) => assert_eq!(*index, i, "{name}: {res:?}"),
                        other => panic!("{name}: joint {i} cannot be built at {:?} K, the batch gave {other:?}", t.map(|t| t[i])),
                    }
                }
                assert_eq!(states_of(&a), before);
                assert_eq!(states_of(&b), before);
                stats.temperature += 1;
                continue;
            }
            (Some(Err((i, e))), _) => {
                let expect = Err(BatchError::Model { index: *i, source: e.clone() });
                assert_eq!(ra, expect);
                assert_eq!(rb, expect);
                assert_eq!(states_of(&a), before);
                assert_eq!(states_of(&b), before);
                stats.model += 1;
                continue;
            }
            _ => {}
        }
        let bounds = want.unwrap().unwrap();
        ra.unwrap();
        rb.unwrap();
        stats.good += 1;
        stats.cold += (0..n).filter(|&i| t.map_or(sets[set(i)].lubricant.temperature, |t| t[i]) <= COLD_DAY && load[i] != 0.0).count();
        for i in 0..n {
            let w = if call == Call::Sliding { bounds[i] } else { refs[i].torque_at(reported[i], omega[i], bounds[i]) };
            assert_eq!(out_a[i].to_bits(), w.to_bits(), "seed {seed} joint {i} ({call:?}): batch {} != scalar {w}", out_a[i]);
            assert_eq!(out_b[i].to_bits(), w.to_bits(), "seed {seed} joint {i} ({call:?}, step): batch {} != scalar {w}", out_b[i]);
        }
        // The commits.
        match call {
            Call::TorqueCommit => {
                let r = if with_step { a.commit_step(&inputs, &steps) } else { a.commit(&inputs) };
                r.unwrap();
                for i in 0..n {
                    if with_step { refs[i].commit_step(reported[i], omega[i], bounds[i], steps[i]) } else { refs[i].commit(reported[i], bounds[i]) }
                }
            }
            Call::TorqueOtherCommit => {
                // Commit at 0.8× the loads and (maybe) other temperatures: a new solve.
                let l2: Vec<f64> = load.iter().map(|l| l * 0.8).collect();
                let t2: Option<Vec<f64>> = match (sc.cold, r.chance(0.5)) {
                    (Some(c), true) => Some((0..n).map(|_| draw_temperature(&mut r, c)).collect()),
                    _ => temps.clone(),
                };
                let ci = Inputs { load: &l2, temperature: t2.as_deref(), ..inputs };
                let bad = prepare(&mut scalar, &mut fresh, t2.as_deref());
                let res = if with_step { (a.commit_step(&ci, &steps), b.commit_step(&ci, &steps)) } else { (a.commit(&ci), b.commit(&ci)) };
                if let Some(i) = bad {
                    assert!(matches!(res.0, Err(BatchError::Temperature { index, .. }) | Err(BatchError::Level { index, .. }) if index == i), "{:?}", res.0);
                    assert_eq!(res.0, res.1);
                    assert_eq!(states_of(&a), before);
                    continue;
                }
                match bounds_of(&scalar, &fresh, t2.as_deref(), &l2) {
                    Err((i, e)) => {
                        assert_eq!(res.0, Err(BatchError::Model { index: i, source: e }));
                        assert_eq!(res.0, res.1);
                        assert_eq!(states_of(&a), before);
                        continue;
                    }
                    Ok(cb) => {
                        res.0.unwrap();
                        res.1.unwrap();
                        for i in 0..n {
                            if with_step { refs[i].commit_step(reported[i], omega[i], cb[i], steps[i]) } else { refs[i].commit(reported[i], cb[i]) }
                        }
                    }
                }
            }
            Call::Step => {
                // Both step (a with the step when b commits without it, and the other way).
                let ra = if with_step { a.step_with(&inputs, &steps, &mut out_a) } else { a.step(&inputs, &mut out_a) };
                let rb = if with_step { b.torque(&inputs, &mut out_b).and_then(|()| b.commit_step(&inputs, &steps)) } else { b.torque(&inputs, &mut out_b).and_then(|()| b.commit(&inputs)) };
                ra.unwrap();
                rb.unwrap();
                for i in 0..n {
                    let w = refs[i].torque_at(reported[i], omega[i], bounds[i]);
                    assert_eq!(out_a[i].to_bits(), w.to_bits(), "seed {seed} joint {i} step");
                    assert_eq!(out_b[i].to_bits(), w.to_bits(), "seed {seed} joint {i} torque+commit");
                    if with_step { refs[i].commit_step(reported[i], omega[i], bounds[i], steps[i]) } else { refs[i].commit(reported[i], bounds[i]) }
                }
            }
            Call::Torque | Call::Sliding => {}
        }
        // Every state, bit for bit, in both batches.
        let want_states = (
            refs.iter().map(|j| j.presliding_torque().to_bits()).collect::<Vec<_>>(),
            refs.iter().map(|j| j.reference_angle().to_bits()).collect::<Vec<_>>(),
            refs.iter().map(|j| j.last_step().0.to_bits()).collect::<Vec<_>>(),
            refs.iter().map(|j| j.last_step().1.to_bits()).collect::<Vec<_>>(),
            refs.iter().map(PreslidingJoint::is_unreferenced).collect::<Vec<_>>(),
        );
        assert_eq!(states_of(&a), want_states, "seed {seed}: batch a's states");
        assert_eq!(states_of(&b), want_states, "seed {seed}: batch b's states");
        for (i, r) in refs.iter().enumerate() {
            assert_eq!(&a.joint_law(i), r.law(), "seed {seed} joint {i} law");
        }
    }
    stats
}

#[test]
fn full_fidelity_random_scenes() {
    let _serial = serial();
    let mut st = Stats::default();
    for seed in 0..40 {
        let sc = Scene { n: 1 + (seed as usize % 9), fidelity: Fidelity::Full, per_joint: seed % 2 == 0, steps: 40, cold: (seed % 4 != 3).then_some(COLDEST), host: seed % 3 != 0, unreferenced: seed % 5 == 0, paper: false };
        st += run_scene(1000 + seed, &sc);
    }
    eprintln!("full: {st:?}");
    assert!(st.good >= 1000 && st.model >= 5 && st.cold >= 300, "{st:?}");
}

#[test]
fn boundary_fidelity_random_scenes() {
    let _serial = serial();
    let mut st = Stats::default();
    for seed in 0..24 {
        let sc = Scene { n: 1 + (seed as usize % 6), fidelity: Fidelity::Boundary, per_joint: seed % 2 == 1, steps: 30, cold: (seed % 3 != 2).then_some(COLDEST), host: seed % 2 == 0, unreferenced: seed % 4 == 1, paper: false };
        st += run_scene(2000 + seed, &sc);
    }
    eprintln!("boundary: {st:?}");
    assert!(st.good >= 400 && st.cold >= 100, "{st:?}");
}

#[test]
fn table_fidelity_random_scenes() {
    let _serial = serial();
    let mut st = Stats::default();
    // A table build costs milliseconds: few joints, a few temperatures (the cold ones too:
    // where a table cannot be built the batch must refuse naming the joint, as the reference).
    for seed in 0..6 {
        let sc = Scene { n: 1 + (seed as usize % 3), fidelity: Fidelity::Table, per_joint: seed % 2 == 1, steps: 12, cold: (seed % 3 != 0).then_some(COLDEST), host: true, unreferenced: seed == 4, paper: false };
        st += run_scene(3000 + seed, &sc);
    }
    eprintln!("table: {st:?}");
    assert!(st.good >= 20, "{st:?}");
}

#[test]
fn auto_fidelity_random_scenes() {
    let _serial = serial();
    let mut st = Stats::default();
    for seed in 0..6 {
        let sc = Scene { n: 1 + (seed as usize % 3), fidelity: Fidelity::Auto, per_joint: seed % 2 == 0, steps: 12, cold: (seed % 3 != 1).then_some(COLDEST), host: seed % 2 == 1, unreferenced: seed == 3, paper: false };
        st += run_scene(4000 + seed, &sc);
    }
    eprintln!("auto: {st:?}");
    assert!(st.good >= 20, "{st:?}");
}

/// Around the chunking thresholds (2·512 at full, 8·512 at the other levels) and beyond: the
/// parallel path gives the scalar numbers.
#[test]
fn joint_counts_around_the_chunking_threshold() {
    let _serial = serial();
    for (k, n) in [1usize, 2, 511, 512, 513, 1023, 1024, 1025, 1536, 5000].into_iter().enumerate() {
        let sc = Scene { n, fidelity: Fidelity::Full, per_joint: k % 2 == 1, steps: if n > 2000 { 4 } else { 6 }, cold: Some(COLDEST), host: true, unreferenced: k % 3 == 0, paper: false };
        let st = run_scene(5000 + k as u64, &sc);
        eprintln!("n = {n}: {st:?}");
        assert!(st.good >= 2, "n = {n}: {st:?}");
    }
    for (k, n) in [1025usize, 4095, 4096, 4200].into_iter().enumerate() {
        let sc = Scene { n, fidelity: Fidelity::Boundary, per_joint: false, steps: 4, cold: Some(COLDEST), host: true, unreferenced: false, paper: false };
        run_scene(5100 + k as u64, &sc);
    }
}

/// The paper's model beside the complete one: temperatures below its range are refused
/// naming the joint, and so are table levels that cannot be built; the rest bit for bit.
#[test]
fn paper_model_joints_every_fidelity() {
    let _serial = serial();
    let mut st = Stats::default();
    for (k, fidelity) in [Fidelity::Full, Fidelity::Boundary, Fidelity::Table, Fidelity::Auto, Fidelity::Full, Fidelity::Boundary].into_iter().enumerate() {
        let sc = Scene { n: 2 + k % 3, fidelity, per_joint: true, steps: if fidelity == Fidelity::Full || fidelity == Fidelity::Boundary { 40 } else { 10 }, cold: Some(COLDEST), host: true, unreferenced: k == 2, paper: true };
        st += run_scene(6000 + k as u64, &sc);
    }
    eprintln!("paper: {st:?}");
    assert!(st.good >= 60 && st.temperature >= 5, "{st:?}");
}

#[test]
fn no_joints_is_an_error() {
    let _serial = serial();
    for f in [Fidelity::Full, Fidelity::Table] {
        let e = PreslidingBatch::new(0, BatchParams::Shared(Params::default()), Presliding::default(), settings(f)).unwrap_err();
        assert_eq!(e, BatchError::Empty);
        let e = PreslidingBatch::new(0, BatchParams::PerJoint(vec![]), Presliding::default(), settings(f)).unwrap_err();
        assert_eq!(e, BatchError::Empty);
    }
}

type Snapshot = (Vec<(u64, u64)>, Vec<u64>, Vec<u64>, Vec<bool>);

fn snapshot(b: &PreslidingBatch) -> Snapshot {
    let n = b.len();
    let (mut t, mut a, mut h, mut w, mut u) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![false; n]);
    b.states(&mut t, &mut a).unwrap();
    b.last_steps(&mut h, &mut w, &mut u).unwrap();
    (t.iter().zip(&a).map(|(x, y)| (x.to_bits(), y.to_bits())).collect(), h.iter().map(|x| x.to_bits()).collect(), w.iter().map(|x| x.to_bits()).collect(), u)
}

/// Errors in the middle of a chunk (and in several chunks, and in the temperatures): nothing
/// changes, the lowest index is named, and the next good call is the scalar law's.
#[test]
fn errors_mid_chunk_change_nothing_and_the_batch_steps_on() {
    let _serial = serial();
    for n in [700usize, 1025, 5000] {
        for per_joint in [false, true] {
            let mut r = Rng(n as u64 * 7 + u64::from(per_joint));
            let sets: Vec<Params> = if per_joint { (0..n).map(|_| draw_params(&mut r)).collect() } else { vec![Params::default()] };
            let bp = if per_joint { BatchParams::PerJoint(sets.clone()) } else { BatchParams::Shared(sets[0]) };
            let law = Presliding::default();
            let s = settings(Fidelity::Full);
            let mut b = PreslidingBatch::new(n, bp, law, s).unwrap();
            let inertia: Vec<f64> = (0..n).map(|i| (i % 5) as f64 * 3.0).collect();
            b.set_host_inertia(Some(&inertia)).unwrap();
            let mut refs: Vec<PreslidingJoint> = (0..n).map(|i| PreslidingJoint::new(law.with_host_inertia(inertia[i]).unwrap(), 0.0)).collect();
            let set = |i: usize| if per_joint { i } else { 0 };
            let mut scalar: Vec<ScalarBound> = (0..n).map(|i| ScalarBound::new(set(i), sets[set(i)], s)).collect();
            let mut fresh = Fresh::new();
            let mut out = vec![0.0; n];
            let mut angle: Vec<f64> = (0..n).map(|i| 1e-4 * ((i % 13) as f64 - 6.0)).collect();
            let omega: Vec<f64> = (0..n).map(|i| [0.0, 0.3, -0.2, 1e-3, -0.0][i % 5]).collect();
            let load: Vec<f64> = (0..n).map(|i| 3e3 + 17.0 * i as f64 % 5e4).collect();
            let temp0: Vec<f64> = (0..n).map(|i| [COLD_DAY, 293.15, 343.15][i % 3]).collect();
            let steps = vec![2e-3; n];
            // A good step first (states away from rest), at the cold day for a third of the joints.
            let good = |b: &mut PreslidingBatch, refs: &mut Vec<PreslidingJoint>, scalar: &mut Vec<ScalarBound>, fresh: &mut Fresh, angle: &[f64], t: Option<&[f64]>| {
                let mut out = vec![0.0; n];
                for i in 0..n {
                    scalar[i].prepare(fresh, t.map(|t| t[i])).unwrap();
                }
                b.step_with(&Inputs { angle, angular_velocity: &omega, load: &load, temperature: t }, &steps, &mut out).unwrap();
                let tab = tabled(scalar, t);
                for i in 0..n {
                    let bound = scalar[i].bound(fresh, t.map(|t| t[i]), load[i], omega[i], tab[i]).unwrap();
                    let w = refs[i].torque_at(angle[i], omega[i], bound);
                    assert_eq!(out[i].to_bits(), w.to_bits(), "n {n} joint {i}");
                    refs[i].commit_step(angle[i], omega[i], bound, steps[i]);
                }
            };
            good(&mut b, &mut refs, &mut scalar, &mut fresh, &angle, Some(&temp0));
            for a in angle.iter_mut() {
                *a += 3e-4;
            }
            let before = snapshot(&b);
            let mid = [n / 2 + 3, 511.min(n - 1), (n - 1).min(1024 + 100)];
            let capacity = 1e13;
            for &k in &mid {
                // (name, spoil, the expected error's index and kind)
                type Spoil = fn(&mut [f64], &mut [f64], &mut [f64], &mut [f64], &mut [f64], usize);
                let spoils: [(&str, Spoil); 9] = [
                    ("nan load", |_, _, l, _, _, k| l[k] = f64::NAN),
                    ("inf omega", |_, w, _, _, _, k| w[k] = f64::NEG_INFINITY),
                    ("nan angle", |a, _, _, _, _, k| a[k] = f64::NAN),
                    ("negative step", |_, _, _, _, h, k| h[k] = -1e-3),
                    ("nan step", |_, _, _, _, h, k| h[k] = f64::NAN),
                    ("beyond capacity", |_, _, l, _, _, k| l[k] = 1e13),
                    ("too hot", |_, _, _, t, _, k| t[k] = 1e4),
                    ("too cold", |_, _, _, t, _, k| t[k] = 200.0),
                    ("nan temperature", |_, _, _, t, _, k| t[k] = f64::NAN),
                ];
                for (name, spoil) in spoils {
                    let (mut a2, mut w2, mut l2, mut t2, mut h2) = (angle.clone(), omega.clone(), load.clone(), temp0.iter().map(|t| t + 5.0).collect::<Vec<_>>(), steps.clone());
                    spoil(&mut a2, &mut w2, &mut l2, &mut t2, &mut h2, k);
                    // A second bad joint further on: the lowest is named.
                    if k + 7 < n {
                        l2[k + 7] = capacity;
                    }
                    let inputs = Inputs { angle: &a2, angular_velocity: &w2, load: &l2, temperature: Some(&t2) };
                    // The step is an input of step_with and commit_step alone.
                    let calls: &[u8] = if name.contains("step") { &[1, 2] } else { &[0, 1, 2, 3] };
                    for &call in calls {
                        let e = match call {
                            0 => b.torque(&inputs, &mut out),
                            1 => b.step_with(&inputs, &h2, &mut out),
                            2 => b.commit_step(&inputs, &h2),
                            _ => b.step(&inputs, &mut out),
                        };
                        let Err(e) = e else { panic!("n {n} {name} at {k}, call {call}: no error") };
                        let index = match &e {
                            BatchError::NotFinite { index, argument, .. } => {
                                let want = match name {
                                    "nan load" | "beyond capacity" => "load",
                                    "inf omega" => "angular_velocity",
                                    "nan angle" => "angle",
                                    _ => "temperature",
                                };
                                assert_eq!(*argument, want, "{e}");
                                *index
                            }
                            BatchError::Step { index, .. } => {
                                assert!(name.contains("step"), "{name}: {e}");
                                *index
                            }
                            BatchError::Model { index, source: ModelError::BeyondCapacity { .. } } => {
                                assert_eq!(name, "beyond capacity", "{e}");
                                *index
                            }
                            BatchError::Temperature { index, .. } => {
                                assert!(name.starts_with("too"), "{name}: {e}");
                                assert!(e.to_string().contains("lubricant.temperature"), "{e}");
                                *index
                            }
                            other => panic!("n {n} {name} at {k}: {other}"),
                        };
                        assert_eq!(index, k, "n {n} {name} call {call}: {e}");
                        assert!(e.to_string().contains(&format!("index {k}")), "{e}");
                        assert_eq!(snapshot(&b), before, "n {n} {name} at {k} call {call}: a state changed");
                    }
                }
            }
            // After all the failures (some moved the models to other temperatures first): a good
            // call without temperatures is each parameter set's own temperature, bit for bit.
            good(&mut b, &mut refs, &mut scalar, &mut fresh, &angle, None);
            for a in angle.iter_mut() {
                *a -= 7e-4;
            }
            let t1: Vec<f64> = (0..n).map(|i| [343.15, COLDEST, COLD_DAY, 260.0][i % 4]).collect();
            good(&mut b, &mut refs, &mut scalar, &mut fresh, &angle, Some(&t1));
        }
    }
}

/// The bound cache keyed by (load, ω, temperature): the same inputs given again after other
/// temperatures and failed calls must not answer from a stale entry.
#[test]
fn alternating_temperatures_and_identical_inputs() {
    let _serial = serial();
    let n = 6;
    let mut r = Rng(77);
    let sets: Vec<Params> = (0..n).map(|_| draw_params(&mut r)).collect();
    for fidelity in [Fidelity::Full, Fidelity::Boundary, Fidelity::Table] {
        let s = settings(fidelity);
        let mut b = PreslidingBatch::new(n, BatchParams::PerJoint(sets.clone()), Presliding::default(), s).unwrap();
        let mut scalar: Vec<ScalarBound> = sets.iter().enumerate().map(|(i, p)| ScalarBound::new(i, *p, s)).collect();
        let mut fresh = Fresh::new();
        let load = vec![2.2e4, 0.0, -3e4, 1e4, 4.9e4, 6e3];
        let omega = vec![0.0, 0.5, -0.5, 1e-3, 3.0, -0.0];
        let temps = [None, Some(vec![293.15; n]), Some(vec![303.15; n]), Some((0..n).map(|i| if i % 2 == 0 { 293.15 } else { 343.15 }).collect())];
        let mut out = vec![0.0; n];
        for k in 0..40 {
            let t = temps[(k * 7 + k / 3) % temps.len()].as_deref();
            // Table levels at each temperature: the reference builds them too.
            for (i, sb) in scalar.iter_mut().enumerate() {
                sb.prepare(&mut fresh, t.map(|t| t[i])).unwrap();
            }
            b.sliding_torque(&load, &omega, t, &mut out).unwrap();
            let tab = tabled(&scalar, t);
            for i in 0..n {
                let w = scalar[i].bound(&fresh, t.map(|t| t[i]), load[i], omega[i], tab[i]).unwrap();
                assert_eq!(out[i].to_bits(), w.to_bits(), "{fidelity} call {k} joint {i}: {} != {w}", out[i]);
            }
            if k % 5 == 0 {
                // A failed call at yet another temperature in between.
                let bad: Vec<f64> = (0..n).map(|i| if i == 3 { f64::NAN } else { 250.0 }).collect();
                assert!(b.sliding_torque(&load, &omega, Some(&bad), &mut out).is_err());
                let mut l = load.clone();
                l[4] = f64::NAN;
                let cold = vec![COLD_DAY; n];
                let e = b.sliding_torque(&l, &omega, Some(&cold), &mut out);
                assert!(matches!(e, Err(BatchError::NotFinite { index: 4, .. }) | Err(BatchError::Level { .. })), "{e:?}");
            }
        }
    }
}

/// The allocations of `rounds` rounds of the six calls (torque, commit_step, step_with, step,
/// commit, sliding_torque) on `b`, with inputs that change every round; `temperature(k)`
/// gives round k's temperatures. The rounds run twice and the second time is counted: the
/// first solves the rows of the solver's start table the loads visit (`solve_start`: rows
/// solved once, on first use, then kept) and builds the models.
fn allocations_of(b: &mut PreslidingBatch, rounds: usize, temperature: &dyn Fn(usize) -> Option<Vec<f64>>) -> usize {
    let n = b.len();
    let steps = vec![1e-3; n];
    let mut out = vec![0.0; n];
    let temps: Vec<Option<Vec<f64>>> = (0..rounds).map(temperature).collect();
    let mut ok = true;
    for pass in 0..2 {
        let mut angle: Vec<f64> = (0..n).map(|i| 1e-4 * (i % 7) as f64).collect();
        let mut omega: Vec<f64> = (0..n).map(|i| 0.5 - (i % 9) as f64 * 0.1).collect();
        let mut load: Vec<f64> = (0..n).map(|i| 4e3 + 9.0 * i as f64).collect();
        ALLOCATIONS.store(0, Ordering::SeqCst);
        count(pass == 1);
        for t in &temps {
            for x in angle.iter_mut() {
                *x += 1e-5;
            }
            for w in omega.iter_mut() {
                *w *= -1.01;
            }
            for l in load.iter_mut() {
                *l += 3.0;
            }
            let t = t.as_deref();
            let inputs = Inputs { angle: &angle, angular_velocity: &omega, load: &load, temperature: t };
            ok &= b.torque(&inputs, &mut out).is_ok();
            ok &= b.commit_step(&inputs, &steps).is_ok();
            ok &= b.step_with(&inputs, &steps, &mut out).is_ok();
            ok &= b.step(&inputs, &mut out).is_ok();
            ok &= b.commit(&inputs).is_ok();
            ok &= b.sliding_torque(&load, &omega, t, &mut out).is_ok();
        }
        count(false);
    }
    assert!(ok, "a call failed");
    ALLOCATIONS.load(Ordering::SeqCst)
}

/// The allocations of rayon alone over `passes` parallel passes from this thread (jobs
/// injected from outside its pool go through crossbeam's `Injector`, a list of blocks of
/// 63 jobs: a block is allocated now and then).
fn rayon_allocations(passes: usize) -> usize {
    use rayon::prelude::*;
    let mut v = vec![0.0f64; 3000];
    v.par_chunks_mut(512).for_each(|c| c[0] += 1.0);
    ALLOCATIONS.store(0, Ordering::SeqCst);
    count(true);
    for _ in 0..passes {
        v.par_chunks_mut(512).enumerate().for_each(|(k, c)| c[0] += k as f64);
    }
    count(false);
    std::hint::black_box(&v);
    ALLOCATIONS.load(Ordering::SeqCst)
}

/// "No allocation per step" (issue 30), measured: once a batch has its models (the same
/// temperatures as before, or none given) and its joints' loads have been seen, torque,
/// commit, step, step_with, commit_step and sliding_torque allocate nothing on the calling
/// thread (n < 2·512), at every level, shared or per-joint sets, with inputs that change
/// every call (new solves). On rayon's threads (n ≥ 2·512 at full) the batch's code allocates
/// nothing either: the count is at most rayon's own over as many parallel passes (two a
/// call) and one more.
#[test]
fn no_allocation_per_step_once_the_temperatures_settle() {
    let _serial = serial();
    let rounds = 40;
    let calls = 6 * rounds;
    let rayon_alone = rayon_allocations(2 * calls);
    eprintln!("rayon alone: {rayon_alone} allocations in {} parallel passes", 2 * calls);
    for fidelity in [Fidelity::Full, Fidelity::Boundary, Fidelity::Table, Fidelity::Auto] {
        for (n, per_joint) in [(100usize, true), (100, false), (3000, false)] {
            let mut r = Rng(n as u64);
            let sets: Vec<Params> = (0..4).map(|_| draw_params(&mut r)).collect();
            let bp = if per_joint { BatchParams::PerJoint((0..n).map(|i| sets[i % 4]).collect()) } else { BatchParams::Shared(sets[0]) };
            let temps: Vec<f64> = (0..n).map(|i| [COLD_DAY, 293.15, 343.15][i % 3]).collect();
            for given in [true, false] {
                let mut b = PreslidingBatch::new(n, bp.clone(), Presliding::default(), settings(fidelity)).unwrap();
                b.set_host_inertia(Some(&vec![20.0; n])).unwrap();
                let count = allocations_of(&mut b, rounds, &|_| given.then(|| temps.clone()));
                eprintln!("{fidelity}, n = {n}, per joint {per_joint}, temperatures given {given}: {count} allocations in {calls} calls");
                if n < 1024 {
                    assert_eq!(count, 0, "{fidelity}, n = {n}, per joint {per_joint}, temperatures given {given}: {count} allocations in {calls} calls");
                } else {
                    assert!(count <= rayon_alone + 1, "{fidelity}, n = {n}, temperatures given {given}: {count} allocations in {calls} calls (rayon alone: {rayon_alone})");
                }
            }
        }
    }
}

/// The model cache's claim (`batch::cache`): a host that alternates between temperatures, or
/// calls with temperatures and then without, does not rebuild a model each call, as long as
/// the models released in a call fit among the retained ones (joints sharing a parameter
/// set: one model per temperature). Measured by the allocations a rebuild makes (a level
/// built again allocates its table; a joint moved to a temperature clones its parts).
#[test]
fn alternating_temperatures_rebuild_nothing_with_a_shared_set() {
    let _serial = serial();
    for fidelity in [Fidelity::Full, Fidelity::Boundary, Fidelity::Table] {
        let n = 100;
        let temps: Vec<f64> = (0..n).map(|i| [COLD_DAY, 343.15][i % 2]).collect();
        let hot = vec![320.0; n];
        let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), settings(fidelity)).unwrap();
        let count = allocations_of(&mut b, 30, &|k| match k % 3 {
            0 => Some(temps.clone()),
            1 => None,
            _ => Some(hot.clone()),
        });
        assert_eq!(count, 0, "{fidelity}: {count} allocations: a model was built again");
        assert!(b.models_held() <= 1 + pinjoint::batch::cache::RETAINED, "{}", b.models_held());
    }
}
