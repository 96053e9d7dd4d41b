//! The FMU state functions of both standards (`fmi2GetFMUstate` … `fmi2DeSerializeFMUstate`
//! and `fmi3GetFMUState` … `fmi3DeserializeFMUState`): one [`Snapshot`] type and one
//! serialized format, so a state taken or serialized through one standard is read back
//! through the other for the same model. The two standards' functions differ only in name
//! (which the messages carry) and spelling of the C types.

#![allow(non_snake_case)]

use super::guard::{guarded, slice, slice_mut};
use crate::error::CallError;
use crate::fmi2::instance::{CallResult, Instance};
use crate::fmi2::snapshot::Snapshot;
use crate::fmi2::types::{Fmi2Byte, Fmi2Component, Fmi2FmuState, Fmi2StatusC, Status};
use crate::fmi3::types::{Fmi3Byte, Fmi3FmuState, Fmi3Instance, Fmi3StatusC};
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
fn is_live(s: Fmi2FmuState) -> bool {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).contains(&(s as usize))
}

/// A new FMU state: `snap` on the heap, registered as live.
fn hand_out(snap: Snapshot) -> Fmi2FmuState {
    let s = Box::into_raw(Box::new(snap)) as Fmi2FmuState;
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).insert(s as usize);
    s
}

/// Unregister `s`; true when it was live (then the caller owns the box).
fn take_back(s: Fmi2FmuState) -> bool {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner).remove(&(s as usize))
}

/// The FMU state behind the handle `s` (named `handle` in messages), or an error for NULL
/// or a handle that is not (any more) a live FMU state of this FMU.
///
/// # Safety
/// A non-NULL `s` must be an FMU state returned by this FMU.
unsafe fn live_state<'a>(s: Fmi2FmuState, handle: &'static str) -> Result<&'a mut Snapshot, CallError> {
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
unsafe fn store(slot: *mut Fmi2FmuState, snap: Snapshot, reuse_error: impl FnOnce(CallError) -> CallError) -> Result<(), CallError> {
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
unsafe fn get_state(inst: &mut Instance, slot: *mut Fmi2FmuState) -> CallResult {
    // SAFETY: per the contract.
    unsafe { store(slot, inst.snapshot(), |_| CallError::NotReusableState) }?;
    inst.event(&format!("FMU state stored at t = {} s ({})", inst.time, inst.state.name()));
    Ok(Status::Ok)
}

/// `fmi2SetFMUstate`: the instance back to the state `s`.
///
/// # Safety
/// As for `fmi2SetFMUstate`.
unsafe fn set_state(inst: &mut Instance, s: Fmi2FmuState) -> CallResult {
    // SAFETY: per the contract.
    inst.restore(unsafe { live_state(s, "FMUstate") }?)
}

/// `fmi2FreeFMUstate`: free `*slot` and set it to NULL (nothing to do for NULL).
///
/// # Safety
/// As for `fmi2FreeFMUstate`.
unsafe fn free_state(slot: *mut Fmi2FmuState) -> CallResult {
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
unsafe fn serialized_size(s: Fmi2FmuState, size: *mut usize) -> CallResult {
    // SAFETY: per the contract.
    let snap = unsafe { live_state(s, "FMUstate") }?;
    // SAFETY: per the contract.
    unsafe { super::guard::write_out(size, snap.encode().len(), "size") }
}

/// `fmi2SerializeFMUstate`: `s` serialized into `out[0..size]`.
///
/// # Safety
/// As for `fmi2SerializeFMUstate`.
unsafe fn serialize(s: Fmi2FmuState, out: *mut u8, size: usize) -> CallResult {
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
unsafe fn deserialize(inst: &mut Instance, bytes: *const u8, size: usize, slot: *mut Fmi2FmuState) -> CallResult {
    if slot.is_null() {
        return Err(CallError::Null("FMUstate"));
    }
    // SAFETY: per the contract.
    let snap = inst.decode_state(unsafe { slice(bytes, size, "serializedState[]") }?)?;
    // SAFETY: per the contract.
    unsafe { store(slot, snap, |e| e) }?;
    Ok(Status::Ok)
}

guarded! {
    /// `fmi2GetFMUstate` (FMI 2.0 §2.1.8): saves the instance's complete state (time, mode,
    /// model state) into `*FMUstate`: a new FMU state when `*FMUstate` is NULL, else the given
    /// one is overwritten. Returns `fmi2Error` for a NULL `FMUstate` or a `*FMUstate` that is
    /// not a live FMU state of this FMU.
    ///
    /// # Safety
    /// `FMUstate` is NULL or points to NULL or to an FMU state of this instance's model.
    unsafe fn fmi2GetFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |inst| unsafe { get_state(inst, FMUstate) };
    /// `fmi3GetFMUState` (FMI 3.0): saves the instance's complete state into
    /// `*FMUState`, as [`fmi2GetFMUstate`] (the same FMU state type).
    ///
    /// # Safety
    /// As `fmi2GetFMUstate`.
    unsafe fn fmi3GetFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |inst| unsafe { get_state(inst, FMUState) };

    /// `fmi2SetFMUstate` (FMI 2.0 §2.1.8): restores the instance to the saved `FMUstate`
    /// (time, mode, model state). Returns `fmi2Error`, the instance unchanged, for a NULL or
    /// dead state or one saved from another model.
    ///
    /// # Safety
    /// `FMUstate` is NULL or an FMU state returned by this FMU.
    unsafe fn fmi2SetFMUstate(c: Fmi2Component, FMUstate: Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |inst| unsafe { set_state(inst, FMUstate) };
    /// `fmi3SetFMUState` (FMI 3.0): restores the instance to `FMUState`, as
    /// [`fmi2SetFMUstate`]; `fmi3Error`, nothing changed, for a dead or foreign state.
    ///
    /// # Safety
    /// As `fmi2SetFMUstate`.
    unsafe fn fmi3SetFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |inst| unsafe { set_state(inst, FMUState) };

    /// `fmi2FreeFMUstate` (FMI 2.0 §2.1.8): frees `*FMUstate` and sets it to NULL; a NULL
    /// `FMUstate` or `*FMUstate` is `fmi2OK` (nothing to free), a dead or foreign state is
    /// `fmi2Error`.
    ///
    /// # Safety
    /// `FMUstate` is NULL or points to NULL or to an FMU state returned by this FMU.
    unsafe fn fmi2FreeFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |_| unsafe { free_state(FMUstate) };
    /// `fmi3FreeFMUState` (FMI 3.0): frees `*FMUState` and sets it to NULL, as
    /// [`fmi2FreeFMUstate`].
    ///
    /// # Safety
    /// As `fmi2FreeFMUstate`.
    unsafe fn fmi3FreeFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |_| unsafe { free_state(FMUState) };

    /// `fmi2SerializedFMUstateSize` (FMI 2.0 §2.1.8): writes to `*size` the length in bytes
    /// of `FMUstate` serialized (the layer's versioned format with CRC). Returns `fmi2Error`
    /// for a dead state or a NULL `size`.
    ///
    /// # Safety
    /// `FMUstate` is an FMU state returned by this FMU; `size` is NULL or writable.
    unsafe fn fmi2SerializedFMUstateSize(c: Fmi2Component, FMUstate: Fmi2FmuState, size: *mut usize) -> Fmi2StatusC: FMU_STATE =>
        |_| unsafe { serialized_size(FMUstate, size) };
    /// `fmi3SerializedFMUStateSize` (FMI 3.0): writes to `*size` the length in bytes
    /// of `FMUState` serialized, as [`fmi2SerializedFMUstateSize`].
    ///
    /// # Safety
    /// As `fmi2SerializedFMUstateSize`.
    unsafe fn fmi3SerializedFMUStateSize(instance: Fmi3Instance, FMUState: Fmi3FmuState, size: *mut usize) -> Fmi3StatusC: FMU_STATE =>
        |_| unsafe { serialized_size(FMUState, size) };

    /// `fmi2SerializeFMUstate` (FMI 2.0 §2.1.8): writes `FMUstate` serialized into
    /// `serializedState`. Returns `fmi2Error`, nothing written, when `size` differs from what
    /// `fmi2SerializedFMUstateSize` reports or the state is dead.
    ///
    /// # Safety
    /// `FMUstate` is an FMU state returned by this FMU; `serializedState` points to `size`
    /// writable bytes.
    unsafe fn fmi2SerializeFMUstate(c: Fmi2Component, FMUstate: Fmi2FmuState, serializedState: *mut Fmi2Byte, size: usize) -> Fmi2StatusC: FMU_STATE =>
        |_| unsafe { serialize(FMUstate, serializedState.cast(), size) };
    /// `fmi3SerializeFMUState` (FMI 3.0): writes `FMUState` serialized into
    /// `serializedState` (the same bytes as through FMI 2.0), as [`fmi2SerializeFMUstate`];
    /// `fmi3Error` when `size` is wrong.
    ///
    /// # Safety
    /// As `fmi2SerializeFMUstate`.
    unsafe fn fmi3SerializeFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState, serializedState: *mut Fmi3Byte, size: usize) -> Fmi3StatusC: FMU_STATE =>
        |_| unsafe { serialize(FMUState, serializedState, size) };

    /// `fmi2DeSerializeFMUstate` (FMI 2.0 §2.1.8): decodes `serializedState` (as written by
    /// `fmi2SerializeFMUstate` of this model, through FMI 2.0 or 3.0) into `*FMUstate`, a new
    /// state when it is NULL, else overwriting the given one. Returns `fmi2Error`, nothing
    /// changed, for bytes of another model or format version, a wrong length or a CRC mismatch.
    ///
    /// # Safety
    /// `serializedState` points to `size` readable bytes; `FMUstate` is writable and
    /// holds NULL or an FMU state returned by this FMU.
    unsafe fn fmi2DeSerializeFMUstate(c: Fmi2Component, serializedState: *const Fmi2Byte, size: usize, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC: FMU_STATE =>
        |inst| unsafe { deserialize(inst, serializedState.cast(), size, FMUstate) };
    /// `fmi3DeserializeFMUState` (FMI 3.0): decodes `serializedState` (written
    /// through FMI 3.0 or 2.0 for this model) into `*FMUState`, as [`fmi2DeSerializeFMUstate`];
    /// `fmi3Error`, nothing changed, for bytes of another model or version, a wrong length or
    /// a CRC mismatch.
    ///
    /// # Safety
    /// As `fmi2DeSerializeFMUstate`.
    unsafe fn fmi3DeserializeFMUState(instance: Fmi3Instance, serializedState: *const Fmi3Byte, size: usize, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE =>
        |inst| unsafe { deserialize(inst, serializedState, size, FMUState) };
}
