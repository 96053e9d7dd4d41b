//! The C types of the FMI 2.0 API (`fmi2TypesPlatform.h`, `fmi2FunctionTypes.h`).
//!
//! Enumerations that the host passes in (`fmi2Type`, `fmi2StatusKind`) are taken as
//! plain `c_int` so that an out-of-range value is an error message, never undefined
//! behaviour.

use std::ffi::{c_char, c_int, c_uint, c_void};

pub type Fmi2Component = *mut c_void;
pub type Fmi2ComponentEnvironment = *mut c_void;
pub type Fmi2FmuState = *mut c_void;
pub type Fmi2ValueReference = c_uint;
pub type Fmi2Real = f64;
pub type Fmi2Integer = c_int;
pub type Fmi2Boolean = c_int;
pub type Fmi2String = *const c_char;
pub type Fmi2Byte = c_char;

pub const FMI2_TRUE: Fmi2Boolean = 1;
pub const FMI2_FALSE: Fmi2Boolean = 0;

/// `fmi2Status` as returned through the C ABI.
pub type Fmi2StatusC = c_int;

/// `fmi2Type`: 0 = Model Exchange, 1 = Co-Simulation.
pub const FMI2_MODEL_EXCHANGE: c_int = 0;
pub const FMI2_CO_SIMULATION: c_int = 1;

/// `fmi2StatusKind`.
pub const FMI2_DO_STEP_STATUS: c_int = 0;
pub const FMI2_PENDING_STATUS: c_int = 1;
pub const FMI2_LAST_SUCCESSFUL_TIME: c_int = 2;
pub const FMI2_TERMINATED: c_int = 3;

/// The FMI 2.0 status, ordered by severity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[repr(i32)]
pub enum Status {
    Ok = 0,
    Warning = 1,
    Discard = 2,
    Error = 3,
    Fatal = 4,
    Pending = 5,
}

impl Status {
    pub fn c(self) -> Fmi2StatusC {
        self as c_int
    }
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "fmi2OK",
            Status::Warning => "fmi2Warning",
            Status::Discard => "fmi2Discard",
            Status::Error => "fmi2Error",
            Status::Fatal => "fmi2Fatal",
            Status::Pending => "fmi2Pending",
        }
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
pub type Fmi2CallbackAllocateMemory = unsafe extern "C" fn(usize, usize) -> *mut c_void;
pub type Fmi2CallbackFreeMemory = unsafe extern "C" fn(*mut c_void);
pub type Fmi2StepFinished = unsafe extern "C" fn(Fmi2ComponentEnvironment, Fmi2StatusC);

/// `fmi2CallbackFunctions`. This FMU declares `canNotUseMemoryManagementFunctions`,
/// so only `logger` and `componentEnvironment` are used.
#[repr(C)]
pub struct Fmi2CallbackFunctions {
    pub logger: Option<Fmi2CallbackLogger>,
    pub allocate_memory: Option<Fmi2CallbackAllocateMemory>,
    pub free_memory: Option<Fmi2CallbackFreeMemory>,
    pub step_finished: Option<Fmi2StepFinished>,
    pub component_environment: Fmi2ComponentEnvironment,
}

/// `fmi2GetTypesPlatform()`.
pub const TYPES_PLATFORM: &std::ffi::CStr = c"default";
/// `fmi2GetVersion()`.
pub const VERSION: &std::ffi::CStr = c"2.0";
