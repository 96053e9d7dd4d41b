//! The FMI 2.0 functions common to Model Exchange and Co-Simulation.
//!
//! Every function taking an instance `c` runs through the layer's guard: it returns
//! `fmi2Error` for a NULL, freed or foreign `c` and for a call its state mask does not
//! allow in the instance's current state (logged under `logStatusError`), `fmi2Error` with a
//! logged message for a rejected argument, and `fmi2Fatal` when a panic is contained inside
//! the call (the instance then accepts only `fmi2FreeInstance`).

#![allow(non_snake_case)]

use crate::core::guard::{guarded, maybe_forced_panic, slice, slice_mut};
use crate::core::state::{Mask, State, ENTER_INITIALIZATION_MODE, EXIT_INITIALIZATION_MODE, GET_VALUE, RESET, SET_DEBUG_LOGGING, SET_VALUE, TERMINATE};
use crate::core::instance::{Instance, Interface, Rules};
use crate::core::instantiate::{free_instance, instance_name_checked, looks_like_uri, model_of, refuse_instance, set_debug_logging, text};
use crate::core::logging::{c_text, Category, HostLog, Logger};
use crate::core::values::{get_as, reject_as, set_as, Arrays};
use crate::core::variables::{Kind, ModelInfo};
use crate::error::CallError;
use crate::fmi2::types::*;
use std::ffi::{c_char, c_int, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;
use std::rc::Rc;

// The state masks of FMI 2.0's own functions; the functions both standards have use the
// core's (`crate::core::state`).

/// `fmi2SetupExperiment`: right after instantiation only.
const SETUP_EXPERIMENT: Mask = Mask::of(&[State::Instantiated]);
/// `fmi2GetDirectionalDerivative` (FMI 2.0 §3.2.3 and §4.2.4 tables): as [`GET_VALUE`]
/// (initialization, event and continuous-time mode; stepComplete, stepFailed, stepCanceled;
/// terminated, error).
const GET_DIRECTIONAL_DERIVATIVE: Mask = GET_VALUE;

/// FMI 2.0's names of the arrays of a get/set call (`vr[]`, `value[]`: one value per value
/// reference); `fmi2GetString`/`fmi2SetString` check the value array too.
const ARRAYS: Arrays = Arrays { vr: "vr[]", values: "value[]", check_unused_values: true };

/// Whether a variable of kind `variable` is read and written by the FMI 2.0 getter/setter of
/// `requested` (Real, Integer or Boolean): an Enumeration goes through the Integer functions
/// (FMI 2.0 §2.1.7), every other kind through its own.
pub fn accessed_as(variable: Kind, requested: Kind) -> bool {
    match (variable, requested) {
        (Kind::Enumeration(_), Kind::Integer) => true,
        (a, b) => std::mem::discriminant(&a) == std::mem::discriminant(&b),
    }
}

/// What FMI 2.0 defines its own way for an instance it creates.
pub static RULES: Rules = Rules {
    accessed_as,
    no_directional_derivatives: "directional derivatives are not provided (providesDirectionalDerivative = false)",
};

/// The host's `fmi2CallbackLogger` with its `componentEnvironment`: every message goes to it
/// with the instance name, through a `"%s"` format, `#` doubled (FMI 2.0 reads `#vr#` in a
/// message as a value-reference reference; `##` is a literal `#`).
#[derive(Debug)]
struct Fmi2Log {
    callback: Fmi2CallbackLogger,
    env: Fmi2ComponentEnvironment,
}

impl HostLog for Fmi2Log {
    fn emit(&self, instance_name: &CStr, status: Status, category: &CStr, message: &str) {
        let msg = c_text(&message.replace('#', "##"));
        // SAFETY: the callback was checked non-NULL at instantiation; all strings are
        // NUL-terminated and outlive the call; the message goes through "%s".
        unsafe {
            (self.callback)(self.env, instance_name.as_ptr(), status.c(), category.as_ptr(), c"%s".as_ptr(), msg.as_ptr());
        }
    }
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
/// passes the library's registry in: this layer knows no model. Checks the callbacks,
/// instance name, `fmuType` and GUID, and returns the boxed [`Instance`] or NULL (with the
/// reason logged when there is a logger to log it); a panic returns NULL.
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
        let sink: Rc<dyn HostLog> = Rc::new(Fmi2Log { callback: cb, env: f.component_environment });
        let logger = Logger::new(Some(sink), name.as_deref().unwrap_or("(NULL)"), logging_on != FMI2_FALSE);
        maybe_forced_panic("fmi2Instantiate");
        let checked = instance_name_checked(name).and_then(|name| {
            if fmu_type != FMI2_CO_SIMULATION && fmu_type != FMI2_MODEL_EXCHANGE {
                return Err(CallError::FmuType(fmu_type));
            }
            let (info, guid) = model_of(registry, guid, "fmuGUID")?;
            if fmu_type == FMI2_MODEL_EXCHANGE && !info.model_exchange {
                return Err(CallError::CoSimulationOnly { model: info.model_name, asked: "fmuType = 0 (Model Exchange): ", offered: " (fmuType = 1)" });
            }
            Ok((name, info, guid))
        });
        let (name, info, guid) = match checked {
            Ok(c) => c,
            Err(e) => return refuse_instance(&logger, "fmi2Instantiate", &e),
        };
        let interface = if fmu_type == FMI2_MODEL_EXCHANGE { Interface::ModelExchange } else { Interface::CoSimulation };
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
        let inst = Instance::with_interface(info, &name, logger, interface, &RULES);
        inst.event(&format!("instantiated {} (GUID {guid})", info.model_name));
        Box::into_raw(Box::new(inst)) as Fmi2Component
    }))
    .unwrap_or(null_mut())
}

/// `fmi2FreeInstance` (FMI 2.0 §2.1.5): frees the instance in any state (the `fatal` one
/// included) and everything it owns. NULL, or an instance already freed (the tag check), is
/// a no-op; a panic during the release is contained.
///
/// # Safety
/// `c` is NULL or a component from `fmi2Instantiate` not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    // SAFETY: forwarded under the same contract.
    unsafe { free_instance(c) }
}

guarded! {
    /// `fmi2SetDebugLogging` (FMI 2.0 §2.1.5): switches the named log categories on or off
    /// (`loggingOn`), or all of them when `nCategories` is 0. Returns `fmi2Error` and changes
    /// nothing for a NULL or unknown category name (the message lists the known ones).
    ///
    /// # Safety
    /// `categories` points to `nCategories` strings when `nCategories > 0`.
    unsafe fn fmi2SetDebugLogging(c: Fmi2Component, loggingOn: Fmi2Boolean, nCategories: usize, categories: *const Fmi2String) -> Fmi2StatusC: SET_DEBUG_LOGGING =>
        |inst| unsafe { set_debug_logging(inst, loggingOn != FMI2_FALSE, categories, nCategories) };

    /// `fmi2SetupExperiment` (FMI 2.0 §2.1.6): records the start time (s) and, when
    /// `stopTimeDefined`, the stop time (s); the tolerance is ignored (no error control).
    /// Returns `fmi2Error` for a non-finite time or a stop time before the start time.
    fn fmi2SetupExperiment(
        c: Fmi2Component,
        _toleranceDefined: Fmi2Boolean,
        _tolerance: Fmi2Real,
        startTime: Fmi2Real,
        stopTimeDefined: Fmi2Boolean,
        stopTime: Fmi2Real,
    ) -> Fmi2StatusC: SETUP_EXPERIMENT => |inst| inst.setup_experiment(startTime, (stopTimeDefined != FMI2_FALSE).then_some(stopTime));

    /// `fmi2EnterInitializationMode` (FMI 2.0 §2.1.6): moves the instance into initialization
    /// mode, where parameters and start values may still be set.
    fn fmi2EnterInitializationMode(c: Fmi2Component) -> Fmi2StatusC: ENTER_INITIALIZATION_MODE => Instance::enter_initialization_mode;

    /// `fmi2ExitInitializationMode` (FMI 2.0 §2.1.6): lets the model validate its parameters
    /// ([`crate::core::model::Model::exit_initialization`]) and compute its first outputs, then
    /// enters step mode (Co-Simulation) or event mode (Model Exchange). A parameter the model
    /// rejects, or an output out of its range, is `fmi2Error` and puts the instance in the
    /// `error` state.
    fn fmi2ExitInitializationMode(c: Fmi2Component) -> Fmi2StatusC: EXIT_INITIALIZATION_MODE => Instance::exit_initialization_mode;

    /// `fmi2Terminate` (FMI 2.0 §2.1.6): ends the simulation run; afterwards only getters,
    /// FMU state functions, `fmi2Reset` and `fmi2FreeInstance` are allowed.
    fn fmi2Terminate(c: Fmi2Component) -> Fmi2StatusC: TERMINATE => Instance::terminate;

    /// `fmi2Reset` (FMI 2.0 §2.1.6): returns the instance to the state right after
    /// `fmi2Instantiate`, every variable at its start value.
    fn fmi2Reset(c: Fmi2Component) -> Fmi2StatusC: RESET => Instance::reset;

    /// `fmi2GetReal` (FMI 2.0 §2.1.7): writes the values of the Real variables `vr[0..nvr]`
    /// into `value` (outputs at the current inputs, in the units of the modelDescription).
    /// Returns `fmi2Error` for an unknown or non-Real value reference, a NULL array with
    /// `nvr > 0`, or a model failure computing the outputs.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2GetReal(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut Fmi2Real) -> Fmi2StatusC: GET_VALUE =>
        |inst| unsafe { get_as(inst, Kind::Real, &ARRAYS, vr, nvr, value, nvr, |v| v) };

    /// `fmi2SetReal` (FMI 2.0 §2.1.7): sets the Real variables `vr[0..nvr]`. Every value is
    /// checked (variability and causality for the current state, the model's range check)
    /// before any is stored, so a call that returns `fmi2Error` changes nothing.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2SetReal(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const Fmi2Real) -> Fmi2StatusC: SET_VALUE =>
        |inst| unsafe { set_as(inst, Kind::Real, &ARRAYS, vr, nvr, value, nvr, Ok) };

    /// `fmi2GetInteger` (FMI 2.0 §2.1.7): writes the values of the Integer (and Enumeration)
    /// variables `vr[0..nvr]` into `value` (the model holds them as f64; see [`Kind`]).
    /// Returns `fmi2Error` for an unknown value reference or one of another type.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2GetInteger(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut Fmi2Integer) -> Fmi2StatusC: GET_VALUE =>
        |inst| unsafe { get_as(inst, Kind::Integer, &ARRAYS, vr, nvr, value, nvr, |v| v as Fmi2Integer) };

    /// `fmi2SetInteger` (FMI 2.0 §2.1.7): sets the Integer (and Enumeration) variables
    /// `vr[0..nvr]` (stored as f64; see [`Kind`]). Every value is checked before any is
    /// stored, so a call that returns `fmi2Error` changes nothing.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2SetInteger(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const Fmi2Integer) -> Fmi2StatusC: SET_VALUE =>
        |inst| unsafe { set_as(inst, Kind::Integer, &ARRAYS, vr, nvr, value, nvr, |v| Ok(f64::from(v))) };

    /// `fmi2GetBoolean` (FMI 2.0 §2.1.7): writes the values of the Boolean variables
    /// `vr[0..nvr]` into `value` (`fmi2True` or `fmi2False`). Returns `fmi2Error` for an
    /// unknown value reference or one of another type.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2GetBoolean(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut Fmi2Boolean) -> Fmi2StatusC: GET_VALUE =>
        |inst| unsafe { get_as(inst, Kind::Boolean, &ARRAYS, vr, nvr, value, nvr, |v| v as Fmi2Boolean) };

    /// `fmi2SetBoolean` (FMI 2.0 §2.1.7): sets the Boolean variables `vr[0..nvr]`; any
    /// non-zero `fmi2Boolean` is true. Every value is checked before any is stored, so a call
    /// that returns `fmi2Error` changes nothing.
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2SetBoolean(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const Fmi2Boolean) -> Fmi2StatusC: SET_VALUE =>
        |inst| unsafe { set_as(inst, Kind::Boolean, &ARRAYS, vr, nvr, value, nvr, |v| Ok(if v != FMI2_FALSE { 1.0 } else { 0.0 })) };

    /// `fmi2GetString` (FMI 2.0 §2.1.7): no model of this layer has String variables, so
    /// every value reference is rejected with `fmi2Error` (`nvr = 0` is `fmi2OK`).
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2GetString(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *mut Fmi2String) -> Fmi2StatusC: GET_VALUE =>
        |inst| unsafe { reject_as(inst, "String", &ARRAYS, vr, nvr, value.cast_const(), nvr) };

    /// `fmi2SetString` (FMI 2.0 §2.1.7): no model of this layer has String variables, so
    /// every value reference is rejected with `fmi2Error` (`nvr = 0` is `fmi2OK`).
    ///
    /// # Safety
    /// `vr` and `value` point to `nvr` elements when `nvr > 0`.
    unsafe fn fmi2SetString(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, value: *const Fmi2String) -> Fmi2StatusC: SET_VALUE =>
        |inst| unsafe { reject_as(inst, "String", &ARRAYS, vr, nvr, value, nvr) };

    /// `fmi2GetDirectionalDerivative` (FMI 2.0 §2.1.9): `dvUnknown = J · dvKnown`, where
    /// `J[i][j]` is the partial derivative of variable `vUnknown_ref[i]` with respect to
    /// `vKnown_ref[j]` at the current values (the model's [`crate::core::model::Model::jacobian`];
    /// unknowns: outputs, and under Model Exchange state derivatives; knowns: inputs, and under
    /// Model Exchange continuous states). `nUnknown` or `nKnown` = 0 is `fmi2OK` with nothing
    /// written. `fmi2Error` for a model without `providesDirectionalDerivative`, a NULL array,
    /// an unknown value reference, a variable that is no unknown/known, or a model failure.
    ///
    /// # Safety
    /// `vUnknown_ref` and `dvUnknown` point to `nUnknown` elements, `vKnown_ref` and `dvKnown`
    /// to `nKnown`.
    unsafe fn fmi2GetDirectionalDerivative(
        c: Fmi2Component,
        vUnknown_ref: *const Fmi2ValueReference,
        nUnknown: usize,
        vKnown_ref: *const Fmi2ValueReference,
        nKnown: usize,
        dvKnown: *const Fmi2Real,
        dvUnknown: *mut Fmi2Real,
    ) -> Fmi2StatusC: GET_DIRECTIONAL_DERIVATIVE => |inst| unsafe {
        let unknowns = slice(vUnknown_ref, nUnknown, "vUnknown_ref[]")?;
        let knowns = slice(vKnown_ref, nKnown, "vKnown_ref[]")?;
        let seed = slice(dvKnown, nKnown, "dvKnown[]")?;
        let out = slice_mut(dvUnknown, nUnknown, "dvUnknown[]")?;
        inst.directional_derivative(unknowns, knowns, seed, out)
    };
}

pub use super::fmu_state::{
    fmi2DeSerializeFMUstate, fmi2FreeFMUstate, fmi2GetFMUstate, fmi2SerializeFMUstate, fmi2SerializedFMUstateSize,
    fmi2SetFMUstate,
};
