//! Everything that can go wrong when building or using a fidelity level.

use crate::joint::ModelError;
use crate::params::ParamError;
use thiserror::Error;

/// A rejected fidelity setting, or an evaluation the model cannot take.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FidelityError {
    /// The fidelity name is not one of `full | table | boundary | auto`.
    #[error("fidelity = \"{0}\" is not a fidelity level: it must be one of full, table, boundary, auto")]
    UnknownFidelity(String),
    /// Tolerance not a finite number > 0.
    #[error("tolerance = {0} (relative error, dimensionless) is invalid: it must be a finite number > 0")]
    Tolerance(f64),
    /// Tolerance below what the reference (the full solve) itself guarantees.
    #[error(
        "tolerance = {value} (relative error, dimensionless) is below the accuracy of the full solve itself ({floor}): no level can be shown to meet it"
    )]
    ToleranceBelowModelAccuracy {
        /// The requested tolerance (relative error, dimensionless).
        value: f64,
        /// The full solve's own error bound, [`crate::fidelity::FULL_ERROR_BOUND`] (dimensionless).
        floor: f64,
    },
    /// One end of an envelope range is not a finite number > 0.
    #[error("envelope {quantity} {end} = {value} {unit} is invalid: it must be a finite number > 0 {unit}")]
    EnvelopeBound {
        /// Which range: `load` or `speed`.
        quantity: &'static str,
        /// Which end: `minimum` or `maximum`.
        end: &'static str,
        /// The invalid value, in `unit`.
        value: f64,
        /// Unit of the quantity (`N` or `rad/s`).
        unit: &'static str,
    },
    /// An envelope range whose minimum is not below its maximum.
    #[error("envelope {quantity}: minimum = {min} {unit} must be below maximum = {max} {unit}")]
    EnvelopeOrder {
        /// Which range: `load` or `speed`.
        quantity: &'static str,
        /// The given minimum, in `unit`.
        min: f64,
        /// The given maximum, in `unit`.
        max: f64,
        /// Unit of the quantity (`N` or `rad/s`).
        unit: &'static str,
    },
    /// The table would need more cells than allowed to meet the tolerance.
    #[error(
        "table: meeting tolerance = {tolerance} (relative error) over the envelope needs more than {limit} cells \
         (reached {cells} cells with a measured error of {measured}); use a larger tolerance, a smaller envelope, or fidelity full"
    )]
    TableTooLarge {
        /// The requested tolerance (relative error, dimensionless).
        tolerance: f64,
        /// Cells of the last table built before giving up.
        cells: usize,
        /// Largest number of cells allowed.
        limit: usize,
        /// Error measured on that last table (relative, dimensionless).
        measured: f64,
    },
    /// A point of the envelope where the model has no answer (beyond the asperity model's
    /// load capacity, or a speed where the film or viscosity overflows).
    #[error("the envelope reaches load = {load} N, speed = {speed} rad/s, where the model has no answer ({source}); use a smaller envelope (envelope load/speed ranges) or fidelity full")]
    Envelope {
        /// Load at the failing point (N).
        load: crate::fmt::Num,
        /// Speed |ω| at the failing point (rad/s).
        speed: crate::fmt::Num,
        /// The model's error at that point.
        source: ModelError,
    },
    /// The parameter set is invalid.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The operating point is invalid (load ≤ 0, non-finite speed).
    #[error(transparent)]
    Model(#[from] ModelError),
}
