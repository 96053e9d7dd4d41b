//! The fit's coordinates: μ_c and the torque offset as they are (the model is linear in both),
//! every other parameter mapped to an unbounded coordinate from its range in the parameter
//! table (`pinjoint::params::PARAMS`): ln θ for θ > 0 (a positive parameter spans decades and
//! cannot cross zero), a logit for a bounded one.

use super::error::CalibrationError;
use pinjoint::params::{spec_by_name, ParamSpec, Range, PARAMS};
use pinjoint::rig::params::RigParamSpec;
use pinjoint::rig::{RigParams, RIG_PARAMS};
use pinjoint::Params;

/// The key of the boundary friction coefficient μ_c.
pub const MU_C: &str = "friction.boundary_friction_coefficient";

/// How a parameter maps to its fit coordinate β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Transform {
    /// β = θ.
    Identity,
    /// β = ln θ.
    Log,
    /// β = ln((θ − lo)/(hi − θ)).
    Logit(f64, f64),
}

impl Transform {
    /// The transform for a parameter's range.
    pub fn for_range(range: Range) -> Self {
        match range {
            Range::Positive | Range::NonNegative => Transform::Log,
            Range::HalfOpen(lo, hi) | Range::OpenClosed(lo, hi) | Range::Closed(lo, hi) => Transform::Logit(lo, hi),
        }
    }
    /// θ → β (None outside the domain).
    pub fn forward(&self, v: f64) -> Option<f64> {
        let b = match *self {
            Transform::Identity => v,
            Transform::Log => v.ln(),
            Transform::Logit(lo, hi) => ((v - lo) / (hi - v)).ln(),
        };
        b.is_finite().then_some(b)
    }
    /// β → θ.
    pub fn inverse(&self, b: f64) -> f64 {
        match *self {
            Transform::Identity => b,
            Transform::Log => b.exp(),
            Transform::Logit(lo, hi) => lo + (hi - lo) / (1.0 + (-b).exp()),
        }
    }
    /// dθ/dβ at β.
    pub fn slope(&self, b: f64) -> f64 {
        match *self {
            Transform::Identity => 1.0,
            Transform::Log => b.exp(),
            Transform::Logit(lo, hi) => {
                let s = 1.0 / (1.0 + (-b).exp());
                (hi - lo) * s * (1.0 - s)
            }
        }
    }
}

/// A parameter fitted besides μ_c: a key of the model's table or (rig model only) of the rig's.
#[derive(Clone, Copy)]
pub enum Key {
    /// A key of `pinjoint::params::PARAMS` (`section.key`).
    Model(&'static ParamSpec),
    /// A key of `pinjoint::rig::RIG_PARAMS` (`rig.key`), fitted through the rig simulation.
    Rig(&'static RigParamSpec),
}

impl Key {
    /// `section.key` or `rig.key`.
    pub fn name(&self) -> String {
        match self {
            Key::Model(s) => s.name(),
            Key::Rig(s) => s.name(),
        }
    }
    /// SI unit.
    pub fn unit(&self) -> &'static str {
        match self {
            Key::Model(s) => s.unit,
            Key::Rig(s) => s.unit,
        }
    }
    /// Admissible values (from the parameter table).
    pub fn range(&self) -> Range {
        match self {
            Key::Model(s) => s.range,
            Key::Rig(s) => s.range,
        }
    }
    /// The value in `params` / `rig`.
    pub fn get(&self, params: &Params, rig: &RigParams) -> f64 {
        match self {
            Key::Model(s) => (s.get)(params),
            Key::Rig(s) => (s.get)(rig),
        }
    }
    /// Set the value in `params` / `rig`.
    pub fn set(&self, params: &mut Params, rig: &mut RigParams, v: f64) {
        match self {
            Key::Model(s) => (s.set)(params, v),
            Key::Rig(s) => (s.set)(rig, v),
        }
    }
}

/// A parameter fitted besides μ_c.
#[derive(Clone, Copy)]
pub struct Extra {
    /// The parameter's name, unit, default and bounds.
    pub key: Key,
    /// Map between the parameter's value and the unconstrained fit coordinate.
    pub transform: Transform,
    /// The start value (the given one, or moved inside from a bound of the range).
    pub start: f64,
}

/// `[rig]` keys that are not properties of the rig: the excitation (taken from each record)
/// and the integrator's settings.
const NOT_FITTABLE: [(&str, &str); 8] = [
    ("amplitude", "the command is taken from each record's angle"),
    ("frequency", "the command is taken from each record's angle"),
    ("load", "the load is taken from each record"),
    ("rtol", "an integrator setting"),
    ("atol", "an integrator setting"),
    ("rk4_step", "an integrator setting"),
    ("event_tolerance", "an integrator setting"),
    ("segment_length", "an integrator setting"),
];

/// Resolve `--fit` keys (μ_c may be named or not; it is always fitted). `rig` says whether the
/// rig model is fitted (then `rig.*` keys are allowed: start values from `start_rig`). Unknown
/// keys, repeats and start values outside the transform's domain are errors naming the key; a
/// rig key whose start value lies on a closed bound of its range (`rig.breakaway_factor` = 1,
/// its default) starts 5 % inside it instead.
pub fn resolve(keys: &[String], start: &Params, start_rig: &RigParams, rig: bool) -> Result<Vec<Extra>, CalibrationError> {
    let mut out: Vec<Extra> = Vec::new();
    for key in keys {
        let key = key.trim();
        if key.is_empty() || key == MU_C {
            continue;
        }
        let found = match (spec_by_name(key), key.strip_prefix("rig.")) {
            (Some(s), _) => Key::Model(s),
            (None, Some(k)) => {
                let s = RIG_PARAMS.iter().find(|s| s.key == k).ok_or_else(|| {
                    let known: Vec<String> = RIG_PARAMS.iter().map(RigParamSpec::name).collect();
                    CalibrationError::Option(format!("--fit: unknown rig parameter `{key}`; the rig keys are {}", known.join(", ")))
                })?;
                if !rig {
                    return Err(CalibrationError::Option(format!(
                        "--fit {key}: a rig key is fitted through the rig simulation; add --model rig (the quasi-static model has no rig)"
                    )));
                }
                if let Some((_, why)) = NOT_FITTABLE.iter().find(|(n, _)| *n == k) {
                    return Err(CalibrationError::Option(format!("--fit {key}: not a property of the rig to be fitted ({why})")));
                }
                Key::Rig(s)
            }
            (None, None) => {
                let known: Vec<String> = PARAMS.iter().map(ParamSpec::name).collect();
                return Err(CalibrationError::Option(format!(
                    "--fit: unknown parameter `{key}`; the keys are {}{}",
                    known.join(", "),
                    if rig { " and the rig.* keys" } else { "" }
                )));
            }
        };
        if out.iter().any(|e| e.key.name() == key) {
            return Err(CalibrationError::Option(format!("--fit: `{key}` is named twice")));
        }
        let range = found.range();
        let transform = Transform::for_range(range);
        let mut v = found.get(start, start_rig);
        if let (Key::Rig(_), Range::HalfOpen(lo, _)) = (found, range)
            && v == lo
        {
            v = lo + 0.05 * lo.abs().max(f64::MIN_POSITIVE);
        }
        if transform.forward(v).is_none() {
            return Err(CalibrationError::Option(format!(
                "--fit {key}: its start value {v} {} is on the boundary of its range ({}); start it inside",
                found.unit(),
                range.describe()
            )));
        }
        out.push(Extra { key: found, transform, start: v });
    }
    Ok(out)
}

impl std::fmt::Debug for Extra {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Extra({}, {:?}, start {})", self.key.name(), self.transform, self.start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_invert() {
        for t in [Transform::Identity, Transform::Log, Transform::Logit(0.0, 0.5)] {
            for v in [0.01, 0.2, 0.49] {
                let b = t.forward(v).unwrap();
                assert!((t.inverse(b) - v).abs() < 1e-15);
                let h = 1e-6;
                let fd = (t.inverse(b + h) - t.inverse(b - h)) / (2.0 * h);
                assert!((fd - t.slope(b)).abs() < 1e-8 * fd.abs().max(1.0));
            }
        }
    }

    #[test]
    fn unknown_and_boundary_keys_are_named() {
        let p = Params::default();
        let r = RigParams::default();
        let e = resolve(&["lubricant.viscosityy".into()], &p, &r, false).unwrap_err().to_string();
        assert!(e.contains("lubricant.viscosityy") && e.contains("lubricant.viscosity"), "{e}");
        let mut q = p;
        q.lubricant.roelands_index = 0.0;
        let e = resolve(&["lubricant.roelands_index".into()], &q, &r, false).unwrap_err().to_string();
        assert!(e.contains("roelands_index") && e.contains("start"), "{e}");
        assert_eq!(resolve(&[MU_C.into(), "lubricant.viscosity".into()], &p, &r, false).unwrap().len(), 1);
    }

    #[test]
    fn rig_keys_need_the_rig_model_and_start_inside() {
        let (p, r) = (Params::default(), RigParams::default());
        let e = resolve(&["rig.breakaway_factor".into()], &p, &r, false).unwrap_err().to_string();
        assert!(e.contains("rig.breakaway_factor") && e.contains("--model rig"), "{e}");
        let e = resolve(&["rig.breakaway_facter".into()], &p, &r, true).unwrap_err().to_string();
        assert!(e.contains("rig.breakaway_facter") && e.contains("rig.servo_time_constant"), "{e}");
        let e = resolve(&["rig.frequency".into()], &p, &r, true).unwrap_err().to_string();
        assert!(e.contains("rig.frequency") && e.contains("record"), "{e}");
        // The default breakaway factor is the closed lower bound 1: the fit starts at 1.05.
        let x = resolve(&["rig.breakaway_factor".into(), "rig.servo_time_constant".into()], &p, &r, true).unwrap();
        assert_eq!((x[0].start, x[1].start), (1.05, r.servo_time_constant));
    }
}
