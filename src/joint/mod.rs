//! The pin joint at one operating point: friction coefficient (eq. 10), torque (eq. 11),
//! Sommerfeld number (eq. 20), λ (eq. 21) and everything the load-sharing solve gives.
//!
//! - [`Joint`] (`model.rs`): the validated parameter set with its precomputed groups, built
//!   for a lubricant temperature; its accessors and validity edges.
//! - `load_terms.rs`: what depends on the load alone ([`LoadTerms`], [`LoadSpeed`]): Hertz,
//!   the rheology at p_m, the Sommerfeld number, the torque at rest.
//! - `evaluate.rs`: the solve at an operating point and the [`OperatingPoint`] from its root
//!   ([`Joint::evaluate`], [`Joint::friction_at`], [`Friction`], the one-shot [`evaluate`]).
//! - `outputs.rs`: h_min and the complete model's clearance outputs.
//! - `operating_point.rs`: [`OperatingPoint`]; `regime.rs`: [`Regime`]; `error.rs`:
//!   [`ModelError`], [`EvaluateError`].

mod regime;
mod error;
mod operating_point;
mod model;
mod load_terms;
mod outputs;
mod evaluate;

pub use error::{EvaluateError, ModelError};
pub use evaluate::{evaluate, Friction, START_AGREEMENT};
pub use load_terms::{LoadSpeed, LoadTerms};
pub use model::Joint;
pub use operating_point::{opposing, OperatingPoint};
pub use regime::{Regime, REGIME_SHARE};
