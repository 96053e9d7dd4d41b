//! The operating envelope a scene declares: the load and speed-magnitude ranges it visits.

use super::error::FidelityError;
use crate::joint::{Joint, ModelError, OperatingPoint};

/// The complete solve at a point of an envelope being tabulated or checked; a point without a
/// model answer becomes [`FidelityError::Envelope`] naming it (the builders never panic).
pub(crate) fn solve_at(joint: &Joint, load: f64, omega: f64, guess: Option<f64>) -> Result<OperatingPoint, FidelityError> {
    let r: Result<OperatingPoint, ModelError> = joint.evaluate_from(load, omega, guess);
    r.map_err(|source| FidelityError::Envelope { load: load.into(), speed: omega.into(), source })
}
use serde::{Deserialize, Serialize};

/// The load range (N) and speed-magnitude range (|ω|, rad/s) a scene will visit.
///
/// Both ranges are closed and strictly positive: the table levels are built in
/// (ln P, ln |ω|), and ω = 0 (rest) is handled separately and exactly, so the speed
/// range is that of the *moving* joint. The model depends on |ω| only, so one range
/// covers both directions of motion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Envelope {
    /// Smallest load, N (> 0).
    pub load_min: f64,
    /// Largest load, N (> load_min).
    pub load_max: f64,
    /// Smallest speed magnitude |ω|, rad/s (> 0).
    pub speed_min: f64,
    /// Largest speed magnitude |ω|, rad/s (> speed_min).
    pub speed_max: f64,
}

impl Envelope {
    /// The default envelope of the library's batch ([`crate::batch::Settings::default`]) and of
    /// the Python package's table, boundary and auto levels for the complete model (the paper's
    /// model: [`Envelope::PAPER_RIG`], [`Envelope::default_for`]): loads 1–100 kN (light loads to
    /// beyond the paper's 60 kN, up to the paper's joint's load edge of 96.7 kN where the
    /// Hertz half-width reaches the pin's radius), speed magnitudes 0.01–100 rad/s (the rig's
    /// strokes peak at 4.4 rad/s); the table level also covers the speeds below, down to rest.
    /// A scene of held, creeping, reversing or sliding joints anywhere in it is answered by the
    /// table. Its table at the paper's joint: about 150 × 235 cells, 13 MiB, built in 0.2 s
    /// (one core) at 20–120 °C; 25 × 78 cells at −54 °C. The PinJoint FMU keeps its own
    /// default parameters (5–60 kN, 0.01–10 rad/s: a live temperature input rebuilds the table
    /// at each new temperature there, so it is kept small).
    pub const SERVICE: Envelope = Envelope { load_min: 1e3, load_max: 1e5, speed_min: 0.01, speed_max: 100.0 };

    /// The paper's rig region, 5–60 kN and 0.01–10 rad/s: the default envelope for the paper's
    /// model (`model.paper`), whose line-contact film passes the clearance at light loads and
    /// high speeds (at 1 kN and 26 rad/s already), where a table over [`Envelope::SERVICE`]
    /// could not be built; the PinJoint FMU's default envelope parameters.
    pub const PAPER_RIG: Envelope = Envelope { load_min: 5e3, load_max: 60e3, speed_min: 0.01, speed_max: 10.0 };

    /// The default envelope of a joint with `params`: [`Envelope::SERVICE`] for the complete
    /// model, [`Envelope::PAPER_RIG`] for the paper's.
    pub fn default_for(params: &crate::Params) -> Envelope {
        if params.model.paper { Envelope::PAPER_RIG } else { Envelope::SERVICE }
    }

    /// The default envelope of a batch of parameter sets: [`Envelope::PAPER_RIG`] if any is the
    /// paper's model (one envelope serves the batch), else [`Envelope::SERVICE`].
    pub fn default_for_all<'a>(params: impl IntoIterator<Item = &'a crate::Params>) -> Envelope {
        if params.into_iter().any(|p| p.model.paper) { Envelope::PAPER_RIG } else { Envelope::SERVICE }
    }

    /// A validated envelope: loads in N, speed magnitudes in rad/s.
    pub fn new(load_min: f64, load_max: f64, speed_min: f64, speed_max: f64) -> Result<Self, FidelityError> {
        let e = Self { load_min, load_max, speed_min, speed_max };
        e.validate()?;
        Ok(e)
    }

    /// Check every bound: finite, > 0, min < max. Errors name the quantity, value and unit.
    pub fn validate(&self) -> Result<(), FidelityError> {
        for (quantity, unit, min, max) in
            [("load", "N", self.load_min, self.load_max), ("speed magnitude |omega|", "rad/s", self.speed_min, self.speed_max)]
        {
            for (end, value) in [("minimum", min), ("maximum", max)] {
                if !(value.is_finite() && value > 0.0) {
                    return Err(FidelityError::EnvelopeBound { quantity, end, value, unit });
                }
            }
            if min >= max {
                return Err(FidelityError::EnvelopeOrder { quantity, min, max, unit });
            }
        }
        Ok(())
    }

    /// Whether `load` (N) and |`omega`| (rad/s) are inside the envelope (ends included).
    #[inline]
    pub fn contains(&self, load: f64, omega: f64) -> bool {
        let w = omega.abs();
        load >= self.load_min && load <= self.load_max && w >= self.speed_min && w <= self.speed_max
    }

    /// Whether `load` (N) is inside the load range (ends included).
    #[inline]
    pub fn contains_load(&self, load: f64) -> bool {
        load >= self.load_min && load <= self.load_max
    }

    /// The point at fractions (a, b) ∈ [0, 1]² of the envelope in (ln P, ln |ω|).
    pub fn at_log_fraction(&self, a: f64, b: f64) -> (f64, f64) {
        (lerp_log(self.load_min, self.load_max, a), lerp_log(self.speed_min, self.speed_max, b))
    }
}

/// The point at fraction `a` of [lo, hi] in logarithmic coordinates, ends exact.
pub(crate) fn lerp_log(lo: f64, hi: f64, a: f64) -> f64 {
    if a <= 0.0 {
        lo
    } else if a >= 1.0 {
        hi
    } else {
        (lo.ln() + a * (hi.ln() - lo.ln())).exp().clamp(lo, hi)
    }
}

#[cfg(test)]
mod tests {

    /// The paper's model takes its rig region (its film passes the clearance at light loads
    /// and high speeds, so no table could be built over the service envelope); the complete
    /// model the service envelope; both valid and nested.
    #[test]
    fn default_envelopes_follow_the_model() {
        use crate::fidelity::{Evaluator, Fidelity};
        use crate::Params;
        let (s, p) = (Envelope::SERVICE, Envelope::PAPER_RIG);
        assert!(s.validate().is_ok() && p.validate().is_ok());
        assert!(s.load_min <= p.load_min && p.load_max <= s.load_max && s.speed_min <= p.speed_min && p.speed_max <= s.speed_max);
        assert_eq!(Envelope::default_for(&Params::default()), s);
        assert_eq!(Envelope::default_for(&Params::paper()), p);
        assert_eq!(Envelope::default_for_all([&Params::default(), &Params::paper()]), p);
        assert_eq!(Envelope::default_for_all([&Params::default()]), s);
        assert!(Evaluator::new(&Params::paper(), Fidelity::Table, 1e-4, Envelope::default_for(&Params::paper())).is_ok());
        // Why: over the service envelope the paper's model has no answer at its light, fast corner.
        assert!(Evaluator::new(&Params::paper(), Fidelity::Table, 1e-4, s).is_err());
    }
    use super::*;

    #[test]
    fn validation_names_quantity_value_and_unit() {
        assert!(Envelope::new(5e3, 60e3, 0.01, 10.0).is_ok());
        let e = Envelope::new(60e3, 5e3, 0.01, 10.0).unwrap_err().to_string();
        assert!(e.contains("load") && e.contains("60000") && e.contains(" N"), "{e}");
        let e = Envelope::new(5e3, 60e3, 0.0, 10.0).unwrap_err().to_string();
        assert!(e.contains("speed") && e.contains("minimum = 0") && e.contains("rad/s"), "{e}");
        let e = Envelope::new(5e3, f64::NAN, 0.01, 10.0).unwrap_err().to_string();
        assert!(e.contains("load maximum = NaN N"), "{e}");
        assert!(Envelope::new(-1.0, 60e3, 0.01, 10.0).is_err());
        assert!(Envelope::new(5e3, 60e3, 1.0, 1.0).is_err());
        assert!(Envelope::new(5e3, 60e3, 1.0, f64::INFINITY).is_err());
    }

    #[test]
    fn contains_uses_the_speed_magnitude_and_includes_the_ends() {
        let e = Envelope::new(5e3, 60e3, 0.01, 10.0).unwrap();
        assert!(e.contains(5e3, -10.0) && e.contains(60e3, 0.01));
        assert!(!e.contains(4999.0, 1.0) && !e.contains(20e3, 0.0) && !e.contains(20e3, -10.5));
        let (p, w) = e.at_log_fraction(1.0, 0.0);
        assert_eq!((p, w), (60e3, 0.01));
        let (p, _) = e.at_log_fraction(0.5, 0.5);
        assert!((p - (5e3f64 * 60e3).sqrt()).abs() < 1e-6);
    }
}
