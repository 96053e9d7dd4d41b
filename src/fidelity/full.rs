//! The `full` level: the complete solve at every call, warm-started from the previous one.

use crate::joint::{Joint, LoadTerms, ModelError, OperatingPoint};

/// Accuracy of the complete solve itself, relative in μ and h_c: the bracket test of
/// `tests/solver.rs` (the root is bracketed to ±1e-11 in the logit and μ, h_c move by
/// less than 1e-10 inside that bracket). No level can be verified below it.
pub const FULL_ERROR_BOUND: f64 = 1e-10;

/// The complete solve, warm-started from the last solution's logit.
///
/// The warm start changes only the iteration count, not the answer (same root to the
/// solver's step tolerance, ~1e-12); a rest point (logit −∞) leaves the next call cold.
/// The terms that depend on the load alone (Hertz, Roelands, Bair–Winer, the asperity
/// model's load ratio: [`Joint::load_terms`]) are kept from the last call and computed again
/// only when the load changes (bit for bit: the same function of the same load; a new
/// temperature is a new solver, [`crate::fidelity::Evaluator::set_temperature`]).
#[derive(Debug, Clone)]
pub struct WarmSolver {
    joint: Joint,
    last: Option<f64>,
    terms: Option<LoadTerms>,
}

impl WarmSolver {
    /// A solver of `joint` whose first call starts cold.
    pub fn new(joint: Joint) -> Self {
        Self { joint, last: None, terms: None }
    }

    /// The complete operating point at `load` (N) and `omega` (rad/s).
    #[inline]
    pub fn evaluate(&mut self, load: f64, omega: f64) -> Result<OperatingPoint, ModelError> {
        let magnitude = load.abs();
        let cached = self.terms.as_ref().is_some_and(|t| t.load.to_bits() == magnitude.to_bits());
        if !cached {
            if !(magnitude.is_finite() && magnitude > 0.0 && omega.is_finite()) {
                // The joint's own checks and errors, in its order.
                return self.joint.evaluate_from(load, omega, self.last);
            }
            self.terms = Some(self.joint.load_terms(magnitude)?);
        }
        let lt = self.terms.as_ref().expect("set above");
        let op = self.joint.evaluate_from_terms(lt, omega, self.last)?;
        self.last = op.logit.is_finite().then_some(op.logit);
        Ok(op)
    }

    /// The logit the next call starts from (None: cold). With [`WarmSolver::set_warm_start`]
    /// a caller can save and restore it, so a restored run repeats bit for bit.
    pub fn warm_start(&self) -> Option<f64> {
        self.last
    }

    /// Start the next call from `logit` (None or non-finite: cold).
    pub fn set_warm_start(&mut self, logit: Option<f64>) {
        self.last = logit.filter(|l| l.is_finite());
    }

    /// Forget the previous solution (the next call starts cold).
    pub fn reset(&mut self) {
        self.last = None;
    }

    /// The joint it evaluates.
    pub fn joint(&self) -> &Joint {
        &self.joint
    }
}
