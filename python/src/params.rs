//! `pinjoint.Params`: the model's parameter set, with the parameter file's keys, validation
//! and messages (`pinjoint::params`).

use crate::values::{merge_mapping, to_text};
use pinjoint::params::{PARAMS, ParamError, spec_by_name};
use pinjoint::rig::RIG_PARAMS;
use pinjoint::Params;
use pyo3::exceptions::{PyKeyError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// A rejected parameter set as a Python `ValueError` with the library's message.
pub fn param_err(e: ParamError) -> PyErr {
    PyValueError::new_err(pinjoint::fmt::bounded_message(&e.to_string()))
}

/// Read a parameter file (TOML) as text; an unreadable file is an `OSError` naming it.
pub fn read_file(path: &Bound<'_, PyAny>) -> PyResult<(String, String)> {
    let os = path.py().import("os")?;
    let p: String = os.call_method1("fspath", (path,))?.extract()?;
    let text = std::fs::read_to_string(&p).map_err(|e| PyOSError::new_err(format!("cannot read parameter file {}: {e}", pinjoint::fmt::excerpt(&p))))?;
    Ok((p, text))
}

/// Model parameters of the pin joint: Tables 1-3 of the paper and the boundary friction
/// coefficient, in SI units, validated.
///
/// Params()                         the paper's joint (the defaults)
/// Params({"geometry": {"pin_radius": 0.03, "bush_radius": 0.03003}})
/// Params({"friction.boundary_friction_coefficient": 0.1})   dotted names work too
/// Params.from_toml("joint.toml")   a parameter file, as written by `pinjoint params`
///
/// Any subset of keys may be given; the rest keep their defaults. An unknown key, a value
/// that is not finite or outside its range raises ValueError naming the parameter, its value
/// and unit, with the same messages as the parameter file. Keys are `section.key`
/// (see `pinjoint.param_table()` for names, units, ranges and meanings).
/// Params are immutable and hashable by value; `with_values` returns a changed copy.
#[pyclass(name = "Params", module = "pinjoint", frozen, eq)]
#[derive(Clone, PartialEq)]
pub struct PyParams {
    pub inner: Params,
}

impl PyParams {
    /// Parse a TOML table through the library (its keys, its validation, its messages).
    fn from_table(table: &toml::Table) -> PyResult<Self> {
        crate::values::check_keys(table, false)?;
        let inner = Params::from_toml_str(&to_text(table)?).map_err(param_err)?;
        Ok(Self { inner })
    }
    fn table(&self) -> toml::Table {
        toml::from_str(&self.inner.to_toml_string()).expect("the library's own file parses")
    }
}

#[pymethods]
impl PyParams {
    #[new]
    #[pyo3(signature = (values=None))]
    fn new(values: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        match values {
            None => Ok(Self { inner: Params::default() }),
            Some(v) => {
                if let Ok(p) = v.cast::<PyParams>() {
                    return Ok(p.get().clone());
                }
                let mut t = toml::Table::new();
                merge_mapping(&mut t, v)?;
                Self::from_table(&t)
            }
        }
    }

    /// Read a parameter file (TOML, SI units, any subset of keys) from `path`.
    #[staticmethod]
    fn from_toml(path: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (p, text) = read_file(path)?;
        let inner = Params::from_toml_str(&text).map_err(|e| PyValueError::new_err(pinjoint::fmt::bounded_message(&format!("{}: {e}", pinjoint::fmt::excerpt(&p)))))?;
        Ok(Self { inner })
    }

    /// Parse the text of a parameter file (TOML).
    #[staticmethod]
    fn from_toml_str(text: &str) -> PyResult<Self> {
        Ok(Self { inner: Params::from_toml_str(text).map_err(param_err)? })
    }

    /// The complete parameter file (TOML, SI units, units as comments); reads back unchanged.
    fn to_toml(&self) -> String {
        self.inner.to_toml_string()
    }

    /// Every parameter as a nested dict {section: {key: value}} (floats, SI units; the switches
    /// `model.paper` and `grease.enabled` as bools).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for s in PARAMS.iter() {
            let sec = match d.get_item(s.section)? {
                Some(x) => x.cast_into::<PyDict>()?,
                None => {
                    let x = PyDict::new(py);
                    d.set_item(s.section, &x)?;
                    x
                }
            };
            match s.kind {
                pinjoint::params::Kind::Real => sec.set_item(s.key, (s.get)(&self.inner))?,
                pinjoint::params::Kind::Boolean => sec.set_item(s.key, (s.get)(&self.inner) != 0.0)?,
            }
        }
        Ok(d)
    }

    /// A copy with some values changed (same forms as the constructor), validated.
    fn with_values(&self, values: &Bound<'_, PyAny>) -> PyResult<Self> {
        let mut t = self.table();
        merge_mapping(&mut t, values)?;
        Self::from_table(&t)
    }

    /// The `section.key` names, in file order.
    #[staticmethod]
    fn keys() -> Vec<String> {
        PARAMS.iter().map(|s| s.name()).collect()
    }

    /// A value by its `section.key` name (SI units; a switch reads 1.0 for true, 0.0 for false).
    fn __getitem__(&self, name: &str) -> PyResult<f64> {
        spec_by_name(name)
            .map(|s| (s.get)(&self.inner))
            .ok_or_else(|| PyKeyError::new_err(format!("no parameter `{name}` (names are section.key, see Params.keys())")))
    }

    fn __len__(&self) -> usize {
        PARAMS.len()
    }

    fn __contains__(&self, name: &str) -> bool {
        spec_by_name(name).is_some()
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        for s in PARAMS.iter() {
            (s.get)(&self.inner).to_bits().hash(&mut h);
        }
        h.finish()
    }

    fn __repr__(&self) -> String {
        let d = Params::default();
        let changed: Vec<String> = PARAMS
            .iter()
            .filter(|s| (s.get)(&self.inner).to_bits() != (s.get)(&d).to_bits())
            .map(|s| match s.kind {
                pinjoint::params::Kind::Real => format!("'{}': {:?}", s.name(), (s.get)(&self.inner)),
                pinjoint::params::Kind::Boolean => format!("'{}': {}", s.name(), if (s.get)(&self.inner) != 0.0 { "True" } else { "False" }),
            })
            .collect();
        if changed.is_empty() { "pinjoint.Params()".into() } else { format!("pinjoint.Params({{{}}})", changed.join(", ")) }
    }

    /// Pickle as the constructor and the full dict (floats round-trip exactly).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let cls = slf.get_type().into_any();
        let args = PyTuple::new(py, [slf.get().to_dict(py)?])?;
        Ok((cls, args))
    }
}

/// One dict per model parameter, in file order: name (`section.key`), symbol, unit ("1" for
/// dimensionless), range, default, description and source in the paper.
#[pyfunction]
pub fn param_table<'py>(py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
    table(py, PARAMS.iter().map(|s| Row { name: s.name(), symbol: Some(s.symbol), unit: s.unit, range: s.range.describe(), default: s.default_value(), description: s.description, source: Some(s.source) }))
}

/// One dict per numeric `[rig]` parameter (the keyword arguments of `simulate_cycle`):
/// name (`rig.key`), unit, range, default and description.
#[pyfunction]
pub fn rig_param_table<'py>(py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
    let def = pinjoint::rig::RigParams::default();
    table(py, RIG_PARAMS.iter().map(|s| Row { name: s.name(), symbol: None, unit: s.unit, range: s.range.describe(), default: (s.get)(&def), description: s.description, source: None }))
}

/// One row of a parameter table; `symbol` and `source` are keys only where given.
struct Row {
    name: String,
    symbol: Option<&'static str>,
    unit: &'static str,
    range: String,
    default: f64,
    description: &'static str,
    source: Option<&'static str>,
}

/// The rows as dicts, keys in the order name, symbol, unit, range, default, description, source.
fn table<'py>(py: Python<'py>, rows: impl Iterator<Item = Row>) -> PyResult<Vec<Bound<'py, PyDict>>> {
    rows.map(|r| {
        let d = PyDict::new(py);
        d.set_item("name", r.name)?;
        if let Some(symbol) = r.symbol {
            d.set_item("symbol", symbol)?;
        }
        d.set_item("unit", r.unit)?;
        d.set_item("range", r.range)?;
        d.set_item("default", r.default)?;
        d.set_item("description", r.description)?;
        if let Some(source) = r.source {
            d.set_item("source", source)?;
        }
        Ok(d)
    })
    .collect()
}
