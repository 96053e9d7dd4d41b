//! The exponential and ln(1 + e) of the load-sharing solve's inner loop (eqs. 13, 16, 19 in
//! logarithms): the same functions as `f64::exp` and `(1.0 + e).ln()` to within a couple of
//! units in the last place, inlined, without the C library's call and error-handling wrapper
//! (glibc's `exp` and `log` were 40 % of a cold evaluation's instructions; callgrind).
//!
//! [`exp`], method (Tang's table-driven scheme): x = (64m + j)·ln2/64 + r with |r| ≤ ln2/128, so
//! eˣ = 2^m · 2^(j/64) · e^r; 2^(j/64) comes from a table of the 64 values correctly rounded
//! (computed to 50 digits), e^r − 1 from its Taylor polynomial to r⁶ (remainder below 3e-20),
//! and 2^m is added to the exponent bits. The reduction is exact: ln2/64 is split into a
//! 32-bit head (so that m·head is exact for |x| ≤ 708) and a tail. Outside |x| ≤ 708 (near
//! overflow, underflow, subnormal results) and for NaN it is `f64::exp` itself.

/// 2^(j/64), j = 0..63, correctly rounded.
#[allow(clippy::unreadable_literal, clippy::excessive_precision, clippy::approx_constant)] // 2^(32/64) is √2, as a table entry
const TABLE: [f64; 64] = [
    1.0, 1.0108892860517005, 1.0218971486541166, 1.0330248790212284, 1.0442737824274138, 1.0556451783605572, 1.0671404006768237,
    1.0787607977571199, 1.0905077326652577, 1.102382583307841, 1.1143867425958924, 1.1265216186082418, 1.1387886347566916,
    1.1511892299529827, 1.1637248587775775, 1.1763969916502812, 1.189207115002721, 1.202156731452703, 1.215247359980469,
    1.22848053610687, 1.241857812073484, 1.255380757024691, 1.2690509571917332, 1.2828700160787783, 1.2968395546510096,
    1.3109612115247644, 1.3252366431597413, 1.339667524053303, 1.3542555469368927, 1.3690024229745905, 1.383909881963832,
    1.3989796725383112, 1.4142135623730951, 1.42961333839197, 1.4451808069770467, 1.460917794180647, 1.4768261459394993,
    1.4929077282912648, 1.5091644275934228, 1.5255981507445384, 1.5422108254079407, 1.559004400237837, 1.5759808451078865,
    1.593142151342267, 1.6104903319492543, 1.6280274218573478, 1.645755478153965, 1.6636765803267364, 1.681792830507429,
    1.7001063537185235, 1.718619298122478, 1.7373338352737062, 1.7562521603732995, 1.7753764925265212, 1.7947090750031072,
    1.8142521755003989, 1.8340080864093424, 1.8539791250833855, 1.8741676341103, 1.8945759815869656, 1.9152065613971474,
    1.9360617934922943, 1.9571441241754002, 1.978456026387951,
];
/// 64/ln 2.
const INV_STEP: f64 = 92.33248261689366;
/// ln2/64 = STEP_HI + STEP_LO, STEP_HI with 32 significant bits.
const STEP_HI: f64 = 0.01083042469326756;
const STEP_LO: f64 = 2.9815858269852933e-12;
/// 1.5·2^52: adding it rounds to an integer held in the low bits of the mantissa.
const SHIFT: f64 = 6_755_399_441_055_744.0;

/// eˣ (see the module documentation for the method and its accuracy).
#[inline]
pub fn exp(x: f64) -> f64 {
    // `!(… <= …)` also sends NaN to the library.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(x.abs() <= 708.0) {
        return x.exp();
    }
    let z = x * INV_STEP + SHIFT;
    let k = z.to_bits() as i64 - SHIFT.to_bits() as i64; // round(x·64/ln2)
    let kf = z - SHIFT;
    let r = (x - kf * STEP_HI) - kf * STEP_LO;
    // Estrin's scheme (three independent pairs, combined with r²): a shorter chain of
    // dependent operations than Horner's, the same polynomial.
    let r2 = r * r;
    let p = r * ((1.0 + 0.5 * r) + r2 * ((1.0 / 6.0 + r * (1.0 / 24.0)) + r2 * (1.0 / 120.0 + r * (1.0 / 720.0))));
    let t = TABLE[(k & 63) as usize];
    let m = t + t * p;
    f64::from_bits((m.to_bits() as i64 + ((k >> 6) << 52)) as u64)
}

/// ln(1 + e) for 0 ≤ e ≤ 1 (the log-sum-exp and softplus corrections, e = e^(−|d|)), to an
/// absolute error of about ε. With v = 1 + e (or v/2 past √2), f = (v − 1)/(v + 1) has
/// |f| ≤ 3 − 2√2 ≈ 0.1716 and ln v = 2 atanh f = 2f Σ f^(2n)/(2n + 1), summed to n = 9
/// (remainder below 3e-17 relative).
#[inline]
pub fn ln_1p_unit(e: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&e), "{e}");
    let (f, base) = if e <= std::f64::consts::SQRT_2 - 1.0 { (e / (2.0 + e), 0.0) } else { ((e - 1.0) / (e + 3.0), std::f64::consts::LN_2) };
    let s = f * f;
    // Σ s^k/(2k + 1), k = 0..9, by Estrin's scheme (pairs combined with s², s⁴, s⁸): a chain
    // of about five dependent operations instead of Horner's nine.
    let (s2, p01, p23, p45, p67, p89) = (s * s, 1.0 + s * (1.0 / 3.0), 1.0 / 5.0 + s * (1.0 / 7.0), 1.0 / 9.0 + s * (1.0 / 11.0), 1.0 / 13.0 + s * (1.0 / 15.0), 1.0 / 17.0 + s * (1.0 / 19.0));
    let s4 = s2 * s2;
    let series = (p01 + s2 * p23) + s4 * ((p45 + s2 * p67) + s4 * p89);
    base + 2.0 * f * series
}

/// π/2 in three parts for the argument reduction of [`sin_cos`] (Cody and Waite, as in
/// fdlibm): `PIO2_1` and `PIO2_2` carry 33 significant bits each, so k·`PIO2_1` and
/// k·`PIO2_2` are exact for |k| < 2^20, and `PIO2_3` is the rest.
#[allow(clippy::excessive_precision, clippy::unreadable_literal)]
const PIO2_1: f64 = 1.57079632673412561417e+00;
#[allow(clippy::excessive_precision, clippy::unreadable_literal)]
const PIO2_2: f64 = 6.07710050630396597660e-11;
#[allow(clippy::excessive_precision, clippy::unreadable_literal)]
const PIO2_3: f64 = 2.02226624879595063154e-21;
/// Largest |x| reduced here (|k| < 2^20); beyond it, and for NaN and ±∞, `f64::sin_cos`.
const SIN_COS_REDUCED: f64 = 1.6e6;

/// (sin x, cos x), within a couple of units in the last place of `f64::sin_cos` for
/// |x| ≤ 1.6e6 (`f64::sin_cos` itself beyond), inlined, at about a third of the C library's
/// instructions (the rig's sine command is evaluated at every right-hand side: callgrind,
/// `examples/rig_once.rs`).
///
/// Method: x = k·π/2 + r, |r| ≤ π/4, with k = round(2x/π) and r by the three-part
/// Cody–Waite reduction (exact products, so r is accurate to its own rounding); sin r and
/// cos r from their Taylor polynomials to r¹⁷ and r¹⁸ (remainders below 1e-19 on
/// |r| ≤ π/4), cos r's leading 1 − r²/2 summed with fdlibm's correction; the quadrant
/// k mod 4 swaps and negates.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    // `!(… <= …)` also sends NaN to the library.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    if !(x.abs() <= SIN_COS_REDUCED) {
        return x.sin_cos();
    }
    // k = round(2x/π) by the SHIFT trick, as in [`exp`] (`f64::round` is a library call on
    // the baseline x86-64 target).
    let z = x * std::f64::consts::FRAC_2_PI + SHIFT;
    let k = z.to_bits() as i64 - SHIFT.to_bits() as i64;
    let kf = z - SHIFT;
    let r = ((x - kf * PIO2_1) - kf * PIO2_2) - kf * PIO2_3;
    let z = r * r;
    // sin r = r + r·z·(−1/3! + z/5! − … + z⁷/17!).
    let z2 = z * z;
    let s_poly = (-1.0 / 6.0 + z * (1.0 / 120.0))
        + z2 * ((-1.0 / 5040.0 + z * (1.0 / 362_880.0)) + z2 * ((-1.0 / 39_916_800.0 + z * (1.0 / 6_227_020_800.0)) + z2 * (-1.0 / 1_307_674_368_000.0 + z * (1.0 / 355_687_428_096_000.0))));
    let sin = r + r * (z * s_poly);
    // cos r = 1 − z/2 + z²·(1/4! − z/6! + … + z⁷/18!).
    let c_poly = (1.0 / 24.0 - z * (1.0 / 720.0))
        + z2 * ((1.0 / 40_320.0 - z * (1.0 / 3_628_800.0)) + z2 * ((1.0 / 479_001_600.0 - z * (1.0 / 87_178_291_200.0)) + z2 * (1.0 / 20_922_789_888_000.0 - z * (1.0 / 6_402_373_705_728_000.0))));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    let cos = w + (((1.0 - w) - hz) + z2 * c_poly);
    match k & 3 {
        0 => (sin, cos),
        1 => (cos, -sin),
        2 => (-sin, -cos),
        _ => (-cos, sin),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in units in the last place (same sign, finite).
    fn ulps(a: f64, b: f64) -> u64 {
        (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
    }

    #[test]
    fn agrees_with_the_library_to_two_ulps_everywhere() {
        let mut worst = 0;
        let mut x = -745.5;
        while x < 710.0 {
            for d in [0.0, 1e-9, 0.3191, 0.7043] {
                let v = x + d;
                let (a, b) = (exp(v), v.exp());
                if b.is_finite() && b > f64::MIN_POSITIVE {
                    worst = worst.max(ulps(a, b));
                } else {
                    assert_eq!(a.to_bits(), b.to_bits(), "{v}");
                }
            }
            x += 0.0137;
        }
        // Small arguments, where e^x − 1 ≈ x matters.
        for i in -400..400 {
            let v = f64::from(i) * 1.7e-5;
            worst = worst.max(ulps(exp(v), v.exp()));
        }
        assert!(worst <= 2, "worst {worst} ulp");
    }

    /// |a − b| in units of the last place of b (b ≠ 0).
    fn ulp_error(a: f64, b: f64) -> f64 {
        let ulp = f64::from_bits(b.abs().to_bits() + 1) - b.abs();
        (a - b).abs() / ulp
    }

    #[test]
    fn sin_cos_agrees_with_the_library() {
        let mut worst: f64 = 0.0;
        let mut check = |x: f64| {
            let ((s, c), (ls, lc)) = (sin_cos(x), x.sin_cos());
            for (a, b) in [(s, ls), (c, lc)] {
                if b == 0.0 {
                    assert!(a.abs() < 1e-300, "{x}: {a} vs {b}");
                } else {
                    worst = worst.max(ulp_error(a, b));
                }
            }
        };
        // A dense sweep of a few turns, one of long times, the quadrant edges and the
        // multiples of π (where sin is tiny and the reduction's accuracy shows).
        for i in -200_000..200_000 {
            check(f64::from(i) * 1.37e-4);
        }
        for i in 0..100_000 {
            check(1.6e6 * f64::from(i) / 100_000.0 + 0.123);
        }
        for k in -2000..2000 {
            let m = f64::from(k) * std::f64::consts::FRAC_PI_2;
            for d in [0.0, 1e-12, -3e-9, std::f64::consts::FRAC_PI_4, -std::f64::consts::FRAC_PI_4 + 1e-15] {
                check(m + d);
            }
        }
        for x in [0.0, -0.0, 1e-300, -1e-30, 5e-9, 1.6e6, -1.6e6] {
            check(x);
        }
        assert!(worst <= 2.0, "worst {worst} ulp");
        // Outside the reduced range and at special values: the library's.
        for x in [1.7e6, -3e15, f64::INFINITY, f64::NAN] {
            let (a, b) = (sin_cos(x), x.sin_cos());
            assert_eq!((a.0.to_bits(), a.1.to_bits()), (b.0.to_bits(), b.1.to_bits()), "{x}");
        }
        // sin(−x) = −sin x, cos(−x) = cos x exactly (the method is odd/even by construction).
        for i in 1..1000 {
            let x = f64::from(i) * 0.731;
            let (a, b) = (sin_cos(x), sin_cos(-x));
            assert_eq!((a.0, a.1), (-b.0, b.1), "{x}");
        }
    }

    #[test]
    fn ln_1p_unit_agrees_with_the_library() {
        let mut worst: f64 = 0.0;
        for i in 0..=20000 {
            let e = f64::from(i) / 20000.0;
            for v in [e, e * 0.999_999_7, (e * 1e-3) * (e * 1e-3)] {
                let d = (ln_1p_unit(v) - v.ln_1p()).abs();
                worst = worst.max(d / f64::EPSILON);
                // And relative accuracy where ln(1 + e) ≈ e is tiny.
                if v > 0.0 {
                    assert!((ln_1p_unit(v) / v.ln_1p() - 1.0).abs() < 4.0 * f64::EPSILON, "{v}");
                }
            }
        }
        assert!(worst <= 1.0, "worst {worst} ε");
        assert_eq!(ln_1p_unit(0.0), 0.0);
        assert!((ln_1p_unit(1.0) - std::f64::consts::LN_2).abs() <= f64::EPSILON);
    }

    #[test]
    fn exact_points_and_special_values() {
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(exp(-0.0), 1.0);
        assert_eq!(exp(1.0), std::f64::consts::E);
        assert!(exp(f64::NAN).is_nan());
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(1e300), f64::INFINITY);
        assert_eq!(exp(-1e300), 0.0);
        // Powers of two: e^(m ln 2) = 2^m to rounding of the argument.
        for m in [-1000, -10, -1, 1, 10, 1000] {
            // The argument m·ln2 carries a rounding of |m|·ln2·ε/2, which e^x turns into a
            // relative error of the same size.
            let x = f64::from(m) * std::f64::consts::LN_2;
            let v = exp(x);
            assert!((v / 2f64.powi(m) - 1.0).abs() < (x.abs() + 4.0) * f64::EPSILON, "{m}");
        }
        // The table against 2^(j/64) from the library's exp2.
        for (j, t) in TABLE.iter().enumerate() {
            assert!(ulps(*t, (j as f64 / 64.0).exp2()) <= 1, "{j}");
        }
    }
}
