//! The bodies of the Model Exchange functions with an array of continuous states or event
//! indicators, the same in both standards (FMI 2.0 §3.2, FMI 3.0 §3.2): the version shims
//! (each in its `api::model_exchange`) pass their argument names, for
//! the messages, and their arrays.

use super::guard::{slice, slice_mut};
use super::instance::{CallResult, Instance};
use super::types::Status;

/// The body of the Model Exchange functions with an array of event indicators (`what` =
/// `n`), of which this layer's models have none: `n` must be 0.
pub(crate) fn none(what: &'static str, n: usize) -> impl FnOnce(&mut Instance) -> CallResult {
    move |inst| inst.require_none(what, n).map(|()| Status::Ok)
}

/// The body of the two SetContinuousStates functions: the count (argument `what`) and the
/// array (`array`), then [`Instance::set_continuous_states`].
///
/// # Safety
/// `x` points to `n` values.
pub(crate) unsafe fn set_states(inst: &mut Instance, what: &'static str, array: &'static str, x: *const f64, n: usize) -> CallResult {
    inst.require_state_count(what, n)?;
    // SAFETY: per the contract.
    let x = unsafe { slice(x, n, array)? };
    inst.set_continuous_states(x)
}

/// The body of the functions that write one value per continuous state: the count
/// (argument `what`) and the array (`array`), then `fill`.
///
/// # Safety
/// `out` points to `n` writable values.
pub(crate) unsafe fn get_states(
    inst: &mut Instance,
    what: &'static str,
    array: &'static str,
    out: *mut f64,
    n: usize,
    fill: impl FnOnce(&mut Instance, &mut [f64]) -> CallResult,
) -> CallResult {
    inst.require_state_count(what, n)?;
    // SAFETY: per the contract.
    let out = unsafe { slice_mut(out, n, array)? };
    fill(inst, out)
}
