//! The finite-difference (finite-volume) solution of the Reynolds equation of a rigid,
//! isoviscous, 360° plain journal bearing with the Swift–Stieber (Reynolds) cavitation
//! condition, for one eccentricity ratio ε and one length-to-diameter ratio L/D.
//!
//! # Equation
//! θ is measured from the line of centres at the minimum film, in the direction the journal
//! surface moves; ζ = z/(L/2) ∈ [−1, 1] is the axial coordinate. With the film
//! h = c·H, H = 1 − ε cos θ, and the pressure p = η ω (R/c)² p̄, the Reynolds equation
//! (Pinkus & Sternlicht, *Theory of Hydrodynamic Lubrication*, 1961, ch. 3; the form of
//! Raimondi & Boyd, 1958, ASLE Trans. 1, part I, eq. 2) reads
//!
//! ∂/∂θ (H³ ∂p̄/∂θ) + (D/L)² ∂/∂ζ (H³ ∂p̄/∂ζ) = 6 ∂H/∂θ,
//!
//! with p̄ = 0 at the bearing's ends (ζ = ±1). The Swift–Stieber condition (the "Reynolds
//! condition" of Raimondi & Boyd, who set p = ∂p/∂n = 0 on the unknown film-rupture boundary)
//! is the linear complementarity problem: p̄ ≥ 0, the Reynolds residual ≥ 0 where p̄ = 0, and
//! their product 0 (Cryer, 1971, "The method of Christopherson for solving free boundary
//! problems for infinite journal bearings by means of finite differences", Math. Comp. 25,
//! 435–443; Christopherson 1941). The problem is symmetric in ζ: only ζ ∈ [0, 1] is solved,
//! with ∂p̄/∂ζ = 0 at ζ = 0.
//!
//! # Discretisation
//! Finite volumes on a tensor grid, conservative, second order: the circumferential grid is
//! uniform in the angle ψ of the substitution tan(θ/2) = k tan(ψ/2), k = √((1−ε)/(1+ε)),
//! which places a fixed share of the nodes across the pressure peak at the minimum film
//! however close ε is to 1 (the same substitution integrates ∫dθ/H in closed form); the
//! axial grid ζ_j = sin(π j/(2 n_z)) is refined towards the bearing's end, where the
//! pressure's boundary layer sits at high ε. The film starts at the maximum film,
//! θ = −π, at ambient pressure (p̄ = 0 there along the whole length): Raimondi & Boyd's
//! boundary condition (their part I: the lubricant is supplied at the position of maximum
//! film thickness, at ambient pressure). Without it the 360° problem has no ambient line
//! and the complementarity problem lets the pressurised arc begin in the diverging film
//! (an infinitely long bearing would then carry a full-Sommerfeld-like film lifted to p ≥ 0).
//! The domain is θ ∈ [−π, π] with p̄ = 0 on θ = ±π, so the matrix is banded (no periodic
//! wrap).
//!
//! The complementarity problem is solved by the primal–dual active-set method (Hintermüller,
//! Ito & Kunisch, 2003, SIAM J. Optim. 13, 865–888), exact for this M-matrix in finitely many
//! steps; each step is a banded Cholesky solve (bandwidth n_z) of the equations on the free
//! (pressurised) nodes. A warm start (the active set of the neighbouring ε) takes 2–4 steps.

use std::f64::consts::PI;

/// Grid resolution of a solve: circumferential cells and axial nodes of the half bearing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Grid {
    /// Number of circumferential intervals over 2π (the nodes are `n_theta − 1` unknowns).
    pub n_theta: usize,
    /// Number of axial intervals over ζ ∈ [0, 1] (`n_zeta` unknowns per circumferential node).
    pub n_zeta: usize,
}

impl Grid {
    /// The table's grid (a compromise of build time and accuracy; its error against a grid
    /// of 4× the nodes is stated in the tests, `grid_convergence`).
    pub const TABLE: Grid = Grid { n_theta: 120, n_zeta: 12 };
}

/// The integrated solution of one solve.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Dimensionless load along the line of centres, ∫∫ p̄ cos θ dθ dζ over ζ ∈ [−1, 1].
    pub load_radial: f64,
    /// Dimensionless load perpendicular to it, −∫∫ p̄ sin θ dθ dζ (positive: the pressure sits
    /// ahead of the minimum film).
    pub load_tangential: f64,
    /// Sommerfeld number S = η N/P (R/c)² = 2/(π |W̄|), |W̄| the magnitude of the two loads
    /// (derivation: W = η ω (R/c)² R (L/2) |W̄|, P = W/(2RL), N = ω/2π).
    pub sommerfeld: f64,
    /// Attitude angle φ between the load line and the line of centres (rad).
    pub attitude: f64,
    /// Number of active-set steps taken.
    pub steps: usize,
    /// The active set (cavitated nodes), for a warm start of the next solve.
    pub(crate) active: Vec<bool>,
}

/// Errors of a solve (none is reachable from a valid ε and L/D; they guard the bounds).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// ε outside (0, 1) or L/D not positive and finite.
    #[error("journal-bearing solve: eccentricity ratio {eps} must be in (0, 1) and L/D = {ld} positive and finite")]
    Input {
        /// ε given.
        eps: f64,
        /// L/D given.
        ld: f64,
    },
    /// The active-set iteration did not settle in its step budget.
    #[error("journal-bearing solve: the cavitation (active-set) iteration did not settle in {steps} steps at eccentricity ratio {eps}")]
    NotSettled {
        /// Steps taken.
        steps: usize,
        /// ε of the solve.
        eps: f64,
    },
    /// The banded factorisation met a non-positive pivot (not reachable for an M-matrix).
    #[error("journal-bearing solve: the Reynolds matrix lost positive definiteness at eccentricity ratio {eps}")]
    Factorisation {
        /// ε of the solve.
        eps: f64,
    },
}

/// Most active-set steps of one solve, plus the grid's size: each step moves the cavitation
/// boundary by a few cells, so a cold start on a fine grid takes more; 2–6 are usual.
const MAX_STEPS: usize = 40;
/// The ends of the circumferential domain, θ = ±π: the maximum film, where the lubricant
/// enters at ambient pressure (Raimondi & Boyd's boundary condition).
const THETA_CUT: f64 = PI;

/// θ(ψ) of the substitution tan(θ/2) = k tan(ψ/2), continuous (θ(ψ + 2π) = θ(ψ) + 2π):
/// θ = ψ − 2 atan(β sin ψ / (1 + β cos ψ)), β = (1 − k)/(1 + k).
fn theta_of_psi(psi: f64, beta: f64) -> f64 {
    psi - 2.0 * (beta * psi.sin()).atan2(1.0 + beta * psi.cos())
}

/// The inverse, ψ(θ) = θ + 2 atan(β sin θ / (1 − β cos θ)).
fn psi_of_theta(theta: f64, beta: f64) -> f64 {
    theta + 2.0 * (beta * theta.sin()).atan2(1.0 - beta * theta.cos())
}

/// Solves the Reynolds equation at eccentricity ratio `eps` for length-to-diameter ratio
/// `ld` on `grid`; `warm` is the active set of a previous solve on the same grid.
pub fn solve(eps: f64, ld: f64, grid: Grid, warm: Option<&[bool]>) -> Result<Solution, SolveError> {
    if !(eps > 0.0 && eps < 1.0 && ld > 0.0 && ld.is_finite()) {
        return Err(SolveError::Input { eps, ld });
    }
    let (nt, nz) = (grid.n_theta.max(8), grid.n_zeta.max(2));
    let h = |t: f64| 1.0 - eps * t.cos();
    // Circumferential nodes θ_0 = −π … θ_nt = π, uniform in ψ.
    let k = ((1.0 - eps) / (1.0 + eps)).sqrt();
    let beta = (1.0 - k) / (1.0 + k);
    let psi_end = psi_of_theta(THETA_CUT, beta);
    let theta: Vec<f64> = (0..=nt)
        .map(|i| theta_of_psi(psi_end - 2.0 * PI + 2.0 * PI * i as f64 / nt as f64, beta))
        .collect();
    // Faces θ_{i+1/2} (midpoints in ψ, i = 0 … nt−1).
    let theta_face: Vec<f64> = (0..nt)
        .map(|i| theta_of_psi(psi_end - 2.0 * PI + 2.0 * PI * (i as f64 + 0.5) / nt as f64, beta))
        .collect();
    // Axial nodes ζ_0 = 0 … ζ_nz = 1 and faces.
    let zeta: Vec<f64> = (0..=nz).map(|j| (0.5 * PI * j as f64 / nz as f64).sin()).collect();
    let zeta_face: Vec<f64> = (0..nz).map(|j| 0.5 * (zeta[j] + zeta[j + 1])).collect();
    let dzeta: Vec<f64> = (0..nz).map(|j| zeta_face[j] - if j == 0 { 0.0 } else { zeta_face[j - 1] }).collect();
    let d2 = 1.0 / (ld * ld); // (D/L)²
    // Unknowns: i = 1 … nt−1, j = 0 … nz−1, index (i−1)·nz + j.
    let n = (nt - 1) * nz;
    let bw = nz;
    // Coefficients: east (θ) conductance per unknown, north (ζ) conductance, diagonal, rhs.
    let mut a_e = vec![0.0; n]; // between (i, j) and (i+1, j)
    let mut a_n = vec![0.0; n]; // between (i, j) and (i, j+1)
    let mut diag = vec![0.0; n];
    let mut rhs = vec![0.0; n];
    let mut cos_w = vec![0.0; n]; // ∫_CV cos θ dθ dζ
    let mut sin_w = vec![0.0; n];
    for i in 1..nt {
        let (tw, te) = (theta_face[i - 1], theta_face[i]);
        let dth = te - tw;
        let hw3 = h(tw).powi(3) / (theta[i] - theta[i - 1]);
        let he3 = h(te).powi(3) / (theta[i + 1] - theta[i]);
        let hp3 = h(theta[i]).powi(3) * dth;
        for j in 0..nz {
            let kk = (i - 1) * nz + j;
            let cw = hw3 * dzeta[j];
            let ce = he3 * dzeta[j];
            let cn = d2 * hp3 / (zeta[j + 1] - zeta[j]);
            let cs = if j == 0 { 0.0 } else { d2 * hp3 / (zeta[j] - zeta[j - 1]) };
            a_e[kk] = if i + 1 < nt { ce } else { 0.0 };
            a_n[kk] = if j + 1 < nz { cn } else { 0.0 };
            diag[kk] = cw + ce + cn + cs;
            rhs[kk] = -6.0 * (h(te) - h(tw)) * dzeta[j];
            cos_w[kk] = (te.sin() - tw.sin()) * dzeta[j];
            sin_w[kk] = (tw.cos() - te.cos()) * dzeta[j];
        }
    }
    // Active set (p = 0): warm start, else the film past θ = 0.6 rad (a guess of the
    // pressurised arc: the converging film and the start of the diverging one).
    let mut active: Vec<bool> = match warm {
        Some(w) if w.len() == n => w.to_vec(),
        _ => (0..n).map(|kk| theta[kk / nz + 1] > 0.6).collect(),
    };
    let mut p = vec![0.0; n];
    let mut band = vec![0.0; n * (bw + 1)];
    let mut steps = 0;
    loop {
        steps += 1;
        // Assemble the banded SPD matrix of the free nodes (identity rows on the active ones).
        band.iter_mut().for_each(|x| *x = 0.0);
        for kk in 0..n {
            let row = kk * (bw + 1);
            if active[kk] {
                band[row + bw] = 1.0;
                continue;
            }
            band[row + bw] = diag[kk];
            if kk % nz > 0 && !active[kk - 1] {
                band[row + bw - 1] = -a_n[kk - 1];
            }
            if kk >= nz && !active[kk - nz] {
                band[row] = -a_e[kk - nz];
            }
        }
        cholesky_band(&mut band, n, bw, &active).map_err(|_| SolveError::Factorisation { eps })?;
        for kk in 0..n {
            p[kk] = if active[kk] { 0.0 } else { rhs[kk] };
        }
        solve_band(&band, n, bw, &mut p);
        // Update: a free node with p < 0 becomes active; an active node whose residual
        // A p − f < 0 (the equations would pull its pressure up) becomes free.
        let mut changed = false;
        for kk in 0..n {
            let now = if active[kk] {
                let mut r = -rhs[kk];
                if kk % nz > 0 {
                    r -= a_n[kk - 1] * p[kk - 1];
                }
                if kk % nz + 1 < nz {
                    r -= a_n[kk] * p[kk + 1];
                }
                if kk >= nz {
                    r -= a_e[kk - nz] * p[kk - nz];
                }
                if kk + nz < n {
                    r -= a_e[kk] * p[kk + nz];
                }
                r >= 0.0
            } else {
                p[kk] <= 0.0
            };
            if now != active[kk] {
                changed = true;
                active[kk] = now;
            }
        }
        if !changed {
            break;
        }
        if steps >= MAX_STEPS + nt + nz {
            return Err(SolveError::NotSettled { steps, eps });
        }
    }
    // Loads over the whole length (2× the half bearing).
    let (mut wc, mut ws) = (0.0, 0.0);
    for kk in 0..n {
        let pk = p[kk].max(0.0);
        wc += pk * cos_w[kk];
        ws += pk * sin_w[kk];
    }
    let (load_radial, load_tangential) = (2.0 * wc, -2.0 * ws);
    let w = load_radial.hypot(load_tangential);
    Ok(Solution {
        load_radial,
        load_tangential,
        sommerfeld: 2.0 / (PI * w),
        attitude: load_tangential.atan2(load_radial),
        steps,
        active,
    })
}

/// In-place Cholesky factorisation A = L Lᵀ of a symmetric positive definite band matrix
/// stored by rows of its lower band: `band[k·(bw+1) + bw − d]` = A(k, k − d), d = 0 … bw.
/// Rows flagged in `skip` are identity rows decoupled from the rest (an active node: its
/// row and column of A are those of the identity, so are its row and column of L); they are
/// left as they are.
fn cholesky_band(band: &mut [f64], n: usize, bw: usize, skip: &[bool]) -> Result<(), ()> {
    let w = bw + 1;
    for k in 0..n {
        if skip[k] {
            continue;
        }
        let j0 = k.saturating_sub(bw);
        for j in j0..=k {
            if skip[j] {
                continue;
            }
            // s = A(k, j) − Σ_{l = max(k, j) − bw}^{j−1} L(k, l) L(j, l): the dot product of
            // row k's entries at columns l0 … j−1 and row j's at the same columns.
            let l0 = j.saturating_sub(bw).max(j0);
            let rk = &band[k * w + bw - (k - l0)..k * w + bw - (k - j)];
            let rj = &band[j * w + bw - (j - l0)..j * w + bw];
            let dot: f64 = rk.iter().zip(rj).map(|(a, b)| a * b).sum();
            let s = band[k * w + bw - (k - j)] - dot;
            if j == k {
                if s <= 0.0 || !s.is_finite() {
                    return Err(());
                }
                band[k * w + bw] = s.sqrt();
            } else {
                band[k * w + bw - (k - j)] = s / band[j * w + bw];
            }
        }
    }
    Ok(())
}

/// Solves L Lᵀ x = b in place (`x` holds b on entry) with the factor of [`cholesky_band`].
fn solve_band(band: &[f64], n: usize, bw: usize, x: &mut [f64]) {
    let w = bw + 1;
    for k in 0..n {
        let l0 = k.saturating_sub(bw);
        let row = &band[k * w + bw - (k - l0)..k * w + bw];
        let dot: f64 = row.iter().zip(&x[l0..k]).map(|(a, b)| a * b).sum();
        x[k] = (x[k] - dot) / band[k * w + bw];
    }
    for k in (0..n).rev() {
        let mut s = x[k];
        for l in k + 1..(k + bw + 1).min(n) {
            s -= band[l * w + bw - (l - k)] * x[l];
        }
        x[k] = s / band[k * w + bw];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn substitution_round_trips() {
        for &eps in &[0.1f64, 0.5, 0.9, 0.99] {
            let k: f64 = ((1.0 - eps) / (1.0 + eps)).sqrt();
            let beta = (1.0 - k) / (1.0 + k);
            for i in 0..50 {
                let t = -3.0 + 6.0 * i as f64 / 49.0;
                let psi = psi_of_theta(t, beta);
                assert!((theta_of_psi(psi, beta) - t).abs() < 1e-12);
                // tan(θ/2) = k tan(ψ/2)
                assert!(((t / 2.0).tan() - k * (psi / 2.0).tan()).abs() < 1e-9 * (1.0 + (t / 2.0).tan().abs()));
            }
        }
    }

    #[test]
    fn band_cholesky_solves_a_small_system() {
        // Tridiagonal 2, −1 (bw = 1), n = 5: A x = b with x = (1, 2, 3, 4, 5).
        let n = 5;
        let bw = 1;
        let mut band = vec![0.0; n * 2];
        for k in 0..n {
            band[k * 2 + 1] = 2.0;
            if k > 0 {
                band[k * 2] = -1.0;
            }
        }
        let x: Vec<f64> = (1..=n).map(|v| v as f64).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|k| 2.0 * x[k] - if k > 0 { x[k - 1] } else { 0.0 } - if k + 1 < n { x[k + 1] } else { 0.0 })
            .collect();
        cholesky_band(&mut band, n, bw, &[false; 5]).unwrap();
        solve_band(&band, n, bw, &mut b);
        for k in 0..n {
            assert!((b[k] - x[k]).abs() < 1e-12);
        }
    }
}
