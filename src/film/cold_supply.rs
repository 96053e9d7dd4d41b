//! The grease's oil supply to the contact (complete model, grease enabled): a starved inlet
//! fed by the oil layer that the grease's bleed leaves on the track between passes. Not in
//! the paper; docs/cold-day.md.
//!
//! A grease lubricates the contact through the oil its thickener releases (bleed) and the
//! oil that flows back into the track between passes: Darcy flow of the base oil through the
//! thickener (Baart, van der Vorst, Lugt & van Ostayen, 2010, Tribol. Trans. 53, 340–348;
//! Akchurin, van den Ende & Lugt, 2022, Tribol. Int. 170, 107507) and capillary
//! replenishment of the track (Gershuni, Larson & Lugt, 2008, Tribol. Trans. 51, 643–651),
//! both viscous flows driven by a capillary pressure that hardly depends on temperature, so
//! the layer rebuilt in a given time scales like 1/η_b(T):
//!
//! `h_oil(T) = h_oil(T_ref)·(η_b(T_ref)/η_b(T))^m`, m = `grease.supply_exponent` (1 for
//! Darcy/capillary flow), h_oil(T_ref) = 1/`grease.supply_layer_inverse`.
//!
//! The contact is fed by that layer as any starved EHL contact is (Chevalier, Lubrecht, Cann,
//! Colin & Dalmaz, 1998, ASME J. Tribol. 120, 126–133; [`crate::film::starvation`]):
//! `h^−γs = h_ff^−γs + h_oil^−γs`, with h_ff the flooded film and γs `starvation.exponent`.
//! Where the user's own starved inlet (`starvation.inlet_layer_inverse`) is on as well, the
//! two layers add as reciprocals to the power γs: `q^γs = q_user^γs + q_grease^γs`, q = 1/h.
//!
//! This is one physical law at every temperature: T_ref only says where the layer is quoted,
//! as it says where η0, α, τ_y and K are. Re-quoting the layer at T' by the same law
//! (`h_oil(T') = h_oil(T_ref)·(η_b(T_ref)/η_b(T'))^m`, what `pinjoint params
//! --reference-temperature` writes, [`crate::params::Params::requoted_at`]) leaves h_oil(T)
//! unchanged at every T, so every answer is unchanged. It is smooth in T (η_b(T) is), with no kink anywhere. The default
//! layer is thick against the flooded film at room temperature (the paper's rig is flooded)
//! and thin against it on the cold day, where η_b is a thousand times the room's.
//!
//! `grease.supply_layer_inverse = 0` turns the supply limit off (a flooded contact at every
//! temperature).

/// ln(1/h_oil(T)) (1/m) of the grease's supply layer at the temperature where the base oil's
/// viscosity is e^`ln_eta` (Pa·s), from its value `layer_inverse` (1/m) where the viscosity is
/// e^`ln_eta_ref`, with the exponent m; `None` when the supply limit is off (grease disabled or
/// `layer_inverse` = 0).
pub fn ln_layer_inverse(enabled: bool, layer_inverse: f64, exponent: f64, ln_eta_ref: f64, ln_eta: f64) -> Option<f64> {
    (enabled && layer_inverse > 0.0).then(|| layer_inverse.ln() + exponent * (ln_eta - ln_eta_ref))
}

/// q = 1/h of two starving layers together: (q_a^γ + q_b^γ)^(1/γ), in logarithms (either may be
/// absent).
pub fn ln_combined(ln_a: Option<f64>, ln_b: Option<f64>, gamma: f64) -> Option<f64> {
    match (ln_a, ln_b) {
        (Some(a), Some(b)) => Some(crate::film::log_add_exp(gamma * a, gamma * b) / gamma),
        (a, None) => a,
        (None, b) => b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn off_without_grease_or_layer_and_exact_at_the_reference() {
        assert_eq!(ln_layer_inverse(false, 2e4, 1.0, -4.0, -2.0), None);
        assert_eq!(ln_layer_inverse(true, 0.0, 1.0, -4.0, -2.0), None);
        assert_eq!(ln_layer_inverse(true, 2e4, 1.0, -4.0, -4.0), Some(2e4f64.ln()));
        // Ten times the viscosity, m = 1: a ten times thinner layer.
        let q = ln_layer_inverse(true, 2e4, 1.0, -4.0, -4.0 + 10f64.ln()).unwrap();
        assert!((q.exp() / 2e5 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn layers_combine_as_a_smooth_maximum_of_inverses() {
        let (a, b) = (1e4f64.ln(), 3e4f64.ln());
        let c = ln_combined(Some(a), Some(b), 2.8).unwrap().exp();
        assert!((c - (1e4f64.powf(2.8) + 3e4f64.powf(2.8)).powf(1.0 / 2.8)).abs() < 1e-9 * c);
        assert!(c > 3e4 && c < 4e4);
        assert_eq!(ln_combined(Some(a), None, 2.8), Some(a));
        assert_eq!(ln_combined(None, Some(b), 2.8), Some(b));
        assert_eq!(ln_combined(None, None, 2.8), None);
    }
}
