//! The Co-Simulation functions.

#![allow(non_snake_case)]

use super::guard::call;
use crate::fmi2::state;
use crate::fmi2::types::*;
use std::ffi::c_int;

#[unsafe(no_mangle)]
pub extern "C" fn fmi2DoStep(
    c: Fmi2Component,
    currentCommunicationPoint: Fmi2Real,
    communicationStepSize: Fmi2Real,
    _noSetFMUStatePriorToCurrentPoint: Fmi2Boolean,
) -> Fmi2StatusC {
    call(c, "fmi2DoStep", state::DO_STEP, |inst| inst.do_step(currentCommunicationPoint, communicationStepSize))
}

/// Only meaningful for asynchronous slaves; its mask (`stepInProgress`) is never met.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2CancelStep(c: Fmi2Component) -> Fmi2StatusC {
    call(c, "fmi2CancelStep", state::CANCEL_STEP, |_| Err("no step is in progress".into()))
}

/// Rejected: `canInterpolateInputs = false`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetRealInputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *const Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2SetRealInputDerivatives", state::SET_REAL_INPUT_DERIVATIVES, |_| {
        Err("input derivatives are not used (canInterpolateInputs = false)".into())
    })
}

/// Rejected: `maxOutputDerivativeOrder = 0`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetRealOutputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *mut Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2GetRealOutputDerivatives", state::GET_REAL_OUTPUT_DERIVATIVES, |_| {
        Err("output derivatives are not provided (maxOutputDerivativeOrder = 0)".into())
    })
}

fn kind_name(s: c_int) -> String {
    match s {
        FMI2_DO_STEP_STATUS => "fmi2DoStepStatus".into(),
        FMI2_PENDING_STATUS => "fmi2PendingStatus".into(),
        FMI2_LAST_SUCCESSFUL_TIME => "fmi2LastSuccessfulTime".into(),
        FMI2_TERMINATED => "fmi2Terminated".into(),
        k => format!("status kind {k} (not an fmi2StatusKind)"),
    }
}

fn unsupported(func: &str, s: c_int) -> Result<crate::fmi2::types::Status, String> {
    Err(format!("{} is not available through {func} (this FMU steps synchronously)", kind_name(s)))
}

/// # Safety
/// `value` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2StatusC) -> Fmi2StatusC {
    call(c, "fmi2GetStatus", state::GET_STATUS, |_| unsupported("fmi2GetStatus", s))
}

/// `fmi2LastSuccessfulTime`: the end of the last completed step.
///
/// # Safety
/// `value` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(c: Fmi2Component, s: c_int, value: *mut Fmi2Real) -> Fmi2StatusC {
    call(c, "fmi2GetRealStatus", state::GET_STATUS, |inst| {
        if s != FMI2_LAST_SUCCESSFUL_TIME {
            return unsupported("fmi2GetRealStatus", s);
        }
        if value.is_null() {
            return Err("value is NULL".into());
        }
        // SAFETY: non-NULL and writable per the contract.
        unsafe { *value = inst.time };
        Ok(Status::Ok)
    })
}

/// # Safety
/// `value` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2Integer) -> Fmi2StatusC {
    call(c, "fmi2GetIntegerStatus", state::GET_STATUS, |_| unsupported("fmi2GetIntegerStatus", s))
}

/// `fmi2Terminated`: always false (the model never asks to stop).
///
/// # Safety
/// `value` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(c: Fmi2Component, s: c_int, value: *mut Fmi2Boolean) -> Fmi2StatusC {
    call(c, "fmi2GetBooleanStatus", state::GET_STATUS, |_| {
        if s != FMI2_TERMINATED {
            return unsupported("fmi2GetBooleanStatus", s);
        }
        if value.is_null() {
            return Err("value is NULL".into());
        }
        // SAFETY: non-NULL and writable per the contract.
        unsafe { *value = FMI2_FALSE };
        Ok(Status::Ok)
    })
}

/// # Safety
/// `value` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(c: Fmi2Component, s: c_int, _value: *mut Fmi2String) -> Fmi2StatusC {
    call(c, "fmi2GetStringStatus", state::GET_STATUS, |_| unsupported("fmi2GetStringStatus", s))
}
