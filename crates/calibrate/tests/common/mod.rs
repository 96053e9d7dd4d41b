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

/// The signed recorded (actuator) torque of the joint with parameters `p` at load `load` N,
/// angular velocity `w` rad/s and lubricant temperature `t` K: what a quasi-static record holds.
pub fn torque(p: &pinjoint::Params, load: f64, w: f64, t: f64) -> f64 {
    let mut q = *p;
    q.lubricant.temperature = t;
    -pinjoint::Joint::new(&q).unwrap().evaluate(load, w).unwrap().signed_torque()
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
        temperature: None,
    }
}

/// A 17-bit encoder over one turn (rad).
pub const ENCODER: f64 = std::f64::consts::TAU / 131072.0;

/// A direct record: θ = A·sin(2πft) (A = 40°) sampled `spc` times a cycle for `cycles` cycles
/// on a 17-bit encoder at a random phase, torque = J·α − friction(P, ω) (the library's, with
/// μ_c = `mu_c`) + `offset` + white noise of `noise` N·m. No velocity column.
#[allow(clippy::too_many_arguments)]
pub fn direct_record(load: f64, f: f64, j: f64, mu_c: f64, noise: f64, offset: f64, (cycles, spc): (usize, f64), seed: u64) -> Record {
    let mut p = pinjoint::Params::default();
    p.friction.boundary_friction_coefficient = mu_c;
    let joint = pinjoint::Joint::new(&p).unwrap();
    let (a, w, q) = (40f64.to_radians(), std::f64::consts::TAU * f, ENCODER);
    let mut rng = SplitMix::new(seed);
    // A random phase of the encoder's counts against the motion.
    let shift = q * rng.uniform();
    let n = (cycles as f64 * spc).round() as usize;
    let time: Vec<f64> = (0..n).map(|i| i as f64 / (f * spc)).collect();
    let angle = time.iter().map(|&t| ((a * (w * t).sin() + shift) / q).round() * q).collect();
    let torque = time
        .iter()
        .map(|&t| {
            let omega = a * w * (w * t).cos();
            let alpha = -a * w * w * (w * t).sin();
            j * alpha - joint.evaluate(load, omega).unwrap().signed_torque() + offset + noise * normal(&mut rng)
        })
        .collect();
    Record { name: format!("direct {load} N {f} Hz J {j}"), angle: Some(angle), angular_velocity: None, torque, load: vec![load; n], temperature: None, time }
}

/// A rig record (`pinjoint cycle`'s simulation, breakaway factor 1.3) with inertia `j`, μ_c =
/// `mu_c`, `cycles` cycles of `spc` samples, white torque noise of `noise` N·m, `offset` N·m, and
/// the angle on a 17-bit encoder at a random phase (each seed its own pattern).
#[allow(clippy::too_many_arguments)]
pub fn rig_record(load: f64, f: f64, j: f64, mu_c: f64, noise: f64, offset: f64, (cycles, spc): (usize, usize), seed: u64) -> Record {
    let mut cfg = RigConfig::default();
    cfg.model.friction.boundary_friction_coefficient = mu_c;
    cfg.rig.load = load;
    cfg.rig.frequency = f;
    cfg.rig.inertia = j;
    cfg.rig.breakaway_factor = 1.3;
    let s = run_cycles(&cfg, cycles as f64, spc).expect("rig runs");
    logged(&format!("rig {load} N {f} Hz J {j}"), &s, noise, offset, seed)
}

/// What a data logger records of rig run `s`: white torque noise of `noise` N·m, `offset` N·m,
/// and the angle on a 17-bit encoder at a random phase (each seed its own pattern).
pub fn logged(name: &str, s: &[Sample], noise: f64, offset: f64, seed: u64) -> Record {
    let mut r = record(name, s, noise, 0.0, offset, seed);
    let shift = ENCODER * SplitMix::new(seed ^ 0xA5A5).uniform();
    r.angle = Some(s.iter().map(|x| ((x.angle + shift) / ENCODER).round() * ENCODER).collect());
    r
}
