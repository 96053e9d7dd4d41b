//! Issue 13 items 3–5: the extensions beyond the paper (h_min, temperature, starved inlet)
//! against their limits, their sources' forms and the paper model they must leave unchanged.

use pinjoint::{Joint, OperatingPoint, Params};

fn points() -> Vec<(f64, f64)> {
    let mut v = Vec::new();
    for &p in &[5e3, 20e3, 60e3] {
        for &w in &[0.0, 1e-6, 0.01, 0.2, 1.0, 4.39, 20.0, 83.8, 1000.0] {
            v.push((p, w));
        }
    }
    v
}

#[test]
fn reference_temperature_reproduces_the_paper_model_bit_for_bit() {
    let base = Joint::new(&Params::paper()).unwrap();
    // Any reference temperature, with T = T_ref, and any S0: identical doubles.
    for (t, s0) in [(293.15, 1.262), (250.0, 3.0), (400.0, 0.0)] {
        let mut p = Params::paper();
        p.lubricant.temperature = t;
        p.lubricant.reference_temperature = t;
        p.lubricant.roelands_temperature_index = s0;
        let j = Joint::new(&p).unwrap();
        for (load, w) in points() {
            let (a, b) = (base.evaluate_unbounded(load, w).unwrap(), j.evaluate_unbounded(load, w).unwrap());
            let bits = |o: &OperatingPoint| {
                [o.friction_coefficient, o.torque, o.film_thickness, o.fluid_load_fraction, o.sommerfeld_number, o.contact_viscosity, o.min_film_thickness].map(f64::to_bits)
            };
            assert_eq!(bits(&a), bits(&b), "T = {t}, P = {load}, ω = {w}");
        }
    }
}

fn at(t: f64) -> Joint {
    let mut p = Params::paper();
    p.lubricant.temperature = t;
    Joint::new(&p).unwrap()
}

#[test]
fn colder_means_more_viscous_and_lower_mu_at_mixed_speeds_hotter_the_opposite() {
    let (cold, room, hot) = (at(253.15), at(293.15), at(333.15)); // −20, 20, 60 °C
    assert!(cold.lubricant().viscosity > room.lubricant().viscosity && room.lubricant().viscosity > hot.lubricant().viscosity);
    // Mixed-regime speeds at 20 kN (the flooded model's film carries half the load near 107 rpm).
    for &w in &[0.5, 1.0, 2.0, 4.39] {
        let (c, r, h) = (cold.evaluate(20e3, w).unwrap(), room.evaluate(20e3, w).unwrap(), hot.evaluate(20e3, w).unwrap());
        assert_eq!(r.regime, pinjoint::Regime::Mixed, "ω = {w}");
        assert!(c.friction_coefficient < r.friction_coefficient, "ω = {w}: {} vs {}", c.friction_coefficient, r.friction_coefficient);
        assert!(h.friction_coefficient > r.friction_coefficient, "ω = {w}");
        assert!(c.film_thickness > r.film_thickness && r.film_thickness > h.film_thickness);
    }
    // At rest the temperature changes nothing (μ = μ_c, film from the asperities alone).
    let (c, r) = (cold.evaluate(20e3, 0.0).unwrap(), room.evaluate(20e3, 0.0).unwrap());
    assert_eq!(c.friction_coefficient, r.friction_coefficient);
    assert_eq!(c.film_thickness.to_bits(), r.film_thickness.to_bits());
}

#[test]
fn cold_soak_and_hot_apron_viscosities() {
    // −55 °C and +70 °C with the defaults: the numbers the README and FMU pages quote. (−55 °C
    // is below the model's declared temperature range, −35 °C, where the film would pass the
    // clearance at rig speeds: the viscosity relation itself is evaluated there.)
    let cold = |t: f64| pinjoint::rheology::viscosity::at_temperature(&pinjoint::params::Lubricant { temperature: t, ..Params::paper().lubricant }).viscosity;
    let (c, h) = (cold(218.15), at(343.15).lubricant().viscosity);
    assert!((c / 12.25 - 1.0).abs() < 0.01, "{c}");
    assert!((h / 2.59e-3 - 1.0).abs() < 0.01, "{h}");
}

#[test]
fn an_overflowing_temperature_is_a_typed_error() {
    let mut p = Params::paper();
    p.lubricant.temperature = 140.0;
    p.lubricant.roelands_temperature_index = 60.0;
    let e = Joint::new(&p).unwrap_err().to_string();
    assert!(e.contains("lubricant.temperature = 140 K"), "{e}");
}

fn starved(h_oil: f64, gamma: f64) -> Joint {
    let mut p = Params::paper();
    p.starvation.inlet_layer_inverse = 1.0 / h_oil;
    p.starvation.exponent = gamma;
    Joint::new(&p).unwrap()
}

#[test]
fn starvation_off_is_the_flooded_model_and_a_thick_layer_tends_to_it() {
    let flooded = Joint::new(&Params::paper()).unwrap();
    // Off (1/h_oil = 0, the default) whatever the exponent: bit for bit.
    let mut p = Params::paper();
    p.starvation.exponent = 1.3;
    let off = Joint::new(&p).unwrap();
    for (load, w) in points() {
        let (a, b) = (flooded.evaluate_unbounded(load, w).unwrap(), off.evaluate_unbounded(load, w).unwrap());
        assert_eq!(a.friction_coefficient.to_bits(), b.friction_coefficient.to_bits());
        assert_eq!(a.film_thickness.to_bits(), b.film_thickness.to_bits());
    }
    // A layer far thicker than any film: the flooded answer to rounding (h = h_ff(1 + R^−γ)^(−1/γ)).
    let thick = starved(1.0, 2.8); // 1 m
    for (load, w) in points() {
        let (a, b) = (flooded.evaluate_unbounded(load, w).unwrap(), thick.evaluate_unbounded(load, w).unwrap());
        assert!((a.friction_coefficient / b.friction_coefficient - 1.0).abs() < 1e-9, "P = {load}, ω = {w}");
        assert!((a.film_thickness / b.film_thickness - 1.0).abs() < 1e-9);
    }
    // Thinner layers: μ never lower than flooded, and monotone in the layer.
    for (load, w) in points() {
        let mut prev = flooded.evaluate_unbounded(load, w).unwrap().friction_coefficient;
        for h in [20e-6, 8e-6, 5e-6, 4e-6, 3e-6] {
            let mu = starved(h, 2.8).evaluate_unbounded(load, w).unwrap().friction_coefficient;
            assert!(mu >= prev - 1e-12, "P = {load}, ω = {w}, h_oil = {h}: {mu} < {prev}");
            prev = mu;
        }
    }
}

#[test]
fn starved_film_obeys_its_relation_where_the_fluid_carries_everything() {
    // At high speed the asperities carry ~nothing, so the solved h_c is the starved film of the
    // fluid-only problem: h = (h_ff^−γ + h_oil^−γ)^(−1/γ) with h_ff the flooded full film.
    let flooded = Joint::new(&Params::paper()).unwrap();
    let (load, w) = (5e3, 1000.0);
    let hff = flooded.evaluate_unbounded(load, w).unwrap();
    assert!(hff.asperity_load_fraction < 1e-12);
    for (r, g) in [(1.0, 2.8), (0.5, 2.8), (2.0, 3.5)] {
        let h_oil = r * hff.film_thickness;
        let s = starved(h_oil, g).evaluate_unbounded(load, w).unwrap();
        let want = hff.film_thickness * pinjoint::film::starvation::starved_ratio(r, g);
        if s.asperity_load_fraction < 1e-9 {
            assert!((s.film_thickness / want - 1.0).abs() < 1e-6, "R = {r}: {} vs {want}", s.film_thickness);
        }
    }
}

#[test]
fn a_layer_thinner_than_the_rest_gap_leaves_the_joint_in_boundary_friction() {
    let flooded = Joint::new(&Params::paper()).unwrap();
    let rest = flooded.evaluate(20e3, 0.0).unwrap().film_thickness;
    let j = starved(0.9 * rest, 2.8);
    for &w in &[0.01, 1.0, 100.0, 1000.0] {
        let o = j.evaluate(20e3, w).unwrap();
        assert_eq!(o.fluid_load_fraction, 0.0);
        assert_eq!(o.asperity_load_fraction, 1.0);
        // μ = μ_c plus the (tiny) Bair–Winer shear of the starved layer.
        assert!(o.friction_coefficient >= 0.12);
    }
}

#[test]
fn min_film_is_below_the_central_film_and_zero_at_rest() {
    let j = Joint::new(&Params::paper()).unwrap();
    for (load, w) in points() {
        let o = j.evaluate_unbounded(load, w).unwrap();
        assert!(o.min_film_thickness <= o.film_thickness && o.min_film_thickness >= 0.0);
        assert_eq!(o.min_lambda_ratio, o.min_film_thickness / j.composite_roughness());
        if w == 0.0 {
            assert_eq!(o.min_film_thickness, 0.0);
        } else if w >= 0.2 {
            assert!(o.min_film_thickness > 0.3 * o.film_thickness, "P = {load}, ω = {w}: {}", o.min_film_thickness / o.film_thickness);
        }
    }
}

#[test]
fn fmu_temperature_input_and_min_film_outputs_are_the_library_values() {
    use fmi_layer::core::model::Model;
    use pinjoint_fmu::pin_joint::model::PinJointModel;
    use pinjoint_fmu::pin_joint::variables::TABLE;
    let index = |name: &str| TABLE.index(name).unwrap();
    let (angular_velocity, load, temperature) = (index("angular_velocity"), index("load"), index("temperature"));
    let mut m = PinJointModel::new();
    // Default input 293.15 K, with model.paper = true: the paper model, bit for bit.
    m.set_real(index("model.paper"), 1.0);
    assert_eq!(m.get_real(temperature), 293.15);
    m.set_real(load, 20e3);
    m.set_real(angular_velocity, 1.0);
    m.exit_initialization(0.0).unwrap();
    m.compute_outputs().unwrap();
    let out = |m: &PinJointModel, o: &str| m.get_real(index(o));
    let op = Joint::new(&Params::paper()).unwrap().evaluate(20e3, 1.0).unwrap();
    assert_eq!(out(&m, "friction_coefficient").to_bits(), op.friction_coefficient.to_bits());
    assert_eq!(out(&m, "min_film_thickness").to_bits(), op.min_film_thickness.to_bits());
    assert_eq!(out(&m, "min_lambda_ratio").to_bits(), op.min_lambda_ratio.to_bits());
    // A cold lubricant through the input: the library at that temperature.
    assert!(m.check_real(temperature, 100.0).is_err());
    m.check_real(temperature, 253.15).unwrap();
    m.set_real(temperature, 253.15);
    m.compute_outputs().unwrap();
    let cold = at(253.15).evaluate(20e3, 1.0).unwrap();
    assert_eq!(out(&m, "friction_coefficient").to_bits(), cold.friction_coefficient.to_bits());
    assert!(cold.friction_coefficient < op.friction_coefficient);
}
