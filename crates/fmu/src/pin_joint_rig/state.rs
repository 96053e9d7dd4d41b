//! The PinJointRig part of the serialized FMU state (inside the generic layer's
//! container, [`fmi_layer::fmi2::snapshot`]), little-endian, version 3:
//!
//! | bytes | content |
//! |---|---|
//! | 1 | version (3) |
//! | 2 | n, number of settings |
//! | 8·n | every input and parameter value in table order (Booleans 0/1, Integers as f64), the fidelity settings (`fidelity`, `tolerance`, envelope), then the `temperature` input last |
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

// Version 3: the `temperature` input is the last setting.

use super::settings::Settings;
use super::variables::{Var, LAYOUT};
use fmi_layer::fmi2::bytes::{ByteReader, ByteWriter};
use fmi_layer::fmi2::model::ModelResult;
use pinjoint::rig::RigState;

const VERSION: u8 = 3;

fn settings_vars() -> impl Iterator<Item = Var> {
    LAYOUT.iter().copied().filter(|v| !matches!(v, Var::Out(_)))
}

/// Append the PinJointRig state (the layout of the module documentation) to `out`: every
/// setting, the start time (s) and, after initialization, the simulator's `state`.
pub fn encode(settings: &Settings, start_time: f64, state: Option<RigState>, out: &mut Vec<u8>) {
    let mut w = ByteWriter::default();
    w.u8(VERSION);
    w.u16(settings_vars().count() as u16);
    for v in settings_vars() {
        w.f64(settings.get(v));
    }
    w.f64(start_time);
    match state {
        None => w.u8(0),
        Some(s) => {
            let b = s.to_bytes();
            w.u8(1);
            w.u16(b.len() as u16);
            w.bytes(&b);
        }
    }
    out.extend_from_slice(&w.buf);
}

/// Inverse of [`encode`]; inputs are checked as `fmi2SetReal` checks them, Booleans
/// must be 0 or 1 and Integers whole numbers (parameter ranges are checked when the
/// simulator is rebuilt).
pub fn decode(bytes: &[u8]) -> ModelResult<(Settings, f64, Option<RigState>)> {
    let mut r = ByteReader::new(bytes);
    let version = r.u8("PinJointRig state version")?;
    if version != VERSION {
        return Err(format!("PinJointRig state version {version}; this FMU reads version {VERSION}").into());
    }
    let n = r.u16("settings count")? as usize;
    let expected = settings_vars().count();
    if n != expected {
        return Err(format!("PinJointRig state holds {n} settings; version {VERSION} has {expected}").into());
    }
    let mut s = Settings::default();
    for v in settings_vars() {
        let x = r.f64("setting")?;
        Settings::check_input(v, x)?;
        let whole = x.fract() == 0.0;
        match v {
            Var::UseCommandInput if x != 0.0 && x != 1.0 => return Err(format!("use_command_input = {x} is not a Boolean").into()),
            Var::Formulation | Var::Method | Var::Fidelity if !whole => return Err(format!("an Integer parameter holds {x}").into()),
            _ => {}
        }
        s.set(v, x);
    }
    let start_time = r.f64("start time")?;
    if !start_time.is_finite() {
        return Err(format!("start time {start_time} s is not finite").into());
    }
    let state = match r.u8("simulator flag")? {
        0 => None,
        1 => {
            let m = r.u16("simulator state length")? as usize;
            Some(RigState::from_bytes(r.take(m, "simulator state")?).map_err(|e| e.to_string())?)
        }
        f => return Err(format!("bad simulator flag {f}").into()),
    };
    r.finish()?;
    Ok((s, start_time, state))
}
