//! The one FMI host of the Rust tests, for any model of the FMU library: calls the
//! exported `fmi2*` functions directly, records every logger message, and resolves
//! variable names through the model's own table (`Host::for_model`). The PinJoint
//! tests use it directly (`Host::new()` and the free `set`/`get`); [`crate::rig_host`] binds
//! the same functions to PinJointRig.
// The functions take the instance handle a test got from `fmi2Instantiate` and hand it to the
// FMU's exported functions, as a host does; the FMU checks the handle (a test of misuse passes
// a bad one on purpose), so they stay safe to call.
#![allow(clippy::not_unsafe_ptr_arg_deref)]

use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::fmi2DoStep;
use fmi_layer::fmi2::types::*;
use fmi_layer::core::variables::{Kind, ModelInfo};
use pinjoint_fmu::fmi2Instantiate;
use std::ffi::{c_char, CStr, CString};
use std::sync::Mutex;

/// One message the FMU logged.
#[derive(Debug, Clone)]
pub struct Msg {
    /// The status it was logged with (`fmi2OK` = 0 … `fmi2Fatal` = 4).
    pub status: i32,
    /// Its category (`logEvents`, `logStatusError`, …).
    pub category: String,
    /// The message.
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

/// The logger callback that records every message into the host's log.
pub fn logger() -> Fmi2CallbackLogger {
    // SAFETY: see `record`.
    unsafe { std::mem::transmute::<*const (), Fmi2CallbackLogger>(record as *const ()) }
}

/// A host of one model of the FMU library: its callbacks and the messages they recorded.
pub struct Host {
    /// Every message logged so far.
    pub log: Box<Mutex<Vec<Msg>>>,
    /// The callbacks handed to `fmi2Instantiate` (their environment is `log`).
    pub callbacks: Box<Fmi2CallbackFunctions>,
    /// The model this host instantiates.
    pub info: &'static ModelInfo,
}

impl Default for Host {
    /// A host of PinJoint ([`Host::new`]).
    fn default() -> Self {
        Self::new()
    }
}

impl Host {
    /// A host of PinJoint.
    pub fn new() -> Self {
        Self::for_model(&pinjoint_fmu::pin_joint::INFO)
    }

    /// A host of any model of the library.
    pub fn for_model(info: &'static ModelInfo) -> Self {
        let log = Box::new(Mutex::new(Vec::new()));
        let env = &*log as *const Mutex<Vec<Msg>> as Fmi2ComponentEnvironment;
        let callbacks = Box::new(Fmi2CallbackFunctions {
            logger: Some(logger()),
            allocate_memory: None,
            free_memory: None,
            step_finished: None,
            component_environment: env,
        });
        Host { log, callbacks, info }
    }

    /// Every message logged so far.
    pub fn messages(&self) -> Vec<Msg> {
        self.log.lock().unwrap().clone()
    }

    /// Forget the messages logged so far.
    pub fn clear(&self) {
        self.log.lock().unwrap().clear();
    }

    /// The last message, for assertions.
    pub fn last(&self) -> String {
        self.messages().last().map(|m| m.text.clone()).unwrap_or_default()
    }

    /// A Co-Simulation instance named `name` with debug logging on (so logEvents reach the
    /// host), `sets` applied, initialized at t = 0.
    pub fn logged(&self, name: &str, sets: &[(&str, f64)]) -> Fmi2Component {
        let c = self.instantiate_with(name, 1, &self.info.guid(), Some("file:///tmp"), true);
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
        for (n, v) in sets {
            assert_eq!(set_in(self.info, c, n, *v), OK, "{n}: {}", self.last());
        }
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", self.last());
        c
    }

    /// `fmi2Instantiate` with these arguments (the instance may be null).
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
                i32::from(logging_on),
            )
        }
    }

    /// A Co-Simulation instance of the model (must succeed), logging off.
    pub fn instantiate(&self) -> Fmi2Component {
        let c = self.instantiate_with(self.info.model_identifier, FMI2_CO_SIMULATION, &self.info.guid(), Some("file:///tmp/resources"), false);
        assert!(!c.is_null(), "instantiate failed: {:?}", self.messages());
        c
    }

    /// Instantiate, set up the experiment at t = 0 without a stop time and enter
    /// initialization mode.
    pub fn init_mode(&self) -> Fmi2Component {
        let c = self.instantiate();
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        c
    }

    /// Instantiate, set up the experiment at `start`, set `sets` (parameters and inputs, by
    /// name, each accepted), enter initialization mode; the instance and what
    /// `fmi2ExitInitializationMode` returned.
    pub fn initialize_at(&self, start: f64, sets: &[(&str, f64)]) -> (Fmi2Component, i32) {
        let c = self.instantiate();
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, start, 0, 0.0), OK);
        for (n, v) in sets {
            assert_eq!(set_in(self.info, c, n, *v), OK, "{n}: {}", self.last());
        }
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        (c, fmi2ExitInitializationMode(c))
    }

    /// [`Host::initialize_at`] t = 0.
    pub fn initialize(&self, sets: &[(&str, f64)]) -> (Fmi2Component, i32) {
        self.initialize_at(0.0, sets)
    }

    /// Instantiate, set `sets` (parameters and inputs, by name), initialize at `start`.
    pub fn ready_at(&self, start: f64, sets: &[(&str, f64)]) -> Fmi2Component {
        let (c, status) = self.initialize_at(start, sets);
        assert_eq!(status, OK, "{}", self.last());
        c
    }

    /// [`Host::ready_at`] t = 0.
    pub fn ready(&self, sets: &[(&str, f64)]) -> Fmi2Component {
        self.ready_at(0.0, sets)
    }

    /// Step from `t` to `t_next` and return every output of the model there.
    pub fn step(&self, c: Fmi2Component, t: f64, t_next: f64) -> Vec<f64> {
        assert_eq!(fmi2DoStep(c, t, t_next - t, 0), OK, "doStep({t}, {}): {}", t_next - t, self.last());
        outputs_in(self.info, c)
    }
}

/// `fmi2OK`.
pub const OK: i32 = 0;
/// `fmi2Error`.
pub const ERROR: i32 = 3;

fn index_in(info: &ModelInfo, name: &str) -> usize {
    info.index_by_name(name).unwrap_or_else(|| panic!("{} has no variable {name}", info.model_name))
}

/// The value reference of `name` in `info`'s table.
pub fn vr_in(info: &ModelInfo, name: &str) -> u32 {
    info.variables[index_in(info, name)].value_reference
}

/// Set any variable, through the setter of its type (Boolean: non-zero is true).
pub fn set_in(info: &ModelInfo, c: Fmi2Component, name: &str, v: f64) -> i32 {
    let i = index_in(info, name);
    let r = [info.variables[i].value_reference];
    unsafe {
        match info.variables[i].kind {
            Kind::Real => fmi2SetReal(c, r.as_ptr(), 1, [v].as_ptr()),
            Kind::Integer | Kind::Enumeration(_) => fmi2SetInteger(c, r.as_ptr(), 1, [v as i32].as_ptr()),
            Kind::Boolean => fmi2SetBoolean(c, r.as_ptr(), 1, [i32::from(v != 0.0)].as_ptr()),
        }
    }
}

/// Get any variable through the getter of its type, as f64; `Err(status)` on failure.
pub fn try_get_in(info: &ModelInfo, c: Fmi2Component, name: &str) -> Result<f64, i32> {
    let i = index_in(info, name);
    let r = [info.variables[i].value_reference];
    let (s, v) = unsafe {
        match info.variables[i].kind {
            Kind::Real => {
                let mut v = [f64::NAN];
                (fmi2GetReal(c, r.as_ptr(), 1, v.as_mut_ptr()), v[0])
            }
            Kind::Integer | Kind::Enumeration(_) => {
                let mut v = [-7];
                (fmi2GetInteger(c, r.as_ptr(), 1, v.as_mut_ptr()), f64::from(v[0]))
            }
            Kind::Boolean => {
                let mut v = [-7];
                (fmi2GetBoolean(c, r.as_ptr(), 1, v.as_mut_ptr()), f64::from(v[0]))
            }
        }
    };
    if s == OK { Ok(v) } else { Err(s) }
}

/// Every output of the model, in table order.
pub fn outputs_in(info: &ModelInfo, c: Fmi2Component) -> Vec<f64> {
    info.variables
        .iter()
        .filter(|v| v.causality == fmi_layer::core::variables::Causality::Output)
        .map(|v| try_get_in(info, c, &v.name).unwrap_or_else(|s| panic!("get({}) returned {s}", v.name)))
        .collect()
}

/// Free an instance.
pub fn free(c: Fmi2Component) {
    unsafe { fmi2FreeInstance(c) };
}

/// The instance's FMU state (`fmi2GetFMUstate`, which must succeed).
pub fn get_state(c: Fmi2Component) -> Fmi2FmuState {
    let mut s: Fmi2FmuState = std::ptr::null_mut();
    assert_eq!(unsafe { fmi2GetFMUstate(c, &mut s) }, OK);
    s
}

/// A state serialized (size, then the bytes; both must succeed).
pub fn serialize(c: Fmi2Component, s: Fmi2FmuState) -> Vec<u8> {
    let mut n = 0usize;
    assert_eq!(unsafe { fmi2SerializedFMUstateSize(c, s, &mut n) }, OK);
    let mut buf = vec![0u8; n];
    assert_eq!(unsafe { fmi2SerializeFMUstate(c, s, buf.as_mut_ptr() as *mut Fmi2Byte, n) }, OK);
    buf
}

/// `bytes` deserialized into a new state, or the status of the refusal.
pub fn deserialize(c: Fmi2Component, bytes: &[u8]) -> Result<Fmi2FmuState, i32> {
    let mut s: Fmi2FmuState = std::ptr::null_mut();
    let st = unsafe { fmi2DeSerializeFMUstate(c, bytes.as_ptr() as *const Fmi2Byte, bytes.len(), &mut s) };
    if st == OK { Ok(s) } else { Err(st) }
}

fn pin_joint() -> &'static ModelInfo {
    &pinjoint_fmu::pin_joint::INFO
}

/// A PinJoint Co-Simulation instance named "joint" with debug logging on, `sets` applied,
/// initialized at t = 0 ([`Host::logged`]).
pub fn logged(h: &Host, sets: &[(&str, f64)]) -> Fmi2Component {
    h.logged("joint", sets)
}

/// A PinJoint host and an instance of it with the default parameters, initialized at t = 0.
pub fn ready_pin_joint() -> (Host, Fmi2Component) {
    let h = Host::new();
    let c = h.ready(&[]);
    (h, c)
}

/// PinJoint's GUID.
pub fn guid() -> String {
    pin_joint().guid()
}

/// A PinJoint value reference.
pub fn vr(name: &str) -> u32 {
    vr_in(pin_joint(), name)
}

/// Set a PinJoint variable.
pub fn set(c: Fmi2Component, name: &str, v: f64) -> i32 {
    set_in(pin_joint(), c, name, v)
}

/// Get a PinJoint variable (panics on a non-OK status).
pub fn get(c: Fmi2Component, name: &str) -> f64 {
    try_get(c, name).unwrap_or_else(|s| panic!("fmi2GetReal({name}) returned {s}"))
}

/// Get a PinJoint variable.
pub fn try_get(c: Fmi2Component, name: &str) -> Result<f64, i32> {
    try_get_in(pin_joint(), c, name)
}

/// PinJoint's outputs of the paper's model, in table order.
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

/// The values of [`OUTPUTS`].
pub fn all_outputs(c: Fmi2Component) -> Vec<f64> {
    OUTPUTS.iter().map(|n| get(c, n)).collect()
}

/// `zero_velocity.model = band` (0), the stateless law: set it where a test checks the torque
/// against the library's stateless value or the band's ramp (the band is bit for bit the law
/// before the presliding model, which is the default).
pub const BAND: (&str, f64) = ("zero_velocity.model", 0.0);
