//! What several crates' integration tests share (a dev-dependency only, never published).
//!
//! Each crate owns its tests in its own `tests/` folder; what more than one test file needs
//! lives here, once:
//!
//! - [`paths`]: the workspace root and the files tests read from it (docs pages, the committed
//!   modelDescription files, the fuzz corpora);
//! - [`strategies`]: the proptest strategies the property tests of several crates draw from;
//! - with the `fmu` feature, the FMI 2.0 hosts of the FMU library: `fmi2_host` (the one
//!   host, bound to PinJoint), `rig_host` (the same host bound to PinJointRig) and
//!   `model_table` (the consistency every model's variable table must have);
//! - with the `importer` feature, `packaged`: the FMU packaged from this build's cdylib and
//!   imported by the Rust `fmi` crate.
//!
//! Helpers that only one crate's tests use stay in that crate (`crates/cli/tests/cli_support`,
//! `crates/calibrate/tests/common`, `tests/rig_support`); docs/README.md states the convention.

pub mod paths;
pub mod strategies;

#[cfg(feature = "fmu")]
pub mod fmi2_host;
#[cfg(feature = "fmu")]
pub mod model_table;
#[cfg(feature = "fmu")]
pub mod rig_host;

#[cfg(feature = "importer")]
pub mod packaged;
