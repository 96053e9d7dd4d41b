//! Evaluating the joint: the load-sharing solve at an operating point (eqs. 9, 13, 19), from a
//! start (a caller's guess, the start table or its cut at a load), and μ (eq. 10), the torque
//! (eq. 11), λ (eq. 21) and every other output from its root; the checks of the answer.

use super::load_terms::contact_friction;
use super::{EvaluateError, Joint, LoadTerms, ModelError, OperatingPoint, Regime, REGIME_SHARE};
use crate::composite::Parts;
use crate::load_sharing::solve::{solve_composite, LoadSharing, THIRD_ORDER_ACCEPT};
use crate::load_sharing::start::StartCut;
use crate::params::Params;
use crate::rheology::viscosity::limiting_shear_stress;

/// How close (in the logit) a caller's start must be to the start table's for the solve to
/// begin from it ([`Joint::evaluate_from`]): half the step the solve ends in one evaluation
/// after ([`THIRD_ORDER_ACCEPT`]).
pub const START_AGREEMENT: f64 = 0.5 * THIRD_ORDER_ACCEPT;

/// Where a solve starts: a caller's guess checked against the start table (or the table
/// alone), or the table's cut at the load.
enum Start<'c> {
    From(Option<f64>),
    Cut(&'c mut StartCut),
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

impl Joint {
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
        let ln_r = crate::film::min_film::ln_min_to_central(self.ln_w_unit + lt.ln_load, self.ln_u_mean_unit + ln_u, self.ln_g, op.fluid_load_fraction.ln());
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

/// One-shot convenience: validate `params` and evaluate one point.
pub fn evaluate(params: &Params, load: f64, omega: f64) -> Result<OperatingPoint, EvaluateError> {
    Ok(Joint::new(params)?.evaluate(load, omega)?)
}
