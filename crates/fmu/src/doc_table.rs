//! The variable tables of both FMUs' `documentation/index.html`, written from the same
//! declarations as the modelDescription.

use fmi_layer::core::variables::{Causality, Kind, Variable};
use fmi_layer::core::xml::escape;
use std::fmt::Write;

/// Whether a table has a `type` column (the rig has Boolean and Enumeration variables
/// among its Reals and names their values).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// name, value reference, unit, display unit, start, min, max, description.
    Plain,
    /// As [`Style::Plain`] with the type after the value reference; Booleans and
    /// Enumerations shown by name.
    Typed,
}

/// The header row.
pub fn head(style: Style) -> &'static str {
    match style {
        Style::Plain => "<tr><th>name</th><th>value reference</th><th>unit</th><th>display unit</th><th>start</th><th>min</th><th>max</th><th>description</th></tr>",
        Style::Typed => "<tr><th>name</th><th>value reference</th><th>type</th><th>unit</th><th>display unit</th><th>start</th><th>min</th><th>max</th><th>description</th></tr>",
    }
}

fn num(style: Style, v: &Variable, x: Option<f64>) -> String {
    match (style, v.kind, x) {
        (_, _, None) => "&ndash;".into(),
        (Style::Typed, Kind::Boolean, Some(x)) => (x != 0.0).to_string(),
        (Style::Typed, Kind::Integer, Some(x)) => format!("{}", x as i64),
        (Style::Typed, Kind::Enumeration(t), Some(x)) => format!("{} ({})", x as i64, t.item(x as i64).unwrap_or("?")),
        (_, _, Some(x)) => format!("{x:e}").replace("e0", ""),
    }
}

/// One row per variable of `causality`, in table order.
pub fn rows(vars: &[Variable], causality: Causality, style: Style) -> String {
    let mut s = String::new();
    for v in vars.iter().filter(|v| v.causality == causality) {
        let unit = v.unit.unwrap_or(if style == Style::Plain || v.kind == Kind::Real { "1" } else { "" });
        let kind = if style == Style::Typed { format!("<td>{}</td>", v.kind.as_str()) } else { String::new() };
        writeln!(
            s,
            "<tr><td><code>{}</code></td><td>{}</td>{kind}<td>{unit}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            escape(&v.name),
            v.value_reference,
            v.display_unit.unwrap_or(""),
            num(style, v, v.start),
            num(style, v, v.min),
            num(style, v, v.max),
            escape(&v.description)
        )
        .expect("writing to a String");
    }
    s
}
