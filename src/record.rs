//! The one result record of an operating point: the columns every front end writes for a
//! [`OperatingPoint`] (the CSV of `pinjoint sweep`, `stribeck` and `map`, the Python
//! package's `Joint.evaluate` dict), in one order, with their SI units. A column added here
//! appears in all of them.
//!
//! The order is the sweep's: the nine quantities of the paper's model, `regime`, then the
//! extensions (h_min, eq. 21 as printed), so the earlier columns keep their positions.

use crate::joint::{OperatingPoint, Regime};

/// How a column's value is read from an [`OperatingPoint`].
#[derive(Debug, Clone, Copy)]
pub enum Value {
    /// A number in the column's SI unit.
    Number(fn(&OperatingPoint) -> f64),
    /// The regime's name ([`Regime::as_str`]).
    Regime,
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
pub const COLUMNS: [Column; 12] = [
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
];

/// The names of [`COLUMNS`], in order.
pub const NAMES: [&str; 12] = {
    let mut names = [""; 12];
    let mut i = 0;
    while i < COLUMNS.len() {
        names[i] = COLUMNS[i].name;
        i += 1;
    }
    names
};

/// The column named `name`, if the record has one (how the FMU outputs find their
/// quantities in the record).
pub fn column(name: &str) -> Option<&'static Column> {
    COLUMNS.iter().find(|c| c.name == name)
}

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

    #[test]
    fn every_numeric_column_reads_its_own_field() {
        let op = Joint::new(&Params::default()).unwrap().evaluate(20e3, 3.0).unwrap();
        let expect = [
            op.friction_coefficient,
            op.torque,
            op.film_thickness,
            op.lambda_ratio,
            op.fluid_load_fraction,
            op.asperity_load_fraction,
            op.mean_pressure,
            op.contact_half_width,
            op.sommerfeld_number,
        ];
        let numbers: Vec<f64> = COLUMNS
            .iter()
            .filter_map(|c| match c.value {
                Value::Number(f) => Some(f(&op)),
                Value::Regime => None,
            })
            .collect();
        assert_eq!(numbers[..9], expect);
        assert_eq!(numbers[9..], [op.min_film_thickness, op.min_lambda_ratio]);
        assert_eq!(NAMES[9], "regime");
        assert_eq!(column("lambda_ratio").map(|c| c.unit), Some("1"));
        assert!(column("power_loss").is_none());
        for (k, r) in REGIMES.iter().enumerate() {
            assert_eq!(usize::from(regime_code(*r)), k);
        }
    }
}
