//! Numbers in CSV output: the shortest text that parses back to the same f64, exactly as
//! Rust's `{:?}` prints it (the form every CSV of this tool has always had), but several
//! times faster: the digits come from `zmij` (shortest round-trip, Ryū-like), and the two
//! places where its layout differs from `{:?}` are rewritten:
//! - `zmij` writes a positive exponent as `e+301`, `{:?}` as `e301`;
//! - for 1e-5 <= |v| < 1e-4 `zmij` writes the decimal form `0.0000352`, `{:?}` the
//!   scientific `3.52e-5` (`{:?}` is decimal from 1e-4 to 1e16, scientific outside).
//!
//! Both print a shortest digit string, the one nearest the exact value; they differ only on
//! an exact tie between two shortest candidates (`{:?}` rounds the tie up, `zmij` to even,
//! e.g. 216486192242783.625 -> `…83.63` against `…83.62`). A tie needs the exact binary
//! value to have at most 18 significant decimal digits; `tie_impossible` proves from the
//! bits that it has more, and any other value goes through `{:?}` itself (integers beyond
//! 2^53 and values with few significant bits: rare among computed results).
//! `tests` compares the two over millions of doubles of every magnitude.

/// Append the `{:?}` text of `v` to `out`. Non-finite values (never written by the model,
/// which checks its outputs) go through `{:?}` itself.
pub fn push_exact(out: &mut Vec<u8>, v: f64) {
    if !v.is_finite() || !tie_impossible(v) {
        out.extend_from_slice(format!("{v:?}").as_bytes());
        return;
    }
    let mut buf = zmij::Buffer::new();
    let s = buf.format_finite(v).as_bytes();
    let a = v.abs();
    // Shortest digits from 1e-4 to below 1e15 stay in fixed notation in both (no exponent).
    if (1e-4..1e15).contains(&a) {
        out.extend_from_slice(s);
        return;
    }
    if (1e-5..1e-4).contains(&a) {
        // "-0.0000ddd" -> "-d.dde-5" (shortest digits d, at least one).
        let (sign, rest) = if v < 0.0 { (&b"-"[..], &s[1..]) } else { (&b""[..], s) };
        debug_assert!(rest.starts_with(b"0.0000"), "{v:?}");
        let digits = &rest[6..];
        out.extend_from_slice(sign);
        out.push(digits[0]);
        if digits.len() > 1 {
            out.push(b'.');
            out.extend_from_slice(&digits[1..]);
        }
        out.extend_from_slice(b"e-5");
    } else if let Some(i) = s.iter().position(|&b| b == b'+') {
        out.extend_from_slice(&s[..i]);
        out.extend_from_slice(&s[i + 1..]);
    } else {
        out.extend_from_slice(s);
    }
}

/// Whether the exact value of `v` = m·2^e (m odd) has at least 19 significant decimal
/// digits, so that no two 17-or-fewer-digit decimals can be equally near it. For e < 0 the
/// exact decimal digits are those of m·5^(−e); their count is estimated by logarithms with a
/// margin of half a digit. Integers (e >= 0) and zero answer false/true conservatively.
fn tie_impossible(v: f64) -> bool {
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mut m, mut e) = if exp == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp - 1075) };
    if m == 0 {
        return true;
    }
    let tz = m.trailing_zeros();
    m >>= tz;
    e += tz as i32;
    if e >= 0 {
        return false;
    }
    // log10 m ≥ 0 (m ≥ 1): from −e ≥ 27 the second term alone is ≥ 18.87 (no logarithm needed).
    if e <= -27 {
        return true;
    }
    (m as f64).log10() + f64::from(-e) * std::f64::consts::LOG10_2.mul_add(-1.0, 1.0) >= 18.5
}

/// The `{:?}` text of `v` as a String (see [`push_exact`]).
pub fn exact_string(v: f64) -> String {
    let mut out = Vec::with_capacity(24);
    push_exact(&mut out, v);
    // Only ASCII digits, signs, '.', 'e' and "inf"/"NaN" are ever written.
    String::from_utf8(out).unwrap_or_else(|_| format!("{v:?}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(v: f64) {
        let mut out = Vec::new();
        push_exact(&mut out, v);
        assert_eq!(std::str::from_utf8(&out).unwrap(), format!("{v:?}"), "bits {:#x}", v.to_bits());
    }

    #[test]
    // The tie literals are written as the decimal expansions the test is about; shortening them
    // (what the lint asks) would hide which ties they are.
    #[allow(clippy::excessive_precision)]
    fn same_text_as_debug_at_every_magnitude_and_boundary() {
        for e in -325..=308 {
            for m in [1.0, 1.5, 2.0, 9.99, 9.999999999999998, 3.524486419174144, 5.0, 7.2] {
                let v = m * 10f64.powi(e);
                check(v);
                check(-v);
                check(f64::from_bits(v.to_bits().wrapping_add(1)));
                check(f64::from_bits(v.to_bits().wrapping_sub(1)));
            }
        }
        // Exact ties between two shortest candidates ({:?} rounds them up).
        for v in [216486192242783.625, -34900697272382.8125, 1500000000000000.25, f64::from_bits(0x431550f7dca70001)] {
            check(v);
        }
        for v in [0.0, -0.0, 1e-4, 1e-5, 1e16, 1e15, f64::MIN_POSITIVE, 5e-324, f64::MAX, f64::MIN, f64::EPSILON] {
            check(v);
        }
        for v in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            check(v);
        }
    }

    #[test]
    fn same_text_as_debug_over_random_bit_patterns_and_decades() {
        let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for _ in 0..300_000 {
            check(f64::from_bits(next()));
            // Uniform in [1e-7, 1e-3): the decade where the layouts differ, and its neighbours.
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            check(1e-7 * 10f64.powf(4.0 * u));
            check(-1e-7 * 10f64.powf(4.0 * u));
            // 1e13 to 1e16, where ties with a fractional part exist.
            check(1e13 * 10f64.powf(3.0 * u));
        }
    }
}
