//! # fmi-layer
//!
//! A generic FMI export layer for Rust models, after the structure of the
//! Reference-FMUs: everything the standard prescribes lives here (C types, the
//! exported functions, the state machine with one mask per function, logging by
//! category, value-reference dispatch, FMU state get/set/serialize, and the
//! modelDescription.xml generator); a model only stores values, computes its
//! outputs and advances.
//!
//! Three parts, as Reference-FMUs keeps `fmi2Functions.c` and `fmi3Functions.c` over one
//! `cosimulation.c`:
//! - [`core`]: version-neutral, written once: the [`Model`](core::Model) trait a model
//!   implements once for both standards, the variable table, the instance, the state machine,
//!   the FMU state and its serialized format, logging, value-reference lookup, the guard every
//!   export runs through;
//! - [`fmi2`] and [`fmi3`]: symmetric thin shims, each with only its version's exported
//!   functions (`api`), C types (`types`) and modelDescription.xml generator (`xml`), and what
//!   its standard defines its own way: the [`Rules`](core::Rules) of its instances (which
//!   getter reads which type, a capability's name), the state masks of its own functions, its
//!   status names and (FMI 2.0) status-kind codes. Neither names the other, and the core
//!   names neither (a test, `tests/version_shims.rs`, fails if one does).
//!
//! Errors are typed at every boundary ([`error`]): [`CallError`] for why an exported
//! function fails (its text is what the host's logger receives), [`StateFormatError`] for a
//! serialized FMU state that is not well formed, [`XmlError`] for a model table no valid
//! modelDescription.xml can be written from.
//!
//! This crate knows no physics. The shared library that exports the models (the
//! `pinjoint-fmu` crate) passes its registry of models in from its own root with
//! [`export_fmi2!`] and [`export_fmi3!`], the entry points that must choose a model by GUID
//! or instantiation token.

// Modules in dependency order, lowest first: `fmt` (numfmt, another crate); `core` (whose
// leaves `error` uses; the rest of `core` uses `error`); `error`; the shims `fmi2` and `fmi3`,
// which name the core and `error`, never each other; neither `core` nor `error` names a shim.
pub mod core;
pub mod error;
pub mod fmi2;
pub mod fmi3;
#[cfg(test)]
mod tests;

pub use error::{CallError, StateFormatError, XmlError};

// The number formatting every message uses (`crate::fmt::…`): another crate's, so no file of
// this crate depends on the root through it.
pub(crate) use numfmt as fmt;
