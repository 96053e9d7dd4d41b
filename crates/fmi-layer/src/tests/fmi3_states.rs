//! FMI 3.0: the same as `fmi2_states` through the `fmi3*` functions: continuous states
//! (FMI 3.0 §3.2), their counts, and directional derivatives (§2.2.12).

use super::host::Host;
use super::linear::*;
use crate::core::interface::Interface;
use crate::fmi3::api::*;
use std::ffi::c_void;
use std::ptr::{null, null_mut};

const OK: i32 = 0;
const ERROR: i32 = 3;

fn init(c: *mut c_void) {
    assert_eq!(fmi3EnterInitializationMode(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi3ExitInitializationMode(c), OK);
}

fn me(h: &Host) -> *mut c_void {
    let c = h.fmi3(&LINEAR, Interface::ModelExchange);
    init(c);
    assert_eq!(fmi3EnterContinuousTimeMode(c), OK);
    c
}

fn one(c: *mut c_void, f: unsafe extern "C" fn(*mut c_void, *mut f64, usize) -> i32) -> f64 {
    let mut v = [f64::NAN];
    assert_eq!(unsafe { f(c, v.as_mut_ptr(), 1) }, OK);
    v[0]
}

/// `sensitivity` for one call.
fn dd(c: *mut c_void, unknowns: &[u32], knowns: &[u32], seed: &[f64]) -> (i32, Vec<f64>) {
    let mut out = vec![f64::NAN; unknowns.len()];
    let s = unsafe {
        fmi3GetDirectionalDerivative(c, unknowns.as_ptr(), unknowns.len(), knowns.as_ptr(), knowns.len(), seed.as_ptr(), seed.len(), out.as_mut_ptr(), out.len())
    };
    (s, out)
}

#[test]
fn counts_states_nominals_and_derivatives() {
    let h = Host::new();
    let c = me(&h);
    let (mut nx, mut nz) = (99, 99);
    assert_eq!(unsafe { fmi3GetNumberOfContinuousStates(c, &mut nx) }, OK);
    assert_eq!(unsafe { fmi3GetNumberOfEventIndicators(c, &mut nz) }, OK);
    assert_eq!((nx, nz), (1, 0));
    assert_eq!(one(c, fmi3GetContinuousStates), X0);
    assert_eq!(one(c, fmi3GetNominalsOfContinuousStates), X_NOMINAL);
    assert_eq!(one(c, fmi3GetContinuousStateDerivatives), -PA * X0 + PB * U0);
    assert_eq!(unsafe { fmi3SetContinuousStates(c, [-4.0].as_ptr(), 1) }, OK);
    assert_eq!(one(c, fmi3GetContinuousStates), -4.0);
    assert_eq!(one(c, fmi3GetContinuousStateDerivatives), -PA * -4.0 + PB * U0);
    let mut y = f64::NAN;
    assert_eq!(unsafe { fmi3GetFloat64(c, &VR_Y, 1, &mut y, 1) }, OK);
    assert_eq!(y, PC * -4.0 + PD * U0);
    // Wrong count, refused value, local set: nothing changes.
    assert_eq!(unsafe { fmi3SetContinuousStates(c, [1.0, 2.0].as_ptr(), 2) }, ERROR);
    assert!(h.last().contains("nContinuousStates = 2, but Linear has 1 continuous state"), "{}", h.last());
    assert_eq!(unsafe { fmi3SetContinuousStates(c, [f64::NAN].as_ptr(), 1) }, ERROR);
    assert!(h.last().contains("x = NaN"), "{}", h.last());
    assert_eq!(unsafe { fmi3SetFloat64(c, &VR_X, 1, &1.0, 1) }, ERROR);
    assert!(h.last().contains("local 'x' (value reference 1) cannot be set"), "{}", h.last());
    assert_eq!(one(c, fmi3GetContinuousStates), -4.0);
    let mut z = [0.0];
    assert_eq!(fmi3GetEventIndicators(c, z.as_mut_ptr(), 1), ERROR);
    assert!(h.last().contains("nEventIndicators = 1, but Linear has no event indicators"), "{}", h.last());
    unsafe { fmi3FreeInstance(c) };
}

#[test]
fn directional_derivatives_are_the_system_matrices() {
    let h = Host::new();
    let c = me(&h);
    let vr = |i: usize| [VR_X, VR_U, VR_DX, VR_Y][i];
    for i in [DX, Y] {
        for j in [X, U] {
            assert_eq!(dd(c, &[vr(i)], &[vr(j)], &[1.0]), (OK, vec![expected(i, j)]), "{}", h.last());
        }
    }
    let seed = [-0.6, 2.5];
    assert_eq!(dd(c, &[VR_DX, VR_Y], &[VR_X, VR_U], &seed), (OK, vec![-PA * seed[0] + PB * seed[1], PC * seed[0] + PD * seed[1]]));
    // Length checks (all scalars), NULL arrays, bad references.
    let mut out = [f64::NAN];
    let (y, u) = ([VR_Y], [VR_U]);
    assert_eq!(unsafe { fmi3GetDirectionalDerivative(c, y.as_ptr(), 1, u.as_ptr(), 1, [1.0, 1.0].as_ptr(), 2, out.as_mut_ptr(), 1) }, ERROR);
    assert!(h.last().contains("nSeed = 2, but nKnowns = 1"), "{}", h.last());
    assert_eq!(unsafe { fmi3GetDirectionalDerivative(c, y.as_ptr(), 1, u.as_ptr(), 1, [1.0].as_ptr(), 1, out.as_mut_ptr(), 0) }, ERROR);
    assert!(h.last().contains("nSensitivity = 0, but nUnknowns = 1"), "{}", h.last());
    assert_eq!(unsafe { fmi3GetDirectionalDerivative(c, y.as_ptr(), 1, null(), 1, [1.0].as_ptr(), 1, out.as_mut_ptr(), 1) }, ERROR);
    assert!(h.last().contains("knowns[] is NULL"), "{}", h.last());
    assert_eq!(unsafe { fmi3GetDirectionalDerivative(c, y.as_ptr(), 1, u.as_ptr(), 1, [1.0].as_ptr(), 1, null_mut(), 1) }, ERROR);
    assert!(h.last().contains("sensitivity[] is NULL"), "{}", h.last());
    assert!(out[0].is_nan());
    assert_eq!(dd(c, &[VR_Y], &[77], &[1.0]).0, ERROR);
    assert!(h.last().contains("unknown value reference 77"), "{}", h.last());
    assert_eq!(dd(c, &[VR_Y], &[VR_A], &[1.0]).0, ERROR);
    assert!(h.last().contains("parameter 'a' (value reference 5) cannot be a known"), "{}", h.last());
    // Empty: fmi3OK, nothing written.
    assert_eq!(unsafe { fmi3GetDirectionalDerivative(c, y.as_ptr(), 1, null(), 0, null(), 0, out.as_mut_ptr(), 1) }, OK);
    assert!(out[0].is_nan());
    // Adjoint derivatives stay refused.
    assert_eq!(fmi3GetAdjointDerivative(c, y.as_ptr(), 1, u.as_ptr(), 1, [1.0].as_ptr(), 1, out.as_mut_ptr(), 1), ERROR);
    assert!(h.last().contains("providesAdjointDerivatives = false"), "{}", h.last());
    unsafe { fmi3FreeInstance(c) };
}

#[test]
fn capability_and_co_simulation_rules() {
    let h = Host::new();
    let c = h.fmi3(&LINEAR_NO_DD, Interface::ModelExchange);
    init(c);
    assert_eq!(dd(c, &[VR_Y], &[VR_U], &[1.0]).0, ERROR);
    assert!(h.last().contains("providesDirectionalDerivatives = false"), "{}", h.last());
    unsafe { fmi3FreeInstance(c) };
    let c = h.fmi3(&LINEAR_DEFAULT_JACOBIAN, Interface::ModelExchange);
    init(c);
    assert_eq!(dd(c, &[VR_Y], &[VR_U], &[1.0]).0, ERROR);
    assert!(h.last().contains("directional derivatives are not provided by this model"), "{}", h.last());
    unsafe { fmi3FreeInstance(c) };
    // Co-Simulation (step mode): outputs with respect to inputs only; no Model Exchange arrays.
    let c = h.fmi3(&LINEAR, Interface::CoSimulation);
    init(c);
    assert_eq!(dd(c, &[VR_Y], &[VR_U], &[3.0]), (OK, vec![3.0 * PD]));
    assert_eq!(dd(c, &[VR_Y], &[VR_X], &[1.0]).0, ERROR);
    let mut x = [0.0];
    assert_eq!(unsafe { fmi3GetContinuousStates(c, x.as_mut_ptr(), 1) }, ERROR);
    unsafe { fmi3FreeInstance(c) };
}

#[test]
fn variable_dependencies_of_outputs_and_derivatives_name_state_and_input() {
    let h = Host::new();
    let c = me(&h);
    for (vr, n) in [(VR_Y, 2), (VR_DX, 2), (VR_X, 0), (VR_U, 0)] {
        let mut got = 99;
        assert_eq!(unsafe { fmi3GetNumberOfVariableDependencies(c, vr, &mut got) }, OK);
        assert_eq!(got, n, "value reference {vr}");
    }
    let (mut e, mut ind, mut ei, mut kinds) = ([9usize; 2], [0u32; 2], [9usize; 2], [0i32; 2]);
    let s = unsafe { fmi3GetVariableDependencies(c, VR_DX, e.as_mut_ptr(), ind.as_mut_ptr(), ei.as_mut_ptr(), kinds.as_mut_ptr(), 2) };
    assert_eq!(s, OK);
    assert_eq!((ind, e, ei), ([VR_X, VR_U], [0, 0], [0, 0]));
    unsafe { fmi3FreeInstance(c) };
}
