//! The Model Exchange functions of FMI 2.0 (§3.2), for models with
//! `ModelInfo::model_exchange`: the host's integrator owns the model's continuous states
//! (`ModelInfo::continuous_states`, possibly none) and sets them with
//! `fmi2SetContinuousStates`; the outputs and state derivatives are recomputed from states,
//! inputs and parameters on the next getter. There are no event indicators (nz = 0); a model
//! may ask for step events at `fmi2CompletedIntegratorStep` and update its discrete states
//! (and reinitialize its continuous states) in `fmi2NewDiscreteStates`, which never asks for
//! another iteration, a change of nominals or a time event. The functions are
//! refused on a Co-Simulation instance (and their masks keep them out of Co-Simulation states).
//!
//! The bodies of the functions with an array of continuous states or event indicators are
//! the core's (`core::model_exchange`), shared with FMI 3.0.

#![allow(non_snake_case)]

use crate::core::guard::{guarded, write_out};
use crate::core::state::{COMPLETED_INTEGRATOR_STEP, ENTER_CONTINUOUS_TIME_MODE, ENTER_EVENT_MODE, GET_CONTINUOUS_STATES, GET_DERIVATIVES, NEW_DISCRETE_STATES, SET_CONTINUOUS_STATES, SET_TIME};
use crate::core::instance::Instance;
use crate::core::model_exchange::{get_states, none, set_states};
use crate::error::CallError;
use crate::fmi2::types::*;
use std::ffi::c_void;

/// `fmi2EventInfo` (FMI 2.0 `fmi2FunctionTypes.h`).
#[repr(C)]
pub struct Fmi2EventInfo {
    /// `newDiscreteStatesNeeded`: another event iteration is needed (always false here).
    pub new_discrete_states_needed: Fmi2Boolean,
    /// `terminateSimulation`: the model asks the host to stop (always false here).
    pub terminate_simulation: Fmi2Boolean,
    /// `nominalsOfContinuousStatesChanged` (always false: the nominals are constants).
    pub nominals_of_continuous_states_changed: Fmi2Boolean,
    /// `valuesOfContinuousStatesChanged` (always false: the model never changes its states
    /// in event mode).
    pub values_of_continuous_states_changed: Fmi2Boolean,
    /// `nextEventTimeDefined`: whether `next_event_time` holds a time event (always false).
    pub next_event_time_defined: Fmi2Boolean,
    /// `nextEventTime`: the next time event, in s (0, unused, here).
    pub next_event_time: Fmi2Real,
}

guarded! {
    /// `fmi2EnterEventMode` (FMI 2.0 §3.2.2): Model Exchange, to event mode; `fmi2Error` on a
    /// Co-Simulation instance.
    fn fmi2EnterEventMode(c: Fmi2Component) -> Fmi2StatusC: ENTER_EVENT_MODE => Instance::enter_event_mode;

    /// `fmi2NewDiscreteStates` (FMI 2.0 §3.2.2): the event iteration. Checks the outputs at
    /// the current inputs (a model failure is `fmi2Error`), lets the model update its discrete
    /// states ([`Instance::update_discrete_states`]), then writes an `fmi2EventInfo`:
    /// `valuesOfContinuousStatesChanged` as the model says, every other flag false, no next
    /// time event.
    ///
    /// # Safety
    /// `eventInfo` is NULL or points to a writable `fmi2EventInfo`.
    unsafe fn fmi2NewDiscreteStates(c: Fmi2Component, eventInfo: *mut c_void) -> Fmi2StatusC: NEW_DISCRETE_STATES => |inst| {
        inst.require_model_exchange()?;
        if eventInfo.is_null() {
            return Err(CallError::Null("eventInfo"));
        }
        let changed = inst.update_discrete_states()?;
        let none = Fmi2EventInfo {
            new_discrete_states_needed: FMI2_FALSE,
            terminate_simulation: FMI2_FALSE,
            nominals_of_continuous_states_changed: FMI2_FALSE,
            values_of_continuous_states_changed: if changed { FMI2_TRUE } else { FMI2_FALSE },
            next_event_time_defined: FMI2_FALSE,
            next_event_time: 0.0,
        };
        // SAFETY: non-NULL and writable per the contract.
        unsafe { write_out(eventInfo.cast::<Fmi2EventInfo>(), none, "eventInfo") }
    };

    /// `fmi2EnterContinuousTimeMode` (FMI 2.0 §3.2.2): Model Exchange, from event mode to
    /// continuous-time mode; `fmi2Error` on a Co-Simulation instance.
    fn fmi2EnterContinuousTimeMode(c: Fmi2Component) -> Fmi2StatusC: ENTER_CONTINUOUS_TIME_MODE => Instance::enter_continuous_time_mode;

    /// `fmi2CompletedIntegratorStep` (FMI 2.0 §3.2.2): checks the outputs at the current
    /// inputs (a model failure is `fmi2Error`); `enterEventMode` is the model's step event
    /// ([`Instance::completed_integrator_step`]), `terminateSimulation` `fmi2False`.
    /// `fmi2Error` if either pointer is NULL.
    ///
    /// # Safety
    /// `enterEventMode` and `terminateSimulation` are writable.
    unsafe fn fmi2CompletedIntegratorStep(
        c: Fmi2Component,
        _noSetFMUStatePriorToCurrentPoint: Fmi2Boolean,
        enterEventMode: *mut Fmi2Boolean,
        terminateSimulation: *mut Fmi2Boolean,
    ) -> Fmi2StatusC: COMPLETED_INTEGRATOR_STEP => |inst| {
        inst.require_model_exchange()?;
        if enterEventMode.is_null() || terminateSimulation.is_null() {
            return Err(CallError::Null("enterEventMode or terminateSimulation"));
        }
        let due = inst.completed_integrator_step()?;
        // SAFETY: non-NULL and writable per the contract.
        unsafe {
            *enterEventMode = if due { FMI2_TRUE } else { FMI2_FALSE };
            *terminateSimulation = FMI2_FALSE;
        }
        Ok(Status::Ok)
    };

    /// `fmi2SetTime` (FMI 2.0 §3.2.1): Model Exchange, records the host's solver time `time`
    /// in s (the model's outputs and derivatives do not depend on time explicitly); `fmi2Error` for a non-finite time or on a
    /// Co-Simulation instance.
    fn fmi2SetTime(c: Fmi2Component, time: Fmi2Real) -> Fmi2StatusC: SET_TIME => |inst| inst.set_time(time);

    /// `fmi2SetContinuousStates` (FMI 2.0 §3.2.1): the host's state vector `x[0..nx]`
    /// (`nx` must be the number of continuous states, in the order of `<Derivatives>`). Every
    /// value is checked by the model before any is stored, so `fmi2Error` changes nothing; the
    /// outputs and derivatives are recomputed on the next getter.
    ///
    /// # Safety
    /// `x` points to `nx` values.
    unsafe fn fmi2SetContinuousStates(c: Fmi2Component, x: *const Fmi2Real, nx: usize) -> Fmi2StatusC: SET_CONTINUOUS_STATES =>
        |inst| unsafe { set_states(inst, "nx", "x[]", x, nx) };

    /// `fmi2GetDerivatives` (FMI 2.0 §3.2.2): the derivatives of the continuous states at the
    /// current time, states and inputs (`nx` must be the number of states); a model failure
    /// computing them is `fmi2Error`.
    ///
    /// # Safety
    /// `derivatives` points to `nx` writable values.
    unsafe fn fmi2GetDerivatives(c: Fmi2Component, derivatives: *mut Fmi2Real, nx: usize) -> Fmi2StatusC: GET_DERIVATIVES =>
        |inst| unsafe { get_states(inst, "nx", "derivatives[]", derivatives, nx, Instance::get_derivatives) };

    /// `fmi2GetEventIndicators` (FMI 2.0 §3.2.2): this FMU has no event indicators, so `ni`
    /// must be 0 (then `fmi2OK`, nothing written); `fmi2Error` otherwise.
    fn fmi2GetEventIndicators(c: Fmi2Component, _eventIndicators: *mut Fmi2Real, ni: usize) -> Fmi2StatusC: GET_DERIVATIVES => none("ni", ni);

    /// `fmi2GetContinuousStates` (FMI 2.0 §3.2.2): the current state vector (`nx` must be the
    /// number of states).
    ///
    /// # Safety
    /// `x` points to `nx` writable values.
    unsafe fn fmi2GetContinuousStates(c: Fmi2Component, x: *mut Fmi2Real, nx: usize) -> Fmi2StatusC: GET_CONTINUOUS_STATES =>
        |inst| unsafe { get_states(inst, "nx", "x[]", x, nx, |i: &mut Instance, o: &mut [f64]| i.get_continuous_states(o)) };

    /// `fmi2GetNominalsOfContinuousStates` (FMI 2.0 §3.2.2): each state's declared `nominal`,
    /// or 1.0 (`nx` must be the number of states).
    ///
    /// # Safety
    /// `x_nominal` points to `nx` writable values.
    unsafe fn fmi2GetNominalsOfContinuousStates(c: Fmi2Component, x_nominal: *mut Fmi2Real, nx: usize) -> Fmi2StatusC: GET_CONTINUOUS_STATES =>
        |inst| unsafe { get_states(inst, "nx", "x_nominal[]", x_nominal, nx, |i: &mut Instance, o: &mut [f64]| i.nominals_of_continuous_states(o)) };
}
