//! The C types both standards share under their own names: the instance and FMU state
//! handles, value references, the status and its C code. Each shim's `types` module
//! spells them `Fmi2Component`/`Fmi3Instance`, `Fmi2FmuState`/`Fmi3FmuState`, … as aliases of
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
    /// OK (`fmi2OK`, `fmi3OK`): all well.
    Ok = 0,
    /// Warning (`fmi2Warning`, `fmi3Warning`): done, but the host should look at the log.
    Warning = 1,
    /// Discard (`fmi2Discard`, `fmi3Discard`): the step was not done (Co-Simulation).
    Discard = 2,
    /// Error (`fmi2Error`, `fmi3Error`): the call failed; the instance may still be usable where the standard allows.
    Error = 3,
    /// Fatal (`fmi2Fatal`, `fmi3Fatal`): the instance is broken; only freeing it is allowed.
    Fatal = 4,
    /// Pending (FMI 2.0's `fmi2Pending`): an asynchronous step is running (never returned by
    /// this layer).
    Pending = 5,
}

impl Status {
    /// The value passed through the C ABI.
    pub fn c(self) -> StatusC {
        self as c_int
    }
}

/// What a host may ask a Co-Simulation instance about with a `Get*Status` function (FMI 2.0
/// §4.2.3; FMI 3.0 has no such functions). The shim that has them maps its C codes to these
/// and names them in its own words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StatusKind {
    /// The status of an asynchronous step.
    DoStepStatus,
    /// A string describing an asynchronous step in progress.
    PendingStatus,
    /// The end time of the last successful step.
    LastSuccessfulTime,
    /// Whether the slave wants the simulation to end.
    Terminated,
}

impl StatusKind {
    /// Every status kind, in the order of their C codes in FMI 2.0.
    pub const ALL: [StatusKind; 4] = [StatusKind::DoStepStatus, StatusKind::PendingStatus, StatusKind::LastSuccessfulTime, StatusKind::Terminated];

    /// The kind's name without the standard's prefix, e.g. `DoStepStatus`.
    pub fn name(self) -> &'static str {
        match self {
            StatusKind::DoStepStatus => "DoStepStatus",
            StatusKind::PendingStatus => "PendingStatus",
            StatusKind::LastSuccessfulTime => "LastSuccessfulTime",
            StatusKind::Terminated => "Terminated",
        }
    }
}
