//! The inputs of one call, struct of arrays: one value per joint in each.

use super::error::BatchError;

/// One call's inputs, one value per joint in each slice (index i is joint i).
#[derive(Debug, Clone, Copy)]
pub struct Inputs<'a> {
    /// The joint's angle (rad): drives the presliding state (the angle the host integrates).
    pub angle: &'a [f64],
    /// Angular velocity ω (rad/s); the friction torque opposes it.
    pub angular_velocity: &'a [f64],
    /// Radial load P (N), its magnitude is used; 0 is an unloaded joint (no torque).
    pub load: &'a [f64],
    /// Lubricant temperature (K) per joint; None: each joint's parameter set's
    /// `lubricant.temperature`.
    pub temperature: Option<&'a [f64]>,
}

/// `values` has one value per joint, else [`BatchError::Shape`] naming `argument`.
pub fn check_length(argument: &'static str, values: &[f64], n: usize) -> Result<(), BatchError> {
    if values.len() == n { Ok(()) } else { Err(BatchError::Shape { argument, expected: n, got: values.len() }) }
}

/// A finite `value`, else [`BatchError::NotFinite`] naming `argument`, the joint and the unit.
#[inline]
pub fn finite(argument: &'static str, index: usize, value: f64, unit: &'static str) -> Result<f64, BatchError> {
    if value.is_finite() { Ok(value) } else { Err(BatchError::NotFinite { argument, index, value, unit }) }
}

impl Inputs<'_> {
    /// Every slice has `n` values (checked in the order angle, angular_velocity, load,
    /// temperature), and every temperature is finite.
    pub fn check(&self, n: usize) -> Result<(), BatchError> {
        check_length("angle", self.angle, n)?;
        check_length("angular_velocity", self.angular_velocity, n)?;
        check_length("load", self.load, n)?;
        if let Some(t) = self.temperature {
            check_length("temperature", t, n)?;
            for (i, &x) in t.iter().enumerate() {
                finite("temperature", i, x, "K")?;
            }
        }
        Ok(())
    }
}
