//! The paper's Figure 4 — λ and μ over load and speed, with the rig experiments' operating
//! region marked — as CSV (or Parquet) and SVG: written by `pinjoint map` and by
//! `pinjoint figures`.

use crate::common::{log_space, rig_peak_speed, RAD_S_PER_RPM, RIG_LOAD_RANGE_N};
use crate::error::{CliError, Result};
use crate::output::{output_dir, write_atomic, write_atomic_send, write_text};
use super::{curve, points_csv};
use crate::plot::{heat_map, stacked_plot, Axis, Chart, Corner, HeatMap, Region, Series};
use pinjoint::{Joint, OperatingPoint};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// The loads of the paper's Table 1, in N: one curve each in map_curves.svg.
pub const PAPER_LOADS: [f64; 5] = pinjoint::paper::LOADS;

/// The map grid: loads (N) and speeds (rad/s).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Loads, in N, evenly spaced.
    pub loads: Vec<f64>,
    /// Speeds, in rad/s, log-spaced.
    pub speeds: Vec<f64>,
}

/// Every grid point, load-major (all speeds of the first load, then the next load ...).
pub fn evaluate(joint: &Joint, g: &Grid) -> Result<Vec<OperatingPoint>> {
    let pts: Vec<(f64, f64)> = g.loads.iter().flat_map(|&p| g.speeds.iter().map(move |&w| (p, w))).collect();
    pts.par_iter().map(|&(p, w)| joint.evaluate(p, w).map_err(CliError::from)).collect()
}

fn rpm(w: f64) -> f64 {
    w / RAD_S_PER_RPM
}

/// The rig experiments' region on the (rpm, kN) axes, clipped to the grid.
fn rig_region(g: &Grid) -> Option<Region> {
    let x0 = rpm(g.speeds[0]);
    let x1 = rpm(rig_peak_speed()).min(rpm(*g.speeds.last()?));
    let y0 = (RIG_LOAD_RANGE_N.0 / 1e3).max(g.loads[0] / 1e3);
    let y1 = (RIG_LOAD_RANGE_N.1 / 1e3).min(g.loads.last()? / 1e3);
    (x0 < x1 && y0 < y1).then(|| Region {
        x: (x0, x1),
        y: (y0, y1),
        label: "rig experiments: 5-60 kN, up to 41.9 rpm (1 Hz, ±40°): validity checked; outside extrapolation".into(),
    })
}

/// One heat map of `f` over the grid.
fn map_plot(g: &Grid, ops: &[OperatingPoint], title: &str, z_axis: Axis, levels: &[f64], f: fn(&OperatingPoint) -> f64) -> Result<String> {
    let n = g.speeds.len();
    let z: Vec<Vec<f64>> = ops.chunks(n).map(|row| row.iter().map(f).collect()).collect();
    let (lo, hi) = z.iter().flatten().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let h = HeatMap {
        title: title.into(),
        x: Axis::log("speed [rpm]"),
        y: Axis::linear("load P_T [kN]"),
        xs: g.speeds.iter().map(|&w| rpm(w)).collect(),
        ys: g.loads.iter().map(|&p| p / 1e3).collect(),
        z,
        z_axis,
        contours: levels.iter().copied().filter(|&l| l > lo && l < hi).collect(),
        regions: rig_region(g).into_iter().collect(),
    };
    Ok(heat_map(&h, (960, 640))?)
}

/// μ and λ against speed at the paper's loads, with the rig's speed range shaded.
fn curves_plot(joint: &Joint, g: &Grid) -> Result<String> {
    let (lo, hi) = (rpm(g.speeds[0]), rpm(*g.speeds.last().unwrap_or(&g.speeds[0])));
    let speeds = log_space(g.speeds[0], *g.speeds.last().unwrap_or(&g.speeds[0]), 200);
    let x = || Axis::log("speed [rpm]");
    let mut mu = Chart::new("(b) friction coefficient", x(), Axis::linear("μ [-]")).legend(Corner::LowerLeft);
    let mut lambda = Chart::new("(a) lambda ratio", x(), Axis::log("λ = h_c / √(σ² + σ_b²) [-]")).legend(Corner::UpperLeft);
    for &p in &PAPER_LOADS {
        let ops = curve(joint, p, &speeds)?;
        let name = format!("{} kN", p / 1e3);
        mu = mu.series(Series::line(&name, ops.iter().map(|o| (rpm(o.angular_velocity), o.friction_coefficient)).collect()));
        lambda = lambda.series(Series::line(&name, ops.iter().map(|o| (rpm(o.angular_velocity), o.lambda_ratio)).collect()));
    }
    let rig_hi = rpm(rig_peak_speed()).min(hi);
    if lo < rig_hi {
        mu = mu.band(lo, rig_hi, "rig experiments, up to 41.9 rpm");
        lambda = lambda.band(lo, rig_hi, "rig experiments, up to 41.9 rpm");
    }
    Ok(stacked_plot("Pin joint operation at the paper's loads", &[lambda, mu], (900, 1000))?)
}

/// Most loads (and most speeds) of one map: at most 1000 × 1000 = 1e6 solves.
pub const MAX_GRID_SIDE: usize = 1000;

/// The files `map` writes into its directory.
pub const MAP_FILES: &[&str] = &["map.csv", "map_lambda.svg", "map_friction.svg", "map_curves.svg"];

/// Write the CSV and the three plots ([`MAP_FILES`]) into `dir`; returns their paths.
/// `inputs`: the command's input files, never overwritten. Fails if a point cannot be
/// evaluated or a file cannot be written.
pub fn write_map(dir: &Path, inputs: &[&Path], joint: &Joint, g: &Grid) -> Result<Vec<PathBuf>> {
    write_map_as(dir, inputs, joint, g, false)
}

/// [`write_map`], the grid's table as `map.parquet` ([`crate::columnar::points_parquet`]: the
/// same columns and numbers) instead of `map.csv` when `parquet`.
pub fn write_map_as(dir: &Path, inputs: &[&Path], joint: &Joint, g: &Grid, parquet: bool) -> Result<Vec<PathBuf>> {
    let ops = evaluate(joint, g)?;
    let lambda = map_plot(
        g,
        &ops,
        "(a) lambda ratio λ = h_c / √(σ² + σ_b²)",
        Axis::log("λ [-]"),
        &[1.5, 2.0, 3.0, 5.0, 10.0, 20.0, 50.0],
        |o| o.lambda_ratio,
    )?;
    let friction = map_plot(
        g,
        &ops,
        "(b) friction coefficient μ",
        Axis::linear("μ [-]"),
        &[0.02, 0.05, 0.08, 0.1, 0.11, 0.115],
        |o| o.friction_coefficient,
    )?;
    let curves = curves_plot(joint, g)?;
    let dir = output_dir(dir)?;
    let mut paths: Vec<PathBuf> = MAP_FILES.iter().map(|f| dir.join(f)).collect();
    if parquet {
        paths[0] = dir.join("map.parquet");
        write_atomic_send(&paths[0], inputs, |w| crate::columnar::points_parquet(w, &ops))?;
    } else {
        write_atomic(&paths[0], inputs, |w| points_csv(w, &ops))?;
    }
    write_text(&paths[1], inputs, &lambda)?;
    write_text(&paths[2], inputs, &friction)?;
    write_text(&paths[3], inputs, &curves)?;
    Ok(paths)
}

/// The map of λ from the minimum film (an extension, [`pinjoint::film::min_film`]) into `dir`:
/// written by the `map` command beside the paper's Figure 4 files.
pub fn write_min_lambda_map(dir: &Path, inputs: &[&Path], joint: &Joint, g: &Grid) -> Result<PathBuf> {
    let ops = evaluate(joint, g)?;
    let svg = map_plot(
        g,
        &ops,
        "lambda ratio from the minimum film, h_min / √(σ² + σ_b²) (Pan–Hamrock h_min/h_c, extrapolated)",
        Axis::log("λ_min [-]"),
        &[0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 20.0],
        |o| o.min_lambda_ratio,
    )?;
    let path = output_dir(dir)?.join("map_min_lambda.svg");
    write_text(&path, inputs, &svg)?;
    Ok(path)
}
