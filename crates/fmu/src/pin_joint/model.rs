//! The PinJoint co-simulation model: library outputs at the held inputs, the
//! zero-velocity treatment of the torque, and the dissipated energy. Every variable is
//! read, checked, stored and serialized through its row of [`TABLE`].

use super::variables::{Outputs, Values, STATE_VERSION, TABLE};
use super::zero_speed::check_band;
use crate::fidelity::{describe, envelope_text};
use crate::inputs::check_capacity;
use crate::table::rejected;
use fmi_layer::fmi2::bytes::{ByteReader, ByteWriter};
use fmi_layer::fmi2::logging::show;
use fmi_layer::fmi2::model::{Model, ModelError, ModelResult};
use fmi_layer::fmi2::variables::Causality;
use pinjoint::fidelity::Evaluator;
use pinjoint::Joint;

/// The outputs at (`load`, `omega`) with band ω_b = `band`, from `ev` at its fidelity. At
/// zero load the joint is unloaded and every output is 0. Inside the band the torque is the
/// band-edge torque ramped linearly ([`super::zero_speed`]). An error names the inputs when
/// the library rejects them or returns a non-finite value. Also returns whether this call
/// was the first to fall outside the envelope.
///
/// The full level is evaluated cold (no warm start): the solve starts from the joint's
/// deterministic start ([`pinjoint::Joint::cold_start`]), so the outputs are a function of the
/// current inputs alone, bit-identical to [`pinjoint::Joint::evaluate`], whatever the history
/// (a host that rolls back with get/set FMU state, or re-steps, gets the same numbers).
/// Every quantity is computed once ([`Evaluator::evaluate_complete`]); the outputs are
/// checked once, by the FMI layer (finite and within their declared min/max).
pub fn outputs(ev: &mut Evaluator, load: f64, omega: f64, band: f64) -> ModelResult<(Outputs, bool)> {
    if load == 0.0 {
        return Ok((Outputs::default(), false));
    }
    ev.reset();
    let (op, _, mut first) = ev.evaluate_complete(load, omega).map_err(|e| ModelError::failed("", e))?;
    let torque = if omega.abs() >= band {
        op.signed_torque()
    } else {
        ev.reset();
        let (edge, _, f) = ev.evaluate_complete(load, band).map_err(|e| ModelError::failed("", e))?;
        first |= f;
        -edge.torque * (omega / band)
    };
    Ok((Outputs { point: Some(op), torque, power_loss: (torque * omega).abs() }, first))
}

/// A PinJoint instance: the values of its variables and the evaluator built from them; it
/// implements the FMI layer's [`Model`].
#[derive(Debug, Clone, Default)]
pub struct PinJointModel {
    v: Values,
    /// Built from the parameters, the temperature input and the fidelity settings on first
    /// use (at exit of initialization); dropped when a parameter changes, moved to a new
    /// temperature input by [`Evaluator::set_temperature`].
    evaluator: Option<Evaluator>,
    /// For the host's log (fidelity chosen; first fallback; a validity excursion).
    message: Option<String>,
    /// Whether the inputs were outside the validity envelope at the last evaluation.
    validity: pinjoint::validity::Tracker,
}

impl PinJointModel {
    /// An instance at the start values of every variable (no evaluator built yet).
    pub fn new() -> Self {
        Self::default()
    }

    fn evaluator(&mut self) -> ModelResult<&mut Evaluator> {
        check_band(self.v.band)?;
        if let Some(ev) = self.evaluator.as_mut().filter(|e| e.temperature().to_bits() != self.v.temperature.to_bits()) {
            // A new temperature: the same evaluator moved there (bit for bit one built there;
            // at full a few logarithms, a table or boundary level is built again).
            ev.set_temperature(self.v.temperature).map_err(|e| ModelError::failed("", e))?;
        }
        if self.evaluator.is_none() {
            // Every parameter is checked as set, `lubricant.temperature` too (the input replaces it).
            self.v.params.validate().map_err(|e| ModelError::failed("", e))?;
            let params = self.effective_params();
            Joint::new(&params).map_err(|e| ModelError::failed("", e))?;
            let ev = self.v.fidelity.build(&params)?;
            self.message = Some(describe(&ev, ""));
            self.evaluator = Some(ev);
        }
        Ok(self.evaluator.as_mut().expect("just built"))
    }

    /// The parameters with the lubricant temperature taken from the `temperature` input.
    /// At the default input (293.15 K = the default reference) they equal the parameters,
    /// so the outputs are exactly the paper model's.
    fn effective_params(&self) -> pinjoint::Params {
        let mut p = self.v.params;
        p.lubricant.temperature = self.v.temperature;
        p
    }

    /// The evaluator in use (after initialization).
    pub fn current_evaluator(&self) -> Option<&Evaluator> {
        self.evaluator.as_ref()
    }
}

impl Model for PinJointModel {
    fn set_start_values(&mut self) {
        *self = PinJointModel::new();
    }

    fn get_real(&self, i: usize) -> f64 {
        TABLE.get(&self.v, i)
    }

    fn check_real(&self, i: usize, x: f64) -> ModelResult<()> {
        // Beyond the asperity model's capacity the load is refused here, leaving the
        // instance and its outputs as they were.
        TABLE.check_input(i, x, self.evaluator.as_ref().map(|e| e.joint().capacity()))
    }

    fn set_real(&mut self, i: usize, x: f64) {
        // A parameter drops the evaluator (a new temperature input is seen at next use).
        if TABLE.set(&mut self.v, i, x).causality == Causality::Parameter {
            self.evaluator = None;
        }
    }

    fn take_message(&mut self) -> Option<String> {
        self.message.take()
    }

    fn exit_initialization(&mut self, _start_time: f64) -> ModelResult<()> {
        self.evaluator().map(|_| ())
    }

    fn compute_outputs(&mut self) -> ModelResult<()> {
        let (load, omega, band) = (self.v.load, self.v.omega, self.v.band);
        let (out, first_fallback) = outputs(self.evaluator()?, load, omega, band)?;
        if first_fallback {
            let ev = self.evaluator.as_ref().expect("built above");
            self.message = Some(format!(
                "fidelity {}: load = {} N, angular_velocity = {} rad/s is outside the envelope ({}); \
                 the full solve answers there (said once)",
                ev.chosen(),
                show(load),
                show(omega),
                envelope_text(ev.envelope())
            ));
        }
        self.v.out = out;
        let v = super::variables::validity(&self.v);
        let s = &self.v;
        let excursion = || pinjoint::validity::excursion(s.load, s.omega.abs() * s.params.geometry.pin_radius, s.temperature);
        crate::validity::note(&mut self.validity, v, excursion, "", &mut self.message);
        Ok(())
    }

    fn do_step(&mut self, _time: f64, step: f64) -> ModelResult<()> {
        let e = self.v.energy + self.v.out.power_loss * step;
        if !e.is_finite() {
            return Err(ModelError::NotFinite(format!("dissipated_energy overflows ({e} J)")));
        }
        self.v.energy = e;
        Ok(())
    }

    fn serialize(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter::default();
        TABLE.write(STATE_VERSION, &self.v, &mut w);
        out.extend_from_slice(&w.buf);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let mut v = Values::default();
        let mut r = ByteReader::new(bytes);
        TABLE.read("PinJoint", STATE_VERSION, &mut r, &mut v)?;
        r.finish().map_err(rejected)?;
        // Every value passed its setter's check; now those of fmi2ExitInitializationMode
        // (parameters, band, fidelity settings, load capacity of the state's own joint),
        // before anything of this instance changes.
        let joint = Joint::new(&v.params).map_err(|e| ModelError::failed("state: ", e))?;
        check_band(v.band)?;
        v.fidelity.validate()?;
        check_capacity(v.load, joint.capacity())?;
        // The same parameters keep the built evaluator (a table is not rebuilt on every restore).
        let same = v.params == self.v.params && v.fidelity == self.v.fidelity && v.band == self.v.band;
        let evaluator = if same { self.evaluator.take() } else { None };
        *self = PinJointModel { v, evaluator, message: None, validity: self.validity };
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::error::Error;

    /// A parameter the library rejects: the host sees the library's message, and the
    /// error carries the library's typed error as its source.
    #[test]
    fn a_rejected_parameter_carries_the_library_error() {
        let mut m = PinJointModel::new();
        m.set_real(TABLE.index("geometry.pin_radius").unwrap(), -0.028);
        let e = m.exit_initialization(0.0).unwrap_err();
        assert!(e.to_string().starts_with("parameter geometry.pin_radius = -0.028 m "), "{e}");
        let source = e.source().and_then(|s| s.downcast_ref::<pinjoint::ParamError>());
        assert!(matches!(source, Some(pinjoint::ParamError::OutOfRange { .. })), "{source:?}");
    }

    /// A state with another layout version is rejected by name, nothing changed.
    #[test]
    fn a_foreign_state_is_rejected() {
        let mut m = PinJointModel::new();
        let mut bytes = Vec::new();
        m.serialize(&mut bytes);
        bytes[0] = 9;
        let e = m.deserialize(&bytes).unwrap_err();
        assert!(matches!(e, ModelError::RejectedState(_)));
        assert_eq!(e.to_string(), "PinJoint state version 9; this FMU reads version 4");
        bytes[0] = STATE_VERSION;
        m.deserialize(&bytes).unwrap();
    }
}
