//! The PinJointRig variable table: the single source of the modelDescription.xml
//! and of the get/set dispatch. Layout (value references):
//!
//! | value references | variables |
//! |---|---|
//! | 1–2 | inputs `load`, `command_angle` |
//! | 10–22 | outputs ([`Output`] order; `stuck` is a Boolean) |
//! | 100–102 | stroke parameters `frequency`, `amplitude`, Boolean `use_command_input` |
//! | 200 + i | `rig.<key>` for row i of [`RIG_PARAMS`] (all but `amplitude`, `frequency`, `load`) |
//! | 230, 231 | Integer `rig.formulation`, `rig.method` |
//! | 300 + i | `section.key` for row i of [`pinjoint::params::PARAMS`] |
//! | 400 | Integer `fidelity` (0 full, 1 table, 2 boundary, 3 auto), as PinJoint's |
//! | 401–405 | `tolerance`, `envelope.load_min`, `envelope.load_max`, `envelope.speed_min`, `envelope.speed_max` |
//! | 3 | input `temperature` (K, display degC), last in the table so earlier entries keep their places |
//!
//! The `[rig]` file keys `frequency` and `amplitude` are the stroke parameters
//! `frequency` and `amplitude`; the key `load` is the `load` input.

use fmi_layer::fmi2::variables::{Causality, DisplayUnit, EnumType, Initial, Kind, UnitDef, Variability, Variable};
use crate::pin_joint::variables::{self as pj};
use pinjoint::params::PARAMS;
use pinjoint::rig::params::{RigParamSpec, RigParams, RIG_PARAMS};
use std::sync::LazyLock;

/// Start value of the `load` input (N): the `[rig]` default, the paper's 20 kN.
pub fn default_load() -> f64 {
    RigParams::default().load
}

/// `[rig]` keys that are not `rig.<key>` parameters (the stroke parameters and the load input).
pub const NOT_RIG_PARAMETERS: [&str; 3] = ["amplitude", "frequency", "load"];

/// What a table entry stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    /// The `load` input (N): the radial load on the pin.
    Load,
    /// The `command_angle` input (rad): the actuator's command when `use_command_input` is true.
    CommandAngle,
    /// An output.
    Out(Output),
    /// The stroke parameter `frequency` (Hz) of the sine command.
    Frequency,
    /// The stroke parameter `amplitude` (rad) of the sine command.
    Amplitude,
    /// The Boolean parameter `use_command_input`: follow `command_angle` instead of the sine stroke.
    UseCommandInput,
    /// Row of [`RIG_PARAMS`].
    Rig(usize),
    /// The Integer parameter `rig.formulation` ([`FORMULATION_TYPE`]).
    Formulation,
    /// The Integer parameter `rig.method` ([`METHOD_TYPE`]).
    Method,
    /// Row of [`PARAMS`].
    Model(usize),
    /// Integer code of the friction fidelity ([`pj::fidelity_of_code`]).
    Fidelity,
    /// The `tolerance` parameter (relative, dimensionless) of the table fidelity levels.
    Tolerance,
    /// Entry of the envelope, in [`ENVELOPE_NAMES`] order: load_min, load_max, speed_min, speed_max.
    Envelope(usize),
    /// The `temperature` input (K): the lubricant temperature.
    Temperature,
}

/// Names of the envelope parameters, in [`Var::Envelope`] order, with their units.
pub use crate::ENVELOPE_NAMES;

/// Start values of the fidelity parameters: the full solve (today's rig, bit for bit);
/// tolerance 1e-4 (PinJoint's); an envelope wide enough for the rig's strokes and loads,
/// 1-100 kN and |omega| 1e-3-10 rad/s (the default 1 Hz, 40 deg stroke peaks at 4.4 rad/s).
/// Speeds below speed_min (around every reversal) and points outside it are answered by
/// the full solve (logged once).
pub const DEFAULT_TOLERANCE: f64 = pj::DEFAULT_TOLERANCE;
/// Start values of `envelope.load_min`, `load_max` (N), `speed_min`, `speed_max` (rad/s):
/// 1–100 kN, 1e-3–10 rad/s (see [`DEFAULT_TOLERANCE`]).
pub const DEFAULT_ENVELOPE: [f64; 4] = [1e3, 100e3, 1e-3, 10.0];

/// The outputs, in table order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// `angle` (rad): the pin's angle.
    Angle,
    /// `angular_velocity` (rad/s): the pin's angular velocity.
    AngularVelocity,
    /// `torque` (N·m): the recorded torque, the actuator torque T_a the transducer reads.
    Torque,
    /// `friction_torque` (N·m): the joint's friction torque (eq. 11; static torque when stuck).
    FrictionTorque,
    /// `friction_coefficient` (dimensionless): μ (eq. 10).
    FrictionCoefficient,
    /// `film_thickness` (m): central film thickness h_c.
    FilmThickness,
    /// `fluid_load_fraction` (dimensionless, 0–1): share of the load on the film, 1/γ₁ (eq. 9).
    FluidLoadFraction,
    /// `stuck` (Boolean): true in a stick phase (hybrid formulation), or |ω| at or below
    /// `rig.regularisation_speed` (regularised formulation).
    Stuck,
    /// `commanded_angle` (rad): the command θ_cmd the position loop follows.
    CommandedAngle,
    /// `actuator_work` (J): work done by the actuator since the start.
    ActuatorWork,
    /// `friction_dissipation` (J): energy dissipated by friction since the start.
    FrictionDissipation,
    /// `kinetic_energy` (J): kinetic energy of the rotating parts, J ω²/2.
    KineticEnergy,
    /// `min_film_thickness` (m): minimum film thickness h_min (extension beyond the paper).
    MinFilmThickness,
    /// `min_lambda_ratio` (dimensionless): h_min/√(σ² + σ_b²) (eq. 21 with h_min).
    MinLambdaRatio,
}

impl Output {
    /// Every output, in table order (value references 10, 11, …).
    pub const ALL: [Output; 14] = [
        Output::Angle,
        Output::AngularVelocity,
        Output::Torque,
        Output::FrictionTorque,
        Output::FrictionCoefficient,
        Output::FilmThickness,
        Output::FluidLoadFraction,
        Output::Stuck,
        Output::CommandedAngle,
        Output::ActuatorWork,
        Output::FrictionDissipation,
        Output::KineticEnergy,
        Output::MinFilmThickness,
        Output::MinLambdaRatio,
    ];
}

/// Every table entry, in table order (the same order as [`table`]).
pub static LAYOUT: LazyLock<Vec<Var>> = LazyLock::new(|| {
    let mut v = vec![Var::Load, Var::CommandAngle];
    v.extend(Output::ALL.iter().map(|&o| Var::Out(o)));
    v.extend([Var::Frequency, Var::Amplitude, Var::UseCommandInput]);
    v.extend(rig_rows().map(Var::Rig));
    v.extend([Var::Formulation, Var::Method]);
    v.extend((0..PARAMS.len()).map(Var::Model));
    v.extend([Var::Fidelity, Var::Tolerance]);
    v.extend((0..4).map(Var::Envelope));
    v.push(Var::Temperature);
    v
});

/// Rows of [`RIG_PARAMS`] that are `rig.<key>` parameters.
pub fn rig_rows() -> impl Iterator<Item = usize> {
    (0..RIG_PARAMS.len()).filter(|&i| !NOT_RIG_PARAMETERS.contains(&RIG_PARAMS[i].key))
}

/// The row of [`RIG_PARAMS`] with `key`.
pub fn rig_spec(key: &str) -> &'static RigParamSpec {
    RIG_PARAMS.iter().find(|s| s.key == key).expect("a [rig] key")
}

const DEG: f64 = 57.29577951308232; // 180/π

/// Units of the rig's own variables, beyond those PinJoint defines.
static RIG_UNITS: &[UnitDef] = &[
    UnitDef { name: "Hz", quantity: "Frequency", kg: 0, m: 0, s: -1, rad: 0, k: 0, display: &[] },
    UnitDef { name: "s", quantity: "Time", kg: 0, m: 0, s: 1, rad: 0, k: 0, display: &[DisplayUnit { name: "ms", factor: 1e3, offset: 0.0 }] },
    UnitDef { name: "kg.m2", quantity: "MomentOfInertia", kg: 1, m: 2, s: 0, rad: 0, k: 0, display: &[] },
    UnitDef {
        name: "N.m/rad", quantity: "RotationalStiffness",
        kg: 1,
        m: 2,
        s: -2,
        rad: -1,
        k: 0, display: &[DisplayUnit { name: "N.m/deg", factor: 1.0 / DEG, offset: 0.0 }],
    },
    UnitDef { name: "N.m.s/rad", quantity: "RotationalDampingConstant", kg: 1, m: 2, s: -1, rad: -1, k: 0, display: &[] },
];

/// Every unit used by a PinJointRig variable (PinJoint's definitions where shared).
pub static UNITS: LazyLock<Vec<UnitDef>> = LazyLock::new(|| {
    let vars = table();
    pj::UNITS
        .iter()
        .chain(RIG_UNITS)
        .filter(|u| vars.iter().any(|v| v.unit == Some(u.name)))
        .copied()
        .collect()
});

fn var(name: &str, vr: u32, kind: Kind, causality: Causality, variability: Variability, description: String) -> Variable {
    Variable {
        name: name.into(),
        kind,
        value_reference: vr,
        causality,
        variability,
        initial: if causality == Causality::Output { Initial::Calculated } else { Initial::Exact },
        unit: None,
        display_unit: None,
        start: None,
        min: None,
        max: None,
        description,
        depends_on: vec![],
    }
}

fn real(name: &str, vr: u32, causality: Causality, variability: Variability, unit: Option<&'static str>, display: Option<&'static str>, d: &str) -> Variable {
    Variable { unit, display_unit: display, ..var(name, vr, Kind::Real, causality, variability, d.into()) }
}

fn output(o: Output) -> Variable {
    use Causality::Output as Out;
    use Variability::Continuous as C;
    let vr = 10 + o as u32;
    let mut v = match o {
        Output::Angle => real("angle", vr, Out, C, Some("rad"), Some("deg"), "Pin angle theta (rad), relative to the bush"),
        Output::AngularVelocity => real("angular_velocity", vr, Out, C, Some("rad/s"), Some("deg/s"), "Pin angular velocity omega"),
        Output::Torque => real("torque", vr, Out, C, Some("N.m"), None,
            "Recorded torque: what the actuator's torque transducer reads, the actuator torque T_a (= J domega/dt - T_f)"),
        Output::FrictionTorque => real("friction_torque", vr, Out, C, Some("N.m"), None,
            "Friction torque T_f on the pin: -sign(omega) mu(P,|omega|) R P while slipping, the reaction -T_a while stuck, 0 at zero load"),
        Output::FrictionCoefficient => real("friction_coefficient", vr, Out, C, None, None,
            "The core's mu(P, |omega|) (eq. 10); mu_c while stuck (the capacity, not the mobilised |T_a|/(R P)); 0 at zero load"),
        Output::FilmThickness => real("film_thickness", vr, Out, C, Some("m"), Some("um"),
            "The core's central film thickness h_c at (P, |omega|); 0 at zero load (no contact)"),
        Output::FluidLoadFraction => real("fluid_load_fraction", vr, Out, C, None, None,
            "The core's 1/gamma_1, share of the load carried by the film; 0 at zero load"),
        Output::Stuck => var("stuck", vr, Kind::Boolean, Out, Variability::Discrete,
            "True in a stick phase (hybrid formulation), or |omega| <= rig.regularisation_speed (regularised formulation)".into()),
        Output::CommandedAngle => real("commanded_angle", vr, Out, C, Some("rad"), Some("deg"),
            "The command theta_cmd the position loop follows: amplitude sin(2 pi frequency (t - t_start)), or the command_angle input when use_command_input is true"),
        Output::ActuatorWork => real("actuator_work", vr, Out, C, Some("J"), None,
            "Work done by the actuator on the rotating parts since initialization, W = integral of T_a omega dt"),
        Output::FrictionDissipation => real("friction_dissipation", vr, Out, C, Some("J"), None,
            "Energy dissipated by friction since initialization, D = integral of -T_f omega dt"),
        Output::KineticEnergy => real("kinetic_energy", vr, Out, C, Some("J"), None,
            "Kinetic energy of the rotating parts, J omega^2 / 2 (energy balance: W - D = change of kinetic energy)"),
        Output::MinFilmThickness => real("min_film_thickness", vr, Out, C, Some("m"), Some("um"),
            "Minimum film thickness h_min at (P, |omega|): h_c times Pan and Hamrock's (1989) line-contact ratio under eq. 13's substitution (extension; an extrapolation for this joint); 0 at rest and at zero load"),
        Output::MinLambdaRatio => real("min_lambda_ratio", vr, Out, C, None, None,
            "h_min/sqrt(sigma^2 + sigma_b^2) (eq. 21 as printed, with h_min); 0 at rest and at zero load"),
    };
    v.min = match o {
        Output::FrictionCoefficient
        | Output::FilmThickness
        | Output::FluidLoadFraction
        | Output::FrictionDissipation
        | Output::KineticEnergy
        | Output::MinFilmThickness
        | Output::MinLambdaRatio => Some(0.0),
        _ => None,
    };
    if o == Output::FluidLoadFraction {
        v.max = Some(1.0);
    }
    // Direct feedthrough: the friction quantities follow the load at once (and the load
    // decides stick against breakaway); the commanded angle is the command input.
    v.depends_on = match o {
        Output::FrictionTorque | Output::FrictionCoefficient | Output::FilmThickness | Output::FluidLoadFraction | Output::Stuck => {
            vec!["load", "temperature"]
        }
        Output::MinFilmThickness | Output::MinLambdaRatio => vec!["load", "temperature"],
        Output::CommandedAngle => vec!["command_angle"],
        _ => vec![],
    };
    v
}

fn rig_parameter(i: usize) -> Variable {
    let s = &RIG_PARAMS[i];
    let (min, max) = pj::declared_bounds(s.range);
    let unit = (s.unit != "1").then_some(s.unit);
    let display = match s.unit {
        "rad" => Some("deg"),
        "s" => Some("ms"),
        "N.m/rad" => Some("N.m/deg"),
        _ => None,
    };
    let mut v = real(&s.name(), 200 + i as u32, Causality::Parameter, Variability::Fixed, unit, display, "");
    v.start = Some((s.get)(&RigParams::default()));
    v.min = min;
    v.max = max;
    v.description = format!("{} (must be {}; [rig] {} in the parameter file)", s.description, s.range.describe(), s.key);
    v
}

fn stroke_parameter(key: &str, vr: u32, display: Option<&'static str>, what: &str) -> Variable {
    let s = rig_spec(key);
    let (min, max) = pj::declared_bounds(s.range);
    let mut v = real(key, vr, Causality::Parameter, Variability::Fixed, Some(s.unit), display, "");
    v.start = Some((s.get)(&RigParams::default()));
    v.min = min;
    v.max = max;
    v.description = format!("{what} (must be {}; [rig] {key} in the parameter file)", s.range.describe());
    v
}

/// `rig.formulation`: the codes of the former Integer parameter.
pub static FORMULATION_TYPE: EnumType = EnumType {
    name: "RigFormulation",
    description: "Friction at zero speed in the rig",
    items: &[
        ("hybrid", 0, "Stick/slip with located events"),
        ("regularised", 1, "tanh(omega/rig.regularisation_speed) regularisation"),
    ],
};

/// `rig.method`: the codes of the former Integer parameter.
pub static METHOD_TYPE: EnumType = EnumType {
    name: "RigMethod",
    description: "Integrator of the rig's equations of motion",
    items: &[
        ("dopri5", 0, "Dormand-Prince 5(4), adaptive (rig.rtol, rig.atol)"),
        ("dop853", 1, "Dormand-Prince 8(5,3), adaptive"),
        ("rk4", 2, "Classical Runge-Kutta, fixed step rig.rk4_step"),
    ],
};

/// An enumeration parameter with codes 0..=`max` (start 0).
fn integer(name: &str, vr: u32, max: f64, d: &str) -> Variable {
    let t: &'static EnumType = match name {
        "rig.formulation" => &FORMULATION_TYPE,
        "rig.method" => &METHOD_TYPE,
        _ => &pj::FIDELITY_TYPE,
    };
    debug_assert_eq!(t.items.len() as f64, max + 1.0);
    let mut v = var(name, vr, Kind::Enumeration(t), Causality::Parameter, Variability::Fixed, d.into());
    v.start = Some(0.0);
    v.min = Some(0.0);
    v.max = Some(max);
    v
}

/// The full table, in [`LAYOUT`] order.
pub fn table() -> Vec<Variable> {
    let mut v = vec![
        real("load", 1, Causality::Input, Variability::Continuous, Some("N"), Some("kN"),
            "Radial load P on the joint: any finite value, its magnitude |P| is the load (a signed reaction component is accepted; -P acts as +P); at 0 there is no contact and no friction. Held over each communication step"),
        real("command_angle", 2, Causality::Input, Variability::Continuous, Some("rad"), Some("deg"),
            "Command angle theta_cmd, used only when use_command_input is true; held over each communication step (its rate is then 0 in the derivative term)"),
    ];
    v[0].start = Some(default_load());
    // No min: a negative value is a signed reaction component, its magnitude the load.
    v[1].start = Some(0.0);
    v.extend(Output::ALL.iter().map(|&o| output(o)));
    v.push(stroke_parameter("frequency", 100, None, "Stroke frequency f of the internal command A sin(2 pi f (t - t_start))"));
    v.push(stroke_parameter("amplitude", 101, Some("deg"), "Stroke amplitude A of the internal command (default 40 deg, section 4.4)"));
    let mut use_input = var("use_command_input", 102, Kind::Boolean, Causality::Parameter, Variability::Fixed,
        "false: the position loop follows the internal sine A sin(2 pi f (t - t_start)); true: it follows the command_angle input".into());
    use_input.start = Some(0.0);
    v.push(use_input);
    v.extend(rig_rows().map(rig_parameter));
    v.push(integer("rig.formulation", 230, 1.0,
        "Friction at zero speed: 0 = hybrid (stick/slip with located events), 1 = regularised (tanh(omega/rig.regularisation_speed)); [rig] formulation = \"hybrid\" | \"regularised\""));
    v.push(integer("rig.method", 231, 2.0,
        "Integrator: 0 = Dopri5 (adaptive, rig.rtol/rig.atol), 1 = Dop853 (adaptive), 2 = RK4 (fixed step rig.rk4_step); [rig] method = \"dopri5\" | \"dop853\" | \"rk4\""));
    v.extend(PARAMS.iter().enumerate().map(|(i, s)| Variable { value_reference: 300 + i as u32, ..pj::parameter(i, s) }));
    v.push(integer("fidelity", 400, 3.0,
        "Fidelity of the friction evaluation inside the rig: 0 = full (the complete solve, warm-started: the rig as without this parameter, bit for bit), \
         1 = table (Stribeck map tabulated over the envelope at exit of initialization, interpolated, within tolerance of full), \
         2 = boundary (mu = mu_c), 3 = auto (the cheapest level within tolerance; the choice and its measured bound are logged). \
         Outside the envelope (e.g. speeds below envelope.speed_min around reversals) table and boundary answer with the full solve (logged once)"));
    let fid = |name: &str, vr: u32, unit: Option<&'static str>, start: f64, d: &str| {
        let mut x = real(name, vr, Causality::Parameter, Variability::Fixed, unit, None, d);
        x.start = Some(start);
        // Each must be > 0: no min attribute (0 is refused; see the description).
        x
    };
    let [l0, l1, w0, w1] = DEFAULT_ENVELOPE;
    v.push(fid("tolerance", 401, None, DEFAULT_TOLERANCE,
        "Largest relative error accepted in mu, torque and film thickness (absolute in the load shares) for fidelity table, boundary and auto; must be > 0 (table and auto: >= 1e-10, the full solve's own accuracy)"));
    v.push(fid("envelope.load_min", 402, Some("N"), l0, "Smallest load of the envelope the scene visits (> 0)"));
    v.push(fid("envelope.load_max", 403, Some("N"), l1, "Largest load of the envelope (> envelope.load_min)"));
    v.push(fid("envelope.speed_min", 404, Some("rad/s"), w0,
        "Smallest speed magnitude |omega| of the envelope (> 0; slower speeds, around every reversal, are answered by the full solve)"));
    v.push(fid("envelope.speed_max", 405, Some("rad/s"), w1, "Largest speed magnitude |omega| of the envelope (> envelope.speed_min)"));
    let mut t = real("temperature", 3, Causality::Input, Variability::Continuous, Some("K"), Some("degC"),
        "Lubricant temperature T (K; display degC). eta_0 and alpha follow Roelands' temperature relation from their values at lubricant.reference_temperature (Table 3 at 293.15 K by default: at T = T_ref the rig is exactly the paper model's). Must be in (138.15, 673.15] K. Held over each step; a change rebuilds the friction model and continues the integration from the current state (a table level is re-tabulated)");
    t.start = Some(pinjoint::params::DEFAULT_TEMPERATURE);
    t.min = Some(pinjoint::params::MIN_TEMPERATURE);
    t.max = Some(pinjoint::params::MAX_TEMPERATURE);
    v.push(t);
    debug_assert_eq!(v.len(), LAYOUT.len());
    v
}
