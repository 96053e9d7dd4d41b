//! What `pinjoint calibrate` writes: the calibrated parameter file, the report (Markdown and
//! HTML, from one list of blocks), the fit as CSV, the plots, and the JSON summary.

use pinjoint::rig::RigConfig;
use pinjoint_calibrate::{Calibration, Estimate, Model, Reason, INERTIA, MU_C};
use crate::common::exact;
use crate::error::Result;
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series, Style};
use serde_json::{json, Map, Value};
use std::io::{self, Write};

/// Records drawn in the plots (the report says when there are more).
const MAX_PLOTTED: usize = 6;
/// Points per plotted series at most (every k-th sample beyond).
const MAX_POINTS: usize = 4000;

/// `calibrated.toml`: the complete parameter file with the fitted values, a comment header
/// naming the inputs and the intervals.
pub fn toml_file(c: &Calibration, inputs: &[String]) -> String {
    let mut head = String::from("# Calibrated by `pinjoint calibrate` from:\n");
    for i in inputs {
        head.push_str(&format!("#   {i}\n"));
    }
    for e in &c.estimates {
        head.push_str(&format!("# {} = {} (standard error {:.3e}, 95 % interval [{}, {}])\n", e.key, exact(e.value), e.standard_error, exact(e.ci95.0), exact(e.ci95.1)));
    }
    head.push_str(&format!("# {}\n", inertia_line(c)));
    if !c.temperatures.is_empty() {
        let t: Vec<String> = c.temperatures.iter().map(|t| exact(*t)).collect();
        head.push_str(&format!("# Records at {} K; [lubricant] temperature below is the start file's, not a record's.\n", t.join(", ")));
    }
    head.push_str(&format!("# rms residual {:.4} N.m over {} samples ({} excluded).\n", c.rms_residual, c.points_used, c.points_excluded));
    match c.rig {
        Some(rig) => head + &RigConfig { model: c.params, rig }.to_toml_string(),
        None => head + &c.params.to_toml_string(),
    }
}

/// The `--json` object.
pub fn report_json(c: &Calibration) -> String {
    let est = |e: &Estimate| json!({"value": e.value, "standard_error": e.standard_error, "ci95": [e.ci95.0, e.ci95.1]});
    let mut params = Map::new();
    for e in &c.estimates {
        params.insert(e.key.clone(), est(e));
    }
    let mut out = Map::new();
    out.insert("parameters".into(), Value::Object(params));
    out.insert("rms_residual".into(), json!(c.rms_residual));
    out.insert("points_used".into(), json!(c.points_used));
    out.insert("points_excluded".into(), json!(c.points_excluded));
    if let Some(o) = &c.offset {
        out.insert("torque_offset".into(), est(o));
    }
    out.insert("inertia".into(), json!(c.inertia));
    out.insert("inertia_fitted".into(), json!(c.inertia_estimate.is_some()));
    if let Some(j) = &c.inertia_estimate {
        out.insert("inertia_estimate".into(), est(j));
    }
    out.insert("temperatures".into(), json!(c.temperatures));
    out.insert("samples_read".into(), json!(c.samples_read));
    out.insert("block_length".into(), json!(c.block_length));
    out.insert("warnings".into(), json!(c.warnings));
    Value::Object(out).to_string()
}

/// The report's line on J: its value and whether it was fitted (with its interval) or given.
pub fn inertia_line(c: &Calibration) -> String {
    match &c.inertia_estimate {
        Some(e) => format!(
            "{} = {} kg.m2 fitted (standard error {:.3e}, 95 % interval [{}, {}]){}",
            e.key,
            exact(e.value),
            e.standard_error,
            exact(e.ci95.0),
            exact(e.ci95.1),
            if c.model == Model::Rig { ", by the quasi-static fit; the rig simulation used it" } else { "" }
        ),
        None => format!("{INERTIA} = {} kg.m2 given (not fitted)", exact(c.inertia)),
    }
}

/// `fit.csv`: every `stride`-th sample of every record (the fit's samples: block means when the
/// records were averaged), measured and fitted (SI units).
pub fn fit_csv(w: &mut dyn Write, c: &Calibration, stride: usize) -> io::Result<()> {
    writeln!(w, "record,time,angle,angular_velocity,load,torque,inertia_torque,fitted_torque,residual,used")?;
    for s in &c.series {
        for i in (0..s.time.len()).step_by(stride.max(1)) {
            let angle = s.angle.as_ref().map_or(String::new(), |a| exact(a[i]));
            writeln!(
                w,
                "{},{},{},{},{},{},{},{},{},{}",
                csv_text(&s.record),
                exact(s.time[i]),
                angle,
                exact(s.angular_velocity[i]),
                exact(s.load[i]),
                exact(s.measured[i]),
                exact(s.inertia_torque[i]),
                exact(s.fitted[i]),
                exact(s.measured[i] - s.fitted[i]),
                u8::from(s.used[i])
            )?;
        }
    }
    Ok(())
}

fn csv_text(s: &str) -> String {
    if s.contains([',', '"', '\n']) { format!("\"{}\"", s.replace('"', "\"\"")) } else { s.to_string() }
}

fn thin<T: Copy>(v: impl Iterator<Item = T>, n: usize) -> Vec<T> {
    let k = n.div_ceil(MAX_POINTS).max(1);
    v.step_by(k).collect()
}

/// The three plots: torque against time, against angle, and the residuals, one panel a record.
pub fn svgs(c: &Calibration) -> Result<(String, String, String)> {
    let shown = &c.series[..c.series.len().min(MAX_PLOTTED)];
    let more = if c.series.len() > MAX_PLOTTED { format!(" (first {MAX_PLOTTED} of {} records)", c.series.len()) } else { String::new() };
    let mut time = Vec::new();
    let mut angle = Vec::new();
    let mut resid = Vec::new();
    for s in shown {
        let n = s.time.len();
        let pts = |f: &dyn Fn(usize) -> (f64, f64)| thin((0..n).map(f), n);
        let used_res: Vec<(f64, f64)> = thin((0..n).filter(|&i| s.used[i]).map(|i| (s.time[i], s.measured[i] - s.fitted[i])), n);
        time.push(
            Chart::new(s.record.clone(), Axis::linear("time [s]"), Axis::linear("torque [N·m]"))
                .series(Series::line("measured", pts(&|i| (s.time[i], s.measured[i]))))
                .series(Series::line("fitted", pts(&|i| (s.time[i], s.fitted[i]))).styled(Style::Dashed))
                .legend(Corner::LowerLeft),
        );
        let (x_label, x): (&str, Box<dyn Fn(usize) -> f64>) = match &s.angle {
            Some(a) => ("pin angle [deg]", Box::new(move |i| a[i].to_degrees())),
            None => ("angular velocity [rad/s]", Box::new(|i| s.angular_velocity[i])),
        };
        angle.push(
            Chart::new(s.record.clone(), Axis::linear(x_label), Axis::linear("torque [N·m]"))
                .series(Series::line("measured", pts(&|i| (x(i), s.measured[i]))))
                .series(Series::line("fitted", pts(&|i| (x(i), s.fitted[i]))).styled(Style::Dashed))
                .legend(Corner::LowerLeft),
        );
        resid.push(
            Chart::new(s.record.clone(), Axis::linear("time [s]"), Axis::linear("measured − fitted [N·m]"))
                .series(Series::line("residual (used samples)", used_res).styled(Style::Points))
                .legend(Corner::LowerLeft),
        );
    }
    let h = (360 * shown.len().max(1)) as u32;
    Ok((
        stacked_plot(&format!("Measured and fitted torque against time{more}"), &time, (1000, h))?,
        stacked_plot(&format!("Measured and fitted torque against angle{more}"), &angle, (900, h))?,
        stacked_plot(&format!("Residuals of the used samples{more}"), &resid, (1000, h))?,
    ))
}

/// A block of the report.
enum Block {
    /// A section heading.
    Heading(String),
    /// A paragraph of text.
    Para(String),
    /// A table: header cells, then rows of cells.
    Table(Vec<String>, Vec<Vec<String>>),
    /// An SVG plot: its file name and its index in the inline list.
    Plot(&'static str, usize),
}

fn g(v: f64) -> String {
    if v == 0.0 || (1e-3..1e5).contains(&v.abs()) { format!("{v:.6}") } else { format!("{v:.4e}") }
}

/// The report's paragraph on the model fitted.
fn model_text(c: &Calibration) -> String {
    let offset = if c.offset.is_some() { "" } else { " (not fitted)" };
    if c.model == Model::Rig {
        let cmds: Vec<String> = c.commands.iter().map(|m| format!("{} rad at {} Hz", g(m.amplitude()), g(m.frequency))).collect();
        return format!(
            "Model of the recorded torque: the rig simulation (pinjoint::rig, as `pinjoint cycle`) with J = {} kg·m², started at rest \
             on a sine command estimated from each record's angle ({}), T = T_a + T0 with T0 a fitted sensor offset{offset}. \
             μ_c and the --fit keys by Levenberg-Marquardt (ln/logit coordinates), {} evaluations, {} simulations of the records.",
            g(c.inertia),
            cmds.join("; "),
            c.evaluations,
            c.simulations
        );
    }
    format!(
        "Model of the recorded torque: T = J·α + sign(ω)·μ(P,|ω|)·R·P + T0 with μ = μ_fluid + μ_c/γ2 (eqs. 3, 8, 10, 11); \
         J = {} kg·m² ({}), T0 a fitted sensor offset{offset}. {}",
        g(c.inertia),
        if c.inertia_estimate.is_some() {
            "fitted with μ_c and T0; the torque and the model filtered with the differentiator's matched taps"
        } else {
            "given: J·α subtracted"
        },
        if c.evaluations == 0 {
            "μ_c (and J, T0) by linear least squares on the model's shape (γ2 and μ_fluid do not depend on them).".to_string()
        } else {
            format!("Levenberg-Marquardt over the --fit keys in log/logit coordinates, {} evaluations; μ_c and T0 linear at its optimum.", c.evaluations)
        }
    )
}

fn blocks(c: &Calibration, inputs: &[String], csv_stride: Option<usize>) -> Vec<Block> {
    use Block::*;
    let mut b = vec![Heading("Calibration of the pin-joint friction model".into())];
    b.push(Para(format!("Inputs: {}.", inputs.join(", "))));
    b.push(Para(model_text(c)));
    b.push(Para(format!("Inertia: {}.", inertia_line(c))));
    if !c.temperatures.is_empty() {
        let t: Vec<String> = c.temperatures.iter().map(|t| exact(*t)).collect();
        b.push(Para(format!(
            "Temperatures: the records are at {} K (each evaluated by the joint at its lubricant temperature).",
            t.join(", ")
        )));
    }
    if c.block_length > 1 {
        b.push(Para(format!(
            "Long records: {} samples were read; over the sample budget, every record was averaged in blocks of {} consecutive \
             samples (m = ceil(samples / budget)) as it was read, and the fit, the counts and fit.csv are of the block means.",
            c.samples_read, c.block_length
        )));
    }
    b.push(Heading("Fitted values".into()));
    let rows = c
        .estimates
        .iter()
        .chain(c.inertia_estimate.iter())
        .chain(c.offset.iter())
        .map(|e| {
            vec![
                e.key.clone(),
                if e.unit == "1" { "-".into() } else { e.unit.to_string() },
                g(e.initial),
                g(e.value),
                g(e.standard_error),
                format!("[{}, {}]", g(e.ci95.0), g(e.ci95.1)),
                g(e.standard_error_iid),
                e.standard_error_cluster.map_or("-".into(), g),
                e.bootstrap_ci95.map_or("-".into(), |(lo, hi)| format!("[{}, {}]", g(lo), g(hi))),
            ]
        })
        .collect();
    b.push(Table(
        ["key", "unit", "start", "fitted", "standard error", "95 % interval", "s.e. (iid)", "s.e. (strokes)", "bootstrap 95 %"].map(String::from).to_vec(),
        rows,
    ));
    b.push(Para(format!(
        "Standard error: the larger of the iid σ²(JᵀJ)⁻¹ and the cluster-robust (strokes as clusters) estimate; the \
         95 % interval is its Student-t interval ({} degrees of freedom, quantile {:.3}) joined with the bootstrap over strokes \
         (when there are at least 20). rms residual {:.4} N·m over {} samples used; {} excluded; {} strokes. Condition number \
         of the scaled normal matrix {:.3e}.",
        c.dof, c.quantile, c.rms_residual, c.points_used, c.points_excluded, c.strokes, c.condition
    )));
    if c.correlation_keys.len() > 1 {
        b.push(Heading("Correlations".into()));
        let mut head = vec![String::new()];
        head.extend(c.correlation_keys.iter().cloned());
        let rows = c.correlation_keys.iter().zip(&c.correlation).map(|(k, r)| std::iter::once(k.clone()).chain(r.iter().map(|v| format!("{v:.4}"))).collect()).collect();
        b.push(Table(head, rows));
    }
    b.push(Heading("Warnings".into()));
    if c.warnings.is_empty() {
        b.push(Para("None.".into()));
    }
    for w in &c.warnings {
        b.push(Para(format!("⚠ {w}")));
    }
    b.push(Heading("Excluded samples".into()));
    b.push(Para(if c.model == Model::Rig {
        format!(
            "Rule (rig model): every sample is fitted (the stick, breakaway peak and servo ringing are what the rig \
             describes) except the start-up: up to the first reversal plus the settling time ({} s), since the simulation starts \
             at rest and a record taken from a running rig does not.",
            g(c.settle_time)
        )
    } else {
        format!(
            "Rule: a sample is left out when |ω| is below the speed threshold (the stated fraction of the record's 95th-percentile \
             speed: the stick and static peak at each reversal), or within the settling time ({} s used) after the motion rose \
             above that threshold past a reversal, or after the record's start (breakaway, servo ringing).",
            g(c.settle_time)
        )
    }));
    let rows = c
        .exclusions
        .iter()
        .zip(&c.half_widths)
        .map(|(x, k)| {
            vec![
                x.record.clone(),
                g(x.speed_threshold),
                x.reversals.len().to_string(),
                x.low_speed.to_string(),
                (x.settling + x.start_up).to_string(),
                x.used.to_string(),
                k.to_string(),
            ]
        })
        .collect();
    b.push(Table(
        ["record", "speed threshold [rad/s]", "reversals", "low speed", "settling or start-up", "used", "differentiator half-width [samples]"].map(String::from).to_vec(),
        rows,
    ));
    for x in &c.exclusions {
        let list: Vec<String> = x
            .windows
            .iter()
            .take(12)
            .map(|w| format!("{}–{} s ({}, {} samples)", g(w.start), g(w.end), match w.reason {
                Reason::LowSpeed => "low speed",
                Reason::Settling => "settling",
                Reason::StartUp => "start-up",
            }, w.samples))
            .collect();
        let more = x.windows.len().saturating_sub(12);
        b.push(Para(format!("{}: {}{}", x.record, list.join("; "), if more > 0 { format!("; … and {more} more windows (all in fit.csv, column used)") } else { String::new() })));
    }
    b.push(Heading("Plots".into()));
    b.push(Plot("torque_time.svg", 0));
    b.push(Plot("torque_angle.svg", 1));
    b.push(Plot("residuals.svg", 2));
    let samples: usize = c.series.iter().map(|s| s.time.len()).sum();
    let csv = match csv_stride {
        None => "No fit.csv was written (--fit-csv-rows 0).".to_string(),
        Some(1) => format!("fit.csv holds every sample ({samples} rows): measured, J·α, fitted, residual and whether it was used."),
        Some(k) => format!(
            "fit.csv holds every {k}-th of the {samples} samples ({} rows, --fit-csv-rows): measured, J·α, fitted, residual and \
             whether it was used.",
            samples.div_ceil(k)
        ),
    };
    b.push(Para(format!(
        "calibrated.toml holds the complete parameter set with {MU_C} = {} (and any --fit keys); pass it as --params or load \
         its values as the FMUs' start values. {csv}",
        exact(c.params.friction.boundary_friction_coefficient)
    )));
    b
}

/// `report.md`.
pub fn report_md(c: &Calibration, inputs: &[String], csv_stride: Option<usize>) -> String {
    let mut s = String::new();
    for b in blocks(c, inputs, csv_stride) {
        match b {
            Block::Heading(h) => s.push_str(&format!("## {h}\n\n")),
            Block::Para(p) => s.push_str(&format!("{p}\n\n")),
            Block::Table(head, rows) => {
                let cell = |x: &String| x.replace('|', "\\|");
                s.push_str(&format!("| {} |\n|{}\n", head.iter().map(cell).collect::<Vec<_>>().join(" | "), "---|".repeat(head.len())));
                for r in rows {
                    s.push_str(&format!("| {} |\n", r.iter().map(cell).collect::<Vec<_>>().join(" | ")));
                }
                s.push('\n');
            }
            Block::Plot(file, _) => s.push_str(&format!("![{file}]({file})\n\n")),
        }
    }
    s.replacen("## ", "# ", 1)
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// `report.html`, with the plots inline.
pub fn report_html(c: &Calibration, inputs: &[String], csv_stride: Option<usize>, svg: [&str; 3]) -> String {
    let mut s = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>pinjoint calibrate</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:auto}\
         table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}</style></head><body>\n",
    );
    let mut first = true;
    for b in blocks(c, inputs, csv_stride) {
        match b {
            Block::Heading(h) => {
                let tag = if first { "h1" } else { "h2" };
                first = false;
                s.push_str(&format!("<{tag}>{}</{tag}>\n", esc(&h)));
            }
            Block::Para(p) => s.push_str(&format!("<p>{}</p>\n", esc(&p))),
            Block::Table(head, rows) => {
                s.push_str("<table><tr>");
                for h in head {
                    s.push_str(&format!("<th>{}</th>", esc(&h)));
                }
                s.push_str("</tr>\n");
                for r in rows {
                    s.push_str("<tr>");
                    for x in r {
                        s.push_str(&format!("<td>{}</td>", esc(&x)));
                    }
                    s.push_str("</tr>\n");
                }
                s.push_str("</table>\n");
            }
            Block::Plot(file, i) => s.push_str(&format!("<figure>{}<figcaption>{file}</figcaption></figure>\n", svg[i])),
        }
    }
    s.push_str("</body></html>\n");
    s
}
