//! `_simulate_cycle`: whole strokes of the paper's torsion rig (`pinjoint::rig`), the columns
//! of `pinjoint cycle`'s `cycle.csv`, computed the way that command computes them.

use crate::params::{read_file, PyParams};
use crate::values::{merge_mapping, to_text};
use numpy::IntoPyArray;
use pinjoint::fidelity::Fidelity;
use pinjoint::rig::{run_cycles, RigConfig, RigError, RigSim, Sample};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// The columns of `cycle.csv` (SI units: s, rad, rad, rad/s, N·m, N·m, -, m, -, bool).
pub const CYCLE_COLUMNS: [&str; 10] = pinjoint::rig::record::COLUMNS;

/// The same limits as `pinjoint cycle`: strokes, and samples held in memory.
pub const MAX_CYCLES: usize = 100_000;
pub const MAX_SAMPLES: usize = 20_000_000;

fn rig_err(e: RigError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The rig configuration: `params` (None, a Params, a mapping possibly with a "rig" section,
/// or a TOML file path), then the `rig` keyword overrides; parsed and validated by the library.
pub fn config(params: Option<&Bound<'_, PyAny>>, rig: &Bound<'_, PyDict>) -> PyResult<RigConfig> {
    let mut table = table_of(params)?;
    let overrides = PyDict::new(rig.py());
    overrides.set_item("rig", rig)?;
    merge_mapping(&mut table, overrides.as_any())?;
    crate::values::check_keys(&table, true)?;
    RigConfig::from_toml_str(&to_text(&table)?).map_err(|e| PyValueError::new_err(pinjoint::fmt::bounded_message(&e.to_string())))
}

/// The parameter table `params` gives (None, a Params, a TOML path or a mapping), before any
/// `[rig]` overrides.
pub fn table_of(params: Option<&Bound<'_, PyAny>>) -> PyResult<toml::Table> {
    let table: toml::Table = match params {
        None => toml::Table::new(),
        Some(p) if p.is_none() => toml::Table::new(),
        Some(p) => {
            if let Ok(pp) = p.cast::<PyParams>() {
                toml::from_str(&pp.get().inner.to_toml_string()).expect("the library's own file parses")
            } else if p.is_instance_of::<PyString>() || p.hasattr("__fspath__")? {
                let (path, text) = read_file(p)?;
                text.parse::<toml::Table>().map_err(|e| {
                    PyValueError::new_err(format!("{}: parameter file: {}", pinjoint::fmt::excerpt(&path), pinjoint::params::parse_message(&text, &e)))
                })?
            } else {
                let mut t = toml::Table::new();
                merge_mapping(&mut t, p)?;
                t
            }
        }
    };
    Ok(table)
}

/// Simulate `cycles` strokes with `samples_per_cycle` samples each; `rig` holds the `[rig]`
/// keys (frequency, amplitude, load and any other). Returns {column: array}.
#[pyfunction]
#[pyo3(name = "_simulate_cycle", signature = (params, rig, cycles, samples_per_cycle, fidelity, tolerance))]
pub fn simulate_cycle<'py>(
    py: Python<'py>,
    params: Option<&Bound<'py, PyAny>>,
    rig: &Bound<'py, PyDict>,
    cycles: usize,
    samples_per_cycle: usize,
    fidelity: &str,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let cfg = config(params, rig)?;
    if cfg.rig.load <= 0.0 {
        return Err(PyValueError::new_err(format!(
            "load = {:?} N is invalid: the cycle-average friction coefficient needs a load > 0 N",
            cfg.rig.load
        )));
    }
    if !(1..=MAX_CYCLES).contains(&cycles) {
        return Err(PyValueError::new_err(format!("cycles = {cycles} is invalid: it must be between 1 and {MAX_CYCLES}")));
    }
    if samples_per_cycle < 8 || samples_per_cycle.saturating_mul(cycles) > MAX_SAMPLES {
        return Err(PyValueError::new_err(format!(
            "samples_per_cycle = {samples_per_cycle} is invalid: it must be >= 8, and cycles × samples_per_cycle <= {MAX_SAMPLES}"
        )));
    }
    let fid: Fidelity = fidelity.parse().map_err(|e: pinjoint::fidelity::FidelityError| PyValueError::new_err(e.to_string()))?;
    pinjoint::fidelity::validate_tolerance(tolerance).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let samples: Vec<Sample> = py
        .detach(|| -> Result<Vec<Sample>, RigError> {
            if fid == Fidelity::Full {
                // As `pinjoint cycle` without --fidelity.
                run_cycles(&cfg, cycles as f64, samples_per_cycle)
            } else {
                // As `pinjoint cycle --fidelity ...`: the level over the drive's envelope.
                let mut sim = RigSim::new(&cfg)?;
                let env = RigSim::drive_envelope(&cfg)?;
                sim.set_fidelity(fid, tolerance, env)?;
                let period = cfg.rig.period();
                sim.run(cycles as f64 * period, period / samples_per_cycle as f64)
            }
        })
        .map_err(rig_err)?;
    let d = PyDict::new(py);
    let col = |f: fn(&Sample) -> f64| samples.iter().map(f).collect::<Vec<f64>>();
    for (name, _, f) in pinjoint::rig::record::NUMERIC_COLUMNS {
        d.set_item(name, col(f).into_pyarray(py))?;
    }
    let stuck: Vec<bool> = samples.iter().map(|s| s.stuck).collect();
    d.set_item("stuck", stuck.into_pyarray(py))?;
    Ok(d)
}
