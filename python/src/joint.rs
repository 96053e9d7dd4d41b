//! `_Joint`: the model at many operating points, on every core, without the GIL.

use crate::messages::{index_text, model_error, short};
use crate::params::PyParams;
use numpy::{IntoPyArray, PyReadonlyArray1};
use pinjoint::fidelity::{Envelope, Evaluator, Fidelity, Level};
use pinjoint::record::{regime_code, Value, COLUMNS};
use pinjoint::{Joint, ModelError, OperatingPoint};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// Numeric result columns of the one result record ([`pinjoint::record::COLUMNS`]), counted
/// from it (a new column of the record cannot leave this count behind).
const NUMERIC: usize = {
    let (mut n, mut i) = (0, 0);
    while i < COLUMNS.len() {
        if matches!(COLUMNS[i].value, Value::Number(_)) {
            n += 1;
        }
        i += 1;
    }
    n
};

/// The numeric result columns (every column of the record but `regime` and `validity`), in
/// record order.
pub fn numeric_columns() -> impl Iterator<Item = (&'static str, fn(&OperatingPoint) -> f64)> {
    COLUMNS.iter().filter_map(|c| match c.value {
        Value::Number(f) => Some((c.name, f)),
        Value::Regime | Value::Validity => None,
    })
}

/// The code of a point's regime and validity in one byte: regime + 4·validity
/// ([`regime_code`], [`pinjoint::Validity::code`]).
fn point_code(op: &OperatingPoint) -> u8 {
    regime_code(op.regime) + 4 * op.validity.code()
}

/// Every point's numeric outputs and regime code.
pub type Rows = (Vec<[f64; NUMERIC]>, Vec<u8>);

/// Points handed to one rayon task; below two chunks the work stays on the calling thread.
const CHUNK: usize = 2048;

fn row(op: &OperatingPoint) -> [f64; NUMERIC] {
    let mut out = [0.0; NUMERIC];
    for (slot, (_, f)) in out.iter_mut().zip(numeric_columns()) {
        *slot = f(op);
    }
    out
}

/// The model at a fidelity level (native half of `pinjoint.Joint`).
#[pyclass(name = "_Joint", module = "pinjoint._native", frozen)]
pub struct NativeJoint {
    joint: Joint,
    /// The table or boundary level; None for `full` (and for `auto` when it picked full).
    level: Option<Evaluator>,
    /// What `auto` picked (or the level asked for), and its measured error bound.
    chosen: Level,
    error_bound: f64,
    /// Points answered by the full solve because they were outside the envelope.
    fallbacks: AtomicU64,
}

impl NativeJoint {
    /// One point: the level inside its envelope, the complete (cold) solve elsewhere. The
    /// cold solve makes every answer independent of the order and chunking of the points.
    fn point(&self, load: f64, speed: f64) -> Result<OperatingPoint, ModelError> {
        if let Some(ev) = &self.level {
            if let Some(e) = ev.evaluate_inside(load, speed) {
                return Ok(ev.operating_point(&e));
            }
            let op = self.joint.evaluate(load, speed)?;
            self.fallbacks.fetch_add(1, Ordering::Relaxed);
            return Ok(op);
        }
        self.joint.evaluate(load, speed)
    }

    /// Fill `out`/`codes` for `loads`/`speeds` (same length); the first failing point's
    /// offset and error, if any.
    fn fill(&self, loads: &[f64], speeds: &[f64], out: &mut [[f64; NUMERIC]], codes: &mut [u8]) -> Option<(usize, ModelError)> {
        for (i, (&l, &w)) in loads.iter().zip(speeds).enumerate() {
            match self.point(l, w) {
                Ok(op) => {
                    out[i] = row(&op);
                    codes[i] = point_code(&op);
                }
                Err(e) => return Some((i, e)),
            }
        }
        None
    }

    /// Evaluate every point; on the cores when there are many. The error is the one at the
    /// lowest index, whatever the scheduling.
    pub fn run(&self, loads: &[f64], speeds: &[f64]) -> Result<Rows, (usize, ModelError)> {
        let n = loads.len();
        let mut out = vec![[0.0f64; NUMERIC]; n];
        let mut codes = vec![0u8; n];
        let err = if n < 2 * CHUNK {
            self.fill(loads, speeds, &mut out, &mut codes)
        } else {
            out.par_chunks_mut(CHUNK)
                .zip(codes.par_chunks_mut(CHUNK))
                .enumerate()
                .filter_map(|(k, (o, c))| {
                    let a = k * CHUNK;
                    let b = a + o.len();
                    self.fill(&loads[a..b], &speeds[a..b], o, c).map(|(i, e)| (a + i, e))
                })
                .min_by_key(|(i, _)| *i)
        };
        match err {
            Some(e) => Err(e),
            None => Ok((out, codes)),
        }
    }
}

#[pymethods]
impl NativeJoint {
    #[new]
    #[pyo3(signature = (params, fidelity, tolerance, envelope))]
    fn new(params: &PyParams, fidelity: &str, tolerance: f64, envelope: (f64, f64, f64, f64)) -> PyResult<Self> {
        let p = params.inner;
        let joint = Joint::new(&p).map_err(crate::params::param_err)?;
        let fid: Fidelity = fidelity.parse().map_err(|e: pinjoint::fidelity::FidelityError| PyValueError::new_err(e.to_string()))?;
        pinjoint::fidelity::validate_tolerance(tolerance).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let env = Envelope::new(envelope.0, envelope.1, envelope.2, envelope.3).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let (level, chosen, error_bound) = if fid == Fidelity::Full {
            (None, Level::Full, pinjoint::fidelity::FULL_ERROR_BOUND)
        } else {
            let ev = Evaluator::new(&p, fid, tolerance, env).map_err(|e| PyValueError::new_err(e.to_string()))?;
            let (chosen, bound) = (ev.chosen(), ev.error_bound());
            ((chosen != Level::Full).then_some(ev), chosen, bound)
        };
        Ok(Self { joint, level, chosen, error_bound, fallbacks: AtomicU64::new(0) })
    }

    /// This model at lubricant temperature `temperature` (K): bit for bit the `_Joint` built
    /// from the parameters with that temperature, at the cost of a few logarithms at full
    /// (the start table and the temperature-independent groups are shared); a table or
    /// boundary level is built and measured again there. An invalid temperature raises
    /// ValueError naming it.
    fn at_temperature(&self, temperature: f64) -> PyResult<Self> {
        let joint = self.joint.at_temperature(temperature).map_err(crate::params::param_err)?;
        let level = match &self.level {
            Some(ev) => {
                let mut ev = ev.clone();
                ev.set_temperature(temperature).map_err(|e| PyValueError::new_err(e.to_string()))?;
                Some(ev)
            }
            None => None,
        };
        let (chosen, error_bound) = level.as_ref().map_or((self.chosen, self.error_bound), |ev| (ev.chosen(), ev.error_bound()));
        // `auto` may pick full at the new temperature: then no level is kept.
        let level = level.filter(|ev| ev.chosen() != Level::Full);
        Ok(Self { joint, level, chosen, error_bound, fallbacks: AtomicU64::new(0) })
    }

    /// Evaluate flat float64 arrays of equal length; `shape` is the broadcast shape (for the
    /// index in error messages). Returns ({column: float64 array}, codes uint8 array:
    /// regime + 4·validity).
    fn evaluate_flat<'py>(
        &self,
        py: Python<'py>,
        load: PyReadonlyArray1<'py, f64>,
        speed: PyReadonlyArray1<'py, f64>,
        shape: Vec<usize>,
    ) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyAny>)> {
        // Copies: the arrays may be changed by other Python threads while the GIL is released.
        let loads = load.as_array().to_vec();
        let speeds = speed.as_array().to_vec();
        if loads.len() != speeds.len() {
            return Err(PyValueError::new_err(format!("load has {} points, speed {}", loads.len(), speeds.len())));
        }
        let res = py.detach(|| crate::pool::run(loads.len() >= 2 * CHUNK, || self.run(&loads, &speeds)));
        let (rows, codes) = res.map_err(|(i, e)| {
            let at = index_text(i, &shape);
            let sep = if at.is_empty() { "" } else { ": " };
            PyValueError::new_err(format!("{at}{sep}{}", model_error(&e)))
        })?;
        let d = PyDict::new(py);
        for (c, (name, _)) in numeric_columns().enumerate() {
            let col: Vec<f64> = rows.iter().map(|r| r[c]).collect();
            d.set_item(name, col.into_pyarray(py))?;
        }
        Ok((d, codes.into_pyarray(py).into_any()))
    }

    /// The level in use: "full", "table" or "boundary" (what "auto" picked).
    #[getter]
    fn chosen(&self) -> &'static str {
        self.chosen.as_str()
    }
    /// The level's measured error bound inside its envelope (relative in μ, torque, h_c).
    #[getter]
    fn error_bound(&self) -> f64 {
        self.error_bound
    }
    /// Points answered by the full solve because they were outside the envelope.
    #[getter]
    fn fallbacks(&self) -> u64 {
        self.fallbacks.load(Ordering::Relaxed)
    }
    /// The largest load the asperity model can take (N): refused at and beyond it.
    #[getter]
    fn capacity(&self) -> f64 {
        self.joint.capacity()
    }
    /// The declared load capacity (N): where the Hertz half-width reaches the pin radius;
    /// answered beyond it with the validity `outside` ([`pinjoint::Joint::load_edge`]).
    #[getter]
    fn load_edge(&self) -> f64 {
        self.joint.load_edge()
    }
    fn __repr__(&self) -> String {
        format!("_Joint(level={}, bound={})", self.chosen.as_str(), short(self.error_bound))
    }
}
