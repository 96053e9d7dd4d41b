//! Contact geometry and Hertz line-contact quantities (eq. 6 and the text after it).
//!
//! The pin in its bush is a conformal contact: the reduced radius
//! `1/R' = 1/R − 1/R_b` is large (31.4 m for Table 1).

use crate::params::{Geometry, Materials};
use std::f64::consts::PI;

/// Reduced radius R' = R·R_b/(R_b − R) (text after eq. 6), m.
pub fn reduced_radius(g: &Geometry) -> f64 {
    g.pin_radius * g.bush_radius / (g.bush_radius - g.pin_radius)
}

/// Effective modulus E' from `1/E' = ½[(1−ν²)/E + (1−ν_b²)/E_b]`, Pa.
///
/// Erratum 1 (docs/model.md): the paper prints a minus sign between the two terms; only
/// the plus sign reproduces its own mean pressures (13 MPa at 20 kN).
pub fn effective_modulus(m: &Materials) -> f64 {
    2.0 / ((1.0 - m.pin_poisson_ratio.powi(2)) / m.pin_elastic_modulus
        + (1.0 - m.bush_poisson_ratio.powi(2)) / m.bush_elastic_modulus)
}

/// Hertz quantities of a line contact under the whole load (eq. 6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    /// a = √(8 P R'/(π E' B)), half-width of the contact, m.
    pub half_width: f64,
    /// p_m = P/(2 a B), mean contact pressure, Pa.
    pub mean_pressure: f64,
    /// p0 = √(P E'/(2π B R')), peak (maximum) Hertz pressure, Pa.
    pub peak_pressure: f64,
}

/// Eq. 6 for load `p_t` (N) on a contact of reduced radius `r_red`, modulus `e_eff`, length `b`.
pub fn hertz(p_t: f64, r_red: f64, e_eff: f64, b: f64) -> Hertz {
    let half_width = (8.0 * p_t * r_red / (PI * e_eff * b)).sqrt();
    Hertz {
        half_width,
        mean_pressure: p_t / (2.0 * half_width * b),
        peak_pressure: (p_t * e_eff / (2.0 * PI * b * r_red)).sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Params;

    #[test]
    fn table1_reduced_radius_and_modulus() {
        let p = Params::default();
        assert!((reduced_radius(&p.geometry) - 31.388).abs() < 1e-9);
        let e = effective_modulus(&p.materials);
        assert!((e / 1e9 - 165.9).abs() < 0.05, "E' = {e}");
    }

    #[test]
    fn printed_minus_sign_cannot_reproduce_the_papers_pressures() {
        // Erratum 1: with the printed minus sign E' would be 2/((1−νb²)/Eb − (1−ν²)/E).
        let m = Params::default().materials;
        let printed = 2.0
            / ((1.0 - m.bush_poisson_ratio.powi(2)) / m.bush_elastic_modulus
                - (1.0 - m.pin_poisson_ratio.powi(2)) / m.pin_elastic_modulus);
        let g = Params::default().geometry;
        let pm_printed = hertz(20e3, reduced_radius(&g), printed, g.bush_length).mean_pressure;
        let pm = hertz(20e3, reduced_radius(&g), effective_modulus(&m), g.bush_length).mean_pressure;
        assert!((pm / 1e6 - 13.0).abs() < 0.5, "plus sign: {pm}");
        assert!((pm_printed / 1e6 - 13.0).abs() > 3.0, "printed sign: {pm_printed}");
    }

    #[test]
    fn paper_mean_pressures() {
        let p = Params::default();
        let (r, e, b) = (reduced_radius(&p.geometry), effective_modulus(&p.materials), p.geometry.bush_length);
        let h = hertz(20e3, r, e, b);
        assert!((h.half_width - 12.74e-3).abs() < 0.01e-3);
        assert!((h.mean_pressure / 1e6 - 13.0).abs() < 0.3);
        // 7–23 MPa over 5–60 kN (docs/model.md: 6.61 and 22.89 MPa).
        assert!((hertz(5e3, r, e, b).mean_pressure / 1e6 - 6.61).abs() < 0.01);
        assert!((hertz(60e3, r, e, b).mean_pressure / 1e6 - 22.89).abs() < 0.01);
    }

    #[test]
    fn hertz_identities() {
        // Elliptic (semi-circular) Hertz line pressure: p_m = (π/4) p0, and the
        // integral of the pressure over the width equals the load per unit length.
        let h = hertz(12345.0, 3.0, 2e11, 0.05);
        assert!((h.mean_pressure - std::f64::consts::FRAC_PI_4 * h.peak_pressure).abs() < 1e-9 * h.peak_pressure);
        assert!((2.0 * h.half_width * 0.05 * h.mean_pressure - 12345.0).abs() < 1e-8);
        // a scales with √P, p_m with √P.
        let h4 = hertz(4.0 * 12345.0, 3.0, 2e11, 0.05);
        assert!((h4.half_width / h.half_width - 2.0).abs() < 1e-12);
        assert!((h4.mean_pressure / h.mean_pressure - 2.0).abs() < 1e-12);
    }
}
