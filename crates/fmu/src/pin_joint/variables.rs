//! The PinJoint variable table: the single source of the modelDescription.xml and
//! of the get/set dispatch. Layout (table index → value reference):
//!
//! | index | value references | variables |
//! |---|---|---|
//! | 0–2 | 1–3 | inputs `angle`, `angular_velocity`, `load` |
//! | 3–14 | 10–21 | outputs ([`Output`] order; `min_film_thickness`, `min_lambda_ratio` last) |
//! | 15–40 | 100–125 | the 26 parameters of [`pinjoint::params::PARAMS`], `section.key` |
//! | 41 | 200 | `zero_velocity.speed_band` |
//! | 42 | 300 | `fidelity` (Integer: 0 full, 1 table, 2 boundary, 3 auto) |
//! | 43–47 | 301–305 | `tolerance`, `envelope.load_min`, `envelope.load_max`, `envelope.speed_min`, `envelope.speed_max` |
//! | 48 | 4 | input `temperature` (K; last in the table, so every earlier value reference is unchanged) |

use super::zero_speed::DEFAULT_SPEED_BAND;
use fmi_layer::fmi2::variables::{Causality, DisplayUnit, EnumType, Initial, Kind, UnitDef, Variability, Variable};
use pinjoint::params::{ParamSpec, PARAMS};

/// Table index of the `angle` input (rad).
pub const ANGLE: usize = 0;
/// Table index of the `angular_velocity` input (rad/s).
pub const ANGULAR_VELOCITY: usize = 1;
/// Table index of the `load` input (N).
pub const LOAD: usize = 2;
/// Table index of the first output; the outputs follow in [`Output::ALL`] order.
pub const FIRST_OUTPUT: usize = 3;
/// Table index of the first model parameter; the 26 follow in
/// [`pinjoint::params::PARAMS`] order.
pub const FIRST_PARAM: usize = FIRST_OUTPUT + Output::ALL.len();
/// Table index of the `zero_velocity.speed_band` parameter (rad/s).
pub const SPEED_BAND: usize = FIRST_PARAM + PARAMS.len();
/// Table index of the `fidelity` parameter (Enumeration, [`FIDELITY_TYPE`]).
pub const FIDELITY: usize = SPEED_BAND + 1;
/// Table index of the `tolerance` parameter (relative, dimensionless).
pub const TOLERANCE: usize = FIDELITY + 1;
/// Table index of the `envelope.load_min` parameter (N).
pub const ENVELOPE_LOAD_MIN: usize = TOLERANCE + 1;
/// Table index of the `envelope.load_max` parameter (N).
pub const ENVELOPE_LOAD_MAX: usize = TOLERANCE + 2;
/// Table index of the `envelope.speed_min` parameter (rad/s).
pub const ENVELOPE_SPEED_MIN: usize = TOLERANCE + 3;
/// Table index of the `envelope.speed_max` parameter (rad/s).
pub const ENVELOPE_SPEED_MAX: usize = TOLERANCE + 4;
/// The `temperature` input (K): the lubricant temperature (overrides `lubricant.temperature`).
pub const TEMPERATURE: usize = ENVELOPE_SPEED_MAX + 1;
/// Number of variables in the table.
pub const COUNT: usize = TEMPERATURE + 1;

/// Start values of the fidelity parameters: full solve; tolerance 1e-4; the paper's rig
/// envelope 5–60 kN, 0.01–10 rad/s.
pub const DEFAULT_FIDELITY: i32 = 0;
/// Start value of `tolerance` (relative, dimensionless).
pub const DEFAULT_TOLERANCE: f64 = 1e-4;
/// Start values of `envelope.load_min`, `load_max` (N), `speed_min`, `speed_max` (rad/s).
pub const DEFAULT_ENVELOPE: [f64; 4] = [5e3, 60e3, 0.01, 10.0];

/// The fidelity level of an Integer code of the `fidelity` parameter.
pub fn fidelity_of_code(code: i32) -> Option<pinjoint::fidelity::Fidelity> {
    use pinjoint::fidelity::Fidelity::*;
    [Full, Table, Boundary, Auto].get(usize::try_from(code).ok()?).copied()
}

/// The `fidelity` parameter's choices (both FMUs); the codes are those of the former
/// Integer parameter, so hosts that set 0..3 through fmi2SetInteger see no change.
pub static FIDELITY_TYPE: EnumType = EnumType {
    name: "Fidelity",
    description: "Fidelity level of the friction evaluation",
    items: &[
        ("full", 0, "Complete load-sharing solve at every evaluation"),
        ("table", 1, "Stribeck map tabulated over the envelope, interpolated within tolerance of full"),
        ("boundary", 2, "Boundary friction mu = mu_c"),
        ("auto", 3, "The cheapest level within tolerance over the envelope"),
    ],
};

/// Start value of the `load` input (N): the paper's reference load of 20 kN.
pub const DEFAULT_LOAD: f64 = 20e3;

/// The outputs, in table order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// `torque` (N·m): friction torque on the pin, -sign(ω) μ R P_T (eq. 11).
    Torque,
    /// `friction_coefficient` (dimensionless): μ = (Q_H + Q_C)/P_T (eq. 10).
    FrictionCoefficient,
    /// `film_thickness` (m): central film thickness h_c (eqs. 9, 13, 19).
    FilmThickness,
    /// `lambda_ratio` (dimensionless): h_c/√(σ² + σ_b²) (eq. 21).
    LambdaRatio,
    /// `fluid_load_fraction` (dimensionless, 0–1): share of the load on the film, 1/γ₁ (eq. 9).
    FluidLoadFraction,
    /// `asperity_load_fraction` (dimensionless, 0–1): share on the asperities, 1/γ₂ (eq. 9).
    AsperityLoadFraction,
    /// `mean_pressure` (Pa): Hertz mean contact pressure p_m = P_T/(2aB) (eq. 6).
    MeanPressure,
    /// `sommerfeld_number` (dimensionless): S of eq. 20.
    SommerfeldNumber,
    /// `power_loss` (W): frictional power |torque · angular_velocity|.
    PowerLoss,
    /// `dissipated_energy` (J): power_loss summed over the Co-Simulation steps.
    DissipatedEnergy,
    /// `min_film_thickness` (m): minimum film thickness h_min (extension beyond the paper).
    MinFilmThickness,
    /// `min_lambda_ratio` (dimensionless): h_min/√(σ² + σ_b²) (eq. 21 with h_min).
    MinLambdaRatio,
}

impl Output {
    /// Every output, in table order (value references 10, 11, …).
    pub const ALL: [Output; 12] = [
        Output::Torque,
        Output::FrictionCoefficient,
        Output::FilmThickness,
        Output::LambdaRatio,
        Output::FluidLoadFraction,
        Output::AsperityLoadFraction,
        Output::MeanPressure,
        Output::SommerfeldNumber,
        Output::PowerLoss,
        Output::DissipatedEnergy,
        Output::MinFilmThickness,
        Output::MinLambdaRatio,
    ];
}

const DEG: f64 = 57.29577951308232; // 180/π
const RPM: f64 = 9.549296585513721; // 60/(2π)

/// Every unit used by a PinJoint variable, with its SI base units and display units.
pub static UNITS: &[UnitDef] = &[
    UnitDef { name: "rad", quantity: "Angle", kg: 0, m: 0, s: 0, rad: 1, k: 0, display: &[DisplayUnit { name: "deg", factor: DEG, offset: 0.0 }] },
    UnitDef {
        name: "rad/s", quantity: "AngularVelocity",
        kg: 0,
        m: 0,
        s: -1,
        rad: 1,
        k: 0, display: &[DisplayUnit { name: "deg/s", factor: DEG, offset: 0.0 }, DisplayUnit { name: "rpm", factor: RPM, offset: 0.0 }],
    },
    UnitDef { name: "N", quantity: "Force", kg: 1, m: 1, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kN", factor: 1e-3, offset: 0.0 }] },
    UnitDef { name: "N.m", quantity: "Torque", kg: 1, m: 2, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kN.m", factor: 1e-3, offset: 0.0 }] },
    UnitDef {
        name: "m", quantity: "Length",
        kg: 0,
        m: 1,
        s: 0,
        rad: 0,
        k: 0, display: &[DisplayUnit { name: "mm", factor: 1e3, offset: 0.0 }, DisplayUnit { name: "um", factor: 1e6, offset: 0.0 }],
    },
    UnitDef {
        name: "Pa", quantity: "Pressure",
        kg: 1,
        m: -1,
        s: -2,
        rad: 0,
        k: 0, display: &[DisplayUnit { name: "MPa", factor: 1e-6, offset: 0.0 }, DisplayUnit { name: "GPa", factor: 1e-9, offset: 0.0 }],
    },
    UnitDef { name: "Pa.s", quantity: "DynamicViscosity", kg: 1, m: -1, s: -1, rad: 0, k: 0, display: &[DisplayUnit { name: "mPa.s", factor: 1e3, offset: 0.0 }] },
    UnitDef { name: "1/Pa", quantity: "PressureViscosityCoefficient", kg: -1, m: 1, s: 2, rad: 0, k: 0, display: &[DisplayUnit { name: "1/GPa", factor: 1e9, offset: 0.0 }] },
    UnitDef { name: "1/m2", quantity: "AsperityDensity", kg: 0, m: -2, s: 0, rad: 0, k: 0, display: &[] },
    UnitDef { name: "W", quantity: "Power", kg: 1, m: 2, s: -3, rad: 0, k: 0, display: &[] },
    UnitDef { name: "J", quantity: "Energy", kg: 1, m: 2, s: -2, rad: 0, k: 0, display: &[DisplayUnit { name: "kJ", factor: 1e-3, offset: 0.0 }] },
    UnitDef { name: "K", quantity: "ThermodynamicTemperature", kg: 0, m: 0, s: 0, rad: 0, k: 1, display: &[DisplayUnit { name: "degC", factor: 1.0, offset: -273.15 }] },
    UnitDef { name: "1/m", quantity: "InverseLength", kg: 0, m: -1, s: 0, rad: 0, k: 0, display: &[] },
];

fn input(name: &str, vr: u32, unit: &'static str, display: Option<&'static str>, start: f64, min: Option<f64>, d: &str) -> Variable {
    Variable {
        name: name.into(),
        kind: Kind::Real,
        value_reference: vr,
        causality: Causality::Input,
        variability: Variability::Continuous,
        initial: Initial::Exact,
        unit: Some(unit),
        display_unit: display,
        start: Some(start),
        min,
        max: None,
        description: d.into(),
        depends_on: vec![],
    }
}

/// (name, unit, display unit, min, max, inputs it depends on, description) of an output.
type OutputRow = (&'static str, Option<&'static str>, Option<&'static str>, Option<f64>, Option<f64>, &'static [&'static str], &'static str);

fn output(o: Output) -> Variable {
    const SPEED_LOAD: [&str; 3] = ["angular_velocity", "load", "temperature"];
    let (name, unit, display, min, max, deps, d): OutputRow = match o {
        Output::Torque => ("torque", Some("N.m"), None, None, None, &SPEED_LOAD,
            "Friction torque on the pin, opposite to the angular velocity: -sign(omega) mu R P_T (eq. 11); linear in omega inside the zero-velocity band"),
        Output::FrictionCoefficient => ("friction_coefficient", None, None, Some(0.0), None, &SPEED_LOAD,
            "Friction coefficient mu = (Q_H + Q_C)/P_T (eq. 10) at the input speed and load"),
        Output::FilmThickness => ("film_thickness", Some("m"), Some("um"), Some(0.0), None, &SPEED_LOAD,
            "Central film thickness h_c from the load-sharing solve (eqs. 9, 13, 19)"),
        Output::LambdaRatio => ("lambda_ratio", None, None, Some(0.0), None, &SPEED_LOAD,
            "Lambda ratio h_c/sqrt(sigma^2 + sigma_b^2) (eq. 21, evaluated with the central film h_c)"),
        Output::FluidLoadFraction => ("fluid_load_fraction", None, None, Some(0.0), Some(1.0), &SPEED_LOAD,
            "Share of the load carried by the fluid film, 1/gamma_1 (eq. 9)"),
        Output::AsperityLoadFraction => ("asperity_load_fraction", None, None, Some(0.0), Some(1.0), &SPEED_LOAD,
            "Share of the load carried by the asperities, 1/gamma_2 (eq. 9)"),
        Output::MeanPressure => ("mean_pressure", Some("Pa"), Some("MPa"), Some(0.0), None, &["load"],
            "Hertz mean contact pressure p_m = P_T/(2aB) (eq. 6)"),
        Output::SommerfeldNumber => ("sommerfeld_number", None, None, Some(0.0), None, &SPEED_LOAD,
            "Sommerfeld number S = eta_0 |omega| /(2 pi P_L) (R/c)^2 with P_L = P_T/(2RB) (eq. 20)"),
        Output::PowerLoss => ("power_loss", Some("W"), None, Some(0.0), None, &SPEED_LOAD,
            "Frictional power loss |torque * angular_velocity|"),
        Output::DissipatedEnergy => ("dissipated_energy", Some("J"), Some("kJ"), Some(0.0), None, &[],
            "Energy dissipated by friction since initialization: sum over the Co-Simulation steps taken of power_loss * step size (inputs held over each step). Co-Simulation only: under Model Exchange no steps are taken and it stays 0 (integrate power_loss in the host)"),
        Output::MinFilmThickness => ("min_film_thickness", Some("m"), Some("um"), Some(0.0), None, &SPEED_LOAD,
            "Minimum film thickness h_min: h_c times Pan and Hamrock's (1989) line-contact ratio h_min/h_c under eq. 13's substitution (extension; an extrapolation for this joint, 0 at rest)"),
        Output::MinLambdaRatio => ("min_lambda_ratio", None, None, Some(0.0), None, &SPEED_LOAD,
            "Lambda ratio from the minimum film, h_min/sqrt(sigma^2 + sigma_b^2) (eq. 21 as printed, with h_min)"),
    };
    Variable {
        name: name.into(),
        kind: Kind::Real,
        value_reference: 10 + o as u32,
        causality: Causality::Output,
        variability: Variability::Continuous,
        initial: Initial::Calculated,
        unit,
        display_unit: display,
        start: None,
        min,
        max,
        description: d.into(),
        depends_on: deps.to_vec(),
    }
}

/// Display unit a user expects for a parameter.
pub(crate) fn param_display(s: &ParamSpec) -> Option<&'static str> {
    match (s.section, s.unit) {
        ("geometry", "m") => Some("mm"),
        (_, "m") => Some("um"),
        (_, "Pa") if s.key.contains("modulus") => Some("GPa"),
        (_, "Pa") => Some("MPa"),
        (_, "Pa.s") => Some("mPa.s"),
        (_, "1/Pa") => Some("1/GPa"),
        (_, "K") => Some("degC"),
        _ => None,
    }
}

/// The min/max attributes of a parameter: only inclusive bounds are written (a bound the
/// value may not take, as the 0 of "> 0", is left off; the description states the range).
pub(crate) fn declared_bounds(range: pinjoint::params::Range) -> (Option<f64>, Option<f64>) {
    use pinjoint::params::Range;
    match range {
        Range::Positive => (None, None),
        Range::NonNegative => (Some(0.0), None),
        Range::HalfOpen(lo, _) => (Some(lo), None),
        Range::OpenClosed(_, hi) => (None, Some(hi)),
    }
}

pub(crate) fn parameter(i: usize, s: &ParamSpec) -> Variable {
    let (min, max) = declared_bounds(s.range);
    Variable {
        name: s.name(),
        kind: Kind::Real,
        value_reference: 100 + i as u32,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        initial: Initial::Exact,
        unit: (s.unit != "1").then_some(s.unit),
        display_unit: param_display(s),
        start: Some(s.default_value()),
        min,
        max,
        description: if s.section == "lubricant" && s.key == "temperature" {
            format!(
                "{} ({}, {}; must be {}). In this FMU the input `temperature` sets the lubricant temperature; this parameter is not used",
                s.description, s.symbol, s.source, s.range.describe()
            )
        } else {
            format!("{} ({}, {}; must be {})", s.description, s.symbol, s.source, s.range.describe())
        },
        depends_on: vec![],
    }
}

/// The full PinJoint table, in index order (the layout of the module documentation); it
/// generates modelDescription.xml and drives get/set.
pub fn table() -> Vec<Variable> {
    let mut v = vec![
        input("angle", 1, "rad", Some("deg"), 0.0, None,
            "Angle of the pin relative to the bush. The friction law does not depend on position: no output uses it; it is kept in the FMU state for hosts that wire the full joint kinematics"),
        input("angular_velocity", 2, "rad/s", Some("deg/s"), 0.0, None,
            "Angular velocity omega of the pin relative to the bush (any finite value; sliding speed u = |omega| R)"),
        input("load", 3, "N", Some("kN"), DEFAULT_LOAD, None,
            "Radial load P_T on the joint: any finite value, its magnitude |P_T| is the load (a signed reaction component is accepted; the outputs at -P equal those at +P); at 0 the joint is unloaded and every output but dissipated_energy is 0"),
    ];
    v.extend(Output::ALL.iter().map(|&o| output(o)));
    v.extend(PARAMS.iter().enumerate().map(|(i, s)| parameter(i, s)));
    v.push(Variable {
        name: "zero_velocity.speed_band".into(),
        kind: Kind::Real,
        value_reference: 200,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        initial: Initial::Exact,
        unit: Some("rad/s"),
        display_unit: Some("deg/s"),
        start: Some(DEFAULT_SPEED_BAND),
        min: Some(0.0),
        max: None,
        description: "Half-width omega_b of the speed band around zero in which the torque is ramped linearly, \
                      T = -T(P, omega_b) omega/omega_b; outside it the torque is exactly the model's. 0 switches the ramp off"
            .into(),
        depends_on: vec![],
    });
    v.push(Variable {
        name: "fidelity".into(),
        kind: Kind::Enumeration(&FIDELITY_TYPE),
        value_reference: 300,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        initial: Initial::Exact,
        unit: None,
        display_unit: None,
        start: Some(f64::from(DEFAULT_FIDELITY)),
        min: Some(0.0),
        max: Some(3.0),
        description: "Fidelity of the friction evaluation: 0 = full (complete solve, cold: outputs depend on the current inputs only), 1 = table \
                      (Stribeck map tabulated over the envelope at exit of initialization, interpolated, within \
                      tolerance of full), 2 = boundary (mu = mu_c), 3 = auto (the cheapest level within tolerance). \
                      Outside the envelope table and boundary answer with the full solve (logged once)"
            .into(),
        depends_on: vec![],
    });
    let real = |name: &str, vr: u32, unit: Option<&'static str>, start: f64, d: &str| Variable {
        name: name.into(),
        kind: Kind::Real,
        value_reference: vr,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        initial: Initial::Exact,
        unit,
        display_unit: None,
        start: Some(start),
        // Each must be > 0: no min attribute (0 itself is refused; see the description).
        min: None,
        max: None,
        description: d.into(),
        depends_on: vec![],
    };
    let [l0, l1, w0, w1] = DEFAULT_ENVELOPE;
    v.push(real("tolerance", 301, None, DEFAULT_TOLERANCE,
        "Largest relative error accepted in mu, torque and film thickness (absolute in the load shares) for fidelity table, boundary and auto; must be > 0"));
    v.push(real("envelope.load_min", 302, Some("N"), l0, "Smallest load of the envelope the scene visits (> 0)"));
    v.push(real("envelope.load_max", 303, Some("N"), l1, "Largest load of the envelope (> envelope.load_min)"));
    v.push(real("envelope.speed_min", 304, Some("rad/s"), w0, "Smallest speed magnitude |omega| of the envelope (> 0; omega = 0 is handled exactly)"));
    v.push(real("envelope.speed_max", 305, Some("rad/s"), w1, "Largest speed magnitude |omega| of the envelope (> envelope.speed_min)"));
    v.push(Variable {
        min: Some(pinjoint::params::MIN_TEMPERATURE),
        max: Some(pinjoint::params::MAX_TEMPERATURE),
        ..input("temperature", 4, "K", Some("degC"), pinjoint::params::DEFAULT_TEMPERATURE, None,
            "Lubricant temperature T (K; display degC). eta_0 and alpha follow Roelands' temperature relation from their values at lubricant.reference_temperature (Table 3 at 293.15 K by default: at T = T_ref the outputs are exactly the paper model's). Must be in (138.15, 673.15] K. A change rebuilds the friction evaluator (cheap at fidelity full; a table is re-tabulated)")
    });
    debug_assert_eq!(v.len(), COUNT);
    v
}
