//! `pinjoint sweep`'s input, read in bounded batches: records split off the stream with
//! their line numbers (blank and `#` comment lines skipped, quoted fields may span lines),
//! then each record cut into trimmed fields, on any thread.
//!
//! The rules are those of the `csv` crate as the command has always used it (trim all
//! fields, comment character `#` at the start of a record, rows may have any number of
//! fields, which the caller checks): a record without a quote or a stray carriage return
//! is split on commas here (the common case, no copy of the text but into the reused
//! record); any other goes through a `csv` reader.

use crate::error::{CliError, Result};
use std::io::{BufRead, Read};

/// The longest record accepted, in bytes: keeps memory bounded whatever the input.
pub const MAX_RECORD_BYTES: u64 = 1 << 20;

/// One record of a batch: bytes `start..end` of the batch's text (terminator removed) and
/// the 1-based line on which it starts.
#[derive(Debug, Clone, Copy)]
pub struct Record {
    /// Byte offset of the record's first byte in [`Batch::text`].
    pub start: usize,
    /// Byte offset just past the record's last byte (terminator excluded).
    pub end: usize,
    /// 1-based line number on which the record starts.
    pub line: u64,
}

/// Consecutive records and the text that holds them.
#[derive(Debug, Default)]
pub struct Batch {
    /// The raw bytes of the records.
    pub text: Vec<u8>,
    /// The records, in input order.
    pub records: Vec<Record>,
}

impl Batch {
    /// The bytes of record `r` (without its line terminator).
    pub fn bytes(&self, r: &Record) -> &[u8] {
        &self.text[r.start..r.end]
    }
    /// Empties the batch, keeping its allocations for the next one.
    pub fn clear(&mut self) {
        self.text.clear();
        self.records.clear();
    }
}

/// Splits an input stream into records.
pub struct RecordReader<R> {
    input: R,
    /// Line number of the next line to be read.
    line: u64,
    /// Bytes read so far (for a progress bar).
    pub consumed: u64,
    file: String,
}

impl<R: BufRead> RecordReader<R> {
    /// A reader of `input`, named `file` in error messages, starting at line 1.
    pub fn new(input: R, file: &str) -> Self {
        Self { input, line: 1, consumed: 0, file: file.to_string() }
    }

    fn bad(&self, line: u64, message: String) -> CliError {
        CliError::Input { file: self.file.clone(), line, message }
    }

    /// Append one line (with its `\n`, if any) to `text`; the number of bytes read.
    fn read_line(&mut self, text: &mut Vec<u8>, record_start: usize, line: u64) -> Result<usize> {
        let room = (MAX_RECORD_BYTES + 1).saturating_sub((text.len() - record_start) as u64);
        let n = (&mut self.input)
            .take(room)
            .read_until(b'\n', text)
            .map_err(|source| CliError::Read { path: self.file.clone().into(), source })?;
        if (text.len() - record_start) as u64 > MAX_RECORD_BYTES {
            return Err(self.bad(line, format!("the record is longer than {MAX_RECORD_BYTES} bytes")));
        }
        self.consumed += n as u64;
        Ok(n)
    }

    /// The next record appended to `text`, or None at the end of the input. Blank lines
    /// and lines starting with `#` are skipped; a record continues over line breaks while a
    /// quoted field is open.
    pub fn next_record(&mut self, text: &mut Vec<u8>) -> Result<Option<Record>> {
        loop {
            let start = text.len();
            let line = self.line;
            if self.read_line(text, start, line)? == 0 {
                return Ok(None);
            }
            self.line += 1;
            let first = &text[start..];
            let blank = matches!(first, b"\n" | b"\r\n" | b"\r");
            if blank || first[0] == b'#' {
                text.truncate(start);
                continue;
            }
            let mut quotes = first.iter().filter(|&&b| b == b'"').count();
            while quotes % 2 == 1 && text.last() == Some(&b'\n') {
                let from = text.len();
                if self.read_line(text, start, line)? == 0 {
                    break;
                }
                self.line += 1;
                quotes += text[from..].iter().filter(|&&b| b == b'"').count();
            }
            let mut end = text.len();
            if text[start..end].ends_with(b"\n") {
                end -= 1;
                if text[start..end].ends_with(b"\r") {
                    end -= 1;
                }
            }
            text.truncate(end);
            return Ok(Some(Record { start, end, line }));
        }
    }

    /// Read records into `batch` (cleared first) until it holds `rows` of them or the input
    /// ends; false once the input is exhausted.
    ///
    /// The records are those of [`RecordReader::next_record`], with the same lines: the whole
    /// lines without a quote that lie in the input's buffer are taken from it directly (a word
    /// of bytes at a time to find their ends), any other line through `next_record`.
    pub fn fill(&mut self, batch: &mut Batch, rows: usize) -> Result<bool> {
        batch.clear();
        while batch.records.len() < rows {
            let buf = self.input.fill_buf().map_err(|source| CliError::Read { path: self.file.clone().into(), source })?;
            let used = take_plain_lines(buf, batch, rows, &mut self.line);
            self.input.consume(used);
            self.consumed += used as u64;
            if used > 0 {
                continue;
            }
            // The line at hand has a quote, or does not end in this buffer (or the input did).
            match self.next_record(&mut batch.text)? {
                Some(r) => batch.records.push(r),
                None => return Ok(false),
            }
        }
        Ok(true)
    }

    /// The header: the first record's fields as text, and its line.
    pub fn header(&mut self) -> Result<(Vec<String>, u64)> {
        let mut text = Vec::new();
        let Some(r) = self.next_record(&mut text)? else { return Ok((Vec::new(), 1)) };
        let mut rec = csv::ByteRecord::new();
        split(&text[r.start..r.end], &mut rec).map_err(|e| self.bad(r.line, e.to_string()))?;
        let mut header = Vec::with_capacity(rec.len());
        for f in rec.iter() {
            let s = std::str::from_utf8(f).map_err(|e| self.bad(r.line, format!("unreadable CSV: invalid UTF-8 in the header: {e}")))?;
            header.push(s.to_string());
        }
        Ok((header, r.line))
    }
}

/// Take from `buf` the whole lines (ending in `\n`) without a quote, up to the first other one
/// or until `batch` holds `rows` records, as [`RecordReader::next_record`] reads them: blank
/// lines and `#` comments skipped, the terminator (`\n` or `\r\n`) removed, `line` counted.
/// Returns the bytes used (0 when the first line is not such a line).
fn take_plain_lines(buf: &[u8], batch: &mut Batch, rows: usize, line: &mut u64) -> usize {
    let mut used = 0;
    while batch.records.len() < rows {
        let rest = &buf[used..];
        let comment = rest.first() == Some(&b'#');
        // A comment's quotes do not matter (it is skipped whole, as next_record does).
        let Some(at) = first_of(rest, comment) else { break };
        // A line of MAX_RECORD_BYTES or more (with its `\n`, more) is next_record's to refuse.
        if rest[at] != b'\n' || at as u64 >= MAX_RECORD_BYTES {
            break;
        }
        let mut end = at;
        if end > 0 && rest[end - 1] == b'\r' {
            end -= 1;
        }
        if !comment && end > 0 {
            let start = batch.text.len();
            batch.text.extend_from_slice(&rest[..end]);
            batch.records.push(Record { start, end: batch.text.len(), line: *line });
        }
        *line += 1;
        used += at + 1;
    }
    used
}

/// The index of the first `\n` in `bytes` (or of the first `"`, unless `newline_only`),
/// eight bytes at a time.
fn first_of(bytes: &[u8], newline_only: bool) -> Option<usize> {
    let quote_mask = if newline_only { 0 } else { u64::MAX };
    let mut words = bytes.chunks_exact(8);
    let mut base = 0;
    for chunk in &mut words {
        let w = le_word(chunk);
        let hits = bytes_equal(w, b'\n') | (bytes_equal(w, b'"') & quote_mask);
        if hits != 0 {
            return Some(base + (hits.trailing_zeros() / 8) as usize);
        }
        base += 8;
    }
    words.remainder().iter().position(|&b| b == b'\n' || (!newline_only && b == b'"')).map(|i| base + i)
}

/// Why [`split`] could not cut a record.
#[derive(Debug, thiserror::Error)]
pub enum SplitError {
    /// The `csv` reader refused the record.
    #[error("unreadable CSV: {0}")]
    Csv(#[from] csv::Error),
    /// The `csv` reader splits it into several records.
    #[error("unreadable CSV: a line break inside the record that is not within quotes (a carriage return alone?)")]
    LineBreak,
}

/// Cut one record (terminator removed) into trimmed fields, replacing `out`'s contents.
/// Errors: a record the `csv` reader splits into several (a line break inside it that is
/// not within quotes, i.e. a carriage return alone).
pub fn split(bytes: &[u8], out: &mut csv::ByteRecord) -> std::result::Result<(), SplitError> {
    out.clear();
    if !bytes.iter().any(|&b| b == b'"' || b == b'\r') {
        for f in bytes.split(|&b| b == b',') {
            out.push_field(f.trim_ascii());
        }
        return Ok(());
    }
    let mut rdr = csv::ReaderBuilder::new().has_headers(false).flexible(true).trim(csv::Trim::All).from_reader(bytes);
    match rdr.read_byte_record(out) {
        Ok(true) => {}
        Ok(false) => out.push_field(b""),
        Err(e) => return Err(e.into()),
    }
    let mut extra = csv::ByteRecord::new();
    if matches!(rdr.read_byte_record(&mut extra), Ok(true)) {
        return Err(SplitError::LineBreak);
    }
    Ok(())
}

/// A record cut into trimmed fields, reusable from record to record: [`Fields::cut`] gives
/// the same fields as [`split`], without a copy for a record of plain ASCII text.
#[derive(Debug, Default)]
pub struct Fields {
    /// Each field's bytes as a range of the text they lie in (see [`Cut::all`]).
    ranges: Vec<(usize, usize)>,
    /// The fields of a record [`split`] had to read (quotes, a carriage return, non-ASCII).
    rec: csv::ByteRecord,
}

/// The fields of one record, as [`Fields::cut`] gives them.
#[derive(Debug, Clone, Copy)]
pub struct Cut<'a> {
    /// The bytes the fields lie in: the record itself, or [`split`]'s copy.
    text: &'a [u8],
    ranges: &'a [(usize, usize)],
    /// Whether every byte is ASCII (then every field is valid UTF-8).
    pub ascii: bool,
}

impl<'a> Cut<'a> {
    /// Number of fields.
    pub fn len(&self) -> usize {
        self.ranges.len()
    }
    /// Whether there is no field (never: an empty record has one, empty).
    pub fn is_empty(&self) -> bool {
        self.ranges.is_empty()
    }
    /// Field `i`'s place in [`Cut::all`].
    pub fn range(&self, i: usize) -> (usize, usize) {
        self.ranges[i]
    }
    /// Field `i`'s bytes, trimmed.
    pub fn get(&self, i: usize) -> &'a [u8] {
        let (a, b) = self.ranges[i];
        &self.text[a..b]
    }
    /// The bytes the fields lie in, end to end (for a UTF-8 check).
    pub fn all(&self) -> &'a [u8] {
        self.text
    }
    /// The fields in order.
    pub fn iter(&self) -> impl Iterator<Item = &'a [u8]> + '_ {
        (0..self.len()).map(|i| self.get(i))
    }
}

impl Fields {
    /// Cut one record (terminator removed) into trimmed fields, as [`split`] does: a record
    /// of ASCII text without a quote or a carriage return is cut on its commas in place (no
    /// copy); any other goes through [`split`].
    pub fn cut<'a>(&'a mut self, bytes: &'a [u8]) -> std::result::Result<Cut<'a>, SplitError> {
        self.ranges.clear();
        if self.cut_plain(bytes) {
            return Ok(Cut { text: bytes, ranges: &self.ranges, ascii: true });
        }
        self.ranges.clear();
        split(bytes, &mut self.rec)?;
        for i in 0..self.rec.len() {
            let r = self.rec.range(i).unwrap_or(0..0);
            self.ranges.push((r.start, r.end));
        }
        Ok(Cut { text: self.rec.as_slice(), ranges: &self.ranges, ascii: false })
    }
}

/// Bytes of 0x01 and of 0x80: the constants of the word-at-a-time byte tests.
const ONES: u64 = 0x0101_0101_0101_0101;
const HIGH: u64 = 0x8080_8080_8080_8080;

/// The eight bytes of `chunk` (of `chunks_exact(8)`) as one little-endian word.
#[inline(always)]
fn le_word(chunk: &[u8]) -> u64 {
    let mut a = [0u8; 8];
    a.copy_from_slice(chunk);
    u64::from_le_bytes(a)
}

/// The high bit of each byte of `w` that equals `c` (exactly: no carry crosses bytes).
#[inline(always)]
fn bytes_equal(w: u64, c: u8) -> u64 {
    let v = w ^ (ONES * u64::from(c));
    !(((v & !HIGH) + !HIGH) | v) & HIGH
}

impl Fields {
    /// The fields of `bytes` cut on its commas into `self.ranges`, if it is plain (ASCII, no
    /// quote, no carriage return): eight bytes at a time, each comma found from a bit mask.
    /// False (ranges unspecified) for any other record.
    fn cut_plain(&mut self, bytes: &[u8]) -> bool {
        let mut start = 0;
        let mut words = bytes.chunks_exact(8);
        let mut base = 0;
        for chunk in &mut words {
            let w = le_word(chunk);
            if (w & HIGH) | bytes_equal(w, b'"') | bytes_equal(w, b'\r') != 0 {
                return false;
            }
            let mut commas = bytes_equal(w, b',');
            while commas != 0 {
                let at = base + (commas.trailing_zeros() / 8) as usize;
                self.ranges.push(trimmed(bytes, start, at));
                start = at + 1;
                commas &= commas - 1;
            }
            base += 8;
        }
        for (i, &b) in words.remainder().iter().enumerate() {
            match b {
                b',' => {
                    self.ranges.push(trimmed(bytes, start, base + i));
                    start = base + i + 1;
                }
                b'"' | b'\r' | 0x80.. => return false,
                _ => {}
            }
        }
        self.ranges.push(trimmed(bytes, start, bytes.len()));
        true
    }
}

/// `bytes[start..end]` without its leading and trailing ASCII white space (as `trim_ascii`), as a range.
fn trimmed(bytes: &[u8], mut start: usize, mut end: usize) -> (usize, usize) {
    while start < end && bytes[start].is_ascii_whitespace() {
        start += 1;
    }
    while end > start && bytes[end - 1].is_ascii_whitespace() {
        end -= 1;
    }
    (start, end)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn records(text: &str) -> Vec<(u64, Vec<String>)> {
        let mut r = RecordReader::new(text.as_bytes(), "t");
        let mut b = Batch::default();
        r.fill(&mut b, usize::MAX).unwrap();
        let mut rec = csv::ByteRecord::new();
        b.records
            .iter()
            .map(|x| {
                split(b.bytes(x), &mut rec).unwrap();
                (x.line, rec.iter().map(|f| String::from_utf8(f.to_vec()).unwrap()).collect())
            })
            .collect()
    }

    /// What the csv crate makes of the same text (trim, comments, flexible).
    fn csv_records(text: &str) -> Vec<Vec<String>> {
        let mut rdr = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .trim(csv::Trim::All)
            .comment(Some(b'#'))
            .from_reader(text.as_bytes());
        rdr.records().map(|r| r.unwrap().iter().map(str::to_string).collect()).collect()
    }

    #[test]
    fn fields_and_lines_as_the_csv_crate_gives_them() {
        let text = "# c\nload , speed,id\n\n 1,2 ,x\r\n\r\n#x,y\n3,\"a,\"\"b\"\"\nc\",4\n  \n5,6\n\t7 ,8,\"q\"\n9";
        let got = records(text);
        let lines: Vec<u64> = got.iter().map(|g| g.0).collect();
        assert_eq!(lines, [2, 4, 7, 9, 10, 11, 12]);
        let fields: Vec<Vec<String>> = got.into_iter().map(|g| g.1).collect();
        assert_eq!(fields, csv_records(text));
        assert_eq!(fields[2], ["3", "a,\"b\"\nc", "4"]);
    }

    /// [`Fields::cut`] gives [`split`]'s fields (and its errors) on every kind of record: plain,
    /// quoted, with carriage returns, tabs, non-ASCII bytes, empty fields.
    #[test]
    fn cut_fields_are_the_split_fields() {
        let mut f = Fields::default();
        let mut rec = csv::ByteRecord::new();
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let alphabet: &[u8] = b"0123456789.,e- \t\"\r+x#\xc3\xa9\xff\x0c\x0b";
        let mut records: Vec<Vec<u8>> = [&b""[..], b" ", b",", b" 1 , 2 ", b"\t5e3,\x0c-0.5\x0c", b"a,\"b,c\",d", b"1\r2", b"\xc3\xa9,1"].iter().map(|r| r.to_vec()).collect();
        for _ in 0..20_000 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let n = (s % 24) as usize;
            let mut r = Vec::with_capacity(n);
            let mut t = s;
            for _ in 0..n {
                t = t.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
                r.push(alphabet[((t >> 33) % alphabet.len() as u64) as usize]);
            }
            records.push(r);
        }
        for r in &records {
            let want = split(r, &mut rec).map(|()| rec.iter().map(<[u8]>::to_vec).collect::<Vec<_>>()).map_err(|e| e.to_string());
            let got = f.cut(r).map(|c| c.iter().map(<[u8]>::to_vec).collect::<Vec<_>>()).map_err(|e| e.to_string());
            assert_eq!(got, want, "record {:?}", String::from_utf8_lossy(r));
            if let Ok(c) = f.cut(r) {
                assert_eq!(c.ascii, r.is_ascii() && !r.contains(&b'"') && !r.contains(&b'\r'));
            }
        }
    }

    /// [`RecordReader::fill`] gives the records, lines, bytes consumed and errors of
    /// [`RecordReader::next_record`] read one by one, on random texts of blank lines, comments,
    /// quotes spanning lines, carriage returns and a last line without `\n`, through buffers
    /// of any size (records cut across the buffer's refills) and batches of any size.
    #[test]
    fn fill_reads_what_next_record_reads() {
        let pieces: [&[u8]; 12] = [b"1,2\n", b"\n", b"\r\n", b"# c,\"\n", b"\"a\nb\",3\n", b" 4 , 5\r\n", b"\r\r\n", b"x\"y\n", b"#\n", b"6,7", b"\"", b"  \n"];
        let mut s = 0x853c_49e6_748f_ea9bu64;
        let mut next = |n: u64| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s % n) as usize
        };
        for case in 0..3000 {
            let text: Vec<u8> = (0..next(30)).flat_map(|_| pieces[next(12)].iter().copied()).collect();
            let (capacity, rows) = (1 + next(64), 1 + next(9));
            // One by one.
            let mut one = RecordReader::new(std::io::BufReader::with_capacity(capacity, &text[..]), "t");
            let mut want = Vec::new();
            let mut t = Vec::new();
            let end = loop {
                match one.next_record(&mut t) {
                    Ok(Some(r)) => want.push((t[r.start..r.end].to_vec(), r.line)),
                    Ok(None) => break Ok(one.consumed),
                    Err(e) => break Err(e.to_string()),
                }
            };
            // In batches.
            let mut many = RecordReader::new(std::io::BufReader::with_capacity(capacity, &text[..]), "t");
            let mut got = Vec::new();
            let mut b = Batch::default();
            let got_end = loop {
                match many.fill(&mut b, rows) {
                    Ok(more) => {
                        got.extend(b.records.iter().map(|r| (b.bytes(r).to_vec(), r.line)));
                        if !more {
                            break Ok(many.consumed);
                        }
                    }
                    Err(e) => break Err(e.to_string()),
                }
            };
            assert_eq!(got, want, "case {case}: {:?} (buffer {capacity}, batch {rows})", String::from_utf8_lossy(&text));
            assert_eq!(got_end, end, "case {case}");
        }
    }

    #[test]
    fn an_overlong_record_is_refused_with_its_line() {
        // Longer, and exactly as long as the limit (with its `\n`, one byte more), as a record
        // and as a comment; one byte less is a record.
        let max = MAX_RECORD_BYTES as usize;
        for (line, refused) in [("1".repeat(max + 5), true), ("1".repeat(max), true), (format!("#{}", "1".repeat(max - 1)), true), ("1".repeat(max - 1), false)] {
            let text = format!("load,speed\n{line}\n3,4\n");
            let mut r = RecordReader::new(text.as_bytes(), "t");
            let mut b = Batch::default();
            match r.fill(&mut b, 10) {
                Err(e) => {
                    let e = e.to_string();
                    assert!(refused && e.contains("line 2") && e.contains("longer than"), "{e}");
                }
                Ok(_) => assert!(!refused && b.records.len() == 3 && b.bytes(&b.records[1]).len() == max - 1),
            }
        }
    }
}
