//! `pinjoint._native`: the Python extension module behind the `pinjoint` package.
//!
//! The Python package (`python/pinjoint/`) wraps these pieces: argument coercion and NumPy
//! broadcasting happen there, the physics here. Only the physics crate (`params`,
//! `joint`, `fidelity`, `rig`) and the calibration crate are used; every number comes from the same functions as the CLI, so the
//! results equal `pinjoint sweep` and `pinjoint cycle` bit for bit.
//!
//! - [`params`]: the `Params` class (the parameter file's keys, validation and messages).
//! - [`joint`]: `_Joint`, the vectorised, parallel, GIL-free evaluation.
//! - [`presliding`]: `_Presliding`, the stateful presliding joint (the FMU's zero-velocity law).
//! - [`presliding_batch`]: `_PreslidingBatch`, n presliding joints stepped together (`pinjoint::batch`).
//! - [`cycle`]: `_simulate_cycle`, whole rig strokes (the columns of `cycle.csv`).
//! - [`calibrate`]: `_calibrate`, the fit of `pinjoint calibrate` (`pinjoint-calibrate`).
//! - [`messages`]: error texts with values in their shortest round-trip form.
//! - [`pool`]: the threads a large call runs on (the calling thread among them).

use pyo3::prelude::*;

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod messages;
pub mod values;
pub mod pool;
pub mod params;
pub mod joint;
pub mod presliding;
pub mod presliding_batch;
pub mod cycle;
pub mod calibrate;

/// The native half of the `pinjoint` package; use `pinjoint` itself.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<params::PyParams>()?;
    m.add_class::<joint::NativeJoint>()?;
    m.add_class::<presliding::NativePresliding>()?;
    m.add_class::<presliding_batch::NativePreslidingBatch>()?;
    m.add_function(wrap_pyfunction!(cycle::simulate_cycle, m)?)?;
    m.add_function(wrap_pyfunction!(calibrate::calibrate, m)?)?;
    m.add("MU_C", pinjoint_calibrate::MU_C)?;
    m.add_function(wrap_pyfunction!(params::param_table, m)?)?;
    m.add_function(wrap_pyfunction!(params::rig_param_table, m)?)?;
    let e = pinjoint::fidelity::Envelope::SERVICE;
    m.add("DEFAULT_ENVELOPE", (e.load_min, e.load_max, e.speed_min, e.speed_max))?;
    let e = pinjoint::fidelity::Envelope::PAPER_RIG;
    m.add("PAPER_ENVELOPE", (e.load_min, e.load_max, e.speed_min, e.speed_max))?;
    m.add("RESULT_COLUMNS", pinjoint::record::NAMES.to_vec())?;
    m.add("CYCLE_COLUMNS", cycle::CYCLE_COLUMNS.to_vec())?;
    m.add("REGIMES", pinjoint::record::REGIMES.iter().map(|r| r.as_str()).collect::<Vec<_>>())?;
    m.add("VALIDITIES", pinjoint::Validity::ALL.iter().map(|v| v.as_str()).collect::<Vec<_>>())?;
    Ok(())
}
