//! The bodies of the FMU state functions of both standards (`fmi2GetFMUstate` …
//! `fmi2DeSerializeFMUstate`, `fmi3GetFMUState` … `fmi3DeserializeFMUState`, each in its
//! shim's `api::fmu_state`): one [`Snapshot`] type, one registry
//! of live states and one serialized format, so a state taken or serialized through one
//! standard is read back through the other for the same model. The two standards' exports
//! differ only in name (which the messages carry) and spelling of the C types.

use super::guard::{slice, slice_mut};
use super::instance::{CallResult, Instance};
use super::snapshot::Snapshot;
use super::types::{StateHandle, Status};
use crate::error::CallError;
use std::collections::BTreeSet;
use std::ptr::null_mut;
use std::sync::{Mutex, PoisonError};

/// Addresses of the FMU states this library has handed out and not yet freed. A handle is
/// dereferenced only when it is one of them, so a freed, foreign or garbage handle is an
/// `fmi2Error`, never a read through a bad pointer: Reference-FMUs' fmusim v0.0.39, for one,
/// passes the state itself to `fmi2FreeFMUstate` where the standard passes its address,
/// which used to crash the host. Process-wide (states may move between instances of the
/// same model); a lock per state call, negligible next to encoding a state.
static LIVE: Mutex<BTreeSet<usize>> = Mutex::new(BTreeSet::new());

/// Whether `s` is a live FMU state of this library.
fn is_live(s: StateHandle) -> bool {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).contains(&(s as usize))
}

/// A new FMU state: `snap` on the heap, registered as live.
fn hand_out(snap: Snapshot) -> StateHandle {
    let s = Box::into_raw(Box::new(snap)) as StateHandle;
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).insert(s as usize);
    s
}

/// Unregister `s`; true when it was live (then the caller owns the box).
fn take_back(s: StateHandle) -> bool {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).remove(&(s as usize))
}

/// The FMU state behind the handle `s` (named `handle` in messages), or an error for NULL
/// or a handle that is not (any more) a live FMU state of this FMU.
///
/// # Safety
/// A non-NULL `s` must be an FMU state returned by this FMU.
unsafe fn live_state<'a>(s: StateHandle, handle: &'static str) -> Result<&'a mut Snapshot, CallError> {
    if s.is_null() {
        return Err(CallError::Null(handle));
    }
    if !is_live(s) {
        return Err(CallError::NotLiveState { handle });
    }
    // SAFETY: `s` is a live state handed out by `hand_out` and not freed (the registry);
    // the tag is a second check.
    let snap = unsafe { &mut *(s as *mut Snapshot) };
    if !snap.is_live() {
        return Err(CallError::NotLiveState { handle });
    }
    Ok(snap)
}

/// Store `snap` in the host's slot: a new FMU state when `*slot` is NULL, else over the live
/// one it holds (`reuse_error` when it holds none).
///
/// # Safety
/// `slot` is NULL or writable and holds NULL or an FMU state returned by this FMU.
unsafe fn store(slot: *mut StateHandle, snap: Snapshot, reuse_error: impl FnOnce(CallError) -> CallError) -> Result<(), CallError> {
    if slot.is_null() {
        return Err(CallError::Null("FMUstate"));
    }
    // SAFETY: non-NULL pointer to the host's slot.
    let slot = unsafe { &mut *slot };
    if slot.is_null() {
        *slot = hand_out(snap);
    } else {
        // The standard lets the host pass back a state for reuse.
        // SAFETY: a non-NULL slot holds a state returned by this FMU.
        *unsafe { live_state(*slot, "*FMUstate") }.map_err(reuse_error)? = snap;
    }
    Ok(())
}

/// `fmi2GetFMUstate`: the instance's complete state into `*slot`.
///
/// # Safety
/// As for `fmi2GetFMUstate`.
pub(crate) unsafe fn get_state(inst: &mut Instance, slot: *mut StateHandle) -> CallResult {
    // SAFETY: per the contract.
    unsafe { store(slot, inst.snapshot(), |_| CallError::NotReusableState) }?;
    inst.event(&format!("FMU state stored at t = {} s ({})", inst.time, inst.state.name()));
    Ok(Status::Ok)
}

/// `fmi2SetFMUstate`: the instance back to the state `s`.
///
/// # Safety
/// As for `fmi2SetFMUstate`.
pub(crate) unsafe fn set_state(inst: &mut Instance, s: StateHandle) -> CallResult {
    // SAFETY: per the contract.
    inst.restore(unsafe { live_state(s, "FMUstate") }?)
}

/// `fmi2FreeFMUstate`: free `*slot` and set it to NULL (nothing to do for NULL).
///
/// # Safety
/// As for `fmi2FreeFMUstate`.
pub(crate) unsafe fn free_state(slot: *mut StateHandle) -> CallResult {
    // SAFETY: per the contract.
    if slot.is_null() || unsafe { (*slot).is_null() } {
        return Ok(Status::Ok); // nothing to free
    }
    // SAFETY: per the contract.
    let s = unsafe { *slot };
    // SAFETY: `live_state` dereferences only a registered state.
    unsafe { live_state(s, "FMUstate") }?.kill();
    if !take_back(s) {
        return Err(CallError::NotLiveState { handle: "FMUstate" });
    }
    // SAFETY: the state came from Box::into_raw in `hand_out` and was live until just now.
    unsafe {
        drop(Box::from_raw(*slot as *mut Snapshot));
        *slot = null_mut();
    }
    Ok(Status::Ok)
}

/// `fmi2SerializedFMUstateSize`: the serialized length of `s` into `*size`.
///
/// # Safety
/// As for `fmi2SerializedFMUstateSize`.
pub(crate) unsafe fn serialized_size(s: StateHandle, size: *mut usize) -> CallResult {
    // SAFETY: per the contract.
    let snap = unsafe { live_state(s, "FMUstate") }?;
    // SAFETY: per the contract.
    unsafe { super::guard::write_out(size, snap.encode().len(), "size") }
}

/// `fmi2SerializeFMUstate`: `s` serialized into `out[0..size]`.
///
/// # Safety
/// As for `fmi2SerializeFMUstate`.
pub(crate) unsafe fn serialize(s: StateHandle, out: *mut u8, size: usize) -> CallResult {
    // SAFETY: per the contract.
    let bytes = unsafe { live_state(s, "FMUstate") }?.encode();
    if size != bytes.len() {
        return Err(CallError::StateSize { given: size, actual: bytes.len() });
    }
    // SAFETY: per the contract.
    unsafe { slice_mut(out, size, "serializedState[]") }?.copy_from_slice(&bytes);
    Ok(Status::Ok)
}

/// `fmi2DeSerializeFMUstate`: `bytes[0..size]` decoded (container and model part checked)
/// into `*slot`.
///
/// # Safety
/// As for `fmi2DeSerializeFMUstate`.
pub(crate) unsafe fn deserialize(inst: &mut Instance, bytes: *const u8, size: usize, slot: *mut StateHandle) -> CallResult {
    if slot.is_null() {
        return Err(CallError::Null("FMUstate"));
    }
    // SAFETY: per the contract.
    let snap = inst.decode_state(unsafe { slice(bytes, size, "serializedState[]") }?)?;
    // SAFETY: per the contract.
    unsafe { store(slot, snap, |e| e) }?;
    Ok(Status::Ok)
}
