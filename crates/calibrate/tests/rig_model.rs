//! The fit through the rig simulation (`Model::Rig`): synthetic rig records with known μ_c,
//! breakaway factor and servo time constant, torque noise, an offset and a 17-bit encoder, are
//! recovered within their 95 % intervals (all three on the paper's model; on the complete model
//! μ_c with the rig's constants given: fitting them is not yet reliable there, see
//! docs/calibration.md); bad uses give clear errors; the work is bounded.
//! Records are kept short (3–4 cycles, 500 samples a cycle): each evaluation simulates them all.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint::Params;
use pinjoint_calibrate::{calibrate, CalibrationError, Model, Options, Record, MU_C};

const MU: f64 = 0.105;

fn rig_options(keys: &[&str]) -> Options {
    // J given (the rig's 0.05 kg·m², as simulated): without it the rig fit would simulate with the
    // quasi-static fit's J, whose error on these short records would show in the other keys.
    Options { model: Model::Rig, fit: keys.iter().map(ToString::to_string).collect(), inertia: Some(0.05), ..Options::default() }
}

fn within(e: &pinjoint_calibrate::Estimate, truth: f64) {
    assert!(e.ci95.0 <= truth && truth <= e.ci95.1, "{} = {} ci95 {:?}, truth {truth}", e.key, e.value, e.ci95);
}

/// Rig records at 20 and 40 kN, 1 Hz, 3 cycles of 500 samples, μ_c = [`MU`], breakaway factor
/// `kb`, servo time constant `tau`, 0.5 N·m of noise, a 0.3 N·m offset, a 17-bit encoder; the
/// joint's model `model` (the paper's or the complete one).
fn servo_records(model: Params, kb: f64, tau: f64) -> Vec<Record> {
    [20e3, 40e3]
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            let mut cfg = RigConfig { model, ..RigConfig::default() };
            cfg.model.friction.boundary_friction_coefficient = MU;
            (cfg.rig.load, cfg.rig.frequency, cfg.rig.breakaway_factor, cfg.rig.servo_time_constant) = (p, 1.0, kb, tau);
            record(&format!("{p} N"), &run_cycles(&cfg, 3.0, 500).expect("rig runs"), 0.5, ENCODER, 0.3, 21 + k as u64)
        })
        .collect()
}

/// The fitting machinery on the paper's model (`[model] paper = true`), where k_b and τ_s are
/// found together from their defaults. On the complete model the same fit ends in a local
/// minimum (k_b = 1.50, rms 29.4 N·m: docs/calibration.md, "The fit is local"); what it does
/// there is checked by [`complete_model_recovers_mu_c_with_the_rig_constants_given`].
#[test]
fn recovers_mu_c_breakaway_and_servo_lag_with_noise_and_quantisation() {
    let (kb, tau) = (1.3, 0.004);
    let records = servo_records(Params::paper(), kb, tau);
    // k_b starts from its default 1 (the fit scans it), τ_s from its default 3 ms.
    let options = Options { params: Params::paper(), ..rig_options(&["rig.breakaway_factor", "rig.servo_time_constant"]) };
    let c = calibrate(&records, &options).expect("fits");
    for e in c.estimates.iter().chain(c.offset.iter()) {
        println!("{} = {} (se {:.3e}, ci95 {:?}, start {})", e.key, e.value, e.standard_error, e.ci95, e.initial);
    }
    println!("rms {:.4} N.m, {} used, {} excluded, {} strokes, {} LM evaluations, {} simulations; {:?}", c.rms_residual, c.points_used,
        c.points_excluded, c.strokes, c.evaluations, c.simulations, c.warnings);
    assert_eq!(c.model, Model::Rig);
    let keys: Vec<&str> = c.estimates.iter().map(|e| e.key.as_str()).collect();
    assert_eq!(keys, [MU_C, "rig.breakaway_factor", "rig.servo_time_constant"]);
    within(&c.estimates[0], MU);
    within(&c.estimates[1], kb);
    within(&c.estimates[2], tau);
    within(c.offset.as_ref().unwrap(), 0.3);
    assert!((c.estimates[0].value - MU).abs() < 1e-4 && (c.estimates[1].value - kb).abs() < 0.01);
    // The residual is the noise: the rig describes the reversals the quasi-static model leaves out.
    assert!(c.rms_residual < 0.55, "{}", c.rms_residual);
    // Only the start-up is left out; the fitted rig constants are in the result.
    assert!(c.exclusions.iter().all(|x| x.low_speed == 0 && x.settling == 0 && x.start_up > 0 && x.start_up < 400));
    let rig = c.rig.expect("rig parameters");
    assert_eq!((rig.breakaway_factor, rig.servo_time_constant), (c.estimates[1].value, c.estimates[2].value));
    assert!(c.simulations <= Options::default().max_simulations);
    // The command is recovered from the angle: ±40° at 1 Hz.
    for m in &c.commands {
        assert!((m.frequency - 1.0).abs() < 1e-5 && (m.amplitude() - 40f64.to_radians()).abs() < 1e-3, "{m:?}");
    }
}

/// The rig fit on the complete model (the default), k_b and τ_s given (the truth): μ_c and
/// the offset recovered, each interval holding the truth, the residual the noise (the rig fit's
/// simulation reproduces the complete model's records). Fitting k_b too is not yet reliable on
/// the complete model (docs/calibration.md, "Validation of the rig fit").
#[test]
fn complete_model_recovers_mu_c_with_the_rig_constants_given() {
    let (kb, tau) = (1.3, 0.004);
    let records = servo_records(Params::default(), kb, tau);
    let mut options = rig_options(&[]);
    (options.rig.breakaway_factor, options.rig.servo_time_constant) = (kb, tau);
    let c = calibrate(&records, &options).expect("fits");
    for e in c.estimates.iter().chain(c.offset.iter()) {
        println!("{} = {} (se {:.3e}, ci95 {:?}, start {})", e.key, e.value, e.standard_error, e.ci95, e.initial);
    }
    println!("rms {:.4} N.m, {} simulations; {:?}", c.rms_residual, c.simulations, c.warnings);
    let keys: Vec<&str> = c.estimates.iter().map(|e| e.key.as_str()).collect();
    assert_eq!(keys, [MU_C]);
    within(&c.estimates[0], MU);
    assert!((c.estimates[0].value - MU).abs() < 1e-4);
    within(c.offset.as_ref().unwrap(), 0.3);
    assert!(c.rms_residual < 0.55, "{}", c.rms_residual);
}

#[test]
fn bad_uses_are_clear_errors() {
    let s = rig_run(20e3, 1.0, MU, 1.3, 3, 500);
    let rec = record("r", &s, 0.0, 0.0, 0.0, 1);
    // A rig key without the rig model.
    let e = calibrate(std::slice::from_ref(&rec), &Options { fit: vec!["rig.breakaway_factor".into()], ..Options::default() }).unwrap_err().to_string();
    assert!(e.contains("rig.breakaway_factor") && e.contains("--model rig"), "{e}");
    // An excitation key is not fitted.
    let e = calibrate(std::slice::from_ref(&rec), &rig_options(&["rig.frequency"])).unwrap_err().to_string();
    assert!(e.contains("rig.frequency") && e.contains("record"), "{e}");
    // Less than a cycle of angle: no command to estimate.
    let short = Record { time: rec.time[..350].to_vec(), angle: rec.angle.as_ref().map(|a| a[..350].to_vec()), torque: rec.torque[..350].to_vec(),
        load: rec.load[..350].to_vec(), ..rec.clone() };
    let e = calibrate(&[short], &rig_options(&[])).unwrap_err();
    assert!(matches!(e, CalibrationError::TooShort { .. }) && e.to_string().contains("full cycle"), "{e}");
    // No angle column: the command cannot be estimated.
    let w: Vec<f64> = s.iter().map(|x| x.angular_velocity).collect();
    let no_angle = Record { angle: None, angular_velocity: Some(w), ..rec.clone() };
    let e = calibrate(&[no_angle], &rig_options(&[])).unwrap_err().to_string();
    assert!(e.contains("angle column"), "{e}");
    // Bounded work: too small a simulation budget is refused before any simulation, and a
    // budget the fit runs out of is refused naming the limit.
    let e = calibrate(std::slice::from_ref(&rec), &Options { max_simulations: 3, ..rig_options(&[]) }).unwrap_err().to_string();
    assert!(e.contains("max_simulations = 3") && e.contains("at least"), "{e}");
    let e = calibrate(&[rec], &Options { max_simulations: 40, ..rig_options(&["rig.breakaway_factor", "rig.servo_time_constant"]) }).unwrap_err();
    assert!(matches!(e, CalibrationError::Budget(_)) && e.to_string().contains("--max-simulations"), "{e}");
}
