//! The C types of the FMI 3.0 API (`fmi3PlatformTypes.h`, `fmi3FunctionTypes.h`).
//!
//! Where FMI 3.0 only renames a C type of FMI 2.0 (the instance and FMU state handles, value
//! references, Float64, Int32, strings, the status), the FMI 3.0 name is the FMI 2.0 type
//! itself, so the two layers cannot disagree about it. `fmi3Boolean` is C's `bool`; values
//! coming from the host are read as bytes (any non-zero byte is true), so a byte other than 0
//! or 1 is never undefined behaviour in Rust.

use std::ffi::c_int;

/// `fmi3Instance` (a `void*`), `fmi3FMUState` (a `void*`), `fmi3ValueReference` (a
/// `uint32_t`), `fmi3Float64`, `fmi3Int32`, `fmi3String` (NULL or a NUL-terminated UTF-8
/// string) and `fmi3Status` through the C ABI (same codes as `fmi2Status`: OK 0 … Fatal 4):
/// the C types of FMI 2.0 under their FMI 3.0 names.
pub use crate::fmi2::types::{
    Fmi2Component as Fmi3Instance, Fmi2FmuState as Fmi3FmuState, Fmi2Integer as Fmi3Int32, Fmi2Real as Fmi3Float64,
    Fmi2StatusC as Fmi3StatusC, Fmi2String as Fmi3String, Fmi2ValueReference as Fmi3ValueReference,
};

/// `fmi3Int64`.
pub type Fmi3Int64 = i64;
/// `fmi3Boolean` (C `bool`, one byte) as passed by value or read from the host.
pub type Fmi3Boolean = u8;
/// `fmi3Byte`, the element of a serialized FMU state and of Binary values.
pub type Fmi3Byte = u8;

/// `fmi3DependencyKind::fmi3Dependent`.
pub const FMI3_DEPENDENT: c_int = 5;

/// `fmi3GetVersion()`.
pub const VERSION: &std::ffi::CStr = c"3.0";
