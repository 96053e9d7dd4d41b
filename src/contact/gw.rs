//! The Greenwood–Williamson statistical function of eq. 16 for Gaussian summit heights,
//!
//! `F_{3/2}(t) = (2π)^(-1/2) ∫_t^∞ (s − t)^{3/2} e^{−s²/2} ds`,
//!
//! evaluated in logarithms so that the full-film limit (t of hundreds, F far below
//! the smallest f64) stays finite.
//!
//! Write `F(t) = (2π)^(-1/2) e^{−t²/2} G(t)` with `G(t) = ∫_0^∞ s^{3/2} e^{−s t − s²/2} ds`.
//! With `s = w²`, `G(t) = ∫_{−∞}^{∞} w⁴ e^{−t w² − w⁴/2} dw`: an entire, even, rapidly
//! decaying integrand, for which the trapezoidal rule converges geometrically. That
//! is the reference path ([`ln_g_reference`]). The fast path ([`ln_f32`]) is a
//! piecewise Chebyshev interpolant of `ln G` on [`T_LO`, `T_HI`] built once from the
//! reference path, and asymptotic series outside that interval:
//! - t > T_HI: `G(t) ~ Σ_k (−1/2)^k/k! · Γ(5/2+2k) · t^{−5/2−2k}` (Watson's lemma);
//! - t < T_LO: `F(t) ~ |t|^{3/2} Σ_k C(3/2, 2k)·(2k−1)!!·t^{−2k}` (moments of the
//!   normal distribution; the neglected tail is below e^{−t²/2} ≈ 1e−22).
//!
//! The polynomial fits of the literature are poor past t ≈ 2.5 (docs/model.md) and are
//! not used. Accuracy of the fast path against the reference: see the tests (≤ 2e-14
//! relative in F over [−12, 40]).

use crate::numerics::newton::newton_increasing;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Lower end of the Chebyshev-interpolated interval.
pub const T_LO: f64 = -10.0;
/// Upper end of the Chebyshev-interpolated interval.
pub const T_HI: f64 = 12.0;
/// Width of one Chebyshev panel.
const PANEL: f64 = 0.5;
/// Chebyshev nodes (= polynomial degree + 1) per panel.
const NODES: usize = 12;
const PANELS: usize = ((T_HI - T_LO) / PANEL) as usize;

/// ln Γ(5/2) = ln(3√π/4).
const LN_GAMMA_5_2: f64 = 0.284_682_870_472_919_2;
/// ½ ln(2π).
const HALF_LN_2PI: f64 = 0.918_938_533_204_672_8;

/// Reference: ln G(t) by the trapezoidal rule on the whole real line (see module docs).
/// Slow (hundreds of exponentials); used to build and to test the fast path.
pub fn ln_g_reference(t: f64) -> f64 {
    // Peak of the exponent −t w² − w⁴/2: at w = 0 for t ≥ 0, at w² = −t otherwise.
    let (w_peak, shift) = if t >= 0.0 { (0.0, 0.0) } else { ((-t).sqrt(), t * t / 2.0) };
    // Width of the peak: ~ 1/sqrt(|t|) on both sides; ~1 near t = 0.
    let width = 1.0 / (1.0 + t.abs()).sqrt();
    let h = width / 12.0;
    let f = |w: f64| {
        let w2 = w * w;
        w2 * w2 * (-t * w2 - w2 * w2 / 2.0 - shift).exp()
    };
    // Sum over w = k h, k ∈ Z; the integrand is even, so sum k ≥ 1 twice (f(0) = 0).
    let mut sum = 0.0;
    let mut k = 1usize;
    loop {
        let w = k as f64 * h;
        let v = f(w);
        sum += v;
        if w > w_peak + 2.0 && v < sum * 1e-20 {
            break;
        }
        k += 1;
    }
    shift + (2.0 * h * sum).ln()
}

/// Reference ln F_{3/2}(t).
pub fn ln_f32_reference(t: f64) -> f64 {
    ln_g_reference(t) - t * t / 2.0 - HALF_LN_2PI
}

struct Table {
    coef: [[f64; NODES]; PANELS],
}

fn table() -> &'static Table {
    static TABLE: OnceLock<Table> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut coef = [[0.0; NODES]; PANELS];
        let n = NODES as f64;
        for (p, c) in coef.iter_mut().enumerate() {
            let a = T_LO + p as f64 * PANEL;
            let vals: Vec<f64> = (0..NODES)
                .map(|j| {
                    let x = (PI * (j as f64 + 0.5) / n).cos();
                    ln_g_reference(a + 0.5 * PANEL * (x + 1.0))
                })
                .collect();
            for (k, ck) in c.iter_mut().enumerate() {
                let s: f64 = vals
                    .iter()
                    .enumerate()
                    .map(|(j, v)| v * (PI * k as f64 * (j as f64 + 0.5) / n).cos())
                    .sum();
                *ck = 2.0 * s / n;
            }
        }
        Table { coef }
    })
}

/// Build the interpolation table now (it is otherwise built on first use, ~1 ms).
pub fn warm_up() {
    table();
}

/// ln G(t) and d ln G/dt on [T_LO, T_HI]: Clenshaw's recurrence and its derivative
/// (b_k = 2x b_{k+1} − b_{k+2} + c_k, b'_k = 2 b_{k+1} + 2x b'_{k+1} − b'_{k+2}).
fn ln_g_chebyshev(t: f64) -> (f64, f64) {
    let tab = table();
    let p = (((t - T_LO) / PANEL) as usize).min(PANELS - 1);
    let a = T_LO + p as f64 * PANEL;
    let x = 2.0 * (t - a) / PANEL - 1.0;
    let c = &tab.coef[p];
    let (mut b1, mut b2, mut d1, mut d2) = (0.0, 0.0, 0.0, 0.0);
    for &ck in c[1..].iter().rev() {
        let b0 = 2.0 * x * b1 - b2 + ck;
        let d0 = 2.0 * b1 + 2.0 * x * d1 - d2;
        b2 = b1;
        b1 = b0;
        d2 = d1;
        d1 = d0;
    }
    (x * b1 - b2 + 0.5 * c[0], (b1 + x * d1 - d2) * 2.0 / PANEL)
}

/// ln G(t) and its derivative for t > T_HI by Watson's lemma (relative error < 1e-16 there).
fn ln_g_large(t: f64) -> (f64, f64) {
    let inv_t2 = 1.0 / (t * t);
    let mut term = 1.0;
    let (mut sum, mut dsum) = (1.0, 0.0); // S = Σ c_k t^{−2k}, −t·S' = Σ 2k c_k t^{−2k}
    for k in 0..40 {
        let kf = f64::from(k);
        term *= -0.5 / (kf + 1.0) * (2.5 + 2.0 * kf) * (3.5 + 2.0 * kf) * inv_t2;
        sum += term;
        dsum += 2.0 * (kf + 1.0) * term;
        if term.abs() < 1e-17 * sum {
            break;
        }
    }
    (LN_GAMMA_5_2 - 2.5 * t.ln() + sum.ln(), (-2.5 - dsum / sum) / t)
}

/// ln F(t) and its derivative for t < T_LO from the moments of the normal distribution.
fn ln_f_very_negative(t: f64) -> (f64, f64) {
    let inv_t2 = 1.0 / (t * t);
    // term_k = C(3/2, 2k)·(2k−1)!!·t^{−2k}
    let mut binom = 1.0; // C(3/2, 2k)
    let mut dfact = 1.0; // (2k−1)!!
    let mut pow = 1.0;
    let (mut sum, mut dsum) = (1.0, 0.0);
    for k in 1..40 {
        let kf = f64::from(k);
        let m = 2.0 * kf; // C(3/2, m) = C(3/2, m−2)·(3/2−m+2)(3/2−m+1)/((m−1)m)
        binom *= (1.5 - m + 2.0) * (1.5 - m + 1.0) / ((m - 1.0) * m);
        dfact *= 2.0 * kf - 1.0;
        pow *= inv_t2;
        let term = binom * dfact * pow;
        sum += term;
        dsum += 2.0 * kf * term;
        if term.abs() < 1e-17 * sum {
            break;
        }
    }
    (1.5 * (-t).ln() + sum.ln(), (1.5 - dsum / sum) / t)
}

/// ln F_{3/2}(t) with its first and second derivatives on the interpolated interval
/// [`T_LO`, `T_HI`] (Clenshaw's recurrence differentiated twice:
/// b″_k = 4 b′_{k+1} + 2x b″_{k+1} − b″_{k+2}); the second derivative is NaN outside it. The
/// value and the first derivative are [`ln_f32_slope`]'s, bit for bit.
pub fn ln_f32_slope2(t: f64) -> (f64, f64, f64) {
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(…)` also sends NaN to the general path
    if !((T_LO..=T_HI).contains(&t)) {
        let (v, d) = ln_f32_slope(t);
        return (v, d, f64::NAN);
    }
    let tab = table();
    let p = (((t - T_LO) / PANEL) as usize).min(PANELS - 1);
    let a = T_LO + p as f64 * PANEL;
    let x = 2.0 * (t - a) / PANEL - 1.0;
    let c = &tab.coef[p];
    let (mut b1, mut b2, mut d1, mut d2, mut e1, mut e2) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for &ck in c[1..].iter().rev() {
        let b0 = 2.0 * x * b1 - b2 + ck;
        let d0 = 2.0 * b1 + 2.0 * x * d1 - d2;
        let e0 = 4.0 * d1 + 2.0 * x * e1 - e2;
        b2 = b1;
        b1 = b0;
        d2 = d1;
        d1 = d0;
        e2 = e1;
        e1 = e0;
    }
    let (g, dg) = (x * b1 - b2 + 0.5 * c[0], (b1 + x * d1 - d2) * 2.0 / PANEL);
    let ddg = (2.0 * d1 + x * e1 - e2) * (2.0 / PANEL) * (2.0 / PANEL);
    (g - t * t / 2.0 - HALF_LN_2PI, dg - t, ddg - 1.0)
}

/// ln F_{3/2}(t), eq. 16, for every finite t; −∞ for t = +∞.
pub fn ln_f32(t: f64) -> f64 {
    ln_f32_slope(t).0
}

/// ln F_{3/2}(t) and d ln F_{3/2}/dt (= −(3/2) F_{1/2}/F_{3/2}, always < 0).
pub fn ln_f32_slope(t: f64) -> (f64, f64) {
    if t > T_HI {
        if t == f64::INFINITY {
            return (f64::NEG_INFINITY, f64::NEG_INFINITY);
        }
        let (g, dg) = ln_g_large(t);
        (g - t * t / 2.0 - HALF_LN_2PI, dg - t)
    } else if t < T_LO {
        ln_f_very_negative(t)
    } else {
        let (g, dg) = ln_g_chebyshev(t);
        (g - t * t / 2.0 - HALF_LN_2PI, dg - t)
    }
}

/// F_{3/2}(t), eq. 16 (underflows to 0 past t ≈ 38; use [`ln_f32`] there).
pub fn f32(t: f64) -> f64 {
    ln_f32(t).exp()
}

/// Solve `ln F_{3/2}(t) = target` for t (F strictly decreasing: unique root).
pub fn inverse_ln_f32(target: f64) -> f64 {
    let f = |t: f64| {
        let (v, d) = ln_f32_slope(t);
        (target - v, -d)
    };
    newton_increasing(f, 1.0, |t| 1e-14 * (1.0 + t.abs())).0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The check values of docs/model.md, computed independently from the parabolic-cylinder closed form.
    const CHECK: [(f64, f64); 7] = [
        (-3.0, 5.418377276511698),
        (0.0, 0.4300199936622599),
        (0.5, 0.19520360374379062),
        (1.0, 0.07566817739097503),
        (2.0, 0.006648177623587),
        (3.0, 2.639675542694661e-4),
        (4.0, 4.4391559585389115e-6),
    ];

    #[test]
    fn reference_matches_model_notes() {
        for (t, f) in CHECK {
            let got = ln_f32_reference(t).exp();
            assert!(((got - f) / f).abs() < 1e-13, "t={t}: {got} vs {f}");
        }
    }

    #[test]
    fn fast_path_matches_model_notes() {
        for (t, f) in CHECK {
            let got = f32(t);
            assert!(((got - f) / f).abs() < 1e-13, "t={t}: {got} vs {f}");
        }
    }

    #[test]
    fn fast_path_matches_reference_everywhere() {
        // |Δ ln F| is the relative error in F. ln F = ln G − t²/2 − ½ln 2π loses the
        // absolute precision of its largest term, so measure it in units of that scale.
        let mut worst: f64 = 0.0;
        let mut t = -14.0;
        while t < 40.0 {
            let scale = 1.0 + t * t / 2.0 + ln_f32_reference(t).abs();
            let d = (ln_f32(t) - ln_f32_reference(t)).abs() / scale;
            worst = worst.max(d);
            t += 0.0137;
        }
        // Both paths carry summation rounding of a few ulp of the scale; 1e-14 is ~45 ulp.
        assert!(worst < 1e-14, "worst scaled error {worst:e}");
    }

    #[test]
    fn independent_quadrature_in_s() {
        // Direct Gauss-free check: composite Simpson in the original variable s − t = v²
        // (removes the (s−t)^{3/2} kink), on a fine grid. Independent of the w-substitution.
        for t in [-2.0, 0.3, 1.7, 5.0] {
            let n = 200_000;
            let vmax = 12.0 + f64::max(-t, 0.0).sqrt() * 2.0;
            let h = vmax / f64::from(n);
            let f = |v: f64| 2.0 * v.powi(4) * (-(v * v + t).powi(2) / 2.0).exp();
            let mut s = f(0.0) + f(vmax);
            for i in 1..n {
                s += f(f64::from(i) * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            let direct = s * h / 3.0 / (2.0 * PI).sqrt();
            assert!(((f32(t) - direct) / direct).abs() < 1e-10, "t={t}");
        }
    }

    #[test]
    fn monotone_asymptotic_and_continuous() {
        // F strictly decreasing, the classical large-t asymptote
        // F ~ Γ(5/2)/√(2π) t^{-5/2} e^{-t²/2}, and no jump at the branch and panel joins.
        let mut prev = f64::INFINITY;
        for i in 0..2000 {
            let t = -20.0 + f64::from(i) * 0.05;
            let v = ln_f32(t);
            assert!(v < prev, "not decreasing at {t}");
            prev = v;
        }
        let t: f64 = 300.0;
        let asym = LN_GAMMA_5_2 - HALF_LN_2PI - 2.5 * t.ln() - t * t / 2.0;
        assert!((ln_f32(t) - asym).abs() < 1e-4);
        // Continuity across the panel joins and the branch switches.
        for t0 in [T_LO, T_HI, 0.0, 3.0] {
            let fast = ln_f32(t0 + 1e-6) - ln_f32(t0 - 1e-6);
            let reference = ln_f32_reference(t0 + 1e-6) - ln_f32_reference(t0 - 1e-6);
            assert!((fast - reference).abs() < 1e-12, "jump at {t0}: {fast} vs {reference}");
        }
    }

    #[test]
    fn slope_matches_differences_and_half_order_identity() {
        // The slope against central differences of the reference path, in every branch.
        for t in [-30.0, -10.5, -9.99, -3.0, 0.0, 0.7, 5.5, 11.99, 12.01, 30.0, 200.0] {
            let (_, d) = ln_f32_slope(t);
            let e = 1e-5 * (1.0 + f64::abs(t));
            let fd = (ln_f32_reference(t + e) - ln_f32_reference(t - e)) / (2.0 * e);
            assert!((d - fd).abs() < 1e-6 * (1.0 + fd.abs()), "t={t}: {d} vs {fd}");
        }
        // Closed form at t = 0: F_{1/2}(0) = (2π)^{-1/2} ∫_0^∞ s^{1/2} e^{-s²/2} ds = 2^{-1/4} Γ(3/4)/√(2π).
        let gamma_3_4 = 1.225_416_702_465_177_6;
        let f_half_0 = 2f64.powf(-0.25) * gamma_3_4 / (2.0 * PI).sqrt();
        let (lnf, d) = ln_f32_slope(0.0);
        // A Chebyshev interpolant's derivative is ~N² less accurate than its values: 1e-12.
        assert!((d * lnf.exp() / (-1.5 * f_half_0) - 1.0).abs() < 1e-12, "{} vs {}", d * lnf.exp(), -1.5 * f_half_0);
    }

    #[test]
    fn second_derivative_matches_differences_and_agrees_with_slope() {
        for t in [-9.9, -3.0, -0.2, 0.0, 0.7, 2.49, 2.5, 5.5, 11.9] {
            let (v, d, dd) = ln_f32_slope2(t);
            assert_eq!((v, d), ln_f32_slope(t), "t={t}");
            let e = 1e-4;
            let fd = (ln_f32_slope(t + e).1 - ln_f32_slope(t - e).1) / (2.0 * e);
            assert!((dd - fd).abs() < 1e-6 * (1.0 + fd.abs()), "t={t}: {dd} vs {fd}");
        }
        assert!(ln_f32_slope2(12.5).2.is_nan() && ln_f32_slope2(-10.5).2.is_nan() && ln_f32_slope2(f64::NAN).2.is_nan());
    }

    #[test]
    fn inverse_roundtrips() {
        for t in [-15.0, -3.0, 0.0, 1.234, 7.0, 25.0, 400.0] {
            let back = inverse_ln_f32(ln_f32(t));
            assert!((back - t).abs() < 1e-9 * (1.0 + t.abs()), "{t} -> {back}");
        }
    }
}
