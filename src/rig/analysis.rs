//! What the paper computes from a torque record (the cycle average of eq. 11, time means), what
//! a perfect rig would record (the core's quasi-static torque and stroke average), and the
//! energy balance.

use super::config::RigConfig;
use super::sim::{RigSim, Sample};
use super::RigError;
use crate::{Joint, ModelError};
use std::borrow::Borrow;
use std::f64::consts::TAU;

/// The paper's cycle-average friction coefficient (section 5 with eq. 11): the mean of |torque|
/// over whole cycles, divided by R·P. Cycles are counted from t = 0 at `frequency`; the first
/// `skip_cycles` are left out (start-up transient); the window ends at the last whole cycle in
/// the record. The mean is the trapezoidal time average of the samples in the window, and P is
/// the time-averaged load there. None if no whole cycle remains or the load is zero.
pub fn cycle_average_friction_coefficient(samples: &[Sample], frequency: f64, pin_radius: f64, skip_cycles: usize) -> Option<f64> {
    let period = 1.0 / frequency;
    let t_last = samples.last()?.time;
    let start = skip_cycles as f64 * period;
    let cycles = ((t_last + 1e-9 * period) / period).floor() - skip_cycles as f64;
    if cycles < 1.0 {
        return None;
    }
    let end = start + cycles * period;
    let tol = 1e-9 * period;
    let w: Vec<&Sample> = samples.iter().filter(|s| s.time >= start - tol && s.time <= end + tol).collect();
    if w.len() < 2 {
        return None;
    }
    let (torque, span) = trapezoid(&w, |s| s.torque.abs());
    let (load, _) = trapezoid(&w, |s| s.load);
    (load > 0.0).then(|| torque / span / (pin_radius * load / span))
}

/// The trapezoidal integral ∫f dt over consecutive samples, and the time ∫dt it spans.
fn trapezoid<S: Borrow<Sample>>(samples: &[S], f: impl Fn(&Sample) -> f64) -> (f64, f64) {
    let (mut sum, mut span) = (0.0, 0.0);
    for p in samples.windows(2) {
        let (a, b) = (p[0].borrow(), p[1].borrow());
        let dt = b.time - a.time;
        sum += 0.5 * dt * (f(a) + f(b));
        span += dt;
    }
    (sum, span)
}

/// Trapezoidal time-mean of `f` over consecutive samples: ∫f dt / ∫dt between the first and
/// the last sample's times (NaN if they span no time, as with fewer than two samples).
pub fn time_mean<S: Borrow<Sample>>(samples: &[S], f: impl Fn(&Sample) -> f64) -> f64 {
    let (sum, span) = trapezoid(samples, f);
    if span > 0.0 { sum / span } else { f64::NAN }
}

/// The core's μ(P, |θ̇_cmd(t)|) (eq. 10) averaged over a sine stroke θ_cmd = A·sin(2πft)
/// (midpoint rule, 512 points a stroke; `amplitude` A in rad, `frequency` f in Hz, `load` P in
/// N): the cycle average of eq. 11 for a rig that follows its command exactly and never sticks.
pub fn stroke_average(joint: &Joint, load: f64, frequency: f64, amplitude: f64) -> Result<f64, ModelError> {
    const N: usize = 512;
    let peak = TAU * frequency * amplitude;
    let mut sum = 0.0;
    for k in 0..N {
        let phase = TAU * (k as f64 + 0.5) / N as f64;
        sum += joint.evaluate(load, (peak * phase.cos()).abs())?.friction_coefficient;
    }
    Ok(sum / N as f64)
}

/// The core's quasi-static friction torque at a sample's speed, signed like the recorded
/// torque: sign ω · μ(P, |ω|) · R · P (eq. 11's T_f, in N·m, with `pin_radius` R in m); NaN
/// while stuck (no speed to evaluate at).
pub fn core_torque(s: &Sample, pin_radius: f64) -> f64 {
    if s.stuck || s.angular_velocity == 0.0 {
        f64::NAN
    } else {
        s.angular_velocity.signum() * s.friction_coefficient * pin_radius * s.load
    }
}

/// Energy balance residual between two samples: actuator work − friction dissipation − change of
/// kinetic energy (J). Zero for the exact solution.
pub fn energy_residual(from: &Sample, to: &Sample) -> f64 {
    (to.actuator_work - from.actuator_work) - (to.friction_dissipation - from.friction_dissipation) - (to.kinetic_energy - from.kinetic_energy)
}

/// `cycles` strokes of the configured rig from rest, `samples_per_cycle` samples a cycle
/// (t = 0 included).
pub fn run_cycles(config: &RigConfig, cycles: f64, samples_per_cycle: usize) -> Result<Vec<Sample>, RigError> {
    let mut sim = RigSim::new(config)?;
    let period = config.rig.period();
    sim.run(cycles * period, period / samples_per_cycle as f64)
}
