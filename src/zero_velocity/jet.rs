//! Forward-mode derivatives for the presliding law: a [`Jet`] carries a value and its
//! partial derivatives with respect to three inputs, and the law is written once over the
//! [`Scalar`] trait, so its `f64` instance (the hot path of every step) is plain arithmetic
//! and its [`Jet`] instance gives the exact partials the FMU's directional derivatives
//! report.
//!
//! Hand-written rather than the `num-dual` crate: the law needs six operations
//! (`+ − × ÷`, `exp`, `sqrt`) on `Copy` values, while `num-dual`'s `DualNum` trait brings its own
//! nalgebra major version and a `Clone`-only API for a few dozen lines of arithmetic.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// What the law needs of a number: arithmetic, `exp`, its real part (for branching) and
/// constants. Implemented by `f64` and [`Jet`].
pub trait Scalar: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self> {
    /// Whether the type carries a value alone (no derivatives): then an expression whose value
    /// is known may be answered without evaluating it (e.g. `b − 0·e^x` is b whatever x).
    const VALUE_ONLY: bool;
    /// A constant (zero derivatives).
    fn c(x: f64) -> Self;
    /// The value (the real part).
    fn re(self) -> f64;
    /// e^self.
    fn exp(self) -> Self;
    /// √self (self ≥ 0).
    fn sqrt(self) -> Self;
}

impl Scalar for f64 {
    const VALUE_ONLY: bool = true;
    #[inline]
    fn c(x: f64) -> Self {
        x
    }
    #[inline]
    fn re(self) -> f64 {
        self
    }
    #[inline]
    fn exp(self) -> Self {
        f64::exp(self)
    }
    #[inline]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
}

/// A value with its partial derivatives with respect to three inputs (which three is the
/// caller's convention, e.g. angle, angular velocity and load).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// The value.
    pub v: f64,
    /// ∂v/∂x_i.
    pub d: [f64; 3],
}

impl Jet {
    /// The input `i` (0, 1 or 2) at value `v`: ∂/∂x_i = 1, the others 0.
    pub fn var(v: f64, i: usize) -> Self {
        let mut d = [0.0; 3];
        d[i] = 1.0;
        Jet { v, d }
    }

    /// A value with the given partials.
    pub fn with(v: f64, d: [f64; 3]) -> Self {
        Jet { v, d }
    }

    fn map(self, v: f64, f: impl Fn(f64) -> f64) -> Self {
        Jet { v, d: self.d.map(f) }
    }
}

impl Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        Jet { v: self.v + o.v, d: [self.d[0] + o.d[0], self.d[1] + o.d[1], self.d[2] + o.d[2]] }
    }
}
impl Sub for Jet {
    type Output = Jet;
    fn sub(self, o: Jet) -> Jet {
        Jet { v: self.v - o.v, d: [self.d[0] - o.d[0], self.d[1] - o.d[1], self.d[2] - o.d[2]] }
    }
}
#[allow(clippy::suspicious_arithmetic_impl)] // the product rule
impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        let d = std::array::from_fn(|i| self.d[i] * o.v + self.v * o.d[i]);
        Jet { v: self.v * o.v, d }
    }
}
#[allow(clippy::suspicious_arithmetic_impl)] // the quotient rule
impl Div for Jet {
    type Output = Jet;
    fn div(self, o: Jet) -> Jet {
        let v = self.v / o.v;
        let d = std::array::from_fn(|i| (self.d[i] - v * o.d[i]) / o.v);
        Jet { v, d }
    }
}
impl Neg for Jet {
    type Output = Jet;
    fn neg(self) -> Jet {
        self.map(-self.v, |x| -x)
    }
}

impl Scalar for Jet {
    const VALUE_ONLY: bool = false;
    fn c(x: f64) -> Self {
        Jet { v: x, d: [0.0; 3] }
    }
    fn re(self) -> f64 {
        self.v
    }
    fn exp(self) -> Self {
        let e = self.v.exp();
        self.map(e, |x| x * e)
    }
    fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        // d√v = dv/(2√v); at v = 0 the derivative is unbounded: 0 there (a value the callers
        // never differentiate: the law takes √(k·J) only for a loaded joint, k > 0).
        let f = if r > 0.0 { 0.5 / r } else { 0.0 };
        self.map(r, |x| x * f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rules against central differences of a composite function of three inputs.
    #[test]
    fn partials_match_central_differences() {
        fn f<S: Scalar>(x: S, y: S, z: S) -> S {
            (x * y - z).exp() / (y + S::c(2.0)) - (-x) * z + (x * x + z).sqrt()
        }
        let p = [0.3, -0.7, 1.1];
        let j = f(Jet::var(p[0], 0), Jet::var(p[1], 1), Jet::var(p[2], 2));
        assert_eq!(j.v, f(p[0], p[1], p[2]));
        for i in 0..3 {
            let h = 1e-6;
            let (mut a, mut b) = (p, p);
            a[i] += h;
            b[i] -= h;
            let fd = (f(a[0], a[1], a[2]) - f(b[0], b[1], b[2])) / (2.0 * h);
            assert!((j.d[i] - fd).abs() < 1e-8, "input {i}: {} vs {fd}", j.d[i]);
        }
    }
}
