//! What a batch rejects: a setting, an input array, or a joint's operating point.

use crate::fidelity::FidelityError;
use crate::joint::ModelError;
use crate::params::ParamError;
use crate::zero_velocity::ZeroVelocityError;
use thiserror::Error;

/// A rejected batch setting or input. Errors about one joint name the argument and the
/// joint's index, as [`crate::Joint::evaluate`]'s front ends do.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BatchError {
    /// An input array whose length is not the batch's joint count.
    #[error("{argument} has {got} values, the batch has {expected} joints: every input must have one value per joint")]
    Shape {
        /// The argument's name (`angle`, `angular_velocity`, `load`, `temperature`, ...).
        argument: &'static str,
        /// The batch's joint count.
        expected: usize,
        /// The array's length.
        got: usize,
    },
    /// A NaN or infinite input.
    #[error("{argument} = {} {unit} at index {index} is not a finite number", crate::fmt::Num(*value))]
    NotFinite {
        /// The argument's name.
        argument: &'static str,
        /// The joint's index.
        index: usize,
        /// The value given.
        value: f64,
        /// Its unit.
        unit: &'static str,
    },
    /// An invalid host inertia.
    #[error("host_inertia = {} kg.m2 at index {index} is invalid: it must be a number in [0, 1e9] kg.m2 (0: not given)", crate::fmt::Num(*value))]
    HostInertia {
        /// The joint's index.
        index: usize,
        /// The value given (kg·m²).
        value: f64,
    },
    /// An invalid host step (not a finite number ≥ 0).
    #[error("step = {} s at index {index} is invalid: it must be a finite number >= 0", crate::fmt::Num(*value))]
    Step {
        /// The joint's index.
        index: usize,
        /// The value given (s).
        value: f64,
    },
    /// A batch of no joints.
    #[error("a batch needs at least one joint (n = 0)")]
    Empty,
    /// More joints than a batch indexes (n ≥ 2³¹).
    #[error("a batch holds fewer than 2^31 joints (n = {0}): split it")]
    TooMany(usize),
    /// Per-joint parameters whose count is not the joint count.
    #[error("{got} parameter sets were given for {expected} joints: give one shared set or one per joint")]
    ParamCount {
        /// The batch's joint count.
        expected: usize,
        /// Parameter sets given.
        got: usize,
    },
    /// A parameter set rejected (per-joint sets name the first joint using it).
    #[error("parameters of joint {index}: {source}")]
    Params {
        /// The (first) joint with this parameter set.
        index: usize,
        /// The parameter's error.
        source: ParamError,
    },
    /// A temperature the model cannot take (out of the parameter's range).
    #[error("temperature at index {index}: {source}")]
    Temperature {
        /// The joint's index.
        index: usize,
        /// The parameter's error (names lubricant.temperature, its value and unit).
        source: ParamError,
    },
    /// The fidelity settings (tolerance, envelope).
    #[error("fidelity: {0}")]
    Fidelity(FidelityError),
    /// A level (a table, the boundary level) that cannot be built for a joint's parameters
    /// at its temperature.
    #[error("fidelity level for the joint at index {index}: {source}")]
    Level {
        /// The (first) joint asking for it.
        index: usize,
        /// Why it cannot be built.
        source: FidelityError,
    },
    /// The presliding law's settings.
    #[error("{0}")]
    Law(ZeroVelocityError),
    /// An operating point the model cannot take (load beyond capacity, a film beyond the
    /// clearance...).
    #[error("at index {index}: {source}")]
    Model {
        /// The joint's index.
        index: usize,
        /// The model's error.
        source: ModelError,
    },
}
