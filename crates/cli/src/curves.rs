//! Operating points along a speed sweep at one load, and their CSV: shared by `stribeck`
//! (Figure 3) and `map` (Figure 4).

use super::common::{csv_io, exact, result_fields, RAD_S_PER_RPM, RESULT_COLUMNS};
use super::error::{CliError, Result};
use pinjoint::{Joint, OperatingPoint};
use rayon::prelude::*;

/// The model over `speeds` (rad/s) at `load`, on every core, in order.
pub fn curve(joint: &Joint, load: f64, speeds: &[f64]) -> Result<Vec<OperatingPoint>> {
    speeds.par_iter().map(|&w| joint.evaluate(load, w).map_err(CliError::from)).collect()
}

/// CSV: load, speed, speed_rpm, then the result columns.
pub fn points_csv(w: &mut dyn std::io::Write, ops: &[OperatingPoint]) -> std::io::Result<()> {
    let mut wtr = csv::Writer::from_writer(w);
    wtr.write_record(["load", "speed", "speed_rpm"].into_iter().chain(RESULT_COLUMNS)).map_err(csv_io)?;
    for op in ops {
        let head = [exact(op.load), exact(op.angular_velocity), exact(op.angular_velocity / RAD_S_PER_RPM)];
        wtr.write_record(head.into_iter().chain(result_fields(op))).map_err(csv_io)?;
    }
    wtr.flush()?;
    Ok(())
}
