//! The outputs of PinJoint at a set of values: the library's operating point and the friction
//! of the zero-velocity treatment ([`super::zero_velocity`]), for the model's steps
//! ([`super::model`]) and its directional derivatives ([`super::partials`]).

use super::variables::{Outputs, Values};
use super::zero_velocity::{band_friction, presliding_friction};
use fmi_layer::fmi2::model::{ModelError, ModelResult};
use pinjoint::fidelity::Evaluator;
use pinjoint::zero_velocity::modes::Mode;
use pinjoint::zero_velocity::ZeroVelocityModel;

/// The library's operating point at (`load`, `omega`) from `ev`, cold (no warm start): the
/// outputs are a function of the current inputs alone, bit-identical to
/// [`pinjoint::Joint::evaluate`] at fidelity full whatever the history (a host that rolls back
/// with get/set FMU state, or re-steps, gets the same numbers). Also says whether this was the
/// first evaluation outside the envelope.
pub fn operating_point(ev: &mut Evaluator, load: f64, omega: f64) -> ModelResult<(pinjoint::OperatingPoint, bool)> {
    ev.reset();
    let (op, _, first) = ev.evaluate_complete(load, omega).map_err(|e| ModelError::failed("", e))?;
    Ok((op, first))
}

/// The outputs at (`load`, `omega`): the library's operating point and the friction of the
/// zero-velocity `model`. Presliding: the presliding torque `tau` deflected by `delta` (rad, the
/// angle increment since the state was committed; 0 under Model Exchange). Band of width
/// `band`: outside it the library's torque exactly, inside it the band-edge torque ramped
/// linearly. At zero load the joint is unloaded and every output is 0. Also says whether this
/// call was the first to fall outside the envelope. Every quantity is computed once
/// ([`Evaluator::evaluate_complete`]); the outputs are checked once, by the FMI layer (finite and
/// within their declared min/max).
pub fn outputs(ev: &mut Evaluator, v: &Values, model: ZeroVelocityModel, delta: f64) -> ModelResult<(Outputs, bool)> {
    let (load, omega) = (v.load, v.omega);
    if load == 0.0 {
        return Ok((Outputs::default(), false));
    }
    let (op, mut first) = operating_point(ev, load, omega)?;
    let friction = match model {
        ZeroVelocityModel::Presliding => {
            let law = v.zv.law.at_step(v.step);
            let mode = Mode::from_code(v.mode).unwrap_or_default();
            presliding_friction(&law, mode, law.deflect(v.tau, delta, op.torque), omega, op.torque)
        }
        ZeroVelocityModel::Band => band_friction(omega, v.zv.band, op.torque, || {
            let (edge, f) = operating_point(ev, load, v.zv.band)?;
            first |= f;
            Ok(edge.torque)
        })?,
    };
    Ok((Outputs { point: Some(op), friction }, first))
}
