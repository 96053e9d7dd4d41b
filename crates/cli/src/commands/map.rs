//! `pinjoint map`: the paper's Figure 4 — λ and μ over load and speed — as CSV and SVG,
//! with the rig experiments' operating region marked.

use crate::common::{lin_space, log_space, positive, ParamsArg, RAD_S_PER_RPM};
use crate::curves::map::{write_map_as, write_min_lambda_map, Grid, MAP_FILES, MAX_GRID_SIDE};
use crate::error::{CliError, Result};
use crate::output::{inputs_of, refuse_files, report_written};
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
#[command(
    about = "Maps of λ and μ over load and speed (the paper's Figure 4), as CSV and SVG",
    long_about = "Evaluate the model over a grid of loads (evenly spaced) and speeds (log-spaced) and \
write the paper's Figure 4:\n  \
DIR/map.csv           every grid point: load [N], speed [rad/s], speed_rpm, then the result columns of `sweep`\n  \
                      (DIR/map.parquet instead with --format parquet: the same columns, Apache Parquet)\n  \
DIR/map_lambda.svg    (a) lambda ratio, colour map with contour lines\n  \
DIR/map_friction.svg  (b) friction coefficient, colour map with contour lines\n  \
DIR/map_min_lambda.svg  lambda ratio from the minimum film h_min (extension: Pan–Hamrock ratio on h_c)\n  \
DIR/map_curves.svg    μ and λ against speed at the paper's loads 5, 10, 20, 40 and 60 kN\n\
The plots mark the rig experiments' operating region: 5-60 kN and speeds up to the peak of the \
fastest stroke (1 Hz, ±40°: 2π·1 Hz·40° = 4.39 rad/s = 41.9 rpm); the strokes pass through \
every lower speed.\n\n\
Examples:\n  \
pinjoint map --output out/fig4\n  \
pinjoint map --min-rpm 0.1 --max-rpm 5000 --speeds 150 --output out/wide"
)]
/// Arguments of `pinjoint map` (its `--help` text is the `#[command]` attribute's).
pub struct MapCmd {
    /// Lowest load, in N
    #[arg(long, value_name = "N", default_value_t = 5e3, allow_negative_numbers = true)]
    pub min_load: f64,
    /// Highest load, in N
    #[arg(long, value_name = "N", default_value_t = 60e3, allow_negative_numbers = true)]
    pub max_load: f64,
    /// Number of loads, evenly spaced (>= 2)
    #[arg(long, value_name = "COUNT", default_value_t = 56)]
    pub loads: usize,
    /// Lowest speed, in rpm (1 rpm = 2π/60 rad/s)
    #[arg(long, value_name = "RPM", default_value_t = 1.0, allow_negative_numbers = true)]
    pub min_rpm: f64,
    /// Highest speed, in rpm
    #[arg(long, value_name = "RPM", default_value_t = 800.0, allow_negative_numbers = true)]
    pub max_rpm: f64,
    /// Number of speeds, log-spaced (>= 2)
    #[arg(long, value_name = "COUNT", default_value_t = 100)]
    pub speeds: usize,
    /// --params and --temperature.
    #[command(flatten)]
    pub params: ParamsArg,
    /// Output directory (created if needed)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// The grid's table: csv (map.csv) or parquet (map.parquet, the same columns)
    #[arg(long, value_name = "csv|parquet", default_value = "csv")]
    pub format: String,
}

/// Runs `pinjoint map`: checks the flags, evaluates the grid and writes the map files.
pub fn run(cmd: &MapCmd) -> Result<()> {
    let parquet = match cmd.format.as_str() {
        "csv" => false,
        "parquet" => true,
        other => return Err(CliError::Invalid(format!("--format {other} is not a format: csv or parquet"))),
    };
    refuse_files(&cmd.output, MAP_FILES, cmd.params.params.as_ref())?;
    refuse_files(&cmd.output, &["map.parquet"], cmd.params.params.as_ref())?;
    let joint = cmd.params.joint()?;
    let (p0, p1) = (positive("min-load", cmd.min_load, "N")?, positive("max-load", cmd.max_load, "N")?);
    let (n0, n1) = (positive("min-rpm", cmd.min_rpm, "rpm")?, positive("max-rpm", cmd.max_rpm, "rpm")?);
    if p0 >= p1 {
        return Err(CliError::Invalid(format!("the load range is empty: min-load {p0} N >= max-load {p1} N")));
    }
    if n0 >= n1 {
        return Err(CliError::Invalid(format!("the speed range is empty: min-rpm {n0} rpm >= max-rpm {n1} rpm")));
    }
    for (name, n) in [("loads", cmd.loads), ("speeds", cmd.speeds)] {
        if !(2..=MAX_GRID_SIDE).contains(&n) {
            return Err(CliError::Invalid(format!("{name} = {n} is invalid: it must be in 2..={MAX_GRID_SIDE} (bounded work and memory)")));
        }
    }
    let grid = Grid { loads: lin_space(p0, p1, cmd.loads), speeds: log_space(n0 * RAD_S_PER_RPM, n1 * RAD_S_PER_RPM, cmd.speeds) };
    let inputs = inputs_of(cmd.params.params.as_ref());
    let mut paths = write_map_as(&cmd.output, &inputs, &joint, &grid, parquet)?;
    paths.push(write_min_lambda_map(&cmd.output, &inputs, &joint, &grid)?);
    report_written(&paths)
}
