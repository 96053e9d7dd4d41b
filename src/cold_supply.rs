//! The cold supply (complete model, grease enabled): below the reference temperature the
//! grease feeds the contact less oil. Not in the paper; docs/cold-day.md.
//!
//! A grease lubricates the contact through the oil its thickener releases (bleed) and the
//! oil that flows back into the track between passes: Darcy flow of the base oil through the
//! thickener (Baart, van der Vorst, Lugt & van Ostayen, 2010, Tribol. Trans. 53, 340–348) and
//! capillary replenishment of the track (Gershuni, Larson & Lugt, 2008, Tribol. Trans. 51,
//! 643–651), both viscous flows driven by surface tension, so their rate scales like 1/η_b
//! (the exponent m = 1, [`crate::grease::DEFAULT_SUPPLY_EXPONENT`]; the papers' findings as
//! the journal-bearing work recalled them, not checked against their text here). The film the
//! supply allows is the film the flooded contact had at the
//! reference temperature, scaled by the replenishment ratio:
//!
//! `h_13,supplied(x1; T) = min(h_13(x1; T), h_13(x1; T_ref)·(η_b(T_ref)/η_b(T))^m)` for
//! T < T_ref, unchanged for T ≥ T_ref (the contact flooded there: T_ref is where this
//! assumption puts the boundary between a flooded and a supply-limited contact).
//!
//! The minimum is always its second argument: eq. 12's film grows with η0·u and with α
//! (Moes' H in M and L), and below T_ref both η_b and α (Roelands' temperature relation,
//! [`crate::viscosity::at_temperature`]) are at least their reference values, so
//! h_13(x1; T) ≥ h_13(x1; T_ref) ≥ h_13(x1; T_ref)·(η_b(T_ref)/η_b(T))^m for m ≥ 0
//! (`tests/complete.rs` checks it on the film groups). The supplied film is therefore the
//! reference film groups (η0 and α at T_ref) with ln(R'U^½) shifted by
//! m·ln(η_b(T_ref)/η_b(T)) ≤ 0 ([`supplied`]): one shift, no extra work per solve. The film
//! is non-increasing as T falls, so the contact's torque stiffens as it cools.
//!
//! m (`grease.supply_exponent`, default 1) is the uncertain part: no published measurement
//! of the replenishment of a landing-gear grease against temperature was found; docs/cold-day.md
//! shows the sensitivity to m over 0.5–2. The same ratio scales the journal bearing's film
//! below T_ref ([`crate::composite`]).

use crate::mixed::FilmGroups;

/// ln of the replenishment ratio (η_b(T_ref)/η_b(T))^m, i.e. m·(ln η_b(T_ref) − ln η_b(T)),
/// when the supply limits the film (grease enabled, T < T_ref); `None` when the contact is
/// flooded (T ≥ T_ref or grease disabled).
pub fn ln_supply_ratio(enabled: bool, exponent: f64, temperature: f64, reference_temperature: f64, ln_eta_ref: f64, ln_eta: f64) -> Option<f64> {
    (enabled && temperature < reference_temperature).then(|| exponent * (ln_eta_ref - ln_eta))
}

/// The film groups of the supplied film: `reference` (eq. 12's groups with η0 and α at
/// T_ref) with the film scaled by the replenishment ratio e^`ln_ratio`.
pub fn supplied(reference: &FilmGroups, ln_ratio: f64) -> FilmGroups {
    FilmGroups { ln_scale: reference.ln_scale + ln_ratio, ..*reference }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_is_one_at_the_reference_and_absent_above_or_without_grease() {
        assert_eq!(ln_supply_ratio(true, 1.0, 293.15, 293.15, -4.0, -4.0), None);
        assert_eq!(ln_supply_ratio(true, 1.0, 300.0, 293.15, -4.0, -5.0), None);
        assert_eq!(ln_supply_ratio(false, 1.0, 250.0, 293.15, -4.0, -2.0), None);
        let r = ln_supply_ratio(true, 2.0, 250.0, 293.15, -4.0, -2.0).unwrap();
        assert_eq!(r, -4.0);
        // Just below the reference the ratio tends to 1 (continuity in temperature).
        let r = ln_supply_ratio(true, 1.0, 293.15 - 1e-9, 293.15, -4.0, -4.0 + 1e-11).unwrap();
        assert!(r.abs() < 1e-10);
    }

    #[test]
    fn supplied_film_scales_the_reference_film() {
        let g = FilmGroups::new(0.1, 31.4, 1.66e11, 0.0594, 20e3, 0.01245, 1.69e-8);
        let s = supplied(&g, -1.5);
        for ln_x1 in [-20.0, -3.0, -0.1] {
            assert!((s.ln_film(ln_x1) - g.ln_film(ln_x1) + 1.5).abs() < 1e-12);
        }
    }
}
