//! The rig side of `pinjoint figures`: the paper's 15 test conditions (loads 5–60 kN ×
//! 0.03, 0.3, 1 Hz, ±40°) simulated in parallel, what the paper reads from each (eq. 11
//! average, characteristic speeds), and the measures the captions quote (flatness of the
//! slow stroke, mid-stroke dip, servo oscillation).

use crate::common::{csv_table, exact};
use crate::rig_run::{sample_fields, CycleRun, CYCLE_COLUMNS};
use pinjoint::rig::core_torque;
use crate::error::Result;
use pinjoint::paper::LOADS as PAPER_LOADS;
use indicatif::ProgressBar;
use pinjoint::rig::{RigConfig, Sample};
use pinjoint::Joint;
use rayon::prelude::*;

/// The paper's stroke frequencies (section 4.4), Hz.
pub const PAPER_FREQUENCIES: [f64; 3] = pinjoint::paper::FREQUENCIES;
/// Strokes per run: the first (from rest) is left out of every average and plot.
pub const CYCLES: usize = 2;
/// Strokes left out of the averages at the start of each run (the one from rest).
pub const SKIP: usize = 1;

/// How finely the rig runs are resolved.
#[derive(Debug, Clone, Copy)]
pub struct RigSettings {
    /// Output samples per stroke.
    pub samples_per_cycle: usize,
    /// Relative tolerance of the rig's adaptive ODE solver.
    pub rtol: f64,
    /// Absolute tolerance of the rig's adaptive ODE solver.
    pub atol: f64,
}

impl RigSettings {
    /// The full run: 2000 samples a stroke (0.5 ms at 1 Hz, 16 per period of the 78 Hz servo
    /// ringing) and the rig's default tolerances (Dopri5, rtol 1e-8, atol 1e-9).
    pub fn full() -> Self {
        let d = RigConfig::default().rig;
        Self { samples_per_cycle: 2000, rtol: d.rtol, atol: d.atol }
    }
    /// `--quick`: 400 samples a stroke, rtol 1e-6, atol 1e-7.
    pub fn quick() -> Self {
        Self { samples_per_cycle: 400, rtol: 1e-6, atol: 1e-7 }
    }
}

/// One test condition's run and what is read from it.
#[derive(Debug, Clone)]
pub struct RigResult {
    /// The simulated strokes.
    pub run: CycleRun,
    /// The core's Sommerfeld number at the run's mean |ω| (eq. 20).
    pub sommerfeld: f64,
    /// The core's μ(P, |θ̇_cmd(t)|) averaged over a stroke: eq. 11 for a perfect rig.
    pub quasi_static_average: f64,
    /// The core's μ at the command's peak speed 2πfA.
    pub quasi_static_peak: f64,
    /// Measures of the recorded torque over the averaged stroke.
    pub shape: StrokeShape,
}

/// Measures of the torque over the averaged stroke(s).
#[derive(Debug, Clone, Copy, Default)]
pub struct StrokeShape {
    /// Mean |T| where |θ| < 5 % of A (mid-stroke, peak speed), N·m.
    pub mid_torque: f64,
    /// Mean |T| where 70 % < |θ|/A < 80 % (towards the stroke ends, past the reversal), N·m.
    pub outer_torque: f64,
    /// The same two means of the core's quasi-static torque μ(P, |ω|)·R·P at those samples.
    pub mid_core: f64,
    /// The core's quasi-static torque averaged like `outer_torque`, N·m.
    pub outer_core: f64,
    /// Fraction of the time stuck (at the reversals).
    pub stuck_fraction: f64,
    /// (max − min)/mean of |T| in slip where |θ| < 80 % of A.
    pub spread: f64,
    /// Largest |T − core torque| in slip within 0.2 s after a reversal or breakaway, N·m.
    pub ringing: f64,
    /// Largest |T − core torque| in slip later than 0.2 s after one, N·m.
    pub settled: f64,
    /// Largest |θ − θ_cmd| over the averaged stroke(s), degrees.
    pub tracking_error_deg: f64,
}

impl StrokeShape {
    /// The mid-stroke dip relative to the torque towards the stroke ends.
    pub fn dip(&self) -> f64 {
        (self.outer_torque - self.mid_torque) / self.outer_torque
    }

    /// Measures the averaged strokes of `run`.
    pub fn of(run: &CycleRun) -> Self {
        let a = run.config.rig.amplitude;
        let r = run.config.model.geometry.pin_radius;
        let w = run.window();
        let mean_abs = |keep: &dyn Fn(&Sample) -> bool, value: &dyn Fn(&Sample) -> f64| {
            let v: Vec<f64> = w.iter().filter(|s| !s.stuck && keep(s)).map(|s| value(s).abs()).collect();
            v.iter().sum::<f64>() / v.len() as f64
        };
        let mid = |s: &Sample| s.angle.abs() < 0.05 * a;
        let outer = |s: &Sample| (0.7 * a..0.8 * a).contains(&s.angle.abs());
        let (recorded, core) = (|s: &Sample| s.torque, |s: &Sample| core_torque(s, r));
        let (mid_torque, outer_torque) = (mean_abs(&mid, &recorded), mean_abs(&outer, &recorded));
        let (mid_core, outer_core) = (mean_abs(&mid, &core), mean_abs(&outer, &core));
        let stuck_fraction = w.iter().filter(|s| s.stuck).count() as f64 / w.len() as f64;
        let inner: Vec<f64> = w.iter().filter(|s| !s.stuck && s.angle.abs() < 0.8 * a).map(|s| s.torque.abs()).collect();
        let (lo, hi) = inner.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| (l.min(v), h.max(v)));
        let spread = (hi - lo) / (inner.iter().sum::<f64>() / inner.len() as f64);
        // Time since the joint last started to slide (a breakaway, or a reversal through ω = 0).
        let (mut ringing, mut settled): (f64, f64) = (0.0, 0.0);
        let mut start = f64::NEG_INFINITY;
        let mut prev: Option<&Sample> = None;
        for s in w {
            if let Some(p) = prev
                && (p.stuck || p.angular_velocity.signum() != s.angular_velocity.signum())
            {
                start = p.time;
            }
            if !s.stuck {
                let d = (s.torque - core_torque(s, r)).abs();
                if d.is_finite() {
                    if s.time - start < 0.2 { ringing = ringing.max(d) } else { settled = settled.max(d) }
                }
            }
            prev = Some(s);
        }
        let tracking = w.iter().map(|s| (s.angle - s.command_angle).abs()).fold(0.0, f64::max);
        Self {
            mid_torque,
            outer_torque,
            mid_core,
            outer_core,
            stuck_fraction,
            spread,
            ringing,
            settled,
            tracking_error_deg: tracking.to_degrees(),
        }
    }
}

/// Every (frequency, load) of the paper, frequency-major: 0.03 Hz at 5…60 kN, then 0.3 Hz, 1 Hz.
pub fn conditions() -> Vec<(f64, f64)> {
    PAPER_FREQUENCIES.iter().flat_map(|&f| PAPER_LOADS.iter().map(move |&p| (f, p))).collect()
}

/// Simulate every condition on every core (rayon), ticking `bar` once per finished run.
pub fn simulate_all(joint: &Joint, base: &RigConfig, settings: RigSettings, bar: &ProgressBar) -> Result<Vec<RigResult>> {
    conditions()
        .par_iter()
        .map(|&(f, p)| {
            let mut cfg = *base;
            cfg.rig.frequency = f;
            cfg.rig.load = p;
            cfg.rig.rtol = settings.rtol;
            cfg.rig.atol = settings.atol;
            let run = CycleRun::simulate(&cfg, CYCLES, settings.samples_per_cycle, SKIP)?;
            let result = RigResult {
                sommerfeld: joint.evaluate(p, run.mean_speed)?.sommerfeld_number,
                quasi_static_average: run.quasi_static_average(joint)?,
                quasi_static_peak: run.quasi_static_at_peak(joint)?,
                shape: StrokeShape::of(&run),
                run,
            };
            bar.inc(1);
            Ok(result)
        })
        .collect()
}

/// The runs at one frequency, in load order.
pub fn at_frequency(results: &[RigResult], f: f64) -> Vec<&RigResult> {
    results.iter().filter(|r| r.run.config.rig.frequency == f).collect()
}

/// The run at one frequency and load.
pub fn find(results: &[RigResult], f: f64, load: f64) -> Option<&RigResult> {
    results.iter().find(|r| r.run.config.rig.frequency == f && r.run.load() == load)
}

/// The columns of `rig_averages.csv` (SI units; see the figures' README for each).
pub const AVERAGE_COLUMNS: [&str; 18] = [
    "frequency",
    "load",
    "amplitude",
    "cycle_average_friction_coefficient",
    "mean_speed",
    "rms_speed",
    "peak_command_speed",
    "sliding_speed",
    "sommerfeld_number",
    "paper_nominal_rpm",
    "quasi_static_average_friction_coefficient",
    "quasi_static_peak_friction_coefficient",
    "mid_stroke_torque",
    "outer_stroke_torque",
    "reversal_ringing_torque",
    "settled_deviation_torque",
    "max_tracking_error_deg",
    "stuck_fraction",
];

/// One row per run: what Figures 8–10 plot and the captions quote.
pub fn averages_csv(w: &mut dyn std::io::Write, results: &[RigResult]) -> std::io::Result<()> {
    let rows = results.iter().map(|r| {
        let (c, s) = (&r.run.config, &r.shape);
        [
            c.rig.frequency,
            c.rig.load,
            c.rig.amplitude,
            r.run.average_friction_coefficient,
            r.run.mean_speed,
            r.run.rms_speed,
            r.run.peak_command_speed(),
            r.run.mean_speed * c.model.geometry.pin_radius,
            r.sommerfeld,
            60.0 * c.rig.frequency,
            r.quasi_static_average,
            r.quasi_static_peak,
            s.mid_torque,
            s.outer_torque,
            s.ringing,
            s.settled,
            s.tracking_error_deg,
            s.stuck_fraction,
        ]
        .map(exact)
    });
    csv_table(w, AVERAGE_COLUMNS, rows)
}

/// The averaged stroke(s) of several runs in one CSV: load, time since the stroke began
/// (cycle_time), then the columns of `cycle.csv`.
pub fn traces_csv(w: &mut dyn std::io::Write, runs: &[&CycleRun]) -> std::io::Result<()> {
    let rows = runs.iter().flat_map(|run| {
        let t0 = run.skip as f64 * run.period();
        run.window().iter().map(move |s| [exact(run.load()), exact(s.time - t0)].into_iter().chain(sample_fields(s)))
    });
    csv_table(w, ["load", "cycle_time"].into_iter().chain(CYCLE_COLUMNS), rows)
}
