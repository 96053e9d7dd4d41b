//! The joint at rest in figures (issue 22 item 7): the two zero-velocity models of
//! [`pinjoint::zero_velocity`] in the scenes a system simulation puts the joint in.
//!
//! Files (into the figures directory):
//!   at_rest_hold.svg / .csv   a body (J = 50 kg·m²) on the pin at 20 kN under a drive of half
//!                             the breakaway torque, applied at t = 0: angle against time with
//!                             the band (it creeps) and with the presliding state (it holds);
//!                             symplectic Euler, h = 1 ms, the torque held over each step, as a
//!                             Co-Simulation host steps the FMU
//!   at_rest_loop.svg / .csv   torque against angle over a prescribed small-amplitude sine of the
//!                             angle (0.5 Hz, amplitudes 0.5 and 2 presliding angles): the band is
//!                             a function of ω (an ellipse through the origin); presliding gives
//!                             the elastic line and, past breakaway, the elasto-plastic loop

use crate::common::exact;
use crate::error::Result;
use crate::output::{output_dir, write_csv, write_text};
use crate::plot::{stacked_plot, Axis, Chart, Corner, Series};
use pinjoint::zero_velocity::{band, Presliding, PreslidingJoint};
use pinjoint::{Joint, Params};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// Load of the scenes (N).
const LOAD: f64 = 20e3;
/// Host inertia of the hold (kg·m²).
const INERTIA: f64 = 50.0;
/// Host step (s).
const STEP: f64 = 1e-3;
/// Length of the hold (s).
const HOLD: f64 = 30.0;

/// One host run: (time s, angle deg, torque N·m) every 10 ms, from a body at rest under
/// `drive` (N·m) with the friction `torque(angle, ω)`.
fn hold(drive: f64, mut torque: impl FnMut(f64, f64) -> Result<f64>) -> Result<Vec<(f64, f64, f64)>> {
    let (mut angle, mut omega) = (0.0_f64, 0.0_f64);
    let steps = (HOLD / STEP).round() as usize;
    let mut out = Vec::with_capacity(steps / 10 + 1);
    for k in 0..=steps {
        let t = torque(angle, omega)?;
        if k % 10 == 0 {
            out.push((k as f64 * STEP, angle.to_degrees(), t));
        }
        omega += STEP * (drive + t) / INERTIA;
        angle += STEP * omega;
    }
    Ok(out)
}

/// The sliding torque T(P, |ω|) (N·m).
fn bound(joint: &Joint, omega: f64) -> Result<f64> {
    Ok(joint.evaluate(LOAD, omega)?.torque)
}

/// Writes the two figures and their data into `dir`.
pub fn write(dir: &Path, params: &Params) -> Result<Vec<PathBuf>> {
    let dir = output_dir(dir)?;
    let joint = Joint::new(params)?;
    let law = Presliding::default();
    let ts = joint.boundary_torque(LOAD);
    let drive = 0.5 * ts;

    let band_run = hold(drive, |_, w| {
        let edge = if band::inside(w, band::DEFAULT_SPEED_BAND) { bound(&joint, band::DEFAULT_SPEED_BAND)? } else { 0.0 };
        Ok(band::torque(w, band::DEFAULT_SPEED_BAND, bound(&joint, w)?, edge))
    })?;
    let mut state = PreslidingJoint::new(law, 0.0);
    let presliding_run = hold(drive, |a, w| {
        let t = bound(&joint, w)?;
        let torque = state.torque_at(a, w, t);
        state.commit(a, t);
        Ok(torque)
    })?;
    let mut angle_chart = Chart::new(
        format!("(a) a body J = {INERTIA} kg·m² held at {} kN by a drive of 0.5·T_s = {:.1} N·m, explicit host h = 1 ms", LOAD / 1e3, drive),
        Axis::linear("time [s]"),
        Axis::linear("angle [deg]"),
    )
    .legend(Corner::UpperLeft);
    angle_chart = angle_chart
        .series(Series::line(format!("band (ω_b = {} rad/s): creeps", band::DEFAULT_SPEED_BAND), band_run.iter().map(|r| (r.0, r.1)).collect()))
        .series(Series::line(format!("presliding (φ_s = {} rad): holds", law.angle), presliding_run.iter().map(|r| (r.0, r.1)).collect()));
    let mut zoom = Chart::new("(b) the presliding run alone: elastic deflection, no drift", Axis::linear("time [s]"), Axis::linear("angle [deg]"))
        .legend(Corner::LowerRight);
    zoom = zoom.series(Series::line("presliding", presliding_run.iter().map(|r| (r.0, r.1)).collect()).coloured(1));
    let hold_svg = stacked_plot("Friction at rest: band against presliding under a holding drive", &[angle_chart, zoom], (900, 900))?;

    // Prescribed angle θ = A sin 2πft, ω = 2πfA cos 2πft, sampled at 1 ms.
    let f = 0.5;
    let mut loop_chart = Chart::new(
        format!("torque against angle over a 0.5 Hz sine of the angle at {} kN", LOAD / 1e3),
        Axis::linear("angle [mrad]"),
        Axis::linear("friction torque [N·m]"),
    )
    .legend(Corner::UpperLeft);
    let mut loop_rows = Vec::new();
    for (k, amplitude) in [0.5 * law.angle, 2.0 * law.angle].into_iter().enumerate() {
        let mut state = PreslidingJoint::new(law, 0.0);
        let (mut pre, mut bnd) = (Vec::new(), Vec::new());
        for i in 0..=4000 {
            let t = f64::from(i) * 1e-3;
            let (angle, w) = (amplitude * (2.0 * PI * f * t).sin(), 2.0 * PI * f * amplitude * (2.0 * PI * f * t).cos());
            let tb = bound(&joint, w)?;
            let p = state.torque_at(angle, w, tb);
            state.commit(angle, tb);
            let edge = if band::inside(w, band::DEFAULT_SPEED_BAND) { bound(&joint, band::DEFAULT_SPEED_BAND)? } else { 0.0 };
            let b = band::torque(w, band::DEFAULT_SPEED_BAND, tb, edge);
            // The second cycle: the loop, not the first loading.
            if t >= 2.0 {
                pre.push((angle * 1e3, p));
                bnd.push((angle * 1e3, b));
            }
            loop_rows.push((amplitude, t, angle, w, p, b));
        }
        let a = amplitude / law.angle;
        loop_chart = loop_chart
            .series(Series::line(format!("presliding, amplitude {a} φ_s"), pre).coloured(2 * k + 1))
            .series(Series::line(format!("band, amplitude {a} φ_s"), bnd).coloured(2 * k));
    }
    let loop_svg = stacked_plot("Friction at rest: a small-amplitude loop of the angle", &[loop_chart], (900, 600))?;

    let paths: Vec<PathBuf> = ["at_rest_hold.svg", "at_rest_hold.csv", "at_rest_loop.svg", "at_rest_loop.csv"].iter().map(|f| dir.join(f)).collect();
    let hold_rows = band_run.iter().zip(&presliding_run).map(|(b, p)| [b.0, b.1, b.2, p.1, p.2].map(exact));
    let loop_rows = loop_rows.iter().map(|r| [r.0, r.1, r.2, r.3, r.4, r.5].map(exact));
    write_text(&paths[0], &[], &hold_svg)?;
    write_csv(&paths[1], &[], ["time", "angle_band_deg", "torque_band", "angle_presliding_deg", "torque_presliding"], hold_rows)?;
    write_text(&paths[2], &[], &loop_svg)?;
    write_csv(&paths[3], &[], ["amplitude", "time", "angle", "angular_velocity", "torque_presliding", "torque_band"], loop_rows)?;
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figure shows what it says: the band creeps by degrees, presliding holds within its
    /// elastic deflection and does not drift after the first second.
    #[test]
    fn the_band_creeps_and_presliding_holds() {
        let dir = tempfile::tempdir().unwrap();
        write(dir.path(), &Params::paper()).unwrap();
        let text = std::fs::read_to_string(dir.path().join("at_rest_hold.csv")).unwrap();
        let rows: Vec<Vec<f64>> = text.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
        let last = rows.last().unwrap();
        assert!(last[1] > 5.0, "band angle after 30 s: {} deg", last[1]);
        let at_1s = rows.iter().find(|r| r[0] >= 1.0).unwrap();
        assert!(last[3].abs() < 0.1, "presliding angle {} deg", last[3]);
        assert!((last[3] - at_1s[3]).abs() < 1e-3, "presliding drift {} deg", last[3] - at_1s[3]);
    }
}
