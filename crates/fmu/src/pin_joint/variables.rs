//! The PinJoint variable table ([`TABLE`]): the single source of the modelDescription.xml,
//! the get/set dispatch, the value checks and the FMU state. Layout (table order → value
//! references; the state order in brackets):
//!
//! | value references | variables | state |
//! |---|---|---|
//! | 1–3 | inputs `angle`, `angular_velocity`, `load` | 27–29 |
//! | 10–21 | outputs (`min_film_thickness`, `min_lambda_ratio` last; the quantities of the library's record, [`pinjoint::record`], by name) | `dissipated_energy` 30 |
//! | 100–125 | the 26 parameters of [`pinjoint::params::PARAMS`], `section.key` | 0–25 |
//! | 200 | `zero_velocity.speed_band` | 26 |
//! | 300 | `fidelity` (Enumeration: 0 full, 1 table, 2 boundary, 3 auto) | 31 |
//! | 301–305 | `tolerance`, `envelope.load_min`, `envelope.load_max`, `envelope.speed_min`, `envelope.speed_max` | 32–36 |
//! | 4 | input `temperature` (K; last in the table, so every earlier value reference is unchanged) | 37 |

use super::zero_speed::DEFAULT_SPEED_BAND;
use crate::declare::declare;
use crate::fidelity::{self, FidelitySettings};
use crate::table::{Access, Row, Rule, Table};
use fmi_layer::fmi2::variables::{Causality, Kind, UnitDef, Variable};
use pinjoint::params::PARAMS;
use pinjoint::record::{self, Value};
use pinjoint::{OperatingPoint, Params};
use std::sync::LazyLock;

/// Version of the serialized state's layout (4: 26 parameters and the temperature input).
/// The state also carries its value count, so a layout with another number of values is
/// refused whatever its version.
pub const STATE_VERSION: u8 = 4;

/// Start value of the `load` input (N): the paper's reference load of 20 kN.
pub const DEFAULT_LOAD: f64 = 20e3;

/// Start values of the fidelity parameters: full solve; tolerance 1e-4; the paper's rig
/// envelope 5–60 kN, 0.01–10 rad/s.
pub const DEFAULT_FIDELITY: FidelitySettings = FidelitySettings::full([5e3, 60e3, 0.01, 10.0]);

/// The outputs of one evaluation: the library's record of the operating point (every
/// output of [`pinjoint::record::COLUMNS`] is read from it by name) and the FMU's own
/// signed, band-ramped torque and its power. All 0 at zero load.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// The library's operating point at the inputs; `None` at zero load (and before the
    /// first evaluation).
    pub point: Option<OperatingPoint>,
    /// Friction torque on the pin (N·m), -sign(ω) μ R P_T (eq. 11), ramped inside the band.
    pub torque: f64,
    /// Frictional power loss |torque · ω| (W).
    pub power_loss: f64,
}

/// Every value of a PinJoint instance a variable reads or writes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Values {
    /// The 26 model parameters (`lubricant.temperature` is replaced by the input).
    pub params: Params,
    /// `zero_velocity.speed_band` (rad/s).
    pub band: f64,
    /// The `angle` input (rad).
    pub angle: f64,
    /// The `angular_velocity` input (rad/s).
    pub omega: f64,
    /// The `load` input (N).
    pub load: f64,
    /// The `temperature` input (K): the lubricant temperature the evaluator is built with.
    pub temperature: f64,
    /// `dissipated_energy` (J), summed over the Co-Simulation steps.
    pub energy: f64,
    /// `fidelity`, `tolerance` and the envelope.
    pub fidelity: FidelitySettings,
    /// The outputs of the last evaluation.
    pub out: Outputs,
}

impl Default for Values {
    /// The start value of every variable.
    fn default() -> Self {
        Values {
            params: Params::default(),
            band: DEFAULT_SPEED_BAND,
            angle: 0.0,
            omega: 0.0,
            load: DEFAULT_LOAD,
            temperature: pinjoint::params::DEFAULT_TEMPERATURE,
            energy: 0.0,
            fidelity: DEFAULT_FIDELITY,
            out: Outputs::default(),
        }
    }
}

/// The table, in modelDescription order.
pub static TABLE: LazyLock<Table<Values>> = LazyLock::new(|| Table::new(rows()));

/// The declarations of [`TABLE`] (the registry's variable list).
pub fn table() -> Vec<Variable> {
    TABLE.variables()
}

/// The units the PinJoint variables use.
pub static UNITS: LazyLock<Vec<UnitDef>> = LazyLock::new(|| crate::units::used_by(&table()));

/// The outputs depend on these inputs (all but `mean_pressure` and `dissipated_energy`).
const SPEED_LOAD: [&str; 3] = ["angular_velocity", "load", "temperature"];

/// An input row at state position `slot`; `units`: its unit and display unit.
fn input(name: &str, vr: u32, units: (&'static str, &'static str), (start, rule): (f64, Rule), slot: usize, (get, set): Access<Values>, d: &str) -> Row<Values> {
    let (unit, display) = units;
    let mut v = declare(name, vr, Kind::Real, Causality::Input, Some(unit), Some(display), d);
    v.start = Some(start);
    Row::new(v, get, set, rule).at_slot(slot)
}

/// An output declaration: `unit`, `display`, `min`, `max`, the inputs it `depends` on.
fn output(name: &str, vr: u32, unit: Option<&'static str>, display: Option<&'static str>, range: (Option<f64>, Option<f64>), depends: &[&'static str], d: &str) -> Variable {
    let mut v = declare(name, vr, Kind::Real, Causality::Output, unit, display, d);
    (v.min, v.max) = range;
    v.depends_on = depends.to_vec();
    v
}

/// An output that is a column of the library's record: its name and unit are the record's.
fn recorded(vr: u32, name: &str, display: Option<&'static str>, range: (Option<f64>, Option<f64>), depends: &[&'static str], d: &str) -> Row<Values> {
    let column = record::column(name).unwrap_or_else(|| panic!("{name} is a column of pinjoint::record"));
    let Value::Number(read) = column.value else { panic!("{name} is a number") };
    let unit = (column.unit != "1").then_some(column.unit);
    Row::output(output(column.name, vr, unit, display, range, depends, d), move |s: &Values| s.out.point.as_ref().map_or(0.0, read))
}

const FIDELITY_TEXTS: fidelity::Texts = fidelity::Texts {
    fidelity: "Fidelity of the friction evaluation: 0 = full (complete solve, cold: outputs depend on the current inputs only), 1 = table \
               (Stribeck map tabulated over the envelope at exit of initialization, interpolated, within \
               tolerance of full), 2 = boundary (mu = mu_c), 3 = auto (the cheapest level within tolerance). \
               Outside the envelope table and boundary answer with the full solve (logged once)",
    tolerance: "Largest relative error accepted in mu, torque and film thickness (absolute in the load shares) for fidelity table, boundary and auto; must be > 0",
    speed_min: "Smallest speed magnitude |omega| of the envelope (> 0; omega = 0 is handled exactly)",
};

/// Every row, in table order (the layout of the module documentation).
fn rows() -> Vec<Row<Values>> {
    let p = PARAMS.len();
    let zero = Some(0.0);
    let share = (zero, Some(1.0));
    let mut rows = vec![
        input("angle", 1, ("rad", "deg"), (0.0, crate::inputs::FINITE), p + 1, (|s| s.angle, |s, x| s.angle = x),
            "Angle of the pin relative to the bush. The friction law does not depend on position: no output uses it; it is kept in the FMU state for hosts that wire the full joint kinematics"),
        input("angular_velocity", 2, ("rad/s", "deg/s"), (0.0, crate::inputs::FINITE), p + 2, (|s| s.omega, |s, x| s.omega = x),
            "Angular velocity omega of the pin relative to the bush (any finite value; sliding speed u = |omega| R)"),
        input("load", 3, ("N", "kN"), (DEFAULT_LOAD, crate::inputs::LOAD_RULE), p + 3, (|s| s.load, |s, x| s.load = x),
            "Radial load P_T on the joint: any finite value, its magnitude |P_T| is the load (a signed reaction component is accepted; the outputs at -P equal those at +P); at 0 the joint is unloaded and every output but dissipated_energy is 0"),
        Row::output(output("torque", 10, Some("N.m"), None, (None, None), &SPEED_LOAD,
            "Friction torque on the pin, opposite to the angular velocity: -sign(omega) mu R P_T (eq. 11); linear in omega inside the zero-velocity band"),
            |s: &Values| s.out.torque),
        recorded(11, "friction_coefficient", None, (zero, None), &SPEED_LOAD,
            "Friction coefficient mu = (Q_H + Q_C)/P_T (eq. 10) at the input speed and load"),
        recorded(12, "film_thickness", Some("um"), (zero, None), &SPEED_LOAD,
            "Central film thickness h_c from the load-sharing solve (eqs. 9, 13, 19)"),
        recorded(13, "lambda_ratio", None, (zero, None), &SPEED_LOAD,
            "Lambda ratio h_c/sqrt(sigma^2 + sigma_b^2) (eq. 21, evaluated with the central film h_c)"),
        recorded(14, "fluid_load_fraction", None, share, &SPEED_LOAD, "Share of the load carried by the fluid film, 1/gamma_1 (eq. 9)"),
        recorded(15, "asperity_load_fraction", None, share, &SPEED_LOAD, "Share of the load carried by the asperities, 1/gamma_2 (eq. 9)"),
        recorded(16, "mean_pressure", Some("MPa"), (zero, None), &["load"], "Hertz mean contact pressure p_m = P_T/(2aB) (eq. 6)"),
        recorded(17, "sommerfeld_number", None, (zero, None), &SPEED_LOAD,
            "Sommerfeld number S = eta_0 |omega| /(2 pi P_L) (R/c)^2 with P_L = P_T/(2RB) (eq. 20)"),
        Row::output(output("power_loss", 18, Some("W"), None, (zero, None), &SPEED_LOAD, "Frictional power loss |torque * angular_velocity|"),
            |s: &Values| s.out.power_loss),
        // A state of the model as well as an output: stored, and checked when a state is restored.
        Row::new(output("dissipated_energy", 19, Some("J"), Some("kJ"), (zero, None), &[],
            "Energy dissipated by friction since initialization: sum over the Co-Simulation steps taken of power_loss * step size (inputs held over each step). Co-Simulation only: under Model Exchange no steps are taken and it stays 0 (integrate power_loss in the host)"),
            |s: &Values| s.energy, |s, x| s.energy = x, Rule::NonNegative).at_slot(p + 4),
        recorded(20, "min_film_thickness", Some("um"), (zero, None), &SPEED_LOAD,
            "Minimum film thickness h_min: h_c times Pan and Hamrock's (1989) line-contact ratio h_min/h_c under eq. 13's substitution (extension; an extrapolation for this joint, 0 at rest)"),
        recorded(21, "min_lambda_ratio", None, (zero, None), &SPEED_LOAD,
            "Lambda ratio from the minimum film, h_min/sqrt(sigma^2 + sigma_b^2) (eq. 21 as printed, with h_min)"),
    ];
    rows.extend(crate::parameters::rows(100, Some(0), |s: &Values| &s.params, |s| &mut s.params));
    let mut band = declare("zero_velocity.speed_band", 200, Kind::Real, Causality::Parameter, Some("rad/s"), Some("deg/s"),
        "Half-width omega_b of the speed band around zero in which the torque is ramped linearly, \
         T = -T(P, omega_b) omega/omega_b; outside it the torque is exactly the model's. 0 switches the ramp off");
    band.start = Some(DEFAULT_SPEED_BAND);
    band.min = zero;
    // Checked at exit of initialization ([`super::zero_speed::check_band`]).
    rows.push(Row::new(band, |s: &Values| s.band, |s, x| s.band = x, Rule::Any).at_slot(p));
    rows.extend(fidelity::rows(300, Some(p + 5), DEFAULT_FIDELITY, FIDELITY_TEXTS, |s: &Values| &s.fidelity, |s| &mut s.fidelity));
    rows.push(crate::inputs::temperature(4,
        "Lubricant temperature T (K; display degC). eta_0 and alpha follow Roelands' temperature relation from their values at lubricant.reference_temperature (Table 3 at 293.15 K by default: at T = T_ref the outputs are exactly the paper model's). Must be in [238.15, 673.15] K (-35 to 400 C; below, the film at 20 kN passes the diametral clearance at rig speeds: see lubricant.temperature). A change rebuilds the friction evaluator (cheap at fidelity full; a table is re-tabulated)",
        |s: &Values| s.temperature, |s, x| s.temperature = x).at_slot(p + 11));
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The state order of version 4 (the bytes hosts have stored): parameters, band,
    /// angle, speed, load, energy, fidelity code, tolerance, envelope, temperature.
    #[test]
    fn the_state_order_is_that_of_version_4() {
        let names: Vec<&str> = TABLE.stored().iter().map(|&i| TABLE.rows()[i].var.name.as_str()).collect();
        let p = PARAMS.len();
        assert_eq!(names[..p], PARAMS.iter().map(pinjoint::params::ParamSpec::name).collect::<Vec<_>>()[..]);
        assert_eq!(
            names[p..],
            [
                "zero_velocity.speed_band", "angle", "angular_velocity", "load", "dissipated_energy", "fidelity", "tolerance",
                "envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max", "temperature"
            ]
        );
    }

    /// Every stored row round-trips through get/set and the state; the state holds every
    /// input and parameter and the energy (a new row needs nothing else).
    #[test]
    fn every_row_round_trips_get_set_and_the_state() {
        crate::table::assert_round_trip(&TABLE, "PinJoint", STATE_VERSION, |v| v.causality != Causality::Output || v.name == "dissipated_energy");
    }

    #[test]
    fn checks_name_the_variable_value_and_unit() {
        let at = |n: &str| TABLE.index(n).unwrap();
        let msg = |n: &str, x: f64| TABLE.check(at(n), x).unwrap_err().to_string();
        assert_eq!(msg("angle", f64::NAN), "input angle = NaN rad is not a finite number");
        assert_eq!(msg("load", f64::INFINITY), "input load = inf N is invalid: it must be a finite number (a negative value is taken as its magnitude)");
        assert_eq!(msg("temperature", 1e308), "input temperature = 1e308 K is out of range: it must be in [238.15, 673.15] K");
        assert_eq!(msg("fidelity", 0.5), "parameter fidelity = 0.5 is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)");
        assert!(TABLE.check(at("load"), -1e308).is_ok());
    }
}
