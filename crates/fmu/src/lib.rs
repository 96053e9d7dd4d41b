//! # pinjoint-fmu
//!
//! The FMU shared library: the models PinJoint and PinJointRig (and the PassThrough
//! benchmark baseline, `pinjoint-bench`), each implementing the version-neutral
//! [`fmi_layer::core::Model`] trait once and served through both of the layer's shims, FMI 2.0
//! and FMI 3.0. The registry below is passed to the layer from this root with
//! [`fmi_layer::export_fmi2!`] and [`fmi_layer::export_fmi3!`]; `fmi2Instantiate` finds a
//! model in it by GUID, the `fmi3Instantiate*` functions by the same token.
//!
//! Each model is one declarative variable table ([`table::Table`]): a row declares the
//! variable (XML), reads and stores it, checks it and places it in the FMU state. The rows
//! both models share are written once: [`parameters`] (the parameter file),
//! [`fidelity`] (fidelity, tolerance, envelope), [`inputs`] (load rule, temperature,
//! capacity), [`units`].

// Modules in dependency order, lowest first; each file uses only files listed before it:
// the leaves (the capacity check, the declaration constructor, the documentation pieces, the
// models' shared description, the units), the variable table, the rows both models share,
// then the models.
mod capacity;
pub mod declare;
pub mod doc_table;
pub mod extensions_doc;
mod info;
pub mod platforms_doc;
pub mod units;
pub mod table;
pub mod fidelity;
pub mod inputs;
pub mod parameters;
pub mod validity;
pub mod pass_through;
pub mod pin_joint;
pub mod pin_joint_rig;

use fmi_layer::core::variables::ModelInfo;

pub use info::{model_info, requirements_html, LEGAL};

fmi_layer::export_fmi2!(crate::registry);
fmi_layer::export_fmi3!(crate::registry);

/// Every model the shared library serves.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*pin_joint::INFO, &*pin_joint_rig::INFO, &*pass_through::INFO]
}
