//! The deterministic starting point of the load-sharing solve (eqs. 9, 13, 19).
//!
//! The root y* = ln(x1/x2) of [`crate::mixed::solve`] is a smooth function of ln P_T and
//! ln u (it depends on nothing else once the parameters are fixed). [`StartTable`] holds y*
//! and its two partial derivatives (the implicit function theorem at each converged node:
//! [`crate::mixed::LoadSharing::dlogit_dln_load`], [`crate::mixed::LoadSharing::dlogit_dln_speed`])
//! on a grid in (ln P_T, ln u), built once per parameter set by [`crate::Joint::new`]; a cold
//! evaluation starts Newton from the table's cubic Hermite interpolation, which is a function
//! of (P_T, u) alone. The answer is then still the root to the solver's own stopping rule
//! (only the number of iterations changes), and it is bit-identical whatever was evaluated
//! before: a host that rolls back or re-steps gets the same numbers.
//!
//! Interpolation: bicubic Hermite (tensor product of cubic Hermite in ln u and in ln P_T), the
//! node values and first derivatives exact, the mixed derivative ∂²y/∂ln P ∂ln u from central
//! differences of ∂y/∂ln P along ln u. Its error is O(h³) against the bilinear O(h²).
//!
//! Outside the grid the nearest edge value is used (still a valid start: the solve is
//! safeguarded by a bracket and converges from any finite start).

/// Grid points per decade of load and of speed.
pub const PER_DECADE: f64 = 8.0;
/// Load range of the grid, N (cut at half the asperity model's capacity).
pub const LOAD_RANGE: (f64, f64) = (1e-1, 1e8);
/// Sliding-speed range of the grid, m/s.
pub const SPEED_RANGE: (f64, f64) = (1e-8, 1e3);

/// One node of the table: the converged logit and its partial derivatives in ln P_T, ln u.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    /// y* = ln(x1/x2) at the node.
    pub y: f64,
    /// ∂y*/∂ln P_T.
    pub dy_dln_load: f64,
    /// ∂y*/∂ln u.
    pub dy_dln_speed: f64,
}

/// Converged logits on a regular grid in (ln P_T, ln u), row-major in load.
#[derive(Debug, Clone, PartialEq)]
pub struct StartTable {
    ln_p0: f64,
    dp: f64,
    np: usize,
    ln_u0: f64,
    du: f64,
    nu: usize,
    nodes: Vec<Node>,
    /// ∂²y*/∂ln P_T ∂ln u at the nodes: central differences of ∂y*/∂ln P_T along ln u
    /// (one-sided at the ends of a row).
    cross: Vec<f64>,
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

/// Cubic Hermite on [0, 1] through (0, a) and (1, b) with slopes `da`, `db` (per unit t).
#[inline]
fn hermite(t: f64, a: f64, da: f64, b: f64, db: f64) -> f64 {
    // a + t·da + t²·(3(b − a) − 2da − db) + t³·(2(a − b) + da + db), in Horner form.
    let d = b - a;
    a + t * (da + t * ((3.0 * d - 2.0 * da - db) + t * (da + db - 2.0 * d)))
}

impl StartTable {
    /// An empty table: every guess is NaN (the solve then starts from its default).
    pub fn empty() -> Self {
        Self { ln_p0: 0.0, dp: 1.0, np: 0, ln_u0: 0.0, du: 1.0, nu: 0, nodes: Vec::new(), cross: Vec::new() }
    }

    /// Solve at every node with `root(ln P, ln u, warm)`, `capacity` the largest load the
    /// model takes (N). Nodes are visited in a fixed order, each warm-started from the one
    /// before (its value plus its ln u slope times the spacing), so the table (and every answer started from it) is deterministic.
    pub fn build(capacity: f64, mut root: impl FnMut(f64, f64, Option<f64>) -> Node) -> Self {
        let p_hi = LOAD_RANGE.1.min(0.5 * capacity);
        if !(p_hi > 0.0 && p_hi.is_finite()) {
            return Self::empty();
        }
        let (ln_p0, dp, np) = axis(LOAD_RANGE.0.min(p_hi).ln(), p_hi.ln());
        let (ln_u0, du, nu) = axis(SPEED_RANGE.0.ln(), SPEED_RANGE.1.ln());
        let mut nodes = Vec::with_capacity(np * nu);
        for i in 0..np {
            let ln_p = ln_p0 + dp * i as f64;
            let mut warm = None;
            for j in 0..nu {
                let v = root(ln_p, ln_u0 + du * j as f64, warm);
                // The next node's start: first order in ln u from this one.
                warm = Some(v.y + du * v.dy_dln_speed).filter(|w| w.is_finite());
                nodes.push(v);
            }
        }
        let mut cross = vec![0.0; nodes.len()];
        if nu > 1 {
            for i in 0..np {
                let row = &nodes[i * nu..(i + 1) * nu];
                for j in 0..nu {
                    let (a, b) = (j.saturating_sub(1), (j + 1).min(nu - 1));
                    cross[i * nu + j] = (row[b].dy_dln_load - row[a].dy_dln_load) / (du * (b - a) as f64);
                }
            }
        }
        Self { ln_p0, dp, np, ln_u0, du, nu, nodes, cross }
    }

    /// The start at ln P_T = `ln_p`, ln u = `ln_u`: cubic Hermite in the grid cell (module
    /// docs), clamped to the grid. NaN when the table is empty or a corner did not converge.
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
        let (i1, j1) = ((i + 1).min(self.np - 1), (j + 1).min(self.nu - 1));
        let (v0, g0) = self.row(i * self.nu, j, j1, fu);
        let (v1, g1) = self.row(i1 * self.nu, j, j1, fu);
        let y = hermite(fp, v0, g0, v1, g1);
        if y.is_finite() {
            y
        } else {
            // A corner without derivatives (or without a root): the bilinear value (NaN if a
            // corner has no root).
            let at = |a: usize, b: usize| self.nodes[a * self.nu + b].y;
            let lo = at(i, j) + fu * (at(i, j1) - at(i, j));
            let hi = at(i1, j) + fu * (at(i1, j1) - at(i1, j));
            lo + fp * (hi - lo)
        }
    }

    /// Along ln u in the row starting at node `base`, between columns `j` and `j1` at
    /// fraction `fu`: the value and Δln P·∂y/∂ln P, each cubic Hermite.
    #[inline]
    fn row(&self, base: usize, j: usize, j1: usize, fu: f64) -> (f64, f64) {
        let (n0, n1) = (&self.nodes[base + j], &self.nodes[base + j1]);
        let v = hermite(fu, n0.y, self.du * n0.dy_dln_speed, n1.y, self.du * n1.dy_dln_speed);
        let (c0, c1) = (self.cross[base + j], self.cross[base + j1]);
        let g = hermite(fu, n0.dy_dln_load, self.du * c0, n1.dy_dln_load, self.du * c1);
        (v, self.dp * g)
    }

    /// Nodes in the table.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the table has no node.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(y: f64, dy_dln_load: f64, dy_dln_speed: f64) -> Node {
        Node { y, dy_dln_load, dy_dln_speed }
    }

    #[test]
    fn interpolation_is_exact_for_a_bicubic_like_function_and_clamped_outside() {
        // Cubic in ln u, quadratic in ln P with a mixed term linear in ln u: the scheme (cubic
        // Hermite in u, Hermite in P with ∂/∂P linear in u) reproduces it exactly.
        let f = |a: f64, b: f64| 2.0 * a - 0.5 * b + 0.1 * a * b + 0.03 * b * b * b - 0.02 * a * a + 3.0;
        let fa = |a: f64, b: f64| 2.0 + 0.1 * b - 0.04 * a;
        let fb = |a: f64, b: f64| -0.5 + 0.1 * a + 0.09 * b * b;
        let t = StartTable::build(1e30, |a, b, _| node(f(a, b), fa(a, b), fb(a, b)));
        for &(p, u) in &[(20e3, 0.1), (1.0, 1e-6), (5e7, 300.0), (123.0, 4.56)] {
            let (a, b) = (f64::ln(p), f64::ln(u));
            assert!((t.guess(a, b) - f(a, b)).abs() < 1e-9 * (1.0 + f(a, b).abs()), "{p} {u}: {} vs {}", t.guess(a, b), f(a, b));
        }
        let corner = f(LOAD_RANGE.0.ln(), SPEED_RANGE.0.ln());
        assert!((t.guess(-1e3, -1e3) - corner).abs() < 1e-9);
        assert!(t.guess(f64::NAN, 0.0).is_finite());
    }

    #[test]
    fn hermite_beats_linear_on_a_smooth_function() {
        // y = sin(ln u): the cubic start is much closer than the chord of the same cell.
        let t = StartTable::build(1e30, |_, b, _| node(b.sin(), 0.0, b.cos()));
        let (mut worst, mut worst_linear) = (0.0f64, 0.0f64);
        for k in 0..200 {
            let b = -10.0 + 0.0731 * f64::from(k);
            worst = worst.max((t.guess(5.0, b) - b.sin()).abs());
            let s = (b - t.ln_u0) / t.du;
            let (j, f) = (s.floor(), s - s.floor());
            let (b0, b1) = (t.ln_u0 + j * t.du, t.ln_u0 + (j + 1.0) * t.du);
            worst_linear = worst_linear.max((b0.sin() + f * (b1.sin() - b0.sin()) - b.sin()).abs());
        }
        assert!(worst < 0.1 * worst_linear, "{worst} vs {worst_linear}");
    }

    #[test]
    fn capacity_cuts_the_grid_and_a_zero_capacity_empties_it() {
        let t = StartTable::build(2e3, |a, _, _| node(a, 1.0, 0.0));
        assert!((t.guess(1e3f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12);
        assert!((t.guess(1e9f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12, "clamped to half the capacity");
        assert!(StartTable::build(0.0, |a, _, _| node(a, 1.0, 0.0)).guess(0.0, 0.0).is_nan());
    }

    #[test]
    fn a_corner_without_derivatives_falls_back_to_bilinear() {
        let t = StartTable::build(1e30, |a, b, _| node(a + b, f64::NAN, 1.0));
        let (a, b) = (3.3, -2.2);
        assert!((t.guess(a, b) - (a + b)).abs() < 1e-9);
    }
}
