//! Jₙ(ε, θ_c) tabulated once per flow index n (a process-wide cache), for the model's hot
//! path: a bicubic lookup instead of the 12-node rule of [`super::integrals`].
//!
//! Coordinates: x = −ln k ∈ [0, X_MAX], k = ((1−ε)/(1+ε))^¼ (the balanced substitution's k;
//! X_MAX at ε = 1 − 1e-9), and w = ln tan(χ_c/2) = ln(tan(θ_c/2)/k), the contact arc's end in
//! the balanced angle on a logarithmic scale. The integrand's two features, the narrow gap
//! (θ_c ~ √(1−ε), w ≈ −x) and the wide one (χ_c → π, w ≈ +x), are each about one unit wide
//! in w at every ε. Tabulated: F(x) = ln Jₙ(ε, 0) and L(x, w) = ln(Jₙ(ε, θ_c)/Jₙ(ε, 0)) on a
//! uniform grid, w ∈ [−W, W], W = X_MAX + 6; beyond, L → 0 like e^w (w < −W) and L linear in
//! w (w > W, Jₙ ∝ e^−w as θ_c → π). Values and finite-difference derivatives (second order)
//! define C¹ cubic Hermite interpolants (bicubic for L). The nodes come from a composite
//! rule (8 panels × 12 Gauss–Legendre nodes in χ).

use std::f64::consts::PI;
use std::sync::Arc;

use super::integrals::{GAUSS12, MAX_ECCENTRICITY, ln};
use crate::numerics::table_cache::TableCache;

/// Intervals in x.
const NX: usize = 27;
/// Intervals in w.
const NW: usize = 120;
/// Margin of the w range beyond ±X_MAX.
const W_MARGIN: f64 = 6.0;
/// Panels of the composite rule that computes the nodes.
const PANELS: usize = 8;
/// The process-wide cache of tables by flow index: at most 64 (emptied when full; tables in
/// use live on).
static CACHE: TableCache<PowerLawTable> = TableCache::new(64);

/// The flow index is outside (0, 1].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("clearance: flow index n = {0} (dimensionless) must be in (0, 1] for the power-law table")]
pub struct FlowIndexError(pub f64);

/// x at the largest eccentricity ratio.
fn x_max() -> f64 {
    -0.25 * ((1.0 - MAX_ECCENTRICITY) / (1.0 + MAX_ECCENTRICITY)).ln()
}

/// Jₙ and ∂Jₙ/∂ε (at fixed θ_c) by the composite rule in χ over [χ_c, π], at x (k = e^−x):
/// ∂/∂ε (1 − ε cos θ)^−n = n (1 − ε cos θ)^(−n−1) cos θ, with cos θ = (p − k²m)/(p + k²m),
/// p = 1 + cos χ, m = 1 − cos χ.
fn rule(x: f64, chi_c: f64, n: f64) -> (f64, f64) {
    let k = (-x).exp();
    let k2 = k * k;
    let k4 = k2 * k2;
    // 1 − ε and 1 + ε without cancellation: ε = (1 − k⁴)/(1 + k⁴).
    let (a0, one_plus) = (2.0 * k4 / (1.0 + k4), 2.0 / (1.0 + k4));
    let a1 = one_plus * k2;
    let width = (PI - chi_c) / PANELS as f64;
    let (mut sum, mut dsum) = (0.0, 0.0);
    for p in 0..PANELS {
        let mid = chi_c + (p as f64 + 0.5) * width;
        for (t, w) in GAUSS12 {
            let c = (mid + 0.5 * width * t).cos();
            let (pp, m) = (1.0 + c, 1.0 - c);
            let b = pp + k2 * m;
            let h = (a0 * pp + a1 * m) / b;
            let g = h.powf(-n) / b;
            sum += 0.5 * width * w * g;
            dsum += 0.5 * width * w * n * g / h * (pp - k2 * m) / b;
        }
    }
    (4.0 * k * sum, 4.0 * k * dsum)
}

/// dε/dx at x: ε = (1 − k⁴)/(1 + k⁴), k = e^−x, so dε/dx = 8k⁴/(1 + k⁴)².
fn deps_dx(x: f64) -> f64 {
    let k4 = (-4.0 * x).exp();
    8.0 * k4 / ((1.0 + k4) * (1.0 + k4))
}

/// (1 − ε cos θ_c)^−n at x and θ_c.
fn h_pow(x: f64, theta_c: f64, n: f64) -> f64 {
    let k4 = (-4.0 * x).exp();
    let e = (1.0 - k4) / (1.0 + k4);
    (1.0 - e * theta_c.cos()).powf(-n)
}

/// Cubic Hermite basis at s ∈ [0, 1]: (h00, h10, h01, h11).
fn hermite(s: f64) -> [f64; 4] {
    let s2 = s * s;
    let s3 = s2 * s;
    [2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, -2.0 * s3 + 3.0 * s2, s3 - s2]
}

/// Second-order finite-difference derivative (in cell units) of `f` at index `i` of `len+1`.
fn diff(f: &dyn Fn(usize) -> f64, i: usize, last: usize) -> f64 {
    if i == 0 {
        -1.5 * f(0) + 2.0 * f(1) - 0.5 * f(2)
    } else if i == last {
        1.5 * f(last) - 2.0 * f(last - 1) + 0.5 * f(last - 2)
    } else {
        0.5 * (f(i + 1) - f(i - 1))
    }
}

/// Jₙ(ε, θ_c) tabulated for one flow index n.
#[derive(Debug, Clone, PartialEq)]
pub struct PowerLawTable {
    flow_index: f64,
    dx: f64,
    w_max: f64,
    dw: f64,
    /// F and dF (cell units) per x node.
    full: Vec<[f64; 2]>,
    /// Per node (i, j), index i·(NW+1) + j: [L, L_x, L_w, L_xw] (cell units).
    nodes: Vec<[f64; 4]>,
}

impl PowerLawTable {
    /// The table of flow index `n` ∈ (0, 1] from the process-wide cache, built on first use
    /// (tens of milliseconds: `benches/journal.rs`).
    pub fn shared(n: f64) -> Result<Arc<PowerLawTable>, FlowIndexError> {
        CACHE.get_or_build(n, Self::build)
    }

    /// Builds the table of flow index `n` ∈ (0, 1] (not cached; at n = 1 the torque uses the
    /// closed form J₁ instead).
    pub fn build(n: f64) -> Result<PowerLawTable, FlowIndexError> {
        if !(n > 0.0 && n <= 1.0) {
            return Err(FlowIndexError(n));
        }
        let dx = x_max() / NX as f64;
        let w_max = x_max() + W_MARGIN;
        let dw = 2.0 * w_max / NW as f64;
        // F = ln J(x, θ_c = 0) and dF/dx (exact, from ∂J/∂ε); derivatives in cell units.
        let full: Vec<[f64; 2]> = (0..=NX)
            .map(|i| {
                let x = i as f64 * dx;
                let (j0, dj0) = rule(x, 0.0, n);
                [j0.ln(), dj0 * deps_dx(x) / j0 * dx]
            })
            .collect();
        // L = ln(J/J0), L_x and L_w exact (θ_c = 2 atan(k e^w): ∂θ_c/∂w = −∂θ_c/∂x =
        // 2k e^w/(1 + k² e^2w); ∂J/∂θ_c = −2 (1 − ε cos θ_c)^−n), L_xw by differences of L_w.
        let mut vals = vec![[0.0f64; 3]; (NX + 1) * (NW + 1)];
        for i in 0..=NX {
            let x = i as f64 * dx;
            let k = (-x).exp();
            for j in 0..=NW {
                let w = -w_max + j as f64 * dw;
                let chi_c = 2.0 * w.exp().atan();
                let (jv, dj_eps) = rule(x, chi_c, n);
                let kew = k * w.exp();
                let theta_c = 2.0 * kew.atan();
                let dtheta = 2.0 * kew / (1.0 + kew * kew);
                let dj_dtheta = -2.0 * h_pow(x, theta_c, n);
                let lx = (dj_eps * deps_dx(x) - dj_dtheta * dtheta) / jv - full[i][1] / dx;
                let lw = dj_dtheta * dtheta / jv;
                vals[i * (NW + 1) + j] = [jv.ln() - full[i][0], lx * dx, lw * dw];
            }
        }
        let at = |i: usize, j: usize| vals[i * (NW + 1) + j];
        let mut nodes = Vec::with_capacity(vals.len());
        for i in 0..=NX {
            for j in 0..=NW {
                let v = at(i, j);
                nodes.push([v[0], v[1], v[2], diff(&|k| at(k, j)[2], i, NX)]);
            }
        }
        Ok(PowerLawTable { flow_index: n, dx, w_max, dw, full, nodes })
    }

    /// The flow index n of the table.
    pub fn flow_index(&self) -> f64 {
        self.flow_index
    }

    /// L and ∂L/∂w (per unit w) at x-cell (i, u) and w-node j, interpolated in x.
    fn edge(&self, i: usize, hu: &[f64; 4], j: usize) -> (f64, f64) {
        let a = &self.nodes[i * (NW + 1) + j];
        let b = &self.nodes[(i + 1) * (NW + 1) + j];
        let v = a[0] * hu[0] + a[1] * hu[1] + b[0] * hu[2] + b[1] * hu[3];
        let d = a[2] * hu[0] + a[3] * hu[1] + b[2] * hu[2] + b[3] * hu[3];
        (v, d / self.dw)
    }

    /// Jₙ(ε, θ_c) = ∫_{θ_c}^{2π−θ_c} (1 − ε cos θ)^−n dθ by the table (ε clamped to
    /// [0, [`super::MAX_ECCENTRICITY`]], θ_c to [0, π]).
    pub fn integral(&self, eps: f64, theta_c: f64) -> f64 {
        let (x, i, hu, f) = self.whole_of(eps);
        let t = theta_c.clamp(0.0, PI);
        if t == 0.0 {
            return crate::numerics::fast_math::exp(f);
        }
        self.outside_of(x, i, &hu, f, t)
    }

    /// (Jₙ(ε, 0), Jₙ(ε, θ_c)): the whole clearance's integral and the one outside the arc,
    /// bit for bit two calls of [`PowerLawTable::integral`], sharing the eccentricity's
    /// interpolation (the complete model needs both at every evaluation).
    pub fn integral_pair(&self, eps: f64, theta_c: f64) -> (f64, f64) {
        let (x, i, hu, f) = self.whole_of(eps);
        let t = theta_c.clamp(0.0, PI);
        let whole = crate::numerics::fast_math::exp(f);
        (whole, if t == 0.0 { whole } else { self.outside_of(x, i, &hu, f, t) })
    }

    /// x = ¼ ln((1 + ε)/(1 − ε)), its cell, the cell's Hermite weights and ln Jₙ(ε, 0).
    #[inline]
    fn whole_of(&self, eps: f64) -> (f64, usize, [f64; 4], f64) {
        let e = eps.clamp(0.0, MAX_ECCENTRICITY);
        let x = -0.25 * ln((1.0 - e) / (1.0 + e));
        let gx = (x / self.dx).clamp(0.0, NX as f64);
        let i = (gx as usize).min(NX - 1);
        let hu = hermite(gx - i as f64);
        let (f0, f1) = (&self.full[i], &self.full[i + 1]);
        let f = f0[0] * hu[0] + f0[1] * hu[1] + f1[0] * hu[2] + f1[1] * hu[3];
        (x, i, hu, f)
    }

    /// Jₙ outside the arc |θ| ≤ `t` (0 < t, clamped to ≤ π) from [`PowerLawTable::whole_of`].
    #[inline]
    fn outside_of(&self, x: f64, i: usize, hu: &[f64; 4], f: f64, t: f64) -> f64 {
        if t >= PI {
            return 0.0;
        }
        let w = ln((0.5 * t).tan()) + x;
        let l = if w <= -self.w_max {
            let (v, _) = self.edge(i, hu, 0);
            v * crate::numerics::fast_math::exp(w + self.w_max)
        } else if w >= self.w_max {
            let (v, d) = self.edge(i, hu, NW);
            v + d * (w - self.w_max)
        } else {
            let gw = ((w + self.w_max) / self.dw).clamp(0.0, NW as f64);
            let j = (gw as usize).min(NW - 1);
            let hv = hermite(gw - j as f64);
            let n = |a: usize, b: usize| &self.nodes[a * (NW + 1) + b];
            let corner = |nd: &[f64; 4], au: f64, bu: f64, av: f64, bv: f64| nd[0] * au * av + nd[1] * bu * av + nd[2] * au * bv + nd[3] * bu * bv;
            corner(n(i, j), hu[0], hu[1], hv[0], hv[1]) + corner(n(i, j + 1), hu[0], hu[1], hv[2], hv[3]) + corner(n(i + 1, j), hu[2], hu[3], hv[0], hv[1]) + corner(n(i + 1, j + 1), hu[2], hu[3], hv[2], hv[3])
        };
        crate::numerics::fast_math::exp(f + l)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_at_zero_eccentricity_and_rejects_bad_n() {
        let t = PowerLawTable::build(0.4).unwrap();
        for th in [0.0, 0.3, 2.0] {
            assert!((t.integral(0.0, th) / (2.0 * PI - 2.0 * th) - 1.0).abs() < 1e-6, "{th}: {}", t.integral(0.0, th));
        }
        for bad in [0.0, -0.5, 1.0 + 1e-12, 1.5, f64::NAN] {
            assert!(PowerLawTable::build(bad).unwrap_err().to_string().contains("flow index"));
        }
        let a = PowerLawTable::shared(0.4).unwrap();
        assert!(Arc::ptr_eq(&a, &PowerLawTable::shared(0.4).unwrap()));
    }

    /// The worst errors over a scan against the high-order reference, by region (measured:
    /// 7.2e-5 for ε ≤ 0.999 and θ_c ≤ 1 rad, 7.3e-5 for ε ≤ 0.99999, 1e-2 beyond, where the
    /// gap is below 2.5e-4 µm per 25 µm of clearance).
    #[test]
    fn table_error_scan() {
        let mut worst = [0.0f64; 3];
        for n in [0.05, 0.2, 0.4, 0.7, 0.95] {
            let t = PowerLawTable::build(n).unwrap();
            for le in [-6.0f64, -3.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 6.9, 8.0, 9.2, 10.5, 12.0, 14.0, 16.0, 20.7] {
                let eps: f64 = (1.0 / (1.0 + (-le).exp())).min(MAX_ECCENTRICITY);
                for th in [0.0, 0.001, 0.01, 0.03, 0.1, 0.2, 0.35, 0.5, 0.78, 1.0, 1.5, 2.0, 2.5, 3.0, 3.13] {
                    let r = super::super::tests::reference(eps, th, n);
                    let err = (t.integral(eps, th) / r - 1.0).abs();
                    let region = if eps <= 0.999 && th <= 1.0 { 0 } else if eps <= 0.99999 { 1 } else { 2 };
                    worst[region] = worst[region].max(err);
                }
            }
        }
        println!("table worst relative error: ε ≤ 0.999 & θc ≤ 1: {:.1e}; ε ≤ 0.99999: {:.1e}; beyond: {:.1e}", worst[0], worst[1], worst[2]);
        assert!(worst[0] < 1e-4 && worst[1] < 1e-4 && worst[2] < 2e-2, "{worst:?}");
    }

    proptest::proptest! {
        /// Random points: the table within 1e-4 of the reference for ε ≤ 0.99999, and
        /// continuous (neighbouring points differ by O(step)).
        #[test]
        fn table_accuracy_and_continuity(n_idx in 1usize..19, logit_eps in -8.0f64..11.5, theta in 0.0f64..3.1) {
            let n = n_idx as f64 * 0.05;
            let t = PowerLawTable::shared(n).unwrap();
            let eps = 1.0 / (1.0 + (-logit_eps).exp());
            let r = super::super::tests::reference(eps, theta, n);
            let got = t.integral(eps, theta);
            proptest::prop_assert!((got / r - 1.0).abs() < 1e-4, "n {} ε {} θc {}: {} vs {}", n, eps, theta, got, r);
            let near = t.integral(eps, theta + 1e-7);
            proptest::prop_assert!((near / got - 1.0).abs() < 1e-5);
        }
    }
}
