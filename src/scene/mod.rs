//! Scenes: the joint model inside a mechanism, as a system simulation puts it (issue 28).
//!
//! [`free_fall`]: a main landing gear's free-fall (gravity) extension through a cold soak. The
//! leg swings down about its trunnion under gravity, slowed by the retraction actuator throttled
//! as a damper; near the down position a lock spring drives the lock links over centre. The
//! trunnion pins' friction is the joint model's with the presliding state
//! ([`crate::zero_velocity`]), at the load the leg's dynamics put on them; the lock margin
//! compares the lock spring with the lock-link pivots' breakaway torque. CS 25.729 asks for the
//! friction loads of the mechanism and the temperature range in this analysis. The parameters
//! ([`params::FreeFallParams`]) are illustrative of a narrow-body main gear, assumed, not
//! taken from a specific aircraft.
//!
//! ```
//! use pinjoint::scene::{simulate, FreeFallParams};
//! let outcome = simulate(&FreeFallParams::default(), &pinjoint::Params::default(), 293.15).unwrap();
//! assert!(outcome.locked && outcome.time_to_lock > 1.0 && outcome.lock_margin > 0.0);
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod params;
pub mod trunnion;
pub mod free_fall;

pub use error::SceneError;
pub use free_fall::{simulate, FreeFallOutcome, Sample};
pub use params::FreeFallParams;

#[cfg(test)]
mod tests;
