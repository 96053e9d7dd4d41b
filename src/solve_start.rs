//! The deterministic starting point of the load-sharing solve (eqs. 9, 13, 19).
//!
//! The root y* = ln(x1/x2) of [`crate::mixed::solve`] is a smooth function of ln P_T and
//! ln u (it depends on nothing else once the parameters are fixed). [`StartTable`] holds y*
//! on a grid in (ln P_T, ln u), built once per parameter set by [`crate::Joint::new`]; a
//! cold evaluation starts Newton from the table's bilinear interpolation, which is a function
//! of (P_T, u) alone. The answer is then still the root to the solver's own stopping rule
//! (only the number of iterations changes), and it is bit-identical whatever was evaluated
//! before: a host that rolls back or re-steps gets the same numbers.
//!
//! Outside the grid the nearest edge value is used (still a valid start: the solve is
//! safeguarded by a bracket and converges from any finite start).

/// Grid points per decade of load and of speed.
pub const PER_DECADE: f64 = 3.0;
/// Load range of the grid, N (cut at half the asperity model's capacity).
pub const LOAD_RANGE: (f64, f64) = (1e-1, 1e8);
/// Sliding-speed range of the grid, m/s.
pub const SPEED_RANGE: (f64, f64) = (1e-8, 1e3);

/// Converged logits on a regular grid in (ln P_T, ln u), row-major in load.
#[derive(Debug, Clone, PartialEq)]
pub struct StartTable {
    ln_p0: f64,
    dp: f64,
    np: usize,
    ln_u0: f64,
    du: f64,
    nu: usize,
    y: Vec<f64>,
}

/// Nodes from `lo` to `hi` (logarithms), `PER_DECADE` a decade: (first, spacing, count).
#[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(hi > lo)` also catches NaN; kept as written
fn axis(lo: f64, hi: f64) -> (f64, f64, usize) {
    if !(hi > lo) {
        return (lo, 1.0, 1);
    }
    let n = ((hi - lo) / std::f64::consts::LN_10 * PER_DECADE).ceil().max(1.0) as usize + 1;
    (lo, (hi - lo) / (n - 1) as f64, n)
}

impl StartTable {
    /// An empty table: every guess is NaN (the solve then starts from its default).
    pub fn empty() -> Self {
        Self { ln_p0: 0.0, dp: 1.0, np: 0, ln_u0: 0.0, du: 1.0, nu: 0, y: Vec::new() }
    }

    /// Solve at every node with `root(ln P, ln u, warm)`, `capacity` the largest load the
    /// model takes (N). Nodes are visited in a fixed order, each warm-started from the one
    /// before, so the table (and every answer started from it) is deterministic.
    pub fn build(capacity: f64, mut root: impl FnMut(f64, f64, Option<f64>) -> f64) -> Self {
        let p_hi = LOAD_RANGE.1.min(0.5 * capacity);
        if !(p_hi > 0.0 && p_hi.is_finite()) {
            return Self::empty();
        }
        let (ln_p0, dp, np) = axis(LOAD_RANGE.0.min(p_hi).ln(), p_hi.ln());
        let (ln_u0, du, nu) = axis(SPEED_RANGE.0.ln(), SPEED_RANGE.1.ln());
        let mut y = Vec::with_capacity(np * nu);
        for i in 0..np {
            let ln_p = ln_p0 + dp * i as f64;
            let mut warm = None;
            for j in 0..nu {
                let v = root(ln_p, ln_u0 + du * j as f64, warm);
                warm = v.is_finite().then_some(v);
                y.push(v);
            }
        }
        Self { ln_p0, dp, np, ln_u0, du, nu, y }
    }

    /// The start at ln P_T = `ln_p`, ln u = `ln_u`: bilinear in the grid cell, clamped to
    /// the grid. NaN when the table is empty or a corner did not converge.
    #[inline]
    pub fn guess(&self, ln_p: f64, ln_u: f64) -> f64 {
        if self.np == 0 || self.nu == 0 {
            return f64::NAN;
        }
        let cell = |x: f64, x0: f64, dx: f64, n: usize| -> (usize, f64) {
            if n < 2 {
                return (0, 0.0);
            }
            let s = ((x - x0) / dx).clamp(0.0, (n - 1) as f64);
            let s = if s.is_nan() { 0.0 } else { s };
            let i = (s as usize).min(n - 2);
            (i, s - i as f64)
        };
        let (i, fp) = cell(ln_p, self.ln_p0, self.dp, self.np);
        let (j, fu) = cell(ln_u, self.ln_u0, self.du, self.nu);
        let at = |a: usize, b: usize| self.y[a.min(self.np - 1) * self.nu + b.min(self.nu - 1)];
        let lo = at(i, j) + fu * (at(i, j + 1) - at(i, j));
        let hi = at(i + 1, j) + fu * (at(i + 1, j + 1) - at(i + 1, j));
        lo + fp * (hi - lo)
    }

    /// Nodes in the table.
    pub fn len(&self) -> usize {
        self.y.len()
    }

    /// Whether the table has no node.
    pub fn is_empty(&self) -> bool {
        self.y.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_is_exact_for_a_bilinear_function_and_clamped_outside() {
        let f = |a: f64, b: f64| 2.0 * a - 0.5 * b + 0.1 * a * b + 3.0;
        let t = StartTable::build(1e30, |a, b, _| f(a, b));
        for &(p, u) in &[(20e3, 0.1), (1.0, 1e-6), (5e7, 300.0), (123.0, 4.56)] {
            let (a, b) = (f64::ln(p), f64::ln(u));
            assert!((t.guess(a, b) - f(a, b)).abs() < 1e-9 * (1.0 + f(a, b).abs()), "{p} {u}");
        }
        let corner = f(LOAD_RANGE.0.ln(), SPEED_RANGE.0.ln());
        assert!((t.guess(-1e3, -1e3) - corner).abs() < 1e-9);
        assert!(t.guess(f64::NAN, 0.0).is_finite());
    }

    #[test]
    fn capacity_cuts_the_grid_and_a_zero_capacity_empties_it() {
        let t = StartTable::build(2e3, |a, _, _| a);
        assert!((t.guess(1e3f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12);
        assert!((t.guess(1e9f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12, "clamped to half the capacity");
        assert!(StartTable::build(0.0, |a, _, _| a).guess(0.0, 0.0).is_nan());
    }
}
