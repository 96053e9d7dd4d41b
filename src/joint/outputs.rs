//! The outputs beyond the paper's load-sharing solve, at an operating point: the minimum film
//! h_min (eq. 21 as printed; an extension, [`crate::film::min_film`]) and the complete model's
//! journal weight, eccentricity, clearance and grease yield torques ([`crate::composite`]).

use super::load_terms::contact_friction;
use super::Joint;

impl Joint {
    /// h_min (m) for a central film `h_c` (m) at `load` (N), `omega` (rad/s) and fluid share
    /// `fluid_fraction` (1/γ1): [`crate::film::min_film`]. 0 where there is no fluid film.
    pub fn min_film(&self, load: f64, omega: f64, film_thickness: f64, fluid_fraction: f64) -> f64 {
        let u = omega.abs() * self.params.geometry.pin_radius;
        let ln_r = crate::film::min_film::ln_min_to_central(self.ln_w_unit + load.ln(), self.ln_u_mean_unit + u.ln(), self.ln_g, fluid_fraction.ln());
        film_thickness * Self::min_film_ratio(ln_r, self.journal_weight(load, omega))
    }

    /// h_min/h_c from the line contact's ln(h_min/h_c) and the journal's weight w: the
    /// composite (h_min/h_c)^(1 − w) (the journal's film h_J is its own minimum), exactly the
    /// line contact's e^{ln r} at w = 0.
    #[inline]
    pub(super) fn min_film_ratio(ln_r: f64, weight: f64) -> f64 {
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
        self.rest_yield().at(load)
    }

    /// The grease's yield torque at rest ([`Joint::rest_yield_torque`], the same at every load),
    /// for the fidelity levels' rest state.
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
}
