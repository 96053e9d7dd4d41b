//! Little-endian byte writer/reader and CRC-32 for the serialized FMU state.

use crate::error::StateFormatError;

/// Appends fixed-width little-endian values.
#[derive(Debug, Default)]
pub struct ByteWriter {
    /// The bytes written so far.
    pub buf: Vec<u8>,
}

impl ByteWriter {
    /// Append one byte.
    pub fn u8(&mut self, v: u8) {
        self.buf.push(v);
    }
    /// Append a little-endian u16.
    pub fn u16(&mut self, v: u16) {
        self.buf.extend_from_slice(&v.to_le_bytes());
    }
    /// Append a little-endian u32.
    pub fn u32(&mut self, v: u32) {
        self.buf.extend_from_slice(&v.to_le_bytes());
    }
    /// The exact bit pattern, so that NaN payloads and −0.0 survive.
    pub fn f64(&mut self, v: f64) {
        self.buf.extend_from_slice(&v.to_bits().to_le_bytes());
    }
    /// Append raw bytes.
    pub fn bytes(&mut self, v: &[u8]) {
        self.buf.extend_from_slice(v);
    }
}

/// Reads what [`ByteWriter`] wrote; every read checks the remaining length and fails with a
/// [`StateFormatError`] naming the field and its offset.
#[derive(Debug)]
pub struct ByteReader<'a> {
    /// The bytes not read yet.
    rest: &'a [u8],
    /// The length of the whole input, for offsets in messages.
    total: usize,
}

impl<'a> ByteReader<'a> {
    /// A reader at the start of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self { rest: data, total: data.len() }
    }
    /// The next `n` bytes; an error names `what` was being read when fewer remain.
    pub fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8], StateFormatError> {
        let Some((head, tail)) = self.rest.split_at_checked(n) else {
            return Err(StateFormatError::Truncated {
                what: what.to_owned(),
                needed: n,
                offset: self.total - self.rest.len(),
                remaining: self.rest.len(),
            });
        };
        self.rest = tail;
        Ok(head)
    }
    /// The next `N` bytes as an array.
    fn array<const N: usize>(&mut self, what: &str) -> Result<[u8; N], StateFormatError> {
        let mut a = [0; N];
        a.copy_from_slice(self.take(N, what)?);
        Ok(a)
    }
    /// Read one byte (`what`: for the error message).
    pub fn u8(&mut self, what: &str) -> Result<u8, StateFormatError> {
        Ok(self.array::<1>(what)?[0])
    }
    /// Read a little-endian u16.
    pub fn u16(&mut self, what: &str) -> Result<u16, StateFormatError> {
        self.array(what).map(u16::from_le_bytes)
    }
    /// Read a little-endian u32.
    pub fn u32(&mut self, what: &str) -> Result<u32, StateFormatError> {
        self.array(what).map(u32::from_le_bytes)
    }
    /// Read an f64 from its exact bit pattern.
    pub fn f64(&mut self, what: &str) -> Result<f64, StateFormatError> {
        self.array(what).map(|b| f64::from_bits(u64::from_le_bytes(b)))
    }
    /// Fail unless every byte was read.
    pub fn finish(&self) -> Result<(), StateFormatError> {
        if !self.rest.is_empty() {
            return Err(StateFormatError::Trailing(self.rest.len()));
        }
        Ok(())
    }
}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), as in zip and PNG.
pub fn crc32(data: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_check_value() {
        // The standard check value of CRC-32/ISO-HDLC.
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }

    #[test]
    fn round_trip_and_truncation() {
        let mut w = ByteWriter::default();
        w.u8(7);
        w.u16(513);
        w.u32(70000);
        w.f64(-0.0);
        w.f64(f64::from_bits(0x7ff8_0000_0000_0001));
        let mut r = ByteReader::new(&w.buf);
        assert_eq!(r.u8("a").unwrap(), 7);
        assert_eq!(r.u16("b").unwrap(), 513);
        assert_eq!(r.u32("c").unwrap(), 70000);
        assert_eq!(r.f64("d").unwrap().to_bits(), (-0.0f64).to_bits());
        assert_eq!(r.f64("e").unwrap().to_bits(), 0x7ff8_0000_0000_0001);
        r.finish().unwrap();
        let mut r = ByteReader::new(&w.buf[..4]);
        r.u8("a").unwrap();
        let e = r.u32("c").unwrap_err().to_string();
        assert_eq!(e, "truncated: c needs 4 bytes at offset 1 but only 3 remain");
        assert_eq!(ByteReader::new(&[1, 2]).finish().unwrap_err().to_string(), "2 unexpected trailing bytes");
    }
}
