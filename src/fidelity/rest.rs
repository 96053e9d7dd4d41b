//! The rest state (ω = 0) tabulated in load: a 1-D cubic Hermite table of ln h_c(ln P).
//!
//! At ω = 0 the model is exact and simple: 1/γ1 = 0, 1/γ2 = 1, μ = μ_c (no interpolation),
//! and h_c comes from eq. 19 alone, a smooth function of the load only. The table holds
//! ln h_c on a uniform grid in ln P with two ghost nodes beyond each end, slopes from
//! fourth-order central differences (see the private `hermite` module), and is refined until the
//! relative error of h_c, measured against the rest solve at every cell centre and at
//! random loads, is below the target.

use super::check::CheckRng;
use super::hermite::{central_slope, cubic, cubic_coefficients};
use super::envelope::solve_at;
use super::error::FidelityError;
use crate::joint::Joint;

/// ln h_c(ln P) at rest over a load range.
#[derive(Debug, Clone)]
pub struct RestTable {
    x0: f64,
    inv_h: f64,
    cells: usize,
    coeffs: Vec<[f64; 4]>,
    load_min: f64,
    load_max: f64,
    /// Largest relative error of h_c measured on the check points.
    measured: f64,
}

fn rest_film(joint: &Joint, load: f64) -> Result<f64, FidelityError> {
    Ok(solve_at(joint, load, 0.0, None)?.film_thickness)
}

impl RestTable {
    /// Tabulate over [load_min, load_max] (N, 0 < min < max) until the measured relative
    /// error in h_c is at most `target`.
    pub fn build(joint: &Joint, load_min: f64, load_max: f64, target: f64) -> Result<Self, FidelityError> {
        let (a, b) = (load_min.ln(), load_max.ln());
        let mut cells = ((b - a) / 0.5).ceil().max(2.0) as usize;
        loop {
            let t = Self::with_cells(joint, load_min, load_max, cells)?;
            if t.measured <= target || cells >= 1 << 16 {
                return Ok(t);
            }
            let grow = (t.measured / target).powf(0.25) * 1.2;
            cells = ((cells as f64 * grow).ceil() as usize).max(cells + 1);
        }
    }

    fn with_cells(joint: &Joint, load_min: f64, load_max: f64, cells: usize) -> Result<Self, FidelityError> {
        let (a, b) = (load_min.ln(), load_max.ln());
        let h = (b - a) / cells as f64;
        // Nodes −2 ..= cells + 2.
        let node = |k: isize| (a + k as f64 * h).exp();
        let v: Vec<f64> = (-2..=cells as isize + 2).map(|k| rest_film(joint, node(k)).map(f64::ln)).collect::<Result<_, _>>()?;
        let coeffs = (0..cells)
            .map(|i| {
                let k = i + 2;
                let d0 = central_slope(v[k - 2], v[k - 1], v[k + 1], v[k + 2]);
                let d1 = central_slope(v[k - 1], v[k], v[k + 2], v[k + 3]);
                cubic_coefficients(v[k], v[k + 1], d0, d1)
            })
            .collect();
        let mut t = Self { x0: a, inv_h: 1.0 / h, cells, coeffs, load_min, load_max, measured: 0.0 };
        let mut rng = CheckRng::new(0x7e57_0001);
        let centres = (0..cells).map(|i| (a + (i as f64 + 0.5) * h).exp());
        let random: Vec<f64> = (0..16).map(|_| (a + rng.uniform() * (b - a)).exp()).collect();
        let mut worst = 0.0f64;
        for p in centres.chain(random) {
            let p = p.clamp(load_min, load_max);
            let exact = rest_film(joint, p)?;
            let e = ((t.film_unchecked(p) - exact) / exact).abs();
            worst = worst.max(if e.is_nan() { f64::INFINITY } else { e });
        }
        t.measured = worst;
        Ok(t)
    }

    #[inline(always)]
    fn film_unchecked(&self, load: f64) -> f64 {
        let f = (load.ln() - self.x0) * self.inv_h;
        let i = (f as usize).min(self.cells - 1); // `as` saturates: f < 0 (rounding) → 0
        cubic(&self.coeffs[i], f - i as f64).exp()
    }

    /// h_c at rest (m), or `None` outside the load range.
    #[inline]
    pub fn film(&self, load: f64) -> Option<f64> {
        self.contains(load).then(|| self.film_unchecked(load))
    }

    /// Whether `load` (N) is inside the load range (where [`RestTable::film`] answers).
    #[inline]
    pub fn contains(&self, load: f64) -> bool {
        load >= self.load_min && load <= self.load_max
    }

    /// h_c at rest (m) at the load clamped into the load range.
    #[inline]
    pub(crate) fn film_clamped(&self, load: f64) -> f64 {
        self.film_unchecked(load.clamp(self.load_min, self.load_max))
    }

    /// Largest relative error of h_c measured on the check points.
    pub fn measured_error(&self) -> f64 {
        self.measured
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.cells
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Params;

    #[test]
    fn rest_table_meets_its_target_on_fresh_loads() {
        let j = Joint::new(&Params::default()).unwrap();
        for target in [1e-3, 1e-6, 1e-9] {
            let t = RestTable::build(&j, 1e3, 300e3, target).unwrap();
            assert!(t.measured_error() <= target);
            let mut rng = CheckRng::new(99);
            for _ in 0..200 {
                let p = 1e3 * (300f64).powf(rng.uniform());
                let exact = rest_film(&j, p).unwrap();
                let e = ((t.film(p).unwrap() - exact) / exact).abs();
                assert!(e <= 2.0 * target, "target {target}: P = {p} N, error {e}");
            }
            assert!(t.film(999.0).is_none() && t.film(300.1e3).is_none());
        }
    }
}
