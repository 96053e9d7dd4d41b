//! The model parameters of both FMUs: one row per entry of the parameter file
//! ([`pinjoint::params::PARAMS`]), named `section.key`, with the file's defaults, ranges,
//! units and texts. They are checked together at exit of initialization
//! ([`pinjoint::Params::validate`]), not as they are set.

use crate::declare::declare;
use crate::table::{Row, Rule};
use fmi_layer::core::variables::{Causality, Kind, Variable};
use pinjoint::params::{Kind as ParamKind, ParamSpec, Range, PARAMS};
use pinjoint::Params;

/// Display unit a user expects for a parameter.
fn display_unit(s: &ParamSpec) -> Option<&'static str> {
    match (s.section, s.unit) {
        // The grease's values in their SI units (an activation temperature is no temperature
        // to show in degC; its stresses are Pa, not MPa).
        ("grease", "K") if s.key == "upper_service_temperature" => Some("degC"),
        ("grease", _) => None,
        ("geometry", "m") => Some("mm"),
        (_, "m") => Some("um"),
        (_, "Pa") if s.key.contains("modulus") => Some("GPa"),
        (_, "Pa") => Some("MPa"),
        (_, "Pa.s") => Some("mPa.s"),
        (_, "1/Pa") => Some("1/GPa"),
        (_, "K") => Some("degC"),
        _ => None,
    }
}

/// The min/max attributes of a parameter: only inclusive bounds are written (a bound the
/// value may not take, as the 0 of "> 0", is left off; the description states the range).
pub fn declared_bounds(range: Range) -> (Option<f64>, Option<f64>) {
    match range {
        Range::Positive => (None, None),
        Range::NonNegative => (Some(0.0), None),
        Range::HalfOpen(lo, _) => (Some(lo), None),
        Range::OpenClosed(_, hi) => (None, Some(hi)),
        Range::Closed(lo, hi) => (Some(lo), Some(hi)),
    }
}

/// The declaration of parameter `s` at value reference `vr`.
fn declaration(s: &ParamSpec, vr: u32) -> Variable {
    let (min, max) = declared_bounds(s.range);
    let mut description = format!("{} ({}, {}; must be {})", s.description, s.symbol, s.source, s.range.describe());
    if s.section == "lubricant" && s.key == "temperature" {
        description.push_str(". In this FMU the input `temperature` sets the lubricant temperature; this parameter is not used");
    }
    let kind = match s.kind {
        ParamKind::Real => Kind::Real,
        ParamKind::Boolean => Kind::Boolean,
    };
    // A unit with a parameter's exponent (K in Pa.s^n) has no SI base-unit form for the
    // modelDescription: said in the description instead.
    let declarable = !s.unit.contains('^');
    if !declarable {
        description.push_str(&format!(" [{}]", s.unit));
    }
    let unit = (s.unit != "1" && kind == Kind::Real && declarable).then_some(s.unit);
    let display = if kind == Kind::Real && declarable { display_unit(s) } else { None };
    let mut v = declare(&s.name(), vr, kind, Causality::Parameter, unit, display, description);
    v.start = Some(s.default_value());
    if kind == Kind::Real {
        v.min = min;
        v.max = max;
    }
    v
}

/// One row per entry of [`PARAMS`], at value references `vr`, `vr + 1`, …; `slot` places
/// them in the state (consecutive slots), `at` finds the parameters in the model's values.
pub fn rows<S: 'static>(vr: u32, slot: Option<usize>, at: fn(&S) -> &Params, at_mut: fn(&mut S) -> &mut Params) -> Vec<Row<S>> {
    PARAMS
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (get, set) = (s.get, s.set);
            let row = Row::new(declaration(s, vr + i as u32), move |m| get(at(m)), move |m, x| set(at_mut(m), x), Rule::Any);
            match slot {
                Some(first) => row.at_slot(first + i),
                None => row,
            }
        })
        .collect()
}
