//! What the paper computes from a torque record, and the energy balance.

use super::config::RigConfig;
use super::sim::{RigSim, Sample};
use super::RigError;

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
    let (mut torque, mut load, mut span) = (0.0, 0.0, 0.0);
    for p in w.windows(2) {
        let dt = p[1].time - p[0].time;
        torque += 0.5 * dt * (p[0].torque.abs() + p[1].torque.abs());
        load += 0.5 * dt * (p[0].load + p[1].load);
        span += dt;
    }
    (load > 0.0).then(|| torque / span / (pin_radius * load / span))
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
