//! The fidelity parameters both FMUs share: `fidelity`, `tolerance` and the four
//! `envelope.*` bounds, as table rows, with their validation and the messages of the log.

use crate::declare::declare;
use crate::table::{Row, Rule};
use fmi_layer::core::logging::show;
use fmi_layer::core::model::{ModelError, ModelResult};
use fmi_layer::core::variables::{Causality, EnumType, Kind};
use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};

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

/// The envelope parameters of both FMUs (`envelope.*`), with their units.
pub const ENVELOPE_NAMES: [(&str, &str); 4] =
    [("envelope.load_min", "N"), ("envelope.load_max", "N"), ("envelope.speed_min", "rad/s"), ("envelope.speed_max", "rad/s")];

/// Start value of `tolerance` (relative, dimensionless), both FMUs.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

/// The fidelity level of a code of the `fidelity` parameter (0 full, 1 table, 2 boundary,
/// 3 auto); `None` for anything else, fractions included.
pub fn fidelity_of_code(code: f64) -> Option<Fidelity> {
    use pinjoint::fidelity::Fidelity::{Auto, Boundary, Full, Table};
    if code.fract() != 0.0 || !(0.0..=3.0).contains(&code) {
        return None;
    }
    [Full, Table, Boundary, Auto].get(code as usize).copied()
}

/// The fidelity settings of an instance, as the host set them (checked by [`FidelitySettings::validate`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FidelitySettings {
    /// Code of the `fidelity` parameter: 0 full, 1 table, 2 boundary, 3 auto.
    pub code: f64,
    /// The `tolerance` parameter: the relative error a table level may have against full.
    pub tolerance: f64,
    /// load_min, load_max (N), speed_min, speed_max (rad/s).
    pub envelope: [f64; 4],
}

impl FidelitySettings {
    /// Full fidelity, the default tolerance and `envelope`.
    pub const fn full(envelope: [f64; 4]) -> Self {
        FidelitySettings { code: 0.0, tolerance: DEFAULT_TOLERANCE, envelope }
    }

    /// The validated level, tolerance and envelope. They are checked whatever the level,
    /// though `full` uses neither tolerance nor envelope. An error names the parameter, its
    /// value and unit.
    pub fn validate(&self) -> ModelResult<(Fidelity, f64, Envelope)> {
        let level = fidelity_of_code(self.code).ok_or_else(|| {
            ModelError::invalid("parameter", "fidelity", self.code, "", Rule::Code(&FIDELITY_TYPE).broken_by(self.code, "").unwrap_or_default())
        })?;
        let t = self.tolerance;
        if !(t.is_finite() && t > 0.0) {
            return Err(ModelError::invalid("parameter", "tolerance", t, "(relative error, dimensionless)", "is invalid: it must be a finite number > 0"));
        }
        Ok((level, t, envelope_from_parameters(self.envelope)?))
    }

    /// The evaluator of these settings for `params` (validated first).
    pub fn build(&self, params: &pinjoint::Params) -> ModelResult<Evaluator> {
        let (level, tolerance, envelope) = self.validate()?;
        Evaluator::new(params, level, tolerance, envelope).map_err(|e| ModelError::failed("parameter ", e))
    }
}

/// The envelope from the four `envelope.*` parameter values; an error names the parameter,
/// its value and unit.
pub fn envelope_from_parameters(values: [f64; 4]) -> ModelResult<Envelope> {
    for (&x, (name, unit)) in values.iter().zip(ENVELOPE_NAMES) {
        if !(x.is_finite() && x > 0.0) {
            return Err(ModelError::invalid("parameter", name, x, unit, format!("is invalid: it must be a finite number > 0 {unit}")));
        }
    }
    for k in [0, 2] {
        let ((lo_name, unit), (hi_name, _)) = (ENVELOPE_NAMES[k], ENVELOPE_NAMES[k + 1]);
        let (lo, hi) = (values[k], values[k + 1]);
        if lo >= hi {
            return Err(ModelError::invalid("parameter", lo_name, lo, unit, format!("is invalid: it must be below {hi_name} = {} {unit}", show(hi))));
        }
    }
    let [a, b, c, d] = values;
    Envelope::new(a, b, c, d).map_err(|e| ModelError::failed("parameter ", e))
}

/// The envelope as the log writes it: `load 5000..60000 N, |omega| 0.01..10 rad/s`.
pub fn envelope_text(e: &Envelope) -> String {
    format!("load {}..{} N, |omega| {}..{} rad/s", e.load_min, e.load_max, e.speed_min, e.speed_max)
}

/// What the log says about a built evaluator: what was asked, what runs (auto's pick), the
/// measured bound, the tolerance and the envelope, then `tail`.
pub fn describe(ev: &Evaluator, tail: &str) -> String {
    format!(
        "fidelity {} -> {}: measured error bound {:e} (tolerance {:e}) over {}{tail}",
        ev.requested(),
        ev.chosen(),
        ev.error_bound(),
        ev.tolerance(),
        envelope_text(ev.envelope())
    )
}

/// The model-specific texts of the fidelity rows.
#[derive(Debug, Clone, Copy)]
pub struct Texts {
    /// Description of `fidelity`.
    pub fidelity: &'static str,
    /// Description of `tolerance`.
    pub tolerance: &'static str,
    /// Description of `envelope.speed_min`.
    pub speed_min: &'static str,
}

/// The rows `fidelity`, `tolerance`, `envelope.load_min`, …, `envelope.speed_max` at value
/// references `vr`, `vr + 1`, … with start values `start`; `slot` places them in the state
/// (consecutive slots), `at` finds the settings in the model's values.
pub fn rows<S: 'static>(
    vr: u32,
    slot: Option<usize>,
    start: FidelitySettings,
    texts: Texts,
    at: fn(&S) -> &FidelitySettings,
    at_mut: fn(&mut S) -> &mut FidelitySettings,
) -> Vec<Row<S>> {
    let mut fidelity = declare("fidelity", vr, Kind::Enumeration(&FIDELITY_TYPE), Causality::Parameter, None, None, texts.fidelity);
    fidelity.start = Some(start.code);
    fidelity.min = Some(0.0);
    fidelity.max = Some(3.0);
    let mut rows = vec![
        Row::new(fidelity, move |s| at(s).code, move |s, x| at_mut(s).code = x, Rule::Code(&FIDELITY_TYPE)),
        Row::new(
            // Each must be > 0: no min attribute (0 itself is refused; see the description).
            declare_start("tolerance", vr + 1, None, start.tolerance, texts.tolerance),
            move |s| at(s).tolerance,
            move |s, x| at_mut(s).tolerance = x,
            Rule::Any,
        ),
    ];
    let envelope_texts = [
        "Smallest load of the envelope the scene visits (> 0)",
        "Largest load of the envelope (> envelope.load_min)",
        texts.speed_min,
        "Largest speed magnitude |omega| of the envelope (> envelope.speed_min)",
    ];
    for (k, ((name, unit), text)) in ENVELOPE_NAMES.into_iter().zip(envelope_texts).enumerate() {
        let var = declare_start(name, vr + 2 + k as u32, Some(unit), start.envelope[k], text);
        rows.push(Row::new(var, move |s| at(s).envelope[k], move |s, x| at_mut(s).envelope[k] = x, Rule::Any));
    }
    match slot {
        Some(first) => rows.into_iter().enumerate().map(|(k, r)| r.at_slot(first + k)).collect(),
        None => rows,
    }
}

fn declare_start(name: &str, vr: u32, unit: Option<&'static str>, start: f64, text: &str) -> fmi_layer::core::variables::Variable {
    let mut v = declare(name, vr, Kind::Real, Causality::Parameter, unit, None, text);
    v.start = Some(start);
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_and_messages() {
        assert_eq!(fidelity_of_code(3.0), Some(Fidelity::Auto));
        assert_eq!(fidelity_of_code(1.5), None);
        assert_eq!(fidelity_of_code(-0.0), Some(Fidelity::Full));
        assert_eq!(fidelity_of_code(4.0), None);
        let bad = FidelitySettings { code: 1.5, ..FidelitySettings::full([1.0, 2.0, 1.0, 2.0]) };
        assert_eq!(
            bad.validate().unwrap_err().to_string(),
            "parameter fidelity = 1.5 is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)"
        );
        let bad = FidelitySettings { tolerance: 1e308, ..FidelitySettings::full([1.0, 2.0, 1.0, 2.0]) };
        assert!(bad.validate().is_ok());
        let bad = FidelitySettings { tolerance: -1e308, ..FidelitySettings::full([1.0, 2.0, 1.0, 2.0]) };
        assert_eq!(
            bad.validate().unwrap_err().to_string(),
            "parameter tolerance = -1e308 (relative error, dimensionless) is invalid: it must be a finite number > 0"
        );
        let e = envelope_from_parameters([2.0, 1.0, 1.0, 2.0]).unwrap_err().to_string();
        assert_eq!(e, "parameter envelope.load_min = 2 N is invalid: it must be below envelope.load_max = 1 N");
    }
}
