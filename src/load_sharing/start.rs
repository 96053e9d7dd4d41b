//! The deterministic starting point of the load-sharing solve (eqs. 9, 13, 19).
//!
//! The root y* = ln(x1/x2) of [`crate::load_sharing::solve::solve`] is a smooth function of ln P_T and
//! ln u (it depends on nothing else once the parameters are fixed). [`StartTable`] holds y*
//! and its two partial derivatives (the implicit function theorem at each converged node:
//! [`crate::load_sharing::solve::LoadSharing::dlogit_dln_load`], [`crate::load_sharing::solve::LoadSharing::dlogit_dln_speed`])
//! on a grid in (ln P_T, ln u), 8 nodes a decade, one row of speeds per load, each row solved
//! the first time a start is asked for at a load next to it (so [`crate::Joint::new`] solves
//! nothing, and a host that stays in 5–60 kN solves the 11 rows there); a cold evaluation
//! starts the solve from the table's cubic Hermite interpolation, which is a function of
//! (P_T, u) alone. The answer is then still the root to the solver's own stopping rule (only
//! the number of iterations changes), and it is bit-identical whatever was evaluated before:
//! a host that rolls back or re-steps gets the same numbers. The start is within 1e-6 of the
//! root at 20 kN, 6 rad/s and within [`crate::load_sharing::solve::THIRD_ORDER_ACCEPT`] over most of the
//! boundary and mixed regimes, where the solve then takes one residual evaluation.
//!
//! Interpolation: bicubic Hermite (tensor product of cubic Hermite in ln u and in ln P_T), the
//! node values and first derivatives exact, the mixed derivative ∂²y/∂ln P ∂ln u from central
//! differences of ∂y/∂ln P along ln u. Its error is O(h³) against the bilinear O(h²).
//!
//! Outside the grid the nearest edge value is used (still a valid start: the solve is
//! safeguarded by a bracket and converges from any finite start).

use std::sync::OnceLock;

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

/// Converged logits on a regular grid in (ln P_T, ln u): one row of speeds per load, each
/// row solved on first use ([`StartTable::guess`]) and kept.
///
/// A row is a function of its load alone (its nodes are solved in a fixed order, each
/// warm-started from the one before), so the table, and every answer started from it, is
/// the same whichever rows were built before and in whichever order: it is deterministic
/// whatever the history of calls, also across threads.
#[derive(Debug, Clone)]
pub struct StartTable {
    ln_p0: f64,
    dp: f64,
    np: usize,
    ln_u0: f64,
    du: f64,
    nu: usize,
    rows: Vec<OnceLock<Row>>,
}

/// Two tables are equal when their grids are: the rows are functions of the grid and of the
/// solve, which is the owner's to compare ([`crate::Joint`] compares its parameters).
impl PartialEq for StartTable {
    fn eq(&self, other: &Self) -> bool {
        (self.ln_p0, self.dp, self.np, self.ln_u0, self.du, self.nu) == (other.ln_p0, other.dp, other.np, other.ln_u0, other.du, other.nu)
    }
}

/// One load's nodes along ln u, with ∂²y*/∂ln P_T ∂ln u at each: central differences of
/// ∂y*/∂ln P_T along ln u (one-sided at the ends).
#[derive(Debug, Clone, PartialEq)]
struct Row {
    nodes: Vec<Node>,
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

/// The cell of `x` on the axis (first `x0`, spacing `dx`, `n` nodes): its first node and the
/// fraction across it, clamped to the axis (NaN: the first cell).
#[inline]
fn cell(x: f64, x0: f64, dx: f64, n: usize) -> (usize, f64) {
    if n < 2 {
        return (0, 0.0);
    }
    let s = ((x - x0) / dx).clamp(0.0, (n - 1) as f64);
    let s = if s.is_nan() { 0.0 } else { s };
    let i = (s as usize).min(n - 2);
    (i, s - i as f64)
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
        Self { ln_p0: 0.0, dp: 1.0, np: 0, ln_u0: 0.0, du: 1.0, nu: 0, rows: Vec::new() }
    }

    /// The grid for a model whose largest load is `capacity` (N), no row solved yet: rows
    /// are solved on first use by the `root` given to [`StartTable::guess`].
    pub fn new(capacity: f64) -> Self {
        let p_hi = LOAD_RANGE.1.min(0.5 * capacity);
        if !(p_hi > 0.0 && p_hi.is_finite()) {
            return Self::empty();
        }
        let (ln_p0, dp, np) = axis(LOAD_RANGE.0.min(p_hi).ln(), p_hi.ln());
        let (ln_u0, du, nu) = axis(SPEED_RANGE.0.ln(), SPEED_RANGE.1.ln());
        Self { ln_p0, dp, np, ln_u0, du, nu, rows: (0..np).map(|_| OnceLock::new()).collect() }
    }

    /// [`StartTable::new`] with every row solved now by `root(ln P, ln u, warm)`.
    pub fn build(capacity: f64, root: impl Fn(f64, f64, Option<f64>) -> Node) -> Self {
        let t = Self::new(capacity);
        for i in 0..t.np {
            t.row(i, &root);
        }
        t
    }

    /// Row `i`, solved now with `root` if it was not yet: nodes in order of speed, each
    /// warm-started from the one before (its value plus its ln u slope times the spacing).
    #[inline]
    fn row(&self, i: usize, root: &impl Fn(f64, f64, Option<f64>) -> Node) -> &Row {
        self.rows[i].get_or_init(|| {
            let ln_p = self.ln_p0 + self.dp * i as f64;
            let mut warm = None;
            let nodes: Vec<Node> = (0..self.nu)
                .map(|j| {
                    let v = root(ln_p, self.ln_u0 + self.du * j as f64, warm);
                    // The next node's start: first order in ln u from this one.
                    warm = Some(v.y + self.du * v.dy_dln_speed).filter(|w| w.is_finite());
                    v
                })
                .collect();
            let nu = self.nu;
            let cross = (0..nu)
                .map(|j| {
                    if nu < 2 {
                        return 0.0;
                    }
                    let (a, b) = (j.saturating_sub(1), (j + 1).min(nu - 1));
                    (nodes[b].dy_dln_load - nodes[a].dy_dln_load) / (self.du * (b - a) as f64)
                })
                .collect();
            Row { nodes, cross }
        })
    }

    /// The start at ln P_T = `ln_p`, ln u = `ln_u`: cubic Hermite in the grid cell (module
    /// docs), clamped to the grid; the two rows of the cell are solved with `root` first if
    /// they were not yet. NaN when the table is empty or a corner did not converge.
    #[inline]
    pub fn guess(&self, ln_p: f64, ln_u: f64, root: impl Fn(f64, f64, Option<f64>) -> Node) -> f64 {
        if self.np == 0 || self.nu == 0 {
            return f64::NAN;
        }
        let (i, fp) = cell(ln_p, self.ln_p0, self.dp, self.np);
        let (j, fu) = cell(ln_u, self.ln_u0, self.du, self.nu);
        let (i1, j1) = ((i + 1).min(self.np - 1), (j + 1).min(self.nu - 1));
        let (r0, r1) = (self.row(i, &root), self.row(i1, &root));
        let (v0, g0) = self.along(r0, j, j1, fu);
        let (v1, g1) = self.along(r1, j, j1, fu);
        let y = hermite(fp, v0, g0, v1, g1);
        if y.is_finite() {
            y
        } else {
            // A corner without derivatives (or without a root): the bilinear value (NaN if a
            // corner has no root).
            let lo = r0.nodes[j].y + fu * (r0.nodes[j1].y - r0.nodes[j].y);
            let hi = r1.nodes[j].y + fu * (r1.nodes[j1].y - r1.nodes[j].y);
            lo + fp * (hi - lo)
        }
    }

    /// Along ln u in `row`, between columns `j` and `j1` at fraction `fu`: the value and
    /// Δln P·∂y/∂ln P, each cubic Hermite.
    #[inline]
    fn along(&self, row: &Row, j: usize, j1: usize, fu: f64) -> (f64, f64) {
        let (n0, n1) = (&row.nodes[j], &row.nodes[j1]);
        let v = hermite(fu, n0.y, self.du * n0.dy_dln_speed, n1.y, self.du * n1.dy_dln_speed);
        let (c0, c1) = (row.cross[j], row.cross[j1]);
        let g = hermite(fu, n0.dy_dln_load, self.du * c0, n1.dy_dln_load, self.du * c1);
        (v, self.dp * g)
    }

    /// The table at one load ln P_T = `ln_p`, for many starts at that load ([`StartCut`],
    /// read with [`StartTable::cut_guess`]).
    pub fn cut(&self, ln_p: f64) -> StartCut {
        let mut cut = StartCut { ln_p, row: 0, fp: 0.0, columns: Vec::new() };
        self.recut(&mut cut, ln_p);
        cut
    }

    /// Move `cut` to this table at ln P_T = `ln_p`, keeping its allocation: the same cut as
    /// [`StartTable::cut`] there.
    pub fn recut(&self, cut: &mut StartCut, ln_p: f64) {
        let (row, fp) = cell(ln_p, self.ln_p0, self.dp, self.np);
        (cut.ln_p, cut.row, cut.fp) = (ln_p, row, fp);
        cut.columns.clear();
        cut.columns.resize(self.nu, None);
    }

    /// The start of [`StartTable::guess`] at (the cut's load, ln u = `ln_u`), to rounding,
    /// from the cut (its nodes there computed first if they were not yet, and the table's
    /// two rows there solved with `root` if they were not yet). NaN when the table is empty,
    /// when the cut is not of a table of this size (a cut of another table of the same size
    /// is read: it is the caller's to keep a cut with its table), and where the bicubic is not finite (a
    /// corner without derivatives: [`StartTable::guess`] then falls back to bilinear).
    #[inline]
    pub fn cut_guess(&self, cut: &mut StartCut, ln_u: f64, root: impl Fn(f64, f64, Option<f64>) -> Node) -> f64 {
        if self.np == 0 || cut.columns.len() != self.nu || cut.row >= self.np {
            return f64::NAN;
        }
        let (j, fu) = cell(ln_u, self.ln_u0, self.du, self.nu);
        let j1 = (j + 1).min(self.nu - 1);
        let (a, da) = match cut.columns[j] {
            Some(c) => c,
            None => self.cut_column(cut, j, &root),
        };
        let (b, db) = match cut.columns[j1] {
            Some(c) => c,
            None => self.cut_column(cut, j1, &root),
        };
        hermite(fu, a, da, b, db)
    }

    /// The cut's node `j`, computed and kept: the bicubic's value and scaled ln u slope at
    /// (its load, node j).
    #[cold]
    #[inline(never)]
    fn cut_column(&self, cut: &mut StartCut, j: usize, root: &impl Fn(f64, f64, Option<f64>) -> Node) -> (f64, f64) {
        let (r0, r1) = (self.row(cut.row, root), self.row((cut.row + 1).min(self.np - 1), root));
        let (n0, n1) = (&r0.nodes[j], &r1.nodes[j]);
        let (dp, du) = (self.dp, self.du);
        let y = hermite(cut.fp, n0.y, dp * n0.dy_dln_load, n1.y, dp * n1.dy_dln_load);
        let s = hermite(cut.fp, du * n0.dy_dln_speed, dp * (du * r0.cross[j]), du * n1.dy_dln_speed, dp * (du * r1.cross[j]));
        cut.columns[j] = Some((y, s));
        (y, s)
    }


    /// Nodes in the table (solved or not).
    pub fn len(&self) -> usize {
        self.np * self.nu
    }

    /// Nodes solved so far.
    pub fn solved(&self) -> usize {
        self.rows.iter().filter(|r| r.get().is_some()).count() * self.nu
    }

    /// Whether the table has no node.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// [`StartTable::guess`] at one load, for a host that starts many solves there (the rig at a
/// constant load), read with [`StartTable::cut_guess`]: a cubic Hermite along ln u through
/// the cut's nodes, each node's value and ln u slope being the bicubic's at this load,
/// computed on first use and kept.
///
/// The bicubic is linear in its node data, so at a fixed ln P_T it *is* a cubic Hermite in
/// ln u, whose node values are the Hermite in ln P_T of the two rows' values and ln P_T
/// slopes, and whose node slopes are the Hermite in ln P_T of the rows' ln u slopes and
/// mixed derivatives: the same start as [`StartTable::guess`] to rounding, at one Hermite
/// an evaluation instead of five. Each node is a function of the load (and the table)
/// alone, so a start is the same whichever starts came before, and whether the cut is new
/// or kept: deterministic, as the table's.
#[derive(Debug, Clone, PartialEq)]
pub struct StartCut {
    ln_p: f64,
    /// The table row below the load, and the fraction of the way to the next.
    row: usize,
    fp: f64,
    /// (value, Δln u·∂y/∂ln u) at each ln u node, once computed.
    columns: Vec<Option<(f64, f64)>>,
}

impl StartCut {
    /// ln P_T of the cut.
    pub fn ln_load(&self) -> f64 {
        self.ln_p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(y: f64, dy_dln_load: f64, dy_dln_speed: f64) -> Node {
        Node { y, dy_dln_load, dy_dln_speed }
    }

    /// The start from a table whose rows are all solved (by `build`).
    fn at(t: &StartTable, ln_p: f64, ln_u: f64) -> f64 {
        t.guess(ln_p, ln_u, |_, _, _| panic!("every row is solved by build"))
    }

    #[test]
    fn rows_are_solved_on_first_use_and_give_the_eagerly_built_values() {
        let f = |a: f64, b: f64| (0.3 * a).sin() + 0.2 * b * b - 0.01 * a * b;
        let root = |a: f64, b: f64, _: Option<f64>| node(f(a, b), 0.3 * (0.3 * a).cos() - 0.01 * b, 0.4 * b - 0.01 * a);
        let eager = StartTable::build(1e30, root);
        let lazy = StartTable::new(1e30);
        assert_eq!(lazy.solved(), 0);
        let (a, b) = (f64::ln(20e3), f64::ln(0.168));
        let v = lazy.guess(a, b, root);
        assert_eq!(lazy.solved(), 2 * lazy.nu, "the two rows of the cell");
        assert_eq!(v.to_bits(), at(&eager, a, b).to_bits());
        assert_eq!(lazy, eager);
        let copy = lazy.clone();
        assert_eq!(copy.guess(a, b, |_, _, _| panic!("solved already")).to_bits(), v.to_bits());
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
            assert!((at(&t, a, b) - f(a, b)).abs() < 1e-9 * (1.0 + f(a, b).abs()), "{p} {u}: {} vs {}", at(&t, a, b), f(a, b));
        }
        let corner = f(LOAD_RANGE.0.ln(), SPEED_RANGE.0.ln());
        assert!((at(&t, -1e3, -1e3) - corner).abs() < 1e-9);
        assert!(at(&t, f64::NAN, 0.0).is_finite());
    }

    #[test]
    fn hermite_beats_linear_on_a_smooth_function() {
        // y = sin(ln u): the cubic start is much closer than the chord of the same cell.
        let t = StartTable::build(1e30, |_, b, _| node(b.sin(), 0.0, b.cos()));
        let (mut worst, mut worst_linear) = (0.0f64, 0.0f64);
        for k in 0..200 {
            let b = -10.0 + 0.0731 * f64::from(k);
            worst = worst.max((at(&t, 5.0, b) - b.sin()).abs());
            let s = (b - t.ln_u0) / t.du;
            let (j, f) = (s.floor(), s - s.floor());
            let (b0, b1) = (t.ln_u0 + j * t.du, t.ln_u0 + (j + 1.0) * t.du);
            worst_linear = worst_linear.max((b0.sin() + f * (b1.sin() - b0.sin()) - b.sin()).abs());
        }
        assert!(worst < 0.1 * worst_linear, "{worst} vs {worst_linear}");
    }

    #[test]
    fn a_cut_is_the_bicubic_at_its_load() {
        // A function with every kind of term: the cut must give the table's start (to
        // rounding) at any load and speed, inside and outside the grid, whatever the order.
        let f = |a: f64, b: f64| (0.3 * a).sin() * (0.2 * b).cos() + 0.01 * a * b * b;
        let fa = |a: f64, b: f64| 0.3 * (0.3 * a).cos() * (0.2 * b).cos() + 0.01 * b * b;
        let fb = |a: f64, b: f64| -0.2 * (0.3 * a).sin() * (0.2 * b).sin() + 0.02 * a * b;
        let root = |a: f64, b: f64, _: Option<f64>| node(f(a, b), fa(a, b), fb(a, b));
        let t = StartTable::new(1e30);
        let mut worst = 0.0f64;
        for k in 0..40 {
            let ln_p = -4.0 + 0.61 * f64::from(k);
            let mut cut = t.cut(ln_p);
            assert_eq!(cut.ln_load(), ln_p);
            for m in (0..120).rev() {
                let ln_u = -25.0 + 0.29 * f64::from(m);
                let (c, g) = (t.cut_guess(&mut cut, ln_u, root), t.guess(ln_p, ln_u, root));
                worst = worst.max((c - g).abs() / (1.0 + g.abs()));
                // Asked again (the column is kept) and from a new cut: the same value.
                assert_eq!(t.cut_guess(&mut cut, ln_u, root).to_bits(), c.to_bits());
                assert_eq!(t.cut_guess(&mut t.cut(ln_p), ln_u, root).to_bits(), c.to_bits());
            }
        }
        assert!(worst < 1e-14, "{worst}");
        // A different cut of the same table gives a different start (the test can fail).
        let mut other = t.cut(3.0);
        assert!((t.cut_guess(&mut other, 0.5, root) - t.guess(3.5, 0.5, root)).abs() > 1e-3);
        // Moved to another load: the cut made there, bit for bit.
        t.recut(&mut other, 7.7);
        let mut fresh = t.cut(7.7);
        for m in 0..50 {
            let ln_u = -20.0 + 0.5 * f64::from(m);
            assert_eq!(t.cut_guess(&mut other, ln_u, root).to_bits(), t.cut_guess(&mut fresh, ln_u, root).to_bits());
        }
        // An empty table has no start; a cut of a table of another size is not read.
        let empty = StartTable::empty();
        assert!(empty.cut_guess(&mut empty.cut(1.0), 0.0, root).is_nan());
        assert!(StartTable::new(1e5).cut_guess(&mut t.cut(30.0), 0.0, root).is_nan(), "a row beyond the table");
    }

    #[test]
    fn capacity_cuts_the_grid_and_a_zero_capacity_empties_it() {
        let t = StartTable::build(2e3, |a, _, _| node(a, 1.0, 0.0));
        assert!((at(&t, 1e3f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12);
        assert!((at(&t, 1e9f64.ln(), 0.0) - 1e3f64.ln()).abs() < 1e-12, "clamped to half the capacity");
        assert!(at(&StartTable::build(0.0, |a, _, _| node(a, 1.0, 0.0)), 0.0, 0.0).is_nan());
    }

    #[test]
    fn a_corner_without_derivatives_falls_back_to_bilinear() {
        let t = StartTable::build(1e30, |a, b, _| node(a + b, f64::NAN, 1.0));
        let (a, b) = (3.3, -2.2);
        assert!((at(&t, a, b) - (a + b)).abs() < 1e-9);
    }
}
