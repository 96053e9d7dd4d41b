//! Lubricant rheology: Roelands pressure–viscosity (eq. 5), the Bair–Winer
//! limiting shear stress (eq. 4), and (an extension, not in the paper) the temperature
//! dependence of η0 and α by Roelands' temperature relation ([`at_temperature`]).

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
    ln_roelands_from(l, p, l.viscosity.ln(), ln_eta_ratio)
}

/// [`ln_roelands_with`] with ln η0 precomputed too (the same number, bit for bit).
pub fn ln_roelands_from(l: &Lubricant, p: f64, ln_eta0: f64, ln_eta_ratio: f64) -> f64 {
    let expo = -((l.roelands_index * (p / l.roelands_pressure_constant).ln_1p()).exp_m1());
    ln_eta0 + expo * ln_eta_ratio
}

/// Limiting shear stress at pressure `p` (Pa), eq. 4: `τ_L = τ_L0 + β0 p`, Pa.
pub fn limiting_shear_stress(l: &Lubricant, p: f64) -> f64 {
    l.limiting_shear_stress + l.limiting_shear_stress_slope * p
}

/// Where the default S0 = 1.262 comes from: Roelands' relation
/// `log10(η/1 mPa·s) + 1.2 = G0·(1 + θ/135 °C)^−S0` through two points of a mineral oil of
/// class ISO VG 100, typical of grease base oils: ν = 100 mm²/s at 40 °C (the ISO 3448 grade
/// mid-point) and 11.1 mm²/s at 100 °C (viscosity index ≈ 95, a solvent-refined paraffinic
/// oil), with densities 870 and 830 kg/m³, i.e. η = 87.0 and 9.21 mPa·s. These are
/// class-typical datasheet numbers, not measurements of the paper's grease (Aeroshell 33 has
/// a synthetic base oil); [`roelands_s0_from_two_points`] reproduces the number. Only the
/// 40 °C value is a standard's (ISO 3448: VG 100 is 90–110 mm²/s); the 100 °C value (for
/// VI ≈ 95) and the densities were written from memory, not from a datasheet. Cross-check
/// (`tests/published_values.rs`): S0 fitted through the 30 and 100 °C viscosities of the 13
/// mineral oils of Stachowiak & Batchelor's Table 2.3 spans 1.04–1.57, and the default lies
/// inside (their medium-VI spindle oil gives 1.262).
pub const DEFAULT_S0_SOURCE: &str = "Roelands (1966) temperature relation fitted to an ISO VG 100 mineral oil: 87.0 mPa.s at 40 C, 9.21 mPa.s at 100 C";

/// Roelands' temperature–viscosity index S0 of the line through two (θ °C, η Pa·s) points:
/// `S0 = ln[ln(η1/η∞)/ln(η2/η∞)] / ln[(135 + θ2)/(135 + θ1)]` with η∞ of eq. 5 (Roelands'
/// log10 η + 1.2 with η in mPa·s is ln(η/η∞)/ln 10 with η∞ = 10^−4.2 Pa·s ≈ 6.31e-5 Pa·s).
pub fn roelands_s0_from_two_points(theta1: f64, eta1: f64, theta2: f64, eta2: f64, eta_inf: f64) -> f64 {
    ((eta1 / eta_inf).ln() / (eta2 / eta_inf).ln()).ln() / ((135.0 + theta2) / (135.0 + theta1)).ln()
}

/// The lubricant at its temperature `l.temperature`, from its values at
/// `l.reference_temperature` (Table 3's η0 and α). Extension; the paper runs at room
/// temperature.
///
/// Viscosity (Roelands 1966, "Correlational aspects of the viscosity–temperature–pressure
/// relationship of lubricating oils", thesis, TH Delft; in Hamrock, *Fundamentals of Fluid
/// Film Lubrication*, the paper's ref. \[8\]): at ambient pressure
/// `ln(η0(T)/η∞) = ln(η0(T_ref)/η∞)·f`, `f = [(135 + θ)/(135 + θ_ref)]^−S0`, θ = T − 273.15 K
/// in °C, with η∞ of eq. 5 (6.31e-5 Pa·s, Roelands' universal constant). The thesis was not at
/// hand; the form is checked against Stachowiak & Batchelor, *Engineering Tribology*, ch. 2,
/// p. 21, who print Roelands' combined equation as
/// `η = η0 exp{(ln η0 + 9.67)[−1 + (1 + 5.1e-9 p)^Z ((T − 138)/(T0 − 138))^−S0]}` (T in K;
/// 9.67 = −ln 6.31e-5, 5.1e-9 = 1/1.96e8 Pa, 138 K ≈ −135 °C, all rounded): with those
/// constants the code is the same function of T and p, α included (`tests/published_values.rs`).
/// Against their Table 2.3 (13 mineral oils at 30, 60, 100 °C) S0 fitted through 30 and
/// 100 °C predicts η at 60 °C with an RMS error of 4.9 % (largest 13 %).
///
/// Pressure–viscosity: in Roelands' pressure relation (eq. 5) the index Z does not depend on
/// temperature, so its initial pressure–viscosity coefficient
/// `α* = d ln η/dp|₀ = Z·ln(η0/η∞)/c_p` scales with ln(η0/η∞): α(T) = α(T_ref)·f. Eq. 5 itself
/// takes the new η0, so the Roelands viscosity at p_m follows too. Against Table 2.3 of
/// Stachowiak & Batchelor this rule predicts α at 60 and 100 °C from α at 30 °C with an RMS
/// error of 7.2 % (largest 23 %). τ_L0 and β0 (eq. 4) are kept constant (no temperature data
/// in the paper).
///
/// Validity: Roelands fitted the relation to mineral and synthetic oils at ordinary
/// temperatures; its form needs θ > −135 °C. Below about 0 °C and for a grease's bleed oil it is
/// an extrapolation, as is a single S0 for a grease whose base oil is not known.
///
/// At `T == T_ref` it returns `*l` unchanged (bit for bit, no arithmetic).
pub fn at_temperature(l: &Lubricant) -> Lubricant {
    if l.temperature == l.reference_temperature {
        return *l;
    }
    let f = temperature_factor(l);
    Lubricant {
        viscosity: crate::rheology::roelands_temperature::viscosity(l.viscosity, l.roelands_viscosity_limit, l.temperature, l.reference_temperature, l.roelands_temperature_index),
        pressure_viscosity_coefficient: l.pressure_viscosity_coefficient * f,
        ..*l
    }
}

/// f = [(135 + θ)/(135 + θ_ref)]^−S0 of [`at_temperature`] (1 at T = T_ref).
pub fn temperature_factor(l: &Lubricant) -> f64 {
    crate::rheology::roelands_temperature::factor(l.temperature, l.reference_temperature, l.roelands_temperature_index)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_temperature_returns_table3_bit_for_bit() {
        let l = Lubricant::default();
        assert_eq!(l.temperature, l.reference_temperature);
        let t = at_temperature(&l);
        assert_eq!(t.viscosity.to_bits(), l.viscosity.to_bits());
        assert_eq!(t.pressure_viscosity_coefficient.to_bits(), l.pressure_viscosity_coefficient.to_bits());
        // Another reference: still exact at equality.
        let l2 = Lubricant { temperature: 250.0, reference_temperature: 250.0, ..l };
        assert_eq!(at_temperature(&l2), l2);
    }

    #[test]
    fn default_s0_reproduces_its_two_source_points() {
        // η = ν·ρ: 100 mm²/s × 870 kg/m³ at 40 °C, 11.1 mm²/s × 830 kg/m³ at 100 °C.
        let (e40, e100) = (100e-6 * 870.0, 11.1e-6 * 830.0);
        let s0 = roelands_s0_from_two_points(40.0, e40, 100.0, e100, Lubricant::default().roelands_viscosity_limit);
        assert!((s0 - crate::params::DEFAULT_ROELANDS_TEMPERATURE_INDEX).abs() < 5e-4, "{s0}");
        // With that S0 the relation carries one point onto the other.
        let l = Lubricant { viscosity: e40, reference_temperature: 313.15, temperature: 373.15, roelands_temperature_index: s0, ..Lubricant::default() };
        let v = at_temperature(&l).viscosity;
        assert!((v / e100 - 1.0).abs() < 1e-12, "{v} vs {e100}");
    }

    #[test]
    fn roelands_temperature_agrees_with_astm_d341_walther_in_range() {
        // Independent standard relation through the same two points: ASTM D341 (Walther),
        // log10 log10(ν + 0.7) = A − B log10 T, ν in mm²/s. Between 20 and 120 °C the two
        // relations, each fitted to the 40/100 °C points, agree within 5 % in viscosity
        // (measured: see the assertion); they diverge in extrapolation far below 0 °C.
        let (t1, n1, t2, n2) = (313.15f64, 100.0f64, 373.15f64, 11.1f64);
        let ll = |n: f64| (n + 0.7).log10().log10();
        let b = (ll(n1) - ll(n2)) / (t2.log10() - t1.log10());
        let a = ll(n1) + b * t1.log10();
        let walther = |t: f64| 10f64.powf(10f64.powf(a - b * t.log10())) - 0.7;
        let s0 = crate::params::DEFAULT_ROELANDS_TEMPERATURE_INDEX;
        let base = Lubricant { viscosity: 87.0e-3, reference_temperature: 313.15, roelands_temperature_index: s0, ..Lubricant::default() };
        for theta in [20.0, 60.0, 80.0, 120.0] {
            let t = 273.15 + theta;
            // Kinematic → dynamic with ρ(θ) linear through 870 @ 40 °C and 830 @ 100 °C.
            let rho = 870.0 - (theta - 40.0) * 40.0 / 60.0;
            let w = walther(t) * 1e-6 * rho;
            let r = at_temperature(&Lubricant { temperature: t, ..base }).viscosity;
            assert!((r / w - 1.0).abs() < 0.05, "θ={theta}: Roelands {r} vs D341 {w}");
        }
    }

    #[test]
    fn colder_is_more_viscous_and_more_piezoviscous() {
        let l = Lubricant::default();
        let cold = at_temperature(&Lubricant { temperature: 218.15, ..l }); // −55 °C
        let hot = at_temperature(&Lubricant { temperature: 343.15, ..l }); // +70 °C
        assert!(cold.viscosity > 100.0 * l.viscosity, "{}", cold.viscosity);
        assert!(hot.viscosity < l.viscosity && hot.viscosity > l.roelands_viscosity_limit);
        assert!(cold.pressure_viscosity_coefficient > l.pressure_viscosity_coefficient);
        assert!(hot.pressure_viscosity_coefficient < l.pressure_viscosity_coefficient);
        // α ∝ ln(η0/η∞) (Roelands' α* at fixed Z).
        let r = |x: &Lubricant| x.pressure_viscosity_coefficient / (x.viscosity / x.roelands_viscosity_limit).ln();
        assert!((r(&cold) / r(&l) - 1.0).abs() < 1e-12 && (r(&hot) / r(&l) - 1.0).abs() < 1e-12);
    }

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
            let v = roelands(&l, f64::from(i) * 1e7);
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
