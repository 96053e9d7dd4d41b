//! `pinjoint figures`: the paper's Figures 3, 4, 7, 8–10 (simulated side) and 11–13 in one run,
//! on the built-in parameters, with an index page and a README in the output directory.
//!
//! This folder holds the command and its parts, each in a module (in dependency order):
//! [`rig`] simulates the paper's 15 rig conditions; [`mod@claims`] computes the claims table;
//! [`plots`] draws Figures 7–13; [`index`] writes the captions, `index.html` and `README.md`;
//! [`starvation`] and [`at_rest`] are the extensions' figures; [`cold_day`] the cold-day scene. This file holds the
//! command's arguments and [`run`], which writes Figures 3 and 4 (through `stribeck` and
//! `map`) and calls the parts. A new figure goes in a module of its own here, declared
//! below and called from [`run`], with an entry in [`index`].

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod rig;
pub mod claims;
pub mod plots;
pub mod index;
pub mod starvation;
pub mod at_rest;
pub mod cold_day;

use crate::common::{csv_table, exact, lin_space, log_space, readable, PAPER_RPM_RANGE, RAD_S_PER_RPM};
use crate::error::Result;
use self::claims::claims;
use self::index::{entries, html, markdown, RunInfo};
use self::plots::{fig10_svg, fig7_svg, fig8_svg, fig9_svg, nominal_speed, torque_cycle_svg, CoreCurves};
use self::rig::{at_frequency, averages_csv, conditions, find, simulate_all, traces_csv, RigResult, RigSettings, PAPER_FREQUENCIES};
use crate::curves::map::{write_map, Grid};
use pinjoint::paper::LOADS as PAPER_LOADS;
use crate::output::{output_dir, to_stdout, write_atomic, write_text};
use crate::curves::stribeck::{write_stribeck, DEFAULT_SPEED_RANGE};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use pinjoint::rig::RigConfig;
use pinjoint::Joint;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Args, Debug)]
#[command(
    about = "Reproduce the paper's figures (3, 4, 7, 8-10 simulated, 11-13) in one run, with index.html",
    long_about = "Reproduce the paper's figures on the built-in parameters and write them, with the data \
behind each, into DIR:\n  \
stribeck.svg/.csv                 Figure 3: μ, 1/γ1, 1/γ2, λ against Sommerfeld number at 20 kN\n  \
map_lambda.svg, map_friction.svg, map_curves.svg, map.csv   Figure 4: λ and μ over 5-60 kN, 1-800 rpm\n  \
fig07_cycle_1Hz_20kN.svg/.csv     Figure 7: one 1 Hz stroke (angle, speed, torque against time and angle)\n  \
fig08_mu_sommerfeld.svg           Figure 8: cycle-average μ (eq. 11) against Sommerfeld number\n  \
fig09_mu_sliding_speed.svg        Figure 9: ... against sliding speed\n  \
fig10_mu_load.svg                 Figure 10: ... against load\n  \
rig_averages.csv, core_curves.csv the data of Figures 8-10\n  \
fig11_torque_0.03Hz.svg/.csv, fig12_torque_0.3Hz.svg/.csv, fig13_torque_1Hz.svg/.csv   Figures 11-13\n  \
at_rest_hold.svg/.csv, at_rest_loop.svg/.csv   friction at rest: band against presliding\n  \
cold_day.svg/.csv, cold_day_series.csv   the cold-day scene: a main gear's free-fall extension at +20, -20, -40, -54 C\n  \
index.html, README.md             every figure with a caption comparing it with the paper\n\
The rig side is 15 simulations (loads 5, 10, 20, 40, 60 kN × 0.03, 0.3, 1 Hz, ±40°), two strokes \
each from rest, the first left out, run on every core. The x value of a run in Figures 8 and 9 is \
the time-mean of |ω| over the averaged stroke. Progress is shown on standard error when it is a \
terminal. A full run takes a few seconds in a release build; --quick is coarser still.\n\n\
The figures run on the paper's model (model.paper = true, the comparison the captions make); \
--complete runs them on the complete model.\n\n\
Example:\n  pinjoint figures --output figures"
)]
/// Arguments of `pinjoint figures` (its `--help` text is the `#[command]` attribute's).
pub struct FiguresCmd {
    /// Output directory (created if needed)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// Coarser sweeps, fewer samples, looser tolerances: every file, a fraction of the time
    #[arg(long)]
    pub quick: bool,
    /// Run the figures on the complete model (model.paper = false: journal bearing, grease in
    /// the clearance, cold supply) instead of the paper's model, which the comparison with the
    /// paper and the claims table are written for
    #[arg(long)]
    pub complete: bool,
}

/// Sizes of the core sweeps.
struct CoreSettings {
    stribeck_points: usize,
    map_loads: usize,
    map_speeds: usize,
    curve_points: usize,
}

impl CoreSettings {
    fn new(quick: bool) -> Self {
        if quick {
            Self { stribeck_points: 41, map_loads: 12, map_speeds: 30, curve_points: 30 }
        } else {
            Self { stribeck_points: 121, map_loads: 56, map_speeds: 100, curve_points: 120 }
        }
    }
}

/// `core_curves.csv`: the model's lines of Figures 8–10, the eq. 11 stroke averages: one row
/// per (load, frequency) of the frequency sweep (`curve` = `stroke_average_vs_frequency`) and of
/// the load sweep (`stroke_average_vs_load`), with both speed readings of a stroke: the paper's
/// nominal ω = 2πf and the mean |ω| = 4Af.
fn core_csv(w: &mut dyn std::io::Write, core: &CoreCurves, pin_radius: f64, amplitude: f64) -> std::io::Result<()> {
    let header = [
        "curve",
        "frequency",
        "load",
        "nominal_speed",
        "mean_speed",
        "nominal_sliding_speed",
        "sommerfeld_number_nominal",
        "sommerfeld_number_mean_speed",
        "friction_coefficient",
    ];
    let row = move |curve: &str, f: f64, p: f64, s_per: f64, mu: f64| {
        let (nominal, mean) = (nominal_speed(f), 4.0 * amplitude * f);
        let vals = [f, p, nominal, mean, nominal * pin_radius, s_per * nominal, s_per * mean, mu];
        std::iter::once(curve.to_string()).chain(vals.map(exact))
    };
    let by_frequency = PAPER_LOADS.iter().zip(&core.curves).zip(&core.s_per_rad_s).flat_map(|((&p, curve), &s_per)| {
        curve.iter().map(move |&(f, mu)| row("stroke_average_vs_frequency", f, p, s_per, mu))
    });
    let by_load = PAPER_FREQUENCIES.iter().zip(&core.stroke_averages).flat_map(|(&f, averages)| {
        core.loads.iter().zip(averages).zip(&core.load_s_per_rad_s).map(move |((&p, &mu), &s_per)| row("stroke_average_vs_load", f, p, s_per, mu))
    });
    csv_table(w, header, by_frequency.chain(by_load))
}

fn progress(total: u64) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(total);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} [{elapsed}]").expect("valid template"));
    bar
}

/// The core figures (3, 4) into `dir`.
fn core_figures(dir: &Path, joint: &Joint, s: &CoreSettings) -> Result<Vec<PathBuf>> {
    let (lo, hi) = DEFAULT_SPEED_RANGE;
    let mut paths = write_stribeck(dir, &[], joint, 20e3, &log_space(lo, hi, s.stribeck_points))?;
    let grid = Grid {
        loads: lin_space(PAPER_LOADS[0], PAPER_LOADS[PAPER_LOADS.len() - 1], s.map_loads),
        speeds: log_space(PAPER_RPM_RANGE.0 * RAD_S_PER_RPM, PAPER_RPM_RANGE.1 * RAD_S_PER_RPM, s.map_speeds),
    };
    paths.extend(write_map(dir, &[], joint, &grid)?);
    Ok(paths)
}

/// Writes one CSV's content.
type CsvFill<'a> = Box<dyn Fn(&mut dyn std::io::Write) -> std::io::Result<()> + 'a>;

/// Render and write Figures 7–13 and their data.
fn rig_figures(dir: &Path, results: &[RigResult], core: &CoreCurves, pin_radius: f64, amplitude: f64) -> Result<Vec<PathBuf>> {
    let mut files: Vec<(String, String)> = Vec::new();
    let mut csvs: Vec<(&str, CsvFill<'_>)> = Vec::new();
    if let Some(r) = find(results, 1.0, 20e3) {
        files.push(("fig07_cycle_1Hz_20kN.svg".into(), fig7_svg(r)?));
        csvs.push(("fig07_cycle_1Hz_20kN.csv", Box::new(move |w| traces_csv(w, &[&r.run]))));
    }
    files.push(("fig08_mu_sommerfeld.svg".into(), fig8_svg(results, core)?));
    files.push(("fig09_mu_sliding_speed.svg".into(), fig9_svg(results, core, pin_radius)?));
    files.push(("fig10_mu_load.svg".into(), fig10_svg(results, core)?));
    csvs.push(("rig_averages.csv", Box::new(|w| averages_csv(w, results))));
    csvs.push(("core_curves.csv", Box::new(move |w| core_csv(w, core, pin_radius, amplitude))));
    let names = ["fig11_torque_0.03Hz", "fig12_torque_0.3Hz", "fig13_torque_1Hz"];
    for ((i, &f), name) in PAPER_FREQUENCIES.iter().enumerate().zip(names) {
        files.push((format!("{name}.svg"), torque_cycle_svg(results, f, 20e3, 11 + i as u32)?));
        let runs: Vec<_> = at_frequency(results, f).into_iter().map(|r| &r.run).collect();
        csvs.push((["fig11_torque_0.03Hz.csv", "fig12_torque_0.3Hz.csv", "fig13_torque_1Hz.csv"][i], Box::new(move |w| traces_csv(w, &runs))));
    }
    let mut paths = Vec::new();
    for (name, svg) in &files {
        let p = dir.join(name);
        write_text(&p, &[], svg)?;
        paths.push(p);
    }
    for (name, fill) in &csvs {
        let p = dir.join(name);
        write_atomic(&p, &[], |w| fill(w))?;
        paths.push(p);
    }
    Ok(paths)
}

/// Runs `pinjoint figures`: computes every figure on the built-in parameters and writes them,
/// their data, README.md and index.html into the output directory.
pub fn run(cmd: &FiguresCmd) -> Result<()> {
    let start = Instant::now();
    let mut cfg = RigConfig::default();
    // The paper's figures on the paper's model (model.paper = true) unless asked otherwise.
    cfg.model.model.paper = !cmd.complete;
    let joint = Joint::new(&cfg.model)?;
    let pin_radius = cfg.model.geometry.pin_radius;
    let core_settings = CoreSettings::new(cmd.quick);
    let rig_settings = if cmd.quick { RigSettings::quick() } else { RigSettings::full() };
    let dir = output_dir(&cmd.output)?;

    let bar = progress(conditions().len() as u64 + 3);
    bar.set_message("rig runs and core sweeps");
    let (core_paths, rig) = rayon::join(
        || {
            let paths = core_figures(&dir, &joint, &core_settings);
            bar.inc(1);
            let curves = CoreCurves::compute(&joint, cfg.rig.amplitude, core_settings.curve_points);
            bar.inc(1);
            paths.and_then(|p| curves.map(|c| (p, c)))
        },
        || simulate_all(&joint, &cfg, rig_settings, &bar),
    );
    let (mut paths, core) = core_paths?;
    let results = rig?;
    bar.set_message("figures");
    paths.extend(rig_figures(&dir, &results, &core, pin_radius, cfg.rig.amplitude)?);
    // The starved-inlet extension (off by default): how it moves Fig. 3 and the 1 Hz cycle.
    paths.extend(self::starvation::write(&dir, &cfg.model)?);
    // Friction at rest: the band and the presliding state under a holding drive and a small loop.
    paths.extend(self::at_rest::write(&dir, &cfg.model)?);
    // The cold-day scene: a main gear's free-fall extension at four temperatures. Its joint has
    // the library's default parameters, whatever model the paper's figures are drawn with.
    let (cold_paths, cold_entry) = self::cold_day::write(&dir, &pinjoint::Params::default())?;
    paths.extend(cold_paths);
    let info = RunInfo { quick: cmd.quick, samples_per_cycle: rig_settings.samples_per_cycle, rtol: rig_settings.rtol, atol: rig_settings.atol };
    let mut list = entries(&joint, &results, &core)?;
    list.push(cold_entry);
    let table = claims(&joint, &results, cfg.rig.amplitude)?;
    for (name, text) in [("index.html", html(&list, &table, &info)), ("README.md", markdown(&list, &table, &info))] {
        let p = dir.join(name);
        write_text(&p, &[], &text)?;
        paths.push(p);
    }
    bar.inc(1);
    bar.finish_and_clear();
    let elapsed = start.elapsed().as_secs_f64();
    to_stdout(|w| {
        for p in &paths {
            writeln!(w, "wrote {}", p.display())?;
        }
        writeln!(w, "figures: {} files in {} ({} s); open {}", paths.len(), dir.display(), readable((elapsed * 10.0).round() / 10.0), dir.join("index.html").display())
    })
}
