//! What the rig library's test suites (rig_hard.rs, rig_physics.rs) share: the default rig at
//! a frequency and load, and a run of whole strokes.
#![allow(dead_code)]

use pinjoint::rig::{RigConfig, RigSim, Sample};

/// The default rig at `frequency` (Hz) and `load` (N).
pub fn cfg(frequency: f64, load: f64) -> RigConfig {
    let mut c = RigConfig::default();
    c.rig.frequency = frequency;
    c.rig.load = load;
    c
}

/// `cycles` strokes of `c`, sampled `per_cycle` times a stroke: the simulation after the
/// run and its samples.
pub fn run(c: &RigConfig, cycles: f64, per_cycle: usize) -> (RigSim, Vec<Sample>) {
    let mut sim = RigSim::new(c).unwrap();
    let p = c.rig.period();
    let tr = sim.run(cycles * p, p / per_cycle as f64).unwrap();
    (sim, tr)
}
