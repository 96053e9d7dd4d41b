//! PinJointRig's fidelity parameters (`fidelity` Integer 0..3, `tolerance`, the envelope),
//! as PinJoint's: applied at exit of initialization with `RigSim::set_fidelity`. A table run
//! of the 1 Hz stroke at 20 kN stays within the tolerance of the full run; auto logs its
//! choice and bound, the first fallback is logged once; bad values are refused with name,
//! value and unit; the settings are in the FMU state (restore continues bit for bit); full
//! (the default) is the library's rig bit for bit, whatever the tolerance and envelope.

use test_support::rig_host;
use pinjoint::fidelity::{Envelope, Fidelity, Level};
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::types::*;
use pinjoint::rig::{Inputs, RigConfig, RigSim};
use rig_host::*;

/// Outputs at every 1 ms point from `t0` for `n` steps.
fn run(h: &Host, c: Fmi2Component, t0: f64, n: usize) -> Vec<Vec<f64>> {
    (0..n).map(|k| step(h, c, t0 + k as f64 * 1e-3, t0 + (k + 1) as f64 * 1e-3)).collect()
}

fn col(rows: &[Vec<f64>], name: &str) -> Vec<f64> {
    let i = output_index(name);
    rows.iter().map(|r| r[i]).collect()
}

fn bits(rows: &[Vec<f64>]) -> Vec<u64> {
    rows.iter().flatten().map(|x| x.to_bits()).collect()
}

/// max |a - b| / max |b|.
fn rel_to_peak(a: &[f64], b: &[f64]) -> f64 {
    let peak = b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / peak
}

/// Three strokes of the default rig (1 Hz, 40 deg, 20 kN; six reversals, stick phases),
/// table against full: the recorded torque and the friction torque differ from full's by at
/// most the tolerance relative to full's peak torque, at every 1 ms point; the angle by at
/// most the tolerance relative to the amplitude.
#[test]
fn table_stroke_at_20kn_stays_within_the_tolerance_of_full() {
    let h = new_host();
    let full = ready(&h, &[]);
    let reference = run(&h, full, 0.0, 3000);
    for tol in [1e-3, 1e-4] {
        let c = logged(&h, &[("fidelity", 1.0), ("tolerance", tol)]);
        let rows = run(&h, c, 0.0, 3000);
        let mut worst = Vec::new();
        for name in ["torque", "friction_torque", "angle", "angular_velocity"] {
            let (a, b) = (col(&rows, name), col(&reference, name));
            let e = rel_to_peak(&a, &b);
            println!("tolerance {tol:e}: {name} max |table - full| / peak |full| = {e:.3e}");
            assert!(a != b, "{name}: the table level must not be the full solve");
            worst.push(e);
        }
        assert!(worst[0] <= tol && worst[1] <= tol, "torque {:e}, friction_torque {:e} > tolerance {tol:e}", worst[0], worst[1]);
        assert!(worst[2] <= tol, "angle {:e}", worst[2]);
        // Energies over the run agree too.
        let (d, dref) = (get(c, "friction_dissipation"), get(full, "friction_dissipation"));
        assert!(((d - dref) / dref).abs() <= tol, "dissipation {d} vs {dref}");
        let log: Vec<String> = h.messages().into_iter().map(|m| m.text).collect();
        assert!(log.iter().any(|m| m.contains("fidelity table -> table: measured error bound")), "{log:?}");
        free(c);
        h.clear();
    }
    // The comparison sees a wrong level: boundary (mu = mu_c) misses the Stribeck fall of mu
    // with speed by tens of percent of the peak torque.
    let c = ready(&h, &[("fidelity", 2.0)]);
    let e = rel_to_peak(&col(&run(&h, c, 0.0, 3000), "torque"), &col(&reference, "torque"));
    println!("boundary: torque max |boundary - full| / peak |full| = {e:.3e}");
    assert!(e > 1e-2, "{e}");
    free(c);
    free(full);
}

/// The table run is the library's rig at that level (`RigSim::set_fidelity`), bit for bit;
/// full with any tolerance and envelope is `RigSim::new`'s, bit for bit.
#[test]
fn fmu_levels_are_the_library_levels_bit_for_bit() {
    let lib = |level: Option<(Fidelity, f64, Envelope)>| {
        let mut sim = RigSim::new(&RigConfig::default()).unwrap();
        if let Some((f, t, e)) = level {
            sim.set_fidelity(f, t, e).unwrap();
        }
        let held = Inputs { load: Some(20e3), command_angle: None };
        (1..=1500).map(|k| {
            sim.advance_to(f64::from(k) * 1e-3, &held).unwrap();
            sim.sample().unwrap().torque
        }).collect::<Vec<f64>>()
    };
    let h = new_host();
    let fmu = |sets: &[(&str, f64)]| {
        let c = ready(&h, sets);
        let t = col(&run(&h, c, 0.0, 1500), "torque");
        free(c);
        t
    };
    let env = Envelope::new(5e3, 100e3, 1e-3, 10.0).unwrap();
    let table = lib(Some((Fidelity::Table, 1e-4, env)));
    let plain = lib(None);
    assert_ne!(table, plain);
    assert_eq!(fmu(&[("fidelity", 1.0)]), table, "default tolerance 1e-4 and envelope 5-100 kN, 1e-3-10 rad/s");
    let odd = [("fidelity", 0.0), ("tolerance", 0.3), ("envelope.load_min", 7.0), ("envelope.speed_max", 1e3)];
    assert_eq!(fmu(&odd), plain, "full ignores tolerance and envelope");
    assert_eq!(fmu(&[]), plain);
}

#[test]
fn auto_logs_its_pick_and_the_first_fallback_once() {
    let h = new_host();
    let c = logged(&h, &[("fidelity", 3.0), ("tolerance", 1e-4)]);
    let mut rig = RigSim::new(&RigConfig::default()).unwrap();
    let ev = rig.set_fidelity(Fidelity::Auto, 1e-4, Envelope::new(5e3, 100e3, 1e-3, 10.0).unwrap()).unwrap();
    assert_eq!(ev.chosen(), Level::Table);
    let text: Vec<String> = h.messages().into_iter().map(|m| m.text).collect();
    let pick = format!("fidelity auto -> table: measured error bound {:e} (tolerance 1e-4)", ev.error_bound());
    assert!(text.iter().any(|m| m.contains(&pick)), "{pick} not in {text:?}");
    // Reversals pass below envelope.speed_min = 1e-3 rad/s, where the table's low speeds
    // answer, down to rest: no fallback.
    run(&h, c, 0.0, 2500);
    let falls: Vec<String> = h.messages().into_iter().map(|m| m.text).filter(|m| m.contains("outside the envelope")).collect();
    assert!(falls.is_empty(), "{falls:?}");
    free(c);
    // A full run says nothing about fidelity.
    let h = new_host();
    let c = logged(&h, &[]);
    run(&h, c, 0.0, 500);
    assert!(!h.messages().iter().any(|m| m.text.contains("fidelity")), "{:?}", h.messages());
    free(c);
}

#[test]
fn fidelity_parameters_have_defaults_and_bad_values_are_refused_by_name() {
    let h = new_host();
    let c = h.init_mode();
    assert_eq!(get(c, "fidelity"), 0.0);
    assert_eq!(get(c, "tolerance"), 1e-4);
    let env: Vec<f64> = ["envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max"].iter().map(|n| get(c, n)).collect();
    assert_eq!(env, [5e3, 100e3, 1e-3, 10.0]);
    // Out-of-range code: refused at once by fmi2SetInteger; fidelity is Integer, not Real.
    assert_eq!(set(c, "fidelity", 4.0), ERROR);
    assert!(h.last().contains("fidelity = 4") && h.last().contains("3 (auto)"), "{}", h.last());
    assert_eq!(set(c, "fidelity", -1.0), ERROR);
    let r = [vr("fidelity")];
    assert_eq!(unsafe { fmi2SetReal(c, r.as_ptr(), 1, [1.0].as_ptr()) }, ERROR);
    assert!(h.last().contains("Enumeration variable, not Real"), "{}", h.last());
    assert_eq!(get(c, "fidelity"), 0.0);
    free(c);
    // Refused at exit of initialization, naming parameter, value and unit (even at full).
    let cases: &[(&[(&str, f64)], &str)] = &[
        (&[("fidelity", 1.0), ("tolerance", 0.0)], "tolerance = 0 (relative error, dimensionless) is invalid"),
        (&[("tolerance", f64::NAN)], "tolerance = NaN"),
        (&[("fidelity", 1.0), ("tolerance", 1e-12)], "tolerance = 1e-12 (relative error, dimensionless) is below the accuracy"),
        (&[("fidelity", 1.0), ("envelope.load_min", 2e5)], "envelope.load_min = 200000 N is invalid: it must be below envelope.load_max = 100000 N"),
        (&[("envelope.speed_min", -1.0)], "envelope.speed_min = -1 rad/s is invalid: it must be a finite number > 0 rad/s"),
        (&[("fidelity", 3.0), ("envelope.speed_max", f64::INFINITY)], "envelope.speed_max = inf rad/s is invalid"),
        (&[("fidelity", 2.0), ("envelope.speed_max", 1e-3)], "envelope.speed_min = 0.001 rad/s is invalid: it must be below envelope.speed_max = 0.001 rad/s"),
    ];
    for (sets, expect) in cases {
        let (c, status) = h.initialize(sets);
        assert_eq!(status, ERROR, "{sets:?}");
        assert!(h.last().contains(expect), "{sets:?}: {}", h.last());
        free(c);
    }
}

/// Get/set and serialize/deserialize with fidelity table: the continuation is bit for bit,
/// in the same instance and in a fresh one (which rebuilds the table from the state's
/// settings: the fidelity settings travel in the state).
#[test]
fn state_round_trip_with_fidelity_is_bit_exact() {
    let h = new_host();
    let sets = [("fidelity", 1.0), ("tolerance", 1e-3), ("envelope.load_min", 5e3), ("envelope.load_max", 60e3), ("envelope.speed_max", 8.0)];
    let c = ready(&h, &sets);
    run(&h, c, 0.0, 1300); // past the first reversal
    assert_eq!(set(c, "load", 30e3), OK);
    let s = get_state(c);
    let bytes = serialize(c, s);
    let first = run(&h, c, 1.3, 700);
    assert_eq!(unsafe { fmi2SetFMUstate(c, s) }, OK);
    assert_eq!(bits(&run(&h, c, 1.3, 700)), bits(&first));

    // Another instance with other fidelity settings, not initialized, takes the state over.
    let d = instantiate(&h);
    assert_eq!(set(d, "fidelity", 2.0), OK);
    assert_eq!(set(d, "tolerance", 0.5), OK);
    let mut sd = deserialize(d, &bytes).unwrap_or_else(|st| panic!("deserialize returned {st}: {}", h.last()));
    assert_eq!(unsafe { fmi2SetFMUstate(d, sd) }, OK, "{}", h.last());
    for (n, v) in sets {
        assert_eq!(get(d, n), v, "{n} restored");
    }
    assert_eq!(get(d, "load"), 30e3);
    let again = run(&h, d, 1.3, 700);
    assert_eq!(bits(&again), bits(&first));
    // ... and the continuation differs from the full level's (the fidelity is not lost).
    let e = ready(&h, &[]);
    run(&h, e, 0.0, 1300);
    assert_eq!(set(e, "load", 30e3), OK);
    assert_ne!(bits(&run(&h, e, 1.3, 700)), bits(&first));

    // A state of an earlier layout (version 2, before the temperature input) is refused by version.
    let mut old = bytes.clone();
    let model = model_part_offset(&old);
    assert_eq!(old[model], 6, "rig state version 6");
    old[model] = 2;
    let n = old.len();
    let crc = fmi_layer::core::bytes::crc32(&old[..n - 4]);
    old[n - 4..].copy_from_slice(&crc.to_le_bytes());
    assert!(deserialize(d, &old).is_err());
    assert!(h.last().contains("PinJointRig state version 2; this FMU reads version 6"), "{}", h.last());
    let mut s = s;
    assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
    assert_eq!(unsafe { fmi2FreeFMUstate(d, &mut sd) }, OK);
    free(c);
    free(d);
    free(e);
}

/// Offset of the model part in a serialized state: the rig part is the container's tail
/// before the CRC, of known length (version, count, settings, start time, flag, length,
/// 112-byte simulator state).
fn model_part_offset(bytes: &[u8]) -> usize {
    let settings = pinjoint_fmu::pin_joint_rig::variables::TABLE.stored().len();
    let len = 1 + 2 + 8 * settings + 8 + 1 + 2 + 112;
    bytes.len() - 4 - len
}
