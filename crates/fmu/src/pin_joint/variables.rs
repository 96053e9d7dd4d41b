//! The PinJoint variable table ([`TABLE`]): the single source of the modelDescription.xml,
//! the get/set dispatch, the value checks and the FMU state. Layout (table order → value
//! references; the state order in brackets):
//!
//! | value references | variables | state |
//! |---|---|---|
//! | 1–3 | inputs `angle`, `angular_velocity`, `load` | 37–39 |
//! | 10–21, 22–25 | outputs (`min_film_thickness`, `min_lambda_ratio` at 20, 21; then the complete model's `clearance_torque`, `journal_weight`, `eccentricity_ratio`, `grease_yield_torque`; the quantities of the library's record, [`pinjoint::record`], by name) | `dissipated_energy` 40 |
//! | 100–135 | the 36 parameters of [`pinjoint::params::PARAMS`], `section.key` (`model.paper` and `grease.enabled` Booleans) | 0–35 |
//! | 200 | `zero_velocity.speed_band` | 36 |
//! | 300 | `fidelity` (Enumeration: 0 full, 1 table, 2 boundary, 3 auto) | 41 |
//! | 301–305 | `tolerance`, `envelope.load_min`, `envelope.load_max`, `envelope.speed_min`, `envelope.speed_max` | 42–46 |
//! | 4 | input `temperature` (K; last in the table, so every earlier value reference is unchanged) | 47 |
//! | 201–204 | `zero_velocity.model` (Enumeration: 0 band, 1 presliding), `zero_velocity.presliding_angle`, `zero_velocity.elastic_limit`, `zero_velocity.damping_time` | 48–51 |
//! | 40, 41 | local `presliding_torque` (the continuous state) and `der(presliding_torque)` | 52 |
//! | 42, 43 | locals `presliding_reference_angle`, `presliding_angle_driven` (Co-Simulation bookkeeping of the state) | 53, 54 |
//! | 30 | output `validity` (Enumeration: 0 checked, 1 extrapolation, 2 known_wrong, 3 outside; [`pinjoint::validity`]), after the temperature | not stored |
//! | 205 | `zero_velocity.host_inertia` | 55 |
//! | 44–47 | locals `presliding_mode` (Model Exchange: 0 stick, ±1 slip), `presliding_step` and `presliding_reference_speed` (Co-Simulation: the last step and ω there), `presliding_angle_pending` (no angle set since initialization yet) | 56–59 |
//! | 206 | `zero_velocity.host_coupling` (Integer: 0 sequential, 1 parallel) | 60 |
//! | 310, 207, 31 | Integer mirrors `fidelity_code`, `zero_velocity.model_code`, `validity_code` of the three enumerations ([`crate::table::integer_mirrors`]) | not stored |

use super::zero_velocity::{self, Friction, ZeroVelocitySettings};
use crate::declare::declare;
use crate::fidelity::{self, FidelitySettings};
use crate::table::{Access, Row, Rule, Table};
use fmi_layer::core::variables::{Causality, Kind, UnitDef, Variable};
use pinjoint::params::PARAMS;
use pinjoint::record::{self, Value};
use pinjoint::{OperatingPoint, Params};
use std::sync::LazyLock;

/// Version of the serialized state's layout (9: the parameters `grease.supply_layer_inverse` and
/// `grease.upper_service_temperature` after the other parameters, then version 7's values, then
/// `zero_velocity.host_coupling`; 7: version 5's values with the complete model's
/// eight parameters, `model.paper` and `grease.*`, after the paper's, then the host inertia,
/// the Model Exchange mode, the last step, ω there and whether the first angle is pending;
/// 6 was each of those two changes alone on its branch; 5: version 4's values, then the
/// zero-velocity model and presliding parameters and the presliding state). The state also
/// carries its value count, so a layout with another number of values is refused whatever its
/// version.
pub const STATE_VERSION: u8 = 9;

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
    /// The quantities of [`pinjoint::fidelity::evaluation::DERIVED_COLUMNS`] in `point` are
    /// not yet computed (NaN): a table or boundary level answered and no host read asked for
    /// them yet ([`crate::pin_joint::model`]'s `prepare_read`).
    pub pending: bool,
    /// The friction outputs: torque on the pin (N·m), the power dissipated (W), the presliding
    /// torque they use and its rate ([`zero_velocity::Friction`]).
    pub friction: Friction,
}

/// Every value of a PinJoint instance a variable reads or writes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Values {
    /// The 35 model parameters (`lubricant.temperature` is replaced by the input).
    pub params: Params,
    /// `zero_velocity.*`: the model, the band and the presliding parameters.
    pub zv: ZeroVelocitySettings,
    /// `presliding_torque` (N·m): the presliding state τ (Co-Simulation: committed at
    /// `presliding_reference_angle`; Model Exchange: the host's continuous state).
    pub tau: f64,
    /// `presliding_reference_angle` (rad): the angle at which τ was committed (Co-Simulation).
    pub angle_ref: f64,
    /// `presliding_angle_driven` (0 or 1): the host has set the angle since initialization, so
    /// the angle's increments drive the state (else angular_velocity·h).
    pub angle_driven: f64,
    /// `presliding_angle_pending` (0 or 1): no angle was set in initialization and none since:
    /// the next angle set is the reference (no deflection there).
    pub angle_pending: f64,
    /// `presliding_mode` (0 stick, ±1 slip): the Model Exchange mode
    /// ([`pinjoint::zero_velocity::modes`]); 0 under Co-Simulation.
    pub mode: f64,
    /// `presliding_step` (s): the last Co-Simulation step (0 before the first): the angle's
    /// increment is read against ω·h, and the host-inertia damping capped at h.
    pub step: f64,
    /// `presliding_reference_speed` (rad/s): ω at the last Co-Simulation step.
    pub omega_ref: f64,
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
            zv: ZeroVelocitySettings::default(),
            tau: 0.0,
            angle_ref: 0.0,
            angle_driven: 0.0,
            angle_pending: 0.0,
            mode: 0.0,
            step: 0.0,
            omega_ref: 0.0,
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

/// The friction outputs (torque, power) and the state's derivative also depend on the angle
/// (Co-Simulation: its increment deflects the presliding state) and on the state.
const FRICTION: [&str; 5] = ["angle", "angular_velocity", "load", "temperature", "presliding_torque"];

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
            "Angle of the pin relative to the bush. Co-Simulation with zero_velocity.model = presliding: once the host sets it, its increments between steps deflect the presliding state \
             (set it at every step with angular_velocity; a host that never sets it drives the state by angular_velocity * step). Not used by the band or under Model Exchange"),
        input("angular_velocity", 2, ("rad/s", "deg/s"), (0.0, crate::inputs::FINITE), p + 2, (|s| s.omega, |s, x| s.omega = x),
            "Angular velocity omega of the pin relative to the bush (any finite value; sliding speed u = |omega| R)"),
        input("load", 3, ("N", "kN"), (DEFAULT_LOAD, crate::inputs::LOAD_RULE), p + 3, (|s| s.load, |s, x| s.load = x),
            "Radial load P_T on the joint: any finite value, its magnitude |P_T| is the load (a signed reaction component is accepted; the outputs at -P equal those at +P); at 0 the joint is unloaded and every output but dissipated_energy is 0"),
        Row::output(output("torque", 10, Some("N.m"), None, (None, None), &FRICTION,
            "Friction torque on the pin, opposite to the motion: in sliding -sign(omega) mu R P_T (eq. 11); at and near rest the zero-velocity model's \
             (presliding: the elastic presliding torque plus its damping, never beyond the sliding torque by more than the damping; band: linear in omega inside the band)"),
            |s: &Values| s.out.friction.torque),
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
        Row::output(output("power_loss", 18, Some("W"), None, (zero, None), &FRICTION,
            "Power dissipated by friction: |torque * angular_velocity| in sliding (and for the band); under presliding the elastic power stored in the deflection is not counted (plastic slip and damping only)"),
            |s: &Values| s.out.friction.power_loss),
        // A state of the model as well as an output: stored, and checked when a state is restored.
        Row::new(output("dissipated_energy", 19, Some("J"), Some("kJ"), (zero, None), &[],
            "Energy dissipated by friction since initialization: sum over the Co-Simulation steps taken of power_loss * step size (inputs held over each step). Co-Simulation only: under Model Exchange no steps are taken and it stays 0 (integrate power_loss in the host)"),
            |s: &Values| s.energy, |s, x| s.energy = x, Rule::NonNegative).at_slot(p + 4),
        recorded(20, "min_film_thickness", Some("um"), (zero, None), &SPEED_LOAD,
            "Minimum film thickness h_min: h_c times Pan and Hamrock's (1989) line-contact ratio h_min/h_c under eq. 13's substitution (extension; an extrapolation for this joint, 0 at rest)"),
        recorded(21, "min_lambda_ratio", None, (zero, None), &SPEED_LOAD,
            "Lambda ratio from the minimum film, h_min/sqrt(sigma^2 + sigma_b^2) (eq. 21 as printed, with h_min)"),
        recorded(22, "clearance_torque", None, (zero, None), &SPEED_LOAD,
            "Complete model: torque magnitude of the lubricant (grease or base oil) in the clearance outside the contact arc, its yield part included (part of torque; 0 with model.paper = true)"),
        recorded(23, "journal_weight", None, share, &SPEED_LOAD,
            "Complete model: weight w of the journal bearing in the composite film (0 the paper's line contact, 1 the full-film journal bearing; 0 with model.paper = true)"),
        recorded(24, "eccentricity_ratio", None, (zero, Some(1.0)), &SPEED_LOAD,
            "Eccentricity ratio of the clearance around the film, 1 - h_c/(R_b - R), clamped to [0, 1)"),
        recorded(25, "grease_yield_torque", None, (zero, None), &SPEED_LOAD,
            "Complete model: the grease's yield torque tau_y(T)(2 pi - 2 theta_c) R^2 B, part of clearance_torque and of the torque at rest (breakaway); 0 without grease and with model.paper = true"),
    ];
    rows.extend(crate::parameters::rows(100, Some(0), |s: &Values| &s.params, |s| &mut s.params));
    let mut band = declare("zero_velocity.speed_band", 200, Kind::Real, Causality::Parameter, Some("rad/s"), Some("deg/s"),
        "zero_velocity.model = band: half-width omega_b of the speed band around zero in which the torque is ramped linearly, \
         T = -T(P, omega_b) omega/omega_b; outside it the torque is exactly the model's. 0 switches the ramp off");
    band.start = Some(pinjoint::zero_velocity::band::DEFAULT_SPEED_BAND);
    band.min = zero;
    // Checked at exit of initialization ([`super::zero_velocity::ZeroVelocitySettings::validate`]).
    rows.push(Row::new(band, |s: &Values| s.zv.band, |s, x| s.zv.band = x, Rule::Any).at_slot(p));
    rows.extend(fidelity::rows(300, Some(p + 5), DEFAULT_FIDELITY, FIDELITY_TEXTS, |s: &Values| &s.fidelity, |s| &mut s.fidelity));
    rows.push(crate::inputs::temperature(4,
        "Lubricant temperature T (K; display degC). eta_0 and alpha follow Roelands' temperature relation from their values at lubricant.reference_temperature (Table 3 at 293.15 K by default: at T = T_ref the outputs are exactly the paper model's). Must be in [218.15, 673.15] K (-55 to 400 C; with model.paper = true from 238.15 K, -35 C, below which the paper's film at 20 kN passes the diametral clearance at rig speeds). A change costs a few logarithms at fidelity full (the outputs are bit for bit those of an FMU started at that temperature); at table, boundary and auto the level is built and measured again at the new temperature. Outside 15-25 C the validity output says extrapolation; below 0 C with model.paper = true known_wrong (mu too low: no grease); above grease.upper_service_temperature (121 C by default) outside",
        |s: &Values| s.temperature, |s, x| s.temperature = x).at_slot(p + 11));
    rows.push(crate::validity::output(30, &SPEED_LOAD, VALIDITY_TEXT, |s: &Values| f64::from(validity(s).code())));
    rows.extend(zero_velocity::rows(201, p + 12, |s: &Values| &s.zv, |s| &mut s.zv));
    rows.extend(presliding_rows(p + 16));
    rows.push(zero_velocity::host_inertia_row(205, p + 19, |s: &Values| &s.zv, |s| &mut s.zv));
    rows.extend(host_rows(p + 20));
    rows.push(zero_velocity::host_coupling_row(206, p + 24, |s: &Values| &s.zv, |s| &mut s.zv));
    crate::table::integer_mirrors(rows, &MIRRORS)
}

/// The Integer mirrors of PinJoint's enumerations: (enumeration, mirror, value reference).
pub const MIRRORS: [(&str, &str, u32); 3] =
    [("fidelity", "fidelity_code", 310), ("zero_velocity.model", "zero_velocity.model_code", 207), ("validity", "validity_code", 31)];

/// The host-convention bookkeeping of the presliding state (version 7): the Model Exchange
/// mode, the last step and ω there, the pending first angle; slots from `slot`.
fn host_rows(slot: usize) -> Vec<Row<Values>> {
    let local = |name: &str, vr: u32, kind: Kind, unit: Option<&'static str>, text: &str| {
        let mut v = declare(name, vr, kind, Causality::Local, unit, None, text);
        v.start = Some(0.0);
        v
    };
    let finite = crate::inputs::FINITE;
    vec![
        Row::new(local("presliding_mode", 44, Kind::Integer, None,
            "Model Exchange: 0 = stick (presliding_torque integrated), 1 / -1 = slip in +omega / -omega (the torque is the sliding torque, the state held); \
             changed only in event mode, the model asking for a step event when the state reaches the bound or a slip stops"),
            |s: &Values| s.mode, |s, x| s.mode = x, Rule::Closed(-1.0, 1.0)).at_slot(slot),
        Row::new(local("presliding_step", 45, Kind::Real, Some("s"),
            "Co-Simulation: the last communication step h (0 before the first): the angle's increment is read modulo 2 pi as the one closest to \
             presliding_reference_speed * h, and the host-inertia damping is capped at h"),
            |s: &Values| s.step, |s, x| s.step = x, Rule::NonNegative).at_slot(slot + 1),
        Row::new(local("presliding_reference_speed", 46, Kind::Real, Some("rad/s"),
            "Co-Simulation: angular_velocity at the last communication step"),
            |s: &Values| s.omega_ref, |s, x| s.omega_ref = x, finite).at_slot(slot + 2),
        Row::new(local("presliding_angle_pending", 47, Kind::Boolean, None,
            "Co-Simulation: true while no angle was set, in initialization or since: the first angle set is the reference (no deflection there)"),
            |s: &Values| s.angle_pending, |s, x| s.angle_pending = x, Rule::Any).at_slot(slot + 3),
    ]
}

/// The presliding state's rows: `presliding_torque` (the continuous state, slot `slot`), its
/// derivative, and the Co-Simulation bookkeeping (reference angle, angle-driven flag).
fn presliding_rows(slot: usize) -> Vec<Row<Values>> {
    let local = |name: &str, vr: u32, kind: Kind, unit: Option<&'static str>, text: &str| {
        let mut v = declare(name, vr, kind, Causality::Local, unit, None, text);
        v.start = Some(0.0);
        v
    };
    let mut state = local("presliding_torque", 40, Kind::Real, Some("N.m"),
        "Presliding state tau: the elastic presliding torque, signed as the deflection (the friction torque is -tau plus damping; |tau| <= the sliding torque while the joint moves). \
         Co-Simulation: committed at presliding_reference_angle at each step; Model Exchange: the continuous state the host integrates");
    state.nominal = Some(100.0);
    let mut rate = declare("der(presliding_torque)", 41, Kind::Real, Causality::Local, Some("N.m/s"), None,
        "Time derivative of presliding_torque: k omega g, with k = T/phi_s and g the elastic fraction (1 below the elastic limit, 0 at the sliding torque)");
    rate.derivative_of = Some("presliding_torque");
    rate.initial = fmi_layer::core::variables::Initial::Calculated;
    rate.depends_on = vec!["angular_velocity", "load", "temperature", "presliding_torque"];
    let finite = crate::inputs::FINITE;
    vec![
        Row::new(state, |s: &Values| s.tau, |s, x| s.tau = x, finite).at_slot(slot),
        Row::output(rate, |s: &Values| s.out.friction.rate),
        Row::new(local("presliding_reference_angle", 42, Kind::Real, Some("rad"),
            "Co-Simulation: the angle at which presliding_torque was committed (the angle input at the last step, or advanced by angular_velocity * step when the host does not set the angle)"),
            |s: &Values| s.angle_ref, |s, x| s.angle_ref = x, finite).at_slot(slot + 1),
        Row::new(local("presliding_angle_driven", 43, Kind::Boolean, None,
            "Co-Simulation: true once the host has set the angle after initialization: the angle's increments then drive the presliding state"),
            |s: &Values| s.angle_driven, |s, x| s.angle_driven = x, Rule::Any).at_slot(slot + 2),
    ]
}

/// The `validity` output's description.
const VALIDITY_TEXT: &str = "Whether load, sliding speed |omega| R and temperature are inside the conditions the model was checked against (the paper's rig: 5-60 kN, |omega| up to 4.386 rad/s on its 28 mm pin, 15-25 C): 0 checked, 1 extrapolation, 2 known_wrong (below 0 C: base-oil film only, no grease yield stress, mu and torque too LOW), 3 outside (beyond the model's assumptions: load above the one at which the Hertz half-width of eq. 6 reaches the pin radius, pi E' B R^2/(8 R') = 96.7 kN with the default parameters, or temperature above grease.upper_service_temperature, 121 C by default; still answered, continuous across the edge). Logged once per excursion, and again when it goes outside. At zero load (unloaded) it is 1: the load is outside 5-60 kN";

/// The validity of the held inputs ([`pinjoint::validity::Edges::of_point`] with the
/// parameters' edges).
pub fn validity(s: &Values) -> pinjoint::Validity {
    validity_within(s, &pinjoint::validity::Edges::new(&s.params))
}

/// [`validity`] with the parameters' `edges` given (the evaluator's joint holds them).
pub fn validity_within(s: &Values, edges: &pinjoint::validity::Edges) -> pinjoint::Validity {
    edges.of_point(s.load, s.omega.abs() * s.params.geometry.pin_radius, s.temperature, s.params.model.paper)
}

/// The first excursion of the held inputs (as [`validity`]), for the log.
pub fn excursion(s: &Values) -> Option<pinjoint::validity::Excursion> {
    pinjoint::validity::Edges::new(&s.params).excursion(s.load, s.omega.abs() * s.params.geometry.pin_radius, s.temperature, s.params.model.paper)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The state order of version 9: the parameters (the complete model's among them), then
    /// version 5's values, then the host inertia and the host-convention bookkeeping, then the
    /// host coupling. Version 5: version 4's (parameters, band, angle, speed, load,
    /// energy, fidelity code, tolerance, envelope, temperature), then the zero-velocity
    /// parameters and the presliding state.
    #[test]
    fn the_state_order_is_that_of_version_8() {
        let names: Vec<&str> = TABLE.stored().iter().map(|&i| TABLE.rows()[i].var.name.as_str()).collect();
        let p = PARAMS.len();
        assert_eq!(names[..p], PARAMS.iter().map(pinjoint::params::ParamSpec::name).collect::<Vec<_>>()[..]);
        assert_eq!(
            names[p..],
            [
                "zero_velocity.speed_band", "angle", "angular_velocity", "load", "dissipated_energy", "fidelity", "tolerance",
                "envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max", "temperature",
                "zero_velocity.model", "zero_velocity.presliding_angle", "zero_velocity.elastic_limit", "zero_velocity.damping_time",
                "presliding_torque", "presliding_reference_angle", "presliding_angle_driven", "zero_velocity.host_inertia",
                "presliding_mode", "presliding_step", "presliding_reference_speed", "presliding_angle_pending",
                "zero_velocity.host_coupling"
            ]
        );
    }

    /// Every stored row round-trips through get/set and the state; the state holds every
    /// input and parameter and the energy (a new row needs nothing else).
    #[test]
    fn every_row_round_trips_get_set_and_the_state() {
        crate::table::assert_round_trip(&TABLE, "PinJoint", STATE_VERSION, |v| {
            (v.causality != Causality::Output || v.name == "dissipated_energy") && v.derivative_of.is_none()
        });
    }

    #[test]
    fn checks_name_the_variable_value_and_unit() {
        let at = |n: &str| TABLE.index(n).unwrap();
        let msg = |n: &str, x: f64| TABLE.check(at(n), x).unwrap_err().to_string();
        assert_eq!(msg("angle", f64::NAN), "input angle = NaN rad is not a finite number");
        assert_eq!(msg("load", f64::INFINITY), "input load = inf N is invalid: it must be a finite number (a negative value is taken as its magnitude)");
        assert_eq!(msg("temperature", 1e308), "input temperature = 1e308 K is out of range: it must be in [218.15, 673.15] K");
        assert_eq!(msg("fidelity", 0.5), "parameter fidelity = 0.5 is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)");
        assert!(TABLE.check(at("load"), -1e308).is_ok());
        assert_eq!(msg("zero_velocity.model_code", 2.0), "parameter zero_velocity.model_code = 2 is out of range: it must be 0 (band) or 1 (presliding)");
        assert_eq!(msg("zero_velocity.host_coupling", 2.0), "parameter zero_velocity.host_coupling = 2 is out of range: it must be in [0, 1]");
    }

    /// Each Integer mirror reads and sets its enumeration's value, with the enumeration's
    /// codes as its range, and is not stored.
    #[test]
    fn the_integer_mirrors_are_their_enumerations() {
        for (of, name, _) in MIRRORS {
            let (e, m) = (TABLE.index(of).unwrap(), TABLE.index(name).unwrap());
            let (ev, mv) = (&TABLE.rows()[e].var, &TABLE.rows()[m].var);
            let Kind::Enumeration(t) = ev.kind else { panic!("{of} is an Enumeration") };
            assert_eq!(mv.kind, Kind::Integer);
            assert_eq!((mv.causality, mv.variability, mv.start), (ev.causality, ev.variability, ev.start));
            assert_eq!(mv.min, Some(t.items.iter().map(|i| i.1).min().unwrap() as f64));
            assert_eq!(mv.max, Some(t.items.iter().map(|i| i.1).max().unwrap() as f64));
            for (item, code, _) in t.items {
                assert!(mv.description.contains(&format!("{code} = {item}")), "{name}: {}", mv.description);
            }
            assert!(!TABLE.stored().contains(&m), "{name} is not stored");
            let mut v = Values::default();
            if ev.causality == Causality::Parameter {
                let last = t.items.last().unwrap().1 as f64;
                assert_eq!(TABLE.set(&mut v, m, last).name, of, "a set of {name} reports {of}");
                assert_eq!((TABLE.get(&v, e), TABLE.get(&v, m)), (last, last));
                TABLE.set(&mut v, e, 0.0);
                assert_eq!(TABLE.get(&v, m), 0.0);
            } else {
                v.load = 0.0;
                assert_eq!(TABLE.get(&v, m), TABLE.get(&v, e));
            }
        }
    }
}
