//! Calibration on the cold day (issue 37, item 6): rig records (what `pinjoint cycle` runs:
//! stick at every reversal, breakaway, servo, J = 0.05 kg·m²) of a joint whose μ_c and grease
//! differ from the defaults, at −40, −20, 0 and 20 °C, 5 and 10 kN, 0.3 (−40 °C) or 0.5 Hz and 1 Hz, with torque noise, an offset and a
//! 17-bit encoder, are fitted across temperature (each record at its temperature, the grease's
//! keys by default); the calibrated parameters then predict the rig's stroke at −30 °C, a
//! temperature between the records, within 5 % of the truth's mean |T| (here within 1e-2).
//!
//! At −40 °C and 0.3 Hz a grease this stiff made the rig's event logic chatter and refuse
//! before the Filippov stop rule (`pinjoint::rig`'s sim.rs): those records could not be made.
//!
//! The loads are 5 and 10 kN: at 40 kN the records at −20 and 0 °C stick and slip (the fit's
//! irregular-motion warning, 47–52 % rms at −20 °C): there the grease's supply layer lets the
//! oil lift the surfaces as the speed rises, so the torque falls steeply with speed (the
//! default joint at 40 kN, −20 °C: from about 108 to 35 N·m between 0.3 and 3 rad/s), which the
//! quasi-static fit does not describe; with them the grease's keys were not determined.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint::Params;
use pinjoint_calibrate::{calibrate, Options, Record};

/// The record temperatures: −40, −20, 0 and 20 °C.
const TEMPERATURES: [f64; 4] = [233.15, 253.15, 273.15, 293.15];
/// The prediction's: −30 °C.
const PREDICTED: f64 = 243.15;

/// The truth: μ_c 0.11 and a grease 1.5× stiffer than the default (yield stress and
/// consistency × 1.5, whatever the defaults are).
fn truth() -> Params {
    let mut p = Params::default();
    p.friction.boundary_friction_coefficient = 0.11;
    p.grease.yield_stress *= 1.5;
    p.grease.consistency *= 1.5;
    p
}

/// The default rig with the model `p` at `temperature` K, `load` N and `frequency` Hz.
fn rig(p: &Params, temperature: f64, load: f64, frequency: f64) -> RigConfig {
    let mut c = RigConfig { model: *p, ..RigConfig::default() };
    c.model.lubricant.temperature = temperature;
    c.rig.load = load;
    c.rig.frequency = frequency;
    c
}

/// A ±40° record of the truth at `temperature` K, `load` N and `frequency` Hz: 4 strokes of 400
/// samples, 0.5 N·m of torque noise, a 0.3 N·m offset, a 17-bit encoder; it carries its
/// temperature.
fn record_at(temperature: f64, load: f64, frequency: f64, seed: u64) -> Record {
    let s = run_cycles(&rig(&truth(), temperature, load, frequency), 4.0, 400).expect("the cold rig runs");
    let mut r = record(&format!("{temperature} K, {load} N, {frequency} Hz"), &s, 0.5, ENCODER, 0.3, seed);
    r.temperature = Some(vec![temperature; r.len()]);
    r
}

/// The rig's mean |T_a| over the second of two strokes (N·m): the cycle torque
/// `pinjoint cycle` averages (eq. 11 times R·P).
fn stroke_torque(p: &Params, temperature: f64, load: f64, frequency: f64) -> f64 {
    let per = 500;
    let s = run_cycles(&rig(p, temperature, load, frequency), 2.0, per).expect("the cold rig runs");
    let second = &s[per..2 * per];
    second.iter().map(|x| x.torque.abs()).sum::<f64>() / second.len() as f64
}

#[test]
fn records_at_minus_40_to_20_celsius_predict_minus_30_within_5_percent() {
    // 5 and 10 kN at 0.3 (−40 °C) or 0.5 Hz and at 1 Hz: at −40 °C the 0.3 Hz strokes are the
    // ones the event logic refused before; at −20 °C, 10 kN, 0.3 Hz the rig sticks and slips
    // (12 % rms irregular motion), the slower strokes reaching down the falling friction curve.
    let mut records = Vec::new();
    for (i, &t) in TEMPERATURES.iter().enumerate() {
        let slow = if t < 240.0 { 0.3 } else { 0.5 };
        for (j, p) in [5e3, 10e3].into_iter().enumerate() {
            for (k, f) in [slow, 1.0].into_iter().enumerate() {
                records.push(record_at(t, p, f, 7 + 10 * i as u64 + 2 * j as u64 + k as u64));
            }
        }
    }
    let c = calibrate(&records, &Options::default()).expect("fits");
    for e in &c.estimates {
        println!("{} = {} [{}, {}]", e.key, e.value, e.ci95.0, e.ci95.1);
    }
    for w in &c.warnings {
        println!("warning: {w}");
    }
    assert_eq!(c.temperatures, TEMPERATURES.to_vec());
    // The grease is fitted across temperature (μ_c, τ_y, K and their activations at least).
    for key in ["grease.yield_stress", "grease.consistency"] {
        assert!(c.estimates.iter().any(|e| e.key == key), "{key} not fitted: {:?}", c.estimates);
    }
    // The noise is what is left.
    assert!(c.rms_residual < 0.6, "rms {}", c.rms_residual);
    let (mut worst, mut worst_default): (f64, f64) = (0.0, 0.0);
    for load in [5e3, 20e3, 40e3] {
        for f in [0.3, 1.0] {
            let want = stroke_torque(&truth(), PREDICTED, load, f);
            let got = stroke_torque(&c.params, PREDICTED, load, f);
            let default = stroke_torque(&Params::default(), PREDICTED, load, f);
            let err = (got / want - 1.0).abs();
            println!("-30 C, {load} N, {f} Hz: truth {want:.4} N.m, calibrated {got:.4} ({err:.2e}), defaults {default:.4}");
            worst = worst.max(err);
            worst_default = worst_default.max((default / want - 1.0).abs());
        }
    }
    println!("worst relative error at -30 C: calibrated {worst:.2e}, uncalibrated defaults {worst_default:.2e}");
    assert!(worst < 0.05, "the calibrated rig misses the -30 C stroke torque by {worst:.3}");
    // What the test discriminates: the defaults miss by more than the 5 %.
    assert!(worst_default > 0.05, "{worst_default}");
    // And the fit does far better than the bound on these records.
    assert!(worst < 1e-2, "{worst}");
}
