//! `--fidelity`, `--tolerance` and the envelope flags shared by `point` and `sweep`, and the
//! messages on standard error: which level `auto` picked with its measured bound, and a
//! one-time note when a point falls outside the envelope.

use super::error::{CliError, Result};
use clap::Args;
use pinjoint::fidelity::{Envelope, Evaluation, Evaluator, Fidelity, Source};
use pinjoint::Params;
use std::sync::atomic::{AtomicBool, Ordering};

/// The `--fidelity`, `--tolerance` and envelope options shared by `point` and `sweep`: which
/// approximation of the model answers (see [`pinjoint::fidelity::Fidelity`]).
#[derive(Args, Debug, Clone)]
pub struct FidelityArgs {
    /// Fidelity level: full (complete solve), table (Stribeck map tabulated over the envelope
    /// to --tolerance), boundary (μ = μ_c), auto (the cheapest level within --tolerance)
    #[arg(long, value_name = "LEVEL", default_value = "full")]
    pub fidelity: String,
    /// Largest relative error accepted in μ, torque and h_c (dimensionless; absolute in the
    /// load shares) for table, boundary and auto
    #[arg(long, value_name = "REL", default_value_t = 1e-4, allow_negative_numbers = true)]
    pub tolerance: f64,
    /// Load range of the envelope, MIN:MAX in N (default: taken from the input)
    #[arg(long, value_name = "MIN:MAX")]
    pub envelope_load: Option<String>,
    /// Speed-magnitude range |ω| of the envelope, MIN:MAX in rad/s (default: from the input)
    #[arg(long, value_name = "MIN:MAX")]
    pub envelope_speed: Option<String>,
}

/// Parse `MIN:MAX` of the flag `flag` (quantity with `unit`).
pub fn parse_range(flag: &str, text: &str, unit: &str) -> Result<(f64, f64)> {
    let bad = |why: &str| CliError::Invalid(format!("{flag} = `{text}` {unit} is invalid: {why}"));
    let (a, b) = text.split_once(':').ok_or_else(|| bad("expected MIN:MAX, e.g. 5000:60000"))?;
    let num = |s: &str, end: &str| -> Result<f64> {
        let v: f64 = s.trim().parse().map_err(|_| bad(&format!("the {end} `{s}` is not a number")))?;
        if v.is_finite() && v > 0.0 { Ok(v) } else { Err(bad(&format!("the {end} = {v} {unit} must be a finite number > 0 {unit}"))) }
    };
    let (lo, hi) = (num(a, "minimum")?, num(b, "maximum")?);
    if lo >= hi {
        return Err(bad(&format!("the minimum {lo} {unit} must be below the maximum {hi} {unit}")));
    }
    Ok((lo, hi))
}

/// A range around the values seen (min < max even when they are all equal).
pub fn range_of(values: impl Iterator<Item = f64>, fallback: (f64, f64)) -> (f64, f64) {
    let (lo, hi) = values.filter(|v| *v > 0.0 && v.is_finite()).fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return fallback;
    }
    if lo < hi { (lo, hi) } else { (lo * (1.0 - 1e-3), hi * (1.0 + 1e-3)) }
}

impl FidelityArgs {
    /// The requested level.
    pub fn level(&self) -> Result<Fidelity> {
        Ok(self.fidelity.parse::<Fidelity>()?)
    }

    /// Whether the complete, cold solve of the library is asked for (the default: outputs
    /// unchanged bit for bit from before fidelity levels existed).
    /// The tolerance is checked in every case, so a mistyped flag is never silently ignored.
    pub fn is_full(&self) -> Result<bool> {
        pinjoint::fidelity::validate_tolerance(self.tolerance)?;
        Ok(self.level()? == Fidelity::Full)
    }

    /// The envelope: flags first, else `loads`/`speeds` (ranges taken from the input).
    pub fn envelope(&self, loads: (f64, f64), speeds: (f64, f64)) -> Result<Envelope> {
        let l = match &self.envelope_load {
            Some(t) => parse_range("--envelope-load", t, "N")?,
            None => loads,
        };
        let s = match &self.envelope_speed {
            Some(t) => parse_range("--envelope-speed", t, "rad/s")?,
            None => speeds,
        };
        Ok(Envelope::new(l.0, l.1, s.0, s.1)?)
    }

    /// Build the evaluator and say on standard error what it is.
    pub fn build(&self, params: &Params, loads: (f64, f64), speeds: (f64, f64)) -> Result<Evaluator> {
        let level = self.level()?;
        let env = self.envelope(loads, speeds)?;
        let ev = Evaluator::new(params, level, self.tolerance, env)?;
        eprintln!("{}", describe(&ev));
        Ok(ev)
    }
}

/// One line on what the evaluator is: level (what auto picked), bound, envelope, candidates.
pub fn describe(ev: &Evaluator) -> String {
    let e = ev.envelope();
    let mut s = format!(
        "fidelity: {} -> {} (measured error bound {:.3e}, tolerance {:.3e}{}) over load {}..{} N, |speed| {}..{} rad/s",
        ev.requested(),
        ev.chosen(),
        ev.error_bound(),
        ev.tolerance(),
        if ev.within_tolerance() { "" } else { ": NOT within the tolerance" },
        e.load_min,
        e.load_max,
        e.speed_min,
        e.speed_max
    );
    if let Some(t) = ev.table() {
        let st = t.stats();
        s.push_str(&format!("; table {}x{} cells, {} KiB", st.load_cells, st.speed_cells, t.size_bytes() / 1024));
    }
    let rejected: Vec<String> = ev
        .assessments()
        .iter()
        .filter(|a| !a.accepted)
        .map(|a| match a.error_bound {
            Some(b) => format!("{} ({b:.3e})", a.level),
            None => format!("{} ({})", a.level, a.note),
        })
        .collect();
    if !rejected.is_empty() {
        s.push_str(&format!("; rejected: {}", rejected.join(", ")));
    }
    s
}

/// Say once per process (`said`) that a point left the envelope.
pub fn note_fallback(e: &Evaluation, ev: &Evaluator, said: &AtomicBool) {
    if e.source == Source::Fallback && !said.swap(true, Ordering::Relaxed) {
        let env = ev.envelope();
        eprintln!(
            "fidelity: load = {} N, speed = {} rad/s is outside the envelope (load {}..{} N, |speed| {}..{} rad/s): \
             answered by the full solve there (said once)",
            e.load, e.angular_velocity, env.load_min, env.load_max, env.speed_min, env.speed_max
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_parse_and_errors_name_flag_value_and_unit() {
        assert_eq!(parse_range("--envelope-load", "5000:60000", "N").unwrap(), (5000.0, 60000.0));
        let e = parse_range("--envelope-load", "6e4:5e3", "N").unwrap_err().to_string();
        assert!(e.contains("--envelope-load") && e.contains("60000 N") && e.contains("below"), "{e}");
        let e = parse_range("--envelope-speed", "0:1", "rad/s").unwrap_err().to_string();
        assert!(e.contains("minimum = 0 rad/s"), "{e}");
        assert!(parse_range("--envelope-speed", "1", "rad/s").unwrap_err().to_string().contains("MIN:MAX"));
        assert!(parse_range("--envelope-speed", "x:1", "rad/s").is_err());
    }

    #[test]
    fn range_of_skips_zero_and_widens_a_single_value() {
        assert_eq!(range_of([0.0, 2.0, 5.0].into_iter(), (1.0, 2.0)), (2.0, 5.0));
        let (lo, hi) = range_of([3.0, 3.0].into_iter(), (1.0, 2.0));
        assert!(lo < 3.0 && hi > 3.0);
        assert_eq!(range_of([0.0].into_iter(), (1.0, 2.0)), (1.0, 2.0));
    }
}
