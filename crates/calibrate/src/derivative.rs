//! Velocity and acceleration from sampled angle: a Savitzky–Golay differentiator.
//!
//! At each sample i a polynomial of degree `d` is fitted by least squares to the 2k+1 samples
//! around it (the window is shifted inward at the record's ends, so it always holds 2k+1
//! samples), and its derivatives at t_i are taken. On a uniform grid this is exactly the
//! Savitzky–Golay filter; the direct least-squares form also handles uneven sampling.
//! A cubic (d = 3) passes any cubic exactly, so the velocity of a sine sampled N times a
//! period has a relative error of order (2π k/N)⁴/…, negligible for k ≪ N, while white angle
//! noise (and quantisation, noise of variance q²/12) is averaged over 2k+1 samples: the
//! velocity noise falls as k^(−3/2).
//!
//! The default half-width is 1/40 of a stroke (the samples between two velocity reversals,
//! estimated from the angle's crossings of its mid-range), at least 3 samples.

use nalgebra::{Matrix4, Vector4};

/// Derivatives at every sample of a local polynomial fit of degree `degree` (1..=3) over ±`k`
/// samples: (first, second) derivative of `y` with respect to `t`. The second derivative is 0
/// for degree 1. `t` must increase strictly and hold at least 2k+1 ≥ degree+1 samples.
pub fn local_poly_derivatives(t: &[f64], y: &[f64], k: usize, degree: usize) -> Vec<(f64, f64)> {
    let n = t.len();
    let m = degree.clamp(1, 3) + 1;
    let w = (2 * k + 1).min(n);
    (0..n)
        .map(|i| {
            let lo = i.saturating_sub(k).min(n - w);
            let (hi, t0) = (lo + w, t[i]);
            let h = ((t[hi - 1] - t0).abs().max((t[lo] - t0).abs())).max(f64::MIN_POSITIVE);
            let mut a = Matrix4::<f64>::zeros();
            let mut b = Vector4::<f64>::zeros();
            for j in lo..hi {
                let tau = (t[j] - t0) / h;
                let mut p = [1.0, tau, tau * tau, tau * tau * tau];
                for v in p.iter_mut().skip(m) {
                    *v = 0.0;
                }
                for r in 0..m {
                    b[r] += p[r] * y[j];
                    for c in 0..m {
                        a[(r, c)] += p[r] * p[c];
                    }
                }
            }
            for r in m..4 {
                a[(r, r)] = 1.0;
            }
            match a.cholesky() {
                Some(ch) => {
                    let c = ch.solve(&b);
                    (c[1] / h, if m > 2 { 2.0 * c[2] / (h * h) } else { 0.0 })
                }
                None => (0.0, 0.0),
            }
        })
        .collect()
}

/// The number of strokes (motions between reversals) in an angle record: crossings of the
/// mid-range level with a hysteresis of ±25 % of the range, plus one.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(a > b)` also catches NaN; kept as written
pub fn stroke_count(angle: &[f64]) -> usize {
    let (lo, hi) = angle.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| (l.min(x), h.max(x)));
    if !(hi > lo) {
        return 1;
    }
    let (mid, band) = (0.5 * (lo + hi), 0.25 * (hi - lo));
    let mut state = 0i8;
    let mut crossings = 0usize;
    for &a in angle {
        let s = if a > mid + band { 1 } else if a < mid - band { -1 } else { 0 };
        if s != 0 && s != state {
            if state != 0 {
                crossings += 1;
            }
            state = s;
        }
    }
    crossings + 1
}

/// The default half-width: 1/40 of the samples of a stroke, at least 3.
pub fn default_half_width(samples: usize, strokes: usize) -> usize {
    (samples / (40 * strokes.max(1))).max(3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_is_differentiated_exactly_on_uneven_samples() {
        let t: Vec<f64> = (0..60).map(|i| f64::from(i) * 0.01 + 0.003 * f64::from(i * 7 % 5)).collect();
        let f = |x: f64| 1.0 - 2.0 * x + 0.5 * x * x + 3.0 * x * x * x;
        let y: Vec<f64> = t.iter().map(|&x| f(x)).collect();
        for (i, (d1, d2)) in local_poly_derivatives(&t, &y, 5, 3).into_iter().enumerate() {
            let x = t[i];
            assert!((d1 - (-2.0 + x + 9.0 * x * x)).abs() < 1e-9, "{i}: {d1}");
            assert!((d2 - (1.0 + 18.0 * x)).abs() < 1e-7, "{i}: {d2}");
        }
    }

    #[test]
    fn sine_velocity_and_noise_reduction() {
        let n = 1000;
        let t: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
        let w = std::f64::consts::TAU;
        let y: Vec<f64> = t.iter().map(|&x| (w * x).sin()).collect();
        let d = local_poly_derivatives(&t, &y, 12, 3);
        for i in 0..n {
            assert!((d[i].0 - w * (w * t[i]).cos()).abs() < 1e-5 * w, "{i}");
        }
        // Quantised angle: the velocity error is far below the quantum / dt.
        let q = 1e-4;
        let yq: Vec<f64> = y.iter().map(|v| (v / q).round() * q).collect();
        let dq = local_poly_derivatives(&t, &yq, 12, 3);
        let err = (0..n).map(|i| (dq[i].0 - d[i].0).abs()).fold(0.0, f64::max);
        assert!(err < 0.1 * q / 1e-3, "{err}");
    }

    #[test]
    fn strokes_of_a_sine() {
        let a: Vec<f64> = (0..3000).map(|i| (f64::from(i) / 1000.0 * std::f64::consts::TAU).sin()).collect();
        // 3 periods from the zero: crossings of the mid level at each half period: 5 inside, 6 strokes.
        assert_eq!(stroke_count(&a), 6);
    }
}
