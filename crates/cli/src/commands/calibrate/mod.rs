//! `pinjoint calibrate`: fit the model to measured torque cycles (issue 14).
//!
//! Reads one CSV per test (the columns `pinjoint cycle` writes: `time` s, `angle` rad and/or
//! `angular_velocity` rad/s, `torque` N·m, and `load` N or `--load`), fits with the
//! `pinjoint-calibrate` library and writes `calibrated.toml`, `report.md`, `report.html`,
//! `fit.csv` and three SVG plots (see [`report`]).
//!
//! This folder holds the command (arguments, reading the records, the fit, in this file)
//! and [`report`], what it writes.

pub mod report;

use pinjoint_calibrate as cal;

use self::report::{fit_csv, report_html, report_json, report_md, svgs, toml_file};
use crate::error::{CliError, Result};
use crate::output::{output_dir, report_written, to_stdout, write_atomic, write_text};
use cal::decimate::BlockMean;
use cal::{Calibration, ExclusionRule, Model, Options, Record};
use clap::Args;
use pinjoint::rig::RigConfig;
use std::io::Write;
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
#[command(
    about = "Fit the model to measured torque cycles: mu_c (and any --fit key) with 95 % intervals",
    long_about = "Fit the friction model to recorded torque cycles (several files: several loads and \
frequencies, fitted jointly).\n\n\
Each --input is a CSV with a header naming (as `pinjoint cycle` writes them): time [s], angle [rad] \
and/or angular_velocity [rad/s], torque [N·m] (the recorded actuator torque, positive in the direction \
of motion) and load [N] (or --load for the whole file). Other columns are ignored; '#' starts a comment line.\n\n\
The recorded torque is modelled as T = J·α + sign(ω)·μ(P,|ω|)·R·P + T0 with μ = μ_fluid + μ_c/γ2: \
the rotating inertia J is fitted with μ_c and the offset T0 (all three by linear least squares on the \
model's shape: γ2 and μ_fluid do not depend on them), unless it is given by --inertia or by [rig] inertia \
in --params, then J·α is subtracted. With J fitted, the torque and the model are filtered with the taps \
that make the differentiator's α a weighted mean of the true one, so servo ringing does not bias J. \
--fit adds parameter keys, fitted by Levenberg-Marquardt in log/logit coordinates. \
Velocity, when not recorded, comes from the angle by a Savitzky-Golay cubic over 1/40 of a stroke.\n\n\
Long records: beyond --max-samples samples (all inputs together, default 1e6) every input is averaged in \
blocks of m = ceil(rows / max-samples) consecutive rows as it is read (the report says m); fit.csv holds \
at most --fit-csv-rows rows (every k-th fitted sample; 0 for none).\n\n\
Exclusion rule (reported): samples with |ω| below --speed-fraction × the record's peak speed (95th \
percentile), and the first --settle-time seconds of each stroke above that speed (breakaway peak, servo \
ringing) and of the record.\n\n\
Temperature: --temperature (K; one for all inputs or one per input) or a `temperature` column evaluates each record \
by the joint at its lubricant temperature. With records at 3 or more temperatures (more than 1 K apart) and no --fit, \
the grease's parameters are fitted with μ_c (grease.yield_stress, grease.consistency, the activation temperatures \
grease.yield_activation and grease.consistency_activation, grease.flow_index), each dropped with a warning when the \
records cannot determine it (its Jacobian column nearly collinear with the others', or its standard error larger than \
its value); calibrated.toml then predicts the torque at any temperature between them (pinjoint point --temperature).\n\n\
Intervals: the larger of the iid and the cluster-robust (strokes as clusters) standard error with \
Student-t quantiles, joined with a bootstrap over strokes when there are at least 20.\n\n\
--model rig fits through the rig simulation instead (what `pinjoint cycle` runs: the position loop, \
servo lag, stick and breakaway peak at each reversal): each record is simulated from rest on a sine command \
estimated from its angle (refined by simulation, then fitted jointly: the residuals are the torque and \
K_p × the angle error), and every sample after the start-up (the first reversal plus --settle-time) is fitted, \
reversals included; a recorded angular_velocity is ignored. μ_c, T0 and the --fit keys (model keys and rig.* keys of the [rig] table, e.g. rig.breakaway_factor, \
rig.servo_time_constant; not the excitation or integrator settings) by Levenberg-Marquardt, intervals from \
the Jacobian as above. The rig constants not fitted come from --params [rig]; J is --inertia or [rig] inertia, \
else the quasi-static fit's J (clamped into the rig's range; --fit rig.inertia fits it through the simulation). \
Each evaluation simulates \
every record: at most --max-simulations of them (refused beyond), 2e5 samples and 3600 s of records. \
Use it when the quasi-static fit is biased by stick-slip (slow strokes with a static peak) or to fit the \
rig's own keys.\n\n\
Writes DIR/calibrated.toml (a complete parameter file for --params and as FMU start values), \
DIR/report.md, DIR/report.html, DIR/fit.csv (unless --fit-csv-rows 0), DIR/torque_time.svg, DIR/torque_angle.svg, \
DIR/residuals.svg.\n\n\
Examples:\n  \
pinjoint calibrate --input a.csv --load 20000 --input b.csv --load 40000 --output out/cal\n  \
pinjoint calibrate --input rig.csv --load 20000 --fit lubricant.viscosity --output out/cal --json\n  \
pinjoint calibrate --load 20000 --input a.csv --temperature 253.15 --input b.csv --temperature 273.15 --input c.csv --temperature 293.15 --output out/cal\n  \
pinjoint calibrate --input a.csv --load 20000 --model rig --fit rig.breakaway_factor --output out/cal"
)]
/// Arguments of `pinjoint calibrate` (its `--help` text is the `#[command]` attribute's).
// The field docs are the --help text, where `[rig]`/`[lubricant]` name TOML sections, not
// intra-doc links; rewording them would change --help.
#[allow(rustdoc::broken_intra_doc_links)]
pub struct CalibrateCmd {
    /// A record (CSV); repeat for several
    #[arg(long, value_name = "FILE", required = true)]
    pub input: Vec<PathBuf>,
    /// Radial load in N for inputs without a `load` column (> 0): one value for every input, or
    /// one per --input in the same order (`pinjoint cycle` writes no load column)
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub load: Vec<f64>,
    /// Lubricant temperature in K of inputs without a `temperature` column: one value for every
    /// input, or one per --input in the same order; each record is evaluated at its temperature.
    /// Records at 3 or more temperatures fit the grease's parameters by default (unless --fit names keys)
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    pub temperature: Vec<f64>,
    /// Parameter file (TOML): start values and fixed parameters; a [rig] inertia in it is the given J
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// Parameter keys fitted besides friction.boundary_friction_coefficient (section.key, comma-separated)
    #[arg(long, value_name = "KEY,...", value_delimiter = ',')]
    pub fit: Vec<String>,
    /// Rotating inertia J in kg·m², given: J·α is subtracted [default: the --params file's [rig]
    /// inertia if it has one, else J is fitted with its interval]
    #[arg(long, value_name = "KG_M2", allow_negative_numbers = true)]
    pub inertia: Option<f64>,
    /// The most samples, all inputs together, that enter the fit; longer inputs are averaged in
    /// blocks of m consecutive rows as they are read (m = ceil(rows / max-samples))
    #[arg(long, value_name = "N", default_value_t = cal::MAX_FIT_SAMPLES)]
    pub max_samples: usize,
    /// The most rows of fit.csv (every k-th fitted sample, k = ceil(samples / rows)); 0 writes no fit.csv
    #[arg(long, value_name = "ROWS", default_value_t = DEFAULT_FIT_CSV_ROWS)]
    pub fit_csv_rows: usize,
    /// Do not fit a torque offset
    #[arg(long)]
    pub no_offset: bool,
    /// Exclude samples slower than this fraction of the record's peak speed
    #[arg(long, value_name = "FRACTION", default_value_t = ExclusionRule::default().speed_fraction, allow_negative_numbers = true)]
    pub speed_fraction: f64,
    /// Exclude this many seconds at the start of each stroke above the speed threshold
    #[arg(long, value_name = "S", default_value_t = ExclusionRule::default().settle_time, allow_negative_numbers = true)]
    pub settle_time: f64,
    /// The model fitted: `core`, the quasi-static model away from reversals, or `rig`, the rig
    /// simulation (stick, breakaway peak, servo lag) driven by a sine command estimated from each
    /// record's angle; `rig` also fits rig.* keys (e.g. rig.breakaway_factor, rig.servo_time_constant)
    #[arg(long, value_name = "MODEL", default_value = "core", value_parser = ["core", "rig"])]
    pub model: String,
    /// With --model rig: the most simulations of the record set the fit may run (refused beyond)
    #[arg(long, value_name = "N", default_value_t = cal::rig_fit::DEFAULT_MAX_SIMULATIONS)]
    pub max_simulations: usize,
    /// Output directory (created if needed)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// Print the result as one JSON object on standard output (instead of the summary)
    #[arg(long)]
    pub json: bool,
}

/// The value of input `i` of a flag given once for every input or once per input in order
/// (`values`, the flag's values; `inputs`, the number of --input files): `None` where the flag
/// was not given. Refuses several values that are not one per input, naming the flag (`flag`)
/// and the quantity (`what`).
fn per_input<'a>(values: &'a [f64], flag: &str, what: &str, inputs: usize) -> Result<impl Fn(usize) -> Option<f64> + 'a> {
    if values.len() > 1 && values.len() != inputs {
        return Err(CliError::Invalid(format!(
            "{} {flag} values for {inputs} --input files: give one {what} for all, or one per input in order",
            values.len()
        )));
    }
    Ok(move |i: usize| if values.len() == 1 { Some(values[0]) } else { values.get(i).copied() })
}

/// Runs `pinjoint calibrate`: reads the recorded cycles, fits μ_c (and any --fit key) and
/// writes the report. Fails on invalid flags, unreadable records, or a fit that cannot be made.
pub fn run(cmd: &CalibrateCmd) -> Result<()> {
    if let Some(p) = cmd.load.iter().find(|p| !(p.is_finite() && **p > 0.0)) {
        return Err(CliError::Invalid(format!("--load = {p} N is invalid: it must be a finite number > 0 N")));
    }
    let load_of = per_input(&cmd.load, "--load", "load", cmd.input.len())?;
    if let Some(t) = cmd.temperature.iter().find(|t| !(t.is_finite() && **t >= cal::record::CELSIUS_SUSPECT)) {
        let why = if t.is_finite() { cal::record::celsius_hint(*t) } else { "it must be a finite number of kelvin".into() };
        return Err(CliError::Invalid(format!("--temperature = {t} K is invalid: {why}")));
    }
    let temperature_of = per_input(&cmd.temperature, "--temperature", "temperature", cmd.input.len())?;
    let (config, file_inertia) = match &cmd.params {
        None => (RigConfig::default(), None),
        Some(path) => {
            let text = std::fs::read_to_string(path).map_err(|source| CliError::Read { path: path.clone(), source })?;
            let config = RigConfig::from_toml_str(&text).map_err(|source| CliError::ParamFile { path: path.clone(), source })?;
            (config, given_inertia(&text).then_some(config.rig.inertia))
        }
    };
    if cmd.max_samples < MIN_MAX_SAMPLES {
        return Err(CliError::Invalid(format!("--max-samples = {} is invalid: it must be at least {MIN_MAX_SAMPLES}", cmd.max_samples)));
    }
    // Rows of every input (a cheap pass over the bytes), then the block length of the averaging.
    let rows = cmd.input.iter().map(|p| count_rows(p)).collect::<Result<Vec<usize>>>()?;
    let block = cal::decimate::block_length(rows.iter().sum(), cmd.max_samples);
    let records = cmd.input.iter().enumerate().map(|(i, p)| read_record_blocks(p, load_of(i), temperature_of(i), block)).collect::<Result<Vec<_>>>()?;
    if block > 1 {
        cal::decimate::check_blocks(&records, block).map_err(|e| CliError::Invalid(format!("calibrate: {e}")))?;
    }
    let model = if cmd.model == "rig" { Model::Rig } else { Model::Core };
    let options = Options {
        model,
        rig: config.rig,
        max_simulations: cmd.max_simulations,
        params: config.model,
        fit: cmd.fit.iter().map(|k| k.trim().to_string()).filter(|k| !k.is_empty()).collect(),
        inertia: cmd.inertia.or(file_inertia),
        max_samples: cmd.max_samples,
        fit_offset: !cmd.no_offset,
        exclusion: ExclusionRule { speed_fraction: cmd.speed_fraction, settle_time: cmd.settle_time },
        ..Options::default()
    };
    let mut cal = cal::calibrate(&records, &options).map_err(|e| CliError::Invalid(format!("calibrate: {e}")))?;
    cal.samples_read = rows.iter().sum();
    cal.block_length = block;
    let csv_stride = fit_csv_stride(&cal, cmd.fit_csv_rows);
    let dir = output_dir(&cmd.output)?;
    let inputs: Vec<String> = cmd.input.iter().map(|p| p.display().to_string()).collect();
    let (time_svg, angle_svg, resid_svg) = svgs(&cal)?;
    let files: [(&str, String); 6] = [
        ("calibrated.toml", toml_file(&cal, &inputs)),
        ("report.md", report_md(&cal, &inputs, csv_stride)),
        ("report.html", report_html(&cal, &inputs, csv_stride, [&time_svg, &angle_svg, &resid_svg])),
        ("torque_time.svg", time_svg.clone()),
        ("torque_angle.svg", angle_svg.clone()),
        ("residuals.svg", resid_svg.clone()),
    ];
    // Every output is refused if it is one of the inputs (same file), before anything is written.
    let read: Vec<&Path> = cmd.input.iter().map(PathBuf::as_path).chain(cmd.params.as_deref()).collect();
    let mut written = Vec::new();
    if let Some(k) = csv_stride {
        let csv_path = dir.join("fit.csv");
        write_atomic(&csv_path, &read, |w| fit_csv(w, &cal, k))?;
        written.push(csv_path);
    }
    for (name, text) in &files {
        let path = dir.join(name);
        write_text(&path, &read, text)?;
        written.push(path);
    }
    if cmd.json {
        let json = report_json(&cal);
        to_stdout(|w| writeln!(w, "{json}"))
    } else {
        to_stdout(|w| summary(w, &cal))?;
        report_written(&written)
    }
}

/// An output must not replace one of the inputs.
fn summary(w: &mut dyn Write, c: &Calibration) -> std::io::Result<()> {
    for e in c.estimates.iter().chain(c.inertia_estimate.iter()).chain(c.offset.iter()) {
        writeln!(
            w,
            "{} = {:.6} (standard error {:.2e}, 95 % interval {:.6} to {:.6}) {}",
            e.key, e.value, e.standard_error, e.ci95.0, e.ci95.1, if e.unit == "1" { "" } else { e.unit }
        )?;
    }
    if c.inertia_estimate.is_none() {
        writeln!(w, "{} = {} kg.m2 (given, not fitted)", cal::INERTIA, c.inertia)?;
    }
    writeln!(w, "rms residual {:.4} N.m over {} samples used, {} excluded, {} strokes", c.rms_residual, c.points_used, c.points_excluded, c.strokes)?;
    if c.block_length > 1 {
        writeln!(w, "{} samples read, averaged in blocks of {} (the sample budget --max-samples)", c.samples_read, c.block_length)?;
    }
    for x in &c.warnings {
        writeln!(w, "warning: {x}")?;
    }
    Ok(())
}

/// Default `--fit-csv-rows`.
pub const DEFAULT_FIT_CSV_ROWS: usize = 100_000;
/// The smallest `--max-samples` accepted (as the library's check).
pub const MIN_MAX_SAMPLES: usize = 1000;

/// Whether a parameter file's text sets `[rig] inertia` (then J is given, not fitted).
fn given_inertia(text: &str) -> bool {
    text.parse::<toml::Table>().ok().and_then(|t| t.get("rig").and_then(|r| r.as_table()).map(|r| r.contains_key("inertia"))).unwrap_or(false)
}

/// fit.csv's stride k: every k-th fitted sample, at most `rows` rows; None for no file.
fn fit_csv_stride(c: &Calibration, rows: usize) -> Option<usize> {
    let n: usize = c.series.iter().map(|s| s.time.len()).sum();
    (rows > 0).then(|| n.div_ceil(rows).max(1))
}

/// Data rows of a CSV file, counted without parsing: non-blank lines not starting with `#`,
/// less the header. An upper bound of the rows the reader takes (a quoted field spanning
/// lines counts twice), so the block length it gives keeps the sample budget.
pub fn count_rows(path: &Path) -> Result<usize> {
    use std::io::BufRead;
    let file = std::fs::File::open(path).map_err(|source| CliError::Read { path: path.to_path_buf(), source })?;
    let mut reader = std::io::BufReader::with_capacity(1 << 20, file);
    let (mut lines, mut line) = (0usize, Vec::new());
    loop {
        line.clear();
        let n = reader.read_until(b'\n', &mut line).map_err(|source| CliError::Read { path: path.to_path_buf(), source })?;
        if n == 0 {
            break;
        }
        let t = line.trim_ascii();
        if !t.is_empty() && t[0] != b'#' {
            lines += 1;
        }
    }
    Ok(lines.saturating_sub(1))
}

/// Read one record: the header must name `time`, `torque`, `angle` and/or `angular_velocity`,
/// and `load` unless `load` is given; an optional `temperature` column (K) or `temperature`;
/// every value must be a finite number.
pub fn read_record(path: &Path, load: Option<f64>, temperature: Option<f64>) -> Result<Record> {
    read_record_blocks(path, load, temperature, 1)
}

/// Largest difference (K) between a `temperature` column and a --temperature given beside it.
pub const TEMPERATURE_AGREEMENT: f64 = 1.0;

/// [`read_record`], streaming the file and averaging blocks of `block` consecutive rows
/// ([`pinjoint_calibrate::decimate`]) as it reads: memory holds the averaged record only.
pub fn read_record_blocks(path: &Path, load: Option<f64>, temperature: Option<f64>, block: usize) -> Result<Record> {
    let file = path.display().to_string();
    let bad = |line: u64, message: String| CliError::Input { file: file.clone(), line, message };
    let handle = std::fs::File::open(path).map_err(|source| CliError::Read { path: path.to_path_buf(), source })?;
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .flexible(true)
        .comment(Some(b'#'))
        .from_reader(std::io::BufReader::with_capacity(1 << 20, handle));
    let header: Vec<String> = rdr.headers().map_err(|e| bad(1, format!("unreadable CSV: {e}")))?.iter().map(str::to_string).collect();
    let header_line = rdr.headers().ok().and_then(|h| h.position().map(csv::Position::line)).unwrap_or(1);
    let find = |name: &str| -> Result<Option<usize>> {
        let hits: Vec<usize> = header.iter().enumerate().filter(|(_, h)| *h == name).map(|(i, _)| i).collect();
        match hits.as_slice() {
            [] => Ok(None),
            [i] => Ok(Some(*i)),
            _ => Err(bad(header_line, format!("the header names the column `{name}` more than once"))),
        }
    };
    let need = |name: &str, unit: &str, why: &str| -> Result<usize> {
        find(name)?.ok_or_else(|| bad(header_line, format!("the header has no `{name}` column ({unit}){why}; it reads: {}", header.join(","))))
    };
    let it = need("time", "s", "")?;
    let iq = need("torque", "N.m, the recorded actuator torque", "")?;
    let (ia, iw) = (find("angle")?, find("angular_velocity")?);
    if ia.is_none() && iw.is_none() {
        return Err(bad(header_line, format!("the header has neither `angle` (rad) nor `angular_velocity` (rad/s); it reads: {}", header.join(","))));
    }
    let il = match load {
        Some(_) => find("load")?,
        None => Some(need("load", "N", " and no --load was given")?),
    };
    let itemp = find("temperature")?;
    let mut out = BlockMean::new(&file, block, ia.is_some(), iw.is_some());
    if itemp.is_some() || temperature.is_some() {
        out = out.with_temperature();
    }
    let (mut rows, mut previous) = (0usize, f64::NEG_INFINITY);
    let mut rec = csv::StringRecord::new();
    loop {
        match rdr.read_record(&mut rec) {
            Ok(true) => {}
            Ok(false) => break,
            Err(e) => return Err(bad(e.position().map_or(0, csv::Position::line), format!("unreadable CSV: {e}"))),
        }
        let line = rec.position().map_or(0, csv::Position::line);
        let num = |i: usize, name: &str, unit: &str| -> Result<f64> {
            let text = rec.get(i).ok_or_else(|| bad(line, format!("column {name} ({unit}) is missing: the row has {} field(s)", rec.len())))?;
            if text.is_empty() {
                return Err(bad(line, format!("column {name} ({unit}) is empty")));
            }
            let v: f64 = text.parse().map_err(|_| bad(line, format!("column {name} = `{}` is not a number ({unit})", excerpt(text))))?;
            if !v.is_finite() {
                return Err(bad(line, format!("column {name} = {} {unit} is not a finite number", excerpt(text))));
            }
            Ok(v)
        };
        let time = num(it, "time", "s")?;
        let torque = num(iq, "torque", "N.m")?;
        let angle = match ia {
            Some(i) => num(i, "angle", "rad")?,
            None => 0.0,
        };
        let velocity = match iw {
            Some(i) => num(i, "angular_velocity", "rad/s")?,
            None => 0.0,
        };
        let p = match (il, load) {
            (Some(i), given) => {
                // The column is the record; a --load beside it must agree with it (1 %).
                let p = num(i, "load", "N")?;
                if let Some(g) = given
                    && (p - g).abs() > 0.01 * g
                {
                    return Err(bad(line, format!("column load = {p} N disagrees with --load {g} N: drop one")));
                }
                p
            }
            (None, Some(p)) => p,
            (None, None) => unreachable!("load column required above"),
        };
        if p <= 0.0 {
            return Err(bad(line, format!("column load = {p} N is invalid: the load must be > 0 N")));
        }
        if time <= previous {
            return Err(bad(line, format!("time = {time} s does not increase (the row before has {previous} s)")));
        }
        let temp = match (itemp, temperature) {
            (Some(i), given) => {
                // The column is the record; a --temperature beside it must agree with it.
                let t = num(i, "temperature", "K")?;
                if t < cal::record::CELSIUS_SUSPECT {
                    return Err(bad(line, format!("column temperature = {t} K is invalid: {}", cal::record::celsius_hint(t))));
                }
                if let Some(g) = given
                    && (t - g).abs() > TEMPERATURE_AGREEMENT
                {
                    return Err(bad(line, format!("column temperature = {t} K disagrees with --temperature {g} K: drop one")));
                }
                t
            }
            (None, Some(t)) => t,
            (None, None) => 0.0,
        };
        previous = time;
        rows += 1;
        out.push_temperature(time, angle, velocity, torque, p, temp);
    }
    if rows == 0 {
        return Err(bad(header_line, "no data rows".into()));
    }
    Ok(out.finish())
}

/// At most 40 characters of a field, for a message.
fn excerpt(text: &str) -> String {
    let mut e: String = text.chars().take(40).collect();
    if e.len() < text.len() {
        e.push('…');
    }
    e
}
