//! Apache Parquet output and input (`pinjoint sweep --output X.parquet`, `--input X.parquet`,
//! `pinjoint map --format parquet`): written through the Rust `parquet` crate's column writers
//! ([`ParquetSink`]), read through its Arrow reader ([`ParquetRows`]).
//!
//! The columns are the CSV's: the input columns, then the result columns of
//! `pinjoint::record::COLUMNS` in the same order. Every number is a `DOUBLE` column holding the
//! double the CSV prints (bit for bit: the CSV's text is the shortest that reads back as it),
//! `regime` and `validity` are `UTF8` text columns, dictionary-encoded in the file (a handful of
//! distinct values), and an input column other than `load`, `speed` and `temperature` is text as
//! read. Pages are uncompressed (no codec is built: the floats of a sweep compress little, and
//! the sweep's floor is the evaluation) and carry no statistics. Rows are written in row groups of at most
//! [`ROW_GROUP_ROWS`], so memory stays bounded whatever the number of rows.

use arrow_schema::DataType;
use parquet::basic::{ConvertedType, LogicalType, Repetition, Type as PhysicalType};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType};
use parquet::file::properties::{EnabledStatistics, WriterProperties};
use bytes::Bytes;
use parquet::basic::{Compression, Encoding};
use parquet::column::page::{CompressedPage, Page, PageWriter};
use parquet::column::writer::ColumnCloseResult;
use parquet::file::metadata::ColumnChunkMetaData;
use parquet::file::page_index::offset_index::{OffsetIndexMetaData, PageLocation};
use parquet::file::writer::{SerializedFileWriter, SerializedPageWriter, TrackedWrite};
use parquet::schema::types::{ColumnDescPtr, ColumnPath, Type, TypePtr};
use pinjoint::OperatingPoint;
use std::io::{self, Write};
use std::sync::Arc;

/// Rows per Parquet row group (the writer holds one row group's columns in memory: 65536 rows
/// of the sweep's 20 columns are about 10 MiB).
pub const ROW_GROUP_ROWS: usize = 65_536;

/// Whether `path` names a Parquet file (its extension is `.parquet` or `.parq`, any case).
pub fn is_parquet_path(path: &std::path::Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("parquet") || e.eq_ignore_ascii_case("parq"))
}

/// One column's values for a run of rows.
#[derive(Debug, Clone)]
pub enum Values {
    /// Numbers (a `DOUBLE` column).
    Number(Vec<f64>),
    /// Text of a fixed set (regime, validity).
    Name(Vec<&'static str>),
    /// Text as read (an input column copied through).
    Text(Vec<String>),
}

impl Values {
    fn len(&self) -> usize {
        match self {
            Values::Number(v) => v.len(),
            Values::Name(v) => v.len(),
            Values::Text(v) => v.len(),
        }
    }

    /// The values from `at` on, removed from `self` (as `Vec::split_off`).
    fn split_off(&mut self, at: usize) -> Values {
        match self {
            Values::Number(v) => Values::Number(v.split_off(at)),
            Values::Name(v) => Values::Name(v.split_off(at)),
            Values::Text(v) => Values::Text(v.split_off(at)),
        }
    }
}

/// The result columns as [`Values`] of `rows` rows each, empty.
pub fn result_values(rows: usize) -> Vec<Values> {
    pinjoint::record::COLUMNS
        .iter()
        .map(|c| match c.value {
            pinjoint::record::Value::Number(_) => Values::Number(Vec::with_capacity(rows)),
            _ => Values::Name(Vec::with_capacity(rows)),
        })
        .collect()
}

/// Append the result columns of `op` to `cols` (as [`result_values`] made them).
#[inline]
pub fn push_result(cols: &mut [Values], op: &OperatingPoint) {
    for (c, v) in pinjoint::record::COLUMNS.iter().zip(cols) {
        match (c.value, v) {
            (pinjoint::record::Value::Number(f), Values::Number(v)) => v.push(f(op)),
            (pinjoint::record::Value::Regime, Values::Name(v)) => v.push(op.regime.as_str()),
            (pinjoint::record::Value::Validity, Values::Name(v)) => v.push(op.validity.as_str()),
            _ => unreachable!("result_values makes each column of its kind"),
        }
    }
}

/// The Parquet schema of columns named `names` holding `kinds` (the first block's columns):
/// `required double` for numbers, `required binary (STRING)` for text.
fn schema(names: &[String], kinds: &[Values]) -> io::Result<TypePtr> {
    let fields = names
        .iter()
        .zip(kinds)
        .map(|(n, k)| {
            let t = if matches!(k, Values::Number(_)) {
                Type::primitive_type_builder(n, PhysicalType::DOUBLE)
            } else {
                Type::primitive_type_builder(n, PhysicalType::BYTE_ARRAY).with_logical_type(Some(LogicalType::String)).with_converted_type(ConvertedType::UTF8)
            };
            t.with_repetition(Repetition::REQUIRED).build().map(Arc::new)
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(to_io)?;
    Type::group_type_builder("schema").with_fields(fields).build().map(Arc::new).map_err(to_io)
}

/// Streams blocks of rows into a Parquet file: each [`ParquetSink::write_owned`] call appends rows
/// (a row group is written every [`ROW_GROUP_ROWS`] rows), [`ParquetSink::finish`] writes the
/// rest and the footer.
///
/// The file is written through the `parquet` crate's column writers, without Arrow arrays: a
/// row group's blocks are kept as they came (no copy) and each column is handed to its
/// writer block by block. Numbers are `PLAIN` pages (a copy of the bytes; no dictionary, whose
/// hashing the floats of a sweep would not repay); names (regime, validity: a handful of
/// values) are dictionary column chunks written directly (`names_chunk`); other text goes
/// through the column writer, dictionary-encoded. No page or chunk carries statistics.
pub struct ParquetSink<W: Write + Send> {
    writer: SerializedFileWriter<W>,
    /// Whether each column holds numbers.
    numeric: Vec<bool>,
    /// The blocks of the row group being gathered, and their rows.
    pending: Vec<Vec<Values>>,
    rows: usize,
    /// The text of each name met (regime, validity), shared by its values (no copy per row).
    names: Vec<(&'static str, ByteArray)>,
}

/// Most distinct names a column chunk of [`names_chunk`] holds (its indices are bit-packed in
/// at most 8 bits).
const MAX_NAMES: usize = 256;
/// Groups of 8 values in one bit-packed run (its header one byte, as the `parquet` crate's own
/// encoder keeps it).
const RUN_GROUPS: usize = 63;

/// Column `k` of `blocks` (`rows` values) as a dictionary-encoded column chunk, when it holds
/// names ([`Values::Name`]: regime, validity) of at most [`MAX_NAMES`] distinct texts; `None`
/// otherwise (the column writer then writes it). The names are told apart by their static
/// text's address first, so no value is hashed: the dictionary page holds each distinct name
/// once (`PLAIN`), the data page their indices (`RLE_DICTIONARY`: the bit width, then
/// bit-packed runs), as the Parquet format defines them and any reader decodes them.
fn names_chunk(descr: ColumnDescPtr, blocks: &[Vec<Values>], k: usize, rows: usize) -> parquet::errors::Result<Option<(Bytes, ColumnCloseResult)>> {
    let mut names: Vec<&'static str> = Vec::new();
    let mut index: Vec<u8> = Vec::with_capacity(rows);
    for block in blocks {
        let Values::Name(v) = &block[k] else { return Ok(None) };
        for s in v {
            let i = match names.iter().position(|n| std::ptr::eq(n.as_ptr(), s.as_ptr()) && n.len() == s.len()) {
                Some(i) => i,
                None => match names.iter().position(|n| n == s) {
                    Some(i) => i,
                    None if names.len() < MAX_NAMES => {
                        names.push(s);
                        names.len() - 1
                    }
                    None => return Ok(None),
                },
            };
            index.push(i as u8);
        }
    }
    if index.len() != rows {
        return Ok(None);
    }
    let mut dict = Vec::new();
    for n in &names {
        dict.extend_from_slice(&(n.len() as u32).to_le_bytes());
        dict.extend_from_slice(n.as_bytes());
    }
    let width = (usize::BITS - (names.len().max(2) - 1).leading_zeros()) as usize;
    let mut data = Vec::with_capacity(1 + rows * width / 8 + rows / (8 * RUN_GROUPS) + 16);
    data.push(width as u8);
    for run in index.chunks(8 * RUN_GROUPS) {
        let groups = run.len().div_ceil(8);
        data.push(((groups << 1) | 1) as u8);
        for group in run.chunks(8) {
            let mut bits = 0u64;
            for (j, &v) in group.iter().enumerate() {
                bits |= u64::from(v) << (j * width);
            }
            data.extend_from_slice(&bits.to_le_bytes()[..width]);
        }
    }
    let mut sink = TrackedWrite::new(Vec::new());
    let (dict_at, data_at) = {
        let mut pages = SerializedPageWriter::new(&mut sink);
        let (dict_len, data_len) = (dict.len(), data.len());
        let d = pages.write_page(CompressedPage::new(Page::DictionaryPage { buf: dict.into(), num_values: names.len() as u32, encoding: Encoding::PLAIN, is_sorted: false }, dict_len))?;
        let page = Page::DataPage {
            buf: data.into(),
            num_values: rows as u32,
            encoding: Encoding::RLE_DICTIONARY,
            def_level_encoding: Encoding::RLE,
            rep_level_encoding: Encoding::RLE,
            statistics: None,
        };
        let v = pages.write_page(CompressedPage::new(page, data_len))?;
        pages.close()?;
        (d, v)
    };
    let chunk = Bytes::from(sink.into_inner()?);
    let len = chunk.len() as i64;
    let metadata = ColumnChunkMetaData::builder(descr)
        .set_compression(Compression::UNCOMPRESSED)
        .set_encodings(vec![Encoding::PLAIN, Encoding::RLE, Encoding::RLE_DICTIONARY])
        .set_total_compressed_size(len)
        .set_total_uncompressed_size(len)
        .set_num_values(rows as i64)
        .set_dictionary_page_offset(Some(dict_at.offset as i64))
        .set_data_page_offset(data_at.offset as i64)
        .build()?;
    let offset_index = OffsetIndexMetaData {
        page_locations: vec![PageLocation { offset: data_at.offset as i64, compressed_page_size: data_at.compressed_size as i32, first_row_index: 0 }],
        unencoded_byte_array_data_bytes: None,
    };
    let close = ColumnCloseResult { bytes_written: len as u64, rows_written: rows as u64, metadata, bloom_filter: None, column_index: None, offset_index: Some(offset_index) };
    Ok(Some((chunk, close)))
}

/// The bytes of the name `s`, shared through `names` (a handful of names: a linear search).
fn name_bytes(names: &mut Vec<(&'static str, ByteArray)>, s: &'static str) -> ByteArray {
    // The same name is the same static text: its address is compared first.
    if let Some((_, b)) = names.iter().find(|(n, _)| std::ptr::eq(n.as_ptr(), s.as_ptr()) && n.len() == s.len()).or_else(|| names.iter().find(|(n, _)| *n == s)) {
        return b.clone();
    }
    let b = ByteArray::from(s);
    names.push((s, b.clone()));
    b
}

impl<W: Write + Send> ParquetSink<W> {
    /// A sink writing to `w` the columns `names`, of the kinds of `kinds` (one [`Values`] per
    /// name, its contents ignored).
    pub fn new(w: W, names: &[String], kinds: &[Values]) -> io::Result<Self> {
        let schema = schema(names, kinds)?;
        let mut props = WriterProperties::builder()
            .set_max_row_group_size(ROW_GROUP_ROWS)
            .set_write_batch_size(8192)
            .set_dictionary_enabled(false)
            .set_statistics_enabled(EnabledStatistics::None)
            .set_created_by(format!("pinjoint {}", env!("CARGO_PKG_VERSION")));
        for (n, k) in names.iter().zip(kinds) {
            if !matches!(k, Values::Number(_)) {
                let col = ColumnPath::from(n.as_str());
                props = props.set_column_dictionary_enabled(col, true);
            }
        }
        let writer = SerializedFileWriter::new(w, schema, Arc::new(props.build())).map_err(to_io)?;
        Ok(ParquetSink { writer, numeric: kinds.iter().map(|k| matches!(k, Values::Number(_))).collect(), pending: Vec::new(), rows: 0, names: Vec::new() })
    }

    /// Append the rows of `blocks`, in order: each block one [`Values`] per column, every
    /// column of a block as long. The blocks are kept as they are (moved, not copied) until a
    /// row group of [`ROW_GROUP_ROWS`] rows is complete, which is then written.
    pub fn write_owned(&mut self, blocks: impl IntoIterator<Item = Vec<Values>>) -> io::Result<()> {
        let ncols = self.numeric.len();
        for mut block in blocks {
            let rows = block.first().map_or(0, Values::len);
            if rows == 0 {
                continue;
            }
            let kinds_match = block.iter().zip(&self.numeric).all(|(c, &n)| matches!(c, Values::Number(_)) == n);
            if block.len() != ncols || !kinds_match || block.iter().any(|c| c.len() != rows) {
                return Err(io::Error::other(format!("a block of {} columns for a schema of {ncols}, or of unequal columns or other kinds", block.len())));
            }
            let room = ROW_GROUP_ROWS - self.rows;
            if rows > room {
                // The rows past the row group's end start the next one.
                let rest: Vec<Values> = block.iter_mut().map(|c| c.split_off(room)).collect();
                self.pending.push(block);
                self.rows += room;
                self.write_row_group()?;
                self.write_owned([rest])?;
                continue;
            }
            self.pending.push(block);
            self.rows += rows;
            if self.rows == ROW_GROUP_ROWS {
                self.write_row_group()?;
            }
        }
        Ok(())
    }

    /// Write the pending blocks as one row group, column after column.
    fn write_row_group(&mut self) -> io::Result<()> {
        if self.rows == 0 {
            return Ok(());
        }
        let descrs: Vec<ColumnDescPtr> = (0..self.numeric.len()).map(|k| self.writer.schema_descr().column(k)).collect();
        let mut group = self.writer.next_row_group().map_err(to_io)?;
        for (k, descr) in descrs.into_iter().enumerate() {
            if let Some((chunk, close)) = names_chunk(descr, &self.pending, k, self.rows).map_err(to_io)? {
                group.append_column(&chunk, close).map_err(to_io)?;
                continue;
            }
            let mut col = group.next_column().map_err(to_io)?.ok_or_else(|| io::Error::other("fewer columns in the schema than in the blocks"))?;
            for block in &self.pending {
                match &block[k] {
                    Values::Number(v) => {
                        col.typed::<DoubleType>().write_batch(v, None, None).map_err(to_io)?;
                    }
                    other => {
                        let text: Vec<ByteArray> = match other {
                            Values::Name(v) => v.iter().map(|s| name_bytes(&mut self.names, s)).collect(),
                            Values::Text(v) => v.iter().map(|s| ByteArray::from(s.as_str())).collect(),
                            Values::Number(_) => unreachable!("matched above"),
                        };
                        col.typed::<ByteArrayType>().write_batch(&text, None, None).map_err(to_io)?;
                    }
                }
            }
            col.close().map_err(to_io)?;
        }
        group.close().map_err(to_io)?;
        self.pending.clear();
        self.rows = 0;
        Ok(())
    }

    /// Write the last row group and the footer (the file is complete only then) and flush.
    pub fn finish(mut self) -> io::Result<()> {
        self.write_row_group()?;
        let mut w = self.writer.into_inner().map_err(to_io)?;
        w.flush()
    }
}

/// A Parquet error as an io::Error (an I/O error as itself, so that its kind is kept).
fn to_io(e: parquet::errors::ParquetError) -> io::Error {
    match e {
        parquet::errors::ParquetError::External(inner) => match inner.downcast::<io::Error>() {
            Ok(io) => *io,
            Err(other) => io::Error::other(other.to_string()),
        },
        other => io::Error::other(other.to_string()),
    }
}

/// The points of `pinjoint map` (load, speed, speed_rpm, then the result columns) as one
/// Parquet file, the same columns and numbers as its CSV ([`crate::curves::points_csv`]).
pub fn points_parquet(w: &mut (dyn Write + Send), ops: &[OperatingPoint]) -> io::Result<()> {
    let names: Vec<String> = ["load", "speed", "speed_rpm"].iter().map(|s| (*s).to_string()).chain(crate::common::RESULT_COLUMNS.iter().map(|s| (*s).to_string())).collect();
    let mut sink = ParquetSink::new(w, &names, &block_kinds(3))?;
    for part in ops.chunks(ROW_GROUP_ROWS) {
        let mut cols: Vec<Values> = (0..3).map(|_| Values::Number(Vec::with_capacity(part.len()))).collect();
        cols.extend(result_values(part.len()));
        for op in part {
            for (k, x) in [op.load, op.angular_velocity, op.angular_velocity / crate::common::RAD_S_PER_RPM].into_iter().enumerate() {
                if let Values::Number(v) = &mut cols[k] {
                    v.push(x);
                }
            }
            push_result(&mut cols[3..], op);
        }
        sink.write_owned([cols])?;
    }
    sink.finish()
}

/// `numbers` number columns then the result columns, empty (a schema's kinds).
fn block_kinds(numbers: usize) -> Vec<Values> {
    let mut v: Vec<Values> = (0..numbers).map(|_| Values::Number(Vec::new())).collect();
    v.extend(result_values(0));
    v
}

/// One batch of a Parquet input: load (N), speed (rad/s) and temperature (K) per row.
pub type Rows = (Vec<f64>, Vec<f64>, Option<Vec<f64>>);

/// Reads `load`, `speed` and (when present) `temperature` from a Parquet file in batches.
pub struct ParquetRows {
    reader: parquet::arrow::arrow_reader::ParquetRecordBatchReader,
    /// Rows read before the current batch.
    pub row: u64,
    /// Whether the file has a `temperature` column.
    pub has_temperature: bool,
    /// The file's name, for messages.
    file: String,
}

/// Where the columns wanted are in a batch.
const WANTED: [&str; 3] = ["load", "speed", "temperature"];

impl ParquetRows {
    /// Open `path`; the columns `load` and `speed` must be there (numbers), `temperature` may be.
    pub fn open(path: &std::path::Path, batch_rows: usize) -> Result<Self, String> {
        let file = path.display().to_string();
        let f = std::fs::File::open(path).map_err(|e| format!("cannot open {file}: {e}"))?;
        let builder = parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder::try_new(f).map_err(|e| format!("{file} is not a readable Parquet file: {e}"))?;
        let schema = builder.schema().clone();
        let mut roots = Vec::new();
        let mut has_temperature = false;
        for name in WANTED {
            let hits: Vec<usize> = schema.fields().iter().enumerate().filter(|(_, f)| f.name() == name).map(|(i, _)| i).collect();
            match hits.as_slice() {
                [i] => {
                    let t = schema.field(*i).data_type();
                    if !is_number_type(t) {
                        return Err(format!("{file}: column `{name}` holds {t}, not numbers"));
                    }
                    roots.push(*i);
                    has_temperature |= name == "temperature";
                }
                [] if name == "temperature" => {}
                [] => {
                    let names: Vec<&str> = schema.fields().iter().map(|f| f.name().as_str()).collect();
                    return Err(format!("{file} has no `{name}` column (it has: {})", names.join(",")));
                }
                _ => return Err(format!("{file} names the column `{name}` more than once")),
            }
        }
        let mask = parquet::arrow::ProjectionMask::roots(builder.parquet_schema(), roots);
        let reader = builder.with_projection(mask).with_batch_size(batch_rows).build().map_err(|e| format!("{file}: {e}"))?;
        Ok(ParquetRows { reader, row: 0, has_temperature, file })
    }

    /// The next batch: (load, speed, temperature) per row, or None at the end. A missing
    /// (null) value is an error naming its row (1-based, in the file's order).
    pub fn next_batch(&mut self) -> Result<Option<Rows>, String> {
        let Some(batch) = self.reader.next() else { return Ok(None) };
        let batch = batch.map_err(|e| format!("{}: {e}", self.file))?;
        let column = |name: &str| -> Result<Option<Vec<f64>>, String> {
            let Some(a) = batch.column_by_name(name) else { return Ok(None) };
            numbers(a.as_ref()).map(Some).map_err(|(i, what)| format!("{}: row {}: column {name} {what}", self.file, self.row + i as u64 + 1))
        };
        let load = column("load")?.ok_or_else(|| format!("{}: no `load` column", self.file))?;
        let speed = column("speed")?.ok_or_else(|| format!("{}: no `speed` column", self.file))?;
        let temperature = column("temperature")?;
        self.row += load.len() as u64;
        Ok(Some((load, speed, temperature)))
    }
}

fn is_number_type(t: &DataType) -> bool {
    matches!(t, DataType::Float64 | DataType::Float32 | DataType::Int8 | DataType::Int16 | DataType::Int32 | DataType::Int64 | DataType::UInt8 | DataType::UInt16 | DataType::UInt32 | DataType::UInt64)
}

/// A numeric Arrow array as doubles (integers and floats converted as Rust's `as` does: exact
/// for every float and for integers up to 2^53); the index of a null and what is wrong.
fn numbers(a: &dyn arrow_array::Array) -> Result<Vec<f64>, (usize, &'static str)> {
    use arrow_array::cast::AsArray;
    use arrow_array::types::{Float32Type, Float64Type, Int16Type, Int32Type, Int64Type, Int8Type, UInt16Type, UInt32Type, UInt64Type, UInt8Type};
    if let Some(i) = (0..a.len()).find(|&i| a.is_null(i)) {
        return Err((i, "is missing (null)"));
    }
    // `as`: exact for every float and small integer; 64-bit integers round to the nearest double.
    #[allow(clippy::cast_lossless)]
    fn cast<T: Copy + num_cast::ToDouble>(v: &[T]) -> Vec<f64> {
        v.iter().map(|&x| x.to_double()).collect()
    }
    macro_rules! conv {
        ($t:ty) => {
            cast(a.as_primitive::<$t>().values())
        };
    }
    Ok(match a.data_type() {
        DataType::Float64 => a.as_primitive::<Float64Type>().values().to_vec(),
        DataType::Float32 => conv!(Float32Type),
        DataType::Int8 => conv!(Int8Type),
        DataType::Int16 => conv!(Int16Type),
        DataType::Int32 => conv!(Int32Type),
        DataType::Int64 => conv!(Int64Type),
        DataType::UInt8 => conv!(UInt8Type),
        DataType::UInt16 => conv!(UInt16Type),
        DataType::UInt32 => conv!(UInt32Type),
        DataType::UInt64 => conv!(UInt64Type),
        _ => return Err((0, "is not numbers")),
    })
}

/// `as f64` for the numeric types of an Arrow column.
mod num_cast {
    /// The value as a double (Rust's `as`).
    pub trait ToDouble {
        /// See the trait.
        fn to_double(self) -> f64;
    }
    macro_rules! impl_as {
        ($($t:ty),*) => {
            $(impl ToDouble for $t {
                #[allow(clippy::cast_lossless, clippy::cast_precision_loss)]
                fn to_double(self) -> f64 {
                    self as f64
                }
            })*
        };
    }
    impl_as!(f32, i8, i16, i32, i64, u8, u16, u32, u64);
}

#[cfg(test)]
mod tests {
    use super::*;
    use arrow_array::cast::AsArray;
    use arrow_array::types::Float64Type;

    /// A file of a number column and a name column written by [`ParquetSink`] in blocks of
    /// `block` rows, read back by the Arrow reader: (numbers, names).
    fn round_trip(names: &[&'static str], block: usize) -> (Vec<f64>, Vec<String>) {
        let cols = ["x".to_string(), "name".to_string()];
        let mut file = Vec::new();
        let mut sink = ParquetSink::new(&mut file, &cols, &[Values::Number(Vec::new()), Values::Name(Vec::new())]).unwrap();
        for (b, part) in names.chunks(block).enumerate() {
            let x = (0..part.len()).map(|i| (b * block + i) as f64 * 0.1).collect();
            sink.write_owned([vec![Values::Number(x), Values::Name(part.to_vec())]]).unwrap();
        }
        sink.finish().unwrap();
        let reader = parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder::try_new(Bytes::from(file)).unwrap();
        assert!(reader.metadata().row_groups().iter().all(|g| g.num_rows() as usize <= ROW_GROUP_ROWS));
        let (mut x, mut n) = (Vec::new(), Vec::new());
        for batch in reader.build().unwrap() {
            let batch = batch.unwrap();
            x.extend(batch.column(0).as_primitive::<Float64Type>().values().iter());
            n.extend(batch.column(1).as_string::<i32>().iter().map(|s| s.unwrap().to_string()));
        }
        (x, n)
    }

    /// Name columns read back as written: one name, a few (regime's, validity's), as many as a
    /// byte indexes and more (then the column writer's path); row counts that are not multiples
    /// of 8 nor of a bit-packed run, several row groups, blocks split across them; equal names
    /// at other addresses are one name.
    #[test]
    fn name_columns_read_back_as_written() {
        let many: Vec<&'static str> = (0..300).map(|i| &*Box::leak(format!("name{i}").into_boxed_str())).collect();
        let same_text: &'static str = Box::leak(String::from("mixed").into_boxed_str());
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let mut pick = |n: usize| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s % n as u64) as usize
        };
        let few = ["boundary", "mixed", "full-film", same_text];
        let cases: Vec<(Vec<&'static str>, usize)> = vec![
            (vec!["checked"; 5], 512),
            ((0..1001).map(|_| few[pick(4)]).collect(), 512),
            ((0..ROW_GROUP_ROWS + 777).map(|_| few[pick(4)]).collect(), 1000),
            ((0..5000).map(|_| many[pick(256)]).collect(), 333),
            ((0..5000).map(|_| many[pick(300)]).collect(), 4096),
        ];
        for (names, block) in cases {
            let (x, got) = round_trip(&names, block);
            assert_eq!(got, names, "{} rows in blocks of {block}", names.len());
            assert!(x.iter().enumerate().all(|(i, v)| v.to_bits() == (i as f64 * 0.1).to_bits()));
        }
    }
}
