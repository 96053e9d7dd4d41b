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
//! Convergence: Newton's method safeguarded by a bracket (`numerics::newton`) stops when a
//! step is below `y_tol(y) = 1e-13 + 4ε|y|`. Its first evaluation also gives r″, and when that
//! first Newton step is at most [`THIRD_ORDER_ACCEPT`] (a start from the start table,
//! [`crate::load_sharing::start`], in the boundary and mixed regimes) Halley's step ends the solve
//! after that one evaluation with an error below 1e-14. Since ∂ln x1/∂y = x2 ≤ 1, ∂ln x2/∂y = −x1 and
//! |∂ln h_c/∂y| ≤ 1/2 + 3/4·... is O(1), the shares and h_c are then exact to ~1e-12
//! relative, and μ (a smooth function of them) likewise; `tests/solver.rs` checks
//! 1e-10 against a bisection to the last bit.

use crate::contact::asperity::{AsperityGroups, A2, A3};
use crate::numerics::fast_math::exp;
use crate::film::{ln_moes_directional, ln_moes_grad, ln_moes_grad_directional, ln_scaled_moes};
use crate::contact::gw::{inverse_ln_f32, ln_f32_slope, ln_f32_slope2};
use crate::numerics::newton::{newton_increasing_seeded, Seed};
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
    /// evaluated point, within a Newton step below tolerance of the root; 0 at rest; NaN when
    /// not asked for, [`solve_starved_with`]): with [`Self::dlogit_dln_speed`] a first-order
    /// predictor of the root at a nearby operating point, for starting the next solve.
    pub dlogit_dln_load: f64,
    /// ∂y/∂ln u of the root at fixed load (0 at rest; NaN when not asked for).
    pub dlogit_dln_speed: f64,
}

/// Step tolerance on the logit.
pub fn y_tol(y: f64) -> f64 {
    1e-13 + 4.0 * f64::EPSILON * y.abs()
}

/// Solve eqs. 9, 13, 19. `film = None` means zero speed: then 1/γ1 = 0 exactly, 1/γ2 = 1,
/// and h_c comes from eq. 19 alone (the limit of the moving case, docs/model.md).
/// `guess` is the logit of a nearby solution, if any.
pub fn solve(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>) -> LoadSharing {
    solve_starved(film, asp, s, guess, None)
}

/// Starved-inlet correction for [`solve_starved`]: `ln_q = ln(1/h_oil)` and the exponent γs
/// of [`crate::film::starvation::ln_starved`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StarvedInlet {
    /// ln(1/h_oil), h_oil being the oil-supply film thickness (m).
    pub ln_q: f64,
    /// Exponent γs of the starvation blend (dimensionless).
    pub gamma: f64,
}

/// [`solve`] with the film of eq. 13 replaced by its starved form
/// `h^−γs = h_13^−γs + h_oil^−γs` when `starved` is given (an extension, [`crate::film::starvation`]).
/// `None` is exactly [`solve`]'s path.
///
/// The residual stays strictly increasing in y (the starved film is an increasing function of
/// the flooded one), but the film is now bounded by h_oil as x1 → 0, so r(−∞) is finite:
/// when r(−∞) ≥ 0 the layer is too thin to lift the surfaces off the asperities' rest
/// separation and the fluid carries nothing (the zero-speed solution, 1/γ1 = 0).
pub fn solve_starved(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>, starved: Option<StarvedInlet>) -> LoadSharing {
    solve_starved_with(film, asp, s, guess, starved, true)
}

/// [`solve_starved`], with the root's sensitivities ([`LoadSharing::dlogit_dln_load`],
/// [`LoadSharing::dlogit_dln_speed`]) only when `sensitivities` is true (NaN otherwise,
/// unless at rest, where they are 0). When the solve ends with its third-order step more than
/// 1e-7 from its start they cost one more residual evaluation, at the root. The root, the
/// shares and h_c are the same either way, bit for bit.
pub fn solve_starved_with(film: Option<&FilmGroups>, asp: &AsperityGroups, s: &Surface, guess: Option<f64>, starved: Option<StarvedInlet>, sensitivities: bool) -> LoadSharing {
    solve_composite(film, asp, s, guess, starved, None, sensitivities)
}

/// [`solve_starved_with`] with the composite film of the complete model when `journal` is
/// given ([`crate::composite`]): `ln h(x1) = (1 − w)·ln h_13(x1) + w·ln h_J(x1)`,
/// `h_J(x1) = c·(1 − ε(S/x1))`. `None` is exactly [`solve_starved_with`]'s path, bit for bit.
///
/// Both films decrease in x1 (ε grows with the journal's load x1·P, i.e. falls with S/x1), so
/// the residual stays strictly increasing in y with one root; h_J → c as x1 → 0, so with
/// w = 1 (or a starved inlet) r(−∞) is finite, and when r(−∞) ≥ 0 the fluid carries nothing
/// (the zero-speed solution), as for the starved film. The journal's term has no analytic
/// second derivative here, so the solve takes Newton's iteration (no third-order first step).
pub fn solve_composite(
    film: Option<&FilmGroups>,
    asp: &AsperityGroups,
    s: &Surface,
    guess: Option<f64>,
    starved: Option<StarvedInlet>,
    journal: Option<&JournalFilm>,
    sensitivities: bool,
) -> LoadSharing {
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
    if film.is_some() {
        // r(−∞): h_13 → ∞, h_J → c; the composite film is bounded only with w = 1, the
        // starved one by h_oil (the asperities carry everything there: ln x2 = 0).
        let ln_h = match journal {
            // h_13 → ∞ capped at c; with the journal's h_J → c, their smooth maximum
            // (c^8 + (w·c)^8)^(1/8).
            Some(j) if j.weight > 0.0 => j.ln_clearance + j.weight.powf(SMOOTH_MAX_EXPONENT).ln_1p() / SMOOTH_MAX_EXPONENT,
            Some(j) => j.ln_clearance,
            None => f64::INFINITY,
        };
        let ln_h = match starved {
            Some(st) => crate::film::starvation::ln_starved(ln_h, st.ln_q, st.gamma).0,
            None => ln_h,
        };
        if ln_h.is_finite() {
            let (ln_f, _) = ln_f32_slope((exp(ln_h) - s.summit_mean_plane_offset) / s.summit_height_std);
            if ln_f - asp.required_ln_f32(0.0) >= 0.0 {
                return rest(asp);
            }
        }
    }
    let Some(film) = film else {
        return rest(asp);
    };
    // r(y) and r'(y): every factor's derivative is analytic (film::ln_moes_grad,
    // gw::ln_f32_slope, AsperityGroups::required_ln_f32_grad). The film at the last
    // evaluated point is kept, so the final h_c costs no further film evaluation, and so are
    // the parts of r's partial derivatives in ln P_T and ln u at fixed y (for the caller's
    // next start; see `Point::sensitivities`).
    let y0 = guess.filter(|g| g.is_finite()).unwrap_or(0.0);
    // The first evaluation also gives r″ (flooded inlet only). From a start whose Newton step
    // s = −r/r′ is at most THIRD_ORDER_ACCEPT, Halley's step y0 + s/(1 + K s) (K = r″/2r′)
    // leaves an error C·s³ with C = K² − r‴/6r′, and the solve ends after one evaluation.
    // Otherwise Newton's iteration continues from y0, its first step Halley's.
    // r″ is analytic for the flooded line contact, and for the complete model wherever the
    // journal's weight is 0 (the clearance's cap and the supply's starvation by the chain rule).
    let second = match journal {
        None => starved.is_none(),
        Some(j) => j.weight == 0.0,
    };
    let p0 = Point::at(film, asp, s, starved, journal, y0, second, sensitivities);
    let step = -p0.r / p0.dr;
    let k = p0.d2r / (2.0 * p0.dr);
    let (y, ln_h, last, mut evaluations) = if p0.raw_r >= COMPRESS_FROM && step.abs() <= THIRD_ORDER_ACCEPT && (k * step).abs() <= 0.1 {
        let y = y0 + step / (1.0 + k * step);
        let d = y - y0;
        // ln h_c to second order in the move: the error is O(d³) ≤ 1e-14.
        (y, p0.ln_h + d * (p0.dln_h + 0.5 * d * p0.d2ln_h), p0, 1)
    } else {
        let mut last = p0;
        let residual = |y: f64| {
            let p = Point::at(film, asp, s, starved, journal, y, false, true);
            last = p;
            (p.r, p.dr)
        };
        // The first step is Halley's where r″ is known and the compression is the identity.
        let curvature = if p0.raw_r >= COMPRESS_FROM { k } else { f64::NAN };
        let seed = Seed { value: p0.r, slope: p0.dr, curvature };
        let (y, evaluations) = newton_increasing_seeded(residual, y0, Some(seed), y_tol);
        // The last step is below tol (or zero), so first order is exact to O(tol²).
        (y, last.ln_h + last.dln_h * (y - last.y), last, evaluations)
    };
    // The sensitivities at the root: after the one-evaluation solve its evaluation may be up
    // to THIRD_ORDER_ACCEPT away, so beyond SENSITIVITY_REUSE they are evaluated once more at
    // the root (within it, their relative error is of that order; after Newton's iteration
    // the last evaluation is within its last step, below 5e-7, as before).
    let (dlogit_dln_load, dlogit_dln_speed) = if !sensitivities {
        (f64::NAN, f64::NAN)
    } else if last.g_m.is_nan() || (evaluations == 1 && (y - last.y).abs() > SENSITIVITY_REUSE) {
        evaluations += 1;
        Point::at(film, asp, s, starved, journal, y, false, true).sensitivities()
    } else {
        last.sensitivities()
    };
    let sh = Shares::new(y);
    LoadSharing {
        fluid_fraction: sh.x1,
        asperity_fraction: sh.x2,
        logit: y,
        film_thickness: exp(ln_h),
        ln_film_thickness: ln_h,
        evaluations,
        dlogit_dln_load,
        dlogit_dln_speed,
    }
}

/// Largest first Newton step |s| = |r/r′| after which the solve ends with Halley's step (third
/// order): the error left is C·s³ with C = K² − r‴/(6r′), K = r″/(2r′). |C| ≤ 0.32 over the
/// boundary and mixed regimes of the paper's joint (finite differences of r at the roots of
/// 8 loads from 1 N to 1 MN × 400 speeds from 1e-6 to 100 rad/s, y < 20), so the error is
/// below 8e-15 with a margin of 3 on C: 10× below the absolute tolerance of [`y_tol`].
/// `tests/solver.rs` checks such roots against Newton's and against sign changes of r, and
/// `tests/properties.rs` against Newton's over random parameter sets.
pub const THIRD_ORDER_ACCEPT: f64 = 2e-5;

/// How far (in y) from the root the last evaluation may be for its sensitivities to be the
/// root's (their relative error is of this order; the test asks 1e-6).
const SENSITIVITY_REUSE: f64 = 1e-7;

/// The residual (compressed) and what the solve keeps of one evaluation at y.
#[derive(Debug, Clone, Copy)]
struct Point {
    y: f64,
    /// g(r) and g′(r)·r′ (the compression g of [`compress`]).
    r: f64,
    dr: f64,
    /// r itself, and r′ and r″ uncompressed (r″ NaN unless asked for and available).
    raw_r: f64,
    raw_dr: f64,
    d2r: f64,
    /// ln h_c and its first two derivatives in y (the second NaN unless asked for).
    ln_h: f64,
    dln_h: f64,
    d2ln_h: f64,
    /// ∂ln F/∂ln h_c times the starvation weight, ∂ln H/∂ln M, ∂ln H/∂ln L, and the sigmoid
    /// of eq. 18's bracket: the parts of r's partial derivatives in ln P_T and ln u at fixed y.
    kw: f64,
    g_m: f64,
    g_l: f64,
    sigmoid: f64,
    /// ∂ln F/∂ln h_c times the journal's part of ∂ln h/∂ln P_T at fixed y (0 without the
    /// journal; its ∂/∂ln u is the opposite: S ∝ u/P).
    kj: f64,
}

/// k of the smooth maximum (a^k + b^k)^(1/k) of the complete model's composite film (the
/// weighted journal film and the line contact's, [`crate::composite`]), and of the contact arc's
/// torque ([`crate::composite::smooth_max`]).
pub const SMOOTH_MAX_EXPONENT: f64 = 8.0;

/// The exponent k of the cap that holds the complete model's line-contact film inside the
/// clearance, h^−k = h_13^−k + c^−k ([`crate::composite`]).
pub const CLEARANCE_CAP_EXPONENT: f64 = 4.0;

/// The journal bearing's film in the load-sharing solve (the complete model,
/// [`crate::composite`]): its weight w in (0, 1], ln S at the full load and ln c.
#[derive(Clone, Copy)]
pub struct JournalFilm<'a> {
    /// w, the journal's weight in the composite film.
    pub weight: f64,
    /// ln S (eq. 20) at the whole load: the journal carrying x1·P has ln S − ln x1.
    pub ln_sommerfeld: f64,
    /// ln c, the radial clearance's logarithm (m).
    pub ln_clearance: f64,
    /// ε(S) of the joint's L/D.
    pub table: &'a crate::journal::JournalTable,
    /// ln P* − ln P ≥ 0: the line contact's film in the composite is that at the load P*
    /// ([`crate::composite::onset_load`]); 0 where the weight is 0.
    pub ln_onset: f64,
}

impl JournalFilm<'_> {
    /// ln h_J and d ln h_J/d ln x1 when the fluid carries the share x1 (given as ln x1).
    #[inline]
    pub fn ln_film(&self, ln_x1: f64) -> (f64, f64) {
        let (e, de) = self.table.eccentricity(self.ln_sommerfeld - ln_x1);
        (self.ln_clearance + (-e).ln_1p(), de / (1.0 - e))
    }
}

impl Point {
    /// r and its derivatives at y; with `second`, r″ and d²ln h_c/dy² too (flooded inlet, t
    /// inside the Chebyshev interval of F_{3/2}; NaN otherwise), and with it the parts of the
    /// sensitivities only if `gradient` (NaN otherwise).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn at(film: &FilmGroups, asp: &AsperityGroups, s: &Surface, starved: Option<StarvedInlet>, journal: Option<&JournalFilm>, y: f64, second: bool, gradient: bool) -> Self {
        let sh = Shares::new(y);
        // Eq. 13 by eq. 12's substitution (film::ln_scaled_moes_grad): along y, ln x1 moves
        // by x2, and (ln M, ln L) by (1/2, 3/4) per unit ln x1.
        // In the complete model's transition the line contact's film is that of the load P*
        // ≥ P (crate::composite::onset_load): ln M moves by ln P* − ln P (0.0 elsewhere, exactly).
        let onset = journal.map_or(0.0, |j| j.ln_onset);
        let (ln_m, ln_l) = (film.ln_m + onset + 0.5 * sh.ln_x1, film.ln_l + 0.75 * sh.ln_x1);
        // With `second`, only the derivatives along that direction (the gradient, for the
        // sensitivities, is then NaN).
        let (ln_hm, g_m, g_l, q1, d2m) = if second && gradient {
            let (v, g_m, g_l, d1, d2) = ln_moes_grad_directional(ln_m, ln_l, 0.5, 0.75);
            (v, g_m, g_l, d1 - 0.5, d2)
        } else if second {
            let (v, d1, d2) = ln_moes_directional(ln_m, ln_l, 0.5, 0.75);
            (v, f64::NAN, f64::NAN, d1 - 0.5, d2)
        } else {
            let (a, _, b, c) = ln_moes_grad(ln_m, ln_l);
            (a, b, c, 0.5 * b + 0.75 * c - 0.5, f64::NAN)
        }; // q1 = d ln h_c/d ln x1
        let mut ln_h = film.ln_scale + (ln_hm - 0.5 * sh.ln_x1);
        let mut dln_h = sh.x2 * q1; // d ln x1/dy = x2
        let mut d2ln_h = sh.x2 * sh.x2 * d2m - sh.x1 * sh.x2 * q1; // d² ln x1/dy² = −x1·x2
        let mut w = 1.0;
        let mut jp = 0.0; // the journal's ∂ln h/∂ln P_T at fixed y
        if let Some(j) = journal {
            // The line contact's film held inside the clearance (crate::composite); its second
            // derivative by the chain rule (d²l/dln h² = −k·w·(1 − w)).
            let (l, wc) = crate::film::starvation::ln_starved(ln_h, -j.ln_clearance, CLEARANCE_CAP_EXPONENT);
            ln_h = l;
            d2ln_h = wc * d2ln_h - CLEARANCE_CAP_EXPONENT * wc * (1.0 - wc) * dln_h * dln_h;
            dln_h *= wc;
            w = wc;
            if j.weight > 0.0 {
                // The smooth maximum (crate::composite::smooth_max) of w·h_J and the line
                // contact's film at P*: ln of (a⁸ + b⁸)^(1/8) = −ln of the power-law minimum of
                // 1/a and 1/b, whose weight on a is a's share of the derivative.
                d2ln_h = f64::NAN;
                let (ln_hj, dj) = j.ln_film(sh.ln_x1);
                let (l, wj) = crate::film::starvation::ln_starved(-(j.weight.ln() + ln_hj), ln_h, SMOOTH_MAX_EXPONENT);
                ln_h = -l;
                dln_h = (1.0 - wj) * dln_h + wj * sh.x2 * dj;
                // Above the onset the line contact's film no longer follows the load (P* is
                // the onset's), nor does its part of the sensitivities.
                w *= (1.0 - wj) * if j.ln_onset > 0.0 { 0.0 } else { 1.0 };
                jp = wj * dj; // ln S − ln x1: ∂/∂ln P = ∂/∂ln x1
            }
        }
        // The starved inlet starves the (composite) film.
        if let Some(st) = starved {
            let (l, ws) = crate::film::starvation::ln_starved(ln_h, st.ln_q, st.gamma);
            ln_h = l;
            // The second derivative by the chain rule (d²l/dln h² = −γ·w·(1 − w)) for the
            // complete model, whose first step may be third order; the paper's starved inlet
            // keeps Newton's iteration (its path bit for bit).
            d2ln_h = if journal.is_some() { ws * d2ln_h - st.gamma * ws * (1.0 - ws) * dln_h * dln_h } else { f64::NAN };
            dln_h *= ws;
            w *= ws;
            jp *= ws;
        }
        let h = exp(ln_h);
        let t = (h - s.summit_mean_plane_offset) / s.summit_height_std;
        let (ln_f, dln_f, d2ln_f) = if second {
            ln_f32_slope2(t)
        } else {
            let (a, b) = ln_f32_slope(t);
            (a, b, f64::NAN)
        };
        let (req, dreq, sigmoid) = asp.required_ln_f32_grad(sh.ln_x2); // d ln x2/dy = −x1
        let k = dln_f * h / s.summit_height_std; // ∂ ln F/∂ ln h_c
        let raw_dr = k * dln_h + dreq * sh.x1;
        let raw_r = ln_f - req;
        let d2r = if second {
            // t′ = h·ln h′/σ_s, t″ = h·(ln h′² + ln h″)/σ_s; d² ln x2/dy² = −x1·x2.
            let t1 = h * dln_h / s.summit_height_std;
            let t2 = h * (dln_h * dln_h + d2ln_h) / s.summit_height_std;
            d2ln_f * t1 * t1 + dln_f * t2 - AsperityGroups::required_ln_f32_curvature(sigmoid) * sh.x1 * sh.x1 + dreq * sh.x1 * sh.x2
        } else {
            f64::NAN
        };
        let (r, dr) = compress(raw_r, raw_dr);
        Self { y, r, dr, raw_r, raw_dr, d2r, ln_h, dln_h, d2ln_h, kw: k * w, g_m, g_l, sigmoid, kj: if journal.is_some() { k * jp } else { 0.0 } }
    }

    /// dy/dln P_T and dy/dln u by the implicit function theorem at this point,
    /// −(∂r/∂θ)/(∂r/∂y) (0 where not finite; the compression scales both alike): ln M′ = 1,
    /// ln L′ = 0, ln R′U^½′ = 0, ln C′ = −½, ln K′ = a2 − a3 in ln P_T, and ln M′ = −½,
    /// ln L′ = ¼, ln R′U^½′ = ½ in ln u (FilmGroups::at_ratio, AsperityGroups::at_load_ratio).
    fn sensitivities(&self) -> (f64, f64) {
        let mut dr_load = self.kw * self.g_m - (self.sigmoid * (A2 - A3) + 0.5);
        let mut dr_speed = self.kw * (0.5 - 0.5 * self.g_m + 0.25 * self.g_l);
        if self.kj != 0.0 {
            dr_load += self.kj;
            dr_speed -= self.kj;
        }
        let finite_or_zero = |v: f64| if v.is_finite() { -v } else { 0.0 };
        (finite_or_zero(dr_load / self.raw_dr), finite_or_zero(dr_speed / self.raw_dr))
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
        let l = crate::numerics::fast_math::ln_1p_unit(e); // absolute accuracy ε suffices for logarithms (see film.rs)
        let (big, small) = (1.0 / (1.0 + e), e / (1.0 + e));
        if y >= 0.0 {
            Shares { x1: big, x2: small, ln_x1: -l, ln_x2: -y - l }
        } else {
            Shares { x1: small, x2: big, ln_x1: y - l, ln_x2: -l }
        }
    }
}

/// Where the compression of [`compress`] starts.
const COMPRESS_FROM: f64 = -1.0;

/// g(r) = r for r ≥ −1, −1 − ln(−r) for r < −1: monotone, C¹, the same root, and the
/// identity near it (so the third-order first step sees r itself). Towards zero speed r falls
/// like −exp(e^{−1.2 y}) (ln F ≈ −t²/2 with t ∝ x1^{−0.6}); g makes that side nearly linear
/// in y, so Newton does not crawl.
fn compress(r: f64, dr: f64) -> (f64, f64) {
    if r >= COMPRESS_FROM { (r, dr) } else { (COMPRESS_FROM - (-r).ln(), -dr / r) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::newton::newton_increasing;

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
    fn a_seeded_halley_step_converges_to_tolerance_in_fewer_evaluations() {
        // f(x) = e^x − 2 + x (increasing, curved): from 0.3 off, the first step Halley's.
        let root = {
            let (r, _) = newton_increasing(|x: f64| (x.exp() - 2.0 + x, x.exp() + 1.0), 0.0, |_| 1e-15);
            r
        };
        let f = |x: f64| (x.exp() - 2.0 + x, x.exp() + 1.0);
        for d in [3e-1, 3e-2, -1e-2, 1e-3, -1e-4] {
            let x0 = root + d;
            let (r, dr) = f(x0);
            let seed = crate::numerics::newton::Seed { value: r, slope: dr, curvature: x0.exp() / (2.0 * dr) };
            let (with, n_with) = newton_increasing_seeded(f, x0, Some(seed), y_tol);
            let (without, n_without) = newton_increasing(f, x0, y_tol);
            assert!((with - root).abs() < 1e-14 && (without - root).abs() < 1e-14, "{d}: {with} {without} vs {root}");
            assert!(n_with <= n_without, "{d}: {n_with} vs {n_without} evaluations");
            // Without a curvature the seeded iteration is newton_increasing's, bit for bit.
            let plain = crate::numerics::newton::Seed { curvature: f64::NAN, ..seed };
            let (same, n_same) = newton_increasing_seeded(f, x0, Some(plain), y_tol);
            assert_eq!((same.to_bits(), n_same), (without.to_bits(), n_without));
        }
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
