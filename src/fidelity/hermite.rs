//! Cubic Hermite interpolation on uniform grids, the building block of the tables.
//!
//! On a cell of a uniform grid, local coordinate t ∈ [0, 1], the cubic with values
//! f0, f1 and slopes d0, d1 (per unit t, i.e. the derivative times the step h) at the
//! ends has the power coefficients `M·[f0, f1, d0, d1]` with
//!
//! ```text
//!       | 1  0  0  0 |
//!   M = | 0  0  1  0 |      c0 = f0, c1 = d0,
//!       |-3  3 -2 -1 |      c2 = −3f0 + 3f1 − 2d0 − d1,
//!       | 2 -2  1  1 |      c3 = 2f0 − 2f1 + d0 + d1.
//! ```
//!
//! In two dimensions the bicubic on a cell is `Σ a_kl t^k u^l` with `A = M·G·Mᵀ`, G holding
//! the corner values, the two first derivatives and the cross derivative (each times the
//! steps). With exact derivatives the error of the cubic Hermite interpolant is at most
//! `h⁴·max|f⁗|/384` (at the cell centre, for each direction). The derivatives here are the
//! fourth-order central differences of the node values, `(f₋₂ − 8f₋₁ + 8f₊₁ − f₊₂)/12`, whose
//! error `h⁵·f⁽⁵⁾/30` keeps the interpolant fourth-order: halving the step divides the error
//! by about 16. The tables use two rings of ghost nodes outside the envelope so that the
//! same central stencil applies at every node of the envelope (the model is defined there).

/// Power coefficients of the cubic on [0, 1] with end values f0, f1 and end slopes d0, d1.
#[inline]
pub(crate) fn cubic_coefficients(f0: f64, f1: f64, d0: f64, d1: f64) -> [f64; 4] {
    [f0, d0, -3.0 * f0 + 3.0 * f1 - 2.0 * d0 - d1, 2.0 * f0 - 2.0 * f1 + d0 + d1]
}

/// Fourth-order central difference: h·f'(x) ≈ (f(x−2h) − 8f(x−h) + 8f(x+h) − f(x+2h))/12.
#[inline]
pub(crate) fn central_slope(fm2: f64, fm1: f64, fp1: f64, fp2: f64) -> f64 {
    (fm2 - 8.0 * fm1 + 8.0 * fp1 - fp2) / 12.0
}

/// Fourth difference Δ⁴f = f₋₂ − 4f₋₁ + 6f₀ − 4f₊₁ + f₊₂ ≈ h⁴ f⁗: the error indicator.
#[inline]
pub(crate) fn fourth_difference(f: [f64; 5]) -> f64 {
    f[0] - 4.0 * f[1] + 6.0 * f[2] - 4.0 * f[3] + f[4]
}

/// Evaluate a cubic given by its power coefficients at t (Horner).
#[inline(always)]
pub(crate) fn cubic(c: &[f64; 4], t: f64) -> f64 {
    ((c[3] * t + c[2]) * t + c[1]) * t + c[0]
}

/// Bicubic coefficients `a[4k + l]` (of t^k u^l) of one cell from its corner data.
///
/// `f[a][b]`, `ft[a][b]`, `fu[a][b]`, `ftu[a][b]` are the value, t-slope, u-slope and cross
/// slope (all per unit local coordinate) at corner (t, u) = (a, b).
pub(crate) fn bicubic_coefficients(f: [[f64; 2]; 2], ft: [[f64; 2]; 2], fu: [[f64; 2]; 2], ftu: [[f64; 2]; 2]) -> [f64; 16] {
    // G rows: f(0,·), f(1,·), ft(0,·), ft(1,·); columns: value(u=0), value(u=1), u-slope(0), u-slope(1).
    let g = [
        [f[0][0], f[0][1], fu[0][0], fu[0][1]],
        [f[1][0], f[1][1], fu[1][0], fu[1][1]],
        [ft[0][0], ft[0][1], ftu[0][0], ftu[0][1]],
        [ft[1][0], ft[1][1], ftu[1][0], ftu[1][1]],
    ];
    // B = M·G (apply the 1-D map down each column), then A = B·Mᵀ (along each row).
    let mut b = [[0.0; 4]; 4];
    for col in 0..4 {
        let c = cubic_coefficients(g[0][col], g[1][col], g[2][col], g[3][col]);
        for k in 0..4 {
            b[k][col] = c[k];
        }
    }
    let mut a = [0.0; 16];
    for k in 0..4 {
        let c = cubic_coefficients(b[k][0], b[k][1], b[k][2], b[k][3]);
        a[4 * k..4 * k + 4].copy_from_slice(&c);
    }
    a
}

/// Evaluate `Σ a[4k+l] t^k u^l` (Horner in u, then in t).
#[inline(always)]
pub(crate) fn bicubic(a: &[f64; 16], t: f64, u: f64) -> f64 {
    let r = |k: usize| ((a[4 * k + 3] * u + a[4 * k + 2]) * u + a[4 * k + 1]) * u + a[4 * k];
    ((r(3) * t + r(2)) * t + r(1)) * t + r(0)
}

/// Two patches at once: `[bicubic(a, t, u), bicubic(b, t, u)]` bit for bit, from their
/// coefficients interleaved (`p[i] = [a[i], b[i]]`). The same operations in the same order on
/// each of the pair, so that a processor with two-wide floating-point vectors (SSE2, NEON)
/// does both with one instruction each.
#[inline(always)]
pub(crate) fn bicubic_pair(p: &[[f64; 2]; 16], t: f64, u: f64) -> [f64; 2] {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{__m128d, _mm_add_pd, _mm_cvtsd_f64, _mm_mul_pd, _mm_set1_pd, _mm_set_pd, _mm_unpackhi_pd};
        // SSE2: a mulpd and an addpd per step, each lane the scalar `x * s + c` of the
        // portable branch below (IEEE products and sums, rounded alike: the same bits).
        // SAFETY: these intrinsics only compute on registers (no memory access); their one
        // requirement, SSE2, is part of every x86_64 target.
        unsafe {
            let load = |i: usize| -> __m128d { _mm_set_pd(p[i][1], p[i][0]) };
            let (vt, vu) = (_mm_set1_pd(t), _mm_set1_pd(u));
            let step = |x: __m128d, s: __m128d, c: __m128d| _mm_add_pd(_mm_mul_pd(x, s), c);
            let r = |k: usize| step(step(step(load(4 * k + 3), vu, load(4 * k + 2)), vu, load(4 * k + 1)), vu, load(4 * k));
            let v = step(step(step(r(3), vt, r(2)), vt, r(1)), vt, r(0));
            [_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))]
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let step = |x: [f64; 2], s: f64, c: [f64; 2]| [x[0] * s + c[0], x[1] * s + c[1]];
        let r = |k: usize| step(step(step(p[4 * k + 3], u, p[4 * k + 2]), u, p[4 * k + 1]), u, p[4 * k]);
        step(step(step(r(3), t, r(2)), t, r(1)), t, r(0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_reproduces_cubics_exactly() {
        let p = |x: f64| 0.3 - 1.2 * x + 0.7 * x * x + 2.1 * x * x * x;
        let dp = |x: f64| -1.2 + 1.4 * x + 6.3 * x * x;
        let (x0, h) = (0.4, 0.25);
        let c = cubic_coefficients(p(x0), p(x0 + h), h * dp(x0), h * dp(x0 + h));
        for i in 0..=10 {
            let t = f64::from(i) / 10.0;
            assert!((cubic(&c, t) - p(x0 + t * h)).abs() < 1e-14);
        }
        // The central slope is exact for quartics.
        let q = |x: f64| x.powi(4) - x;
        let s = central_slope(q(x0 - 2.0 * h), q(x0 - h), q(x0 + h), q(x0 + 2.0 * h));
        assert!((s - h * (4.0 * x0.powi(3) - 1.0)).abs() < 1e-14);
        assert!((fourth_difference([q(0.0), q(h), q(2.0 * h), q(3.0 * h), q(4.0 * h)]) - 24.0 * h.powi(4)).abs() < 1e-13);
    }

    #[test]
    fn bicubic_reproduces_bicubics_and_is_fourth_order() {
        let f = |x: f64, y: f64| 1.0 + x - 2.0 * y + x * y * y - 0.5 * x.powi(3) * y.powi(2) + y.powi(3);
        let fx = |x: f64, y: f64| 1.0 + y * y - 1.5 * x * x * y * y;
        let fy = |x: f64, y: f64| -2.0 + 2.0 * x * y - x.powi(3) * y + 3.0 * y * y;
        let fxy = |x: f64, y: f64| 2.0 * y - 3.0 * x * x * y;
        let (x0, y0, hx, hy) = (0.2, -0.3, 0.5, 0.25);
        let c = |d: fn(f64, f64) -> f64, s: f64| {
            [[s * d(x0, y0), s * d(x0, y0 + hy)], [s * d(x0 + hx, y0), s * d(x0 + hx, y0 + hy)]]
        };
        let a = bicubic_coefficients(c(f, 1.0), c(fx, hx), c(fy, hy), c(fxy, hx * hy));
        for (t, u) in [(0.0, 0.0), (0.5, 0.5), (0.3, 0.9), (1.0, 1.0), (0.1, 0.7)] {
            assert!((bicubic(&a, t, u) - f(x0 + t * hx, y0 + u * hy)).abs() < 1e-13, "{t} {u}");
        }
        // exp(x) on [0, h] with central-difference slopes: error ∝ h⁴.
        let err = |h: f64| {
            let e = |k: f64| (k * h).exp();
            let d0 = central_slope(e(-2.0), e(-1.0), e(1.0), e(2.0));
            let d1 = central_slope(e(-1.0), e(0.0), e(2.0), e(3.0));
            let c = cubic_coefficients(e(0.0), e(1.0), d0, d1);
            (cubic(&c, 0.5) - e(0.5)).abs()
        };
        let ratio = err(0.2) / err(0.1);
        assert!(ratio > 12.0 && ratio < 20.0, "{ratio}");
    }
}
