//! FMU states (`fmi2GetFMUstate`, `fmi3GetFMUState`) and their serialized form, one for both
//! standards.
//!
//! A [`Snapshot`] holds the life-cycle state, the time and the model's own
//! serialized state. `fmi2GetFMUstate`/`fmi2SetFMUstate` go through the model's
//! `serialize`/`deserialize` too, so the in-memory and the byte form are one path.
//!
//! Serialized layout (all integers little-endian), format version 1:
//!
//! | bytes | content |
//! |---|---|
//! | 8 | magic `b"FMI2STAT"` |
//! | 2 | format version (1) |
//! | 4 | total length in bytes, checksum included |
//! | 1 + n | GUID length n, GUID (ASCII) |
//! | 1 | life-cycle state code |
//! | 8 + 8 | time, start time (IEEE 754 bits) |
//! | 4 + m | model state length m, model state (the model's own versioned format) |
//! | 4 | CRC-32 of every preceding byte |
//!
//! Nothing is a memory image: no pointers, no padding, no host-dependent layout.

use super::bytes::{crc32, ByteReader, ByteWriter};
use super::state::{self, State};
use crate::error::StateFormatError;

/// The first 8 bytes of every serialized FMU state.
pub const MAGIC: [u8; 8] = *b"FMI2STAT";
/// The version of the serialized layout above; a state with another version is rejected.
pub const FORMAT_VERSION: u16 = 1;
/// Marks a live [`Snapshot`] so that a foreign or freed pointer is (usually) noticed.
const TAG: u64 = 0x5354_4154_4520_4f4b;

/// An FMU state (`fmi2FMUstate`/`fmi3FMUState`): what `fmi2SetFMUstate` needs to put an
/// instance back where it was.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    tag: u64,
    /// The GUID (instantiation token) of the model the state was taken from.
    pub guid: String,
    /// The instance's life-cycle state when the state was taken.
    pub state: State,
    /// The instance's time when the state was taken, in s.
    pub time: f64,
    /// The experiment's start time (`fmi2SetupExperiment`), in s.
    pub start_time: f64,
    /// The model's own serialized state ([`crate::core::model::Model::serialize`]).
    pub model: Vec<u8>,
}

impl Snapshot {
    /// A live FMU state from its parts.
    pub fn new(guid: &str, state: State, time: f64, start_time: f64, model: Vec<u8>) -> Self {
        Snapshot { tag: TAG, guid: guid.to_owned(), state, time, start_time, model }
    }

    /// Whether the tag is intact: false for a freed FMU state and (usually) for a pointer
    /// that never was one.
    pub fn is_live(&self) -> bool {
        self.tag == TAG
    }

    /// Clear the tag before the memory is released.
    pub fn kill(&mut self) {
        self.tag = 0;
    }

    /// The serialized form (layout in the module doc), CRC included.
    pub fn encode(&self) -> Vec<u8> {
        let mut w = ByteWriter::default();
        w.bytes(&MAGIC);
        w.u16(FORMAT_VERSION);
        w.u32(0); // total length, patched below
        w.u8(self.guid.len() as u8);
        w.bytes(self.guid.as_bytes());
        w.u8(self.state.code());
        w.f64(self.time);
        w.f64(self.start_time);
        w.u32(self.model.len() as u32);
        w.bytes(&self.model);
        let total = (w.buf.len() + 4) as u32;
        w.buf[10..14].copy_from_slice(&total.to_le_bytes());
        let crc = crc32(&w.buf);
        w.u32(crc);
        w.buf
    }

    /// Parse and check a serialized state for the model with `guid`. The model part
    /// is returned as bytes; the caller has the model check it.
    pub fn decode(bytes: &[u8], guid: &str) -> Result<Snapshot, StateFormatError> {
        let mut r = ByteReader::new(bytes);
        if r.take(8, "magic")? != MAGIC {
            return Err(StateFormatError::BadMagic);
        }
        let version = r.u16("format version")?;
        if version != FORMAT_VERSION {
            return Err(StateFormatError::Version { found: version, reads: FORMAT_VERSION });
        }
        let total = r.u32("total length")? as usize;
        if total != bytes.len() {
            return Err(StateFormatError::Length { actual: bytes.len(), header: total });
        }
        let body = &bytes[..bytes.len() - 4];
        let stored = u32::from_le_bytes(bytes[bytes.len() - 4..].try_into().unwrap());
        if crc32(body) != stored {
            return Err(StateFormatError::Crc);
        }
        let n = r.u8("GUID length")? as usize;
        let g = r.take(n, "GUID")?;
        if g != guid.as_bytes() {
            return Err(StateFormatError::OtherGuid { found: String::from_utf8_lossy(g).into_owned(), guid: guid.to_owned() });
        }
        let code = r.u8("life-cycle state")?;
        let st = State::from_code(code)
            .filter(|s| state::FMU_STATE.allows(*s))
            .ok_or(StateFormatError::LifeCycleCode(code))?;
        let time = r.f64("time")?;
        let start_time = r.f64("start time")?;
        if !time.is_finite() || !start_time.is_finite() || time < start_time {
            return Err(StateFormatError::Time { time, start: start_time });
        }
        let m = r.u32("model state length")? as usize;
        let model = r.take(m, "model state")?.to_vec();
        r.u32("checksum")?;
        r.finish()?;
        Ok(Snapshot::new(guid, st, time, start_time, model))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Snapshot {
        Snapshot::new("{g}", State::StepComplete, 1.5, 0.0, vec![1, 2, 3, 4])
    }

    #[test]
    fn round_trip() {
        let s = sample();
        let b = s.encode();
        assert_eq!(Snapshot::decode(&b, "{g}").unwrap(), s);
    }

    #[test]
    fn every_single_bit_flip_and_every_truncation_is_rejected() {
        let b = sample().encode();
        for i in 0..b.len() {
            for bit in 0..8 {
                let mut c = b.clone();
                c[i] ^= 1 << bit;
                assert!(Snapshot::decode(&c, "{g}").is_err(), "flip of bit {bit} of byte {i} accepted");
            }
        }
        for n in 0..b.len() {
            assert!(Snapshot::decode(&b[..n], "{g}").is_err(), "truncation to {n} accepted");
        }
        let mut longer = b.clone();
        longer.push(0);
        assert!(Snapshot::decode(&longer, "{g}").is_err());
    }

    #[test]
    fn wrong_version_and_wrong_model_are_named() {
        let mut b = sample().encode();
        b[8] = 2;
        let n = b.len();
        let crc = crc32(&b[..n - 4]);
        b[n - 4..].copy_from_slice(&crc.to_le_bytes());
        assert!(Snapshot::decode(&b, "{g}").unwrap_err().to_string().contains("format version 2"));
        let e = Snapshot::decode(&sample().encode(), "{other}").unwrap_err().to_string();
        assert!(e.contains("GUID"), "{e}");
    }
}
