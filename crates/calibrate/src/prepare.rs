//! From records to fit points: kinematics (given or differentiated), plausibility checks,
//! the exclusion rule, and the targets y = T − J·α.

use super::derivative::{default_half_width, local_poly_derivatives, stroke_count};
use super::error::CalibrationError;
use super::exclusion::{classify, ExclusionRule, RecordExclusion};
use super::record::{range_of, Record, MAX_SPEED, MIN_MOTION_SPEED};
use super::result::Series;
use pinjoint::Params;

/// The samples needed in a record at the least.
pub const MIN_SAMPLES: usize = 20;

/// One record after kinematics and exclusion.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// Name of the record.
    pub name: String,
    /// Sample times (s).
    pub time: Vec<f64>,
    /// Recorded angle (rad), if the record has one.
    pub angle: Option<Vec<f64>>,
    /// Angular velocity used by the model (rad/s).
    pub omega: Vec<f64>,
    /// Angular acceleration (rad/s²).
    pub alpha: Vec<f64>,
    /// Whether `alpha` is the angle's cubic second derivative (no velocity column), so that
    /// [`crate::derivative::matched_taps`] apply.
    pub alpha_from_angle: bool,
    /// Recorded torque (N·m).
    pub torque: Vec<f64>,
    /// Radial load on the pin (N).
    pub load: Vec<f64>,
    /// Lubricant temperature (K) at each sample, if the record gives it.
    pub temperature: Option<Vec<f64>>,
    /// Stroke index of each used sample, None for an excluded one.
    pub stroke: Vec<Option<usize>>,
    /// Time since the sample's settling window began (s).
    pub since: Vec<f64>,
    /// What the exclusion rule did to the record.
    pub exclusion: RecordExclusion,
    /// Differentiator half-width used (samples).
    pub half_width: usize,
    /// rms(raw − smoothed velocity)/rms(smoothed) over the used samples, the raw velocity
    /// being the angle's central difference: ≈ 0 for smooth motion, ≈ 1 for stick-slip
    /// (None without an angle column).
    pub irregularity: Option<f64>,
}

impl Prepared {
    /// The record's [`Series`] with the model's J·α, fitted torque and used flags.
    pub fn series(&self, inertia_torque: Vec<f64>, fitted: Vec<f64>, used: Vec<bool>) -> Series {
        Series {
            record: self.name.clone(),
            time: self.time.clone(),
            angle: self.angle.clone(),
            angular_velocity: self.omega.clone(),
            load: self.load.clone(),
            measured: self.torque.clone(),
            inertia_torque,
            fitted,
            used,
        }
    }
}

/// Irregularity above which a record is reported as stick-slip.
pub const STICK_SLIP_IRREGULARITY: f64 = 0.1;

/// Check `record` (its temperatures inside the model's range for `params`), find its velocity
/// and acceleration, and apply the exclusion rule.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(a >= b)` also catches NaN; kept as written
pub fn prepare(record: &Record, params: &Params, rule: &ExclusionRule, half_width: Option<usize>) -> Result<Prepared, CalibrationError> {
    let name = record.name.clone();
    record.validate()?;
    check_temperatures(record, params)?;
    let n = record.len();
    if n < MIN_SAMPLES {
        return Err(CalibrationError::TooShort { record: name, samples: n, needed: MIN_SAMPLES, why: "a record must hold a few strokes" });
    }
    let strokes = match (&record.angle, &record.angular_velocity) {
        (Some(a), _) => stroke_count(a),
        (None, Some(w)) => 1 + w.windows(2).filter(|p| p[0] * p[1] < 0.0).count(),
        (None, None) => unreachable!("validate() requires angle or angular_velocity"),
    };
    let k = half_width.unwrap_or_else(|| default_half_width(n, strokes));
    if n < 2 * k + 1 {
        return Err(CalibrationError::TooShort { record: name, samples: n, needed: 2 * k + 1, why: "the differentiator's window" });
    }
    let t = &record.time;
    let from_angle = record.angle.as_ref().map(|a| local_poly_derivatives(t, a, k, 3));
    let (omega, alpha): (Vec<f64>, Vec<f64>) = match (&record.angular_velocity, &from_angle) {
        (Some(w), derived) => {
            let alpha = local_poly_derivatives(t, w, k, 2).into_iter().map(|d| d.0).collect();
            if let Some(d) = derived {
                check_consistent(&name, w, d)?;
            }
            (w.clone(), alpha)
        }
        (None, Some(d)) => d.iter().copied().unzip(),
        (None, None) => unreachable!("validate() requires angle or angular_velocity"),
    };
    let peak = omega.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let angle_range = record.angle.as_deref().map(range_of).unwrap_or(f64::NAN);
    if !(peak >= MIN_MOTION_SPEED) {
        return Err(CalibrationError::NoMotion { record: name, peak, angle_range });
    }
    if peak > MAX_SPEED {
        return Err(CalibrationError::SpeedRange { record: name, peak, limit: MAX_SPEED, as_rad: peak.to_radians() });
    }
    let c = classify(&name, t, &omega, rule);
    let irregularity = record.angle.as_ref().map(|a| {
        let (mut num, mut den) = (0.0, 0.0);
        for i in 1..n - 1 {
            if c.stroke[i].is_some() {
                let raw = (a[i + 1] - a[i - 1]) / (t[i + 1] - t[i - 1]);
                num += (raw - omega[i]).powi(2);
                den += omega[i].powi(2);
            }
        }
        if den > 0.0 { (num / den).sqrt() } else { 0.0 }
    });
    Ok(Prepared {
        name,
        time: t.clone(),
        angle: record.angle.clone(),
        omega,
        alpha,
        alpha_from_angle: record.angular_velocity.is_none() && record.angle.is_some(),
        torque: record.torque.clone(),
        load: record.load.clone(),
        temperature: record.temperature.clone(),
        stroke: c.stroke,
        since: c.since,
        exclusion: c.summary,
        half_width: k,
        irregularity,
    })
}

/// Every temperature of `record` must be one the model takes with `params` (its range, and
/// η0(T) a liquid's): checked at each change of value, so a constant column costs one check.
pub fn check_temperatures(record: &Record, params: &Params) -> Result<(), CalibrationError> {
    let Some(t) = &record.temperature else { return Ok(()) };
    let mut last = f64::NAN;
    for (row, &x) in t.iter().enumerate() {
        if x.to_bits() == last.to_bits() {
            continue;
        }
        last = x;
        let mut p = *params;
        p.lubricant.temperature = x;
        if let Err(e) = p.validate() {
            return Err(CalibrationError::Temperature { record: record.name.clone(), row, value: x, why: format!("the model refuses it: {e}") });
        }
    }
    Ok(())
}

/// The derivative of the angle must match the given velocity (least-squares ratio within 20 %).
fn check_consistent(name: &str, w: &[f64], d: &[(f64, f64)]) -> Result<(), CalibrationError> {
    let (num, den) = w.iter().zip(d).fold((0.0, 0.0), |(a, b), (w, d)| (a + w * d.0, b + w * w));
    if den == 0.0 {
        return Ok(());
    }
    let ratio = num / den;
    if (ratio - 1.0).abs() <= 0.2 {
        return Ok(());
    }
    let deg = 180.0 / std::f64::consts::PI;
    let hint = if (ratio / deg - 1.0).abs() < 0.1 {
        ": the angle looks like degrees"
    } else if (ratio * deg - 1.0).abs() < 0.1 {
        ": the angular_velocity looks like deg/s"
    } else if (ratio * 60.0 / std::f64::consts::TAU - 1.0).abs() < 0.1 {
        ": the angular_velocity looks like rpm"
    } else {
        ""
    };
    Err(CalibrationError::Inconsistent { record: name.to_string(), ratio, hint })
}
