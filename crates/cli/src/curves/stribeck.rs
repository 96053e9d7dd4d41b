//! The paper's Figure 3 — μ, 1/γ1, 1/γ2 and λ against the Sommerfeld number at one load — as
//! CSV and SVG: written by `pinjoint stribeck` and by `pinjoint figures`.

use crate::common::{readable, rig_peak_speed, PAPER_RPM_RANGE, RAD_S_PER_RPM, RIG_LOAD_RANGE_N};
use crate::error::Result;
use crate::output::{output_dir, write_atomic, write_text};
use super::{curve, points_csv};
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series};
use pinjoint::{Joint, OperatingPoint};
use std::path::{Path, PathBuf};

/// Default speed range of the curve (lowest, highest), in rad/s.
pub const DEFAULT_SPEED_RANGE: (f64, f64) = (0.01, 1000.0);

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
