//! The outputs of PinJoint at a set of values: the library's operating point and the friction
//! of the zero-velocity treatment ([`super::zero_velocity`]), for the model's steps
//! ([`super::model`]) and its directional derivatives ([`super::partials`]).

use super::variables::{Outputs, Values};
use super::zero_velocity::{band_friction, presliding_friction};
use fmi_layer::core::model::{ModelError, ModelResult};
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
/// ([`Evaluator::evaluate_complete`]); the FMI layer checks each output as the host reads it
/// (finite and within its declared min/max).
pub fn outputs(ev: &mut Evaluator, v: &Values, model: ZeroVelocityModel, delta: f64) -> ModelResult<(Outputs, bool)> {
    let (mut out, first) = outputs_deferred(ev, v, model, delta)?;
    derive(ev, &mut out);
    Ok((out, first))
}

/// As [`outputs`], but where a table or the boundary level answers, the operating point's
/// derived quantities ([`pinjoint::fidelity::evaluation::DERIVED_COLUMNS`]) are left for
/// [`derive()`] (`pending`): the torque, μ, film and load shares are there.
pub fn outputs_deferred(ev: &mut Evaluator, v: &Values, model: ZeroVelocityModel, delta: f64) -> ModelResult<(Outputs, bool)> {
    let (load, omega) = (v.load, v.omega);
    if load == 0.0 {
        return Ok((Outputs::default(), false));
    }
    ev.reset();
    let (op, derived, _, mut first) = ev.evaluate_deferred(load, omega).map_err(|e| ModelError::failed("", e))?;
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
    Ok((Outputs { point: Some(op), pending: !derived, friction }, first))
}

/// Compute the derived quantities `out` left pending ([`outputs_deferred`]), bit for bit
/// those of [`Evaluator::evaluate_complete`].
pub fn derive(ev: &Evaluator, out: &mut Outputs) {
    if out.pending {
        if let Some(op) = out.point.as_mut() {
            ev.derive(op);
        }
        out.pending = false;
    }
}
