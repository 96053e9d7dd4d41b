//! Every `fmi3*` function of the FMI 3.0 standard but the two instantiation functions that
//! need the model registry ([`crate::export_fmi3!`]), exported with C linkage. Each goes
//! through the same guard as the FMI 2.0 functions: NULL or dead instance, the state mask,
//! error logging, panic containment (a panic returns `fmi3Fatal`).
//!
//! Unsupported parts of the standard (clocks, scheduled execution, configuration mode,
//! directional and adjoint derivatives, output derivatives, Float32/8-/16-bit/unsigned/String/
//! Binary variables) are refused with a message naming why.

#![allow(non_snake_case)]

use super::types::*;
use crate::error::CallError;
use crate::fmi2::api::common::{
    deserialize_fmu_state, free_fmu_state, get_fmu_state, looks_like_uri, serialize_fmu_state, serialized_fmu_state_size,
    set_fmu_state, text,
};
use crate::fmi2::api::guard::{call, maybe_forced_panic, slice, slice_mut};
use crate::fmi2::instance::{CallResult, Instance, Interface};
use crate::fmi2::logging::{Category, Fmi3LogMessageCallback, Logger};
use crate::fmi2::state;
use crate::fmi2::types::Status;
use crate::fmi2::variables::{Causality, EnumType, Kind, ModelInfo};
use std::ffi::{c_char, c_int, c_void};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;

/// Stands for "any enumeration type" when an `fmi3GetInt64`/`fmi3SetInt64` call is matched
/// against the variable table (only the kind is compared).
static ANY_ENUMERATION: EnumType = EnumType { name: "", description: "", items: &[] };

/// `fmi3GetVersion` (FMI 3.0): returns the static string `"3.0"` ([`VERSION`]).
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

/// The body of both instantiation functions: finds the model by instantiation token (the
/// FMI 2.0 GUID of the same model: one interface, one token).
///
/// # Safety
/// Pointers as in the FMI 3.0 standard; NULL is handled everywhere.
#[allow(clippy::too_many_arguments)]
pub unsafe fn instantiate_from(
    registry: &[&'static ModelInfo],
    interface: Interface,
    instance_name: Fmi3String,
    token: Fmi3String,
    resource_path: Fmi3String,
    logging_on: Fmi3Boolean,
    event_mode_used: Fmi3Boolean,
    env: *mut c_void,
    log_message: Option<Fmi3LogMessageCallback>,
) -> Fmi3Instance {
    catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: strings from the host are NULL or NUL-terminated.
        let (name, token, resources) = unsafe { (text(instance_name), text(token), text(resource_path)) };
        let shown = name.clone().unwrap_or_else(|| "(NULL)".into());
        let logger = Logger::new_fmi3(log_message, env, &shown, logging_on != 0);
        let func = match interface {
            Interface::CoSimulation => "fmi3InstantiateCoSimulation",
            Interface::ModelExchange => "fmi3InstantiateModelExchange",
        };
        let fail = |msg: String| {
            logger.log(Status::Error, Category::StatusError, &format!("{func}: {msg}"));
            null_mut()
        };
        maybe_forced_panic(func);
        let name = match name {
            Some(n) if !n.is_empty() => n,
            _ => return fail("instanceName must be a non-empty string".into()),
        };
        let Some(token) = token else {
            return fail("instantiationToken is NULL".into());
        };
        let Some(info) = registry.iter().copied().find(|m| m.guid() == token) else {
            let known: Vec<String> = registry.iter().map(|m| format!("{} {}", m.model_name, m.guid())).collect();
            return fail(format!(
                "instantiationToken {token} matches no model of this binary (known: {}); the modelDescription.xml does not belong to this binary",
                known.join(", ")
            ));
        };
        if interface == Interface::ModelExchange && !info.model_exchange {
            return fail(format!("{} implements Co-Simulation only", info.model_name));
        }
        if event_mode_used != 0 {
            return fail("eventModeUsed = true, but this FMU's Co-Simulation has no event mode (hasEventMode = false)".into());
        }
        // This FMU needs no resources: NULL or "" is fine; a path that is not absolute is a warning.
        if let Some(r) = resources.as_deref().filter(|r| !r.is_empty() && !r.starts_with('/') && !looks_like_uri(r) && !r.contains('\\')) {
            logger.log(
                Status::Warning,
                Category::StatusWarning,
                &format!("{func}: resourcePath '{r}' is not an absolute path; this FMU needs no resources, continuing"),
            );
        }
        let inst = Instance::with_interface(info, &name, logger, interface, true);
        inst.event(&format!("instantiated {} (FMI 3.0 {:?}, instantiationToken {token})", info.model_name, interface));
        Box::into_raw(Box::new(inst)) as Fmi3Instance
    }))
    .unwrap_or(null_mut())
}

/// `fmi3InstantiateScheduledExecution` (FMI 3.0): not supported (no Scheduled
/// Execution interface); always returns NULL, with the reason logged when `logMessage` is given.
///
/// # Safety
/// Pointers as in the FMI 3.0 standard.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
    instanceName: Fmi3String,
    _instantiationToken: Fmi3String,
    _resourcePath: Fmi3String,
    _visible: Fmi3Boolean,
    _loggingOn: Fmi3Boolean,
    instanceEnvironment: *mut c_void,
    logMessage: Option<Fmi3LogMessageCallback>,
    _clockUpdate: *mut c_void,
    _lockPreemption: *mut c_void,
    _unlockPreemption: *mut c_void,
) -> Fmi3Instance {
    let _ = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: NULL or NUL-terminated.
        let name = unsafe { text(instanceName) }.unwrap_or_else(|| "(NULL)".into());
        Logger::new_fmi3(logMessage, instanceEnvironment, &name, false).log(
            Status::Error,
            Category::StatusError,
            "fmi3InstantiateScheduledExecution: this FMU does not provide Scheduled Execution",
        );
    }));
    null_mut()
}

/// `fmi3FreeInstance` (FMI 3.0): frees the instance in any state (as
/// [`crate::fmi2::api::common::fmi2FreeInstance`], the same instance type). NULL or an
/// instance already freed is a no-op.
///
/// # Safety
/// `instance` is NULL or an instance of this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeInstance(instance: Fmi3Instance) {
    // SAFETY: same contract as the FMI 2.0 function (the same instance type).
    unsafe { crate::fmi2::api::common::fmi2FreeInstance(instance) }
}

/// `fmi3SetDebugLogging` (FMI 3.0): switches the named log categories on or off
/// (`loggingOn`), or all of them when `nCategories` is 0. Returns `fmi3Error` and changes
/// nothing for a NULL or unknown category name (the message lists the known ones).
///
/// # Safety
/// `categories` points to `nCategories` strings when `nCategories > 0`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetDebugLogging(
    instance: Fmi3Instance,
    loggingOn: Fmi3Boolean,
    nCategories: usize,
    categories: *const Fmi3String,
) -> Fmi3StatusC {
    call(instance, "fmi3SetDebugLogging", state::SET_DEBUG_LOGGING, |inst| {
        // SAFETY: per the contract.
        let cats = unsafe { slice(categories, nCategories, "categories[]") }?;
        let mut parsed = Vec::with_capacity(cats.len());
        for &p in cats {
            // SAFETY: each entry is NULL or a NUL-terminated string.
            let name = unsafe { text(p) }.ok_or(CallError::Null("a category name"))?;
            let known: Vec<&str> = Category::ALL.iter().map(|c| c.name()).collect();
            parsed.push(Category::from_name(&name).ok_or_else(|| CallError::UnknownCategory { name, known: known.join(", ") })?);
        }
        if parsed.is_empty() {
            inst.logger.set_all(loggingOn != 0);
        } else {
            for cat in parsed {
                inst.logger.set(cat, loggingOn != 0);
            }
        }
        Ok(Status::Ok)
    })
}

/// `fmi3EnterInitializationMode` (FMI 3.0): records the start time (s) and, when
/// `stopTimeDefined`, the stop time (s) (the tolerance is ignored), then enters
/// initialization mode. Returns `fmi3Error`, nothing changed, for a non-finite time or a stop
/// time before the start time.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterInitializationMode(
    instance: Fmi3Instance,
    _toleranceDefined: Fmi3Boolean,
    _tolerance: f64,
    startTime: f64,
    stopTimeDefined: Fmi3Boolean,
    stopTime: f64,
) -> Fmi3StatusC {
    call(instance, "fmi3EnterInitializationMode", state::ENTER_INITIALIZATION_MODE, |inst| {
        inst.setup_experiment(startTime, (stopTimeDefined != 0).then_some(stopTime))?;
        inst.enter_initialization_mode()
    })
}

/// `fmi3ExitInitializationMode` (FMI 3.0): lets the model validate its parameters
/// and compute its first outputs, then enters step mode (Co-Simulation) or event mode (Model
/// Exchange). A rejected parameter or an output out of range is `fmi3Error` and puts the
/// instance in the error state.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3ExitInitializationMode(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3ExitInitializationMode", state::EXIT_INITIALIZATION_MODE, Instance::exit_initialization_mode)
}

/// `fmi3EnterEventMode` (FMI 3.0): Model Exchange only (this Co-Simulation has no
/// event mode): to event mode. `fmi3Error` on a Co-Simulation instance.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterEventMode(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3EnterEventMode", state::ENTER_EVENT_MODE, Instance::enter_event_mode)
}

/// `fmi3Terminate` (FMI 3.0): ends the simulation run; afterwards only getters,
/// FMU state functions, `fmi3Reset` and `fmi3FreeInstance` are allowed.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3Terminate(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3Terminate", state::TERMINATE, Instance::terminate)
}

/// `fmi3Reset` (FMI 3.0): returns the instance to the state right after
/// instantiation, every variable at its start value, time 0.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3Reset(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3Reset", state::RESET, Instance::reset)
}

/// All variables are scalars: one value per value reference.
fn check_n_values(nvr: usize, n_values: usize) -> Result<(), CallError> {
    if nvr != n_values {
        return Err(CallError::NotScalar { nvr, n_values });
    }
    Ok(())
}

/// Get values of `kind` as f64 and convert each with `to`.
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
unsafe fn get_as<T>(
    inst: &mut Instance,
    kind: Kind,
    vr: *const u32,
    nvr: usize,
    values: *mut T,
    n_values: usize,
    to: impl Fn(f64) -> T,
) -> CallResult {
    check_n_values(nvr, n_values)?;
    // SAFETY: per the contract.
    let (vrs, out) = unsafe { (slice(vr, nvr, "valueReferences[]")?, slice_mut(values, n_values, "values[]")?) };
    let mut vals = vec![0.0; vrs.len()];
    let status = inst.get_values(kind, vrs, &mut vals)?;
    for (o, v) in out.iter_mut().zip(vals) {
        *o = to(v);
    }
    Ok(status)
}

/// Set values of `kind`, converting each with `from` (checked: an out-of-range Int64 is refused).
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
unsafe fn set_as<T: Copy>(
    inst: &mut Instance,
    kind: Kind,
    vr: *const u32,
    nvr: usize,
    values: *const T,
    n_values: usize,
    from: impl Fn(T) -> Result<f64, CallError>,
) -> CallResult {
    check_n_values(nvr, n_values)?;
    // SAFETY: per the contract.
    let (vrs, vals) = unsafe { (slice(vr, nvr, "valueReferences[]")?, slice(values, n_values, "values[]")?) };
    let vals: Vec<f64> = vals.iter().map(|&v| from(v)).collect::<Result<_, _>>()?;
    inst.set_values(kind, vrs, &vals)
}

macro_rules! typed {
    ($get:ident, $set:ident, $tname:literal, $t:ty, $kind:expr, $to:expr, $from:expr) => {
        #[doc = concat!("`", stringify!($get), "` (FMI 3.0): writes the values of the ", $tname,
            " variables `valueReferences[0..nValueReferences]` into `values` (`nValues` must equal ",
            "`nValueReferences`: all scalars). Returns `fmi3Error` for an unknown value reference or ",
            "one of another type.")]
        ///
        /// # Safety
        /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut $t, nValues: usize) -> Fmi3StatusC {
            call(instance, stringify!($get), state::GET_VALUE, |inst| {
                // SAFETY: per the contract.
                unsafe { get_as(inst, $kind, valueReferences, nValueReferences, values, nValues, $to) }
            })
        }
        #[doc = concat!("`", stringify!($set), "` (FMI 3.0): sets the ", $tname,
            " variables `valueReferences[0..nValueReferences]`. Every value is checked before any ",
            "is stored, so a call that returns `fmi3Error` changes nothing.")]
        ///
        /// # Safety
        /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const $t, nValues: usize) -> Fmi3StatusC {
            call(instance, stringify!($set), state::SET_VALUE, |inst| {
                // SAFETY: per the contract.
                unsafe { set_as(inst, $kind, valueReferences, nValueReferences, values, nValues, $from) }
            })
        }
    };
}

/// `fmi3SetFloat64` (FMI 3.0): sets the Float64 (FMI 2.0 Real) variables
/// `valueReferences[0..nValueReferences]`. Every value is checked (variability and causality
/// for the current state, the model's range check) before any is stored, so a call that
/// returns `fmi3Error` changes nothing; `nValues` must equal `nValueReferences` (all scalars).
///
/// # Safety
/// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFloat64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const f64, nValues: usize) -> Fmi3StatusC {
    call(instance, "fmi3SetFloat64", state::SET_VALUE, |inst| {
        // SAFETY: per the contract.
        unsafe { set_as(inst, Kind::Real, valueReferences, nValueReferences, values, nValues, Ok) }
    })
}

/// `fmi3GetFloat64` (FMI 3.0): writes the values of the Float64 variables into
/// `values` (outputs at the current inputs, in the units of the modelDescription); the
/// independent variable `time` (value reference [`super::xml::TIME_VR`]) reads the instance's
/// time in s. Returns `fmi3Error` for an unknown or non-Float64 value reference, `nValues`
/// ≠ `nValueReferences`, or a model failure computing the outputs.
///
/// # Safety
/// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFloat64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut f64, nValues: usize) -> Fmi3StatusC {
    call(instance, "fmi3GetFloat64", state::GET_VALUE, |inst| {
        check_n_values(nValueReferences, nValues)?;
        // SAFETY: per the contract.
        let (vrs, out) = unsafe { (slice(valueReferences, nValueReferences, "valueReferences[]")?, slice_mut(values, nValues, "values[]")?) };
        let time_vr = super::xml::TIME_VR;
        if !vrs.contains(&time_vr) || inst.info.index_of(time_vr).is_some() {
            return inst.get_values(Kind::Real, vrs, out);
        }
        let others: Vec<u32> = vrs.iter().copied().filter(|&v| v != time_vr).collect();
        let mut vals = vec![0.0; others.len()];
        inst.get_values(Kind::Real, &others, &mut vals)?;
        let mut it = vals.into_iter();
        for (o, &vr) in out.iter_mut().zip(vrs) {
            *o = if vr == time_vr { inst.time } else { it.next().unwrap_or(f64::NAN) };
        }
        Ok(Status::Ok)
    })
}
typed!(fmi3GetInt32, fmi3SetInt32, "Int32 (FMI 2.0 Integer)", i32, Kind::Integer, |v| v as i32, |v: i32| Ok(f64::from(v)));
typed!(fmi3GetInt64, fmi3SetInt64, "Enumeration (accessed as Int64)", i64, Kind::Enumeration(&ANY_ENUMERATION), |v| v as i64, |v: i64| {
    // Enumeration codes are small; anything beyond i32 is no item of any type here.
    i32::try_from(v).map(f64::from).map_err(|_| CallError::NotAnEnumerationItem(v))
});
typed!(fmi3GetBoolean, fmi3SetBoolean, "Boolean (any non-zero byte is true)", u8, Kind::Boolean, |v| u8::from(v != 0.0), |v: u8| Ok(if v != 0 { 1.0 } else { 0.0 }));

macro_rules! no_such_type {
    ($get:ident, $set:ident, $t:ty, $name:literal) => {
        #[doc = concat!("`", stringify!($get), "` (FMI 3.0): this FMU has no ", $name,
            " variables; every value reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).")]
        ///
        /// # Safety
        /// `valueReferences` points to `nValueReferences` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, _values: *mut $t, _nValues: usize) -> Fmi3StatusC {
            call(instance, stringify!($get), state::GET_VALUE, |inst| {
                // SAFETY: per the contract.
                let vrs = unsafe { slice(valueReferences, nValueReferences, "valueReferences[]")? };
                inst.reject_type($name, vrs)
            })
        }
        #[doc = concat!("`", stringify!($set), "` (FMI 3.0): this FMU has no ", $name,
            " variables; every value reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).")]
        ///
        /// # Safety
        /// `valueReferences` points to `nValueReferences` elements.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, _values: *const $t, _nValues: usize) -> Fmi3StatusC {
            call(instance, stringify!($set), state::SET_VALUE, |inst| {
                // SAFETY: per the contract.
                let vrs = unsafe { slice(valueReferences, nValueReferences, "valueReferences[]")? };
                inst.reject_type($name, vrs)
            })
        }
    };
}

no_such_type!(fmi3GetFloat32, fmi3SetFloat32, f32, "Float32");
no_such_type!(fmi3GetInt8, fmi3SetInt8, i8, "Int8");
no_such_type!(fmi3GetUInt8, fmi3SetUInt8, u8, "UInt8");
no_such_type!(fmi3GetInt16, fmi3SetInt16, i16, "Int16");
no_such_type!(fmi3GetUInt16, fmi3SetUInt16, u16, "UInt16");
no_such_type!(fmi3GetUInt32, fmi3SetUInt32, u32, "UInt32");
no_such_type!(fmi3GetUInt64, fmi3SetUInt64, u64, "UInt64");
no_such_type!(fmi3GetString, fmi3SetString, Fmi3String, "String");

/// `fmi3GetBinary` (FMI 3.0): this FMU has no Binary variables; every value
/// reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).
///
/// # Safety
/// `valueReferences` points to `nValueReferences` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetBinary(
    instance: Fmi3Instance,
    valueReferences: *const u32,
    nValueReferences: usize,
    _valueSizes: *mut usize,
    _values: *mut *const u8,
    _nValues: usize,
) -> Fmi3StatusC {
    call(instance, "fmi3GetBinary", state::GET_VALUE, |inst| {
        // SAFETY: per the contract.
        let vrs = unsafe { slice(valueReferences, nValueReferences, "valueReferences[]")? };
        inst.reject_type("Binary", vrs)
    })
}

/// `fmi3SetBinary` (FMI 3.0): this FMU has no Binary variables; every value
/// reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).
///
/// # Safety
/// `valueReferences` points to `nValueReferences` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetBinary(
    instance: Fmi3Instance,
    valueReferences: *const u32,
    nValueReferences: usize,
    _valueSizes: *const usize,
    _values: *const *const u8,
    _nValues: usize,
) -> Fmi3StatusC {
    call(instance, "fmi3SetBinary", state::SET_VALUE, |inst| {
        // SAFETY: per the contract.
        let vrs = unsafe { slice(valueReferences, nValueReferences, "valueReferences[]")? };
        inst.reject_type("Binary", vrs)
    })
}

fn no_clocks(instance: Fmi3Instance, name: &'static str) -> Fmi3StatusC {
    call(instance, name, state::RESET, |_| Err(CallError::Unsupported("this FMU has no clocks")))
}

/// `fmi3GetClock` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetClock(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _values: *mut u8) -> Fmi3StatusC {
    no_clocks(instance, "fmi3GetClock")
}
/// `fmi3SetClock` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetClock(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _values: *const u8) -> Fmi3StatusC {
    no_clocks(instance, "fmi3SetClock")
}
/// `fmi3GetIntervalDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetIntervalDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _intervals: *mut f64, _qualifiers: *mut c_int) -> Fmi3StatusC {
    no_clocks(instance, "fmi3GetIntervalDecimal")
}
/// `fmi3GetIntervalFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetIntervalFraction(
    instance: Fmi3Instance,
    _vr: *const u32,
    _nvr: usize,
    _counters: *mut u64,
    _resolutions: *mut u64,
    _qualifiers: *mut c_int,
) -> Fmi3StatusC {
    no_clocks(instance, "fmi3GetIntervalFraction")
}
/// `fmi3GetShiftDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetShiftDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _shifts: *mut f64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3GetShiftDecimal")
}
/// `fmi3GetShiftFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetShiftFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *mut u64, _resolutions: *mut u64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3GetShiftFraction")
}
/// `fmi3SetIntervalDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetIntervalDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _intervals: *const f64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3SetIntervalDecimal")
}
/// `fmi3SetIntervalFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetIntervalFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3SetIntervalFraction")
}
/// `fmi3SetShiftDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetShiftDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _shifts: *const f64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3SetShiftDecimal")
}
/// `fmi3SetShiftFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetShiftFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3SetShiftFraction")
}
/// `fmi3ActivateModelPartition` (FMI 3.0): no Scheduled Execution; always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3ActivateModelPartition(instance: Fmi3Instance, _clockReference: u32, _activationTime: f64) -> Fmi3StatusC {
    no_clocks(instance, "fmi3ActivateModelPartition")
}

/// `fmi3GetNumberOfVariableDependencies` (FMI 3.0): writes to `*nDependencies`
/// the number of inputs `valueReference` depends on directly (an output: its ModelStructure
/// dependencies; any other variable: 0). `fmi3Error` for an unknown value reference or a NULL
/// `nDependencies`.
///
/// # Safety
/// `nDependencies` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetNumberOfVariableDependencies(instance: Fmi3Instance, valueReference: u32, nDependencies: *mut usize) -> Fmi3StatusC {
    call(instance, "fmi3GetNumberOfVariableDependencies", state::RESET, |inst| {
        let deps = dependencies(inst, valueReference)?;
        if nDependencies.is_null() {
            return Err(CallError::Null("nDependencies"));
        }
        // SAFETY: non-NULL and writable per the contract.
        unsafe { *nDependencies = deps.len() };
        Ok(Status::Ok)
    })
}

/// The value references an output depends on directly (all scalar: element index 0, kind
/// `fmi3Dependent`).
fn dependencies(inst: &Instance, vr: u32) -> Result<Vec<u32>, CallError> {
    let info = inst.info;
    let i = info.index_of(vr).ok_or(CallError::UnknownDependent(vr))?;
    let v = &info.variables[i];
    if v.causality != Causality::Output {
        return Ok(vec![]);
    }
    v.depends_on
        .iter()
        .map(|n| info.index_by_name(n).map(|j| info.variables[j].value_reference).ok_or_else(|| CallError::UnknownInput { output: v.name.clone(), name: n }))
        .collect()
}

/// `fmi3GetVariableDependencies` (FMI 3.0): writes the direct dependencies of
/// `dependent` (value references of the inputs, element index 0, kind `fmi3Dependent`).
/// `fmi3Error` when `nDependencies` differs from what
/// [`fmi3GetNumberOfVariableDependencies`] reports, or an array is NULL.
///
/// # Safety
/// The four arrays hold `nDependencies` writable elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetVariableDependencies(
    instance: Fmi3Instance,
    dependent: u32,
    elementIndicesOfDependent: *mut usize,
    independents: *mut u32,
    elementIndicesOfIndependents: *mut usize,
    dependencyKinds: *mut c_int,
    nDependencies: usize,
) -> Fmi3StatusC {
    call(instance, "fmi3GetVariableDependencies", state::RESET, |inst| {
        let deps = dependencies(inst, dependent)?;
        if deps.len() != nDependencies {
            return Err(CallError::DependencyCount { given: nDependencies, vr: dependent, actual: deps.len() });
        }
        // SAFETY: per the contract.
        let (a, b, c, d) = unsafe {
            (
                slice_mut(elementIndicesOfDependent, nDependencies, "elementIndicesOfDependent[]")?,
                slice_mut(independents, nDependencies, "independents[]")?,
                slice_mut(elementIndicesOfIndependents, nDependencies, "elementIndicesOfIndependents[]")?,
                slice_mut(dependencyKinds, nDependencies, "dependencyKinds[]")?,
            )
        };
        for (k, vr) in deps.into_iter().enumerate() {
            (a[k], b[k], c[k], d[k]) = (0, vr, 0, FMI3_DEPENDENT);
        }
        Ok(Status::Ok)
    })
}

/// `fmi3GetFMUState` (FMI 3.0): saves the instance's complete state into
/// `*FMUState`, as [`crate::fmi2::api::common::fmi2GetFMUstate`] (the same FMU state type).
///
/// # Safety
/// As `fmi2GetFMUstate`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { get_fmu_state("fmi3GetFMUState", instance, FMUState) }
}
/// `fmi3SetFMUState` (FMI 3.0): restores the instance to `FMUState`, as
/// [`crate::fmi2::api::common::fmi2SetFMUstate`]; `fmi3Error`, nothing changed, for a dead
/// or foreign state.
///
/// # Safety
/// As `fmi2SetFMUstate`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SetFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { set_fmu_state("fmi3SetFMUState", instance, FMUState) }
}
/// `fmi3FreeFMUState` (FMI 3.0): frees `*FMUState` and sets it to NULL, as
/// [`crate::fmi2::api::common::fmi2FreeFMUstate`].
///
/// # Safety
/// As `fmi2FreeFMUstate`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { free_fmu_state("fmi3FreeFMUState", instance, FMUState) }
}
/// `fmi3SerializedFMUStateSize` (FMI 3.0): writes to `*size` the length in bytes
/// of `FMUState` serialized, as [`crate::fmi2::api::common::fmi2SerializedFMUstateSize`].
///
/// # Safety
/// As `fmi2SerializedFMUstateSize`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializedFMUStateSize(instance: Fmi3Instance, FMUState: Fmi3FmuState, size: *mut usize) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { serialized_fmu_state_size("fmi3SerializedFMUStateSize", instance, FMUState, size) }
}
/// `fmi3SerializeFMUState` (FMI 3.0): writes `FMUState` serialized into
/// `serializedState` (the same bytes as through FMI 2.0), as
/// [`crate::fmi2::api::common::fmi2SerializeFMUstate`]; `fmi3Error` when `size` is wrong.
///
/// # Safety
/// As `fmi2SerializeFMUstate`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3SerializeFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState, serializedState: *mut Fmi3Byte, size: usize) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { serialize_fmu_state("fmi3SerializeFMUState", instance, FMUState, serializedState as *mut c_char, size) }
}
/// `fmi3DeserializeFMUState` (FMI 3.0): decodes `serializedState` (written
/// through FMI 3.0 or 2.0 for this model) into `*FMUState`, as
/// [`crate::fmi2::api::common::fmi2DeSerializeFMUstate`]; `fmi3Error`, nothing changed, for
/// bytes of another model or version, a wrong length or a CRC mismatch.
///
/// # Safety
/// As `fmi2DeSerializeFMUstate`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3DeserializeFMUState(
    instance: Fmi3Instance,
    serializedState: *const Fmi3Byte,
    size: usize,
    FMUState: *mut Fmi3FmuState,
) -> Fmi3StatusC {
    // SAFETY: same contract.
    unsafe { deserialize_fmu_state("fmi3DeserializeFMUState", instance, serializedState as *const c_char, size, FMUState) }
}

fn refuse(instance: Fmi3Instance, name: &'static str, why: &'static str) -> Fmi3StatusC {
    call(instance, name, state::RESET, |_| Err(CallError::Unsupported(why)))
}

/// `fmi3GetDirectionalDerivative` (FMI 3.0): not provided
/// (`providesDirectionalDerivatives = false`); always `fmi3Error`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3GetDirectionalDerivative(
    instance: Fmi3Instance,
    _unknowns: *const u32,
    _nUnknowns: usize,
    _knowns: *const u32,
    _nKnowns: usize,
    _seed: *const f64,
    _nSeed: usize,
    _sensitivity: *mut f64,
    _nSensitivity: usize,
) -> Fmi3StatusC {
    refuse(instance, "fmi3GetDirectionalDerivative", "directional derivatives are not provided (providesDirectionalDerivatives = false)")
}
/// `fmi3GetAdjointDerivative` (FMI 3.0): not provided
/// (`providesAdjointDerivatives = false`); always `fmi3Error`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn fmi3GetAdjointDerivative(
    instance: Fmi3Instance,
    _unknowns: *const u32,
    _nUnknowns: usize,
    _knowns: *const u32,
    _nKnowns: usize,
    _seed: *const f64,
    _nSeed: usize,
    _sensitivity: *mut f64,
    _nSensitivity: usize,
) -> Fmi3StatusC {
    refuse(instance, "fmi3GetAdjointDerivative", "adjoint derivatives are not provided (providesAdjointDerivatives = false)")
}
/// `fmi3EnterConfigurationMode` (FMI 3.0): this FMU has no structural parameters;
/// always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterConfigurationMode(instance: Fmi3Instance) -> Fmi3StatusC {
    refuse(instance, "fmi3EnterConfigurationMode", "this FMU has no structural parameters (no configuration mode)")
}
/// `fmi3ExitConfigurationMode` (FMI 3.0): this FMU has no structural parameters;
/// always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3ExitConfigurationMode(instance: Fmi3Instance) -> Fmi3StatusC {
    refuse(instance, "fmi3ExitConfigurationMode", "this FMU has no structural parameters (no configuration mode)")
}
/// `fmi3EvaluateDiscreteStates` (FMI 3.0): not provided
/// (`providesEvaluateDiscreteStates = false`); always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EvaluateDiscreteStates(instance: Fmi3Instance) -> Fmi3StatusC {
    refuse(instance, "fmi3EvaluateDiscreteStates", "not provided (providesEvaluateDiscreteStates = false)")
}

/// Writes `v` through `p` if `p` is not NULL.
///
/// # Safety
/// `p` is NULL or writable.
unsafe fn put<T>(p: *mut T, v: T) {
    if !p.is_null() {
        // SAFETY: per the contract.
        unsafe { *p = v };
    }
}

/// `fmi3UpdateDiscreteStates` (FMI 3.0): the Model Exchange event iteration.
/// Checks the outputs at the current inputs (a model failure is `fmi3Error`), then reports
/// nothing discrete to update, no termination, no time event: every non-NULL flag false.
///
/// # Safety
/// Each pointer is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3UpdateDiscreteStates(
    instance: Fmi3Instance,
    discreteStatesNeedUpdate: *mut Fmi3Boolean,
    terminateSimulation: *mut Fmi3Boolean,
    nominalsOfContinuousStatesChanged: *mut Fmi3Boolean,
    valuesOfContinuousStatesChanged: *mut Fmi3Boolean,
    nextEventTimeDefined: *mut Fmi3Boolean,
    nextEventTime: *mut f64,
) -> Fmi3StatusC {
    call(instance, "fmi3UpdateDiscreteStates", state::NEW_DISCRETE_STATES, |inst| {
        inst.require_model_exchange()?;
        inst.refresh_outputs()?;
        // SAFETY: per the contract.
        unsafe {
            for p in [discreteStatesNeedUpdate, terminateSimulation, nominalsOfContinuousStatesChanged, valuesOfContinuousStatesChanged, nextEventTimeDefined] {
                put(p, 0);
            }
            put(nextEventTime, 0.0);
        }
        Ok(Status::Ok)
    })
}

/// `fmi3EnterContinuousTimeMode` (FMI 3.0): Model Exchange, from event mode to
/// continuous-time mode; `fmi3Error` on a Co-Simulation instance.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterContinuousTimeMode(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3EnterContinuousTimeMode", state::ENTER_CONTINUOUS_TIME_MODE, Instance::enter_continuous_time_mode)
}

/// `fmi3CompletedIntegratorStep` (FMI 3.0): checks the outputs at the current
/// inputs (a model failure is `fmi3Error`); never asks for an event or termination (both
/// flags false where non-NULL).
///
/// # Safety
/// `enterEventMode` and `terminateSimulation` are NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3CompletedIntegratorStep(
    instance: Fmi3Instance,
    _noSetFMUStatePriorToCurrentPoint: Fmi3Boolean,
    enterEventMode: *mut Fmi3Boolean,
    terminateSimulation: *mut Fmi3Boolean,
) -> Fmi3StatusC {
    call(instance, "fmi3CompletedIntegratorStep", state::COMPLETED_INTEGRATOR_STEP, |inst| {
        inst.require_model_exchange()?;
        inst.refresh_outputs()?;
        // SAFETY: per the contract.
        unsafe {
            put(enterEventMode, 0);
            put(terminateSimulation, 0);
        }
        Ok(Status::Ok)
    })
}

/// `fmi3SetTime` (FMI 3.0): Model Exchange, records the host's solver time `time`
/// in s (the outputs depend on the inputs only); `fmi3Error` for a non-finite time or on a
/// Co-Simulation instance.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3SetTime(instance: Fmi3Instance, time: f64) -> Fmi3StatusC {
    call(instance, "fmi3SetTime", state::SET_TIME, |inst| {
        inst.require_model_exchange()?;
        inst.set_time(time)
    })
}

macro_rules! no_states {
    ($name:ident, $mask:expr, $what:literal, $t:ty) => {
        #[doc = concat!("`", stringify!($name), "` (FMI 3.0, Model Exchange): this FMU has no continuous ",
            "states and no event indicators, so `", $what, "` must be 0 (then `fmi3OK`, nothing ",
            "read or written); `fmi3Error` otherwise or on a Co-Simulation instance.")]
        #[unsafe(no_mangle)]
        pub extern "C" fn $name(instance: Fmi3Instance, _values: $t, n: usize) -> Fmi3StatusC {
            call(instance, stringify!($name), $mask, |inst| inst.require_none($what, n).map(|_| Status::Ok))
        }
    };
}

no_states!(fmi3SetContinuousStates, state::SET_CONTINUOUS_STATES, "nContinuousStates", *const f64);
no_states!(fmi3GetContinuousStateDerivatives, state::GET_DERIVATIVES, "nContinuousStates", *mut f64);
no_states!(fmi3GetEventIndicators, state::GET_DERIVATIVES, "nEventIndicators", *mut f64);
no_states!(fmi3GetContinuousStates, state::GET_CONTINUOUS_STATES, "nContinuousStates", *mut f64);
no_states!(fmi3GetNominalsOfContinuousStates, state::GET_CONTINUOUS_STATES, "nContinuousStates", *mut f64);

/// `fmi3GetNumberOfEventIndicators` (FMI 3.0): writes 0 to `*nEventIndicators`
/// (this FMU has no event indicators); `fmi3Error` if it is NULL.
///
/// # Safety
/// `nEventIndicators` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetNumberOfEventIndicators(instance: Fmi3Instance, nEventIndicators: *mut usize) -> Fmi3StatusC {
    call(instance, "fmi3GetNumberOfEventIndicators", state::RESET, |_| {
        if nEventIndicators.is_null() {
            return Err(CallError::Null("nEventIndicators"));
        }
        // SAFETY: non-NULL, writable.
        unsafe { *nEventIndicators = 0 };
        Ok(Status::Ok)
    })
}

/// `fmi3GetNumberOfContinuousStates` (FMI 3.0): writes 0 to `*nContinuousStates`
/// (this FMU has no continuous states); `fmi3Error` if it is NULL.
///
/// # Safety
/// `nContinuousStates` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3GetNumberOfContinuousStates(instance: Fmi3Instance, nContinuousStates: *mut usize) -> Fmi3StatusC {
    call(instance, "fmi3GetNumberOfContinuousStates", state::RESET, |_| {
        if nContinuousStates.is_null() {
            return Err(CallError::Null("nContinuousStates"));
        }
        // SAFETY: non-NULL, writable.
        unsafe { *nContinuousStates = 0 };
        Ok(Status::Ok)
    })
}

/// `fmi3EnterStepMode` (FMI 3.0): only allowed after event mode, which this
/// Co-Simulation never enters (`hasEventMode = false`); always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3EnterStepMode(instance: Fmi3Instance) -> Fmi3StatusC {
    call(instance, "fmi3EnterStepMode", state::ENTER_STEP_MODE, |_| {
        Err(CallError::Unsupported("this FMU's Co-Simulation has no event mode (hasEventMode = false), so there is no step mode to return to"))
    })
}

/// `fmi3GetOutputDerivatives` (FMI 3.0): not provided
/// (`maxOutputDerivativeOrder = 0`); always `fmi3Error`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi3GetOutputDerivatives(
    instance: Fmi3Instance,
    _vr: *const u32,
    _nvr: usize,
    _orders: *const i32,
    _values: *mut f64,
    _nValues: usize,
) -> Fmi3StatusC {
    refuse(instance, "fmi3GetOutputDerivatives", "output derivatives are not provided (maxOutputDerivativeOrder = 0)")
}

/// `fmi3DoStep` (FMI 3.0): one communication step from `currentCommunicationPoint`
/// over `communicationStepSize` (s), as [`crate::fmi2::api::cosim::fmi2DoStep`]. Never returns
/// early, never asks for event handling or termination; `*lastSuccessfulTime` is the end of
/// the step (or, after a failed step, the end of the last good one), in s. `fmi3Error` for a
/// step that is not positive or does not continue the last one, or that the model fails.
///
/// # Safety
/// The four output pointers are NULL or writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn fmi3DoStep(
    instance: Fmi3Instance,
    currentCommunicationPoint: f64,
    communicationStepSize: f64,
    _noSetFMUStatePriorToCurrentPoint: Fmi3Boolean,
    eventHandlingNeeded: *mut Fmi3Boolean,
    terminateSimulation: *mut Fmi3Boolean,
    earlyReturn: *mut Fmi3Boolean,
    lastSuccessfulTime: *mut f64,
) -> Fmi3StatusC {
    call(instance, "fmi3DoStep", state::DO_STEP, |inst| {
        let r = inst.do_step(currentCommunicationPoint, communicationStepSize);
        // SAFETY: per the contract.
        unsafe {
            put(eventHandlingNeeded, 0);
            put(terminateSimulation, 0);
            put(earlyReturn, 0);
            put(lastSuccessfulTime, inst.time);
        }
        r
    })
}
