//! A generic FMI 2.0 Co-Simulation layer: C types, the exported `fmi2*` functions,
//! the standard's state machine (one mask per function), logging by category,
//! value-reference dispatch, FMU state get/set/serialize, and the
//! modelDescription.xml generator.
//!
//! A model plugs in through the [`model::Model`] trait plus a [`variables::ModelInfo`]
//! (variable table, units, default experiment). `fmi2Instantiate` finds the model
//! by GUID among [`crate::fmu::registry`], so one shared library can serve several
//! FMUs (PinJoint, and later PinJointRig), each packaged with its own
//! modelDescription.xml and a copy of the library named for its model identifier.

pub mod api;
pub mod bytes;
pub mod instance;
pub mod logging;
pub mod model;
pub mod snapshot;
pub mod state;
pub mod types;
pub mod variables;
pub mod xml;
