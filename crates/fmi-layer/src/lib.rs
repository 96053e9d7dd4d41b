//! # fmi-layer
//!
//! A generic FMI export layer for Rust models, after the structure of the
//! Reference-FMUs: everything the standard prescribes lives here (C types, the
//! exported functions, the state machine with one mask per function, logging by
//! category, value-reference dispatch, FMU state get/set/serialize, and the
//! modelDescription.xml generator); a model only stores values, computes its
//! outputs and advances.
//!
//! Errors are typed at every boundary ([`error`]): [`CallError`] for why an exported
//! function fails (its text is what the host's logger receives), [`StateFormatError`] for a
//! serialized FMU state that is not well formed, [`XmlError`] for a model table no valid
//! modelDescription.xml can be written from. The parts both standards share (the instance,
//! state machine, FMU state functions, typed get/set bodies, the XML writer for the common
//! attributes) exist once; `fmi2` and `fmi3` only spell their own functions and elements.
//!
//! This crate knows no physics. The shared library that exports the models (the
//! `pinjoint-fmu` crate) passes its registry of models in from its own root with
//! [`export_fmi2!`], the one entry point that must choose a model by GUID.

// Modules in dependency order, lowest first; each file uses only files listed before it:
// `fmt` (numfmt, another crate); in `fmi2`, the leaves `types`, `state`, `logging`, `interface`, `model`;
// then `error` (which uses only those leaves); then the rest of `fmi2` (`bytes`, `snapshot`,
// `variables`, `instance`, `api`), the shared XML writer `xml`, `fmi2::xml`, and `fmi3`.
pub mod fmi2;
pub mod error;
mod xml;
pub mod fmi3;
#[cfg(test)]
mod tests;

pub use error::{CallError, StateFormatError, XmlError};

// The number formatting every message uses (`crate::fmt::…`): another crate's, so no file of
// this crate depends on the root through it.
pub(crate) use numfmt as fmt;
