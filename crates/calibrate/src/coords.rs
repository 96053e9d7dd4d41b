//! The fit's coordinates: μ_c and the torque offset as they are (the model is linear in both),
//! every other parameter mapped to an unbounded coordinate from its range in the parameter
//! table (`pinjoint::params::PARAMS`): ln θ for θ > 0 (a positive parameter spans decades and
//! cannot cross zero), a logit for a bounded one.

use super::error::CalibrationError;
use pinjoint::params::{spec_by_name, ParamSpec, Range, PARAMS};
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
            Range::HalfOpen(lo, hi) | Range::OpenClosed(lo, hi) => Transform::Logit(lo, hi),
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

/// A model parameter fitted besides μ_c.
#[derive(Clone, Copy)]
pub struct Extra {
    /// The parameter's name, unit, default and bounds.
    pub spec: &'static ParamSpec,
    /// Map between the parameter's value and the unconstrained fit coordinate.
    pub transform: Transform,
}

/// Resolve `--fit` keys (μ_c may be named or not; it is always fitted). Unknown keys, repeats
/// and start values outside the transform's domain are errors naming the key.
pub fn resolve(keys: &[String], start: &Params) -> Result<Vec<Extra>, CalibrationError> {
    let mut out: Vec<Extra> = Vec::new();
    for key in keys {
        let key = key.trim();
        if key.is_empty() || key == MU_C {
            continue;
        }
        let spec = spec_by_name(key).ok_or_else(|| {
            let known: Vec<String> = PARAMS.iter().map(pinjoint::params::ParamSpec::name).collect();
            CalibrationError::Option(format!("--fit: unknown parameter `{key}`; the keys are {}", known.join(", ")))
        })?;
        if out.iter().any(|e| e.spec.name() == key) {
            return Err(CalibrationError::Option(format!("--fit: `{key}` is named twice")));
        }
        let transform = Transform::for_range(spec.range);
        let v = (spec.get)(start);
        if transform.forward(v).is_none() {
            return Err(CalibrationError::Option(format!(
                "--fit {key}: its start value {v} {} is on the boundary of its range ({}); start it inside",
                spec.unit,
                spec.range.describe()
            )));
        }
        out.push(Extra { spec, transform });
    }
    Ok(out)
}

impl std::fmt::Debug for Extra {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Extra({}, {:?})", self.spec.name(), self.transform)
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
        let e = resolve(&["lubricant.viscosityy".into()], &p).unwrap_err().to_string();
        assert!(e.contains("lubricant.viscosityy") && e.contains("lubricant.viscosity"), "{e}");
        let mut q = p;
        q.lubricant.roelands_index = 0.0;
        let e = resolve(&["lubricant.roelands_index".into()], &q).unwrap_err().to_string();
        assert!(e.contains("roelands_index") && e.contains("start"), "{e}");
        assert_eq!(resolve(&[MU_C.into(), "lubricant.viscosity".into()], &p).unwrap().len(), 1);
    }
}
