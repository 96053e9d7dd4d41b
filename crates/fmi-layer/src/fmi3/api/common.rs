//! The FMI 3.0 functions common to Model Exchange and Co-Simulation: version, instantiation
//! bodies, freeing, debug logging, initialization, the typed getters and setters, variable
//! dependencies and directional derivatives. Each goes through the core's guard
//! ([`crate::core::guard`]): NULL or dead instance, the state mask, error logging, panic
//! containment (a panic returns `fmi3Fatal`).
//!
//! Unsupported parts of the standard (clocks, scheduled execution, configuration mode,
//! adjoint derivatives, output derivatives, Float32/8-/16-bit/unsigned/String/
//! Binary variables) are refused with a message naming why.

#![allow(non_snake_case)]

use super::super::types::*;
use crate::core::guard::{guarded, maybe_forced_panic, refuse, slice, slice_mut, write_out};
use crate::core::state::{Mask, State, ENTER_INITIALIZATION_MODE, EXIT_INITIALIZATION_MODE, GET_VALUE, RESET, SET_DEBUG_LOGGING, SET_VALUE, TERMINATE};
use crate::core::instance::{CallResult, Instance, Interface, Rules};
use crate::core::instantiate::{free_instance, instance_name_checked, looks_like_uri, model_of, refuse_instance, set_debug_logging, text};
use crate::core::logging::{c_text, Category, HostLog, Logger};
use crate::core::types::Status;
use crate::core::values::{check_n_values, get_as, reject_as, set_as, Arrays};
use crate::core::variables::{Causality, EnumType, Kind, ModelInfo};
use crate::error::CallError;
use std::ffi::{c_char, c_int, c_void, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;
use std::rc::Rc;

/// `fmi3GetDirectionalDerivative`, whose states FMI 3.0 defines its own way (state machine,
/// §3.2 and §4.2): initialization mode, event mode, continuous-time mode, step mode
/// (`stepComplete`) and terminated. The functions both standards have use the core's masks
/// (`crate::core::state`).
const GET_DIRECTIONAL_DERIVATIVE: Mask =
    Mask::of(&[State::InitializationMode, State::EventMode, State::ContinuousTimeMode, State::StepComplete, State::Terminated]);

/// FMI 3.0's names of the arrays of a get/set call (`valueReferences[]`, `values[]`, with
/// `nValues` given separately).
const ARRAYS: Arrays = Arrays { vr: "valueReferences[]", values: "values[]", check_unused_values: false };

/// Whether a variable of kind `variable` is read and written by the FMI 3.0 getter/setter of
/// `requested`: each kind through its own functions only (Real as Float64, Integer as Int32,
/// Enumeration as Int64, Boolean as Boolean).
pub fn accessed_as(variable: Kind, requested: Kind) -> bool {
    std::mem::discriminant(&variable) == std::mem::discriminant(&requested)
}

/// What FMI 3.0 defines its own way for an instance it creates.
pub static RULES: Rules = Rules {
    accessed_as,
    no_directional_derivatives: "directional derivatives are not provided (providesDirectionalDerivatives = false)",
};

/// The host's `fmi3LogMessageCallback` with its `instanceEnvironment`. FMI 3.0 messages carry
/// no instance name, so it is prefixed to each message.
#[derive(Debug)]
struct Fmi3Log {
    callback: Fmi3LogMessageCallback,
    env: *mut c_void,
}

impl HostLog for Fmi3Log {
    fn emit(&self, instance_name: &CStr, status: Status, category: &CStr, message: &str) {
        let msg = c_text(&format!("[{}] {message}", crate::fmt::excerpt(&instance_name.to_string_lossy())));
        // SAFETY: non-NULL callback from the host; the strings outlive the call.
        unsafe { (self.callback)(self.env, status.c(), category.as_ptr(), msg.as_ptr()) }
    }
}

/// The logger of an FMI 3.0 instance (`logMessage` may be NULL: then nothing is logged).
fn logger(log_message: Option<Fmi3LogMessageCallback>, env: *mut c_void, instance_name: &str, logging_on: bool) -> Logger {
    let sink = log_message.map(|callback| Rc::new(Fmi3Log { callback, env }) as Rc<dyn HostLog>);
    Logger::new(sink, instance_name, logging_on)
}

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
        let logger = logger(log_message, env, name.as_deref().unwrap_or("(NULL)"), logging_on != 0);
        let func = match interface {
            Interface::CoSimulation => "fmi3InstantiateCoSimulation",
            Interface::ModelExchange => "fmi3InstantiateModelExchange",
        };
        maybe_forced_panic(func);
        let checked = instance_name_checked(name).and_then(|name| {
            let (info, token) = model_of(registry, token, "instantiationToken")?;
            if interface == Interface::ModelExchange && !info.model_exchange {
                return Err(CallError::CoSimulationOnly { model: info.model_name, asked: "", offered: "" });
            }
            if event_mode_used != 0 {
                return Err(CallError::EventModeUsed);
            }
            Ok((name, info, token))
        });
        let (name, info, token) = match checked {
            Ok(c) => c,
            Err(e) => return refuse_instance(&logger, func, &e),
        };
        // This FMU needs no resources: NULL or "" is fine; a path that is not absolute is a warning.
        if let Some(r) = resources.as_deref().filter(|r| !r.is_empty() && !r.starts_with('/') && !looks_like_uri(r) && !r.contains('\\')) {
            logger.log(
                Status::Warning,
                Category::StatusWarning,
                &format!("{func}: resourcePath '{r}' is not an absolute path; this FMU needs no resources, continuing"),
            );
        }
        let inst = Instance::with_interface(info, &name, logger, interface, &RULES);
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
        logger(logMessage, instanceEnvironment, &name, false).log(
            Status::Error,
            Category::StatusError,
            "fmi3InstantiateScheduledExecution: this FMU does not provide Scheduled Execution",
        );
    }));
    null_mut()
}

/// `fmi3FreeInstance` (FMI 3.0): frees the instance in any state (the `fatal` one included)
/// and everything it owns. NULL or an instance already freed is a no-op; a panic during the
/// release is contained.
///
/// # Safety
/// `instance` is NULL or an instance of this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi3FreeInstance(instance: Fmi3Instance) {
    // SAFETY: forwarded under the same contract.
    unsafe { free_instance(instance) }
}


/// The body of `fmi3GetFloat64`: as the other getters, but the independent variable `time`
/// (value reference [`crate::fmi3::xml::TIME_VR`], not in the model's table) reads the instance's time.
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
unsafe fn get_float64(inst: &mut Instance, vr: *const u32, nvr: usize, values: *mut f64, n_values: usize) -> CallResult {
    check_n_values(nvr, n_values)?;
    // SAFETY: per the contract.
    let (vrs, out) = unsafe { (slice(vr, nvr, "valueReferences[]")?, slice_mut(values, n_values, "values[]")?) };
    let time_vr = crate::fmi3::xml::TIME_VR;
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
}

/// Int64 values are Enumeration codes: anything beyond i32 is no item of any type here.
fn enumeration_code(v: i64) -> Result<f64, CallError> {
    i32::try_from(v).map(f64::from).map_err(|_| CallError::NotAnEnumerationItem(v))
}

/// The value references an output or a state derivative depends on directly (its
/// ModelStructure `dependencies`, FMI 3.0 §2.4.8; all scalar: element index 0, kind
/// `fmi3Dependent`); none for any other variable.
fn dependencies(inst: &Instance, vr: u32) -> Result<Vec<u32>, CallError> {
    let info = inst.info;
    let i = info.index_of(vr).ok_or(CallError::UnknownDependent(vr))?;
    let v = &info.variables[i];
    if v.causality != Causality::Output && v.derivative_of.is_none() {
        return Ok(vec![]);
    }
    v.depends_on
        .iter()
        .map(|&n| info.index_by_name(n).map(|j| info.variables[j].value_reference).ok_or_else(|| CallError::UnknownInput { output: v.name.clone(), name: n }))
        .collect()
}

/// The body of `fmi3GetVariableDependencies`.
///
/// # Safety
/// The four arrays hold `n` writable elements.
unsafe fn variable_dependencies(inst: &Instance, dependent: u32, arrays: (*mut usize, *mut u32, *mut usize, *mut c_int), n: usize) -> CallResult {
    let deps = dependencies(inst, dependent)?;
    if deps.len() != n {
        return Err(CallError::DependencyCount { given: n, vr: dependent, actual: deps.len() });
    }
    // SAFETY: per the contract.
    let (a, b, c, d) = unsafe {
        (
            slice_mut(arrays.0, n, "elementIndicesOfDependent[]")?,
            slice_mut(arrays.1, n, "independents[]")?,
            slice_mut(arrays.2, n, "elementIndicesOfIndependents[]")?,
            slice_mut(arrays.3, n, "dependencyKinds[]")?,
        )
    };
    for (k, vr) in deps.into_iter().enumerate() {
        (a[k], b[k], c[k], d[k]) = (0, vr, 0, FMI3_DEPENDENT);
    }
    Ok(Status::Ok)
}

/// The reason of every clock function.
const NO_CLOCKS: &str = "this FMU has no clocks";
/// The reason of both configuration-mode functions.
const NO_CONFIGURATION: &str = "this FMU has no structural parameters (no configuration mode)";

guarded! {
    /// `fmi3SetDebugLogging` (FMI 3.0): switches the named log categories on or off
    /// (`loggingOn`), or all of them when `nCategories` is 0. Returns `fmi3Error` and changes
    /// nothing for a NULL or unknown category name (the message lists the known ones).
    ///
    /// # Safety
    /// `categories` points to `nCategories` strings when `nCategories > 0`.
    unsafe fn fmi3SetDebugLogging(instance: Fmi3Instance, loggingOn: Fmi3Boolean, nCategories: usize, categories: *const Fmi3String) -> Fmi3StatusC:
        SET_DEBUG_LOGGING => |inst| unsafe { set_debug_logging(inst, loggingOn != 0, categories, nCategories) };

    /// `fmi3EnterInitializationMode` (FMI 3.0): records the start time (s) and, when
    /// `stopTimeDefined`, the stop time (s) (the tolerance is ignored), then enters
    /// initialization mode. Returns `fmi3Error`, nothing changed, for a non-finite time or a stop
    /// time before the start time.
    fn fmi3EnterInitializationMode(
        instance: Fmi3Instance,
        _toleranceDefined: Fmi3Boolean,
        _tolerance: f64,
        startTime: f64,
        stopTimeDefined: Fmi3Boolean,
        stopTime: f64,
    ) -> Fmi3StatusC: ENTER_INITIALIZATION_MODE => |inst| {
        inst.setup_experiment(startTime, (stopTimeDefined != 0).then_some(stopTime))?;
        inst.enter_initialization_mode()
    };

    /// `fmi3ExitInitializationMode` (FMI 3.0): lets the model validate its parameters
    /// and compute its first outputs, then enters step mode (Co-Simulation) or event mode (Model
    /// Exchange). A rejected parameter or an output out of range is `fmi3Error` and puts the
    /// instance in the error state.
    fn fmi3ExitInitializationMode(instance: Fmi3Instance) -> Fmi3StatusC: EXIT_INITIALIZATION_MODE => Instance::exit_initialization_mode;

    /// `fmi3Terminate` (FMI 3.0): ends the simulation run; afterwards only getters,
    /// FMU state functions, `fmi3Reset` and `fmi3FreeInstance` are allowed.
    fn fmi3Terminate(instance: Fmi3Instance) -> Fmi3StatusC: TERMINATE => Instance::terminate;

    /// `fmi3Reset` (FMI 3.0): returns the instance to the state right after
    /// instantiation, every variable at its start value, time 0.
    fn fmi3Reset(instance: Fmi3Instance) -> Fmi3StatusC: RESET => Instance::reset;

    /// `fmi3GetFloat64` (FMI 3.0): writes the values of the Float64 variables into
    /// `values` (outputs at the current inputs, in the units of the modelDescription); the
    /// independent variable `time` (value reference [`crate::fmi3::xml::TIME_VR`]) reads the instance's
    /// time in s. Returns `fmi3Error` for an unknown or non-Float64 value reference, `nValues`
    /// ≠ `nValueReferences`, or a model failure computing the outputs.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3GetFloat64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut f64, nValues: usize) -> Fmi3StatusC:
        GET_VALUE => |inst| unsafe { get_float64(inst, valueReferences, nValueReferences, values, nValues) };

    /// `fmi3SetFloat64` (FMI 3.0): sets the Float64 (FMI 2.0 Real) variables
    /// `valueReferences[0..nValueReferences]`. Every value is checked (variability and causality
    /// for the current state, the model's range check) before any is stored, so a call that
    /// returns `fmi3Error` changes nothing; `nValues` must equal `nValueReferences` (all scalars).
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3SetFloat64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const f64, nValues: usize) -> Fmi3StatusC:
        SET_VALUE => |inst| unsafe { set_as(inst, Kind::Real, &ARRAYS, valueReferences, nValueReferences, values, nValues, Ok) };

    /// `fmi3GetInt32` (FMI 3.0): writes the values of the Int32 (FMI 2.0 Integer) variables
    /// `valueReferences[0..nValueReferences]` into `values` (`nValues` must equal
    /// `nValueReferences`: all scalars). Returns `fmi3Error` for an unknown value reference or
    /// one of another type.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3GetInt32(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut i32, nValues: usize) -> Fmi3StatusC:
        GET_VALUE => |inst| unsafe { get_as(inst, Kind::Integer, &ARRAYS, valueReferences, nValueReferences, values, nValues, |v| v as i32) };

    /// `fmi3SetInt32` (FMI 3.0): sets the Int32 (FMI 2.0 Integer) variables
    /// `valueReferences[0..nValueReferences]`. Every value is checked before any is stored, so
    /// a call that returns `fmi3Error` changes nothing.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3SetInt32(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const i32, nValues: usize) -> Fmi3StatusC:
        SET_VALUE => |inst| unsafe { set_as(inst, Kind::Integer, &ARRAYS, valueReferences, nValueReferences, values, nValues, |v| Ok(f64::from(v))) };

    /// `fmi3GetInt64` (FMI 3.0): writes the codes of the Enumeration variables (accessed as
    /// Int64) `valueReferences[0..nValueReferences]` into `values` (`nValues` must equal
    /// `nValueReferences`). Returns `fmi3Error` for an unknown value reference or one of another
    /// type.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3GetInt64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut i64, nValues: usize) -> Fmi3StatusC:
        GET_VALUE => |inst| unsafe { get_as(inst, Kind::Enumeration(&ANY_ENUMERATION), &ARRAYS, valueReferences, nValueReferences, values, nValues, |v| v as i64) };

    /// `fmi3SetInt64` (FMI 3.0): sets the Enumeration variables (accessed as Int64)
    /// `valueReferences[0..nValueReferences]`; a code beyond i32 is no item. Every value is
    /// checked before any is stored, so a call that returns `fmi3Error` changes nothing.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3SetInt64(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const i64, nValues: usize) -> Fmi3StatusC:
        SET_VALUE => |inst| unsafe { set_as(inst, Kind::Enumeration(&ANY_ENUMERATION), &ARRAYS, valueReferences, nValueReferences, values, nValues, enumeration_code) };

    /// `fmi3GetBoolean` (FMI 3.0): writes the values of the Boolean variables
    /// `valueReferences[0..nValueReferences]` into `values` (1 or 0). Returns `fmi3Error` for an
    /// unknown value reference or one of another type.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3GetBoolean(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut u8, nValues: usize) -> Fmi3StatusC:
        GET_VALUE => |inst| unsafe { get_as(inst, Kind::Boolean, &ARRAYS, valueReferences, nValueReferences, values, nValues, |v| u8::from(v != 0.0)) };

    /// `fmi3SetBoolean` (FMI 3.0): sets the Boolean variables
    /// `valueReferences[0..nValueReferences]` (any non-zero byte is true). Every value is
    /// checked before any is stored, so a call that returns `fmi3Error` changes nothing.
    ///
    /// # Safety
    /// `valueReferences` and `values` point to `nValueReferences` / `nValues` elements.
    unsafe fn fmi3SetBoolean(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const u8, nValues: usize) -> Fmi3StatusC:
        SET_VALUE => |inst| unsafe { set_as(inst, Kind::Boolean, &ARRAYS, valueReferences, nValueReferences, values, nValues, |v| Ok(if v != 0 { 1.0 } else { 0.0 })) };
}

/// The getters and setters of the FMI 3.0 types this layer's models have no variables of:
/// every value reference is refused (none is `fmi3OK`).
macro_rules! no_such_type {
    ($($get:ident, $set:ident, $t:ty, $name:literal;)*) => {
        guarded! {
            $(
                #[doc = concat!("`", stringify!($get), "` (FMI 3.0): this FMU has no ", $name,
                    " variables; every value reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).")]
                ///
                /// # Safety
                /// `valueReferences` points to `nValueReferences` elements.
                unsafe fn $get(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *mut $t, nValues: usize) -> Fmi3StatusC:
                    GET_VALUE => |inst| unsafe { reject_as(inst, $name, &ARRAYS, valueReferences, nValueReferences, values.cast_const(), nValues) };
                #[doc = concat!("`", stringify!($set), "` (FMI 3.0): this FMU has no ", $name,
                    " variables; every value reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).")]
                ///
                /// # Safety
                /// `valueReferences` points to `nValueReferences` elements.
                unsafe fn $set(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, values: *const $t, nValues: usize) -> Fmi3StatusC:
                    SET_VALUE => |inst| unsafe { reject_as(inst, $name, &ARRAYS, valueReferences, nValueReferences, values, nValues) };
            )*
        }
    };
}

no_such_type! {
    fmi3GetFloat32, fmi3SetFloat32, f32, "Float32";
    fmi3GetInt8, fmi3SetInt8, i8, "Int8";
    fmi3GetUInt8, fmi3SetUInt8, u8, "UInt8";
    fmi3GetInt16, fmi3SetInt16, i16, "Int16";
    fmi3GetUInt16, fmi3SetUInt16, u16, "UInt16";
    fmi3GetUInt32, fmi3SetUInt32, u32, "UInt32";
    fmi3GetUInt64, fmi3SetUInt64, u64, "UInt64";
    fmi3GetString, fmi3SetString, Fmi3String, "String";
}

guarded! {
    /// `fmi3GetBinary` (FMI 3.0): this FMU has no Binary variables; every value
    /// reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).
    ///
    /// # Safety
    /// `valueReferences` points to `nValueReferences` elements.
    unsafe fn fmi3GetBinary(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, _valueSizes: *mut usize, values: *mut *const u8, nValues: usize) -> Fmi3StatusC:
        GET_VALUE => |inst| unsafe { reject_as(inst, "Binary", &ARRAYS, valueReferences, nValueReferences, values.cast_const(), nValues) };

    /// `fmi3SetBinary` (FMI 3.0): this FMU has no Binary variables; every value
    /// reference is refused with `fmi3Error` (`nValueReferences = 0` is `fmi3OK`).
    ///
    /// # Safety
    /// `valueReferences` points to `nValueReferences` elements.
    unsafe fn fmi3SetBinary(instance: Fmi3Instance, valueReferences: *const u32, nValueReferences: usize, _valueSizes: *const usize, values: *const *const u8, nValues: usize) -> Fmi3StatusC:
        SET_VALUE => |inst| unsafe { reject_as(inst, "Binary", &ARRAYS, valueReferences, nValueReferences, values, nValues) };

    /// `fmi3GetClock` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3GetClock(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _values: *mut u8) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3SetClock` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3SetClock(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _values: *const u8) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3GetIntervalDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3GetIntervalDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _intervals: *mut f64, _qualifiers: *mut c_int) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3GetIntervalFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3GetIntervalFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *mut u64, _resolutions: *mut u64, _qualifiers: *mut c_int) -> Fmi3StatusC:
        RESET => refuse(NO_CLOCKS);

    /// `fmi3GetShiftDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3GetShiftDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _shifts: *mut f64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3GetShiftFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3GetShiftFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *mut u64, _resolutions: *mut u64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3SetIntervalDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3SetIntervalDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _intervals: *const f64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3SetIntervalFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3SetIntervalFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3SetShiftDecimal` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3SetShiftDecimal(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _shifts: *const f64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3SetShiftFraction` (FMI 3.0): this FMU has no clocks; always `fmi3Error`.
    fn fmi3SetShiftFraction(instance: Fmi3Instance, _vr: *const u32, _nvr: usize, _counters: *const u64, _resolutions: *const u64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3ActivateModelPartition` (FMI 3.0): no Scheduled Execution; always `fmi3Error`.
    fn fmi3ActivateModelPartition(instance: Fmi3Instance, _clockReference: u32, _activationTime: f64) -> Fmi3StatusC: RESET => refuse(NO_CLOCKS);

    /// `fmi3GetNumberOfVariableDependencies` (FMI 3.0): writes to `*nDependencies`
    /// the number of variables `valueReference` depends on directly (an output or a state
    /// derivative: its ModelStructure dependencies, inputs and continuous states; any other
    /// variable: 0). `fmi3Error` for an unknown value reference or a NULL
    /// `nDependencies`.
    ///
    /// # Safety
    /// `nDependencies` is writable.
    unsafe fn fmi3GetNumberOfVariableDependencies(instance: Fmi3Instance, valueReference: u32, nDependencies: *mut usize) -> Fmi3StatusC: RESET => |inst| {
        let n = dependencies(inst, valueReference)?.len();
        // SAFETY: per the contract.
        unsafe { write_out(nDependencies, n, "nDependencies") }
    };

    /// `fmi3GetVariableDependencies` (FMI 3.0): writes the direct dependencies of
    /// `dependent` (value references of the inputs and states, element index 0, kind `fmi3Dependent`).
    /// `fmi3Error` when `nDependencies` differs from what
    /// [`fmi3GetNumberOfVariableDependencies`] reports, or an array is NULL.
    ///
    /// # Safety
    /// The four arrays hold `nDependencies` writable elements.
    unsafe fn fmi3GetVariableDependencies(
        instance: Fmi3Instance,
        dependent: u32,
        elementIndicesOfDependent: *mut usize,
        independents: *mut u32,
        elementIndicesOfIndependents: *mut usize,
        dependencyKinds: *mut c_int,
        nDependencies: usize,
    ) -> Fmi3StatusC: RESET => |inst| unsafe {
        let arrays = (elementIndicesOfDependent, independents, elementIndicesOfIndependents, dependencyKinds);
        variable_dependencies(inst, dependent, arrays, nDependencies)
    };

    /// `fmi3GetDirectionalDerivative` (FMI 3.0 §2.2.12): `sensitivity = J · seed`, where
    /// `J[i][j]` is the partial derivative of variable `unknowns[i]` with respect to
    /// `knowns[j]` at the current values (as `fmi2GetDirectionalDerivative`:
    /// unknowns outputs and, under Model Exchange, state derivatives; knowns inputs and, under
    /// Model Exchange, continuous states). Every variable is a scalar, so `nSeed` must equal
    /// `nKnowns` and `nSensitivity` `nUnknowns`. `fmi3Error` for a model without
    /// `providesDirectionalDerivatives`, a NULL array, a length mismatch, an unknown value
    /// reference, a variable that is no unknown/known, or a model failure.
    ///
    /// # Safety
    /// Each array points to as many elements as its length argument says.
    #[allow(clippy::too_many_arguments)]
    unsafe fn fmi3GetDirectionalDerivative(
        instance: Fmi3Instance,
        unknowns: *const u32,
        nUnknowns: usize,
        knowns: *const u32,
        nKnowns: usize,
        seed: *const f64,
        nSeed: usize,
        sensitivity: *mut f64,
        nSensitivity: usize,
    ) -> Fmi3StatusC: GET_DIRECTIONAL_DERIVATIVE => |inst| unsafe {
        if nSeed != nKnowns {
            return Err(CallError::ArrayLength { what: "nSeed", given: nSeed, of: "nKnowns", expected: nKnowns });
        }
        if nSensitivity != nUnknowns {
            return Err(CallError::ArrayLength { what: "nSensitivity", given: nSensitivity, of: "nUnknowns", expected: nUnknowns });
        }
        let u = slice(unknowns, nUnknowns, "unknowns[]")?;
        let k = slice(knowns, nKnowns, "knowns[]")?;
        let s = slice(seed, nSeed, "seed[]")?;
        let out = slice_mut(sensitivity, nSensitivity, "sensitivity[]")?;
        inst.directional_derivative(u, k, s, out)
    };

    /// `fmi3GetAdjointDerivative` (FMI 3.0): not provided
    /// (`providesAdjointDerivatives = false`); always `fmi3Error`.
    #[allow(clippy::too_many_arguments)]
    fn fmi3GetAdjointDerivative(instance: Fmi3Instance, _unknowns: *const u32, _nUnknowns: usize, _knowns: *const u32, _nKnowns: usize, _seed: *const f64, _nSeed: usize, _sensitivity: *mut f64, _nSensitivity: usize) -> Fmi3StatusC:
        RESET => refuse("adjoint derivatives are not provided (providesAdjointDerivatives = false)");

    /// `fmi3EnterConfigurationMode` (FMI 3.0): this FMU has no structural parameters;
    /// always `fmi3Error`.
    fn fmi3EnterConfigurationMode(instance: Fmi3Instance) -> Fmi3StatusC: RESET => refuse(NO_CONFIGURATION);

    /// `fmi3ExitConfigurationMode` (FMI 3.0): this FMU has no structural parameters;
    /// always `fmi3Error`.
    fn fmi3ExitConfigurationMode(instance: Fmi3Instance) -> Fmi3StatusC: RESET => refuse(NO_CONFIGURATION);

    /// `fmi3EvaluateDiscreteStates` (FMI 3.0): not provided
    /// (`providesEvaluateDiscreteStates = false`); always `fmi3Error`.
    fn fmi3EvaluateDiscreteStates(instance: Fmi3Instance) -> Fmi3StatusC: RESET => refuse("not provided (providesEvaluateDiscreteStates = false)");
}
