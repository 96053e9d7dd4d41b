//! Coverage of the quasi-static fit's 95 % intervals (issue 24 item 5): over 300 synthetic fits
//! (direct and rig records, J of 0, 0.05 and 2 kg·m² fitted or given, 5–60 kN, 0.5–1.5 Hz,
//! 0.2–1 N·m of torque noise, a 17-bit encoder at a random phase, a new seed each fit), the
//! intervals of μ_c and of J must cover the truth at close to the nominal rate.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint_calibrate::{calibrate, Calibration, Options, Record};

const TRUTH: f64 = 0.105;
const OFFSET: f64 = 0.3;
/// Cycles and samples a cycle of every record.
const CYCLES: usize = 8;
const SPC: usize = 1000;

/// One fit: the error over the standard error and whether the interval covers, for μ_c and
/// (when fitted) J.
struct Outcome {
    mu: (f64, bool),
    j: Option<(f64, bool)>,
}

fn outcome(c: &Calibration, j: f64) -> Outcome {
    let m = &c.estimates[0];
    Outcome {
        mu: ((m.value - TRUTH) / m.standard_error, m.ci95.0 <= TRUTH && TRUTH <= m.ci95.1),
        j: c.inertia_estimate.as_ref().map(|e| ((e.value - j) / e.standard_error, e.ci95.0 <= j && j <= e.ci95.1)),
    }
}

/// Covered count and rms of error/standard error of μ_c and of J over `out`.
fn tally(out: &[Outcome]) -> ((usize, usize, f64), (usize, usize, f64)) {
    let of = |v: Vec<(f64, bool)>| {
        let n = v.len();
        let rms = (v.iter().map(|x| x.0 * x.0).sum::<f64>() / n.max(1) as f64).sqrt();
        (v.iter().filter(|x| x.1).count(), n, rms)
    };
    (of(out.iter().map(|o| o.mu).collect()), of(out.iter().filter_map(|o| o.j).collect()))
}

fn report(what: &str, out: &[Outcome]) {
    let ((cm, nm, zm), (cj, nj, zj)) = tally(out);
    println!("{what:44} mu_c {cm:3}/{nm:3} (rms z {zm:.2})   J {cj:3}/{nj:3} (rms z {zj:.2})");
}

#[test]
fn the_95_percent_intervals_cover_the_truth_in_at_least_90_percent_of_300_fits() {
    // The bootstrap with 400 resamples (the default's 1000 only smooth its percentiles).
    let options = |inertia: Option<f64>| Options { inertia, resamples: 400, ..Options::default() };
    let mut all = Vec::new();
    // Direct records (prescribed sine, exact J·α): J, loads, frequency, noise; J fitted.
    let direct_cases = [
        (0.0, [20e3, 40e3], 1.0, 0.5),
        (0.0, [10e3, 60e3], 1.5, 1.0),
        (0.05, [20e3, 40e3], 1.0, 0.2),
        (0.05, [5e3, 30e3], 1.5, 0.5),
        (0.05, [20e3, 40e3], 0.5, 1.0),
        (2.0, [20e3, 40e3], 0.5, 0.5),
        (2.0, [10e3, 60e3], 1.0, 0.5),
        (2.0, [20e3, 40e3], 1.5, 0.5),
    ];
    // J given (subtracted, not fitted): J, loads, frequency, noise.
    let given_cases =
        [(0.05, [20e3, 40e3], 1.0, 0.5), (2.0, [10e3, 60e3], 1.0, 0.5), (2.0, [20e3, 40e3], 0.5, 0.2), (2.0, [20e3, 40e3], 1.5, 0.5)];
    for (k, &(j, loads, f, noise)) in direct_cases.iter().chain(&given_cases).enumerate() {
        let given = k >= direct_cases.len();
        let out: Vec<Outcome> = (0..20u64)
            .map(|seed| {
                let recs: Vec<Record> = loads
                    .iter()
                    .enumerate()
                    .map(|(i, &p)| direct_record(p, f, j, TRUTH, noise, OFFSET, (CYCLES, SPC as f64), 50_000 + 1000 * k as u64 + 10 * seed + i as u64))
                    .collect();
                outcome(&calibrate(&recs, &options(given.then_some(j))).expect("calibrates"), j)
            })
            .collect();
        report(&format!("direct J {j}{} {loads:?} N {f} Hz noise {noise}", if given { " given" } else { "" }), &out);
        all.extend(out);
    }
    // Rig records (`pinjoint cycle`'s simulation, run once per case; each seed draws new noise
    // and a new encoder phase): J fitted.
    let rig_cases = [(0.05, [20e3, 40e3], 1.0), (0.05, [10e3, 60e3], 1.5), (2.0, [20e3, 40e3], 1.0), (2.0, [10e3, 60e3], 0.5)];
    for (k, &(j, loads, f)) in rig_cases.iter().enumerate() {
        let runs: Vec<_> = loads
            .iter()
            .map(|&p| {
                let mut cfg = RigConfig::default();
                cfg.model.friction.boundary_friction_coefficient = TRUTH;
                (cfg.rig.load, cfg.rig.frequency, cfg.rig.inertia, cfg.rig.breakaway_factor) = (p, f, j, 1.3);
                run_cycles(&cfg, CYCLES as f64, SPC).expect("rig runs")
            })
            .collect();
        let out: Vec<Outcome> = (0..15u64)
            .map(|seed| {
                let recs: Vec<Record> =
                    runs.iter().enumerate().map(|(i, s)| logged("rig", s, 0.5, OFFSET, 90_000 + 1000 * k as u64 + 10 * seed + i as u64)).collect();
                outcome(&calibrate(&recs, &options(None)).expect("calibrates"), j)
            })
            .collect();
        report(&format!("rig J {j} {loads:?} N {f} Hz noise 0.5"), &out);
        all.extend(out);
    }
    report("all", &all);
    // A true coverage of 95 % gives at least 90 % (270 of 300 for μ_c, 198 of 220 for J) with
    // probability 0.9998 and 0.9992 (binomial); a true 85 % passes with probability 0.006 and
    // 0.018, and a true 90 % about half the time. Measured: 287/300 and 206/220. Before a given J
    // went through the matched filter and before the two-way clusters: 262/300 (3/20 with J = 2
    // given at 1.5 Hz) and 203/220.
    let ((cm, nm, zm), (cj, nj, zj)) = tally(&all);
    assert_eq!((nm, nj), (300, 220));
    assert!(cm * 10 >= 9 * nm, "mu_c intervals cover {cm}/{nm}");
    assert!(cj * 10 >= 9 * nj, "J intervals cover {cj}/{nj}");
    // And the standard errors are the spread of the errors: the rms of error/standard error is
    // 1 for calibrated errors (its spread over N fits about 1/√(2N) = 0.05, so 1.15 is 3 of
    // them). Measured 0.95 (μ_c) and 1.09 (J); without the two-way clusters 1.09 and 1.19,
    // before the matched filter for a given J 1.41 (μ_c).
    assert!(zm < 1.15 && zj < 1.15, "rms error/standard error: mu_c {zm:.3}, J {zj:.3}");
}
