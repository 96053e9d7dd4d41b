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
/// share ([`Joint::min_film`]).
pub(crate) fn complete(joint: &Joint, e: &Evaluation) -> OperatingPoint {
    let q = joint.load_speed(e.load, e.angular_velocity);
    // h_min from h_c and the fluid share exactly as the core does it (crate::min_film).
    let h_min = joint.min_film(e.load, e.angular_velocity, e.film_thickness, e.fluid_load_fraction);
    let (clearance_torque, journal_weight, eccentricity_ratio, grease_yield_torque) = joint.clearance_outputs(e.load, e.angular_velocity, e.film_thickness);
    OperatingPoint {
        load: e.load,
        angular_velocity: e.angular_velocity,
        sliding_speed: q.sliding_speed,
        friction_coefficient: e.friction_coefficient,
        torque: e.torque,
        film_thickness: e.film_thickness,
        lambda_ratio: e.lambda_ratio,
        fluid_load_fraction: e.fluid_load_fraction,
        asperity_load_fraction: e.asperity_load_fraction,
        mean_pressure: q.hertz.mean_pressure,
        peak_pressure: q.hertz.peak_pressure,
        contact_half_width: q.hertz.half_width,
        sommerfeld_number: q.sommerfeld_number,
        contact_viscosity: q.contact_viscosity,
        fluid_friction_coefficient: e.fluid_friction_coefficient,
        asperity_friction_coefficient: e.asperity_friction_coefficient,
        logit: e.logit,
        regime: e.regime,
        min_film_thickness: h_min,
        min_lambda_ratio: h_min / joint.composite_roughness(),
        validity: joint.validity(e.load, e.angular_velocity),
        clearance_torque,
        journal_weight,
        eccentricity_ratio,
        grease_yield_torque,
    }
}
