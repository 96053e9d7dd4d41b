//! Friction at zero velocity: what the joint does when it stops, holds and breaks away.
//!
//! Eq. 11 gives the sliding torque's magnitude T = μ(P, |ω|)·R·P; its direction opposes ω,
//! so as a function of ω alone it jumps from −T to +T at rest. Two treatments of the rest
//! point are offered, selected by [`ZeroVelocityModel`]:
//!
//! - [`band`]: the stateless law of earlier versions, a linear ramp of the torque inside a
//!   speed band |ω| < ω_b. Simple, but a drive below breakaway makes the joint creep at
//!   ω = T_drive·ω_b/T, and a small band chatters at large host steps.
//! - [`presliding`]: a single-state elasto-plastic law (Dupont et al. 2002): the joint holds
//!   an elastic presliding torque below breakaway (no creep, no drift below the elastic
//!   limit), breaks away at the sliding torque and slides with the model's torque exactly.
//!   [`joint::PreslidingJoint`] is the stateful object every front end (FMU, Python) steps.
//!
//! [`jet`] gives the law's exact partial derivatives (the FMU's directional derivatives);
//! [`wrap`] the angle convention (any angle continuous modulo 2π); [`modes`] the stick and
//! slip modes of the Model Exchange state (no stiffness for explicit integrators).

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod jet;
pub mod band;
pub mod presliding;
pub mod wrap;
pub mod modes;
pub mod joint;

pub use error::ZeroVelocityError;
pub use joint::PreslidingJoint;
pub use presliding::{HostCoupling, Presliding};

/// Which zero-velocity treatment a front end applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ZeroVelocityModel {
    /// The speed band: a linear torque ramp inside |ω| < ω_b ([`band`]).
    Band,
    /// The presliding state ([`presliding`]); the default.
    #[default]
    Presliding,
}

impl ZeroVelocityModel {
    /// Its code in the FMU's enumeration and the Python API: 0 band, 1 presliding.
    pub fn code(self) -> i64 {
        match self {
            ZeroVelocityModel::Band => 0,
            ZeroVelocityModel::Presliding => 1,
        }
    }

    /// The model of `code`, if it is one.
    pub fn from_code(code: i64) -> Option<Self> {
        match code {
            0 => Some(ZeroVelocityModel::Band),
            1 => Some(ZeroVelocityModel::Presliding),
            _ => None,
        }
    }

    /// Its name: `band` or `presliding`.
    pub fn as_str(self) -> &'static str {
        match self {
            ZeroVelocityModel::Band => "band",
            ZeroVelocityModel::Presliding => "presliding",
        }
    }

    /// The model named `name` (`band` or `presliding`).
    pub fn parse(name: &str) -> Result<Self, ZeroVelocityError> {
        match name {
            "band" => Ok(ZeroVelocityModel::Band),
            "presliding" => Ok(ZeroVelocityModel::Presliding),
            _ => Err(ZeroVelocityError::UnknownModel(name.chars().take(40).collect())),
        }
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod host_tests;
#[cfg(test)]
mod coupling_tests;
