//! One measured test: sampled time, angle and/or angular velocity, recorded actuator torque and
//! load (SI units), and the checks that catch a bad record before it is fitted.

use super::error::CalibrationError;

/// The largest angle range accepted (rad): one turn. A landing-gear pin joint articulates
/// through well under a turn; a record spanning more is taken to be in degrees.
pub const MAX_ANGLE_RANGE: f64 = std::f64::consts::TAU;
/// The largest |angular velocity| accepted (rad/s, ≈ 955 rpm; the paper's maps stop at 800 rpm).
pub const MAX_SPEED: f64 = 100.0;
/// The smallest peak speed that counts as motion (rad/s).
pub const MIN_MOTION_SPEED: f64 = 1e-4;
/// A temperature below this (K) is taken for degrees Celsius given as kelvin: no pin joint runs
/// at −123 °C, and every temperature a joint meets in °C (−60 to +150) is below it.
pub const CELSIUS_SUSPECT: f64 = 150.0;

/// One test record (SI units). `torque` is the recorded actuator torque, positive in the
/// direction of motion (the convention of `pinjoint cycle`'s `torque` column: T = J·α + sign(ω)·μRP).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Record {
    /// A name for messages and the report (e.g. the file name).
    pub name: String,
    /// Sample times (s), strictly increasing.
    pub time: Vec<f64>,
    /// Pin angle (rad), if recorded.
    pub angle: Option<Vec<f64>>,
    /// Pin angular velocity (rad/s), if recorded; else differentiated from `angle`.
    pub angular_velocity: Option<Vec<f64>>,
    /// Recorded actuator torque (N·m), positive in the direction of motion.
    pub torque: Vec<f64>,
    /// Radial load (N) at each sample.
    pub load: Vec<f64>,
    /// Lubricant temperature (K) at each sample, if known; the model is evaluated at it
    /// (`pinjoint::Joint::at_temperature`). None: the parameters' `lubricant.temperature`.
    pub temperature: Option<Vec<f64>>,
}

impl Record {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.time.len()
    }
    /// True when the record has no samples.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// Check lengths, finiteness, time order, load and the plausibility of the angle range.
    pub fn validate(&self) -> Result<(), CalibrationError> {
        self.columns().validate()
    }

    /// The record's columns, borrowed.
    pub fn columns(&self) -> Columns<'_> {
        Columns {
            name: &self.name,
            time: &self.time,
            angle: self.angle.as_deref(),
            angular_velocity: self.angular_velocity.as_deref(),
            torque: &self.torque,
            load: &self.load,
            temperature: self.temperature.as_deref(),
        }
    }
}

/// A record's columns borrowed from elsewhere (e.g. NumPy arrays), so that a long record can be
/// checked and block-averaged ([`crate::decimate`]) without a copy of every sample.
#[derive(Debug, Clone, Copy)]
pub struct Columns<'a> {
    /// A name for messages and the report.
    pub name: &'a str,
    /// Sample times (s), strictly increasing.
    pub time: &'a [f64],
    /// Pin angle (rad), if recorded.
    pub angle: Option<&'a [f64]>,
    /// Pin angular velocity (rad/s), if recorded.
    pub angular_velocity: Option<&'a [f64]>,
    /// Recorded actuator torque (N·m), positive in the direction of motion.
    pub torque: &'a [f64],
    /// Radial load (N) at each sample.
    pub load: &'a [f64],
    /// Lubricant temperature (K) at each sample, if known.
    pub temperature: Option<&'a [f64]>,
}

impl Columns<'_> {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.time.len()
    }
    /// True when there are no samples.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// Check lengths, finiteness, time order, load and the plausibility of the angle range
    /// (the checks of [`Record::validate`], sample indices those of these columns).
    pub fn validate(&self) -> Result<(), CalibrationError> {
        let rec = || self.name.to_string();
        let n = self.time.len();
        let mut columns: Vec<(&'static str, &'static str, &[f64])> =
            vec![("time", "s", self.time), ("torque", "N.m", self.torque), ("load", "N", self.load)];
        if let Some(a) = self.angle {
            columns.push(("angle", "rad", a));
        }
        if let Some(w) = self.angular_velocity {
            columns.push(("angular_velocity", "rad/s", w));
        }
        if let Some(t) = self.temperature {
            columns.push(("temperature", "K", t));
        }
        if self.angle.is_none() && self.angular_velocity.is_none() {
            return Err(CalibrationError::NoKinematics { record: rec() });
        }
        for (column, unit, v) in &columns {
            if v.len() != n {
                return Err(CalibrationError::Length { record: rec(), column, len: v.len(), expected: n });
            }
            if let Some(row) = v.iter().position(|x| !x.is_finite()) {
                let time = self.time[row];
                return Err(CalibrationError::NonFinite { record: rec(), column, row, time, value: v[row], unit });
            }
        }
        for (row, w) in self.time.windows(2).enumerate() {
            if w[1] <= w[0] {
                return Err(CalibrationError::TimeOrder { record: rec(), row: row + 1, previous: w[0], time: w[1] });
            }
        }
        if let Some(row) = self.load.iter().position(|&p| p <= 0.0) {
            return Err(CalibrationError::Load { record: rec(), row, value: self.load[row] });
        }
        if let Some(t) = self.temperature
            && let Some(row) = t.iter().position(|&x| x < CELSIUS_SUSPECT)
        {
            return Err(CalibrationError::Temperature { record: rec(), row, value: t[row], why: celsius_hint(t[row]) });
        }
        if let Some(a) = self.angle {
            let range = range_of(a);
            if range > MAX_ANGLE_RANGE {
                return Err(CalibrationError::AngleRange {
                    record: rec(),
                    range,
                    turns: range / MAX_ANGLE_RANGE,
                    limit: MAX_ANGLE_RANGE,
                    as_rad: range.to_radians(),
                });
            }
        }
        if let Some(w) = self.angular_velocity {
            let peak = w.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            if peak > MAX_SPEED {
                return Err(CalibrationError::SpeedRange { record: rec(), peak, limit: MAX_SPEED, as_rad: peak.to_radians() });
            }
        }
        Ok(())
    }
}

/// Why a temperature below [`CELSIUS_SUSPECT`] is refused, with the hint.
pub fn celsius_hint(value: f64) -> String {
    if value <= 0.0 {
        format!("a temperature must be > 0 K (kelvin? as degrees Celsius it would be {} K)", value + 273.15)
    } else {
        format!(
            "below {CELSIUS_SUSPECT} K, colder than any pin joint runs: kelvin? (as degrees Celsius it would be {} K)",
            value + 273.15
        )
    }
}

/// max − min of a non-empty slice (0 for an empty one).
pub fn range_of(v: &[f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    let (lo, hi) = v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| (lo.min(x), hi.max(x)));
    hi - lo
}
