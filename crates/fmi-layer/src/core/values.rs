//! The bodies of the typed getters and setters of both standards, generic over the C value
//! type: the model holds every value as an f64 ([`crate::core::variables::Kind`]), and each
//! exported function only names its C type and the conversion.

use super::guard::{slice, slice_mut};
use crate::error::CallError;
use crate::core::instance::{CallResult, Instance};
use crate::core::variables::Kind;

/// How a standard names the arrays of a get/set call in messages, and whether a function
/// of a type without variables checks its value array too: each shim gives its own.
pub(crate) struct Arrays {
    /// The value references, e.g. `vr[]`.
    pub(crate) vr: &'static str,
    /// The values, e.g. `value[]`.
    pub(crate) values: &'static str,
    /// Whether the getter/setter of a type without variables (FMI 2.0's String functions)
    /// checks its value array as well.
    pub(crate) check_unused_values: bool,
}

/// All variables are scalars: one value per value reference.
pub(crate) fn check_n_values(nvr: usize, n_values: usize) -> Result<(), CallError> {
    if nvr != n_values {
        return Err(CallError::NotScalar { nvr, n_values });
    }
    Ok(())
}

/// Get the values of `kind` into the C array `values`, each converted with `to`.
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn get_as<T>(
    inst: &mut Instance,
    kind: Kind,
    arrays: &Arrays,
    vr: *const u32,
    nvr: usize,
    values: *mut T,
    n_values: usize,
    to: impl Fn(f64) -> T,
) -> CallResult {
    check_n_values(nvr, n_values)?;
    // SAFETY: per the contract.
    let (vrs, out) = unsafe { (slice(vr, nvr, arrays.vr)?, slice_mut(values, n_values, arrays.values)?) };
    inst.get_values_by(kind, vrs, |k, v| out[k] = to(v))
}

/// Set the values of `kind` from the C array `values`, each converted with `from` (which
/// may refuse a value the type cannot hold); all are checked before any is stored.
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn set_as<T: Copy>(
    inst: &mut Instance,
    kind: Kind,
    arrays: &Arrays,
    vr: *const u32,
    nvr: usize,
    values: *const T,
    n_values: usize,
    from: impl Fn(T) -> Result<f64, CallError>,
) -> CallResult {
    check_n_values(nvr, n_values)?;
    // SAFETY: per the contract.
    let (vrs, vals) = unsafe { (slice(vr, nvr, arrays.vr)?, slice(values, n_values, arrays.values)?) };
    inst.set_values_by(kind, vrs, |k| from(vals[k]))
}

/// A getter or setter of `type_name`, a type no model of this layer has: `fmi2OK` for no
/// value references, else an error naming the first one.
///
/// # Safety
/// `vr` and `values` point to `nvr` / `n_values` elements.
pub(crate) unsafe fn reject_as<T>(inst: &Instance, type_name: &'static str, arrays: &Arrays, vr: *const u32, nvr: usize, values: *const T, n_values: usize) -> CallResult {
    // SAFETY: per the contract.
    let vrs = unsafe { slice(vr, nvr, arrays.vr)? };
    if arrays.check_unused_values {
        // SAFETY: per the contract.
        unsafe { slice(values, n_values, arrays.values)? };
    }
    inst.reject_type(type_name, vrs)
}
