//! # fmi-layer
//!
//! A generic FMI export layer for Rust models, after the structure of the
//! Reference-FMUs: everything the standard prescribes lives here (C types, the
//! exported functions, the state machine with one mask per function, logging by
//! category, value-reference dispatch, FMU state get/set/serialize, and the
//! modelDescription.xml generator); a model only stores values, computes its
//! outputs and advances.
//!
//! This crate knows no physics. The shared library that exports the models (the
//! `pinjoint-fmu` crate) passes its registry of models in from its own root with
//! [`export_fmi2!`], the one entry point that must choose a model by GUID.

pub mod error;
pub mod fmi2;
pub mod fmi3;
mod xml;

pub use error::{CallError, StateFormatError, XmlError};

use numfmt as fmt;
