//! The C types of the FMI 3.0 API (`fmi3PlatformTypes.h`, `fmi3FunctionTypes.h`).
//!
//! Where FMI 3.0 only renames a C type of FMI 2.0 (the instance and FMU state handles, value
//! references, Float64, Int32, strings, the status), the FMI 3.0 name is the core's type
//! ([`crate::core::types`]), as is the FMI 2.0 name, so the two versions cannot disagree about
//! it. `fmi3Boolean` is C's `bool`; values coming from the host are read as bytes (any
//! non-zero byte is true), so a byte other than 0 or 1 is never undefined behaviour in Rust.

use crate::core::types::{InstanceHandle, StateHandle, StatusC, ValueReference};
use std::ffi::{c_char, c_int, c_void};

pub use crate::core::types::Status;

/// `fmi3Instance` (a `void*`).
pub type Fmi3Instance = InstanceHandle;
/// `fmi3FMUState` (a `void*`).
pub type Fmi3FmuState = StateHandle;
/// `fmi3ValueReference` (a `uint32_t`).
pub type Fmi3ValueReference = ValueReference;
/// `fmi3Status` through the C ABI (the same codes as `fmi2Status`: OK 0 … Fatal 4).
pub type Fmi3StatusC = StatusC;
/// `fmi3Float64`.
pub type Fmi3Float64 = f64;
/// `fmi3Int32`.
pub type Fmi3Int32 = c_int;
/// `fmi3String`: NULL or a NUL-terminated UTF-8 string.
pub type Fmi3String = *const c_char;
/// `fmi3Int64`.
pub type Fmi3Int64 = i64;
/// `fmi3Boolean` (C `bool`, one byte) as passed by value or read from the host.
pub type Fmi3Boolean = u8;
/// `fmi3Byte`, the element of a serialized FMU state and of Binary values.
pub type Fmi3Byte = u8;

/// `fmi3LogMessageCallback(instanceEnvironment, status, category, message)`.
pub type Fmi3LogMessageCallback = unsafe extern "C" fn(*mut c_void, c_int, *const c_char, *const c_char);

/// The `fmi3Status` name of a status, e.g. `fmi3Error`, for messages and the
/// modelDescription's log category descriptions. FMI 3.0 has no pending status (this layer
/// never returns it under either standard).
pub fn status_name(status: Status) -> &'static str {
    match status {
        Status::Ok => "fmi3OK",
        Status::Warning => "fmi3Warning",
        Status::Discard => "fmi3Discard",
        Status::Error => "fmi3Error",
        Status::Fatal => "fmi3Fatal",
        Status::Pending => "status 5 (no fmi3Status)",
    }
}

/// `fmi3DependencyKind::fmi3Dependent`.
pub const FMI3_DEPENDENT: c_int = 5;

/// `fmi3GetVersion()`.
pub const VERSION: &std::ffi::CStr = c"3.0";
