//! Monotone, C¹ piecewise-cubic (Hermite) interpolation with Steffen's slopes (Steffen,
//! 1990, "A simple method for monotonic interpolation in one dimension", Astron. Astrophys.
//! 239, 443–450): between nodes the cubic is monotone when the data are, and the slope at a
//! node is never zero between strictly monotone data, so the interpolant is strictly
//! monotone. Outside the nodes it continues with the end slope (linear), so it is C¹
//! everywhere. Used by [`super::table`] in the coordinates (ln S, logit ε), where the
//! asymptotes are straight lines.

/// A monotone cubic Hermite interpolant on ascending nodes, linear beyond them.
#[derive(Debug, Clone, PartialEq)]
pub struct Monotone {
    x: Vec<f64>,
    y: Vec<f64>,
    d: Vec<f64>,
}

impl Monotone {
    /// The interpolant through (`x`, `y`), `x` strictly ascending, `y` monotone, at least two
    /// nodes (the caller guarantees it; fewer or unordered nodes give `None`).
    pub fn new(x: Vec<f64>, y: Vec<f64>) -> Option<Self> {
        Self::with_last_slope(x, y, None)
    }

    /// As [`Self::new`], with the slope at the last node prescribed (`Some`), e.g. from a
    /// known asymptote; `None`: the last interval's secant.
    pub fn with_last_slope(x: Vec<f64>, y: Vec<f64>, last: Option<f64>) -> Option<Self> {
        let n = x.len();
        if n < 2 || y.len() != n || x.windows(2).any(|w| !(w[1] > w[0])) || y.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let s: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
        let mut d = vec![0.0; n];
        d[0] = s[0];
        d[n - 1] = last.unwrap_or(s[n - 2]);
        for i in 1..n - 1 {
            let p = (s[i - 1] * h[i] + s[i] * h[i - 1]) / (h[i - 1] + h[i]);
            d[i] = (s[i - 1].signum() + s[i].signum()) * s[i - 1].abs().min(s[i].abs()).min(0.5 * p.abs());
        }
        Some(Self { x, y, d })
    }

    /// Value and derivative at `t` (linear beyond the end nodes, with the end slopes).
    pub fn eval(&self, t: f64) -> (f64, f64) {
        let n = self.x.len();
        if t <= self.x[0] {
            return (self.y[0] + self.d[0] * (t - self.x[0]), self.d[0]);
        }
        if t >= self.x[n - 1] {
            return (self.y[n - 1] + self.d[n - 1] * (t - self.x[n - 1]), self.d[n - 1]);
        }
        if t.is_nan() {
            return (f64::NAN, f64::NAN);
        }
        // The interval x[i] ≤ t < x[i+1].
        let i = self.x.partition_point(|&v| v <= t).saturating_sub(1).min(n - 2);
        let h = self.x[i + 1] - self.x[i];
        let u = (t - self.x[i]) / h;
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.d[i] * h, self.d[i + 1] * h);
        let u2 = u * u;
        let u3 = u2 * u;
        let v = (2.0 * u3 - 3.0 * u2 + 1.0) * y0 + (u3 - 2.0 * u2 + u) * d0 + (-2.0 * u3 + 3.0 * u2) * y1 + (u3 - u2) * d1;
        let dv = ((6.0 * u2 - 6.0 * u) * (y0 - y1) + (3.0 * u2 - 4.0 * u + 1.0) * d0 + (3.0 * u2 - 2.0 * u) * d1) / h;
        (v, dv)
    }

    /// The first and last node abscissae.
    pub fn range(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }

    /// The node values at the first and last nodes and the end slopes.
    pub fn ends(&self) -> ((f64, f64), (f64, f64)) {
        let n = self.x.len();
        ((self.y[0], self.d[0]), (self.y[n - 1], self.d[n - 1]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn reproduces_a_cubic_closely_and_a_line_exactly() {
        let x: Vec<f64> = (0..20).map(|i| i as f64 * 0.25).collect();
        let line: Vec<f64> = x.iter().map(|v| 3.0 - 2.0 * v).collect();
        let m = Monotone::new(x.clone(), line).unwrap();
        for i in 0..100 {
            let t = -1.0 + i as f64 * 0.07;
            let (v, d) = m.eval(t);
            assert!((v - (3.0 - 2.0 * t)).abs() < 1e-12 && (d + 2.0).abs() < 1e-12);
        }
        let cube: Vec<f64> = x.iter().map(|v| v.powi(3)).collect();
        let m = Monotone::new(x, cube).unwrap();
        let (v, _) = m.eval(2.1);
        assert!((v - 2.1f64.powi(3)).abs() < 0.02, "{v}");
    }

    proptest! {
        /// Strictly decreasing data give a strictly decreasing interpolant whose derivative
        /// matches its finite difference (C¹, no sign change).
        #[test]
        fn strictly_monotone_and_consistent(steps in proptest::collection::vec((0.05f64..2.0, 0.01f64..3.0), 2..12), t in -3.0f64..30.0) {
            let mut x = vec![0.0];
            let mut y = vec![0.0];
            for (dx, dy) in &steps {
                x.push(x.last().unwrap() + dx);
                y.push(y.last().unwrap() - dy);
            }
            let m = Monotone::new(x, y).unwrap();
            let (v0, d0) = m.eval(t);
            let (v1, _) = m.eval(t + 1e-6);
            prop_assert!(d0 < 0.0);
            prop_assert!(v1 < v0);
            prop_assert!(((v1 - v0) / 1e-6 - d0).abs() < 1e-3 * (1.0 + d0.abs()));
        }
    }
}
