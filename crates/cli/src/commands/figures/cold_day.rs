//! The cold-day scene in figures (issue 28 item 8): a main gear's free-fall extension at +20,
//! −20, −40 and −54 °C ([`pinjoint::scene`]), the trunnion pins' friction from the joint model
//! with the presliding state, and the lock links' margin at the lock.
//!
//! Files (into the figures directory):
//!   cold_day.svg          (a) the leg's angle against time at each temperature the model runs,
//!                         with the trunnion friction off for comparison; (b) how far each leg
//!                         lags behind the one without trunnion friction; (c) the trunnion
//!                         friction torque against time; (d) the lock margin against
//!                         temperature, the temperatures the model refuses marked
//!   cold_day.csv          per temperature: status (`locked`, `not locked`, `not run`), time to
//!                         lock (`inf` if not locked), speed at lock, lock margin, breakaway
//!                         torque, friction energy, the same run without trunnion friction, and
//!                         the model's reason where it refused
//!   cold_day_series.csv   the runs' time series every 10 ms (time, angle, ω, pin load, torque)
//!
//! A temperature the joint model refuses (or an operating point it has no answer at) is shown
//! as not run, with the model's reason in the CSV and the caption: never an error of the command.

use super::index::Entry;
use crate::common::{csv_table, exact};
use crate::error::Result;
use crate::numbers::sig;
use crate::output::{output_dir, write_atomic, write_text};
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series, Style};
use pinjoint::scene::{simulate, FreeFallOutcome, FreeFallParams, SceneError};
use pinjoint::Params;
use std::path::{Path, PathBuf};

/// The temperatures of the scene (°C).
pub const TEMPERATURES_C: [f64; 4] = [20.0, -20.0, -40.0, -54.0];

/// The series are written and drawn every this many steps (10 ms at the default 1 ms step).
const DECIMATE: usize = 10;

/// °C to K, exact for whole and centi-degrees (233.15 for −40, where c + 273.15 is 233.14999999999998).
pub fn kelvin(celsius: f64) -> f64 {
    (100.0 * celsius + 27315.0) / 100.0
}

/// One temperature's runs: with the trunnion friction, and without it (the joint model's share).
#[derive(Debug, Clone)]
pub struct Row {
    /// The temperature, °C.
    pub celsius: f64,
    /// The run with the trunnion friction, or why the model could not run it.
    pub run: std::result::Result<FreeFallOutcome, String>,
    /// The same scene with no trunnion friction (the lock margin still the model's).
    pub frictionless: std::result::Result<FreeFallOutcome, String>,
}

/// Run the scene at one temperature: the model's refusals are a row's reason, any other error
/// (an invalid scene) the command's.
fn outcome(scene: &FreeFallParams, params: &Params, celsius: f64) -> Result<std::result::Result<FreeFallOutcome, String>> {
    match simulate(scene, params, kelvin(celsius)) {
        Ok(o) => Ok(Ok(o)),
        Err(e @ (SceneError::Temperature { .. } | SceneError::Joint { .. } | SceneError::Breakaway { .. })) => Ok(Err(e.to_string())),
        Err(e) => Err(e.into()),
    }
}

/// The scene at every temperature of [`TEMPERATURES_C`].
pub fn rows(scene: &FreeFallParams, params: &Params) -> Result<Vec<Row>> {
    let frictionless = FreeFallParams { trunnion_joints: 0, ..*scene };
    TEMPERATURES_C
        .iter()
        .map(|&c| Ok(Row { celsius: c, run: outcome(scene, params, c)?, frictionless: outcome(&frictionless, params, c)? }))
        .collect()
}

fn status(o: &std::result::Result<FreeFallOutcome, String>) -> &'static str {
    match o {
        Ok(o) if o.locked => "locked",
        Ok(_) => "not locked",
        Err(_) => "not run",
    }
}

/// `cold_day.csv`.
fn summary_csv(w: &mut dyn std::io::Write, rows: &[Row]) -> std::io::Result<()> {
    let header = [
        "temperature_C",
        "temperature_K",
        "status",
        "time_to_lock",
        "speed_at_lock",
        "lock_margin",
        "breakaway_torque",
        "friction_energy",
        "time_to_lock_without_friction",
        "speed_at_lock_without_friction",
        "reason",
    ];
    let num = |o: &std::result::Result<FreeFallOutcome, String>, f: fn(&FreeFallOutcome) -> Option<f64>| o.as_ref().ok().and_then(f).map_or_else(String::new, exact);
    let time = |o: &FreeFallOutcome| Some(o.time_to_lock);
    let speed = |o: &FreeFallOutcome| o.speed_at_lock;
    csv_table(
        w,
        header,
        rows.iter().map(|r| {
            let reason = r.run.as_ref().err().or(r.frictionless.as_ref().err()).cloned().unwrap_or_default();
            [
                exact(r.celsius),
                exact(kelvin(r.celsius)),
                status(&r.run).to_string(),
                num(&r.run, time),
                num(&r.run, speed),
                num(&r.run, |o| Some(o.lock_margin)),
                num(&r.run, |o| Some(o.breakaway_torque)),
                num(&r.run, |o| Some(o.friction_energy)),
                num(&r.frictionless, time),
                num(&r.frictionless, speed),
                reason,
            ]
        }),
    )
}

/// `cold_day_series.csv`: every [`DECIMATE`]th step of each run with friction, and its last sample.
fn series_csv(w: &mut dyn std::io::Write, rows: &[Row]) -> std::io::Result<()> {
    let runs = rows.iter().filter_map(|r| r.run.as_ref().ok().map(|o| (r.celsius, o)));
    csv_table(
        w,
        ["temperature_C", "time", "angle", "angular_velocity", "load", "friction_torque"],
        runs.flat_map(|(celsius, o)| decimated(o).map(move |s| [celsius, s.time, s.angle, s.angular_velocity, s.load, s.friction_torque].map(exact))),
    )
}

/// Every [`DECIMATE`]th sample and the last.
fn decimated(o: &FreeFallOutcome) -> impl Iterator<Item = &pinjoint::scene::Sample> {
    let last = o.series.len().saturating_sub(1);
    o.series.iter().enumerate().filter(move |(i, _)| i % DECIMATE == 0 || *i == last).map(|(_, s)| s)
}

fn label(c: f64) -> String {
    format!("{c:+} °C")
}

/// The points of one temperature's lag behind the leg without trunnion friction: (time s, lag
/// deg) every [`DECIMATE`] steps. Both runs have the same step, so sample i of both is at the same
/// time (the lock samples, at interpolated times, are left out).
fn lag_points(o: &FreeFallOutcome, f: &FreeFallOutcome) -> Vec<(f64, f64)> {
    let n = o.series.len().min(f.series.len()).saturating_sub(1);
    o.series[..n].iter().zip(&f.series[..n]).step_by(DECIMATE).map(|(a, b)| (a.time, (a.angle - b.angle).to_degrees())).collect()
}

/// The largest lag (deg) of a row's run behind its run without trunnion friction.
fn lag(r: &Row) -> Option<f64> {
    let (Ok(o), Ok(f)) = (&r.run, &r.frictionless) else { return None };
    let n = o.series.len().min(f.series.len()).saturating_sub(1);
    Some(o.series[..n].iter().zip(&f.series[..n]).map(|(a, b)| (a.angle - b.angle).to_degrees()).fold(0.0, f64::max))
}

/// The figure's caption, with this run's numbers.
pub fn caption(rows: &[Row], scene: &FreeFallParams) -> String {
    let mut ran = Vec::new();
    let mut refused = Vec::new();
    for r in rows {
        match (&r.run, &r.frictionless) {
            (Ok(o), Ok(f)) => {
                let lock = if o.locked {
                    let delay = if f.locked { format!(", {} ms after the leg without trunnion friction", sig(1e3 * (o.time_to_lock - f.time_to_lock), 3)) } else { String::new() };
                    format!("locks after {} s at {} rad/s{delay}", sig(o.time_to_lock, 5), sig(o.speed_at_lock.unwrap_or(0.0), 4))
                } else {
                    format!("does not lock within {} s", sig(scene.end_time, 3))
                };
                ran.push(format!(
                    "{}: {lock}, trunnion friction energy {} J, lock margin {} (lock-link breakaway {} N·m per pivot)",
                    label(r.celsius),
                    sig(o.friction_energy, 3),
                    sig(o.lock_margin, 4),
                    sig(o.breakaway_torque, 4)
                ));
            }
            (Err(e), _) | (_, Err(e)) => refused.push(format!("{}: not run — {e}", label(r.celsius))),
        }
    }
    let mut text = format!(
        "Not in the paper: a main gear's free-fall extension (an illustrative narrow-body gear, assumed: leg {} kg, \
centre of gravity {} m from the trunnion, J = {} kg·m², released at {} rad, actuator throttled as a damper \
c1 = {} N·m·s/rad, c2 = {} N·m·s²/rad², lock spring {} N·m below {} rad, {} trunnion pins each carrying {} of the \
leg's reaction), integrated by semi-implicit Euler at h = {} s with the trunnion friction from the joint model and its \
presliding state at the pin load the leg's dynamics give. The lock margin is the lock spring's {} N·m about the lock \
links against the breakaway torque of their {} pivots at {} N: lock_link_torque / (pivots × T_break) − 1. The damper \
does not depend on temperature (stated). ",
        sig(scene.leg_mass, 4),
        sig(scene.cg_distance, 4),
        sig(scene.inertia, 4),
        sig(scene.up_angle, 3),
        sig(scene.damper_linear, 4),
        sig(scene.damper_quadratic, 4),
        sig(scene.lock_spring_torque, 4),
        sig(scene.lock_spring_angle, 3),
        scene.trunnion_joints,
        sig(scene.trunnion_load_share, 3),
        sig(scene.step, 3),
        sig(scene.lock_link_torque, 4),
        scene.lock_link_pivots,
        sig(scene.lock_link_load, 4),
    );
    text.push_str(&ran.join("; "));
    if !refused.is_empty() {
        if !ran.is_empty() {
            text.push_str(". ");
        }
        text.push_str(&refused.join("; "));
    }
    if let Some(worst) = rows.iter().filter_map(|r| lag(r).map(|l| (r.celsius, l))).max_by(|a, b| a.1.total_cmp(&b.1)) {
        text.push_str(&format!(
            ". Gravity and the damper set the motion: the trunnion friction holds the leg back by at most {}° (at {}; panel b)",
            sig(worst.1, 3),
            label(worst.0)
        ));
    }
    text.push_str(
        ". The margin moves with temperature only through the lock links' breakaway torque. docs/cold-day-scene.md says \
which of the model's mechanisms move these numbers, and by how much.",
    );
    text
}

/// The figure's entry in `index.html` and `README.md`.
pub fn entry(rows: &[Row], scene: &FreeFallParams) -> Entry {
    Entry {
        title: "The cold-day scene: a main gear's free-fall extension at +20, −20, −40 and −54 °C".into(),
        images: vec!["cold_day.svg".into()],
        data: vec!["cold_day.csv".into(), "cold_day_series.csv".into()],
        caption: caption(rows, scene),
    }
}

/// Runs the scene at every temperature, writes the figure and its data into `dir`; returns their
/// paths and the figure's index entry.
pub fn write(dir: &Path, params: &Params) -> Result<(Vec<PathBuf>, Entry)> {
    let dir = output_dir(dir)?;
    let scene = FreeFallParams::default();
    let rows = rows(&scene, params)?;
    let mut angle = Chart::new("(a) the leg's angle from down-locked against time", Axis::linear("time [s]"), Axis::linear("angle [deg]")).legend(Corner::UpperRight);
    for (k, r) in rows.iter().enumerate() {
        if let Ok(o) = &r.run {
            angle = angle.series(Series::line(label(r.celsius), decimated(o).map(|s| (s.time, s.angle.to_degrees())).collect()).coloured(k));
        }
    }
    let mut lags = Chart::new(
        "(b) how far the leg lags behind the one without trunnion friction (the joint model's effect on the motion)",
        Axis::linear("time [s]"),
        Axis::linear("angle lag [deg]"),
    )
    .legend(Corner::UpperLeft);
    for (k, r) in rows.iter().enumerate() {
        if let (Ok(o), Ok(f)) = (&r.run, &r.frictionless) {
            lags = lags.series(Series::line(label(r.celsius), lag_points(o, f)).coloured(k));
        }
    }
    let mut torque = Chart::new("(c) the trunnion pins' friction torque on the leg against time", Axis::linear("time [s]"), Axis::linear("friction torque [N·m]")).legend(Corner::UpperRight);
    for (k, r) in rows.iter().enumerate() {
        if let Ok(o) = &r.run {
            torque = torque.series(Series::line(label(r.celsius), decimated(o).map(|s| (s.time, s.friction_torque)).collect()).coloured(k));
        }
    }
    if let Some(Ok(f)) = rows.first().map(|r| &r.frictionless) {
        angle = angle.series(Series::line(format!("{}, no trunnion friction", label(rows[0].celsius)), decimated(f).map(|s| (s.time, s.angle.to_degrees())).collect()).styled(Style::Dashed).coloured(7));
    }
    let margins: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.run.as_ref().ok().map(|o| (r.celsius, o.lock_margin))).collect();
    let refused: Vec<f64> = rows.iter().filter(|r| r.run.is_err()).map(|r| r.celsius).collect();
    let top = margins.iter().map(|m| m.1).fold(1.0_f64, f64::max);
    let mut margin = Chart::new(
        "(d) the lock margin at the lock, lock_link_torque / (pivots × T_break) − 1",
        Axis::linear("temperature [°C]").with_range(-60.0, 30.0),
        Axis::linear("lock margin [-]").with_range(0.0_f64.min(margins.iter().map(|m| m.1).fold(0.0, f64::min)), 1.2 * top),
    )
    .legend(Corner::LowerRight);
    margin = margin.series(Series::line("lock margin (positive: the lock engages)", margins).styled(Style::LinePoints).coloured(0));
    if !refused.is_empty() {
        let list: Vec<String> = refused.iter().map(|c| label(*c)).collect();
        margin = margin.marker(&refused, format!("not run, the joint model refuses: {}", list.join(", ")));
    }
    let svg = stacked_plot("The cold-day scene: free-fall extension of a main gear (illustrative)", &[angle, lags, torque, margin], (900, 1650))?;
    let paths: Vec<PathBuf> = ["cold_day.svg", "cold_day.csv", "cold_day_series.csv"].iter().map(|f| dir.join(f)).collect();
    write_text(&paths[0], &[], &svg)?;
    write_atomic(&paths[1], &[], |w| summary_csv(w, &rows))?;
    write_atomic(&paths[2], &[], |w| series_csv(w, &rows))?;
    Ok((paths, entry(&rows, &scene)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lubricant the model refuses at the cold end (Roelands' S0 = 5 makes η0 a glass's at
    /// −54 °C): the figure still draws, the CSV has every temperature, and the refused ones are
    /// shown as not run with the model's reason, in the CSV, the caption and the figure.
    #[test]
    fn a_refused_temperature_is_shown_as_not_run() {
        let mut params = Params::default();
        params.lubricant.roelands_temperature_index = 5.0;
        let dir = tempfile::tempdir().unwrap();
        let (paths, entry) = write(dir.path(), &params).unwrap();
        assert_eq!(paths.len(), 3);
        let text = std::fs::read_to_string(dir.path().join("cold_day.csv")).unwrap();
        let mut rdr = csv::Reader::from_reader(text.as_bytes());
        let rows: Vec<csv::StringRecord> = rdr.records().map(std::result::Result::unwrap).collect();
        assert_eq!(rows.iter().map(|r| r[0].parse::<f64>().unwrap()).collect::<Vec<_>>(), TEMPERATURES_C);
        let cold = rows.iter().find(|r| &r[0] == "-54.0").unwrap();
        assert_eq!(&cold[2], "not run");
        assert!(cold[10].contains("lubricant.temperature") && cold[10].contains("219.15 K"), "{:?}", &cold[10]);
        assert!(entry.caption.contains("-54 °C: not run"), "{}", entry.caption);
        let svg = std::fs::read_to_string(dir.path().join("cold_day.svg")).unwrap();
        assert!(svg.contains("not run, the joint model refuses") && svg.contains("-54 °C"));
        // The room-temperature run is untouched by the cold end's refusal.
        let room = rows.iter().find(|r| &r[0] == "20.0").unwrap();
        assert_eq!(&room[2], "locked");
    }
}
