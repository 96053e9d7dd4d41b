//! The version-neutral core of the layer: everything FMI 2.0 and FMI 3.0 share, written once,
//! as Reference-FMUs keeps one `cosimulation.c` under `fmi2Functions.c` and
//! `fmi3Functions.c`. The two version shims (the crate's FMI 2.0 and FMI 3.0 modules) only read
//! their C arguments, spell their types, write their modelDescription.xml elements and give
//! the few rules their standard defines its own way ([`Rules`], the masks of their own
//! functions, the names of their status values); this module names neither of them, nothing
//! of either standard in code (`tests/version_shims.rs` checks it).
//!
//! - the model side: the [`Model`] trait a model implements once (for both standards and both
//!   interfaces), its [`ModelInfo`] variable table ([`variables`]), the byte format of its own
//!   state ([`bytes`]);
//! - the instance ([`Instance`]): value checks, output range checks, value-reference lookup
//!   ([`lookup`]), the life-cycle [`state`] machine with one mask per function, the
//!   [`Interface`] it was created for and the [`Rules`] of the standard that created it;
//! - the FMU state ([`snapshot`], `fmu_state`): one snapshot type, one registry of live
//!   states, one serialized format with CRC, so a state taken through one standard is read
//!   back through the other;
//! - logging by category with a rate limit ([`logging`]), behind the [`HostLog`] sink each
//!   shim implements for its host callback;
//! - the guard every export runs through ([`guard`]: NULL and dead instances, masks, error
//!   logging, panic containment) and the bodies the shims share (`values`,
//!   `instantiate`, `model_exchange`);
//! - the C types both standards rename ([`types`]) and the XML writer for the attributes both
//!   modelDescriptions share ([`xml`]).

// Files in dependency order, lowest first; each uses only files listed before it (and
// `crate::error`, which uses only the leaves `types`, `state`, `logging`, `interface`, `model`).
pub mod types;
pub mod state;
pub mod logging;
pub mod interface;
pub mod model;
pub mod bytes;
pub mod snapshot;
pub mod variables;
pub mod lookup;
pub mod instance;
pub mod guard;
pub(crate) mod values;
pub(crate) mod instantiate;
pub(crate) mod fmu_state;
pub(crate) mod model_exchange;
pub mod xml;

pub use instance::{Instance, Interface, Rules};
pub use logging::HostLog;
pub use model::{Model, ModelError, ModelResult};
pub use types::Status;
pub use variables::ModelInfo;
