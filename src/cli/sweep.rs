//! `pinjoint sweep`: evaluate every row of a CSV file, in parallel, order preserved.

use super::common::{csv_io, result_fields, ParamsArg, RESULT_COLUMNS};
use super::error::{CliError, Result};
use super::fidelity_args::{note_fallback, range_of, FidelityArgs};
use super::output::{to_stdout, write_atomic};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use pinjoint::fidelity::Evaluator;
use pinjoint::{Joint, OperatingPoint};
use std::sync::atomic::AtomicBool;
use rayon::prelude::*;
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
#[command(
    about = "Evaluate the model at every row of a CSV file of loads and speeds",
    long_about = "Evaluate the model at every row of a CSV file, on every core, keeping the row order.\n\n\
INPUT: a header row naming at least the columns `load` (N, > 0) and `speed` (angular velocity \
in rad/s; the model uses its magnitude), in any order, and optionally `temperature` (lubricant temperature in K, per row; otherwise --temperature or the parameter file's). Other columns are allowed and copied \
through unchanged (e.g. a case id), but must not reuse an output column's name. Spaces around \
fields are ignored; blank lines and lines starting with # are skipped.\n\n\
OUTPUT: the input columns as given, followed by friction_coefficient (-), torque (N·m, eq. 11's \
magnitude μRP_T), film_thickness (m, central h_c), lambda_ratio (-), fluid_load_fraction (1/γ1), \
asperity_load_fraction (1/γ2), mean_pressure (Pa), contact_half_width (m), sommerfeld_number (-) \
regime (boundary | mixed | full-film), then min_film_thickness (m, h_min: Pan–Hamrock line-contact ratio applied to h_c) and min_lambda_ratio (-, eq. 21 with h_min). Numbers are printed in full (shortest text that \
reads back as the same double). Without --output the CSV goes to standard output.\n\n\
A malformed row (missing field, non-numeric, non-finite, load <= 0) stops the run with an \
error naming its line; no output file is written then (the file is written to a temporary \
name beside it and renamed only on success).\n\n\
Examples:\n  \
printf 'load,speed\\n20000,0.2\\n60000,4.39\\n' > pts.csv\n  \
pinjoint sweep --input pts.csv\n  \
pinjoint sweep --input pts.csv --output results.csv --params my-joint.toml\n  \
pinjoint sweep --input pts.csv --fidelity auto --tolerance 1e-4\n\n\
FIDELITY: --fidelity table|boundary|auto builds that level once over the envelope, by default \
the input's own load range and |speed| range (or --envelope-load/--envelope-speed), and \
standard error says which level answered (what auto picked) and the error bound it measured. \
Rows outside a given envelope are answered by the full solve (said once on standard error)."
)]
pub struct SweepCmd {
    /// Input CSV with columns `load` (N) and `speed` (rad/s); `-` reads standard input
    #[arg(long, value_name = "FILE.csv")]
    pub input: PathBuf,
    /// Output CSV (written atomically); standard output when absent or `-`
    #[arg(long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub params: ParamsArg,
    #[command(flatten)]
    pub fidelity: FidelityArgs,
}

/// One validated input row.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub line: u64,
    pub fields: Vec<String>,
    pub load: f64,
    pub speed: f64,
    /// Lubricant temperature (K) of this row, from the optional `temperature` column.
    pub temperature: Option<f64>,
}

/// The parsed input: its header and rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Row>,
}

fn is_stdio(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// 1-based line numbers from byte offsets, counting every line (blank and comment lines too).
struct Lines<'a> {
    text: &'a [u8],
    /// Byte offset of each line's first character.
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    fn new(text: &'a [u8]) -> Self {
        let starts = std::iter::once(0).chain(text.iter().enumerate().filter(|(_, b)| **b == b'\n').map(|(i, _)| i + 1)).collect();
        Self { text, starts }
    }
    /// The line of the record that the csv reader places at `byte`. The reader reports a
    /// position before the line terminator, blank lines and comment lines it then skips,
    /// so step over those to the record's first character.
    fn of(&self, byte: u64) -> u64 {
        let t = self.text;
        let mut b = (byte as usize).min(t.len());
        loop {
            while b < t.len() && matches!(t[b], b'\r' | b'\n') {
                b += 1;
            }
            let at_line_start = b == 0 || t[b - 1] == b'\n';
            if b < t.len() && t[b] == b'#' && at_line_start {
                b = t[b..].iter().position(|&c| c == b'\n').map_or(t.len(), |i| b + i + 1);
                continue;
            }
            break;
        }
        self.starts.partition_point(|&start| start <= b) as u64
    }
}

/// Parse and validate the whole input before anything is computed or written.
pub fn parse(mut input: impl Read, file: &str) -> Result<Table> {
    let bad = |line: u64, message: String| CliError::Input { file: file.to_string(), line, message };
    let mut text = Vec::new();
    input.read_to_end(&mut text).map_err(|source| CliError::Read { path: file.into(), source })?;
    let lines = Lines::new(&text);
    let line_of = |pos: Option<&csv::Position>| pos.map_or(1, |p| lines.of(p.byte()));
    let csv_err = |e: csv::Error| bad(line_of(e.position()), format!("unreadable CSV: {e}"));
    let mut rdr = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .flexible(true)
        .comment(Some(b'#'))
        .from_reader(text.as_slice());
    let header: Vec<String> = rdr.headers().map_err(csv_err)?.iter().map(str::to_string).collect();
    let header_line = rdr.headers().ok().map_or(1, |h| line_of(h.position()));
    if header.is_empty() || header.iter().all(String::is_empty) {
        return Err(bad(header_line, "no header row: the first line must name the columns, e.g. `load,speed`".into()));
    }
    let find = |name: &str| -> Result<usize> {
        let hits: Vec<usize> = header.iter().enumerate().filter(|(_, h)| *h == name).map(|(i, _)| i).collect();
        match hits.as_slice() {
            [i] => Ok(*i),
            [] => Err(bad(header_line, format!("the header has no `{name}` column (it reads: {})", header.join(",")))),
            _ => Err(bad(header_line, format!("the header names the column `{name}` more than once"))),
        }
    };
    let (il, is) = (find("load")?, find("speed")?);
    let it = if header.iter().any(|h| h == "temperature") { Some(find("temperature")?) } else { None };
    if let Some(clash) = header.iter().find(|h| RESULT_COLUMNS.contains(&h.as_str())) {
        return Err(bad(header_line, format!("input column `{clash}` has the name of an output column; rename it")));
    }

    let mut rows = Vec::new();
    for rec in rdr.records() {
        let rec = rec.map_err(csv_err)?;
        let line = line_of(rec.position());
        if rec.len() != header.len() {
            let detail = if rec.len() < header.len() {
                format!("missing column(s) {}", header[rec.len()..].join(","))
            } else {
                format!("{} more field(s) than the header's columns", rec.len() - header.len())
            };
            return Err(bad(
                line,
                format!("{detail}: the row has {} field(s), the header {} ({})", rec.len(), header.len(), header.join(",")),
            ));
        }
        let num = |i: usize, name: &str, unit: &str| -> Result<f64> {
            let text = &rec[i];
            if text.is_empty() {
                return Err(bad(line, format!("column {name} ({unit}) is empty")));
            }
            let v: f64 = text.parse().map_err(|_| bad(line, format!("column {name} = `{text}` is not a number ({unit})")))?;
            if !v.is_finite() {
                return Err(bad(line, format!("column {name} = {text} {unit} is not a finite number")));
            }
            Ok(v)
        };
        let load = num(il, "load", "N")?;
        if load <= 0.0 {
            return Err(bad(line, format!("column load = {} N is invalid: the load must be > 0 N", &rec[il])));
        }
        let speed = num(is, "speed", "rad/s")?;
        let temperature = it.map(|i| num(i, "temperature", "K")).transpose()?;
        rows.push(Row { line, fields: rec.iter().map(str::to_string).collect(), load, speed, temperature });
    }
    Ok(Table { header, rows })
}

/// The joints of the rows' distinct temperatures (rows without one use `joint`), each
/// validated; a bad temperature is an error naming its line.
fn joints_by_temperature(joint: &Joint, rows: &[Row], file: &str) -> Result<std::collections::HashMap<u64, Joint>> {
    let mut out = std::collections::HashMap::new();
    for row in rows {
        if let Some(t) = row.temperature {
            if let std::collections::hash_map::Entry::Vacant(e) = out.entry(t.to_bits()) {
                let mut p = *joint.params();
                p.lubricant.temperature = t;
                let j = Joint::new(&p).map_err(|err| CliError::Input { file: file.to_string(), line: row.line, message: err.to_string() })?;
                e.insert(j);
            }
        }
    }
    Ok(out)
}

/// Evaluate every row on every core; results are in row order. A row with a `temperature`
/// is evaluated with the lubricant at that temperature.
pub fn evaluate(joint: &Joint, rows: &[Row], file: &str) -> Result<Vec<OperatingPoint>> {
    let by_t = joints_by_temperature(joint, rows, file)?;
    let bar = if rows.len() >= 20_000 { ProgressBar::new(rows.len() as u64) } else { ProgressBar::hidden() };
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} points, {per_sec}, eta {eta}").expect("valid template"));
    let out = rows
        .par_chunks(256)
        .map(|chunk| {
            let r: Result<Vec<_>> = chunk
                .iter()
                .map(|row| {
                    let joint = row.temperature.map_or(joint, |t| &by_t[&t.to_bits()]);
                    joint.evaluate(row.load, row.speed).map_err(|e| CliError::Input {
                        file: file.to_string(),
                        line: row.line,
                        message: e.to_string(),
                    })
                })
                .collect();
            bar.inc(chunk.len() as u64);
            r
        })
        .collect::<Result<Vec<Vec<_>>>>()?;
    bar.finish_and_clear();
    Ok(out.into_iter().flatten().collect())
}

/// Evaluate every row through (clones of) `ev`, on every core; results in row order.
pub fn evaluate_with(ev: &Evaluator, rows: &[Row], file: &str) -> Result<Vec<OperatingPoint>> {
    let said = AtomicBool::new(false);
    let out = rows
        .par_chunks(256)
        .map_init(
            || ev.clone(),
            |ev, chunk| {
                chunk
                    .iter()
                    .map(|row| {
                        let e = ev.evaluate(row.load, row.speed).map_err(|e| CliError::Input {
                            file: file.to_string(),
                            line: row.line,
                            message: e.to_string(),
                        })?;
                        note_fallback(&e, ev, &said);
                        Ok(ev.operating_point(&e))
                    })
                    .collect::<Result<Vec<_>>>()
            },
        )
        .collect::<Result<Vec<Vec<_>>>>()?;
    Ok(out.into_iter().flatten().collect())
}

/// Write the header and rows: input columns, then the results.
pub fn write_csv(w: &mut dyn Write, table: &Table, results: &[OperatingPoint]) -> io::Result<()> {
    let mut wtr = csv::Writer::from_writer(w);
    let header = table.header.iter().map(String::as_str).chain(RESULT_COLUMNS);
    wtr.write_record(header).map_err(csv_io)?;
    for (row, op) in table.rows.iter().zip(results) {
        wtr.write_record(row.fields.iter().cloned().chain(result_fields(op))).map_err(csv_io)?;
    }
    wtr.flush()?;
    Ok(())
}

pub fn run(cmd: &SweepCmd) -> Result<()> {
    let joint = cmd.params.joint()?;
    let table = if is_stdio(&cmd.input) {
        parse(io::stdin().lock(), "standard input")?
    } else {
        let f = std::fs::File::open(&cmd.input).map_err(|source| CliError::Read { path: cmd.input.clone(), source })?;
        parse(io::BufReader::new(f), &cmd.input.display().to_string())?
    };
    let file = cmd.input.display().to_string();
    let results = if cmd.fidelity.is_full()? {
        evaluate(&joint, &table.rows, &file)?
    } else if table.rows.iter().any(|r| r.temperature.is_some()) {
        return Err(CliError::Invalid(
            "a `temperature` column needs --fidelity full (a table or boundary level is built for one temperature; use --temperature)".into(),
        ));
    } else {
        let loads = range_of(table.rows.iter().map(|r| r.load), (1.0, 2.0));
        let speeds = range_of(table.rows.iter().map(|r| r.speed.abs()), (1e-3, 1.0));
        let ev = cmd.fidelity.build(&cmd.params.load()?, loads, speeds)?;
        evaluate_with(&ev, &table.rows, &file)?
    };
    match &cmd.output {
        Some(path) if !is_stdio(path) => write_atomic(path, |w| write_csv(w, &table, &results)),
        _ => to_stdout(|w| write_csv(w, &table, &results)),
    }
}

