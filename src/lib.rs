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
//! The modules, by concern (each folder one concern), in dependency order: each uses only
//! those above it, but for `params` and `rheology`, which use each other's files (the
//! parameter checks use the grease's defaults and Roelands' temperature factor; the viscosity
//! takes the parameter set's lubricant); `tests/module_graph.py` checks it:
//!
//! | group | what it holds |
//! |---|---|
//! | `numerics` (internal) | inlined exp/ln/sin-cos, the bracketed Newton solver, the table cache |
//! | [`film`] | Moes' central film (eqs. 12–14), h_min, the starved inlet, the grease's oil supply |
//! | [`rheology`] | Roelands viscosity (eq. 5), Bair–Winer limiting shear (eq. 4), temperature, the grease |
//! | [`journal`] | the joint as a finite journal bearing (Reynolds equation, Raimondi & Boyd) |
//! | [`params`] | the parameter set (Tables 1–3 and the extensions' sections), one table of them |
//! | [`clearance`] | the torque of the grease in the clearance outside the contact |
//! | [`contact`] | reduced radius, E', Hertz (eq. 6), Greenwood–Williamson F_{3/2} (eq. 16), asperities (eqs. 17–19) |
//! | [`load_sharing`] | the solve of eqs. 9, 13, 19 for γ1, γ2, h_c, and its start table |
//! | [`paper`], [`validity`] | the paper's test conditions; where the model was checked |
//! | [`composite`] | the complete model: journal weight, composite film, clearance torque |
//! | [`joint`] | [`Joint`]: μ (eq. 10), torque (eq. 11), every output at an [`OperatingPoint`] |
//! | [`record`] | the one result record the front ends write |
//! | [`fidelity`], [`zero_velocity`], [`batch`] | the levels of evaluation, friction at rest, many joints at once |
//! | [`rig`], [`scene`] | the paper's test rig as a dynamic model; the joint in a mechanism |
//!
//! ```
//! use pinjoint::{Joint, Params};
//! let joint = Joint::new(&Params::default()).unwrap();
//! let op = joint.evaluate(20e3, 0.2).unwrap(); // 20 kN, 0.2 rad/s
//! assert!(op.friction_coefficient <= 0.12 && op.friction_coefficient > 0.11);
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
// Numerical helpers, the film and rheology relations (the parameter set uses their formulas
// and defaults; the rheology's viscosity takes the parameter set's lubricant), the journal
// bearing, the parameters, the grease in the clearance:
pub(crate) mod numerics;
pub mod film;
pub mod rheology;
pub mod journal;
pub mod params;
pub mod clearance;
// The paper's equations on a parameter set:
pub mod contact;
pub mod load_sharing;
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
