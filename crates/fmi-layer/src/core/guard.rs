//! The wrapper of every exported function: NULL and dead instances, the state mask,
//! logging of errors, and containment of panics (no panic crosses the C boundary;
//! one that happens inside a call returns `fmi2Fatal` and puts the instance in the
//! `fatal` state, in which only `fmi2FreeInstance` is accepted).

use crate::error::CallError;
use crate::core::instance::{CallResult, Instance};
use crate::core::logging::Category;
use crate::core::state::{Mask, State};
use crate::core::types::{InstanceHandle, Status, StatusC};
use std::cell::RefCell;
use std::ffi::{c_char, c_int, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};

thread_local! {
    static FORCED_PANIC: RefCell<Option<Box<str>>> = const { RefCell::new(None) };
}

/// Test hook: the next call of the FMI function `name` (e.g. `"fmi2DoStep"`) on this
/// thread panics inside its guard, so that tests can check the containment.
#[doc(hidden)]
pub fn force_panic_in(name: &str) {
    FORCED_PANIC.with(|p| *p.borrow_mut() = Some(name.into()));
}

/// The same test hook with C linkage, so that a C host can check the containment on a
/// built binary (tests/platforms: the cross-built Linux, Windows and aarch64 libraries
/// must still unwind, i.e. return `fmi2Fatal`, not abort). Not part of FMI; no FMI
/// host calls it. Returns 0, or 1 when `name` is NULL or not UTF-8 (nothing armed).
///
/// # Safety
/// `name` is NULL or a NUL-terminated string.
#[doc(hidden)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pinjoint_test_force_panic(name: *const c_char) -> c_int {
    if name.is_null() {
        return 1;
    }
    // SAFETY: per the contract above.
    match unsafe { CStr::from_ptr(name) }.to_str() {
        Ok(s) => {
            force_panic_in(s);
            0
        }
        Err(_) => 1,
    }
}

pub(crate) fn maybe_forced_panic(name: &str) {
    let armed = FORCED_PANIC.with(|p| p.borrow().as_deref() == Some(name));
    if armed {
        FORCED_PANIC.with(|p| *p.borrow_mut() = None);
        panic!("forced panic in {name} (test hook)");
    }
}

pub(crate) fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic payload".to_owned()
    }
}

/// Run `body` for the instance `c` if `mask` allows its state.
pub(crate) fn call(
    c: InstanceHandle,
    name: &'static str,
    mask: Mask,
    body: impl FnOnce(&mut Instance) -> CallResult,
) -> StatusC {
    if c.is_null() {
        return Status::Error.c();
    }
    let ptr = c as *mut Instance;
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: a non-NULL component is the pointer fmi2Instantiate returned; the
        // tag check catches most foreign or freed pointers.
        let inst = unsafe { &mut *ptr };
        if !inst.is_live() {
            return Status::Error;
        }
        if inst.logger.is_enabled(Category::All) {
            inst.logger.log(Status::Ok, Category::All, &format!("{name} called in state {}", inst.state.name()));
        }
        if !mask.allows(inst.state) {
            inst.log(
                Status::Error,
                &format!(
                    "{name}: illegal call sequence: not allowed in state {} (allowed in: {})",
                    inst.state.name(),
                    mask.describe()
                ),
            );
            return Status::Error;
        }
        maybe_forced_panic(name);
        match body(inst) {
            Ok(s) => s,
            Err(msg) => {
                inst.log(Status::Error, &format!("{name}: {msg}"));
                Status::Error
            }
        }
    }));
    match outcome {
        Ok(s) => s.c(),
        Err(payload) => {
            let text = panic_text(payload.as_ref());
            let _ = catch_unwind(AssertUnwindSafe(|| {
                // SAFETY: as above; the instance memory is still owned by the host.
                let inst = unsafe { &mut *ptr };
                if inst.is_live() {
                    inst.state = State::Fatal;
                    inst.log(Status::Fatal, &format!("{name}: internal error (panic: {text}); the instance can only be freed"));
                }
            }));
            Status::Fatal.c()
        }
    }
}

/// Convert a `(pointer, count)` pair from the host into a slice.
///
/// # Safety
/// For `n > 0` a non-NULL `p` must point to `n` readable values.
pub(crate) unsafe fn slice<'a, T>(p: *const T, n: usize, what: &'static str) -> Result<&'a [T], CallError> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(CallError::NullArray { what, len: n });
    }
    // SAFETY: per the contract above.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// As [`slice`], for an output array.
///
/// # Safety
/// For `n > 0` a non-NULL `p` must point to `n` writable values.
pub(crate) unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, what: &'static str) -> Result<&'a mut [T], CallError> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(CallError::NullArray { what, len: n });
    }
    // SAFETY: per the contract above.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// Define exported FMI functions whose whole body runs through [`call`]: for each entry
///
/// ```text
/// /// doc
/// [unsafe] fn NAME(instance: Type, arg: Type, ...) -> Status: MASK => BODY;
/// ```
///
/// a `#[unsafe(no_mangle)] pub [unsafe] extern "C" fn NAME` with exactly that signature that
/// runs `BODY` (an `FnOnce(&mut Instance) -> CallResult`, which may use the arguments) for the
/// instance if the state mask `MASK` allows its state, logging an error under the function's
/// name. `MASK` is a [`Mask`] constant in scope where the macro is used: one of the core's
/// (`crate::core::state`, for a function both standards have) or one the shim defines for a
/// function of its standard only. Both standards' exports are written with it, so the guard
/// boilerplate (NULL and dead instances, masks, logging, panics) is in one place.
macro_rules! guarded {
    () => {};
    ($(#[$attr:meta])* unsafe fn $name:ident($c:ident: $ct:ty $(, $p:ident: $t:ty)* $(,)?) -> $ret:ty: $mask:ident => $body:expr; $($rest:tt)*) => {
        $(#[$attr])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name($c: $ct $(, $p: $t)*) -> $ret {
            $crate::core::guard::call($c, stringify!($name), $mask, $body)
        }
        $crate::core::guard::guarded!($($rest)*);
    };
    ($(#[$attr:meta])* fn $name:ident($c:ident: $ct:ty $(, $p:ident: $t:ty)* $(,)?) -> $ret:ty: $mask:ident => $body:expr; $($rest:tt)*) => {
        $(#[$attr])*
        #[unsafe(no_mangle)]
        pub extern "C" fn $name($c: $ct $(, $p: $t)*) -> $ret {
            $crate::core::guard::call($c, stringify!($name), $mask, $body)
        }
        $crate::core::guard::guarded!($($rest)*);
    };
}
pub(crate) use guarded;

/// The body of a function this layer does not provide: `fmi2Error` with `why` (after the
/// state check).
pub(crate) fn refuse(why: &'static str) -> impl FnOnce(&mut Instance) -> CallResult {
    move |_| Err(CallError::Unsupported(why))
}

/// Write `v` through the host's pointer `p` (named `what` in the error for NULL).
///
/// # Safety
/// `p` is NULL or writable.
pub(crate) unsafe fn write_out<T>(p: *mut T, v: T, what: &'static str) -> CallResult {
    if p.is_null() {
        return Err(CallError::Null(what));
    }
    // SAFETY: non-NULL and writable per the contract.
    unsafe { *p = v };
    Ok(crate::core::types::Status::Ok)
}

/// Write `v` through the host's pointer `p` if it is not NULL (the optional flags of
/// FMI 3.0's functions).
///
/// # Safety
/// `p` is NULL or writable.
pub(crate) unsafe fn put<T>(p: *mut T, v: T) {
    if !p.is_null() {
        // SAFETY: per the contract.
        unsafe { *p = v };
    }
}
