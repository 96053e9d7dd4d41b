//! The FMU state functions of FMI 3.0: `fmi3GetFMUState` … `fmi3DeserializeFMUState`.
//! Their bodies are the core's (`core::fmu_state`), shared with FMI 2.0: one FMU
//! state type, one serialized format, so a state serialized through FMI 3.0 reads back
//! through FMI 2.0 for the same model and vice versa.

#![allow(non_snake_case)]

use crate::core::fmu_state::{deserialize, free_state, get_state, serialize, serialized_size, set_state};
use crate::core::guard::guarded;
use crate::core::state::FMU_STATE;
use crate::fmi3::types::{Fmi3Byte, Fmi3FmuState, Fmi3Instance, Fmi3StatusC};

guarded! {
    /// `fmi3GetFMUState` (FMI 3.0): saves the instance's complete state into
    /// `*FMUState`, as `fmi2GetFMUstate` (the same FMU state type).
    ///
    /// # Safety
    /// As `fmi2GetFMUstate`.
    unsafe fn fmi3GetFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |inst| unsafe { get_state(inst, FMUState) };

    /// `fmi3SetFMUState` (FMI 3.0): restores the instance to `FMUState`, as
    /// `fmi2SetFMUstate`; `fmi3Error`, nothing changed, for a dead or foreign state.
    ///
    /// # Safety
    /// As `fmi2SetFMUstate`.
    unsafe fn fmi3SetFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |inst| unsafe { set_state(inst, FMUState) };

    /// `fmi3FreeFMUState` (FMI 3.0): frees `*FMUState` and sets it to NULL, as
    /// `fmi2FreeFMUstate`.
    ///
    /// # Safety
    /// As `fmi2FreeFMUstate`.
    unsafe fn fmi3FreeFMUState(instance: Fmi3Instance, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE => |_| unsafe { free_state(FMUState) };

    /// `fmi3SerializedFMUStateSize` (FMI 3.0): writes to `*size` the length in bytes
    /// of `FMUState` serialized, as `fmi2SerializedFMUstateSize`.
    ///
    /// # Safety
    /// As `fmi2SerializedFMUstateSize`.
    unsafe fn fmi3SerializedFMUStateSize(instance: Fmi3Instance, FMUState: Fmi3FmuState, size: *mut usize) -> Fmi3StatusC: FMU_STATE =>
        |_| unsafe { serialized_size(FMUState, size) };

    /// `fmi3SerializeFMUState` (FMI 3.0): writes `FMUState` serialized into
    /// `serializedState` (the same bytes as through FMI 2.0), as `fmi2SerializeFMUstate`;
    /// `fmi3Error` when `size` is wrong.
    ///
    /// # Safety
    /// As `fmi2SerializeFMUstate`.
    unsafe fn fmi3SerializeFMUState(instance: Fmi3Instance, FMUState: Fmi3FmuState, serializedState: *mut Fmi3Byte, size: usize) -> Fmi3StatusC: FMU_STATE =>
        |_| unsafe { serialize(FMUState, serializedState, size) };

    /// `fmi3DeserializeFMUState` (FMI 3.0): decodes `serializedState` (written
    /// through FMI 3.0 or 2.0 for this model) into `*FMUState`, as `fmi2DeSerializeFMUstate`;
    /// `fmi3Error`, nothing changed, for bytes of another model or version, a wrong length or
    /// a CRC mismatch.
    ///
    /// # Safety
    /// As `fmi2DeSerializeFMUstate`.
    unsafe fn fmi3DeserializeFMUState(instance: Fmi3Instance, serializedState: *const Fmi3Byte, size: usize, FMUState: *mut Fmi3FmuState) -> Fmi3StatusC: FMU_STATE =>
        |inst| unsafe { deserialize(inst, serializedState, size, FMUState) };
}
