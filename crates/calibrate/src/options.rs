//! How to calibrate: the model fitted and every option, with their defaults.

use super::exclusion::ExclusionRule;
use pinjoint::rig::RigParams;
use pinjoint::params::spec_by_name;
use pinjoint::Params;

/// The grease's keys fitted by default across temperature ([`crate::across`]), in the order
/// they are kept: of two equally poorly determined, the later is dropped.
pub const GREASE_KEYS: [&str; 5] =
    ["grease.yield_stress", "grease.consistency", "grease.yield_activation", "grease.consistency_activation", "grease.flow_index"];

/// The default [`Options::across_temperature`]: the [`GREASE_KEYS`] the parameter table has.
pub fn default_across_temperature() -> Vec<String> {
    GREASE_KEYS.iter().filter(|k| spec_by_name(k).is_some()).map(|k| (*k).to_string()).collect()
}

/// Default [`Options::max_simulations`] of the rig fit.
pub const DEFAULT_MAX_SIMULATIONS: usize = 200;

/// Default [`Options::max_samples`]: the most samples (all records together) that enter the
/// fit; longer records are block-averaged down to it ([`crate::decimate`]).
pub const MAX_FIT_SAMPLES: usize = 1_000_000;

/// Which model of the record is fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Model {
    /// The quasi-static model T = J·α + sign(ω)·μRP + T_0, away from reversals (the default).
    #[default]
    Core,
    /// The rig simulation (`pinjoint::rig`, what `pinjoint cycle` runs) driven by a sine
    /// command estimated from each record's angle: stick, breakaway peaks and servo ringing
    /// included; fits `rig.*` keys besides μ_c ([`crate::rig_fit`]).
    Rig,
}

/// How to calibrate.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Start values and every parameter not fitted.
    pub params: Params,
    /// Parameter keys fitted besides μ_c (`section.key`, as in the parameter file).
    pub fit: Vec<String>,
    /// Keys fitted by default when `fit` names none besides μ_c and the records are at
    /// [`crate::across::MIN_DEFAULT_TEMPERATURES`] or more temperatures (quasi-static fit only),
    /// each dropped with a warning when the records cannot determine it ([`crate::across`]).
    /// Default: [`default_across_temperature`], the grease's keys.
    pub across_temperature: Vec<String>,
    /// Rotating inertia J (kg·m²). `None` (the default): J is fitted together with μ_c and the
    /// offset (the torque is linear in it: T = … + J·α), with its interval. `Some(j)`: J is
    /// given, and j·α is subtracted from the recorded torque (0 subtracts nothing).
    pub inertia: Option<f64>,
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
    /// constant not fitted. Its `inertia` is replaced by [`Options::inertia`] when that is given
    /// (J has one meaning: J·α in the core model, simulated by the rig model) and by the core
    /// model's fitted J when it is not; its amplitude, frequency and load are not used (each
    /// record gives its own).
    pub rig: RigParams,
    /// [`Model::Rig`]: the most simulations of the whole record set the fit may run
    /// (default [`DEFAULT_MAX_SIMULATIONS`]); beyond it the fit is refused, saying so.
    pub max_simulations: usize,
    /// The most samples, all records together, that enter the fit (default
    /// [`MAX_FIT_SAMPLES`]); beyond it every record is block-averaged by the same factor
    /// ([`crate::decimate`]), and the result says so.
    pub max_samples: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            params: Params::default(),
            fit: Vec::new(),
            across_temperature: default_across_temperature(),
            inertia: None,
            fit_offset: true,
            exclusion: ExclusionRule::default(),
            half_width: None,
            resamples: 1000,
            seed: 0x5EED,
            model: Model::Core,
            rig: RigParams::default(),
            max_simulations: DEFAULT_MAX_SIMULATIONS,
            max_samples: MAX_FIT_SAMPLES,
        }
    }
}
