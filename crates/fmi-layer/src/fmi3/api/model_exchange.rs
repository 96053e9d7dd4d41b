//! The Model Exchange functions of FMI 3.0 (§3.2), for models with
//! `ModelInfo::model_exchange`: the host's integrator owns the model's continuous states and
//! sets them with `fmi3SetContinuousStates`; the outputs and state derivatives are recomputed
//! on the next getter. There are no event indicators; a model may ask for step events at
//! `fmi3CompletedIntegratorStep` and update its discrete states in
//! `fmi3UpdateDiscreteStates`, which never asks for another iteration or a time event. The
//! functions are refused on a Co-Simulation instance. The bodies of the functions with an
//! array of continuous states are the core's (`core::model_exchange`), shared with
//! FMI 2.0.

#![allow(non_snake_case)]

use super::super::types::*;
use crate::core::guard::{guarded, put, write_out};
use crate::core::state::{COMPLETED_INTEGRATOR_STEP, ENTER_CONTINUOUS_TIME_MODE, ENTER_EVENT_MODE, GET_CONTINUOUS_STATES, GET_DERIVATIVES, NEW_DISCRETE_STATES, RESET, SET_CONTINUOUS_STATES, SET_TIME};
use crate::core::instance::{CallResult, Instance};
use crate::core::model_exchange::{get_states, none, set_states};
use crate::core::types::Status;

/// Checks the outputs at the current inputs (the Model Exchange event iteration and
/// integrator step), then clears every flag the host passed (NULL ones are skipped).
///
/// # Safety
/// Each pointer is NULL or writable.
unsafe fn nothing_to_do(inst: &mut Instance, flags: &[*mut Fmi3Boolean]) -> CallResult {
    inst.require_model_exchange()?;
    inst.refresh_outputs()?;
    for &p in flags {
        // SAFETY: per the contract.
        unsafe { put(p, 0) };
    }
    Ok(Status::Ok)
}

guarded! {
    /// `fmi3EnterEventMode` (FMI 3.0): Model Exchange only (this Co-Simulation has no
    /// event mode): to event mode. `fmi3Error` on a Co-Simulation instance.
    fn fmi3EnterEventMode(instance: Fmi3Instance) -> Fmi3StatusC: ENTER_EVENT_MODE => Instance::enter_event_mode;

    /// `fmi3UpdateDiscreteStates` (FMI 3.0): the Model Exchange event iteration.
    /// Checks the outputs at the current inputs (a model failure is `fmi3Error`), then reports
    /// nothing discrete to update, no termination, no time event: every non-NULL flag false.
    ///
    /// # Safety
    /// Each pointer is NULL or writable.
    unsafe fn fmi3UpdateDiscreteStates(
        instance: Fmi3Instance,
        discreteStatesNeedUpdate: *mut Fmi3Boolean,
        terminateSimulation: *mut Fmi3Boolean,
        nominalsOfContinuousStatesChanged: *mut Fmi3Boolean,
        valuesOfContinuousStatesChanged: *mut Fmi3Boolean,
        nextEventTimeDefined: *mut Fmi3Boolean,
        nextEventTime: *mut f64,
    ) -> Fmi3StatusC: NEW_DISCRETE_STATES => |inst| unsafe {
        inst.require_model_exchange()?;
        let changed = inst.update_discrete_states()?;
        let flags = [discreteStatesNeedUpdate, terminateSimulation, nominalsOfContinuousStatesChanged, nextEventTimeDefined];
        nothing_to_do(inst, &flags)?;
        put(valuesOfContinuousStatesChanged, Fmi3Boolean::from(changed));
        put(nextEventTime, 0.0);
        Ok(Status::Ok)
    };

    /// `fmi3EnterContinuousTimeMode` (FMI 3.0): Model Exchange, from event mode to
    /// continuous-time mode; `fmi3Error` on a Co-Simulation instance.
    fn fmi3EnterContinuousTimeMode(instance: Fmi3Instance) -> Fmi3StatusC: ENTER_CONTINUOUS_TIME_MODE => Instance::enter_continuous_time_mode;

    /// `fmi3CompletedIntegratorStep` (FMI 3.0): checks the outputs at the current
    /// inputs (a model failure is `fmi3Error`); `enterEventMode` is the model's step event,
    /// `terminateSimulation` false (where non-NULL).
    ///
    /// # Safety
    /// `enterEventMode` and `terminateSimulation` are NULL or writable.
    unsafe fn fmi3CompletedIntegratorStep(instance: Fmi3Instance, _noSetFMUStatePriorToCurrentPoint: Fmi3Boolean, enterEventMode: *mut Fmi3Boolean, terminateSimulation: *mut Fmi3Boolean) -> Fmi3StatusC:
        COMPLETED_INTEGRATOR_STEP => |inst| unsafe {
            inst.require_model_exchange()?;
            let due = inst.completed_integrator_step()?;
            nothing_to_do(inst, &[terminateSimulation])?;
            put(enterEventMode, Fmi3Boolean::from(due));
            Ok(Status::Ok)
        };

    /// `fmi3SetTime` (FMI 3.0): Model Exchange, records the host's solver time `time`
    /// in s (the model's outputs and derivatives do not depend on time explicitly); `fmi3Error` for a non-finite time or on a
    /// Co-Simulation instance.
    fn fmi3SetTime(instance: Fmi3Instance, time: f64) -> Fmi3StatusC: SET_TIME => |inst| inst.set_time(time);

    /// `fmi3GetNumberOfEventIndicators` (FMI 3.0 §3.2): writes 0 to `*nEventIndicators`
    /// (this FMU has no event indicators); `fmi3Error` if it is NULL.
    ///
    /// # Safety
    /// `nEventIndicators` is writable.
    unsafe fn fmi3GetNumberOfEventIndicators(instance: Fmi3Instance, nEventIndicators: *mut usize) -> Fmi3StatusC: RESET =>
        |_| unsafe { write_out(nEventIndicators, 0, "nEventIndicators") };

    /// `fmi3GetNumberOfContinuousStates` (FMI 3.0 §3.2): writes the number of continuous
    /// states (`<ContinuousStateDerivative>` elements) to `*nContinuousStates`; `fmi3Error` if
    /// it is NULL.
    ///
    /// # Safety
    /// `nContinuousStates` is writable.
    unsafe fn fmi3GetNumberOfContinuousStates(instance: Fmi3Instance, nContinuousStates: *mut usize) -> Fmi3StatusC: RESET =>
        |inst| unsafe { write_out(nContinuousStates, inst.number_of_continuous_states(), "nContinuousStates") };

    /// `fmi3SetContinuousStates` (FMI 3.0 §3.2): as `fmi2SetContinuousStates`
    /// (`nContinuousStates` must be the number of states); `fmi3Error` on a Co-Simulation instance.
    ///
    /// # Safety
    /// `values` points to `n` values.
    unsafe fn fmi3SetContinuousStates(instance: Fmi3Instance, values: *const f64, n: usize) -> Fmi3StatusC: SET_CONTINUOUS_STATES =>
        |inst| unsafe { set_states(inst, "nContinuousStates", "continuousStates[]", values, n) };

    /// `fmi3GetContinuousStateDerivatives` (FMI 3.0 §3.2): as `fmi2GetDerivatives`.
    ///
    /// # Safety
    /// `values` points to `n` writable values.
    unsafe fn fmi3GetContinuousStateDerivatives(instance: Fmi3Instance, values: *mut f64, n: usize) -> Fmi3StatusC: GET_DERIVATIVES =>
        |inst| unsafe { get_states(inst, "nContinuousStates", "derivatives[]", values, n, Instance::get_derivatives) };

    /// `fmi3GetEventIndicators` (FMI 3.0, Model Exchange): this FMU has no event indicators,
    /// so `nEventIndicators` must be 0 (then `fmi3OK`, nothing written); `fmi3Error` otherwise
    /// or on a Co-Simulation instance.
    fn fmi3GetEventIndicators(instance: Fmi3Instance, _values: *mut f64, n: usize) -> Fmi3StatusC: GET_DERIVATIVES => none("nEventIndicators", n);

    /// `fmi3GetContinuousStates` (FMI 3.0 §3.2): as `fmi2GetContinuousStates`.
    ///
    /// # Safety
    /// `values` points to `n` writable values.
    unsafe fn fmi3GetContinuousStates(instance: Fmi3Instance, values: *mut f64, n: usize) -> Fmi3StatusC: GET_CONTINUOUS_STATES =>
        |inst| unsafe { get_states(inst, "nContinuousStates", "continuousStates[]", values, n, |i: &mut Instance, o: &mut [f64]| i.get_continuous_states(o)) };

    /// `fmi3GetNominalsOfContinuousStates` (FMI 3.0 §3.2): as
    /// `fmi2GetNominalsOfContinuousStates`.
    ///
    /// # Safety
    /// `values` points to `n` writable values.
    unsafe fn fmi3GetNominalsOfContinuousStates(instance: Fmi3Instance, values: *mut f64, n: usize) -> Fmi3StatusC: GET_CONTINUOUS_STATES =>
        |inst| unsafe { get_states(inst, "nContinuousStates", "nominals[]", values, n, |i: &mut Instance, o: &mut [f64]| i.nominals_of_continuous_states(o)) };
}
