//! The rig figures of `pinjoint figures`: Figure 7 (one 1 Hz stroke), Figures 8–10 (eq. 11
//! averages against Sommerfeld number, sliding speed and load, with the core's curves) and
//! Figures 11–13 (torque against time at 0.03, 0.3 and 1 Hz).

use crate::common::{lin_space, log_space, readable};
use crate::rig_plots::{overview_svg, run_label, torque_time_chart, RECORDED};
use crate::error::Result;
use super::rig::{at_frequency, RigResult, PAPER_FREQUENCIES};
use pinjoint::paper::LOADS as PAPER_LOADS;
use pinjoint::rig::stroke_average;
use crate::plot::{line_plot, stacked_plot, Axis, Chart, Corner, Series, Style};
use pinjoint::Joint;
use rayon::prelude::*;
use std::f64::consts::TAU;

/// The paper's measured friction coefficient at low speed (section 5).
pub const PAPER_LOW_SPEED_MU: f64 = pinjoint::paper::MEASURED_LOW_SPEED_MU;

/// Frequencies (Hz) of the core's stroke-average curves in Figures 8 and 9: a factor of 3
/// below the paper's slowest stroke and 3 above its fastest.
pub const CURVE_FREQUENCIES: (f64, f64) = (0.01, 3.0);

/// The nominal speed the paper labels a stroke of frequency `f` with: 60·f rpm, i.e.
/// ω = 2π·f rad/s (section 4.4: 0.03 Hz "1.8 rpm", 1 Hz "60 rpm").
pub fn nominal_speed(f: f64) -> f64 {
    TAU * f
}

/// The core's eq. 11 stroke averages: μ(P, |θ̇(t)|) averaged over a sine stroke θ = A·sin(2πft)
/// (`stroke_average`), the way the paper reduced its records, for Figures 8–10.
#[derive(Debug, Clone)]
pub struct CoreCurves {
    /// One curve per load of `PAPER_LOADS`: (frequency, stroke-average μ).
    pub curves: Vec<Vec<(f64, f64)>>,
    /// Per load of `PAPER_LOADS`: the Sommerfeld number (eq. 20) per rad/s; S is
    /// proportional to |ω| at a fixed load (inlet viscosity η0).
    pub s_per_rad_s: Vec<f64>,
    /// Loads (N) of the curves of Figure 10 and, per paper frequency, the stroke average at each.
    pub loads: Vec<f64>,
    /// Per paper frequency, the stroke-average μ at each of `loads` (Figure 10).
    pub stroke_averages: Vec<Vec<f64>>,
    /// The Sommerfeld number per rad/s at each of `loads`.
    pub load_s_per_rad_s: Vec<f64>,
    /// The stroke average at the paper's conditions: `[frequency][load]` over
    /// `PAPER_FREQUENCIES` × `PAPER_LOADS`.
    pub at_paper: Vec<Vec<f64>>,
}

impl CoreCurves {
    /// Computes the curves for strokes of `amplitude` (rad) with `points` frequencies per curve;
    /// fails if the model cannot be evaluated at a point.
    pub fn compute(joint: &Joint, amplitude: f64, points: usize) -> Result<Self> {
        let frequencies = log_space(CURVE_FREQUENCIES.0, CURVE_FREQUENCIES.1, points);
        let curves = PAPER_LOADS
            .iter()
            .map(|&p| {
                frequencies
                    .par_iter()
                    .map(|&f| Ok((f, stroke_average(joint, p, f, amplitude)?)))
                    .collect::<Result<Vec<_>>>()
            })
            .collect::<Result<Vec<_>>>()?;
        let loads = lin_space(PAPER_LOADS[0], PAPER_LOADS[PAPER_LOADS.len() - 1], points.max(12));
        let stroke_averages = PAPER_FREQUENCIES
            .iter()
            .map(|&f| loads.par_iter().map(|&p| Ok(stroke_average(joint, p, f, amplitude)?)).collect::<Result<Vec<_>>>())
            .collect::<Result<Vec<_>>>()?;
        let at_paper = PAPER_FREQUENCIES
            .iter()
            .map(|&f| PAPER_LOADS.iter().map(|&p| Ok(stroke_average(joint, p, f, amplitude)?)).collect::<Result<Vec<_>>>())
            .collect::<Result<Vec<_>>>()?;
        let s_per_rad_s = PAPER_LOADS.iter().map(|&p| Ok(joint.evaluate(p, 1.0)?.sommerfeld_number)).collect::<Result<Vec<_>>>()?;
        let load_s_per_rad_s = loads.iter().map(|&p| Ok(joint.evaluate(p, 1.0)?.sommerfeld_number)).collect::<Result<Vec<_>>>()?;
        Ok(Self { curves, s_per_rad_s, loads, stroke_averages, load_s_per_rad_s, at_paper })
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

/// Figures 8 and 9: per load, the core's stroke-average μ against `x` of the stroke's nominal
/// speed (lines, dots at the paper's frequencies) and the rig simulation's eq. 11 average at
/// the same x (crosses).
/// `curve_x(i, f)` is the x value of a stroke of frequency `f` at load `PAPER_LOADS[i]`.
fn averages_against(results: &[RigResult], core: &CoreCurves, title: &str, x: Axis, curve_x: impl Fn(usize, f64) -> f64) -> Result<String> {
    let mut chart = Chart::new(title, x, Axis::linear("friction coefficient μ = mean|T| / (R·P) [-]")).legend(Corner::LowerLeft);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, (&p, curve)) in PAPER_LOADS.iter().zip(&core.curves).enumerate() {
        let pts: Vec<(f64, f64)> = curve.iter().map(|&(f, mu)| (curve_x(i, f), mu)).collect();
        lo = lo.min(pts[0].0);
        hi = hi.max(pts[pts.len() - 1].0);
        chart = chart.series(Series::line(format!("{}: model, eq. 11 over the stroke", kn(p)), pts).coloured(i));
        let dots: Vec<(f64, f64)> = PAPER_FREQUENCIES.iter().zip(&core.at_paper).map(|(&f, row)| (curve_x(i, f), row[i])).collect();
        chart = chart.series(Series::line("", dots).styled(Style::Points).coloured(i));
    }
    for (i, &p) in PAPER_LOADS.iter().enumerate() {
        let rig: Vec<(f64, f64)> = results
            .iter()
            .filter(|r| r.run.load() == p)
            .map(|r| {
                let f = r.run.config.rig.frequency;
                (curve_x(i, f), r.run.average_friction_coefficient)
            })
            .collect();
        let name = if i == 0 { "×: rig simulation, eq. 11 of the recorded torque (load's colour)" } else { "" };
        chart = chart.series(Series::line(name, rig).styled(Style::Crosses).coloured(i));
    }
    chart = chart.series(paper_line(lo, hi));
    Ok(line_plot(&chart, (1000, 650))?)
}

/// Figure 8: μ against the Sommerfeld number (eq. 20) at the paper's nominal speed 2πf.
pub fn fig8_svg(results: &[RigResult], core: &CoreCurves) -> Result<String> {
    averages_against(
        results,
        core,
        "Fig. 8: friction coefficient against Sommerfeld number (dots: 0.03, 0.3, 1 Hz)",
        Axis::log("Sommerfeld number S (eq. 20) at the nominal speed ω = 2πf (60·f rpm) [-]"),
        |i, f| core.s_per_rad_s[i] * nominal_speed(f),
    )
}

/// Figure 9: μ against the nominal sliding speed u = R·2πf.
pub fn fig9_svg(results: &[RigResult], core: &CoreCurves, pin_radius: f64) -> Result<String> {
    averages_against(
        results,
        core,
        "Fig. 9: friction coefficient against sliding speed (dots: 0.03, 0.3, 1 Hz)",
        Axis::log("sliding speed u = R·2πf at the nominal speed (60·f rpm) [m/s]"),
        |_, f| pin_radius * nominal_speed(f),
    )
}

/// Figure 10: μ against load, per frequency the core's stroke average (solid) and the rig
/// simulation's eq. 11 average (dashed with crosses).
pub fn fig10_svg(results: &[RigResult], core: &CoreCurves) -> Result<String> {
    let mut chart = Chart::new(
        "Fig. 10: friction coefficient against load (solid: model, eq. 11 over the stroke; ×: rig simulation)",
        Axis::linear("load P_T [kN]"),
        Axis::linear("friction coefficient μ = mean|T| / (R·P) [-]"),
    )
    .legend(Corner::LowerRight);
    for (j, &f) in PAPER_FREQUENCIES.iter().enumerate() {
        let core_pts = core.loads.iter().zip(&core.stroke_averages[j]).map(|(&p, &mu)| (p / 1e3, mu)).collect();
        chart = chart.series(Series::line(format!("{} Hz: model, eq. 11 over the stroke", readable(f)), core_pts).coloured(j));
        let dots = PAPER_LOADS.iter().zip(&core.at_paper[j]).map(|(&p, &mu)| (p / 1e3, mu)).collect();
        chart = chart.series(Series::line("", dots).styled(Style::Points).coloured(j));
        let pts: Vec<(f64, f64)> = at_frequency(results, f).iter().map(|r| (r.run.load() / 1e3, r.run.average_friction_coefficient)).collect();
        chart = chart.series(Series::line(format!("{} Hz: rig simulation", readable(f)), pts.clone()).styled(Style::Dashed).coloured(j));
        chart = chart.series(Series::line("", pts).styled(Style::Crosses).coloured(j));
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
        let name = if f >= 1.0 { "recorded torque (the ringing after each breakaway is the servo's)" } else { RECORDED };
        charts.push(torque_time_chart(&r.run, r.run.window(), t0, &title, name));
    }
    let title = format!("Fig. {figure}: frictional torque against time at f = {} Hz ({} rpm nominal), ±40°", readable(f), readable(60.0 * f));
    Ok(stacked_plot(&title, &charts, (1000, 1100))?)
}

/// Figure 7 from the averaged stroke of one run.
pub fn fig7_svg(r: &RigResult) -> Result<String> {
    let t0 = r.run.skip as f64 * r.run.period();
    let title = format!("Fig. 7: one stroke of the simulated rig, {}", run_label(&r.run));
    overview_svg(&r.run, r.run.window(), t0, &title, "recorded torque (overshoot after breakaway: servo ringing)")
}
