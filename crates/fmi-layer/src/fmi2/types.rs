//! The C types of the FMI 2.0 API (`fmi2TypesPlatform.h`, `fmi2FunctionTypes.h`).
//!
//! Enumerations that the host passes in (`fmi2Type`, `fmi2StatusKind`) are taken as
//! plain `c_int` so that an out-of-range value is an error message, never undefined
//! behaviour. The handles, value references and the status are the core's types
//! ([`crate::core::types`]) under their FMI 2.0 names.

use crate::core::types::{Environment, InstanceHandle, StateHandle, StatusC, ValueReference};
use std::ffi::{c_char, c_int, c_void};

pub use crate::core::types::{Status, StatusKind};

/// `fmi2Component`: the instance handle the FMU returns from `fmi2Instantiate`.
pub type Fmi2Component = InstanceHandle;
/// `fmi2ComponentEnvironment`: the host's pointer, passed back to its logger.
pub type Fmi2ComponentEnvironment = Environment;
/// `fmi2FMUstate`: a handle to a saved FMU state.
pub type Fmi2FmuState = StateHandle;
/// `fmi2ValueReference`: the number that names a variable in the modelDescription.
pub type Fmi2ValueReference = ValueReference;
/// `fmi2Real`.
pub type Fmi2Real = f64;
/// `fmi2Integer`.
pub type Fmi2Integer = c_int;
/// `fmi2Boolean` (`fmi2True` = 1, `fmi2False` = 0).
pub type Fmi2Boolean = c_int;
/// `fmi2String`: NULL or a NUL-terminated string.
pub type Fmi2String = *const c_char;
/// `fmi2Byte`, the element of a serialized FMU state.
pub type Fmi2Byte = c_char;

/// `fmi2True`.
pub const FMI2_TRUE: Fmi2Boolean = 1;
/// `fmi2False`.
pub const FMI2_FALSE: Fmi2Boolean = 0;

/// `fmi2Status` as returned through the C ABI.
pub type Fmi2StatusC = StatusC;

/// `fmi2Type`: 0 = Model Exchange, 1 = Co-Simulation.
pub const FMI2_MODEL_EXCHANGE: c_int = 0;
/// `fmi2CoSimulation`.
pub const FMI2_CO_SIMULATION: c_int = 1;

/// `fmi2StatusKind`.
pub const FMI2_DO_STEP_STATUS: c_int = 0;
/// `fmi2PendingStatus`.
pub const FMI2_PENDING_STATUS: c_int = 1;
/// `fmi2LastSuccessfulTime`.
pub const FMI2_LAST_SUCCESSFUL_TIME: c_int = 2;
/// `fmi2Terminated`.
pub const FMI2_TERMINATED: c_int = 3;

/// The status kind of the `fmi2StatusKind` code `code`, or the code if it is none.
pub fn status_kind(code: c_int) -> Result<StatusKind, c_int> {
    match code {
        FMI2_DO_STEP_STATUS => Ok(StatusKind::DoStepStatus),
        FMI2_PENDING_STATUS => Ok(StatusKind::PendingStatus),
        FMI2_LAST_SUCCESSFUL_TIME => Ok(StatusKind::LastSuccessfulTime),
        FMI2_TERMINATED => Ok(StatusKind::Terminated),
        other => Err(other),
    }
}

/// The `fmi2Status` name of a status, e.g. `fmi2Error`, for messages and the
/// modelDescription's log category descriptions.
pub fn status_name(status: Status) -> &'static str {
    match status {
        Status::Ok => "fmi2OK",
        Status::Warning => "fmi2Warning",
        Status::Discard => "fmi2Discard",
        Status::Error => "fmi2Error",
        Status::Fatal => "fmi2Fatal",
        Status::Pending => "fmi2Pending",
    }
}

/// `fmi2CallbackLogger`: `(env, instanceName, status, category, message, ...)`.
/// The FMU always passes the message as the argument of a `"%s"` format, so that
/// a `%` in a message can never be read as a conversion by the host.
pub type Fmi2CallbackLogger = unsafe extern "C" fn(
    Fmi2ComponentEnvironment,
    Fmi2String,
    Fmi2StatusC,
    Fmi2String,
    Fmi2String,
    ...
);
/// `fmi2CallbackAllocateMemory` (not used: see [`Fmi2CallbackFunctions`]).
pub type Fmi2CallbackAllocateMemory = unsafe extern "C" fn(usize, usize) -> *mut c_void;
/// `fmi2CallbackFreeMemory` (not used).
pub type Fmi2CallbackFreeMemory = unsafe extern "C" fn(*mut c_void);
/// `fmi2StepFinished`, for asynchronous steps (not used: `canRunAsynchronuously` is false).
pub type Fmi2StepFinished = unsafe extern "C" fn(Fmi2ComponentEnvironment, Fmi2StatusC);

/// `fmi2CallbackFunctions`. This FMU declares `canNotUseMemoryManagementFunctions`,
/// so only `logger` and `componentEnvironment` are used.
#[repr(C)]
pub struct Fmi2CallbackFunctions {
    /// The host's logger; required (an instance without one is refused).
    pub logger: Option<Fmi2CallbackLogger>,
    /// The host's allocator (not used).
    pub allocate_memory: Option<Fmi2CallbackAllocateMemory>,
    /// The host's deallocator (not used).
    pub free_memory: Option<Fmi2CallbackFreeMemory>,
    /// The host's callback for asynchronous steps (not used).
    pub step_finished: Option<Fmi2StepFinished>,
    /// Passed back as the first argument of every `logger` call.
    pub component_environment: Fmi2ComponentEnvironment,
}

/// `fmi2GetTypesPlatform()`.
pub const TYPES_PLATFORM: &std::ffi::CStr = c"default";
/// `fmi2GetVersion()`.
pub const VERSION: &std::ffi::CStr = c"2.0";
