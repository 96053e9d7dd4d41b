//! The models this crate packages as FMUs, each plugged into the generic
//! [`crate::fmi2`] layer. `fmi2Instantiate` finds a model here by its GUID.
//! `PassThrough` is a benchmark baseline only (`pinjoint bench`).

pub mod pass_through;
pub mod pin_joint;
pub mod pin_joint_rig;
pub mod platforms_doc;

use crate::fmi2::variables::ModelInfo;

/// Every model the shared library serves.
pub fn registry() -> Vec<&'static ModelInfo> {
    vec![&*pin_joint::INFO, &*pin_joint_rig::INFO, &*pass_through::INFO]
}

/// The envelope parameters of both FMUs (`envelope.*`), with their units.
pub const ENVELOPE_NAMES: [(&str, &str); 4] =
    [("envelope.load_min", "N"), ("envelope.load_max", "N"), ("envelope.speed_min", "rad/s"), ("envelope.speed_max", "rad/s")];

/// The envelope from the four `envelope.*` parameter values; an error names the parameter,
/// its value and unit.
pub fn envelope_from_parameters(values: [f64; 4]) -> Result<crate::fidelity::Envelope, String> {
    use crate::fmi2::logging::show;
    for (k, (name, unit)) in ENVELOPE_NAMES.iter().enumerate() {
        let x = values[k];
        if !(x.is_finite() && x > 0.0) {
            return Err(format!("parameter {name} = {} {unit} is invalid: it must be a finite number > 0 {unit}", show(x)));
        }
    }
    for k in [0, 2] {
        let ((lo_name, unit), (hi_name, _)) = (ENVELOPE_NAMES[k], ENVELOPE_NAMES[k + 1]);
        let (lo, hi) = (values[k], values[k + 1]);
        if lo >= hi {
            return Err(format!("parameter {lo_name} = {} {unit} is invalid: it must be below {hi_name} = {} {unit}", show(lo), show(hi)));
        }
    }
    let [a, b, c, d] = values;
    crate::fidelity::Envelope::new(a, b, c, d).map_err(|e| format!("parameter {e}"))
}
