//! Calibration fits the inertia J with μ_c and the offset when J is not given (issue 24 item 5):
//! records with J = 0, 0.05 and 2 kg·m², white torque noise and a 17-bit angle encoder, made
//! two independent ways: the rig simulation (what `pinjoint cycle` runs: position loop, servo,
//! breakaway peaks) and a direct model (a prescribed sine motion with exact J·α plus the
//! library's friction torque, which allows J = 0, below the rig's range). Over several seeds,
//! loads and frequencies, μ_c is within 0.1 % and J within 5 % (of J, or of 0.05 kg·m² for
//! J = 0), and both 95 % intervals cover the truth.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint_calibrate::{calibrate, Calibration, Options, Record, INERTIA};

const TRUTH: f64 = 0.105;

/// Cycles of every record, samples a cycle, torque noise (N·m, rms) and offset (N·m).
const CYCLES: usize = 8;
const SPC: usize = 1000;
const NOISE: f64 = 0.5;
const OFFSET: f64 = 0.3;

/// A direct record ([`direct_record`]) of [`CYCLES`] cycles.
fn direct(load: f64, f: f64, j: f64, seed: u64) -> Record {
    direct_record(load, f, j, TRUTH, NOISE, OFFSET, (CYCLES, SPC as f64), seed)
}

/// A rig record ([`rig_record`]) of [`CYCLES`] cycles.
fn rig(load: f64, f: f64, j: f64, seed: u64) -> Record {
    rig_record(load, f, j, TRUTH, NOISE, OFFSET, (CYCLES, SPC), seed)
}

fn fitted(records: &[Record]) -> Calibration {
    calibrate(records, &Options::default()).expect("calibrates")
}

/// One fit's outcome against the truth.
struct Outcome {
    mu_within: bool,
    j_within: bool,
    mu_covered: bool,
    j_covered: bool,
}

/// μ_c within 0.1 %, J within 5 % (of 0.05 kg·m² for J = 0); whether each interval covers.
fn judge(c: &Calibration, j: f64, what: &str) -> Outcome {
    let mu = &c.estimates[0];
    let je = c.inertia_estimate.as_ref().expect("J is fitted");
    assert_eq!(je.key, INERTIA);
    assert_eq!(je.unit, "kg.m2");
    assert_eq!(c.inertia, je.value);
    let o = Outcome {
        mu_within: (mu.value / TRUTH - 1.0).abs() < 1e-3,
        j_within: (je.value - j).abs() <= 0.05 * j.max(0.05),
        mu_covered: mu.ci95.0 <= TRUTH && TRUTH <= mu.ci95.1,
        j_covered: je.ci95.0 <= j && j <= je.ci95.1,
    };
    println!(
        "{what}: mu_c {:.6} [{:.6}, {:.6}] ({:+.3} %), J {:.5} [{:.5}, {:.5}] (truth {j}){}{}",
        mu.value,
        mu.ci95.0,
        mu.ci95.1,
        100.0 * (mu.value / TRUTH - 1.0),
        je.value,
        je.ci95.0,
        je.ci95.1,
        if o.mu_covered { "" } else { "  mu_c NOT COVERED" },
        if o.j_covered { "" } else { "  J NOT COVERED" },
    );
    o
}

/// Every fit within the tolerances; at least `percent` % of the intervals of each quantity cover
/// the truth. The nominal rate is 95 %; measured here (24 fits each): direct records μ_c 23/24,
/// J 21/24; rig records μ_c 22/24, J 21/24 (before the two-way clusters: 23, 20, 21, 20; the
/// rig's simulation is the same for every seed, so a small systematic repeats). Over 100 direct fits at 1 Hz the intervals cover 93/100 (μ_c and
/// J); the rms of error/standard error is 1.10. The thresholds assert 80 % (at least 20 of 24,
/// which a true 95 % misses with probability 0.006); the coverage itself is asserted over 300
/// fits in `tests/coverage.rs`.
fn assess(outcomes: &[Outcome], percent: usize) {
    let n = outcomes.len();
    let count = |f: fn(&Outcome) -> bool| outcomes.iter().filter(|o| f(o)).count();
    println!(
        "{n} fits: mu_c within 0.1 %: {}, J within 5 %: {}, mu_c covered {}, J covered {}",
        count(|o| o.mu_within),
        count(|o| o.j_within),
        count(|o| o.mu_covered),
        count(|o| o.j_covered)
    );
    assert_eq!(count(|o| o.mu_within), n, "mu_c outside 0.1 %");
    assert_eq!(count(|o| o.j_within), n, "J outside 5 %");
    assert!(count(|o| o.mu_covered) * 100 >= percent * n, "mu_c coverage {}/{n}", count(|o| o.mu_covered));
    assert!(count(|o| o.j_covered) * 100 >= percent * n, "J coverage {}/{n}", count(|o| o.j_covered));
}

#[test]
fn direct_records_with_j_0_005_and_2_over_loads_frequencies_and_seeds() {
    let mut out = Vec::new();
    let cases = [
        (0.0, [20e3, 40e3], 1.0),
        (0.0, [10e3, 60e3], 1.5),
        (0.05, [20e3, 40e3], 1.0),
        (0.05, [5e3, 30e3], 1.5),
        (2.0, [20e3, 40e3], 0.5),
        (2.0, [10e3, 60e3], 1.0),
    ];
    for (k, &(j, loads, f)) in cases.iter().enumerate() {
        for seed in 0..4u64 {
            let recs: Vec<Record> =
                loads.iter().enumerate().map(|(i, &p)| direct(p, f, j, 1000 * k as u64 + 10 * seed + i as u64)).collect();
            out.push(judge(&fitted(&recs), j, &format!("direct J {j} {loads:?} N {f} Hz seed {seed}")));
        }
    }
    assess(&out, 80);
}

#[test]
fn rig_records_with_j_005_and_2_over_loads_frequencies_and_seeds() {
    let mut out = Vec::new();
    let cases = [(0.05, [20e3, 40e3], 1.0), (0.05, [10e3, 60e3], 1.5), (2.0, [20e3, 40e3], 1.0), (2.0, [10e3, 60e3], 0.5)];
    for (k, &(j, loads, f)) in cases.iter().enumerate() {
        for seed in 0..6u64 {
            let recs: Vec<Record> =
                loads.iter().enumerate().map(|(i, &p)| rig(p, f, j, 1000 * k as u64 + 10 * seed + i as u64)).collect();
            out.push(judge(&fitted(&recs), j, &format!("rig J {j} {loads:?} N {f} Hz seed {seed}")));
        }
    }
    assess(&out, 80);
}

#[test]
fn rig_ringing_does_not_bias_j_at_any_sampling() {
    // Noise-free, unquantised rig records with J = 2 (the servo rings after each breakaway):
    // the matched filter leaves J and μ_c unbiased to 1e-4 and 1e-5 relative from 500 to 4000
    // samples a cycle (without the triangle's taps the bias was 6e-4 at 500).
    let mut cfg = RigConfig::default();
    cfg.model.friction.boundary_friction_coefficient = TRUTH;
    (cfg.rig.load, cfg.rig.frequency, cfg.rig.inertia, cfg.rig.breakaway_factor) = (20e3, 1.0, 2.0, 1.3);
    for spc in [500usize, 1000, 4000] {
        let s = run_cycles(&cfg, 8.0, spc).unwrap();
        let c = fitted(&[record("x", &s, 0.0, 0.0, 0.0, 1)]);
        println!("{spc} samples a cycle: mu_c {:.8}, J {:.7}", c.estimates[0].value, c.inertia);
        assert!((c.inertia / 2.0 - 1.0).abs() < 1e-4, "{spc}: J {}", c.inertia);
        assert!((c.estimates[0].value / TRUTH - 1.0).abs() < 3e-5, "{spc}: mu_c {}", c.estimates[0].value);
    }
}

#[test]
fn a_given_inertia_is_used_as_given_and_reported() {
    let recs = [direct(20e3, 1.0, 0.05, 7)];
    let c = calibrate(&recs, &Options { inertia: Some(0.05), ..Options::default() }).unwrap();
    assert!(c.inertia_estimate.is_none());
    assert_eq!(c.inertia, 0.05);
    assert!((c.estimates[0].value / TRUTH - 1.0).abs() < 1e-3);
    assert!(!c.correlation_keys.iter().any(|k| k == INERTIA), "{:?}", c.correlation_keys);
    // The wrong J given biases μ_c (the 0.35 % for J = 0.05 on J = 0 records) where the
    // fitted one does not.
    let zero = [direct(20e3, 1.0, 0.0, 8)];
    let wrong = calibrate(&zero, &Options { inertia: Some(0.05), ..Options::default() }).unwrap().estimates[0].value;
    let free = fitted(&zero);
    println!("J = 0 records: mu_c {wrong} with J = 0.05 given, {} with J fitted ({})", free.estimates[0].value, free.inertia);
    assert!((wrong / TRUTH - 1.0).abs() > 1e-3, "{wrong}");
    assert!((free.estimates[0].value / TRUTH - 1.0).abs() < 1e-3);
    // J and μ_c are in one covariance: the correlation matrix holds J.
    let k = free.correlation_keys.iter().position(|k| k == INERTIA).expect("J in the correlation");
    assert!(free.correlation[0][k].abs() > 0.0 && free.correlation[0][k].abs() < 1.0);
}


