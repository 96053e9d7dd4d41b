//! `pinjoint cycle`, streamed: each sample is written to the CSV as soon as it is computed,
//! the paper's averages are accumulated on the way, and only a bounded, evenly strided
//! subset of the samples is kept for the plots. Memory is then independent of the number of
//! strokes; a progress bar shows on long runs when standard error is a terminal.
//!
//! With at most [`PLOT_SAMPLES`] samples (e.g. 50 strokes at 2000 a stroke) every sample is
//! kept and everything (CSV, plots, averages) is what [`CycleRun::simulate`] gives, bit for
//! bit: the averages are the same trapezoidal sums in the same order.

use crate::common::csv_io;
use crate::rig_run::{sample_fields, CycleRun, CYCLE_COLUMNS};
use crate::error::{CliError, Result};
use indicatif::{ProgressBar, ProgressStyle};
use pinjoint::rig::{RigConfig, RigSim, Sample};
use std::io::Write;

/// Most samples kept for the plots (every `stride`-th sample beyond that).
pub const PLOT_SAMPLES: usize = 100_000;
/// Runs with at least this many samples show a progress bar (on a terminal).
const PROGRESS_SAMPLES: usize = 200_000;

/// Trapezoidal sums over the averaged window, in sample order (as `time_mean` and
/// `cycle_average_friction_coefficient` form them).
#[derive(Default)]
struct Sums {
    prev: Option<Sample>,
    torque: f64,
    load: f64,
    span: f64,
    speed: f64,
    speed2: f64,
}

impl Sums {
    fn add(&mut self, s: &Sample) {
        if let Some(p) = self.prev {
            let dt = s.time - p.time;
            self.torque += 0.5 * dt * (p.torque.abs() + s.torque.abs());
            self.load += 0.5 * dt * (p.load + s.load);
            self.speed += 0.5 * dt * (p.angular_velocity.abs() + s.angular_velocity.abs());
            self.speed2 += 0.5 * dt * (p.angular_velocity * p.angular_velocity + s.angular_velocity * s.angular_velocity);
            self.span += dt;
        }
        self.prev = Some(*s);
    }
}

/// Simulate `cycles` strokes of `sim` (at rest at t = 0, fidelity already set), writing every
/// sample as a CSV row into `w`; returns the run with the averages over strokes after `skip`
/// and the samples kept for the plots.
pub fn stream_cycles(
    sim: &mut RigSim,
    config: &RigConfig,
    (cycles, per_cycle, skip): (usize, usize, usize),
    w: &mut dyn Write,
) -> Result<CycleRun> {
    let period = config.rig.period();
    let (t0, interval) = (sim.time(), period / per_cycle as f64);
    let t_end = cycles as f64 * period;
    let n = ((t_end - t0) / interval + 1e-9).floor() as usize;
    let stride = (n + 1).div_ceil(PLOT_SAMPLES).max(1);
    // The averaged window, as `cycle_average_friction_coefficient` and `CycleRun::window` bound it.
    let t_last = t0 + n as f64 * interval;
    let tol = 1e-9 * period;
    let (w0, w1) = (skip as f64 * period, cycles as f64 * period);
    let avg_cycles = ((t_last + tol) / period).floor() - skip as f64;
    let avg_end = w0 + avg_cycles * period;
    let inputs = sim.inputs();
    let bar = if n + 1 >= PROGRESS_SAMPLES { ProgressBar::new(n as u64 + 1) } else { ProgressBar::hidden() };
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} samples, {per_sec}, eta {eta}").expect("valid template"));
    let mut wtr = csv::Writer::from_writer(w);
    let io = |e: csv::Error| CliError::Invalid(format!("writing cycle.csv: {}", csv_io(e)));
    wtr.write_record(CYCLE_COLUMNS).map_err(io)?;
    let (mut avg, mut speeds) = (Sums::default(), Sums::default());
    let mut kept = Vec::with_capacity((n / stride + 2).min(PLOT_SAMPLES + 2));
    for k in 0..=n {
        if k > 0 {
            sim.advance_to(t0 + k as f64 * interval, &inputs)?;
        }
        let s = sim.sample()?;
        wtr.write_record(sample_fields(&s)).map_err(io)?;
        if avg_cycles >= 1.0 && s.time >= w0 - tol && s.time <= avg_end + tol {
            avg.add(&s);
        }
        if s.time >= w0 - tol && s.time <= w1 + tol {
            speeds.add(&s);
        }
        if k % stride == 0 || k == n {
            kept.push(s);
        }
        if k % 4096 == 0 {
            bar.set_position(k as u64);
        }
    }
    wtr.flush().map_err(|e| CliError::Invalid(format!("writing cycle.csv: {e}")))?;
    bar.finish_and_clear();
    let r = config.model.geometry.pin_radius;
    let average_friction_coefficient = if avg.prev.is_some() && avg.load > 0.0 && avg.span > 0.0 {
        avg.torque / avg.span / (r * avg.load / avg.span)
    } else {
        f64::NAN
    };
    let (mean_speed, rms_speed) =
        if speeds.span > 0.0 { (speeds.speed / speeds.span, (speeds.speed2 / speeds.span).sqrt()) } else { (f64::NAN, f64::NAN) };
    Ok(CycleRun { config: *config, cycles, skip, samples: kept, average_friction_coefficient, mean_speed, rms_speed })
}
