//! Elastohydrodynamic film: Moes' central film thickness for a line contact (eq. 12),
//! and its load-sharing form (eqs. 13–14), where the fluid carries `P_T/γ1`.
//!
//! Everything is evaluated in logarithms: at ω → 0 the dimensionless speed U_Σ spans
//! dozens of decades, and γ1 goes to infinity.
//!
//! Dimensionless groups (eq. 12): `W = P_T/(E'R'B)`, `U_Σ = η0 u/(E'R')`, `G = α E'`,
//! `M = W U_Σ^{-1/2}`, `L = G U_Σ^{1/4}`, `H_C = (h_c/R') U_Σ^{-1/2}`. Per docs/model.md (errata 2 and 3),
//! `u` is Moes' sum velocity, which for a fixed bush equals the sliding speed |ω|R.

/// Numerically stable ln(eᵃ + eᵇ), exact for infinite arguments.
pub fn log_add_exp(a: f64, b: f64) -> f64 {
    if a == b {
        return a + std::f64::consts::LN_2;
    }
    let (hi, lo) = if a > b { (a, b) } else { (b, a) };
    if lo == f64::NEG_INFINITY || hi == f64::INFINITY {
        return hi;
    }
    hi + (lo - hi).exp().ln_1p()
}

use crate::numerics::fast_math::exp;

const LN_3: f64 = 1.098_612_288_668_109_8; // ln 3
const C_EI: f64 = 2.621;
const C_RP: f64 = 1.287;
const C_EP: f64 = 1.311;
// ln of the three constants (tests check them against C_*.ln()).
const LN_C_EI: f64 = 0.9635559243412692;
const LN_C_RP: f64 = 0.25231392861398955;
const LN_C_EP: f64 = 0.27079020478156274;

/// Unscaled Moes central film, eq. 12, in logarithms: returns (ln H_C, s) for (ln M, ln L).
pub fn ln_moes(ln_m: f64, ln_l: f64) -> (f64, f64) {
    let (ln_h, s, _) = ln_moes_slope(ln_m, ln_l, 0.0, 0.0);
    (ln_h, s)
}

/// Eq. 12 in logarithms with its directional derivative: returns (ln H_C, s, d ln H_C) for
/// a change (d ln M, d ln L) = (`dm`, `dl`). The derivative is exact (chain rule through
/// the log-sum-exp weights and through s); it costs no extra transcendental function.
pub fn ln_moes_slope(ln_m: f64, ln_l: f64, dm: f64, dl: f64) -> (f64, f64, f64) {
    let (ln_h, s, g_m, g_l) = ln_moes_grad(ln_m, ln_l);
    (ln_h, s, g_m * dm + g_l * dl)
}

/// Eq. 12 in logarithms with its gradient: returns (ln H_C, s, ∂ln H_C/∂ln M, ∂ln H_C/∂ln L).
/// Exact (chain rule through the log-sum-exp weights and through s), from the same five
/// exponentials and three logarithms as the value.
pub fn ln_moes_grad(ln_m: f64, ln_l: f64) -> (f64, f64, f64, f64) {
    let ln_hri = LN_3 - ln_m;
    let ln_hei = LN_C_EI - ln_m / 5.0;
    let ln_hrp = LN_C_RP + 2.0 / 3.0 * ln_l;
    let ln_hep = LN_C_EP - ln_m / 8.0 + 0.75 * ln_l;
    let q = exp(ln_hei - ln_hri); // H_EI/H_RI
    let e2q = exp(-2.0 * q);
    let s = (7.0 + 8.0 * e2q) / 5.0;
    // A = ln(H_RI^{7/3} + H_EI^{7/3}), B = ln(H_RP^{-7/2} + H_EP^{-7/2}), with softmax weights.
    let (a, va) = log_add_exp_weight(7.0 / 3.0 * ln_hri, 7.0 / 3.0 * ln_hei);
    let (b, ub) = log_add_exp_weight(-3.5 * ln_hrp, -3.5 * ln_hep);
    let (phi, w1) = log_add_exp_weight(3.0 * s / 7.0 * a, -2.0 * s / 7.0 * b);
    let ln_h = phi / s;
    // ∂/∂ln M of the four ln H's: −1, −1/5, 0, −1/8; ∂/∂ln L: 0, 0, 2/3, 3/4.
    // s depends on ln M only: ∂s/∂ln M = (8/5) e^{−2q} (−2q) ∂ln q/∂ln M, ∂ln q/∂ln M = 4/5.
    let ds_m = 8.0 / 5.0 * e2q * (-2.0 * q) * 0.8;
    let w2 = 1.0 - w1;
    let da_m = -va - (1.0 - va) / 5.0; // (3/7)·∂A/∂ln M
    let db_m = -(1.0 - ub) / 8.0; // −(2/7)·∂B/∂ln M
    let db_l = ub * (2.0 / 3.0) + (1.0 - ub) * 0.75; // −(2/7)·∂B/∂ln L
    let terms = if w1 > 0.0 { 3.0 / 7.0 * w1 * a } else { 0.0 } - if w2 > 0.0 { 2.0 / 7.0 * w2 * b } else { 0.0 };
    let g_m = if ds_m != 0.0 { ds_m * (-phi / (s * s) + terms / s) } else { 0.0 } + w1 * da_m + w2 * db_m;
    (ln_h, s, g_m, w2 * db_l)
}

/// Eq. 12 in logarithms with its first and second derivatives along the direction
/// (d ln M, d ln L) = (`dm`, `dl`): returns (ln H_C, d ln H_C/dτ, d²ln H_C/dτ²) for
/// ln M = ln M₀ + dm·τ, ln L = ln L₀ + dl·τ. The chain rule through the same log-sum-exp
/// weights (for ln(eᵃ + eᵇ) with weights w, 1 − w: the first derivative is w a′ + (1 − w) b′,
/// the second w a″ + (1 − w) b″ + w(1 − w)(a′ − b′)²) and through s of eq. 14; the curvature
/// of the load-sharing residual's film term ([`crate::load_sharing::solve`]'s third-order first step).
/// Not guarded for infinite intermediate values (the caller checks the result is finite).
pub fn ln_moes_directional(ln_m: f64, ln_l: f64, dm: f64, dl: f64) -> (f64, f64, f64) {
    let (ln_h, _, _, d1, d2) = moes_second::<false>(ln_m, ln_l, dm, dl);
    (ln_h, d1, d2)
}

/// [`ln_moes_directional`] and the gradient of [`ln_moes_grad`] (bit for bit): returns
/// (ln H_C, ∂ln H_C/∂ln M, ∂ln H_C/∂ln L, d ln H_C/dτ, d²ln H_C/dτ²).
pub fn ln_moes_grad_directional(ln_m: f64, ln_l: f64, dm: f64, dl: f64) -> (f64, f64, f64, f64, f64) {
    moes_second::<true>(ln_m, ln_l, dm, dl)
}

#[inline(always)]
fn moes_second<const GRAD: bool>(ln_m: f64, ln_l: f64, dm: f64, dl: f64) -> (f64, f64, f64, f64, f64) {
    let ln_hri = LN_3 - ln_m;
    let ln_hei = LN_C_EI - ln_m / 5.0;
    let ln_hrp = LN_C_RP + 2.0 / 3.0 * ln_l;
    let ln_hep = LN_C_EP - ln_m / 8.0 + 0.75 * ln_l;
    let q = exp(ln_hei - ln_hri);
    let e2q = exp(-2.0 * q);
    let s = (7.0 + 8.0 * e2q) / 5.0;
    let (a, va) = log_add_exp_weight(7.0 / 3.0 * ln_hri, 7.0 / 3.0 * ln_hei);
    let (b, ub) = log_add_exp_weight(-3.5 * ln_hrp, -3.5 * ln_hep);
    let (phi, w1) = log_add_exp_weight(3.0 * s / 7.0 * a, -2.0 * s / 7.0 * b);
    let ln_h = phi / s;
    let w2 = 1.0 - w1;
    // Along τ: q′ = q·c_q with c_q = (4/5)dm; s′ = −(16/5) q′ e^{−2q}, s″ = −(16/5) c_q q′ e^{−2q}(1 − 2q).
    let c_q = 0.8 * dm;
    let s1 = -3.2 * c_q * q * e2q;
    let s2 = s1 * c_q * (1.0 - 2.0 * q);
    // A = ln(e^{a1} + e^{a2}) with a1′ = −(7/3)dm, a2′ = −(7/15)dm; B likewise with
    // b1′ = −(7/3)dl, b2′ = (7/16)dm − (21/8)dl.
    let (a1, a2) = (-7.0 / 3.0 * dm, -7.0 / 15.0 * dm);
    let (b1, b2) = (-7.0 / 3.0 * dl, 0.4375 * dm - 2.625 * dl);
    let a_1 = va * a1 + (1.0 - va) * a2;
    let a_2 = va * (1.0 - va) * (a1 - a2) * (a1 - a2);
    let b_1 = ub * b1 + (1.0 - ub) * b2;
    let b_2 = ub * (1.0 - ub) * (b1 - b2) * (b1 - b2);
    // φ = ln(e^{P1} + e^{P2}), P1 = (3s/7)A, P2 = −(2s/7)B.
    let p1_1 = 3.0 / 7.0 * (s1 * a + s * a_1);
    let p1_2 = 3.0 / 7.0 * (s2 * a + 2.0 * s1 * a_1 + s * a_2);
    let p2_1 = -2.0 / 7.0 * (s1 * b + s * b_1);
    let p2_2 = -2.0 / 7.0 * (s2 * b + 2.0 * s1 * b_1 + s * b_2);
    let phi_1 = w1 * p1_1 + w2 * p2_1;
    let phi_2 = w1 * p1_2 + w2 * p2_2 + w1 * w2 * (p1_1 - p2_1) * (p1_1 - p2_1);
    // ln H = φ/s: (ln H)′ = (φ′ − ln H·s′)/s, (ln H)″ = (φ″ − 2(ln H)′s′ − ln H·s″)/s.
    let inv_s = 1.0 / s;
    let h_1 = (phi_1 - ln_h * s1) * inv_s;
    let h_2 = (phi_2 - 2.0 * h_1 * s1 - ln_h * s2) * inv_s;
    if !GRAD {
        return (ln_h, f64::NAN, f64::NAN, h_1, h_2);
    }
    // The gradient, as ln_moes_grad.
    let ds_m = 8.0 / 5.0 * e2q * (-2.0 * q) * 0.8;
    let da_m = -va - (1.0 - va) / 5.0;
    let db_m = -(1.0 - ub) / 8.0;
    let db_l = ub * (2.0 / 3.0) + (1.0 - ub) * 0.75;
    let terms = if w1 > 0.0 { 3.0 / 7.0 * w1 * a } else { 0.0 } - if w2 > 0.0 { 2.0 / 7.0 * w2 * b } else { 0.0 };
    let g_m = if ds_m != 0.0 { ds_m * (-phi / (s * s) + terms / s) } else { 0.0 } + w1 * da_m + w2 * db_m;
    (ln_h, g_m, w2 * db_l, h_1, h_2)
}

/// ln(eᵃ + eᵇ) and the weight eᵃ/(eᵃ + eᵇ) of its first argument, from one exponential.
fn log_add_exp_weight(a: f64, b: f64) -> (f64, f64) {
    if a == b {
        return (a + std::f64::consts::LN_2, 0.5);
    }
    let a_hi = a > b;
    let (hi, lo) = if a_hi { (a, b) } else { (b, a) };
    if lo == f64::NEG_INFINITY || hi == f64::INFINITY {
        return (hi, if a_hi { 1.0 } else { 0.0 });
    }
    let e = exp(lo - hi); // ≤ 1
    let w_hi = 1.0 / (1.0 + e);
    // ln(1 + e) to an absolute error of ε (crate::numerics::fast_math::ln_1p_unit): an absolute error of ε
    // in a logarithm is a relative error of ε in the quantity.
    (hi + crate::numerics::fast_math::ln_1p_unit(e), if a_hi { w_hi } else { e * w_hi })
}

/// Unscaled Moes central film H_C (eq. 12) and its exponent s.
pub fn moes(m: f64, l: f64) -> (f64, f64) {
    let (ln_h, s) = ln_moes(m.ln(), l.ln());
    (ln_h.exp(), s)
}

/// Eq. 13 as a function of γ1, by the substitution the text states:
/// eq. 12 with `E' → E'/γ1`, `P_T → P_T/γ1`, which maps `U_Σ → γ1 U_Σ`, `W → W`,
/// `G → G/γ1`, hence `M → M γ1^{-1/2}`, `L → L γ1^{-3/4}`, and
/// `(h_c/R') U_Σ^{-1/2} = γ1^{1/2} H_C(M γ1^{-1/2}, L γ1^{-3/4})`.
///
/// Returns ln[(h_c/R') U_Σ^{-1/2}] for `ln_x1 = ln(1/γ1)`.
pub fn ln_scaled_moes(ln_m: f64, ln_l: f64, ln_x1: f64) -> (f64, f64) {
    let (ln_h, s) = ln_moes(ln_m + 0.5 * ln_x1, ln_l + 0.75 * ln_x1);
    (ln_h - 0.5 * ln_x1, s)
}

/// [`ln_scaled_moes`] and its derivative with respect to ln x1.
pub fn ln_scaled_moes_slope(ln_m: f64, ln_l: f64, ln_x1: f64) -> (f64, f64) {
    let (ln_h, g_m, g_l) = ln_scaled_moes_grad(ln_m, ln_l, ln_x1);
    (ln_h, 0.5 * g_m + 0.75 * g_l - 0.5)
}

/// [`ln_scaled_moes`] and its partial derivatives with respect to ln M and ln L (at fixed
/// ln x1); its derivative with respect to ln x1 is `0.5·∂_M + 0.75·∂_L − 0.5`.
pub fn ln_scaled_moes_grad(ln_m: f64, ln_l: f64, ln_x1: f64) -> (f64, f64, f64) {
    let (ln_h, _, g_m, g_l) = ln_moes_grad(ln_m + 0.5 * ln_x1, ln_l + 0.75 * ln_x1);
    (ln_h - 0.5 * ln_x1, g_m, g_l)
}

/// Eq. 13 in its closed form with the corrected exponents (errata 2 and 3):
/// `[γ1^{s/2}(H_RI^{7/3} + γ1^{-14/15} H_EI^{7/3})^{3s/7} + γ1^{-s/2}(H_RP^{-7/2} + H_EP^{-7/2})^{-2s/7}]^{1/s} γ1^{1/2}`
/// with `s = (7 + 8 exp(−2 (H_EI/H_RI) γ1^{-2/5}))/5` (eq. 14), H's of the unscaled M, L.
/// `hei_exp` and `s_exp` are the exponents on γ1 (−14/15 and −2/5 corrected;
/// the paper prints −14/5 and −7/5), so the tests can show the printed ones are wrong.
pub fn eq13_closed_form(m: f64, l: f64, gamma1: f64, hei_exp: f64, s_exp: f64) -> f64 {
    let hri = 3.0 / m;
    let hei = C_EI * m.powf(-0.2);
    let hrp = C_RP * l.powf(2.0 / 3.0);
    let hep = C_EP * m.powf(-0.125) * l.powf(0.75);
    let s = (7.0 + 8.0 * (-2.0 * hei / hri * gamma1.powf(s_exp)).exp()) / 5.0;
    let t1 = gamma1.powf(s / 2.0) * (hri.powf(7.0 / 3.0) + gamma1.powf(hei_exp) * hei.powf(7.0 / 3.0)).powf(3.0 * s / 7.0);
    let t2 = gamma1.powf(-s / 2.0) * (hrp.powf(-3.5) + hep.powf(-3.5)).powf(-2.0 * s / 7.0);
    (t1 + t2).powf(1.0 / s) * gamma1.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The check values of eq. 12 in docs/model.md: (M, L, H, s).
    const CHECK: [(f64, f64, f64, f64); 4] = [
        (1.0, 1.0, 4.05598902635954, 1.678780734472748),
        (10.0, 10.0, 5.464316870977172, 1.4000260648115448),
        (100.0, 10.0, 4.296808913149384, 1.4),
        (1000.0, 5.0, 2.110980706283332, 1.4),
    ];

    #[test]
    fn moes_matches_model_notes() {
        for (m, l, h, s) in CHECK {
            let (gh, gs) = moes(m, l);
            assert!(((gh - h) / h).abs() < 1e-13, "M={m} L={l}: {gh} vs {h}");
            assert!((gs - s).abs() < 1e-13, "s at M={m}: {gs} vs {s}");
        }
    }

    #[test]
    fn moes_asymptotes() {
        // Each regime's asymptote dominates far inside it.
        // Rigid-isoviscous: M → 0, L → 0: H → H_RI = 3/M.
        let (h, _) = moes(1e-6, 1e-6);
        assert!((h / 3e6 - 1.0).abs() < 1e-6);
        // Elastic-isoviscous: M → ∞, L → 0: H → H_EI = 2.621 M^{-1/5}.
        let m: f64 = 1e8;
        let (h, _) = moes(m, 1e-12);
        assert!((h / (2.621 * m.powf(-0.2)) - 1.0).abs() < 1e-3, "{h}");
        // Elastic-piezoviscous: M, L large: H → H_EP = 1.311 M^{-1/8} L^{3/4}.
        let (m, l): (f64, f64) = (1e12, 1e6);
        let (h, _) = moes(m, l);
        assert!((h / (1.311 * m.powf(-0.125) * l.powf(0.75)) - 1.0).abs() < 1e-3, "{h}");
    }

    #[test]
    fn substitution_identity_holds_for_corrected_exponents() {
        // Erratum 2 and 3: eq. 13 must equal eq. 12 evaluated directly with E'/γ1 and
        // P_T/γ1 times γ1^{1/2}. Evaluate eq. 12 *from the dimensional quantities* with
        // E' and P replaced, independent of the algebra in ln_scaled_moes.
        let (e, r, b, eta_u, alpha, p) = (165.9e9, 31.388, 0.0594, 12.45e-3 * 0.5, 16.9e-9, 20e3);
        let groups = |e: f64, p: f64| {
            let w = p / (e * r * b);
            let u = eta_u / (e * r);
            let g = alpha * e;
            (w * u.powf(-0.5), g * u.powf(0.25), u)
        };
        let (m, l, u) = groups(e, p);
        for gamma1 in [1.0, 1.5, 3.0, 10.0, 1e3, 1e6] {
            let (ms, ls, us) = groups(e / gamma1, p / gamma1);
            let (h_sub, _) = moes(ms, ls);
            // h_c/R' from the substituted problem, re-expressed in the unscaled U_Σ, times γ1^{1/2} as printed:
            // (h_c/R') U^{-1/2} = H(ms, ls) (us/u)^{1/2} = γ1^{1/2} H(ms, ls).
            let direct = h_sub * (us / u).sqrt();
            assert!((direct / (gamma1.sqrt() * h_sub) - 1.0).abs() < 1e-12);
            let closed = eq13_closed_form(m, l, gamma1, -14.0 / 15.0, -0.4);
            assert!((closed / direct - 1.0).abs() < 1e-12, "γ1={gamma1}: {closed} vs {direct}");
            let (ln_code, _) = ln_scaled_moes(m.ln(), l.ln(), -gamma1.ln());
            assert!((ln_code.exp() / direct - 1.0).abs() < 1e-12, "γ1={gamma1}");
            if gamma1 > 1.0 && gamma1 < 1e5 {
                // (At γ1 ≳ 1e5 the rigid term dominates both forms and they coincide.)
                // The printed exponents (−14/5 and −7/5) fail the same test.
                let printed = eq13_closed_form(m, l, gamma1, -14.0 / 5.0, -1.4);
                assert!((printed / direct - 1.0).abs() > 1e-3, "γ1={gamma1}: printed form agrees?");
            }
        }
    }

    #[test]
    fn corrected_film_is_monotone_in_gamma1_printed_is_not() {
        // h_c must grow with γ1 (the fluid carries less load → thicker film).
        // Over a range of conditions where eq. 12's elastic terms matter.
        let (m, l) = (30.0, 8.0);
        let mut prev = 0.0;
        let mut printed_monotone = true;
        let mut prev_p = 0.0;
        for i in 0..400 {
            let g = 1.0 + f64::from(i) * 0.05;
            let v = eq13_closed_form(m, l, g, -14.0 / 15.0, -0.4);
            assert!(v > prev, "corrected form not increasing at γ1={g}");
            prev = v;
            let vp = eq13_closed_form(m, l, g, -14.0 / 5.0, -1.4);
            if vp <= prev_p {
                printed_monotone = false;
            }
            prev_p = vp;
        }
        assert!(!printed_monotone, "printed exponents unexpectedly monotone");
    }

    #[test]
    fn slope_matches_central_differences() {
        for (lm, ll) in [(0.0, 0.0), (2.3, 2.3), (4.6, 2.3), (6.9, 1.6), (-3.0, -5.0), (15.0, 4.0), (-0.5, 0.7)] {
            for (dm, dl) in [(1.0, 0.0), (0.0, 1.0), (0.5, 0.75)] {
                let (_, _, d) = ln_moes_slope(lm, ll, dm, dl);
                let e = 1e-6;
                let fd = (ln_moes(lm + e * dm, ll + e * dl).0 - ln_moes(lm - e * dm, ll - e * dl).0) / (2.0 * e);
                assert!((d - fd).abs() < 1e-7 * (1.0 + fd.abs()), "({lm},{ll}) dir ({dm},{dl}): {d} vs {fd}");
            }
        }
    }

    #[test]
    fn directional_derivatives_match_the_gradient_and_differences() {
        // d ln H/dτ against the gradient of ln_moes_grad, d²ln H/dτ² against central
        // differences of that exact first derivative, across the regimes of eq. 12.
        for (lm, ll) in [(0.0, 0.0), (2.3, 2.3), (4.6, 2.3), (6.9, 1.6), (-3.0, -5.0), (15.0, 4.0), (-0.5, 0.7), (1.2, 3.0)] {
            for (dm, dl) in [(1.0, 0.0), (0.0, 1.0), (0.5, 0.75), (-0.5, 0.25)] {
                let (ln_h, d1, d2) = ln_moes_directional(lm, ll, dm, dl);
                let (v, _, g) = ln_moes_slope(lm, ll, dm, dl);
                assert_eq!(ln_h, v, "the value is ln_moes_grad's");
                let (v2, g_m, g_l, d1b, d2b) = ln_moes_grad_directional(lm, ll, dm, dl);
                let (_, _, gm0, gl0) = ln_moes_grad(lm, ll);
                assert_eq!((v2, g_m, g_l, d1b, d2b), (ln_h, gm0, gl0, d1, d2), "the same numbers with the gradient");
                assert!((d1 - g).abs() < 1e-13 * (1.0 + g.abs()), "({lm},{ll}) dir ({dm},{dl}): {d1} vs {g}");
                let e = 1e-5;
                let slope = |k: f64| ln_moes_slope(lm + k * e * dm, ll + k * e * dl, dm, dl).2;
                let fd = (slope(1.0) - slope(-1.0)) / (2.0 * e);
                assert!((d2 - fd).abs() < 1e-6 * (1.0 + fd.abs()), "({lm},{ll}) dir ({dm},{dl}): {d2} vs {fd}");
            }
        }
    }

    #[test]
    fn log_constants() {
        assert_eq!(LN_C_EI, C_EI.ln());
        assert_eq!(LN_C_RP, C_RP.ln());
        assert_eq!(LN_C_EP, C_EP.ln());
        assert_eq!(LN_3, 3f64.ln());
    }

    #[test]
    fn log_add_exp_edge_cases() {
        assert_eq!(log_add_exp(f64::NEG_INFINITY, 1.0), 1.0);
        assert_eq!(log_add_exp(f64::INFINITY, f64::INFINITY), f64::INFINITY);
        assert!((log_add_exp(0.0, 0.0) - 2f64.ln()).abs() < 1e-15);
        assert!((log_add_exp(1000.0, 999.0) - (1000.0 + (1.0 + (-1.0f64).exp()).ln())).abs() < 1e-12);
    }
}
