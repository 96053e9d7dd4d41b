//! Python values into the parameter file's TOML table, so that a dict goes through exactly
//! the library's parsing and validation (same keys, same messages) as a file would.

use pinjoint::fmt::excerpt;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyMapping, PyString};

/// Whether `name` (`section.key`) is a switch of the parameter table (`model.paper`,
/// `grease.enabled`): a bool there, a number everywhere else.
fn is_switch(name: &str) -> bool {
    pinjoint::params::spec_by_name(name).is_some_and(|s| s.kind == pinjoint::params::Kind::Boolean)
}

/// One leaf value: a real number (int or float, not bool), a bool for the switches
/// (`model.paper`, `grease.enabled`) or, for `rig.formulation` and `rig.method`, a string.
fn leaf(name: &str, v: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    let switch = is_switch(name);
    let name = excerpt(name);
    let name = name.as_str();
    if switch {
        if v.is_instance_of::<PyBool>() {
            return Ok(toml::Value::Boolean(v.extract::<bool>()?));
        }
        return Err(PyTypeError::new_err(format!("parameter {name} = {} must be a bool (True or False)", excerpt(&v.repr()?.to_string()))));
    }
    if v.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("parameter {name} = {} must be a number, not a bool", excerpt(&v.repr()?.to_string()))));
    }
    if v.is_instance_of::<PyString>() {
        if matches!(name, "rig.formulation" | "rig.method") {
            return Ok(toml::Value::String(v.extract::<String>()?));
        }
        return Err(PyTypeError::new_err(format!("parameter {name} = {} must be a number, not a string", excerpt(&v.repr()?.to_string()))));
    }
    if v.is_instance_of::<PyFloat>() || v.is_instance_of::<PyInt>() || v.hasattr("__float__")? {
        // float() of an int beyond f64 raises OverflowError: a ValueError naming the parameter
        // instead (the documented type), with a short form of the value.
        let x: Result<f64, PyErr> = v.extract().or_else(|_| v.call_method0("__float__")?.extract());
        return match x {
            Ok(x) => Ok(toml::Value::Float(x)),
            Err(e) => Err(PyValueError::new_err(format!(
                "parameter {name} = {} is not representable as a finite float ({}): it must be a real number in the parameter's range",
                short_repr(v),
                excerpt(&e.to_string())
            ))),
        };
    }
    Err(PyTypeError::new_err(format!(
        "parameter {name} = {} must be a number (got {})",
        excerpt(&v.repr()?.to_string()),
        v.get_type().name()?
    )))
}

/// A value as a message may show it: its repr, or for an int too large for a float its
/// number of digits (its repr may be millions of characters), at most an [`excerpt`].
fn short_repr(v: &Bound<'_, PyAny>) -> String {
    if let Ok(bits @ 65..) = v.call_method0("bit_length").and_then(|b| b.extract::<u64>()) {
        // log10(2) = 0.30103: the int has about this many decimal digits.
        let sign = if v.lt(0).unwrap_or(false) { "-" } else { "" };
        return format!("{sign}(an int of about {} digits)", (bits as f64 * std::f64::consts::LOG10_2).ceil() as u64);
    }
    v.repr().map(|r| excerpt(&r.to_string())).unwrap_or_else(|_| "(a value without repr)".into())
}

/// Merge a Python mapping into `table`: keys are either sections holding mappings
/// (`{"geometry": {"pin_radius": 0.028}}`) or dotted names (`{"geometry.pin_radius": 0.028}`).
/// Later entries override earlier ones and anything already in `table`.
pub fn merge_mapping(table: &mut toml::Table, mapping: &Bound<'_, PyAny>) -> PyResult<()> {
    let mapping = mapping
        .cast::<PyMapping>()
        .map_err(|_| PyTypeError::new_err(format!("parameters must be a mapping, got {}", mapping.get_type().name().map(|n| n.to_string()).unwrap_or_default())))?;
    for item in mapping.items()?.iter() {
        let (k, v): (Bound<'_, PyAny>, Bound<'_, PyAny>) = item.extract()?;
        let key: String = k.extract().map_err(|_| PyTypeError::new_err(format!("parameter names must be strings, got {}", excerpt(&k.repr().map(|r| r.to_string()).unwrap_or_default()))))?;
        if let Some((section, name)) = key.split_once('.') {
            set(table, section, name, leaf(&key, &v)?)?;
        } else if v.cast::<PyMapping>().is_ok() && !v.is_instance_of::<PyString>() {
            let inner = v.cast::<PyMapping>().expect("checked");
            for item in inner.items()?.iter() {
                let (k2, v2): (Bound<'_, PyAny>, Bound<'_, PyAny>) = item.extract()?;
                let name: String = k2.extract().map_err(|_| PyTypeError::new_err(format!("parameter names in [{}] must be strings", excerpt(&key))))?;
                set(table, &key, &name, leaf(&format!("{key}.{name}"), &v2)?)?;
            }
        } else {
            return Err(PyValueError::new_err(format!(
                "parameter `{}`: expected a section holding a mapping (e.g. {{\"geometry\": {{\"pin_radius\": 0.028}}}}) \
                 or a dotted name (e.g. \"geometry.pin_radius\")",
                excerpt(&key)
            )));
        }
    }
    Ok(())
}

fn set(table: &mut toml::Table, section: &str, name: &str, value: toml::Value) -> PyResult<()> {
    let entry = table.entry(section.to_string()).or_insert_with(|| toml::Value::Table(toml::Table::new()));
    match entry {
        toml::Value::Table(t) => {
            t.insert(name.to_string(), value);
            Ok(())
        }
        _ => Err(PyValueError::new_err(format!("parameter section `{}` is not a table", excerpt(section)))),
    }
}

/// Check every `section.key` of `table` against the parameter file's names (the model's
/// sections, and `[rig]` when `rig` is true), so that a dict's unknown key is named as given
/// rather than as a line of generated TOML.
pub fn check_keys(table: &toml::Table, rig: bool) -> PyResult<()> {
    use pinjoint::params::PARAMS;
    use pinjoint::rig::RIG_PARAMS;
    for (section, inner) in table {
        let known: Vec<String> = if section == "rig" && rig {
            RIG_PARAMS.iter().map(|s| s.key.to_string()).chain(["formulation".into(), "method".into()]).collect()
        } else {
            PARAMS.iter().filter(|s| s.section == section).map(|s| s.key.to_string()).collect()
        };
        if known.is_empty() {
            let mut sections: Vec<&str> = PARAMS.iter().map(|s| s.section).collect();
            sections.dedup();
            if rig {
                sections.push("rig");
            }
            return Err(PyValueError::new_err(format!(
                "unknown parameter section `{}`: the sections are {}",
                excerpt(section),
                sections.join(", ")
            )));
        }
        if let Some(k) = inner.as_table().and_then(|t| t.keys().find(|k| !known.contains(k))) {
            return Err(PyValueError::new_err(format!(
                "unknown parameter `{}`: [{section}] has {}",
                excerpt(&format!("{section}.{k}")),
                known.join(", ")
            )));
        }
    }
    Ok(())
}

/// The text of `table` as a parameter file.
pub fn to_text(table: &toml::Table) -> PyResult<String> {
    toml::to_string(table).map_err(|e| PyValueError::new_err(format!("parameter file: {}", excerpt(&e.to_string()))))
}
