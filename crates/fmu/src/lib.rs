//! # pinjoint-fmu
//!
//! The FMU shared library: the models PinJoint and PinJointRig (and the PassThrough
//! benchmark baseline, `pinjoint-bench`), each plugged into the generic
//! [`fmi_layer::fmi2`] layer. The registry below is passed to that layer from this
//! root with [`fmi_layer::export_fmi2!`]; `fmi2Instantiate` finds a model in it by GUID.
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

use fmi_layer::fmi2::variables::ModelInfo;

pub use info::{model_info, requirements_html, LEGAL};

fmi_layer::export_fmi2!(crate::registry);
fmi_layer::export_fmi3!(crate::registry);

/// Every model the shared library serves.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*pin_joint::INFO, &*pin_joint_rig::INFO, &*pass_through::INFO]
}
