//! The load-sharing solve: eqs. 9, 13 and 19 in the three unknowns γ1, γ2, h_c.
//!
//! With `x1 = 1/γ1` (fluid share) and `x2 = 1/γ2 = 1 − x1` (asperity share, eq. 9), the
//! film equation (eq. 13) gives h_c(x1), decreasing in x1 and growing without bound as
//! x1 → 0; the asperity equation (eq. 19) gives the h_c at which the asperities carry
//! x2, growing without bound as x2 → 0. So
//!
//! `r(y) = ln F_{3/2}((h_film(y) − d_d)/σ_s) − ln[RHS_19(x2)/C]`
//!
//! is strictly increasing in the logit `y = ln(x1/x2)`, from −∞ to +∞, and has exactly
//! one root. Working in y keeps both shares accurate when either is tiny
//! (x1 = 1/(1+e^{−y}), x2 = 1/(1+e^{y}), both without cancellation, so x1 + x2 = 1 to
//! rounding), and working in logarithms keeps F_{3/2} finite in full film.
//!
//! Convergence: the root is bracketed by stepping outward from the initial guess until
//! r changes sign, then Brent's method keeps the bracket and stops when it is narrower
//! than `Y_TOL(y) = 1e-13 + 4ε|y|`. Since ∂ln x1/∂y = x2 ≤ 1, ∂ln x2/∂y = −x1 and
//! |∂ln h_c/∂y| ≤ 1/2 + 3/4·... is O(1), the shares and h_c are then exact to ~1e-12
//! relative, and μ (a smooth function of them) likewise; `tests/solver.rs` checks
//! 1e-10 against a bisection to the last bit.

use crate::asperity::{softplus, AsperityGroups};
use crate::film::ln_scaled_moes;
use crate::gw::{inverse_ln_f32, ln_f32};
use crate::params::Surface;

/// The speed-dependent film groups of eq. 12, in logarithms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmGroups {
    /// ln M = ln W − ½ ln U_Σ
    pub ln_m: f64,
    /// ln L = ln G + ¼ ln U_Σ
    pub ln_l: f64,
    /// ln(R' U_Σ^{1/2}), so that ln h_c = this + ln[(h_c/R') U_Σ^{-1/2}]
    pub ln_scale: f64,
}

impl FilmGroups {
    /// Groups for sum velocity `u` (m/s, > 0), reduced radius, effective modulus, length,
    /// load, inlet viscosity η0 and pressure–viscosity coefficient α.
    pub fn new(u: f64, r_red: f64, e_eff: f64, b: f64, p_t: f64, eta0: f64, alpha: f64) -> Self {
        let ln_u = (eta0 / (e_eff * r_red)).ln() + u.ln();
        let ln_w = (p_t / (e_eff * r_red * b)).ln();
        Self { ln_m: ln_w - 0.5 * ln_u, ln_l: (alpha * e_eff).ln() + 0.25 * ln_u, ln_scale: r_red.ln() + 0.5 * ln_u }
    }

    /// ln h_c (m) from eq. 13 when the fluid carries the share x1 (given as ln x1).
    pub fn ln_film(&self, ln_x1: f64) -> f64 {
        self.ln_scale + ln_scaled_moes(self.ln_m, self.ln_l, ln_x1).0
    }
}

/// Solution of the load sharing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSharing {
    /// 1/γ1, share of the load carried by the fluid.
    pub fluid_fraction: f64,
    /// 1/γ2, share carried by the asperities.
    pub asperity_fraction: f64,
    /// ln(x1/x2); −∞ at zero speed. Pass it back as a warm start.
    pub logit: f64,
    /// Central film thickness h_c (m).
    pub film_thickness: f64,
    /// Residual evaluations used.
    pub evaluations: u32,
}

/// Bracket half-width tolerance on the logit.
pub fn y_tol(y: f64) -> f64 {
    1e-13 + 4.0 * f64::EPSILON * y.abs()
}

/// Solve eqs. 9, 13, 19. `film = None` means zero speed: then 1/γ1 = 0 exactly, 1/γ2 = 1,
/// and h_c comes from eq. 19 alone (the limit of the moving case, MODEL_NOTES).
pub fn solve(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>) -> LoadSharing {
    let t_of_h = |h: f64| (h - s.summit_mean_plane_offset) / s.summit_height_std;
    let Some(film) = film else {
        let t = inverse_ln_f32(asp.required_ln_f32(0.0));
        return LoadSharing {
            fluid_fraction: 0.0,
            asperity_fraction: 1.0,
            logit: f64::NEG_INFINITY,
            film_thickness: s.summit_mean_plane_offset + t * s.summit_height_std,
            evaluations: 0,
        };
    };
    let mut evals = 0u32;
    let mut r = |y: f64| {
        evals += 1;
        let ln_x1 = -softplus(-y);
        let ln_x2 = -softplus(y);
        ln_f32(t_of_h(film.ln_film(ln_x1).exp())) - asp.required_ln_f32(ln_x2)
    };
    // Bracket by stepping outward from the guess.
    let y0 = match guess {
        Some(g) if g.is_finite() => g,
        _ => 0.0,
    };
    let r0 = r(y0);
    let (lo, hi) = if r0 == 0.0 {
        (y0, y0)
    } else {
        let dir = if r0 > 0.0 { -1.0 } else { 1.0 };
        let mut step = if guess.is_some() { 0.05 } else { 4.0 };
        let mut a = y0;
        // r is monotone and unbounded both ways, so the search ends; the root can sit far
        // out (y ≈ t²/2 in deep full film, where x2 = e^{−y} underflows but ln x2 = −y does not).
        loop {
            let b = y0 + dir * step;
            let rb = r(b);
            if (rb > 0.0) != (r0 > 0.0) || rb == 0.0 || !b.is_finite() {
                break if dir > 0.0 { (a, b) } else { (b, a) };
            }
            a = b;
            step *= 4.0;
        }
    };
    let y = if lo == hi { lo } else { brent(&mut r, lo, hi, y_tol(lo.abs().max(hi.abs()))) };
    let ln_x1 = -softplus(-y);
    LoadSharing {
        fluid_fraction: 1.0 / (1.0 + (-y).exp()),
        asperity_fraction: 1.0 / (1.0 + y.exp()),
        logit: y,
        film_thickness: film.ln_film(ln_x1).exp(),
        evaluations: evals,
    }
}

/// Brent's root finder (inverse quadratic interpolation, secant and bisection, Brent 1973
/// ch. 4) on a sign-changing bracket [a, b]; returns a point of a final bracket narrower
/// than 2·tol. Hand-written because a solve must cost well under a microsecond with no
/// allocation or trait-object overhead; it is ~40 lines and tested below.
pub fn brent<F: FnMut(f64) -> f64>(mut f: F, a: f64, b: f64, tol: f64) -> f64 {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..300 {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let rr = fb / fc;
                p = s * (2.0 * xm * qq * (qq - rr) - (b - a) * (rr - 1.0));
                q = (qq - 1.0) * (rr - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * xm * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b);
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_roots_to_tolerance() {
        let r = brent(|x| x * x * x - 2.0, 0.0, 3.0, 1e-14);
        assert!((r - 2f64.cbrt()).abs() < 1e-13);
        let r = brent(|x| (x - 1e-3).tanh() * 1e6, -50.0, 50.0, 1e-14);
        assert!((r - 1e-3).abs() < 1e-13);
        // Step function: pure bisection must still converge.
        let r = brent(|x| if x < 0.3 { -1.0 } else { 1.0 }, 0.0, 1.0, 1e-12);
        assert!((r - 0.3).abs() < 1e-11);
    }
}
