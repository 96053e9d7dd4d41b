//! Lubricant rheology: Roelands pressure–viscosity (eq. 5) and the Bair–Winer
//! limiting shear stress (eq. 4).

use crate::params::Lubricant;

/// Roelands viscosity at pressure `p` (Pa), eq. 5:
/// `η = η0 (η∞/η0)^[1 − (1 + p/c_p)^Z]`, Pa·s.
pub fn roelands(l: &Lubricant, p: f64) -> f64 {
    roelands_with(l, p, (l.roelands_viscosity_limit / l.viscosity).ln())
}

/// [`roelands`] with ln(η∞/η0) precomputed.
pub fn roelands_with(l: &Lubricant, p: f64, ln_eta_ratio: f64) -> f64 {
    ln_roelands_with(l, p, ln_eta_ratio).exp()
}

/// ln η of eq. 5, which stays finite where η itself overflows (large Z at GPa pressures).
pub fn ln_roelands_with(l: &Lubricant, p: f64, ln_eta_ratio: f64) -> f64 {
    let expo = -((l.roelands_index * (p / l.roelands_pressure_constant).ln_1p()).exp_m1());
    l.viscosity.ln() + expo * ln_eta_ratio
}

/// Limiting shear stress at pressure `p` (Pa), eq. 4: `τ_L = τ_L0 + β0 p`, Pa.
pub fn limiting_shear_stress(l: &Lubricant, p: f64) -> f64 {
    l.limiting_shear_stress + l.limiting_shear_stress_slope * p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roelands_limits() {
        let l = Lubricant::default();
        // Ambient pressure: η0 (to the ulp of exp(ln η0): eq. 5 is evaluated in logarithms).
        assert!((roelands(&l, 0.0) / l.viscosity - 1.0).abs() <= 4.0 * f64::EPSILON);
        // Low pressure: η ≈ η0 exp(α* p) with α* = Z ln(η0/η∞)/c_p (the Roelands pressure-viscosity coefficient).
        let alpha_star = l.roelands_index * (l.viscosity / l.roelands_viscosity_limit).ln() / l.roelands_pressure_constant;
        let p = 1e5;
        assert!((roelands(&l, p) / (l.viscosity * (alpha_star * p).exp()) - 1.0).abs() < 1e-5);
        // Monotone increasing with pressure for η∞ < η0.
        let mut prev = 0.0;
        for i in 0..100 {
            let v = roelands(&l, i as f64 * 1e7);
            assert!(v > prev);
            prev = v;
        }
        // Hand value at 13.22 MPa: 1 - 1.06745^0.63 = -0.04198..., ln(η∞/η0) = -5.2848
        let v = roelands(&l, 13.22e6);
        let hand = 12.45e-3 * ((1.0 - (1.0f64 + 13.22e6 / 1.96e8).powf(0.63)) * (6.31e-5f64 / 12.45e-3).ln()).exp();
        assert!((v / hand - 1.0).abs() < 1e-15);
        assert!((v / l.viscosity - 1.248).abs() < 0.01, "{}", v / l.viscosity);
    }

    #[test]
    fn limiting_shear_is_linear() {
        let l = Lubricant::default();
        assert_eq!(limiting_shear_stress(&l, 0.0), 2.28e6);
        assert!((limiting_shear_stress(&l, 10e6) - (2.28e6 + 0.047 * 10e6)).abs() < 1e-6);
    }
}
