//! The Co-Simulation functions of FMI 3.0 (§4): one communication step at a time, no event
//! mode (`hasEventMode = false`), no early return, no output derivatives.

#![allow(non_snake_case)]

use super::super::types::*;
use crate::core::guard::{guarded, put, refuse};
use crate::core::state::{Mask, State, DO_STEP, RESET};

/// `fmi3EnterStepMode`, FMI 3.0's own (§4.2 state chart): only after event mode, which this
/// layer's Co-Simulation never enters (`hasEventMode = false`).
const ENTER_STEP_MODE: Mask = Mask::of(&[State::EventMode]);

guarded! {
    /// `fmi3EnterStepMode` (FMI 3.0): only allowed after event mode, which this
    /// Co-Simulation never enters (`hasEventMode = false`); always `fmi3Error`.
    fn fmi3EnterStepMode(instance: Fmi3Instance) -> Fmi3StatusC: ENTER_STEP_MODE =>
        refuse("this FMU's Co-Simulation has no event mode (hasEventMode = false), so there is no step mode to return to");

    /// `fmi3GetOutputDerivatives` (FMI 3.0): not provided
    /// (`maxOutputDerivativeOrder = 0`); always `fmi3Error`.
    fn fmi3GetOutputDerivatives(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _orders: *const i32, _values: *mut f64, _nValues: usize) -> Fmi3StatusC:
        RESET => refuse("output derivatives are not provided (maxOutputDerivativeOrder = 0)");

    /// `fmi3DoStep` (FMI 3.0): one communication step from `currentCommunicationPoint`
    /// over `communicationStepSize` (s), as `fmi2DoStep`. Never returns
    /// early, never asks for event handling or termination; `*lastSuccessfulTime` is the end of
    /// the step (or, after a failed step, the end of the last good one), in s. `fmi3Error` for a
    /// step that is not positive or does not continue the last one, or that the model fails.
    ///
    /// # Safety
    /// The four output pointers are NULL or writable.
    #[allow(clippy::too_many_arguments)]
    unsafe fn fmi3DoStep(
        instance: Fmi3Instance,
        currentCommunicationPoint: f64,
        communicationStepSize: f64,
        _noSetFMUStatePriorToCurrentPoint: Fmi3Boolean,
        eventHandlingNeeded: *mut Fmi3Boolean,
        terminateSimulation: *mut Fmi3Boolean,
        earlyReturn: *mut Fmi3Boolean,
        lastSuccessfulTime: *mut f64,
    ) -> Fmi3StatusC: DO_STEP => |inst| {
        let r = inst.do_step(currentCommunicationPoint, communicationStepSize);
        // SAFETY: per the contract.
        unsafe {
            for p in [eventHandlingNeeded, terminateSimulation, earlyReturn] {
                put(p, 0);
            }
            put(lastSuccessfulTime, inst.time);
        }
        r
    };
}
