//! The rig on the cold day (issue 37, item 6): the grease's running torque
//! T(ω) = T(0⁺) + c·ω^n with n < 1 has an infinite slope at rest, and the hybrid
//! formulation's event logic must neither chatter nor refuse on it anywhere in
//! −55..+120 °C × 5..60 kN × 0.03..1 Hz, with the default grease and one 1.5× stiffer
//! (consistency and yield stress × 1.5).
//!
//! Each run is checked for what the physics demands, not for numbers:
//! - no refusal, and no burst of near-coincident events (the slip's zero of ω is an event only
//!   where the law's one-sided limit at rest lets the joint stop, `rig/sim.rs`);
//! - the energy the friction dissipates over each whole stroke is ≥ 0, and the balance
//!   W − D = ΔE_kin closes to the integration tolerance;
//! - in stick the friction (the reaction −T_a) is within the breakaway torque; in slip it
//!   opposes the motion and is the core's running torque at |ω|;
//! - the trajectory converges as the integrator's tolerance shrinks (the law is integrated
//!   exactly, no regularisation: the answer is the event-exact one to the tolerance).

use pinjoint::rig::{RigConfig, RigSim, Sample};
use proptest::prelude::*;

/// The default rig at (temperature K, load N, frequency Hz), its grease's consistency and yield
/// stress multiplied by `stiffer` (whatever the defaults are).
fn config(temperature: f64, load: f64, frequency: f64, stiffer: f64) -> RigConfig {
    let mut c = RigConfig::default();
    c.model.lubricant.temperature = temperature;
    c.model.grease.consistency *= stiffer;
    c.model.grease.yield_stress *= stiffer;
    c.rig.load = load;
    c.rig.frequency = frequency;
    c
}

/// `cycles` strokes sampled `per_cycle` times each.
fn simulate(c: &RigConfig, cycles: f64, per_cycle: usize) -> (RigSim, Vec<Sample>) {
    let mut sim = RigSim::new(c).unwrap_or_else(|e| panic!("{e}"));
    let p = c.rig.period();
    let tr = sim.run(cycles * p, p / per_cycle as f64).unwrap_or_else(|e| {
        panic!("T = {} K, P = {} N, f = {} Hz, K = {} Pa.s^n: {e}", c.model.lubricant.temperature, c.rig.load, c.rig.frequency, c.model.grease.consistency)
    });
    (sim, tr)
}

/// The physical checks of one run (see the module documentation).
fn check(c: &RigConfig, sim: &RigSim, tr: &[Sample], per_cycle: usize) {
    let what = format!("T = {} K, P = {} N, f = {} Hz, K = {} Pa.s^n", c.model.lubricant.temperature, c.rig.load, c.rig.frequency, c.model.grease.consistency);
    let joint = sim.joint();
    let breakaway = c.rig.breakaway_factor * joint.boundary_torque(c.rig.load);
    let stats = sim.stats();
    assert!(stats.max_event_burst <= 3, "{what}: a burst of {} near-coincident events ({stats:?})", stats.max_event_burst);
    for s in tr {
        assert!(s.torque.abs() <= c.rig.torque_limit * (1.0 + 1e-12), "{what}: {s:?}");
        if s.stuck {
            assert_eq!(s.angular_velocity, 0.0, "{what}: {s:?}");
            // Stick holds while |T_a| is within the breakaway torque (an event located to
            // 1e-10 s: the torque's rate times that, far below 1e-9 relative).
            assert!(s.friction_torque.abs() <= breakaway * (1.0 + 1e-9), "{what}: stuck with |T_f| = {} > {breakaway} N.m", s.friction_torque.abs());
        } else if s.angular_velocity.abs() > 1e-6 {
            // Slip: the friction opposes the motion and is the core's running torque at |ω|
            // (to the warm-started solve's tolerance).
            assert!(s.friction_torque * s.angular_velocity < 0.0, "{what}: {s:?}");
            let running = joint.evaluate(s.load, s.angular_velocity.abs()).unwrap().torque;
            assert!((s.friction_torque.abs() - running).abs() <= 1e-6 * running, "{what}: {} vs {running}", s.friction_torque.abs());
        }
    }
    // Whole strokes: the dissipation over each is ≥ 0 (more than a stick's nothing: the pin
    // moves every stroke), and the energy balance closes.
    let strokes = (tr.len() - 1) / per_cycle;
    for k in 0..strokes {
        let (a, b) = (&tr[k * per_cycle], &tr[(k + 1) * per_cycle]);
        let dissipated = b.friction_dissipation - a.friction_dissipation;
        assert!(dissipated > 0.0, "{what}: stroke {k} dissipates {dissipated} J");
        let residual = (b.actuator_work - a.actuator_work) - dissipated - (b.kinetic_energy - a.kinetic_energy);
        assert!(residual.abs() <= 1e-6 * dissipated + 1e-9, "{what}: stroke {k}: energy residual {residual} J of {dissipated} J");
    }
}

/// The points where the event logic refused before (issue 37): −55 °C at 5 kN, 0.3 Hz and at
/// 60 kN, 0.03 Hz; −40 °C with a grease 1.4× stiffer.
#[test]
fn the_points_that_chattered_run() {
    for (t, p, f, k) in [(218.15, 5e3, 0.3, 1.0), (218.15, 60e3, 0.03, 1.0), (233.15, 20e3, 1.0, 1.4), (233.15, 5e3, 0.3, 1.4)] {
        let c = config(t, p, f, k);
        let per = 400;
        let (sim, tr) = simulate(&c, 2.0, per);
        check(&c, &sim, &tr, per);
        let s = sim.stats();
        println!("{t} K, {p} N, {f} Hz, x{k}: {s:?}");
        assert!(s.sticks + s.breakaways >= 2, "it sticks at the reversals: {s:?}");
    }
}

/// The corners of the box (coarse: the default test; `rig_cold_box` in proptest below
/// samples its inside).
#[test]
fn the_box_corners_run_and_are_physical() {
    for t in [218.15, 393.15] {
        for p in [5e3, 60e3] {
            for f in [0.03, 1.0] {
                for k in [1.0, 1.5] {
                    let c = config(t, p, f, k);
                    // One and a half strokes at 0.03 Hz (50 s of rig time), two at 1 Hz.
                    let cycles = if f < 0.1 { 1.0 } else { 2.0 };
                    let per = 200;
                    let (sim, tr) = simulate(&c, cycles, per);
                    check(&c, &sim, &tr, per);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// Random points of the box: the same checks.
    #[test]
    fn rig_cold_box(
        celsius in -55.0f64..=120.0,
        load in 5e3f64..=60e3,
        log_f in (0.03f64).ln()..=0.0,
        stiffer in prop::sample::select(vec![1.0, 1.5]),
    ) {
        let f = log_f.exp();
        let c = config(celsius + 273.15, load, f, stiffer);
        let cycles = if f < 0.1 { 1.0 } else { 2.0 };
        let per = 200;
        let (sim, tr) = simulate(&c, cycles, per);
        check(&c, &sim, &tr, per);
    }
}

/// The worst of the refusing points at a tolerance 100× tighter: the stroke's mean |T_a| and
/// the trace converge (the law is integrated as it is, so the tighter run is closer to the
/// event-exact trajectory; the difference is of the tolerance's order, not of a
/// regularisation's).
#[test]
fn the_cold_answer_converges_in_the_step_tolerance() {
    for (t, p, f, k) in [(218.15, 5e3, 0.3, 1.5), (218.15, 60e3, 0.03, 1.0)] {
        let mean_abs = |rtol: f64, atol: f64| {
            let mut c = config(t, p, f, k);
            c.rig.rtol = rtol;
            c.rig.atol = atol;
            let per = 1000;
            let (_, tr) = simulate(&c, 2.0, per);
            let second = &tr[per..];
            let mean = second.iter().map(|s| s.torque.abs()).sum::<f64>() / second.len() as f64;
            (mean, tr)
        };
        let (m0, a) = mean_abs(1e-6, 1e-7);
        let (m1, b) = mean_abs(1e-8, 1e-9);
        let (m2, c) = mean_abs(1e-10, 1e-11);
        let peak = c.iter().map(|s| s.torque.abs()).fold(0.0, f64::max);
        let dev = |x: &[Sample], y: &[Sample]| x.iter().zip(y).map(|(u, v)| (u.torque - v.torque).abs()).fold(0.0, f64::max) / peak;
        let (d0, d1) = ((m0 - m2).abs() / m2, (m1 - m2).abs() / m2);
        println!("{t} K, {p} N, {f} Hz, x{k}: mean |T| {m0} / {m1} / {m2} N.m; trace {:.2e} / {:.2e} of the peak", dev(&a, &c), dev(&b, &c));
        assert!(d1 < 1e-5, "mean |T| at the default tolerance off the tight one by {d1:.2e}");
        assert!(d1 <= d0.max(1e-9), "no convergence: {d0:.2e} then {d1:.2e}");
        assert!(dev(&b, &c) < 1e-3, "trace at the default tolerance off by {:.2e} of the peak", dev(&b, &c));
    }
}
