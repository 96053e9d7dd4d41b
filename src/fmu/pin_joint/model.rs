//! The PinJoint co-simulation model: library outputs at the held inputs, the
//! zero-velocity treatment of the torque, and the dissipated energy.

use super::variables::{self as var, Output, ANGLE, ANGULAR_VELOCITY, FIRST_OUTPUT, FIRST_PARAM, LOAD, SPEED_BAND};
use super::zero_speed::{check_band, friction_torque, DEFAULT_SPEED_BAND};
use crate::fmi2::bytes::{ByteReader, ByteWriter};
use crate::fmi2::logging::show;
use crate::fmi2::model::{Model, ModelResult};
use crate::params::PARAMS;
use crate::{Joint, Params};

/// Version of [`PinJointModel::serialize`]'s layout.
const STATE_VERSION: u8 = 1;
/// f64 values in the serialized state: parameters, band, three inputs, energy.
const STATE_VALUES: usize = PARAMS.len() + 1 + 3 + 1;

/// Every output but the energy, from one evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    pub torque: f64,
    pub friction_coefficient: f64,
    pub film_thickness: f64,
    pub lambda_ratio: f64,
    pub fluid_load_fraction: f64,
    pub asperity_load_fraction: f64,
    pub mean_pressure: f64,
    pub sommerfeld_number: f64,
    pub power_loss: f64,
}

impl Outputs {
    fn get(&self, o: Output) -> f64 {
        match o {
            Output::Torque => self.torque,
            Output::FrictionCoefficient => self.friction_coefficient,
            Output::FilmThickness => self.film_thickness,
            Output::LambdaRatio => self.lambda_ratio,
            Output::FluidLoadFraction => self.fluid_load_fraction,
            Output::AsperityLoadFraction => self.asperity_load_fraction,
            Output::MeanPressure => self.mean_pressure,
            Output::SommerfeldNumber => self.sommerfeld_number,
            Output::PowerLoss => self.power_loss,
            Output::DissipatedEnergy => unreachable!("the energy is a state"),
        }
    }
}

/// The outputs at (`load`, `omega`) with band ω_b = `band`. At zero load the joint
/// is unloaded and every output is 0. An error names the inputs when the library
/// rejects them or returns a non-finite value.
pub fn outputs(joint: &Joint, load: f64, omega: f64, band: f64) -> ModelResult<Outputs> {
    if load == 0.0 {
        return Ok(Outputs::default());
    }
    let op = joint.evaluate(load, omega).map_err(|e| e.to_string())?;
    let torque = friction_torque(joint, load, omega, band, &op).map_err(|e| e.to_string())?;
    let out = Outputs {
        torque,
        friction_coefficient: op.friction_coefficient,
        film_thickness: op.film_thickness,
        lambda_ratio: op.lambda_ratio,
        fluid_load_fraction: op.fluid_load_fraction,
        asperity_load_fraction: op.asperity_load_fraction,
        mean_pressure: op.mean_pressure,
        sommerfeld_number: op.sommerfeld_number,
        power_loss: (torque * omega).abs(),
    };
    for o in Output::ALL.iter().filter(|o| **o != Output::DissipatedEnergy) {
        let v = out.get(*o);
        if !v.is_finite() {
            let name = &super::INFO.variables[FIRST_OUTPUT + *o as usize].name;
            return Err(format!(
                "the model gives {name} = {} at load = {} N, angular_velocity = {} rad/s (outside its numerical range)",
                show(v),
                show(load),
                show(omega)
            ));
        }
        // The modelDescription promises min/max (e.g. film_thickness >= 0); an output
        // outside them is a model failure, not a value to pass on.
        let var = &super::INFO.variables[FIRST_OUTPUT + *o as usize];
        let below = var.min.is_some_and(|m| v < m);
        let above = var.max.is_some_and(|m| v > m);
        if below || above {
            return Err(format!(
                "the model gives {} = {} {}, {} its declared {} {}, at load = {} N, angular_velocity = {} rad/s: \
                 the parameters are outside the range in which the model is defined",
                var.name,
                show(v),
                var.unit.unwrap_or(""),
                if below { "below" } else { "above" },
                if below { "minimum" } else { "maximum" },
                show(if below { var.min.unwrap() } else { var.max.unwrap() }),
                show(load),
                show(omega)
            ));
        }
    }
    Ok(out)
}

#[derive(Debug, Clone)]
pub struct PinJointModel {
    params: Params,
    band: f64,
    angle: f64,
    omega: f64,
    load: f64,
    energy: f64,
    out: Outputs,
    /// Built from `params` on first use; dropped when a parameter changes.
    joint: Option<Joint>,
}

impl PinJointModel {
    pub fn new() -> Self {
        let mut m = PinJointModel {
            params: Params::default(),
            band: DEFAULT_SPEED_BAND,
            angle: 0.0,
            omega: 0.0,
            load: var::DEFAULT_LOAD,
            energy: 0.0,
            out: Outputs::default(),
            joint: None,
        };
        m.set_start_values();
        m
    }

    fn joint(&mut self) -> ModelResult<&Joint> {
        check_band(self.band)?;
        if self.joint.is_none() {
            self.joint = Some(Joint::new(&self.params).map_err(|e| e.to_string())?);
        }
        Ok(self.joint.as_ref().expect("just built"))
    }
}

impl Default for PinJointModel {
    fn default() -> Self {
        Self::new()
    }
}

impl Model for PinJointModel {
    fn set_start_values(&mut self) {
        self.params = Params::default();
        self.band = DEFAULT_SPEED_BAND;
        self.angle = 0.0;
        self.omega = 0.0;
        self.load = var::DEFAULT_LOAD;
        self.energy = 0.0;
        self.out = Outputs::default();
        self.joint = None;
    }

    fn get_real(&self, i: usize) -> f64 {
        match i {
            ANGLE => self.angle,
            ANGULAR_VELOCITY => self.omega,
            LOAD => self.load,
            SPEED_BAND => self.band,
            i if i >= FIRST_PARAM => (PARAMS[i - FIRST_PARAM].get)(&self.params),
            i => match Output::ALL[i - FIRST_OUTPUT] {
                Output::DissipatedEnergy => self.energy,
                o => self.out.get(o),
            },
        }
    }

    fn check_real(&self, i: usize, v: f64) -> ModelResult<()> {
        match i {
            ANGLE if !v.is_finite() => Err(format!("input angle = {} rad is not a finite number", show(v))),
            ANGULAR_VELOCITY if !v.is_finite() => Err(format!("input angular_velocity = {} rad/s is not a finite number", show(v))),
            LOAD if !(v.is_finite() && v >= 0.0) => {
                Err(format!("input load = {} N is invalid: the load is a magnitude, a finite number >= 0 N", show(v)))
            }
            // Parameters are checked together at fmi2ExitInitializationMode.
            _ => Ok(()),
        }
    }

    fn set_real(&mut self, i: usize, v: f64) {
        match i {
            ANGLE => self.angle = v,
            ANGULAR_VELOCITY => self.omega = v,
            LOAD => self.load = v,
            SPEED_BAND => self.band = v,
            i if i >= FIRST_PARAM => {
                (PARAMS[i - FIRST_PARAM].set)(&mut self.params, v);
                self.joint = None;
            }
            _ => unreachable!("the FMI layer never sets outputs"),
        }
    }

    fn exit_initialization(&mut self) -> ModelResult<()> {
        self.joint().map(|_| ())
    }

    fn compute_outputs(&mut self) -> ModelResult<()> {
        let (load, omega, band) = (self.load, self.omega, self.band);
        let out = outputs(self.joint()?, load, omega, band)?;
        self.out = out;
        Ok(())
    }

    fn do_step(&mut self, _time: f64, step: f64) -> ModelResult<()> {
        let e = self.energy + self.out.power_loss * step;
        if !e.is_finite() {
            return Err(format!("dissipated_energy overflows ({e} J)"));
        }
        self.energy = e;
        Ok(())
    }

    fn serialize(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter::default();
        w.u8(STATE_VERSION);
        w.u16(STATE_VALUES as u16);
        for s in PARAMS.iter() {
            w.f64((s.get)(&self.params));
        }
        for v in [self.band, self.angle, self.omega, self.load, self.energy] {
            w.f64(v);
        }
        out.extend_from_slice(&w.buf);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let mut r = ByteReader::new(bytes);
        let version = r.u8("PinJoint state version")?;
        if version != STATE_VERSION {
            return Err(format!("PinJoint state version {version}; this FMU reads version {STATE_VERSION}"));
        }
        let n = r.u16("value count")? as usize;
        if n != STATE_VALUES {
            return Err(format!("PinJoint state holds {n} values; version {STATE_VERSION} has {STATE_VALUES}"));
        }
        let mut params = Params::default();
        for s in PARAMS.iter() {
            (s.set)(&mut params, r.f64(&s.name())?);
        }
        let band = r.f64("zero_velocity.speed_band")?;
        let (angle, omega, load, energy) = (r.f64("angle")?, r.f64("angular_velocity")?, r.f64("load")?, r.f64("dissipated_energy")?);
        r.finish()?;
        for (i, v) in [(ANGLE, angle), (ANGULAR_VELOCITY, omega), (LOAD, load)] {
            self.check_real(i, v)?;
        }
        if !(energy.is_finite() && energy >= 0.0) {
            return Err(format!("dissipated_energy = {energy} J is not a finite number >= 0"));
        }
        *self = PinJointModel { params, band, angle, omega, load, energy, out: Outputs::default(), joint: None };
        Ok(())
    }
}
