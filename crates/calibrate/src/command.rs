//! The command that drove a recorded stroke, for the rig fit ([`crate::rig_fit`]).
//!
//! The rig (`pinjoint::rig`) follows a sine command θ_cmd = c + a·sin(2πfτ) + b·cos(2πfτ)
//! (τ: time since the record's first sample) through its position loop, lagging it by about
//! T/K_p. A record holds the angle, not the command, so:
//! 1. f, c, a, b are fitted to the recorded angle: (c, a, b) by linear least squares at a
//!    given f, f by a golden-section search of that fit's residual around the estimate from the
//!    angle's crossings of its mid-range ([`fit_sine`]);
//! 2. the lag is then taken out by simulation: the rig is run on the command, the same sine
//!    (f free, within ±1 %) is fitted to the simulated and to the recorded angle after the
//!    start-up, and the command's (c, a, b, f) are moved by the difference; repeated until the
//!    move is below [`COMMAND_TOLERANCE`] ([`crate::rig_fit`] does this).

use nalgebra::{Matrix3, Vector3};
use std::f64::consts::TAU;

/// The command's (c, a, b) are refined until they move by less than this (rad), and f until
/// f·(record duration) moves by less than this (cycles).
pub const COMMAND_TOLERANCE: f64 = 1e-7;

/// θ_cmd(τ) = `offset` + `sin`·sin(2π f τ) + `cos`·cos(2π f τ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Command {
    /// c (rad).
    pub offset: f64,
    /// a (rad).
    pub sin: f64,
    /// b (rad).
    pub cos: f64,
    /// f (Hz).
    pub frequency: f64,
}

impl Command {
    /// Command angle (rad) and rate (rad/s) at τ (s).
    pub fn at(&self, tau: f64) -> (f64, f64) {
        let w = TAU * self.frequency;
        let (s, c) = (w * tau).sin_cos();
        (self.offset + self.sin * s + self.cos * c, w * (self.sin * c - self.cos * s))
    }
    /// Amplitude √(a² + b²) (rad).
    pub fn amplitude(&self) -> f64 {
        self.sin.hypot(self.cos)
    }
}

/// (c, a, b) by least squares at frequency `f` over the samples with `keep` true, and the
/// residual sum of squares; None if singular.
pub fn sine_at(tau: &[f64], angle: &[f64], keep: &[bool], f: f64) -> Option<(Command, f64)> {
    let w = TAU * f;
    let (mut m, mut v) = (Matrix3::<f64>::zeros(), Vector3::<f64>::zeros());
    for i in (0..tau.len()).filter(|&i| keep[i]) {
        let (s, c) = (w * tau[i]).sin_cos();
        let x = Vector3::new(1.0, s, c);
        m += x * x.transpose();
        v += x * angle[i];
    }
    let p = m.cholesky()?.solve(&v);
    let cmd = Command { offset: p[0], sin: p[1], cos: p[2], frequency: f };
    let rss = (0..tau.len()).filter(|&i| keep[i]).map(|i| (angle[i] - cmd.at(tau[i]).0).powi(2)).sum();
    Some((cmd, rss))
}

/// The first estimate of the frequency: mid-range crossings (hysteresis ±25 % of the range)
/// are half a period apart. None with fewer than three crossings (less than a cycle).
pub fn crossing_frequency(tau: &[f64], angle: &[f64]) -> Option<f64> {
    let (lo, hi) = angle.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| (l.min(x), h.max(x)));
    let (mid, band) = (0.5 * (lo + hi), 0.25 * (hi - lo));
    let mut state = 0i8;
    let mut crossings = Vec::new();
    for (i, &a) in angle.iter().enumerate() {
        let s = if a > mid + band { 1 } else if a < mid - band { -1 } else { 0 };
        if s != 0 && s != state {
            if state != 0 {
                crossings.push(tau[i]);
            }
            state = s;
        }
    }
    let k = crossings.len();
    (k >= 3).then(|| (k - 1) as f64 / (2.0 * (crossings[k - 1] - crossings[0])))
}

/// The sine fitted to the whole recorded angle (step 1 of the module documentation).
pub fn fit_sine(tau: &[f64], angle: &[f64]) -> Option<Command> {
    let f0 = crossing_frequency(tau, angle)?;
    // The crossing estimate is within a few % of f.
    fit_sine_near(tau, angle, &vec![true; tau.len()], f0, 0.2)
}

/// The sine fitted to the samples with `keep`, its frequency searched (golden section on the
/// residual of [`sine_at`]) within a factor 1 ± `bracket` of `f0`.
pub fn fit_sine_near(tau: &[f64], angle: &[f64], keep: &[bool], f0: f64, bracket: f64) -> Option<Command> {
    let rss = |f: f64| sine_at(tau, angle, keep, f).map_or(f64::INFINITY, |x| x.1);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (f0 * (1.0 - bracket), f0 * (1.0 + bracket));
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let (mut f1, mut f2) = (rss(x1), rss(x2));
    while b - a > 1e-12 * f0 {
        if f1 <= f2 {
            (b, x2, f2) = (x2, x1, f1);
            x1 = b - g * (b - a);
            f1 = rss(x1);
        } else {
            (a, x1, f1) = (x1, x2, f2);
            x2 = a + g * (b - a);
            f2 = rss(x2);
        }
    }
    sine_at(tau, angle, keep, 0.5 * (a + b)).map(|x| x.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_a_sampled_sine() {
        let cmd = Command { offset: 0.01, sin: 0.6, cos: -0.05, frequency: 0.7 };
        let tau: Vec<f64> = (0..5000).map(|i| f64::from(i) * 1e-3).collect();
        let q = 4.8e-5; // quantised like a 17-bit encoder
        let angle: Vec<f64> = tau.iter().map(|&t| (cmd.at(t).0 / q).round() * q).collect();
        let f = fit_sine(&tau, &angle).unwrap();
        assert!((f.frequency / 0.7 - 1.0).abs() < 1e-6, "{f:?}");
        // Quantisation errors of 4.8e-5 rad average to a few 1e-7 rad over 5000 samples.
        for (x, y) in [(f.offset, 0.01), (f.sin, 0.6), (f.cos, -0.05)] {
            assert!((x - y).abs() < 5e-6, "{f:?}");
        }
        // The rate is the derivative of the angle.
        let h = 1e-6;
        let d = (cmd.at(1.0 + h).0 - cmd.at(1.0 - h).0) / (2.0 * h);
        assert!((d - cmd.at(1.0).1).abs() < 1e-8);
    }

    #[test]
    fn less_than_a_cycle_has_no_frequency() {
        let tau: Vec<f64> = (0..500).map(|i| f64::from(i) * 1e-3).collect();
        let angle: Vec<f64> = tau.iter().map(|&t| (TAU * t).sin()).collect();
        assert!(fit_sine(&tau, &angle).is_none());
    }
}
