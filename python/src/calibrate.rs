//! `_calibrate`: fit the model to measured torque cycles through `pinjoint-calibrate`, the same
//! library and the same options as `pinjoint calibrate` (its `--json` content, bit for bit).

use crate::cycle::{config, table_of};
use crate::messages::short;
use crate::params::PyParams;
use numpy::{IntoPyArray, PyReadonlyArray1};
use pinjoint_calibrate::{calibrate_columns as fit, Calibration, CalibrationError, Columns, Estimate, ExclusionRule, Options};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// One record as the Python half passes it: name, time, angle, angular_velocity, torque, load,
/// temperature (float64, 1-D; load and temperature already broadcast to the length of time).
pub type RecordArgs<'py> = (
    String,
    PyReadonlyArray1<'py, f64>,
    Option<PyReadonlyArray1<'py, f64>>,
    Option<PyReadonlyArray1<'py, f64>>,
    PyReadonlyArray1<'py, f64>,
    PyReadonlyArray1<'py, f64>,
    Option<PyReadonlyArray1<'py, f64>>,
);

/// The library's message, with every value in its shortest round-trip form.
pub fn calibration_error(e: &CalibrationError) -> String {
    #[allow(unreachable_patterns)]
    match e {
        CalibrationError::NonFinite { record, column, row, time, value, unit } => format!(
            "record {record}: {column} = {} {unit} at index {row} (time = {} s) is not a finite number",
            short(*value),
            short(*time)
        ),
        CalibrationError::TimeOrder { record, row, previous, time } => format!(
            "record {record}: time does not increase at index {row}: {} s then {} s",
            short(*previous),
            short(*time)
        ),
        CalibrationError::Load { record, row, value } => {
            format!("record {record}: load = {} N at index {row} is invalid: it must be > 0 N", short(*value))
        }
        CalibrationError::Temperature { record, row, value, why } => {
            format!("record {record}: temperature = {} K at index {row} is invalid: {why}", short(*value))
        }
        other => other.to_string(),
    }
}

fn estimate<'py>(py: Python<'py>, e: &Estimate) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("value", e.value)?;
    d.set_item("standard_error", e.standard_error)?;
    d.set_item("ci95", PyList::new(py, [e.ci95.0, e.ci95.1])?)?;
    Ok(d)
}

/// Everything in a [`Calibration`] as Python objects; the keys of `pinjoint calibrate --json`
/// (`parameters`, `rms_residual`, `points_used`, `points_excluded`, `torque_offset` when fitted,
/// `warnings`) hold exactly its values.
fn to_dict<'py>(py: Python<'py>, c: &Calibration) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let params = PyDict::new(py);
    let details = PyDict::new(py);
    for e in &c.estimates {
        params.set_item(&e.key, estimate(py, e)?)?;
    }
    for e in c.estimates.iter().chain(c.inertia_estimate.iter()).chain(c.offset.iter()) {
        let x = PyDict::new(py);
        x.set_item("unit", e.unit)?;
        x.set_item("initial", e.initial)?;
        x.set_item("standard_error_iid", e.standard_error_iid)?;
        x.set_item("standard_error_cluster", e.standard_error_cluster)?;
        x.set_item("bootstrap_ci95", e.bootstrap_ci95.map(|(a, b)| vec![a, b]))?;
        details.set_item(&e.key, x)?;
    }
    d.set_item("parameters", params)?;
    d.set_item("rms_residual", c.rms_residual)?;
    d.set_item("points_used", c.points_used)?;
    d.set_item("points_excluded", c.points_excluded)?;
    if let Some(o) = &c.offset {
        d.set_item("torque_offset", estimate(py, o)?)?;
    }
    d.set_item("inertia", c.inertia)?;
    d.set_item("inertia_fitted", c.inertia_estimate.is_some())?;
    if let Some(j) = &c.inertia_estimate {
        d.set_item("inertia_estimate", estimate(py, j)?)?;
    }
    d.set_item("temperatures", c.temperatures.clone())?;
    d.set_item("samples_read", c.samples_read)?;
    d.set_item("block_length", c.block_length)?;
    d.set_item("warnings", c.warnings.clone())?;
    d.set_item("estimate_details", details)?;
    let excluded = PyList::empty(py);
    for x in &c.exclusions {
        let r = PyDict::new(py);
        r.set_item("record", &x.record)?;
        r.set_item("speed_threshold", x.speed_threshold)?;
        r.set_item("reversals", x.reversals.clone())?;
        let windows = PyList::empty(py);
        for w in &x.windows {
            let wd = PyDict::new(py);
            wd.set_item("start", w.start)?;
            wd.set_item("end", w.end)?;
            wd.set_item("reason", w.reason.as_str())?;
            wd.set_item("samples", w.samples)?;
            windows.append(wd)?;
        }
        r.set_item("windows", windows)?;
        r.set_item("low_speed", x.low_speed)?;
        r.set_item("settling", x.settling)?;
        r.set_item("used", x.used)?;
        excluded.append(r)?;
    }
    d.set_item("excluded", excluded)?;
    d.set_item("strokes", c.strokes)?;
    d.set_item("dof", c.dof)?;
    d.set_item("condition", c.condition)?;
    d.set_item("correlation_keys", c.correlation_keys.clone())?;
    d.set_item("correlation", c.correlation.clone())?;
    d.set_item("half_widths", c.half_widths.clone())?;
    d.set_item("evaluations", c.evaluations)?;
    let series = PyList::empty(py);
    for s in &c.series {
        let r = PyDict::new(py);
        r.set_item("record", &s.record)?;
        r.set_item("time", s.time.clone().into_pyarray(py))?;
        r.set_item("angle", s.angle.clone().map(|a| a.into_pyarray(py)))?;
        r.set_item("angular_velocity", s.angular_velocity.clone().into_pyarray(py))?;
        r.set_item("load", s.load.clone().into_pyarray(py))?;
        r.set_item("torque", s.measured.clone().into_pyarray(py))?;
        r.set_item("inertia_torque", s.inertia_torque.clone().into_pyarray(py))?;
        r.set_item("fitted_torque", s.fitted.clone().into_pyarray(py))?;
        r.set_item("used", s.used.clone().into_pyarray(py))?;
        series.append(r)?;
    }
    d.set_item("series", series)?;
    Ok(d)
}

/// Fit `records` (see [`RecordArgs`]) as `pinjoint calibrate` does. `params`: None, a Params,
/// a mapping or a TOML path (a `[rig] inertia` in a file or mapping is the given J when
/// `inertia` is None, as with `--params`; without either, J is fitted). `None` options take the
/// library's defaults; records longer than `max_samples` together are block-averaged straight
/// from the arrays. Returns (result dict, calibrated Params).
#[pyfunction]
#[pyo3(name = "_calibrate", signature = (records, params, fit_keys, inertia, fit_offset, speed_fraction, settle_time, half_width, resamples, seed, max_samples=None))]
#[allow(clippy::too_many_arguments)]
pub fn calibrate<'py>(
    py: Python<'py>,
    records: Vec<RecordArgs<'py>>,
    params: Option<&Bound<'py, PyAny>>,
    fit_keys: Vec<String>,
    inertia: Option<f64>,
    fit_offset: bool,
    speed_fraction: Option<f64>,
    settle_time: Option<f64>,
    half_width: Option<usize>,
    resamples: Option<usize>,
    seed: Option<u64>,
    max_samples: Option<usize>,
) -> PyResult<(Bound<'py, PyDict>, PyParams)> {
    let cfg = config(params, &PyDict::new(py))?;
    let file_inertia = table_of(params)?
        .get("rig")
        .and_then(|r| r.as_table())
        .is_some_and(|r| r.contains_key("inertia"))
        .then_some(cfg.rig.inertia);
    // The arrays are contiguous float64 (the Python half makes them so): borrowed, not copied.
    fn slice<'a>(name: &str, a: &'a PyReadonlyArray1<'_, f64>) -> PyResult<&'a [f64]> {
        a.as_slice().map_err(|_| PyValueError::new_err(format!("record {name}: a column is not a contiguous float64 array")))
    }
    let records: Vec<Columns<'_>> = records
        .iter()
        .map(|(name, t, a, w, q, p, temp)| {
            Ok(Columns {
                name,
                time: slice(name, t)?,
                angle: a.as_ref().map(|a| slice(name, a)).transpose()?,
                angular_velocity: w.as_ref().map(|w| slice(name, w)).transpose()?,
                torque: slice(name, q)?,
                load: slice(name, p)?,
                temperature: temp.as_ref().map(|x| slice(name, x)).transpose()?,
            })
        })
        .collect::<PyResult<_>>()?;
    let def = Options::default();
    let rule = ExclusionRule::default();
    let options = Options {
        params: cfg.model,
        fit: fit_keys,
        inertia: inertia.or(file_inertia),
        max_samples: max_samples.unwrap_or(def.max_samples),
        fit_offset,
        exclusion: ExclusionRule {
            speed_fraction: speed_fraction.unwrap_or(rule.speed_fraction),
            settle_time: settle_time.unwrap_or(rule.settle_time),
        },
        half_width: half_width.or(def.half_width),
        resamples: resamples.unwrap_or(def.resamples),
        seed: seed.unwrap_or(def.seed),
        ..def
    };
    let cal = py.detach(|| crate::pool::install(|| fit(&records, &options))).map_err(|e| PyValueError::new_err(calibration_error(&e)))?;
    Ok((to_dict(py, &cal)?, PyParams { inner: cal.params }))
}
