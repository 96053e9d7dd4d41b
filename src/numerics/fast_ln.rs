//! ln x inlined, for the table level's cell coordinates (ln P, ln |ω|): two logarithms per
//! table evaluation were glibc's `log` through its call and error-handling wrapper, ~50
//! instructions each (callgrind, the batch's table step); this is ~25, inlined.
//!
//! Method (the table-driven reduction of Tang, "Table-driven implementation of the logarithm
//! function in IEEE floating-point arithmetic", ACM TOMS 16(4), 1990): x = 2^k·m with
//! m ∈ [1, 2); the top seven bits of m's fraction pick c = 1 + (i + ½)/128, the centre of m's
//! 1/128-wide interval, so that r = m/c − 1 has |r| < 1/256; then
//! ln x = k·ln 2 + ln c + ln(1 + r), ln(1 + r) from its Taylor polynomial to r⁶ (remainder
//! below |r|⁷/7 < 2e-18). 1/c is the double nearest 1/c and r = m·(1/c) − 1 (one rounding,
//! ≤ 1.2e-16 absolute, the −1 exact); the table holds ln of that double's reciprocal, so the
//! reduction is consistent: ln x = k·ln 2 − ln(1/c) + ln(m·(1/c)). `LN_C` was computed to 40
//! digits (Python's `decimal`, `-Decimal(1/c).ln()`) and rounded to the nearest double.
//!
//! Accuracy: within 2.5e-16 + 1 ulp of ln x (tests: the C library's `ln` on every decade of
//! the normal range and on the table's envelopes). The table level needs the absolute error
//! of its coordinates small against a cell (1e-16 against cells of ~0.05 in ln P): the
//! interpolant moves by 1e-14 of a cell at most. It is not monotone at the last place: across
//! an interval's edge it can step back by an ulp (where a point then falls into the cell below,
//! at its edge, the neighbouring patches agree there to rounding: the interpolant is C¹).
//! Zero, negative, subnormal, infinite and NaN arguments are `f64::ln`'s.

/// ln(1/c_i) for c_i = 1 + (i + ½)/128, 1/c_i the double nearest (see the module doc).
#[allow(clippy::unreadable_literal, clippy::excessive_precision)]
const LN_C: [f64; 128] = [
    0.003898640415657309, 0.01165061721997525, 0.019342962843130987, 0.026976587698202083, 0.03455238150665973, 0.042071213920687044,
    0.049533935122276676, 0.05694137640013845, 0.06429435070539725, 0.07159365318700882, 0.078840061707776, 0.08603433734180316,
    0.09317722485418334, 0.10026945316367517, 0.10731173578908804, 0.11430477128005863, 0.12124924363286965, 0.12814582269193006,
    0.13499516453750482, 0.1417979118602574, 0.1485546943231372, 0.15526612891112396, 0.16193282026931324, 0.16855536102980664,
    0.17513433212784915, 0.18167030310763463, 0.18816383241818294, 0.19461546769967167, 0.2010257460605908, 0.2073951943460706,
    0.21372432939771818, 0.22001365830528213, 0.2262636786504534, 0.232474878743094, 0.238647737850175, 0.24478272641769092,
    0.25088030628580943, 0.2569409308975004, 0.26296504550088134, 0.26895308734550394, 0.2749054858727992, 0.2808226629008878,
    0.2867050328039543, 0.29255300268637746, 0.2983669725517973, 0.3041473354672968, 0.3098944777228647, 0.3156087789863033,
    0.32129061245373425, 0.3269403449958533, 0.3325583373000766, 0.3381449440087164, 0.34370051385331846, 0.3492253897852883,
    0.354719909102929, 0.3601844035750078, 0.3656191995609647, 0.37102461812787263, 0.376400975164253, 0.3817485814908484,
    0.3870677429684483, 0.3923587606028639, 0.3976219306471385, 0.4028575447010835, 0.4080658898082217, 0.41324724855021927,
    0.41840189913888387, 0.4235301155058032, 0.42863216738969867, 0.4337083204215594, 0.43875883620762796, 0.44378397241030104,
    0.4487839828270067, 0.4537591174671205, 0.4587096226269767, 0.46363574096303256, 0.46853771156323926, 0.4734157700166721,
    0.47827014848147026, 0.48310107575113576, 0.48790877731923904, 0.4926934754425752, 0.4974553892028189, 0.5021947345667155,
    0.5069117244448544, 0.5116065687490621, 0.5162794744484545, 0.5209306456241853, 0.5255602835229274, 0.5301685866091216,
    0.5347557506160276, 0.5393219685956089, 0.5438674309672835, 0.5483923255655733, 0.5528968376866776, 0.5573811501340064,
    0.5618454432626918, 0.5662898950231159, 0.5707146810034716, 0.575119974471388, 0.5795059464146423, 0.5838727655809826,
    0.588220598517086, 0.5925496096066716, 0.5968599611077938, 0.6011518131893347, 0.6054253239667169, 0.6096806495368553,
    0.6139179440123704, 0.6181373595550788, 0.6223390464087787, 0.6265231529313529, 0.6306898256261987, 0.6348392091730102,
    0.6389714464579207, 0.6430866786030273, 0.6471850449953095, 0.6512666833149582, 0.6553317295631277, 0.6593803180891278,
    0.6634125816170662, 0.6674286512719563, 0.6714286566053024, 0.6754127256201768, 0.6793809847957973, 0.6833335591116206,
    0.6872705720709603, 0.691192145724142,
];

/// 1/c_i, the double nearest, c_i = 1 + (i + ½)/128 (exact in binary).
const INV_C: [f64; 128] = {
    let mut t = [0.0; 128];
    let mut i = 0;
    while i < 128 {
        t[i] = 1.0 / (1.0 + (i as f64 + 0.5) / 128.0);
        i += 1;
    }
    t
};

/// ln 2 = LN2_HI + LN2_LO, LN2_HI with its low 32 bits zero (k·LN2_HI exact for |k| < 2^20).
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = std::f64::consts::LN_2 - LN2_HI;

/// ln x (module doc: method and accuracy). The crate calls [`ln_normal`] inside bounds it has
/// checked; this checked form is what the tests compare with `f64::ln` over all of f64.
#[cfg_attr(not(test), allow(dead_code))]
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    // Positive normal finite numbers only; everything else (and NaN, by the negated test) to
    // the library.
    if !(f64::MIN_POSITIVE..=f64::MAX).contains(&x) {
        return x.ln();
    }
    ln_normal(x)
}

/// [`ln`] of a positive normal finite `x` (anything else gives a meaningless number, never
/// undefined behaviour): for a caller that has already bounded `x`, e.g. inside an envelope.
#[inline(always)]
pub fn ln_normal(x: f64) -> f64 {
    debug_assert!((f64::MIN_POSITIVE..=f64::MAX).contains(&x), "{x}");
    let bits = x.to_bits();
    let k = (bits >> 52) as i64 - 1023;
    let i = ((bits >> 45) & 127) as usize;
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let r = m * INV_C[i] - 1.0;
    // ln(1 + r) − r = r²·(−1/2 + r/3 − r²/4 + r³/5 − r⁴/6), Estrin's pairs.
    let r2 = r * r;
    let tail = r2 * ((-0.5 + r * (1.0 / 3.0)) + r2 * ((-0.25 + r * 0.2) + r2 * (-1.0 / 6.0)));
    let kf = k as f64;
    (kf * LN2_HI + LN_C[i]) + (r + (tail + kf * LN2_LO))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One unit in the last place of `x`.
    fn ulp(x: f64) -> f64 {
        let a = x.abs();
        f64::from_bits(a.to_bits() + 1) - a
    }

    /// Within 2.5e-16 + 1 ulp of the C library's ln (itself within an ulp of ln) over every
    /// decade of the normal range, 20 000 points each, and exactly its answer outside.
    #[test]
    fn agrees_with_the_library_over_the_normal_range() {
        let mut s = 0x9e37_79b9_7f4a_7c15_u64;
        let mut u = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for decade in -307..308 {
            for _ in 0..2_000 {
                let x = 10f64.powf(f64::from(decade) + u());
                if !(f64::MIN_POSITIVE..=f64::MAX).contains(&x) {
                    continue;
                }
                let (got, want) = (ln(x), x.ln());
                let err = (got - want).abs();
                assert!(err <= 2.5e-16 + ulp(want), "ln({x:e}) = {got:e}, library {want:e}");
            }
        }
        // Interval ends and powers of two, where the reduction changes interval.
        for e in -1021..1023 {
            for f in [1.0, 1.0 + 1.0 / 128.0, 2.0 - f64::EPSILON, 1.5, std::f64::consts::SQRT_2] {
                let x = f * 2f64.powi(e);
                assert!((ln(x) - x.ln()).abs() <= 2.5e-16 + ulp(x.ln()), "{x:e}");
            }
        }
        for x in [0.0, -0.0, -1.0, 1e-310, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(ln(x).to_bits(), x.ln().to_bits(), "{x}");
        }
        assert!(ln(f64::NAN).is_nan());
    }
}
