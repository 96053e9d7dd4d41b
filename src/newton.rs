//! The root finder of the load-sharing solve (`crate::mixed`) and of the GW inverse
//! (`crate::gw::inverse_ln_f32`): Newton's method on a strictly increasing function,
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

/// [`newton_increasing`] when f(`y0`) and f′(`y0`) are already known (`first`, counted as one
/// evaluation): the same iterates as without it, one call of `f` fewer.
pub fn newton_increasing_seeded<F: FnMut(f64) -> (f64, f64)>(mut f: F, y0: f64, first: Option<(f64, f64)>, tol: fn(f64) -> f64) -> (f64, u32) {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let mut y = y0;
    let mut evals = 0;
    let (mut last_step, mut step_before_last) = (f64::INFINITY, f64::INFINITY);
    let mut last_was_newton = false;
    let mut first = first;
    while evals < 400 {
        let (r, dr) = match first.take() {
            Some(v) => v,
            None => f(y),
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
        let newton = y - r / dr;
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
        if newton_step && last_was_newton && last_step.abs() < 1e-2 && step.abs() < 0.1 * last_step.abs() {
            let predicted = step.abs().powi(3) / (last_step * last_step);
            if predicted <= 0.01 * tol(y) {
                break;
            }
        }
        last_was_newton = newton_step;
        step_before_last = last_step;
        last_step = step;
    }
    (y, evals)
}
