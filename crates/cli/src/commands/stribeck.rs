//! `pinjoint stribeck`: the paper's Figure 3 — μ, 1/γ1, 1/γ2 and λ against the Sommerfeld
//! number at one load — as CSV and SVG.

use crate::common::{log_space, positive, readable, rig_peak_speed, ParamsArg, PAPER_RPM_RANGE, RAD_S_PER_RPM, RIG_LOAD_RANGE_N};
use crate::curves::{curve, points_csv};
use crate::error::{CliError, Result};
use crate::output::{inputs_of, output_dir, refuse_files, report_written, write_atomic, write_text};
use clap::Args;
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series};
use pinjoint::{Joint, OperatingPoint};
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
#[command(
    about = "Stribeck curve at one load (the paper's Figure 3), as CSV and SVG",
    long_about = "Sweep the speed at one load and write the paper's Figure 3: friction coefficient μ, \
the load fractions 1/γ1 (fluid) and 1/γ2 (asperities) and the lambda ratio against the \
Sommerfeld number (eq. 20), log-spaced in speed.\n\
Writes DIR/stribeck.csv (columns load, speed [rad/s], speed_rpm, then the same result columns \
as `sweep`) and DIR/stribeck.svg. The plot shades the paper's simulated speed range (1-800 rpm) \
and the rig experiments' range (up to the 1 Hz, ±40° stroke's peak speed, 41.9 rpm).\n\
Each end of the speed range is given in rad/s or in rpm.\n\n\
Examples:\n  \
pinjoint stribeck --load 20000 --output out/fig3\n  \
pinjoint stribeck --load 60000 --min-rpm 0.1 --max-rpm 10000 --points 200 --output out/60kN"
)]
/// Arguments of `pinjoint stribeck` (its `--help` text is the `#[command]` attribute's).
pub struct StribeckCmd {
    /// Normal load P_T, in N (20000 for the paper's Figure 3)
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub load: f64,
    /// Lowest speed, in rad/s [default: 0.01 rad/s]
    #[arg(long, value_name = "RAD/S", allow_negative_numbers = true, conflicts_with = "min_rpm")]
    pub min_speed: Option<f64>,
    /// Highest speed, in rad/s [default: 1000 rad/s]
    #[arg(long, value_name = "RAD/S", allow_negative_numbers = true, conflicts_with = "max_rpm")]
    pub max_speed: Option<f64>,
    /// Lowest speed, in rpm (instead of --min-speed)
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub min_rpm: Option<f64>,
    /// Highest speed, in rpm (instead of --max-speed)
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub max_rpm: Option<f64>,
    /// Number of speeds, log-spaced from the lowest to the highest (>= 2)
    #[arg(long, value_name = "COUNT", default_value_t = 121)]
    pub points: usize,
    /// --params and --temperature.
    #[command(flatten)]
    pub params: ParamsArg,
    /// Output directory (created if needed)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
}

/// Default speed range of the curve (lowest, highest), in rad/s.
pub const DEFAULT_SPEED_RANGE: (f64, f64) = (0.01, 1000.0);

/// A speed-range end from rad/s or rpm flags, validated (> 0, finite), in rad/s.
fn end(rad: Option<f64>, rpm: Option<f64>, name: &str, default: f64) -> Result<f64> {
    match (rad, rpm) {
        (Some(w), _) => positive(&format!("{name}-speed"), w, "rad/s"),
        (None, Some(n)) => Ok(positive(&format!("{name}-rpm"), n, "rpm")? * RAD_S_PER_RPM),
        (None, None) => Ok(default),
    }
}

/// The Figure 3 plot: three panels against the Sommerfeld number.
pub fn figure(joint: &Joint, load: f64, ops: &[OperatingPoint]) -> Result<String> {
    // S is proportional to |ω| at fixed load: the factor from the model at 1 rad/s.
    let s_per_rad_s = joint.evaluate(load, 1.0)?.sommerfeld_number;
    let s_min = ops.iter().map(|o| o.sommerfeld_number).fold(f64::INFINITY, f64::min);
    let col = |f: fn(&OperatingPoint) -> f64| ops.iter().map(|o| (o.sommerfeld_number, f(o))).collect::<Vec<_>>();
    let x = || Axis::log("Sommerfeld number S (eq. 20) [-]");
    let paper = (PAPER_RPM_RANGE.0 * RAD_S_PER_RPM * s_per_rad_s, PAPER_RPM_RANGE.1 * RAD_S_PER_RPM * s_per_rad_s);
    let rig = (s_min, rig_peak_speed() * s_per_rad_s);
    // The shaded speeds are the validity envelope's checked ones; outside them (and at a load
    // or temperature outside it) the curve is an extrapolation.
    let inside_load = (RIG_LOAD_RANGE_N.0..=RIG_LOAD_RANGE_N.1).contains(&load);
    let band_label = if inside_load {
        "rig experiments, up to 41.9 rpm (validity: checked; beyond it extrapolation)"
    } else if load.abs() > joint.load_edge() {
        "rig experiments' speeds, up to 41.9 rpm (this load is past the Hertz contact's edge, a > R: outside)"
    } else {
        "rig experiments' speeds, up to 41.9 rpm (this load is outside 5-60 kN: extrapolation)"
    };
    let marks = |c: Chart| {
        c.band(rig.0, rig.1, band_label).marker(&[paper.0, paper.1], "paper's simulated range, 1 and 800 rpm")
    };
    let mu = marks(Chart::new("(a) friction coefficient", x(), Axis::linear("μ [-]")))
        .series(Series::line("μ (eq. 10)", col(|o| o.friction_coefficient)))
        .legend(Corner::LowerLeft);
    let shares = marks(Chart::new("(b) load sharing", x(), Axis::linear("load fraction [-]").with_range(-0.02, 1.02)))
        .series(Series::line("1/γ1 (fluid film)", col(|o| o.fluid_load_fraction)))
        .series(Series::line("1/γ2 (asperities)", col(|o| o.asperity_load_fraction)))
        .legend(Corner::UpperLeft);
    let lambda = marks(Chart::new("(c) film thickness parameter", x(), Axis::log("λ = h_c / √(σ² + σ_b²) [-]")))
        .series(Series::line("λ (eq. 21, central film)", col(|o| o.lambda_ratio)))
        .legend(Corner::UpperLeft);
    let p_m = ops.first().map_or(0.0, |o| o.mean_pressure);
    let title = format!(
        "Stribeck curve at P_T = {} kN (p_m = {} MPa); S = {} per rad/s{}",
        readable(load / 1e3),
        readable((p_m / 1e6 * 100.0).round() / 100.0),
        readable(s_per_rad_s),
        crate::common::temperature_note(joint.params())
    );
    Ok(stacked_plot(&title, &[mu, shares, lambda], (900, 1200))?)
}

/// Write DIR/stribeck.csv and DIR/stribeck.svg; returns their paths.
/// `inputs`: the command's input files, never overwritten.
pub fn write_stribeck(dir: &Path, inputs: &[&Path], joint: &Joint, load: f64, speeds: &[f64]) -> Result<Vec<PathBuf>> {
    let ops = curve(joint, load, speeds)?;
    let dir = output_dir(dir)?;
    let (csv_path, svg_path) = (dir.join("stribeck.csv"), dir.join("stribeck.svg"));
    let svg = figure(joint, load, &ops)?;
    write_atomic(&csv_path, inputs, |w| points_csv(w, &ops))?;
    write_text(&svg_path, inputs, &svg)?;
    Ok(vec![csv_path, svg_path])
}

/// Most points of one Stribeck curve.
pub const MAX_POINTS: usize = 100_000;

/// Runs `pinjoint stribeck`: evaluates the curve and writes stribeck.csv and stribeck.svg.
pub fn run(cmd: &StribeckCmd) -> Result<()> {
    refuse_files(&cmd.output, &["stribeck.csv", "stribeck.svg"], cmd.params.params.as_ref())?;
    let joint = cmd.params.joint()?;
    let load = positive("load", cmd.load, "N")?;
    let lo = end(cmd.min_speed, cmd.min_rpm, "min", DEFAULT_SPEED_RANGE.0)?;
    let hi = end(cmd.max_speed, cmd.max_rpm, "max", DEFAULT_SPEED_RANGE.1)?;
    if lo >= hi {
        return Err(CliError::Invalid(format!("the speed range is empty: lowest {lo} rad/s >= highest {hi} rad/s")));
    }
    if !(2..=MAX_POINTS).contains(&cmd.points) {
        return Err(CliError::Invalid(format!("points = {} is invalid: it must be in 2..={MAX_POINTS} (bounded work and memory)", cmd.points)));
    }
    report_written(&write_stribeck(&cmd.output, &inputs_of(cmd.params.params.as_ref()), &joint, load, &log_space(lo, hi, cmd.points))?)
}
