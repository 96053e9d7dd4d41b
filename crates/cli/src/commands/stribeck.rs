//! `pinjoint stribeck`: the paper's Figure 3 — μ, 1/γ1, 1/γ2 and λ against the Sommerfeld
//! number at one load — as CSV and SVG.

use crate::common::{log_space, positive, ParamsArg, RAD_S_PER_RPM};
use crate::curves::stribeck::{write_stribeck, DEFAULT_SPEED_RANGE};
use crate::error::{CliError, Result};
use crate::output::{inputs_of, refuse_files, report_written};
use clap::Args;
use std::path::PathBuf;

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

/// A speed-range end from rad/s or rpm flags, validated (> 0, finite), in rad/s.
fn end(rad: Option<f64>, rpm: Option<f64>, name: &str, default: f64) -> Result<f64> {
    match (rad, rpm) {
        (Some(w), _) => positive(&format!("{name}-speed"), w, "rad/s"),
        (None, Some(n)) => Ok(positive(&format!("{name}-rpm"), n, "rpm")? * RAD_S_PER_RPM),
        (None, None) => Ok(default),
    }
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
