//! A minimal host for the PinJointRig FMU in the Rust tests: the exported `fmi2*`
//! functions called directly (logger from `tests/common`), names resolved through
//! the rig's variable table.
#![allow(dead_code)]

#[path = "../common/mod.rs"]
mod common;
pub use common::Host;

use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::fmi2DoStep;
use fmi_layer::fmi2::types::*;
use fmi_layer::fmi2::variables::Kind;
use pinjoint_fmu::pin_joint_rig::INFO;

pub const OK: i32 = 0;
pub const ERROR: i32 = 3;

/// Every output, in table order.
pub const OUTPUTS: [&str; 12] = [
    "angle",
    "angular_velocity",
    "torque",
    "friction_torque",
    "friction_coefficient",
    "film_thickness",
    "fluid_load_fraction",
    "stuck",
    "commanded_angle",
    "actuator_work",
    "friction_dissipation",
    "kinetic_energy",
];

pub fn guid() -> String {
    INFO.guid()
}

pub fn vr(name: &str) -> u32 {
    INFO.variables[INFO.index_by_name(name).unwrap_or_else(|| panic!("no variable {name}"))].value_reference
}

pub fn kind(name: &str) -> Kind {
    INFO.variables[INFO.index_by_name(name).unwrap()].kind
}

/// Set any variable, converting to its type (Boolean: non-zero is true).
pub fn set(c: Fmi2Component, name: &str, v: f64) -> i32 {
    let r = [vr(name)];
    unsafe {
        match kind(name) {
            Kind::Real => fmi2SetReal(c, r.as_ptr(), 1, [v].as_ptr()),
            Kind::Integer | Kind::Enumeration(_) => fmi2SetInteger(c, r.as_ptr(), 1, [v as i32].as_ptr()),
            Kind::Boolean => fmi2SetBoolean(c, r.as_ptr(), 1, [(v != 0.0) as i32].as_ptr()),
        }
    }
}

pub fn try_get(c: Fmi2Component, name: &str) -> Result<f64, i32> {
    let r = [vr(name)];
    let (s, v) = unsafe {
        match kind(name) {
            Kind::Real => {
                let mut v = [f64::NAN];
                (fmi2GetReal(c, r.as_ptr(), 1, v.as_mut_ptr()), v[0])
            }
            Kind::Integer | Kind::Enumeration(_) => {
                let mut v = [-7];
                (fmi2GetInteger(c, r.as_ptr(), 1, v.as_mut_ptr()), v[0] as f64)
            }
            Kind::Boolean => {
                let mut v = [-7];
                (fmi2GetBoolean(c, r.as_ptr(), 1, v.as_mut_ptr()), v[0] as f64)
            }
        }
    };
    if s == OK { Ok(v) } else { Err(s) }
}

pub fn get(c: Fmi2Component, name: &str) -> f64 {
    try_get(c, name).unwrap_or_else(|s| panic!("get({name}) returned {s}"))
}

pub fn outputs(c: Fmi2Component) -> Vec<f64> {
    OUTPUTS.iter().map(|n| get(c, n)).collect()
}

pub fn instantiate(h: &Host) -> Fmi2Component {
    let c = h.instantiate_with("rig", FMI2_CO_SIMULATION, &guid(), Some("file:///tmp/resources"), false);
    assert!(!c.is_null(), "instantiate failed: {:?}", h.messages());
    c
}

/// Instantiate, set `sets`, initialize at `start`.
pub fn ready_at(h: &Host, start: f64, sets: &[(&str, f64)]) -> Fmi2Component {
    let c = instantiate(h);
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, start, 0, 0.0), OK);
    for (n, v) in sets {
        assert_eq!(set(c, n, *v), OK, "{n}: {}", h.last());
    }
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
    c
}

pub fn ready(h: &Host, sets: &[(&str, f64)]) -> Fmi2Component {
    ready_at(h, 0.0, sets)
}

/// Step from `t` to `t_next` and return the outputs there.
pub fn step(h: &Host, c: Fmi2Component, t: f64, t_next: f64) -> Vec<f64> {
    assert_eq!(fmi2DoStep(c, t, t_next - t, 0), OK, "doStep({t}, {}): {}", t_next - t, h.last());
    outputs(c)
}

pub fn free(c: Fmi2Component) {
    unsafe { fmi2FreeInstance(c) };
}
