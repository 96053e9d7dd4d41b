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
//! with J the rig's rotating inertia (α from the differentiator), and T_0 a torque sensor
//! offset (fitted by default). The load shares γ1, γ2 and μ_fluid do not depend on μ_c, so the
//! default fit, μ_c, J and T_0, is *linear* least squares on the model's own shape; a given J
//! ([`Options::inertia`]) is subtracted as J·α instead of fitted ([`fit`]).
//! [`Options::fit`] adds any key of the parameter table, fitted by Levenberg–Marquardt (the
//! `levenberg-marquardt` crate) in log / logit coordinates from the table's ranges.
//!
//! A record at a known lubricant temperature ([`Record::temperature`]) is evaluated by the joint
//! at that temperature; records at three or more temperatures fit the grease's parameters by
//! default, each kept only when the records determine it ([`across`]).
//!
//! Velocity comes from the angle by a Savitzky–Golay differentiator ([`derivative`]) when the
//! record has none; the transients the quasi-static model does not describe are left out by a
//! stated rule ([`exclusion`]) and reported; records longer than a sample budget are
//! block-averaged to it ([`decimate`]); the uncertainty is honest about residuals
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
//!     temperature: None,
//!     time,
//! };
//! let options = Options { inertia: Some(0.0), ..Options::default() };
//! let cal = calibrate(&[rec], &options).unwrap();
//! assert!((cal.estimates[0].value - 0.1).abs() < 1e-5, "{}", cal.estimates[0].value);
//! ```

// In dependency order: each module uses only those listed before it.
pub mod error;
pub mod record;
pub mod derivative;
pub mod decimate;
pub mod exclusion;
pub mod model;
pub mod coords;
pub mod uncertainty;
pub mod command;
pub mod lm;
pub mod options;
pub mod result;
pub mod across;
pub mod prepare;
pub mod estimates;
pub mod fit;
pub mod rig_fit;
pub mod entry;

pub use command::Command;
pub use coords::MU_C;
pub use entry::{calibrate, calibrate_columns};
pub use error::CalibrationError;
pub use estimates::INERTIA;
pub use exclusion::{ExclusionRule, Reason, RecordExclusion, Window};
pub use options::{Model, Options, MAX_FIT_SAMPLES};
pub use record::{Columns, Record};
pub use result::{Calibration, Estimate, Series};
