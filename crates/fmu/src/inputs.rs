//! The inputs both FMUs share: the `load` rule, the `temperature` input and the check of a
//! load against the joint's asperity capacity.

use crate::declare::declare;
use crate::table::{Row, Rule};
use fmi_layer::core::variables::{Causality, Kind};
use pinjoint::params::{DEFAULT_TEMPERATURE, MAX_TEMPERATURE, MIN_TEMPERATURE};

pub use crate::capacity::check_capacity;

/// The rule of the `load` input (N): any finite number, its magnitude the load.
pub const LOAD_RULE: Rule = Rule::Finite("is invalid: it must be a finite number (a negative value is taken as its magnitude)");

/// The rule of an angle or speed input: any finite number.
pub const FINITE: Rule = Rule::Finite("is not a finite number");

/// The `temperature` input (K, display degC) at value reference `vr`: the lubricant
/// temperature, in [218.15, 673.15] K (the library's range, [`pinjoint::params::MIN_TEMPERATURE`]; the
/// paper's model, `model.paper = true`, refuses below [`pinjoint::params::PAPER_MIN_TEMPERATURE`]
/// when the evaluator is built), start 293.15 K; `description` is the model's.
pub fn temperature<S: 'static>(vr: u32, description: &str, get: fn(&S) -> f64, set: fn(&mut S, f64)) -> Row<S> {
    let mut v = declare("temperature", vr, Kind::Real, Causality::Input, Some("K"), Some("degC"), description);
    v.start = Some(DEFAULT_TEMPERATURE);
    v.min = Some(MIN_TEMPERATURE);
    v.max = Some(MAX_TEMPERATURE);
    Row::new(v, get, set, Rule::Closed(MIN_TEMPERATURE, MAX_TEMPERATURE))
}
