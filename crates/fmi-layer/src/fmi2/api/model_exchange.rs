//! The Model Exchange functions: exported, as the standard requires of every
//! binary, and rejected with a message, since this FMU is Co-Simulation only
//! (`fmi2Instantiate` refuses `fmi2ModelExchange`, so no instance can be in a
//! Model Exchange state).

#![allow(non_snake_case)]

use super::guard::call;
use crate::fmi2::state;
use crate::fmi2::types::*;
use std::ffi::c_void;

fn reject(c: Fmi2Component, name: &'static str) -> Fmi2StatusC {
    call(c, name, state::MODEL_EXCHANGE, |_| {
        Err("this is a Model Exchange function; this FMU implements Co-Simulation only".into())
    })
}

#[unsafe(no_mangle)]
pub extern "C" fn fmi2EnterEventMode(c: Fmi2Component) -> Fmi2StatusC {
    reject(c, "fmi2EnterEventMode")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2NewDiscreteStates(c: Fmi2Component, _eventInfo: *mut c_void) -> Fmi2StatusC {
    reject(c, "fmi2NewDiscreteStates")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2EnterContinuousTimeMode(c: Fmi2Component) -> Fmi2StatusC {
    reject(c, "fmi2EnterContinuousTimeMode")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2CompletedIntegratorStep(
    c: Fmi2Component,
    _noSetFMUStatePriorToCurrentPoint: Fmi2Boolean,
    _enterEventMode: *mut Fmi2Boolean,
    _terminateSimulation: *mut Fmi2Boolean,
) -> Fmi2StatusC {
    reject(c, "fmi2CompletedIntegratorStep")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetTime(c: Fmi2Component, _time: Fmi2Real) -> Fmi2StatusC {
    reject(c, "fmi2SetTime")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetContinuousStates(c: Fmi2Component, _x: *const Fmi2Real, _nx: usize) -> Fmi2StatusC {
    reject(c, "fmi2SetContinuousStates")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetDerivatives(c: Fmi2Component, _derivatives: *mut Fmi2Real, _nx: usize) -> Fmi2StatusC {
    reject(c, "fmi2GetDerivatives")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetEventIndicators(c: Fmi2Component, _eventIndicators: *mut Fmi2Real, _ni: usize) -> Fmi2StatusC {
    reject(c, "fmi2GetEventIndicators")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetContinuousStates(c: Fmi2Component, _x: *mut Fmi2Real, _nx: usize) -> Fmi2StatusC {
    reject(c, "fmi2GetContinuousStates")
}
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetNominalsOfContinuousStates(c: Fmi2Component, _x_nominal: *mut Fmi2Real, _nx: usize) -> Fmi2StatusC {
    reject(c, "fmi2GetNominalsOfContinuousStates")
}
