//! The result of one evaluation at any fidelity, and how it was obtained.

use crate::joint::{Joint, OperatingPoint, Regime};
use serde::Serialize;

/// How an [`Evaluation`] was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Source {
    /// The complete load-sharing solve (warm-started when a previous solution exists).
    Full,
    /// Interpolated in the Stribeck table.
    Table,
    /// μ = μ_c, shares 0/1, film of the rest state (the boundary level).
    Boundary,
    /// ω = 0 exactly: the rest state (μ = μ_c exactly, film from the 1-D rest table).
    Rest,
    /// Outside the envelope of a table or boundary level: the complete solve instead.
    Fallback,
}

impl Source {
    /// The name shown in logs and the CLI (`full`, `table`, `boundary`, `rest`, `fallback`).
    pub fn as_str(&self) -> &'static str {
        match self {
            Source::Full => "full",
            Source::Table => "table",
            Source::Boundary => "boundary",
            Source::Rest => "rest",
            Source::Fallback => "fallback",
        }
    }
}

/// The outputs of one evaluation (SI units): the quantities every level produces directly.
/// The remaining load- and speed-only quantities of an [`OperatingPoint`] (Hertz pressures,
/// Sommerfeld number, contact viscosity) follow exactly from load and speed:
/// [`super::Evaluator::operating_point`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Evaluation {
    /// P_T, N.
    pub load: f64,
    /// ω as given, rad/s.
    pub angular_velocity: f64,
    /// μ.
    pub friction_coefficient: f64,
    /// T = μ R P_T, magnitude, N·m (the sign opposes ω: [`Evaluation::signed_torque`]).
    pub torque: f64,
    /// h_c, central film thickness, m.
    pub film_thickness: f64,
    /// λ = h_c/√(σ² + σ_b²).
    pub lambda_ratio: f64,
    /// 1/γ1, share of the load carried by the fluid.
    pub fluid_load_fraction: f64,
    /// 1/γ2 = 1 − 1/γ1, share carried by the asperities.
    pub asperity_load_fraction: f64,
    /// Fluid (Bair–Winer) part of μ.
    pub fluid_friction_coefficient: f64,
    /// Asperity part of μ, μ_c/γ2.
    pub asperity_friction_coefficient: f64,
    /// ln(x1/x2) (−∞ at rest and in the boundary level).
    pub logit: f64,
    /// Regime named from the shares (as [`Regime`]).
    pub regime: Regime,
    /// How this value was obtained.
    pub source: Source,
    /// True on the evaluator's first out-of-envelope evaluation only, so that a caller can
    /// say so once in its log ([`super::Evaluator::fallbacks`] counts them all).
    pub first_fallback: bool,
}

impl Evaluation {
    /// The friction torque on the pin with its sign: opposite to ω (eq. 11), zero at ω = 0.
    pub fn signed_torque(&self) -> f64 {
        crate::joint::opposing(self.torque, self.angular_velocity)
    }

    /// The outputs of a complete solve.
    pub fn from_point(op: &OperatingPoint, source: Source) -> Self {
        Self {
            load: op.load,
            angular_velocity: op.angular_velocity,
            friction_coefficient: op.friction_coefficient,
            torque: op.torque,
            film_thickness: op.film_thickness,
            lambda_ratio: op.lambda_ratio,
            fluid_load_fraction: op.fluid_load_fraction,
            asperity_load_fraction: op.asperity_load_fraction,
            fluid_friction_coefficient: op.fluid_friction_coefficient,
            asperity_friction_coefficient: op.asperity_friction_coefficient,
            logit: op.logit,
            regime: op.regime,
            source,
            first_fallback: false,
        }
    }
}

/// Regime from the shares, as the core names it.
#[inline]
pub(crate) fn regime_from_shares(fluid: f64, asperity: f64) -> Regime {
    Regime::from_shares(fluid, asperity)
}

/// Complete an [`Evaluation`] into an [`OperatingPoint`]: the Hertz quantities (eq. 6),
/// Roelands viscosity at p_m (eq. 5) and Sommerfeld number (eq. 20) depend on load and
/// speed only and come from the core ([`Joint::load_speed`]); h_min from h_c and the fluid
/// share ([`Joint::min_film`]); the complete model's clearance outputs
/// ([`Joint::clearance_outputs`]). Exactly [`provisional`] then [`derive()`].
pub(crate) fn complete(joint: &Joint, e: &Evaluation) -> OperatingPoint {
    let mut op = provisional(joint, e);
    derive(joint, &mut op);
    op
}

/// The columns of an [`OperatingPoint`] (names of [`crate::record::COLUMNS`]) that
/// [`provisional`] leaves NaN and [`derive()`] fills: the quantities that follow from the
/// evaluation and cost more than it at a table level (a caller that reads only the torque
/// and μ, such as an FMU stepping in a system simulation, never pays for them).
pub const DERIVED_COLUMNS: [&str; 11] = [
    "mean_pressure",
    "peak_pressure",
    "contact_half_width",
    "sommerfeld_number",
    "contact_viscosity",
    "min_film_thickness",
    "min_lambda_ratio",
    "clearance_torque",
    "journal_weight",
    "eccentricity_ratio",
    "grease_yield_torque",
];

/// The [`OperatingPoint`] of an [`Evaluation`] with what the evaluation holds (and the
/// sliding speed and validity, which are immediate); the quantities of
/// [`DERIVED_COLUMNS`] NaN until [`derive()`] computes them.
pub fn provisional(joint: &Joint, e: &Evaluation) -> OperatingPoint {
    OperatingPoint {
        load: e.load,
        angular_velocity: e.angular_velocity,
        sliding_speed: e.angular_velocity.abs() * joint.params().geometry.pin_radius,
        friction_coefficient: e.friction_coefficient,
        torque: e.torque,
        film_thickness: e.film_thickness,
        lambda_ratio: e.lambda_ratio,
        fluid_load_fraction: e.fluid_load_fraction,
        asperity_load_fraction: e.asperity_load_fraction,
        mean_pressure: f64::NAN,
        peak_pressure: f64::NAN,
        contact_half_width: f64::NAN,
        sommerfeld_number: f64::NAN,
        contact_viscosity: f64::NAN,
        fluid_friction_coefficient: e.fluid_friction_coefficient,
        asperity_friction_coefficient: e.asperity_friction_coefficient,
        logit: e.logit,
        regime: e.regime,
        min_film_thickness: f64::NAN,
        min_lambda_ratio: f64::NAN,
        validity: joint.validity(e.load, e.angular_velocity),
        clearance_torque: f64::NAN,
        journal_weight: f64::NAN,
        eccentricity_ratio: f64::NAN,
        grease_yield_torque: f64::NAN,
    }
}

/// Fill the quantities of [`DERIVED_COLUMNS`] of a [`provisional`] operating point from its
/// load, speed, film and fluid share (bit for bit what [`super::Evaluator::evaluate_complete`] gives).
pub fn derive(joint: &Joint, op: &mut OperatingPoint) {
    let q = joint.load_speed(op.load, op.angular_velocity);
    // h_min from h_c and the fluid share exactly as the core does it (crate::film::min_film).
    let h_min = joint.min_film(op.load, op.angular_velocity, op.film_thickness, op.fluid_load_fraction);
    let (clearance_torque, journal_weight, eccentricity_ratio, grease_yield_torque) = joint.clearance_outputs(op.load, op.angular_velocity, op.film_thickness);
    op.mean_pressure = q.hertz.mean_pressure;
    op.peak_pressure = q.hertz.peak_pressure;
    op.contact_half_width = q.hertz.half_width;
    op.sommerfeld_number = q.sommerfeld_number;
    op.contact_viscosity = q.contact_viscosity;
    op.min_film_thickness = h_min;
    op.min_lambda_ratio = h_min / joint.composite_roughness();
    op.clearance_torque = clearance_torque;
    op.journal_weight = journal_weight;
    op.eccentricity_ratio = eccentricity_ratio;
    op.grease_yield_torque = grease_yield_torque;
}
