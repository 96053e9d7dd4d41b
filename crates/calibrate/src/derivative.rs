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

/// The matched filter of the second derivative: taps (m = −k..=k, sum 1) with which the cubic
/// Savitzky–Golay second derivative over ±`k` samples of a uniform grid is a weighted mean of
/// the true second derivative. If w_j are the filter's weights on the angle (Σ w_j = Σ w_j·j = 0,
/// Σ w_j·j²/2 = 1/Δt²), then w = v ∗ [1, −2, 1]/Δt² with v_m zero beyond |m| = k − 1, so
/// α_SG(i) = Σ_m v_m·Δ²θ(i+m)/Δt²; and the second difference Δ²θ/Δt² is α averaged over ±Δt
/// with a triangle, which the taps [1/12, 5/6, 1/12] reproduce to fourth order
/// (α + α''·Δt²/12 + O(Δt⁴)). The taps are v ∗ [1/12, 5/6, 1/12].
///
/// Filtering the recorded torque and the model's other terms with these taps keeps
/// T = J·α + friction + T_0 exact for J whatever the differentiator does to α: fast servo
/// ringing that it smooths away is smoothed the same way in the torque, so it does not bias J
/// (the quasi-static fit uses this when J is fitted, [`crate::fit`]). For k = 1 the taps are
/// [1/12, 5/6, 1/12].
pub fn matched_taps(k: usize) -> Vec<f64> {
    let k = k.max(1);
    // The second-derivative weights of the cubic (the even part: the quadratic) over j = −k..=k.
    let kf = k as f64;
    let j2: Vec<f64> = (-(k as i64)..=k as i64).map(|j| (j * j) as f64).collect();
    let n = 2.0 * kf + 1.0;
    let (s2, s4) = (j2.iter().sum::<f64>(), j2.iter().map(|x| x * x).sum::<f64>());
    // Least squares of c0 + c2·j² over the window: c2 = Σ (j² − s2/n)·y / (s4 − s2²/n).
    let den = s4 - s2 * s2 / n;
    let w: Vec<f64> = j2.iter().map(|x| 2.0 * (x - s2 / n) / den).collect();
    // w_j = v_{j−1} − 2 v_j + v_{j+1}, v zero outside −(k−1)..=k−1: forward recurrence.
    let mut v = vec![0.0; 2 * k + 3]; // index m + k + 1, m = −k−1..=k+1
    for j in -(k as i64)..k as i64 {
        let at = |m: i64| (m + k as i64 + 1) as usize;
        v[at(j + 1)] = w[(j + k as i64) as usize] + 2.0 * v[at(j)] - v[at(j - 1)];
    }
    // v at m = −k..=k is v[1..2k+2] (its ends zero); convolved with the triangle's taps.
    let (a, b) = (1.0 / 12.0, 5.0 / 6.0);
    (1..2 * k + 2).map(|i| a * v[i - 1] + b * v[i] + a * v[i + 1]).collect()
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
    fn matched_taps_turn_the_true_acceleration_into_the_differentiators() {
        // A signal with a slow sine and a fast ringing the window smooths: the differentiator's
        // α at interior samples equals the taps' mean of the exact α (to the triangle's O(Δt²)).
        let dt = 1e-3;
        let t: Vec<f64> = (0..600).map(|i| f64::from(i) * dt).collect();
        let (w1, w2) = (std::f64::consts::TAU, std::f64::consts::TAU * 40.0);
        let y: Vec<f64> = t.iter().map(|&x| (w1 * x).sin() + 0.01 * (w2 * x).sin()).collect();
        let a: Vec<f64> = t.iter().map(|&x| -w1 * w1 * (w1 * x).sin() - 0.01 * w2 * w2 * (w2 * x).sin()).collect();
        for (x, y) in matched_taps(1).iter().zip([1.0 / 12.0, 5.0 / 6.0, 1.0 / 12.0]) {
            assert!((x - y).abs() < 1e-15, "{x} {y}");
        }
        for k in [2usize, 4, 12] {
            let v = matched_taps(k);
            assert_eq!(v.len(), 2 * k + 1);
            assert!((v.iter().sum::<f64>() - 1.0).abs() < 1e-12);
            let d = local_poly_derivatives(&t, &y, k, 3);
            let h = k;
            let mut worst = 0.0f64;
            for i in k + 1..t.len() - k - 1 {
                let mean: f64 = (0..v.len()).map(|m| v[m] * a[i + m - h]).sum();
                worst = worst.max((d[i].1 - mean).abs());
            }
            // The ringing's α is 0.01·w2² = 632 rad/s²; the triangle alone would miss (w2·dt)²/12
            // = 5.3e-3 of it, its taps leave the fourth order, (w2·dt)⁴/360 = 1.1e-5.
            let ring = 0.01 * w2 * w2;
            assert!(worst < 2e-5 * ring, "k {k}: {worst}");
            if k == 12 {
                // ... while the differentiator alone misses most of the ringing.
                let raw = (k + 1..t.len() - k - 1).map(|i| (d[i].1 - a[i]).abs()).fold(0.0, f64::max);
                assert!(raw > 0.3 * ring, "{raw}");
            }
        }
    }

    #[test]
    fn strokes_of_a_sine() {
        let a: Vec<f64> = (0..3000).map(|i| (f64::from(i) / 1000.0 * std::f64::consts::TAU).sin()).collect();
        // 3 periods from the zero: crossings of the mid level at each half period: 5 inside, 6 strokes.
        assert_eq!(stroke_count(&a), 6);
    }
}
