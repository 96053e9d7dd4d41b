//! The load-sharing solve and the operating point in every regime: convergence,
//! limits (docs/model.md, "Limits the solver meets"), monotonicity and continuity.

use pinjoint::contact::asperity::{softplus, AsperityGroups};
use pinjoint::contact::gw::ln_f32;
use pinjoint::load_sharing::solve::FilmGroups;
use pinjoint::{Joint, Params, Regime};

fn joint() -> Joint {
    Joint::new(&Params::paper()).unwrap()
}

/// Residual of eq. 13 = eq. 19 in the logit y, rebuilt here from the public pieces.
fn residual(j: &Joint, load: f64, omega: f64, y: f64) -> f64 {
    let p = j.params();
    let g = &p.geometry;
    let film = FilmGroups::new(
        omega.abs() * g.pin_radius,
        j.reduced_radius(),
        j.effective_modulus(),
        g.bush_length,
        load,
        p.lubricant.viscosity,
        p.lubricant.pressure_viscosity_coefficient,
    );
    let asp = AsperityGroups::new(&p.surface, load, j.reduced_radius(), j.effective_modulus(), g.bush_length);
    let h = film.ln_film(-softplus(-y)).exp();
    let t = (h - p.surface.summit_mean_plane_offset) / p.surface.summit_height_std;
    ln_f32(t) - asp.required_ln_f32(-softplus(y))
}

/// Speeds from 1e-12 rad/s to 1e4 rad/s, log-spaced.
fn speeds(n: usize) -> Vec<f64> {
    (0..n).map(|i| 10f64.powf(-12.0 + 16.0 * i as f64 / (n - 1) as f64)).collect()
}

#[test]
fn solution_is_bracketed_to_tolerance_and_mu_hc_converged_to_1e_10() {
    let j = joint();
    for load in [1.0, 5e3, 20e3, 60e3, 1e6] {
        for omega in speeds(60) {
            let op = j.evaluate_unbounded(load, omega).unwrap();
            let y = op.logit;
            // A bracket of ±(a few × tolerance) around the returned logit has a sign change:
            // the root is within it.
            // The root itself is only defined to ~|y|·1e-15·(a few): in deep full film
            // ln F ≈ −t²/2 ≈ −y, so a rounding δ in h moves the root by ≈ 2|y|δ. Hence the
            // |y| term; the 1e-11 is 100× the solver's absolute tolerance.
            let dy = 1e-11 + 1e-13 * y.abs();
            let (lo, hi) = (residual(&j, load, omega, y - dy), residual(&j, load, omega, y + dy));
            assert!(lo <= 0.0 && hi >= 0.0, "P={load} ω={omega}: root not bracketed near y={y}: {lo} {hi}");
            // Anywhere in that bracket μ and h_c agree with the returned ones to 1e-10.
            for yy in [y - dy, y + dy] {
                let x2 = 1.0 / (1.0 + yy.exp());
                let mu_c = j.params().friction.boundary_friction_coefficient;
                let mu_asp = mu_c * x2;
                let rel_mu = ((mu_asp + op.fluid_friction_coefficient) - op.friction_coefficient).abs() / op.friction_coefficient;
                assert!(rel_mu < 1e-10, "P={load} ω={omega}: μ moves by {rel_mu}");
            }
        }
    }
}

#[test]
fn shares_sum_to_one_to_rounding() {
    let j = joint();
    for load in [1.0, 20e3, 1e6] {
        for omega in speeds(50) {
            let op = j.evaluate_unbounded(load, omega).unwrap();
            let s = op.fluid_load_fraction + op.asperity_load_fraction;
            assert!((s - 1.0).abs() <= 2.0 * f64::EPSILON, "P={load} ω={omega}: {s}");
        }
    }
}

#[test]
fn zero_speed_is_the_boundary_limit_exactly() {
    let j = joint();
    for load in [1.0, 5e3, 20e3, 60e3, 1e6] {
        let op = j.evaluate_unbounded(load, 0.0).unwrap();
        assert_eq!(op.fluid_load_fraction, 0.0);
        assert_eq!(op.asperity_load_fraction, 1.0);
        assert_eq!(op.friction_coefficient, 0.12);
        assert_eq!(op.regime, Regime::Boundary);
        assert_eq!(op.sommerfeld_number, 0.0);
        assert!(op.film_thickness > 0.0 && op.film_thickness.is_finite());
        // Tiny speeds approach it continuously.
        for omega in [1e-12, 1e-9, 1e-6] {
            let o = j.evaluate_unbounded(load, omega).unwrap();
            assert!((o.friction_coefficient - 0.12).abs() < 1e-4 * (omega / 1e-6).sqrt().max(1e-6), "P={load} ω={omega}");
            assert!((o.film_thickness / op.film_thickness - 1.0).abs() < 1e-2 * (omega / 1e-6).sqrt().max(1e-6));
        }
        let tiny = j.evaluate_unbounded(load, 1e-12).unwrap();
        assert!((tiny.friction_coefficient - 0.12).abs() < 1e-9);
        assert!((tiny.film_thickness / op.film_thickness - 1.0).abs() < 1e-9);
        // Negative speed is the same joint turning the other way.
        let neg = j.evaluate_unbounded(load, -0.3).unwrap();
        let pos = j.evaluate_unbounded(load, 0.3).unwrap();
        assert_eq!(neg.friction_coefficient, pos.friction_coefficient);
        assert_eq!(neg.signed_torque(), -pos.signed_torque());
        assert!(pos.signed_torque() < 0.0);
    }
}

#[test]
fn boundary_torque_check_values() {
    // docs/model.md: μ_c R P_T = 67.2 N·m at 20 kN and 201.6 N·m at 60 kN at low speed.
    let j = joint();
    let t20 = j.evaluate(20e3, 1e-6).unwrap().torque;
    let t60 = j.evaluate(60e3, 1e-6).unwrap().torque;
    assert!((t20 - 67.2).abs() < 1e-3, "{t20}");
    assert!((t60 - 201.6).abs() < 1e-3, "{t60}");
    assert!((j.boundary_torque(20e3) - 67.2).abs() < 1e-9);
}

#[test]
fn fluid_share_rises_and_mu_falls_with_speed_until_the_stribeck_minimum() {
    let j = joint();
    for load in [1.0, 5e3, 20e3, 60e3, 1e6] {
        let ops: Vec<_> = speeds(400).into_iter().map(|w| j.evaluate_unbounded(load, w).unwrap()).collect();
        // 1/γ1 non-decreasing over the whole range.
        for w in ops.windows(2) {
            assert!(w[1].fluid_load_fraction >= w[0].fluid_load_fraction, "P={load}: 1/γ1 falls at ω={}", w[1].angular_velocity);
            assert!(w[1].film_thickness >= w[0].film_thickness * (1.0 - 1e-12), "P={load}: h_c falls at ω={}", w[1].angular_velocity);
        }
        // μ non-increasing up to its minimum (the Stribeck minimum); past it, in full film,
        // the Bair–Winer fluid term rises with speed (the hydrodynamic branch).
        let imin = (0..ops.len()).min_by(|&a, &b| ops[a].friction_coefficient.total_cmp(&ops[b].friction_coefficient)).unwrap();
        for w in ops[..=imin].windows(2) {
            assert!(w[1].friction_coefficient <= w[0].friction_coefficient, "P={load}: μ rises at ω={}", w[1].angular_velocity);
        }
        assert!(ops[imin].asperity_load_fraction < 0.05, "P={load}: minimum before full film");
        for w in ops[imin..].windows(2) {
            assert!(w[1].friction_coefficient >= w[0].friction_coefficient);
        }
    }
}

#[test]
fn full_film_limit_is_the_fluid_term_alone() {
    // At high speed 1/γ2 → 0 and μ is eq. 3 alone with h_c from the unscaled eq. 12 (γ1 = 1).
    let j = joint();
    let p = j.params();
    for (load, omega) in [(20e3, 300.0), (5e3, 1e3), (1.0, 1e4)] {
        let op = j.evaluate_unbounded(load, omega).unwrap();
        assert!(op.asperity_load_fraction < 1e-30, "P={load} ω={omega}: {}", op.asperity_load_fraction);
        assert_eq!(op.regime, Regime::FullFilm);
        // Independent: eq. 12 in plain (non-log) form.
        let (r, e, b) = (j.reduced_radius(), j.effective_modulus(), p.geometry.bush_length);
        let u = omega * p.geometry.pin_radius;
        let uu = p.lubricant.viscosity * u / (e * r);
        let w = load / (e * r * b);
        let (m, l) = (w / uu.sqrt(), p.lubricant.pressure_viscosity_coefficient * e * uu.powf(0.25));
        let (hh, _) = pinjoint::film::moes(m, l);
        let h = hh * r * uu.sqrt();
        assert!((op.film_thickness / h - 1.0).abs() < 1e-12, "h_c {} vs {h}", op.film_thickness);
        let pm = op.mean_pressure;
        let eta = pinjoint::rheology::viscosity::roelands(&p.lubricant, pm);
        let tau = p.lubricant.limiting_shear_stress + p.lubricant.limiting_shear_stress_slope * pm;
 // 1 − e^{−x} written as −expm1(−x): x is ~1e-8 at 1 N, where the plain form loses 8 digits.
        let mu = tau / pm * -(-eta * u / (tau * h)).exp_m1();
        assert!((op.friction_coefficient / mu - 1.0).abs() < 1e-12, "P={load} ω={omega}: {} vs {mu}", op.friction_coefficient);
    }
}

#[test]
fn continuous_across_regime_changes() {
    // Dense sweep through boundary → mixed → full film: no jumps. A jump would show as a
    // relative change between neighbours far larger than the local trend.
    let j = joint();
    for load in [5e3, 20e3, 60e3] {
        let n = 4000;
        let ws: Vec<f64> = (0..n).map(|i| 10f64.powf(-3.0 + 5.0 * i as f64 / (n - 1) as f64)).collect();
        let ops: Vec<_> = ws.iter().map(|&w| j.evaluate(load, w).unwrap()).collect();
        let mut regimes = std::collections::HashSet::new();
        for k in 1..n - 1 {
            regimes.insert(ops[k].regime);
            for f in [|o: &pinjoint::OperatingPoint| o.friction_coefficient, |o: &pinjoint::OperatingPoint| o.film_thickness] {
                let (a, b, c) = (f(&ops[k - 1]), f(&ops[k]), f(&ops[k + 1]));
                // Second difference small compared with first differences (smooth curve on this grid).
                let d1 = (c - a).abs() + 1e-12 * b.abs();
                assert!((c - 2.0 * b + a).abs() <= 0.5 * d1 + 1e-4 * b.abs(), "P={load}: kink at ω={}: {a} {b} {c}", ws[k]);
            }
            // No step between neighbours (0.3 % apart in speed) larger than 1.5 % of μ_c, or 1 % in h_c.
            assert!((ops[k + 1].friction_coefficient - ops[k].friction_coefficient).abs() < 1.8e-3, "P={load}: μ jump at ω={}", ws[k]);
            assert!((ops[k + 1].film_thickness / ops[k].film_thickness - 1.0).abs() < 0.01, "P={load}: h jump at ω={}", ws[k]);
        }
        // At the steepest step, a 10× finer grid gives ~10× smaller steps (continuity, not a jump).
        let k = (0..n - 1)
            .max_by(|&a, &b| {
                let d = |i: usize| (ops[i + 1].friction_coefficient - ops[i].friction_coefficient).abs();
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        let coarse = (ops[k + 1].friction_coefficient - ops[k].friction_coefficient).abs();
        let fine: Vec<f64> = (0..=10)
            .map(|i| j.evaluate(load, ws[k] * (ws[k + 1] / ws[k]).powf(f64::from(i) / 10.0)).unwrap().friction_coefficient)
            .collect();
        let fine_max = fine.windows(2).map(|w| (w[1] - w[0]).abs()).fold(0.0, f64::max);
        assert!(fine_max < 0.2 * coarse, "P={load}: refining does not shrink the step at ω={}", ws[k]);
        assert_eq!(regimes.len(), 3, "P={load}: sweep should visit all three regimes");
    }
}

#[test]
fn warm_start_gives_the_same_answer() {
    let j = joint();
    let mut prev: Option<f64> = None;
    for omega in speeds(300) {
        let cold = j.evaluate_unbounded(20e3, omega).unwrap();
        let warm = match j.evaluate_from(20e3, omega, prev) {
            Err(pinjoint::ModelError::FilmBeyondClearance { .. }) => continue,
            r => r.unwrap(),
        };
        assert!((warm.friction_coefficient / cold.friction_coefficient - 1.0).abs() < 1e-12);
        assert!((warm.film_thickness / cold.film_thickness - 1.0).abs() < 1e-12);
        prev = Some(cold.logit);
    }
    // A poor guess still converges.
    let far = j.evaluate_from(20e3, 1.0, Some(500.0)).unwrap();
    let cold = j.evaluate_unbounded(20e3, 1.0).unwrap();
    assert!((far.friction_coefficient / cold.friction_coefficient - 1.0).abs() < 1e-12);
}

#[test]
fn invalid_operating_points_are_named() {
    let j = joint();
    for bad in [0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = j.evaluate(bad, 1.0).unwrap_err().to_string();
        assert!(e.contains("load") && e.contains(" N"), "{e}");
    }
    // A negative load is the magnitude of the radial reaction (issue 9): the same point.
    assert_eq!(j.evaluate(-1e3, 1.0).unwrap(), j.evaluate(1e3, 1.0).unwrap());
    // A film thicker than the diametral clearance is an error naming it (1 N at 1 rad/s: 1.9 mm).
    let e = j.evaluate(1.0, 1.0).unwrap_err();
    assert!(matches!(e, pinjoint::ModelError::FilmBeyondClearance { .. }), "{e}");
    let m = e.to_string();
    assert!(m.contains("film_thickness = 0.00194983") && m.contains("2(R_b - R) = 5.0000000000001") && m.contains("load = 1 N"), "{m}");
    assert_eq!(j.evaluate(-1.0, 1.0), j.evaluate(1.0, 1.0));
    let e = j.evaluate(1e3, f64::NAN).unwrap_err().to_string();
    assert!(e.contains("angular velocity") && e.contains("rad/s"), "{e}");
}

#[test]
fn extreme_operating_range_is_finite() {
    let j = joint();
    for load in [1.0, 10.0, 1e3, 1e5, 1e6, 1e7] {
        for omega in [0.0, 5e-324, 1e-300, 1e-12, 1.0, 1e3, 1e4, 1e6] {
            let o = j.evaluate_unbounded(load, omega).unwrap();
            for (name, v) in [
                ("mu", o.friction_coefficient),
                ("h", o.film_thickness),
                ("x1", o.fluid_load_fraction),
                ("x2", o.asperity_load_fraction),
                ("torque", o.torque),
                ("S", o.sommerfeld_number),
                ("lambda", o.lambda_ratio),
            ] {
                assert!(v.is_finite() && v >= 0.0, "P={load} ω={omega}: {name} = {v}");
            }
            assert!(o.film_thickness > 0.0);
        }
    }
}

#[test]
fn asperity_capacity_bounds_the_load() {
    // Fuzz finding 2: at rest eq. 19 gives h_c = d_d + σ_s t < 0 above ≈ 5.05e8 N for the
    // paper's joint. Such loads are an error naming the load and the capacity.
    let j = joint();
    let cap = j.capacity();
    assert!(cap > 5.0e8 && cap < 5.1e8, "capacity {cap}");
    let below = j.evaluate(cap * (1.0 - 1e-6), 0.0).unwrap();
    assert!(below.film_thickness > 0.0 && below.film_thickness < 1e-11, "{}", below.film_thickness);
    for omega in [0.0, 1e-300, 1.0] {
        let e = j.evaluate(cap * 1.01, omega).unwrap_err().to_string();
        assert!(e.contains("load = ") && e.contains(" N") && e.contains("capacity"), "{e}");
    }
    // The capacity is where the rest film crosses zero: continuity of h_c in load below it.
    let h1 = j.evaluate(cap * 0.5, 0.0).unwrap().film_thickness;
    let h2 = j.evaluate(cap * 0.9, 0.0).unwrap().film_thickness;
    assert!(h1 > h2 && h2 > 0.0);
}

#[test]
fn overflowing_viscosity_is_harmless_at_rest_and_named_elsewhere() {
    // Fuzz finding 7: with Z = 4× its default the Roelands viscosity at p_m overflows at
    // 2.3e8 N; at rest μ must still be μ_c exactly (no ∞·0), and a moving point gives a
    // finite μ (the Bair–Winer exponent is formed from ln η).
    let mut p = Params::paper();
    p.lubricant.roelands_index *= 4.0;
    let j = Joint::new(&p).unwrap();
    let load = 2.3e8_f64.min(0.9 * j.capacity());
    let rest = j.evaluate(load, 0.0).unwrap();
    assert_eq!(rest.contact_viscosity, f64::INFINITY, "the case must overflow to test anything");
    assert_eq!(rest.friction_coefficient, p.friction.boundary_friction_coefficient);
    match j.evaluate(load, 1.0) {
        Ok(op) => assert!(op.friction_coefficient.is_finite()),
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn degenerate_but_valid_parameters_never_give_nan() {
    // Fuzz finding 1: subnormal lengths and moduli pass `validate` (they are > 0); the
    // evaluation must then be an error that names a quantity, never a NaN.
    for (name, v) in [("geometry.pin_radius", 8.5e-322), ("materials.pin_elastic_modulus", 5e-324), ("geometry.bush_length", 1e-300)] {
        let mut p = Params::paper();
        p.set_by_name(name, v).unwrap();
        if name == "geometry.pin_radius" {
            p.geometry.bush_radius = 1e-3;
        }
        let Ok(j) = Joint::new(&p) else { continue };
        for omega in [0.0, 1.0] {
            match j.evaluate(20e3, omega) {
                Ok(op) => {
                    for v in [op.friction_coefficient, op.film_thickness, op.torque, op.lambda_ratio] {
                        assert!(v.is_finite(), "{name}: {op:?}");
                    }
                }
                Err(e) => assert!(!e.to_string().is_empty()),
            }
        }
    }
}

#[test]
fn friction_at_is_the_evaluations_torque_bit_for_bit() {
    // Joint::friction_at (the rig's lean path, load terms computed once) gives the torque, μ and
    // root of Joint::evaluate_from with the same start, bit for bit, and the same errors.
    let j = joint();
    for load in [5e3, 20e3, -60e3] {
        let lt = j.load_terms(load).unwrap();
        for omega in speeds(40).into_iter().chain([0.0, -3.0]) {
            for guess in [None, Some(-1.0), Some(40.0)] {
                // Beyond the film bound both give the same error (ModelError::FilmBeyondClearance).
                let (op, f) = match (j.evaluate_from(load, omega, guess), j.friction_at(&lt, omega, guess)) {
                    (Ok(op), Ok(f)) => (op, f),
                    (a, b) => {
                        assert_eq!(a.unwrap_err(), b.unwrap_err(), "P={load} ω={omega}");
                        continue;
                    }
                };
                assert_eq!(f.torque.to_bits(), op.torque.to_bits(), "P={load} ω={omega} {guess:?}");
                assert_eq!(f.friction_coefficient.to_bits(), op.friction_coefficient.to_bits());
                assert_eq!(f.logit.to_bits(), op.logit.to_bits());
            }
        }
    }
    assert_eq!(j.load_terms(0.0).unwrap_err(), j.evaluate(0.0, 1.0).unwrap_err());
    assert_eq!(j.load_terms(1e12).unwrap_err(), j.evaluate(1e12, 1.0).unwrap_err());
    let lt = j.load_terms(20e3).unwrap();
    assert_eq!(j.friction_at(&lt, f64::NAN, None).unwrap_err().to_string(), j.evaluate(20e3, f64::NAN).unwrap_err().to_string());
}

#[test]
fn root_sensitivities_match_finite_differences() {
    // ∂y/∂ln u and ∂y/∂ln P from the implicit function theorem (the rig's predictor, the start
    // table's derivatives) against central differences of converged roots.
    let j = joint();
    let lt = |p: f64| j.load_terms(p).unwrap();
    for (load, omega) in [(5e3, 0.05), (20e3, 0.6), (20e3, 6.0), (60e3, 10.0), (30e3, 30.0)] {
        let f = j.friction_at(&lt(load), omega, None).unwrap();
        let e: f64 = 1e-5;
        let y = |p: f64, w: f64| j.evaluate(p, w).unwrap().logit;
        let du = (y(load, omega * e.exp()) - y(load, omega * (-e).exp())) / (2.0 * e);
        let dp = (y(load * e.exp(), omega) - y(load * (-e).exp(), omega)) / (2.0 * e);
        assert!((f.dlogit_dln_speed - du).abs() < 1e-6 * (1.0 + du.abs()), "P={load} ω={omega}: {} vs {du}", f.dlogit_dln_speed);
        assert!((f.dlogit_dln_load - dp).abs() < 1e-6 * (1.0 + dp.abs()), "P={load} ω={omega}: {} vs {dp}", f.dlogit_dln_load);
    }
}

#[test]
fn a_start_within_rounding_of_the_root_stops_at_once() {
    // A Newton step below the tolerance ends the solve even when it rounds onto the end of
    // the bracket just evaluated (it used to bisect that converged bracket, 10 evaluations).
    let j = joint();
    let lt = j.load_terms(20e3).unwrap();
    let root = j.evaluate(20e3, 1.0177).unwrap().logit;
    for d in [0.0, 8.8e-12, -8.8e-12, 1e-9] {
        let f = j.friction_at(&lt, 1.0177, Some(root + d)).unwrap();
        assert!(f.evaluations <= 2, "start {d:e} off: {} evaluations", f.evaluations);
        assert!((f.logit - root).abs() < 1e-12, "{d:e}");
    }
}

#[test]
fn the_one_evaluation_solve_agrees_with_newton_to_1e_13() {
    // A cold solve that ends with the third-order step after one residual evaluation gives the
    // root of a Newton iteration from a far start (0.5 away: no third-order step) to 1e-13 in
    // the logit, and h_c to 1e-12; and in the boundary and mixed regimes, on the start table's
    // speed range, it is the common case (the table's start within THIRD_ORDER_ACCEPT of the root).
    use pinjoint::load_sharing::solve::{solve_starved_with, THIRD_ORDER_ACCEPT};
    let j = joint();
    let p = j.params();
    let g = &p.geometry;
    let (mut one, mut total) = (0, 0);
    for load in [1.0, 300.0, 5e3, 20e3, 60e3, 1e6] {
        let asp = AsperityGroups::new(&p.surface, load, j.reduced_radius(), j.effective_modulus(), g.bush_length);
        for omega in speeds(400) {
            let u = omega * g.pin_radius;
            let film = FilmGroups::new(u, j.reduced_radius(), j.effective_modulus(), g.bush_length, load, p.lubricant.viscosity, p.lubricant.pressure_viscosity_coefficient);
            let start = j.cold_start(load, omega);
            let cold = solve_starved_with(Some(&film), &asp, &p.surface, Some(start), None, false);
            let far = solve_starved_with(Some(&film), &asp, &p.surface, Some(start + 0.5), None, false);
            assert!(far.evaluations > 1);
            let tol = 1e-13 + 8.0 * f64::EPSILON * cold.logit.abs();
            assert!((cold.logit - far.logit).abs() <= tol, "P={load} ω={omega}: {} vs {} ({} evaluations)", cold.logit, far.logit, cold.evaluations);
            assert!((cold.film_thickness / far.film_thickness - 1.0).abs() < 1e-12, "P={load} ω={omega}: h_c");
            let op = j.evaluate_unbounded(load, omega).unwrap();
            // (The joint scales its groups from 1 N and 1 m/s: the same solve to rounding.)
            assert!((op.logit - cold.logit).abs() <= 1e-12 + 1e-13 * cold.logit.abs(), "P={load} ω={omega}: evaluate {} vs {}", op.logit, cold.logit);
            if cold.asperity_fraction > 0.01 && u >= pinjoint::load_sharing::start::SPEED_RANGE.0 {
                total += 1;
                if cold.evaluations == 1 {
                    one += 1;
                    assert!((start - cold.logit).abs() <= 1.1 * THIRD_ORDER_ACCEPT);
                }
            }
        }
    }
    // (The others are in the last part of the transition to full film, where the table's
    // start is 1e-4 to 1e-2 off.)
    assert!(one * 100 >= total * 85, "{one} of {total} boundary/mixed solves took one evaluation");
}

#[test]
fn a_cold_evaluation_is_the_same_whatever_was_evaluated_before() {
    // The start table's rows are solved on first use; each is a function of its load alone,
    // so a cold evaluation is bit-identical whichever points (and rows) came before, in
    // whichever order, on whichever thread, and in a clone.
    let points = [(20e3, 6.0), (5e3, 0.05), (60e3, 30.0), (20e3, -6.0), (1.0, 1e-3), (7e5, 2.0), (20e3, 6.3)];
    let fresh: Vec<_> = points.iter().map(|&(p, w)| joint().evaluate(p, w).unwrap()).collect();
    let j = joint();
    let mut order: Vec<usize> = (0..points.len()).rev().collect();
    order.rotate_left(2);
    for &k in &order {
        let (p, w) = points[k];
        assert_eq!(j.evaluate(p, w).unwrap(), fresh[k], "after others: P={p} ω={w}");
    }
    let j2 = joint();
    std::thread::scope(|s| {
        for (k, &(p, w)) in points.iter().enumerate() {
            let (j2, fresh) = (&j2, &fresh);
            s.spawn(move || assert_eq!(j2.evaluate(p, w).unwrap(), fresh[k], "threaded: P={p} ω={w}"));
        }
    });
    let c = j.clone();
    for (k, &(p, w)) in points.iter().enumerate() {
        assert_eq!(c.evaluate(p, w).unwrap(), fresh[k], "clone: P={p} ω={w}");
        let warm = c.evaluate_from(p, w, Some(fresh[k].logit)).unwrap().friction_coefficient;
        assert!((warm / fresh[k].friction_coefficient - 1.0).abs() < 1e-13, "started at the root: P={p} ω={w}");
    }
    assert_eq!(c, joint(), "equal joints whatever rows each has solved");
}

#[test]
fn friction_cold_at_is_evaluate_bit_for_bit_whatever_came_before() {
    // Joint::friction_cold_at (what the rig integrates) starts from the table and skips the
    // sensitivities: the torque and μ of Joint::evaluate bit for bit, in any call order, and
    // the sensitivities NaN while moving (0 at rest).
    let j = joint();
    for load in [5e3, 20e3, -60e3] {
        let lt = j.load_terms(load).unwrap();
        let mut omegas: Vec<f64> = speeds(40).into_iter().chain([0.0, -3.0]).collect();
        for pass in 0..2 {
            for &omega in &omegas {
                let (op, f) = match (j.evaluate(load, omega), j.friction_cold_at(&lt, omega)) {
                    (Ok(op), Ok(f)) => (op, f),
                    (a, b) => {
                        assert_eq!(a.unwrap_err(), b.unwrap_err(), "P={load} ω={omega}");
                        continue;
                    }
                };
                assert_eq!(f.torque.to_bits(), op.torque.to_bits(), "P={load} ω={omega} pass {pass}");
                assert_eq!(f.friction_coefficient.to_bits(), op.friction_coefficient.to_bits());
                assert_eq!(f.logit.to_bits(), op.logit.to_bits());
                if omega != 0.0 {
                    assert!(f.dlogit_dln_speed.is_nan() && f.dlogit_dln_load.is_nan(), "ω={omega}");
                }
            }
            omegas.reverse();
        }
    }
    let lt = j.load_terms(20e3).unwrap();
    assert_eq!(j.friction_cold_at(&lt, f64::INFINITY).unwrap_err().to_string(), j.evaluate(20e3, f64::INFINITY).unwrap_err().to_string());
}
