//! The PinJointRig part of the serialized FMU state (inside the generic layer's
//! container, [`fmi_layer::core::snapshot`]), little-endian, version 3:
//!
//! | bytes | content |
//! |---|---|
//! | 1 | version (3) |
//! | 2 | n, number of settings |
//! | 8·n | every input and parameter value in table order (Booleans 0/1, Integers as f64): the stored rows of [`TABLE`], the fidelity settings (`fidelity`, `tolerance`, envelope) among them and the `temperature` input last |
//! | 8 | start time (s) |
//! | 1 | 1 if the rig simulator exists (after initialization), else 0 |
//! | 2 + m | m, then the simulator's [`RigState::to_bytes`] (m = 112) |
//!
//! Parameters are stored because the simulator is rebuilt from them on restore;
//! [`RigState`] holds the integration node, the clock and the held inputs, from
//! which the simulator continues bit for bit (its segment cache is recomputed from
//! the same node). Not stored: the integration counters and the chatter detector's
//! run length, which do not affect the results. The fidelity level (a table) is rebuilt from
//! the stored settings (deterministically: the same table) unless the instance already holds
//! one built from the same settings.
//!
//! Versions 1 (before the fidelity parameters) and 2 (before the temperature input and the
//! temperature/starvation parameters) are refused: their settings counts differ.

use super::settings::Settings;
use super::variables::{Values, STATE_VERSION, TABLE};
use crate::table::rejected;
use fmi_layer::core::bytes::{ByteReader, ByteWriter};
use fmi_layer::core::model::{ModelError, ModelResult};
use pinjoint::rig::RigState;

/// Append the PinJointRig state (the layout of the module documentation) to `out`: every
/// setting, the start time (s) and, after initialization, the simulator's `state`.
pub fn encode(settings: &Settings, start_time: f64, state: Option<RigState>, out: &mut Vec<u8>) {
    let mut w = ByteWriter::default();
    TABLE.write(STATE_VERSION, &Values { settings: *settings, ..Values::default() }, &mut w);
    w.f64(start_time);
    match state {
        None => w.u8(0),
        Some(s) => {
            let b = s.to_bytes();
            w.u8(1);
            w.u16(u16::try_from(b.len()).expect("a simulator state of 112 bytes"));
            w.bytes(&b);
        }
    }
    out.extend_from_slice(&w.buf);
}

/// Inverse of [`encode`]; every setting is checked as `fmi2SetReal` checks it, Booleans
/// must be 0 or 1 and Integers whole numbers (parameter ranges are checked when the
/// simulator is rebuilt).
pub fn decode(bytes: &[u8]) -> ModelResult<(Settings, f64, Option<RigState>)> {
    let mut r = ByteReader::new(bytes);
    let mut v = Values::default();
    TABLE.read("PinJointRig", STATE_VERSION, &mut r, &mut v)?;
    let start_time = r.f64("start time").map_err(rejected)?;
    if !start_time.is_finite() {
        return Err(ModelError::RejectedState(format!("start time {start_time} s is not finite")));
    }
    let state = match r.u8("simulator flag").map_err(rejected)? {
        0 => None,
        1 => {
            let m = usize::from(r.u16("simulator state length").map_err(rejected)?);
            let bytes = r.take(m, "simulator state").map_err(rejected)?;
            Some(RigState::from_bytes(bytes).map_err(|e| ModelError::failed("", e))?)
        }
        f => return Err(ModelError::RejectedState(format!("bad simulator flag {f}"))),
    };
    r.finish().map_err(rejected)?;
    Ok((v.settings, start_time, state))
}
