//! The models this crate packages as FMUs, each plugged into the generic
//! [`crate::fmi2`] layer. `fmi2Instantiate` finds a model here by its GUID.
//! `PassThrough` is a benchmark baseline only (`pinjoint bench`).

pub mod pass_through;
pub mod pin_joint;
pub mod pin_joint_rig;

use crate::fmi2::variables::ModelInfo;

/// Every model the shared library serves.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*pin_joint::INFO, &*pin_joint_rig::INFO, &*pass_through::INFO]
}
