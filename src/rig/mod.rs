//! Integrated articulation mode: the paper's torsion-actuator rig (section 4) around the joint.
//!
//! A servo-hydraulic torsional actuator in angle control swings the pin through sine strokes
//! while the friction core gives the joint's torque at the current load and speed; at each
//! stroke end the joint may stick until the actuator torque exceeds the breakaway torque.
//!
//! - [`error`]: [`RigError`], why a rig call failed.
//! - [`params`]: the `[rig]` constants, their equations and the reasoning for the defaults;
//!   [`config`]: one file with the model's sections and `[rig]`.
//! - [`excitation`]: command angle and load as functions of time, and held (FMU) inputs.
//! - `state`: the integrated state vector and its indices.
//! - [`dynamics`]: the ODE of each phase (slip, stick, regularised) and the friction torque.
//! - [`integrate`]: segments with `ode_solvers` (Dopri5, Dop853, RK4), event location.
//! - `linear_loop`: the loop linearised about a slip and its matrix exponential (modal form).
//! - `lawson`: Dopri5 in Lawson (integrating-factor) form, the linearised loop solved exactly
//!   (`dopri5-dense` in slip).
//! - `steady`: the loop's steady response to the sine command (`dopri5-dense` integrates the
//!   deviation from it).
//! - [`sim`]: [`RigSim`], the stepping simulator (state get/set, serialisation).
//! - [`analysis`]: the paper's cycle-average friction coefficient (eq. 11), energy balance.
//!
//! ```
//! use pinjoint::rig::{RigConfig, RigSim, cycle_average_friction_coefficient};
//! let mut cfg = RigConfig::default();
//! cfg.rig.frequency = 0.3;
//! let mut sim = RigSim::new(&cfg).unwrap();
//! let trace = sim.run(2.0 / 0.3, 1e-3 / 0.3).unwrap(); // two cycles, 1000 samples a cycle
//! let mu = cycle_average_friction_coefficient(&trace, 0.3, cfg.model.geometry.pin_radius, 1).unwrap();
//! assert!(mu > 0.1 && mu < 0.125, "{mu}");
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod params;
pub mod config;
pub mod excitation;
pub(crate) mod state;
pub(crate) mod linear_loop;
pub mod dynamics;
pub(crate) mod lawson;
pub(crate) mod steady;
pub mod integrate;
pub mod sim;
pub mod analysis;
pub mod record;

pub use analysis::{core_torque, cycle_average_friction_coefficient, energy_residual, run_cycles, stroke_average, time_mean};
pub use config::RigConfig;
pub use dynamics::Phase;
pub use excitation::{Excitation, FnExcitation, Inputs, SineCommand, SineDrive, StepLoad};
pub use params::{Formulation, Method, RigParams, RIG_PARAMS};
pub use sim::{Node, RigSim, RigState, Sample, Stats};
pub use error::RigError;
