//! The speed-band treatment of the rest point (the law of earlier versions, unchanged).
//!
//! Inside a band |ω| < ω_b the torque is the band-edge torque scaled linearly,
//!
//! `T(ω) = −T(P, ω_b) · ω / ω_b`   for |ω| < ω_b,
//!
//! and outside it exactly the library's −sign(ω)·μRP ([`crate::OperatingPoint::signed_torque`]),
//! bit for bit. The ramp is continuous at |ω| = ω_b, odd in ω and zero at rest.
//!
//! Stability: inside the band the friction acts as a viscous damper of coefficient
//! k = T(P, ω_b)/ω_b; an explicit host step h with inertia J multiplies ω by 1 − h·k/J, which
//! does not change sign (no chatter) when ω_b > h·T(P, ω_b)/J. The price of the band is
//! creep: a drive torque below breakaway moves the joint at ω = T_drive·ω_b/T(P, ω_b)
//! instead of holding it.

use crate::joint::opposing;

/// Default band half-width ω_b (rad/s).
pub const DEFAULT_SPEED_BAND: f64 = 0.01;

/// Whether ω is inside the band (where the edge torque is needed).
#[inline]
pub fn inside(omega: f64, band: f64) -> bool {
    omega.abs() < band
}

/// The friction torque on the pin (N·m): outside the band, `sliding` (the magnitude T(P, |ω|))
/// opposing ω; inside, the band-edge magnitude `edge` = T(P, ω_b) ramped linearly.
#[inline]
pub fn torque(omega: f64, band: f64, sliding: f64, edge: f64) -> f64 {
    if inside(omega, band) { -edge * (omega / band) } else { opposing(sliding, omega) }
}

/// Check ω_b (a finite number ≥ 0).
pub fn check_band(band: f64) -> Result<(), super::error::ZeroVelocityError> {
    if band.is_finite() && band >= 0.0 {
        Ok(())
    } else {
        Err(super::error::ZeroVelocityError::Invalid { name: "zero_velocity.speed_band", value: band, unit: "rad/s", rule: "it must be a finite number >= 0" })
    }
}
