//! The error of the zero-velocity parameters.

use thiserror::Error;

/// A rejected zero-velocity parameter.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ZeroVelocityError {
    /// A parameter out of its range: its name, value, unit and rule.
    #[error("parameter {name} = {}{}{unit} is out of range: {rule}", crate::fmt::Num(*value), if unit.is_empty() { "" } else { " " })]
    Invalid {
        /// The parameter's name, e.g. `zero_velocity.presliding_angle`.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Its unit (empty for a ratio).
        unit: &'static str,
        /// What it must be.
        rule: &'static str,
    },
    /// A model name that is neither `band` nor `presliding` (its first 40 characters).
    #[error("zero_velocity.model = \"{0}\" is not a zero-velocity model: it must be band or presliding")]
    UnknownModel(String),
}
