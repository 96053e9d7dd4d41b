//! The model's parameter set: every value of the paper's Tables 1–3 plus the
//! boundary friction coefficient μ_c = 0.12 (section 3.1), in SI units.
//!
//! [`PARAMS`] is the one table of parameters: name, unit, symbol, range and
//! accessors. TOML validation, the FMU's parameter variables and the
//! documentation are all generated from it.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Pin and bush geometry (Table 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Geometry {
    /// R, outer radius of the pin (m).
    pub pin_radius: f64,
    /// R_b, inner radius of the bush (m). The radial clearance is R_b − R.
    pub bush_radius: f64,
    /// B, length of the bush (m).
    pub bush_length: f64,
}

/// Elastic properties of pin and bush (Table 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Materials {
    /// E (Pa).
    pub pin_elastic_modulus: f64,
    /// ν (-).
    pub pin_poisson_ratio: f64,
    /// E_b (Pa).
    pub bush_elastic_modulus: f64,
    /// ν_b (-).
    pub bush_poisson_ratio: f64,
}

/// Combined surface topography (Table 2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Surface {
    /// n, asperity density (1/m²).
    pub asperity_density: f64,
    /// β, mean asperity summit radius (m).
    pub asperity_radius: f64,
    /// σ_s, standard deviation of the summit heights (m).
    pub summit_height_std: f64,
    /// σ, RMS roughness of the pin (m).
    pub pin_rms_roughness: f64,
    /// σ_b, RMS roughness of the bush (m).
    pub bush_rms_roughness: f64,
    /// d_d, distance between the summit and surface mean planes (m).
    pub summit_mean_plane_offset: f64,
}

/// Lubricant (Table 3): Roelands viscosity (eq. 5), Bair–Winer limiting shear (eq. 4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Lubricant {
    /// η0, viscosity at inlet temperature (Pa·s).
    pub viscosity: f64,
    /// η∞, Roelands constant (Pa·s).
    pub roelands_viscosity_limit: f64,
    /// c_p, Roelands pressure constant (Pa).
    pub roelands_pressure_constant: f64,
    /// Z, Roelands pressure–viscosity index (-).
    pub roelands_index: f64,
    /// α, pressure–viscosity coefficient (1/Pa).
    pub pressure_viscosity_coefficient: f64,
    /// τ_L0, limiting shear stress at ambient pressure (Pa).
    pub limiting_shear_stress: f64,
    /// β0, slope of the limiting shear stress against pressure (-).
    pub limiting_shear_stress_slope: f64,
    /// T, lubricant (bulk/inlet) temperature (K). Not in the paper (room temperature); see
    /// [`crate::rheology::viscosity::at_temperature`].
    pub temperature: f64,
    /// T_ref, the temperature at which η0 and α above hold (K).
    pub reference_temperature: f64,
    /// S0, Roelands' temperature–viscosity index (-), see [`crate::rheology::viscosity::at_temperature`].
    pub roelands_temperature_index: f64,
}

/// Default temperature and reference temperature: 293.15 K (20 °C), the paper's "room
/// temperature" (section 4.3), an assumption: the paper gives no number.
pub const DEFAULT_TEMPERATURE: f64 = 293.15;
/// Default Roelands temperature–viscosity index S0 for a mineral base oil of class ISO VG 100
/// (see [`crate::rheology::viscosity::DEFAULT_S0_SOURCE`]); inside the 1.04–1.57 fitted to the 13
/// mineral oils of Stachowiak & Batchelor's Table 2.3 (`tests/published_values.rs`).
pub const DEFAULT_ROELANDS_TEMPERATURE_INDEX: f64 = 1.262;

/// Default upper service temperature of the grease (K), +121 °C: the upper limit of
/// MIL-PRF-23827 Type I (−73 °C to +121 °C), the class of the default grease (a lithium-soap
/// grease on a diester base oil; [`crate::rheology::grease`], docs/cold-day.md). Above it a grease of
/// this class is outside its specification (it bleeds, softens and oxidises; its dropping
/// point is not far above): the model's grease and its supply of oil to the contact are not
/// this joint's any more. A MIL-PRF-81322 grease (−54 °C to +177 °C) would set 450.15 K.
pub const DEFAULT_UPPER_SERVICE_TEMPERATURE: f64 = 394.15;

/// Starved-inlet correction of the central film (an extension, off by default; see
/// [`crate::film::starvation`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Starvation {
    /// 1/h_oil, reciprocal of the lubricant layer available at the inlet (1/m); 0 = fully
    /// flooded, the paper's model (default).
    pub inlet_layer_inverse: f64,
    /// γ_s, exponent of the starvation relation (-).
    pub exponent: f64,
}

/// Boundary friction (section 3.1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Friction {
    /// μ_c, friction coefficient of the asperity contacts (-).
    pub boundary_friction_coefficient: f64,
}

/// Which model answers (issue 28): the paper's, or the complete model (default).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Model {
    /// true: the paper's model, bit for bit (the line-contact film of eq. 12 refused beyond
    /// the diametral clearance, temperatures from [`PAPER_MIN_TEMPERATURE`]); false (default):
    /// the complete model (journal bearing in full film, the grease in the clearance, the
    /// grease's oil supply to the contact; docs/cold-day.md).
    pub paper: bool,
}

/// The grease in the clearance and its supply to the contact (complete model only; see
/// [`crate::rheology::grease`] for the rheology and the sources of the defaults).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Grease {
    /// true (default): Herschel–Bulkley grease in the clearance, its oil supply to the contact;
    /// false: the base oil alone fills the clearance (Newtonian), flooded supply.
    pub enabled: bool,
    /// τ_y, yield stress at `lubricant.reference_temperature` (Pa).
    pub yield_stress: f64,
    /// K, Herschel–Bulkley consistency at the reference temperature (Pa·s^n).
    pub consistency: f64,
    /// n, Herschel–Bulkley flow index (-), 0 < n ≤ 1.
    pub flow_index: f64,
    /// E_y/R_gas (K): τ_y(T) = τ_y,ref·exp(E_y/R (1/T − 1/T_ref)).
    pub yield_activation: f64,
    /// E_K/R_gas (K): K(T) = K_ref·exp(E_K/R (1/T − 1/T_ref)).
    pub consistency_activation: f64,
    /// m, exponent of the supply layer's temperature law h_oil(T) = h_oil(T_ref)·(η_b(T_ref)/η_b(T))^m (-).
    pub supply_exponent: f64,
    /// 1/h_oil(T_ref), reciprocal of the oil layer the grease's bleed leaves on the track at
    /// the reference temperature (1/m); 0 = no supply limit ([`crate::film::cold_supply`]).
    pub supply_layer_inverse: f64,
    /// T_max, the grease's upper service temperature (K, absolute: not quoted at the
    /// reference temperature). Above it every answer is `outside` the model's assumptions
    /// (the validity module's `Edges`; docs/validity.md), with either model.
    pub upper_service_temperature: f64,
}

/// The full parameter set. `Params::default()` is the paper's rig with the complete model;
/// [`Params::paper`] the paper's model.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Params {
    /// Pin radius, bush radius and bush length (m).
    pub geometry: Geometry,
    /// Elastic moduli (Pa) and Poisson ratios of pin and bush.
    pub materials: Materials,
    /// Combined surface topography: asperity density, summit radius and heights, roughnesses (Table 2).
    pub surface: Surface,
    /// Viscosity (Roelands, eq. 5), limiting shear (Bair–Winer, eq. 4) and temperature data (Table 3).
    pub lubricant: Lubricant,
    /// Boundary friction coefficient μ_c of the asperity contacts (dimensionless).
    pub friction: Friction,
    /// Extension, not in the paper; off by default.
    pub starvation: Starvation,
    /// The paper's model or the complete one (default).
    pub model: Model,
    /// The grease in the clearance (complete model).
    pub grease: Grease,
}

impl Default for Geometry {
    fn default() -> Self {
        Self { pin_radius: 28e-3, bush_radius: 28.025e-3, bush_length: 59.4e-3 }
    }
}
impl Default for Materials {
    fn default() -> Self {
        Self {
            pin_elastic_modulus: 205e9,
            pin_poisson_ratio: 0.28,
            bush_elastic_modulus: 117e9,
            bush_poisson_ratio: 0.34,
        }
    }
}
impl Default for Surface {
    fn default() -> Self {
        Self {
            asperity_density: 7.15e9,
            asperity_radius: 3.4e-6,
            summit_height_std: 1.09e-6,
            pin_rms_roughness: 0.83e-6,
            bush_rms_roughness: 1.35e-6,
            summit_mean_plane_offset: 1.25e-6,
        }
    }
}
impl Default for Lubricant {
    fn default() -> Self {
        Self {
            viscosity: 12.45e-3,
            roelands_viscosity_limit: 6.31e-5,
            roelands_pressure_constant: 1.96e8,
            roelands_index: 0.63,
            pressure_viscosity_coefficient: 16.9e-9,
            limiting_shear_stress: 2.28e6,
            limiting_shear_stress_slope: 0.047,
            temperature: DEFAULT_TEMPERATURE,
            reference_temperature: DEFAULT_TEMPERATURE,
            roelands_temperature_index: DEFAULT_ROELANDS_TEMPERATURE_INDEX,
        }
    }
}
impl Default for Starvation {
    fn default() -> Self {
        Self { inlet_layer_inverse: 0.0, exponent: crate::film::starvation::DEFAULT_EXPONENT }
    }
}
impl Default for Grease {
    fn default() -> Self {
        use crate::rheology::grease as c;
        Self {
            enabled: true,
            yield_stress: c::DEFAULT_YIELD_STRESS,
            consistency: c::DEFAULT_CONSISTENCY,
            flow_index: c::DEFAULT_FLOW_INDEX,
            yield_activation: c::DEFAULT_YIELD_ACTIVATION,
            consistency_activation: c::DEFAULT_CONSISTENCY_ACTIVATION,
            supply_exponent: c::DEFAULT_SUPPLY_EXPONENT,
            supply_layer_inverse: c::DEFAULT_SUPPLY_LAYER_INVERSE,
            upper_service_temperature: DEFAULT_UPPER_SERVICE_TEMPERATURE,
        }
    }
}

impl Default for Friction {
    fn default() -> Self {
        Self { boundary_friction_coefficient: 0.12 }
    }
}

/// Admissible range of one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Range {
    /// value > 0
    Positive,
    /// value ≥ 0
    NonNegative,
    /// lo ≤ value < hi
    HalfOpen(f64, f64),
    /// lo < value ≤ hi
    OpenClosed(f64, f64),
    /// lo ≤ value ≤ hi
    Closed(f64, f64),
}

impl Range {
    /// Whether `v` lies in the range (false for NaN).
    pub fn contains(&self, v: f64) -> bool {
        match *self {
            Range::Positive => v > 0.0,
            Range::NonNegative => v >= 0.0,
            Range::HalfOpen(lo, hi) => v >= lo && v < hi,
            Range::OpenClosed(lo, hi) => v > lo && v <= hi,
            Range::Closed(lo, hi) => v >= lo && v <= hi,
        }
    }
    /// Human-readable form, e.g. "> 0" or "in [0, 0.5)" (bounds in the short form, `1e12`).
    pub fn describe(&self) -> String {
        use crate::fmt::Num;
        match *self {
            Range::Positive => "> 0".into(),
            Range::NonNegative => ">= 0".into(),
            Range::HalfOpen(lo, hi) => format!("in [{}, {})", Num(lo), Num(hi)),
            Range::OpenClosed(lo, hi) => format!("in ({}, {}]", Num(lo), Num(hi)),
            Range::Closed(lo, hi) => format!("in [{}, {}]", Num(lo), Num(hi)),
        }
    }
    /// (min, max) for an FMU variable's attributes, where the bound is inclusive-or-open.
    pub fn bounds(&self) -> (Option<f64>, Option<f64>) {
        match *self {
            Range::Positive | Range::NonNegative => (Some(0.0), None),
            Range::HalfOpen(lo, hi) | Range::OpenClosed(lo, hi) | Range::Closed(lo, hi) => (Some(lo), Some(hi)),
        }
    }
}

/// One row of the parameter table.
#[derive(Clone, Copy)]
pub struct ParamSpec {
    /// Section of the parameter file (`geometry`, `lubricant`, ...).
    pub section: &'static str,
    /// Key within the section.
    pub key: &'static str,
    /// The paper's symbol.
    pub symbol: &'static str,
    /// SI unit as written in messages and the modelDescription ("" for dimensionless).
    pub unit: &'static str,
    /// One-line description for help text and the modelDescription.
    pub description: &'static str,
    /// Where the default comes from in the paper.
    pub source: &'static str,
    /// The values the parameter may take.
    pub range: Range,
    /// Reads the parameter from a [`Params`], in SI units.
    pub get: fn(&Params) -> f64,
    /// Writes the parameter into a [`Params`], in SI units (no range check).
    pub set: fn(&mut Params, f64),
    /// Real number or boolean switch.
    pub kind: Kind,
}

/// The type of a parameter's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A real number (SI unit).
    Real,
    /// A switch, `true | false` in the file; 1.0 / 0.0 through [`ParamSpec::get`], and any
    /// value other than 0 is `true` through [`ParamSpec::set`].
    Boolean,
}

impl ParamSpec {
    /// `section.key`, the name in messages and in the FMU.
    pub fn name(&self) -> String {
        format!("{}.{}", self.section, self.key)
    }
    /// The value in `Params::default()` (the paper's rig), in SI units.
    pub fn default_value(&self) -> f64 {
        (self.get)(&Params::default())
    }
}

macro_rules! spec {
    ($sec:ident . $key:ident, $sym:expr, $unit:expr, $range:expr, $src:expr, $desc:expr) => {
        ParamSpec {
            section: stringify!($sec),
            key: stringify!($key),
            symbol: $sym,
            unit: $unit,
            description: $desc,
            source: $src,
            range: $range,
            get: |p: &Params| p.$sec.$key,
            set: |p: &mut Params, v: f64| p.$sec.$key = v,
            kind: Kind::Real,
        }
    };
}

macro_rules! switch {
    ($sec:ident . $key:ident, $src:expr, $desc:expr) => {
        ParamSpec {
            section: stringify!($sec),
            key: stringify!($key),
            symbol: "-",
            unit: "1",
            description: $desc,
            source: $src,
            range: Range::Closed(0.0, 1.0),
            get: |p: &Params| if p.$sec.$key { 1.0 } else { 0.0 },
            set: |p: &mut Params, v: f64| p.$sec.$key = v != 0.0,
            kind: Kind::Boolean,
        }
    };
}

/// Every parameter, in file order.
pub static PARAMS: [ParamSpec; 36] = [
    spec!(geometry.pin_radius, "R", "m", Range::Positive, "Table 1", "Outer radius of the pin"),
    spec!(geometry.bush_radius, "R_b", "m", Range::Positive, "Table 1", "Inner radius of the bush (must exceed the pin radius; the radial clearance is R_b - R)"),
    spec!(geometry.bush_length, "B", "m", Range::Positive, "Table 1", "Length of the bush (contact length)"),
    spec!(materials.pin_elastic_modulus, "E", "Pa", Range::Positive, "Table 1", "Elastic modulus of the pin"),
    spec!(materials.pin_poisson_ratio, "nu", "1", Range::HalfOpen(0.0, 0.5), "Table 1", "Poisson's ratio of the pin"),
    spec!(materials.bush_elastic_modulus, "E_b", "Pa", Range::Positive, "Table 1", "Elastic modulus of the bush"),
    spec!(materials.bush_poisson_ratio, "nu_b", "1", Range::HalfOpen(0.0, 0.5), "Table 1", "Poisson's ratio of the bush"),
    spec!(surface.asperity_density, "n", "1/m2", Range::Positive, "Table 2", "Density of asperity summits (combined surface)"),
    spec!(surface.asperity_radius, "beta", "m", Range::Positive, "Table 2", "Mean radius of the asperity summits"),
    spec!(surface.summit_height_std, "sigma_s", "m", Range::Positive, "Table 2", "Standard deviation of the summit heights"),
    spec!(surface.pin_rms_roughness, "sigma", "m", Range::NonNegative, "Table 2", "RMS roughness of the pin (used in the lambda ratio, eq. 21)"),
    spec!(surface.bush_rms_roughness, "sigma_b", "m", Range::NonNegative, "Table 2", "RMS roughness of the bush (used in the lambda ratio, eq. 21)"),
    spec!(surface.summit_mean_plane_offset, "d_d", "m", Range::NonNegative, "Table 2", "Distance between the mean plane of the summits and that of the surface heights"),
    spec!(lubricant.viscosity, "eta_0", "Pa.s", Range::OpenClosed(0.0, GLASS_VISCOSITY), "Table 3", "Lubricant viscosity at inlet temperature (at most 1e12 Pa.s, the viscosity of a glass: Roelands' relations describe a liquid)"),
    spec!(lubricant.roelands_viscosity_limit, "eta_inf", "Pa.s", Range::Positive, "Table 3", "Roelands constant eta_inf (eq. 5)"),
    spec!(lubricant.roelands_pressure_constant, "c_p", "Pa", Range::Positive, "Table 3", "Roelands pressure constant c_p (eq. 5)"),
    spec!(lubricant.roelands_index, "Z", "1", Range::NonNegative, "Table 3", "Roelands pressure-viscosity index (eq. 5)"),
    spec!(lubricant.pressure_viscosity_coefficient, "alpha", "1/Pa", Range::NonNegative, "Table 3", "Pressure-viscosity coefficient (Moes material parameter G = alpha E', eq. 12)"),
    spec!(lubricant.limiting_shear_stress, "tau_L0", "Pa", Range::Positive, "Table 3", "Limiting shear stress at ambient pressure (eq. 4)"),
    spec!(lubricant.limiting_shear_stress_slope, "beta_0", "1", Range::NonNegative, "Table 3", "Slope of the limiting shear stress against pressure (eq. 4)"),
    spec!(friction.boundary_friction_coefficient, "mu_c", "1", Range::NonNegative, "Section 3.1", "Friction coefficient of the asperity contacts (boundary friction)"),
    // Appended after the paper's parameters (existing order, FMU value references and state layouts kept).
    spec!(lubricant.temperature, "T", "K", Range::Closed(MIN_TEMPERATURE, MAX_TEMPERATURE), "Extension (default: room temperature, 20 C, assumed)", "Lubricant temperature; eta_0 and alpha follow Roelands' temperature relation from their values at the reference temperature (exactly the Table 3 values at T = T_ref). From -55 C with the complete model; the paper's model (model.paper = true) from -35 C: Roelands' relation has its pole at -135 C (eta_0 infinite), the Table 3 oil would be a glass (1e12 Pa.s) at -102 C, and at -40 C its film at 20 kN passes the diametral clearance from 5.5 rad/s (the default rig's start-up overshoot), at -35 C from 8 rad/s; for any parameters eta_0(T) above 1e12 Pa.s is rejected"),
    spec!(lubricant.reference_temperature, "T_ref", "K", Range::Closed(MIN_TEMPERATURE, MAX_TEMPERATURE), "Extension (default: room temperature, 20 C, assumed)", "Temperature at which eta_0 and alpha hold (Table 3: room temperature)"),
    spec!(lubricant.roelands_temperature_index, "S_0", "1", Range::NonNegative, "Extension: Roelands (1966); default fitted to an ISO VG 100 mineral oil", "Roelands temperature-viscosity index S_0: ln(eta_0/eta_inf) scales as (1 + (T - 273.15 K)/135 K)^-S_0"),
    spec!(starvation.inlet_layer_inverse, "1/h_oil", "1/m", Range::NonNegative, "Extension: Chevalier et al. (1998); default 0 = fully flooded (the paper's model)", "Reciprocal of the lubricant layer thickness available at the inlet (starved-inlet film correction); 0 = fully flooded"),
    spec!(starvation.exponent, "gamma_s", "1", Range::OpenClosed(0.0, 100.0), "Extension: Chevalier et al. (1998)", "Exponent of the starvation relation h = (h_ff^-g + h_oil^-g)^(-1/g)"),
    switch!(model.paper, "Issue 28 (default false: the complete model)", "true: the paper's model, bit for bit (film refused beyond the diametral clearance, temperature from -35 C); false: the complete model (journal bearing in full film, grease in the clearance, its oil supply to the contact)"),
    switch!(grease.enabled, "Complete model (default true)", "true: Herschel-Bulkley grease in the clearance and its oil supply to the contact (a starved inlet); false: the base oil alone fills the clearance (Newtonian), flooded supply"),
    spec!(grease.yield_stress, "tau_y", "Pa", Range::NonNegative, GREASE_SOURCE, "Yield stress of the grease at the reference temperature (Herschel-Bulkley)"),
    spec!(grease.consistency, "K", "Pa.s^n", Range::NonNegative, GREASE_SOURCE, "Consistency of the grease at the reference temperature (Herschel-Bulkley tau = tau_y + K gamma_dot^n + eta_b gamma_dot)"),
    spec!(grease.flow_index, "n", "1", Range::OpenClosed(0.0, 1.0), GREASE_SOURCE, "Flow index of the grease (Herschel-Bulkley)"),
    spec!(grease.yield_activation, "E_y/R", "K", Range::NonNegative, GREASE_SOURCE, "Activation temperature of the yield stress: tau_y(T) = tau_y exp(E_y/R (1/T - 1/T_ref))"),
    spec!(grease.consistency_activation, "E_K/R", "K", Range::NonNegative, GREASE_SOURCE, "Activation temperature of the consistency: K(T) = K exp(E_K/R (1/T - 1/T_ref))"),
    spec!(grease.supply_exponent, "m", "1", Range::Closed(0.0, 10.0), "Complete model: the grease's oil supply (docs/cold-day.md), default 1 (Darcy/capillary flow)", "Exponent of the supply layer's temperature law h_oil(T) = h_oil(T_ref) (eta_b(T_ref)/eta_b(T))^m"),
    spec!(grease.supply_layer_inverse, "1/h_oil", "1/m", Range::NonNegative, "Complete model: the grease's oil supply (docs/cold-day.md)", "Reciprocal of the oil layer the grease's bleed leaves on the track at the reference temperature; the contact is a starved inlet fed by it (h^-g = h_ff^-g + h_oil^-g, g = starvation.exponent); 0 = no supply limit"),
    spec!(grease.upper_service_temperature, "T_max", "K", Range::Closed(MIN_TEMPERATURE, MAX_TEMPERATURE), "Grease class: MIL-PRF-23827 Type I, -73 to +121 C (default 394.15 K); MIL-PRF-81322 would be 450.15 K (+177 C)", "Upper service temperature of the grease (absolute, not re-quoted): above it every answer, of either model, has validity outside (code 3: beyond the model's assumptions) instead of extrapolation; the answer itself is unchanged"),
];

/// Where the grease's defaults come from ([`crate::rheology::grease`]: chosen for the paper's grease class
/// where no published value was found; docs/cold-day.md).
const GREASE_SOURCE: &str = "Complete model: lithium-complex grease to MIL-PRF-23827 Type I, chosen within published ranges (crate::rheology::grease, docs/cold-day.md)";

/// Lowest admissible temperature (K) of the paper's model (`model.paper = true`), −35 °C. Roelands' temperature term (1 + θ/135 °C)
/// has its pole at θ = −135 °C, where η0 → ∞ (at 145 K the film of the Table 3 oil was
/// 1e108 m); the relation describes a liquid, and the Table 3 oil (S0 = 1.262) would reach
/// [`GLASS_VISCOSITY`] at −102 °C (171.1 K). Long before that the film leaves the joint: at
/// the paper's 20 kN and the rig's peak speed of 4.4 rad/s (1 Hz, ±40°) the Table 3 oil's
/// film passes the diametral clearance 2(R_b − R) = 50 µm below about −42 °C (175 µm at
/// −50 °C, 42 µm at −40 °C; `ModelError::FilmBeyondClearance`), and at −70 °C even the
/// zero-speed band's edge (0.01 rad/s) does. The default rig's start-up overshoots to
/// 5.5 rad/s, where −40 °C gives 52 µm: at −35 °C the film stays inside up to 8 rad/s
/// (42 µm), twice the stroke's peak. For other lubricant parameters
/// [`Params::validate`] also rejects a temperature where η0(T) exceeds [`GLASS_VISCOSITY`].
pub const PAPER_MIN_TEMPERATURE: f64 = 238.15;

/// Lowest admissible temperature (K) of the complete model, −55 °C: the declared service range
/// (issue 28). The paper's model (`model.paper = true`) keeps [`PAPER_MIN_TEMPERATURE`].
pub const MIN_TEMPERATURE: f64 = 218.15;

/// The largest lubricant viscosity the model takes (Pa·s): 1e12 Pa·s, the conventional
/// viscosity of a liquid at its glass transition. Above it the lubricant is a glass, Roelands'
/// relations (eq. 5 and the temperature relation) do not describe it, and the film of eq. 12
/// grows without physical bound.
pub const GLASS_VISCOSITY: f64 = 1e12;
/// Highest admissible temperature (K), 400 °C: far above any grease's dropping point.
pub const MAX_TEMPERATURE: f64 = 673.15;

/// Look a parameter up by its `section.key` name.
pub fn spec_by_name(name: &str) -> Option<&'static ParamSpec> {
    PARAMS.iter().find(|s| s.name() == name)
}

/// A rejected parameter value or file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ParamError {
    /// A parameter value is NaN or infinite.
    #[error("parameter {name} = {v} {unit} is not a finite number", v = crate::fmt::Num(*.value))]
    NotFinite {
        /// The parameter's `section.key`.
        name: String,
        /// The rejected value, in `unit`.
        value: f64,
        /// The parameter's SI unit.
        unit: &'static str,
    },
    /// A parameter value lies outside its allowed [`Range`].
    #[error("parameter {name} = {v} {unit} is out of range: it must be {range}", v = crate::fmt::Num(*.value))]
    OutOfRange {
        /// The parameter's `section.key`.
        name: String,
        /// The rejected value, in `unit`.
        value: f64,
        /// The parameter's SI unit.
        unit: &'static str,
        /// The allowed range, as [`Range::describe`] writes it.
        range: String,
    },
    /// The bush radius does not exceed the pin radius, so the radial clearance is not positive.
    #[error(
        "parameter geometry.bush_radius = {b} m must exceed geometry.pin_radius = {p} m (the radial clearance R_b - R must be positive)",
        b = crate::fmt::Num(*.bush_radius),
        p = crate::fmt::Num(*.pin_radius)
    )]
    NoClearance {
        /// Pin radius R (m).
        pin_radius: f64,
        /// Bush radius R_b (m).
        bush_radius: f64,
    },
    /// The parameter file could not be parsed (TOML syntax, unknown key, wrong type).
    #[error("parameter file: {0}")]
    Parse(String),
}

/// A TOML error as a message of bounded length: where it is (line and column), what is
/// wrong and the line, with at most [`crate::fmt::EXCERPT_CHARS`] characters of it quoted (toml's own text
/// echoes the offending line, which may be megabytes long).
pub fn parse_message(text: &str, e: &toml::de::Error) -> String {
    let what = crate::fmt::excerpt(e.message().trim());
    match e.span() {
        Some(span) => {
            let start = span.start.min(text.len());
            let before = text.get(..start).unwrap_or("");
            let line = before.matches('\n').count() + 1;
            let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
            // The line itself (it names the key of a wrongly typed value), cut to an excerpt.
            let line_start = before.rfind('\n').map_or(0, |i| i + 1);
            let text_line = text[line_start..].split('\n').next().unwrap_or("").trim_end_matches('\r');
            format!("line {line}, column {column}: {what} (in `{}`)", crate::fmt::excerpt(text_line.trim()))
        }
        None => what,
    }
}

fn unit_text(unit: &'static str) -> &'static str {
    if unit == "1" { "(dimensionless)" } else { unit }
}

impl Params {
    /// Check every value against its range and the cross-constraints.
    pub fn validate(&self) -> Result<(), ParamError> {
        // The paper's model's own temperature floor first (its message names the way out).
        let paper_range = self.model.paper && self.lubricant.temperature.is_finite() && !(PAPER_MIN_TEMPERATURE..=MAX_TEMPERATURE).contains(&self.lubricant.temperature);
        for s in PARAMS.iter() {
            if paper_range && s.section == "lubricant" && s.key == "temperature" {
                break;
            }
            let v = (s.get)(self);
            if !v.is_finite() {
                return Err(ParamError::NotFinite { name: s.name(), value: v, unit: unit_text(s.unit) });
            }
            if !s.range.contains(v) {
                return Err(ParamError::OutOfRange {
                    name: s.name(),
                    value: v,
                    unit: unit_text(s.unit),
                    range: s.range.describe(),
                });
            }
        }
        if paper_range {
            return Err(ParamError::OutOfRange {
                name: "lubricant.temperature".into(),
                value: self.lubricant.temperature,
                unit: "K",
                range: format!(
                    "in [{}, {}] with model.paper = true (the paper's film leaves the clearance below -35 C); set model.paper = false for the complete model, which takes temperatures from {} K (-55 C)",
                    crate::fmt::Num(PAPER_MIN_TEMPERATURE),
                    crate::fmt::Num(MAX_TEMPERATURE),
                    crate::fmt::Num(MIN_TEMPERATURE)
                ),
            });
        }
        let g = &self.geometry;
        if g.bush_radius - g.pin_radius <= 0.0 {
            return Err(ParamError::NoClearance { pin_radius: g.pin_radius, bush_radius: g.bush_radius });
        }
        // η0 at the lubricant temperature (Roelands' temperature relation) must stay a liquid's.
        let l = &self.lubricant;
        let eta = crate::rheology::roelands_temperature::viscosity(l.viscosity, l.roelands_viscosity_limit, l.temperature, l.reference_temperature, l.roelands_temperature_index);
        if !(eta.is_finite() && eta > 0.0 && eta <= GLASS_VISCOSITY) {
            let l = &self.lubricant;
            return Err(ParamError::OutOfRange {
                name: "lubricant.temperature".into(),
                value: l.temperature,
                unit: "K",
                range: format!(
                    "such that eta_0(T) <= {GLASS_VISCOSITY:e} Pa.s, a liquid's (here eta_0(T) = {} Pa.s by Roelands' temperature relation from eta_0 = {} Pa.s at {} K with S_0 = {})",
                    crate::fmt::Num(eta),
                    crate::fmt::Num(l.viscosity),
                    crate::fmt::Num(l.reference_temperature),
                    crate::fmt::Num(l.roelands_temperature_index)
                ),
            });
        }
        Ok(())
    }

    /// The same joint quoted at another reference temperature `reference` (K): every
    /// temperature-quoted parameter moved there by its own law, so that every property, at
    /// every temperature, is unchanged (to rounding) and so is every answer. η0 by Roelands'
    /// temperature relation and α by its factor ([`crate::rheology::viscosity::at_temperature`]), τ_y and
    /// K by their Arrhenius laws ([`crate::rheology::grease::arrhenius`]), the grease's supply layer by its
    /// law h_oil ∝ η_b^−m ([`crate::film::cold_supply`]); `lubricant.reference_temperature` set to
    /// `reference`. The operating temperature `lubricant.temperature` is kept. Errors as
    /// [`Params::validate`]'s for the result (for example a reference outside the admissible
    /// temperatures, or η0 beyond a glass's viscosity there).
    pub fn requoted_at(&self, reference: f64) -> Result<Self, ParamError> {
        self.validate()?;
        let refuse = |range: String| ParamError::OutOfRange { name: "lubricant.reference_temperature".into(), value: reference, unit: "K", range };
        if !(MIN_TEMPERATURE..=MAX_TEMPERATURE).contains(&reference) {
            return Err(refuse(format!("in [{MIN_TEMPERATURE}, {MAX_TEMPERATURE}] to quote the joint at it")));
        }
        let mut q = *self;
        q.lubricant.reference_temperature = reference;
        let l = &self.lubricant;
        // Roelands' temperature relation ([`crate::rheology::viscosity::at_temperature`]) on plain numbers.
        let viscosity = crate::rheology::roelands_temperature::viscosity(l.viscosity, l.roelands_viscosity_limit, reference, l.reference_temperature, l.roelands_temperature_index);
        let factor = crate::rheology::roelands_temperature::factor(reference, l.reference_temperature, l.roelands_temperature_index);
        let moved = Lubricant { viscosity, pressure_viscosity_coefficient: l.pressure_viscosity_coefficient * factor, ..*l };
        if !(moved.viscosity.is_finite() && moved.viscosity > 0.0 && moved.viscosity <= GLASS_VISCOSITY) {
            return Err(refuse(format!(
                "such that eta_0 there stays a liquid's viscosity (here {:e} Pa.s; Roelands' temperature relation from {} K)",
                moved.viscosity,
                crate::fmt::Num(l.reference_temperature)
            )));
        }
        q.lubricant.viscosity = moved.viscosity;
        q.lubricant.pressure_viscosity_coefficient = moved.pressure_viscosity_coefficient;
        let g = &self.grease;
        q.grease.yield_stress = crate::rheology::grease::arrhenius(g.yield_stress, g.yield_activation, reference, l.reference_temperature);
        q.grease.consistency = crate::rheology::grease::arrhenius(g.consistency, g.consistency_activation, reference, l.reference_temperature);
        if g.supply_layer_inverse > 0.0 {
            q.grease.supply_layer_inverse = g.supply_layer_inverse * (moved.viscosity / l.viscosity).powf(g.supply_exponent);
        }
        q.validate()?;
        Ok(q)
    }


    /// The paper's rig with the paper's model (`model.paper = true`): today's numbers, bit for bit.
    pub fn paper() -> Self {
        Self { model: Model { paper: true }, ..Self::default() }
    }

    /// Radial clearance c = R_b − R (m), derived, never an input.
    pub fn radial_clearance(&self) -> f64 {
        self.geometry.bush_radius - self.geometry.pin_radius
    }

    /// Parse a (partial) TOML parameter file; missing keys keep their defaults.
    pub fn from_toml_str(text: &str) -> Result<Self, ParamError> {
        let p: Params = toml::from_str(text).map_err(|e| ParamError::Parse(parse_message(text, &e)))?;
        p.validate()?;
        Ok(p)
    }

    /// The full parameter file, with units as comments. Loads back unchanged.
    pub fn to_toml_string(&self) -> String {
        let mut out = String::from(
            "# pinjoint parameter file (SI units). Defaults: Tables 1-3 of the paper.\n\
             # Any subset of keys may be given; missing keys keep their defaults.\n",
        );
        // Sections in order of first appearance; parameters appended later to a section
        // (e.g. the lubricant temperature) are written with it (TOML forbids a repeated table).
        let mut sections: Vec<&str> = Vec::new();
        for s in PARAMS.iter() {
            if !sections.contains(&s.section) {
                sections.push(s.section);
            }
        }
        for section in sections {
            out.push_str(&format!("\n[{section}]\n"));
            for s in PARAMS.iter().filter(|s| s.section == section) {
            let unit = if s.unit == "1" { "-" } else { s.unit };
            // `{:?}` prints the shortest representation that round-trips exactly.
            let value = match s.kind {
                Kind::Real => format!("{:?}", (s.get)(self)),
                Kind::Boolean => ((s.get)(self) != 0.0).to_string(),
            };
            out.push_str(&format!("{} = {value}  # {} [{}], {}\n", s.key, s.symbol, unit, s.description));
            }
        }
        out
    }

    /// Set a parameter by its `section.key` name (no validation; call [`Params::validate`]).
    pub fn set_by_name(&mut self, name: &str, value: f64) -> Option<()> {
        spec_by_name(name).map(|s| (s.set)(self, value))
    }

    /// Get a parameter by its `section.key` name.
    pub fn get_by_name(&self, name: &str) -> Option<f64> {
        spec_by_name(name).map(|s| (s.get)(self))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_roundtrip_through_toml() {
        let p = Params::default();
        p.validate().unwrap();
        let text = p.to_toml_string();
        let q = Params::from_toml_str(&text).unwrap();
        assert_eq!(p, q);
    }

    #[test]
    fn table_covers_every_field_once() {
        // Serialising through serde lists the fields; the table must name each exactly once.
        let v: toml::Table = toml::from_str(&toml::to_string(&Params::default()).unwrap()).unwrap();
        let mut names: Vec<String> = v
            .iter()
            .flat_map(|(sec, t)| t.as_table().unwrap().keys().map(move |k| format!("{sec}.{k}")))
            .collect();
        names.sort();
        let mut table: Vec<String> = PARAMS.iter().map(super::ParamSpec::name).collect();
        table.sort();
        assert_eq!(names, table);
        // And each accessor reads its own field: set a distinct value through the table, read back through serde.
        let mut p = Params::default();
        for (i, s) in PARAMS.iter().enumerate() {
            (s.set)(&mut p, 1000.0 + i as f64);
        }
        let v: toml::Table = toml::from_str(&toml::to_string(&p).unwrap()).unwrap();
        for (i, s) in PARAMS.iter().enumerate() {
            match s.kind {
                Kind::Real => assert_eq!(v[s.section][s.key].as_float().unwrap(), 1000.0 + i as f64, "{}", s.name()),
                Kind::Boolean => assert_eq!(v[s.section][s.key].as_bool(), Some(true), "{}", s.name()),
            }
        }
        // A switch reads back what was set, both ways.
        for s in PARAMS.iter().filter(|s| s.kind == Kind::Boolean) {
            for v in [0.0, 1.0] {
                (s.set)(&mut p, v);
                assert_eq!((s.get)(&p), v, "{}", s.name());
            }
        }
    }

    #[test]
    fn switches_parse_as_booleans_and_the_paper_model_keeps_its_floor() {
        let p = Params::from_toml_str("[model]\npaper = true\n[grease]\nenabled = false\n").unwrap();
        assert!(p.model.paper && !p.grease.enabled);
        assert_eq!(Params::from_toml_str(&p.to_toml_string()).unwrap(), p);
        assert!(Params::from_toml_str("[model]\npaper = 1.0\n").is_err());
        // −40 C: the complete model takes it, the paper's model names the key and the way out.
        let mut q = Params::default();
        q.lubricant.temperature = 233.15;
        q.validate().unwrap();
        q.model.paper = true;
        let m = q.validate().unwrap_err().to_string();
        assert!(m.contains("lubricant.temperature = 233.15 K") && m.contains("model.paper = false"), "{m}");
        q.lubricant.temperature = MIN_TEMPERATURE - 0.01;
        q.model.paper = false;
        assert!(q.validate().is_err());
    }

    #[test]
    fn partial_file_keeps_defaults() {
        let p = Params::from_toml_str("[geometry]\npin_radius = 0.02\nbush_radius = 0.0201\n").unwrap();
        assert_eq!(p.geometry.pin_radius, 0.02);
        assert_eq!(p.geometry.bush_length, 59.4e-3);
        assert_eq!(p.lubricant, Lubricant::default());
        assert!((p.radial_clearance() - 1e-4).abs() < 1e-15);
    }

    #[test]
    fn unknown_key_is_rejected_by_name() {
        let e = Params::from_toml_str("[geometry]\npin_radiuss = 0.02\n").unwrap_err();
        assert!(e.to_string().contains("pin_radiuss"), "{e}");
        let e = Params::from_toml_str("[geometryy]\npin_radius = 0.02\n").unwrap_err();
        assert!(e.to_string().contains("geometryy"), "{e}");
    }

    #[test]
    fn out_of_range_message_names_key_value_and_unit() {
        let e = Params::from_toml_str("[materials]\npin_elastic_modulus = -5.0\n").unwrap_err();
        let m = e.to_string();
        assert!(m.contains("materials.pin_elastic_modulus") && m.contains("-5") && m.contains("Pa"), "{m}");
        let e = Params::from_toml_str("[materials]\nbush_poisson_ratio = 0.5\n").unwrap_err();
        assert!(e.to_string().contains("materials.bush_poisson_ratio = 0.5"), "{e}");
        let e = Params::from_toml_str("[surface]\npin_rms_roughness = -1e-6\n").unwrap_err();
        assert!(e.to_string().contains("surface.pin_rms_roughness = -1e-6 m"), "{e}");
        let e = Params::from_toml_str("[geometry]\nbush_radius = 0.028\n").unwrap_err();
        assert!(matches!(e, ParamError::NoClearance { .. }), "{e}");
        assert!(e.to_string().contains("geometry.bush_radius"));
    }

    #[test]
    fn a_huge_bad_file_gives_a_short_message() {
        // A 10 MB junk line, a 10 MB unknown key, a 10 MB string value: the message quotes at
        // most an excerpt of each.
        let junk = "x".repeat(10_000_000);
        for text in [junk.clone(), format!("[geometry]\n{junk} = 1.0\n"), format!("[geometry]\npin_radius = \"{junk}\"\n")] {
            let m = Params::from_toml_str(&text).unwrap_err().to_string();
            assert!(m.len() < crate::fmt::MESSAGE_CHARS, "{} characters: {}", m.len(), &m[..300.min(m.len())]);
            assert!(m.starts_with("parameter file: line "), "{m}");
        }
        let m = Params::from_toml_str(&format!("[geometry]\n{junk} = 1.0\n")).unwrap_err().to_string();
        assert!(m.contains("line 2, column 1") && m.contains("more characters"), "{m}");
    }

    #[test]
    fn non_finite_is_rejected() {
        let e = Params::from_toml_str("[lubricant]\nviscosity = nan\n").unwrap_err();
        assert!(matches!(e, ParamError::NotFinite { .. }), "{e}");
        assert!(e.to_string().contains("lubricant.viscosity") && e.to_string().contains("Pa.s"));
        let e = Params::from_toml_str("[lubricant]\nviscosity = inf\n").unwrap_err();
        assert!(e.to_string().contains("inf"), "{e}");
    }

    #[test]
    fn every_range_rejects_a_bad_value() {
        for s in PARAMS.iter().filter(|s| s.kind == Kind::Real) {
            let mut p = Params::default();
            (s.set)(&mut p, -1.0);
            assert!(p.validate().is_err(), "{} accepted -1", s.name());
        }
    }
}
