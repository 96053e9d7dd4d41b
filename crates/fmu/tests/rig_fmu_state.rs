//! PinJointRig FMU state: get/set and serialize/deserialize round-trip bit for bit
//! mid-simulation, after reversals and inside a stick phase; damaged or foreign
//! states are rejected.

use test_support::rig_host;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::types::*;
use rig_host::*;

/// Steps of 7 ms from `t0` for `n` steps, the load changing every 50 steps.
fn drive(h: &Host, c: Fmi2Component, t0: f64, n: usize) -> (Vec<u64>, f64) {
    let mut out = Vec::new();
    let mut t = t0;
    for _ in 0..n {
        let block = ((t / 0.007).round() as usize) / 50;
        assert_eq!(set(c, "load", 10e3 + 5e3 * (block % 4) as f64), OK);
        out.extend(step(h, c, t, t + 0.007).iter().map(|x| x.to_bits()));
        t += 0.007;
    }
    (out, t)
}

#[test]
fn get_set_round_trip_is_bit_exact_after_reversals_and_in_stick() {
    let h = new_host();
    let c = ready(&h, &[("rig.breakaway_factor", 1.5)]);
    let (_, t) = drive(&h, c, 0.0, 230); // 1.61 s: three reversals
    let s = get_state(c);
    let (first, _) = drive(&h, c, t, 150);
    assert_eq!(unsafe { fmi2SetFMUstate(c, s) }, OK);
    let (again, _) = drive(&h, c, t, 150);
    assert_eq!(first, again);

    // Inside a stick phase (just after the reversal at 1.75 s the joint holds).
    let c2 = ready(&h, &[("rig.breakaway_factor", 1.5)]);
    let mut t = 0.0;
    while get(c2, "stuck") == 0.0 || t < 1.0 {
        step(&h, c2, t, t + 0.001);
        t += 0.001;
    }
    let s2 = get_state(c2);
    let (first, _) = drive(&h, c2, t, 60);
    assert_eq!(unsafe { fmi2SetFMUstate(c2, s2) }, OK);
    assert_eq!(get(c2, "stuck"), 1.0);
    let (again, _) = drive(&h, c2, t, 60);
    assert_eq!(first, again);
    let mut s = s;
    let mut s2 = s2;
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    assert_eq!(unsafe { fmi2FreeFMUstate(c2, &mut s2) }, OK);
    free(c);
    free(c2);
}

#[test]
fn serialized_state_continues_bit_exactly_in_another_instance() {
    let h = new_host();
    let a = ready(&h, &[("frequency", 0.7), ("rig.formulation", 0.0), ("use_command_input", 0.0), ("surface.asperity_radius", 3e-5)]);
    let (_, t) = drive(&h, a, 0.0, 170);
    let sa = get_state(a);
    let bytes = serialize(a, sa);
    assert_eq!(&bytes[..8], b"FMI2STAT");
    assert!(bytes.len() < 800, "small: {} bytes", bytes.len());
    let (expect, _) = drive(&h, a, t, 120);

    // An instance with other parameters, even before initialization, takes it over.
    let b = instantiate(&h);
    assert_eq!(set(b, "frequency", 0.2), OK);
    let sb = deserialize(b, &bytes).unwrap();
    assert_eq!(unsafe { fmi2SetFMUstate(b, sb) }, OK, "{}", h.last());
    assert_eq!(get(b, "frequency"), 0.7);
    assert_eq!(get(b, "surface.asperity_radius"), 3e-5);
    let (got, _) = drive(&h, b, t, 120);
    assert_eq!(got, expect);
    free(a);
    free(b);
}

#[test]
fn regularised_and_rk4_states_round_trip_too() {
    let h = new_host();
    let c = ready(&h, &[("rig.formulation", 1.0), ("rig.method", 2.0), ("rig.rk4_step", 1e-5)]);
    let (_, t) = drive(&h, c, 0.0, 40);
    let bytes = serialize(c, get_state(c));
    let (expect, _) = drive(&h, c, t, 30);
    let d = instantiate(&h);
    let s = deserialize(d, &bytes).unwrap();
    assert_eq!(unsafe { fmi2SetFMUstate(d, s) }, OK);
    assert_eq!(get(d, "rig.method"), 2.0);
    assert_eq!(drive(&h, d, t, 30).0, expect);
    free(c);
    free(d);
}

/// Dopri5 dense (rig.method = 3): a restored state recomputes the segment and its continuous
/// extension from the saved node, so the continuation is the original's bit for bit.
#[test]
fn dense_states_round_trip_too() {
    let h = new_host();
    let c = ready(&h, &[("rig.method", 3.0)]);
    let (_, t) = drive(&h, c, 0.0, 40);
    let bytes = serialize(c, get_state(c));
    let (expect, _) = drive(&h, c, t, 30);
    let d = instantiate(&h);
    let s = deserialize(d, &bytes).unwrap();
    assert_eq!(unsafe { fmi2SetFMUstate(d, s) }, OK);
    assert_eq!(get(d, "rig.method"), 3.0);
    assert_eq!(drive(&h, d, t, 30).0, expect);
    free(c);
    free(d);
}

#[test]
fn damaged_and_foreign_states_are_rejected() {
    let (h, c) = ready_rig();
    drive(&h, c, 0.0, 20);
    let bytes = serialize(c, get_state(c));
    let n = bytes.len();
    assert!(deserialize(c, &bytes[..n - 3]).is_err());
    let mut flipped = bytes.clone();
    flipped[n / 2] ^= 4;
    assert!(deserialize(c, &flipped).is_err());
    // A valid container whose rig part is damaged: the model part is checked too.
    let mut bad_phase = bytes.clone();
    // Phase code word of the RigState (7th f64) set to 5.0, CRC recomputed.
    let phase_at = n - 4 - 112 + 6 * 8;
    bad_phase[phase_at..phase_at + 8].copy_from_slice(&5.0f64.to_le_bytes());
    let crc = fmi_layer::core::bytes::crc32(&bad_phase[..n - 4]);
    bad_phase[n - 4..].copy_from_slice(&crc.to_le_bytes());
    assert!(deserialize(c, &bad_phase).is_err());
    assert!(h.last().contains("bad phase code 5"), "{}", h.last());
    // A PinJoint state is refused by GUID.
    let p = h.instantiate_with("pj", FMI2_CO_SIMULATION, &pinjoint_fmu::pin_joint::INFO.guid(), Some("file:///x"), false);
    let ps = get_state(p);
    let pbytes = serialize(p, ps);
    assert!(deserialize(c, &pbytes).is_err());
    assert!(h.last().contains("GUID"), "{}", h.last());
    free(p);
    free(c);
}
