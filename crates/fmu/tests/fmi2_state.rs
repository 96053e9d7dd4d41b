//! FMU state: get/set/free, serialize/deserialize round trips (bit-exact, mid-run
//! and after reversals) and rejection of truncated, corrupted or foreign states.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::core::bytes::crc32;
use fmi_layer::fmi2::types::*;
use std::ptr::null_mut;


fn drive(c: Fmi2Component, from: usize, to: usize) -> Vec<u64> {
    let mut out = Vec::new();
    for k in from..to {
        let t = k as f64 * 0.01;
        assert_eq!(set(c, "angular_velocity", 0.5 * (2.0 * t).sin()), OK);
        assert_eq!(set(c, "angle", -0.25 * (2.0 * t).cos()), OK);
        assert_eq!(set(c, "load", 5e3 + 1e3 * k as f64), OK);
        assert_eq!(fmi2DoStep(c, t, 0.01, 0), OK);
        out.extend(all_outputs(c).iter().map(|x| x.to_bits()));
    }
    out
}

/// A default PinJoint host and instance driven for `steps` steps, and its state there.
fn driven(steps: usize) -> (Host, Fmi2Component, Fmi2FmuState) {
    let (h, c) = ready_pin_joint();
    drive(c, 0, steps);
    let s = get_state(c);
    (h, c, s)
}

#[test]
fn get_set_round_trip_is_bit_exact_after_reversals() {
    let h = Host::new();
    let c = h.ready(&[("zero_velocity.speed_band", 0.05)]);
    drive(c, 0, 300); // passes two reversals
    let mut s = get_state(c);
    let first = drive(c, 300, 500);
    assert_eq!(unsafe { fmi2SetFMUstate(c, s) }, OK);
    assert_eq!(get(c, "zero_velocity.speed_band"), 0.05);
    let again = drive(c, 300, 500);
    assert_eq!(first, again);
    // Reuse of the same state object (the standard allows passing it back).
    let s_before = s;
    assert_eq!(unsafe { fmi2GetFMUstate(c, &mut s) }, OK);
    assert_eq!(s, s_before);
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    assert!(s.is_null());
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK, "freeing NULL is a no-op");
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn serialize_round_trip_across_instances_is_bit_exact() {
    let h = Host::new();
    let a = h.ready(&[("friction.boundary_friction_coefficient", 0.1)]);
    drive(a, 0, 250);
    let mut s = get_state(a);
    let bytes = serialize(a, s);
    // 61 values of 8 bytes (version 9: version 5's 45, the complete model's ten parameters
    // (grease.supply_layer_inverse and grease.upper_service_temperature among them), the host
    // inertia, the host-convention bookkeeping and the host coupling) and the container's header.
    assert!(bytes.len() < 580, "small: {} bytes", bytes.len());
    assert_eq!(&bytes[..8], b"FMI2STAT");
    let expect = drive(a, 250, 400);

    // A second instance, never initialized with these parameters, continues identically.
    let b = h.ready(&[]);
    let s2 = deserialize(b, &bytes).unwrap();
    assert_eq!(unsafe { fmi2SetFMUstate(b, s2) }, OK);
    assert_eq!(get(b, "friction.boundary_friction_coefficient"), 0.1);
    assert_eq!(drive(b, 250, 400), expect);
    // The re-serialized state is byte-identical.
    assert_eq!(serialize(b, s2), bytes);
    let mut s2 = s2;
    assert_eq!(unsafe { fmi2FreeFMUstate(b, &mut s2) }, OK);
    assert_eq!(unsafe { fmi2FreeFMUstate(a, &mut s) }, OK);
    unsafe { fmi2FreeInstance(a) };
    unsafe { fmi2FreeInstance(b) };
}

#[test]
fn truncated_corrupted_and_wrong_version_states_are_rejected() {
    let (h, c, mut s) = driven(100);
    let bytes = serialize(c, s);
    let before = all_outputs(c);

    for n in 0..bytes.len() {
        assert_eq!(deserialize(c, &bytes[..n]), Err(ERROR), "truncated to {n}");
    }
    assert!(h.last().contains("truncated") || h.last().contains("header says"), "{}", h.last());
    for i in 0..bytes.len() {
        for bit in 0..8 {
            let mut b = bytes.clone();
            b[i] ^= 1 << bit;
            assert_eq!(deserialize(c, &b), Err(ERROR), "bit {bit} of byte {i}");
        }
    }
    // Wrong container version with a valid checksum.
    let fix_crc = |b: &mut Vec<u8>| {
        let n = b.len();
        let crc = crc32(&b[..n - 4]);
        b[n - 4..].copy_from_slice(&crc.to_le_bytes());
    };
    let mut b = bytes.clone();
    b[8] = 9;
    fix_crc(&mut b);
    assert_eq!(deserialize(c, &b), Err(ERROR));
    assert!(h.last().contains("format version 9"), "{}", h.last());
    // Wrong model-state version with a valid checksum: the model part starts after
    // magic(8) version(2) length(4) guid(1+38) state(1) times(16) length(4).
    let model_at = 8 + 2 + 4 + 1 + guid().len() + 1 + 16 + 4;
    let mut b = bytes.clone();
    b[model_at] = 10;
    fix_crc(&mut b);
    assert_eq!(deserialize(c, &b), Err(ERROR));
    assert!(h.last().contains("PinJoint state version 10"), "{}", h.last());
    // States of the previous layouts (version 4, before the presliding state; 5, before the
    // host inertia, the Model Exchange mode and the complete model's parameters; 6, either of
    // those alone; 7 and 8, before the host coupling and the two newest parameters) are refused by name.
    for old in [4u8, 5, 6, 7, 8] {
        let mut b = bytes.clone();
        b[model_at] = old;
        fix_crc(&mut b);
        assert_eq!(deserialize(c, &b), Err(ERROR));
        assert!(h.last().contains(&format!("PinJoint state version {old}; this FMU reads version 9")), "{}", h.last());
    }
    // A valid checksum over an impossible value: each is checked as its setter or the
    // parameter check at initialization checks it (issue 9: these were accepted before).
    let word = |k: usize| model_at + 1 + 2 + 8 * k;
    let n = pinjoint::params::PARAMS.len();
    for (at, v, fragment) in [
        (word(n + 1 + 2), f64::NAN, "input load = NaN N"),
        (word(n + 1 + 2), 1e300, "capacity"),
        (word(0), -0.028, "pin_radius"),
        (word(3), f64::NAN, "pin_elastic_modulus"),
        (word(n), -1.0, "speed_band"),
        (word(n + 4), f64::NAN, "dissipated_energy"),
        (word(n + 6), -1.0, "tolerance"),
        (word(n + 12), 2.0, "zero_velocity.model = 2"),
        (word(n + 13), -1.0, "zero_velocity.presliding_angle = -1 rad"),
        (word(n + 14), 1.0, "zero_velocity.elastic_limit = 1"),
        (word(n + 15), f64::NAN, "zero_velocity.damping_time = NaN s"),
        (word(n + 16), f64::NAN, "presliding_torque = NaN"),
        (word(n + 17), f64::INFINITY, "presliding_reference_angle = inf"),
        (word(n + 19), -1.0, "zero_velocity.host_inertia = -1 kg.m2"),
        (word(n + 20), 2.0, "presliding_mode"),
        (word(n + 20), 0.5, "Integer"),
        (word(n + 21), -1.0, "presliding_step"),
        (word(n + 22), f64::NAN, "presliding_reference_speed"),
        (word(n + 23), 0.5, "Boolean"),
    ] {
        let mut b = bytes.clone();
        b[at..at + 8].copy_from_slice(&v.to_bits().to_le_bytes());
        fix_crc(&mut b);
        assert_eq!(deserialize(c, &b), Err(ERROR), "{fragment}");
        assert!(h.last().contains(fragment), "{fragment}: {}", h.last());
    }
    // Wrong serialize buffer size.
    let mut buf = vec![0u8; bytes.len() + 1];
    assert_eq!(unsafe { fmi2SerializeFMUstate(c, s, buf.as_mut_ptr() as *mut Fmi2Byte, buf.len()) }, ERROR);
    // Nothing of this touched the instance.
    assert_eq!(all_outputs(c), before);
    assert_eq!(unsafe { fmi2SetFMUstate(c, null_mut()) }, ERROR);
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn set_state_restores_the_life_cycle_state_and_recovers_from_error() {
    let (_h, c, mut s) = driven(10);
    // Provoke the error state with a step whose dissipated energy overflows.
    assert_eq!(set(c, "load", 5e8), OK);
    assert_eq!(set(c, "angular_velocity", 1e6), OK);
    assert_eq!(fmi2DoStep(c, 0.1, 1e300, 0), ERROR);
    assert_eq!(fmi2DoStep(c, 0.1, 0.01, 0), ERROR, "error state");
    // The standard allows fmi2SetFMUstate in the error state: back to stepComplete.
    assert_eq!(unsafe { fmi2SetFMUstate(c, s) }, OK);
    assert_eq!(fmi2DoStep(c, 0.1, 0.01, 0), OK);
    // A state taken before initialization takes the instance back there.
    let h2 = Host::new();
    let d = h2.instantiate();
    let mut early = get_state(d);
    assert_eq!(fmi2EnterInitializationMode(d), OK);
    assert_eq!(fmi2ExitInitializationMode(d), OK);
    assert_eq!(unsafe { fmi2SetFMUstate(d, early) }, OK);
    assert_eq!(fmi2DoStep(d, 0.0, 0.1, 0), ERROR, "instantiated again");
    assert_eq!(fmi2EnterInitializationMode(d), OK);
    // A state of another instance's life works across instances of one model.
    assert_eq!(unsafe { fmi2FreeFMUstate(d, &mut early) }, OK);
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    unsafe { fmi2FreeInstance(c) };
    unsafe { fmi2FreeInstance(d) };
}

/// A handle that is not a live FMU state — freed, or the state passed where the standard
/// passes its address (as Reference-FMUs' fmusim v0.0.39 does in `fmi2FreeFMUstate`) — is an
/// error, and the host carries on: no read through the bad pointer, no crash.
#[test]
fn freed_and_misplaced_state_handles_are_errors_not_crashes() {
    let h = Host::new();
    let c = h.ready(&[]);
    let mut s: Fmi2FmuState = null_mut();
    assert_eq!(unsafe { fmi2GetFMUstate(c, &mut s) }, OK);
    let kept = s;
    // fmusim's slip: the state itself as the slot; its first bytes are no live handle.
    assert_eq!(unsafe { fmi2FreeFMUstate(c, kept as *mut Fmi2FmuState) }, ERROR);
    assert_eq!(unsafe { fmi2SetFMUstate(c, kept) }, OK, "the state is still live after the refused free");
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    assert!(s.is_null());
    // The freed handle, used again: refused without being read.
    let mut stale = kept;
    assert_eq!(unsafe { fmi2SetFMUstate(c, kept) }, ERROR);
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut stale) }, ERROR);
    let mut size = 0usize;
    assert_eq!(unsafe { fmi2SerializedFMUstateSize(c, kept, &mut size) }, ERROR);
    // A pointer into ordinary memory is no state either.
    let mut junk = [0u64; 8];
    assert_eq!(unsafe { fmi2SetFMUstate(c, junk.as_mut_ptr().cast()) }, ERROR);
    // The instance still steps.
    drive(c, 0, 10);
    unsafe { fmi2FreeInstance(c) };
}

/// A host holding the joint below breakaway: the angle oscillates by 2e-4 rad about a small
/// offset, inside the presliding range (phi_s = 1.5e-3 rad), so the torque is the elastic
/// presliding torque and depends on the history. The state taken mid-hold carries it:
/// restored (get/set) or serialized into another instance, the same inputs give the same
/// torques bit for bit; an instance without the state gives other torques.
fn hold(c: Fmi2Component, from: usize, to: usize) -> Vec<u64> {
    let mut out = Vec::new();
    for k in from..to {
        let t = k as f64 * 0.01;
        assert_eq!(set(c, "angle", 4e-4 + 2e-4 * (3.0 * t).sin()), OK);
        assert_eq!(set(c, "angular_velocity", 6e-4 * (3.0 * t).cos()), OK);
        assert_eq!(set(c, "load", 20e3 + 5e3 * (0.5 * t).sin()), OK);
        out.push(get(c, "torque").to_bits());
        assert_eq!(fmi2DoStep(c, t, 0.01, 0), OK);
        out.extend(all_outputs(c).iter().map(|x| x.to_bits()));
        out.push(get(c, "presliding_torque").to_bits());
    }
    out
}

#[test]
fn the_state_carries_the_presliding_state_mid_hold() {
    let h = Host::new();
    let a = h.ready(&[]);
    hold(a, 0, 150);
    let tau = get(a, "presliding_torque");
    let bound = get(a, "friction_coefficient") * 0.028 * get(a, "load");
    assert!(tau.abs() > 0.05 * bound && tau.abs() < bound, "held below breakaway: tau = {tau} N.m, T = {bound} N.m");
    assert_eq!(get(a, "presliding_angle_driven"), 1.0);
    let mut s = get_state(a);
    let bytes = serialize(a, s);
    let expect = hold(a, 150, 300);
    // get/set on the same instance.
    assert_eq!(unsafe { fmi2SetFMUstate(a, s) }, OK);
    assert_eq!(get(a, "presliding_torque").to_bits(), tau.to_bits());
    assert_eq!(hold(a, 150, 300), expect);
    // Serialized into a fresh instance.
    let b = h.ready(&[]);
    let mut s2 = deserialize(b, &bytes).unwrap();
    assert_eq!(unsafe { fmi2SetFMUstate(b, s2) }, OK);
    assert_eq!(hold(b, 150, 300), expect);
    // Without the state the history differs, and so do the torques.
    let d = h.ready_at(1.5, &[]);
    assert_ne!(hold(d, 150, 300), expect);
    for (c, st) in [(a, &mut s), (b, &mut s2)] {
        assert_eq!(unsafe { fmi2FreeFMUstate(c, st) }, OK);
    }
    for c in [a, b, d] {
        unsafe { fmi2FreeInstance(c) };
    }
}
