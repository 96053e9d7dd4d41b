//! The validity envelope: where the model was checked against the paper's measurements,
//! where it is an extrapolation, and where its error has a known direction. One definition,
//! used by every front end (the FMUs' `validity` output and log, the `validity` column of
//! the CLI's CSV and `point`, the Python results).
//!
//! The paper ("Model and Experiments to Determine Lubricant Film Formation and Frictional
//! Torque in Aircraft Landing Gear Pin Joints") compares the model with its rig (section 5,
//! Figures 8–13) under these conditions:
//!
//! | quantity | checked range | source |
//! |---|---|---|
//! | load P_T | 5–60 kN | section 4.4 ("radial load, from 5 to 60 kN"), Table 1, Figures 8–10 |
//! | sliding speed u = \|ω\|R | 0–0.1228 m/s (\|ω\| ≤ 4.386 rad/s on the 28 mm pin) | section 4.4: ±40° strokes at 0.03, 0.3 and 1 Hz; the sine stroke peaks at 2π·f·40° = 4.386 rad/s at 1 Hz and passes through 0 at every reversal (Figures 11–13) |
//! | temperature T | 288.15–298.15 K (15–25 °C) | section 4.3: short tests, no significant heating above room temperature; the paper gives no number, 20 ± 5 °C is this crate's reading of "room temperature" |
//! | stroke frequency f (rig) | 0.03–1 Hz | section 4.4, Table 1, Figures 11–13 |
//! | stroke amplitude A (rig) | 40° (±1e-6 relative) | section 4.4 ("pin angular displacement of ±40°") |
//!
//! Outside these ranges the answer is an [`Validity::Extrapolation`]: the equations still
//! hold as written, but nothing measured confirms them there. One band is worse for the
//! paper's model (`model.paper = true`; [`Validity::KnownWrong`]): below [`COLD_SOAK`] (0 °C)
//! it has the grease's base oil
//! only, whose film Roelands' temperature relation thickens without bound as it cools, so μ
//! falls (0.021 at −40 °C, 12°/s, 20 kN, against 0.119 at 20 °C), while a cold-soaked
//! grease's thickener gains a yield stress the model does not have and the real joint turns
//! stiffer: the model's μ and torque are then too LOW, by an amount nothing in the model
//! bounds. The complete model (default) has the grease (its yield stress and consistency in
//! the clearance, the cold supply to the contact; docs/cold-day.md): its answers below 0 °C
//! are an [`Validity::Extrapolation`], modelled but not confirmed by a measurement.
//!
//! The ranges are those of the operating point (load, speed, temperature) and the rig's
//! stroke; they assume the paper's joint (Tables 1–3). A parameter set far from those tables
//! is outside what the paper checked whatever the operating point, which this flag does not
//! see.
//!
//! Past the model's own assumptions ([`Edges`]) the answer is [`Validity::Outside`] (code 3),
//! never a plain extrapolation: a load at which the Hertz contact's half-width a of eq. 6
//! would exceed the pin's radius R ([`load_edge`]: a flat strip of half-width a on a pin of
//! radius R needs a ≤ R; at a = R the contact arc's half-angle is already 1 rad, far from
//! eq. 6's half-space, a ≪ R), and a temperature above the grease's upper service
//! temperature (`grease.upper_service_temperature`, default [`DEFAULT_UPPER_SERVICE_TEMPERATURE`],
//! +121 °C: MIL-PRF-23827 Type I, the default grease's class). The model still answers there
//! (the answer is continuous across the edge; only the flag changes): it refuses only where
//! it cannot answer at all (the asperity model's limit [`crate::Joint::capacity`], and the
//! temperatures outside [`crate::params::MIN_TEMPERATURE`]..[`crate::params::MAX_TEMPERATURE`]).

use crate::params::Params;
use serde::Serialize;
use std::f64::consts::PI;

/// How far an answer is from what the model was checked against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Validity {
    /// Code 0: every quantity inside the checked ranges of [`RANGES`].
    #[default]
    Checked,
    /// Code 1: some quantity outside its checked range (the model's equations, unconfirmed
    /// there; the direction of the error is not known).
    Extrapolation,
    /// Code 2: the paper's model (`model.paper = true`) below [`COLD_SOAK`]: μ and torque are
    /// known to be too low.
    KnownWrong,
    /// Code 3: beyond the model's assumptions ([`Edges`]): the Hertz half-width of eq. 6 wider
    /// than the pin's radius, or a temperature above the grease's upper service temperature.
    /// Answered (continuous with the answers just inside), but the physics it rests on does
    /// not hold there.
    Outside,
}

impl Validity {
    /// Every level, in the order of their codes 0, 1, 2, 3.
    pub const ALL: [Validity; 4] = [Validity::Checked, Validity::Extrapolation, Validity::KnownWrong, Validity::Outside];

    /// The code: 0 checked, 1 extrapolation, 2 known-wrong, 3 outside (the FMU output's value).
    pub fn code(self) -> u8 {
        self as u8
    }
    /// The name written in CSV and JSON: `checked`, `extrapolation`, `known-wrong` or `outside`.
    pub fn as_str(self) -> &'static str {
        match self {
            Validity::Checked => "checked",
            Validity::Extrapolation => "extrapolation",
            Validity::KnownWrong => "known-wrong",
            Validity::Outside => "outside",
        }
    }
    /// What the level means, for logs and documentation.
    pub fn meaning(self) -> &'static str {
        match self {
            Validity::Checked => "inside the conditions the model was checked against (the paper's rig tests)",
            Validity::Extrapolation => "outside the conditions the model was checked against: an extrapolation",
            Validity::KnownWrong => {
                "below 0 C (cold soak) with the paper's model (model.paper = true): it has the base oil's film only and no grease, so its friction coefficient and torque are too LOW (the complete model, model.paper = false, has the grease)"
            }
            Validity::Outside => {
                "beyond the model's assumptions (the Hertz contact of eq. 6 wider than the pin's radius, or the grease above its upper service temperature): answered, but not a model of this joint there"
            }
        }
    }
}

impl std::fmt::Display for Validity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A checked range: `lo ≤ x ≤ hi` in `unit`, from the paper's `source`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// The quantity's name (as the outputs and columns name it).
    pub quantity: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Smallest checked value.
    pub lo: f64,
    /// Largest checked value.
    pub hi: f64,
    /// Where in the paper the range comes from.
    pub source: &'static str,
}

impl Range {
    /// Whether `x` is in [lo, hi] (NaN is not).
    pub fn contains(&self, x: f64) -> bool {
        x >= self.lo && x <= self.hi
    }
}

/// The pin radius of the paper's joint (Table 1, 28 mm), which turns the rig's angular
/// speeds into sliding speeds.
pub const PAPER_PIN_RADIUS: f64 = 0.028;

/// The rig's largest angular speed (rad/s): the ±40° sine stroke at 1 Hz, 2π·1 Hz·40°.
pub const MAX_RIG_ANGULAR_SPEED: f64 = 2.0 * PI * 1.0 * (40.0 * PI / 180.0);

/// Load magnitude |P_T| (N): 5–60 kN.
pub const LOAD: Range = Range {
    quantity: "load",
    unit: "N",
    lo: 5e3,
    hi: 60e3,
    source: "section 4.4 (radial load 5 to 60 kN), Table 1, Figures 8-10",
};

/// Sliding speed u = |ω|R (m/s): 0 up to the 1 Hz stroke's peak on the 28 mm pin.
pub const SLIDING_SPEED: Range = Range {
    quantity: "sliding_speed",
    unit: "m/s",
    lo: 0.0,
    hi: MAX_RIG_ANGULAR_SPEED * PAPER_PIN_RADIUS,
    source: "section 4.4 (+-40 deg strokes at 0.03, 0.3, 1 Hz: |omega| up to 4.386 rad/s), Figures 9, 11-13",
};

/// Lubricant temperature (K): room temperature, read as 20 ± 5 °C.
pub const TEMPERATURE: Range = Range {
    quantity: "temperature",
    unit: "K",
    lo: 288.15,
    hi: 298.15,
    source: "section 4.3 (short tests, no significant heating above room temperature; 20 +- 5 C assumed)",
};

/// Stroke frequency of the rig (Hz): 0.03–1 Hz.
pub const FREQUENCY: Range = Range {
    quantity: "frequency",
    unit: "Hz",
    lo: 0.03,
    hi: 1.0,
    source: "section 4.4, Table 1, Figures 11-13 (0.03, 0.3 and 1 Hz)",
};

/// Stroke amplitude of the rig (rad): the paper's one amplitude, 40°, to a relative 1e-6
/// (a host's degree-to-radian conversion).
pub const STROKE_AMPLITUDE: Range = Range {
    quantity: "amplitude",
    unit: "rad",
    lo: 40.0 * PI / 180.0 * (1.0 - 1e-6),
    hi: 40.0 * PI / 180.0 * (1.0 + 1e-6),
    source: "section 4.4 (pin angular displacement +-40 deg)",
};

/// Every checked range: the operating point's three, then the rig's stroke.
pub const RANGES: [Range; 5] = [LOAD, SLIDING_SPEED, TEMPERATURE, FREQUENCY, STROKE_AMPLITUDE];

/// The declared service range of the complete model (issue 28): every operating point with
/// a load in [[`SERVICE_LOAD_MIN`], the capacity), |ω| ≤ [`SERVICE_SPEED_MAX`] and a temperature
/// in [[`SERVICE_TEMPERATURE_MIN`], [`SERVICE_TEMPERATURE_MAX`]] is answered at every fidelity
/// level (no refusal; `tests/complete.rs`). Within the model's assumptions up to the declared
/// load capacity [`load_edge`] (96.7 kN for the paper's joint) and the grease's upper service
/// temperature (394.15 K by default, above [`SERVICE_TEMPERATURE_MAX`]); above the load edge
/// the answers are flagged [`Validity::Outside`].
pub const SERVICE_LOAD_MIN: f64 = 10.0;
/// Largest speed |ω| of the declared service range (rad/s): above the paper's simulated
/// 800 rpm (83.8 rad/s) and the 173 rad/s.
pub const SERVICE_SPEED_MAX: f64 = 200.0;
/// Lowest temperature of the declared service range (K), −55 °C.
pub const SERVICE_TEMPERATURE_MIN: f64 = 218.15;
/// Highest temperature of the declared service range (K), +120 °C.
pub const SERVICE_TEMPERATURE_MAX: f64 = 393.15;

/// Below this temperature (K, 0 °C) the answer is [`Validity::KnownWrong`] for the paper's model.
pub const COLD_SOAK: f64 = 273.15;

/// The first quantity that put an answer outside the checked ranges, with its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Excursion {
    /// How far outside.
    pub validity: Validity,
    /// The range it left (the temperature's for [`Validity::KnownWrong`]).
    pub range: Range,
    /// The value (in the range's unit).
    pub value: f64,
}

impl std::fmt::Display for Excursion {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let r = &self.range;
        let what = if self.validity == Validity::Outside { "is beyond the model's assumptions, which hold for" } else { "is outside the checked range" };
        write!(
            f,
            "{} = {} {} {what} {}..{} {} ({}): {}",
            r.quantity,
            crate::fmt::Num(self.value),
            r.unit,
            crate::fmt::Num(r.lo),
            crate::fmt::Num(r.hi),
            r.unit,
            r.source,
            self.validity.meaning()
        )
    }
}

/// The validity of an operating point of the paper's joint with the default parameters
/// (their [`Edges`], [`Edges::paper`]) at `load` (N, its magnitude is used), sliding speed
/// `sliding_speed` (m/s, its magnitude) and lubricant `temperature` (K), for the paper's
/// model (`paper` true: below [`COLD_SOAK`] known-wrong) or the complete model (below
/// [`COLD_SOAK`] an extrapolation: modelled, not confirmed by a measurement). NaN in any is an
/// extrapolation. For another parameter set use [`Edges::of_point`] with [`Edges::new`] (what
/// [`crate::Joint::validity`] does).
pub fn of_point(load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Validity {
    Edges::paper().of_point(load, sliding_speed, temperature, paper)
}

/// The worst excursion of an operating point of the default joint (as [`of_point`]), `None`
/// when checked: [`Edges::excursion`] with [`Edges::paper`].
pub fn excursion(load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Option<Excursion> {
    Edges::paper().excursion(load, sliding_speed, temperature, paper)
}

/// Default upper service temperature of the grease (K), +121 °C (MIL-PRF-23827 Type I, the
/// default grease's class): [`crate::params::DEFAULT_UPPER_SERVICE_TEMPERATURE`].
pub use crate::params::DEFAULT_UPPER_SERVICE_TEMPERATURE;

/// What the upper service temperature rests on, for messages.
pub const UPPER_SERVICE_SOURCE: &str =
    "grease.upper_service_temperature: the grease's upper service limit, by default +121 C of MIL-PRF-23827 Type I, the default grease's class";

/// What the load edge rests on, for messages.
pub const LOAD_EDGE_SOURCE: &str =
    "the Hertz half-width a = sqrt(8 P R'/(pi E' B)) of eq. 6 at most the pin radius R: P <= pi E' B R^2/(8 R')";

/// The load (N) at which the Hertz half-width a of eq. 6, a = √(8 P R'/(π E' B)), reaches
/// the pin's radius R: P = π E' B R²/(8 R') (R' the reduced radius and E' the effective
/// modulus of [`crate::contact`], B the bush length). 96.7 kN for the paper's joint (Table 1:
/// R' = 31.39 m, E' = 165.9 GPa, B = 59.4 mm, R = 28 mm). The line contact of eq. 6 is a flat
/// strip on an elastic half-space, which needs a ≪ R; a strip wider than the pin (a > R) has
/// no reading on this geometry at all. NaN for parameters that give no finite R' or E'.
pub fn load_edge(params: &Params) -> f64 {
    let g = &params.geometry;
    let r_red = crate::contact::reduced_radius(g);
    let e_eff = crate::contact::effective_modulus(&params.materials);
    PI * e_eff * g.bush_length * g.pin_radius * g.pin_radius / (8.0 * r_red)
}

/// Where a joint's answers leave the model's assumptions ([`Validity::Outside`] beyond them):
/// the load at which the Hertz half-width reaches the pin's radius ([`load_edge`]) and the
/// grease's upper service temperature (`grease.upper_service_temperature`). Both bounds are
/// inclusive: a point on the edge is inside.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Edges {
    /// Largest load magnitude (N) inside the assumptions ([`load_edge`]).
    pub load: f64,
    /// Highest lubricant temperature (K) inside the assumptions: the grease's upper service
    /// temperature.
    pub temperature: f64,
}

impl Edges {
    /// The edges of the joint `params` describes.
    pub fn new(params: &Params) -> Self {
        Self { load: load_edge(params), temperature: params.grease.upper_service_temperature }
    }

    /// The edges of the default parameters (the paper's joint, Tables 1–3, and the default
    /// grease): 96.7 kN and 394.15 K.
    pub fn paper() -> Self {
        Self::new(&Params::default())
    }

    /// The load edge as a [`Range`] (0 to [`Edges::load`] N) for messages.
    pub fn load_range(&self) -> Range {
        Range { quantity: "load", unit: "N", lo: 0.0, hi: self.load, source: LOAD_EDGE_SOURCE }
    }

    /// The temperature edge as a [`Range`] (the declared minimum to [`Edges::temperature`] K).
    pub fn temperature_range(&self) -> Range {
        Range { quantity: "temperature", unit: "K", lo: crate::params::MIN_TEMPERATURE, hi: self.temperature, source: UPPER_SERVICE_SOURCE }
    }

    /// The validity of an operating point of this joint (as [`of_point`]): [`Validity::Outside`]
    /// when |`load`| > [`Edges::load`] or `temperature` > [`Edges::temperature`], else the
    /// checked envelope's level.
    pub fn of_point(&self, load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Validity {
        self.excursion(load, sliding_speed, temperature, paper).map_or(Validity::Checked, |e| e.validity)
    }

    /// The worst excursion of an operating point, `None` when checked: past an edge first
    /// (the load's, then the temperature's), then for the paper's model the cold-soak band,
    /// then the first checked range left in [`RANGES`] order.
    pub fn excursion(&self, load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Option<Excursion> {
        // `>` is false for NaN: NaN stays an extrapolation (below), never `outside`.
        if load.abs() > self.load {
            return Some(Excursion { validity: Validity::Outside, range: self.load_range(), value: load.abs() });
        }
        if temperature > self.temperature {
            return Some(Excursion { validity: Validity::Outside, range: self.temperature_range(), value: temperature });
        }
        // `!(T >= COLD_SOAK)` would take NaN as cold: NaN is an extrapolation, not a known error.
        if paper && temperature < COLD_SOAK {
            return Some(Excursion { validity: Validity::KnownWrong, range: TEMPERATURE, value: temperature });
        }
        [(LOAD, load.abs()), (SLIDING_SPEED, sliding_speed.abs()), (TEMPERATURE, temperature)]
            .into_iter()
            .find(|(r, x)| !r.contains(*x))
            .map(|(range, value)| Excursion { validity: Validity::Extrapolation, range, value })
    }
}

/// The validity of the rig's stroke: `frequency` (Hz) and `amplitude` (rad, its magnitude).
pub fn of_stroke(frequency: f64, amplitude: f64) -> Validity {
    stroke_excursion(frequency, amplitude).map_or(Validity::Checked, |e| e.validity)
}

/// The stroke's excursion (as [`of_stroke`]), `None` when checked.
pub fn stroke_excursion(frequency: f64, amplitude: f64) -> Option<Excursion> {
    [(FREQUENCY, frequency), (STROKE_AMPLITUDE, amplitude.abs())]
        .into_iter()
        .find(|(r, x)| !r.contains(*x))
        .map(|(range, value)| Excursion { validity: Validity::Extrapolation, range, value })
}

/// Says when a run of answers leaves the checked ranges: [`Tracker::update`] is true on the
/// first answer of each excursion (checked → not checked), and again when an excursion goes
/// past the model's assumptions ([`Validity::Outside`], from a lower level); false while it
/// stays at or below the level it was reported at and after it came back; so a host logs once
/// per excursion (and once more if it leaves the assumptions), not once per step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Tracker {
    last: Validity,
}

impl Tracker {
    /// A tracker that has seen only checked answers.
    pub fn new() -> Self {
        Self::default()
    }
    /// Record the validity of the next answer; true when it starts an excursion or the
    /// excursion goes past the assumptions.
    pub fn update(&mut self, v: Validity) -> bool {
        let was = self.last;
        self.last = v;
        v != Validity::Checked && (was == Validity::Checked || (v == Validity::Outside && was != Validity::Outside))
    }
    /// Whether the last answer was outside the checked ranges.
    pub fn outside(&self) -> bool {
        self.last != Validity::Checked
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ranges_are_the_papers() {
        // 2π·1 Hz·0.698 rad = 4.386 rad/s (the issue's ±4.4 rad/s), 0.1228 m/s on the pin.
        assert!((MAX_RIG_ANGULAR_SPEED - 4.3865).abs() < 1e-4, "{MAX_RIG_ANGULAR_SPEED}");
        assert!((SLIDING_SPEED.hi - 0.12282).abs() < 1e-5);
        assert_eq!(crate::paper::LOADS[0], LOAD.lo);
        assert_eq!(crate::paper::LOADS[4], LOAD.hi);
        assert_eq!(crate::paper::FREQUENCIES[0], FREQUENCY.lo);
        assert_eq!(crate::paper::FREQUENCIES[2], FREQUENCY.hi);
        assert!(STROKE_AMPLITUDE.contains(crate::paper::STROKE_AMPLITUDE));
        assert!(TEMPERATURE.contains(crate::params::DEFAULT_TEMPERATURE));
        const { assert!(COLD_SOAK < TEMPERATURE.lo) };
    }

    #[test]
    fn codes_and_names() {
        for (k, v) in Validity::ALL.iter().enumerate() {
            assert_eq!(usize::from(v.code()), k);
        }
        assert_eq!(Validity::KnownWrong.as_str(), "known-wrong");
        assert_eq!(Validity::Outside.as_str(), "outside");
        assert!(Validity::Checked < Validity::Extrapolation && Validity::Extrapolation < Validity::KnownWrong && Validity::KnownWrong < Validity::Outside);
    }

    /// The numbers docs/validity.md quotes in "Past the model's assumptions", each checked
    /// against the code here (the docs checker requires every number of those tables to be
    /// one of this file's).
    #[test]
    fn the_numbers_docs_validity_md_quotes() {
        use crate::contact::{effective_modulus, hertz, reduced_radius};
        let p = Params::default();
        let (g, r_red, e_eff) = (&p.geometry, reduced_radius(&p.geometry), effective_modulus(&p.materials));
        let a = |load: f64| hertz(load, r_red, e_eff, g.bush_length).half_width;
        let round = |x: f64, digits: i32| (x * 10f64.powi(digits)).round() / 10f64.powi(digits);
        let edge = load_edge(&p);
        // | R' | E' (GPa) | P_edge (N) | P_edge (kN) | a/R at 60 kN | a at 5.05e8 N (m) | p_m at P_edge (MPa) |
        let quoted = [31.388, 165.91, 96667.0, 96.7, 0.788, 2.02, 29.06];
        let computed = [
            round(r_red, 3),
            round(e_eff / 1e9, 2),
            round(edge, 0),
            round(edge / 1e3, 1),
            round(a(60.0 * 1e3) / g.pin_radius, 3),
            round(a(5.05e8), 2),
            round(hertz(edge, r_red, e_eff, g.bush_length).mean_pressure / 1e6, 2),
        ];
        assert_eq!(quoted, computed);
        // At the edge the mean pressure is P/(2RB): the strip is the pin's diameter wide.
        assert!((hertz(edge, r_red, e_eff, g.bush_length).mean_pressure * 2.0 * g.pin_radius * g.bush_length / edge - 1.0).abs() < 1e-12);
        // The asperity limit quoted with it (Joint::capacity), to three digits.
        let cap = crate::Joint::new(&p).unwrap().capacity();
        assert_eq!(round(cap / 1e8, 2), 5.05, "{cap}");
        // The grease classes: (class, lower and upper service limit in C, the parameter in K).
        let classes: [(&str, f64, f64, f64); 2] = [("MIL-PRF-23827 Type I", -73.0, 121.0, 394.15), ("MIL-PRF-81322", -54.0, 177.0, 450.15)];
        for (class, lo, hi, kelvin) in classes {
            assert!((hi + 273.15 - kelvin).abs() < 1e-9 && lo < hi, "{class}");
        }
        assert_eq!(classes[0].3, DEFAULT_UPPER_SERVICE_TEMPERATURE);
        assert_eq!(p.grease.upper_service_temperature, DEFAULT_UPPER_SERVICE_TEMPERATURE);
    }

    #[test]
    fn the_paper_joints_edges() {
        // a(P) = R at P = pi E' B R^2/(8 R'): 96.7 kN (the "about 97 kN").
        let e = Edges::paper();
        assert!((e.load - 96_655.0).abs() < 50.0, "{}", e.load);
        let p = Params::default();
        let a = crate::contact::hertz(e.load, crate::contact::reduced_radius(&p.geometry), crate::contact::effective_modulus(&p.materials), p.geometry.bush_length).half_width;
        assert!((a / p.geometry.pin_radius - 1.0).abs() < 1e-12, "a = {a}");
        assert_eq!(e.temperature, DEFAULT_UPPER_SERVICE_TEMPERATURE);
        assert!(SERVICE_TEMPERATURE_MAX < e.temperature && e.load > LOAD.hi);
        for paper in [false, true] {
            assert_eq!(of_point(e.load, 0.01, 293.15, paper), Validity::Extrapolation);
            assert_eq!(of_point(-e.load * (1.0 + 1e-15), 0.01, 293.15, paper), Validity::Outside);
            assert_eq!(of_point(20e3, 0.01, e.temperature, paper), Validity::Extrapolation);
            assert_eq!(of_point(20e3, 0.01, e.temperature + 1e-9, paper), Validity::Outside);
            assert_eq!(of_point(20e3, 0.01, 673.15, paper), Validity::Outside);
        }
        let x = excursion(2e5, 0.01, 293.15, false).unwrap().to_string();
        assert!(x.contains("load = 200000 N is beyond the model's assumptions") && x.contains("eq. 6"), "{x}");
        let x = excursion(20e3, 0.01, 673.15, false).unwrap().to_string();
        assert!(x.contains("temperature = 673.15 K is beyond") && x.contains("upper_service_temperature"), "{x}");
    }

    #[test]
    fn nan_is_an_extrapolation() {
        for paper in [false, true] {
            assert_eq!(of_point(f64::NAN, 0.01, 293.15, paper), Validity::Extrapolation);
            assert_eq!(of_point(20e3, f64::NAN, 293.15, paper), Validity::Extrapolation);
            assert_eq!(of_point(20e3, 0.01, f64::NAN, paper), Validity::Extrapolation);
        }
        assert_eq!(of_stroke(f64::NAN, 0.7), Validity::Extrapolation);
    }

    #[test]
    fn cold_is_known_wrong_only_for_the_paper_model() {
        for t in [273.0, 253.15, 218.15] {
            assert_eq!(of_point(20e3, 0.01, t, true), Validity::KnownWrong);
            assert_eq!(of_point(2e5, 0.01, t, true), Validity::Outside);
            assert_eq!(of_point(20e3, 0.01, t, false), Validity::Extrapolation);
        }
        assert_eq!(of_point(20e3, 0.01, 293.15, false), Validity::Checked);
    }

    #[test]
    fn the_tracker_fires_once_per_excursion() {
        use Validity::*;
        let mut t = Tracker::new();
        let seq = [Checked, Extrapolation, Extrapolation, KnownWrong, Checked, Checked, KnownWrong, Checked, Extrapolation, Outside, Checked, Outside];
        let fired: Vec<bool> = seq.iter().map(|&v| t.update(v)).collect();
        assert_eq!(fired, [false, true, false, false, false, false, true, false, true, true, false, true]);
    }
}
