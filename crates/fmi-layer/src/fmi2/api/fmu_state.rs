//! The FMU state functions of FMI 2.0 (§2.1.8): `fmi2GetFMUstate` … `fmi2DeSerializeFMUstate`.
//! Their bodies are the core's (`core::fmu_state`), shared with FMI 3.0: one FMU
//! state type, one serialized format, so a state serialized through FMI 2.0 reads back
//! through FMI 3.0 for the same model and vice versa.

#![allow(non_snake_case)]

use crate::core::fmu_state::{deserialize, free_state, get_state, serialize, serialized_size, set_state};
use crate::core::guard::guarded;
use crate::core::state::FMU_STATE;
use crate::fmi2::types::{Fmi2Byte, Fmi2Component, Fmi2FmuState, Fmi2StatusC};

guarded! {
    /// `fmi2GetFMUstate` (FMI 2.0 §2.1.8): saves the instance's complete state (time, mode,
    /// model state) into `*FMUstate`: a new FMU state when `*FMUstate` is NULL, else the given
    /// one is overwritten. Returns `fmi2Error` for a NULL `FMUstate` or a `*FMUstate` that is
    /// not a live FMU state of this FMU.
    ///
    /// # Safety
    /// `FMUstate` is NULL or points to NULL or to an FMU state of this instance's model.
    unsafe fn fmi2GetFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |inst| unsafe { get_state(inst, FMUstate) };

    /// `fmi2SetFMUstate` (FMI 2.0 §2.1.8): restores the instance to the saved `FMUstate`
    /// (time, mode, model state). Returns `fmi2Error`, the instance unchanged, for a NULL or
    /// dead state or one saved from another model.
    ///
    /// # Safety
    /// `FMUstate` is NULL or an FMU state returned by this FMU.
    unsafe fn fmi2SetFMUstate(c: Fmi2Component, FMUstate: Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |inst| unsafe { set_state(inst, FMUstate) };

    /// `fmi2FreeFMUstate` (FMI 2.0 §2.1.8): frees `*FMUstate` and sets it to NULL; a NULL
    /// `FMUstate` or `*FMUstate` is `fmi2OK` (nothing to free), a dead or foreign state is
    /// `fmi2Error`.
    ///
    /// # Safety
    /// `FMUstate` is NULL or points to NULL or to an FMU state returned by this FMU.
    unsafe fn fmi2FreeFMUstate(c: Fmi2Component, FMUstate: *mut Fmi2FmuState) -> Fmi2StatusC: FMU_STATE => |_| unsafe { free_state(FMUstate) };

    /// `fmi2SerializedFMUstateSize` (FMI 2.0 §2.1.8): writes to `*size` the length in bytes
    /// of `FMUstate` serialized (the layer's versioned format with CRC). Returns `fmi2Error`
    /// for a dead state or a NULL `size`.
    ///
    /// # Safety
    /// `FMUstate` is an FMU state returned by this FMU; `size` is NULL or writable.
    unsafe fn fmi2SerializedFMUstateSize(c: Fmi2Component, FMUstate: Fmi2FmuState, size: *mut usize) -> Fmi2StatusC: FMU_STATE =>
        |_| unsafe { serialized_size(FMUstate, size) };

    /// `fmi2SerializeFMUstate` (FMI 2.0 §2.1.8): writes `FMUstate` serialized into
    /// `serializedState`. Returns `fmi2Error`, nothing written, when `size` differs from what
    /// `fmi2SerializedFMUstateSize` reports or the state is dead.
    ///
    /// # Safety
    /// `FMUstate` is an FMU state returned by this FMU; `serializedState` points to `size`
    /// writable bytes.
    unsafe fn fmi2SerializeFMUstate(c: Fmi2Component, FMUstate: Fmi2FmuState, serializedState: *mut Fmi2Byte, size: usize) -> Fmi2StatusC: FMU_STATE =>
        |_| unsafe { serialize(FMUstate, serializedState.cast(), size) };

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
}
