//! What the per-evaluation measurements share (`pinjoint-bench`'s bench_eval and the
//! criterion bench benches/fidelity.rs, which includes this file): the Lissajous path through
//! an envelope, the median time per evaluation along it, and the largest errors against the
//! cold full solve on the path and on random points of the envelope.

use pinjoint::fidelity::check::CheckRng;
use pinjoint::fidelity::{Envelope, ErrorReport, Evaluator};
use pinjoint::Joint;
use std::hint::black_box;
use std::time::Instant;

/// `n` points of a Lissajous path through `env` in (ln P, ln |ω|): consecutive points are close,
/// as in a time-stepping host (so a warm start has a neighbour), and ω changes sign.
pub fn path(env: &Envelope, n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|k| {
            let s = k as f64 / n as f64 * std::f64::consts::TAU;
            let (p, w) = env.at_log_fraction(0.5 + 0.5 * (3.0 * s).sin(), 0.5 - 0.5 * (7.0 * s).cos());
            (p, if (7.0 * s).sin() >= 0.0 { w } else { -w })
        })
        .collect()
}

/// Median over `reps` repetitions of the time per evaluation of `f` along `pts`, ns.
pub fn ns_per_eval(mut f: impl FnMut(f64, f64) -> f64, pts: &[(f64, f64)], reps: usize) -> f64 {
    let mut v: Vec<f64> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            let mut acc = 0.0;
            for &(p, w) in pts {
                acc += f(black_box(p), black_box(w));
            }
            black_box(acc);
            t.elapsed().as_secs_f64() * 1e9 / pts.len() as f64
        })
        .collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Largest errors of `ev` against the cold full solve `j` on `pts` and on `random` points of
/// the envelope drawn from `seed`.
pub fn errors(ev: &mut Evaluator, j: &Joint, pts: &[(f64, f64)], random: usize, seed: u64) -> ErrorReport {
    let env = *ev.envelope();
    let mut rng = CheckRng::new(seed);
    let rand = (0..random).map(|_| env.at_log_fraction(rng.uniform(), rng.uniform()));
    let mut r = ErrorReport::default();
    for (p, w) in pts.iter().copied().chain(rand) {
        r.add(&ev.evaluate(p, w).expect("inside the model's range"), &j.evaluate(p, w).expect("inside the model's range"));
    }
    r
}
