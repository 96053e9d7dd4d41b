//! # pinjoint
//!
//! Frictional torque of a grease-lubricated aircraft landing-gear pin joint, after
//! the mixed-lubrication model of the paper *Model and Experiments to Determine Lubricant Film
//! Formation and Frictional Torque in Aircraft Landing Gear Pin Joints* (the equations, errata
//! and check values are in the repository's `docs/model.md`):
//! Greenwood–Williamson asperity contact, Moes central film thickness scaled by
//! the load-sharing factors γ1/γ2, Roelands viscosity and Bair–Winer limiting shear.
//!
//! This crate is the physics layer of the workspace (see ARCHITECTURE.md): pure
//! functions and small value types, no I/O, no FMI, no command line. The FMUs
//! (`pinjoint-fmu`), the `pinjoint` command line (`pinjoint-cli`) and the Python
//! package build on it; nothing here depends on them.
//!
//! The physics modules:
//! [`params`] → [`contact`], [`viscosity`], [`gw`], [`film`], [`asperity`]
//! → [`mixed`] (the load-sharing solve) → [`joint`] (μ, torque, every output).
//!
//! ```
//! use pinjoint::{Joint, Params};
//! let joint = Joint::new(&Params::default()).unwrap();
//! let op = joint.evaluate(20e3, 0.2).unwrap(); // 20 kN, 0.2 rad/s
//! assert!(op.friction_coefficient <= 0.12 && op.friction_coefficient > 0.11);
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
// Numerical helpers and the parameters (the starved-inlet relation's parameters are a section):
pub mod fast_math;
pub mod fast_ln;
pub mod newton;
pub mod table_cache;
pub mod starvation;
pub mod roelands_temperature;
// The joint as a journal bearing and the grease in its clearance (issue 28; no parameters):
pub mod journal;
pub mod grease;
pub mod clearance;
pub mod params;
// The paper's equations:
pub mod gw;
pub mod viscosity;
pub mod contact;
pub mod film;
pub mod min_film;
pub mod asperity;
pub mod mixed;
pub mod cold_supply;
pub mod solve_start;
pub mod paper;
pub mod validity;
pub mod composite;
pub mod joint;
// What the front ends use:
pub mod fidelity;
pub mod record;
pub mod rig;
pub mod zero_velocity;
#[cfg(feature = "batch")]
pub mod batch;
// Scenes that put the joint in a mechanism:
pub mod scene;

/// Numbers in messages in the short round-trip form (the `pinjoint-numfmt` crate).
pub use numfmt as fmt;
pub use joint::{Joint, ModelError, OperatingPoint, Regime};
pub use params::{ParamError, Params};
pub use validity::Validity;
