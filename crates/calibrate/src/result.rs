//! What a calibration returns.

use super::command::Command;
use super::exclusion::RecordExclusion;
use super::options::Model;
use pinjoint::rig::RigParams;
use pinjoint::Params;

/// One fitted quantity (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// `section.key`, or `torque_offset` for T_0.
    pub key: String,
    /// SI unit ("1" for dimensionless).
    pub unit: &'static str,
    /// Fitted value, in `unit`.
    pub value: f64,
    /// Start value.
    pub initial: f64,
    /// Standard error (the larger of iid and cluster-robust, by the delta method for a
    /// transformed parameter).
    pub standard_error: f64,
    /// Textbook σ²(JᵀJ)⁻¹ standard error.
    pub standard_error_iid: f64,
    /// Cluster-robust (strokes) standard error, when there are enough strokes.
    pub standard_error_cluster: Option<f64>,
    /// 95 % interval (t interval on the standard error ∪ bootstrap interval).
    pub ci95: (f64, f64),
    /// Bootstrap-over-strokes 95 % percentile interval, when there are enough strokes.
    pub bootstrap_ci95: Option<(f64, f64)>,
}

/// Measured and fitted torque of one record, every sample.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Name of the record.
    pub record: String,
    /// Sample times (s).
    pub time: Vec<f64>,
    /// Recorded angle (rad), if the record has one.
    pub angle: Option<Vec<f64>>,
    /// Angular velocity used (rad/s).
    pub angular_velocity: Vec<f64>,
    /// Load (N).
    pub load: Vec<f64>,
    /// Recorded torque (N·m).
    pub measured: Vec<f64>,
    /// J·α (N·m).
    pub inertia_torque: Vec<f64>,
    /// Fitted recorded torque J·α + sign(ω)μRP + T_0 (N·m).
    pub fitted: Vec<f64>,
    /// Whether the sample was used in the fit.
    pub used: Vec<bool>,
}

/// The result of [`crate::calibrate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    /// The model fitted.
    pub model: Model,
    /// The complete parameter set with the fitted values.
    pub params: Params,
    /// [`Model::Rig`]: the rig's parameters with the fitted `rig.*` values (None for the core model).
    pub rig: Option<RigParams>,
    /// μ_c first, then the `--fit` keys in order.
    pub estimates: Vec<Estimate>,
    /// T_0, if fitted.
    pub offset: Option<Estimate>,
    /// Keys of the rows/columns of `correlation` (estimates, then `torque_offset`).
    pub correlation_keys: Vec<String>,
    /// Correlation of the fit coordinates.
    pub correlation: Vec<Vec<f64>>,
    /// Condition number of the column-scaled JᵀJ.
    pub condition: f64,
    /// RMS of the residuals over the used samples (N·m).
    pub rms_residual: f64,
    /// Samples used in the fit, over all records.
    pub points_used: usize,
    /// Samples excluded by the rule, over all records.
    pub points_excluded: usize,
    /// Strokes (clusters) among the used samples.
    pub strokes: usize,
    /// Degrees of freedom of the t interval (used samples minus fitted quantities).
    pub dof: usize,
    /// The 97.5 % quantile of Student's t with `dof` degrees of freedom.
    pub quantile: f64,
    /// Differentiator half-width of each record (samples).
    pub half_widths: Vec<usize>,
    /// What was excluded, per record.
    pub exclusions: Vec<RecordExclusion>,
    /// Identifiability and interval warnings.
    pub warnings: Vec<String>,
    /// Distinct temperatures of the records that give one (K, ascending; empty when none does).
    pub temperatures: Vec<f64>,
    /// The inertia J used (kg·m²): the fitted one when [`Calibration::inertia_estimate`] is
    /// Some, else the given one (`Options::inertia`).
    pub inertia: f64,
    /// J fitted with its interval (key `rig.inertia`, unit kg.m2), when it was not given; for
    /// the rig model, the quasi-static fit's J that the simulation used (unless `rig.inertia`
    /// is among the `--fit` keys, then it is in `estimates`).
    pub inertia_estimate: Option<Estimate>,
    /// Samples read, over all records, before any block averaging.
    pub samples_read: usize,
    /// Block length m of the averaging of long records (1: none; see [`crate::decimate`]):
    /// `points_used` and `points_excluded` count the averaged samples.
    pub block_length: usize,
    /// Settling time used (s): the stated one, or longer when the data asked for it.
    pub settle_time: f64,
    /// Levenberg–Marquardt evaluations (0 for the linear fit).
    pub evaluations: usize,
    /// [`Model::Rig`]: simulations of the record set run (command estimate, LM, Jacobians).
    pub simulations: usize,
    /// [`Model::Rig`]: the command estimated for each record (empty for the core model).
    pub commands: Vec<Command>,
    /// Measured and fitted torque of each record, in input order.
    pub series: Vec<Series>,
}
