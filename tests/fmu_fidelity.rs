//! The PinJoint FMU's fidelity parameters: `fidelity` (Integer 0..3), `tolerance` and the
//! envelope, built at exit of initialization. Outputs under `table` stay within the tolerance
//! of `full`, auto logs its choice, a fallback outside the envelope is logged once, and bad
//! values are refused with the parameter's name, value and unit.

mod common;
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
