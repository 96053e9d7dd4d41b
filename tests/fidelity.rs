//! Fidelity levels (issue 6): every level meets its advertised bound on fresh random points
//! of the envelope, `auto` never picks a level that violates the tolerance, the table
//! stays within the tolerance of `full`, out-of-envelope calls fall back to `full`, and
//! ω = 0 is exact.

use pinjoint::fidelity::check::CheckRng;
use pinjoint::fidelity::{Envelope, ErrorReport, Evaluator, Fidelity, FidelityError, Level, Source, FULL_ERROR_BOUND};
use pinjoint::{Joint, OperatingPoint, Params};

fn joint() -> Joint {
    Joint::new(&Params::paper()).unwrap()
}

/// The brief's envelope: 5 to 60 kN, 0.01 to 10 rad/s.
fn brief() -> Envelope {
    Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap()
}

/// An evaluator of the default joint at `fidelity` and `tolerance` over [`brief`].
fn brief_evaluator(fidelity: Fidelity, tolerance: f64) -> Evaluator {
    Evaluator::new(&Params::paper(), fidelity, tolerance, brief()).unwrap()
}

/// Envelopes: deep boundary, the brief's, mixed, mixed into full film, spanning all regimes.
fn envelopes() -> Vec<(&'static str, Envelope)> {
    vec![
        ("deep-boundary", Envelope::new(5e3, 60e3, 1e-5, 1e-3).unwrap()),
        ("brief", brief()),
        ("mixed", Envelope::new(10e3, 60e3, 1.0, 30.0).unwrap()),
        // Up to 3 rad/s: the table reaches past its envelope, and at 1 kN and 10 rad/s the film
        // would pass the diametral clearance (ModelError::FilmBeyondClearance).
        ("spanning", Envelope::new(2e3, 200e3, 1e-3, 3.0).unwrap()),
    ]
}

/// Errors of `ev` against the complete solve on `n` fresh points (seeds unused by the
/// builds): half uniform in (ln P, ln |ω|), half uniform in (P, |ω|), random signs of ω.
fn fresh_errors(ev: &mut Evaluator, j: &Joint, n: usize, seed: u64) -> ErrorReport {
    let env = *ev.envelope();
    let mut rng = CheckRng::new(seed);
    let mut r = ErrorReport::default();
    for k in 0..n {
        let (load, w) = if k % 2 == 0 {
            env.at_log_fraction(rng.uniform(), rng.uniform())
        } else {
            (
                env.load_min + rng.uniform() * (env.load_max - env.load_min),
                env.speed_min + rng.uniform() * (env.speed_max - env.speed_min),
            )
        };
        let omega = if rng.uniform() < 0.5 { -w } else { w };
        let e = ev.evaluate(load, omega).unwrap();
        assert_ne!(e.source, Source::Fallback, "inside the envelope: P = {load} N, ω = {omega} rad/s");
        r.add(&e, &j.evaluate(load, omega).unwrap());
    }
    r
}

#[test]
fn fidelity_names_parse_and_print() {
    for (s, f) in [("full", Fidelity::Full), ("table", Fidelity::Table), ("boundary", Fidelity::Boundary), ("auto", Fidelity::Auto)] {
        assert_eq!(s.parse::<Fidelity>().unwrap(), f);
        assert_eq!(f.to_string(), s);
        assert_eq!(format!(" {} ", s.to_uppercase()).parse::<Fidelity>().unwrap(), f);
    }
    let e = "tabel".parse::<Fidelity>().unwrap_err().to_string();
    assert!(e.contains("tabel") && e.contains("full, table, boundary, auto"), "{e}");
}

#[test]
fn inputs_are_validated_with_quantity_value_and_unit() {
    let p = Params::paper();
    let env = brief();
    for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        let e = Evaluator::new(&p, Fidelity::Table, bad, env).unwrap_err();
        assert!(matches!(e, FidelityError::Tolerance(_)));
        let s = e.to_string();
        assert!(s.contains("tolerance") && s.contains(&format!("{bad}")), "{s}");
    }
    let e = Evaluator::new(&p, Fidelity::Auto, 1e-12, env).unwrap_err();
    assert!(matches!(e, FidelityError::ToleranceBelowModelAccuracy { .. }), "{e}");
    // A bad envelope is rejected for every level, naming quantity, value and unit.
    let bad_env = Envelope { load_min: 5e3, load_max: 60e3, speed_min: 10.0, speed_max: 0.01 };
    for f in Fidelity::ALL {
        let s = Evaluator::new(&p, f, 1e-4, bad_env).unwrap_err().to_string();
        assert!(s.contains("speed") && s.contains("rad/s") && s.contains("minimum = 10"), "{s}");
    }
    // Operating points: the model's own errors.
    let mut ev = Evaluator::new(&p, Fidelity::Boundary, 1e-2, Envelope::new(5e3, 60e3, 1e-5, 1e-3).unwrap()).unwrap();
    assert!(ev.evaluate(0.0, 0.0).unwrap_err().to_string().contains("load = 0 N"));
    // A negative load is its magnitude (issue 9).
    assert_eq!(ev.evaluate(-20e3, 1e-4).unwrap().torque.to_bits(), ev.evaluate(20e3, 1e-4).unwrap().torque.to_bits());
    assert!(ev.evaluate(f64::NAN, 1e-4).is_err());
    assert!(ev.evaluate(20e3, f64::NAN).unwrap_err().to_string().contains("rad/s"));
    assert_eq!(ev.fallbacks(), 0, "invalid inputs are errors, not fallbacks");
    // An invalid parameter set is rejected.
    let mut q = p;
    q.geometry.pin_radius = -1.0;
    assert!(matches!(Evaluator::new(&q, Fidelity::Full, 1e-4, env), Err(FidelityError::Param(_))));
}

#[test]
fn table_meets_its_advertised_bound_on_fresh_points() {
    let j = joint();
    let p = Params::paper();
    let cases = [("brief", 1e-2), ("brief", 1e-4), ("brief", 1e-6), ("mixed", 1e-3), ("mixed", 1e-5), ("spanning", 1e-2)];
    for (name, tol) in cases {
        let env = envelopes().into_iter().find(|e| e.0 == name).unwrap().1;
        let mut ev = Evaluator::new(&p, Fidelity::Table, tol, env).unwrap();
        assert_eq!(ev.chosen(), Level::Table);
        let bound = ev.error_bound();
        assert!(bound <= tol && bound > 0.0, "{name} {tol}: bound {bound}");
        let r = fresh_errors(&mut ev, &j, 3000, 0xf1de_0001);
        // μ, torque, h_c relative; shares absolute: all within the advertised bound.
        assert!(r.max() <= bound, "{name} tol {tol}: fresh error {r:?} exceeds the advertised bound {bound}");
        assert!(r.torque <= tol && r.friction_coefficient <= tol && r.film_thickness <= tol);
    }
}

/// The complete model's table meets its advertised bound on fresh points from the cold day
/// to a hot one (the grease in the clearance, the journal bearing, the cold supply): at 343 K
/// over the brief's envelope at 1e-4, a table that held s = asinh y (a 5 × 14 grid) erred by
/// 2.0e-4 against its bound 1e-4 on such points.
#[test]
fn complete_model_table_meets_its_bound_from_the_cold_day_to_a_hot_one() {
    for (t, tol) in [(219.15, 1e-4), (253.15, 1e-3), (293.15, 1e-4), (343.15, 1e-4), (373.15, 1e-5)] {
        let mut p = Params::default();
        p.lubricant.temperature = t;
        let j = Joint::new(&p).unwrap();
        let mut ev = Evaluator::new(&p, Fidelity::Table, tol, brief()).unwrap();
        assert_eq!(ev.chosen(), Level::Table);
        let bound = ev.error_bound();
        assert!(bound <= tol && bound > 0.0, "{t} K {tol}: bound {bound}");
        let r = fresh_errors(&mut ev, &j, 3000, 0xf1de_0002);
        assert!(r.max() <= bound, "{t} K tol {tol}: fresh error {r:?} exceeds the advertised bound {bound}");
    }
}

#[test]
fn table_is_continuous_across_cells() {
    let j = joint();
    let env = brief();
    let t = pinjoint::fidelity::StribeckTable::build(&j, &env, 1e-4).unwrap();
    let s = t.stats();
    assert!(s.load_cells >= 2 && s.speed_cells >= 2 && s.node_solves >= (s.load_cells + 5) * (s.speed_cells + 5));
    // C¹ Hermite patches share node values and slopes: no jump across a cell boundary.
    let (hx, hz) = ((60e3f64 / 5e3).ln() / s.load_cells as f64, (1000f64).ln() / s.speed_cells as f64);
    for k in 1..s.speed_cells {
        let omega = (0.01f64.ln() + k as f64 * hz).exp();
        let load = (5e3f64.ln() + 0.37 * hx).exp();
        let a = t.evaluate(load, omega * (1.0 - 1e-12)).unwrap().friction_coefficient;
        let b = t.evaluate(load, omega * (1.0 + 1e-12)).unwrap().friction_coefficient;
        assert!(((a - b) / a).abs() < 1e-9, "jump at ω = {omega}: {a} {b}");
    }
}

#[test]
fn auto_never_picks_a_level_that_violates_the_tolerance() {
    let j = joint();
    let p = Params::paper();
    for (name, env) in envelopes() {
        for tol in [1e-1, 1e-2, 1e-3, 1e-4, 1e-6] {
            let mut ev = Evaluator::new(&p, Fidelity::Auto, tol, env).unwrap();
            let bound = ev.error_bound();
            assert!(bound <= tol, "{name} {tol}: picked {} with bound {bound}", ev.chosen());
            // Cheapest first: boundary whenever its own bound was within the tolerance.
            let a = ev.assessments();
            assert_eq!(a[0].level, Level::Boundary);
            if a[0].accepted {
                assert_eq!(ev.chosen(), Level::Boundary);
            } else {
                assert!(a[0].error_bound.unwrap() > tol);
                assert_ne!(ev.chosen(), Level::Boundary);
            }
            if ev.chosen() == Level::Full {
                assert!(a.iter().any(|x| x.level == Level::Table && !x.accepted), "{name} {tol}: {a:?}");
                assert_eq!(bound, FULL_ERROR_BOUND);
            }
            let r = fresh_errors(&mut ev, &j, 400, 0xa070_0000 + (tol.log10().abs() as u64));
            assert!(r.max() <= tol, "{name} tol {tol}: {} measured {r:?}", ev.chosen());
            assert!(r.max() <= bound.max(1e-9), "{name} tol {tol}: {} measured {r:?} > bound {bound}", ev.chosen());
        }
    }
    // The picks the physics implies: deep boundary at 1 % is boundary; the brief's envelope
    // at 1e-4 needs the table; the spanning envelope (up to 3 rad/s, where the film stays
    // inside the clearance) at 1e-6 is tabulated (before the film bound, the envelope ran to
    // 1e3 rad/s and could not be tabulated in 65536 cells).
    let pick = |name: &str, tol: f64| {
        let env = envelopes().into_iter().find(|e| e.0 == name).unwrap().1;
        Evaluator::new(&p, Fidelity::Auto, tol, env).unwrap().chosen()
    };
    assert_eq!(pick("deep-boundary", 1e-2), Level::Boundary);
    assert_eq!(pick("brief", 1e-4), Level::Table);
    assert_eq!(pick("spanning", 1e-6), Level::Table);
}

#[test]
fn boundary_level_reports_its_measured_error() {
    let j = joint();
    let p = Params::paper();
    for (name, env) in envelopes() {
        let mut ev = Evaluator::new(&p, Fidelity::Boundary, 1e-3, env).unwrap();
        assert_eq!(ev.chosen(), Level::Boundary);
        let bound = ev.error_bound();
        let r = fresh_errors(&mut ev, &j, 1000, 0xb0b0_0001);
        assert!(r.max() <= bound, "{name}: fresh {r:?} > advertised {bound}");
        assert_eq!(ev.within_tolerance(), bound <= 1e-3);
        // μ = μ_c, shares 0/1 at every speed.
        let e = ev.evaluate(env.load_min, env.speed_max).unwrap();
        assert_eq!((e.friction_coefficient, e.fluid_load_fraction, e.asperity_load_fraction), (0.12, 0.0, 1.0));
    }
    // Deep boundary: within 1e-3; past the transition, far from it.
    let deep = Evaluator::new(&p, Fidelity::Boundary, 1e-3, envelopes()[0].1).unwrap();
    assert!(deep.within_tolerance(), "{}", deep.error_bound());
    let span = Evaluator::new(&p, Fidelity::Boundary, 1e-3, envelopes()[3].1).unwrap();
    assert!(!span.within_tolerance() && span.error_bound() > 1.0, "{}", span.error_bound());
}

#[test]
fn outside_the_envelope_table_and_boundary_fall_back_to_full_and_say_so_once() {
    let j = joint();
    let p = Params::paper();
    let env = brief();
    for f in [Fidelity::Table, Fidelity::Boundary] {
        let mut ev = Evaluator::new(&p, f, 1e-2, env).unwrap();
        let inside = ev.evaluate(20e3, 1.0).unwrap();
        assert!(matches!(inside.source, Source::Table | Source::Boundary) && !inside.first_fallback);
        // Below the envelope's speeds the table answers down to rest (its low speeds, the
        // rest state under its floor: tests/fidelity_low_speed.rs); the boundary level does not.
        let slow = (20e3, 1e-4);
        if f == Fidelity::Table {
            let e = ev.evaluate(slow.0, slow.1).unwrap();
            assert!(matches!(e.source, Source::Table | Source::Rest), "below the envelope's speeds the table answers: {:?}", e.source);
        }
        let below: &[(f64, f64)] = if f == Fidelity::Table { &[(20e3, 50.0)] } else { &[slow] };
        let outside = [(20e3, 50.0), (1e3, 1.0), (100e3, -3.0), below[0], (1e3, 0.0), (20e3, -10.0001)];
        for (k, (load, omega)) in outside.into_iter().enumerate() {
            let e = ev.evaluate(load, omega).unwrap();
            let full = j.evaluate(load, omega).unwrap();
            assert_eq!(e.source, Source::Fallback, "{f}: P = {load}, ω = {omega}");
            assert_eq!(e.first_fallback, k == 0);
            assert_eq!(ev.fallbacks(), k as u64 + 1);
            for (a, b) in [(e.friction_coefficient, full.friction_coefficient), (e.film_thickness, full.film_thickness), (e.torque, full.torque)] {
                assert!(((a - b) / b).abs() < 1e-11, "{f}: {a} vs {b}");
            }
            assert_eq!(e.signed_torque().signum(), full.signed_torque().signum());
        }
        // The ends of the envelope are inside.
        assert_ne!(ev.evaluate(5e3, -10.0).unwrap().source, Source::Fallback);
        assert_ne!(ev.evaluate(60e3, 0.01).unwrap().source, Source::Fallback);
        assert_eq!(ev.fallbacks(), 6);
    }
}

#[test]
fn rest_is_exact_at_every_level() {
    let j = joint();
    let p = Params::paper();
    let env = brief();
    let mut rng = CheckRng::new(0x0e57);
    for f in Fidelity::ALL {
        let tol = 1e-4;
        let mut ev = Evaluator::new(&p, f, tol, env).unwrap();
        for _ in 0..200 {
            let load = 5e3 + rng.uniform() * 55e3;
            let e = ev.evaluate(load, 0.0).unwrap();
            let full = j.evaluate(load, 0.0).unwrap();
            assert_eq!(e.friction_coefficient, 0.12, "{f}");
            assert_eq!(e.friction_coefficient, full.friction_coefficient);
            assert_eq!(e.torque, full.torque);
            assert_eq!(e.signed_torque(), 0.0);
            assert_eq!((e.fluid_load_fraction, e.asperity_load_fraction), (0.0, 1.0));
            assert!(matches!(e.source, Source::Rest | Source::Full), "{f}: {:?}", e.source);
            let eh = ((e.film_thickness - full.film_thickness) / full.film_thickness).abs();
            assert!(eh <= ev.error_bound().max(1e-12) && eh <= tol, "{f}: h_c error {eh}");
        }
        assert_eq!(ev.fallbacks(), 0);
    }
}

#[test]
fn full_level_is_the_complete_solve_warm_started() {
    let j = joint();
    let mut ev = brief_evaluator(Fidelity::Full, 1e-4);
    assert_eq!((ev.chosen(), ev.error_bound()), (Level::Full, FULL_ERROR_BOUND));
    // A rig-like trajectory through rest, boundary, mixed and full film, in and out of the envelope.
    for k in 0..2000 {
        let t = f64::from(k) / 2000.0;
        let load = 20e3 + 15e3 * (6.0 * t).sin();
        let omega = 100.0 * (40.0 * t).sin().powi(3);
        let e = ev.evaluate(load, omega).unwrap();
        let cold = j.evaluate(load, omega).unwrap();
        assert_eq!(e.source, Source::Full);
        for (a, b) in [(e.friction_coefficient, cold.friction_coefficient), (e.film_thickness, cold.film_thickness)] {
            assert!(((a - b) / b).abs() <= FULL_ERROR_BOUND, "P = {load}, ω = {omega}: {a} vs {b}");
        }
        assert!((e.fluid_load_fraction - cold.fluid_load_fraction).abs() <= FULL_ERROR_BOUND);
    }
    assert_eq!(ev.fallbacks(), 0);
}

#[test]
fn completed_operating_point_matches_the_full_one() {
    let j = joint();
    let mut ev = brief_evaluator(Fidelity::Table, 1e-6);
    for (load, omega) in [(7e3, 0.05), (20e3, -3.0), (55e3, 9.0), (20e3, 0.0)] {
        let (op, src) = ev.evaluate_point(load, omega).unwrap();
        let full = j.evaluate(load, omega).unwrap();
        assert!(matches!(src, Source::Table | Source::Rest));
        // Load- and speed-only quantities: the core's formulas, to rounding.
        let exact = |o: &OperatingPoint| [o.mean_pressure, o.peak_pressure, o.contact_half_width, o.contact_viscosity, o.sommerfeld_number];
        for (a, b) in exact(&op).into_iter().zip(exact(&full)) {
            assert!(a == b || ((a - b) / b).abs() < 1e-13, "{a} vs {b}");
        }
        assert_eq!(op.sliding_speed, full.sliding_speed);
        assert_eq!(op.regime, full.regime);
        assert_eq!(op.signed_torque().signum(), full.signed_torque().signum());
        // Interpolated ones within the tolerance.
        assert!(((op.lambda_ratio - full.lambda_ratio) / full.lambda_ratio).abs() <= 1e-6);
        let mu_parts = op.fluid_friction_coefficient + op.asperity_friction_coefficient;
        assert!(((mu_parts - op.friction_coefficient) / op.friction_coefficient).abs() < 1e-15);
    }
}

/// `Evaluator::torque_inside` (the torque alone, for the presliding law's bound) is bit for bit
/// the torque of `Evaluator::evaluate_inside`, and `None` exactly where it is: at every level,
/// for the paper's model (its film checked against the clearance) and the complete one (at the
/// cold day's temperature, with table cells answered by the complete solve), on random points
/// inside and around each envelope, at rest, with either sign of the load and of ω.
#[test]
fn the_torque_alone_is_the_evaluations_torque_bit_for_bit() {
    let mut cold = Params::default();
    cold.lubricant.temperature = 253.15;
    let spanning = Envelope::new(2e3, 200e3, 1e-3, 3.0).unwrap();
    // Where the grease's supply layer takes the fluid's share to zero at a finite speed.
    let cold_env = Envelope::new(200.0, 20e3, 0.1, 30.0).unwrap();
    let cases = [
        (Params::paper(), Fidelity::Table, 1e-4, brief()),
        (Params::paper(), Fidelity::Table, 1e-3, spanning),
        (Params::paper(), Fidelity::Boundary, 1e-4, brief()),
        (Params::default(), Fidelity::Table, 1e-4, brief()),
        (Params::default(), Fidelity::Boundary, 1e-4, brief()),
        (Params::default(), Fidelity::Auto, 1e-4, brief()),
        (Params::default(), Fidelity::Full, 1e-4, brief()),
        (cold, Fidelity::Table, 1e-3, cold_env),
    ];
    let (mut answered, mut refused, mut solved_cells) = (0, 0, 0);
    for (k, (p, fid, tol, env)) in cases.into_iter().enumerate() {
        let ev = Evaluator::new(&p, fid, tol, env).unwrap();
        solved_cells += ev.table().map_or(0, pinjoint::fidelity::StribeckTable::solved_cells);
        let mut rng = CheckRng::new(0x70_7175 + k as u64);
        // Fractions of the envelope in ln P and ln |ω| from −0.1 to 1.1: inside and around it.
        let widen = |lo: f64, hi: f64, f: f64| (lo.ln() + (1.2 * f - 0.1) * (hi.ln() - lo.ln())).exp();
        for i in 0..4000 {
            let load = widen(env.load_min, env.load_max, rng.uniform()) * if i % 7 == 3 { -1.0 } else { 1.0 };
            let speed = widen(env.speed_min, env.speed_max, rng.uniform());
            let omega = match i % 5 {
                0 => 0.0,
                1 => -speed,
                _ => speed,
            };
            let want = ev.evaluate_inside(load, omega).map(|e| e.torque.to_bits());
            assert_eq!(ev.torque_inside(load, omega).map(f64::to_bits), want, "case {k} ({fid}) at load {load} N, ω {omega} rad/s");
            if want.is_some() { answered += 1 } else { refused += 1 }
        }
        // The envelope's corners and edges exactly.
        for load in [env.load_min, env.load_max] {
            for omega in [0.0, env.speed_min, -env.speed_min, env.speed_max, -env.speed_max] {
                let want = ev.evaluate_inside(load, omega).map(|e| e.torque.to_bits());
                assert_eq!(ev.torque_inside(load, omega).map(f64::to_bits), want, "case {k} ({fid}) at load {load} N, ω {omega} rad/s");
            }
        }
    }
    // Both branches were exercised, and cells answered by the complete solve among them.
    assert!(answered > 10_000 && refused > 5_000 && solved_cells > 0, "{answered} {refused} {solved_cells}");
    // A point located in a larger table and answered by a smaller one: no panic (a cell the
    // table does not have is located again there).
    let big = Evaluator::new(&Params::default(), Fidelity::Table, 1e-4, brief()).unwrap();
    let small = Evaluator::new(&Params::default(), Fidelity::Table, 1e-2, brief()).unwrap();
    let cells = |ev: &Evaluator| ev.table().map(|t| t.stats().load_cells * t.stats().speed_cells).unwrap();
    assert!(cells(&big) > 4 * cells(&small), "{} {}", cells(&big), cells(&small));
    let (load, omega) = (0.99 * brief().load_max, 0.99 * brief().speed_max); // the last cells
    assert_eq!(small.torque_located(load, omega, big.locate_torque(load, omega)), small.torque_inside(load, omega));
}
