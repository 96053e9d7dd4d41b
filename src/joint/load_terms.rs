//! The parts of an operating point that depend on the load (and speed) alone, not on the
//! load-sharing solve: Hertz (eq. 6), Roelands viscosity (eq. 5) and Bair–Winer limiting shear
//! (eq. 4) at p_m, eq. 19's groups, the Sommerfeld number (eq. 20); the fluid friction of eq. 3
//! from them; the torque at rest.

use super::{Joint, ModelError};
use crate::contact::asperity::AsperityGroups;
use crate::rheology::viscosity::{limiting_shear_stress, ln_roelands_from};
use std::f64::consts::PI;

/// The quantities that depend on load and speed only, not on the load-sharing solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSpeed {
    /// Eq. 6 under the whole load.
    pub hertz: crate::contact::Hertz,
    /// u = |ω| R, m/s.
    pub sliding_speed: f64,
    /// S, eq. 20, with P_L = P/(2RB) and c = R_b − R.
    pub sommerfeld_number: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s.
    pub contact_viscosity: f64,
    /// Its logarithm (finite where η overflows).
    pub ln_contact_viscosity: f64,
    /// Bair–Winer limiting shear stress at p_m (eq. 4), Pa.
    pub limiting_shear_stress: f64,
}

/// The parts of an evaluation that depend on the load alone ([`Joint::load_terms`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTerms {
    /// |P_T|, N.
    pub load: f64,
    /// ln |P_T|.
    pub ln_load: f64,
    /// Eq. 6 under the whole load.
    pub hertz: crate::contact::Hertz,
    /// P_L = P/(2RB) of eq. 20, Pa.
    pub line_load: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s (+∞ where it overflows).
    pub contact_viscosity: f64,
    /// Its logarithm.
    pub ln_contact_viscosity: f64,
    /// Bair–Winer limiting shear stress at p_m (eq. 4), Pa.
    pub limiting_shear_stress: f64,
    /// Its logarithm.
    pub ln_limiting_shear_stress: f64,
    /// Eq. 19's groups at this load.
    pub asperity: AsperityGroups,
}

impl Joint {
    /// Hertz quantities, sliding speed, Sommerfeld number and the rheology at p_m: the parts
    /// of an operating point that do not need the load-sharing solve.
    pub fn load_speed(&self, load: f64, omega: f64) -> LoadSpeed {
        let load = load.abs();
        let (hertz, ln_eta, tau_l) = self.rheology(load);
        LoadSpeed {
            hertz,
            sliding_speed: omega.abs() * self.params.geometry.pin_radius,
            sommerfeld_number: self.sommerfeld_at(load / self.projected_area, omega),
            contact_viscosity: ln_eta.exp(),
            ln_contact_viscosity: ln_eta,
            limiting_shear_stress: tau_l,
        }
    }

    /// Eq. 6 under `load` (scaled from 1 N: a, p_m, p0 ∝ √P_T), ln η (eq. 5) and τ_L (eq. 4) at p_m.
    fn rheology(&self, load: f64) -> (crate::contact::Hertz, f64, f64) {
        let sqrt_p = load.sqrt();
        let hertz = crate::contact::Hertz {
            half_width: self.hertz_unit.half_width * sqrt_p,
            mean_pressure: self.hertz_unit.mean_pressure * sqrt_p,
            peak_pressure: self.hertz_unit.peak_pressure * sqrt_p,
        };
        let ln_eta = ln_roelands_from(&self.lub, hertz.mean_pressure, self.ln_eta0, self.ln_eta_ratio);
        (hertz, ln_eta, limiting_shear_stress(&self.lub, hertz.mean_pressure))
    }

    /// The parts of an evaluation that depend on the load alone, checked as
    /// [`Joint::evaluate`] checks the load (its magnitude is used). A host that evaluates
    /// many speeds at one load computes them once ([`Joint::friction_at`]).
    pub fn load_terms(&self, load: f64) -> Result<LoadTerms, ModelError> {
        let load = load.abs();
        if !(load.is_finite() && load > 0.0) {
            return Err(ModelError::Load(load));
        }
        if load >= self.capacity {
            return Err(ModelError::BeyondCapacity { load, capacity: self.capacity });
        }
        Ok(self.load_terms_unchecked(load))
    }

    pub(super) fn load_terms_unchecked(&self, load: f64) -> LoadTerms {
        let (hertz, ln_eta, tau_l) = self.rheology(load);
        let ln_load = load.ln();
        LoadTerms {
            load,
            ln_load,
            hertz,
            line_load: load / self.projected_area,
            contact_viscosity: ln_eta.exp(),
            ln_contact_viscosity: ln_eta,
            limiting_shear_stress: tau_l,
            ln_limiting_shear_stress: tau_l.ln(),
            asperity: self.asp_unit.at_load_ratio(ln_load),
        }
    }

    /// S, eq. 20, with P_L = P/(2RB) and c = R_b − R.
    pub(super) fn sommerfeld(&self, lt: &LoadTerms, omega: f64) -> f64 {
        self.sommerfeld_at(lt.line_load, omega)
    }

    #[inline]
    pub(super) fn sommerfeld_at(&self, line_load: f64, omega: f64) -> f64 {
        self.lub.viscosity * omega.abs() / (2.0 * PI * line_load) * self.clearance_ratio_sq
    }

    /// The torque at rest (ω → 0⁺) at `load` (N): μ_c R |P| (the ω → 0 limit of eq. 11) plus,
    /// for the complete model, the grease's yield torque ([`Joint::rest_yield_torque`]).
    pub fn boundary_torque(&self, load: f64) -> f64 {
        let t = self.params.friction.boundary_friction_coefficient * self.params.geometry.pin_radius * load.abs();
        if self.complete.is_some() { t + self.rest_yield_torque(load) } else { t }
    }
}

/// Eq. 3 with eqs. 4 and 5 at the Hertz mean pressure: Q_H/P_T = τ_L(1 − e^{−ηu/(τ_L h_c)})/p_m
/// at sliding speed `u` (m/s, its logarithm `ln_u`) and ln h_c `ln_film`. At rest (u = 0) there
/// is no fluid shear: 0 exactly (docs/model.md, limits), whatever η. The exponent
/// ηu/(τ_L h_c) is formed in logarithms, so η overflowing is harmless.
#[inline]
pub(super) fn contact_friction(lt: &LoadTerms, u: f64, ln_u: f64, ln_film: f64) -> f64 {
    if u > 0.0 {
        let ln_x = lt.ln_contact_viscosity + ln_u - lt.ln_limiting_shear_stress - ln_film;
        lt.limiting_shear_stress / lt.hertz.mean_pressure * -(-crate::numerics::fast_math::exp(ln_x)).exp_m1()
    } else {
        0.0
    }
}
