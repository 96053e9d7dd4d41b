//! What the quasi-static fit ([`crate::fit`]) and the rig fit ([`crate::rig_fit`]) share: the
//! options' checks, the fitted quantities' keys, their estimates in the parameters' own units
//! and the identifiability warnings.

use super::coords::{Extra, Transform, MU_C};
use super::error::CalibrationError;
use super::options::Options;
use super::result::Estimate;
use super::uncertainty::{Uncertainty, MIN_BOOTSTRAP_CLUSTERS, MIN_CLUSTERS};
use nalgebra::{DMatrix, DVector};

/// Used samples needed per fitted quantity.
pub const MIN_POINTS_PER_PARAMETER: usize = 10;

/// The key of the fitted rotating inertia J (as in the parameter file's `[rig]` table).
pub const INERTIA: &str = "rig.inertia";

/// Check the options that no other check covers: the inertia, the exclusion rule, the
/// differentiator's half-width and the sample budget.
pub fn check_options(o: &Options) -> Result<(), CalibrationError> {
    let bad = |what: String| Err(CalibrationError::Option(what));
    if let Some(j) = o.inertia
        && !(j.is_finite() && j >= 0.0)
    {
        return bad(format!("inertia = {j} kg.m2 is invalid: it must be a finite number >= 0 kg.m2"));
    }
    if o.max_samples < 1000 {
        return bad(format!("max_samples = {} is invalid: the sample budget must be at least 1000 samples", o.max_samples));
    }
    let f = o.exclusion.speed_fraction;
    if !(0.0..1.0).contains(&f) {
        return bad(format!("exclusion speed fraction = {f} is invalid: it must be in [0, 1)"));
    }
    let s = o.exclusion.settle_time;
    if !(s.is_finite() && s >= 0.0) {
        return bad(format!("exclusion settle time = {s} s is invalid: it must be a finite number >= 0 s"));
    }
    if o.half_width == Some(0) {
        return bad("differentiator half-width = 0 samples is invalid: it must be >= 1".into());
    }
    Ok(())
}

/// The keys of the fit coordinates in order: the extras, μ_c, J when fitted, T_0 when fitted.
pub fn keys_of(extras: &[Extra], inertia: bool, offset: bool) -> Vec<String> {
    extras
        .iter()
        .map(|e| e.key.name())
        .chain(std::iter::once(MU_C.to_string()))
        .chain(inertia.then(|| INERTIA.to_string()))
        .chain(offset.then(|| "torque_offset".to_string()))
        .collect()
}

/// The estimate of fit coordinate `k` (value `b`, transform, unit and start value) in the
/// parameter's own units, its interval mapped through the transform.
pub fn estimate(key: &str, (t, unit, initial): (Transform, &'static str, f64), b: f64, u: &Uncertainty, k: usize) -> Estimate {
    let slope = t.slope(b);
    let (lo, hi) = u.ci95[k];
    Estimate {
        key: key.to_string(),
        unit,
        value: t.inverse(b),
        initial,
        standard_error: slope * u.standard_error[k],
        standard_error_iid: slope * u.standard_error_iid[k],
        standard_error_cluster: u.standard_error_cluster.as_ref().map(|s| slope * s[k]),
        ci95: (t.inverse(b + lo), t.inverse(b + hi)),
        bootstrap_ci95: u.bootstrap_ci95.as_ref().map(|c| (t.inverse(b + c[k].0), t.inverse(b + c[k].1))),
    }
}

/// Identifiability, precision, collinearity and interval warnings of a fit.
#[allow(clippy::too_many_arguments)]
pub fn warnings(
    extras: &[Extra],
    jac: &DMatrix<f64>,
    model: &DVector<f64>,
    u: &Uncertainty,
    estimates: &[Estimate],
    keys: &[String],
    clusters: usize,
    o: &Options,
) -> Vec<String> {
    let mut w = Vec::new();
    let scale = model.norm().max(f64::MIN_POSITIVE);
    for (k, e) in extras.iter().enumerate() {
        // ∂T/∂β for a log coordinate is the torque change per unit relative change.
        let rel = jac.column(k).norm() / scale;
        if rel < 1e-3 {
            w.push(format!(
                "{} is not identifiable from these records: a 1 % change of it moves the fitted torque by {:.2e} % (rms); \
                 its interval means nothing (e.g. viscosity from records that never leave the boundary regime)",
                e.key.name(),
                rel
            ));
        }
    }
    for e in estimates {
        if e.value != 0.0 && (e.standard_error / e.value.abs()) > 0.5 {
            w.push(format!("{} is poorly determined: its standard error is {:.0} % of its value", e.key, 100.0 * e.standard_error / e.value.abs()));
        }
    }
    if u.condition > 1e6 {
        let p = keys.len();
        let (mut best, mut pair) = (0.0, (0, 0));
        for a in 0..p {
            for b in a + 1..p {
                if u.correlation[a][b].abs() > best {
                    best = u.correlation[a][b].abs();
                    pair = (a, b);
                }
            }
        }
        w.push(format!(
            "the fitted quantities are nearly collinear (condition number {:.3e}); the strongest correlation is {} with {} ({:.4})",
            u.condition, keys[pair.0], keys[pair.1], u.correlation[pair.0][pair.1]
        ));
    }
    if clusters < MIN_CLUSTERS {
        w.push(format!(
            "only {clusters} strokes: the intervals assume independent residuals and are likely too narrow (cluster-robust errors need {MIN_CLUSTERS})"
        ));
    } else if clusters < MIN_BOOTSTRAP_CLUSTERS && o.resamples > 0 {
        w.push(format!("only {clusters} strokes: no bootstrap (it needs {MIN_BOOTSTRAP_CLUSTERS}); intervals from the cluster-robust errors"));
    }
    let mu = estimates[0].value;
    if mu < 0.0 {
        w.push(format!("fitted {MU_C} = {mu} is negative: the records are not described by this model"));
    }
    w
}

