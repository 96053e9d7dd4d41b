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
    Length {
        /// Name of the offending record.
        record: String,
        /// Name of the column whose length is wrong.
        column: &'static str,
        /// Number of values the column has.
        len: usize,
        /// Number of values in the record's `time` column.
        expected: usize,
    },
    /// Neither `angle` nor `angular_velocity` was given.
    #[error("record {record}: needs an angle (rad) or an angular_velocity (rad/s) column")]
    NoKinematics {
        /// Name of the offending record.
        record: String,
    },
    /// A NaN or infinite value (0-based sample index `row`).
    #[error("record {record}: {column} = {value} {unit} at sample {row} (t = {time} s) is not a finite number")]
    NonFinite {
        /// Name of the offending record.
        record: String,
        /// Name of the column holding the value.
        column: &'static str,
        /// 0-based sample index of the value.
        row: usize,
        /// Time of that sample (s).
        time: f64,
        /// The non-finite value, in `unit`.
        value: f64,
        /// Unit of the column (e.g. `N m`, `rad/s`).
        unit: &'static str,
    },
    /// Time must increase strictly.
    #[error("record {record}: time does not increase at sample {row}: {previous} s then {time} s")]
    TimeOrder {
        /// Name of the offending record.
        record: String,
        /// 0-based index of the first sample whose time does not increase.
        row: usize,
        /// Time of the preceding sample (s).
        previous: f64,
        /// Time of sample `row` (s).
        time: f64,
    },
    /// The load must be a finite number > 0.
    #[error("record {record}: load = {value} N at sample {row} is invalid: it must be > 0 N")]
    Load {
        /// Name of the offending record.
        record: String,
        /// 0-based index of the sample with the invalid load.
        row: usize,
        /// The invalid load (N).
        value: f64,
    },
    /// A temperature that is not a joint's temperature in kelvin, or outside the model's range.
    #[error("record {record}: temperature = {value} K at sample {row} is invalid: {why}")]
    Temperature {
        /// Name of the offending record.
        record: String,
        /// 0-based index of the sample with the invalid temperature.
        row: usize,
        /// The invalid temperature (K).
        value: f64,
        /// What is wrong with it (with a hint when it looks like degrees Celsius).
        why: String,
    },
    /// Too few samples to differentiate and fit.
    #[error("record {record}: {samples} samples is too short: at least {needed} are needed ({why})")]
    TooShort {
        /// Name of the offending record.
        record: String,
        /// Number of samples the record has.
        samples: usize,
        /// Minimum number of samples required.
        needed: usize,
        /// What needs that many samples (differentiation, the fit).
        why: &'static str,
    },
    /// The record does not move.
    #[error("record {record}: no motion: peak |angular velocity| = {peak} rad/s over the record (angle range {angle_range} rad)")]
    NoMotion {
        /// Name of the offending record.
        record: String,
        /// Peak |angular velocity| over the record (rad/s).
        peak: f64,
        /// Range (max - min) of the angle over the record (rad).
        angle_range: f64,
    },
    /// An angle range no pin joint sweeps: most likely degrees.
    #[error(
        "record {record}: angle spans {range} rad ({turns} turns): implausible for a pin joint (at most {limit} rad); \
         was the angle recorded in degrees? (as degrees it would span {as_rad} rad)"
    )]
    AngleRange {
        /// Name of the offending record.
        record: String,
        /// Range (max - min) of the recorded angle, taken as rad.
        range: f64,
        /// The same range in turns (`range / 2π`).
        turns: f64,
        /// Largest plausible angle range for a pin joint (rad).
        limit: f64,
        /// The range the values would span if they were degrees, converted to rad.
        as_rad: f64,
    },
    /// A speed no pin joint reaches: most likely deg/s or rpm.
    #[error(
        "record {record}: |angular_velocity| reaches {peak} rad/s, beyond the plausible {limit} rad/s; \
         was it recorded in deg/s (that would be {as_rad} rad/s) or rpm?"
    )]
    SpeedRange {
        /// Name of the offending record.
        record: String,
        /// Peak |angular velocity| as recorded, taken as rad/s.
        peak: f64,
        /// Largest plausible angular speed for a pin joint (rad/s).
        limit: f64,
        /// The peak converted to rad/s if the values were deg/s.
        as_rad: f64,
    },
    /// The angle's derivative and the given velocity disagree by a factor.
    #[error(
        "record {record}: the derivative of angle is {ratio} times angular_velocity (should be 1){hint}"
    )]
    Inconsistent {
        /// Name of the offending record.
        record: String,
        /// Ratio of the angle's numerical derivative to the given angular velocity (1 if consistent).
        ratio: f64,
        /// Suggested unit mix-up for that ratio (e.g. degrees vs rad), or empty.
        hint: &'static str,
    },
    /// After the exclusion rule, the data cannot determine μ_c and the torque offset.
    #[error("{what}")]
    Unidentifiable {
        /// Which quantity cannot be determined, and why.
        what: String,
    },
    /// An unknown `--fit` key or option value.
    #[error("{0}")]
    Option(String),
    /// A parameter value or parameter name was rejected by [`pinjoint::ParamError`].
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The friction model failed at a record's operating point.
    #[error("record {record}, sample {row}: {source}")]
    Model {
        /// Name of the offending record.
        record: String,
        /// 0-based index of the sample at which the model failed.
        row: usize,
        /// The model's error.
        source: ModelError,
    },
    /// The rig simulation of a record failed (rig fit only).
    #[error("record {record}: the rig simulation failed: {source}")]
    Simulation {
        /// Name of the offending record.
        record: String,
        /// The simulator's error.
        source: pinjoint::rig::RigError,
    },
    /// The rig fit would need more work than it is allowed.
    #[error("{0}")]
    Budget(String),
    /// The nonlinear fit did not converge.
    #[error("the nonlinear fit did not converge: {0}")]
    NoConvergence(String),
}
