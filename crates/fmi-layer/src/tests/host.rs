//! A minimal host for the tests: records every logged message and instantiates the test
//! models through the layer's own instantiation bodies (FMI 2.0 and FMI 3.0).

use super::linear::registry;
use crate::fmi2::api::common::instantiate_from;
use crate::core::interface::Interface;
use crate::fmi2::types::*;
use crate::core::variables::ModelInfo;
use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::sync::Mutex;

/// The layer always logs with format "%s" and the message as the one variadic argument, so
/// a non-variadic function with that signature reads it on the System V x86-64 and AAPCS64
/// ABIs (stable Rust cannot define a C-variadic function).
unsafe extern "C" fn record2(env: Fmi2ComponentEnvironment, _name: Fmi2String, _status: Fmi2StatusC, _category: Fmi2String, _format: Fmi2String, message: *const c_char) {
    // SAFETY: env is the host's log; the message is NUL-terminated.
    let log = unsafe { &*(env as *const Mutex<Vec<String>>) };
    log.lock().unwrap().push(unsafe { CStr::from_ptr(message) }.to_string_lossy().into_owned());
}

/// The FMI 3.0 logger.
unsafe extern "C" fn record3(env: *mut c_void, _status: c_int, _category: *const c_char, message: *const c_char) {
    // SAFETY: as above.
    let log = unsafe { &*(env as *const Mutex<Vec<String>>) };
    log.lock().unwrap().push(unsafe { CStr::from_ptr(message) }.to_string_lossy().into_owned());
}

/// The host: its log and callbacks (boxed, so their addresses stay put).
pub struct Host {
    log: Box<Mutex<Vec<String>>>,
    callbacks: Box<Fmi2CallbackFunctions>,
}

impl Host {
    pub fn new() -> Self {
        let log = Box::new(Mutex::new(Vec::new()));
        let env = &*log as *const Mutex<Vec<String>> as Fmi2ComponentEnvironment;
        // SAFETY: see `record2`.
        let logger = unsafe { std::mem::transmute::<*const (), Fmi2CallbackLogger>(record2 as *const ()) };
        let callbacks = Box::new(Fmi2CallbackFunctions { logger: Some(logger), allocate_memory: None, free_memory: None, step_finished: None, component_environment: env });
        Host { log, callbacks }
    }

    /// The last message logged.
    pub fn last(&self) -> String {
        self.log.lock().unwrap().last().cloned().unwrap_or_default()
    }

    /// An FMI 2.0 instance of `info` (`fmu_type` 0 = Model Exchange, 1 = Co-Simulation).
    pub fn fmi2(&self, info: &ModelInfo, fmu_type: c_int) -> Fmi2Component {
        let (name, guid) = (CString::new("test").unwrap(), CString::new(info.guid()).unwrap());
        // SAFETY: valid strings and callbacks that outlive the instance.
        let c = unsafe { instantiate_from(&registry(), name.as_ptr(), fmu_type, guid.as_ptr(), std::ptr::null(), &*self.callbacks, 1) };
        assert!(!c.is_null(), "{}", self.last());
        c
    }

    /// An FMI 3.0 instance of `info`.
    pub fn fmi3(&self, info: &ModelInfo, interface: Interface) -> *mut c_void {
        let (name, token) = (CString::new("test").unwrap(), CString::new(info.guid()).unwrap());
        let env = &*self.log as *const Mutex<Vec<String>> as *mut c_void;
        // SAFETY: valid strings; the log outlives the instance.
        let c = unsafe { crate::fmi3::api::instantiate_from(&registry(), interface, name.as_ptr(), token.as_ptr(), std::ptr::null(), 1, 0, env, Some(record3)) };
        assert!(!c.is_null(), "{}", self.last());
        c
    }
}
