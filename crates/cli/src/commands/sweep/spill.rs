//! The input's numbers kept between the two passes of a sweep whose fidelity level is built
//! over the input's own ranges: the first pass ([`super::Mode::Spill`]) reads, checks and
//! parses every row, collects the ranges and writes each row's numbers and line here, to an
//! unnamed temporary file (32 bytes a row with load and speed: memory stays bounded); the
//! second pass answers the rows from this file instead of reading and parsing the text again.
//! Used for a Parquet output whose input columns are all numbers (the CSV output copies the
//! input's fields as written, so it reads the text again).

use super::{evaluate_row, push_numbers, return_evaluator, take_evaluator, ChunkOut, Columns, Mode, BATCH_ROWS, CHUNK_ROWS};
use crate::columnar::{self, Values};
use crate::error::{CliError, Result};
use rayon::prelude::*;
use std::io::{self, Read, Write};

/// Append a chunk's numbers and lines ([`ChunkOut::cols`], [`ChunkOut::lines`] of
/// [`super::Mode::Spill`]) to `w`: the number of rows, each number column's doubles, then the
/// lines, all little-endian 8-byte words.
pub(super) fn write(w: &mut impl Write, out: &ChunkOut) -> io::Result<()> {
    let n = out.lines.len();
    if n == 0 {
        return Ok(());
    }
    let mut buf = Vec::with_capacity(8 * (1 + n * (out.cols.len() + 1)));
    buf.extend_from_slice(&(n as u64).to_le_bytes());
    for c in &out.cols {
        if let Values::Number(v) = c {
            for x in v {
                buf.extend_from_slice(&x.to_le_bytes());
            }
        }
    }
    for l in &out.lines {
        buf.extend_from_slice(&l.to_le_bytes());
    }
    w.write_all(&buf)
}

/// One chunk read back: each input column's numbers and the rows' lines.
struct Chunk {
    numbers: Vec<Vec<f64>>,
    lines: Vec<u64>,
}

fn words(bytes: &[u8]) -> impl Iterator<Item = [u8; 8]> + '_ {
    bytes.chunks_exact(8).map(|b| {
        let mut a = [0u8; 8];
        a.copy_from_slice(b);
        a
    })
}

/// The next chunk of `width` columns, or None at the end.
fn read_chunk(r: &mut impl Read, width: usize, buf: &mut Vec<u8>) -> io::Result<Option<Chunk>> {
    let mut head = [0u8; 8];
    match r.read_exact(&mut head) {
        Err(e) if e.kind() == io::ErrorKind::UnexpectedEof => return Ok(None),
        other => other?,
    }
    let n = u64::from_le_bytes(head) as usize;
    if n > CHUNK_ROWS {
        return Err(io::Error::other(format!("a chunk of {n} rows in the sweep's temporary file (at most {CHUNK_ROWS})")));
    }
    buf.resize(8 * n * (width + 1), 0);
    r.read_exact(buf)?;
    let numbers = (0..width).map(|k| words(&buf[8 * n * k..8 * n * (k + 1)]).map(f64::from_le_bytes).collect()).collect();
    let lines = words(&buf[8 * n * width..]).map(u64::from_le_bytes).collect();
    Ok(Some(Chunk { numbers, lines }))
}

/// The next batch: chunks of at least [`BATCH_ROWS`] rows in all, unless the file ends.
fn read_batch(r: &mut impl Read, width: usize, buf: &mut Vec<u8>) -> io::Result<Vec<Chunk>> {
    let (mut batch, mut rows) = (Vec::new(), 0);
    while rows < BATCH_ROWS {
        let Some(c) = read_chunk(r, width, buf)? else { break };
        rows += c.lines.len();
        batch.push(c);
    }
    Ok(batch)
}

/// The second pass: the rows kept in `spill` answered through `mode`, a batch of
/// [`BATCH_ROWS`] at a time on every core (while this thread reads the next batch), handed to
/// `sink` in input order as Parquet columns. An error names the row's line in `file`, as the
/// first pass would.
pub(super) fn stream(spill: &mut (impl Read + Send), cols: &Columns, mode: &Mode, file: &str, sink: &mut dyn FnMut(&mut [ChunkOut]) -> Result<()>) -> Result<()> {
    let width = cols.header.len();
    let tmp_err = |e: io::Error| CliError::Invalid(format!("reading the sweep's temporary file: {e}"));
    let mut buf = Vec::new();
    let mut current = read_batch(spill, width, &mut buf).map_err(tmp_err)?;
    while !current.is_empty() {
        let (outs, next) = std::thread::scope(|s| {
            let work = s.spawn(|| current.par_iter().map(|c| answer(c, cols, mode, file)).collect::<Vec<Result<ChunkOut>>>());
            let next = read_batch(spill, width, &mut buf);
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
fn answer(c: &Chunk, cols: &Columns, mode: &Mode, file: &str) -> Result<ChunkOut> {
    let width = cols.header.len();
    let mut out = ChunkOut { cols: super::parquet_columns(cols, c.lines.len()), ..Default::default() };
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
