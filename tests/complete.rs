//! The complete model (issue 28; `model.paper = false`, the default): its check values and
//! properties over the declared service range ([`pinjoint::validity`]'s `SERVICE_*`).
//!
//! * Raimondi & Boyd (1958), L/D = 1, in full film through the whole joint (w = 1, λ ≥ 3,
//!   the base oil alone): μ·R/c against their friction variable (R/c)f at their S.
//! * Petroff's torque 2πη_bωR³B/c a lower bound over the box.
//! * Continuity in load, speed and temperature: the largest relative step between neighbours
//!   of a fine sweep across the transitions shrinks with the step.
//! * The cold day (−54 °C) stiffer than the room (20 °C) at every load and speed.
//! * At the paper's rig conditions (5–60 kN, |ω|R ≤ 0.1228 m/s, 20 °C) within 3 % of the
//!   paper's model.
//! * No refusal over the box at every fidelity level; the issue's two examples build.
//! * At rest: μ_c R P plus the grease's yield torque, the limit of ω → 0⁺.

use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};
use pinjoint::validity::{SERVICE_LOAD_MIN, SERVICE_SPEED_MAX, SERVICE_TEMPERATURE_MAX, SERVICE_TEMPERATURE_MIN};
use pinjoint::{Joint, Params};
use proptest::prelude::*;
use test_support::strategies::log_uniform;
use std::f64::consts::PI;

fn at(t: f64) -> Params {
    let mut p = Params::default();
    p.lubricant.temperature = t;
    p
}

/// Loads of the box: 10 N to 1 MN (the capacity is 5.05e8 N for the paper's joint).
fn load() -> impl Strategy<Value = f64> {
    log_uniform(SERVICE_LOAD_MIN, 1e6)
}
fn speed() -> impl Strategy<Value = f64> {
    log_uniform(1e-4, SERVICE_SPEED_MAX)
}
fn temperature() -> impl Strategy<Value = f64> {
    SERVICE_TEMPERATURE_MIN..=SERVICE_TEMPERATURE_MAX
}

/// Raimondi & Boyd (1958), Table for L/D = 1 (full 360° bearing), as reproduced in Shigley's
/// *Mechanical Engineering Design* (lubrication chapter): (ε, S, (R/c)f).
const RAIMONDI_BOYD_LD1: [(f64, f64, f64); 5] = [(0.1, 1.33, 26.4), (0.2, 0.631, 12.8), (0.4, 0.264, 5.79), (0.6, 0.121, 3.22), (0.8, 0.0446, 1.70)];

#[test]
fn raimondi_and_boyd_in_full_film_through_the_whole_joint() {
    // L/D = 1 (B = 2R), the base oil alone (Newtonian, R&B's lubricant), 20 C.
    let mut p = Params::default();
    p.grease.enabled = false;
    p.geometry.bush_length = 2.0 * p.geometry.pin_radius;
    let j = Joint::new(&p).unwrap();
    let (r, c, b) = (p.geometry.pin_radius, p.radial_clearance(), p.geometry.bush_length);
    let eta = p.lubricant.viscosity;
    let mut worst = 0.0f64;
    for (eps, s, f) in RAIMONDI_BOYD_LD1 {
        for omega in [3.0, 30.0, 150.0] {
            // S = η ω/(2π P_L) (R/c)², P_L = P/(2RB).
            let load = eta * omega / (2.0 * PI * s) * (r / c).powi(2) * 2.0 * r * b;
            let op = j.evaluate(load, omega).unwrap();
            assert!((op.sommerfeld_number / s - 1.0).abs() < 1e-12);
            if op.journal_weight < 1.0 || op.lambda_ratio < 3.0 {
                continue;
            }
            let fv = op.friction_coefficient * r / c;
            let e = (fv / f - 1.0).abs();
            worst = worst.max(e);
            assert!(e < 0.03, "eps {eps}, S {s}, omega {omega}: (R/c)f = {fv} against {f} ({e:.3})");
            assert!((op.eccentricity_ratio - eps).abs() < 0.03, "eps {eps}: {}", op.eccentricity_ratio);
        }
    }
    assert!(worst > 0.0, "no point in full film");
    eprintln!("Raimondi-Boyd L/D = 1 through the joint: largest relative deviation {worst:.4}");
}

/// Petroff's full-film torque 2π η_b(T) |ω| R³ B / c.
fn petroff(j: &Joint, omega: f64) -> f64 {
    let p = j.params();
    2.0 * PI * j.lubricant().viscosity * omega.abs() * p.geometry.pin_radius.powi(3) * p.geometry.bush_length / p.radial_clearance()
}

/// The declared speed box and the issue's examples as (load N, ω rad/s, T K).
const ISSUE_POINTS: [(f64, f64, f64); 6] = [(200.0, 1.0, 293.15), (200.0, 3.0, 293.15), (23e3, 173.0, 293.15), (100.0, 1.0, 293.15), (20e3, 3.0, 253.15), (20e3, 3.0, 293.15)];

#[test]
fn the_issues_points_answer_above_petroff() {
    for (load, omega, t) in ISSUE_POINTS {
        let j = Joint::new(&at(t)).unwrap();
        let op = j.evaluate(load, omega).unwrap();
        assert!(op.torque >= petroff(&j, omega), "{load} N {omega} rad/s {t} K: {} < Petroff {}", op.torque, petroff(&j, omega));
    }
    // The cold day stiffer than the room (20 kN, 3 rad/s): at -40 C the grease's supply layer
    // no longer lifts the surfaces (at -20 C the thicker oil still does, as in the paper's model).
    let warm = Joint::new(&at(293.15)).unwrap().evaluate(20e3, 3.0).unwrap();
    let cold = Joint::new(&at(233.15)).unwrap().evaluate(20e3, 3.0).unwrap();
    assert!(cold.friction_coefficient > warm.friction_coefficient, "{} against {}", cold.friction_coefficient, warm.friction_coefficient);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Every point of the box answers, finite, with the torque at least Petroff's.
    #[test]
    fn no_refusal_and_petroff_is_a_lower_bound(load in load(), omega in speed(), t in temperature(), sign in prop::bool::ANY) {
        let j = Joint::new(&at(t)).unwrap();
        let w = if sign { omega } else { -omega };
        let op = j.evaluate(load, w).unwrap();
        prop_assert!(op.torque.is_finite() && op.torque > 0.0);
        prop_assert!(op.film_thickness > 0.0 && op.film_thickness <= j.params().radial_clearance() * (1.0 + 1e-12) || op.journal_weight < 1.0);
        prop_assert!((0.0..=1.0).contains(&op.journal_weight));
        let bound = petroff(&j, w);
        prop_assert!(op.torque >= bound * (1.0 - 1e-12), "{load} N {w} rad/s {t} K: {} < Petroff {bound}", op.torque);
        // The grease's yield torque is part of the clearance's, which is part of the torque.
        prop_assert!(op.grease_yield_torque <= op.clearance_torque * (1.0 + 1e-12) && op.clearance_torque <= op.torque * (1.0 + 1e-12));
    }

    /// The cold day (-54 C) is stiffer than the room (20 C) at every load and speed: the grease
    /// in the clearance stiffens and its supply layer thins (between the two the torque may first
    /// fall as the oil thickens, as the paper's model does).
    #[test]
    fn the_cold_day_is_stiffer_than_the_room(load in load(), omega in speed()) {
        let warm = Joint::new(&at(293.15)).unwrap().evaluate(load, omega).unwrap();
        let cold = Joint::new(&at(219.15)).unwrap().evaluate(load, omega).unwrap();
        prop_assert!(cold.torque >= warm.torque, "{load} N {omega} rad/s: {} at -54 C below {} at 20 C", cold.torque, warm.torque);
    }
}

/// Largest relative step of `f` between neighbours of `n` points uniform in `x` over [a, b].
fn largest_step(n: usize, a: f64, b: f64, f: &dyn Fn(f64) -> [f64; 3]) -> f64 {
    let mut worst = 0.0f64;
    let mut prev = f(a);
    for k in 1..=n {
        let x = a + (b - a) * k as f64 / n as f64;
        let v = f(x);
        for (p, q) in prev.iter().zip(v.iter()) {
            worst = worst.max(((q - p) / p).abs());
        }
        prev = v;
    }
    worst
}

/// Torque, film and λ: the quantities the issue asks to be continuous.
fn tfl(j: &Joint, load: f64, omega: f64) -> [f64; 3] {
    let op = j.evaluate(load, omega).unwrap();
    [op.torque, op.film_thickness, op.lambda_ratio]
}

#[test]
fn continuous_across_the_transitions_in_load_speed_and_temperature() {
    // Each sweep crosses a transition: the journal weight from 0 to 1 (load at 30 rad/s; speed
    // at 2 kN), and T_ref (the cold supply starts there) at 20 kN and 3 rad/s, at 2 kN and
    // 30 rad/s (through the journal's region).
    let j = Joint::new(&Params::default()).unwrap();
    type Sweep<'a> = (&'a str, f64, f64, Box<dyn Fn(f64) -> [f64; 3] + 'a>);
    let sweeps: Vec<Sweep> = vec![
        ("load", 100f64.ln(), 100e3f64.ln(), Box::new(|x: f64| tfl(&j, x.exp(), 30.0))),
        ("speed", 0.01f64.ln(), 200f64.ln(), Box::new(|x: f64| tfl(&j, 2e3, x.exp()))),
        ("temperature", 253.15, 313.15, Box::new(|t: f64| tfl(&Joint::new(&at(t)).unwrap(), 20e3, 3.0))),
        ("temperature", 218.15, 313.15, Box::new(|t: f64| tfl(&Joint::new(&at(t)).unwrap(), 2e3, 30.0))),
    ];
    for (name, a, b, f) in &sweeps {
        let steps: Vec<f64> = [200, 800, 3200].iter().map(|&n| largest_step(n, *a, *b, f.as_ref())).collect();
        eprintln!("{name} sweep: largest relative step {:.3e} (200 steps), {:.3e} (800), {:.3e} (3200)", steps[0], steps[1], steps[2]);
        // A jump would keep its size; a continuous (Lipschitz) function's step falls like 1/n
        // (here ×1/4 per refinement: at most ×0.35 asked).
        assert!(steps[1] < 0.35 * steps[0] && steps[2] < 0.35 * steps[1] && steps[2] < 0.05, "{name}: {steps:?}");
    }
}

/// The budget of issue 28: the largest difference is at 5 kN and 4.39 rad/s (the clearance's
/// grease on the paper's 8.39 N·m): 3.09 % with K = 20 Pa·sⁿ, 2.99 % with 19, 2.88 % with the
/// default K = 18 (`src/rheology/grease.rs`).
#[test]
fn within_three_percent_of_the_paper_at_the_rig_conditions() {
    let complete = Joint::new(&Params::default()).unwrap();
    let paper = Joint::new(&Params::paper()).unwrap();
    let mut worst = (0.0f64, 0.0, 0.0);
    for k in 0..=24 {
        let load = 5e3 * 12f64.powf(f64::from(k) / 24.0);
        for m in 0..=40 {
            let omega = if m == 0 { 0.0 } else { pinjoint::validity::MAX_RIG_ANGULAR_SPEED * 1e-4f64.powf(1.0 - f64::from(m) / 40.0) };
            let (a, b) = (complete.evaluate(load, omega).unwrap(), paper.evaluate(load, omega).unwrap());
            let e = (a.torque / b.torque - 1.0).abs();
            if e > worst.0 {
                worst = (e, load, omega);
            }
            assert_eq!(a.journal_weight, 0.0, "{load} N {omega} rad/s: the paper's load sharing must be untouched");
        }
    }
    eprintln!("complete against paper at the rig conditions: largest relative torque difference {:.4} at {} N, {} rad/s", worst.0, worst.1, worst.2);
    assert!(worst.0 <= 0.03, "{worst:?}");
}

#[test]
fn at_rest_the_grease_yield_adds_to_mu_c_and_is_the_limit_of_motion() {
    for t in [218.15, 253.15, 293.15, 393.15] {
        let j = Joint::new(&at(t)).unwrap();
        for load in [10.0, 200.0, 5e3, 60e3] {
            let rest = j.evaluate(load, 0.0).unwrap();
            let yield_torque = j.rest_yield_torque(load);
            assert!(yield_torque > 0.0);
            let mu_c = j.params().friction.boundary_friction_coefficient;
            let expect = mu_c * j.params().geometry.pin_radius * load + yield_torque;
            assert!((rest.torque / expect - 1.0).abs() < 1e-14, "{t} K {load} N: {} against {expect}", rest.torque);
            assert!((j.boundary_torque(load) / expect - 1.0).abs() < 1e-14);
            assert_eq!(rest.grease_yield_torque, yield_torque);
            // ω → 0⁺: the difference from rest shrinks (like ω^n, the grease's power law).
            let gap = |w: f64| (j.evaluate(load, w).unwrap().torque / rest.torque - 1.0).abs();
            let (g9, g12, g15) = (gap(1e-9), gap(1e-12), gap(1e-15));
            assert!(g12 < g9 && g15 < g12 && g15 < 1e-5, "{t} K {load} N: {g9} {g12} {g15}");
        }
    }
    // The paper's model: μ_c exactly, no grease.
    let j = Joint::new(&Params::paper()).unwrap();
    assert_eq!(j.evaluate(20e3, 0.0).unwrap().friction_coefficient, 0.12);
    assert_eq!(j.rest_yield_torque(20e3), 0.0);
}

#[test]
fn every_fidelity_level_builds_over_the_issues_envelopes() {
    // `pinjoint sweep --fidelity table` over the paper's 5-60 kN x 1-800 rpm, and an FMU
    // table (its default envelope, 5-60 kN x 0.01-10 rad/s) at -33 C and at the ends of the range.
    let rpm = PI / 30.0;
    let cases = [(Envelope::new(5e3, 60e3, rpm, 800.0 * rpm).unwrap(), 293.15), (Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap(), 240.15)];
    for (env, t) in cases {
        for f in Fidelity::ALL {
            let mut ev = Evaluator::new(&at(t), f, 1e-4, env).unwrap_or_else(|e| panic!("{f} at {t} K over {env:?}: {e}"));
            let e = ev.evaluate(0.5 * (env.load_min + env.load_max), env.speed_max).unwrap();
            assert!(e.torque.is_finite() && e.torque > 0.0);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Table, boundary and auto build over envelopes anywhere in the box (a decade of load,
    /// two of speed) and answer inside them, within their bound of the full solve.
    #[test]
    fn no_level_refuses_in_the_box(lo in log_uniform(SERVICE_LOAD_MIN, 1e5), wlo in log_uniform(1e-3, 2.0), t in temperature()) {
        let env = Envelope::new(lo, 10.0 * lo, wlo, 100.0 * wlo).unwrap();
        let full = Joint::new(&at(t)).unwrap();
        for f in [Fidelity::Table, Fidelity::Boundary, Fidelity::Auto] {
            let mut ev = Evaluator::new(&at(t), f, 1e-3, env).map_err(|e| TestCaseError::fail(format!("{f} at {t} K over {env:?}: {e}")))?;
            for (a, b) in [(0.3, 0.7), (0.9, 0.1), (0.5, 0.5)] {
                let (load, omega) = env.at_log_fraction(a, b);
                let e = ev.evaluate(load, omega).unwrap();
                let r = full.evaluate(load, omega).unwrap();
                let err = (e.torque / r.torque - 1.0).abs();
                prop_assert!(err <= ev.error_bound() * 1.5 + 1e-12, "{f}: {err} against bound {}", ev.error_bound());
            }
        }
    }
}

/// The grease's supply layer only thins the film: at every temperature the film with the
/// supply is at most the flooded one (`grease.supply_layer_inverse = 0`) and at most the
/// layer's film scale, and the thinner the layer the thinner the film (crate::film::cold_supply).
#[test]
fn the_supplied_film_is_never_thicker_than_the_flooded_one() {
    for t in [313.15, 293.15, 273.15, 253.15, 233.15, 218.15] {
        let mut flooded = at(t);
        flooded.grease.supply_layer_inverse = 0.0;
        let jf = Joint::new(&flooded).unwrap();
        let mut prev: Option<Vec<f64>> = None;
        for q in [1e3, 2e4, 1e5, 1e6] {
            let mut p = at(t);
            p.grease.supply_layer_inverse = q;
            let j = Joint::new(&p).unwrap();
            let mut films = Vec::new();
            for (load, omega) in [(200.0, 1.0), (20e3, 3.0), (5e3, 30.0), (60e3, 0.1)] {
                let (a, b) = (j.evaluate(load, omega).unwrap(), jf.evaluate(load, omega).unwrap());
                assert!(a.film_thickness <= b.film_thickness * (1.0 + 1e-12), "{t} K q {q}: {} above flooded {}", a.film_thickness, b.film_thickness);
                films.push(a.film_thickness);
            }
            if let Some(prev) = &prev {
                for (a, b) in films.iter().zip(prev) {
                    assert!(*a <= b * (1.0 + 1e-12), "{t} K q {q}: {a} above {b} of a thicker layer");
                }
            }
            prev = Some(films);
        }
    }
}

/// The cold day's kinks (the grease's supply layer taking the fluid's share to zero at a finite
/// speed) are not resolved by the table at 1e-3: the cells they cross answer with the complete
/// solve, the rest meet the bound on fresh points.
#[test]
fn unresolved_table_cells_answer_with_the_complete_solve() {
    use pinjoint::fidelity::{Level, Source};
    let p = at(253.15);
    let full = Joint::new(&p).unwrap();
    let env = Envelope::new(200.0, 20e3, 0.1, 30.0).unwrap();
    let mut ev = Evaluator::new(&p, Fidelity::Table, 1e-3, env).unwrap();
    assert_eq!(ev.chosen(), Level::Table);
    let t = ev.table().unwrap().clone();
    let n = t.stats().load_cells * t.stats().speed_cells;
    assert!(t.solved_cells() > 0 && (t.solved_cells() as f64) <= 0.25 * n as f64, "{} of {n}", t.solved_cells());
    let bound = ev.error_bound();
    assert!(bound <= 1e-3);
    let (mut solved, mut worst) = (0, 0.0f64);
    for a in 0..=150 {
        for b in 0..=150 {
            // Off the check points' lattice (steps of 1/151 and 1/152).
            let (load, omega) = env.at_log_fraction((f64::from(a) + 0.37) / 151.0, (f64::from(b) + 0.61) / 152.0);
            let e = ev.evaluate(load, omega).unwrap();
            let r = full.evaluate(load, omega).unwrap();
            assert_ne!(e.source, Source::Fallback, "inside the envelope: {load} N, {omega} rad/s");
            if t.solved_at(load, omega) {
                solved += 1;
                assert_eq!(e.source, Source::Full);
                assert!((e.torque / r.torque - 1.0).abs() <= 1e-9, "{load} N {omega} rad/s");
            } else {
                assert_eq!(e.source, Source::Table);
                worst = worst.max((e.torque / r.torque - 1.0).abs());
            }
        }
    }
    assert!(solved > 0);
    assert!(worst <= bound, "interpolated cells: {worst} against bound {bound}");
    assert_eq!(ev.fallbacks(), 0);
}
