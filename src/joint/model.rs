//! The [`Joint`]: a validated parameter set with its load- and speed-independent groups
//! precomputed (R', E', the Hertz and asperity groups at 1 N, eq. 12's groups, the capacity,
//! the start table), built for a lubricant temperature; its accessors and validity edges.

use crate::composite::Complete;
use crate::contact::asperity::AsperityGroups;
use crate::contact::{effective_modulus, hertz, reduced_radius};
use crate::load_sharing::solve::{solve_composite, FilmGroups};
use crate::load_sharing::start::StartTable;
use crate::params::{Lubricant, ParamError, Params};
use std::f64::consts::PI;
use std::sync::Arc;

/// A validated parameter set with the load- and speed-independent groups precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    pub(super) params: Params,
    pub(super) r_red: f64,
    pub(super) e_eff: f64,
    pub(super) roughness: f64,
    /// Eq. 19's groups at P_T = 1 N.
    pub(super) asp_unit: AsperityGroups,
    /// Eq. 12's groups at u = 1 m/s, P_T = 1 N.
    pub(super) film_unit: FilmGroups,
    /// Hertz quantities at P_T = 1 N (a, p_m and p0 all scale with √P_T).
    pub(super) hertz_unit: crate::contact::Hertz,
    /// ln(η∞/η0) for eq. 5.
    pub(super) ln_eta_ratio: f64,
    /// ln η0 for eq. 5.
    pub(super) ln_eta0: f64,
    /// 2RB, the projected area of eq. 20's P_L = P/(2RB), m².
    pub(super) projected_area: f64,
    /// (R/c)² of eq. 20.
    pub(super) clearance_ratio_sq: f64,
    /// The load (N) at which the rest film of eq. 19 reaches zero (see [`Joint::capacity`]).
    pub(super) capacity: f64,
    /// Where the model's assumptions end (the Hertz half-width reaching the pin's radius, the
    /// grease's upper service temperature): [`Joint::validity`] says `outside` beyond.
    pub(super) edges: crate::validity::Edges,
    /// Converged logits over (ln P_T, ln u) of the lubricant at its reference temperature:
    /// the deterministic start of a cold solve, shared by the joints [`Joint::at_temperature`]
    /// makes (it does not depend on the temperature).
    pub(super) start: Arc<StartTable>,
    /// Eq. 12's groups at u = 1 m/s, P_T = 1 N for the lubricant at its reference
    /// temperature: the film the start table's nodes are solved with.
    pub(super) start_film: FilmGroups,
    /// ln(η0(T)/η0(T_ref)): where the start table is read along ln u (0 at T = T_ref). The
    /// film groups depend on η0 and u only through η0·u, so this shift makes the table's
    /// start exact in η0; only α's change with temperature is not in it.
    pub(super) start_shift: f64,
    /// The lubricant at its temperature ([`crate::rheology::viscosity::at_temperature`]; `params.lubricant`
    /// itself, bit for bit, at the reference temperature).
    pub(super) lub: Lubricant,
    /// ln W' at P_T = 1 N and ln(η0/(2E'R')) (mean-velocity U at u = 1 m/s) and ln G, for h_min.
    pub(super) ln_w_unit: f64,
    pub(super) ln_u_mean_unit: f64,
    pub(super) ln_g: f64,
    /// The starved-inlet correction, if on (`starvation.inlet_layer_inverse > 0`; it does not
    /// depend on the temperature).
    pub(super) starved: Option<crate::load_sharing::solve::StarvedInlet>,
    /// What the start table's nodes are solved with: `starved` for the paper's model; for the
    /// complete model the inlet at the reference temperature (the user's layer and the grease's
    /// supply layer at T_ref, [`crate::film::cold_supply`]), so that at T_ref the table starts the
    /// starved solve at its root (one residual evaluation in most of the boundary and mixed
    /// regimes, against two from the flooded root); a function of the parameters alone.
    pub(super) start_inlet: Option<crate::load_sharing::solve::StarvedInlet>,
    /// The inlet at the temperature: the user's starved inlet and the grease's supply layer
    /// ([`crate::film::cold_supply`]) together; `starved` itself for the paper's model.
    pub(super) inlet: Option<crate::load_sharing::solve::StarvedInlet>,
    /// ln S (eq. 20) at P = 1 N, u = 1 m/s with η0(T_ref): ln η0(T_ref) + ln(B (R/c)²/π).
    pub(super) ln_sommerfeld_reference: f64,
    /// The complete model's terms at the temperature; `None` for the paper's model
    /// (`model.paper = true`), whose path is then today's, bit for bit.
    pub(super) complete: Option<Complete>,
}

impl Joint {
    /// Validate `params` and precompute R', E' and √(σ² + σ_b²).
    pub fn new(params: &Params) -> Result<Self, ParamError> {
        params.validate()?;
        let s = &params.surface;
        let roughness = s.pin_rms_roughness.hypot(s.bush_rms_roughness);
        if roughness <= 0.0 {
            return Err(ParamError::OutOfRange {
                name: "surface.pin_rms_roughness".into(),
                value: s.pin_rms_roughness,
                unit: "m",
                range: "> 0 when surface.bush_rms_roughness is 0 (lambda = h/sqrt(sigma^2 + sigma_b^2))".into(),
            });
        }
        crate::contact::gw::warm_up();
        let g = &params.geometry;
        let (r_red, e_eff) = (reduced_radius(g), effective_modulus(&params.materials));
        let st = &params.starvation;
        let reference = &params.lubricant;
        let asp_unit = AsperityGroups::new(&params.surface, 1.0, r_red, e_eff, g.bush_length);
        let mut joint = Self {
            params: *params,
            r_red,
            e_eff,
            roughness,
            asp_unit,
            // The temperature terms are set by `set_temperature_terms` below.
            film_unit: FilmGroups { ln_m: f64::NAN, ln_l: f64::NAN, ln_scale: f64::NAN },
            hertz_unit: hertz(1.0, r_red, e_eff, g.bush_length),
            ln_eta_ratio: f64::NAN,
            ln_eta0: f64::NAN,
            projected_area: 2.0 * g.pin_radius * g.bush_length,
            clearance_ratio_sq: (g.pin_radius / params.radial_clearance()).powi(2),
            capacity: asperity_capacity(&params.surface, &asp_unit),
            edges: crate::validity::Edges::new(params),
            lub: *reference,
            ln_w_unit: (1.0 / (e_eff * r_red * g.bush_length)).ln(),
            ln_u_mean_unit: f64::NAN,
            ln_g: f64::NAN,
            starved: (st.inlet_layer_inverse > 0.0).then(|| crate::load_sharing::solve::StarvedInlet { ln_q: st.inlet_layer_inverse.ln(), gamma: st.exponent }),
            inlet: None,
            start_inlet: None,
            start: Arc::new(StartTable::empty()),
            start_film: FilmGroups::new(1.0, r_red, e_eff, g.bush_length, 1.0, reference.viscosity, reference.pressure_viscosity_coefficient),
            start_shift: f64::NAN,
            complete: None,
            ln_sommerfeld_reference: (reference.viscosity * g.bush_length / PI * (g.pin_radius / params.radial_clearance()).powi(2)).ln(),
        };
        joint.set_temperature_terms()?;
        joint.start_inlet = match &joint.complete {
            None => joint.starved,
            Some(_) => {
                let (g, st) = (&params.grease, &params.starvation);
                let ln_eta_ref = params.lubricant.viscosity.ln();
                let grease = crate::film::cold_supply::ln_layer_inverse(g.enabled, g.supply_layer_inverse, g.supply_exponent, ln_eta_ref, ln_eta_ref);
                crate::film::cold_supply::ln_combined(joint.starved.map(|s| s.ln_q), grease, st.exponent).map(|ln_q| crate::load_sharing::solve::StarvedInlet { ln_q, gamma: st.exponent })
            }
        };
        joint.start = Arc::new(StartTable::new(joint.capacity));
        Ok(joint)
    }

    /// This joint at lubricant temperature `temperature` (K): bit for bit the joint
    /// [`Joint::new`] builds from these parameters with `lubricant.temperature` =
    /// `temperature` (the same values, the same start of every solve, so the same answers),
    /// at the cost of Roelands' temperature relation and a few logarithms. Everything that
    /// does not depend on the temperature (the Hertz and asperity groups, the capacity, the
    /// start table with the rows solved so far) is kept and shared. Errors as
    /// [`Joint::new`]'s for that temperature (out of range, NaN or infinite, or η0(T) not a
    /// finite positive viscosity).
    pub fn at_temperature(&self, temperature: f64) -> Result<Self, ParamError> {
        let mut joint = self.clone();
        joint.params.lubricant.temperature = temperature;
        joint.params.validate()?;
        joint.set_temperature_terms()?;
        Ok(joint)
    }

    /// The terms that follow from the lubricant at `params.lubricant.temperature`: η0(T) and
    /// α(T) by Roelands' temperature relation and the groups built from them.
    fn set_temperature_terms(&mut self) -> Result<(), ParamError> {
        let params = &self.params;
        let lub = crate::rheology::viscosity::at_temperature(&params.lubricant);
        if !(lub.viscosity.is_finite() && lub.viscosity > 0.0 && lub.pressure_viscosity_coefficient.is_finite()) {
            return Err(ParamError::OutOfRange {
                name: "lubricant.temperature".into(),
                value: params.lubricant.temperature,
                unit: "K",
                range: format!(
                    "such that eta_0(T) stays a finite positive viscosity (here {:e} Pa.s; Roelands' temperature relation, reference {} K)",
                    lub.viscosity, params.lubricant.reference_temperature
                ),
            });
        }
        let (g, r_red, e_eff) = (&params.geometry, self.r_red, self.e_eff);
        self.film_unit = FilmGroups::new(1.0, r_red, e_eff, g.bush_length, 1.0, lub.viscosity, lub.pressure_viscosity_coefficient);
        self.ln_eta_ratio = (lub.roelands_viscosity_limit / lub.viscosity).ln();
        self.ln_eta0 = lub.viscosity.ln();
        self.ln_u_mean_unit = (0.5 * lub.viscosity / (e_eff * r_red)).ln();
        self.ln_g = (lub.pressure_viscosity_coefficient * e_eff).ln();
        self.start_shift = if lub.viscosity == params.lubricant.viscosity { 0.0 } else { self.ln_eta0 - params.lubricant.viscosity.ln() };
        self.inlet = self.starved;
        if !params.model.paper {
            let complete = match &self.complete {
                Some(c) => c.at_temperature(params, lub.viscosity),
                None => Complete::new(params, lub.viscosity)?,
            };
            // τ_y(T) and K(T) by their Arrhenius laws: exp(E/R·(1/T − 1/T_ref)) overflows for an
            // activation temperature far beyond a grease's (e.g. E_y/R = 1.13e6 K at 233 K from
            // 293 K: exp(993)); refused here, naming it, rather than as an infinite torque later.
            let (g, rh) = (&params.grease, &complete.rheology);
            for (name, activation, value) in
                [("grease.yield_activation", g.yield_activation, rh.yield_stress), ("grease.consistency_activation", g.consistency_activation, rh.consistency)]
            {
                if !value.is_finite() {
                    return Err(ParamError::OutOfRange {
                        name: name.into(),
                        value: activation,
                        unit: "K",
                        range: format!(
                            "such that the grease's Arrhenius law stays finite at T = {} K from T_ref = {} K (here {value:e})",
                            params.lubricant.temperature, params.lubricant.reference_temperature
                        ),
                    });
                }
            }
            self.complete = Some(complete);
            // The grease's supply layer at the temperature (crate::film::cold_supply), starving the
            // inlet together with the user's own layer, if any.
            let (g, st) = (&params.grease, &params.starvation);
            let grease = crate::film::cold_supply::ln_layer_inverse(g.enabled, g.supply_layer_inverse, g.supply_exponent, params.lubricant.viscosity.ln(), self.ln_eta0);
            let user = self.starved.map(|s| s.ln_q);
            self.inlet = crate::film::cold_supply::ln_combined(user, grease, st.exponent).map(|ln_q| crate::load_sharing::solve::StarvedInlet { ln_q, gamma: st.exponent });
        }
        self.lub = lub;
        Ok(())
    }

    /// A node of the start table: the root at (ln P_T, ln u) from `warm`, by the same (starved
    /// or flooded) solve, with its sensitivities.
    pub(super) fn start_node(&self, ln_p: f64, ln_u: f64, warm: Option<f64>) -> crate::load_sharing::start::Node {
        let asp = self.asp_unit.at_load_ratio(ln_p);
        let film = self.start_film.at_ratio(ln_p, ln_u);
        // The complete model: the composite film of the flooded joint at the reference
        // temperature (S with η0(T_ref)), so that the table starts the journal's region too.
        let journal = self.complete.as_ref().and_then(|c| {
            let ln_s = self.ln_sommerfeld_reference + ln_u - ln_p;
            c.journal_film(c.weight(ln_s, ln_p, self.start_inlet), ln_s, ln_p, self.start_inlet)
        });
        let ls = solve_composite(Some(&film), &asp, &self.params.surface, warm, self.start_inlet, journal.as_ref(), true);
        crate::load_sharing::start::Node { y: ls.logit, dy_dln_load: ls.dlogit_dln_load, dy_dln_speed: ls.dlogit_dln_speed }
    }

    /// The start table's value at (ln P_T, ln u) (its rows there solved first if not yet).
    #[inline]
    pub(super) fn table_start(&self, ln_p: f64, ln_u: f64) -> f64 {
        self.start.guess(ln_p, ln_u + self.start_shift, |a, b, w| self.start_node(a, b, w))
    }

    /// Where a solve at (`load`, `omega`) starts without a warm start: a function of the
    /// operating point alone ([`crate::load_sharing::start`]); NaN at rest.
    pub fn cold_start(&self, load: f64, omega: f64) -> f64 {
        let u = omega.abs() * self.params.geometry.pin_radius;
        if u > 0.0 { self.table_start(load.abs().ln(), u.ln()) } else { f64::NAN }
    }

    /// The parameter set the joint was built with.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The lubricant at its temperature: η0 and α from [`crate::rheology::viscosity::at_temperature`]
    /// (exactly `params().lubricant` at the reference temperature).
    pub fn lubricant(&self) -> &Lubricant {
        &self.lub
    }

    /// R' (m).
    pub fn reduced_radius(&self) -> f64 {
        self.r_red
    }

    /// E' (Pa).
    pub fn effective_modulus(&self) -> f64 {
        self.e_eff
    }

    /// The largest load (N) the asperity model can take: at rest (1/γ2 = 1) eq. 19 gives
    /// h_c = d_d + σ_s·t with F_{3/2}(t) growing with the load, and at this load h_c reaches 0
    /// (the mean planes of the surfaces would pass through each other). Loads at or beyond it
    /// are a [`ModelError::BeyondCapacity`](super::ModelError::BeyondCapacity). 5.05e8 N for the paper's joint. This is where
    /// the equations stop giving an answer, not where they describe the joint: the declared
    /// load capacity is [`Joint::load_edge`] (96.7 kN for the paper's joint), beyond which
    /// the answers are flagged [`crate::Validity::Outside`].
    pub fn capacity(&self) -> f64 {
        self.capacity
    }

    /// The declared load capacity (N): the load at which the Hertz half-width a of eq. 6
    /// reaches the pin's radius, π E' B R²/(8 R') ([`crate::validity::load_edge`]; 96.7 kN for
    /// the paper's joint). Loads above it are answered (up to [`Joint::capacity`]) with the
    /// validity [`crate::Validity::Outside`]: beyond the model's assumptions.
    pub fn load_edge(&self) -> f64 {
        self.edges.load
    }

    /// Where this joint's answers leave the model's assumptions ([`crate::validity::Edges`]):
    /// the load edge and the grease's upper service temperature.
    pub fn edges(&self) -> crate::validity::Edges {
        self.edges
    }

    /// Whether (`load` N, `omega` rad/s) at this joint's lubricant temperature is inside the
    /// conditions the model was checked against ([`crate::validity::Edges::of_point`] with
    /// this joint's edges and the sliding speed |ω|R): the `validity` of
    /// [`Joint::evaluate`]'s answer there.
    pub fn validity(&self, load: f64, omega: f64) -> crate::validity::Validity {
        self.edges.of_point(load, omega.abs() * self.params.geometry.pin_radius, self.params.lubricant.temperature, self.params.model.paper)
    }

    /// The worst excursion of (`load`, `omega`) at this joint's temperature (as
    /// [`Joint::validity`]), `None` when checked: what a log says.
    pub fn excursion(&self, load: f64, omega: f64) -> Option<crate::validity::Excursion> {
        self.edges.excursion(load, omega.abs() * self.params.geometry.pin_radius, self.params.lubricant.temperature, self.params.model.paper)
    }

    /// √(σ² + σ_b²), the composite roughness of λ (eq. 21), m.
    pub fn composite_roughness(&self) -> f64 {
        self.roughness
    }

    /// Whether this joint runs the paper's model (`model.paper = true`).
    pub fn is_paper(&self) -> bool {
        self.complete.is_none()
    }
}

/// Solve eq. 19 at rest for the load at which h_c = 0, i.e. t = −d_d/σ_s. The required
/// ln F_{3/2} at rest, −ln C(P) + softplus(a4 ln K(P))/a4 with ln C = ln C₁ − ½ ln P and
/// ln K = ln K₁ + (a2 − a3) ln P, increases with ln P, so the root is unique. +∞ when it
/// lies beyond f64 loads.
fn asperity_capacity(s: &crate::params::Surface, unit: &AsperityGroups) -> f64 {
    let target = crate::contact::gw::ln_f32(-s.summit_mean_plane_offset / s.summit_height_std);
    let g = |ln_p: f64| unit.at_load_ratio(ln_p).required_ln_f32(0.0) - target;
    let (mut lo, mut hi) = (-745.0, 709.0);
    if g(hi) < 0.0 {
        return f64::INFINITY;
    }
    if g(lo) >= 0.0 {
        return 0.0;
    }
    while hi - lo > 1e-12 * (1.0 + hi.abs()) {
        let mid = 0.5 * (lo + hi);
        if g(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    lo.exp()
}
