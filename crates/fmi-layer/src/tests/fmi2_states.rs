//! FMI 2.0: continuous states under Model Exchange (FMI 2.0 §3.2), directional derivatives
//! (§2.1.9) and local variables, through the exported functions, on the linear test model.

use super::host::Host;
use super::linear::*;
use crate::fmi2::api::common::*;
use crate::fmi2::api::cosim::fmi2DoStep;
use crate::fmi2::api::model_exchange::*;
use crate::fmi2::types::{Fmi2Component, Status};
use std::ptr::{null, null_mut};

/// One FMI call with its arguments bound.
type Call<'a> = Box<dyn Fn() -> i32 + 'a>;

const OK: i32 = 0;
const ERROR: i32 = 3;

fn init(c: Fmi2Component) {
    assert_eq!(Status::Ok.c(), OK);
    assert_eq!(Status::Error.c(), ERROR);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
}

/// A Model Exchange instance in continuous-time mode.
fn me(h: &Host) -> Fmi2Component {
    let c = h.fmi2(&LINEAR, 0);
    init(c);
    assert_eq!(fmi2EnterContinuousTimeMode(c), OK);
    c
}

fn states(c: Fmi2Component) -> f64 {
    let mut x = [f64::NAN];
    assert_eq!(unsafe { fmi2GetContinuousStates(c, x.as_mut_ptr(), 1) }, OK);
    x[0]
}

fn derivative(c: Fmi2Component) -> f64 {
    let mut d = [f64::NAN];
    assert_eq!(unsafe { fmi2GetDerivatives(c, d.as_mut_ptr(), 1) }, OK);
    d[0]
}

fn real(c: Fmi2Component, vr: u32) -> f64 {
    let mut v = f64::NAN;
    assert_eq!(unsafe { fmi2GetReal(c, &vr, 1, &mut v) }, OK);
    v
}

/// `dvUnknown` for one call.
fn dd(c: Fmi2Component, unknowns: &[u32], knowns: &[u32], seed: &[f64]) -> (i32, Vec<f64>) {
    let mut out = vec![f64::NAN; unknowns.len()];
    let s = unsafe { fmi2GetDirectionalDerivative(c, unknowns.as_ptr(), unknowns.len(), knowns.as_ptr(), knowns.len(), seed.as_ptr(), out.as_mut_ptr()) };
    (s, out)
}

#[test]
fn states_nominals_and_derivatives_round_trip() {
    let h = Host::new();
    let c = me(&h);
    assert_eq!(states(c), X0);
    let mut nominal = [0.0];
    assert_eq!(unsafe { fmi2GetNominalsOfContinuousStates(c, nominal.as_mut_ptr(), 1) }, OK);
    assert_eq!(nominal[0], X_NOMINAL);
    assert_eq!(derivative(c), -PA * X0 + PB * U0);
    for x in [1.5, -3.25, 0.0, 1e6] {
        assert_eq!(unsafe { fmi2SetContinuousStates(c, [x].as_ptr(), 1) }, OK);
        assert_eq!(states(c), x);
        // The derivative and the output follow the new state (outputs were stale).
        assert_eq!(derivative(c), -PA * x + PB * U0);
        assert_eq!(real(c, VR_Y), PC * x + PD * U0);
        assert_eq!(real(c, VR_X), x);
        assert_eq!(real(c, VR_DX), -PA * x + PB * U0);
    }
    // An input changes the derivative too.
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &-1.0) }, OK);
    assert_eq!(derivative(c), -PA * 1e6 - PB);
    // No events: valuesOfContinuousStatesChanged stays false in event mode.
    assert_eq!(fmi2EnterEventMode(c), OK);
    let mut info = Fmi2EventInfo { new_discrete_states_needed: 1, terminate_simulation: 1, nominals_of_continuous_states_changed: 1, values_of_continuous_states_changed: 1, next_event_time_defined: 1, next_event_time: 1.0 };
    assert_eq!(unsafe { fmi2NewDiscreteStates(c, (&mut info as *mut Fmi2EventInfo).cast()) }, OK);
    assert_eq!((info.values_of_continuous_states_changed, info.nominals_of_continuous_states_changed), (0, 0));
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn wrong_counts_null_arrays_and_rejected_states_change_nothing() {
    let h = Host::new();
    let c = me(&h);
    assert_eq!(unsafe { fmi2SetContinuousStates(c, [1.0, 2.0].as_ptr(), 2) }, ERROR);
    assert!(h.last().contains("nx = 2, but Linear has 1 continuous state"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetContinuousStates(c, [1.0].as_ptr(), 0) }, ERROR);
    assert!(h.last().contains("nx = 0, but Linear has 1 continuous state"), "{}", h.last());
    assert_eq!(states(c), X0);
    let mut out = [7.0; 2];
    let p = out.as_mut_ptr();
    let calls: [(&str, Call); 3] = [
        ("fmi2GetDerivatives", Box::new(|| unsafe { fmi2GetDerivatives(c, p, 2) })),
        ("fmi2GetContinuousStates", Box::new(|| unsafe { fmi2GetContinuousStates(c, p, 0) })),
        ("fmi2GetNominalsOfContinuousStates", Box::new(|| unsafe { fmi2GetNominalsOfContinuousStates(c, p, 2) })),
    ];
    for (name, call) in calls {
        assert_eq!(call(), ERROR, "{name}");
        assert!(h.last().starts_with(name) && h.last().contains("continuous state"), "{}", h.last());
    }
    assert_eq!(out, [7.0; 2], "nothing written");
    // NULL arrays.
    assert_eq!(unsafe { fmi2SetContinuousStates(c, null(), 1) }, ERROR);
    assert!(h.last().contains("x[] is NULL"), "{}", h.last());
    assert_eq!(unsafe { fmi2GetDerivatives(c, null_mut(), 1) }, ERROR);
    assert!(h.last().contains("derivatives[] is NULL"), "{}", h.last());
    // A value the model refuses: nothing stored.
    for bad in [f64::NAN, f64::INFINITY, 2e6] {
        assert_eq!(unsafe { fmi2SetContinuousStates(c, [bad].as_ptr(), 1) }, ERROR);
        assert!(h.last().contains("x = ") && h.last().contains("out of range"), "{}", h.last());
        assert_eq!(states(c), X0);
        assert_eq!(derivative(c), -PA * X0 + PB * U0);
    }
    // No event indicators.
    assert_eq!(fmi2GetEventIndicators(c, out.as_mut_ptr(), 1), ERROR);
    assert!(h.last().contains("ni = 1, but Linear has no event indicators"), "{}", h.last());
    assert_eq!(fmi2GetEventIndicators(c, out.as_mut_ptr(), 0), OK);
    // A derivative that is not a number is refused, not handed to the integrator.
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &SINGULAR_U) }, OK);
    assert_eq!(unsafe { fmi2GetDerivatives(c, out.as_mut_ptr(), 1) }, ERROR);
    assert!(h.last().contains("the model gives state derivative der(x) = NaN (dimensionless), which is not a finite number"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &U0) }, OK);
    assert_eq!(derivative(c), -PA * X0 + PB * U0);
    // SetContinuousStates only in continuous-time mode (FMI 2.0 §3.2.3).
    assert_eq!(fmi2EnterEventMode(c), OK);
    assert_eq!(unsafe { fmi2SetContinuousStates(c, [1.0].as_ptr(), 1) }, ERROR);
    assert!(h.last().contains("illegal call sequence"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn local_variables_can_be_read_but_not_set() {
    let h = Host::new();
    for fmu_type in [0, 1] {
        let c = h.fmi2(&LINEAR, fmu_type);
        for vr in [VR_X, VR_DX] {
            assert_eq!(unsafe { fmi2SetReal(c, &vr, 1, &1.0) }, ERROR);
            assert!(h.last().contains(&format!("local '{}' (value reference {vr}) cannot be set", if vr == VR_X { "x" } else { "der(x)" })), "{}", h.last());
        }
        init(c);
        assert_eq!(real(c, VR_X), X0);
        assert_eq!(real(c, VR_DX), -PA * X0 + PB * U0);
        // A refused set of a local among valid values stores none of them.
        assert_eq!(unsafe { fmi2SetReal(c, [VR_U, VR_X].as_ptr(), 2, [9.0, 9.0].as_ptr()) }, ERROR);
        assert_eq!(real(c, VR_U), U0);
        unsafe { fmi2FreeInstance(c) };
    }
}

#[test]
fn directional_derivatives_are_the_system_matrices() {
    let h = Host::new();
    let c = me(&h);
    let vr = |i: usize| [VR_X, VR_U, VR_DX, VR_Y][i];
    for i in [DX, Y] {
        for j in [X, U] {
            let (s, out) = dd(c, &[vr(i)], &[vr(j)], &[1.0]);
            assert_eq!(s, OK, "{}", h.last());
            assert_eq!(out, [expected(i, j)], "d {i} / d {j}");
        }
    }
    // A seed vector: J · seed, both unknowns at once.
    let seed = [0.3, -1.7];
    let (s, out) = dd(c, &[VR_DX, VR_Y], &[VR_X, VR_U], &seed);
    assert_eq!(s, OK);
    assert_eq!(out, [-PA * seed[0] + PB * seed[1], PC * seed[0] + PD * seed[1]]);
    // Independent of the model's Jacobian: a finite difference through SetContinuousStates
    // and GetDerivatives (exact for a linear system, up to rounding).
    let (x0, dx0) = (states(c), derivative(c));
    let step = 0.25;
    assert_eq!(unsafe { fmi2SetContinuousStates(c, [x0 + step].as_ptr(), 1) }, OK);
    let fd = (derivative(c) - dx0) / step;
    assert!((fd - dd(c, &[VR_DX], &[VR_X], &[1.0]).1[0]).abs() < 1e-12, "{fd}");
    // nUnknown or nKnown = 0: fmi2OK, nothing written.
    let mut out = [42.0];
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, [VR_Y].as_ptr(), 1, null(), 0, null(), out.as_mut_ptr()) }, OK);
    assert_eq!(out, [42.0]);
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, null(), 0, [VR_U].as_ptr(), 1, [1.0].as_ptr(), null_mut()) }, OK);
    // Allowed in initialization mode and event mode too; not before initialization.
    assert_eq!(fmi2EnterEventMode(c), OK);
    assert_eq!(dd(c, &[VR_Y], &[VR_U], &[2.0]), (OK, vec![2.0 * PD]));
    let fresh = h.fmi2(&LINEAR, 0);
    assert_eq!(dd(fresh, &[VR_Y], &[VR_U], &[1.0]).0, ERROR);
    assert!(h.last().contains("illegal call sequence"), "{}", h.last());
    assert_eq!(fmi2EnterInitializationMode(fresh), OK);
    assert_eq!(dd(fresh, &[VR_DX], &[VR_X], &[1.0]), (OK, vec![-PA]));
    unsafe { fmi2FreeInstance(fresh) };
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn directional_derivative_errors_name_the_variable_or_argument() {
    let h = Host::new();
    let c = me(&h);
    let cases: [(&[u32], &[u32], &str); 6] = [
        (&[99], &[VR_U], "unknown value reference 99"),
        (&[VR_Y], &[99], "unknown value reference 99"),
        (&[VR_U], &[VR_U], "input 'u' (value reference 2) cannot be an unknown of a directional derivative: unknowns are continuous Real outputs and state derivatives"),
        (&[VR_X], &[VR_U], "local 'x' (value reference 1) cannot be an unknown"),
        (&[VR_Y], &[VR_A], "parameter 'a' (value reference 5) cannot be a known of a directional derivative: knowns are continuous Real inputs and continuous states"),
        (&[VR_Y], &[VR_DX], "local 'der(x)' (value reference 3) cannot be a known"),
    ];
    for (unknowns, knowns, text) in cases {
        let seed = vec![1.0; knowns.len()];
        let (s, out) = dd(c, unknowns, knowns, &seed);
        assert_eq!(s, ERROR, "{text}");
        assert!(h.last().contains(text), "{}", h.last());
        assert!(out.iter().all(|x| x.is_nan()), "nothing written");
    }
    let mut out = [0.0];
    let (y, u, p) = ([VR_Y].as_ptr(), [VR_U].as_ptr(), out.as_mut_ptr());
    let calls: [(&str, Call); 4] = [
        ("vUnknown_ref[] is NULL", Box::new(|| unsafe { fmi2GetDirectionalDerivative(c, null(), 1, u, 1, [1.0].as_ptr(), p) })),
        ("vKnown_ref[] is NULL", Box::new(|| unsafe { fmi2GetDirectionalDerivative(c, y, 1, null(), 1, [1.0].as_ptr(), p) })),
        ("dvKnown[] is NULL", Box::new(|| unsafe { fmi2GetDirectionalDerivative(c, y, 1, u, 1, null(), p) })),
        ("dvUnknown[] is NULL", Box::new(|| unsafe { fmi2GetDirectionalDerivative(c, y, 1, u, 1, [1.0].as_ptr(), null_mut()) })),
    ];
    for (what, call) in calls {
        assert_eq!(call(), ERROR, "{what}");
        assert!(h.last().contains(what), "{}", h.last());
    }
    assert_eq!(out, [0.0], "nothing written");
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn co_simulation_keeps_the_state_internal() {
    let h = Host::new();
    let c = h.fmi2(&LINEAR, 1);
    init(c);
    // Outputs with respect to inputs only.
    assert_eq!(dd(c, &[VR_Y], &[VR_U], &[1.0]), (OK, vec![PD]));
    assert_eq!(dd(c, &[VR_DX], &[VR_U], &[1.0]).0, ERROR);
    assert!(h.last().contains("unknowns are continuous Real outputs"), "{}", h.last());
    assert_eq!(dd(c, &[VR_Y], &[VR_X], &[1.0]).0, ERROR);
    assert!(h.last().contains("knowns are continuous Real inputs"), "{}", h.last());
    // The model advances its state itself (exact solution of the linear system).
    assert_eq!(fmi2DoStep(c, 0.0, 0.5, 1), OK);
    let e = (-PA * 0.5).exp();
    assert!((real(c, VR_X) - (X0 * e + PB * U0 / PA * (1.0 - e))).abs() < 1e-15);
    let mut x = [0.0];
    assert_eq!(unsafe { fmi2GetContinuousStates(c, x.as_mut_ptr(), 1) }, ERROR);
    unsafe { fmi2FreeInstance(c) };
}

/// A step at inputs where the outputs are out of range from the start and the model's step
/// fails names the outputs (the cause), not the model's failure; the instance is in the error
/// state; a step that the model takes at good inputs checks the outputs at its end.
#[test]
fn a_failed_step_names_the_outputs_that_were_out_of_range() {
    let h = Host::new();
    let c = h.fmi2(&LINEAR, 1);
    init(c);
    assert_eq!(fmi2DoStep(c, 0.0, 0.5, 1), OK);
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &SINGULAR_U) }, OK);
    assert_eq!(fmi2DoStep(c, 0.5, 0.5, 1), ERROR);
    assert!(h.last().contains("der(x) = NaN") && !h.last().contains("cannot be taken"), "{}", h.last());
    assert_eq!(fmi2DoStep(c, 0.5, 0.5, 1), ERROR);
    assert!(h.last().contains("illegal call sequence"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}

/// Outputs are checked as the host reads them: a step whose end has an output beyond its
/// declared maximum succeeds, the read of that output is refused naming it (nothing written),
/// the other variables read as ever, and the output reads again once it is back in range.
#[test]
fn an_output_out_of_range_is_refused_when_read() {
    let h = Host::new();
    let c = h.fmi2(&LINEAR_BOUNDED, 1);
    init(c);
    let big = 100.0;
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &big) }, OK);
    assert_eq!(fmi2DoStep(c, 0.0, 0.5, 1), OK);
    let mut y = [-7.0];
    assert_eq!(unsafe { fmi2GetReal(c, &VR_Y, 1, y.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("output y = ") && h.last().contains(&format!("above its declared maximum {Y_MAX}")), "{}", h.last());
    assert_eq!(y, [-7.0], "nothing written");
    let mut both = [-7.0; 2];
    assert_eq!(unsafe { fmi2GetReal(c, [VR_X, VR_Y].as_ptr(), 2, both.as_mut_ptr()) }, ERROR);
    assert_eq!(both, [-7.0; 2], "nothing written");
    let x = real(c, VR_X);
    // y = c x + d u back within its maximum.
    let u = (0.5 * Y_MAX - PC * x) / PD;
    assert_eq!(unsafe { fmi2SetReal(c, &VR_U, 1, &u) }, OK);
    assert!((real(c, VR_Y) - 0.5 * Y_MAX).abs() < 1e-9);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn without_the_capability_directional_derivatives_are_refused() {
    let h = Host::new();
    for (info, text) in [
        (&*LINEAR_NO_DD, "directional derivatives are not provided (providesDirectionalDerivative = false)"),
        (&*LINEAR_DEFAULT_JACOBIAN, "directional derivatives are not provided by this model"),
    ] {
        let c = h.fmi2(info, 0);
        init(c);
        let (s, out) = dd(c, &[VR_Y], &[VR_U], &[1.0]);
        assert_eq!(s, ERROR);
        assert!(h.last().starts_with("fmi2GetDirectionalDerivative: ") && h.last().contains(text), "{}", h.last());
        assert!(out[0].is_nan());
        unsafe { fmi2FreeInstance(c) };
    }
}
