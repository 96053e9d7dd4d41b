//! The root finder of the load-sharing solve (`crate::load_sharing::solve`) and of the GW inverse
//! (`crate::contact::gw::inverse_ln_f32`): Newton's method on a strictly increasing function,
//! safeguarded by a bracket that every evaluation narrows.

/// Root of a strictly increasing function f (given with its derivative) that changes sign
/// on the real line, by Newton's method safeguarded with a bracket.
///
/// Every evaluation narrows the bracket [lo, hi] (f(lo) < 0 < f(hi)), so the iteration
/// cannot leave it. A Newton step that would leave the bracket is replaced by bisection
/// once the bracket is finite (also when it is not less than half the step before last),
/// and by a doubling step (at least 8) while one end is still infinite. It stops when a step is below `tol(y)`: a Newton step of that size
/// means an error of order tol² (quadratic convergence), a bisection step of that size
/// means a bracket of width 2·tol. Returns the root and the number of evaluations.
pub fn newton_increasing<F: FnMut(f64) -> (f64, f64)>(f: F, y0: f64, tol: fn(f64) -> f64) -> (f64, u32) {
    newton_increasing_seeded(f, y0, None, tol)
}

/// The first evaluation of [`newton_increasing_seeded`], made by the caller: f(y0), f′(y0) and
/// K = f″(y0)/(2f′(y0)) (NaN if unknown).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seed {
    /// f(y0).
    pub value: f64,
    /// f′(y0).
    pub slope: f64,
    /// f″(y0)/(2f′(y0)), or NaN.
    pub curvature: f64,
}

/// [`newton_increasing`] when the first evaluation at `y0` is already made (`first`, counted
/// as one evaluation; one call of `f` fewer). With a finite curvature K and a Newton step s
/// with |K s| ≤ 0.1, the first step is Halley's, s/(1 + K s) (error O(s³)); when that step
/// is below 1e-2, the step after it, s₁, leaves an error ≈ K s₁², and the iteration stops
/// when max(2|K|, 1)·s₁² ≤ tol/100 (the rule the secant estimate applies after two Newton
/// steps). Without a curvature the iterates are exactly [`newton_increasing`]'s.
pub fn newton_increasing_seeded<F: FnMut(f64) -> (f64, f64)>(mut f: F, y0: f64, first: Option<Seed>, tol: fn(f64) -> f64) -> (f64, u32) {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut y = y0;
    let mut evals = 0;
    let (mut last_step, mut step_before_last) = (f64::INFINITY, f64::INFINITY);
    let mut last_was_newton = false;
    let mut first = first;
    // K after a Halley step just taken (the next step's error estimate), else NaN.
    let mut after_halley = f64::NAN;
    while evals < 400 {
        let (r, dr, k) = match first.take() {
            Some(v) => (v.value, v.slope, v.curvature),
            None => {
                let (r, dr) = f(y);
                (r, dr, f64::NAN)
            }
        };
        evals += 1;
        if r == 0.0 {
            break;
        }
        if r > 0.0 {
            hi = y;
        } else {
            lo = y;
        }
        // While the bracket is open on the side of the step, a step is capped at
        // 1000·max(8, |y|), and a failed or flat Newton step becomes a doubling step.
        // Inside a finite bracket a Newton step must also be less than half the step before
        // last (Numerical Recipes' rtsafe rule), or the bracket is bisected: the bracket then
        // at least halves every two evaluations, whatever the shape of f.
        let reach = 8f64.max(y.abs());
        let s_newton = -r / dr;
        let halley = (k * s_newton).abs() <= 0.1;
        let newton = if halley { y + s_newton / (1.0 + k * s_newton) } else { y + s_newton };
        // A Newton step below the tolerance ends the iteration here, also when it rounds onto
        // the bracket end just evaluated (a step under half an ulp of y leaves y unchanged): it
        // must not count as leaving the bracket, which would bisect a bracket that is already
        // converged down to tol, one evaluation per halving.
        if newton >= lo && newton <= hi && (newton - y).abs() <= tol(newton) {
            y = newton;
            break;
        }
        let in_bracket = newton > lo && newton < hi && newton.is_finite();
        let bracketed = lo.is_finite() && hi.is_finite();
        let next = if in_bracket && (newton - y).abs() <= 1e3 * reach && (!bracketed || (newton - y).abs() <= 0.5 * step_before_last.abs()) {
            newton
        } else if bracketed {
            0.5 * (lo + hi)
        } else if r > 0.0 {
            y - reach
        } else {
            y + reach
        };
        let step = next - y;
        let newton_step = next == newton;
        y = next;
        if step.abs() <= tol(y) {
            break;
        }
        // Quadratic convergence: after two shrinking Newton steps s_{k−1}, s_k the error left
        // after s_k is ≈ C·s_k² with C ≈ |s_k|/s_{k−1}². Stop when that is 100× below tol.
        // Only in the asymptotic regime (|s_{k−1}| < 1e-2): a first step from a far guess says
        // nothing about C (a guess of 1e6 once stopped the solve 7e-8 short; fuzzing).
        // (Not right after a Halley step: its error is O(s³), not the secant's O(s²).)
        if newton_step && last_was_newton && after_halley.is_nan() && last_step.abs() < 1e-2 && step.abs() < 0.1 * last_step.abs() {
            let predicted = step.abs().powi(3) / (last_step * last_step);
            if predicted <= 0.01 * tol(y) {
                break;
            }
        }
        // After a Halley step below 1e-2 (K then barely moves between the two points) the
        // next Newton step's error is ≈ K·step²; taken as max(2|K|, 1)·step².
        if newton_step && after_halley.is_finite() && (2.0 * after_halley.abs()).max(1.0) * step * step <= 0.01 * tol(y) {
            break;
        }
        after_halley = if newton_step && halley && step.abs() < 1e-2 { k } else { f64::NAN };
        last_was_newton = newton_step;
        step_before_last = last_step;
        last_step = step;
    }
    (y, evals)
}
