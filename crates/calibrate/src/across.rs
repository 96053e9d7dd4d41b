//! Fitting across temperature: the records' temperatures, the keys fitted by default when they
//! span enough of them, and the identifiability screen that drops a default key the records
//! cannot determine.
//!
//! A record at a known lubricant temperature ([`crate::Record::temperature`], `--temperature`)
//! is evaluated by the joint at that temperature. The grease's temperature relations
//! (τ_y(T) = τ_y,ref·exp(E_y/R·(1/T − 1/T_ref)), the same for K with E_K) have two unknowns
//! each, the value at the reference temperature and the activation temperature E/R: records at
//! one temperature cannot tell them apart, records at two determine them exactly with no
//! redundancy, and from three on the relation itself is tested by the fit. So:
//! - with records at [`MIN_DEFAULT_TEMPERATURES`] or more distinct temperatures (more than
//!   [`DISTINCT_TEMPERATURE`] apart) and no keys named besides μ_c, the fitted set is μ_c plus
//!   [`Options::across_temperature`] (default: the grease keys of the parameter table,
//!   [`default_keys`]), screened for identifiability ([`independence`], [`worst`]): a default
//!   key whose Jacobian column is nearly collinear with the other fitted quantities' or whose
//!   standard error exceeds its value is dropped, with a warning naming it, and the fit repeated;
//! - with fewer, only the named keys are fitted, and a warning says the default needs three
//!   temperatures; a temperature relation's parameter ([`TEMPERATURE_RELATION_KEYS`]) named
//!   with records at one temperature gets a warning (it is confounded with the reference value).

use super::coords::MU_C;
use super::error::CalibrationError;
pub use super::options::{default_across_temperature as default_keys, GREASE_KEYS};
use super::options::Options;
use super::record::Record;
use super::result::Estimate;
use nalgebra::{DMatrix, DVector};
use pinjoint::params::spec_by_name;

/// Parameters of a temperature relation: records at one temperature cannot tell them from the
/// value at the reference temperature.
pub const TEMPERATURE_RELATION_KEYS: [&str; 3] =
    ["grease.yield_activation", "grease.consistency_activation", "lubricant.roelands_temperature_index"];

/// Distinct record temperatures needed for the default fit across temperature.
pub const MIN_DEFAULT_TEMPERATURES: usize = 3;

/// Record temperatures closer than this (K) count as one.
pub const DISTINCT_TEMPERATURE: f64 = 1.0;

/// A default key is dropped when the part of its (column-scaled) Jacobian column that the other
/// fitted quantities' columns do not explain is below this: √(1 − R²) < 1e-3, a variance
/// inflation over 1e6, where the fit's condition number passes the collinearity warning's 1e6.
pub const MIN_INDEPENDENCE: f64 = 1e-3;

/// What the records' temperatures make of the fitted set.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Plan {
    /// Keys fitted besides μ_c.
    pub keys: Vec<String>,
    /// Those of `keys` chosen by default, dropped when the records cannot determine them.
    pub screened: Vec<String>,
    /// Distinct temperatures of the records that give one (K, ascending).
    pub temperatures: Vec<f64>,
    /// Warnings for the report.
    pub warnings: Vec<String>,
}

/// Mean temperature of each record (K), None for a record without one.
pub fn record_temperatures(records: &[Record]) -> Vec<Option<f64>> {
    records
        .iter()
        // The mean of the differences from the first value: exact for a constant column.
        .map(|r| r.temperature.as_ref().filter(|t| !t.is_empty()).map(|t| t[0] + t.iter().map(|x| x - t[0]).sum::<f64>() / t.len() as f64))
        .collect()
}

/// The distinct values of `temps` (ascending), values within [`DISTINCT_TEMPERATURE`] of the
/// group's first counting as one (the group's mean is kept).
pub fn distinct(temps: &[f64]) -> Vec<f64> {
    let mut t: Vec<f64> = temps.iter().copied().filter(|x| x.is_finite()).collect();
    t.sort_by(f64::total_cmp);
    let mut groups: Vec<Vec<f64>> = Vec::new();
    for x in t {
        match groups.last_mut() {
            Some(g) if x - g[0] <= DISTINCT_TEMPERATURE => g.push(x),
            _ => groups.push(vec![x]),
        }
    }
    groups.iter().map(|g| g.iter().sum::<f64>() / g.len() as f64).collect()
}

fn list(t: &[f64]) -> String {
    t.iter().map(|x| format!("{}", (x * 100.0).round() / 100.0)).collect::<Vec<_>>().join(", ")
}

/// The keys to fit: the named ones (`options.fit`), or, when none is named besides μ_c and
/// the records span [`MIN_DEFAULT_TEMPERATURES`] temperatures, `options.across_temperature`
/// (only when `defaults` is true: the quasi-static fit). Refuses `lubricant.temperature` in
/// `options.fit` when a record gives its temperature.
pub fn plan(records: &[Record], options: &Options, defaults: bool) -> Result<Plan, CalibrationError> {
    let per_record = record_temperatures(records);
    let given: Vec<f64> = per_record.iter().flatten().copied().collect();
    let named: Vec<String> = options.fit.iter().map(|k| k.trim().to_string()).filter(|k| !k.is_empty() && k != MU_C).collect();
    let mut plan = Plan { temperatures: distinct(&given), ..Plan::default() };
    if given.is_empty() {
        plan.keys = named;
        return Ok(plan);
    }
    if named.iter().any(|k| k == "lubricant.temperature") {
        return Err(CalibrationError::Option(
            "--fit lubricant.temperature: the records give their temperatures (--temperature or a temperature column); \
             the lubricant temperature cannot be fitted to them"
                .into(),
        ));
    }
    let n = plan.temperatures.len();
    let across: Vec<String> = options.across_temperature.iter().filter(|k| spec_by_name(k).is_some()).cloned().collect();
    if named.is_empty() {
        if n >= MIN_DEFAULT_TEMPERATURES && defaults && !across.is_empty() {
            plan.keys = across.clone();
            plan.screened = across;
        } else if !across.is_empty() {
            plan.warnings.push(format!(
                "the records are at {n} temperature{} ({} K): {} {} fitted by default from records at {MIN_DEFAULT_TEMPERATURES} or more \
                 temperatures{}; fitted here: {MU_C} only (name keys with --fit to fit them from these records)",
                if n == 1 { "" } else { "s" },
                list(&plan.temperatures),
                across.join(", "),
                if across.len() == 1 { "is" } else { "are" },
                if defaults { "" } else { " by the quasi-static fit (the rig model fits the named keys only)" },
            ));
        }
        return Ok(plan);
    }
    if n < 2 {
        for k in named.iter().filter(|k| TEMPERATURE_RELATION_KEYS.contains(&k.as_str())) {
            plan.warnings.push(format!(
                "{k} is fitted from records at one temperature ({} K): a temperature relation's parameter is then confounded with \
                 the value at the reference temperature (it moves the torque only through that one temperature); record at 2 or \
                 more temperatures (3 to test the relation)",
                list(&plan.temperatures)
            ));
        }
    }
    plan.keys = named;
    Ok(plan)
}

/// For each column `k` of `jac` in `which`, √(1 − R²) of its regression on the other columns,
/// every column scaled to unit norm: 1 for a column orthogonal to the others, 0 for one they
/// explain exactly. A zero column gives 0.
pub fn independence(jac: &DMatrix<f64>, which: &[usize]) -> Vec<f64> {
    let (n, p) = jac.shape();
    let norms: Vec<f64> = (0..p).map(|k| jac.column(k).norm()).collect();
    which
        .iter()
        .map(|&k| {
            if !(norms[k] > 0.0 && norms[k].is_finite()) {
                return 0.0;
            }
            let others: Vec<usize> = (0..p).filter(|&c| c != k && norms[c] > 0.0 && norms[c].is_finite()).collect();
            let y = jac.column(k) / norms[k];
            if others.is_empty() {
                return 1.0;
            }
            let a = DMatrix::from_fn(n, others.len(), |i, c| jac[(i, others[c])] / norms[others[c]]);
            let fit = a.clone().svd(true, true).solve(&y, 1e-12).unwrap_or_else(|_| DVector::zeros(others.len()));
            (y - a * fit).norm()
        })
        .collect()
}

/// The default key to drop after a fit, and why: of the `screened` keys, one with an
/// [`independence`] below [`MIN_INDEPENDENCE`] (the smallest), else one whose standard error
/// exceeds its value (the largest ratio); None when every screened key is determined.
pub fn worst(estimates: &[Estimate], independence: &[(String, f64)], screened: &[String]) -> Option<(String, String)> {
    let collinear = independence
        .iter()
        .filter(|(k, d)| screened.contains(k) && *d < MIN_INDEPENDENCE)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((k, d)) = collinear {
        return Some((
            k.clone(),
            format!("its Jacobian column is nearly collinear with the other fitted quantities' (the part they do not explain is {d:.2e} of it)"),
        ));
    }
    estimates
        .iter()
        .filter(|e| screened.contains(&e.key))
        .map(|e| (e, e.standard_error / e.value.abs()))
        .filter(|(_, r)| r.is_nan() || *r > 1.0)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(e, r)| {
            (e.key.clone(), format!("its standard error {:.3e} {} is {:.2} times its value {:.6e}", e.standard_error, e.unit, r, e.value))
        })
}

/// The warning for a default key dropped.
pub fn dropped(key: &str, why: &str) -> String {
    format!("{key} is not fitted (dropped from the default fit across temperature): {why}; it keeps its given value")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_groups_within_a_kelvin() {
        assert_eq!(distinct(&[293.15, 253.15, 293.5, 273.15, f64::NAN]), vec![253.15, 273.15, 293.325]);
        assert!(distinct(&[]).is_empty());
    }

    #[test]
    fn independence_of_orthogonal_collinear_and_partial_columns() {
        // Columns e1, e2 and e1 + 1e-6·e3: the first and the last nearly collinear, by 1e-6.
        let j = DMatrix::from_row_slice(3, 3, &[1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1e-6]);
        let d = independence(&j, &[0, 1, 2]);
        assert!(d[0] < 2e-6 && d[2] < 2e-6 && (d[1] - 1.0).abs() < 1e-12, "{d:?}");
        // Columns e1, e2 and e2 + e3: the last is half explained by e2 (√(1/2) left).
        let j = DMatrix::from_row_slice(3, 3, &[1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0]);
        let d = independence(&j, &[0, 2]);
        assert!((d[0] - 1.0).abs() < 1e-12 && (d[1] - 0.5f64.sqrt()).abs() < 1e-12, "{d:?}");
    }

    #[test]
    fn worst_names_collinear_first_then_the_largest_relative_error() {
        let e = |key: &str, value: f64, se: f64| Estimate {
            key: key.into(),
            unit: "1",
            value,
            initial: value,
            standard_error: se,
            standard_error_iid: se,
            standard_error_cluster: None,
            ci95: (value - 2.0 * se, value + 2.0 * se),
            bootstrap_ci95: None,
        };
        let est = [e("a", 1.0, 2.0), e("b", 1.0, 3.0), e("c", 1.0, 0.1)];
        let screened: Vec<String> = ["a", "b", "c"].map(String::from).to_vec();
        let ind = vec![("a".to_string(), 0.5), ("b".to_string(), 0.5), ("c".to_string(), 1e-4)];
        assert_eq!(worst(&est, &ind, &screened).unwrap().0, "c");
        let ind = vec![("c".to_string(), 0.5)];
        assert_eq!(worst(&est, &ind, &screened).unwrap().0, "b");
        // Only screened keys are dropped.
        assert!(worst(&est, &ind, &["c".to_string()]).is_none());
        // A NaN standard error counts as undetermined.
        assert_eq!(worst(&[e("a", 1.0, f64::NAN)], &[], &["a".to_string()]).unwrap().0, "a");
    }
}
