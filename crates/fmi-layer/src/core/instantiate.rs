//! The bodies of the instantiation and life-cycle functions both standards share: the
//! checks of an instantiation's arguments (instance name, model by GUID or instantiation
//! token, resource location), freeing an instance, and switching log categories. The
//! version shims (each in its `api::common`) read their own arguments and
//! build their own logger.

use super::guard::slice;
use super::instance::{CallResult, Instance};
use super::logging::{Category, Logger};
use super::types::{InstanceHandle, Status};
use super::variables::ModelInfo;
use crate::error::CallError;
use std::ffi::{c_char, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;

/// A C string from the host as an owned Rust string (invalid UTF-8 replaced), or `None`
/// for NULL.
///
/// # Safety
/// `p` is NULL or a NUL-terminated string.
pub(crate) unsafe fn text(p: *const c_char) -> Option<String> {
    // SAFETY: per the contract.
    (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// The instance name of an instantiation, which must be a non-empty string.
pub(crate) fn instance_name_checked(name: Option<String>) -> Result<String, CallError> {
    name.filter(|n| !n.is_empty()).ok_or(CallError::EmptyInstanceName)
}

/// The model of `registry` whose GUID is `token` (the argument `arg`: `fmuGUID` or
/// `instantiationToken`), with the token.
pub(crate) fn model_of(registry: &[&'static ModelInfo], token: Option<String>, arg: &'static str) -> Result<(&'static ModelInfo, String), CallError> {
    let token = token.ok_or(CallError::Null(arg))?;
    match registry.iter().copied().find(|m| m.guid() == token) {
        Some(info) => Ok((info, token)),
        None => {
            let known: Vec<String> = registry.iter().map(|m| format!("{} {}", m.model_name, m.guid())).collect();
            Err(CallError::UnknownToken { arg, token, known: known.join(", ") })
        }
    }
}

/// Log why the instantiation function `func` refuses, and return its NULL instance.
pub(crate) fn refuse_instance(logger: &Logger, func: &str, e: &CallError) -> InstanceHandle {
    logger.log(Status::Error, Category::StatusError, &format!("{func}: {e}"));
    null_mut()
}

/// RFC 3986: `scheme ":" ...` with scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ).
pub(crate) fn looks_like_uri(s: &str) -> bool {
    match s.split_once(':') {
        Some((scheme, _)) => {
            let mut ch = scheme.chars();
            ch.next().is_some_and(|c| c.is_ascii_alphabetic())
                && ch.all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c))
                && scheme.len() > 1 // not a Windows drive letter
        }
        None => false,
    }
}

/// The body of `fmi2FreeInstance` and `fmi3FreeInstance`: frees the instance in any state
/// (the `fatal` one included) and everything it owns. NULL, or an instance already freed (the
/// tag check), is a no-op; a panic during the release is contained.
///
/// # Safety
/// `c` is NULL or an instance of this library not yet freed.
pub(crate) unsafe fn free_instance(c: InstanceHandle) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(AssertUnwindSafe(|| {
        let ptr = c as *mut Instance;
        // SAFETY: per the contract; the tag check skips freed or foreign memory.
        let inst = unsafe { &mut *ptr };
        if !inst.is_live() {
            return;
        }
        inst.event("freeing the instance");
        inst.kill();
        // SAFETY: the pointer came from Box::into_raw in the instantiation function.
        drop(unsafe { Box::from_raw(ptr) });
    }));
}

/// The body of `fmi2SetDebugLogging` and `fmi3SetDebugLogging`: switch the named
/// categories (all of them for none) on or off; nothing changes if a name is NULL or unknown.
///
/// # Safety
/// `categories` points to `n` strings when `n > 0`.
pub(crate) unsafe fn set_debug_logging(inst: &mut Instance, on: bool, categories: *const *const c_char, n: usize) -> CallResult {
    // SAFETY: per the contract.
    let cats = unsafe { slice(categories, n, "categories[]") }?;
    let mut parsed = Vec::with_capacity(cats.len());
    for &p in cats {
        // SAFETY: each entry is NULL or a NUL-terminated string.
        let name = unsafe { text(p) }.ok_or(CallError::Null("a category name"))?;
        let known: Vec<&str> = Category::ALL.iter().map(|c| c.name()).collect();
        parsed.push(Category::from_name(&name).ok_or_else(|| CallError::UnknownCategory { name, known: known.join(", ") })?);
    }
    if parsed.is_empty() {
        inst.logger.set_all(on);
    } else {
        for cat in parsed {
            inst.logger.set(cat, on);
        }
    }
    Ok(Status::Ok)
}

