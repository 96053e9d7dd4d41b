//! Measuring a level against the complete solve: the error report and the check points.

use super::evaluation::Evaluation;
use crate::joint::OperatingPoint;
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use rand_xoshiro::SplitMix64;
use serde::Serialize;

/// Largest errors of a level measured against the complete solve on a set of check points.
///
/// Relative errors for μ, torque and h_c (`|approx − full|/|full|`); the load shares are
/// fractions in [0, 1] and their error is absolute (`|Δ(1/γ1)| = |Δ(1/γ2)|`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ErrorReport {
    /// max |Δμ|/μ.
    pub friction_coefficient: f64,
    /// max |ΔT|/T.
    pub torque: f64,
    /// max |Δh_c|/h_c.
    pub film_thickness: f64,
    /// max |Δ(1/γ1)| (absolute).
    pub load_fraction: f64,
    /// Number of check points.
    pub points: usize,
    /// Load (N) of the point with the largest error.
    pub worst_load: f64,
    /// Speed (rad/s) of the point with the largest error.
    pub worst_speed: f64,
}

#[inline]
fn rel(a: f64, b: f64) -> f64 {
    if a == b { 0.0 } else { ((a - b) / b).abs() }
}

impl ErrorReport {
    /// The largest of the four errors.
    pub fn max(&self) -> f64 {
        self.friction_coefficient.max(self.torque).max(self.film_thickness).max(self.load_fraction)
    }

    /// The errors of `e` against the complete solve `r` at the same point (its largest one).
    pub fn point_error(e: &Evaluation, r: &OperatingPoint) -> [f64; 4] {
        [
            rel(e.friction_coefficient, r.friction_coefficient),
            rel(e.torque, r.torque),
            rel(e.film_thickness, r.film_thickness),
            (e.fluid_load_fraction - r.fluid_load_fraction).abs().max((e.asperity_load_fraction - r.asperity_load_fraction).abs()),
        ]
    }

    /// Add one check point; returns its largest error.
    pub fn add(&mut self, e: &Evaluation, r: &OperatingPoint) -> f64 {
        let p = Self::point_error(e, r);
        let m = p.iter().fold(0.0f64, |a, &b| a.max(b));
        // NaN anywhere must count as a failure.
        let m = if p.iter().any(|v| v.is_nan()) { f64::INFINITY } else { m };
        if m > self.max() || self.points == 0 {
            self.worst_load = r.load;
            self.worst_speed = r.angular_velocity;
        }
        self.friction_coefficient = self.friction_coefficient.max(p[0]);
        self.torque = self.torque.max(p[1]);
        self.film_thickness = self.film_thickness.max(p[2]);
        self.load_fraction = self.load_fraction.max(if p[3].is_nan() { f64::INFINITY } else { p[3] });
        if m.is_infinite() {
            self.friction_coefficient = f64::INFINITY;
        }
        self.points += 1;
        m
    }

    /// The union of two reports.
    pub fn merge(&mut self, o: &ErrorReport) {
        if o.max() > self.max() {
            self.worst_load = o.worst_load;
            self.worst_speed = o.worst_speed;
        }
        self.friction_coefficient = self.friction_coefficient.max(o.friction_coefficient);
        self.torque = self.torque.max(o.torque);
        self.film_thickness = self.film_thickness.max(o.film_thickness);
        self.load_fraction = self.load_fraction.max(o.load_fraction);
        self.points += o.points;
    }
}

/// SplitMix64 ([`rand_xoshiro::SplitMix64`]): a small deterministic generator for check points.
#[derive(Debug, Clone)]
pub struct CheckRng(SplitMix64);

impl CheckRng {
    /// A generator started from `seed` (the same seed repeats the same sequence).
    pub fn new(seed: u64) -> Self {
        Self(SplitMix64::seed_from_u64(seed))
    }
    /// The next 64 random bits (SplitMix64).
    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }
    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_points_follow_the_splitmix64_reference() {
        // The first outputs of Vigna's splitmix64.c from this state (the reference values
        // rand_xoshiro tests against).
        let mut r = CheckRng::new(1_477_776_061_723_855_037);
        assert_eq!([r.next_u64(), r.next_u64(), r.next_u64()], [1_985_237_415_132_408_290, 2_979_275_885_539_914_483, 13_511_426_838_097_143_398]);
        let u = CheckRng::new(7).uniform();
        assert!((0.0..1.0).contains(&u));
    }
}
