//! The C types of the FMI 3.0 API (`fmi3PlatformTypes.h`, `fmi3FunctionTypes.h`).
//!
//! `fmi3Boolean` is C's `bool`; values coming from the host are read as bytes (any non-zero
//! byte is true), so a byte other than 0 or 1 is never undefined behaviour in Rust.

use std::ffi::{c_char, c_int, c_void};

/// `fmi3Instance`: the instance handle returned by the instantiation functions.
pub type Fmi3Instance = *mut c_void;
/// `fmi3FMUState`: a handle to a saved FMU state.
pub type Fmi3FmuState = *mut c_void;
/// `fmi3ValueReference`: the number that names a variable in the modelDescription.
pub type Fmi3ValueReference = u32;
/// `fmi3Float64`.
pub type Fmi3Float64 = f64;
/// `fmi3Int32`.
pub type Fmi3Int32 = i32;
/// `fmi3Int64`.
pub type Fmi3Int64 = i64;
/// `fmi3Boolean` (C `bool`, one byte) as passed by value or read from the host.
pub type Fmi3Boolean = u8;
/// `fmi3String`: NULL or a NUL-terminated UTF-8 string.
pub type Fmi3String = *const c_char;
/// `fmi3Byte`, the element of a serialized FMU state and of Binary values.
pub type Fmi3Byte = u8;
/// `fmi3Status` through the C ABI (same codes as `fmi2Status`: OK 0 … Fatal 4).
pub type Fmi3StatusC = c_int;

/// `fmi3DependencyKind::fmi3Dependent`.
pub const FMI3_DEPENDENT: c_int = 5;

/// `fmi3GetVersion()`.
pub const VERSION: &std::ffi::CStr = c"3.0";
