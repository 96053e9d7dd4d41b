//! The FMI 2.0 Co-Simulation (FMI 2.0.4, section 4.2.4) and Model Exchange (section 3.2.3)
//! state machine, also used by the FMI 3.0 layer (its step mode is `stepComplete`), with one
//! bit mask per function naming the states in which the standard allows the call.
//!
//! The masks follow the standard's state chart (and the modelica/Reference-FMUs
//! layout). One deliberate difference: `fmi2FreeInstance` is also accepted in
//! the `Fatal` state, so that a host can always release the memory.

/// One state of the instance's life cycle; in a [`Mask`] it is the bit `1 << code`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum State {
    /// Before `fmi2Instantiate` / after `fmi2FreeInstance` (never held by an instance).
    StartAndEnd,
    /// After `fmi2Instantiate` (or `fmi2Reset`): parameters and start values may be set.
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    InitializationMode,
    /// Co-Simulation: initialized and ready for the next `fmi2DoStep` (FMI 3.0 step mode).
    StepComplete,
    /// Only reached by asynchronous slaves; this FMU steps synchronously.
    StepInProgress,
    /// Co-Simulation: a step was discarded (`fmi2Discard`); this FMU never discards a step.
    StepFailed,
    /// Co-Simulation: an asynchronous step was cancelled (never reached here).
    StepCanceled,
    /// After `fmi2Terminate`: values may still be read, then reset or free.
    Terminated,
    /// After a call returned `fmi2Error` that left the instance inconsistent (a failed step or
    /// initialization): only getters, FMU state functions, reset and free are allowed.
    Error,
    /// After a contained panic (`fmi2Fatal`): only `fmi2FreeInstance` is allowed.
    Fatal,
    /// Model Exchange (both standards): event mode, after initialization.
    EventMode,
    /// Model Exchange: continuous-time mode, in which the host's solver integrates.
    ContinuousTimeMode,
}

impl State {
    /// Every state, in bit order (for [`Mask::describe`] and [`State::from_code`]).
    pub const ALL: [State; 12] = [
        State::StartAndEnd,
        State::Instantiated,
        State::InitializationMode,
        State::StepComplete,
        State::StepInProgress,
        State::StepFailed,
        State::StepCanceled,
        State::Terminated,
        State::Error,
        State::Fatal,
        State::EventMode,
        State::ContinuousTimeMode,
    ];

    /// The standard's name of the state (as in its state chart), for log messages.
    pub fn name(self) -> &'static str {
        match self {
            State::StartAndEnd => "startAndEnd",
            State::Instantiated => "instantiated",
            State::InitializationMode => "initializationMode",
            State::StepComplete => "stepComplete",
            State::StepInProgress => "stepInProgress",
            State::StepFailed => "stepFailed",
            State::StepCanceled => "stepCanceled",
            State::Terminated => "terminated",
            State::Error => "error",
            State::Fatal => "fatal",
            State::EventMode => "eventMode",
            State::ContinuousTimeMode => "continuousTimeMode",
        }
    }

    /// A small code for the serialized FMU state (the state's bit number in a [`Mask`]).
    pub fn code(self) -> u8 {
        self as u8
    }

    /// The state's bit in a [`Mask`].
    const fn bit(self) -> u32 {
        1 << self as u32
    }

    /// The state whose [`State::code`] is `code`, or `None` for a code no state has
    /// (a corrupt serialized FMU state).
    pub fn from_code(code: u8) -> Option<State> {
        State::ALL.iter().copied().find(|s| s.code() == code)
    }
}

/// A set of states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mask(pub u32);

impl Mask {
    /// The set of `states` (a shim builds the masks of its own functions with it).
    pub const fn of(states: &[State]) -> Mask {
        let mut bits = 0;
        let mut i = 0;
        while i < states.len() {
            bits |= states[i].bit();
            i += 1;
        }
        Mask(bits)
    }

    /// Whether the state `s` is in the set.
    pub fn allows(self, s: State) -> bool {
        self.0 & s.bit() != 0
    }

    /// The allowed states, for messages: "instantiated, initializationMode".
    pub fn describe(self) -> String {
        let names: Vec<&str> = State::ALL.iter().filter(|s| self.allows(**s)).map(|s| s.name()).collect();
        if names.is_empty() { "no state".into() } else { names.join(", ") }
    }
}

use State::*;

/// Every state, for the functions that need no instance.
pub const ANY_STATE: Mask = Mask::of(&[
    StartAndEnd, Instantiated, InitializationMode, StepComplete, StepInProgress, StepFailed, StepCanceled,
    Terminated, Error, Fatal, EventMode, ContinuousTimeMode,
]);
/// `fmi2GetVersion` and `fmi3GetVersion`: every state.
pub const GET_VERSION: Mask = ANY_STATE;
/// `fmi2SetDebugLogging`: every state of a live, non-fatal instance.
pub const SET_DEBUG_LOGGING: Mask = Mask::of(&[
    Instantiated, InitializationMode, StepComplete, StepInProgress, StepFailed, StepCanceled, Terminated, Error,
    EventMode, ContinuousTimeMode,
]);
/// `fmi2Instantiate`: before any instance exists.
pub const INSTANTIATE: Mask = Mask::of(&[StartAndEnd]);
/// Every state an instance can be in, `Fatal` included (see the module doc).
pub const FREE_INSTANCE: Mask = Mask::of(&[
    Instantiated, InitializationMode, StepComplete, StepFailed, StepCanceled, Terminated, Error, Fatal, EventMode,
    ContinuousTimeMode,
]);
/// `fmi2EnterInitializationMode`: right after instantiation only.
pub const ENTER_INITIALIZATION_MODE: Mask = Mask::of(&[Instantiated]);
/// `fmi2ExitInitializationMode`: in initialization mode only.
pub const EXIT_INITIALIZATION_MODE: Mask = Mask::of(&[InitializationMode]);
/// `fmi2Terminate`: after initialization, outside error states.
pub const TERMINATE: Mask = Mask::of(&[StepComplete, StepFailed, EventMode, ContinuousTimeMode]);
/// `fmi2Reset`: every state of a live, non-fatal instance.
pub const RESET: Mask = Mask::of(&[
    Instantiated, InitializationMode, StepComplete, StepFailed, StepCanceled, Terminated, Error, EventMode,
    ContinuousTimeMode,
]);
/// `fmi2Get{Real,Integer,Boolean,String}`: from initialization mode on.
pub const GET_VALUE: Mask = Mask::of(&[
    InitializationMode, StepComplete, StepFailed, StepCanceled, Terminated, Error, EventMode, ContinuousTimeMode,
]);
/// In `continuousTimeMode` only continuous inputs may be set (checked by the instance).
pub const SET_VALUE: Mask = Mask::of(&[Instantiated, InitializationMode, StepComplete, EventMode, ContinuousTimeMode]);
/// The FMU state functions (`fmi2GetFMUstate` … `fmi2DeSerializeFMUstate`): as [`RESET`].
pub const FMU_STATE: Mask = RESET;
/// `fmi2DoStep`: in `stepComplete` only.
pub const DO_STEP: Mask = Mask::of(&[StepComplete]);
/// Model Exchange (FMI 2.0 section 3.2.3 state chart; FMI 3.0 the same modes).
pub const ENTER_EVENT_MODE: Mask = Mask::of(&[EventMode, ContinuousTimeMode]);
/// `fmi2NewDiscreteStates` (Model Exchange): in event mode.
pub const NEW_DISCRETE_STATES: Mask = Mask::of(&[EventMode]);
/// `fmi2EnterContinuousTimeMode` (Model Exchange): from event mode.
pub const ENTER_CONTINUOUS_TIME_MODE: Mask = Mask::of(&[EventMode]);
/// `fmi2CompletedIntegratorStep` (Model Exchange): in continuous-time mode.
pub const COMPLETED_INTEGRATOR_STEP: Mask = Mask::of(&[ContinuousTimeMode]);
/// `fmi2SetTime` (Model Exchange): in event and continuous-time mode.
pub const SET_TIME: Mask = Mask::of(&[EventMode, ContinuousTimeMode]);
/// `fmi2SetContinuousStates` (Model Exchange): in continuous-time mode.
pub const SET_CONTINUOUS_STATES: Mask = Mask::of(&[ContinuousTimeMode]);
/// `fmi2GetDerivatives` and `fmi2GetEventIndicators` (Model Exchange).
pub const GET_DERIVATIVES: Mask = Mask::of(&[InitializationMode, EventMode, ContinuousTimeMode, Terminated, Error]);
/// `fmi2GetContinuousStates` and `fmi2GetNominalsOfContinuousStates` (Model Exchange).
pub const GET_CONTINUOUS_STATES: Mask =
    Mask::of(&[Instantiated, InitializationMode, EventMode, ContinuousTimeMode, Terminated, Error]);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_round_trip_and_are_distinct() {
        for s in State::ALL {
            assert_eq!(State::from_code(s.code()), Some(s));
        }
        assert_eq!(State::from_code(12), None);
        // The codes of the Co-Simulation states are those of serialized states written before
        // the Model Exchange states existed.
        assert_eq!((State::StepComplete.code(), State::Error.code(), State::EventMode.code()), (3, 8, 10));
    }

    #[test]
    fn masks_follow_the_standard() {
        assert!(DO_STEP.allows(StepComplete) && !DO_STEP.allows(InitializationMode));
        assert!(!SET_VALUE.allows(Terminated) && !SET_VALUE.allows(Error));
        assert!(!GET_VALUE.allows(Instantiated) && GET_VALUE.allows(Error));
        assert!(TERMINATE.allows(StepFailed) && !TERMINATE.allows(Terminated));
        assert!(FREE_INSTANCE.allows(Fatal) && !RESET.allows(Fatal));
        assert_eq!(EXIT_INITIALIZATION_MODE.describe(), "initializationMode");
    }
}
