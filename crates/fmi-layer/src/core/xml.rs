//! The parts of modelDescription.xml that FMI 2.0 and FMI 3.0 write alike, from a model's
//! [`ModelInfo`]: the root element's attributes, the interface elements with their
//! capabilities, a unit with its base and display units, the log categories, the default
//! experiment, a variable's common attributes and its type attributes (declared type, unit,
//! display unit, min, max, start), and the outputs' direct dependencies. Each standard's
//! generator (each shim's `xml` module) arranges them in its own elements.

use crate::error::XmlError;
use crate::core::logging::Category;
use crate::core::types::Status;
use crate::core::variables::{Causality, Initial, Kind, ModelInfo, UnitDef, Variability, Variable};
use std::fmt::Write;

/// Escape text for an XML attribute value.
pub fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            c => o.push(c),
        }
    }
    o
}

/// Shortest text that reads back to the same f64 (an xs:double).
pub fn num(v: f64) -> String {
    format!("{v:?}")
}

/// The XML declaration and `<fmiModelDescription` with one attribute a line: the
/// version, the model's name, `token_attr` (`guid` or `instantiationToken`) with the GUID,
/// description, author, version, copyright, licence, the generation tool (`pinjoint
/// <layer> layer <version>`), the naming convention and then `extra`; the last one closes the
/// start tag.
pub(crate) fn root_element(w: &mut String, fmi_version: &str, token_attr: &str, layer: &str, info: &ModelInfo, extra: &[(&str, &str)]) {
    let mut attrs: Vec<(&str, String)> = vec![
        ("fmiVersion", fmi_version.into()),
        ("modelName", escape(info.model_name)),
        (token_attr, info.guid()),
        ("description", escape(info.description)),
        ("author", escape(info.legal.author)),
        ("version", escape(info.version)),
        ("copyright", escape(info.legal.copyright)),
        ("license", escape(info.legal.license)),
        ("generationTool", format!("pinjoint {layer} layer {}", env!("CARGO_PKG_VERSION"))),
        ("variableNamingConvention", "structured".into()),
    ];
    attrs.extend(extra.iter().map(|&(k, v)| (k, v.to_owned())));
    writeln!(w, r#"<?xml version="1.0" encoding="UTF-8"?>"#).unwrap();
    writeln!(w, "<fmiModelDescription").unwrap();
    let last = attrs.len() - 1;
    for (i, (k, v)) in attrs.iter().enumerate() {
        writeln!(w, r#"  {k}="{v}"{}"#, if i == last { ">" } else { "" }).unwrap();
    }
}

/// An interface element (`<CoSimulation`, `<ModelExchange`) with the model identifier and
/// one capability a line.
pub(crate) fn interface<'a>(w: &mut String, tag: &str, info: &ModelInfo, capabilities: impl IntoIterator<Item = &'a (&'a str, &'a str)>) {
    write!(w, r#"  <{tag} modelIdentifier="{}""#, escape(info.model_identifier)).unwrap();
    for (k, v) in capabilities {
        write!(w, "\n    {k}=\"{v}\"").unwrap();
    }
    writeln!(w, "/>").unwrap();
}

/// One `<Unit>` with its `<BaseUnit>` exponents and `<DisplayUnit>`s.
pub(crate) fn unit(w: &mut String, u: &UnitDef) {
    writeln!(w, r#"    <Unit name="{}">"#, escape(u.name)).unwrap();
    let mut b = String::new();
    for (k, e) in [("kg", u.kg), ("m", u.m), ("s", u.s), ("K", u.k), ("rad", u.rad)] {
        if e != 0 {
            write!(b, r#" {k}="{e}""#).unwrap();
        }
    }
    writeln!(w, "      <BaseUnit{b}/>").unwrap();
    for d in u.display {
        let off = if d.offset != 0.0 { format!(r#" offset="{}""#, num(d.offset)) } else { String::new() };
        writeln!(w, r#"      <DisplayUnit name="{}" factor="{}"{off}/>"#, escape(d.name), num(d.factor)).unwrap();
    }
    writeln!(w, "    </Unit>").unwrap();
}

/// The units some variable uses, in table order; an error if two share a quantity (the
/// type definitions are named for it) or one has the quantity `reserved` names.
pub(crate) fn used_units<'a>(info: &'a ModelInfo, reserved: &[&str]) -> Result<Vec<&'a UnitDef>, XmlError> {
    let used: Vec<&UnitDef> = info.units.iter().filter(|u| info.variables.iter().any(|v| v.unit == Some(u.name))).collect();
    for (k, u) in used.iter().enumerate() {
        if reserved.contains(&u.quantity) || used[..k].iter().any(|o| o.quantity == u.quantity) {
            return Err(XmlError::DuplicateQuantity(u.quantity));
        }
    }
    Ok(used)
}

/// `<LogCategories>`, each status in a description named by `status_name` (the standard's).
pub(crate) fn log_categories(w: &mut String, status_name: fn(Status) -> &'static str) {
    writeln!(w, "  <LogCategories>").unwrap();
    for c in Category::ALL {
        writeln!(w, r#"    <Category name="{}" description="{}"/>"#, c.name(), escape(&c.description(status_name))).unwrap();
    }
    writeln!(w, "  </LogCategories>").unwrap();
}

/// `<DefaultExperiment>`.
pub(crate) fn default_experiment(w: &mut String, info: &ModelInfo) {
    let (t0, t1, dt) = info.default_experiment;
    writeln!(w, r#"  <DefaultExperiment startTime="{}" stopTime="{}" stepSize="{}"/>"#, num(t0), num(t1), num(dt)).unwrap();
}

/// The attributes every variable element has: name, value reference, description,
/// causality, variability and (but for inputs) initial, each after a space.
pub(crate) fn variable_attributes(v: &Variable) -> String {
    let mut a = format!(
        r#" name="{}" valueReference="{}" description="{}" causality="{}" variability="{}""#,
        escape(&v.name),
        v.value_reference,
        escape(&v.description),
        v.causality.as_str(),
        v.variability.as_str()
    );
    if v.causality != Causality::Input {
        write!(a, r#" initial="{}""#, v.initial.as_str()).unwrap();
    }
    a
}

/// The type attributes of a variable, each after a space: the enumeration type or, for a
/// Real, the quantity's type, unit and display unit; then min and max (not for a Boolean),
/// nominal (a Real only) and start. An error for a unit on a variable that is not Real, a unit missing from the table,
/// or a display unit its unit does not define.
pub(crate) fn type_attributes(info: &ModelInfo, v: &Variable) -> Result<String, XmlError> {
    let mut a = String::new();
    if let Kind::Enumeration(t) = v.kind {
        write!(a, r#" declaredType="{}""#, escape(t.name)).unwrap();
    }
    if v.kind != Kind::Real && (v.unit.is_some() || v.display_unit.is_some()) {
        return Err(XmlError::UnitOnNonReal(v.name.clone()));
    }
    if let Some(u) = v.unit {
        let def = info.unit(u).ok_or_else(|| XmlError::UnknownUnit { variable: v.name.clone(), unit: u })?;
        write!(a, r#" declaredType="{}" unit="{}""#, escape(def.quantity), escape(u)).unwrap();
        if let Some(d) = v.display_unit {
            if !def.display.iter().any(|x| x.name == d) {
                return Err(XmlError::UnknownDisplayUnit { variable: v.name.clone(), display: d, unit: u });
            }
            write!(a, r#" displayUnit="{}""#, escape(d)).unwrap();
        }
    }
    let value = |x: f64| match v.kind {
        Kind::Real => num(x),
        Kind::Integer | Kind::Enumeration(_) => format!("{}", x as i64),
        Kind::Boolean => (x != 0.0).to_string(),
    };
    let bounds = if v.kind == Kind::Boolean { [None, None] } else { [v.min, v.max] };
    let nominal = if v.kind == Kind::Real { v.nominal } else { None };
    for (name, x) in [("min", bounds[0]), ("max", bounds[1]), ("nominal", nominal), ("start", v.start)] {
        if let Some(x) = x {
            write!(a, r#" {name}="{}""#, value(x)).unwrap();
        }
    }
    Ok(a)
}

/// The continuous states as (state index, derivative index) pairs in table order of the
/// derivatives ([`ModelInfo::continuous_states`]), checked against FMI 2.0 §2.2.7-§2.2.8 and
/// FMI 3.0 §2.4.7-§2.4.8: the named state exists, is a continuous Real with causality local or
/// output and is no derivative itself; the derivative is a continuous Real with causality local
/// or output and `initial="calculated"`; no state has two derivatives.
pub(crate) fn continuous_states(info: &ModelInfo) -> Result<Vec<(usize, usize)>, XmlError> {
    let mut out: Vec<(usize, usize)> = Vec::new();
    for (d, v) in info.variables.iter().enumerate() {
        let Some(state) = v.derivative_of else { continue };
        let derivative = || v.name.clone();
        let x = info.index_by_name(state).ok_or_else(|| XmlError::UnknownState { derivative: derivative(), state })?;
        let bad_derivative = |why| Err(XmlError::InvalidDerivative { derivative: derivative(), why });
        if v.kind != Kind::Real {
            return bad_derivative("must be a Real variable");
        }
        if v.variability != Variability::Continuous {
            return bad_derivative("must have variability \"continuous\"");
        }
        if v.initial != Initial::Calculated {
            return bad_derivative("must have initial \"calculated\"");
        }
        if !matches!(v.causality, Causality::Local | Causality::Output) {
            return bad_derivative("must have causality \"local\" or \"output\"");
        }
        let s = &info.variables[x];
        let bad_state = |why| Err(XmlError::InvalidState { state: s.name.clone(), why });
        if s.kind != Kind::Real {
            return bad_state("must be a Real variable");
        }
        if s.variability != Variability::Continuous {
            return bad_state("must have variability \"continuous\"");
        }
        if !matches!(s.causality, Causality::Local | Causality::Output) {
            return bad_state("must have causality \"local\" or \"output\"");
        }
        if s.derivative_of.is_some() {
            return bad_state("is itself a derivative (higher-order states are not supported)");
        }
        if let Some(&(_, first)) = out.iter().find(|&&(y, _)| y == x) {
            return Err(XmlError::DuplicateDerivative { state, first: info.variables[first].name.clone(), second: v.name.clone() });
        }
        out.push((x, d));
    }
    Ok(out)
}

/// The indices of the variables variable `i` depends on directly (its `depends_on`), each an
/// input or a continuous state of `states`; an error for an unknown name or any other variable.
fn dependencies(info: &ModelInfo, i: usize, states: &[(usize, usize)]) -> Result<Vec<usize>, XmlError> {
    let v = &info.variables[i];
    let mut deps = Vec::new();
    for &name in &v.depends_on {
        let j = info.index_by_name(name).ok_or_else(|| XmlError::UnknownDependency { output: v.name.clone(), name })?;
        if info.variables[j].causality != Causality::Input && !states.iter().any(|&(x, _)| x == j) {
            return Err(XmlError::DependsOnNonInput { output: v.name.clone(), name });
        }
        deps.push(j);
    }
    Ok(deps)
}

/// Each output's index in the table with the indices of the inputs and continuous states it
/// depends on directly (ModelStructure `<Outputs>`/`<Output>`); an error for a dependency on
/// an unknown variable or on one that is neither an input nor a state.
pub(crate) fn output_dependencies(info: &ModelInfo) -> Result<Vec<(usize, Vec<usize>)>, XmlError> {
    let states = continuous_states(info)?;
    let outputs = info.variables.iter().enumerate().filter(|(_, v)| v.causality == Causality::Output);
    outputs.map(|(i, _)| Ok((i, dependencies(info, i, &states)?))).collect()
}

/// Each state derivative's index (in state order) with the indices of the inputs and
/// continuous states it depends on directly (ModelStructure `<Derivatives>` /
/// `<ContinuousStateDerivative>`).
pub(crate) fn derivative_dependencies(info: &ModelInfo) -> Result<Vec<(usize, Vec<usize>)>, XmlError> {
    let states = continuous_states(info)?;
    states.iter().map(|&(_, d)| Ok((d, dependencies(info, d, &states)?))).collect()
}

/// The initial unknowns (FMI 2.0 §2.2.8 `<InitialUnknowns>`, FMI 3.0 §2.4.8
/// `<InitialUnknown>`), in ascending table order without duplicates: the outputs with
/// `initial="calculated"` (this layer has no `approx`) and the continuous states and state
/// derivatives with `initial="calculated"` (no model of this layer has a calculatedParameter).
pub(crate) fn initial_unknowns(info: &ModelInfo) -> Result<Vec<usize>, XmlError> {
    let states = continuous_states(info)?;
    let calculated = |i: usize| info.variables[i].initial == Initial::Calculated;
    let mut out: Vec<usize> = info.variables.iter().enumerate().filter(|&(i, v)| v.causality == Causality::Output && calculated(i)).map(|(i, _)| i).collect();
    for &(x, d) in &states {
        out.extend([x, d].into_iter().filter(|&i| calculated(i)));
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}
