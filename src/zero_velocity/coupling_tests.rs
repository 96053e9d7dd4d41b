//! Tests of the parallel (Jacobi) coupling ([`HostCoupling::Parallel`]): a body J on the pin
//! integrated here with the torque of the previous communication point, as libcosim and Ecos
//! couple, against what is independent of the code: the drift and the sign changes of the
//! body's motion, and the eigenvalues of the delayed loop. The sliding torque is held constant
//! (the friction model is not under test).

use super::joint::PreslidingJoint;
use super::presliding::{HostCoupling, Presliding, PARALLEL_LOOP_GAIN};

/// The sliding torque of the paper's joint at 60 kN, rounded (N·m): μ_c·R·P = 0.12·0.028·60e3.
const T60: f64 = 201.6;

/// How the host's body integrates the torque it holds over a step.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Body {
    /// ω ← ω + h·a, θ ← θ + h·ω (the new ω).
    SymplecticEuler,
    /// θ ← θ + h·ω (the old ω), ω ← ω + h·a.
    ExplicitEuler,
    /// Exact with the torque held: θ ← θ + h·ω + h²·a/2, ω ← ω + h·a.
    Exact,
}

struct Run {
    theta: Vec<f64>,
    omega: Vec<f64>,
}

/// A body `j` under `drive(t)` and the joint's friction at `bound`, stepped at `h` for `t_end`:
/// `parallel` integrates the torque the joint gave at the previous communication point (a
/// Jacobi master), else the one of this step (a sequential host). Samples at t_n.
fn run(law: Presliding, j: f64, body: Body, h: f64, t_end: f64, parallel: bool, drive: impl Fn(f64) -> f64) -> Run {
    let mut joint = PreslidingJoint::new(law, 0.0);
    let (mut theta, mut omega, mut held) = (0.0_f64, 0.0_f64, 0.0_f64);
    let n = (t_end / h).round() as usize;
    let mut r = Run { theta: Vec::with_capacity(n), omega: Vec::with_capacity(n) };
    for i in 0..n {
        let t = i as f64 * h;
        r.theta.push(theta);
        r.omega.push(omega);
        let now = joint.step(theta, omega, T60, Some(h));
        let torque = if parallel { held } else { now };
        held = now;
        let a = (drive(t) + torque) / j;
        match body {
            Body::SymplecticEuler => {
                omega += h * a;
                theta += h * omega;
            }
            Body::ExplicitEuler => {
                theta += h * omega;
                omega += h * a;
            }
            Body::Exact => {
                theta += h * omega + 0.5 * h * h * a;
                omega += h * a;
            }
        }
        assert!(theta.is_finite() && omega.abs() < 1e6, "the loop diverged at t = {t}");
    }
    r
}

/// Sign changes of ω over samples `from..` (|ω| < 1e-7 rad/s counts as zero: a ring of a heavy
/// body decaying below that moves less than the drift bound).
fn sign_changes(omega: &[f64], from: usize) -> usize {
    let mut last = 0.0;
    let mut n = 0;
    for &w in &omega[from..] {
        let s = if w > 1e-7 { 1.0 } else if w < -1e-7 { -1.0 } else { 0.0 };
        if s != 0.0 {
            if last != 0.0 && s != last {
                n += 1;
            }
            last = s;
        }
    }
    n
}

/// The scene of issue 38: hold at 0.5·T for 2 s, a ramp to 1.5·T over 2 s (breakaway), then
/// 0.3·T: the body slows under friction, stops and rests for about 3.5 s.
fn scene(t: f64) -> f64 {
    if t < 2.0 {
        0.5 * T60
    } else if t < 4.0 {
        (0.5 + 0.5 * (t - 2.0)) * T60
    } else {
        0.3 * T60
    }
}

fn law(j: f64, coupling: HostCoupling) -> Presliding {
    Presliding::default().with_host_inertia(j).unwrap().with_coupling(coupling)
}

/// Under a Jacobi master, J = 20 and 50 kg·m² at 60 kN hold, break away and come to rest at
/// 1 and 10 ms, for every body integrator: drift ≤ 1e-6 rad over the last 2 s of each rest,
/// no sign change of ω once settled. The sequential law under the same master does not
/// (the failure: it never comes to rest at 10 ms), and stays what it was under a
/// sequential host.
#[test]
fn parallel_coupling_holds_breaks_away_and_rests() {
    let at = |h: f64, t: f64| (t / h).round() as usize;
    for h in [1e-3, 1e-2] {
        for j in [20.0, 50.0, 1400.0] {
            for body in [Body::SymplecticEuler, Body::ExplicitEuler, Body::Exact] {
                let r = run(law(j, HostCoupling::Parallel), j, body, h, 10.0, true, scene);
                let what = format!("J = {j}, h = {h}, {body:?}");
                // The hold: settled by 1 s (1400 kg·m² by 1.5 s), still over 1.5..2 s.
                let settle = if j > 100.0 { 1.5 } else { 1.0 };
                let drift = (r.theta[at(h, 2.0) - 1] - r.theta[at(h, settle)]).abs();
                assert!(drift <= 1e-6, "{what}: the hold drifts {drift:e} rad");
                assert_eq!(sign_changes(&r.omega[..at(h, 2.0)], at(h, settle)), 0, "{what}: chatter in the hold");
                // The breakaway: the body slides well beyond the presliding range T/k (k the
                // stiffness the law holds the body with at this step).
                let slid = r.theta[at(h, 4.0)] - r.theta[at(h, 2.0)];
                let range = T60 / law(j, HostCoupling::Parallel).at_step(h).stiffness(T60);
                assert!(slid > 3.0 * range, "{what}: slid only {slid} rad");
                // The rest: stopped by 6 s, no motion left over 6..10 s.
                let drift = (r.theta[at(h, 10.0) - 1] - r.theta[at(h, 6.0)]).abs();
                assert!(drift <= 1e-6, "{what}: the rest drifts {drift:e} rad");
                assert_eq!(sign_changes(&r.omega, at(h, 6.0)), 0, "{what}: chatter at rest");
                // Where it rests, the joint holds the drive 0.3·T (no slip left).
                assert!(r.omega[at(h, 10.0) - 1].abs() < 1e-9, "{what}: still moving");
            }
        }
    }
    // The law for a sequential host under a Jacobi master: the failure at 10 ms.
    for j in [20.0, 50.0] {
        let r = run(law(j, HostCoupling::Sequential), j, Body::SymplecticEuler, 1e-2, 10.0, true, scene);
        assert!(sign_changes(&r.omega, 600) > 20, "J = {j}: the sequential law was expected to chatter under parallel coupling");
    }
}

/// The sequential coupling is the law of before, bit for bit: the same torques as a law that
/// never heard of coupling, stiffness and damping alike.
#[test]
fn sequential_coupling_is_the_law_of_before() {
    let plain = Presliding::default().with_host_inertia(20.0).unwrap().at_step(1e-2);
    let seq = plain.with_coupling(HostCoupling::Sequential);
    assert_eq!(plain, seq);
    assert_eq!(HostCoupling::default(), HostCoupling::Sequential);
    let par = plain.with_coupling(HostCoupling::Parallel);
    assert_eq!(seq.stiffness(T60).to_bits(), (T60 / seq.angle).to_bits());
    // Parallel: k capped at J/(27 h²), the damping 2ζ√(kJ) uncapped.
    let cap = PARALLEL_LOOP_GAIN * 20.0 / 1e-4;
    assert_eq!(par.stiffness(T60), cap);
    assert!((par.damping(cap) - 1.4 * (cap * 20.0_f64).sqrt()).abs() < 1e-9 * cap);
    // Without the host's inertia or step the cap has nothing to work with: the law of before.
    let unknown = Presliding::default().with_coupling(HostCoupling::Parallel).at_step(1e-2);
    assert_eq!(unknown.stiffness(T60), T60 / unknown.angle);
    let no_step = Presliding::default().with_host_inertia(20.0).unwrap().with_coupling(HostCoupling::Parallel);
    assert_eq!(no_step.stiffness(T60), T60 / no_step.angle);
    for code in 0..2 {
        assert_eq!(HostCoupling::from_code(code).unwrap().code(), code);
    }
    assert_eq!(HostCoupling::from_code(2), None);
}

/// The delayed loop's eigenvalues (the linearised stick: the body's integrator, the torque
/// −k·θ − c·ω of the previous step) have modulus < 0.87 at the cap for each body integrator,
/// and the stiffness cap is the bound the module derives: beyond b = 1/4 no damping holds.
#[test]
fn the_delayed_loop_is_stable_at_the_cap() {
    // One step of the delayed loop as a 4x4 matrix on (θ, h·ω, θ_prev, h·ω_prev), torques scaled by h²/J.
    let spectral_radius = |a: f64, b: f64, body: Body| -> f64 {
        // Power iteration on the growth of an arbitrary start over many steps.
        let step = |x: [f64; 4]| -> [f64; 4] {
            let u = -b * x[2] - a * x[3];
            let (th, wh) = match body {
                Body::SymplecticEuler => (x[0] + x[1] + u, x[1] + u),
                Body::ExplicitEuler => (x[0] + x[1], x[1] + u),
                Body::Exact => (x[0] + x[1] + 0.5 * u, x[1] + u),
            };
            [th, wh, x[0], x[1]]
        };
        let mut x = [1.0, -0.3, 0.2, 0.7];
        let n = 4000;
        let mut log = 0.0;
        for _ in 0..n {
            x = step(x);
            let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
            log += norm.ln();
            x = x.map(|v| v / norm);
        }
        (log / f64::from(n)).exp()
    };
    let b = PARALLEL_LOOP_GAIN;
    let a = 2.0 * super::presliding::HOST_DAMPING_RATIO * b.sqrt();
    for body in [Body::SymplecticEuler, Body::ExplicitEuler, Body::Exact] {
        let r = spectral_radius(a, b, body);
        assert!(r < 0.87, "{body:?}: {r}");
    }
    // b above a(1 − a) is unstable for the symplectic body (Jury), for any damping a.
    for a in [0.1, 0.3, 0.5, 0.7, 0.9] {
        assert!(spectral_radius(a, a * (1.0 - a) * 1.05, Body::SymplecticEuler) > 1.0, "a = {a}");
    }
    assert!(spectral_radius(0.0, 0.672, Body::SymplecticEuler) > 1.0, "J = 20, 60 kN, 10 ms uncapped");
}
