//! `_PreslidingBatch`: n presliding joints stepped together (`pinjoint::batch`), over NumPy
//! arrays of shape (n,), without the GIL: bit for bit n `_Presliding` objects at fidelity
//! full (the same library code).

use crate::messages::{model_error, short};
use crate::params::PyParams;
use numpy::{IntoPyArray, PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pinjoint::batch::{BatchError, BatchParams, Inputs, PreslidingBatch, Settings};
use pinjoint::fidelity::{Envelope, Fidelity, FidelityError};
use pinjoint::zero_velocity::Presliding;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rayon::prelude::*;

/// A batch error as a ValueError with the library's message (a model error's numbers in
/// their short form, as `Joint.evaluate` gives them).
fn batch_err(e: BatchError) -> PyErr {
    let text = match &e {
        BatchError::Model { index, source } => format!("at index {index}: {}", model_error(source)),
        other => other.to_string(),
    };
    PyValueError::new_err(pinjoint::fmt::bounded_message(&text))
}

/// Two float64 arrays of shape (n,).
type ArrayPair<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>);

/// Everything the joints hold, arrays of shape (n,): presliding torques (N·m), reference
/// angles (rad), last steps (s), ω at the last commits (rad/s), pending first angles.
type FullStates<'py> = (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<bool>>);

/// The joints of `pinjoint.PreslidingBatch` (its native half).
#[pyclass(name = "_PreslidingBatch", module = "pinjoint._native")]
pub struct NativePreslidingBatch {
    batch: PreslidingBatch,
    /// Copies of one call's inputs: angle, angular velocity, load, temperature, step (kept
    /// between calls: no allocation once grown). The batch reads these alone ([`Source`]).
    buf: [Vec<f64>; 5],
}

/// The data of a caller's float64 array, copied into the call's buffer after the GIL is
/// released ([`Source::copy_to`]), on the pool's threads for a large batch: the copy then
/// costs the calling thread nothing and leaves the values in the cores that step them
/// (measured against a copy on the calling thread before the hand-over: the median
/// table-level step of 10⁴ joints 1.1–3.6 ns a joint-step lower, in three paired runs, of
/// about 33). As NumPy's own operations that release the GIL, this reads the array while
/// other threads may run: each value is read once, into the buffer, before it is checked or
/// used, so an array another thread writes during the call gives some mix of its old and new
/// values (the caller's race), never a value checked as one number and used as another. The
/// array is read by address and stride, whatever its alignment and layout (no reference to
/// its data is made), and kept alive by the call's reference to it.
#[derive(Clone, Copy)]
struct Source {
    /// The address of element 0.
    ptr: *const u8,
    len: usize,
    /// Bytes from one element to the next (negative for a reversed view).
    stride: isize,
}

// SAFETY: a `Source` is an address, a length and a stride, read only by `copy_to` while the
// call that made it holds a reference to the array (see the type's documentation).
unsafe impl Send for Source {}
unsafe impl Sync for Source {}

impl Source {
    /// The data of `a`.
    fn of(a: &PyReadonlyArray1<'_, f64>) -> Source {
        Source { ptr: a.data().cast_const().cast::<u8>(), len: a.len(), stride: a.strides()[0] }
    }

    /// Copy the array's values from index `start` on into `dst` (as many as it holds).
    fn copy_to(&self, start: usize, dst: &mut [f64]) {
        assert!(start.checked_add(dst.len()).is_some_and(|end| end <= self.len), "a copy within the array");
        if dst.is_empty() {
            return;
        }
        if self.stride == 8 {
            // SAFETY: the source bytes are inside the array's data (checked above; contiguous),
            // which the call keeps alive; the destination is our own buffer of as many values;
            // the two never overlap (the buffer is the batch's own allocation). Bytewise: the
            // data need not be aligned.
            unsafe { std::ptr::copy_nonoverlapping(self.ptr.add(8 * start), dst.as_mut_ptr().cast::<u8>(), 8 * dst.len()) }
        } else {
            for (k, d) in dst.iter_mut().enumerate() {
                // SAFETY: element start + k < len of the array, at its address (NumPy's
                // address + index × stride); read unaligned, the array kept alive by the call.
                *d = unsafe { self.ptr.offset((start + k) as isize * self.stride).cast::<f64>().read_unaligned() };
            }
        }
    }
}

/// The inputs of a call, in the order of [`CallArrays`].
const INPUTS: [&str; 5] = ["angle", "angular_velocity", "load", "temperature", "step"];

/// Values a task of the parallel copy takes.
const COPY_CHUNK: usize = 2048;

/// The arrays of one call, in the order angle, angular velocity, load, temperature, step
/// (None where not given).
type CallArrays<'py> = [Option<PyReadonlyArray1<'py, f64>>; 5];

/// A call's positional arguments, each a float64 array of shape (n,) or None: `names`, the
/// first `required` of them required, placed from position `first` of [`CallArrays`] on.
fn arrays<'py>(args: &Bound<'py, PyTuple>, names: &[&str], required: usize, first: usize) -> PyResult<CallArrays<'py>> {
    if args.len() < required || args.len() > names.len() {
        return Err(PyTypeError::new_err(format!("expected the arrays ({}), the first {required} required; got {} arguments", names.join(", "), args.len())));
    }
    let mut out = CallArrays::default();
    for (i, name) in names.iter().enumerate() {
        out[first + i] = match args.get_item(i) {
            Ok(v) if !v.is_none() => Some(v.extract().map_err(|e| PyTypeError::new_err(format!("argument '{name}': {e}")))?),
            _ => None,
        };
    }
    Ok(out)
}

#[pymethods]
impl NativePreslidingBatch {
    #[new]
    #[pyo3(signature = (n, params, keys, values, law, fidelity, tolerance, envelope))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        n: usize,
        params: Vec<PyRef<'_, PyParams>>,
        keys: Vec<String>,
        values: Option<PyReadonlyArray2<'_, f64>>,
        law: (f64, f64, f64),
        fidelity: &str,
        tolerance: f64,
        envelope: (f64, f64, f64, f64),
    ) -> PyResult<Self> {
        let fid: Fidelity = fidelity.parse().map_err(|e: FidelityError| PyValueError::new_err(e.to_string()))?;
        let env = Envelope::new(envelope.0, envelope.1, envelope.2, envelope.3).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let law = Presliding::new(law.0, law.1, law.2).map_err(|e| PyValueError::new_err(e.to_string()))?;
        let mut sets: Vec<pinjoint::Params> = params.iter().map(|p| p.inner).collect();
        if let Some(v) = values {
            let v = v.as_array();
            if v.ncols() != keys.len() || v.nrows() != n {
                return Err(PyValueError::new_err(format!("per-joint values have shape ({}, {}), expected ({n}, {})", v.nrows(), v.ncols(), keys.len())));
            }
            if sets.len() == 1 {
                sets = vec![sets[0]; n];
            }
            for (c, key) in keys.iter().enumerate() {
                for (i, p) in sets.iter_mut().enumerate() {
                    if p.set_by_name(key, v[(i, c)]).is_none() {
                        return Err(PyValueError::new_err(format!("per_joint: {} is not a parameter (see pinjoint.param_table())", pinjoint::fmt::excerpt(key))));
                    }
                }
            }
        }
        let bp = if sets.len() == 1 { BatchParams::Shared(sets[0]) } else { BatchParams::PerJoint(sets) };
        let batch = PreslidingBatch::new(n, bp, law, Settings { fidelity: fid, tolerance, envelope: env }).map_err(batch_err)?;
        Ok(Self { batch, buf: Default::default() })
    }

    /// The friction torque (N·m) of every joint at the inputs, the states unchanged:
    /// `torque(angle, angular_velocity, load, temperature=None)`.
    #[pyo3(signature = (*args))]
    fn torque<'py>(&mut self, py: Python<'py>, args: &Bound<'py, PyTuple>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.call(py, args, 0).map(|o| o.expect("an output"))
    }

    /// Commit every joint's state at its angle; `step` (s per joint, None: not known) the
    /// host's step, as `_Presliding.commit`:
    /// `commit(angle, angular_velocity, load, temperature=None, step=None)`.
    #[pyo3(signature = (*args))]
    fn commit<'py>(&mut self, py: Python<'py>, args: &Bound<'py, PyTuple>) -> PyResult<()> {
        self.call(py, args, 1).map(|_| ())
    }

    /// The torque at the inputs, then commit (one solve per joint) with the host's `step`:
    /// `step(angle, angular_velocity, load, temperature=None, step=None)`.
    #[pyo3(signature = (*args))]
    fn step<'py>(&mut self, py: Python<'py>, args: &Bound<'py, PyTuple>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.call(py, args, 2).map(|o| o.expect("an output"))
    }

    /// Every joint's sliding torque T(P, |omega|) (N·m) at the inputs:
    /// `sliding_torque(angular_velocity, load, temperature=None)`.
    #[pyo3(signature = (*args))]
    fn sliding_torque<'py>(&mut self, py: Python<'py>, args: &Bound<'py, PyTuple>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.call(py, args, 3).map(|o| o.expect("an output"))
    }

    /// (presliding torques N·m, reference angles rad), arrays of shape (n,).
    #[getter]
    fn states<'py>(&self, py: Python<'py>) -> PyResult<ArrayPair<'py>> {
        let n = self.batch.len();
        let (mut t, mut a) = (vec![0.0; n], vec![0.0; n]);
        self.batch.states(&mut t, &mut a).map_err(batch_err)?;
        Ok((t.into_pyarray(py), a.into_pyarray(py)))
    }

    /// Replace every state: presliding torques (N·m) and reference angles (rad), shape (n,).
    fn set_states(&mut self, torque: PyReadonlyArray1<'_, f64>, angle: PyReadonlyArray1<'_, f64>) -> PyResult<()> {
        let (t, a) = (torque.as_array().to_vec(), angle.as_array().to_vec());
        self.batch.set_states(&t, &a).map_err(batch_err)
    }

    /// Everything the joints hold (for pickling): presliding torques (N·m), reference angles
    /// (rad), last steps (s), ω at the last commits (rad/s), pending first angles.
    #[getter]
    fn full_states<'py>(&self, py: Python<'py>) -> PyResult<FullStates<'py>> {
        let n = self.batch.len();
        let (mut t, mut a, mut h, mut w, mut u) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![false; n]);
        self.batch.states(&mut t, &mut a).map_err(batch_err)?;
        self.batch.last_steps(&mut h, &mut w, &mut u).map_err(batch_err)?;
        Ok((t.into_pyarray(py), a.into_pyarray(py), h.into_pyarray(py), w.into_pyarray(py), u.into_pyarray(py)))
    }

    /// Restore [`NativePreslidingBatch::full_states`] (all true `unreferenced` with the states
    /// at rest: every joint takes its first angle as its reference).
    fn set_full_states(
        &mut self,
        torque: PyReadonlyArray1<'_, f64>,
        angle: PyReadonlyArray1<'_, f64>,
        step: PyReadonlyArray1<'_, f64>,
        omega: PyReadonlyArray1<'_, f64>,
        unreferenced: PyReadonlyArray1<'_, bool>,
    ) -> PyResult<()> {
        let (t, a, h, w, u) = (torque.as_array().to_vec(), angle.as_array().to_vec(), step.as_array().to_vec(), omega.as_array().to_vec(), unreferenced.as_array().to_vec());
        // Checked before anything changes: the last steps first (they fail alone), then both.
        let before = self.batch.clone();
        let res = self.batch.set_states(&t, &a).and_then(|()| self.batch.set_last_steps(&h, &w, &u));
        if res.is_err() {
            self.batch = before;
        }
        res.map_err(batch_err)
    }

    /// Store the host inertia per joint (kg·m²), or clear it (None).
    fn set_host_inertia(&mut self, inertia: Option<PyReadonlyArray1<'_, f64>>) -> PyResult<()> {
        let v = inertia.map(|a| a.as_array().to_vec());
        self.batch.set_host_inertia(v.as_deref()).map_err(batch_err)
    }

    /// Models (parameter set × temperature at a level) held now.
    #[getter]
    fn models_held(&self) -> usize {
        self.batch.models_held()
    }

    /// Models holding a table now (at most `pinjoint::batch::cache::LEVELS_MAX`).
    #[getter]
    fn tables_held(&self) -> usize {
        self.batch.tables_held()
    }

    /// The number of joints.
    fn __len__(&self) -> usize {
        self.batch.len()
    }

    fn __repr__(&self) -> String {
        let l = self.batch.law();
        format!("_PreslidingBatch(n={}, law=({}, {}, {}))", self.batch.len(), short(l.angle), short(l.elastic_limit), short(l.damping_time))
    }
}

impl NativePreslidingBatch {
    /// One call: 0 torque, 1 commit, 2 step (with the host's `step` when given), 3 sliding
    /// torque, on its positional arguments ([`arrays`]). The GIL is released, the inputs are
    /// copied into the call's buffers ([`Source`]), then the joints are stepped from them.
    fn call<'py>(&mut self, py: Python<'py>, args: &Bound<'py, PyTuple>, what: u8) -> PyResult<Option<Bound<'py, PyArray1<f64>>>> {
        let given = if what == 3 {
            // The sliding torque reads no angle.
            arrays(args, &["angular_velocity", "load", "temperature"], 2, 1)?
        } else if what == 0 {
            arrays(args, &["angle", "angular_velocity", "load", "temperature"], 3, 0)?
        } else {
            arrays(args, &["angle", "angular_velocity", "load", "temperature", "step"], 3, 0)?
        };
        let n = self.batch.len();
        // Per input given: its data, to copy once the GIL is released. Each has n values (the
        // first that has not named, in the order the library checks them), before anything
        // is allocated for it.
        let sources: [Option<Source>; 5] = std::array::from_fn(|k| given[k].as_ref().map(Source::of));
        let order: &[usize] = if what == 3 { &[2, 1, 3] } else { &[0, 1, 2, 3, 4] };
        for &k in order {
            if let Some(src) = sources[k].filter(|s| s.len != n) {
                return Err(batch_err(BatchError::Shape { argument: INPUTS[k], expected: n, got: src.len }));
            }
        }
        for (buf, src) in self.buf.iter_mut().zip(&sources) {
            if src.is_some() {
                buf.resize(n, 0.0);
            }
        }
        let (with_t, with_h) = (sources[3].is_some(), sources[4].is_some());
        let mut out = if what == 1 { Vec::new() } else { vec![0.0; n] };
        // A batch the library steps in parallel (two chunks or more at full, eight at the
        // other levels): the copy and the step on the pool ([`crate::pool::install`]); a
        // smaller one on this thread, as the library does.
        let large = pinjoint::batch::step::parallel(n, self.batch.settings().fidelity);
        let Self { batch, buf } = self;
        let mut work = |parallel: bool| {
            for (b, src) in buf.iter_mut().zip(&sources) {
                if let Some(src) = src {
                    if parallel {
                        b.par_chunks_mut(COPY_CHUNK).enumerate().for_each(|(c, d)| src.copy_to(c * COPY_CHUNK, d));
                    } else {
                        src.copy_to(0, b);
                    }
                }
            }
            let inputs = Inputs { angle: &buf[0], angular_velocity: &buf[1], load: &buf[2], temperature: with_t.then_some(&buf[3][..]) };
            let step = with_h.then_some(&buf[4][..]);
            match (what, step) {
                (0, _) => batch.torque(&inputs, &mut out),
                (1, Some(h)) => batch.commit_step(&inputs, h),
                (1, None) => batch.commit(&inputs),
                (2, Some(h)) => batch.step_with(&inputs, h, &mut out),
                (2, None) => batch.step(&inputs, &mut out),
                _ => batch.sliding_torque(inputs.load, inputs.angular_velocity, inputs.temperature, &mut out),
            }
        };
        let res = py.detach(|| crate::pool::run(large, || work(large)));
        res.map_err(batch_err)?;
        Ok((what != 1).then(|| out.into_pyarray(py)))
    }
}
