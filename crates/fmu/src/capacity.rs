//! The check of a load against the joint's asperity capacity (both FMUs; the `load` row's
//! check in [`crate::table::Table::check_input`]).

use fmi_layer::core::logging::show;
use fmi_layer::core::model::{ModelError, ModelResult};

/// A load at or beyond the joint's asperity capacity ([`pinjoint::Joint::capacity`]) is an
/// error naming both.
pub fn check_capacity(load: f64, capacity: f64) -> ModelResult<()> {
    if load.abs() >= capacity {
        let rule = format!("is beyond the asperity model's capacity of {} N for these parameters", show(capacity));
        return Err(ModelError::invalid("input", "load", load, "N", rule));
    }
    Ok(())
}
