//! The complete model's composition (issue 28; not in the paper; docs/cold-day.md): the
//! journal bearing's weight, the composite film, and the torque of the whole clearance.
//!
//! * **Journal weight** w: which film theory the joint obeys, decided by elasticity, as in the
//!   analyses of soft (conformal) EHL: the ratio ξ = δ/h_J of the Hertz flattening of the
//!   contact δ = a²/(2R') = 4P/(π B E') (eq. 6; Johnson, *Contact Mechanics*, 1985, §4.3: the
//!   approach of the surfaces that elastic deformation takes up over the half-width a) to the
//!   rigid journal's minimum film h_J = c·(1 − ε(S)) at the whole load (Raimondi & Boyd's
//!   finite bearing, [`crate::journal`]). Where ξ is small the bush is effectively rigid and
//!   rigid journal theory holds (w = 1); where ξ is large the deflection shapes the gap and
//!   the line-contact (Moes) film of eqs. 12–13 holds (w = 0). For the line contact's own
//!   rigid film (Moes' H_RI = 3/M) the same ratio is δ/h_RI = (4/3π)·M², Moes' elasticity
//!   parameter, whose rigid–elastic crossing (H_RI = H_EI) is at M = 1.18, ξ = 0.59: the
//!   journal's weight falls to 0 by [`XI_1`] = 0.45, below that crossing, and is 1 up to
//!   [`XI_0`] = 2.5e-3, the transition as wide in ξ as Moes' own blend of his rigid and elastic
//!   asymptotes is in M² (M from 0.3 to 4). In between: the quintic smoothstep (C²) of ln ξ.
//!   A narrower transition lets the film thicken and the torque fall as the load rises where
//!   the line contact's film exceeds the journal's (both fall with load, the weight moves from
//!   the thinner to the thicker): over −55 to +120 °C, 0.01–100 rad/s and 50 N–200 kN the
//!   torque falls by at most 6e-4 and the film rises by at most 4e-3 (relative) between
//!   neighbouring loads 4.2 % apart inside the transition, and never outside it
//!   (`tests/one_answer.rs`). w is a function of the operating point only (so the load-sharing residual stays
//!   monotone in its unknown); over the paper's rig conditions (5–60 kN, up to 4.39 rad/s,
//!   15–25 °C) ξ ≥ 0.48, so w = 0 and the paper's load sharing is untouched there.
//! * **Composite film** in the solve ([`crate::load_sharing::solve::solve_composite`]):
//!   ln h(x1) = (1 − w)·ln h_c13(x1) + w·ln h_J(x1), h_J(x1) = c·(1 − ε(S/x1)), where the line
//!   contact's film is held inside the clearance, h_c13^−4 = h_13^−4 + c^−4 (eq. 12's
//!   parabolic gap is a conformal contact's only while the film is small against c; in the
//!   paper's rig conditions, h_13 ≤ 4 µm against c = 25 µm, this moves the film by less than
//!   2e-4); the grease's supply layer ([`crate::film::cold_supply`]) starves the composite film.
//! * **Torque** (magnitude): T = T_asp + (1 − w)·T_contact,fluid + T_clearance + w·T_poiseuille,
//!   T_asp = μ_c·x2·R·P (eq. 8), T_contact,fluid = Q_H·R (eq. 3) with the composite film,
//!   T_clearance the shear of the lubricant in the clearance outside the contact arc
//!   |θ| ≤ θ_c = (1 − w)·a/R over the gap h_g(θ) = c(1 − ε_g cos θ), ε_g = 1 − h/c
//!   ([`crate::clearance::clearance_torque`]), and T_poiseuille = (c·ε_J/2)·x1·P·sin φ(ε_J),
//!   the pressure-flow torque of the journal carrying x1·P (ε_J = 1 − h_J/c; Raimondi & Boyd's
//!   friction variable (R/c)f = 2π²S/√(1 − ε²) + (ε/2) sin φ is the two terms at w = 1).
//!   At rest T = μ_c·R·P + τ_y(T)·(2π − 2a/R)·R²·B: the grease's yield torque adds to breakaway.

use crate::clearance::{clearance_and_arc_torque, clearance_torque_tabulated, yield_torque, ClearanceGeometry, PowerLawTable};
use crate::rheology::grease::{GreaseReference, GreaseRheology as Rheology};
use crate::journal::JournalTable;
use crate::load_sharing::solve::{JournalFilm, LoadSharing, StarvedInlet};
use crate::params::{ParamError, Params};
use std::sync::Arc;

/// ξ = δ/h_J at and below which the journal's weight is 1 (the bush effectively rigid):
/// [`XI_1`]/180, so that the transition spans the range of the elasticity parameter over which
/// Moes' own rigid–elastic blend moves (M from 0.3 to 4, i.e. M² over 2.25 decades).
pub const XI_0: f64 = 2.5e-3;
/// ξ = δ/h_J at and above which the journal's weight is 0 (the deflection shapes the gap):
/// 0.45, below the paper's rig conditions (ξ ≥ 0.48 there) and Moes' crossing (ξ = 0.59).
pub const XI_1: f64 = 0.45;

/// (a⁸ + b⁸)^(1/8) for a, b ≥ 0, without overflow: a smooth maximum, increasing in both.
#[inline]
pub fn smooth_max(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        return a;
    }
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    let r = lo / hi;
    let r2 = r * r;
    let r4 = r2 * r2;
    hi * (1.0 + r4 * r4).powf(0.125)
}

/// The quintic smoothstep t³(10 − 15t + 6t²) on [0, 1], 0 below, 1 above: C², monotone.
pub fn smoothstep(t: f64) -> f64 {
    if t <= 0.0 {
        0.0
    } else if t >= 1.0 {
        1.0
    } else {
        t * t * t * (10.0 + t * (-15.0 + 6.0 * t))
    }
}

/// w(ln ξ): 1 at and below ln [`XI_0`], 0 at and above ln [`XI_1`], the smoothstep of ln ξ
/// between (NaN gives NaN).
pub fn journal_weight(ln_xi: f64) -> f64 {
    if ln_xi.is_nan() {
        return f64::NAN;
    }
    let (a, b) = (XI_0.ln(), XI_1.ln());
    smoothstep((b - ln_xi) / (b - a))
}

/// The lubricant of the clearance at the joint's temperature: the grease's Herschel–Bulkley
/// parameters by their Arrhenius laws from the reference temperature, with the base oil's
/// Newtonian viscosity η_b(T) (Roelands' temperature relation); the base oil alone
/// (τ_y = K = 0) with the grease disabled.
pub fn rheology(params: &Params, base_viscosity: f64) -> Rheology {
    let g = &params.grease;
    if !g.enabled {
        return Rheology::newtonian(base_viscosity);
    }
    let reference = GreaseReference {
        yield_stress: g.yield_stress,
        consistency: g.consistency,
        flow_index: g.flow_index,
        yield_activation: g.yield_activation,
        consistency_activation: g.consistency_activation,
    };
    let l = &params.lubricant;
    reference.at(l.temperature, l.reference_temperature, base_viscosity)
}

/// The complete model's terms of one joint at one temperature.
#[derive(Debug, Clone)]
pub struct Complete {
    /// The journal bearing of the joint's L/D = B/(2R).
    pub journal: Arc<JournalTable>,
    /// c = R_b − R (m) and its logarithm.
    pub clearance: f64,
    ln_clearance: f64,
    radius: f64,
    length: f64,
    /// The clearance's lubricant at the temperature.
    pub rheology: Rheology,
    /// J_n of the grease's flow index, tabulated once per n (process-wide; the clearance
    /// torque's power-law part by a lookup instead of the 12-node rule).
    power_law: Arc<PowerLawTable>,
    /// ln(4/(π B E')): ln δ at P = 1 N (δ = 4P/(π B E'), the Hertz flattening).
    ln_flattening_unit: f64,
}

/// The grease's yield torque at rest as a function of the load alone, for the fidelity
/// levels' rest state: τ_y(T)·(2π − 2a/R)·R²·B with a = a(1 N)·√P (eq. 6). Zero for the paper's
/// model and without grease.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RestYield {
    rheology: Option<Rheology>,
    radius: f64,
    length: f64,
    unit_half_width: f64,
}

impl RestYield {
    /// The rest yield torque of `complete` (None: the paper's model) with the Hertz
    /// half-width `unit_half_width` (m) at 1 N.
    pub fn new(complete: Option<&Complete>, unit_half_width: f64) -> Self {
        match complete {
            Some(c) if c.rheology.yield_stress > 0.0 => Self { rheology: Some(c.rheology), radius: c.radius, length: c.length, unit_half_width },
            _ => Self::default(),
        }
    }

    /// The yield torque at rest under `load` (N), N·m: [`Complete::yield_torque`] at w = 0,
    /// bit for bit.
    #[inline]
    pub fn at(&self, load: f64) -> f64 {
        match &self.rheology {
            Some(r) => {
                let a = self.unit_half_width * load.abs().sqrt();
                yield_torque(r, self.radius, self.length, ((1.0 - 0.0) * a / self.radius).min(std::f64::consts::PI))
            }
            None => 0.0,
        }
    }
}

/// Equal when the geometry and the clearance's lubricant are: the journal table is a function
/// of the geometry's L/D.
impl PartialEq for Complete {
    fn eq(&self, other: &Self) -> bool {
        (self.clearance, self.radius, self.length, self.rheology) == (other.clearance, other.radius, other.length, other.rheology)
    }
}

/// The complete model's parts of the torque at one operating point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Parts {
    /// w, the journal's weight.
    pub weight: f64,
    /// ε_g = 1 − h/c, clamped to [0, 1).
    pub eccentricity: f64,
    /// T_clearance, N·m (its yield part included, and the grease's excess over the line
    /// contact within the contact arc, [`Complete::contact_torque`]).
    pub clearance_torque: f64,
    /// τ_y(T)·(2π − 2θ_c)·R²·B, N·m: the yield part of T_clearance.
    pub yield_torque: f64,
    /// T_poiseuille, N·m (not yet weighted by w).
    pub poiseuille_torque: f64,
    /// The torque the clearance's lubricant would transmit over the contact arc |θ| ≤ θ_c
    /// (N·m): the least the contact's lubricant transmits there ([`Complete::contact_torque`]).
    pub arc_torque: f64,
}

impl Complete {
    /// The terms for `params` with the base oil's viscosity `base_viscosity` (Pa·s) at the
    /// temperature.
    pub fn new(params: &Params, base_viscosity: f64) -> Result<Self, ParamError> {
        let g = &params.geometry;
        let e_eff = crate::contact::effective_modulus(&params.materials);
        let l_over_d = g.bush_length / (2.0 * g.pin_radius);
        let journal = JournalTable::shared(l_over_d).map_err(|e| ParamError::OutOfRange {
            name: "geometry.bush_length".into(),
            value: g.bush_length,
            unit: "m",
            range: format!(
                "such that the journal bearing's L/D = B/(2R) (here {} with geometry.pin_radius = {} m) can be solved ({e})",
                crate::fmt::Num(l_over_d),
                crate::fmt::Num(g.pin_radius)
            ),
        })?;
        let c = params.radial_clearance();
        let power_law = PowerLawTable::shared(params.grease.flow_index).map_err(|e| ParamError::OutOfRange {
            name: "grease.flow_index".into(),
            value: params.grease.flow_index,
            unit: "(dimensionless)",
            range: format!("in (0, 1] ({e})"),
        })?;
        Ok(Self {
            power_law,
            journal,
            clearance: c,
            ln_clearance: c.ln(),
            radius: g.pin_radius,
            length: g.bush_length,
            rheology: rheology(params, base_viscosity),
            ln_flattening_unit: (4.0 / (std::f64::consts::PI * g.bush_length * e_eff)).ln(),
        })
    }

    /// These terms at another temperature: the same journal table, the clearance's lubricant
    /// for `params` (at its temperature) with the base oil's viscosity `base_viscosity`.
    pub fn at_temperature(&self, params: &Params, base_viscosity: f64) -> Self {
        Self { rheology: rheology(params, base_viscosity), ..self.clone() }
    }

    /// ln ξ = ln(δ/h_J) at ln S (eq. 20 at the whole load with η_b(T)) and ln P: the Hertz
    /// flattening δ = 4P/(π B E') over the rigid journal's minimum film h_J = c·(1 − ε(S)),
    /// starved by the inlet's layer if `inlet` is given (the film the journal can form).
    #[inline]
    pub fn ln_elasticity_ratio(&self, ln_sommerfeld: f64, ln_load: f64, inlet: Option<StarvedInlet>) -> f64 {
        let (rho, _) = self.journal.film_ratio(ln_sommerfeld);
        let ln_h = self.ln_clearance + rho.ln();
        let ln_h = match inlet {
            Some(st) => crate::starvation::ln_starved(ln_h, st.ln_q, st.gamma).0,
            None => ln_h,
        };
        self.ln_flattening_unit + ln_load - ln_h
    }

    /// The journal's weight w at ln S and ln P with the inlet `inlet` ([`journal_weight`] of
    /// ln ξ); 0 at rest (ln S = −∞).
    #[inline]
    pub fn weight(&self, ln_sommerfeld: f64, ln_load: f64, inlet: Option<StarvedInlet>) -> f64 {
        if ln_sommerfeld == f64::NEG_INFINITY {
            return 0.0;
        }
        journal_weight(self.ln_elasticity_ratio(ln_sommerfeld, ln_load, inlet))
    }

    /// The journal's film for the solve, with its weight (0: the line contact's film alone, capped
    /// by the clearance; `None` only at rest).
    #[inline]
    pub fn journal_film(&self, weight: f64, ln_sommerfeld: f64) -> Option<JournalFilm<'_>> {
        (ln_sommerfeld > f64::NEG_INFINITY).then_some(JournalFilm { weight, ln_sommerfeld, ln_clearance: self.ln_clearance, table: &self.journal })
    }

    /// ε_g = 1 − h/c for the film `film` (m), clamped to [0, 1).
    #[inline]
    pub fn eccentricity(&self, film: f64) -> f64 {
        (1.0 - film / self.clearance).clamp(0.0, 1.0 - f64::EPSILON)
    }

    /// The half-angle θ_c = (1 − w)·a/R of the contact arc left out of the clearance, rad.
    #[inline]
    pub fn contact_angle(&self, weight: f64, half_width: f64) -> f64 {
        ((1.0 - weight) * half_width / self.radius).min(std::f64::consts::PI)
    }

    /// The yield torque τ_y(T)·(2π − 2θ_c)·R²·B (N·m) at weight w and Hertz half-width a.
    #[inline]
    pub fn yield_torque(&self, weight: f64, half_width: f64) -> f64 {
        yield_torque(&self.rheology, self.radius, self.length, self.contact_angle(weight, half_width))
    }

    /// The clearance's torque (N·m) at sliding speed `u` (m/s) for the film `film` (m).
    #[inline]
    pub fn clearance_torque(&self, weight: f64, half_width: f64, u: f64, film: f64) -> f64 {
        let geometry = ClearanceGeometry { radius: self.radius, length: self.length, clearance: self.clearance };
        clearance_torque_tabulated(&self.power_law, &self.rheology, &geometry, u, self.eccentricity(film), self.contact_angle(weight, half_width)).total()
    }

    /// Every part at the solved load sharing `ls`, weight w, ln S at the whole load, Hertz
    /// half-width a (m), load P (N) and sliding speed u (m/s).
    /// `line_contact` is the line contact's fluid torque (1 − w)·Q_H·R (eq. 3), N·m: where the
    /// grease's flow over the contact arc exceeds it, the excess is the clearance's
    /// ([`Complete::contact_torque`]).
    #[allow(clippy::too_many_arguments)]
    pub fn parts(&self, weight: f64, ln_sommerfeld: f64, ls: &LoadSharing, half_width: f64, load: f64, u: f64, line_contact: f64) -> Parts {
        let poiseuille_torque = if weight > 0.0 && ls.fluid_fraction > 0.0 {
            let (e, _) = self.journal.eccentricity(ln_sommerfeld - ls.fluid_fraction.ln());
            0.5 * self.clearance * e * ls.fluid_fraction * load * self.journal.attitude_angle(e).sin()
        } else {
            0.0
        };
        let eps = self.eccentricity(ls.film_thickness);
        let (clearance_torque, arc_torque) = self.clearance_and_arc(weight, half_width, u, ls.film_thickness, line_contact);
        Parts { weight, eccentricity: eps, clearance_torque, yield_torque: self.yield_torque(weight, half_width), poiseuille_torque, arc_torque }
    }

    /// The clearance's torque (N·m) at weight w, Hertz half-width a, sliding speed u and film
    /// h, with the line contact's fluid torque `line_contact` (N·m): the lubricant outside the
    /// contact arc plus the grease's excess over the line contact within it
    /// ([`Complete::contact_torque`] − `line_contact`, ≥ 0); and the grease's flow over the arc.
    pub fn clearance_and_arc(&self, weight: f64, half_width: f64, u: f64, film: f64, line_contact: f64) -> (f64, f64) {
        let geometry = ClearanceGeometry { radius: self.radius, length: self.length, clearance: self.clearance };
        let (outside, arc) = clearance_and_arc_torque(&self.power_law, &self.rheology, &geometry, u, self.eccentricity(film), self.contact_angle(weight, half_width));
        let excess = smooth_max(line_contact, arc) - line_contact;
        (outside.total() + excess.max(0.0), arc)
    }

    /// The contact arc's fluid torque (N·m) from the line contact's (1 − w)·Q_H·R (eq. 3,
    /// `line_contact`): at least what the clearance's lubricant would transmit over the same
    /// arc (`parts.arc_torque`), by the smooth maximum (a⁸ + b⁸)^(1/8) (C^∞, increasing in
    /// both, within 2e-9 of a where b ≤ a/10, the paper's rig conditions). Where the contact's
    /// film is limited by the base oil's limiting shear (eq. 4) and the grease beside it is not
    /// (the cold day, fast), the arc that the contact takes from the clearance as the load
    /// grows would otherwise carry less than the grease it replaces, and the torque would fall
    /// as the load rises. The excess over `line_contact` is reported in the clearance torque.
    #[inline]
    pub fn contact_torque(line_contact: f64, parts: &Parts) -> f64 {
        smooth_max(line_contact, parts.arc_torque)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smoothstep_is_c2_and_monotone() {
        assert_eq!((smoothstep(-1.0), smoothstep(0.0), smoothstep(1.0), smoothstep(2.0)), (0.0, 0.0, 1.0, 1.0));
        let h = 1e-4;
        let mut prev = 0.0;
        for i in 1..=1000 {
            let t = f64::from(i) / 1000.0;
            let v = smoothstep(t);
            assert!(v >= prev);
            prev = v;
        }
        // First and second derivatives vanish at both ends (one-sided differences).
        for t in [0.0, 1.0 - 2.0 * h] {
            let d1 = (smoothstep(t + h) - smoothstep(t)) / h;
            assert!(d1.abs() < 1e-6, "{t}: {d1}");
        }
        assert!((smoothstep(0.5) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn weight_is_one_and_zero_at_its_ends_and_falls_with_the_ratio() {
        assert_eq!(journal_weight(f64::NEG_INFINITY), 1.0);
        assert_eq!(journal_weight(XI_0.ln()), 1.0);
        assert_eq!(journal_weight(XI_1.ln()), 0.0);
        assert_eq!(journal_weight(10f64.ln()), 0.0);
        let mid = journal_weight(0.5 * (XI_0.ln() + XI_1.ln()));
        assert!((mid - 0.5).abs() < 1e-12, "{mid}");
        let mut prev = 1.0;
        for k in 0..=400 {
            let w = journal_weight(XI_0.ln() - 1.0 + f64::from(k) * 0.02);
            assert!(w <= prev);
            prev = w;
        }
    }

    /// ξ from its definition: the Hertz flattening a²/(2R') over c(1 − ε(S)).
    #[test]
    fn the_elasticity_ratio_is_the_flattening_over_the_rigid_film() {
        let p = Params::default();
        let eta = crate::viscosity::at_temperature(&p.lubricant).viscosity;
        let c = Complete::new(&p, eta).unwrap();
        let (r_red, e_eff) = (crate::contact::reduced_radius(&p.geometry), crate::contact::effective_modulus(&p.materials));
        for (load, ln_s) in [(50.0, 0.5), (2e3, -3.0), (20e3, -8.0)] {
            let a = crate::contact::hertz(load, r_red, e_eff, p.geometry.bush_length).half_width;
            let delta = a * a / (2.0 * r_red);
            let h_j = p.radial_clearance() * (1.0 - c.journal.eccentricity(ln_s).0);
            let xi = c.ln_elasticity_ratio(ln_s, f64::ln(load), None).exp();
            assert!((xi / (delta / h_j) - 1.0).abs() < 1e-9, "{load} {ln_s}: {xi} vs {}", delta / h_j);
        }
    }
}
