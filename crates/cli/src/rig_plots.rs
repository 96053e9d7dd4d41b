//! Plots of one rig run ([`crate::rig_run`]): torque against time (the paper's Figures 11–13),
//! torque against angle (Figure 7d) and the four panels of Figure 7; drawn by `pinjoint cycle`
//! and `pinjoint figures`.

use crate::common::readable;
use crate::rig_run::CycleRun;
use crate::error::Result;
use pinjoint::rig::core_torque;
use crate::plot::{line_plot, stacked_plot, Axis, Chart, Corner, Series, Style};
use pinjoint::rig::Sample;

/// "1 Hz, ±40°, 20 kN".
pub fn run_label(run: &CycleRun) -> String {
    let r = &run.config.rig;
    format!("{} Hz, ±{}°, {} kN", readable(r.frequency), readable(r.amplitude.to_degrees()), readable(r.load / 1e3))
}

fn points(samples: &[Sample], t0: f64, f: impl Fn(&Sample) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time - t0, f(s))).collect()
}

/// A torque axis with room below the traces for a legend in the lower left corner.
pub fn torque_axis(samples: &[Sample]) -> Axis {
    let m = samples.iter().map(|s| s.torque.abs()).filter(|t| t.is_finite()).fold(0.0, f64::max);
    let axis = Axis::linear("torque [N·m]");
    if m > 0.0 { axis.with_range(-1.5 * m, 1.1 * m) } else { axis }
}

/// Recorded torque against time over `samples` (time counted from `t0`), with the core's
/// quasi-static torque at each sample's speed dashed beside it.
/// `recorded` names the recorded trace in the legend.
pub fn torque_time_chart(run: &CycleRun, samples: &[Sample], t0: f64, title: &str, recorded: &str) -> Chart {
    let r = run.config.model.geometry.pin_radius;
    Chart::new(title, time_axis(t0), torque_axis(samples))
        .series(Series::line(recorded, points(samples, t0, |s| s.torque)))
        .series(Series::line("core μ(P, |ω|)·R·P at the sample's speed", points(samples, t0, |s| core_torque(s, r))).styled(Style::Dashed))
        .legend(Corner::LowerLeft)
}

/// The time axis of a trace drawn from `t0`: the run's time when `t0` is 0, else the time since
/// the stroke began (not "t − 33.3333 s").
fn time_axis(t0: f64) -> Axis {
    Axis::linear(if t0 == 0.0 { "time t [s]" } else { "time since the stroke began [s]" })
}

/// The legend name of the recorded torque.
pub const RECORDED: &str = "recorded torque (actuator transducer)";

/// Recorded torque against the pin angle (degrees) over `samples`.
pub fn torque_angle_chart(samples: &[Sample], title: &str) -> Chart {
    let pts = samples.iter().map(|s| (s.angle.to_degrees(), s.torque)).collect();
    Chart::new(title, Axis::linear("pin angle θ [deg]"), Axis::linear("torque [N·m]")).series(Series::line("", pts))
}

/// `torque_time.svg` of `pinjoint cycle`: every sample of the run.
pub fn torque_time_svg(run: &CycleRun) -> Result<String> {
    let title = format!("Torque against time: {} ({} cycles from rest)", run_label(run), run.cycles);
    Ok(line_plot(&torque_time_chart(run, &run.samples, 0.0, &title, RECORDED), (1000, 560))?)
}

/// `torque_angle.svg` of `pinjoint cycle`: the averaged cycles (the start-up stroke left out).
pub fn torque_angle_svg(run: &CycleRun) -> Result<String> {
    let cycles = if run.skip + 1 == run.cycles { format!("cycle {}", run.cycles) } else { format!("cycles {}–{}", run.skip + 1, run.cycles) };
    let title = format!("Torque against angle: {}, {cycles}", run_label(run));
    Ok(line_plot(&torque_angle_chart(run.window(), &title), (900, 600))?)
}

/// The paper's Figure 7 from one stroke: (a) angle, (b) speed, (c) torque against time,
/// (d) torque against angle. `recorded` names the recorded torque in the legend.
pub fn overview_svg(run: &CycleRun, stroke: &[Sample], t0: f64, title: &str, recorded: &str) -> Result<String> {
    let tx = || time_axis(t0);
    let angle = Chart::new("(a) angular displacement", tx(), Axis::linear("angle [deg]"))
        .series(Series::line("pin angle θ", points(stroke, t0, |s| s.angle.to_degrees())))
        .series(Series::line("command θ_cmd", points(stroke, t0, |s| s.command_angle.to_degrees())).styled(Style::Dashed))
        .legend(Corner::UpperRight);
    let speed = Chart::new("(b) rotational speed", tx(), Axis::linear("ω [rad/s]"))
        .series(Series::line("pin speed ω", points(stroke, t0, |s| s.angular_velocity)))
        .legend(Corner::UpperRight);
    let torque = torque_time_chart(run, stroke, t0, "(c) torque against time", recorded);
    let angle_torque = torque_angle_chart(stroke, "(d) torque against angle");
    Ok(stacked_plot(title, &[angle, speed, torque, angle_torque], (900, 1500))?)
}
