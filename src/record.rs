//! The one result record of an operating point: the columns every front end writes for a
//! [`OperatingPoint`] (the CSV of `pinjoint sweep`, `stribeck` and `map`, the Python
//! package's `Joint.evaluate` dict), in one order, with their SI units. A column added here
//! appears in all of them.
//!
//! The order is the sweep's: the nine quantities of the paper's model, `regime`, then the
//! extensions (h_min, eq. 21 as printed; the complete model's clearance torque, journal weight,
//! eccentricity ratio and grease yield torque) and `validity` last, so the earlier columns keep their positions.
//!
//! [`POINT`] is every quantity of an operating point (the CSV columns with the inputs and the
//! parts of μ), in the order of `pinjoint point --json`; [`LUBRICANT`] the lubricant state a
//! joint evaluates with; [`Record`] serialises both as one object. Names, units and
//! descriptions are written here once.

use crate::joint::{OperatingPoint, Regime};
use crate::params::Lubricant;
use serde::ser::{Serialize, SerializeMap, Serializer};

/// How a column's value is read from an [`OperatingPoint`].
#[derive(Debug, Clone, Copy)]
pub enum Value {
    /// A number in the column's SI unit.
    Number(fn(&OperatingPoint) -> f64),
    /// The regime's name ([`Regime::as_str`]).
    Regime,
    /// The validity's name ([`crate::validity::Validity::as_str`]).
    Validity,
}

/// One result column.
#[derive(Debug, Clone, Copy)]
pub struct Column {
    /// The column's name (CSV header, Python dict key).
    pub name: &'static str,
    /// Its SI unit (`1` for a dimensionless number, `-` for the regime's name).
    pub unit: &'static str,
    /// What it holds, with the paper's equation.
    pub description: &'static str,
    /// How to read it.
    pub value: Value,
}

/// Every result column, in the sweep's order.
pub const COLUMNS: [Column; 17] = [
    Column { name: "friction_coefficient", unit: "1", description: "friction coefficient μ (eq. 10)", value: Value::Number(|o| o.friction_coefficient) },
    Column { name: "torque", unit: "N.m", description: "torque magnitude μ·R·P_T (eq. 11)", value: Value::Number(|o| o.torque) },
    Column { name: "film_thickness", unit: "m", description: "central film thickness h_c (eqs. 13, 19)", value: Value::Number(|o| o.film_thickness) },
    Column { name: "lambda_ratio", unit: "1", description: "λ from the central film (eq. 21 with h_c)", value: Value::Number(|o| o.lambda_ratio) },
    Column { name: "fluid_load_fraction", unit: "1", description: "load share of the film 1/γ1 (eq. 9)", value: Value::Number(|o| o.fluid_load_fraction) },
    Column { name: "asperity_load_fraction", unit: "1", description: "load share of the asperities 1/γ2 (eq. 9)", value: Value::Number(|o| o.asperity_load_fraction) },
    Column { name: "mean_pressure", unit: "Pa", description: "Hertz mean pressure p_m (eq. 6)", value: Value::Number(|o| o.mean_pressure) },
    Column { name: "contact_half_width", unit: "m", description: "Hertz half-width a (eq. 6)", value: Value::Number(|o| o.contact_half_width) },
    Column { name: "sommerfeld_number", unit: "1", description: "Sommerfeld number S (eq. 20)", value: Value::Number(|o| o.sommerfeld_number) },
    Column { name: "regime", unit: "-", description: "boundary, mixed or full-film (1 % load-share thresholds)", value: Value::Regime },
    Column { name: "min_film_thickness", unit: "m", description: "minimum film h_min (Pan–Hamrock ratio; extension)", value: Value::Number(|o| o.min_film_thickness) },
    Column { name: "min_lambda_ratio", unit: "1", description: "λ from h_min (eq. 21 as printed; extension)", value: Value::Number(|o| o.min_lambda_ratio) },
    Column { name: "clearance_torque", unit: "N.m", description: "torque of the lubricant in the clearance outside the contact arc, yield part included (complete model; 0 for model.paper)", value: Value::Number(|o| o.clearance_torque) },
    Column { name: "journal_weight", unit: "1", description: "weight w of the journal bearing in the composite film (0 line contact, 1 full-film journal; complete model)", value: Value::Number(|o| o.journal_weight) },
    Column { name: "eccentricity_ratio", unit: "1", description: "eccentricity ratio of the clearance 1 - h_c/c (clamped to [0, 1))", value: Value::Number(|o| o.eccentricity_ratio) },
    Column { name: "grease_yield_torque", unit: "N.m", description: "the grease's yield torque, part of the clearance torque and of the torque at rest (complete model)", value: Value::Number(|o| o.grease_yield_torque) },
    Column { name: "validity", unit: "-", description: "checked, extrapolation, known-wrong or outside: inside the paper's rig conditions, outside them, or past the model's assumptions (crate::validity)", value: Value::Validity },
];

/// The inputs of an operating point: the load magnitude and the angular velocity as given.
pub const INPUTS: [Column; 2] = [
    Column { name: "load", unit: "N", description: "normal load P_T (its magnitude)", value: Value::Number(|o| o.load) },
    Column { name: "speed", unit: "rad/s", description: "angular velocity ω as given (the model uses |ω|)", value: Value::Number(|o| o.angular_velocity) },
];

/// The quantities of an operating point that are not CSV columns: the sliding speed, the
/// Hertz peak pressure, the viscosity at p_m and the two parts of μ.
pub const DETAILS: [Column; 5] = [
    Column { name: "sliding_speed", unit: "m/s", description: "sliding speed u = |ω|·R", value: Value::Number(|o| o.sliding_speed) },
    Column { name: "peak_pressure", unit: "Pa", description: "Hertz peak pressure p0 (eq. 6)", value: Value::Number(|o| o.peak_pressure) },
    Column { name: "contact_viscosity", unit: "Pa.s", description: "Roelands viscosity at p_m (eq. 5; +inf where it overflows)", value: Value::Number(|o| o.contact_viscosity) },
    Column { name: "fluid_friction_coefficient", unit: "1", description: "fluid (Bair–Winer) part of μ, Q_H/P_T (eq. 3)", value: Value::Number(|o| o.fluid_friction_coefficient) },
    Column { name: "asperity_friction_coefficient", unit: "1", description: "asperity part of μ, μ_c/γ2 (eq. 8)", value: Value::Number(|o| o.asperity_friction_coefficient) },
];

/// Every quantity of an operating point but the solver's `logit`, in the order of `pinjoint
/// point --json`: [`INPUTS`], [`COLUMNS`] up to `regime`, [`DETAILS`], then the h_min
/// columns, the complete model's clearance columns and `validity`.
pub const POINT: [Column; 24] = {
    let mut all = [COLUMNS[0]; 24];
    let mut k = 0;
    while k < 24 {
        all[k] = match k {
            0..2 => INPUTS[k],
            2..12 => COLUMNS[k - 2],
            12..17 => DETAILS[k - 12],
            _ => COLUMNS[k - 7],
        };
        k += 1;
    }
    all
};

/// The column of [`POINT`] named `name`, if the record has one (how `point` and the FMU
/// outputs find their quantities in the record).
pub fn column(name: &str) -> Option<&'static Column> {
    POINT.iter().find(|c| c.name == name)
}

/// A quantity of the lubricant state a joint evaluates with ([`crate::Joint::lubricant`]).
#[derive(Debug, Clone, Copy)]
pub struct LubricantColumn {
    /// Its name (JSON key).
    pub name: &'static str,
    /// Its SI unit.
    pub unit: &'static str,
    /// What it holds.
    pub description: &'static str,
    /// How to read it.
    pub value: fn(&Lubricant) -> f64,
}

/// The lubricant's temperature and the viscosity parameters at it, after the [`POINT`] quantities.
pub const LUBRICANT: [LubricantColumn; 3] = [
    LubricantColumn { name: "temperature", unit: "K", description: "lubricant temperature T", value: |l| l.temperature },
    LubricantColumn { name: "inlet_viscosity", unit: "Pa.s", description: "inlet (ambient-pressure) viscosity η0 at T", value: |l| l.viscosity },
    LubricantColumn { name: "pressure_viscosity_coefficient", unit: "1/Pa", description: "pressure-viscosity coefficient α at T", value: |l| l.pressure_viscosity_coefficient },
];

/// One operating point with the lubricant state it was evaluated with: serialises as one
/// object, [`POINT`] then [`LUBRICANT`] in order (numbers in SI units, `regime` as its name).
#[derive(Debug, Clone, Copy)]
pub struct Record<'a> {
    /// The operating point.
    pub point: &'a OperatingPoint,
    /// The lubricant at the joint's temperature ([`crate::Joint::lubricant`]).
    pub lubricant: &'a Lubricant,
}

impl Serialize for Record<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(POINT.len() + LUBRICANT.len()))?;
        for c in &POINT {
            match c.value {
                Value::Number(f) => map.serialize_entry(c.name, &f(self.point))?,
                Value::Regime => map.serialize_entry(c.name, self.point.regime.as_str())?,
                Value::Validity => map.serialize_entry(c.name, self.point.validity.as_str())?,
            }
        }
        for c in &LUBRICANT {
            map.serialize_entry(c.name, &(c.value)(self.lubricant))?;
        }
        map.end()
    }
}

/// The names of [`COLUMNS`], in order.
pub const NAMES: [&str; COLUMNS.len()] = {
    let mut names = [""; COLUMNS.len()];
    let mut i = 0;
    while i < COLUMNS.len() {
        names[i] = COLUMNS[i].name;
        i += 1;
    }
    names
};

/// Every regime, in the order of their codes 0, 1, 2 (see [`regime_code`]).
pub const REGIMES: [Regime; 3] = [Regime::Boundary, Regime::Mixed, Regime::FullFilm];

/// The code of a regime: its position in [`REGIMES`].
pub fn regime_code(r: Regime) -> u8 {
    match r {
        Regime::Boundary => 0,
        Regime::Mixed => 1,
        Regime::FullFilm => 2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Joint, Params};

    /// The operating point as a table of its fields, by serde's names (independent of the
    /// accessors in the record).
    fn fields(op: &OperatingPoint) -> toml::Table {
        toml::Table::try_from(op).unwrap()
    }

    #[test]
    fn every_column_reads_its_own_field() {
        let j = Joint::new(&Params::default()).unwrap();
        for (load, omega) in [(20e3, 3.0), (60e3, -0.01), (5e3, 0.0)] {
            let op = j.evaluate(load, omega).unwrap();
            let t = fields(&op);
            for c in &POINT {
                let field = if c.name == "speed" { "angular_velocity" } else { c.name };
                match c.value {
                    Value::Number(f) => assert_eq!(t[field].as_float().unwrap().to_bits(), f(&op).to_bits(), "{}", c.name),
                    Value::Regime => assert_eq!(t[field].as_str().unwrap(), op.regime.as_str()),
                    Value::Validity => assert_eq!(t[field].as_str().unwrap(), op.validity.as_str()),
                }
            }
            // Every field but the solver's warm start is in the record, once.
            let mut names: Vec<&str> = POINT.iter().map(|c| if c.name == "speed" { "angular_velocity" } else { c.name }).collect();
            names.push("logit");
            names.sort_unstable();
            let mut keys: Vec<&str> = t.keys().map(String::as_str).collect();
            keys.sort_unstable();
            assert_eq!(names, keys);
        }
        assert_eq!(NAMES[9], "regime");
        assert_eq!(column("lambda_ratio").map(|c| c.unit), Some("1"));
        assert!(column("power_loss").is_none());
        for (k, r) in REGIMES.iter().enumerate() {
            assert_eq!(usize::from(regime_code(*r)), k);
        }
    }

    #[test]
    fn the_point_holds_the_columns_in_their_order() {
        let names: Vec<&str> = POINT.iter().map(|c| c.name).collect();
        let columns: Vec<&str> = names.iter().copied().filter(|n| NAMES.contains(n)).collect();
        assert_eq!(columns, NAMES);
        assert_eq!(names[..2], ["load", "speed"]);
        assert_eq!(names[12..17], DETAILS.map(|c| c.name));
        assert_eq!(column("peak_pressure").unwrap().unit, "Pa");
        assert!(column("logit").is_none());
    }

    #[test]
    fn the_record_serialises_in_order_with_the_lubricant() {
        let j = Joint::new(&Params::default()).unwrap();
        let op = j.evaluate(20e3, 0.2).unwrap();
        let t = toml::Table::try_from(Record { point: &op, lubricant: j.lubricant() }).unwrap();
        let mut keys: Vec<&str> = t.keys().map(String::as_str).collect();
        keys.sort_unstable();
        let mut expect: Vec<&str> = POINT.iter().map(|c| c.name).chain(LUBRICANT.iter().map(|c| c.name)).collect();
        expect.sort_unstable();
        assert_eq!(keys, expect);
        assert_eq!(t["temperature"].as_float(), Some(j.lubricant().temperature));
        assert_eq!(t["inlet_viscosity"].as_float(), Some(j.lubricant().viscosity));
        assert_eq!(t["pressure_viscosity_coefficient"].as_float(), Some(j.lubricant().pressure_viscosity_coefficient));
        assert_eq!(t["regime"].as_str(), Some(op.regime.as_str()));
    }
}
