//! The pin joint at one operating point: friction coefficient (eq. 10), torque (eq. 11),
//! Sommerfeld number (eq. 20), λ (eq. 21) and everything the load-sharing solve gives.

use crate::asperity::AsperityGroups;
use crate::contact::{effective_modulus, hertz, reduced_radius};
use crate::composite::{Complete, Parts};
use crate::mixed::{solve_composite, FilmGroups, LoadSharing, THIRD_ORDER_ACCEPT};
use crate::params::{Lubricant, ParamError, Params};
use crate::solve_start::{StartCut, StartTable};
use crate::viscosity::{limiting_shear_stress, ln_roelands_from};
use serde::Serialize;
use std::f64::consts::PI;
use std::sync::Arc;
use thiserror::Error;

/// How close (in the logit) a caller's start must be to the start table's for the solve to
/// begin from it ([`Joint::evaluate_from`]): half the step the solve ends in one evaluation
/// after ([`THIRD_ORDER_ACCEPT`]).
pub const START_AGREEMENT: f64 = 0.5 * THIRD_ORDER_ACCEPT;

/// Share of the load below which a carrier counts as absent when naming the regime.
pub const REGIME_SHARE: f64 = 0.01;

/// Lubrication regime, named from the load shares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// The fluid carries less than [`REGIME_SHARE`] of the load.
    Boundary,
    /// Both fluid and asperities carry at least [`REGIME_SHARE`].
    Mixed,
    /// The asperities carry less than [`REGIME_SHARE`].
    FullFilm,
}

impl Regime {
    /// Lower-case name for reports: `boundary`, `mixed` or `full-film`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Regime::Boundary => "boundary",
            Regime::Mixed => "mixed",
            Regime::FullFilm => "full-film",
        }
    }
    /// The regime of a point whose fluid and asperity shares are `fluid` and `asperity`.
    pub fn from_shares(fluid: f64, asperity: f64) -> Self {
        if fluid < REGIME_SHARE {
            Regime::Boundary
        } else if asperity < REGIME_SHARE {
            Regime::FullFilm
        } else {
            Regime::Mixed
        }
    }
}

/// An operating point the model cannot take.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ModelError {
    /// The load (N) is not a finite number > 0.
    #[error("load = {} N is invalid: the load must be a finite number > 0 N", crate::fmt::Num(*.0))]
    Load(f64),
    /// The angular velocity (rad/s) is NaN or infinite.
    #[error("angular velocity = {} rad/s is invalid: it must be a finite number", crate::fmt::Num(*.0))]
    Speed(f64),
    /// The load exceeds what the asperity model (eq. 19) can carry at rest: the film
    /// thickness h_c would be ≤ 0.
    #[error(
        "load = {l} N is beyond the asperity model's capacity of {capacity:.6e} N for these parameters: \
         at rest eq. 19 would put the mean planes of the surfaces through each other (h_c <= 0)",
        l = crate::fmt::Num(*.load)
    )]
    BeyondCapacity {
        /// The load asked for (N).
        load: f64,
        /// The largest load the asperity model carries for these parameters (N).
        capacity: f64,
    },
    /// The paper's model only (`model.paper = true`): the central film would be thicker than
    /// the diametral clearance 2(R_b − R), the widest gap the bush leaves around the pin: the
    /// line-contact film of eq. 12 has left the geometry it was derived for (a lubricant too
    /// viscous for this speed and load: a low temperature, a high speed or a light load). The
    /// complete model hands the film to the journal bearing there ([`crate::composite`]).
    #[error(
        "the model gives film_thickness = {h} m at load = {l} N, angular velocity = {w} rad/s, more than the \
         diametral clearance 2(R_b - R) = {c} m the bush leaves around the pin: the line-contact film (eq. 12) \
         does not hold here (lubricant too viscous for this speed and load: temperature too low, speed too high or load too light)",
        h = crate::fmt::Num(*.film),
        c = crate::fmt::Num(*.limit),
        l = crate::fmt::Num(*.load),
        w = crate::fmt::Num(*.omega)
    )]
    FilmBeyondClearance {
        /// The central film thickness h_c the model gives (m).
        film: f64,
        /// The diametral clearance 2(R_b − R) (m).
        limit: f64,
        /// Load at the point (N).
        load: f64,
        /// Angular velocity at the point (rad/s).
        omega: f64,
    },
    /// A model quantity overflowed or became NaN at this operating point.
    #[error(
        "the model gives {quantity} = {value} at load = {l} N, angular velocity = {w} rad/s: \
         outside its numerical range for these parameters",
        l = crate::fmt::Num(*.load),
        w = crate::fmt::Num(*.omega)
    )]
    NotFinite {
        /// Name of the quantity that is not finite.
        quantity: &'static str,
        /// Its value (NaN or ±∞).
        value: f64,
        /// Load at the point (N).
        load: f64,
        /// Angular velocity at the point (rad/s).
        omega: f64,
    },
}

/// Every quantity of the model at one operating point (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OperatingPoint {
    /// P_T, N.
    pub load: f64,
    /// ω as given, rad/s (the model depends on |ω|).
    pub angular_velocity: f64,
    /// u = |ω| R, sliding speed = Moes' sum velocity (bush fixed), m/s.
    pub sliding_speed: f64,
    /// μ, eq. 10.
    pub friction_coefficient: f64,
    /// T = μ R P_T, eq. 11: magnitude of the torque to articulate the joint, N·m.
    pub torque: f64,
    /// h_c, central film thickness, m.
    pub film_thickness: f64,
    /// λ = h_c/√(σ² + σ_b²), eq. 21 with the central film (docs/model.md, conventions).
    pub lambda_ratio: f64,
    /// 1/γ1.
    pub fluid_load_fraction: f64,
    /// 1/γ2.
    pub asperity_load_fraction: f64,
    /// p_m, Hertz mean pressure, Pa (eq. 6).
    pub mean_pressure: f64,
    /// p0, Hertz peak pressure, Pa (eq. 6).
    pub peak_pressure: f64,
    /// a, Hertz half-width, m (eq. 6).
    pub contact_half_width: f64,
    /// S, eq. 20.
    pub sommerfeld_number: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s; +∞ where eq. 5 overflows (Z of several
    /// units at GPa pressures): μ is computed from ln η and stays finite.
    pub contact_viscosity: f64,
    /// Q_H/P_T: the fluid (Bair–Winer, eq. 3) part of μ.
    pub fluid_friction_coefficient: f64,
    /// μ_c/γ2: the asperity (eq. 8) part of μ.
    pub asperity_friction_coefficient: f64,
    /// ln(x1/x2) of the load-sharing solve (−∞ at rest): a warm start for the next call.
    pub logit: f64,
    /// Lubrication regime from the fluid and asperity load shares.
    pub regime: Regime,
    /// h_min, minimum film thickness, m: h_c times Pan & Hamrock's line-contact ratio
    /// h_min/h_c under eq. 13's substitution ([`crate::min_film`]; an extrapolation here, 0 at
    /// rest). Extension: the paper gives no h_min relation.
    pub min_film_thickness: f64,
    /// λ_min = h_min/√(σ² + σ_b²), eq. 21 as printed (with h_min).
    pub min_lambda_ratio: f64,
    /// Whether the load, sliding speed and the joint's lubricant temperature are inside the
    /// conditions the model was checked against, or past its assumptions
    /// ([`Joint::validity`]).
    pub validity: crate::validity::Validity,
    /// T_clearance, N·m: the torque of the lubricant in the clearance outside the contact arc,
    /// its yield part included (complete model, [`crate::composite`]; 0 for the paper's model).
    pub clearance_torque: f64,
    /// w, the journal bearing's weight in the composite film (0: the paper's line contact
    /// alone, 1: the full-film journal bearing; 0 for the paper's model).
    pub journal_weight: f64,
    /// ε_g = 1 − h_c/c, the eccentricity ratio of the clearance around the film (clamped to
    /// [0, 1)).
    pub eccentricity_ratio: f64,
    /// τ_y(T)·(2π − 2θ_c)·R²·B, N·m: the grease's yield torque, part of
    /// `clearance_torque` and of the torque at rest (0 without grease and for the paper's model).
    pub grease_yield_torque: f64,
}

/// A friction torque of magnitude `torque` given its sign: opposite to `omega` (eq. 11), zero
/// at ω = 0 (where it has no direction).
pub fn opposing(torque: f64, omega: f64) -> f64 {
    if omega > 0.0 {
        -torque
    } else if omega < 0.0 {
        torque
    } else {
        0.0
    }
}

impl OperatingPoint {
    /// The friction torque on the pin with its sign: opposite to ω (eq. 11), zero at ω = 0.
    pub fn signed_torque(&self) -> f64 {
        opposing(self.torque, self.angular_velocity)
    }
}

/// The quantities that depend on load and speed only, not on the load-sharing solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSpeed {
    /// Eq. 6 under the whole load.
    pub hertz: crate::contact::Hertz,
    /// u = |ω| R, m/s.
    pub sliding_speed: f64,
    /// S, eq. 20, with P_L = P/(2RB) and c = R_b − R.
    pub sommerfeld_number: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s.
    pub contact_viscosity: f64,
    /// Its logarithm (finite where η overflows).
    pub ln_contact_viscosity: f64,
    /// Bair–Winer limiting shear stress at p_m (eq. 4), Pa.
    pub limiting_shear_stress: f64,
}

/// A validated parameter set with the load- and speed-independent groups precomputed.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    params: Params,
    r_red: f64,
    e_eff: f64,
    roughness: f64,
    /// Eq. 19's groups at P_T = 1 N.
    asp_unit: AsperityGroups,
    /// Eq. 12's groups at u = 1 m/s, P_T = 1 N.
    film_unit: FilmGroups,
    /// Hertz quantities at P_T = 1 N (a, p_m and p0 all scale with √P_T).
    hertz_unit: crate::contact::Hertz,
    /// ln(η∞/η0) for eq. 5.
    ln_eta_ratio: f64,
    /// ln η0 for eq. 5.
    ln_eta0: f64,
    /// 2RB, the projected area of eq. 20's P_L = P/(2RB), m².
    projected_area: f64,
    /// (R/c)² of eq. 20.
    clearance_ratio_sq: f64,
    /// The load (N) at which the rest film of eq. 19 reaches zero (see [`Joint::capacity`]).
    capacity: f64,
    /// Where the model's assumptions end (the Hertz half-width reaching the pin's radius, the
    /// grease's upper service temperature): [`Joint::validity`] says `outside` beyond.
    edges: crate::validity::Edges,
    /// Converged logits over (ln P_T, ln u) of the lubricant at its reference temperature:
    /// the deterministic start of a cold solve, shared by the joints [`Joint::at_temperature`]
    /// makes (it does not depend on the temperature).
    start: Arc<StartTable>,
    /// Eq. 12's groups at u = 1 m/s, P_T = 1 N for the lubricant at its reference
    /// temperature: the film the start table's nodes are solved with.
    start_film: FilmGroups,
    /// ln(η0(T)/η0(T_ref)): where the start table is read along ln u (0 at T = T_ref). The
    /// film groups depend on η0 and u only through η0·u, so this shift makes the table's
    /// start exact in η0; only α's change with temperature is not in it.
    start_shift: f64,
    /// The lubricant at its temperature ([`crate::viscosity::at_temperature`]; `params.lubricant`
    /// itself, bit for bit, at the reference temperature).
    lub: Lubricant,
    /// ln W' at P_T = 1 N and ln(η0/(2E'R')) (mean-velocity U at u = 1 m/s) and ln G, for h_min.
    ln_w_unit: f64,
    ln_u_mean_unit: f64,
    ln_g: f64,
    /// The starved-inlet correction, if on (`starvation.inlet_layer_inverse > 0`; it does not
    /// depend on the temperature).
    starved: Option<crate::mixed::StarvedInlet>,
    /// What the start table's nodes are solved with: `starved` for the paper's model; for the
    /// complete model the inlet at the reference temperature (the user's layer and the grease's
    /// supply layer at T_ref, [`crate::cold_supply`]), so that at T_ref the table starts the
    /// starved solve at its root (one residual evaluation in most of the boundary and mixed
    /// regimes, against two from the flooded root); a function of the parameters alone.
    start_inlet: Option<crate::mixed::StarvedInlet>,
    /// The inlet at the temperature: the user's starved inlet and the grease's supply layer
    /// ([`crate::cold_supply`]) together; `starved` itself for the paper's model.
    inlet: Option<crate::mixed::StarvedInlet>,
    /// ln S (eq. 20) at P = 1 N, u = 1 m/s with η0(T_ref): ln η0(T_ref) + ln(B (R/c)²/π).
    ln_sommerfeld_reference: f64,
    /// The complete model's terms at the temperature; `None` for the paper's model
    /// (`model.paper = true`), whose path is then today's, bit for bit.
    complete: Option<Complete>,
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
        crate::gw::warm_up();
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
            starved: (st.inlet_layer_inverse > 0.0).then(|| crate::mixed::StarvedInlet { ln_q: st.inlet_layer_inverse.ln(), gamma: st.exponent }),
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
                let grease = crate::cold_supply::ln_layer_inverse(g.enabled, g.supply_layer_inverse, g.supply_exponent, ln_eta_ref, ln_eta_ref);
                crate::cold_supply::ln_combined(joint.starved.map(|s| s.ln_q), grease, st.exponent).map(|ln_q| crate::mixed::StarvedInlet { ln_q, gamma: st.exponent })
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
        let lub = crate::viscosity::at_temperature(&params.lubricant);
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
            // The grease's supply layer at the temperature (crate::cold_supply), starving the
            // inlet together with the user's own layer, if any.
            let (g, st) = (&params.grease, &params.starvation);
            let grease = crate::cold_supply::ln_layer_inverse(g.enabled, g.supply_layer_inverse, g.supply_exponent, params.lubricant.viscosity.ln(), self.ln_eta0);
            let user = self.starved.map(|s| s.ln_q);
            self.inlet = crate::cold_supply::ln_combined(user, grease, st.exponent).map(|ln_q| crate::mixed::StarvedInlet { ln_q, gamma: st.exponent });
        }
        self.lub = lub;
        Ok(())
    }

    /// A node of the start table: the root at (ln P_T, ln u) from `warm`, by the same (starved
    /// or flooded) solve, with its sensitivities.
    fn start_node(&self, ln_p: f64, ln_u: f64, warm: Option<f64>) -> crate::solve_start::Node {
        let asp = self.asp_unit.at_load_ratio(ln_p);
        let film = self.start_film.at_ratio(ln_p, ln_u);
        // The complete model: the composite film of the flooded joint at the reference
        // temperature (S with η0(T_ref)), so that the table starts the journal's region too.
        let journal = self.complete.as_ref().and_then(|c| {
            let ln_s = self.ln_sommerfeld_reference + ln_u - ln_p;
            c.journal_film(c.weight(ln_s, ln_p, self.start_inlet), ln_s, ln_p, self.start_inlet)
        });
        let ls = solve_composite(Some(&film), &asp, &self.params.surface, warm, self.start_inlet, journal.as_ref(), true);
        crate::solve_start::Node { y: ls.logit, dy_dln_load: ls.dlogit_dln_load, dy_dln_speed: ls.dlogit_dln_speed }
    }

    /// The start table's value at (ln P_T, ln u) (its rows there solved first if not yet).
    #[inline]
    fn table_start(&self, ln_p: f64, ln_u: f64) -> f64 {
        self.start.guess(ln_p, ln_u + self.start_shift, |a, b, w| self.start_node(a, b, w))
    }

    /// Where a solve at (`load`, `omega`) starts without a warm start: a function of the
    /// operating point alone ([`crate::solve_start`]); NaN at rest.
    pub fn cold_start(&self, load: f64, omega: f64) -> f64 {
        let u = omega.abs() * self.params.geometry.pin_radius;
        if u > 0.0 { self.table_start(load.abs().ln(), u.ln()) } else { f64::NAN }
    }

    /// The parameter set the joint was built with.
    pub fn params(&self) -> &Params {
        &self.params
    }
    /// The lubricant at its temperature: η0 and α from [`crate::viscosity::at_temperature`]
    /// (exactly `params().lubricant` at the reference temperature).
    pub fn lubricant(&self) -> &Lubricant {
        &self.lub
    }

    /// h_min (m) for a central film `h_c` (m) at `load` (N), `omega` (rad/s) and fluid share
    /// `fluid_fraction` (1/γ1): [`crate::min_film`]. 0 where there is no fluid film.
    pub fn min_film(&self, load: f64, omega: f64, film_thickness: f64, fluid_fraction: f64) -> f64 {
        let u = omega.abs() * self.params.geometry.pin_radius;
        let ln_r = crate::min_film::ln_min_to_central(self.ln_w_unit + load.ln(), self.ln_u_mean_unit + u.ln(), self.ln_g, fluid_fraction.ln());
        film_thickness * Self::min_film_ratio(ln_r, self.journal_weight(load, omega))
    }

    /// h_min/h_c from the line contact's ln(h_min/h_c) and the journal's weight w: the
    /// composite (h_min/h_c)^(1 − w) (the journal's film h_J is its own minimum), exactly the
    /// line contact's e^{ln r} at w = 0.
    #[inline]
    fn min_film_ratio(ln_r: f64, weight: f64) -> f64 {
        if weight == 0.0 {
            ln_r.exp()
        } else if weight >= 1.0 {
            1.0
        } else {
            ((1.0 - weight) * ln_r).exp()
        }
    }

    /// ε_g = 1 − h/c of the clearance around the film `film` (m), clamped to [0, 1).
    pub fn eccentricity_of(&self, film: f64) -> f64 {
        (1.0 - film / self.params.radial_clearance()).clamp(0.0, 1.0 - f64::EPSILON)
    }

    /// Whether this joint runs the paper's model (`model.paper = true`).
    pub fn is_paper(&self) -> bool {
        self.complete.is_none()
    }

    /// The journal's weight w at (`load` N, `omega` rad/s): a function of the operating
    /// point alone ([`crate::composite`]); 0 at rest and for the paper's model.
    pub fn journal_weight(&self, load: f64, omega: f64) -> f64 {
        match &self.complete {
            Some(c) if omega != 0.0 && omega.is_finite() => c.weight(self.sommerfeld_at(load.abs() / self.projected_area, omega).ln(), load.abs().ln(), self.inlet),
            _ => 0.0,
        }
    }

    /// The grease's yield torque at rest τ_y(T)·2π·R²·B (N·m) under `load` (N), the same at
    /// every load ([`crate::composite`]): what the grease adds to the breakaway torque ([`Joint::boundary_torque`]); 0 without grease
    /// and for the paper's model.
    pub fn rest_yield_torque(&self, load: f64) -> f64 {
        match &self.complete {
            Some(c) => {
                let _ = load;
                c.yield_torque()
            }
            None => 0.0,
        }
    }

    /// The grease's yield torque at rest as a function of the load ([`Joint::rest_yield_torque`],
    /// for the fidelity levels' rest state).
    pub fn rest_yield(&self) -> crate::composite::RestYield {
        crate::composite::RestYield::new(self.complete.as_ref())
    }

    /// The complete model's outputs that follow from the operating point and its film `film`
    /// (m): (clearance torque N·m, journal weight, ε_g, grease yield torque N·m), as
    /// [`Joint::evaluate`] gives them; (0, 0, ε_g, 0) for the paper's model.
    pub fn clearance_outputs(&self, load: f64, omega: f64, film: f64) -> (f64, f64, f64, f64) {
        let eps = self.eccentricity_of(film);
        match &self.complete {
            Some(c) => {
                let w = self.journal_weight(load, omega);
                let a = self.hertz_unit.half_width * load.abs().sqrt();
                let u = omega.abs() * self.params.geometry.pin_radius;
                // The line contact's fluid torque (eq. 3) at this film, for the grease's excess
                // within the contact arc (crate::composite::Complete::contact_torque).
                let load = load.abs();
                let line = if load.is_finite() && load > 0.0 && u > 0.0 && film > 0.0 {
                    let lt = self.load_terms_unchecked(load);
                    (1.0 - w) * contact_friction(&lt, u, u.ln(), film.ln()) * (self.params.geometry.pin_radius * load)
                } else {
                    0.0
                };
                (c.clearance_and_arc(a, u, film, line).0, w, eps, c.yield_torque())
            }
            None => (0.0, 0.0, eps, 0.0),
        }
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
    /// are a [`ModelError::BeyondCapacity`]. 5.05e8 N for the paper's joint. This is where
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

    /// Hertz quantities, sliding speed, Sommerfeld number and the rheology at p_m: the parts
    /// of an operating point that do not need the load-sharing solve.
    pub fn load_speed(&self, load: f64, omega: f64) -> LoadSpeed {
        let load = load.abs();
        let (hertz, ln_eta, tau_l) = self.rheology(load);
        LoadSpeed {
            hertz,
            sliding_speed: omega.abs() * self.params.geometry.pin_radius,
            sommerfeld_number: self.sommerfeld_at(load / self.projected_area, omega),
            contact_viscosity: ln_eta.exp(),
            ln_contact_viscosity: ln_eta,
            limiting_shear_stress: tau_l,
        }
    }

    /// Eq. 6 under `load` (scaled from 1 N: a, p_m, p0 ∝ √P_T), ln η (eq. 5) and τ_L (eq. 4) at p_m.
    fn rheology(&self, load: f64) -> (crate::contact::Hertz, f64, f64) {
        let sqrt_p = load.sqrt();
        let hertz = crate::contact::Hertz {
            half_width: self.hertz_unit.half_width * sqrt_p,
            mean_pressure: self.hertz_unit.mean_pressure * sqrt_p,
            peak_pressure: self.hertz_unit.peak_pressure * sqrt_p,
        };
        let ln_eta = ln_roelands_from(&self.lub, hertz.mean_pressure, self.ln_eta0, self.ln_eta_ratio);
        (hertz, ln_eta, limiting_shear_stress(&self.lub, hertz.mean_pressure))
    }

    /// The parts of an evaluation that depend on the load alone, checked as
    /// [`Joint::evaluate`] checks the load (its magnitude is used). A host that evaluates
    /// many speeds at one load computes them once ([`Joint::friction_at`]).
    pub fn load_terms(&self, load: f64) -> Result<LoadTerms, ModelError> {
        let load = load.abs();
        if !(load.is_finite() && load > 0.0) {
            return Err(ModelError::Load(load));
        }
        if load >= self.capacity {
            return Err(ModelError::BeyondCapacity { load, capacity: self.capacity });
        }
        Ok(self.load_terms_unchecked(load))
    }

    fn load_terms_unchecked(&self, load: f64) -> LoadTerms {
        let (hertz, ln_eta, tau_l) = self.rheology(load);
        let ln_load = load.ln();
        LoadTerms {
            load,
            ln_load,
            hertz,
            line_load: load / self.projected_area,
            contact_viscosity: ln_eta.exp(),
            ln_contact_viscosity: ln_eta,
            limiting_shear_stress: tau_l,
            ln_limiting_shear_stress: tau_l.ln(),
            asperity: self.asp_unit.at_load_ratio(ln_load),
        }
    }

    /// S, eq. 20, with P_L = P/(2RB) and c = R_b − R.
    fn sommerfeld(&self, lt: &LoadTerms, omega: f64) -> f64 {
        self.sommerfeld_at(lt.line_load, omega)
    }

    #[inline]
    fn sommerfeld_at(&self, line_load: f64, omega: f64) -> f64 {
        self.lub.viscosity * omega.abs() / (2.0 * PI * line_load) * self.clearance_ratio_sq
    }

    /// The torque at rest (ω → 0⁺) at `load` (N): μ_c R |P| (the ω → 0 limit of eq. 11) plus,
    /// for the complete model, the grease's yield torque ([`Joint::rest_yield_torque`]).
    pub fn boundary_torque(&self, load: f64) -> f64 {
        let t = self.params.friction.boundary_friction_coefficient * self.params.geometry.pin_radius * load.abs();
        if self.complete.is_some() { t + self.rest_yield_torque(load) } else { t }
    }

    /// The operating point at `load` (N) and angular velocity `omega` (rad/s).
    ///
    /// The load is the magnitude of the radial reaction: a negative value (a signed reaction
    /// component from a gear model) gives exactly the answer of its absolute value, which must
    /// be > 0 and below [`Joint::capacity`].
    pub fn evaluate(&self, load: f64, omega: f64) -> Result<OperatingPoint, ModelError> {
        self.evaluate_from(load, omega, None)
    }

    /// As [`Joint::evaluate`], starting the solve from `guess` (the `logit` of a nearby
    /// point) when it agrees with [`Joint::cold_start`] to [`START_AGREEMENT`], else from
    /// [`Joint::cold_start`] (a guess further off is most likely the worse start); the answer
    /// is the same to the solver tolerance. Without a guess the solve starts from
    /// [`Joint::cold_start`], so the answer depends on (`load`, `omega`) and the parameters alone.
    pub fn evaluate_from(&self, load: f64, omega: f64, guess: Option<f64>) -> Result<OperatingPoint, ModelError> {
        let (load, lt) = self.checked_load_terms(load, omega)?;
        let (op, _) = self.evaluate_at(&lt, omega, guess)?;
        self.check_film(op.film_thickness, op.fluid_load_fraction, load, omega)?;
        Ok(op)
    }

    /// As [`Joint::evaluate_from`] with the load's terms `lt` already computed by
    /// [`Joint::load_terms`] of this joint (at its temperature), bit for bit: a caller whose
    /// load does not change between calls (the FMU's step) computes them once.
    pub fn evaluate_from_terms(&self, lt: &LoadTerms, omega: f64, guess: Option<f64>) -> Result<OperatingPoint, ModelError> {
        if !omega.is_finite() {
            return Err(ModelError::Speed(omega));
        }
        let (op, _) = self.evaluate_at(lt, omega, guess)?;
        self.check_film(op.film_thickness, op.fluid_load_fraction, lt.load, omega)?;
        Ok(op)
    }

    /// The model's equations at (`load`, `omega`) as [`Joint::evaluate`] solves them, without
    /// the geometric bound on the film ([`ModelError::FilmBeyondClearance`]): the answer the
    /// equations give where the film of eq. 12 is thicker than the clearance allows. For
    /// tests of the solver over the whole range of its equations; a model answer is
    /// [`Joint::evaluate`]'s.
    pub fn evaluate_unbounded(&self, load: f64, omega: f64) -> Result<OperatingPoint, ModelError> {
        let (_, lt) = self.checked_load_terms(load, omega)?;
        Ok(self.evaluate_at(&lt, omega, None)?.0)
    }

    /// The load's magnitude and its terms, after checking the inputs of an evaluation: the
    /// load finite and > 0 in magnitude, ω finite.
    fn checked_load_terms(&self, load: f64, omega: f64) -> Result<(f64, LoadTerms), ModelError> {
        let load = load.abs();
        if !(load.is_finite() && load > 0.0) {
            return Err(ModelError::Load(load));
        }
        if !omega.is_finite() {
            return Err(ModelError::Speed(omega));
        }
        Ok((load, self.load_terms(load)?))
    }

    /// Where a moving solve starts: the start table's value at (ln P_T, ln u), or the caller's
    /// `guess` when it agrees with the table's to [`START_AGREEMENT`] (a guess further off is
    /// most likely worse than the table, whose error is ~1e-6 in the mixed regime: a
    /// neighbour's root a few per cent away in speed is ~1e-2 off and would cost Newton steps),
    /// or when the table has no value there.
    #[inline]
    fn start_from(&self, guess: Option<f64>, ln_load: f64, ln_u: f64) -> f64 {
        let table = self.table_start(ln_load, ln_u);
        match guess {
            Some(g) if g.is_finite() && (table.is_nan() || (g - table).abs() <= START_AGREEMENT) => g,
            _ => table,
        }
    }

    /// The load-sharing solve and μ (eqs. 3, 8, 10) at the load of `lt` and speed u = |ω|R:
    /// (ln u, the solve, μ_fluid, μ_asperity, the complete model's parts). `omega` must be
    /// finite. μ_fluid is the lubricant's part of μ: Q_H/P_T (eq. 3) for the paper's model;
    /// for the complete model ((1 − w)·Q_H·R + T_clearance + T_poiseuille)/(R·P)
    /// ([`crate::composite`]), so that μ = μ_fluid + μ_asperity = T/(R·P) either way.
    fn solve_at(&self, lt: &LoadTerms, omega: f64, start: Start, sensitivities: bool) -> (f64, LoadSharing, f64, f64, Parts) {
        let p = &self.params;
        let u = omega.abs() * p.geometry.pin_radius;
        let ln_u = u.ln();
        let film = (u > 0.0).then(|| self.film_unit.at_ratio(lt.ln_load, ln_u));
        // The complete model's journal weight (0 at rest and for the paper's model).
        let (weight, ln_s) = match &self.complete {
            Some(c) if u > 0.0 => {
                let ln_s = self.sommerfeld(lt, omega).ln();
                (c.weight(ln_s, lt.ln_load, self.inlet), ln_s)
            }
            _ => (0.0, f64::NEG_INFINITY),
        };
        let journal = self.complete.as_ref().and_then(|c| c.journal_film(weight, ln_s, lt.ln_load, self.inlet));
        let guess = match start {
            Start::From(guess) if u > 0.0 => Some(self.start_from(guess, lt.ln_load, ln_u)),
            Start::From(guess) => guess,
            // The cut is the table at its load to rounding; where it has no value (another
            // load, a corner without derivatives) the table decides.
            Start::Cut(cut) if u > 0.0 => Some(match self.start.cut_guess(cut, ln_u + self.start_shift, |a, b, w| self.start_node(a, b, w)) {
                g if g.is_finite() && cut.ln_load() == lt.ln_load => g,
                _ => self.table_start(lt.ln_load, ln_u),
            }),
            Start::Cut(_) => None,
        };
        let ls = solve_composite(film.as_ref(), &lt.asperity, &p.surface, guess, self.inlet, journal.as_ref(), sensitivities);
        // Eq. 3 with eq. 4 and 5 at the Hertz mean pressure; Q_H/P_T = τ_L(1 − e^{−ηu/(τ_L h_c)})/p_m.
        // At rest (u = 0) there is no fluid shear: μ = μ_c exactly (docs/model.md, limits), whatever η.
        // The exponent ηu/(τ_L h_c) is formed in logarithms, so η overflowing is harmless.
        let mu_contact = contact_friction(lt, u, ln_u, ls.ln_film_thickness);
        // Eq. 8: Q_C = μ_c P_C = μ_c P_T/γ2.
        let mu_asperity = p.friction.boundary_friction_coefficient * ls.asperity_fraction;
        match &self.complete {
            None => (ln_u, ls, mu_contact, mu_asperity, Parts::default()),
            Some(c) => {
                let rp = p.geometry.pin_radius * lt.load;
                let line = (1.0 - weight) * mu_contact * rp;
                // The excess within the contact arc from the film h_c itself, as
                // Joint::clearance_outputs has it (the same bits on every path).
                let line_of_film = (1.0 - weight) * contact_friction(lt, u, ln_u, ls.film_thickness.ln()) * rp;
                let parts = c.parts(weight, ln_s, &ls, lt.hertz.half_width, lt.load, u, line_of_film);
                let mu_fluid = (line + parts.clearance_torque + parts.poiseuille_torque) / rp;
                (ln_u, ls, mu_fluid, mu_asperity, parts)
            }
        }
    }

    /// The torque magnitude T = μ R P (eq. 11) at the load of `lt` and angular velocity
    /// `omega`, the solve started from `guess` as in [`Joint::evaluate_from`]: bit for bit the
    /// `torque` and `friction_coefficient` of [`Joint::evaluate_from`] with the same guess,
    /// without the quantities a time integration of the torque does not need (h_min, S, λ),
    /// and with the solve's sensitivities for the next start. Errors as
    /// [`Joint::evaluate_from`] (the same checks on the same numbers).
    pub fn friction_at(&self, lt: &LoadTerms, omega: f64, guess: Option<f64>) -> Result<Friction, ModelError> {
        self.friction_with(lt, omega, Start::From(guess), true)
    }

    /// As [`Joint::friction_at`] started from [`Joint::cold_start`] (so a function of the
    /// load of `lt`, `omega` and the parameters alone, whatever was evaluated before) and
    /// without the root's sensitivities (`dlogit_dln_load` and `dlogit_dln_speed` are NaN
    /// when moving): the cheapest full-fidelity torque, one residual evaluation in most of
    /// the boundary and mixed regimes. Bit for bit the torque of [`Joint::evaluate`].
    /// With the start table ~1e-6 from the root, a neighbour's root moved by its
    /// sensitivities is no better a start, and computing those sensitivities cost 18 % of a
    /// rig run's instructions (callgrind, `examples/rig_once.rs`: 79.5 M against 65.4 M); the
    /// rig now starts from the table's cut at its load ([`Joint::friction_cut_at`]).
    pub fn friction_cold_at(&self, lt: &LoadTerms, omega: f64) -> Result<Friction, ModelError> {
        self.friction_with(lt, omega, Start::From(None), false)
    }

    /// The start table at the load of `lt`, for [`Joint::friction_cut_at`].
    pub fn start_cut(&self, lt: &LoadTerms) -> StartCut {
        self.start.cut(lt.ln_load)
    }

    /// Move `cut` to the load of `lt`, keeping its allocation (as a new [`Joint::start_cut`]).
    pub fn recut(&self, cut: &mut StartCut, lt: &LoadTerms) {
        self.start.recut(cut, lt.ln_load);
    }

    /// As [`Joint::friction_cold_at`], the solve started from `cut` (the start table cut at
    /// this load, [`Joint::start_cut`]) instead of the two-dimensional table: the same start
    /// to rounding, a fifth of its interpolation work, so the same root to the solver's
    /// stopping rule (not bit for bit [`Joint::evaluate`]). Still a function of (P, ω) and
    /// the parameters alone, whatever was evaluated before. A cut of another load is not
    /// used (the table is). A cut belongs to the joint that made it: one of another joint with
    /// the same grid would be read, as a worse start the solve still converges from.
    pub fn friction_cut_at(&self, lt: &LoadTerms, cut: &mut StartCut, omega: f64) -> Result<Friction, ModelError> {
        self.friction_with(lt, omega, Start::Cut(cut), false)
    }

    /// [`Joint::friction_at`] with the sensitivities only when `sensitivities`.
    fn friction_with(&self, lt: &LoadTerms, omega: f64, start: Start, sensitivities: bool) -> Result<Friction, ModelError> {
        if !omega.is_finite() {
            return Err(ModelError::Speed(omega));
        }
        let (_, ls, mu_fluid, mu_asperity, _) = self.solve_at(lt, omega, start, sensitivities);
        let mu = mu_fluid + mu_asperity;
        let torque = mu * self.params.geometry.pin_radius * lt.load;
        // The checks of `check_finite`, in its order, on the same numbers (h_min and λ_min are
        // finite whenever h_c is: h_min = h_c·e^{ln r} with ln r ≤ 0 or −∞).
        let hz = &lt.hertz;
        let fields = [
            ("friction_coefficient", mu),
            ("torque", torque),
            ("film_thickness", ls.film_thickness),
            ("lambda_ratio", ls.film_thickness / self.roughness),
            ("fluid_load_fraction", ls.fluid_fraction),
            ("asperity_load_fraction", ls.asperity_fraction),
            ("mean_pressure", hz.mean_pressure),
            ("peak_pressure", hz.peak_pressure),
            ("contact_half_width", hz.half_width),
            ("sommerfeld_number", self.sommerfeld(lt, omega)),
        ];
        for (quantity, value) in fields {
            if !value.is_finite() || (quantity == "film_thickness" && value <= 0.0) {
                return Err(ModelError::NotFinite { quantity, value, load: lt.load, omega });
            }
        }
        self.check_film(ls.film_thickness, ls.fluid_fraction, lt.load, omega)?;
        Ok(Friction {
            friction_coefficient: mu,
            torque,
            logit: ls.logit,
            dlogit_dln_load: ls.dlogit_dln_load,
            dlogit_dln_speed: ls.dlogit_dln_speed,
            evaluations: ls.evaluations,
        })
    }

    /// [`Joint::evaluate_from`] at the load of `lt`: the operating point and the solve.
    fn evaluate_at(&self, lt: &LoadTerms, omega: f64, guess: Option<f64>) -> Result<(OperatingPoint, LoadSharing), ModelError> {
        let g = &self.params.geometry;
        let (load, hz) = (lt.load, lt.hertz);
        let u = omega.abs() * g.pin_radius;
        let (ln_u, ls, mu_fluid, mu_asperity, parts) = self.solve_at(lt, omega, Start::From(guess), false);
        let mu = mu_fluid + mu_asperity;
        let op = OperatingPoint {
            load,
            angular_velocity: omega,
            sliding_speed: u,
            friction_coefficient: mu,
            torque: mu * g.pin_radius * load,
            film_thickness: ls.film_thickness,
            lambda_ratio: ls.film_thickness / self.roughness,
            fluid_load_fraction: ls.fluid_fraction,
            asperity_load_fraction: ls.asperity_fraction,
            mean_pressure: hz.mean_pressure,
            peak_pressure: hz.peak_pressure,
            contact_half_width: hz.half_width,
            sommerfeld_number: self.sommerfeld(lt, omega),
            contact_viscosity: lt.contact_viscosity,
            fluid_friction_coefficient: mu_fluid,
            asperity_friction_coefficient: mu_asperity,
            logit: ls.logit,
            regime: Regime::from_shares(ls.fluid_fraction, ls.asperity_fraction),
            min_film_thickness: 0.0,
            min_lambda_ratio: 0.0,
            validity: self.validity(load, omega),
            clearance_torque: parts.clearance_torque,
            journal_weight: parts.weight,
            eccentricity_ratio: self.eccentricity_of(ls.film_thickness),
            grease_yield_torque: parts.yield_torque,
        };
        // h_min (as Joint::min_film, with ln P_T and ln u already at hand).
        let ln_r = crate::min_film::ln_min_to_central(self.ln_w_unit + lt.ln_load, self.ln_u_mean_unit + ln_u, self.ln_g, op.fluid_load_fraction.ln());
        let h_min = op.film_thickness * Self::min_film_ratio(ln_r, parts.weight);
        let op = OperatingPoint { min_film_thickness: h_min, min_lambda_ratio: h_min / self.roughness, ..op };
        check_finite(&op)?;
        Ok((op, ls))
    }

    /// The diametral clearance 2(R_b − R) (m): the widest gap the bush leaves around the pin,
    /// and so the largest central film the paper's model answers with
    /// ([`ModelError::FilmBeyondClearance`]; the complete model's film is the composite one).
    pub fn max_film_thickness(&self) -> f64 {
        2.0 * self.params.radial_clearance()
    }

    /// The largest friction coefficient the model can give at `load` (N): the asperities
    /// carry at most the whole load at μ_c (eq. 8), and the fluid shear stress is at most
    /// Bair–Winer's limiting stress τ_L(p_m) = τ_L0 + β0 p_m (eq. 3: Q_H/P_T =
    /// τ_L(1 − e^{−ηu/(τ_L h_c)})/p_m ≤ τ_L/p_m), so μ = (Q_H + Q_C)/P_T ≤ μ_c + τ_L0/p_m + β0,
    /// p_m the Hertz mean pressure under the load (eq. 6). Light loads allow a large μ (p_m → 0).
    /// For the paper's model; the complete model adds the clearance's shear, which grows
    /// without bound with the speed (the base oil's Newtonian part): +∞ there.
    pub fn max_friction_coefficient(&self, load: f64) -> f64 {
        if self.complete.is_some() {
            return f64::INFINITY;
        }
        let p_m = self.hertz_unit.mean_pressure * load.abs().sqrt();
        self.params.friction.boundary_friction_coefficient + limiting_shear_stress(&self.lub, p_m) / p_m
    }

    /// [`ModelError::FilmBeyondClearance`] when `film` (m) exceeds [`Joint::max_film_thickness`]
    /// where the fluid sets it: its share `fluid_fraction` (1/γ1) at least [`REGIME_SHARE`].
    /// In the boundary regime and at rest the separation is the asperities' (eq. 19, a few
    /// summit heights), bounded by the surfaces, not by eq. 12.
    pub fn check_film(&self, film: f64, fluid_fraction: f64, load: f64, omega: f64) -> Result<(), ModelError> {
        // The complete model's film is the composite one, bounded by the journal bearing.
        if self.complete.is_some() {
            return Ok(());
        }
        let limit = self.max_film_thickness();
        if film > limit && fluid_fraction >= REGIME_SHARE {
            return Err(ModelError::FilmBeyondClearance { film, limit, load, omega });
        }
        Ok(())
    }
}

/// Where a solve starts: a caller's guess checked against the start table (or the table
/// alone), or the table's cut at the load.
enum Start<'c> {
    From(Option<f64>),
    Cut(&'c mut StartCut),
}

/// Eq. 3 with eqs. 4 and 5 at the Hertz mean pressure: Q_H/P_T = τ_L(1 − e^{−ηu/(τ_L h_c)})/p_m
/// at sliding speed `u` (m/s, its logarithm `ln_u`) and ln h_c `ln_film`. At rest (u = 0) there
/// is no fluid shear: 0 exactly (docs/model.md, limits), whatever η. The exponent
/// ηu/(τ_L h_c) is formed in logarithms, so η overflowing is harmless.
#[inline]
fn contact_friction(lt: &LoadTerms, u: f64, ln_u: f64, ln_film: f64) -> f64 {
    if u > 0.0 {
        let ln_x = lt.ln_contact_viscosity + ln_u - lt.ln_limiting_shear_stress - ln_film;
        lt.limiting_shear_stress / lt.hertz.mean_pressure * -(-crate::fast_math::exp(ln_x)).exp_m1()
    } else {
        0.0
    }
}

/// The parts of an evaluation that depend on the load alone ([`Joint::load_terms`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTerms {
    /// |P_T|, N.
    pub load: f64,
    /// ln |P_T|.
    pub ln_load: f64,
    /// Eq. 6 under the whole load.
    pub hertz: crate::contact::Hertz,
    /// P_L = P/(2RB) of eq. 20, Pa.
    pub line_load: f64,
    /// Roelands viscosity at p_m (eq. 5), Pa·s (+∞ where it overflows).
    pub contact_viscosity: f64,
    /// Its logarithm.
    pub ln_contact_viscosity: f64,
    /// Bair–Winer limiting shear stress at p_m (eq. 4), Pa.
    pub limiting_shear_stress: f64,
    /// Its logarithm.
    pub ln_limiting_shear_stress: f64,
    /// Eq. 19's groups at this load.
    pub asperity: AsperityGroups,
}

/// What [`Joint::friction_at`] gives: μ, the torque and the solve's root with its sensitivities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    /// μ, eq. 10.
    pub friction_coefficient: f64,
    /// T = μ R P_T, eq. 11, N·m (a magnitude).
    pub torque: f64,
    /// ln(x1/x2) of the solve (−∞ at rest): a warm start for the next call.
    pub logit: f64,
    /// ∂logit/∂ln P_T at fixed speed (0 at rest).
    pub dlogit_dln_load: f64,
    /// ∂logit/∂ln u at fixed load (0 at rest).
    pub dlogit_dln_speed: f64,
    /// Residual evaluations the solve took.
    pub evaluations: u32,
}

/// Solve eq. 19 at rest for the load at which h_c = 0, i.e. t = −d_d/σ_s. The required
/// ln F_{3/2} at rest, −ln C(P) + softplus(a4 ln K(P))/a4 with ln C = ln C₁ − ½ ln P and
/// ln K = ln K₁ + (a2 − a3) ln P, increases with ln P, so the root is unique. +∞ when it
/// lies beyond f64 loads.
fn asperity_capacity(s: &crate::params::Surface, unit: &AsperityGroups) -> f64 {
    let target = crate::gw::ln_f32(-s.summit_mean_plane_offset / s.summit_height_std);
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

/// An operating point with a non-finite number is an error naming the quantity (possible only
/// for parameter sets far outside any real joint; found by fuzzing). `contact_viscosity` is
/// exempt: it may be +∞ where eq. 5 overflows, which is harmless (μ uses ln η).
fn check_finite(op: &OperatingPoint) -> Result<(), ModelError> {
    let fields = [
        ("friction_coefficient", op.friction_coefficient),
        ("torque", op.torque),
        ("film_thickness", op.film_thickness),
        ("lambda_ratio", op.lambda_ratio),
        ("fluid_load_fraction", op.fluid_load_fraction),
        ("asperity_load_fraction", op.asperity_load_fraction),
        ("mean_pressure", op.mean_pressure),
        ("peak_pressure", op.peak_pressure),
        ("contact_half_width", op.contact_half_width),
        ("sommerfeld_number", op.sommerfeld_number),
        ("min_film_thickness", op.min_film_thickness),
        ("min_lambda_ratio", op.min_lambda_ratio),
    ];
    for (quantity, value) in fields {
        if !value.is_finite() || (quantity == "film_thickness" && value <= 0.0) {
            return Err(ModelError::NotFinite { quantity, value, load: op.load, omega: op.angular_velocity });
        }
    }
    Ok(())
}

/// Why [`evaluate`] failed: the parameters, or the operating point.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum EvaluateError {
    /// The parameter set was rejected ([`Joint::new`]).
    #[error(transparent)]
    Params(#[from] crate::params::ParamError),
    /// The operating point was rejected ([`Joint::evaluate`]).
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// One-shot convenience: validate `params` and evaluate one point.
pub fn evaluate(params: &Params, load: f64, omega: f64) -> Result<OperatingPoint, EvaluateError> {
    Ok(Joint::new(params)?.evaluate(load, omega)?)
}
