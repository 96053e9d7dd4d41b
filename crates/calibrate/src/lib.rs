//! # pinjoint-calibrate
//!
//! Fit the pin-joint friction model (`pinjoint`) to measured torque cycles.
//!
//! Each [`Record`] is one test: time, angle and/or angular velocity, the recorded actuator
//! torque (positive in the direction of motion, as `pinjoint cycle` writes it) and the load.
//! The model of the recorded torque is
//!
//! ```text
//! T = J·α + sign(ω)·μ(P, |ω|)·R·P + T_0,   μ = μ_fluid + μ_c/γ2   (eqs. 3, 8, 10, 11)
//! ```
//!
//! with J the rig's rotating inertia (subtracted, α from the differentiator), and T_0 a torque
//! sensor offset (fitted by default). The load shares γ1, γ2 and μ_fluid do not depend on μ_c,
//! so the default fit, μ_c (and T_0), is *linear* least squares on the model's own shape.
//! [`Options::fit`] adds any key of the parameter table, fitted by Levenberg–Marquardt (the
//! `levenberg-marquardt` crate) in log / logit coordinates from the table's ranges.
//!
//! Velocity comes from the angle by a Savitzky–Golay differentiator ([`derivative`]) when the
//! record has none; the transients the quasi-static model does not describe are left out by a
//! stated rule ([`exclusion`]) and reported; the uncertainty is honest about residuals
//! correlated within a stroke ([`uncertainty`]).
//!
//! ```
//! use pinjoint_calibrate::{calibrate, Options, Record};
//! use pinjoint::{Joint, Params};
//! // A synthetic 0.3 Hz, ±40° record at 20 kN with μ_c = 0.1 (quasi-static, J = 0).
//! let mut truth = Params::default();
//! truth.friction.boundary_friction_coefficient = 0.1;
//! let joint = Joint::new(&truth).unwrap();
//! let (f, a) = (0.3, 40f64.to_radians());
//! let time: Vec<f64> = (0..3000).map(|i| i as f64 * 0.01).collect();
//! let w = |t: f64| a * std::f64::consts::TAU * f * (std::f64::consts::TAU * f * t).cos();
//! let rec = Record {
//!     name: "demo".into(),
//!     angle: Some(time.iter().map(|&t| a * (std::f64::consts::TAU * f * t).sin()).collect()),
//!     angular_velocity: None,
//!     torque: time.iter().map(|&t| -joint.evaluate(20e3, w(t)).unwrap().signed_torque()).collect(),
//!     load: vec![20e3; time.len()],
//!     time,
//! };
//! let options = Options { inertia: 0.0, ..Options::default() };
//! let cal = calibrate(&[rec], &options).unwrap();
//! assert!((cal.estimates[0].value - 0.1).abs() < 1e-5, "{}", cal.estimates[0].value);
//! ```

pub mod command;
pub mod coords;
pub mod derivative;
pub mod error;
pub mod exclusion;
pub mod fit;
pub mod lm;
pub mod model;
pub mod prepare;
pub mod record;
pub mod result;
pub mod rig_fit;
pub mod uncertainty;

pub use command::Command;
pub use coords::MU_C;
pub use error::CalibrationError;
pub use exclusion::{ExclusionRule, Reason, RecordExclusion, Window};
pub use fit::calibrate;
pub use record::Record;
pub use result::{Calibration, Estimate, Series};

use pinjoint::rig::RigParams;
use pinjoint::Params;

/// Which model of the record is fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Model {
    /// The quasi-static model T = J·α + sign(ω)·μRP + T_0, away from reversals (the default).
    #[default]
    Core,
    /// The rig simulation (`pinjoint::rig`, what `pinjoint cycle` runs) driven by a sine
    /// command estimated from each record's angle: stick, breakaway peaks and servo ringing
    /// included; fits `rig.*` keys besides μ_c ([`rig_fit`]).
    Rig,
}

/// How to calibrate.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Start values and every parameter not fitted.
    pub params: Params,
    /// Parameter keys fitted besides μ_c (`section.key`, as in the parameter file).
    pub fit: Vec<String>,
    /// Rotating inertia J (kg·m²) whose J·α is subtracted from the recorded torque; 0 to
    /// subtract nothing. Default: the rig's default ([`pinjoint::rig::RigParams`], 0.05 kg·m²).
    pub inertia: f64,
    /// Fit a constant torque offset T_0 (default true).
    pub fit_offset: bool,
    /// The exclusion rule.
    pub exclusion: ExclusionRule,
    /// Savitzky–Golay half-width in samples (default: 1/40 of a stroke, at least 3).
    pub half_width: Option<usize>,
    /// Bootstrap resamples (default 1000; 0 turns the bootstrap off).
    pub resamples: usize,
    /// Bootstrap seed.
    pub seed: u64,
    /// The model fitted (default [`Model::Core`]).
    pub model: Model,
    /// The rig's parameters for [`Model::Rig`]: start values of `rig.*` keys and every rig
    /// constant not fitted. Its `inertia` is replaced by [`Options::inertia`] (J has one
    /// meaning: subtracted as J·α by the core model, simulated by the rig model); its
    /// amplitude, frequency and load are not used (each record gives its own).
    pub rig: RigParams,
    /// [`Model::Rig`]: the most simulations of the whole record set the fit may run
    /// (default [`rig_fit::DEFAULT_MAX_SIMULATIONS`]); beyond it the fit is refused, saying so.
    pub max_simulations: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            params: Params::default(),
            fit: Vec::new(),
            inertia: pinjoint::rig::RigParams::default().inertia,
            fit_offset: true,
            exclusion: ExclusionRule::default(),
            half_width: None,
            resamples: 1000,
            seed: 0x5EED,
            model: Model::Core,
            rig: RigParams::default(),
            max_simulations: rig_fit::DEFAULT_MAX_SIMULATIONS,
        }
    }
}
