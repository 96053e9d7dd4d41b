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
}

impl Validity {
    /// Every level, in the order of their codes 0, 1, 2.
    pub const ALL: [Validity; 3] = [Validity::Checked, Validity::Extrapolation, Validity::KnownWrong];

    /// The code: 0 checked, 1 extrapolation, 2 known-wrong (the FMU output's value).
    pub fn code(self) -> u8 {
        self as u8
    }
    /// The name written in CSV and JSON: `checked`, `extrapolation` or `known-wrong`.
    pub fn as_str(self) -> &'static str {
        match self {
            Validity::Checked => "checked",
            Validity::Extrapolation => "extrapolation",
            Validity::KnownWrong => "known-wrong",
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
/// level (no refusal; `tests/complete.rs`).
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
        write!(
            f,
            "{} = {} {} is outside the checked range {}..{} {} ({}): {}",
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

/// The validity of an operating point at `load` (N, its magnitude is used), sliding speed
/// `sliding_speed` (m/s, its magnitude) and lubricant `temperature` (K), for the paper's
/// model (`paper` true: below [`COLD_SOAK`] known-wrong) or the complete model (below
/// [`COLD_SOAK`] an extrapolation: modelled, not confirmed by a measurement). NaN in any is an
/// extrapolation.
pub fn of_point(load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Validity {
    excursion(load, sliding_speed, temperature, paper).map_or(Validity::Checked, |e| e.validity)
}

/// The worst excursion of an operating point (as [`of_point`]), `None` when checked. For the
/// paper's model the cold-soak band comes first; otherwise the first range left in
/// [`RANGES`] order.
pub fn excursion(load: f64, sliding_speed: f64, temperature: f64, paper: bool) -> Option<Excursion> {
    // `!(T >= COLD_SOAK)` would take NaN as cold: NaN is an extrapolation, not a known error.
    if paper && temperature < COLD_SOAK {
        return Some(Excursion { validity: Validity::KnownWrong, range: TEMPERATURE, value: temperature });
    }
    [(LOAD, load.abs()), (SLIDING_SPEED, sliding_speed.abs()), (TEMPERATURE, temperature)]
        .into_iter()
        .find(|(r, x)| !r.contains(*x))
        .map(|(range, value)| Excursion { validity: Validity::Extrapolation, range, value })
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
/// first answer of each excursion (checked → not checked), false while it stays outside and
/// after it came back; so a host logs once per excursion, not once per step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Tracker {
    outside: bool,
}

impl Tracker {
    /// A tracker that has seen only checked answers.
    pub fn new() -> Self {
        Self::default()
    }
    /// Record the validity of the next answer; true when it starts an excursion.
    pub fn update(&mut self, v: Validity) -> bool {
        let was = self.outside;
        self.outside = v != Validity::Checked;
        self.outside && !was
    }
    /// Whether the last answer was outside the checked ranges.
    pub fn outside(&self) -> bool {
        self.outside
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
        assert!(Validity::Checked < Validity::Extrapolation && Validity::Extrapolation < Validity::KnownWrong);
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
            assert_eq!(of_point(20e3, 0.01, t, false), Validity::Extrapolation);
        }
        assert_eq!(of_point(20e3, 0.01, 293.15, false), Validity::Checked);
    }

    #[test]
    fn the_tracker_fires_once_per_excursion() {
        use Validity::*;
        let mut t = Tracker::new();
        let seq = [Checked, Extrapolation, Extrapolation, KnownWrong, Checked, Checked, KnownWrong, Checked, Extrapolation];
        let fired: Vec<bool> = seq.iter().map(|&v| t.update(v)).collect();
        assert_eq!(fired, [false, true, false, false, false, false, true, false, true]);
    }
}
