//! A minimal FMI host for the Rust tests: calls the exported `fmi2*` functions
//! directly and records every logger message.
#![allow(dead_code)]

use fmi_layer::fmi2::api::common::*;
use pinjoint_fmu::fmi2Instantiate;
use fmi_layer::fmi2::types::*;
use std::ffi::{c_char, CStr, CString};
use std::sync::Mutex;

#[derive(Debug, Clone)]
pub struct Msg {
    pub status: i32,
    pub category: String,
    pub text: String,
}

/// The FMU always logs with format "%s" and the message as the one variadic
/// argument, so a non-variadic function with that signature reads it correctly on
/// the System V x86-64 and AAPCS64 Linux ABIs (stable Rust cannot define a
/// C-variadic function).
unsafe extern "C" fn record(
    env: Fmi2ComponentEnvironment,
    _name: Fmi2String,
    status: Fmi2StatusC,
    category: Fmi2String,
    format: Fmi2String,
    message: *const c_char,
) {
    let log = unsafe { &*(env as *const Mutex<Vec<Msg>>) };
    let fmt = unsafe { CStr::from_ptr(format) }.to_string_lossy();
    assert_eq!(fmt, "%s", "the FMU must pass messages through %s");
    log.lock().unwrap().push(Msg {
        status,
        category: unsafe { CStr::from_ptr(category) }.to_string_lossy().into_owned(),
        text: unsafe { CStr::from_ptr(message) }.to_string_lossy().into_owned(),
    });
}

pub fn logger() -> Fmi2CallbackLogger {
    // SAFETY: see `record`.
    unsafe { std::mem::transmute::<*const (), Fmi2CallbackLogger>(record as *const ()) }
}

pub struct Host {
    pub log: Box<Mutex<Vec<Msg>>>,
    pub callbacks: Box<Fmi2CallbackFunctions>,
}

impl Host {
    pub fn new() -> Self {
        let log = Box::new(Mutex::new(Vec::new()));
        let env = &*log as *const Mutex<Vec<Msg>> as Fmi2ComponentEnvironment;
        let callbacks = Box::new(Fmi2CallbackFunctions {
            logger: Some(logger()),
            allocate_memory: None,
            free_memory: None,
            step_finished: None,
            component_environment: env,
        });
        Host { log, callbacks }
    }

    pub fn messages(&self) -> Vec<Msg> {
        self.log.lock().unwrap().clone()
    }

    pub fn clear(&self) {
        self.log.lock().unwrap().clear();
    }

    /// The last message, for assertions.
    pub fn last(&self) -> String {
        self.messages().last().map(|m| m.text.clone()).unwrap_or_default()
    }

    pub fn instantiate_with(&self, name: &str, fmu_type: i32, guid: &str, resources: Option<&str>, logging_on: bool) -> Fmi2Component {
        let name = CString::new(name).unwrap();
        let guid = CString::new(guid).unwrap();
        let res = resources.map(|r| CString::new(r).unwrap());
        unsafe {
            fmi2Instantiate(
                name.as_ptr(),
                fmu_type,
                guid.as_ptr(),
                res.as_ref().map_or(std::ptr::null(), |r| r.as_ptr()),
                &*self.callbacks,
                FMI2_FALSE,
                logging_on as i32,
            )
        }
    }

    pub fn instantiate(&self) -> Fmi2Component {
        let c = self.instantiate_with("joint", FMI2_CO_SIMULATION, &guid(), Some("file:///tmp/resources"), false);
        assert!(!c.is_null(), "instantiate failed: {:?}", self.messages());
        c
    }

    /// Instantiate, set `params` and inputs, initialize at t = 0.
    pub fn ready(&self, sets: &[(&str, f64)]) -> Fmi2Component {
        let c = self.instantiate();
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), 0);
        for (n, v) in sets {
            assert_eq!(set(c, n, *v), 0, "{n}: {}", self.last());
        }
        assert_eq!(fmi2EnterInitializationMode(c), 0);
        assert_eq!(fmi2ExitInitializationMode(c), 0, "{}", self.last());
        c
    }
}

pub fn guid() -> String {
    pinjoint_fmu::pin_joint::INFO.guid()
}

pub fn vr(name: &str) -> u32 {
    let info = &*pinjoint_fmu::pin_joint::INFO;
    info.variables[info.index_by_name(name).unwrap_or_else(|| panic!("no variable {name}"))].value_reference
}

pub fn set(c: Fmi2Component, name: &str, v: f64) -> i32 {
    let r = [vr(name)];
    unsafe { fmi2SetReal(c, r.as_ptr(), 1, [v].as_ptr()) }
}

pub fn get(c: Fmi2Component, name: &str) -> f64 {
    try_get(c, name).unwrap_or_else(|s| panic!("fmi2GetReal({name}) returned {s}"))
}

pub fn try_get(c: Fmi2Component, name: &str) -> Result<f64, i32> {
    let r = [vr(name)];
    let mut v = [f64::NAN];
    let s = unsafe { fmi2GetReal(c, r.as_ptr(), 1, v.as_mut_ptr()) };
    if s == 0 { Ok(v[0]) } else { Err(s) }
}

pub const OUTPUTS: [&str; 10] = [
    "torque",
    "friction_coefficient",
    "film_thickness",
    "lambda_ratio",
    "fluid_load_fraction",
    "asperity_load_fraction",
    "mean_pressure",
    "sommerfeld_number",
    "power_loss",
    "dissipated_energy",
];

pub fn all_outputs(c: Fmi2Component) -> Vec<f64> {
    OUTPUTS.iter().map(|n| get(c, n)).collect()
}
