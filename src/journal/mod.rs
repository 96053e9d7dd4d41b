//! TEMPORARY ADAPTER (branch `complete`): the agreed API of the finite journal bearing, with
//! the short-bearing (Ocvirk) closed forms in place of the Reynolds solution. Replaced by the
//! `journal` branch's module at merge; nothing here is meant to land.

use std::sync::Arc;
use thiserror::Error;

/// A journal table could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum JournalError {
    /// L/D not a finite positive number.
    #[error("geometry: bush length over pin diameter L/D = {0} is invalid")]
    LengthRatio(f64),
}

/// The journal bearing of one L/D, tabulated over ε.
#[derive(Debug, Clone)]
pub struct JournalTable {
    d_over_l_sq: f64,
}

impl JournalTable {
    /// The process-wide table of `l_over_d`.
    pub fn shared(l_over_d: f64) -> Result<Arc<Self>, JournalError> {
        if !(l_over_d.is_finite() && l_over_d > 0.0) {
            return Err(JournalError::LengthRatio(l_over_d));
        }
        Ok(Arc::new(Self { d_over_l_sq: (1.0 / l_over_d).powi(2) }))
    }

    fn ln_s(&self, e: f64) -> f64 {
        let pi = std::f64::consts::PI;
        (self.d_over_l_sq * (1.0 - e * e).powi(2) / (pi * e * (pi * pi * (1.0 - e * e) + 16.0 * e * e).sqrt())).ln()
    }

    /// ε(S) and dε/d ln S at ln S.
    pub fn eccentricity(&self, ln_s: f64) -> (f64, f64) {
        if ln_s == f64::INFINITY {
            return (0.0, 0.0);
        }
        if ln_s == f64::NEG_INFINITY {
            return (1.0, 0.0);
        }
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        for _ in 0..80 {
            let m = 0.5 * (lo + hi);
            if self.ln_s(m) > ln_s { lo = m } else { hi = m }
        }
        let e = 0.5 * (lo + hi);
        let d = 1e-7 * e.min(1.0 - e).max(1e-300);
        let slope = (2.0 * d) / (self.ln_s(e + d) - self.ln_s(e - d));
        (e, if slope.is_finite() { slope } else { 0.0 })
    }

    /// Attitude angle φ(ε), rad.
    pub fn attitude_angle(&self, e: f64) -> f64 {
        (std::f64::consts::PI * (1.0 - e * e).sqrt()).atan2(4.0 * e)
    }

    /// Friction variable (R/c)f at ε.
    pub fn friction_variable(&self, e: f64) -> f64 {
        let pi = std::f64::consts::PI;
        2.0 * pi * pi * self.ln_s(e).exp() / (1.0 - e * e).sqrt() + 0.5 * e * self.attitude_angle(e).sin()
    }
}
