//! Why a calibration could not be made. Every variant names the record, the quantity, its
//! value (shortest round-trip form) and unit, so that the user can fix the input.

use pinjoint::{ModelError, ParamError};
use thiserror::Error;

/// A rejected record, option or fit.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CalibrationError {
    /// No records were given.
    #[error("no records to fit")]
    NoRecords,
    /// A column's length differs from the record's `time` column.
    #[error("record {record}: column {column} has {len} values but time has {expected}")]
    Length { record: String, column: &'static str, len: usize, expected: usize },
    /// Neither `angle` nor `angular_velocity` was given.
    #[error("record {record}: needs an angle (rad) or an angular_velocity (rad/s) column")]
    NoKinematics { record: String },
    /// A NaN or infinite value (0-based sample index `row`).
    #[error("record {record}: {column} = {value} {unit} at sample {row} (t = {time} s) is not a finite number")]
    NonFinite { record: String, column: &'static str, row: usize, time: f64, value: f64, unit: &'static str },
    /// Time must increase strictly.
    #[error("record {record}: time does not increase at sample {row}: {previous} s then {time} s")]
    TimeOrder { record: String, row: usize, previous: f64, time: f64 },
    /// The load must be a finite number > 0.
    #[error("record {record}: load = {value} N at sample {row} is invalid: it must be > 0 N")]
    Load { record: String, row: usize, value: f64 },
    /// Too few samples to differentiate and fit.
    #[error("record {record}: {samples} samples is too short: at least {needed} are needed ({why})")]
    TooShort { record: String, samples: usize, needed: usize, why: &'static str },
    /// The record does not move.
    #[error("record {record}: no motion: peak |angular velocity| = {peak} rad/s over the record (angle range {angle_range} rad)")]
    NoMotion { record: String, peak: f64, angle_range: f64 },
    /// An angle range no pin joint sweeps: most likely degrees.
    #[error(
        "record {record}: angle spans {range} rad ({turns} turns): implausible for a pin joint (at most {limit} rad); \
         was the angle recorded in degrees? (as degrees it would span {as_rad} rad)"
    )]
    AngleRange { record: String, range: f64, turns: f64, limit: f64, as_rad: f64 },
    /// A speed no pin joint reaches: most likely deg/s or rpm.
    #[error(
        "record {record}: |angular_velocity| reaches {peak} rad/s, beyond the plausible {limit} rad/s; \
         was it recorded in deg/s (that would be {as_rad} rad/s) or rpm?"
    )]
    SpeedRange { record: String, peak: f64, limit: f64, as_rad: f64 },
    /// The angle's derivative and the given velocity disagree by a factor.
    #[error(
        "record {record}: the derivative of angle is {ratio} times angular_velocity (should be 1){hint}"
    )]
    Inconsistent { record: String, ratio: f64, hint: &'static str },
    /// After the exclusion rule, the data cannot determine μ_c and the torque offset.
    #[error("{what}")]
    Unidentifiable { what: String },
    /// An unknown `--fit` key or option value.
    #[error("{0}")]
    Option(String),
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The friction model failed at a record's operating point.
    #[error("record {record}, sample {row}: {source}")]
    Model { record: String, row: usize, source: ModelError },
    /// The nonlinear fit did not converge.
    #[error("the nonlinear fit did not converge: {0}")]
    NoConvergence(String),
}
