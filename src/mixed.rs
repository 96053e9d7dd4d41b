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

use crate::asperity::{AsperityGroups, A2, A3};
use crate::film::{ln_scaled_moes, ln_scaled_moes_grad};
use crate::gw::{inverse_ln_f32, ln_f32_slope};
use crate::fast_math::exp;
use crate::newton::newton_increasing;
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

    /// The groups at another speed and load: `self` holds them at (u₀, P₀); the ratios are
    /// given as logarithms. M ∝ P u^{−1/2}, L ∝ u^{1/4}, R' U_Σ^{1/2} ∝ u^{1/2}.
    pub fn at_ratio(&self, ln_load_ratio: f64, ln_speed_ratio: f64) -> Self {
        Self {
            ln_m: self.ln_m + ln_load_ratio - 0.5 * ln_speed_ratio,
            ln_l: self.ln_l + 0.25 * ln_speed_ratio,
            ln_scale: self.ln_scale + 0.5 * ln_speed_ratio,
        }
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
    /// ln h_c, as the solve has it (h_c is its exponential).
    pub ln_film_thickness: f64,
    /// Residual evaluations used.
    pub evaluations: u32,
    /// ∂y/∂ln P_T of the root at fixed speed (implicit function theorem at the last
    /// evaluated point; 0 at rest): with [`Self::dlogit_dln_speed`] a first-order predictor
    /// of the root at a nearby operating point, for starting the next solve.
    pub dlogit_dln_load: f64,
    /// ∂y/∂ln u of the root at fixed load (0 at rest).
    pub dlogit_dln_speed: f64,
}

/// Step tolerance on the logit.
pub fn y_tol(y: f64) -> f64 {
    1e-13 + 4.0 * f64::EPSILON * y.abs()
}

/// Solve eqs. 9, 13, 19. `film = None` means zero speed: then 1/γ1 = 0 exactly, 1/γ2 = 1,
/// and h_c comes from eq. 19 alone (the limit of the moving case, MODEL_NOTES).
/// `guess` is the logit of a nearby solution, if any.
pub fn solve(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>) -> LoadSharing {
    solve_starved(film, asp, s, guess, None)
}

/// Starved-inlet correction for [`solve_starved`]: `ln_q = ln(1/h_oil)` and the exponent γs
/// of [`crate::starvation::ln_starved`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StarvedInlet {
    /// ln(1/h_oil), h_oil being the oil-supply film thickness (m).
    pub ln_q: f64,
    /// Exponent γs of the starvation blend (dimensionless).
    pub gamma: f64,
}

/// [`solve`] with the film of eq. 13 replaced by its starved form
/// `h^−γs = h_13^−γs + h_oil^−γs` when `starved` is given (an extension, [`crate::starvation`]).
/// `None` is exactly [`solve`]'s path.
///
/// The residual stays strictly increasing in y (the starved film is an increasing function of
/// the flooded one), but the film is now bounded by h_oil as x1 → 0, so r(−∞) is finite:
/// when r(−∞) ≥ 0 the layer is too thin to lift the surfaces off the asperities' rest
/// separation and the fluid carries nothing (the zero-speed solution, 1/γ1 = 0).
pub fn solve_starved(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>, starved: Option<StarvedInlet>) -> LoadSharing {
    let rest = |asp: &AsperityGroups| {
        let t = inverse_ln_f32(asp.required_ln_f32(0.0));
        let h = s.summit_mean_plane_offset + t * s.summit_height_std;
        LoadSharing {
            fluid_fraction: 0.0,
            asperity_fraction: 1.0,
            logit: f64::NEG_INFINITY,
            film_thickness: h,
            ln_film_thickness: h.ln(),
            evaluations: 0,
            dlogit_dln_load: 0.0,
            dlogit_dln_speed: 0.0,
        }
    };
    if let (Some(_), Some(st)) = (film, starved) {
        // r(−∞): film = h_oil, asperities carry everything (ln x2 = 0).
        let h_oil = (-st.ln_q).exp();
        let (ln_f, _) = ln_f32_slope((h_oil - s.summit_mean_plane_offset) / s.summit_height_std);
        if ln_f - asp.required_ln_f32(0.0) >= 0.0 {
            return rest(asp);
        }
    }
    let Some(film) = film else {
        return rest(asp);
    };
    // r(y) and r'(y): every factor's derivative is analytic (film::ln_moes_grad,
    // gw::ln_f32_slope, AsperityGroups::required_ln_f32_grad). The film at the last
    // evaluated point is kept, so the final h_c costs no further film evaluation, and so are
    // r's partial derivatives in ln P_T and ln u at fixed y (for the caller's next start):
    // ln M' = 1, ln L' = 0, ln R'U^½' = 0, ln C' = −½, ln K' = a2 − a3 in ln P_T, and
    // ln M' = −½, ln L' = ¼, ln R'U^½' = ½ in ln u (FilmGroups::at_ratio, AsperityGroups::at_load_ratio).
    let mut last = (f64::NAN, f64::NAN, f64::NAN, f64::NAN, f64::NAN); // (y, ln h_c, d ln h_c/dy, r_P/r_y, r_u/r_y)
    let residual = |y: f64| {
        let sh = Shares::new(y);
        let (ln_hs, g_m, g_l) = ln_scaled_moes_grad(film.ln_m, film.ln_l, sh.ln_x1);
        let mut ln_h = film.ln_scale + ln_hs;
        let mut dln_h = sh.x2 * (0.5 * g_m + 0.75 * g_l - 0.5); // d ln x1/dy = x2
        let mut w = 1.0;
        if let Some(st) = starved {
            let (l, ws) = crate::starvation::ln_starved(ln_h, st.ln_q, st.gamma);
            ln_h = l;
            dln_h *= ws;
            w = ws;
        }
        let h = exp(ln_h);
        let t = (h - s.summit_mean_plane_offset) / s.summit_height_std;
        let (ln_f, dln_f) = ln_f32_slope(t);
        let (req, dreq, sigmoid) = asp.required_ln_f32_grad(sh.ln_x2); // d ln x2/dy = −x1
        let k = dln_f * h / s.summit_height_std; // ∂ ln F/∂ ln h_c
        let dr = k * dln_h + dreq * sh.x1;
        let dr_load = k * w * g_m - (sigmoid * (A2 - A3) + 0.5);
        let dr_speed = k * w * (0.5 - 0.5 * g_m + 0.25 * g_l);
        last = (y, ln_h, dln_h, dr_load / dr, dr_speed / dr);
        compress(ln_f - req, dr)
    };
    let y0 = guess.filter(|g| g.is_finite()).unwrap_or(0.0);
    let (y, evaluations) = newton_increasing(residual, y0, y_tol);
    // The last step is below tol (or zero), so first order is exact to O(tol²).
    let ln_h = last.1 + last.2 * (y - last.0);
    let sh = Shares::new(y);
    // Implicit function theorem: dy/dθ = −(∂r/∂θ)/(∂r/∂y) (the compression g(r) scales both alike).
    let finite_or_zero = |v: f64| if v.is_finite() { -v } else { 0.0 };
    LoadSharing {
        fluid_fraction: sh.x1,
        asperity_fraction: sh.x2,
        logit: y,
        film_thickness: exp(ln_h),
        ln_film_thickness: ln_h,
        evaluations,
        dlogit_dln_load: finite_or_zero(last.3),
        dlogit_dln_speed: finite_or_zero(last.4),
    }
}

/// The two load shares and their logarithms from the logit y, with one exponential and
/// no cancellation: x1 = 1/(1+e^{−y}), x2 = 1/(1+e^{y}).
#[derive(Debug, Clone, Copy)]
struct Shares {
    x1: f64,
    x2: f64,
    ln_x1: f64,
    ln_x2: f64,
}

impl Shares {
    fn new(y: f64) -> Self {
        let e = exp(-y.abs());
        let l = crate::fast_math::ln_1p_unit(e); // absolute accuracy ε suffices for logarithms (see film.rs)
        let (big, small) = (1.0 / (1.0 + e), e / (1.0 + e));
        if y >= 0.0 {
            Shares { x1: big, x2: small, ln_x1: -l, ln_x2: -y - l }
        } else {
            Shares { x1: small, x2: big, ln_x1: y - l, ln_x2: -l }
        }
    }
}

/// g(r) = r for r ≥ 0, −ln(1 − r) for r < 0: monotone, C¹ at the root, same root.
/// Towards zero speed r falls like −exp(e^{−1.2 y}) (ln F ≈ −t²/2 with t ∝ x1^{−0.6});
/// g makes that side nearly linear in y, so Newton does not crawl.
fn compress(r: f64, dr: f64) -> (f64, f64) {
    if r >= 0.0 { (r, dr) } else { (-(-r).ln_1p(), dr / (1.0 - r)) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_are_exact_complements() {
        for y in [-800.0, -40.0, -1.0, -1e-300, 0.0, 1e-9, 3.0, 40.0, 800.0, 1e15] {
            let sh = Shares::new(y);
            assert!((sh.x1 + sh.x2 - 1.0).abs() <= f64::EPSILON, "{y}");
            assert!((sh.ln_x1 - sh.ln_x2 - y).abs() <= 4.0 * f64::EPSILON * (1.0 + y.abs()), "{y}");
            if sh.x1 > 1e-300 {
                assert!((sh.x1.ln() - sh.ln_x1).abs() < 1e-14 * (1.0 + sh.ln_x1.abs()));
            }
            if sh.x2 > 1e-300 {
                assert!((sh.x2.ln() - sh.ln_x2).abs() < 1e-14 * (1.0 + sh.ln_x2.abs()));
            }
        }
    }

    #[test]
    fn newton_does_not_cycle_on_an_s_shaped_function() {
        // Steep in the middle, flat at both ends: plain Newton bounces between the two flanks.
        let f = |x: f64| (10.0 * (x + 2.0).tanh() + 0.5 * x, 10.0 / (x + 2.0).cosh().powi(2) + 0.5);
        let (r, n) = newton_increasing(f, 2.0, |_| 1e-14);
        assert!(f(r).0.abs() < 1e-12, "{r} after {n}");
        assert!(n < 60, "{n} evaluations");
    }

    #[test]
    fn newton_finds_roots_to_tolerance() {
        let tol = |_: f64| 1e-14;
        let (r, _) = newton_increasing(|x| (x * x * x - 2.0, 3.0 * x * x), 1.0, tol);
        assert!((r - 2f64.cbrt()).abs() < 1e-13);
        // Far start, saturating function (Newton alone would diverge): the bracket saves it.
        let (r, n) = newton_increasing(|x| ((x - 1e-3).atan(), 1.0 / (1.0 + (x - 1e-3).powi(2))), 50.0, tol);
        assert!((r - 1e-3).abs() < 1e-13, "{r} after {n}");
        // Step function with a useless derivative: pure bisection must still converge.
        let (r, _) = newton_increasing(|x| (if x < 0.3 { -1.0 } else { 1.0 }, 1e-300), 0.0, |_| 1e-12);
        assert!((r - 0.3).abs() < 1e-11);
        // Root far away: y ≈ 1e6 reached by doubling.
        let (r, n) = newton_increasing(|x| ((x - 1e6) / (1.0 + (x - 1e6).abs()), 1e-9), 0.0, tol);
        assert!((r - 1e6).abs() < 1e-6, "{r} {n}");
    }
}
