//! `pinjoint sweep`: evaluate every row of a CSV file, in parallel, order preserved,
//! streaming: read, evaluate and write in bounded batches (memory independent of the
//! number of rows). The batches are parsed, evaluated and formatted in chunks on every core,
//! the chunks of two batches queued at once (no core waits at a batch's end), while this
//! thread writes the batch before and reads the batch after.
//!
//! This folder holds the command (arguments, evaluation and output, in this file),
//! [`input`], which reads the CSV records in bounded batches, and `spill`, which keeps the
//! parsed rows between the two passes of a Parquet sweep whose level is built over the
//! input's own ranges (the input is then parsed once).

pub mod input;
mod spill;

use crate::common::{csv_io, ParamsArg, RESULT_COLUMNS};
use crate::error::{CliError, Result};
use crate::exact::push_exact;
use crate::fidelity_args::{note_fallback, range_of, FidelityArgs};
use crate::columnar::{self, Values};
use crate::output::{refuse_inputs, to_stdout, write_atomic, write_atomic_send};
use self::input::{Batch, Fields, RecordReader};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use pinjoint::fidelity::Evaluator;
use pinjoint::{Joint, OperatingPoint};
use rayon::prelude::*;
use std::io::{self, BufRead, Seek, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::collections::VecDeque;
use std::sync::{Arc, Mutex};

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
regime (boundary | mixed | full-film), then min_film_thickness (m, h_min: Pan–Hamrock line-contact ratio applied to h_c), min_lambda_ratio (-, eq. 21 with h_min) and validity (checked | extrapolation | known-wrong | outside: whether load, sliding speed and temperature are inside the paper's rig conditions, outside them, below 0 C where μ is known to be too low, or past the model's assumptions (the Hertz half-width beyond the pin radius, the grease above its upper service temperature); see docs/validity.md). Numbers are printed in full (shortest text that \
reads back as the same double). Without --output the CSV goes to standard output.\n\n\
PARQUET: --output FILE.parquet (or --format parquet) writes the same columns as Apache Parquet: \
numbers as DOUBLE columns bit for bit, regime and validity as text, other input columns as text, \
in row groups of 65536 rows. --input FILE.parquet reads the numeric columns load, speed and \
optionally temperature (other columns are not copied).\n\n\
A malformed row (missing field, non-numeric, non-finite, load = 0; a negative load is taken as its magnitude) stops the run with an \
error naming its line; no output file is written then (the file is written to a temporary \
name beside it and renamed only on success). The input is read, evaluated and written in \
batches of 16384 rows, so memory does not grow with the number of rows; on standard output the \
rows of the batches before a malformed one have already been written.\n\n\
Examples:\n  \
printf 'load,speed\\n20000,0.2\\n60000,4.39\\n' > pts.csv\n  \
pinjoint sweep --input pts.csv\n  \
pinjoint sweep --input pts.csv --output results.csv --params my-joint.toml\n  \
pinjoint sweep --input pts.csv --fidelity auto --tolerance 1e-4\n\n\
FIDELITY: --fidelity table|boundary|auto builds that level once over the envelope, by default \
the input's own load range and |speed| range (or --envelope-load/--envelope-speed), and \
standard error says which level answered (what auto picked) and the error bound it measured. \
Rows outside a given envelope are answered by the full solve (said once on standard error). With a `temperature` column the level is built again at each distinct temperature (its bound measured there; at full a temperature costs a few logarithms)."
)]
/// Arguments of `pinjoint sweep` (its `--help` text is the `#[command]` attribute's).
pub struct SweepCmd {
    /// Input CSV with columns `load` (N) and `speed` (rad/s), or a Parquet file (`*.parquet`)
    /// with those columns as numbers; `-` reads CSV from standard input
    #[arg(long, value_name = "FILE.csv|FILE.parquet")]
    pub input: PathBuf,
    /// Output file (written atomically): CSV, or Apache Parquet when it is named `*.parquet`
    /// (or with --format parquet); CSV on standard output when absent or `-`
    #[arg(long, value_name = "FILE.csv|FILE.parquet")]
    pub output: Option<PathBuf>,
    /// Output format: csv or parquet (default: parquet for an --output named *.parquet or
    /// *.parq, else csv)
    #[arg(long, value_name = "csv|parquet")]
    pub format: Option<String>,
    /// --params and --temperature.
    #[command(flatten)]
    pub params: ParamsArg,
    /// --fidelity, --tolerance and the envelope.
    #[command(flatten)]
    pub fidelity: FidelityArgs,
}

/// Rows read, evaluated and written together: bounds the memory (a few MiB of text).
pub const BATCH_ROWS: usize = 16_384;
/// Batches of Parquet columns queued for the writer thread at most (each about
/// [`BATCH_ROWS`] × 8 bytes × the columns).
const WRITE_QUEUE: usize = 2;
/// Bytes of CSV text reserved for a row's result columns (about 300 on average at every
/// level, at most 331 in a million random rows at full): a chunk's text is not grown (and
/// copied) as it is written.
const RESULT_TEXT_BYTES: usize = 352;
/// Rows one task parses, evaluates and formats.
const CHUNK_ROWS: usize = 512;

fn is_stdio(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// How rows are answered.
enum Mode<'a> {
    /// The library's cold solve (the default, `--fidelity full`); rows with a `temperature`
    /// use the joint at that temperature ([`Joint::at_temperature`]: the same numbers as a
    /// joint built there, at the cost of a few logarithms).
    Full(&'a Joint),
    /// A fidelity level: clones of one evaluator, one per task at a time; rows with a
    /// `temperature` use the level built at that temperature ([`Temperatures`]).
    Level { proto: &'a Evaluator, pool: Mutex<Vec<Evaluator>>, said: AtomicBool, by_t: Temperatures },
    /// Only validate and collect the load and |speed| ranges (the envelope's default).
    Scan,
    /// As [`Mode::Scan`], and keep every row's numbers and line ([`ChunkOut::cols`] and
    /// [`ChunkOut::lines`]) for a second pass that does not parse the text again ([`spill`]).
    Spill,
}

impl Mode<'_> {
    /// Whether rows are answered (not only scanned).
    fn evaluates(&self) -> bool {
        !matches!(self, Mode::Scan | Mode::Spill)
    }
}

/// The header and where the load, speed and (optional) temperature columns are.
struct Columns {
    header: Vec<String>,
    load: usize,
    speed: usize,
    temperature: Option<usize>,
}

impl Columns {
    /// Whether input column `k` is one of the numbers the sweep reads (load, speed, temperature).
    fn is_number(&self, k: usize) -> bool {
        k == self.load || k == self.speed || self.temperature == Some(k)
    }
}

/// Fidelity levels at the temperatures of a `temperature` column, built once per distinct
/// value ([`Evaluator::set_temperature`]: a table or boundary level is tabulated and measured
/// again at each temperature, so its bound holds there). At most [`MAX_TEMPERATURES`] are
/// kept: past that the cache starts again, so memory stays bounded.
#[derive(Default)]
struct Temperatures(Mutex<std::collections::HashMap<u64, std::sync::Arc<Evaluator>>>);

/// Levels kept by [`Temperatures`] at once.
const MAX_TEMPERATURES: usize = 256;

impl Temperatures {
    fn level(&self, proto: &Evaluator, t: f64) -> std::result::Result<std::sync::Arc<Evaluator>, pinjoint::fidelity::FidelityError> {
        let mut map = self.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(e) = map.get(&t.to_bits()) {
            return Ok(e.clone());
        }
        let mut ev = proto.clone();
        ev.set_temperature(t)?;
        let ev = std::sync::Arc::new(ev);
        if map.len() >= MAX_TEMPERATURES {
            map.clear();
        }
        map.insert(t.to_bits(), ev.clone());
        Ok(ev)
    }
}

/// What one chunk gives: its output text (CSV) or columns (Parquet), and the ranges of
/// positive load and |speed|.
#[derive(Default)]
struct ChunkOut {
    text: Vec<u8>,
    cols: Vec<Values>,
    /// The rows' lines ([`Mode::Spill`]).
    lines: Vec<u64>,
    loads: (f64, f64),
    speeds: (f64, f64),
}

/// The output's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Form {
    /// CSV text.
    Csv,
    /// Apache Parquet columns ([`crate::columnar`]).
    Parquet,
}

/// One row's operating point at (`load`, `speed`, `temperature`) by `mode` (`ev`: the chunk's
/// evaluator at a fidelity level; `at_t`: its levels at other temperatures); an error is
/// given to `bad`, which names the row.
fn evaluate_row(
    mode: &Mode,
    ev: Option<&mut Evaluator>,
    at_t: &mut std::collections::HashMap<u64, Evaluator>,
    (load, speed, temperature): (f64, f64, Option<f64>),
    bad: &dyn Fn(String) -> CliError,
) -> Result<OperatingPoint> {
    Ok(match (mode, ev) {
        (Mode::Scan | Mode::Spill, _) => unreachable!("a scan evaluates nothing"),
        (Mode::Full(joint), _) => match temperature {
            None => joint.evaluate(load, speed),
            Some(t) => joint.at_temperature(t).map_err(|e| bad(e.to_string()))?.evaluate(load, speed),
        }
        .map_err(|e| bad(e.to_string()))?,
        (Mode::Level { said, proto, by_t, .. }, Some(ev)) if temperature.is_some_and(|t| t.to_bits() != ev.temperature().to_bits()) => {
            let t = temperature.unwrap_or_default();
            let level = by_t.level(proto, t).map_err(|e| bad(e.to_string()))?;
            // This chunk's own copy of the level at t (it counts its fallbacks).
            let ev = at_t.entry(t.to_bits()).or_insert_with(|| (*level).clone());
            let e = ev.evaluate(load, speed).map_err(|e| bad(e.to_string()))?;
            note_fallback(&e, ev, said);
            ev.operating_point(&e)
        }
        (Mode::Level { said, .. }, Some(ev)) => {
            let e = ev.evaluate(load, speed).map_err(|e| bad(e.to_string()))?;
            note_fallback(&e, ev, said);
            ev.operating_point(&e)
        }
        (Mode::Level { .. }, None) => unreachable!("an evaluator is taken for every chunk at a fidelity level"),
    })
}

/// Take an evaluator for a chunk (a fidelity level), from the pool or cloned.
fn take_evaluator(mode: &Mode) -> Option<Evaluator> {
    match mode {
        Mode::Level { proto, pool, .. } => Some(pool.lock().ok().and_then(|mut p| p.pop()).unwrap_or_else(|| (*proto).clone())),
        _ => None,
    }
}

/// Give a chunk's evaluator back to the pool.
fn return_evaluator(mode: &Mode, ev: Option<Evaluator>) {
    if let (Mode::Level { pool, .. }, Some(ev)) = (mode, ev)
        && let Ok(mut p) = pool.lock()
    {
        p.push(ev);
    }
}

fn widen(r: &mut (f64, f64), v: f64) {
    if v > 0.0 && v.is_finite() {
        r.0 = r.0.min(v);
        r.1 = r.1.max(v);
    }
}

const EMPTY_RANGE: (f64, f64) = (f64::INFINITY, 0.0);

fn read_header<R: BufRead>(reader: &mut RecordReader<R>, file: &str) -> Result<Columns> {
    let bad = |line: u64, message: String| CliError::Input { file: file.to_string(), line, message };
    let (header, header_line) = reader.header()?;
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
    let (load, speed) = (find("load")?, find("speed")?);
    let temperature = if header.iter().any(|h| h == "temperature") { Some(find("temperature")?) } else { None };
    if let Some(clash) = header.iter().find(|h| RESULT_COLUMNS.contains(&h.as_str())) {
        return Err(bad(header_line, format!("input column `{clash}` has the name of an output column; rename it")));
    }
    Ok(Columns { header, load, speed, temperature })
}

/// The output columns of a chunk of `rows` rows in Parquet form: each input column (a number
/// for load, speed and temperature, text otherwise), then the result columns.
fn parquet_columns(cols: &Columns, rows: usize) -> Vec<Values> {
    let mut v: Vec<Values> = (0..cols.header.len())
        .map(|k| if cols.is_number(k) { Values::Number(Vec::with_capacity(rows)) } else { Values::Text(Vec::with_capacity(rows)) })
        .collect();
    v.extend(columnar::result_values(rows));
    v
}

/// Parse, check, evaluate and format the records `recs` of `batch`.
fn chunk(batch: &Batch, recs: &[self::input::Record], cols: &Columns, mode: &Mode, file: &str, form: Form) -> Result<ChunkOut> {
    let width = cols.header.len();
    let mut out = ChunkOut { loads: EMPTY_RANGE, speeds: EMPTY_RANGE, ..Default::default() };
    let mut fields = Fields::default();
    match (mode, form) {
        (Mode::Scan, _) => {}
        (Mode::Spill, _) => {
            out.cols = (0..width).map(|_| Values::Number(Vec::with_capacity(recs.len()))).collect();
            out.lines.reserve(recs.len());
        }
        (_, Form::Csv) => out.text.reserve(recs.iter().map(|r| r.end - r.start + 1).sum::<usize>() + recs.len() * RESULT_TEXT_BYTES),
        (_, Form::Parquet) => out.cols = parquet_columns(cols, recs.len()),
    }
    let mut ev = take_evaluator(mode);
    let mut at_t: std::collections::HashMap<u64, Evaluator> = std::collections::HashMap::new();
    for r in recs {
        let line = r.line;
        let bad = |message: String| CliError::Input { file: file.to_string(), line, message };
        let rec = fields.cut(batch.bytes(r)).map_err(|e| bad(e.to_string()))?;
        // The record's text checked once; each field is a slice of it.
        let whole = std::str::from_utf8(rec.all()).map_err(|e| bad(format!("unreadable CSV: invalid UTF-8: {e}")))?;
        let text = |i: usize| {
            let (a, b) = rec.range(i);
            whole.get(a..b).unwrap_or("")
        };
        if rec.len() != width {
            let detail = if rec.len() < width {
                format!("missing column(s) {}", cols.header[rec.len()..].join(","))
            } else {
                format!("{} more field(s) than the header's columns", rec.len() - width)
            };
            return Err(bad(format!("{detail}: the row has {} field(s), the header {width} ({})", rec.len(), cols.header.join(","))));
        }
        let number = |i: usize, name: &str, unit: &str| -> Result<f64> {
            let t = text(i);
            if t.is_empty() {
                return Err(bad(format!("column {name} ({unit}) is empty")));
            }
            let v: f64 = t.parse().map_err(|_| bad(format!("column {name} = `{t}` is not a number ({unit})")))?;
            if !v.is_finite() {
                return Err(bad(format!("column {name} = {t} {unit} is not a finite number")));
            }
            Ok(v)
        };
        let load = number(cols.load, "load", "N")?;
        if load == 0.0 {
            return Err(bad(format!("column load = {} N is invalid: the load magnitude must be > 0 N", text(cols.load))));
        }
        let speed = number(cols.speed, "speed", "rad/s")?;
        let temperature = cols.temperature.map(|i| number(i, "temperature", "K")).transpose()?;
        widen(&mut out.loads, load.abs());
        widen(&mut out.speeds, speed.abs());
        if matches!(mode, Mode::Spill) {
            push_numbers(&mut out.cols, cols, (load, speed, temperature));
            out.lines.push(line);
        }
        if !mode.evaluates() {
            continue;
        }
        let op = evaluate_row(mode, ev.as_mut(), &mut at_t, (load, speed, temperature), &bad)?;
        if form == Form::Parquet {
            // The input columns (the numbers as evaluated, other columns as text), then the
            // result record's.
            push_numbers(&mut out.cols[..width], cols, (load, speed, temperature));
            for (k, c) in out.cols[..width].iter_mut().enumerate() {
                if let Values::Text(v) = c {
                    v.push(text(k).to_string());
                }
            }
            columnar::push_result(&mut out.cols[width..], &op);
            continue;
        }
        // The row, written directly (as the `csv` writer with its defaults would: fields
        // quoted only when they hold a comma, a quote or a line break; `\n` after the record):
        // the input fields as read, then the one result record's columns (pinjoint::record).
        let text = &mut out.text;
        for (k, f) in rec.iter().enumerate() {
            if k > 0 {
                text.push(b',');
            }
            push_field(text, f);
        }
        for c in &pinjoint::record::COLUMNS {
            text.push(b',');
            match c.value {
                pinjoint::record::Value::Number(f) => push_exact(text, f(&op)),
                pinjoint::record::Value::Regime => text.extend_from_slice(op.regime.as_str().as_bytes()),
                pinjoint::record::Value::Validity => text.extend_from_slice(op.validity.as_str().as_bytes()),
            }
        }
        text.push(b'\n');
    }
    return_evaluator(mode, ev);
    Ok(out)
}

/// Append a row's numbers to the number columns among `out` (the input's columns, in its order).
fn push_numbers(out: &mut [Values], cols: &Columns, (load, speed, temperature): (f64, f64, Option<f64>)) {
    for (k, c) in out.iter_mut().enumerate() {
        if let Values::Number(v) = c {
            v.push(if k == cols.load {
                load
            } else if k == cols.speed {
                speed
            } else {
                temperature.unwrap_or(f64::NAN)
            });
        }
    }
}

/// One CSV field as the `csv` crate's writer writes it by default (`QuoteStyle::Necessary`,
/// double quotes, `\n` terminator): as is, or in quotes with its quotes doubled when it holds
/// a comma, a quote, a carriage return or a line feed.
fn push_field(out: &mut Vec<u8>, f: &[u8]) {
    if !f.iter().any(|&b| matches!(b, b',' | b'"' | b'\r' | b'\n')) {
        out.extend_from_slice(f);
        return;
    }
    out.push(b'"');
    for &b in f {
        if b == b'"' {
            out.push(b'"');
        }
        out.push(b);
    }
    out.push(b'"');
}

/// Batches of the input being answered at once: while the cores finish one, the next one's
/// chunks are already queued behind it, so no core waits at a batch's end for the slowest
/// chunk (the full solve's cost varies from row to row), for the thread that writes the
/// batch before or for the one that reads the batch after.
const IN_FLIGHT: usize = 2;

/// A batch whose chunks are being answered on the pool.
struct InFlight {
    /// The batch's records (shared with its chunks' tasks; back to this thread at the end).
    batch: Arc<Batch>,
    /// Each chunk's output, as its task reports it.
    outs: Vec<Option<Result<ChunkOut>>>,
    /// Chunks not yet reported.
    left: usize,
}

/// Stream the input through `mode`: every batch read, answered on every core and handed to
/// `sink` in input order. The reading and writing stay on this thread, the chunks of the
/// batches go to the pool as one continuous queue ([`IN_FLIGHT`] batches in it at most, so
/// memory stays bounded): while the cores answer, this thread writes the batch before and
/// reads the batch after. The first error in input order wins. Returns the ranges of
/// positive load and |speed| seen.
fn stream<R: BufRead>(
    reader: &mut RecordReader<R>,
    cols: &Columns,
    mode: &Mode,
    file: &str,
    form: Form,
    bar: &ProgressBar,
    sink: &mut dyn FnMut(&mut [ChunkOut]) -> Result<()>,
) -> Result<((f64, f64), (f64, f64))> {
    let (mut loads, mut speeds) = (EMPTY_RANGE, EMPTY_RANGE);
    // Set on an error: the chunks still queued are then skipped.
    let stop = &AtomicBool::new(false);
    let (tx, rx) = std::sync::mpsc::channel::<(u64, usize, Result<ChunkOut>)>();
    rayon::in_place_scope_fifo(|s| {
        let r = (|| -> Result<()> {
            let mut flight: VecDeque<InFlight> = VecDeque::with_capacity(IN_FLIGHT);
            // The number of the batch at the queue's front (each chunk reports its batch's number).
            let mut front_id: u64 = 0;
            let mut spare = Batch::default();
            let mut more = true;
            // A read error waits for the batches before it: a bad row there is reported first.
            let mut read_err = None;
            loop {
                if more && flight.len() < IN_FLIGHT {
                    let mut batch = std::mem::take(&mut spare);
                    more = match reader.fill(&mut batch, BATCH_ROWS) {
                        Ok(more) => more,
                        Err(e) => {
                            read_err = Some(e);
                            batch.clear();
                            false
                        }
                    };
                    bar.set_position(reader.consumed);
                    if batch.records.is_empty() {
                        continue;
                    }
                    let id = front_id + flight.len() as u64;
                    let batch = Arc::new(batch);
                    let n = batch.records.len().div_ceil(CHUNK_ROWS);
                    for c in 0..n {
                        let (batch, tx) = (Arc::clone(&batch), tx.clone());
                        s.spawn_fifo(move |_| {
                            let out = if stop.load(Ordering::Relaxed) {
                                Err(CliError::Invalid("skipped after an error".into()))
                            } else {
                                let recs = &batch.records[c * CHUNK_ROWS..((c + 1) * CHUNK_ROWS).min(batch.records.len())];
                                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| chunk(&batch, recs, cols, mode, file, form)))
                                    .unwrap_or_else(|_| Err(CliError::Invalid("a worker thread panicked".into())))
                            };
                            // The batch goes back to the reading thread once every chunk is done.
                            drop(batch);
                            let _ = tx.send((id, c, out));
                        });
                    }
                    flight.push_back(InFlight { batch, outs: (0..n).map(|_| None).collect(), left: n });
                    continue;
                }
                if flight.is_empty() {
                    return read_err.map_or(Ok(()), Err);
                }
                while flight[0].left > 0 {
                    let (id, c, out) = rx.recv().map_err(|_| CliError::Invalid("the sweep's workers stopped".into()))?;
                    let f = &mut flight[(id - front_id) as usize];
                    f.outs[c] = Some(out);
                    f.left -= 1;
                }
                let done = flight.pop_front().expect("the queue is not empty");
                front_id += 1;
                let mut outs: Vec<ChunkOut> = done.outs.into_iter().map(|o| o.expect("every chunk reported")).collect::<Result<_>>()?;
                for o in &outs {
                    (loads.0, loads.1) = (loads.0.min(o.loads.0), loads.1.max(o.loads.1));
                    (speeds.0, speeds.1) = (speeds.0.min(o.speeds.0), speeds.1.max(o.speeds.1));
                }
                sink(&mut outs)?;
                // Every task has dropped its share before reporting: the batch's memory is reused.
                if let Ok(b) = Arc::try_unwrap(done.batch) {
                    spare = b;
                }
            }
        })();
        if r.is_err() {
            stop.store(true, Ordering::Relaxed);
        }
        r
    })?;
    Ok((loads, speeds))
}

/// The input, opened (standard input when `-`), as a buffered reader that can be read again
/// from the start: standard input is copied to an unnamed temporary file when a second pass
/// is needed (the envelope of a fidelity level), so memory stays bounded.
fn open(path: &Path, rewindable: bool) -> Result<(Box<dyn ReadSeek>, Option<u64>)> {
    let read_err = |source: io::Error| CliError::Read { path: path.to_path_buf(), source };
    if is_stdio(path) {
        if !rewindable {
            return Ok((Box::new(Unseekable(io::BufReader::with_capacity(1 << 16, io::stdin()))), None));
        }
        let mut tmp = tempfile::tempfile().map_err(read_err)?;
        io::copy(&mut io::stdin().lock(), &mut tmp).map_err(read_err)?;
        tmp.rewind().map_err(read_err)?;
        let len = tmp.metadata().ok().map(|m| m.len());
        return Ok((Box::new(io::BufReader::with_capacity(1 << 16, tmp)), len));
    }
    let f = std::fs::File::open(path).map_err(read_err)?;
    let len = f.metadata().ok().filter(std::fs::Metadata::is_file).map(|m| m.len());
    Ok((Box::new(io::BufReader::with_capacity(1 << 16, f)), len))
}

/// A buffered input that may be rewound.
trait ReadSeek: BufRead {
    fn rewind_input(&mut self) -> io::Result<()>;
}
impl<T: io::Read + Seek> ReadSeek for io::BufReader<T> {
    fn rewind_input(&mut self) -> io::Result<()> {
        self.rewind()
    }
}
/// Standard input read once.
struct Unseekable<T>(T);
impl<T: io::Read> io::Read for Unseekable<T> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.0.read(buf)
    }
}
impl<T: BufRead> BufRead for Unseekable<T> {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        self.0.fill_buf()
    }
    fn consume(&mut self, n: usize) {
        self.0.consume(n);
    }
}
impl<T: BufRead> ReadSeek for Unseekable<T> {
    fn rewind_input(&mut self) -> io::Result<()> {
        Err(io::Error::other("standard input cannot be read twice"))
    }
}

/// A progress bar over the input's bytes for large files (drawn only on a terminal).
fn progress(len: Option<u64>) -> ProgressBar {
    match len {
        Some(n) if n >= 1 << 20 => {
            let bar = ProgressBar::new(n);
            bar.set_style(
                ProgressStyle::with_template("{bar:40} {bytes}/{total_bytes} of input, {elapsed}, eta {eta}").expect("valid template"),
            );
            bar
        }
        _ => ProgressBar::hidden(),
    }
}

/// The rows of a Parquet input ([`columnar::ParquetRows`]) through `mode`, a batch of
/// [`BATCH_ROWS`] at a time answered on every core and handed to `sink` in input order.
/// Returns the ranges of positive load and |speed| seen.
fn stream_parquet(path: &Path, mode: &Mode, form: Form, sink: &mut dyn FnMut(&mut [ChunkOut]) -> Result<()>) -> Result<((f64, f64), (f64, f64))> {
    let file = path.display().to_string();
    let mut rows = columnar::ParquetRows::open(path, BATCH_ROWS).map_err(CliError::Invalid)?;
    let cols = parquet_input_columns(rows.has_temperature);
    let (mut loads, mut speeds) = (EMPTY_RANGE, EMPTY_RANGE);
    loop {
        let first = rows.row;
        let Some((load, speed, temperature)) = rows.next_batch().map_err(CliError::Invalid)? else { break };
        let outs: Vec<Result<ChunkOut>> = (0..load.len())
            .step_by(CHUNK_ROWS)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|start| {
                let end = (start + CHUNK_ROWS).min(load.len());
                let mut out = ChunkOut { loads: EMPTY_RANGE, speeds: EMPTY_RANGE, ..Default::default() };
                match (mode, form) {
                    (Mode::Scan | Mode::Spill, _) => {}
                    (_, Form::Csv) => out.text.reserve((end - start) * (3 * 25 + RESULT_TEXT_BYTES)),
                    (_, Form::Parquet) => out.cols = parquet_columns(&cols, end - start),
                }
                let mut ev = take_evaluator(mode);
                let mut at_t = std::collections::HashMap::new();
                for i in start..end {
                    // Rows are numbered from 1 in the file's order (a Parquet file has no lines).
                    let row = first + i as u64 + 1;
                    let bad = |message: String| CliError::Input { file: format!("{file} (row {row})"), line: row, message };
                    let (p, w, t) = (load[i], speed[i], temperature.as_ref().map(|t| t[i]));
                    for (name, unit, v) in [("load", "N", Some(p)), ("speed", "rad/s", Some(w)), ("temperature", "K", t)] {
                        if let Some(v) = v.filter(|v| !v.is_finite()) {
                            return Err(bad(format!("column {name} = {v} {unit} is not a finite number")));
                        }
                    }
                    if p == 0.0 {
                        return Err(bad("column load = 0 N is invalid: the load magnitude must be > 0 N".into()));
                    }
                    widen(&mut out.loads, p.abs());
                    widen(&mut out.speeds, w.abs());
                    if !mode.evaluates() {
                        continue;
                    }
                    let op = evaluate_row(mode, ev.as_mut(), &mut at_t, (p, w, t), &bad)?;
                    match form {
                        Form::Parquet => {
                            for (c, x) in out.cols.iter_mut().zip([p, w, t.unwrap_or(f64::NAN)]) {
                                if let Values::Number(v) = c {
                                    v.push(x);
                                }
                            }
                            columnar::push_result(&mut out.cols[cols.header.len()..], &op);
                        }
                        Form::Csv => {
                            let text = &mut out.text;
                            push_exact(text, p);
                            text.push(b',');
                            push_exact(text, w);
                            if let Some(t) = t {
                                text.push(b',');
                                push_exact(text, t);
                            }
                            push_result_text(text, &op);
                        }
                    }
                }
                return_evaluator(mode, ev);
                Ok(out)
            })
            .collect();
        let mut outs: Vec<ChunkOut> = outs.into_iter().collect::<Result<_>>()?;
        for o in &outs {
            (loads.0, loads.1) = (loads.0.min(o.loads.0), loads.1.max(o.loads.1));
            (speeds.0, speeds.1) = (speeds.0.min(o.speeds.0), speeds.1.max(o.speeds.1));
        }
        sink(&mut outs)?;
    }
    Ok((loads, speeds))
}

/// The input columns of a Parquet input: load, speed and, when the file has it, temperature.
fn parquet_input_columns(has_temperature: bool) -> Columns {
    let mut header = vec!["load".to_string(), "speed".to_string()];
    if has_temperature {
        header.push("temperature".to_string());
    }
    Columns { header, load: 0, speed: 1, temperature: has_temperature.then_some(2) }
}

/// The result columns of `op` after a row's input fields, then the line's end (CSV).
fn push_result_text(text: &mut Vec<u8>, op: &OperatingPoint) {
    for c in &pinjoint::record::COLUMNS {
        text.push(b',');
        match c.value {
            pinjoint::record::Value::Number(f) => push_exact(text, f(op)),
            pinjoint::record::Value::Regime => text.extend_from_slice(op.regime.as_str().as_bytes()),
            pinjoint::record::Value::Validity => text.extend_from_slice(op.validity.as_str().as_bytes()),
        }
    }
    text.push(b'\n');
}

/// The output's form: `--format`, else Parquet for an output file named `*.parquet` (or
/// `*.parq`), else CSV.
fn output_form(cmd: &SweepCmd) -> Result<Form> {
    let to_file = cmd.output.as_deref().filter(|p| !is_stdio(p));
    let form = match cmd.format.as_deref() {
        None => {
            if to_file.is_some_and(columnar::is_parquet_path) {
                Form::Parquet
            } else {
                Form::Csv
            }
        }
        Some("csv") => Form::Csv,
        Some("parquet") => Form::Parquet,
        Some(other) => return Err(CliError::Invalid(format!("--format {other} is not a format: csv or parquet"))),
    };
    if form == Form::Parquet && to_file.is_none() {
        return Err(CliError::Invalid("Parquet output needs a file (--output FILE.parquet), not standard output".into()));
    }
    Ok(form)
}

/// Runs `pinjoint sweep`: evaluates every row of the input in parallel and writes the output
/// (CSV, or Parquet: [`crate::columnar`]) in the input's row order. Fails on an unreadable
/// file, a bad row (with its line) or a point the model cannot evaluate.
pub fn run(cmd: &SweepCmd) -> Result<()> {
    let mut inputs: Vec<&Path> = vec![cmd.input.as_path()];
    inputs.extend(cmd.params.params.as_deref());
    if let Some(out) = cmd.output.as_deref().filter(|p| !is_stdio(p)) {
        refuse_inputs(&[out], &inputs)?;
    }
    let form = output_form(cmd)?;
    let parquet_in = !is_stdio(&cmd.input) && columnar::is_parquet_path(&cmd.input);
    let joint = cmd.params.joint()?;
    let full = cmd.fidelity.is_full()?;
    let file = if is_stdio(&cmd.input) { "standard input".to_string() } else { cmd.input.display().to_string() };
    let needs_ranges = !full && (cmd.fidelity.envelope_load.is_none() || cmd.fidelity.envelope_speed.is_none());
    let (mut input, len) = if parquet_in { (Box::new(Unseekable(io::BufReader::new(io::empty()))) as Box<dyn ReadSeek>, None) } else { open(&cmd.input, needs_ranges)? };
    let bar = progress(len);
    let level;
    // The rows' numbers kept by the first pass for the second ([`spill`]) and the input's columns.
    let mut spilled: Option<(io::BufReader<std::fs::File>, Columns)> = None;
    let mode = if full {
        Mode::Full(&joint)
    } else {
        let (loads, speeds) = if needs_ranges {
            let (l, s) = if parquet_in {
                stream_parquet(&cmd.input, &Mode::Scan, form, &mut |_: &mut [ChunkOut]| Ok(()))?
            } else {
                let mut reader = RecordReader::new(&mut input, &file);
                let cols = read_header(&mut reader, &file)?;
                // Parse once: the second pass answers the numbers kept by this one (where no
                // temporary file can be made, the second pass reads the input again).
                let keep = if form == Form::Parquet && (0..cols.header.len()).all(|k| cols.is_number(k)) { tempfile::tempfile().ok() } else { None };
                if let Some(tmp) = keep {
                    let tmp_err = |e: io::Error| CliError::Invalid(format!("writing the sweep's temporary file: {e}"));
                    let mut w = io::BufWriter::with_capacity(1 << 16, tmp);
                    let r = stream(&mut reader, &cols, &Mode::Spill, &file, form, &bar, &mut |outs: &mut [ChunkOut]| {
                        outs.iter().try_for_each(|o| spill::write(&mut w, &o.cols, &o.lines)).map_err(tmp_err)
                    })?;
                    let mut f = w.into_inner().map_err(|e| tmp_err(e.into_error()))?;
                    f.rewind().map_err(tmp_err)?;
                    spilled = Some((io::BufReader::with_capacity(1 << 16, f), cols));
                    r
                } else {
                    let r = stream(&mut reader, &cols, &Mode::Scan, &file, form, &ProgressBar::hidden(), &mut |_: &mut [ChunkOut]| Ok(()))?;
                    input.rewind_input().map_err(|source| CliError::Read { path: cmd.input.clone(), source })?;
                    r
                }
            };
            let fallback = |r: (f64, f64), f: (f64, f64)| if r.0.is_finite() { range_of([r.0, r.1].into_iter(), f) } else { f };
            (fallback(l, (1.0, 2.0)), fallback(s, (1e-3, 1.0)))
        } else {
            ((1.0, 2.0), (1e-3, 1.0))
        };
        level = cmd.fidelity.build(&cmd.params.load()?, loads, speeds)?;
        Mode::Level { proto: &level, pool: Mutex::new(Vec::new()), said: AtomicBool::new(false), by_t: Temperatures::default() }
    };
    let mut reader = RecordReader::new(&mut input, &file);
    let (cols, mut spilled) = match spilled {
        Some((f, cols)) => (cols, Some(f)),
        None if parquet_in => (parquet_input_columns(columnar::ParquetRows::open(&cmd.input, 1).map_err(CliError::Invalid)?.has_temperature), None),
        None => (read_header(&mut reader, &file)?, None),
    };
    // An input or model error inside the writer is kept here and returned as itself.
    let failure: Mutex<Option<CliError>> = Mutex::new(None);
    let keep = |e: CliError| {
        let msg = e.to_string();
        *failure.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = Some(e);
        io::Error::other(msg)
    };
    let mut source = |mode: &Mode, sink: &mut dyn FnMut(&mut [ChunkOut]) -> Result<()>| -> Result<()> {
        if let Some(f) = spilled.as_mut() {
            stream_spilled(f, &cols, mode, &file, sink)
        } else if parquet_in {
            stream_parquet(&cmd.input, mode, form, sink).map(|_| ())
        } else {
            stream(&mut reader, &cols, mode, &file, form, &bar, sink).map(|_| ())
        }
    };
    let written = if form == Form::Parquet {
        let path = cmd.output.as_deref().expect("output_form: Parquet goes to a file");
        let names: Vec<String> = cols.header.iter().cloned().chain(RESULT_COLUMNS.iter().map(|s| (*s).to_string())).collect();
        write_atomic_send(path, &inputs, |w| {
            // The row groups are encoded and written on a thread of their own, fed a batch's
            // columns at a time (at most WRITE_QUEUE batches queued: memory stays bounded), so
            // that this thread only reads while the cores evaluate.
            let kinds = parquet_columns(&cols, 0);
            let failed = AtomicBool::new(false);
            std::thread::scope(|s| {
                let (tx, rx) = std::sync::mpsc::sync_channel::<Vec<Vec<Values>>>(WRITE_QUEUE);
                let failed = &failed;
                let writer = s.spawn(move || -> io::Result<()> {
                    let mut pq = columnar::ParquetSink::new(w, &names, &kinds)?;
                    for blocks in rx {
                        pq.write_owned(blocks)?;
                    }
                    // A failed run leaves the temporary file unfinished (it is removed).
                    if failed.load(Ordering::Relaxed) { Ok(()) } else { pq.finish() }
                });
                let r = {
                    let mut sink = |outs: &mut [ChunkOut]| -> Result<()> {
                        // Each chunk's columns move to the writer (no copy of the numbers).
                        let blocks: Vec<Vec<Values>> = outs.iter_mut().map(|o| std::mem::take(&mut o.cols)).collect();
                        tx.send(blocks).map_err(|_| CliError::Invalid("the Parquet writer stopped".into()))
                    };
                    source(&mode, &mut sink)
                };
                failed.store(r.is_err(), Ordering::Relaxed);
                drop(tx);
                bar.finish_and_clear();
                let written = writer.join().unwrap_or_else(|_| Err(io::Error::other("the Parquet writer thread panicked")));
                // The writer's own error first (it is why a send failed), then the input's.
                written?;
                r.map_err(keep)
            })
        })
    } else {
        let fill = |w: &mut dyn Write| -> io::Result<()> {
            let mut wtr = csv::Writer::from_writer(&mut *w);
            wtr.write_record(cols.header.iter().map(String::as_str).chain(RESULT_COLUMNS)).map_err(csv_io)?;
            wtr.flush()?;
            drop(wtr);
            let mut write_err: Option<io::Error> = None;
            let mut sink = |outs: &mut [ChunkOut]| -> Result<()> {
                for o in outs.iter() {
                    if let Err(e) = w.write_all(&o.text) {
                        let msg = e.to_string();
                        write_err = Some(e);
                        return Err(CliError::Invalid(msg));
                    }
                }
                Ok(())
            };
            let r = source(&mode, &mut sink);
            bar.finish_and_clear();
            if let Some(e) = write_err {
                return Err(e);
            }
            r.map_err(keep)
        };
        match &cmd.output {
            Some(path) if !is_stdio(path) => write_atomic(path, &inputs, fill),
            _ => to_stdout(fill),
        }
    };
    match failure.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner) {
        Some(e) => Err(e),
        None => written,
    }
}

/// The second pass of a spilled sweep ([`spill`]): the rows kept in `spill` answered through `mode`, a batch of
/// [`BATCH_ROWS`] at a time on every core (while this thread reads the next batch), handed to
/// `sink` in input order as Parquet columns. An error names the row's line in `file`, as the
/// first pass would.
fn stream_spilled(spill: &mut (impl io::Read + Send), cols: &Columns, mode: &Mode, file: &str, sink: &mut dyn FnMut(&mut [ChunkOut]) -> Result<()>) -> Result<()> {
    let width = cols.header.len();
    let tmp_err = |e: io::Error| CliError::Invalid(format!("reading the sweep's temporary file: {e}"));
    let mut buf = Vec::new();
    let mut current = spill::read_batch(spill, width, BATCH_ROWS, CHUNK_ROWS, &mut buf).map_err(tmp_err)?;
    while !current.is_empty() {
        let (outs, next) = std::thread::scope(|s| {
            let work = s.spawn(|| current.par_iter().map(|c| answer_spilled(c, cols, mode, file)).collect::<Vec<Result<ChunkOut>>>());
            let next = spill::read_batch(spill, width, BATCH_ROWS, CHUNK_ROWS, &mut buf);
            (work.join(), next)
        });
        let outs = outs.unwrap_or_else(|_| vec![Err(CliError::Invalid("a worker thread panicked".into()))]);
        let mut outs: Vec<ChunkOut> = outs.into_iter().collect::<Result<_>>()?;
        sink(&mut outs)?;
        current = next.map_err(tmp_err)?;
    }
    Ok(())
}

/// One chunk's rows answered: the input's numbers then the result columns.
fn answer_spilled(c: &spill::Chunk, cols: &Columns, mode: &Mode, file: &str) -> Result<ChunkOut> {
    let width = cols.header.len();
    let mut out = ChunkOut { cols: parquet_columns(cols, c.lines.len()), ..Default::default() };
    let mut ev = take_evaluator(mode);
    let mut at_t = std::collections::HashMap::new();
    for (i, &line) in c.lines.iter().enumerate() {
        let bad = |message: String| CliError::Input { file: file.to_string(), line, message };
        let row = (c.numbers[cols.load][i], c.numbers[cols.speed][i], cols.temperature.map(|k| c.numbers[k][i]));
        let op = evaluate_row(mode, ev.as_mut(), &mut at_t, row, &bad)?;
        push_numbers(&mut out.cols[..width], cols, row);
        columnar::push_result(&mut out.cols[width..], &op);
    }
    return_evaluator(mode, ev);
    Ok(out)
}
