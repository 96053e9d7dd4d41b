//! The zero-velocity treatment of the friction torque.
//!
//! Eq. 11 gives the torque's magnitude `T = μ R P_T`; its direction opposes ω, so
//! the signed torque jumps from −T to +T as ω passes through zero. A host that
//! integrates `J dω/dt = T_drive − T_friction` with a fixed communication step
//! then chatters around every reversal. Inside a small band `|ω| < ω_b`
//! (`zero_velocity.speed_band`) the torque is the band-edge torque scaled
//! linearly:
//!
//! `T(ω) = −T(P, ω_b) · ω / ω_b`   for `|ω| < ω_b`,
//!
//! and outside the band it is exactly the library's `−sign(ω)·μRP`
//! ([`pinjoint::OperatingPoint::signed_torque`]), bit for bit. The ramp is
//! continuous at `|ω| = ω_b`, odd in ω and zero at rest.
//!
//! Stability: inside the band the friction acts as a viscous damper of
//! coefficient `k = T(P, ω_b)/ω_b`. An explicit host step `h` with inertia `J`
//! then updates ω by the factor `1 − h·k/J`, which has no sign change (no
//! chatter) when `h·k/J < 1`, that is for
//!
//! `ω_b > h · T(P, ω_b) / J  ≈  h · μ_c R P / J`.
//!
//! The default ω_b = 0.01 rad/s (0.57 deg/s, 5 % of the paper's typical 12 deg/s)
//! meets this at h = 1 ms and the paper's largest load (60 kN, μ_c R P = 201.6 N·m)
//! for J ≥ 20.2 kg·m². For lighter inertias or longer steps raise the band;
//! `ω_b = 0` switches the treatment off (pure sign, zero torque exactly at rest).
//! The price of the band is that a drive torque below the breakaway torque makes
//! the joint creep at `ω = T_drive·ω_b/T(P, ω_b)` instead of sticking.

use pinjoint::{Joint, ModelError, OperatingPoint};

/// Default band half-width ω_b (rad/s).
pub const DEFAULT_SPEED_BAND: f64 = 0.01;

/// The friction torque on the pin (N·m, opposite to ω) at `load` (N, > 0) and
/// `omega` (rad/s), where `at_omega` is the library's operating point at (load, ω).
pub fn friction_torque(joint: &Joint, load: f64, omega: f64, band: f64, at_omega: &OperatingPoint) -> Result<f64, ModelError> {
    if omega.abs() >= band {
        return Ok(at_omega.signed_torque());
    }
    let edge = joint.evaluate(load, band)?;
    Ok(-edge.torque * (omega / band))
}

/// Check ω_b; the message names the parameter, its value and unit.
pub fn check_band(band: f64) -> fmi_layer::fmi2::model::ModelResult<()> {
    if band.is_finite() && band >= 0.0 {
        Ok(())
    } else {
        let rule = "is out of range: it must be a finite number >= 0";
        Err(fmi_layer::fmi2::model::ModelError::invalid("parameter", "zero_velocity.speed_band", band, "rad/s", rule))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use pinjoint::Params;

    fn t(j: &Joint, p: f64, w: f64, b: f64) -> f64 {
        friction_torque(j, p, w, b, &j.evaluate(p, w).unwrap()).unwrap()
    }

    #[test]
    fn outside_the_band_the_torque_is_the_library_value_exactly() {
        let j = Joint::new(&Params::default()).unwrap();
        for &w in &[0.01, -0.01, 0.0100001, 0.2, -3.0, 83.8] {
            assert_eq!(t(&j, 20e3, w, 0.01).to_bits(), j.evaluate(20e3, w).unwrap().signed_torque().to_bits(), "w = {w}");
        }
    }

    #[test]
    fn inside_the_band_the_ramp_is_linear_odd_continuous_and_zero_at_rest() {
        let j = Joint::new(&Params::default()).unwrap();
        let edge = j.evaluate(60e3, 0.01).unwrap().torque;
        assert_eq!(t(&j, 60e3, 0.0, 0.01), 0.0);
        assert_eq!(t(&j, 60e3, 0.005, 0.01), -edge * 0.5);
        assert_eq!(t(&j, 60e3, -0.0025, 0.01), edge * 0.25);
        let below = t(&j, 60e3, 0.01 * (1.0 - 1e-12), 0.01);
        let at = t(&j, 60e3, 0.01, 0.01);
        assert!((below - at).abs() <= 1e-9 * at.abs(), "{below} vs {at}");
        // The band edge torque is close to the boundary torque mu_c R P = 201.6 N m.
        assert!((edge - 201.6).abs() < 0.5, "{edge}");
    }

    #[test]
    fn zero_band_is_the_pure_sign() {
        let j = Joint::new(&Params::default()).unwrap();
        assert_eq!(t(&j, 20e3, 0.0, 0.0), 0.0);
        let tiny = t(&j, 20e3, 1e-300, 0.0);
        assert_eq!(tiny, j.evaluate(20e3, 1e-300).unwrap().signed_torque());
        assert!((tiny + 67.2).abs() < 1e-9, "{tiny}");
    }

    #[test]
    fn band_check_names_the_parameter() {
        assert!(check_band(0.0).is_ok());
        let e = check_band(-1.0).unwrap_err().to_string();
        assert!(e.contains("zero_velocity.speed_band = -1 rad/s"), "{e}");
        assert!(check_band(f64::NAN).is_err());
    }
}
