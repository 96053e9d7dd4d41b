//! Fidelity levels: speed against error, with the error always known (issue 6).
//!
//! | level | per call | error |
//! |---|---|---|
//! | [`Fidelity::Full`] | the complete solve, warm-started from the previous call | the solver's, [`FULL_ERROR_BOUND`] |
//! | [`Fidelity::Table`] | bicubic interpolation of the Stribeck map in (ln P, ln \|ω\|) ([`table`]) | measured over the envelope, ≤ tolerance |
//! | [`Fidelity::Boundary`] | μ = μ_c, film of the rest state ([`boundary`]) | measured over the envelope |
//! | [`Fidelity::Auto`] | the cheapest of boundary < table < full whose bound is ≤ tolerance | that level's |
//!
//! Errors are measured against the complete solve: relative in μ, torque and h_c,
//! absolute in the load shares 1/γ1, 1/γ2 ([`ErrorReport`]). The table and boundary levels
//! hold over a declared [`Envelope`] of loads and speed magnitudes; outside it they answer
//! with the complete solve ([`Source::Fallback`]), flag the first such call
//! ([`Evaluation::first_fallback`]) and count them ([`Evaluator::fallbacks`]), so the
//! caller can say so once in its log (the library does no I/O). Inside the envelope, the
//! few table cells the grid cannot resolve within its budget (a kink of the complete model's
//! map along a curve) answer with the complete solve ([`Source::Full`],
//! [`StribeckTable::solved_cells`]). ω = 0 (a stuck joint) is answered by every level with
//! the rest state: μ = μ_c plus the grease's yield torque over R·P (μ_c exactly for the
//! paper's model) and the rest film (1-D table in load for table and boundary).
//!
//! ```
//! use pinjoint::Params;
//! use pinjoint::fidelity::{Envelope, Evaluator, Fidelity, Level};
//! let env = Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap(); // N, rad/s
//! let mut ev = Evaluator::new(&Params::default(), "auto".parse().unwrap(), 1e-4, env).unwrap();
//! assert_eq!(ev.chosen(), Level::Table);
//! assert!(ev.error_bound() <= 1e-4);
//! let e = ev.evaluate(20e3, 0.2).unwrap();
//! assert!((e.friction_coefficient - 0.1183).abs() < 1e-3);
//! // Rest (ω = 0): the breakaway torque, μ_c·R·P plus the grease's yield torque.
//! let joint = pinjoint::Joint::new(&Params::default()).unwrap();
//! let rest = ev.evaluate(20e3, 0.0).unwrap();
//! assert!((rest.torque / joint.boundary_torque(20e3) - 1.0).abs() < 1e-12);
//! assert!(rest.friction_coefficient > 0.12);
//! // The paper's model has no grease yield: μ = μ_c exactly at rest.
//! let mut paper = Evaluator::new(&Params::paper(), Fidelity::Table, 1e-4, env).unwrap();
//! assert_eq!(paper.evaluate(20e3, 0.0).unwrap().friction_coefficient, 0.12);
//! ```

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod envelope;
pub mod evaluation;
pub mod check;
pub mod full;
mod hermite;
pub mod rest;
pub mod table;
pub mod boundary;

pub use boundary::BoundaryLevel;
pub use check::ErrorReport;
pub use envelope::Envelope;
pub use error::FidelityError;
pub use evaluation::{Evaluation, Source};
pub use full::{WarmSolver, FULL_ERROR_BOUND};
pub use table::{Located, StribeckTable, TableStats};

use crate::joint::{Joint, OperatingPoint};
use crate::params::Params;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// The fidelity a caller asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Fidelity {
    /// The complete mixed-lubrication solve at every call (error [`FULL_ERROR_BOUND`]).
    Full,
    /// Bicubic interpolation of a Stribeck table built over the envelope.
    Table,
    /// Boundary lubrication: μ = μ_c and the rest film, valid deep in the boundary regime.
    Boundary,
    /// The cheapest of boundary, table and full whose error bound meets the tolerance.
    Auto,
}

impl Fidelity {
    /// Every fidelity, in the order of the table in the module doc.
    pub const ALL: [Fidelity; 4] = [Fidelity::Full, Fidelity::Table, Fidelity::Boundary, Fidelity::Auto];
    /// Lower-case name, as accepted by the parser and written in reports (`full`, `table`, ...).
    pub fn as_str(&self) -> &'static str {
        match self {
            Fidelity::Full => "full",
            Fidelity::Table => "table",
            Fidelity::Boundary => "boundary",
            Fidelity::Auto => "auto",
        }
    }
}

impl fmt::Display for Fidelity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Fidelity {
    type Err = FidelityError;
    /// `full | table | boundary | auto`, ASCII case-insensitive, surrounding blanks ignored.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let t = s.trim();
        Fidelity::ALL.into_iter().find(|f| f.as_str().eq_ignore_ascii_case(t)).ok_or_else(|| FidelityError::UnknownFidelity(crate::fmt::excerpt(s)))
    }
}

/// The level an [`Evaluator`] actually runs (what `auto` resolved to).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// The complete solve ([`Fidelity::Full`]).
    Full,
    /// The interpolated Stribeck table ([`Fidelity::Table`]).
    Table,
    /// The boundary-lubrication answer ([`Fidelity::Boundary`]).
    Boundary,
}

impl Level {
    /// The fidelity that asks for this level.
    pub fn fidelity(self) -> Fidelity {
        match self {
            Level::Full => Fidelity::Full,
            Level::Table => Fidelity::Table,
            Level::Boundary => Fidelity::Boundary,
        }
    }
    /// Lower-case name, as accepted by the parser and written in reports (`full`, `table`, ...):
    /// its [`Fidelity`]'s.
    pub fn as_str(&self) -> &'static str {
        self.fidelity().as_str()
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.fidelity().fmt(f)
    }
}

/// What `auto` (or an explicit level) found for one level over the envelope.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Assessment {
    /// The level assessed.
    pub level: Level,
    /// The level's advertised bound, when it could be built.
    pub error_bound: Option<f64>,
    /// Whether the bound is within the tolerance.
    pub accepted: bool,
    /// Why not, when it was not (e.g. the table would be too large).
    pub note: String,
}

#[derive(Debug, Clone)]
enum Backend {
    Full,
    Table(Box<StribeckTable>),
    Boundary(Box<BoundaryLevel>),
}

/// One joint at a chosen fidelity: build once per parameter set and envelope, then call
/// [`Evaluator::evaluate`] at every step.
#[derive(Debug, Clone)]
pub struct Evaluator {
    requested: Fidelity,
    tolerance: f64,
    envelope: Envelope,
    backend: Backend,
    solver: WarmSolver,
    error_bound: f64,
    measured: ErrorReport,
    assessments: Vec<Assessment>,
    fallbacks: u64,
}

/// Check a tolerance: a finite number > 0.
pub fn validate_tolerance(tolerance: f64) -> Result<(), FidelityError> {
    if tolerance.is_finite() && tolerance > 0.0 { Ok(()) } else { Err(FidelityError::Tolerance(tolerance)) }
}

impl Evaluator {
    /// Build the level `fidelity` for `params` over `envelope`, with `tolerance` the
    /// largest relative error wanted (in μ, torque and h_c; absolute in the shares).
    ///
    /// * `Full`: nothing to build; the bound is [`FULL_ERROR_BOUND`].
    /// * `Table`: tabulated and refined until its bound is ≤ `tolerance`
    ///   (within [`table::MAX_CELLS`]: the cells a grid of that size does not resolve answer
    ///   with the complete solve, [`FidelityError::TableTooLarge`] if they would be more than
    ///   [`table::MAX_SOLVED_SHARE`] of the cells).
    /// * `Boundary`: built and measured; its bound is reported even when it exceeds
    ///   `tolerance` (the caller asked for this level: see [`Evaluator::within_tolerance`]).
    /// * `Auto`: boundary if its bound is ≤ `tolerance`, else table if it can meet it,
    ///   else full. [`Evaluator::assessments`] says what each candidate measured.
    ///
    /// The envelope is validated for every level (so a caller's flags are checked early),
    /// though `Full` does not use it.
    pub fn new(params: &Params, fidelity: Fidelity, tolerance: f64, envelope: Envelope) -> Result<Self, FidelityError> {
        validate_tolerance(tolerance)?;
        envelope.validate()?;
        Self::with_joint(Joint::new(params)?, fidelity, tolerance, envelope)
    }

    /// As [`Evaluator::new`] for the parameters `joint` was built with, reusing it.
    pub fn with_joint(joint: Joint, fidelity: Fidelity, tolerance: f64, envelope: Envelope) -> Result<Self, FidelityError> {
        validate_tolerance(tolerance)?;
        envelope.validate()?;
        if matches!(fidelity, Fidelity::Table | Fidelity::Auto) && tolerance < FULL_ERROR_BOUND {
            return Err(FidelityError::ToleranceBelowModelAccuracy { value: tolerance, floor: FULL_ERROR_BOUND });
        }
        let mut assessments = Vec::new();
        let full_assessment = || Assessment {
            level: Level::Full,
            error_bound: Some(FULL_ERROR_BOUND),
            accepted: FULL_ERROR_BOUND <= tolerance,
            note: String::new(),
        };
        let mut chosen: Option<(Backend, f64, ErrorReport)> = None;
        if fidelity == Fidelity::Full {
            assessments.push(full_assessment());
            chosen = Some((Backend::Full, FULL_ERROR_BOUND, ErrorReport::default()));
        }
        if matches!(fidelity, Fidelity::Boundary | Fidelity::Auto) {
            let b = BoundaryLevel::build(&joint, &envelope, (0.1 * tolerance).max(FULL_ERROR_BOUND))?;
            let bound = b.error_bound();
            let accepted = bound <= tolerance;
            assessments.push(Assessment {
                level: Level::Boundary,
                error_bound: Some(bound),
                accepted,
                note: if accepted { String::new() } else { format!("measured bound {bound:.3e} exceeds the tolerance") },
            });
            if accepted || fidelity == Fidelity::Boundary {
                chosen = Some((Backend::Boundary(Box::new(b.clone())), bound, *b.measured()));
            }
        }
        if chosen.is_none() && matches!(fidelity, Fidelity::Table | Fidelity::Auto) {
            match StribeckTable::build(&joint, &envelope, tolerance) {
                Ok(t) => {
                    let bound = t.error_bound();
                    assessments.push(Assessment { level: Level::Table, error_bound: Some(bound), accepted: true, note: String::new() });
                    chosen = Some((Backend::Table(Box::new(t.clone())), bound, *t.measured()));
                }
                Err(e @ FidelityError::TableTooLarge { .. }) if fidelity == Fidelity::Auto => {
                    assessments.push(Assessment { level: Level::Table, error_bound: None, accepted: false, note: e.to_string() });
                }
                Err(e) => return Err(e),
            }
        }
        let (backend, error_bound, measured) = match chosen {
            Some(c) => c,
            None => {
                assessments.push(full_assessment());
                (Backend::Full, FULL_ERROR_BOUND, ErrorReport::default())
            }
        };
        Ok(Self {
            requested: fidelity,
            tolerance,
            envelope,
            backend,
            solver: WarmSolver::new(joint),
            error_bound,
            measured,
            assessments,
            fallbacks: 0,
        })
    }

    /// The outputs at `load` (N, > 0) and `omega` (rad/s, finite).
    #[inline]
    pub fn evaluate(&mut self, load: f64, omega: f64) -> Result<Evaluation, FidelityError> {
        // The load is a magnitude (see `Joint::evaluate`).
        let load = load.abs();
        let hit = match &self.backend {
            Backend::Table(t) => t.evaluate(load, omega),
            Backend::Boundary(b) => b.evaluate(load, omega),
            Backend::Full => {
                let op = self.solver.evaluate(load, omega)?;
                return Ok(Evaluation::from_point(&op, Source::Full));
            }
        };
        match hit {
            Some(e) => {
                self.solver.joint().check_film(e.film_thickness, e.fluid_load_fraction, load, omega)?;
                Ok(e)
            }
            None => {
                // Also the path of invalid inputs (NaN fails every comparison): the solver rejects them.
                let op = self.solver.evaluate(load, omega)?;
                if self.solved_inside(load, omega) {
                    return Ok(Evaluation::from_point(&op, Source::Full));
                }
                let mut e = Evaluation::from_point(&op, Source::Fallback);
                e.first_fallback = self.fallbacks == 0;
                self.fallbacks += 1;
                Ok(e)
            }
        }
    }

    /// Whether (load, |ω|) lies in a table cell answered by the complete solve
    /// ([`StribeckTable::solved_cells`]): inside the envelope, not a fallback.
    fn solved_inside(&self, load: f64, omega: f64) -> bool {
        matches!(&self.backend, Backend::Table(t) if t.solved_at(load.abs(), omega))
    }

    /// The table or boundary level's answer when (`load`, `omega`) is inside the envelope (or
    /// `omega` = 0 inside the load range) and its film within [`Joint::max_film_thickness`];
    /// `None` otherwise (also in a table's cells answered by the complete solve) and always
    /// for `full`. Takes `&self`
    /// and keeps no history, so a caller with its own warm-started solve (the rig) can use the
    /// level and do the fallback itself.
    #[inline]
    pub fn evaluate_inside(&self, load: f64, omega: f64) -> Option<Evaluation> {
        let load = load.abs();
        let e = match &self.backend {
            Backend::Table(t) => t.evaluate(load, omega),
            Backend::Boundary(b) => b.evaluate(load, omega),
            Backend::Full => None,
        }?;
        // A film beyond the clearance is the full solve's error to give.
        self.solver.joint().check_film(e.film_thickness, e.fluid_load_fraction, load, omega).ok().map(|()| e)
    }

    /// The torque of [`Evaluator::evaluate_inside`] alone: bit for bit
    /// `evaluate_inside(load, omega).map(|e| e.torque)`, computing only what the torque needs
    /// (for the presliding law's bound, e.g. `pinjoint::batch`). The film is checked against
    /// the clearance only where [`Evaluator::evaluate_inside`] can refuse it: the paper's
    /// model inside a table's envelope (at rest and in the boundary level the fluid carries
    /// nothing, and the complete model's film is never refused).
    #[inline]
    pub fn torque_inside(&self, load: f64, omega: f64) -> Option<f64> {
        self.torque_located(load, omega, self.locate_torque(load, omega))
    }

    /// [`Evaluator::torque_inside`] in two halves, for a caller with many points: locate
    /// (`load` N, `omega` rad/s) now (at the table level its cell, brought into the cache
    /// meanwhile: [`StribeckTable::locate_torque`]; [`Located::OUTSIDE`] at the other levels)
    /// and answer with [`Evaluator::torque_located`] a little later, after locating a few
    /// other points.
    #[inline]
    pub fn locate_torque(&self, load: f64, omega: f64) -> Located {
        match &self.backend {
            Backend::Table(t) if !self.joint().is_paper() => t.locate_torque(load.abs(), omega),
            _ => Located::OUTSIDE,
        }
    }

    /// The answer of [`Evaluator::torque_inside`] at (`load`, `omega`) located by
    /// [`Evaluator::locate_torque`] as `at`, bit for bit.
    #[inline]
    pub fn torque_located(&self, load: f64, omega: f64, at: Located) -> Option<f64> {
        let load = load.abs();
        match &self.backend {
            Backend::Table(t) if !self.joint().is_paper() => t.torque_located(load, omega, at),
            Backend::Table(_) => self.evaluate_inside(load, omega).map(|e| e.torque),
            Backend::Boundary(b) => b.torque(load, omega),
            Backend::Full => None,
        }
    }

    /// As [`Evaluator::evaluate`], completed into every output of the model
    /// ([`Evaluator::operating_point`]).
    pub fn evaluate_point(&mut self, load: f64, omega: f64) -> Result<(OperatingPoint, Source), FidelityError> {
        let e = self.evaluate(load, omega)?;
        Ok((self.operating_point(&e), e.source))
    }

    /// As [`Evaluator::evaluate_point`], but where the full solve answers (the `full` level,
    /// or a fallback outside the envelope) its operating point is returned as computed, not
    /// rebuilt from an [`Evaluation`]: every quantity is computed once. Also says whether
    /// this was the first fallback. Same numbers as [`Evaluator::evaluate_point`].
    pub fn evaluate_complete(&mut self, load: f64, omega: f64) -> Result<(OperatingPoint, Source, bool), FidelityError> {
        let (mut op, derived, source, first) = self.evaluate_deferred(load, omega)?;
        if !derived {
            self.derive(&mut op);
        }
        Ok((op, source, first))
    }

    /// As [`Evaluator::evaluate_complete`], but where a table or the boundary level answers,
    /// the quantities of [`evaluation::DERIVED_COLUMNS`] are left NaN
    /// ([`evaluation::provisional`]) for [`Evaluator::derive`] to fill when a caller reads them
    /// (bit for bit what [`Evaluator::evaluate_complete`] gives). Returns (the operating point,
    /// whether its derived quantities are filled, its source, whether this was the first
    /// fallback).
    pub fn evaluate_deferred(&mut self, load: f64, omega: f64) -> Result<(OperatingPoint, bool, Source, bool), FidelityError> {
        let hit = match &self.backend {
            Backend::Table(t) => t.evaluate(load, omega),
            Backend::Boundary(b) => b.evaluate(load, omega),
            Backend::Full => return Ok((self.solver.evaluate(load, omega)?, true, Source::Full, false)),
        };
        match hit {
            Some(e) => {
                self.solver.joint().check_film(e.film_thickness, e.fluid_load_fraction, load, omega)?;
                Ok((evaluation::provisional(self.solver.joint(), &e), false, e.source, false))
            }
            None => {
                let op = self.solver.evaluate(load, omega)?;
                if self.solved_inside(load, omega) {
                    return Ok((op, true, Source::Full, false));
                }
                let first = self.fallbacks == 0;
                self.fallbacks += 1;
                Ok((op, true, Source::Fallback, first))
            }
        }
    }

    /// Fill the quantities of [`evaluation::DERIVED_COLUMNS`] of an operating point from
    /// [`Evaluator::evaluate_deferred`] ([`evaluation::derive()`]).
    pub fn derive(&self, op: &mut OperatingPoint) {
        evaluation::derive(self.solver.joint(), op);
    }

    /// Complete an evaluation into an [`OperatingPoint`]: Hertz quantities, Roelands
    /// viscosity and Sommerfeld number depend on load and speed only and are computed directly
    /// (equal to the full solve's to rounding).
    pub fn operating_point(&self, e: &Evaluation) -> OperatingPoint {
        evaluation::complete(self.solver.joint(), e)
    }

    /// What the caller asked for.
    pub fn requested(&self) -> Fidelity {
        self.requested
    }
    /// The level in use (what `auto` picked).
    pub fn chosen(&self) -> Level {
        match self.backend {
            Backend::Full => Level::Full,
            Backend::Table(_) => Level::Table,
            Backend::Boundary(_) => Level::Boundary,
        }
    }
    /// The advertised error bound of the level in use inside the envelope: relative in μ,
    /// torque and h_c, absolute in the shares. Outside the envelope the answer is the full
    /// solve's ([`FULL_ERROR_BOUND`]).
    pub fn error_bound(&self) -> f64 {
        self.error_bound
    }
    /// The largest errors measured over the envelope for the level in use (all zero for full).
    pub fn measured(&self) -> &ErrorReport {
        &self.measured
    }
    /// Whether [`Evaluator::error_bound`] is within the tolerance (always for table and
    /// auto; for an explicit boundary level, only if the envelope is deep enough in boundary).
    pub fn within_tolerance(&self) -> bool {
        self.error_bound <= self.tolerance
    }
    /// The tolerance asked for (relative error, dimensionless).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }
    /// The envelope of loads (N) and speeds |ω| (rad/s) the level's bound holds over.
    pub fn envelope(&self) -> &Envelope {
        &self.envelope
    }
    /// Every level considered, in order, with its bound (for auto: why it chose).
    pub fn assessments(&self) -> &[Assessment] {
        &self.assessments
    }
    /// Out-of-envelope evaluations so far (answered by the complete solve).
    pub fn fallbacks(&self) -> u64 {
        self.fallbacks
    }
    /// The table, when the level in use is `table`.
    pub fn table(&self) -> Option<&StribeckTable> {
        match &self.backend {
            Backend::Table(t) => Some(t),
            _ => None,
        }
    }
    /// The model behind the evaluator.
    pub fn joint(&self) -> &Joint {
        self.solver.joint()
    }
    /// The warm start of the full solve (see [`WarmSolver::warm_start`]).
    pub fn warm_start(&self) -> Option<f64> {
        self.solver.warm_start()
    }
    /// Restore a warm start saved by [`Evaluator::warm_start`].
    pub fn set_warm_start(&mut self, logit: Option<f64>) {
        self.solver.set_warm_start(logit);
    }

    /// Move the evaluator to lubricant temperature `temperature` (K): afterwards it answers
    /// bit for bit as an evaluator built by [`Evaluator::new`] with `lubricant.temperature`
    /// = `temperature` (same level, tolerance and envelope). At the full level this costs
    /// [`Joint::at_temperature`] (Roelands' temperature relation and a few logarithms: the
    /// start table and every temperature-independent group are kept); the table and
    /// boundary levels (and what `auto` chose) are built and measured again at the new
    /// temperature ([`Evaluator::new`]'s cost: their error bound is that of the temperature
    /// they answer at), and `auto` may choose another level there. The same temperature
    /// (bit for bit) changes nothing. An invalid temperature (≤ 0 K or outside the
    /// parameter's range, NaN, infinite) is an error naming it, and the evaluator is left
    /// as it was. The warm start and the fallback count are kept.
    pub fn set_temperature(&mut self, temperature: f64) -> Result<(), FidelityError> {
        if temperature.to_bits() == self.joint().params().lubricant.temperature.to_bits() {
            return Ok(());
        }
        let joint = self.joint().at_temperature(temperature)?;
        let warm = self.solver.warm_start();
        if self.requested == Fidelity::Full {
            self.solver = WarmSolver::new(joint);
        } else {
            let fallbacks = self.fallbacks;
            *self = Self::with_joint(joint, self.requested, self.tolerance, self.envelope)?;
            self.fallbacks = fallbacks;
        }
        self.solver.set_warm_start(warm);
        Ok(())
    }

    /// The lubricant temperature (K) the evaluator answers at.
    pub fn temperature(&self) -> f64 {
        self.joint().params().lubricant.temperature
    }

    /// Forget the warm start (e.g. after a jump in the inputs); the answers do not change.
    pub fn reset(&mut self) {
        self.solver.reset();
    }
}

