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
//!   w is a function of the operating point only (so that the load-sharing residual stays
//!   monotone in its unknown); over the paper's rig conditions (5–60 kN, up to 4.39 rad/s,
//!   15–25 °C) ξ ≥ 0.48, so w = 0 and the paper's load sharing is untouched there.
//! * **Composite film** in the solve ([`crate::load_sharing::solve::solve_composite`]): the smooth maximum
//!   h = ((w·h_J)⁸ + h_c13*⁸)^(1/8) ([`SMOOTH_MAX_EXPONENT`]) of the weighted journal film
//!   h_J(x1) = c·(1 − ε(S/x1)) and the line contact's film h_c13* at the load P* ≥ P
//!   ([`onset_load`]: the load P₁ at which w reaches 0, [`Complete::ln_onset_load`], softened
//!   to a C² join; P* = P from P₁ on, where h = h_c13 exactly). The line contact's film is
//!   held inside the clearance, h_c13^−4 = h_13^−4 + c^−4 (eq. 12's parabolic gap is a
//!   conformal contact's only while the film is small against c; in the paper's rig
//!   conditions, h_13 ≤ 4 µm against c = 25 µm, this moves the film by less than 2e-4); the
//!   grease's supply layer ([`crate::film::cold_supply`]) starves the composite film.
//!   **Why this form**: the film must never thicken as the load rises, and the two films it
//!   joins are both thinner at a higher load, but the line contact's is the thicker one in the
//!   transition (its rigid limit, Martin's infinite line contact, ignores the finite bearing's
//!   side leakage that h_J has), so no blend of the two at the same load, with a weight that
//!   moves from the journal to the line contact as the load rises, can be monotone: it must
//!   climb from the thinner to the thicker. The lower bound it uses instead is physical: below
//!   the onset of elasticity the film is at least the rigid journal's at its load (deflection
//!   only widens the gap) and at least the elastic film at the onset load P₁ (the film at a
//!   lighter load is at least that at a heavier one). Each argument of the smooth maximum falls
//!   with the load (w, h_J, and h_c13 at the non-decreasing P*) and the maximum increases in
//!   both, so the fluid's film is a falling function of its load at every share, and so the
//!   solved film falls as the load rises: **monotone by construction**. Where the two are equal
//!   the smooth maximum exceeds both by 2^(1/8) − 1 = 9 % at most (Moes' own blend of his
//!   rigid and elastic asymptotes, power 7/3, by 35 %); at w = 1 with h_c13* ≪ h_J (the rigid
//!   bearings of Raimondi & Boyd's tables) it is h_J to within (h_c13*/h_J)⁸/8.
//! * **Torque** (magnitude): T = T_asp + T_clearance + max̃(T_line, T_arc) + T_poiseuille,
//!   T_asp = μ_c·x2·R·P (eq. 8), T_line = (1 − w)·Q_H·R (eq. 3) with the composite film,
//!   T_clearance the shear of the lubricant in the clearance outside the contact arc
//!   |θ| ≤ θ_c = a/R over the gap h_g(θ) = c(1 − ε_g cos θ), ε_g = 1 − h/c
//!   ([`crate::clearance::clearance_torque`]), with the grease's yield over the whole
//!   circumference; T_arc the lubricant's flow over the arc, max̃ the smooth maximum
//!   ([`Complete::contact_torque`]); and T_poiseuille = (c·ε_J/2)·x1·P·sin φ(ε_J), the
//!   pressure-flow torque of the journal carrying x1·P (ε_J = 1 − h_J(x1)/c; Raimondi & Boyd's
//!   friction variable (R/c)f = 2π²S/√(1 − ε²) + (ε/2) sin φ is the clearance's and this term
//!   at w = 1). No term is weighted by w but the line contact's, which grows with the load: a
//!   term (1 − w)·A + w·B falls somewhere in the transition whenever A < B, so the journal's
//!   pressure-flow torque stays at every weight (it vanishes with the attitude angle as the
//!   joint loads up: 0.23 % of the torque at 5 kN, 4.386 rad/s, 15 °C), the contact arc is
//!   the Hertz half-width's at every weight, and the grease yields over the whole
//!   circumference (the arc takes its flow, not its yield). Over −55…+120 °C, 0.01–100 rad/s
//!   and 50 N–200 kN, grease on and off, the torque never falls as the load rises (measured
//!   at 1e-12 between neighbouring loads, `tests/one_answer.rs`); unlike the film this rests
//!   on the terms' measured growth, not on a construction.
//!   At rest T = μ_c·R·P + τ_y(T)·2π·R²·B: the grease's yield torque adds to breakaway.

use crate::clearance::{clearance_and_arc_torque, yield_torque, ClearanceGeometry, PowerLawTable};
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

/// ln P*, the load at which the line contact's film enters the composite film below the
/// onset of elasticity ln P₁ ([`Complete::ln_onset_load`]): ln P₁ − D·tanh((ln P₁ − ln P)/D),
/// D = [`ONSET_WIDTH`], for P < P₁, and ln P itself from P₁ on. Non-decreasing in P (its
/// slope sech² ∈ (0, 1]), P ≤ P* ≤ P₁, C² at P₁ (tanh″(0) = 0).
#[inline]
pub fn onset_load(ln_onset: f64, ln_load: f64) -> f64 {
    if ln_load >= ln_onset {
        ln_load
    } else {
        ln_onset - ONSET_WIDTH * ((ln_onset - ln_load) / ONSET_WIDTH).tanh()
    }
}

/// D of [`onset_load`]: below the onset the line contact's film is that of a load between
/// e^−D·P₁ and P₁.
pub const ONSET_WIDTH: f64 = 0.5;

pub use crate::load_sharing::solve::SMOOTH_MAX_EXPONENT;

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

/// The grease's yield torque at rest, for the fidelity levels' rest state: τ_y(T)·2π·R²·B (the
/// grease yields over the whole circumference, [`crate::composite`]), the same at every load.
/// Zero for the paper's model and without grease.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RestYield {
    torque: f64,
}

impl RestYield {
    /// The rest yield torque of `complete` (None: the paper's model).
    pub fn new(complete: Option<&Complete>) -> Self {
        Self { torque: complete.map_or(0.0, Complete::yield_torque) }
    }

    /// The yield torque at rest under any load (N), N·m: [`Complete::yield_torque`], bit for
    /// bit (the load does not enter it; the argument keeps the rest state's call shape).
    #[inline]
    pub fn at(&self, _load: f64) -> f64 {
        self.torque
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
    /// τ_y(T)·2π·R²·B, N·m: the yield part of T_clearance (over the whole circumference).
    pub yield_torque: f64,
    /// T_poiseuille, N·m (at every weight; 0 at rest).
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
            Some(st) => crate::film::starvation::ln_starved(ln_h, st.ln_q, st.gamma).0,
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

    /// The journal's film for the solve at ln S and ln P with the inlet `inlet`, with its weight
    /// (0: the line contact's film alone, capped by the clearance; `None` only at rest) and,
    /// where the weight is above 0, the line contact's load [`onset_load`] ln P* − ln P.
    #[inline]
    pub fn journal_film(&self, weight: f64, ln_sommerfeld: f64, ln_load: f64, inlet: Option<StarvedInlet>) -> Option<JournalFilm<'_>> {
        let ln_onset = if weight > 0.0 { onset_load(self.ln_onset_load(ln_sommerfeld, ln_load, inlet), ln_load) - ln_load } else { 0.0 };
        (ln_sommerfeld > f64::NEG_INFINITY).then_some(JournalFilm { weight, ln_sommerfeld, ln_clearance: self.ln_clearance, table: &self.journal, ln_onset })
    }

    /// ln P₁, the load at which ξ reaches [`XI_1`] (the journal's weight reaches 0) at the
    /// speed and temperature of ln S at ln P (S ∝ 1/P): the root of the increasing
    /// ln ξ(ln P + t) = ln [`XI_1`] in t ∈ [0, ln XI_1 − ln ξ(ln P)] (ln ξ grows at least as fast as
    /// ln P: h_J falls with the load), by Newton's iteration kept in that bracket. ln P itself
    /// where ξ ≥ [`XI_1`].
    pub fn ln_onset_load(&self, ln_sommerfeld: f64, ln_load: f64, inlet: Option<StarvedInlet>) -> f64 {
        let target = XI_1.ln();
        let f = |t: f64| {
            let ln_s = ln_sommerfeld - t;
            let (rho, drho) = self.journal.film_ratio(ln_s);
            let (ln_h, dln_h) = (self.ln_clearance + rho.ln(), drho / rho);
            let (ln_h, dln_h) = match inlet {
                Some(st) => {
                    let (l, w) = crate::film::starvation::ln_starved(ln_h, st.ln_q, st.gamma);
                    (l, w * dln_h)
                }
                None => (ln_h, dln_h),
            };
            // d ln ξ/dt = 1 + d ln h_J/d ln S (ln S falls by t).
            (self.ln_flattening_unit + ln_load + t - ln_h - target, 1.0 + dln_h)
        };
        let (f0, _) = f(0.0);
        if f0.is_nan() || f0 >= 0.0 {
            return ln_load;
        }
        let (mut lo, mut hi) = (0.0, -f0);
        let mut t = 0.0;
        for _ in 0..60 {
            let (v, d) = f(t);
            if v < 0.0 { lo = t } else { hi = t }
            let next = t - v / d;
            let next = if next > lo && next < hi && next.is_finite() { next } else { 0.5 * (lo + hi) };
            if (next - t).abs() <= 1e-12 * (1.0 + t.abs()) || hi - lo <= 1e-12 {
                t = next;
                break;
            }
            t = next;
        }
        ln_load + t
    }

    /// ε_g = 1 − h/c for the film `film` (m), clamped to [0, 1).
    #[inline]
    pub fn eccentricity(&self, film: f64) -> f64 {
        (1.0 - film / self.clearance).clamp(0.0, 1.0 - f64::EPSILON)
    }

    /// The half-angle θ_c = a/R of the contact arc left out of the clearance's flow, rad
    /// (at every weight: an arc shrinking with w would hand the clearance's flow to the line
    /// contact faster than the line contact's torque grows).
    #[inline]
    pub fn contact_angle(&self, half_width: f64) -> f64 {
        (half_width / self.radius).min(std::f64::consts::PI)
    }

    /// The grease's yield torque τ_y(T)·2π·R²·B (N·m): over the whole circumference, at every
    /// load and weight (the contact arc takes the grease's flow, not its yield).
    #[inline]
    pub fn yield_torque(&self) -> f64 {
        yield_torque(&self.rheology, self.radius, self.length, 0.0)
    }

    /// Every part at the solved load sharing `ls`, weight w, ln S at the whole load, Hertz
    /// half-width a (m), load P (N) and sliding speed u (m/s).
    /// `line_contact` is the line contact's fluid torque (1 − w)·Q_H·R (eq. 3), N·m: where the
    /// grease's flow over the contact arc exceeds it, the excess is the clearance's
    /// ([`Complete::contact_torque`]).
    #[allow(clippy::too_many_arguments)]
    pub fn parts(&self, weight: f64, ln_sommerfeld: f64, ls: &LoadSharing, half_width: f64, load: f64, u: f64, line_contact: f64) -> Parts {
        let poiseuille_torque = if ln_sommerfeld.is_finite() && ls.fluid_fraction > 0.0 {
            let (e, phi) = self.journal.eccentricity_and_attitude(ln_sommerfeld - ls.fluid_fraction.ln());
            0.5 * self.clearance * e * ls.fluid_fraction * load * phi.sin()
        } else {
            0.0
        };
        let eps = self.eccentricity(ls.film_thickness);
        let (clearance_torque, arc_torque) = self.clearance_and_arc(half_width, u, ls.film_thickness, line_contact);
        Parts { weight, eccentricity: eps, clearance_torque, yield_torque: self.yield_torque(), poiseuille_torque, arc_torque }
    }

    /// The clearance's torque (N·m) at weight w, Hertz half-width a, sliding speed u and film
    /// h, with the line contact's fluid torque `line_contact` (N·m): the lubricant outside the
    /// contact arc plus the grease's excess over the line contact within it
    /// ([`Complete::contact_torque`] − `line_contact`, ≥ 0); and the grease's flow over the arc.
    pub fn clearance_and_arc(&self, half_width: f64, u: f64, film: f64, line_contact: f64) -> (f64, f64) {
        let geometry = ClearanceGeometry { radius: self.radius, length: self.length, clearance: self.clearance };
        let (outside, arc) = clearance_and_arc_torque(&self.power_law, &self.rheology, &geometry, u, self.eccentricity(film), self.contact_angle(half_width));
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
        let eta = crate::rheology::viscosity::at_temperature(&p.lubricant).viscosity;
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
