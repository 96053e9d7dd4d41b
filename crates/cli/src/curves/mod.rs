//! The model along speed sweeps and the paper's figures drawn from them, shared by the commands
//! `stribeck` (Figure 3), `map` (Figure 4) and `figures` (both): this file holds the operating
//! points along a speed sweep at one load and their CSV; [`stribeck`] writes Figure 3,
//! [`map`] Figure 4.

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod stribeck;
pub mod map;

use crate::common::{csv_table, exact, result_fields, RAD_S_PER_RPM, RESULT_COLUMNS};
use crate::error::{CliError, Result};
use pinjoint::{Joint, OperatingPoint};
use rayon::prelude::*;

/// The model over `speeds` (rad/s, ascending) at `load`, on every core, in order. The curve
/// ends before the first speed where the fluid film passes the diametral clearance
/// ([`pinjoint::ModelError::FilmBeyondClearance`], said once on standard error); that error
/// at the first speed, and any other error, is the answer.
pub fn curve(joint: &Joint, load: f64, speeds: &[f64]) -> Result<Vec<OperatingPoint>> {
    let all: Vec<_> = speeds.par_iter().map(|&w| joint.evaluate(load, w)).collect();
    let mut ops = Vec::with_capacity(all.len());
    for r in all {
        match r {
            Ok(op) => ops.push(op),
            Err(e @ pinjoint::ModelError::FilmBeyondClearance { .. }) if !ops.is_empty() => {
                eprintln!("note: the curve at {} N ends at {} of {} speeds: {e}", pinjoint::fmt::Num(load), ops.len(), speeds.len());
                break;
            }
            Err(e) => return Err(CliError::from(e)),
        }
    }
    Ok(ops)
}

/// CSV: load, speed, speed_rpm, then the result columns.
pub fn points_csv(w: &mut dyn std::io::Write, ops: &[OperatingPoint]) -> std::io::Result<()> {
    let rows = ops.iter().map(|op| [op.load, op.angular_velocity, op.angular_velocity / RAD_S_PER_RPM].map(exact).into_iter().chain(result_fields(op)));
    csv_table(w, ["load", "speed", "speed_rpm"].into_iter().chain(RESULT_COLUMNS), rows)
}
