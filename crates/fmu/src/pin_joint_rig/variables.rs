//! The PinJointRig variable table ([`TABLE`]): the single source of the modelDescription.xml,
//! the get/set dispatch, the value checks and the FMU state (every input and parameter, in
//! table order). Layout (value references):
//!
//! | value references | variables |
//! |---|---|
//! | 1–2 | inputs `load`, `command_angle` |
//! | 10–23 | outputs (`stuck` is a Boolean) |
//! | 100–102 | stroke parameters `frequency`, `amplitude`, Boolean `use_command_input` |
//! | 200 + i | `rig.<key>` for row i of [`RIG_PARAMS`] (all but `amplitude`, `frequency`, `load`) |
//! | 230, 231 | Enumerations `rig.formulation`, `rig.method` |
//! | 300 + i | `section.key` for row i of [`pinjoint::params::PARAMS`] |
//! | 400 | Enumeration `fidelity` (0 full, 1 table, 2 boundary, 3 auto), as PinJoint's |
//! | 401–405 | `tolerance`, `envelope.load_min`, `envelope.load_max`, `envelope.speed_min`, `envelope.speed_max` |
//! | 3 | input `temperature` (K, display degC), last in the table so earlier entries keep their places |
//! | 24 | output `validity` (Enumeration: 0 checked, 1 extrapolation, 2 known_wrong, 3 outside; [`pinjoint::validity`]), after the temperature; not stored |
//! | 232, 233, 410, 25 | Integer mirrors `rig.formulation_code`, `rig.method_code`, `fidelity_code`, `validity_code` of the four enumerations ([`crate::table::integer_mirrors`]); not stored |
//!
//! The `[rig]` file keys `frequency` and `amplitude` are the stroke parameters
//! `frequency` and `amplitude`; the key `load` is the `load` input.

use super::settings::Settings;
use crate::declare::declare;
use crate::fidelity::{self, FidelitySettings};
use crate::inputs::{FINITE, LOAD_RULE};
use crate::parameters::declared_bounds;
use crate::table::{Access, Row, Rule, Table};
use fmi_layer::core::variables::{Causality, EnumType, Kind, UnitDef, Variable};
use pinjoint::rig::params::{RigParamSpec, RigParams, RIG_PARAMS};
use pinjoint::rig::{RigConfig, Sample};
use std::sync::LazyLock;

pub use super::settings::rig_spec;

/// Version of the serialized state's layout (5: version 4's with the parameter
/// `grease.upper_service_temperature` after the other model parameters; 4: version 3's with the complete model's eight
/// parameters, `model.paper` and `grease.*`; 3: the `temperature` input is the last setting).
pub const STATE_VERSION: u8 = 6;

/// `[rig]` keys that are not `rig.<key>` parameters (the stroke parameters and the load input).
pub const NOT_RIG_PARAMETERS: [&str; 3] = ["amplitude", "frequency", "load"];

/// Start values of the fidelity parameters: the full solve (today's rig, bit for bit);
/// tolerance 1e-4 (PinJoint's); an envelope wide enough for the rig's strokes and loads,
/// 5-100 kN and |omega| 1e-3-10 rad/s (the default 1 Hz, 40 deg stroke peaks at 4.4 rad/s;
/// from 5 kN, PinJoint's lower end, so that the table's margin beyond the envelope keeps the
/// film inside the diametral clearance: from 1 kN the table reached 398 N x 16 rad/s, an
/// 80 um film in a 50 um clearance, and from 2 kN 752 N x 26 rad/s, 68 um;
/// `pinjoint::ModelError::FilmBeyondClearance`).
/// Speeds below speed_min (around every reversal) and points outside it are answered by
/// the full solve (logged once).
pub const DEFAULT_FIDELITY: FidelitySettings = FidelitySettings::full([5e3, 100e3, 1e-3, 10.0]);

/// The outputs of the last sample: the rig's [`Sample`] and the minimum film from the
/// joint. All 0 before the first sample.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// The rig's sample at the current time.
    pub sample: Option<Sample>,
    /// h_min (m) at the sample's load, speed, film and fluid share; 0 at zero load.
    pub min_film_thickness: f64,
    /// h_min/√(σ² + σ_b²) (dimensionless); 0 at zero load.
    pub min_lambda_ratio: f64,
}

impl Outputs {
    /// The outputs of sample `s`, with h_min and λ_min from `joint`
    /// ([`pinjoint::Joint::min_film`]); 0 at zero load (no contact).
    pub fn of(s: Sample, joint: &pinjoint::Joint) -> Self {
        let mut out = Outputs { sample: Some(s), min_film_thickness: 0.0, min_lambda_ratio: 0.0 };
        if s.load > 0.0 {
            let h_min = joint.min_film(s.load, s.angular_velocity, s.film_thickness, s.fluid_load_fraction);
            if h_min.is_finite() {
                out.min_film_thickness = h_min;
                out.min_lambda_ratio = h_min / joint.composite_roughness();
            }
        }
        out
    }
}

/// Every value of a PinJointRig instance a variable reads or writes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Values {
    /// The inputs and parameters.
    pub settings: Settings,
    /// The outputs of the last sample.
    pub out: Outputs,
}

impl Default for Settings {
    /// The start value of every input and parameter.
    fn default() -> Self {
        Settings {
            cfg: RigConfig::default(),
            use_command_input: false,
            formulation: 0.0,
            method: 0.0,
            load: RigParams::default().load,
            command_angle: 0.0,
            fidelity: DEFAULT_FIDELITY,
            temperature: pinjoint::params::DEFAULT_TEMPERATURE,
        }
    }
}

/// The table, in modelDescription order.
pub static TABLE: LazyLock<Table<Values>> = LazyLock::new(|| Table::new(rows()));

/// The declarations of [`TABLE`] (the registry's variable list).
pub fn table() -> Vec<Variable> {
    TABLE.variables()
}

/// Every unit used by a PinJointRig variable.
pub static UNITS: LazyLock<Vec<UnitDef>> = LazyLock::new(|| crate::units::used_by(&table()));

/// Rows of [`RIG_PARAMS`] that are `rig.<key>` parameters.
pub fn rig_rows() -> impl Iterator<Item = usize> {
    (0..RIG_PARAMS.len()).filter(|&i| !NOT_RIG_PARAMETERS.contains(&RIG_PARAMS[i].key))
}

/// `rig.formulation`: the codes of the former Integer parameter.
pub static FORMULATION_TYPE: EnumType = EnumType { name: "RigFormulation", description: "Friction at zero speed in the rig", items: &[
    ("hybrid", 0, "Stick/slip with located events"),
    ("regularised", 1, "tanh(omega/rig.regularisation_speed) regularisation"),
] };

/// `rig.method`: the codes of the former Integer parameter.
pub static METHOD_TYPE: EnumType = EnumType { name: "RigMethod", description: "Integrator of the rig's equations of motion", items: &[
    ("dopri5", 0, "Dormand-Prince 5(4), adaptive (rig.rtol, rig.atol)"),
    ("dop853", 1, "Dormand-Prince 8(5,3), adaptive"),
    ("rk4", 2, "Classical Runge-Kutta, fixed step rig.rk4_step"),
    ("dopri5-dense", 3, "Dormand-Prince 5(4) on the deviation from the loop's steady sine response, states between steps from its continuous extension"),
] };

/// An input row.
fn input(name: &str, vr: u32, (unit, display): (&'static str, &'static str), (start, rule): (f64, Rule), (get, set): Access<Values>, d: &str) -> Row<Values> {
    let mut v = declare(name, vr, Kind::Real, Causality::Input, Some(unit), Some(display), d);
    v.start = Some(start);
    Row::new(v, get, set, rule)
}

/// An output row reading the sample (0 before the first); `contact`: 0 at zero load too.
fn output(name: &str, vr: u32, kind: Kind, (unit, display): (Option<&'static str>, Option<&'static str>), contact: bool, read: fn(&Sample) -> f64, d: &str) -> Row<Values> {
    let v = declare(name, vr, kind, Causality::Output, unit, display, d);
    Row::output(v, move |s: &Values| s.out.sample.as_ref().filter(|s| !contact || s.load > 0.0).map_or(0.0, read))
}

/// A `[rig]` parameter of row `s` at value reference `vr` with start value from the
/// defaults; `description` as written in the table.
fn rig_parameter(name: &str, s: &'static RigParamSpec, vr: u32, unit: Option<&'static str>, display: Option<&'static str>, description: String) -> Row<Values> {
    let mut v = declare(name, vr, Kind::Real, Causality::Parameter, unit, display, description);
    v.start = Some((s.get)(&RigParams::default()));
    (v.min, v.max) = declared_bounds(s.range);
    let (get, set) = (s.get, s.set);
    Row::new(v, move |m: &Values| get(&m.settings.cfg.rig), move |m, x| set(&mut m.settings.cfg.rig, x), Rule::Any)
}

/// An enumeration parameter of type `t`, start 0; checked at exit of initialization.
fn enumeration(name: &str, vr: u32, t: &'static EnumType, (get, set): Access<Values>, d: &str) -> Row<Values> {
    let mut v = declare(name, vr, Kind::Enumeration(t), Causality::Parameter, None, None, d);
    v.start = Some(0.0);
    v.min = Some(0.0);
    v.max = t.items.last().map(|i| i.1 as f64);
    Row::new(v, get, set, Rule::Any)
}

const FIDELITY_TEXTS: fidelity::Texts = fidelity::Texts {
    fidelity: "Fidelity of the friction evaluation inside the rig: 0 = full (the complete solve, warm-started: the rig as without this parameter, bit for bit), \
               1 = table (Stribeck map tabulated over the envelope at exit of initialization, interpolated, within tolerance of full), \
               2 = boundary (mu = mu_c), 3 = auto (the cheapest level within tolerance; the choice and its measured bound are logged). \
               Outside the envelope (e.g. speeds below envelope.speed_min around reversals) table and boundary answer with the full solve (logged once)",
    tolerance: "Largest relative error accepted in mu, torque and film thickness (absolute in the load shares) for fidelity table, boundary and auto; must be > 0 (table and auto: >= 1e-10, the full solve's own accuracy)",
    speed_min: "Smallest speed magnitude |omega| of the envelope (> 0; slower speeds, around every reversal, are answered by the full solve)",
};

/// Every row, in table order (the layout of the module documentation).
fn rows() -> Vec<Row<Values>> {
    use Kind::{Boolean, Real};
    let mut rows = vec![
        input("load", 1, ("N", "kN"), (RigParams::default().load, LOAD_RULE), (|s| s.settings.load, |s, x| s.settings.load = x),
            "Radial load P on the joint: any finite value, its magnitude |P| is the load (a signed reaction component is accepted; -P acts as +P); at 0 there is no contact and no friction. Held over each communication step"),
        input("command_angle", 2, ("rad", "deg"), (0.0, FINITE), (|s| s.settings.command_angle, |s, x| s.settings.command_angle = x),
            "Command angle theta_cmd, used only when use_command_input is true; held over each communication step (its rate is then 0 in the derivative term)"),
        output("angle", 10, Real, (Some("rad"), Some("deg")), false, |s| s.angle, "Pin angle theta (rad), relative to the bush"),
        output("angular_velocity", 11, Real, (Some("rad/s"), Some("deg/s")), false, |s| s.angular_velocity, "Pin angular velocity omega"),
        output("torque", 12, Real, (Some("N.m"), None), false, |s| s.torque,
            "Recorded torque: what the actuator's torque transducer reads, the actuator torque T_a (= J domega/dt - T_f)"),
        output("friction_torque", 13, Real, (Some("N.m"), None), false, |s| s.friction_torque,
            "Friction torque T_f on the pin: -sign(omega) mu(P,|omega|) R P while slipping, the reaction -T_a while stuck, 0 at zero load"),
        output("friction_coefficient", 14, Real, (None, None), false, |s| s.friction_coefficient,
            "The core's mu(P, |omega|) (eq. 10); mu_c while stuck (the capacity, not the mobilised |T_a|/(R P)); 0 at zero load"),
        output("film_thickness", 15, Real, (Some("m"), Some("um")), true, |s| s.film_thickness,
            "The core's central film thickness h_c at (P, |omega|); 0 at zero load (no contact)"),
        output("fluid_load_fraction", 16, Real, (None, None), true, |s| s.fluid_load_fraction,
            "The core's 1/gamma_1, share of the load carried by the film; 0 at zero load"),
        output("stuck", 17, Boolean, (None, None), false, |s| f64::from(u8::from(s.stuck)),
            "True in a stick phase (hybrid formulation), or |omega| <= rig.regularisation_speed (regularised formulation)"),
        output("commanded_angle", 18, Real, (Some("rad"), Some("deg")), false, |s| s.command_angle,
            "The command theta_cmd the position loop follows: amplitude sin(2 pi frequency (t - t_start)), or the command_angle input when use_command_input is true"),
        output("actuator_work", 19, Real, (Some("J"), None), false, |s| s.actuator_work,
            "Work done by the actuator on the rotating parts since initialization, W = integral of T_a omega dt"),
        output("friction_dissipation", 20, Real, (Some("J"), None), false, |s| s.friction_dissipation,
            "Energy dissipated by friction since initialization, D = integral of -T_f omega dt"),
        output("kinetic_energy", 21, Real, (Some("J"), None), false, |s| s.kinetic_energy,
            "Kinetic energy of the rotating parts, J omega^2 / 2 (energy balance: W - D = change of kinetic energy)"),
        Row::output(declare("min_film_thickness", 22, Real, Causality::Output, Some("m"), Some("um"),
            "Minimum film thickness h_min at (P, |omega|): h_c times Pan and Hamrock's (1989) line-contact ratio under eq. 13's substitution (extension; an extrapolation for this joint); 0 at rest and at zero load"),
            |s: &Values| s.out.min_film_thickness),
        Row::output(declare("min_lambda_ratio", 23, Real, Causality::Output, None, None,
            "h_min/sqrt(sigma^2 + sigma_b^2) (eq. 21 as printed, with h_min); 0 at rest and at zero load"),
            |s: &Values| s.out.min_lambda_ratio),
    ];
    for row in &mut rows {
        let v = &mut row.var;
        let name = v.name.as_str();
        if ["friction_coefficient", "film_thickness", "fluid_load_fraction", "friction_dissipation", "kinetic_energy", "min_film_thickness", "min_lambda_ratio"].contains(&name) {
            v.min = Some(0.0);
        }
        if name == "fluid_load_fraction" {
            v.max = Some(1.0);
        }
        // Direct feedthrough: the friction quantities follow the load at once (and the load
        // decides stick against breakaway); the commanded angle is the command input.
        if ["friction_torque", "friction_coefficient", "film_thickness", "fluid_load_fraction", "stuck", "min_film_thickness", "min_lambda_ratio"].contains(&name) {
            v.depends_on = vec!["load", "temperature"];
        } else if name == "commanded_angle" {
            v.depends_on = vec!["command_angle"];
        }
    }
    for (key, vr, display, what) in [
        ("frequency", 100, None, "Stroke frequency f of the internal command A sin(2 pi f (t - t_start))"),
        ("amplitude", 101, Some("deg"), "Stroke amplitude A of the internal command (default 40 deg, section 4.4)"),
    ] {
        let s = rig_spec(key);
        rows.push(rig_parameter(key, s, vr, Some(s.unit), display, format!("{what} (must be {}; [rig] {key} in the parameter file)", s.range.describe())));
    }
    let mut use_input = declare("use_command_input", 102, Boolean, Causality::Parameter, None, None,
        "false: the position loop follows the internal sine A sin(2 pi f (t - t_start)); true: it follows the command_angle input");
    use_input.start = Some(0.0);
    rows.push(Row::new(use_input, |s: &Values| f64::from(u8::from(s.settings.use_command_input)), |s, x| s.settings.use_command_input = x != 0.0, Rule::Any));
    for i in rig_rows() {
        let s = &RIG_PARAMS[i];
        let display = match s.unit {
            "rad" => Some("deg"),
            "s" => Some("ms"),
            "N.m/rad" => Some("N.m/deg"),
            _ => None,
        };
        let description = format!("{} (must be {}; [rig] {} in the parameter file)", s.description, s.range.describe(), s.key);
        rows.push(rig_parameter(&s.name(), s, 200 + i as u32, (s.unit != "1").then_some(s.unit), display, description));
    }
    rows.push(enumeration("rig.formulation", 230, &FORMULATION_TYPE, (|s| s.settings.formulation, |s, x| s.settings.formulation = x),
        "Friction at zero speed: 0 = hybrid (stick/slip with located events), 1 = regularised (tanh(omega/rig.regularisation_speed)); [rig] formulation = \"hybrid\" | \"regularised\""));
    rows.push(enumeration("rig.method", 231, &METHOD_TYPE, (|s| s.settings.method, |s, x| s.settings.method = x),
        "Integrator: 0 = Dopri5 (adaptive, rig.rtol/rig.atol), 1 = Dop853 (adaptive), 2 = RK4 (fixed step rig.rk4_step), 3 = Dopri5 on the deviation from the loop's steady response to the sine command, states between steps from its continuous extension; [rig] method = \"dopri5\" | \"dop853\" | \"rk4\" | \"dopri5-dense\""));
    rows.extend(crate::parameters::rows(300, None, |s: &Values| &s.settings.cfg.model, |s| &mut s.settings.cfg.model));
    rows.extend(fidelity::rows(400, None, DEFAULT_FIDELITY, FIDELITY_TEXTS, |s: &Values| &s.settings.fidelity, |s| &mut s.settings.fidelity));
    rows.push(crate::inputs::temperature(3,
        "Lubricant temperature T (K; display degC). eta_0 and alpha follow Roelands' temperature relation from their values at lubricant.reference_temperature (Table 3 at 293.15 K by default: at T = T_ref the rig is exactly the paper model's). Must be in [218.15, 673.15] K (-55 to 400 C; with model.paper = true from 238.15 K, -35 C, below which the paper's film at 20 kN passes the diametral clearance at rig speeds). Held over each step; a change moves the friction model to the new temperature (a few logarithms at fidelity full; a table or boundary level is built again) and continues the integration from the current state, exactly as a rig started at that temperature and resumed from that state. Outside 15-25 C the validity output says extrapolation; below 0 C with model.paper = true known_wrong (mu too low: no grease); above grease.upper_service_temperature (121 C by default) outside",
        |s: &Values| s.settings.temperature, |s, x| s.settings.temperature = x));
    rows.push(crate::validity::output(24, &["load", "temperature"], VALIDITY_TEXT, |s: &Values| f64::from(validity(s).code())));
    crate::table::integer_mirrors(rows, &MIRRORS)
}

/// The Integer mirrors of PinJointRig's enumerations: (enumeration, mirror, value reference).
pub const MIRRORS: [(&str, &str, u32); 4] = [
    ("rig.formulation", "rig.formulation_code", 232),
    ("rig.method", "rig.method_code", 233),
    ("fidelity", "fidelity_code", 410),
    ("validity", "validity_code", 25),
];

/// The `validity` output's description.
const VALIDITY_TEXT: &str = "Whether the sample's load, sliding speed |omega| R and temperature, and (with the internal sine stroke) its frequency and amplitude, are inside the conditions the model was checked against (the paper's rig: 5-60 kN, |omega| up to 4.386 rad/s on its 28 mm pin, 15-25 C, 0.03-1 Hz, 40 deg): 0 checked, 1 extrapolation, 2 known_wrong (below 0 C: base-oil film only, no grease yield stress, mu and torque too LOW), 3 outside (beyond the model's assumptions: load above the one at which the Hertz half-width of eq. 6 reaches the pin radius, 96.7 kN with the default parameters, or temperature above grease.upper_service_temperature, 121 C by default). Logged once per excursion, and again when it goes outside";

/// The load (N) and angular velocity (rad/s) of the last sample (the `load` input and 0
/// before the first).
fn sampled(s: &Values) -> (f64, f64) {
    s.out.sample.map_or((s.settings.load, 0.0), |x| (x.load, x.angular_velocity))
}

/// The validity of the last sample ([`pinjoint::validity`]): its operating point, and the
/// stroke's frequency and amplitude unless the command input drives the rig.
pub fn validity(s: &Values) -> pinjoint::Validity {
    let (load, omega) = sampled(s);
    let m = &s.settings.cfg.model;
    let point = pinjoint::validity::Edges::new(m).of_point(load, omega.abs() * m.geometry.pin_radius, s.settings.temperature, m.model.paper);
    let r = &s.settings.cfg.rig;
    let stroke = if s.settings.use_command_input { pinjoint::Validity::Checked } else { pinjoint::validity::of_stroke(r.frequency, r.amplitude) };
    point.max(stroke)
}

/// The first excursion of the last sample (as [`validity`]): the operating point's worst,
/// else the stroke's.
pub fn excursion(s: &Values) -> Option<pinjoint::validity::Excursion> {
    let (load, omega) = sampled(s);
    let r = &s.settings.cfg.rig;
    let m = &s.settings.cfg.model;
    let point = pinjoint::validity::Edges::new(m).excursion(load, omega.abs() * m.geometry.pin_radius, s.settings.temperature, m.model.paper);
    point.or_else(|| (!s.settings.use_command_input).then(|| pinjoint::validity::stroke_excursion(r.frequency, r.amplitude)).flatten())
}

/// The state holds every input and parameter, in table order (a new row needs nothing else).
#[cfg(test)]
#[test]
fn every_row_round_trips_get_set_and_the_state() {
    crate::table::assert_round_trip(&TABLE, "PinJointRig", STATE_VERSION, |v| v.causality != Causality::Output);
    assert!(TABLE.stored().windows(2).all(|w| w[0] < w[1]));
}
