//! Every quantity of the model at one operating point ([`OperatingPoint`]), and the sign of a
//! friction torque ([`opposing`]).

use super::Regime;
use serde::Serialize;

/// Every quantity of the model at one operating point (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OperatingPoint {
    /// P_T, N.
    pub load: f64,
    /// ω as given, rad/s (the model depends on |ω|).
    pub angular_velocity: f64,
    /// u = |ω| R, sliding speed = Moes' sum velocity (bush fixed), m/s.
    pub sliding_speed: f64,
    /// μ, eq. 10.
    pub friction_coefficient: f64,
    /// T = μ R P_T, eq. 11: magnitude of the torque to articulate the joint, N·m.
    pub torque: f64,
    /// h_c, central film thickness, m.
    pub film_thickness: f64,
    /// λ = h_c/√(σ² + σ_b²), eq. 21 with the central film (docs/model.md, conventions).
    pub lambda_ratio: f64,
    /// 1/γ1.
    pub fluid_load_fraction: f64,
    /// 1/γ2.
    pub asperity_load_fraction: f64,
    /// p_m, Hertz mean pressure, Pa (eq. 6).
    pub mean_pressure: f64,
    /// p0, Hertz peak pressure, Pa (eq. 6).
    pub peak_pressure: f64,
    /// a, Hertz half-width, m (eq. 6).
    pub contact_half_width: f64,
    /// S, eq. 20.
    pub sommerfeld_number: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s; +∞ where eq. 5 overflows (Z of several
    /// units at GPa pressures): μ is computed from ln η and stays finite.
    pub contact_viscosity: f64,
    /// Q_H/P_T: the fluid (Bair–Winer, eq. 3) part of μ.
    pub fluid_friction_coefficient: f64,
    /// μ_c/γ2: the asperity (eq. 8) part of μ.
    pub asperity_friction_coefficient: f64,
    /// ln(x1/x2) of the load-sharing solve (−∞ at rest): a warm start for the next call.
    pub logit: f64,
    /// Lubrication regime from the fluid and asperity load shares.
    pub regime: Regime,
    /// h_min, minimum film thickness, m: h_c times Pan & Hamrock's line-contact ratio
    /// h_min/h_c under eq. 13's substitution ([`crate::film::min_film`]; an extrapolation here, 0 at
    /// rest). Extension: the paper gives no h_min relation.
    pub min_film_thickness: f64,
    /// λ_min = h_min/√(σ² + σ_b²), eq. 21 as printed (with h_min).
    pub min_lambda_ratio: f64,
    /// Whether the load, sliding speed and the joint's lubricant temperature are inside the
    /// conditions the model was checked against, or past its assumptions
    /// ([`Joint::validity`](super::Joint::validity)).
    pub validity: crate::validity::Validity,
    /// T_clearance, N·m: the torque of the lubricant in the clearance outside the contact arc,
    /// its yield part included (complete model, [`crate::composite`]; 0 for the paper's model).
    pub clearance_torque: f64,
    /// w, the journal bearing's weight in the composite film (0: the paper's line contact
    /// alone, 1: the full-film journal bearing; 0 for the paper's model).
    pub journal_weight: f64,
    /// ε_g = 1 − h_c/c, the eccentricity ratio of the clearance around the film (clamped to
    /// [0, 1)).
    pub eccentricity_ratio: f64,
    /// τ_y(T)·(2π − 2θ_c)·R²·B, N·m: the grease's yield torque, part of
    /// `clearance_torque` and of the torque at rest (0 without grease and for the paper's model).
    pub grease_yield_torque: f64,
}

/// A friction torque of magnitude `torque` given its sign: opposite to `omega` (eq. 11), zero
/// at ω = 0 (where it has no direction).
pub fn opposing(torque: f64, omega: f64) -> f64 {
    if omega > 0.0 {
        -torque
    } else if omega < 0.0 {
        torque
    } else {
        0.0
    }
}

impl OperatingPoint {
    /// The friction torque on the pin with its sign: opposite to ω (eq. 11), zero at ω = 0.
    pub fn signed_torque(&self) -> f64 {
        opposing(self.torque, self.angular_velocity)
    }
}
