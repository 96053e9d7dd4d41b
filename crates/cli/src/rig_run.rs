//! One rig simulation as the commands use it (`cycle`, `figures`): run whole strokes, the
//! paper's cycle-average friction coefficient (eq. 11) and the cycle's characteristic speeds,
//! the quasi-static core values to compare with, and the trace as CSV. The analysis itself
//! (time means, the stroke average, the core's torque) is the library's ([`pinjoint::rig`]);
//! [`crate::rig_plots`] draws a run.

use crate::common::exact;
use crate::error::Result;
use pinjoint::rig::{cycle_average_friction_coefficient, run_cycles, stroke_average, time_mean, RigConfig, Sample};
use pinjoint::Joint;
use std::f64::consts::TAU;

/// The columns of `cycle.csv` (SI units: s, rad, rad, rad/s, N·m, N·m, -, m, -, 0/1).
pub const CYCLE_COLUMNS: [&str; 10] = pinjoint::rig::record::COLUMNS;

/// A finished rig run of whole strokes and what the paper computes from it.
#[derive(Debug, Clone)]
pub struct CycleRun {
    /// Model and rig parameters of the run (frequency, amplitude, load, solver).
    pub config: RigConfig,
    /// Strokes simulated (from rest at t = 0).
    pub cycles: usize,
    /// Strokes left out of the averages (start-up transient).
    pub skip: usize,
    /// Samples kept for the plots: all of them, or every k-th of a long run that `pinjoint
    /// cycle` streamed (every sample went to its cycle.csv).
    pub samples: Vec<Sample>,
    /// Eq. 11: mean |recorded torque| over cycles skip+1..=cycles, divided by R·P.
    pub average_friction_coefficient: f64,
    /// Time-mean of |ω| over the same cycles (rad/s): the characteristic speed of Figures 8, 9.
    pub mean_speed: f64,
    /// Root mean square of ω over the same cycles (rad/s).
    pub rms_speed: f64,
}

/// The default number of start-up strokes left out: the first when there is more than one.
pub fn default_skip(cycles: usize) -> usize {
    usize::from(cycles >= 2)
}

impl CycleRun {
    /// Simulate `cycles` strokes of `config` with `samples_per_cycle` samples each and average
    /// over the strokes after the first `skip` (which must be < `cycles`).
    pub fn simulate(config: &RigConfig, cycles: usize, samples_per_cycle: usize, skip: usize) -> Result<Self> {
        let samples = run_cycles(config, cycles as f64, samples_per_cycle)?;
        Self::from_samples(config, cycles, skip, samples)
    }

    fn from_samples(config: &RigConfig, cycles: usize, skip: usize, samples: Vec<Sample>) -> Result<Self> {
        debug_assert!(skip < cycles);
        let (f, r) = (config.rig.frequency, config.model.geometry.pin_radius);
        let average_friction_coefficient = cycle_average_friction_coefficient(&samples, f, r, skip).unwrap_or(f64::NAN);
        let mut run = Self { config: *config, cycles, skip, samples, average_friction_coefficient, mean_speed: f64::NAN, rms_speed: f64::NAN };
        let w = run.window();
        let (mean, rms) = (time_mean(w, |s| s.angular_velocity.abs()), time_mean(w, |s| s.angular_velocity * s.angular_velocity).sqrt());
        (run.mean_speed, run.rms_speed) = (mean, rms);
        Ok(run)
    }

    /// Stroke period 1/f, in s.
    pub fn period(&self) -> f64 {
        self.config.rig.period()
    }

    /// The samples of the averaged cycles (both ends included).
    pub fn window(&self) -> &[Sample] {
        let p = self.period();
        let (t0, t1) = (self.skip as f64 * p, self.cycles as f64 * p);
        let tol = 1e-9 * p;
        let a = self.samples.partition_point(|s| s.time < t0 - tol);
        let b = self.samples.partition_point(|s| s.time <= t1 + tol);
        &self.samples[a..b]
    }

    /// Peak speed of the command, 2π f A (rad/s).
    pub fn peak_command_speed(&self) -> f64 {
        TAU * self.config.rig.frequency * self.config.rig.amplitude
    }

    /// Radial load P on the pin, in N.
    pub fn load(&self) -> f64 {
        self.config.rig.load
    }

    /// The core's μ(P, ω) at the stroke's peak speed: the lowest friction a quasi-static stroke
    /// reaches (mid-stroke).
    pub fn quasi_static_at_peak(&self, joint: &Joint) -> Result<f64> {
        Ok(joint.evaluate(self.load(), self.peak_command_speed())?.friction_coefficient)
    }

    /// What eq. 11 gives for a perfect rig: [`stroke_average`] at this run's load and stroke.
    pub fn quasi_static_average(&self, joint: &Joint) -> Result<f64> {
        Ok(stroke_average(joint, self.load(), self.config.rig.frequency, self.config.rig.amplitude)?)
    }
}

/// One sample as the CSV fields of [`CYCLE_COLUMNS`], in full precision.
pub fn sample_fields(s: &Sample) -> [String; 10] {
    let mut out: [String; 10] = Default::default();
    for (slot, (_, _, f)) in out.iter_mut().zip(pinjoint::rig::record::NUMERIC_COLUMNS) {
        *slot = exact(f(s));
    }
    out[9] = u8::from(s.stuck).to_string();
    out
}

