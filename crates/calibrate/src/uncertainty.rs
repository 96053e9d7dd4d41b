//! Standard errors, intervals and correlations of a least-squares fit, honest about
//! residuals that are correlated in time.
//!
//! Sensor noise is white, but model error and the differentiated velocity are not: residuals
//! within a stroke are correlated, and the textbook covariance σ²(JᵀJ)⁻¹ (σ² = RSS/(n−p)) is then
//! too small. So three estimates are made, in the fit's own coordinates β:
//! - **iid**: σ²(JᵀJ)⁻¹;
//! - **cluster-robust** (sandwich with the strokes as clusters, G/(G−1) small-sample factor):
//!   (JᵀJ)⁻¹ (Σ_g J_gᵀ r_g r_gᵀ J_g) (JᵀJ)⁻¹, or the jackknife over strokes when that is larger
//!   in every coordinate (it corrects the sandwich for each stroke's leverage), used when there
//!   are at least [`MIN_CLUSTERS`] strokes, with Student-t quantiles on G − 1 degrees of freedom;
//! - **bootstrap over strokes** (when there are at least [`MIN_BOOTSTRAP_CLUSTERS`]): strokes
//!   drawn with replacement, each draw refitted by one Gauss–Newton step from the fit
//!   (exact for the linear μ_c fit), 95 % percentile interval.
//!
//! The reported standard error is the larger of iid and cluster-robust; the reported 95 %
//! interval is the union of the t interval on it and the bootstrap interval. The quasi-static
//! fit then widens both by the two-way cluster-robust covariance, strokes × phases of the cycle
//! ([`widen_two_way`]), which sees errors repeated in every cycle.

use nalgebra::{DMatrix, DVector};

/// Strokes needed for the cluster-robust covariance.
pub const MIN_CLUSTERS: usize = 6;
/// Strokes needed for the bootstrap.
pub const MIN_BOOTSTRAP_CLUSTERS: usize = 20;

/// Uncertainty of the fit coordinates β.
#[derive(Debug, Clone)]
pub struct Uncertainty {
    /// Standard error of each β (the larger of iid and cluster-robust).
    pub standard_error: Vec<f64>,
    /// iid standard error.
    pub standard_error_iid: Vec<f64>,
    /// Cluster-robust standard error, if enough strokes.
    pub standard_error_cluster: Option<Vec<f64>>,
    /// The t quantile used (97.5 %).
    pub quantile: f64,
    /// Degrees of freedom of that t quantile.
    pub dof: usize,
    /// 95 % interval of each β: t interval ∪ bootstrap interval.
    pub ci95: Vec<(f64, f64)>,
    /// Bootstrap percentile interval, if enough strokes.
    pub bootstrap_ci95: Option<Vec<(f64, f64)>>,
    /// Correlation matrix (from the covariance behind `standard_error`).
    pub correlation: Vec<Vec<f64>>,
    /// Condition number of the column-scaled JᵀJ.
    pub condition: f64,
    /// Residual standard deviation √(RSS/(n−p)).
    pub sigma: f64,
}

/// Student-t 97.5 % quantile on `nu` degrees of freedom: the Cornish–Fisher expansion in 1/ν
/// to the third order (error < 0.005 at ν = 5, < 1e-4 from ν = 10).
pub fn t975(nu: usize) -> f64 {
    let z: f64 = 1.959963984540054;
    let v = nu.max(1) as f64;
    let (z3, z5, z7) = (z.powi(3), z.powi(5), z.powi(7));
    z + (z3 + z) / (4.0 * v) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v)
        + (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * v * v * v)
}

/// SplitMix64, the library's seeded generator (`pinjoint::fidelity::check::CheckRng`), for the
/// bootstrap draws.
pub use pinjoint::fidelity::check::CheckRng as SplitMix;

/// Uniform integer in 0..n (n > 0) from `rng`.
pub fn below(rng: &mut SplitMix, n: usize) -> usize {
    (rng.uniform() * n as f64) as usize % n
}

/// Uncertainty of β from the Jacobian `j` (n × p, of the model with respect to β) and residuals
/// `r` at the fit, with each row's cluster (stroke) index in `cluster` (0..clusters).
pub fn analyse(j: &DMatrix<f64>, r: &DVector<f64>, cluster: &[usize], clusters: usize, resamples: usize, seed: u64) -> Option<Uncertainty> {
    let (n, p) = j.shape();
    if n <= p {
        return None;
    }
    let jtj = j.transpose() * j;
    // Non-finite sums (values overflowing f64) would leave the eigen-solver below without convergence.
    if !(jtj.iter().all(|x| x.is_finite()) && r.iter().all(|x| x.is_finite())) {
        return None;
    }
    let inv = jtj.clone().try_inverse()?;
    let sigma2 = r.norm_squared() / (n - p) as f64;
    let cov_iid = &inv * sigma2;
    // Per-cluster scores g_c = J_cᵀ r_c and normal matrices A_c = J_cᵀ J_c.
    let mut g = vec![DVector::<f64>::zeros(p); clusters];
    let mut a = vec![DMatrix::<f64>::zeros(p, p); clusters];
    for i in 0..n {
        let row = j.row(i).transpose();
        g[cluster[i]] += &row * r[i];
        a[cluster[i]] += &row * row.transpose();
    }
    let live: Vec<usize> = (0..clusters).filter(|&c| a[c].iter().any(|x| *x != 0.0)).collect();
    let gc = live.len();
    let cov_cluster = (gc >= MIN_CLUSTERS).then(|| {
        let mut meat = DMatrix::<f64>::zeros(p, p);
        for &c in &live {
            meat += &g[c] * g[c].transpose();
        }
        let sandwich = &inv * meat * &inv * (gc as f64 / (gc - 1) as f64);
        // The jackknife over strokes: each stroke left out in turn, δ_c = −(JᵀJ − A_c)⁻¹ g_c
        // (exact for a linear fit), cov = (G−1)/G Σ (δ_c − δ̄)(δ_c − δ̄)ᵀ. It corrects the
        // sandwich's shrinkage by each stroke's own leverage (the residuals of a stroke that
        // pulls the fit are too small), which matters when a few dozen strokes fit several
        // quantities; the larger of the two is used.
        let deltas: Vec<DVector<f64>> =
            live.iter().filter_map(|&c| (&jtj - &a[c]).lu().solve(&g[c]).map(|d| -d)).collect();
        if deltas.len() < live.len() {
            return sandwich;
        }
        let mean = deltas.iter().fold(DVector::<f64>::zeros(p), |m, d| m + d) / gc as f64;
        let mut jack = DMatrix::<f64>::zeros(p, p);
        for d in &deltas {
            let e = d - &mean;
            jack += &e * e.transpose();
        }
        jack *= (gc - 1) as f64 / gc as f64;
        if (0..p).all(|k| jack[(k, k)] >= sandwich[(k, k)]) { jack } else { sandwich }
    });
    let se_iid: Vec<f64> = (0..p).map(|k| cov_iid[(k, k)].max(0.0).sqrt()).collect();
    let se_cl: Option<Vec<f64>> = cov_cluster.as_ref().map(|c| (0..p).map(|k| c[(k, k)].max(0.0).sqrt()).collect());
    let (se, cov, dof) = match (&se_cl, &cov_cluster) {
        (Some(s), Some(c)) => {
            let se: Vec<f64> = (0..p).map(|k| s[k].max(se_iid[k])).collect();
            let cov = if (0..p).all(|k| s[k] >= se_iid[k]) { c.clone() } else { cov_iid.clone() };
            (se, cov, gc - 1)
        }
        _ => (se_iid.clone(), cov_iid.clone(), n - p),
    };
    let q = t975(dof);
    let zero = DVector::<f64>::zeros(p);
    let bootstrap = (gc >= MIN_BOOTSTRAP_CLUSTERS && resamples >= 40).then(|| {
        let mut rng = SplitMix::new(seed);
        let mut draws: Vec<Vec<f64>> = vec![Vec::with_capacity(resamples); p];
        for _ in 0..resamples {
            let (mut am, mut gv) = (DMatrix::<f64>::zeros(p, p), zero.clone());
            for _ in 0..gc {
                let c = live[below(&mut rng, gc)];
                am += &a[c];
                gv += &g[c];
            }
            if let Some(step) = am.lu().solve(&gv) {
                for k in 0..p {
                    draws[k].push(step[k]);
                }
            }
        }
        draws
            .into_iter()
            .map(|mut d| {
                d.sort_by(f64::total_cmp);
                if d.is_empty() {
                    return (0.0, 0.0);
                }
                let at = |f: f64| d[((d.len() - 1) as f64 * f).round() as usize];
                (at(0.025), at(0.975))
            })
            .collect::<Vec<_>>()
    });
    let ci95 = (0..p)
        .map(|k| {
            let (mut lo, mut hi) = (-q * se[k], q * se[k]);
            if let Some(b) = &bootstrap {
                lo = lo.min(b[k].0);
                hi = hi.max(b[k].1);
            }
            (lo, hi)
        })
        .collect();
    let correlation = (0..p)
        .map(|x| (0..p).map(|y| cov[(x, y)] / (cov[(x, x)] * cov[(y, y)]).sqrt()).collect())
        .collect();
    // Condition number of the column-scaled normal matrix.
    let d: Vec<f64> = (0..p).map(|k| jtj[(k, k)].sqrt().max(f64::MIN_POSITIVE)).collect();
    let scaled = DMatrix::from_fn(p, p, |x, y| jtj[(x, y)] / (d[x] * d[y]));
    let eig = scaled.symmetric_eigenvalues();
    let (emin, emax) = eig.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &e| (lo.min(e), hi.max(e)));
    let condition = if emin > 0.0 { emax / emin } else { f64::INFINITY };
    Some(Uncertainty {
        standard_error: se,
        standard_error_iid: se_iid,
        standard_error_cluster: se_cl,
        quantile: q,
        dof,
        ci95,
        bootstrap_ci95: bootstrap,
        correlation,
        condition,
        sigma: sigma2.sqrt(),
    })
}

/// Widen `u` by the two-way cluster-robust covariance (Cameron, Gelbach and Miller 2011,
/// "Robust inference with multiway clustering", J. Bus. Econ. Stat. 29(2)): strokes (`cluster`)
/// and phases of the cycle (`phase`, the same place in every stroke of one direction of one
/// record), V = V_stroke + V_phase − V_cell with the cells the (stroke, phase) pairs. It sees
/// errors that repeat in every cycle (the stroke clusters alone do not: their spread from stroke
/// to stroke is 0). A standard error, and its t interval, grow where this one is larger; with
/// fewer than [`MIN_CLUSTERS`] phases nothing changes.
pub fn widen_two_way(u: &mut Uncertainty, j: &DMatrix<f64>, r: &DVector<f64>, cluster: &[usize], phase: &[usize]) {
    let (n, p) = j.shape();
    let Some(inv) = (j.transpose() * j).try_inverse() else { return };
    let phases = phase.iter().max().map_or(0, |m| m + 1);
    if phases < MIN_CLUSTERS {
        return;
    }
    // The meat Σ_g s_g s_gᵀ of the scores summed within each group of `key`.
    let meat = |key: &dyn Fn(usize) -> (usize, usize)| {
        // Ordered: a hash map's iteration order (random per map) changed the sum's last bits
        // from run to run, so the same fit gave different standard errors.
        let mut g: std::collections::BTreeMap<(usize, usize), DVector<f64>> = std::collections::BTreeMap::new();
        for i in 0..n {
            let s = g.entry(key(i)).or_insert_with(|| DVector::zeros(p));
            for k in 0..p {
                s[k] += j[(i, k)] * r[i];
            }
        }
        g.values().fold(DMatrix::<f64>::zeros(p, p), |m, s| m + s * s.transpose())
    };
    let m = meat(&|i| (cluster[i], 0)) + meat(&|i| (0, phase[i])) - meat(&|i| (cluster[i], phase[i]));
    let v = &inv * m * &inv;
    for k in 0..p {
        let se = v[(k, k)].max(0.0).sqrt();
        if se > u.standard_error[k] {
            u.standard_error[k] = se;
            let (lo, hi) = u.ci95[k];
            u.ci95[k] = (lo.min(-u.quantile * se), hi.max(u.quantile * se));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_quantiles() {
        // Published 97.5 % points of Student's t.
        for (nu, t) in [(5, 2.570582), (10, 2.228139), (30, 2.042272), (1000, 1.962339)] {
            assert!((t975(nu) - t).abs() < 5e-3 * t, "{nu}: {}", t975(nu));
        }
        assert!((t975(10) - 2.228139).abs() < 2e-4);
    }

    #[test]
    fn iid_mean_has_the_textbook_standard_error() {
        // Fitting a constant: se = s/√n.
        let y = [1.0, 2.0, 4.0, 3.0, 5.0, 0.0, 2.0, 3.0];
        let n = y.len();
        let mean = y.iter().sum::<f64>() / n as f64;
        let j = DMatrix::from_element(n, 1, 1.0);
        let r = DVector::from_iterator(n, y.iter().map(|v| v - mean));
        let u = analyse(&j, &r, &vec![0; n], 1, 0, 1).unwrap();
        let s = (r.norm_squared() / (n - 1) as f64).sqrt();
        assert!((u.standard_error[0] - s / (n as f64).sqrt()).abs() < 1e-14);
        assert!(u.standard_error_cluster.is_none() && u.bootstrap_ci95.is_none());
    }

    #[test]
    fn cluster_errors_see_correlated_residuals() {
        // 30 clusters of 100 identical residuals: the iid error is √100 too small.
        let mut rng = SplitMix::new(7);
        let (g, m) = (30, 100);
        let mut r = Vec::new();
        let mut cl = Vec::new();
        for c in 0..g {
            let e = rng.uniform() - 0.5;
            for _ in 0..m {
                r.push(e);
                cl.push(c);
            }
        }
        let mean = r.iter().sum::<f64>() / r.len() as f64;
        let r = DVector::from_iterator(r.len(), r.iter().map(|v| v - mean));
        let j = DMatrix::from_element(g * m, 1, 1.0);
        let u = analyse(&j, &r, &cl, g, 400, 3).unwrap();
        let ratio = u.standard_error_cluster.as_ref().unwrap()[0] / u.standard_error_iid[0];
        assert!(ratio > 8.0 && ratio < 11.0, "{ratio}");
        let b = u.bootstrap_ci95.unwrap()[0];
        assert!(b.1 - b.0 > 2.0 * u.standard_error_iid[0] * 1.96 * 5.0);
    }

    #[test]
    fn two_way_errors_see_a_pattern_repeated_in_every_stroke() {
        // 40 strokes of 8 phases: white noise plus a pattern that is the same in every stroke.
        // Fitting a slope on x = ±1 alternating phases, the pattern e_φ·x_φ adds up coherently
        // over the strokes: its variance is 40² Σ_φ e_φ², which the stroke clusters see only
        // as 40 Σ_φ e_φ² (and the fit's residuals hide it). The two-way error must see it.
        let mut rng = SplitMix::new(11);
        let (g, m) = (40usize, 8usize);
        let pattern: Vec<f64> = (0..m).map(|_| rng.uniform() - 0.5).collect();
        let (mut x, mut y, mut cl, mut ph) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for c in 0..g {
            for (k, e) in pattern.iter().enumerate() {
                let xi = if k % 2 == 0 { 1.0 } else { -1.0 };
                x.push(xi);
                y.push(e + 0.01 * (rng.uniform() - 0.5));
                cl.push(c);
                ph.push(k);
            }
        }
        let n = x.len();
        let j = DMatrix::from_iterator(n, 1, x.iter().copied());
        let beta = x.iter().zip(&y).map(|(a, b)| a * b).sum::<f64>() / n as f64;
        let r = DVector::from_iterator(n, x.iter().zip(&y).map(|(a, b)| b - beta * a));
        let mut u = analyse(&j, &r, &cl, g, 0, 1).unwrap();
        let before = u.standard_error[0];
        widen_two_way(&mut u, &j, &r, &cl, &ph);
        // β̂ − β = Σ_φ x_φ·e_φ / m whatever the number of strokes: over draws of the pattern
        // its standard deviation is √(Σ_φ Var e_φ)/m, estimated by √(Σ_φ r_φ²)/m from the
        // per-phase residuals r_φ. The two-way sandwich gives √(1 − 1/g) of that (its meat is
        // g²·Σ r_φ² from the phases, less g·Σ r_φ² from the cells, and ≈ 0 from the strokes,
        // whose scores the fit makes 0); the iid error gives 1/√g of it and the stroke one ≈ 0.
        let exact = (pattern.iter().enumerate().map(|(k, e)| (e - beta * if k % 2 == 0 { 1.0 } else { -1.0 }).powi(2)).sum::<f64>()).sqrt() / m as f64;
        assert!(before < 0.3 * exact, "stroke-clustered {before} vs {exact}");
        assert!((u.standard_error[0] / (exact * (1.0 - 1.0 / g as f64).sqrt()) - 1.0).abs() < 0.02, "two-way {} vs {exact}", u.standard_error[0]);
        assert!(u.ci95[0].1 >= u.quantile * u.standard_error[0] * 0.999);
    }
}
