//! The input's numbers kept between the two passes of a sweep whose fidelity level is built
//! over the input's own ranges: the first pass ([`super::Mode::Spill`]) reads, checks and
//! parses every row, collects the ranges and writes each row's numbers and line here, to an
//! unnamed temporary file (32 bytes a row with load and speed: memory stays bounded); the
//! second pass answers the rows from this file instead of reading and parsing the text again.
//! Used for a Parquet output whose input columns are all numbers (the CSV output copies the
//! input's fields as written, so it reads the text again). This file holds the file's format
//! (writing a chunk, reading a batch back); the sweep answers the rows (`stream_spilled`).

use crate::columnar::Values;
use std::io::{self, Read, Write};

/// Append a chunk's numbers and lines (the number columns of `cols` and `lines`, as
/// `Mode::Spill` leaves them) to `w`: the number of rows, each number column's doubles, then the
/// lines, all little-endian 8-byte words.
pub(super) fn write(w: &mut impl Write, cols: &[Values], lines: &[u64]) -> io::Result<()> {
    let n = lines.len();
    if n == 0 {
        return Ok(());
    }
    let mut buf = Vec::with_capacity(8 * (1 + n * (cols.len() + 1)));
    buf.extend_from_slice(&(n as u64).to_le_bytes());
    for c in cols {
        if let Values::Number(v) = c {
            for x in v {
                buf.extend_from_slice(&x.to_le_bytes());
            }
        }
    }
    for l in lines {
        buf.extend_from_slice(&l.to_le_bytes());
    }
    w.write_all(&buf)
}

/// One chunk read back: each input column's numbers and the rows' lines.
pub(super) struct Chunk {
    pub(super) numbers: Vec<Vec<f64>>,
    pub(super) lines: Vec<u64>,
}

fn words(bytes: &[u8]) -> impl Iterator<Item = [u8; 8]> + '_ {
    bytes.chunks_exact(8).map(|b| {
        let mut a = [0u8; 8];
        a.copy_from_slice(b);
        a
    })
}

/// The next chunk of `width` columns (at most `max_rows` rows), or None at the end.
fn read_chunk(r: &mut impl Read, width: usize, max_rows: usize, buf: &mut Vec<u8>) -> io::Result<Option<Chunk>> {
    let mut head = [0u8; 8];
    match r.read_exact(&mut head) {
        Err(e) if e.kind() == io::ErrorKind::UnexpectedEof => return Ok(None),
        other => other?,
    }
    let n = u64::from_le_bytes(head) as usize;
    if n > max_rows {
        return Err(io::Error::other(format!("a chunk of {n} rows in the sweep's temporary file (at most {max_rows})")));
    }
    buf.resize(8 * n * (width + 1), 0);
    r.read_exact(buf)?;
    let numbers = (0..width).map(|k| words(&buf[8 * n * k..8 * n * (k + 1)]).map(f64::from_le_bytes).collect()).collect();
    let lines = words(&buf[8 * n * width..]).map(u64::from_le_bytes).collect();
    Ok(Some(Chunk { numbers, lines }))
}

/// The next batch: chunks of at least `batch_rows` rows in all (each at most `chunk_rows`),
/// unless the file ends.
pub(super) fn read_batch(r: &mut impl Read, width: usize, batch_rows: usize, chunk_rows: usize, buf: &mut Vec<u8>) -> io::Result<Vec<Chunk>> {
    let (mut batch, mut rows) = (Vec::new(), 0);
    while rows < batch_rows {
        let Some(c) = read_chunk(r, width, chunk_rows, buf)? else { break };
        rows += c.lines.len();
        batch.push(c);
    }
    Ok(batch)
}
