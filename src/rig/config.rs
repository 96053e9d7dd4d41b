//! One parameter file for the integrated mode: the model's sections plus `[rig]`.
//!
//! `Params` keeps its own parsing (it denies unknown sections), so the `[rig]` table is taken
//! out of the file first and the rest is handed to [`Params::from_toml_str`] unchanged.

use super::params::RigParams;
use crate::params::{ParamError, Params};
use serde::{Deserialize, Serialize};

/// The model's parameters and the rig's.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RigConfig {
    /// The joint's model parameters (the sections of the parameter file).
    pub model: Params,
    /// The rig's parameters (the `[rig]` section).
    pub rig: RigParams,
}

impl RigConfig {
    /// Validate both parts.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.model.validate()?;
        self.rig.validate()
    }

    /// Parse a (partial) parameter file with an optional `[rig]` section; missing keys keep
    /// their defaults; unknown keys are rejected by name.
    pub fn from_toml_str(text: &str) -> Result<Self, ParamError> {
        let mut table: toml::Table = toml::from_str(text).map_err(|e| ParamError::Parse(crate::params::parse_message(text, &e)))?;
        let rig = match table.remove("rig") {
            None => RigParams::default(),
            Some(toml::Value::Table(t)) => {
                RigParams::deserialize(t).map_err(|e| ParamError::Parse(format!("[rig]: {}", crate::fmt::excerpt(e.to_string().trim()))))?
            }
            Some(other) => return Err(ParamError::Parse(format!("`rig` must be a table ([rig]), found {}", other.type_str()))),
        };
        let rest = toml::to_string(&table).map_err(|e| ParamError::Parse(crate::fmt::excerpt(&e.to_string())))?;
        let model = Params::from_toml_str(&rest)?;
        rig.validate()?;
        Ok(Self { model, rig })
    }

    /// The whole file: the model's sections (as [`Params::to_toml_string`]) then `[rig]`.
    pub fn to_toml_string(&self) -> String {
        let mut out = self.model.to_toml_string();
        out.push_str("\n[rig]\n");
        out.push_str(&toml::to_string(&self.rig).expect("RigParams serialises"));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rig::params::{Formulation, Method};

    #[test]
    fn defaults_roundtrip_and_partial_file() {
        let c = RigConfig::default();
        c.validate().unwrap();
        assert_eq!(RigConfig::from_toml_str(&c.to_toml_string()).unwrap(), c);
        let c = RigConfig::from_toml_str(
            "[friction]\nboundary_friction_coefficient = 0.1\n[rig]\nfrequency = 0.03\nmethod = \"dop853\"\nformulation = \"regularised\"\n",
        )
        .unwrap();
        assert_eq!(c.model.friction.boundary_friction_coefficient, 0.1);
        assert_eq!(c.rig.frequency, 0.03);
        assert_eq!(c.rig.method, Method::Dop853);
        assert_eq!(c.rig.formulation, Formulation::Regularised);
        assert_eq!(c.rig.inertia, RigParams::default().inertia);
    }

    #[test]
    fn errors_name_key_value_unit() {
        let e = RigConfig::from_toml_str("[rig]\ninertia = -1.0\n").unwrap_err().to_string();
        assert!(e.contains("rig.inertia") && e.contains("-1") && e.contains("kg.m2"), "{e}");
        let e = RigConfig::from_toml_str("[rig]\nintertia = 1.0\n").unwrap_err().to_string();
        assert!(e.contains("intertia"), "{e}");
        let e = RigConfig::from_toml_str("[rig]\nvelocity_gain = 10.0\n").unwrap_err().to_string();
        assert!(e.contains("rig.velocity_gain") && e.contains("Routh"), "{e}");
        let e = RigConfig::from_toml_str("[rig]\nbreakaway_factor = 0.9\n").unwrap_err().to_string();
        assert!(e.contains("rig.breakaway_factor = 0.9"), "{e}");
        let e = RigConfig::from_toml_str("[geometryy]\npin_radius = 0.02\n").unwrap_err().to_string();
        assert!(e.contains("geometryy"), "{e}");
        let e = RigConfig::from_toml_str("rig = 3\n").unwrap_err().to_string();
        assert!(e.contains("table"), "{e}");
    }
}
