//! Asperity side of the load sharing: Greenwood–Williamson central pressure (eq. 17),
//! Gelinck–Schipper's fit of it (eq. 18), and their combination with the asperities
//! carrying `P_T/γ2` (eq. 19: `E' → E'/γ2`, `P_T → P_T/γ2`, `n → n γ2`).
//!
//! Eq. 19 reads `C·F_{3/2}((h_c − d_d)/σ_s) = (1/γ2)[1 + (K γ2^{a2})^{a4}]^{1/a4}` with
//! - `C = (2√(2π)/3)(B R' E'/P_T)^{1/2} n β^{1/2} σ_s^{3/2}` (eq. 17 divided by p0), and
//! - `K = a1 n^{a2} R'^{3a2/2 − a3} β^{a2/2} σ_s^{a3} W^{a2 − a3}` (eq. 18).
//!
//! Both groups are dimensionless (checked in the tests).

use crate::params::Surface;
use std::f64::consts::PI;

/// Gelinck–Schipper fit constant a1 of the central pressure K (eq. 18).
pub const A1: f64 = 1.558;
/// Gelinck–Schipper fit constant a2 of eq. 18 (exponent of n, β and W).
pub const A2: f64 = 0.0337;
/// Gelinck–Schipper fit constant a3 of eq. 18 (exponent of σ_s).
pub const A3: f64 = -0.442;
/// Gelinck–Schipper fit constant a4 of eq. 18.
pub const A4: f64 = -1.7;

/// `ln(1 + eˣ)` without overflow, to an absolute error of a few ε (it is only ever added
/// to logarithms, where that is a relative error of a few ε in the quantity).
pub fn softplus(x: f64) -> f64 {
    softplus_sigmoid(x).0
}

/// `ln(1 + eˣ)` and its derivative `1/(1 + e^{−x})`, from one exponential.
pub fn softplus_sigmoid(x: f64) -> (f64, f64) {
    let e = crate::numerics::fast_math::exp(-x.abs());
    let l = crate::numerics::fast_math::ln_1p_unit(e);
    if x > 0.0 { (x + l, 1.0 / (1.0 + e)) } else { (l, e / (1.0 + e)) }
}

/// The two load-dependent groups of eq. 19 for one load, in logarithms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsperityGroups {
    /// ln C (left side of eq. 19).
    pub ln_c: f64,
    /// ln K (inside eq. 18's bracket).
    pub ln_k: f64,
}

impl AsperityGroups {
    /// Groups for load `p_t` (N), reduced radius `r_red` (m), modulus `e_eff` (Pa), length `b` (m).
    pub fn new(s: &Surface, p_t: f64, r_red: f64, e_eff: f64, b: f64) -> Self {
        let w = p_t / (e_eff * r_red * b);
        let ln_c = (2.0 * (2.0 * PI).sqrt() / 3.0).ln()
            + 0.5 * (b * r_red * e_eff / p_t).ln()
            + s.asperity_density.ln()
            + 0.5 * s.asperity_radius.ln()
            + 1.5 * s.summit_height_std.ln();
        let ln_k = A1.ln()
            + A2 * s.asperity_density.ln()
            + (1.5 * A2 - A3) * r_red.ln()
            + 0.5 * A2 * s.asperity_radius.ln()
            + A3 * s.summit_height_std.ln()
            + (A2 - A3) * w.ln();
        Self { ln_c, ln_k }
    }

    /// The groups at another load: C ∝ P_T^{−1/2}, K ∝ W^{a2−a3} ∝ P_T^{a2−a3}.
    /// `self` holds the groups at load P₀; `ln_ratio` = ln(P_T/P₀).
    pub fn at_load_ratio(&self, ln_ratio: f64) -> Self {
        Self { ln_c: self.ln_c - 0.5 * ln_ratio, ln_k: self.ln_k + (A2 - A3) * ln_ratio }
    }

    /// ln of eq. 18's pressure ratio p_c/p0 with the asperities carrying P_T/γ2,
    /// times 1/γ2 (the right side of eq. 19), for `ln_x2 = ln(1/γ2)`.
    pub fn ln_rhs(&self, ln_x2: f64) -> f64 {
        // [1 + (K γ2^{a2})^{a4}]^{1/a4} with γ2^{a2} = x2^{−a2}
        ln_x2 + softplus(A4 * (self.ln_k - A2 * ln_x2)) / A4
    }

    /// The value ln F_{3/2}((h_c − d_d)/σ_s) that eq. 19 requires when the asperities carry P_T·x2.
    pub fn required_ln_f32(&self, ln_x2: f64) -> f64 {
        self.ln_rhs(ln_x2) - self.ln_c
    }

    /// [`Self::required_ln_f32`] and its derivative with respect to ln x2.
    pub fn required_ln_f32_slope(&self, ln_x2: f64) -> (f64, f64) {
        let (v, d, _) = self.required_ln_f32_grad(ln_x2);
        (v, d)
    }

    /// [`Self::required_ln_f32`], its derivative with respect to ln x2, and its derivative
    /// with respect to ln K (the sigmoid of eq. 18's bracket; ∂/∂ln C is −1).
    pub fn required_ln_f32_grad(&self, ln_x2: f64) -> (f64, f64, f64) {
        let z = A4 * (self.ln_k - A2 * ln_x2);
        let (sp, sigmoid) = softplus_sigmoid(z);
        (ln_x2 + sp / A4 - self.ln_c, 1.0 - A2 * sigmoid, sigmoid)
    }

    /// The second derivative of [`Self::required_ln_f32`] with respect to ln x2 given the
    /// sigmoid σ of [`Self::required_ln_f32_grad`]: a2²·a4·σ(1 − σ) (z = a4(ln K − a2 ln x2)
    /// moves by −a4·a2 per unit ln x2, and softplus″ = σ(1 − σ)).
    pub fn required_ln_f32_curvature(sigmoid: f64) -> f64 {
        A2 * A2 * A4 * sigmoid * (1.0 - sigmoid)
    }
}

/// Greenwood–Williamson central asperity pressure of eq. 17 (Pa) at separation `h` (m).
pub fn gw_pressure(s: &Surface, e_eff: f64, h: f64) -> f64 {
    2.0 / 3.0 * s.asperity_density * s.asperity_radius.sqrt() * s.summit_height_std.powf(1.5) * e_eff
        * crate::contact::gw::f32((h - s.summit_mean_plane_offset) / s.summit_height_std)
}

/// Gelinck–Schipper's fit of the central asperity pressure, eq. 18 (Pa), for the whole load.
pub fn gelinck_schipper_pressure(s: &Surface, p_t: f64, r_red: f64, e_eff: f64, b: f64) -> f64 {
    let g = AsperityGroups::new(s, p_t, r_red, e_eff, b);
    let p0 = (p_t * e_eff / (2.0 * PI * b * r_red)).sqrt();
    p0 * g.ln_rhs(0.0).exp()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{effective_modulus, reduced_radius};
    use crate::params::Params;

    fn setup() -> (Surface, f64, f64, f64) {
        let p = Params::default();
        (p.surface, reduced_radius(&p.geometry), effective_modulus(&p.materials), p.geometry.bush_length)
    }

    #[test]
    fn groups_are_dimensionless() {
        // Scale every length by λ and every force by φ (pressures by φ/λ²): C and K must not change.
        let (s, r, e, b) = setup();
        let g0 = AsperityGroups::new(&s, 20e3, r, e, b);
        let (lam, phi) = (3.7, 11.0);
        let s2 = Surface {
            asperity_density: s.asperity_density / lam / lam,
            asperity_radius: s.asperity_radius * lam,
            summit_height_std: s.summit_height_std * lam,
            pin_rms_roughness: s.pin_rms_roughness * lam,
            bush_rms_roughness: s.bush_rms_roughness * lam,
            summit_mean_plane_offset: s.summit_mean_plane_offset * lam,
        };
        let g1 = AsperityGroups::new(&s2, 20e3 * phi, r * lam, e * phi / lam / lam, b * lam);
        assert!((g0.ln_c - g1.ln_c).abs() < 1e-12);
        assert!((g0.ln_k - g1.ln_k).abs() < 1e-12);
    }

    #[test]
    fn eq19_is_eq17_equals_eq18_under_the_gamma2_substitution() {
        // Erratum note 4: eq. 19 is consistent as printed. Build it independently:
        // eq. 17 with (E'/γ2, nγ2) equals eq. 18 with (E'/γ2, P/γ2, nγ2) at the h where the code's
        // required F holds.
        let (s, r, e, b) = setup();
        let p = 20e3;
        for gamma2 in [1.0, 1.3, 2.0, 10.0, 1e4] {
            let g = AsperityGroups::new(&s, p, r, e, b);
            let ln_f = g.required_ln_f32(-f64::ln(gamma2));
            let t = crate::contact::gw::inverse_ln_f32(ln_f);
            let h = s.summit_mean_plane_offset + t * s.summit_height_std;
            let s_sub = Surface { asperity_density: s.asperity_density * gamma2, ..s };
            let lhs = gw_pressure(&s_sub, e / gamma2, h);
            let rhs = gelinck_schipper_pressure(&s_sub, p / gamma2, r, e / gamma2, b);
            assert!((lhs / rhs - 1.0).abs() < 1e-10, "γ2={gamma2}: {lhs} vs {rhs}");
        }
    }

    #[test]
    fn load_scaling_matches_direct_groups() {
        let (s, r, e, b) = setup();
        let g1 = AsperityGroups::new(&s, 1.0, r, e, b);
        for p in [3.0, 20e3, 1e6] {
            let direct = AsperityGroups::new(&s, p, r, e, b);
            let scaled = g1.at_load_ratio(f64::ln(p));
            assert!((direct.ln_c - scaled.ln_c).abs() < 1e-13 && (direct.ln_k - scaled.ln_k).abs() < 1e-13);
        }
    }

    #[test]
    fn eq18_limits() {
        // a4 < 0: the bracket tends to 1 for large K (p_c → p0) and to K^{...} for small K.
        let g = AsperityGroups { ln_c: 0.0, ln_k: 50.0 };
        assert!(g.ln_rhs(0.0).abs() < 1e-30);
        let g = AsperityGroups { ln_c: 0.0, ln_k: -50.0 };
        assert!((g.ln_rhs(0.0) - -50.0).abs() < 1e-12);
        // Right side of eq. 19 increases with x2 = 1/γ2.
        let (s, r, e, b) = setup();
        let g = AsperityGroups::new(&s, 20e3, r, e, b);
        let mut prev = f64::NEG_INFINITY;
        for i in 0..200 {
            let ln_x2 = -100.0 + f64::from(i) * 0.5;
            let v = g.ln_rhs(ln_x2);
            assert!(v > prev);
            prev = v;
        }
    }

    #[test]
    fn curvature_matches_differences_of_the_slope() {
        let (s, r, e, b) = setup();
        for p in [1.0, 20e3, 1e7] {
            let g = AsperityGroups::new(&s, p, r, e, b);
            for ln_x2 in [-30.0, -3.0, -0.3, 0.0] {
                let (_, _, sigmoid) = g.required_ln_f32_grad(ln_x2);
                let c = AsperityGroups::required_ln_f32_curvature(sigmoid);
                let h = 1e-4;
                let fd = (g.required_ln_f32_slope(ln_x2 + h).1 - g.required_ln_f32_slope(ln_x2 - h).1) / (2.0 * h);
                assert!((c - fd).abs() < 1e-9 + 1e-6 * fd.abs(), "P={p} ln x2={ln_x2}: {c} vs {fd}");
            }
        }
    }

    #[test]
    fn softplus_is_stable() {
        assert_eq!(softplus(1000.0), 1000.0);
        assert_eq!(softplus(-1000.0), 0.0);
        assert!((softplus(0.0) - 2f64.ln()).abs() < 1e-16);
        for x in [-30.0, -3.0, -0.1, 0.2, 4.0, 35.0] {
            let (sp, sg) = softplus_sigmoid(x);
            assert!((sp - (1.0 + f64::exp(x)).ln()).abs() < 4.0 * f64::EPSILON * (1.0 + f64::abs(x)));
            assert!((sg - 1.0 / (1.0 + f64::exp(-x))).abs() < 4.0 * f64::EPSILON);
        }
    }
}
