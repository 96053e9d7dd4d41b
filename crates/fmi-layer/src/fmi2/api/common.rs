//! The FMI 2.0 functions common to Model Exchange and Co-Simulation.
//!
//! Every function taking an instance `c` runs through the layer's guard: it returns
//! `fmi2Error` for a NULL, freed or foreign `c` and for a call its state mask does not
//! allow in the instance's current state (logged under `logStatusError`), `fmi2Error` with a
//! logged message for a rejected argument, and `fmi2Fatal` when a panic is contained inside
//! the call (the instance then accepts only `fmi2FreeInstance`).

#![allow(non_snake_case)]

use super::guard::{call, maybe_forced_panic, slice, slice_mut};
use crate::error::CallError;
use crate::fmi2::instance::{Instance, Interface};
use crate::fmi2::logging::{Category, Logger};
use crate::fmi2::snapshot::Snapshot;
use crate::fmi2::state;
use crate::fmi2::types::*;
use crate::fmi2::variables::{Kind, ModelInfo};
use std::ffi::{c_char, c_int, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;

/// A C string from the host as an owned Rust string (invalid UTF-8 replaced), or `None`
/// for NULL.
///
/// # Safety
/// `p` is NULL or a NUL-terminated string.
pub(crate) unsafe fn text(p: *const c_char) -> Option<String> {
    // SAFETY: per the contract.
    (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// `fmi2GetTypesPlatform` (FMI 2.0 §2.1.4): returns the static string `"default"`
/// ([`TYPES_PLATFORM`]), the platform types of the standard's headers.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    TYPES_PLATFORM.as_ptr()
}

/// `fmi2GetVersion` (FMI 2.0 §2.1.4): returns the static string `"2.0"` ([`VERSION`]).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    VERSION.as_ptr()
}

/// The body of `fmi2Instantiate` for the models of `registry`, found by GUID. The export
/// itself is written at the root of the model library by [`crate::export_fmi2!`], which
/// passes the library's registry in: this layer knows no model.
///
/// # Safety
/// Pointers as in the FMI 2.0 standard; NULL is handled everywhere.
pub unsafe fn instantiate_from(
    registry: &[&'static ModelInfo],
    instance_name: Fmi2String,
    fmu_type: c_int,
    guid: Fmi2String,
    resource_location: Fmi2String,
    functions: *const Fmi2CallbackFunctions,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the host passes NULL or valid pointers.
        unsafe { instantiate(registry, instance_name, fmu_type, guid, resource_location, functions, logging_on) }
    }))
    .unwrap_or(null_mut())
}

/// `fmi2Instantiate` proper (outside the panic guard of [`instantiate_from`]): checks the
/// callbacks, instance name, `fmuType` and GUID, and returns the boxed [`Instance`] or NULL
/// (with the reason logged when there is a logger to log it).
///
/// # Safety
/// As for [`instantiate_from`].
unsafe fn instantiate(
    models: &[&'static ModelInfo],
    instance_name: Fmi2String,
    fmu_type: c_int,
    guid: Fmi2String,
    resource_location: Fmi2String,
    functions: *const Fmi2CallbackFunctions,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    if functions.is_null() {
        return null_mut(); // no logger to say so
    }
    // SAFETY: non-NULL, provided by the host.
    let f = unsafe { &*functions };
    let Some(cb) = f.logger else {
        return null_mut();
    };
    // SAFETY: strings from the host are NULL or NUL-terminated.
    let (name, guid, resources) = unsafe { (text(instance_name), text(guid), text(resource_location)) };
    let shown = name.clone().unwrap_or_else(|| "(NULL)".into());
    let logger = Logger::new(cb, f.component_environment, &shown, logging_on != FMI2_FALSE);
    let fail = |msg: String| {
        logger.log(Status::Error, Category::StatusError, &format!("fmi2Instantiate: {msg}"));
        null_mut()
    };
    maybe_forced_panic("fmi2Instantiate");
    let name = match name {
        Some(n) if !n.is_empty() => n,
        _ => return fail("instanceName must be a non-empty string".into()),
    };
    if fmu_type != FMI2_CO_SIMULATION && fmu_type != FMI2_MODEL_EXCHANGE {
        return fail(format!("fmuType = {fmu_type} is not an fmi2Type (0 = Model Exchange, 1 = Co-Simulation)"));
    }
    let Some(guid) = guid else {
        return fail("fmuGUID is NULL".into());
    };
    let Some(info) = models.iter().copied().find(|m| m.guid() == guid) else {
        let known: Vec<String> = models.iter().map(|m| format!("{} {}", m.model_name, m.guid())).collect();
        return fail(format!(
            "fmuGUID {guid} matches no model of this binary (known: {}); the modelDescription.xml does not belong to this binary",
            known.join(", ")
        ));
    };
    let interface = if fmu_type == FMI2_MODEL_EXCHANGE {
        if !info.model_exchange {
            return fail(format!("fmuType = 0 (Model Exchange): {} implements Co-Simulation (fmuType = 1) only", info.model_name));
        }
        Interface::ModelExchange
    } else {
        Interface::CoSimulation
    };
    // This FMU needs no resources: NULL or "" is fine (no message); a location that is
    // not a URI is only a warning.
    match resources.as_deref() {
        None | Some("") => {}
        Some(r) if !looks_like_uri(r) => logger.log(
            Status::Warning,
            Category::StatusWarning,
            &format!("fmi2Instantiate: fmuResourceLocation '{r}' is not a URI (expected e.g. file:///...); this FMU needs no resources, continuing"),
        ),
        _ => {}
    }
    let inst = Instance::with_interface(info, &name, logger, interface, false);
    inst.event(&format!("instantiated {} (GUID {guid})", info.model_name));
    Box::into_raw(Box::new(inst)) as Fmi2Component
}

/// RFC 3986: `scheme ":" ...` with scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ).
pub(crate) fn looks_like_uri(s: &str) -> bool {
    match s.split_once(':') {
        Some((scheme, _)) => {
            let mut ch = scheme.chars();
            ch.next().is_some_and(|c| c.is_ascii_alphabetic())
                && ch.all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c))
                && scheme.len() > 1 // not a Windows drive letter
        }
        None => false,
    }
}

/// `fmi2FreeInstance` (FMI 2.0 §2.1.5): frees the instance in any state (the `fatal` one
/// included) and everything it owns. NULL, or an instance already freed (the tag check), is
/// a no-op; a panic during the release is contained.
///
/// # Safety
/// `c` is NULL or a component from `fmi2Instantiate` not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(AssertUnwindSafe(|| {
        let ptr = c as *mut Instance;
        // SAFETY: per the contract; the tag check skips freed or foreign memory.
        let inst = unsafe { &mut *ptr };
        if !inst.is_live() {
            return;
        }
        inst.event("freeing the instance");
        inst.kill();
        // SAFETY: the pointer came from Box::into_raw in fmi2Instantiate.
        drop(unsafe { Box::from_raw(ptr) });
    }));
}

/// `fmi2SetDebugLogging` (FMI 2.0 §2.1.5): switches the named log categories on or off
/// (`loggingOn`), or all of them when `nCategories` is 0. Returns `fmi2Error` and changes
/// nothing for a NULL or unknown category name (the message lists the known ones).
///
/// # Safety
/// `categories` points to `nCategories` strings when `nCategories > 0`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Fmi2Component,
    loggingOn: Fmi2Boolean,
    nCategories: usize,
    categories: *const Fmi2String,
) -> Fmi2StatusC {
    call(c, "fmi2SetDebugLogging", state::SET_DEBUG_LOGGING, |inst| {
        let on = loggingOn != FMI2_FALSE;
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
            inst.logger.set_all(on);
        } else {
            for cat in parsed {
                inst.logger.set(cat, on);
            }
        }
        Ok(Status::Ok)
    })
}

/// `fmi2SetupExperiment` (FMI 2.0 §2.1.6): records the start time (s) and, when
/// `stopTimeDefined`, the stop time (s); the tolerance is ignored (no error control).
/// Returns `fmi2Error` for a non-finite time or a stop time before the start time.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetupExperiment(
    c: Fmi2Component,
    _toleranceDefined: Fmi2Boolean,
    _tolerance: Fmi2Real,
    startTime: Fmi2Real,
    stopTimeDefined: Fmi2Boolean,
    stopTime: Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2SetupExperiment", state::SETUP_EXPERIMENT, |inst| {
        inst.setup_experiment(startTime, (stopTimeDefined != FMI2_FALSE).then_some(stopTime))
    })
}

/// `fmi2EnterInitializationMode` (FMI 2.0 §2.1.6): moves the instance into initialization
/// mode, where parameters and start values may still be set.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2EnterInitializationMode(c: Fmi2Component) -> Fmi2StatusC {
    call(c, "fmi2EnterInitializationMode", state::ENTER_INITIALIZATION_MODE, Instance::enter_initialization_mode)
}

/// `fmi2ExitInitializationMode` (FMI 2.0 §2.1.6): lets the model validate its parameters
/// ([`crate::fmi2::model::Model::exit_initialization`]) and compute its first outputs, then
/// enters step mode (Co-Simulation) or event mode (Model Exchange). A parameter the model
/// rejects, or an output out of its range, is `fmi2Error` and puts the instance in the
/// `error` state.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2ExitInitializationMode(c: Fmi2Component) -> Fmi2StatusC {
    call(c, "fmi2ExitInitializationMode", state::EXIT_INITIALIZATION_MODE, Instance::exit_initialization_mode)
}

/// `fmi2Terminate` (FMI 2.0 §2.1.6): ends the simulation run; afterwards only getters,
/// FMU state functions, `fmi2Reset` and `fmi2FreeInstance` are allowed.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Terminate(c: Fmi2Component) -> Fmi2StatusC {
    call(c, "fmi2Terminate", state::TERMINATE, Instance::terminate)
}

/// `fmi2Reset` (FMI 2.0 §2.1.6): returns the instance to the state right after
/// `fmi2Instantiate`, every variable at its start value.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Reset(c: Fmi2Component) -> Fmi2StatusC {
    call(c, "fmi2Reset", state::RESET, Instance::reset)
}

/// `fmi2GetReal` (FMI 2.0 §2.1.7): writes the values of the Real variables `vr[0..nvr]`
/// into `value` (outputs at the current inputs, in the units of the modelDescription).
/// Returns `fmi2Error` for an unknown or non-Real value reference, a NULL array with
/// `nvr > 0`, or a model failure computing the outputs.
///
/// # Safety
/// `vr` and `value` point to `nvr` elements when `nvr > 0`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2GetReal", state::GET_VALUE, |inst| {
        // SAFETY: per the contract.
        let (vrs, vals) = unsafe { (slice(vr, nvr, "vr[]")?, slice_mut(value, nvr, "value[]")?) };
        inst.get_real(vrs, vals)
    })
}

/// `fmi2SetReal` (FMI 2.0 §2.1.7): sets the Real variables `vr[0..nvr]`. Every value is
/// checked (variability and causality for the current state, the model's range check)
/// before any is stored, so a call that returns `fmi2Error` changes nothing.
///
/// # Safety
/// `vr` and `value` point to `nvr` elements when `nvr > 0`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2SetReal", state::SET_VALUE, |inst| {
        // SAFETY: per the contract.
        let (vrs, vals) = unsafe { (slice(vr, nvr, "vr[]")?, slice(value, nvr, "value[]")?) };
        inst.set_real(vrs, vals)
    })
}

macro_rules! no_such_type {
    ($get:ident, $set:ident, $t:ty, $name:literal) => {
        #[doc = concat!("`", stringify!($get), "` (FMI 2.0 §2.1.7): no model of this layer has ", $name,
            " variables, so every value reference is rejected with `fmi2Error` (`nvr = 0` is `fmi2OK`).")]
        ///
        /// # Safety
        /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut $t) -> Fmi2StatusC {
            call(c, stringify!($get), state::GET_VALUE, |inst| {
                // SAFETY: per the contract.
                let vrs = unsafe { slice(vr, nvr, "vr[]")? };
                unsafe { slice_mut(value, nvr, "value[]")? };
                inst.reject_type($name, vrs)
            })
        }
        #[doc = concat!("`", stringify!($set), "` (FMI 2.0 §2.1.7): no model of this layer has ", $name,
            " variables, so every value reference is rejected with `fmi2Error` (`nvr = 0` is `fmi2OK`).")]
        ///
        /// # Safety
        /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const $t) -> Fmi2StatusC {
            call(c, stringify!($set), state::SET_VALUE, |inst| {
                // SAFETY: per the contract.
                let vrs = unsafe { slice(vr, nvr, "vr[]")? };
                unsafe { slice(value, nvr, "value[]")? };
                inst.reject_type($name, vrs)
            })
        }
    };
}

macro_rules! int_type {
    ($get:ident, $set:ident, $tname:literal, $kind:expr, $from:expr) => {
        #[doc = concat!("`", stringify!($get), "` (FMI 2.0 §2.1.7): writes the values of the ", $tname,
            " variables `vr[0..nvr]` into `value` (the model holds them as f64; see [`Kind`]). ",
            "Returns `fmi2Error` for an unknown value reference or one of another type.")]
        ///
        /// # Safety
        /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut c_int) -> Fmi2StatusC {
            call(c, stringify!($get), state::GET_VALUE, |inst| {
                // SAFETY: per the contract.
                let (vrs, out) = unsafe { (slice(vr, nvr, "vr[]")?, slice_mut(value, nvr, "value[]")?) };
                let mut vals = vec![0.0; vrs.len()];
                let status = inst.get_values($kind, vrs, &mut vals)?;
                for (o, v) in out.iter_mut().zip(vals) {
                    *o = v as c_int;
                }
                Ok(status)
            })
        }
        #[doc = concat!("`", stringify!($set), "` (FMI 2.0 §2.1.7): sets the ", $tname,
            " variables `vr[0..nvr]` (stored as f64; see [`Kind`]). Every value is checked before ",
            "any is stored, so a call that returns `fmi2Error` changes nothing.")]
        ///
        /// # Safety
        /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const c_int) -> Fmi2StatusC {
            call(c, stringify!($set), state::SET_VALUE, |inst| {
                // SAFETY: per the contract.
                let (vrs, vals) = unsafe { (slice(vr, nvr, "vr[]")?, slice(value, nvr, "value[]")?) };
                let from: fn(c_int) -> f64 = $from;
                let vals: Vec<f64> = vals.iter().map(|&v| from(v)).collect();
                inst.set_values($kind, vrs, &vals)
            })
        }
    };
}

int_type!(fmi2GetInteger, fmi2SetInteger, "Integer", Kind::Integer, f64::from);
// Any non-zero fmi2Boolean is true.
int_type!(fmi2GetBoolean, fmi2SetBoolean, "Boolean", Kind::Boolean, |v| if v != FMI2_FALSE { 1.0 } else { 0.0 });
no_such_type!(fmi2GetString, fmi2SetString, Fmi2String, "String");

/// `fmi2GetFMUstate` (FMI 2.0 §2.1.8): saves the instance's complete state (time, mode,
/// model state) into `*FMUstate`: a new FMU state when `*FMUstate` is NULL, else the given
/// one is overwritten. Returns `fmi2Error` for a NULL `FMUstate` or a `*FMUstate` that is
/// not a live FMU state of this FMU.
///
/// # Safety
/// `FMUstate` is NULL or points to NULL or to an FMU state of this instance's model.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { get_fmu_state("fmi2GetFMUstate", c, FMUstate) }
}

/// The body of `fmi2GetFMUstate`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2GetFMUstate`.
pub(crate) unsafe fn get_fmu_state(name: &'static str, c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |inst| {
        if FMUstate.is_null() {
            return Err(CallError::Null("FMUstate"));
        }
        let snap = inst.snapshot();
        // SAFETY: non-NULL pointer to the host's slot.
        let slot = unsafe { &mut *FMUstate };
        if slot.is_null() {
            *slot = Box::into_raw(Box::new(snap)) as Fmi2FmuState;
        } else {
            // The standard lets the host pass back a state for reuse.
            // SAFETY: a non-NULL slot holds a state returned by this FMU.
            let old = unsafe { &mut *(*slot as *mut Snapshot) };
            if !old.is_live() {
                return Err(CallError::NotReusableState);
            }
            *old = snap;
        }
        inst.event(&format!("FMU state stored at t = {} s ({})", inst.time, inst.state.name()));
        Ok(Status::Ok)
    })
}

/// The FMU state behind the handle `s`, or an error message for NULL or a handle that is
/// not (any more) a live FMU state of this FMU.
///
/// # Safety
/// A non-NULL `s` must be an FMU state returned by this FMU.
unsafe fn live_state<'a>(s: Fmi2FmuState, handle: &'static str) -> Result<&'a mut Snapshot, CallError> {
    if s.is_null() {
        return Err(CallError::Null(handle));
    }
    // SAFETY: per the contract; the tag catches most foreign or freed pointers.
    let snap = unsafe { &mut *(s as *mut Snapshot) };
    if !snap.is_live() {
        return Err(CallError::NotLiveState { handle });
    }
    Ok(snap)
}

/// `fmi2SetFMUstate` (FMI 2.0 §2.1.8): restores the instance to the saved `FMUstate`
/// (time, mode, model state). Returns `fmi2Error`, the instance unchanged, for a NULL or
/// dead state or one saved from another model.
///
/// # Safety
/// `FMUstate` is NULL or an FMU state returned by this FMU.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Fmi2Component, FMUstate: Fmi2FmuState) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { set_fmu_state("fmi2SetFMUstate", c, FMUstate) }
}

/// The body of `fmi2SetFMUstate`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2SetFMUstate`.
pub(crate) unsafe fn set_fmu_state(name: &'static str, c: Fmi2Component, FMUstate: Fmi2FmuState) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |inst| {
        // SAFETY: per the contract.
        let snap = unsafe { live_state(FMUstate, "FMUstate") }?;
        inst.restore(snap)
    })
}

/// `fmi2FreeFMUstate` (FMI 2.0 §2.1.8): frees `*FMUstate` and sets it to NULL; a NULL
/// `FMUstate` or `*FMUstate` is `fmi2OK` (nothing to free), a dead or foreign state is
/// `fmi2Error`.
///
/// # Safety
/// `FMUstate` is NULL or points to NULL or to an FMU state returned by this FMU.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { free_fmu_state("fmi2FreeFMUstate", c, FMUstate) }
}

/// The body of `fmi2FreeFMUstate`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2FreeFMUstate`.
pub(crate) unsafe fn free_fmu_state(name: &'static str, c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |_inst| {
        // SAFETY: per the contract.
        if FMUstate.is_null() || unsafe { (*FMUstate).is_null() } {
            return Ok(Status::Ok); // nothing to free
        }
        // SAFETY: per the contract.
        let snap = unsafe { live_state(*FMUstate, "FMUstate") }?;
        snap.kill();
        // SAFETY: the state came from Box::into_raw in this module.
        unsafe {
            drop(Box::from_raw(*FMUstate as *mut Snapshot));
            *FMUstate = null_mut();
        }
        Ok(Status::Ok)
    })
}

/// `fmi2SerializedFMUstateSize` (FMI 2.0 §2.1.8): writes to `*size` the length in bytes
/// of `FMUstate` serialized (the layer's versioned format with CRC). Returns `fmi2Error`
/// for a dead state or a NULL `size`.
///
/// # Safety
/// `FMUstate` is an FMU state returned by this FMU; `size` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(c: Fmi2Component, FMUstate: Fmi2FmuState, size: *mut usize) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { serialized_fmu_state_size("fmi2SerializedFMUstateSize", c, FMUstate, size) }
}

/// The body of `fmi2SerializedFMUstateSize`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2SerializedFMUstateSize`.
pub(crate) unsafe fn serialized_fmu_state_size(name: &'static str, c: Fmi2Component, FMUstate: Fmi2FmuState, size: *mut usize) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |_inst| {
        // SAFETY: per the contract.
        let snap = unsafe { live_state(FMUstate, "FMUstate") }?;
        if size.is_null() {
            return Err(CallError::Null("size"));
        }
        // SAFETY: non-NULL.
        unsafe { *size = snap.encode().len() };
        Ok(Status::Ok)
    })
}

/// `fmi2SerializeFMUstate` (FMI 2.0 §2.1.8): writes `FMUstate` serialized into
/// `serializedState`. Returns `fmi2Error`, nothing written, when `size` differs from what
/// `fmi2SerializedFMUstateSize` reports or the state is dead.
///
/// # Safety
/// `FMUstate` is an FMU state returned by this FMU; `serializedState` points to `size`
/// writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Fmi2Component,
    FMUstate: Fmi2FmuState,
    serializedState: *mut Fmi2Byte,
    size: usize,
) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { serialize_fmu_state("fmi2SerializeFMUstate", c, FMUstate, serializedState, size) }
}

/// The body of `fmi2SerializeFMUstate`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2SerializeFMUstate`.
pub(crate) unsafe fn serialize_fmu_state(name: &'static str, 
    c: Fmi2Component,
    FMUstate: Fmi2FmuState,
    serializedState: *mut Fmi2Byte,
    size: usize,
) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |_inst| {
        // SAFETY: per the contract.
        let snap = unsafe { live_state(FMUstate, "FMUstate") }?;
        let bytes = snap.encode();
        if size != bytes.len() {
            return Err(CallError::StateSize { given: size, actual: bytes.len() });
        }
        // SAFETY: per the contract.
        let out = unsafe { slice_mut(serializedState as *mut u8, size, "serializedState[]") }?;
        out.copy_from_slice(&bytes);
        Ok(Status::Ok)
    })
}

/// `fmi2DeSerializeFMUstate` (FMI 2.0 §2.1.8): decodes `serializedState` (as written by
/// `fmi2SerializeFMUstate` of this model, through FMI 2.0 or 3.0) into `*FMUstate`, a new
/// state when it is NULL, else overwriting the given one. Returns `fmi2Error`, nothing
/// changed, for bytes of another model or format version, a wrong length or a CRC mismatch.
///
/// # Safety
/// `serializedState` points to `size` readable bytes; `FMUstate` is writable and
/// holds NULL or an FMU state returned by this FMU.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Fmi2Component,
    serializedState: *const Fmi2Byte,
    size: usize,
    FMUstate: *mut Fmi2FmuState,
) -> Fmi2StatusC {
    // SAFETY: forwarded under the same contract.
    unsafe { deserialize_fmu_state("fmi2DeSerializeFMUstate", c, serializedState, size, FMUstate) }
}

/// The body of `fmi2DeSerializeFMUstate`, shared with the FMI 3.0 function of the same role (`name` in messages).
///
/// # Safety
/// As for `fmi2DeSerializeFMUstate`.
pub(crate) unsafe fn deserialize_fmu_state(name: &'static str, 
    c: Fmi2Component,
    serializedState: *const Fmi2Byte,
    size: usize,
    FMUstate: *mut Fmi2FmuState,
) -> Fmi2StatusC {
    call(c, name, state::FMU_STATE, |inst| {
        if FMUstate.is_null() {
            return Err(CallError::Null("FMUstate"));
        }
        // SAFETY: per the contract.
        let bytes = unsafe { slice(serializedState as *const u8, size, "serializedState[]") }?;
        let snap = inst.decode_state(bytes)?;
        // SAFETY: non-NULL pointer to the host's slot.
        let slot = unsafe { &mut *FMUstate };
        if slot.is_null() {
            *slot = Box::into_raw(Box::new(snap)) as Fmi2FmuState;
        } else {
            // SAFETY: a non-NULL slot holds a state of this FMU.
            let old = unsafe { live_state(*slot, "*FMUstate") }?;
            *old = snap;
        }
        Ok(Status::Ok)
    })
}

/// `fmi2GetDirectionalDerivative` (FMI 2.0 §2.1.9): not provided
/// (`providesDirectionalDerivative = false`); always `fmi2Error` (after the state check).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetDirectionalDerivative(
    c: Fmi2Component,
    _vUnknown_ref: *const Fmi2ValueReference,
    _nUnknown: usize,
    _vKnown_ref: *const Fmi2ValueReference,
    _nKnown: usize,
    _dvKnown: *const Fmi2Real,
    _dvUnknown: *mut Fmi2Real,
) -> Fmi2StatusC {
    call(c, "fmi2GetDirectionalDerivative", state::GET_DIRECTIONAL_DERIVATIVE, |_| {
        Err(CallError::Unsupported("directional derivatives are not provided (providesDirectionalDerivative = false)"))
    })
}
