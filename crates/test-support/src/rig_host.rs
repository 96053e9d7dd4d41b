//! The PinJointRig bindings of the one test host ([`crate::fmi2_host`]): the same functions,
//! with names resolved through the rig's variable table.
// The instance handles go to the FMU's exported functions, which check them (see fmi2_host).
#![allow(clippy::not_unsafe_ptr_arg_deref)]

use crate::fmi2_host as common;
pub use crate::fmi2_host::{deserialize, free, get_state, serialize, Host, ERROR, OK};

use fmi_layer::fmi2::types::Fmi2Component;
use fmi_layer::core::variables::{Kind, ModelInfo};

fn rig() -> &'static ModelInfo {
    &pinjoint_fmu::pin_joint_rig::INFO
}

/// The position of output `name` in [`outputs`] (the table's order of the outputs).
pub fn output_index(name: &str) -> usize {
    rig().variables
        .iter()
        .filter(|v| v.causality == fmi_layer::core::variables::Causality::Output)
        .position(|v| v.name == name)
        .unwrap_or_else(|| panic!("PinJointRig has no output {name}"))
}

/// The rig's GUID.
pub fn guid() -> String {
    rig().guid()
}

/// A rig value reference.
pub fn vr(name: &str) -> u32 {
    common::vr_in(rig(), name)
}

/// The FMI type of a rig variable.
pub fn kind(name: &str) -> Kind {
    rig().variables[rig().index_by_name(name).unwrap()].kind
}

/// Set any rig variable, converting to its type (Boolean: non-zero is true).
pub fn set(c: Fmi2Component, name: &str, v: f64) -> i32 {
    common::set_in(rig(), c, name, v)
}

/// Get any rig variable as f64.
pub fn try_get(c: Fmi2Component, name: &str) -> Result<f64, i32> {
    common::try_get_in(rig(), c, name)
}

/// Get any rig variable (panics on a non-OK status).
pub fn get(c: Fmi2Component, name: &str) -> f64 {
    try_get(c, name).unwrap_or_else(|s| panic!("get({name}) returned {s}"))
}

/// Every output, in table order.
pub fn outputs(c: Fmi2Component) -> Vec<f64> {
    common::outputs_in(rig(), c)
}

/// A rig host's instance, not initialized.
pub fn instantiate(h: &Host) -> Fmi2Component {
    h.instantiate()
}

/// Instantiate, set `sets`, initialize at `start`.
pub fn ready_at(h: &Host, start: f64, sets: &[(&str, f64)]) -> Fmi2Component {
    h.ready_at(start, sets)
}

/// Instantiate, set `sets`, initialize at 0.
pub fn ready(h: &Host, sets: &[(&str, f64)]) -> Fmi2Component {
    h.ready(sets)
}

/// Step from `t` to `t_next` and return the outputs there.
pub fn step(h: &Host, c: Fmi2Component, t: f64, t_next: f64) -> Vec<f64> {
    h.step(c, t, t_next)
}

/// A host of PinJointRig.
pub fn new_host() -> Host {
    Host::for_model(rig())
}

/// A Co-Simulation instance named "rig" with debug logging on, `sets` applied, initialized at
/// t = 0 ([`Host::logged`]).
pub fn logged(h: &Host, sets: &[(&str, f64)]) -> Fmi2Component {
    h.logged("rig", sets)
}

/// A PinJointRig host and an instance of it with the default parameters, initialized at t = 0.
pub fn ready_rig() -> (Host, Fmi2Component) {
    let h = new_host();
    let c = h.ready(&[]);
    (h, c)
}
