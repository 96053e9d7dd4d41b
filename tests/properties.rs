//! Property tests over random valid inputs: every output finite and in range, the
//! load-sharing identity, and continuity in speed and load.

use pinjoint::params::PARAMS;
use pinjoint::{Joint, Params};
use proptest::prelude::*;
use test_support::strategies::log10_uniform as log_uniform;

/// A random valid parameter set: each value scaled by 10^[-0.5, 0.5] from its default
/// (Poisson ratios kept below 0.5, the bush kept larger than the pin).
fn params() -> impl Strategy<Value = Params> {
    (prop::collection::vec(-0.5f64..0.5, PARAMS.len()), 1e-5f64..1e-3).prop_map(|(scales, clearance_rel)| {
        let mut p = Params::paper();
        for (s, k) in PARAMS.iter().zip(scales) {
            let v = s.default_value() * 10f64.powf(k);
            (s.set)(&mut p, v);
        }
        // The paper's model (the switches are not scaled; the complete model has its own
        // properties in tests/complete.rs).
        p.model.paper = true;
        p.grease = pinjoint::params::Grease::default();
        p.materials.pin_poisson_ratio = p.materials.pin_poisson_ratio.min(0.49);
        p.materials.bush_poisson_ratio = p.materials.bush_poisson_ratio.min(0.49);
        p.geometry.bush_radius = p.geometry.pin_radius * (1.0 + clearance_rel);
        // The lubricant at its reference temperature (the Table 3 values as drawn; the temperature
        // extension has its own tests in crates/fmu/tests/extensions.rs: scaled 10^±0.5, T and T_ref could
        // leave the admissible range or overflow η0).
        p.lubricant.temperature = p.lubricant.reference_temperature.clamp(pinjoint::params::PAPER_MIN_TEMPERATURE, 400.0);
        p.lubricant.reference_temperature = p.lubricant.temperature;
        p
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn outputs_finite_and_in_range(p in params(), load in log_uniform(1.0, 1e6), omega in prop_oneof![Just(0.0), log_uniform(1e-12, 1e4)], sign in prop::bool::ANY) {
        let j = Joint::new(&p).unwrap();
        // Beyond the asperity model's capacity the answer is a typed error (BeyondCapacity),
        // not an output: a drawn parameter set can have a capacity below the 1 MN drawn here.
        prop_assume!(load < j.capacity());
        let omega = if sign { omega } else { -omega };
        let o = match j.evaluate(load, omega) {
            // The film bound: an error only where the fluid carries the load and its film is
            // thicker than the diametral clearance.
            Err(pinjoint::ModelError::FilmBeyondClearance { film, limit, .. }) => {
                let u = j.evaluate_unbounded(load, omega).unwrap();
                prop_assert!(film > limit && limit == j.max_film_thickness() && u.film_thickness == film);
                prop_assert!(u.fluid_load_fraction >= pinjoint::joint::REGIME_SHARE);
                return Ok(());
            }
            r => r.unwrap(),
        };
        prop_assert!(o.film_thickness <= j.max_film_thickness() || o.fluid_load_fraction < pinjoint::joint::REGIME_SHARE);
        let mu_c = p.friction.boundary_friction_coefficient;
        for v in [o.friction_coefficient, o.torque, o.film_thickness, o.lambda_ratio, o.fluid_load_fraction,
                  o.asperity_load_fraction, o.mean_pressure, o.contact_half_width, o.sommerfeld_number] {
            prop_assert!(v.is_finite() && v >= 0.0, "{:?}", o);
        }
        prop_assert!(o.film_thickness > 0.0);
        prop_assert!(o.fluid_load_fraction <= 1.0 && o.asperity_load_fraction <= 1.0);
        prop_assert!((o.fluid_load_fraction + o.asperity_load_fraction - 1.0).abs() <= 2.0 * f64::EPSILON);
        // μ is bounded by its two terms' maxima: μ_c·1 + τ_L/p_m (Bair–Winer saturates at τ_L).
        let tau = p.lubricant.limiting_shear_stress + p.lubricant.limiting_shear_stress_slope * o.mean_pressure;
        prop_assert!(o.friction_coefficient <= mu_c + tau / o.mean_pressure);
        prop_assert!(o.asperity_friction_coefficient <= mu_c);
        prop_assert!((o.torque - o.friction_coefficient * p.geometry.pin_radius * load).abs() <= 1e-12 * o.torque);
        if omega == 0.0 {
            prop_assert_eq!(o.friction_coefficient, mu_c);
        }
    }

    #[test]
    fn continuous_in_speed_and_load(p in params(), load in log_uniform(1.0, 1e6), omega in log_uniform(1e-9, 1e4)) {
        let j = Joint::new(&p).unwrap();
        prop_assume!(load * (1.0 + 1e-7) < j.capacity());
        let a = j.evaluate_unbounded(load, omega).unwrap();
        for (dl, dw) in [(1.0, 1.0 + 1e-7), (1.0 + 1e-7, 1.0)] {
            let b = j.evaluate_unbounded(load * dl, omega * dw).unwrap();
            prop_assert!((b.film_thickness / a.film_thickness - 1.0).abs() < 1e-5, "{:?} {:?}", a, b);
            prop_assert!((b.friction_coefficient - a.friction_coefficient).abs() < 1e-5 * a.friction_coefficient.max(1e-3),
                "{:?} {:?}", a, b);
            prop_assert!((b.fluid_load_fraction - a.fluid_load_fraction).abs() < 1e-5);
        }
    }

    #[test]
    fn more_speed_never_thins_the_film(p in params(), load in log_uniform(1.0, 1e6), omega in log_uniform(1e-9, 1e4)) {
        let j = Joint::new(&p).unwrap();
        prop_assume!(load < j.capacity());
        let a = j.evaluate_unbounded(load, omega).unwrap();
        let b = j.evaluate_unbounded(load, omega * 1.5).unwrap();
        prop_assert!(b.fluid_load_fraction >= a.fluid_load_fraction);
        prop_assert!(b.film_thickness >= a.film_thickness * (1.0 - 1e-12));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// The cold evaluation (from the start table, often one residual evaluation ended by
    /// Halley's step) gives the root of a Newton iteration started far away, for any valid
    /// parameter set: to 1e-12 + 1e-13·|y| in the logit, and the asperity share accordingly.
    #[test]
    fn cold_root_is_newtons_root(p in params(), load in log_uniform(1.0, 1e6), omega in log_uniform(1e-9, 1e4)) {
        use pinjoint::contact::asperity::AsperityGroups;
        use pinjoint::load_sharing::solve::{solve_starved_with, FilmGroups};
        let j = Joint::new(&p).unwrap();
        prop_assume!(load < 0.5 * j.capacity() && p.starvation.inlet_layer_inverse == 0.0);
        let op = j.evaluate_unbounded(load, omega).unwrap();
        let (r, e, b, l) = (j.reduced_radius(), j.effective_modulus(), p.geometry.bush_length, j.lubricant());
        let film = FilmGroups::new(omega * p.geometry.pin_radius, r, e, b, load, l.viscosity, l.pressure_viscosity_coefficient);
        let asp = AsperityGroups::new(&p.surface, load, r, e, b);
        // (0.5 away, and beyond the tolerance 4ε|y| in deep full film, where |y| reaches 1e12.)
        let newton = solve_starved_with(Some(&film), &asp, &p.surface, Some(op.logit + 0.5 + 1e-6 * op.logit.abs()), None, false);
        prop_assert!(newton.evaluations > 1);
        prop_assert!((op.logit - newton.logit).abs() <= 1e-12 + 1e-13 * op.logit.abs(), "{} vs {} (Newton)", op.logit, newton.logit);
        // ∂ln x2/∂y = −x1: the shares move relatively by at most the logit's difference.
        let dy = 1e-12 + 1e-13 * op.logit.abs();
        prop_assert!((op.asperity_load_fraction - newton.asperity_fraction).abs() <= (2.0 * dy + 1e-14) * newton.asperity_fraction);
    }
}
