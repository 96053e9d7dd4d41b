//! Synthetic records from the rig simulation (`pinjoint::rig`, what `pinjoint cycle` runs):
//! known parameters, then sensor effects added on top.
#![allow(dead_code)]

use pinjoint::rig::{run_cycles, RigConfig, Sample};
use pinjoint_calibrate::uncertainty::SplitMix;
use pinjoint_calibrate::Record;

/// A rig run: `load` N, `frequency` Hz, ±40°, `cycles` strokes from rest, `spc` samples a cycle,
/// μ_c = `mu_c`, breakaway factor `breakaway` (the static peak at each reversal).
pub fn rig_run(load: f64, frequency: f64, mu_c: f64, breakaway: f64, cycles: usize, spc: usize) -> Vec<Sample> {
    rig_run_servo(load, frequency, mu_c, breakaway, RigConfig::default().rig.servo_time_constant, cycles, spc)
}

/// [`rig_run`] with the servo time constant `servo` (s) too.
pub fn rig_run_servo(load: f64, frequency: f64, mu_c: f64, breakaway: f64, servo: f64, cycles: usize, spc: usize) -> Vec<Sample> {
    let mut cfg = RigConfig::default();
    cfg.model.friction.boundary_friction_coefficient = mu_c;
    cfg.rig.load = load;
    cfg.rig.frequency = frequency;
    cfg.rig.breakaway_factor = breakaway;
    cfg.rig.servo_time_constant = servo;
    run_cycles(&cfg, cycles as f64, spc).expect("rig runs")
}

/// Standard normal deviate (Box–Muller).
pub fn normal(rng: &mut SplitMix) -> f64 {
    let u1 = rng.uniform() + 0.5 / (1u64 << 53) as f64;
    let u2 = rng.uniform();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// What a data logger records of a run: the angle quantised to `quantum` rad, the torque with
/// white noise of `noise` N·m (plus `offset` N·m), no velocity column.
pub fn record(name: &str, s: &[Sample], noise: f64, quantum: f64, offset: f64, seed: u64) -> Record {
    let mut rng = SplitMix::new(seed);
    let q = |a: f64| if quantum > 0.0 { (a / quantum).round() * quantum } else { a };
    Record {
        name: name.into(),
        time: s.iter().map(|x| x.time).collect(),
        angle: Some(s.iter().map(|x| q(x.angle)).collect()),
        angular_velocity: None,
        torque: s.iter().map(|x| x.torque + offset + noise * normal(&mut rng)).collect(),
        load: s.iter().map(|x| x.load).collect(),
    }
}

/// A 17-bit encoder over one turn (rad).
pub const ENCODER: f64 = std::f64::consts::TAU / 131072.0;
