//! The starved-inlet extension in figures (issue 13 item 5): how a finite lubricant layer at
//! the inlet ([`pinjoint::film::starvation`], `[starvation] inlet_layer_inverse`) moves the Stribeck
//! curve and the 1 Hz torque cycle, and what it does to the paper's statements that the
//! flooded model does not reproduce.
//!
//! Files (into the figures directory):
//!   starvation_stribeck.svg / .csv   μ and 1/γ2 against speed at 20 kN for several inlet layers
//!   starvation_cycle_1Hz.svg / .csv  the core's torque along the 1 Hz, ±40° commanded stroke
//!                                    (quasi-static: μ(P, |θ̇_cmd|)·R·P, no servo dynamics)
//!   starvation_summary.csv           per layer and load: the speed where μ falls to 0.11 and where
//!                                    the asperities' share falls to 1/2, μ at 800 rpm, the dip
//!
//! `pinjoint figures` ([`super::run`]) calls [`write()`] into its output directory.


use crate::common::{exact, log_space, RAD_S_PER_RPM, RIG_AMPLITUDE_DEG};
use crate::error::{CliError, Result};
use crate::output::{output_dir, write_csv, write_text};
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series};
use pinjoint::{Joint, OperatingPoint, Params};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// The inlet layers shown, m: `None` is the paper's flooded model.
pub const LAYERS: [Option<f64>; 4] = [None, Some(10e-6), Some(4e-6), Some(3.4e-6)];
/// Loads of the summary, N (the paper's Figure 4 statements are over 5–60 kN).
pub const SUMMARY_LOADS: [f64; 3] = [5e3, 20e3, 60e3];
/// μ threshold of the paper's Figure 4 statement ("friction coefficients do not fall below 0.11").
pub const MU_STATEMENT: f64 = 0.11;
/// The paper's simulated speed range, rpm (section 3.2).
const RPM_RANGE: (f64, f64) = (1.0, 800.0);

fn label(layer: Option<f64>) -> String {
    match layer {
        None => "flooded (paper model)".into(),
        Some(h) => format!("starved, h_oil = {} µm", h * 1e6),
    }
}

/// The joint with the inlet layer `layer` (m; `None`: flooded, the parameters as given).
pub fn joint_with(params: &Params, layer: Option<f64>) -> Result<Joint> {
    let mut p = *params;
    if let Some(h) = layer {
        p.starvation.inlet_layer_inverse = 1.0 / h;
    }
    Joint::new(&p).map_err(CliError::Params)
}

/// The lowest speed (rad/s) in [lo, hi] where `f` (decreasing in speed along the curve)
/// falls below `level`, found on a log grid then by bisection; `None` if it stays above.
fn crossing(joint: &Joint, load: f64, lo: f64, hi: f64, level: f64, f: fn(&OperatingPoint) -> f64) -> Result<Option<f64>> {
    let grid = log_space(lo, hi, 200);
    let mut prev = lo;
    for &w in &grid {
        if f(&joint.evaluate(load, w)?) < level {
            if w == lo {
                return Ok(Some(lo));
            }
            let (mut a, mut b) = (prev, w);
            for _ in 0..60 {
                let m = (a * b).sqrt();
                if f(&joint.evaluate(load, m)?) < level { b = m } else { a = m }
            }
            return Ok(Some((a * b).sqrt()));
        }
        prev = w;
    }
    Ok(None)
}

/// One row of the summary.
#[derive(Debug, Clone, Copy)]
pub struct SummaryRow {
    /// Oil layer thickness h_oil at the inlet, in m (None: flooded, the paper's model).
    pub layer: Option<f64>,
    /// Radial load, in N.
    pub load: f64,
    /// rpm where μ first falls below 0.11 in 1–800 rpm (None: never).
    pub mu_crossing_rpm: Option<f64>,
    /// rpm where the asperities' share first falls below 1/2 (None: never in 1–800 rpm).
    pub half_share_rpm: Option<f64>,
    /// μ at 800 rpm.
    pub mu_800: f64,
    /// λ (central film) at 1 rpm and at 800 rpm.
    pub lambda_1: f64,
    /// λ (central film) at 800 rpm.
    pub lambda_800: f64,
    /// The 1 Hz stroke's torque dip: 1 − T(peak speed)/T(at 75 % of the amplitude).
    pub dip_1hz: f64,
}

/// The summary for every layer and load.
pub fn summary(params: &Params) -> Result<Vec<SummaryRow>> {
    let (lo, hi) = (RPM_RANGE.0 * RAD_S_PER_RPM, RPM_RANGE.1 * RAD_S_PER_RPM);
    let a = RIG_AMPLITUDE_DEG.to_radians();
    let w_peak = 2.0 * PI * a;
    // At |θ| = 0.75 A the speed is w_peak·√(1 − 0.75²).
    let w_75 = w_peak * (1.0f64 - 0.75 * 0.75).sqrt();
    let mut out = Vec::new();
    for layer in LAYERS {
        let joint = joint_with(params, layer)?;
        for &load in &SUMMARY_LOADS {
            let mu = |w: f64| -> Result<f64> { Ok(joint.evaluate(load, w)?.friction_coefficient) };
            out.push(SummaryRow {
                layer,
                load,
                mu_crossing_rpm: crossing(&joint, load, lo, hi, MU_STATEMENT, |o| o.friction_coefficient)?.map(|w| w / RAD_S_PER_RPM),
                half_share_rpm: crossing(&joint, load, lo, hi, 0.5, |o| o.asperity_load_fraction)?.map(|w| w / RAD_S_PER_RPM),
                mu_800: mu(hi)?,
                lambda_1: joint.evaluate(load, lo)?.lambda_ratio,
                lambda_800: joint.evaluate(load, hi)?.lambda_ratio,
                dip_1hz: 1.0 - mu(w_peak)? / mu(w_75)?,
            });
        }
    }
    Ok(out)
}

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "none".into(), exact)
}

fn layer_field(layer: Option<f64>) -> String {
    layer.map_or_else(|| "flooded".into(), exact)
}

/// Write the figures and CSVs into `dir`; returns their paths.
pub fn write(dir: &Path, params: &Params) -> Result<Vec<PathBuf>> {
    let dir = output_dir(dir)?;
    let load = 20e3;
    let speeds = log_space(0.1 * RAD_S_PER_RPM, 1000.0 * RAD_S_PER_RPM, 161);
    let x = || Axis::log("speed [rpm]");
    let mut mu = Chart::new(format!("(a) friction coefficient μ at {} kN", load / 1e3), x(), Axis::linear("μ [-]")).legend(Corner::LowerLeft);
    let mut share = Chart::new("(b) share of the load on the asperities, 1/γ2", x(), Axis::linear("1/γ2 [-]")).legend(Corner::LowerLeft);
    let mut rows = Vec::new();
    for layer in LAYERS {
        let joint = joint_with(params, layer)?;
        let ops = speeds.iter().map(|&w| joint.evaluate(load, w)).collect::<std::result::Result<Vec<_>, _>>()?;
        mu = mu.series(Series::line(label(layer), ops.iter().map(|o| (o.angular_velocity / RAD_S_PER_RPM, o.friction_coefficient)).collect()));
        share = share.series(Series::line(label(layer), ops.iter().map(|o| (o.angular_velocity / RAD_S_PER_RPM, o.asperity_load_fraction)).collect()));
        rows.extend(ops.into_iter().map(|o| (layer, o)));
    }
    let rig_peak_rpm = 2.0 * PI * RIG_AMPLITUDE_DEG.to_radians() / RAD_S_PER_RPM;
    mu = mu.band(RPM_RANGE.0, RPM_RANGE.1, "paper's simulated range 1-800 rpm").marker(&[rig_peak_rpm], "1 Hz stroke peak, 41.9 rpm: validity checked up to here, extrapolation beyond");
    share = share.marker(&[rig_peak_rpm], "validity: checked up to 41.9 rpm, extrapolation beyond");
    share = share.band(RPM_RANGE.0, RPM_RANGE.1, "paper's simulated range 1-800 rpm");
    let stribeck = stacked_plot(
        "Starved-inlet extension (off by default): h_c^-g = h_flooded^-g + h_oil^-g, g = 2.8",
        &[mu, share],
        (900, 1000),
    )?;

    // The 1 Hz, ±40° commanded stroke: θ = A sin 2πft, ω = 2πfA cos 2πft; T = μ(P, |ω|) R P.
    let a = RIG_AMPLITUDE_DEG.to_radians();
    let times: Vec<f64> = (0..=400).map(|i| f64::from(i) / 400.0).collect();
    let mut charts = Vec::new();
    let mut cycle_rows = Vec::new();
    for (k, &p) in [20e3, 60e3].iter().enumerate() {
        let mut c = Chart::new(
            format!("({}) torque along the 1 Hz, ±40° stroke at {} kN (core model, no servo dynamics)", ['a', 'b'][k], p / 1e3),
            Axis::linear("time in the stroke [s]"),
            Axis::linear("torque magnitude μRP [N·m]"),
        )
        .legend(Corner::UpperLeft);
        for layer in LAYERS {
            let joint = joint_with(params, layer)?;
            let mut pts = Vec::new();
            for &t in &times {
                let w = 2.0 * PI * a * (2.0 * PI * t).cos();
                let o = joint.evaluate(p, w)?;
                pts.push((t, o.torque));
                cycle_rows.push((layer, p, t, a * (2.0 * PI * t).sin(), w, o.torque));
            }
            c = c.series(Series::line(label(layer), pts));
        }
        charts.push(c);
    }
    let cycle = stacked_plot("Starved-inlet extension: the 1 Hz torque cycle", &charts, (900, 1000))?;

    let sum = summary(params)?;
    let paths: Vec<PathBuf> = [
        "starvation_stribeck.svg",
        "starvation_stribeck.csv",
        "starvation_cycle_1Hz.svg",
        "starvation_cycle_1Hz.csv",
        "starvation_summary.csv",
    ]
    .iter()
    .map(|f| dir.join(f))
    .collect();
    let stribeck_rows = rows.iter().map(|(layer, o)| {
        let numbers = [o.load, o.angular_velocity, o.angular_velocity / RAD_S_PER_RPM, o.friction_coefficient, o.asperity_load_fraction, o.film_thickness, o.lambda_ratio];
        std::iter::once(layer_field(*layer)).chain(numbers.map(exact))
    });
    let cycle_rows = cycle_rows.iter().map(|&(layer, p, t, th, w, tq)| std::iter::once(layer_field(layer)).chain([p, t, th, w, tq].map(exact)));
    let summary_rows = sum.iter().map(|r| {
        [layer_field(r.layer), exact(r.load), opt(r.mu_crossing_rpm), opt(r.half_share_rpm), exact(r.mu_800), exact(r.lambda_1), exact(r.lambda_800), exact(r.dip_1hz)]
    });
    write_text(&paths[0], &[], &stribeck)?;
    write_csv(&paths[1], &[], ["inlet_layer", "load", "speed", "speed_rpm", "friction_coefficient", "asperity_load_fraction", "film_thickness", "lambda_ratio"], stribeck_rows)?;
    write_text(&paths[2], &[], &cycle)?;
    write_csv(&paths[3], &[], ["inlet_layer", "load", "time", "angle", "speed", "torque"], cycle_rows)?;
    write_csv(&paths[4], &[], ["inlet_layer", "load", "mu_0.11_crossing_rpm", "half_asperity_share_rpm", "mu_800rpm", "lambda_1rpm", "lambda_800rpm", "dip_1Hz"], summary_rows)?;
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_every_file_and_flooded_row_is_the_paper_model() {
        let d = tempfile::tempdir().unwrap();
        // PINJOINT_FIGURES_OUT=DIR keeps a copy of the files (to look at them).
        let dir = std::env::var_os("PINJOINT_FIGURES_OUT").map_or_else(|| d.path().to_path_buf(), std::path::PathBuf::from);
        let paths = write(&dir, &Params::paper()).unwrap();
        for p in &paths {
            assert!(std::fs::metadata(p).unwrap().len() > 100, "{}", p.display());
        }
        let sum = summary(&Params::paper()).unwrap();
        for r in &sum {
            eprintln!(
                "{:>8} {:>6} N  mu<0.11 at {:?} rpm  1/g2<0.5 at {:?} rpm  mu(800)={:.4}  lambda 1rpm {:.3} 800rpm {:.3}  dip {:.3}",
                layer_field(r.layer),
                r.load,
                r.mu_crossing_rpm,
                r.half_share_rpm,
                r.mu_800,
                r.lambda_1,
                r.lambda_800,
                r.dip_1hz
            );
        }
        // The flooded rows are docs/model.md's numbers: μ = 0.11 at 6.6 / 17 / 27 rpm.
        let flooded: Vec<_> = sum.iter().filter(|r| r.layer.is_none()).collect();
        for (r, want) in flooded.iter().zip([6.6, 17.0, 27.0]) {
            let got = r.mu_crossing_rpm.unwrap();
            assert!((got / want - 1.0).abs() < 0.05, "{} N: {got} rpm vs {want}", r.load);
        }
    }
}
