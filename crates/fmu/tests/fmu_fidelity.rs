//! The PinJoint FMU's fidelity parameters: `fidelity` (Integer 0..3), `tolerance` and the
//! envelope, built at exit of initialization. Outputs under `table` stay within the tolerance
//! of `full`, auto logs its choice, a fallback outside the envelope is logged once, and bad
//! values are refused with the parameter's name, value and unit.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::fmi2::types::Fmi2Component;
use pinjoint::{Joint, Params};

fn set_fidelity(c: Fmi2Component, code: i32) -> i32 {
    let r = [vr("fidelity")];
    unsafe { fmi2SetInteger(c, r.as_ptr(), 1, [code].as_ptr()) }
}

/// Instantiate with `fidelity` = `code` and real parameters `sets`, initialize with debug logging.
fn ready(h: &Host, code: i32, sets: &[(&str, f64)]) -> Fmi2Component {
    let c = h.instantiate_with("joint", 1, &guid(), Some("file:///tmp"), true);
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(set_fidelity(c, code), OK, "{}", h.last());
    for (n, v) in sets {
        assert_eq!(set(c, n, *v), OK, "{n}: {}", h.last());
    }
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
    c
}

fn rel(a: f64, b: f64) -> f64 {
    if a == b { 0.0 } else { ((a - b) / b).abs() }
}

/// Points of the default envelope (5-60 kN, 0.01-10 rad/s) the library's tests do not use.
fn points() -> Vec<(f64, f64)> {
    (0..300).map(|k| {
        let a = (f64::from(k) * 0.6180339887).fract();
        let b = (f64::from(k) * 0.4142135623).fract();
        let w = (0.01f64.ln() + b * (10f64.ln() - 0.01f64.ln())).exp();
        (5e3 + a * 55e3, if k % 2 == 0 { w } else { -w })
    }).collect()
}

#[test]
fn table_outputs_stay_within_the_tolerance_of_full() {
    for tol in [1e-3, 1e-4] {
        let h = Host::new();
        let full = ready(&h, 0, &[]);
        let table = ready(&h, 1, &[("tolerance", tol)]);
        let mut differ = false;
        for (p, w) in points() {
            for c in [full, table] {
                assert_eq!(set(c, "load", p), OK);
                assert_eq!(set(c, "angular_velocity", w), OK);
            }
            for name in ["friction_coefficient", "torque", "film_thickness"] {
                let (a, b) = (get(table, name), get(full, name));
                assert!(rel(a, b) <= tol, "{name} at {p} N, {w} rad/s: table {a} vs full {b} (tolerance {tol})");
                differ |= a != b;
            }
            let (a, b) = (get(table, "fluid_load_fraction"), get(full, "fluid_load_fraction"));
            assert!((a - b).abs() <= tol, "shares at {p} N, {w} rad/s");
        }
        assert!(differ, "the table level must not be the full solve");
        // ... and full is the library's solve.
        let j = Joint::new(&Params::default()).unwrap();
        assert!(rel(get(full, "friction_coefficient"), j.evaluate(get(full, "load"), get(full, "angular_velocity")).unwrap().friction_coefficient) < 1e-10);
        unsafe { fmi2FreeInstance(full) };
        unsafe { fmi2FreeInstance(table) };
    }
}

#[test]
fn auto_logs_its_choice_and_a_fallback_is_logged_once() {
    let h = Host::new();
    let c = ready(&h, 3, &[("tolerance", 1e-4)]);
    let log: Vec<String> = h.messages().into_iter().map(|m| m.text).collect();
    assert!(log.iter().any(|m| m.contains("fidelity auto -> table") && m.contains("measured error bound")), "{log:?}");
    for (i, w) in [50.0, 60.0, 0.5, 70.0].into_iter().enumerate() {
        assert_eq!(set(c, "angular_velocity", w), OK);
        let _ = get(c, "torque");
        assert_eq!(fmi2DoStep(c, 0.001 * i as f64, 0.001, 1), OK);
    }
    let falls = h.messages().iter().filter(|m| m.text.contains("outside the envelope")).count();
    assert_eq!(falls, 1, "{:?}", h.messages());
    // Outside the envelope the answer is the full solve.
    let j = Joint::new(&Params::default()).unwrap();
    assert!(rel(get(c, "friction_coefficient"), j.evaluate(20e3, 70.0).unwrap().friction_coefficient) < 1e-10);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn fidelity_parameters_are_checked_and_readable() {
    let h = Host::new();
    let c = h.instantiate();
    let r = [vr("fidelity")];
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    let mut v = [9];
    assert_eq!(unsafe { fmi2GetInteger(c, r.as_ptr(), 1, v.as_mut_ptr()) }, OK);
    assert_eq!(v[0], 0, "default: full");
    assert_eq!(set_fidelity(c, 4), ERROR);
    assert!(h.last().contains("fidelity = 4") && h.last().contains("3 (auto)"), "{}", h.last());
    // fidelity is an Enumeration (Integer functions): the Real setter refuses it.
    assert_eq!(unsafe { fmi2SetReal(c, r.as_ptr(), 1, [1.0].as_ptr()) }, ERROR);
    assert!(h.last().contains("an Enumeration variable, not Real"), "{}", h.last());
    // A bad envelope is refused at exit of initialization, naming it with its unit.
    assert_eq!(set_fidelity(c, 1), OK);
    assert_eq!(unsafe { fmi2GetInteger(c, r.as_ptr(), 1, v.as_mut_ptr()) }, OK);
    assert_eq!(v[0], 1);
    assert_eq!(set(c, "envelope.load_min", 70e3), OK);
    assert_eq!(fmi2ExitInitializationMode(c), ERROR);
    assert!(h.last().contains("load") && h.last().contains("70000 N"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
    let c = h.instantiate();
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(set_fidelity(c, 1), OK);
    assert_eq!(set(c, "tolerance", 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), ERROR);
    assert!(h.last().contains("tolerance = 0"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}

/// What a table or the boundary level leaves of the operating point (Hertz, Sommerfeld, h_min,
/// the clearance's outputs) is computed when the host reads it: whichever outputs the host
/// reads, in whatever order, before or after a step, every output is bit for bit what an
/// instance reading all of them at once gives, and the derived ones are the library's
/// evaluator's (`Evaluator::evaluate_complete` at the same level), at loads and speeds of
/// both signs and temperatures from -54 C to +120 C (the journal weight and the clearance
/// torque away from 0 at the light loads).
#[test]
fn outputs_read_one_at_a_time_are_those_read_all_at_once() {
    let names: Vec<String> = {
        let md = pinjoint_fmu::pin_joint::INFO.variables.iter();
        md.filter(|v| v.causality == fmi_layer::core::variables::Causality::Output && v.kind == fmi_layer::core::variables::Kind::Real).map(|v| v.name.clone()).collect()
    };
    let derived = pinjoint::fidelity::evaluation::DERIVED_COLUMNS;
    assert!(derived.iter().filter(|d| names.iter().any(|n| n == *d)).count() >= 8, "{names:?}");
    let h = Host::new();
    let mut light = false;
    for code in [1, 2] {
        for (k, temperature) in [219.15, 253.15, 293.15, 393.15].into_iter().enumerate() {
            let sets = [("tolerance", 1e-3), ("temperature", temperature), ("envelope.load_min", 200.0), ("envelope.speed_max", 30.0)];
            let (all, one) = (ready(&h, code, &sets), ready(&h, code, &sets));
            let mut params = Params::default();
            params.lubricant.temperature = temperature;
            let joint = Joint::new(&params).unwrap();
            let mut steps = 0u32;
            for (i, (p, w)) in points().into_iter().enumerate().skip(k).step_by(9) {
                let (p, w) = (p * 0.05 + 150.0 * (i % 3) as f64, w * 3.0);
                for c in [all, one] {
                    assert_eq!(set(c, "load", if i % 4 == 0 { -p } else { p }), OK);
                    assert_eq!(set(c, "angular_velocity", w), OK);
                }
                for phase in 0..2 {
                    let vrs: Vec<u32> = names.iter().map(|n| vr(n)).collect();
                    let mut at_once = vec![f64::NAN; names.len()];
                    assert_eq!(unsafe { fmi2GetReal(all, vrs.as_ptr(), vrs.len(), at_once.as_mut_ptr()) }, OK, "{}", h.last());
                    // One at a time: the torque first (what a host reads), then the rest backwards.
                    let mut order: Vec<usize> = (0..names.len()).rev().collect();
                    order.rotate_left(i % names.len());
                    let mut singly = vec![f64::NAN; names.len()];
                    for j in order {
                        singly[j] = get(one, &names[j]);
                    }
                    for (j, n) in names.iter().enumerate() {
                        assert_eq!(singly[j].to_bits(), at_once[j].to_bits(), "{n} at {p} N, {w} rad/s, {temperature} K, level {code}, phase {phase}");
                    }
                    // The derived outputs are the library's functions of the FMU's own load,
                    // speed, film and fluid share (what Evaluator::evaluate_complete computes).
                    let g = |n: &str| at_once[names.iter().position(|m| m == n).unwrap()];
                    let (film, fluid) = (g("film_thickness"), g("fluid_load_fraction"));
                    let q = joint.load_speed(p, w);
                    let h_min = joint.min_film(p, w, film, fluid);
                    let (ct, jw, ecc, yt) = joint.clearance_outputs(p, w, film);
                    let expect = [("mean_pressure", q.hertz.mean_pressure), ("sommerfeld_number", q.sommerfeld_number), ("min_film_thickness", h_min),
                        ("min_lambda_ratio", h_min / joint.composite_roughness()), ("clearance_torque", ct), ("journal_weight", jw), ("eccentricity_ratio", ecc), ("grease_yield_torque", yt)];
                    for (d, x) in expect {
                        assert!(derived.contains(&d), "{d}");
                        assert_eq!(g(d).to_bits(), x.to_bits(), "{d} at {p} N, {w} rad/s, {temperature} K, level {code}: {} vs {x}", g(d));
                    }
                    light |= jw > 0.0 && ct > 0.0;
                    for c in [all, one] {
                        assert_eq!(fmi2DoStep(c, 0.5e-3 * f64::from(steps), 0.5e-3, 1), OK, "{}", h.last());
                    }
                    steps += 1;
                }
            }
            unsafe { fmi2FreeInstance(all) };
            unsafe { fmi2FreeInstance(one) };
        }
    }
    assert!(light, "some points in full film (journal weight and clearance torque > 0)");
}
