//! The batch is n scalar presliding joints, bit for bit (issue 30): random scenes at every
//! fidelity level, shared and per-joint parameters, with and without per-joint temperatures,
//! against n independent `PreslidingJoint`s whose sliding torque is computed here the way the
//! scalar front ends compute it (the Python `Presliding` object's cold full solve; the
//! level's answer inside the envelope otherwise, as the vectorised `Joint.evaluate`).
//! With the host's conventions (issue 29): per-joint host inertia, commits with the host's step
//! (the next angle read modulo 2π against ω·h, the damping capped at h), angles wrapped into
//! (−π, π] or shifted by whole turns, and joints waiting for their first angle.

use pinjoint::batch::{BatchError, BatchParams, Inputs, PreslidingBatch, Settings};
use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};
use pinjoint::zero_velocity::{Presliding, PreslidingJoint};
use pinjoint::{Joint, ModelError, Params};
use proptest::prelude::*;
use std::collections::HashMap;

/// The scalar sliding torque of the front ends, written out independently of the batch.
struct Scalar {
    fidelity: Fidelity,
    settings: Settings,
    joints: HashMap<(usize, u64), (Joint, Option<Evaluator>)>,
}

impl Scalar {
    fn new(settings: Settings) -> Self {
        Scalar { fidelity: settings.fidelity, settings, joints: HashMap::new() }
    }

    fn bound(&mut self, i: usize, params: &Params, temperature: Option<f64>, load: f64, omega: f64) -> Result<f64, ModelError> {
        let mut p = *params;
        if let Some(t) = temperature {
            p.lubricant.temperature = t;
        }
        let s = self.settings;
        let fid = self.fidelity;
        let (joint, level) = self.joints.entry((i, p.lubricant.temperature.to_bits())).or_insert_with(|| {
            let joint = Joint::new(&p).unwrap();
            let level = (fid != Fidelity::Full).then(|| Evaluator::new(&p, fid, s.tolerance, s.envelope).unwrap());
            (joint, level)
        });
        // As python/src/presliding.rs: the capacity, then an unloaded joint, then the model.
        if load.abs() >= joint.capacity() {
            return Err(ModelError::BeyondCapacity { load: load.abs(), capacity: joint.capacity() });
        }
        if load == 0.0 {
            return Ok(0.0);
        }
        if let Some(e) = level.as_ref().and_then(|ev| ev.evaluate_inside(load, omega)) {
            return Ok(e.torque);
        }
        joint.evaluate(load, omega).map(|op| op.torque)
    }
}

#[derive(Debug, Clone)]
struct Step {
    angle: Vec<f64>,
    omega: Vec<f64>,
    load: Vec<f64>,
    temperature: Option<Vec<f64>>,
    /// The host's step per joint (s) given to the commit; None: `commit` without a step.
    step: Option<Vec<f64>>,
    /// 0: torque then commit at the same inputs; 1: step; 2: torque, then commit at other loads.
    mode: u8,
}

fn omega_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), Just(-0.0), -1e-3..1e-3f64, -5.0..5.0f64, -0.05..0.05f64]
}

fn load_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 8 => 1e3..6e4f64, 2 => -6e4..-1e3f64, 1 => 4e3..7e3f64]
}

fn scene(n: usize, steps: usize, temps: bool) -> impl Strategy<Value = Vec<Step>> {
    scene_in(n, steps, temps, 240.0, false)
}

/// A host step (s): 0 (not known) or 0.1 to 20 ms.
fn step_strategy() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 6 => 1e-4..2e-2f64]
}

/// The angle a host reports for the true angle `x` (rad): as is (0), wrapped into (−π, π]
/// (1), or shifted by `turns` whole turns (2).
fn report(x: f64, how: u8, turns: i32) -> f64 {
    use std::f64::consts::{PI, TAU};
    match how {
        0 => x,
        1 => {
            let w = (x + PI).rem_euclid(TAU) - PI;
            if w == -PI { PI } else { w }
        }
        _ => x + f64::from(turns) * TAU,
    }
}

/// Temperatures from `cold` (K) to 330 K (a table is built over the envelope's ghost nodes,
/// where a cold, viscous lubricant's film passes the clearance: the level cannot be built).
/// With `wrap`, the true angles start anywhere in ±10 rad (some near ±π) and the host reports
/// each one as is, wrapped into (−π, π] or shifted by whole turns, at random per joint and step.
fn scene_in(n: usize, steps: usize, temps: bool, cold: f64, wrap: bool) -> impl Strategy<Value = Vec<Step>> {
    let step = (
        prop::collection::vec(-2e-3..2e-3f64, n),
        prop::collection::vec(omega_strategy(), n),
        prop::collection::vec(load_strategy(), n),
        prop::collection::vec(prop_oneof![Just(293.15), Just(cold.max(253.15)), Just(318.15), cold..330.0f64], n),
        0u8..3,
        any::<bool>(),
        any::<bool>(),
        (prop::option::of(prop::collection::vec(step_strategy(), n)), prop::collection::vec((0u8..3, -3i32..4), n)),
    );
    let start = prop::collection::vec(prop_oneof![Just(std::f64::consts::PI - 1e-3), Just(-std::f64::consts::PI + 5e-4), -10.0..10.0f64], n);
    (prop::collection::vec(step, 1..steps), start).prop_map(move |(v, start)| {
        let mut angle = if wrap { start } else { vec![0.0; n] };
        let mut last: Option<(Vec<f64>, Vec<f64>)> = None;
        v.into_iter()
            .map(|(da, omega, load, t, mode, use_t, hold, (step, how))| {
                for (a, d) in angle.iter_mut().zip(&da) {
                    *a += d;
                }
                // Half the steps hold the last load and speed (a joint at rest, a steady
                // slide): only the temperature or the angle moves.
                let (omega, load) = match (&last, hold) {
                    (Some((w, l)), true) => (w.clone(), l.clone()),
                    _ => (omega, load),
                };
                last = Some((omega.clone(), load.clone()));
                let reported = if wrap { angle.iter().zip(&how).map(|(&x, &(h, k))| report(x, h, k)).collect() } else { angle.clone() };
                Step { angle: reported, omega, load, temperature: (temps && use_t).then_some(t), step, mode }
            })
            .collect()
    })
}

fn settings(fidelity: Fidelity) -> Settings {
    Settings { fidelity, tolerance: 1e-3, envelope: Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap() }
}

/// The host's side of a scene: per-joint host inertia (kg·m², 0 = not given) and whether the
/// joints start waiting for their first angle.
#[derive(Debug, Clone, Default)]
struct Host {
    inertia: Option<Vec<f64>>,
    unreferenced: bool,
}

fn host_strategy(n: usize) -> impl Strategy<Value = Host> {
    (prop::option::of(prop::collection::vec(prop_oneof![1 => Just(0.0), 4 => 0.05..1e4f64], n)), any::<bool>())
        .prop_map(|(inertia, unreferenced)| Host { inertia, unreferenced })
}

/// Run `scene` on the batch and on the scalar joints; every output and state bit for bit,
/// every error at the same index.
fn check(params: &[Params], per_joint: bool, fidelity: Fidelity, scene: &[Step]) -> Result<(), TestCaseError> {
    check_host(params, per_joint, fidelity, scene, &Host::default())
}

/// [`check`] with the host's conventions: each scalar joint is built as the scalar front ends
/// build it (`with_host_inertia`, `PreslidingJoint::unreferenced`) and committed with
/// `commit_step` where the scene gives a step.
fn check_host(params: &[Params], per_joint: bool, fidelity: Fidelity, scene: &[Step], host: &Host) -> Result<(), TestCaseError> {
    let n = scene[0].angle.len();
    let law = Presliding::new(2e-3, 0.9, 0.02).unwrap();
    let bp = if per_joint { BatchParams::PerJoint(params.to_vec()) } else { BatchParams::Shared(params[0]) };
    let mut batch = PreslidingBatch::new(n, bp, law, settings(fidelity)).unwrap();
    if host.unreferenced {
        batch.set_last_steps(&vec![0.0; n], &vec![0.0; n], &vec![true; n]).unwrap();
    }
    batch.set_host_inertia(host.inertia.as_deref()).unwrap();
    let mut scalar = Scalar::new(settings(fidelity));
    let mut states: Vec<PreslidingJoint> = (0..n)
        .map(|i| {
            let l = law.with_host_inertia(host.inertia.as_ref().map_or(0.0, |v| v[i])).unwrap();
            if host.unreferenced { PreslidingJoint::unreferenced(l) } else { PreslidingJoint::new(l, 0.0) }
        })
        .collect();
    let p = |i: usize| if per_joint { params[i] } else { params[0] };
    let mut out = vec![0.0; n];
    for s in scene {
        let t = s.temperature.as_deref();
        let inputs = Inputs { angle: &s.angle, angular_velocity: &s.omega, load: &s.load, temperature: t };
        // The reference: every joint's bound, the first error.
        let mut bounds = vec![0.0; n];
        let mut first_err = None;
        for i in 0..n {
            match scalar.bound(i, &p(i), t.map(|t| t[i]), s.load[i], s.omega[i]) {
                Ok(b) => bounds[i] = b,
                Err(e) => {
                    first_err = Some((i, e));
                    break;
                }
            }
        }
        let before: Vec<(f64, f64)> = (0..n).map(|i| batch.state(i)).collect();
        let res = match (s.mode, &s.step) {
            (1, Some(h)) => batch.step_with(&inputs, h, &mut out),
            (1, None) => batch.step(&inputs, &mut out),
            _ => batch.torque(&inputs, &mut out),
        };
        if let Some((i, e)) = first_err {
            prop_assert_eq!(res, Err(BatchError::Model { index: i, source: e }));
            prop_assert_eq!(&before, &(0..n).map(|i| batch.state(i)).collect::<Vec<_>>());
            continue;
        }
        prop_assert!(res.is_ok(), "{res:?}");
        for i in 0..n {
            let want = states[i].torque_at(s.angle[i], s.omega[i], bounds[i]);
            prop_assert_eq!(out[i].to_bits(), want.to_bits(), "joint {} torque {} != {}", i, out[i], want);
        }
        let commit_load: Vec<f64> = if s.mode == 2 { s.load.iter().map(|l| l * 0.75).collect() } else { s.load.clone() };
        if s.mode != 1 {
            let ci = Inputs { load: &commit_load, ..inputs };
            let mut cb = vec![0.0; n];
            let mut cerr = None;
            for i in 0..n {
                match scalar.bound(i, &p(i), t.map(|t| t[i]), commit_load[i], s.omega[i]) {
                    Ok(b) => cb[i] = b,
                    Err(e) => {
                        cerr = Some((i, e));
                        break;
                    }
                }
            }
            let r = match &s.step {
                Some(h) => batch.commit_step(&ci, h),
                None => batch.commit(&ci),
            };
            if let Some((i, e)) = cerr {
                prop_assert_eq!(r, Err(BatchError::Model { index: i, source: e }));
                continue;
            }
            prop_assert!(r.is_ok());
            bounds = cb;
        }
        let (mut h, mut w, mut u) = (vec![0.0; n], vec![0.0; n], vec![false; n]);
        batch.last_steps(&mut h, &mut w, &mut u).unwrap();
        for i in 0..n {
            match &s.step {
                Some(step) => states[i].commit_step(s.angle[i], s.omega[i], bounds[i], step[i]),
                None => states[i].commit(s.angle[i], bounds[i]),
            }
            let (tau, a) = batch.state(i);
            prop_assert_eq!(tau.to_bits(), states[i].presliding_torque().to_bits(), "joint {} state", i);
            prop_assert_eq!(a.to_bits(), states[i].reference_angle().to_bits());
            let (sh, sw) = states[i].last_step();
            prop_assert_eq!((h[i].to_bits(), w[i].to_bits(), u[i]), (sh.to_bits(), sw.to_bits(), states[i].is_unreferenced()));
            prop_assert_eq!(&batch.joint_law(i), states[i].law());
        }
    }
    Ok(())
}

fn mu_params() -> impl Strategy<Value = Params> {
    (0.08..0.16f64, 0.7..1.4f64).prop_map(|(mu, eta)| {
        let mut p = Params::default();
        p.friction.boundary_friction_coefficient = mu;
        p.lubricant.viscosity *= eta;
        p
    })
}

/// Viscosities a table level can be built with over the envelope's ghost nodes.
fn mild_params() -> impl Strategy<Value = Params> {
    (0.08..0.16f64, 0.7..1.0f64).prop_map(|(mu, eta)| {
        let mut p = Params::default();
        p.friction.boundary_friction_coefficient = mu;
        p.lubricant.viscosity *= eta;
        p
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn full_shared_params(s in scene(7, 25, true), p in mu_params()) {
        check(&[p], false, Fidelity::Full, &s)?;
    }

    #[test]
    fn full_per_joint_params(s in scene(6, 20, true), p in prop::collection::vec(mu_params(), 6)) {
        check(&p, true, Fidelity::Full, &s)?;
    }

    #[test]
    fn boundary_per_joint_params(s in scene_in(5, 20, true, 283.0, false), p in prop::collection::vec(mild_params(), 5)) {
        check(&p, true, Fidelity::Boundary, &s)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Host inertia, the host's steps, wrapped angles and a first angle pending: n scalar
    /// joints driven the same way, bit for bit.
    #[test]
    fn host_conventions_full(s in scene_in(6, 25, true, 240.0, true), p in prop::collection::vec(mu_params(), 6), h in host_strategy(6), pj in any::<bool>()) {
        check_host(&p, pj, Fidelity::Full, &s, &h)?;
    }

    #[test]
    fn host_conventions_boundary(s in scene_in(4, 15, true, 283.0, true), p in prop::collection::vec(mild_params(), 4), h in host_strategy(4)) {
        check_host(&p, true, Fidelity::Boundary, &s, &h)?;
    }
}

proptest! {
    // Every table build costs milliseconds: fewer cases, few temperatures.
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    #[test]
    fn table_shared_params(s in scene(9, 20, false), p in mild_params()) {
        check(&[p], false, Fidelity::Table, &s)?;
    }

    #[test]
    fn table_and_auto_with_temperatures(s in scene_in(3, 6, true, 283.0, false), p in prop::collection::vec(mild_params(), 3), auto in any::<bool>()) {
        check(&p, true, if auto { Fidelity::Auto } else { Fidelity::Table }, &s)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4, ..ProptestConfig::default() })]

    /// More joints than one rayon chunk: the parallel path, the same numbers.
    #[test]
    fn many_joints_on_every_thread(s in scene(1500, 4, true), p in mu_params()) {
        check(&[p], false, Fidelity::Full, &s)?;
    }

    #[test]
    fn many_joints_with_host_conventions(s in scene_in(1200, 4, true, 240.0, true), p in mu_params(), h in host_strategy(1200)) {
        check_host(&[p], false, Fidelity::Full, &s, &h)?;
    }
}

#[test]
fn bad_inputs_name_the_argument_and_the_index() {
    let n = 4;
    let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), Settings::default()).unwrap();
    let (a, w, l) = (vec![0.0; n], vec![0.1; n], vec![2e4; n]);
    let mut out = vec![0.0; n];
    let short = vec![0.1; 3];
    let e = b.torque(&Inputs { angle: &a, angular_velocity: &short, load: &l, temperature: None }, &mut out).unwrap_err();
    assert_eq!(e.to_string(), "angular_velocity has 3 values, the batch has 4 joints: every input must have one value per joint");
    let mut l2 = l.clone();
    l2[2] = f64::NAN;
    let e = b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l2, temperature: None }, &mut out).unwrap_err();
    assert_eq!(e.to_string(), "load = NaN N at index 2 is not a finite number");
    let mut a2 = a.clone();
    a2[3] = f64::INFINITY;
    let e = b.commit(&Inputs { angle: &a2, angular_velocity: &w, load: &l, temperature: None }).unwrap_err();
    assert_eq!(e, BatchError::NotFinite { argument: "angle", index: 3, value: f64::INFINITY, unit: "rad" });
    let t = [293.15, f64::NAN, 293.15, 293.15];
    let e = b.torque(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: Some(&t) }, &mut out).unwrap_err();
    assert_eq!(e.to_string(), "temperature = NaN K at index 1 is not a finite number");
    let t = [293.15, 293.15, 293.15, 1e4];
    let e = b.torque(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: Some(&t) }, &mut out).unwrap_err();
    assert!(matches!(e, BatchError::Temperature { index: 3, .. }), "{e}");
    assert!(e.to_string().contains("lubricant.temperature"), "{e}");
    let mut l3 = l.clone();
    l3[1] = 1e12;
    let e = b.torque(&Inputs { angle: &a, angular_velocity: &w, load: &l3, temperature: None }, &mut out).unwrap_err();
    assert!(matches!(e, BatchError::Model { index: 1, source: ModelError::BeyondCapacity { .. } }), "{e}");
    // Nothing changed by the failed calls: the states are still at rest.
    for i in 0..n {
        assert_eq!(b.state(i), (0.0, 0.0));
    }
    assert_eq!(PreslidingBatch::new(0, BatchParams::Shared(Params::default()), Presliding::default(), Settings::default()).unwrap_err(), BatchError::Empty);
    let e = PreslidingBatch::new(3, BatchParams::PerJoint(vec![Params::default(); 2]), Presliding::default(), Settings::default()).unwrap_err();
    assert_eq!(e, BatchError::ParamCount { expected: 3, got: 2 });
    let mut bad = Params::default();
    bad.friction.boundary_friction_coefficient = -1.0;
    let e = PreslidingBatch::new(2, BatchParams::PerJoint(vec![Params::default(), bad]), Presliding::default(), Settings::default()).unwrap_err();
    assert!(matches!(e, BatchError::Params { index: 1, .. }), "{e}");
}

/// Joints at one temperature share one model; a model no joint uses is dropped.
#[test]
fn models_are_shared_and_released() {
    let n = 50;
    let s = Settings { fidelity: Fidelity::Table, ..Settings::default() };
    let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), s).unwrap();
    let (a, w, l) = (vec![0.0; n], vec![0.5; n], vec![2e4; n]);
    let mut out = vec![0.0; n];
    b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: None }, &mut out).unwrap();
    assert_eq!(b.models_held(), 1);
    let t: Vec<f64> = (0..n).map(|i| if i % 2 == 0 { 293.15 } else { 303.15 }).collect();
    b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: Some(&t) }, &mut out).unwrap();
    assert_eq!(b.models_held(), 2);
    let t = vec![310.0; n];
    b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: Some(&t) }, &mut out).unwrap();
    // In use: 310 K; retained: 293.15 K and 303.15 K.
    assert_eq!(b.models_held(), 3);
    // Back to 293.15 K: the retained model, no new one.
    b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: None }, &mut out).unwrap();
    assert_eq!(b.models_held(), 3);
    // Many temperatures one after another: at most RETAINED kept beside the one in use, and
    // no more than LEVELS_MAX tables held.
    for k in 0..10 {
        let t = vec![300.0 + f64::from(k); n];
        b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: Some(&t) }, &mut out).unwrap();
        assert!(b.tables_held() <= pinjoint::batch::cache::LEVELS_MAX, "{}", b.tables_held());
    }
    assert_eq!(b.models_held(), (1 + pinjoint::batch::cache::RETAINED).min(pinjoint::batch::cache::LEVELS_MAX));
}

/// Joints at temperatures (or with parameter sets) of their own at a level: at most
/// LEVELS_MAX tables are built and held whatever their number (before, 40 temperatures held 40
/// tables: 1 GB and 6 s a step); the first keys (lowest joint index) are the level's answer,
/// bit for bit the scalar evaluator's at their temperature, the others the complete solve's,
/// bit for bit `Joint::evaluate`'s; every torque within the level's tolerance of the complete
/// solve. Moving every temperature each step keeps the bound.
#[test]
fn levels_are_bounded_whatever_the_temperatures_and_sets() {
    use pinjoint::batch::cache::LEVELS_MAX;
    let n = 24;
    let env = Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap();
    let settings = Settings { fidelity: Fidelity::Table, tolerance: 1e-4, envelope: env };
    let t: Vec<f64> = (0..n).map(|i| 260.0 + 3.0 * i as f64).collect();
    let (load, omega) = (vec![2e4; n], vec![0.7; n]);
    let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), settings).unwrap();
    let mut out = vec![0.0; n];
    b.sliding_torque(&load, &omega, Some(&t), &mut out).unwrap();
    assert_eq!(b.tables_held(), LEVELS_MAX);
    assert!(b.models_held() <= n + pinjoint::batch::cache::RETAINED);
    for i in 0..n {
        let mut p = Params::default();
        p.lubricant.temperature = t[i];
        let full = Joint::new(&p).unwrap().evaluate(2e4, 0.7).unwrap().torque;
        if i < LEVELS_MAX {
            let ev = Evaluator::new(&p, Fidelity::Table, 1e-4, env).unwrap();
            assert_eq!(out[i].to_bits(), ev.torque_inside(2e4, 0.7).unwrap().to_bits(), "joint {i}: the table's");
            assert!(((out[i] - full) / full).abs() <= 1e-4, "joint {i}");
        } else {
            assert_eq!(out[i].to_bits(), full.to_bits(), "joint {i}: the complete solve's");
        }
    }
    // Every temperature moves at every step: still at most LEVELS_MAX tables.
    let a = vec![0.0; n];
    for k in 1..6 {
        let tk: Vec<f64> = t.iter().map(|x| x + 0.1 * f64::from(k)).collect();
        b.step(&Inputs { angle: &a, angular_velocity: &omega, load: &load, temperature: Some(&tk) }, &mut out).unwrap();
        assert!(b.tables_held() <= LEVELS_MAX, "step {k}: {}", b.tables_held());
        assert!(out.iter().all(|x| x.is_finite()));
    }
    // Parameter sets of their own (a Monte Carlo of μ_c): the same bound.
    let sets: Vec<Params> = (0..n)
        .map(|i| {
            let mut p = Params::default();
            p.friction.boundary_friction_coefficient = 0.10 + 0.001 * i as f64;
            p
        })
        .collect();
    let mut b = PreslidingBatch::new(n, BatchParams::PerJoint(sets.clone()), Presliding::default(), settings).unwrap();
    b.sliding_torque(&load, &omega, None, &mut out).unwrap();
    assert_eq!(b.tables_held(), LEVELS_MAX);
    for (i, p) in sets.iter().enumerate().skip(LEVELS_MAX) {
        assert_eq!(out[i].to_bits(), Joint::new(p).unwrap().evaluate(2e4, 0.7).unwrap().torque.to_bits(), "set {i}");
    }
}

/// A level that cannot be built for one joint's parameters names that joint, and changes
/// nothing.
#[test]
fn a_level_that_cannot_be_built_names_the_joint() {
    // The paper's model (no journal bearing to bound the film) with a thicker oil: its film
    // passes the clearance at the table's ghost nodes, so no table can be built for it.
    let mut thick = Params::paper();
    thick.lubricant.viscosity *= 4.0;
    let s = Settings { fidelity: Fidelity::Table, tolerance: 1e-3, envelope: Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap() };
    let mut b = PreslidingBatch::new(3, BatchParams::PerJoint(vec![Params::default(), thick, thick]), Presliding::default(), s).unwrap();
    let (a, w, l) = (vec![0.0; 3], vec![0.5; 3], vec![2e4; 3]);
    let mut out = vec![0.0; 3];
    let e = b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: None }, &mut out).unwrap_err();
    assert!(matches!(e, BatchError::Level { index: 1, .. }), "{e}");
    assert!(e.to_string().starts_with("fidelity level for the joint at index 1: "), "{e}");
    assert_eq!(b.models_held(), 0);
    assert_eq!(b.state(0), (0.0, 0.0));
}

/// A bad host step or host inertia names the argument and the joint, and changes nothing.
#[test]
fn bad_steps_and_inertias_name_the_joint() {
    let n = 3;
    let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), Settings::default()).unwrap();
    let (a, w, l) = (vec![1e-4; n], vec![0.1; n], vec![2e4; n]);
    let inputs = Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: None };
    let e = b.commit_step(&inputs, &[1e-3, -1e-3, 1e-3]).unwrap_err();
    assert_eq!(e.to_string(), "step = -0.001 s at index 1 is invalid: it must be a finite number >= 0");
    let e = b.step_with(&inputs, &[1e-3, 1e-3, f64::NAN], &mut [0.0; 3]).unwrap_err();
    assert!(matches!(e, BatchError::Step { index: 2, .. }), "{e}");
    let e = b.commit_step(&inputs, &[1e-3; 2]).unwrap_err();
    assert_eq!(e, BatchError::Shape { argument: "step", expected: 3, got: 2 });
    assert_eq!(b.state(0), (0.0, 0.0));
    let e = b.set_host_inertia(Some(&[10.0, -1.0, 10.0])).unwrap_err();
    assert_eq!(e.to_string(), "host_inertia = -1 kg.m2 at index 1 is invalid: it must be a number in [0, 1e9] kg.m2 (0: not given)");
    assert!(matches!(b.set_host_inertia(Some(&[10.0, 10.0, f64::INFINITY])), Err(BatchError::HostInertia { index: 2, .. })));
    assert!(b.host_inertia().is_none() && b.joint_law(0).host_inertia == 0.0);
}

/// Independent of the scalar object: a host that wraps its angle into (−π, π] (or shifts it
/// by turns) gets the torques of a host that reports the continuous angle, when it gives its
/// steps; and the host inertia's damping is capped at the step given (a lighter body at a
/// longer step: less damping torque).
#[test]
fn a_wrapped_angle_reads_as_the_continuous_one() {
    let n = 4;
    let h = 1e-3;
    let new = || {
        let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), Settings::default()).unwrap();
        b.set_host_inertia(Some(&[0.0, 1.0, 30.0, 1e3])).unwrap();
        b
    };
    let (mut cont, mut wrapped) = (new(), new());
    let (mut oc, mut ow) = (vec![0.0; n], vec![0.0; n]);
    let l = vec![2e4; n];
    let mut max_diff: f64 = 0.0;
    for k in 0..4000 {
        let t = f64::from(k) * h;
        // Oscillating about π: small presliding strokes and slides through ±π.
        let w: Vec<f64> = (0..n).map(|i| 0.5 * (1.0 + i as f64) * (7.0 * t).cos()).collect();
        let x: Vec<f64> = (0..n).map(|i| 3.1 + 0.5 * (1.0 + i as f64) / 7.0 * (7.0 * t).sin()).collect();
        let xw: Vec<f64> = x.iter().enumerate().map(|(i, &x)| report(x, if i % 2 == 0 { 1 } else { 2 }, -(i as i32))).collect();
        let steps = vec![h; n];
        cont.step_with(&Inputs { angle: &x, angular_velocity: &w, load: &l, temperature: None }, &steps, &mut oc).unwrap();
        wrapped.step_with(&Inputs { angle: &xw, angular_velocity: &w, load: &l, temperature: None }, &steps, &mut ow).unwrap();
        for i in 0..n {
            max_diff = max_diff.max((oc[i] - ow[i]).abs());
        }
    }
    // The increments differ only by the rounding of x ± 2π: far below the torque's scale.
    assert!(max_diff < 1e-6, "{max_diff}");
    assert!(cont.joint_law(1).step == h && cont.joint_law(3).host_inertia == 1e3);
    // The damping cap: J = 1 kg·m² at h = 10 ms is capped (0.9·J/h·min(1, 2 − h²k/J)).
    let law = cont.joint_law(1);
    let k = 100.0 / law.angle;
    let capped = law.at_step(1e-2).damping(k);
    assert!(capped < law.at_step(0.0).damping(k) && capped <= 0.9 * 1.0 / 1e-2, "{capped}");
}

/// The error of the lowest joint index is the one returned, whatever mixes of bad inputs and
/// model errors the blocks and chunks of the passes hold (a load beyond capacity just before a
/// NaN in one block, errors in several chunks), and a failed call changes no state, from
/// states away from rest.
#[test]
fn the_lowest_failing_joint_is_named_and_nothing_changes() {
    let n = 1500; // three rayon chunks
    for fidelity in [Fidelity::Table, Fidelity::Full] {
        let mut b = PreslidingBatch::new(n, BatchParams::Shared(Params::default()), Presliding::default(), settings(fidelity)).unwrap();
        let angle: Vec<f64> = (0..n).map(|i| 1e-4 * (1.0 + (i % 7) as f64)).collect();
        let omega: Vec<f64> = (0..n).map(|i| 0.05 + 0.01 * (i % 11) as f64).collect();
        let load: Vec<f64> = (0..n).map(|i| 8e3 + 10.0 * i as f64).collect();
        let mut out = vec![0.0; n];
        b.step(&Inputs { angle: &angle, angular_velocity: &omega, load: &load, temperature: None }, &mut out).unwrap();
        let states = |b: &PreslidingBatch| (0..n).map(|i| b.state(i)).collect::<Vec<_>>();
        let before = states(&b);
        assert!(before.iter().all(|&(t, _)| t != 0.0));
        let capacity = 1e12;
        // (what to spoil at which joint: 0 a NaN load, 1 beyond capacity, 2 an infinite ω, 3 a NaN
        // angle; the joint named; whether a model error)
        type Case = (&'static [(usize, u8)], usize, bool);
        let cases: [Case; 5] = [
            (&[(17, 0), (16, 1)], 16, true),   // beyond capacity before a NaN load, one block
            (&[(16, 0), (17, 1)], 16, false),  // a NaN load before beyond capacity
            (&[(1200, 2), (900, 1)], 900, true), // chunks 2 and 1
            (&[(1200, 1), (300, 3), (301, 1)], 300, false), // a NaN angle first
            (&[(1499, 1)], 1499, true),
        ];
        for (spoil, index, model) in cases {
            let (mut a, mut w, mut l) = (angle.clone(), omega.clone(), load.clone());
            for &(i, how) in spoil {
                match how {
                    0 => l[i] = f64::NAN,
                    1 => l[i] = capacity,
                    2 => w[i] = f64::INFINITY,
                    _ => a[i] = f64::NAN,
                }
            }
            let e = b.step(&Inputs { angle: &a, angular_velocity: &w, load: &l, temperature: None }, &mut out).unwrap_err();
            if model {
                assert!(matches!(e, BatchError::Model { index: i, source: ModelError::BeyondCapacity { .. } } if i == index), "{fidelity}: {e}");
            } else {
                assert!(matches!(e, BatchError::NotFinite { index: i, .. } if i == index), "{fidelity}: {e}");
            }
            assert_eq!(states(&b), before, "{fidelity}: a failed step changed a state");
        }
    }
}
