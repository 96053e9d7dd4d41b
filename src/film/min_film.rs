//! Minimum film thickness h_min (eq. 21 names it): an extension; the paper gives no h_min
//! relation and its model's unknown is the central film h_c (docs/model.md, conventions).
//!
//! Relation: Pan & Hamrock (1989), "Simple formulas for performance parameters used in
//! elastohydrodynamically lubricated line contacts", ASME J. Tribol. 111, 246–251, fitted to
//! their numerical line-contact solutions, as printed in Hamrock, Schmid & Jacobson,
//! *Fundamentals of Fluid Film Lubrication* (2nd ed., 2004; the paper's ref. \[8\] is Hamrock's
//! book), eqs. (18.72) and (18.74):
//!
//! `h_min/R' = 1.714 W'^−0.128 U^0.694 G^0.568`, `h_c/R' = 2.922 W'^−0.166 U^0.692 G^0.470`,
//!
//! with `W' = P_T/(E'R'B)` (as eq. 12's W), `U = η0 ũ/(E'R')` (their eq. 18.10) on the MEAN
//! surface velocity ũ = (u_a + u_b)/2 = u/2 (eq. 12 uses the sum velocity u), `G = αE'`. Their ratio
//!
//! `h_min/h_c = (1.714/2.922) W'^0.038 U^0.002 G^0.098`
//!
//! is applied to this model's central film h_c (eq. 13, the Moes film at the fluid's share),
//! with the same substitution as eq. 13 (`E' → E'/γ1`, `P_T → P_T/γ1`: W' unchanged,
//! U → γ1 U, G → G/γ1), so `h_min/h_c = (1.714/2.922) W'^0.038 (γ1 U)^0.002 (G/γ1)^0.098`,
//! capped at 1 (a minimum cannot exceed the centre value). Using the ratio rather than the
//! h_min formula alone keeps h_min consistent with the Moes h_c of the load-sharing solve.
//!
//! Neither the paper nor the book was at hand: the coefficients, exponents and equation
//! numbers were read in an independent transcription (github.com/VictorLier/Tribology,
//! `Assignment3/A3.py`, course code citing the book), and `tests/published_values.rs` checks
//! the code against them. Pan & Hamrock's own check values and the range of W', U, G they
//! fitted were not found: searched 2026-11-23 in stored public web pages, documentation, code
//! and GitHub issue threads (the paper's title and authors, a NASA report version of it, the
//! book and its NASA predecessor RP-1255, worked examples in Hamrock, Schmid & Jacobson's
//! *Fundamentals of Machine Elements*, the coefficient strings 1.714/2.922 and exponents);
//! only the paper's citation and the transcription above turned up, no tabulated solution or
//! worked example with numbers. So issue 13's "matches its source's check values" is not
//! tested; what is tested is that the code is the printed fits.
//!
//! Validity: Pan & Hamrock fitted numerical solutions in the elastic–piezoviscous regime of
//! heavily loaded steel line contacts (W' of order 1e-5 to 1e-4, G of order 5000: the usual
//! range, written from memory, their stated range not found). This conformal pin
//! joint has W' ≈ 2e-8–2e-7: far below it, and its film is near the rigid/elastic–isoviscous
//! boundary (Moes M ≈ 1–100, L ≈ 0.1–1). So h_min here is an extrapolation of the fit. In
//! particular the fit has no rigid–isoviscous limit (where h_min → h_c): as the fluid share
//! 1/γ1 → 0 (speed → 0) the factor (G/γ1)^0.098 → 0 and h_min → 0, which only says the fit
//! does not apply there; at ω = 0 (no fluid film) h_min is reported as 0.

/// ln(1.714/2.922).
const LN_C: f64 = -0.5334384931529198;

/// ln(h_min/h_c) for ln W', ln U (mean-velocity U = η0·(u/2)/(E'R')), ln G and the fluid
/// share ln x1 = ln(1/γ1); capped at 0 (h_min ≤ h_c). −∞ when ln x1 = −∞ (no fluid film).
pub fn ln_min_to_central(ln_w: f64, ln_u_mean: f64, ln_g: f64, ln_x1: f64) -> f64 {
    if ln_x1 == f64::NEG_INFINITY || ln_u_mean == f64::NEG_INFINITY {
        return f64::NEG_INFINITY;
    }
    (LN_C + 0.038 * ln_w + 0.002 * (ln_u_mean - ln_x1) + 0.098 * (ln_g + ln_x1)).min(0.0)
}

/// Pan–Hamrock minimum film h_min/R' (flooded, unscaled): Hamrock, Schmid & Jacobson (2004)
/// eq. (18.72), for W', mean-velocity U and G.
pub fn pan_hamrock_min(w: f64, u_mean: f64, g: f64) -> f64 {
    1.714 * w.powf(-0.128) * u_mean.powf(0.694) * g.powf(0.568)
}

/// Pan–Hamrock central film h_c/R' (flooded, unscaled): Hamrock, Schmid & Jacobson (2004)
/// eq. (18.74), for W', mean-velocity U and G.
pub fn pan_hamrock_central(w: f64, u_mean: f64, g: f64) -> f64 {
    2.922 * w.powf(-0.166) * u_mean.powf(0.692) * g.powf(0.470)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant() {
        assert!((LN_C - (1.714f64 / 2.922).ln()).abs() < 1e-16);
    }

    #[test]
    fn ratio_equals_quotient_of_the_two_fits() {
        // Inside Pan & Hamrock's range: W' = 1e-4, U = 1e-11, G = 5000 (steel, mineral oil).
        for (w, u, g) in [(1e-4f64, 1e-11f64, 5000f64), (2e-5, 1e-12, 2500.0), (5e-4, 1e-10, 4000.0)] {
            let ratio = pan_hamrock_min(w, u, g) / pan_hamrock_central(w, u, g);
            let got = ln_min_to_central(w.ln(), u.ln(), g.ln(), 0.0).exp();
            assert!((got / ratio - 1.0).abs() < 1e-12, "{got} vs {ratio}");
            // Inside their range the exit constriction makes h_min 0.79–0.95 of h_c for these three
            // conditions (computed by hand: 0.906, 0.790, 0.946): below 1, not far below.
            assert!(ratio > 0.75 && ratio < 0.96, "{ratio}");
        }
    }

    #[test]
    fn gamma1_substitution_is_the_fit_at_the_substituted_groups() {
        // Evaluate both fits directly at E'/γ1, P/γ1 (W' same, U·γ1, G/γ1).
        let (w, u, g) = (1e-4f64, 1e-11f64, 5000f64);
        for gamma1 in [1.0f64, 2.0, 10.0] {
            let (us, gs) = (u * gamma1, g / gamma1);
            let direct = pan_hamrock_min(w, us, gs) / pan_hamrock_central(w, us, gs);
            let got = ln_min_to_central(w.ln(), u.ln(), g.ln(), -gamma1.ln()).exp();
            assert!((got / direct - 1.0).abs() < 1e-12, "γ1={gamma1}");
        }
    }

    #[test]
    fn capped_and_zero_without_fluid() {
        assert_eq!(ln_min_to_central(0.0, 0.0, 30.0, 0.0), 0.0);
        assert_eq!(ln_min_to_central(-16.0, -35.0, 8.0, f64::NEG_INFINITY), f64::NEG_INFINITY);
    }
}
