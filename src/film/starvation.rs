//! Starved-inlet correction of the central film: an extension, not in the paper, OFF by
//! default (`starvation.inlet_layer_inverse = 0`, the paper's fully flooded model, bit for bit).
//!
//! Relation (Chevalier, Lubrecht, Cann, Colin & Dalmaz, 1998, "Film thickness in starved EHL
//! point contacts", ASME J. Tribol. 120, 126–133; used for line and elliptical contacts by
//! Damiens, Venner, Cann & Lubrecht, 2004, J. Tribol. 126, 105–111): with the flooded central
//! film h_ff and the lubricant layer h_oil available on the surfaces ahead of the inlet,
//!
//! `h_c/h_ff = R/(1 + R^γs)^(1/γs)`, `R = h_oil/h_ff`, i.e. `h_c^−γs = h_ff^−γs + h_oil^−γs`:
//!
//! a smooth minimum of the flooded film and the layer that feeds it (mass conservation: a film
//! cannot be thicker than the oil brought to it). R → ∞ is the flooded film; R → 0 gives
//! h_c → h_oil. The default γs = 2.8 is a circular-contact value written from memory.
//!
//! **Not verified against the sources.** Neither paper was at hand, and no published value,
//! table, worked example or digitised figure point of the relation, nor any γs for a line
//! contact, was found (searched 2026-11-23 in stored public web pages, documentation, code and
//! GitHub issue threads: the titles and authors of Chevalier et al. 1998, Damiens et al. 2004,
//! Cann, Damiens & Lubrecht 2004, Wedeven, Evans & Cameron 1971, Hamrock & Dowson 1977 (part
//! IV, starvation), Wolveridge, Baglin & Archard 1970; the relation's symbols and phrases;
//! tribology code repositories). Found: (1) Damiens et al.'s abstract (University of Twente
//! repository): "a single parameter, characteristic of the inlet length of the contact in the
//! fully flooded regime, determines the starved behavior", i.e. γs depends on the operating
//! conditions, no number; (2) a secondary source, an AI-assisted Korean summary in public
//! GitHub notes (dated 2026-03-10) of Lugt, *Grease Lubrication in Rolling Bearings* (Wiley,
//! 2013), ch. 9, whose eq. (9.73) is this form, h_c/h_cff = r/(1 + r^γ)^(1/γ), with γ "about 3
//! for circular contacts, up to 15 for wide elliptical contacts". That corroborates the form
//! (not the 1998 paper's own wording) and says nothing sure about a line contact, except that
//! γs there may be well above 2.8. Over 2.8–15 the starvation figure's numbers move a lot:
//! at 20 kN, h_oil = 4 µm, μ = 0.11 is crossed at 26.5 rpm with γs = 2.8 and 17.1 rpm with
//! γs = 15 (flooded: 17.0); h_oil = 3.4 µm: 69.2 and 19.5 rpm
//! (`tests/published_values.rs::starvation_exponent_sensitivity_over_the_quoted_range`). So
//! γs (`starvation.exponent`, a parameter-file key like the layer) is as uncertain as the
//! layer itself. The
//! tests check the form's limits and identities (`tests/published_values.rs`,
//! `crates/fmu/tests/extensions.rs`) and that sensitivity, not published numbers.
//!
//! Here it is applied to the film of eq. 13 (the fluid's share of the load, E'/γ1, P/γ1), so
//! the load sharing is solved with the starved film: `h_c(x1)^−γs = h_13(x1)^−γs + h_oil^−γs`.
//! The parameter 1/h_oil stands for how much grease the reciprocating stroke brings back into
//! the track (the paper, section 5: "the high load squeezes grease out of the contact ... the
//! lower the reciprocation frequency the harder it is for the grease to flow back"); the model
//! holds it constant, it does not predict it. Validity: the relation was derived for steady
//! EHL contacts fed by a uniform oil layer; for a grease-lubricated oscillating pin it is a
//! one-parameter phenomenological description, to be fitted (`pinjoint calibrate` can fit
//! `starvation.inlet_layer_inverse`).

/// Default γs of the starvation relation: a circular-contact value from memory, not verified
/// against the sources (a secondary summary of Lugt 2013 quotes about 3 for circular and up to
/// 15 for wide elliptical contacts; see the module doc).
pub const DEFAULT_EXPONENT: f64 = 2.8;

/// The starvation relation in logarithms: ln h_c from ln h_ff (flooded film) with
/// `ln_q = ln(1/h_oil)`, and d ln h_c / d ln h_ff. Exact for ln h_ff = +∞ (h_c = h_oil).
pub fn ln_starved(ln_hff: f64, ln_q: f64, gamma: f64) -> (f64, f64) {
    let (a, b) = (-gamma * ln_hff, gamma * ln_q);
    let (hi, lo) = if a > b { (a, b) } else { (b, a) };
    if lo == f64::NEG_INFINITY {
        return (-hi / gamma, if a > b { 1.0 } else { 0.0 });
    }
    let e = (lo - hi).exp();
    let w_hi = 1.0 / (1.0 + e);
    let w_a = if a > b { w_hi } else { e * w_hi };
    (-(hi + (1.0 + e).ln()) / gamma, w_a)
}

/// h_c/h_ff = R/(1 + R^γs)^(1/γs) for R = h_oil/h_ff: the relation as published.
pub fn starved_ratio(r: f64, gamma: f64) -> f64 {
    r / (1.0 + r.powf(gamma)).powf(1.0 / gamma)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_form_equals_published_form() {
        for &g in &[1.5, 2.8, 3.5] {
            for &r in &[1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3] {
                let hff: f64 = 2.5e-6;
                let hoil = r * hff;
                let (ln_h, w) = ln_starved(hff.ln(), -hoil.ln(), g);
                let want = starved_ratio(r, g) * hff;
                assert!((ln_h.exp() / want - 1.0).abs() < 1e-13, "γ={g} R={r}");
                // Derivative by central differences.
                let e = 1e-6;
                let fd = (ln_starved(hff.ln() + e, -hoil.ln(), g).0 - ln_starved(hff.ln() - e, -hoil.ln(), g).0) / (2.0 * e);
                assert!((w - fd).abs() < 1e-8, "γ={g} R={r}: {w} vs {fd}");
            }
        }
    }

    #[test]
    fn limits() {
        // Flooded: R → ∞ gives h_ff; fully starved: R → 0 gives h_oil; R = 1 gives 2^(−1/γ).
        assert!((starved_ratio(1e9, 2.8) - 1.0).abs() < 1e-15);
        assert!((starved_ratio(1e-9, 2.8) / 1e-9 - 1.0).abs() < 1e-12);
        assert!((starved_ratio(1.0, 2.8) - 2f64.powf(-1.0 / 2.8)).abs() < 1e-15);
        // Never thicker than either the flooded film or the layer.
        for &r in &[0.01, 0.3, 1.0, 3.0, 100.0] {
            let v = starved_ratio(r, 2.8);
            assert!(v < 1.0 && v < r);
        }
        // ln h_ff = +∞ (x1 → 0 in eq. 13): h_c = h_oil exactly, no NaN.
        let (ln_h, w) = ln_starved(f64::INFINITY, 1e6f64.ln(), 2.8);
        assert!((ln_h + 1e6f64.ln()).abs() < 1e-15 && w == 0.0);
    }
}
