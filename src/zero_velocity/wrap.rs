//! The angle's convention: which increment an angle input stands for.
//!
//! Multibody tools report a revolute angle in many conventions: continuous (unwrapped),
//! wrapped into (−π, π] or [0, 2π), or offset by whole turns after a reset. All of them agree
//! modulo 2π, so the presliding state takes the angle modulo 2π: the increment since the
//! reference angle θ_ref is the one of the 2π-equivalents of θ − θ_ref closest to the
//! increment the motion predicts, ω·h (the angular velocity at the last commit times the
//! step since):
//!
//! ```text
//!   Δ = ω·h + ((θ − θ_ref − ω·h + π) mod 2π) − π,      Δ ∈ [ω·h − π, ω·h + π)
//! ```
//!
//! This is the true increment of any continuous motion whose increment over the step differs
//! from ω·h by less than π: a body whose speed changes by less than π/h over the step (at
//! h = 10 ms, 314 rad/s). With the step not known (h = 0, before the first step) the rule is
//! the equivalent closest to 0, true for any motion of less than half a turn per step.
//! A continuous angle is unchanged by the rule whenever it moves by less than π more than
//! ω·h, so nothing changes for a host that does not wrap; a host that jumps the angle by more
//! than π against its ω·h is read modulo 2π.

use std::f64::consts::{PI, TAU};

/// The increment `raw` = θ − θ_ref (rad) taken modulo 2π as the equivalent closest to
/// `expected` = ω·h (rad): in [expected − π, expected + π). Any finite inputs give a finite
/// result (for |raw| beyond 2^52·2π the remainder carries no digits of the angle, but stays
/// within π of `expected`); a non-finite `expected` counts as 0.
#[inline]
pub fn increment(raw: f64, expected: f64) -> f64 {
    let e = if expected.is_finite() { expected } else { 0.0 };
    if (raw - e).abs() < PI {
        // Already the nearest: returned as is, bit for bit (a host that does not wrap).
        return raw;
    }
    let r = (raw - e + PI).rem_euclid(TAU) - PI;
    // rem_euclid may round up to TAU itself for a remainder a hair below it.
    let r = if r >= PI { r - TAU } else { r };
    e + r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A continuous angle, wrapped into (−π, π] by the host, gives the true increment.
    #[test]
    fn a_wrapped_angle_gives_the_true_increment() {
        let wrap = |x: f64| {
            let w = (x + PI).rem_euclid(TAU) - PI;
            if w == -PI { PI } else { w }
        };
        let h = 1e-3;
        for k in 0..20_000 {
            let omega = 0.1 + 0.01 * f64::from(k % 7);
            let t = f64::from(k) * h;
            let (a, b) = (3.0 + omega * t, 3.0 + omega * (t + h));
            let d = increment(wrap(b) - wrap(a), omega * h);
            assert!((d - omega * h).abs() < 1e-9, "{k}: {d}");
        }
    }

    /// Property: the result is a 2π-equivalent of `raw` within π of `expected`.
    #[test]
    fn the_result_is_the_nearest_equivalent() {
        let mut x = 0x1234_5678_u64;
        let mut draw = || {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..100_000 {
            let raw = (draw() - 0.5) * 200.0;
            let expected = (draw() - 0.5) * 20.0;
            let d = increment(raw, expected);
            assert!(d >= expected - PI - 1e-12 && d < expected + PI + 1e-12, "{raw} {expected} {d}");
            let turns = (raw - d) / TAU;
            assert!((turns - turns.round()).abs() < 1e-9, "{raw} {expected} {d}");
        }
        assert_eq!(increment(0.0, 0.0), 0.0);
        assert_eq!(increment(1e-4, 0.0), 1e-4);
        assert!(increment(1e300, 0.0).abs() <= PI);
        assert!(increment(1.0, f64::NAN).abs() <= PI);
    }
}
