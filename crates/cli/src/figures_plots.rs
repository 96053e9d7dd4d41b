//! The rig figures of `pinjoint figures`: Figure 7 (one 1 Hz stroke), Figures 8–10 (eq. 11
//! averages against Sommerfeld number, sliding speed and load, with the core's curves) and
//! Figures 11–13 (torque against time at 0.03, 0.3 and 1 Hz).

use super::common::{log_space, readable, lin_space};
use super::cycle_run::stroke_average;
use super::cycle_plots::{overview_svg, run_label, torque_time_chart};
use super::error::Result;
use super::figures_rig::{at_frequency, RigResult, PAPER_FREQUENCIES};
use super::map::PAPER_LOADS;
use crate::plot::{line_plot, stacked_plot, Axis, Chart, Corner, Series, Style};
use pinjoint::Joint;
use rayon::prelude::*;

/// The paper's measured friction coefficient at low speed (section 5).
pub const PAPER_LOW_SPEED_MU: f64 = 0.117;

/// Speeds of the core's steady curves in Figures 8 and 9 (rad/s): a factor of 4 below and 3
/// above the rig runs' mean speeds (0.08 to 2.8 rad/s).
pub const CURVE_SPEEDS: (f64, f64) = (0.02, 8.0);

/// The core's steady μ(P, ω) at the paper's loads, for Figures 8 and 9.
#[derive(Debug, Clone)]
pub struct CoreCurves {
    /// One curve per load of `PAPER_LOADS`: (speed, Sommerfeld number, μ).
    pub curves: Vec<Vec<(f64, f64, f64)>>,
    /// Loads (N) and, per frequency, the core's stroke-average μ at each load (Figure 10).
    pub loads: Vec<f64>,
    pub stroke_averages: Vec<Vec<f64>>,
}

impl CoreCurves {
    pub fn compute(joint: &Joint, amplitude: f64, points: usize) -> Result<Self> {
        let speeds = log_space(CURVE_SPEEDS.0, CURVE_SPEEDS.1, points);
        let curves = PAPER_LOADS
            .iter()
            .map(|&p| {
                speeds
                    .par_iter()
                    .map(|&w| joint.evaluate(p, w).map(|o| (w, o.sommerfeld_number, o.friction_coefficient)).map_err(Into::into))
                    .collect::<Result<Vec<_>>>()
            })
            .collect::<Result<Vec<_>>>()?;
        let loads = lin_space(PAPER_LOADS[0], PAPER_LOADS[PAPER_LOADS.len() - 1], points.clamp(6, 23));
        let stroke_averages = PAPER_FREQUENCIES
            .iter()
            .map(|&f| loads.par_iter().map(|&p| stroke_average(joint, p, f, amplitude)).collect::<Result<Vec<_>>>())
            .collect::<Result<Vec<_>>>()?;
        Ok(Self { curves, loads, stroke_averages })
    }
}

fn kn(p: f64) -> String {
    format!("{} kN", readable(p / 1e3))
}

/// A horizontal dashed reference line at the paper's measured low-speed μ.
fn paper_line(x0: f64, x1: f64) -> Series {
    Series::line(format!("paper: measured low-speed μ = {PAPER_LOW_SPEED_MU}"), vec![(x0, PAPER_LOW_SPEED_MU), (x1, PAPER_LOW_SPEED_MU)])
        .styled(Style::Dashed)
        .coloured(7)
}

/// Figures 8 and 9: lines the core's steady μ against `x` (Sommerfeld number or sliding speed),
/// one per load; dots the rig's eq. 11 averages at the runs' mean |ω|.
fn averages_against(
    results: &[RigResult],
    core: &CoreCurves,
    title: &str,
    x: Axis,
    curve_x: impl Fn(f64, f64) -> f64,
    run_x: impl Fn(&RigResult) -> f64,
) -> Result<String> {
    let mut chart = Chart::new(title, x, Axis::linear("friction coefficient μ [-]")).legend(Corner::LowerLeft);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, (&p, curve)) in PAPER_LOADS.iter().zip(&core.curves).enumerate() {
        let pts: Vec<(f64, f64)> = curve.iter().map(|&(w, s, mu)| (curve_x(w, s), mu)).collect();
        lo = lo.min(pts[0].0);
        hi = hi.max(pts[pts.len() - 1].0);
        chart = chart.series(Series::line(format!("{}: core μ(P, ω)", kn(p)), pts).coloured(i));
        let dots: Vec<(f64, f64)> =
            results.iter().filter(|r| r.run.load() == p).map(|r| (run_x(r), r.run.average_friction_coefficient)).collect();
        chart = chart.series(Series::line("", dots).styled(Style::Points).coloured(i));
    }
    chart = chart.series(paper_line(lo, hi));
    Ok(line_plot(&chart, (1000, 650))?)
}

/// Figure 8: μ against the Sommerfeld number (eq. 20) at the runs' mean |ω|.
pub fn fig8_svg(results: &[RigResult], core: &CoreCurves) -> Result<String> {
    averages_against(
        results,
        core,
        "Fig. 8: friction coefficient against Sommerfeld number (lines: core; dots: rig, eq. 11, at mean |ω|)",
        Axis::log("Sommerfeld number S (eq. 20, at the stroke's mean |ω|) [-]"),
        |_, s| s,
        |r| r.sommerfeld,
    )
}

/// Figure 9: μ against the sliding speed u = R·mean|ω|.
pub fn fig9_svg(results: &[RigResult], core: &CoreCurves, pin_radius: f64) -> Result<String> {
    averages_against(
        results,
        core,
        "Fig. 9: friction coefficient against sliding speed (lines: core; dots: rig, eq. 11)",
        Axis::log("sliding speed u = R·mean|ω| [m/s]"),
        |w, _| w * pin_radius,
        |r| r.run.mean_speed * pin_radius,
    )
}

/// Figure 10: μ against load, one line of rig averages per frequency, the core's stroke
/// average dashed.
pub fn fig10_svg(results: &[RigResult], core: &CoreCurves) -> Result<String> {
    let mut chart = Chart::new(
        "Fig. 10: friction coefficient against load (solid: rig, eq. 11; dashed: core's stroke average)",
        Axis::linear("load P_T [kN]"),
        Axis::linear("friction coefficient μ [-]"),
    )
    .legend(Corner::LowerRight);
    for (j, &f) in PAPER_FREQUENCIES.iter().enumerate() {
        let pts = at_frequency(results, f).iter().map(|r| (r.run.load() / 1e3, r.run.average_friction_coefficient)).collect();
        chart = chart.series(Series::line(format!("{} Hz rig", readable(f)), pts).styled(Style::LinePoints).coloured(j));
        let core_pts = core.loads.iter().zip(&core.stroke_averages[j]).map(|(&p, &mu)| (p / 1e3, mu)).collect();
        chart = chart.series(Series::line(format!("{} Hz core", readable(f)), core_pts).styled(Style::Dashed).coloured(j));
    }
    let (x0, x1) = (PAPER_LOADS[0] / 1e3, PAPER_LOADS[PAPER_LOADS.len() - 1] / 1e3);
    chart = chart.series(paper_line(x0, x1));
    Ok(line_plot(&chart, (1000, 650))?)
}

/// Figures 11–13 at frequency `f`: (a) the averaged stroke at every load, (b) the run at
/// `detail_load` with the core's quasi-static torque beside it.
pub fn torque_cycle_svg(results: &[RigResult], f: f64, detail_load: f64, figure: u32) -> Result<String> {
    let runs = at_frequency(results, f);
    let mut all = Chart::new("(a) recorded torque over one stroke at the paper's loads", Axis::linear("time in the stroke [s]"), Axis::linear("torque [N·m]"))
        .legend(Corner::LowerLeft);
    for (i, r) in runs.iter().enumerate() {
        let t0 = r.run.skip as f64 * r.run.period();
        let pts = r.run.window().iter().map(|s| (s.time - t0, s.torque)).collect();
        all = all.series(Series::line(kn(r.run.load()), pts).coloured(i));
    }
    let mut charts = vec![all];
    if let Some(r) = runs.iter().find(|r| r.run.load() == detail_load) {
        let t0 = r.run.skip as f64 * r.run.period();
        let title = format!("(b) {}: recorded torque and the core's quasi-static torque", run_label(&r.run));
        charts.push(torque_time_chart(&r.run, r.run.window(), t0, &title));
    }
    let title = format!("Fig. {figure}: frictional torque against time at f = {} Hz ({} rpm nominal), ±40°", readable(f), readable(60.0 * f));
    Ok(stacked_plot(&title, &charts, (1000, 1100))?)
}

/// Figure 7 from the averaged stroke of one run.
pub fn fig7_svg(r: &RigResult) -> Result<String> {
    let t0 = r.run.skip as f64 * r.run.period();
    let title = format!("Fig. 7: one stroke of the simulated rig, {}", run_label(&r.run));
    overview_svg(&r.run, r.run.window(), t0, &title)
}
