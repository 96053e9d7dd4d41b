//! The Co-Simulation functions.

#![allow(non_snake_case)]

use crate::core::guard::{guarded, refuse, write_out};
use crate::core::state::{Mask, State, DO_STEP};
use crate::error::CallError;
use crate::core::instance::CallResult;
use crate::fmi2::types::*;
use std::ffi::c_int;

// The state masks of FMI 2.0's own Co-Simulation functions (FMI 2.0 §4.2.4 state chart); the
// functions both standards have use the core's (`crate::core::state`).

/// `fmi2CancelStep`: only while an asynchronous step runs (never, here).
const CANCEL_STEP: Mask = Mask::of(&[State::StepInProgress]);
/// `fmi2SetRealInputDerivatives`.
const SET_REAL_INPUT_DERIVATIVES: Mask = Mask::of(&[State::Instantiated, State::InitializationMode, State::StepComplete]);
/// `fmi2GetRealOutputDerivatives`.
const GET_REAL_OUTPUT_DERIVATIVES: Mask =
    Mask::of(&[State::StepComplete, State::StepFailed, State::StepCanceled, State::Terminated, State::Error]);
/// `fmi2Get*Status`.
const GET_STATUS: Mask = Mask::of(&[State::StepComplete, State::StepInProgress, State::StepFailed, State::Terminated]);

/// The error of an `fmi2Get*Status` function for a status kind it does not provide.
fn unsupported(func: &'static str, kind: c_int) -> CallResult {
    Err(CallError::StatusKind { kind: status_kind(kind), prefix: "fmi2", func })
}

/// `*value = v` for the one status kind `provided` that `func` reports, an error for any
/// other kind or a NULL `value`.
///
/// # Safety
/// `value` is NULL or writable.
unsafe fn status_value<T>(func: &'static str, kind: c_int, provided: c_int, value: *mut T, v: T) -> CallResult {
    if kind != provided {
        return unsupported(func, kind);
    }
    // SAFETY: per the contract.
    unsafe { write_out(value, v, "value") }
}

guarded! {
    /// `fmi2DoStep` (FMI 2.0 §4.2.2): advances the model from `currentCommunicationPoint`
    /// over `communicationStepSize` (both in s) with the inputs held; the outputs are then those at
    /// the end of the step. Returns `fmi2Error` for a step size that is not a finite number > 0,
    /// or a communication point that does not continue the last step (nothing changed), and for
    /// a step the model fails (the instance goes to the `error` state).
    fn fmi2DoStep(c: Fmi2Component, currentCommunicationPoint: Fmi2Real, communicationStepSize: Fmi2Real, _noSetFMUStatePriorToCurrentPoint: Fmi2Boolean) -> Fmi2StatusC: DO_STEP =>
        |inst| inst.do_step(currentCommunicationPoint, communicationStepSize);

    /// `fmi2CancelStep` (FMI 2.0 §4.2.2): only meaningful for asynchronous slaves; its mask
    /// (`stepInProgress`) is never met, so it always returns `fmi2Error`.
    fn fmi2CancelStep(c: Fmi2Component) -> Fmi2StatusC: CANCEL_STEP => refuse("no step is in progress");

    /// `fmi2SetRealInputDerivatives` (FMI 2.0 §4.2.1): rejected with `fmi2Error`
    /// (`canInterpolateInputs = false`).
    fn fmi2SetRealInputDerivatives(c: Fmi2Component, _vr: *const Fmi2ValueReference, _nvr: usize, _order: *const Fmi2Integer, _value: *const Fmi2Real) -> Fmi2StatusC:
        SET_REAL_INPUT_DERIVATIVES => refuse("input derivatives are not used (canInterpolateInputs = false)");

    /// `fmi2GetRealOutputDerivatives` (FMI 2.0 §4.2.1): rejected with `fmi2Error`
    /// (`maxOutputDerivativeOrder = 0`).
    fn fmi2GetRealOutputDerivatives(c: Fmi2Component, _vr: *const Fmi2ValueReference, _nvr: usize, _order: *const Fmi2Integer, _value: *mut Fmi2Real) -> Fmi2StatusC:
        GET_REAL_OUTPUT_DERIVATIVES => refuse("output derivatives are not provided (maxOutputDerivativeOrder = 0)");

    /// `fmi2GetStatus` (FMI 2.0 §4.2.3): no status kind is available through it (this FMU
    /// steps synchronously); always `fmi2Error`, `value` untouched.
    ///
    /// # Safety
    /// `value` is writable.
    unsafe fn fmi2GetStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2StatusC) -> Fmi2StatusC: GET_STATUS => |_| unsupported("fmi2GetStatus", s);

    /// `fmi2GetRealStatus` (FMI 2.0 §4.2.3): for `fmi2LastSuccessfulTime`, writes the end of
    /// the last completed step (s) to `*value`; `fmi2Error` for any other status kind or a NULL
    /// `value`.
    ///
    /// # Safety
    /// `value` is writable.
    unsafe fn fmi2GetRealStatus(c: Fmi2Component, s: c_int, value: *mut Fmi2Real) -> Fmi2StatusC: GET_STATUS =>
        |inst| unsafe { status_value("fmi2GetRealStatus", s, FMI2_LAST_SUCCESSFUL_TIME, value, inst.time) };

    /// `fmi2GetIntegerStatus` (FMI 2.0 §4.2.3): no integer status kind exists; always
    /// `fmi2Error`, `value` untouched.
    ///
    /// # Safety
    /// `value` is writable.
    unsafe fn fmi2GetIntegerStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2Integer) -> Fmi2StatusC: GET_STATUS => |_| unsupported("fmi2GetIntegerStatus", s);

    /// `fmi2GetBooleanStatus` (FMI 2.0 §4.2.3): for `fmi2Terminated`, writes `fmi2False` to
    /// `*value` (the model never asks to stop); `fmi2Error` for any other status kind or a NULL
    /// `value`.
    ///
    /// # Safety
    /// `value` is writable.
    unsafe fn fmi2GetBooleanStatus(c: Fmi2Component, s: c_int, value: *mut Fmi2Boolean) -> Fmi2StatusC: GET_STATUS =>
        |_| unsafe { status_value("fmi2GetBooleanStatus", s, FMI2_TERMINATED, value, FMI2_FALSE) };

    /// `fmi2GetStringStatus` (FMI 2.0 §4.2.3): `fmi2PendingStatus` is never available (no
    /// asynchronous step); always `fmi2Error`, `value` untouched.
    ///
    /// # Safety
    /// `value` is writable.
    unsafe fn fmi2GetStringStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2String) -> Fmi2StatusC: GET_STATUS => |_| unsupported("fmi2GetStringStatus", s);
}
