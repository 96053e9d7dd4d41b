//! Records that cannot be fitted are rejected with a typed error naming the record, the
//! quantity, its value and unit; none panics.

use pinjoint::{Joint, Params};
use pinjoint_calibrate::{calibrate, CalibrationError, Options, Record};
use std::f64::consts::TAU;

/// A quasi-static ±40° sine record at `f` Hz, `n` samples a cycle, `cycles` cycles, 20 kN.
fn sine(f: f64, n: usize, cycles: usize) -> Record {
    let joint = Joint::new(&Params::default()).unwrap();
    let a = 40f64.to_radians();
    let time: Vec<f64> = (0..n * cycles).map(|i| i as f64 / (n as f64 * f)).collect();
    let w: Vec<f64> = time.iter().map(|&t| a * TAU * f * (TAU * f * t).cos()).collect();
    Record {
        name: "rec.csv".into(),
        angle: Some(time.iter().map(|&t| a * (TAU * f * t).sin()).collect()),
        angular_velocity: None,
        torque: w.iter().map(|&w| -joint.evaluate(20e3, w).unwrap().signed_torque()).collect(),
        load: vec![20e3; time.len()],
        temperature: None,
        time,
    }
}

fn err(records: &[Record]) -> CalibrationError {
    calibrate(records, &Options { inertia: Some(0.0), ..Options::default() }).unwrap_err()
}

/// The error for the 0.3 Hz record after `edit`; its message must hold every one of `words`.
fn refused(edit: impl FnOnce(&mut Record), words: &[&str]) -> CalibrationError {
    let mut r = sine(0.3, 400, 6);
    edit(&mut r);
    let e = err(&[r]);
    let m = e.to_string();
    assert!(words.iter().all(|w| m.contains(w)), "{m} lacks one of {words:?}");
    e
}

#[test]
fn the_clean_record_fits() {
    let c = calibrate(&[sine(0.3, 400, 6)], &Options { inertia: Some(0.0), ..Options::default() }).unwrap();
    assert!((c.estimates[0].value - 0.12).abs() < 1e-5, "{}", c.estimates[0].value);
}

#[test]
fn too_short() {
    let mut r = sine(0.3, 400, 6);
    for v in [&mut r.time, &mut r.torque, &mut r.load, r.angle.as_mut().unwrap()] {
        v.truncate(10);
    }
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::TooShort { samples: 10, .. }), "{e}");
    assert!(e.to_string().contains("rec.csv") && e.to_string().contains("too short"), "{e}");
    // Long enough to read, too short once the transients are excluded: a quarter stroke.
    let mut r = sine(0.3, 400, 6);
    for v in [&mut r.time, &mut r.torque, &mut r.load, r.angle.as_mut().unwrap()] {
        v.truncate(25);
    }
    let e = err(&[r]);
    assert!(e.to_string().contains("remain after the exclusion rule"), "{e}");
}

#[test]
fn no_motion() {
    let e = refused(|r| r.angle = Some(vec![0.1; r.time.len()]), &["no motion", "rad/s"]);
    assert!(matches!(e, CalibrationError::NoMotion { .. }), "{e}");
}

#[test]
fn one_sign_of_velocity_only() {
    // A ramp: always moving forward.
    let ramp = |r: &mut Record| {
        r.angle = Some(r.time.iter().map(|t| 0.05 * t).collect());
        r.torque = vec![67.0; r.time.len()];
    };
    let e = refused(ramp, &["one direction", "positive"]);
    assert!(matches!(e, CalibrationError::Unidentifiable { .. }), "{e}");
}

#[test]
fn angle_in_degrees() {
    let mut r = sine(0.3, 400, 6);
    r.angle = Some(r.angle.unwrap().iter().map(|a| a.to_degrees()).collect());
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::AngleRange { .. }), "{e}");
    let m = e.to_string();
    assert!(m.contains("degrees") && m.contains("80 rad") && m.contains("1.396"), "{m}");
    // Velocity in deg/s beside an angle in rad: the two disagree by 57.3.
    let mut r = sine(0.3, 400, 6);
    let w: Vec<f64> = r.time.iter().map(|&t| 40f64 * TAU * 0.3 * (TAU * 0.3 * t).cos()).collect();
    r.angular_velocity = Some(w);
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::Inconsistent { .. }) && e.to_string().contains("deg/s"), "{e}");
    // deg/s alone, fast enough to be implausible in rad/s.
    let mut r = sine(1.0, 400, 6);
    r.angular_velocity = Some(r.time.iter().map(|&t| 40f64 * TAU * (TAU * t).cos()).collect());
    r.angle = None;
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::SpeedRange { .. }) && e.to_string().contains("deg/s"), "{e}");
}

#[test]
fn nan_rows_and_bad_values() {
    let mut r = sine(0.3, 400, 6);
    r.torque[17] = f64::NAN;
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::NonFinite { column: "torque", row: 17, .. }), "{e}");
    assert!(e.to_string().contains("N.m") && e.to_string().contains("NaN"), "{e}");
    let mut r = sine(0.3, 400, 6);
    r.load[3] = -5.0;
    assert!(matches!(err(&[r]), CalibrationError::Load { row: 3, .. }));
    let mut r = sine(0.3, 400, 6);
    r.time[5] = r.time[4];
    assert!(matches!(err(&[r]), CalibrationError::TimeOrder { row: 5, .. }));
    let mut r = sine(0.3, 400, 6);
    r.load.pop();
    assert!(matches!(err(&[r]), CalibrationError::Length { column: "load", .. }));
    let mut r = sine(0.3, 400, 6);
    r.angle = None;
    assert!(matches!(err(&[r]), CalibrationError::NoKinematics { .. }));
    assert!(matches!(err(&[]), CalibrationError::NoRecords));
    let mut r = sine(0.3, 400, 6);
    r.torque = r.torque.iter().map(|t| t * 1e300).collect();
    let e = err(&[r]);
    assert!(e.to_string().contains("overflows") && e.to_string().contains("N.m"), "{e}");
    let mut r = sine(0.3, 400, 6);
    r.load = vec![1e12; r.time.len()];
    let e = err(&[r]);
    assert!(matches!(e, CalibrationError::Model { .. }), "{e}");
}

#[test]
fn bad_options_are_named() {
    let r = sine(0.3, 400, 6);
    let bad = |o: Options| calibrate(std::slice::from_ref(&r), &o).unwrap_err().to_string();
    assert!(bad(Options { inertia: Some(-1.0), ..Options::default() }).contains("inertia = -1 kg.m2"));
    assert!(bad(Options { fit: vec!["lubricant.viscosityy".into()], ..Options::default() }).contains("unknown parameter `lubricant.viscosityy`"));
    let mut o = Options::default();
    o.exclusion.speed_fraction = 1.5;
    assert!(bad(o).contains("speed fraction = 1.5"));
    let mut o = Options::default();
    o.params.lubricant.viscosity = -1.0;
    assert!(bad(o).contains("lubricant.viscosity"));
}
