//! The C types both standards share under their own names: the instance and FMU state
//! handles, value references, the status and its C code. `fmi2::types` and `fmi3::types`
//! spell them `Fmi2Component`/`Fmi3Instance`, `Fmi2FmuState`/`Fmi3FmuState`, … as aliases of
//! these, so the two versions cannot disagree about a type the core hands to both.

use std::ffi::{c_int, c_uint, c_void};

/// The instance handle (`fmi2Component`, `fmi3Instance`): a pointer to an
/// [`Instance`](super::instance::Instance).
pub type InstanceHandle = *mut c_void;
/// The host's environment pointer (`fmi2ComponentEnvironment`, `fmi3InstanceEnvironment`),
/// passed back to its logger.
pub type Environment = *mut c_void;
/// A handle to a saved FMU state (`fmi2FMUstate`, `fmi3FMUState`): a pointer to a
/// [`Snapshot`](super::snapshot::Snapshot).
pub type StateHandle = *mut c_void;
/// A value reference (`fmi2ValueReference`, `fmi3ValueReference`).
pub type ValueReference = c_uint;
/// The status as returned through the C ABI (`fmi2Status`, `fmi3Status`: the same codes).
pub type StatusC = c_int;

/// The status of a call, ordered by severity (the same codes in FMI 2.0 and 3.0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[repr(i32)]
pub enum Status {
    /// `fmi2OK`: all well.
    Ok = 0,
    /// `fmi2Warning`: done, but the host should look at the log.
    Warning = 1,
    /// `fmi2Discard`: the step was not done (Co-Simulation).
    Discard = 2,
    /// `fmi2Error`: the call failed; the instance may still be usable where the standard allows.
    Error = 3,
    /// `fmi2Fatal`: the instance is broken; only `fmi2FreeInstance` is allowed.
    Fatal = 4,
    /// `fmi2Pending`: an asynchronous step is running (never returned by this layer).
    Pending = 5,
}

impl Status {
    /// The value passed through the C ABI.
    pub fn c(self) -> StatusC {
        self as c_int
    }
    /// The FMI 2.0 name of the status, e.g. `fmi2Error`, for log messages.
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
