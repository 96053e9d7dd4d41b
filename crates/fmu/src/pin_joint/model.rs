//! The PinJoint co-simulation model: library outputs at the held inputs, the
//! zero-velocity treatment of the torque, and the dissipated energy.

use super::variables::{
    self as var, fidelity_of_code, Output, ANGLE, ANGULAR_VELOCITY, ENVELOPE_LOAD_MIN, ENVELOPE_SPEED_MAX, FIDELITY, FIRST_OUTPUT,
    FIRST_PARAM, LOAD, SPEED_BAND, TEMPERATURE, TOLERANCE,
};
use super::zero_speed::{check_band, DEFAULT_SPEED_BAND};
use pinjoint::fidelity::Evaluator;
use fmi_layer::fmi2::bytes::{ByteReader, ByteWriter};
use fmi_layer::fmi2::logging::show;
use fmi_layer::fmi2::model::{Model, ModelResult};
use pinjoint::params::PARAMS;
use pinjoint::{Joint, Params};

/// Version of [`PinJointModel::serialize`]'s layout (4: 26 parameters and the temperature input).
const STATE_VERSION: u8 = 4;
/// f64 values in the serialized state: parameters, band, three inputs, energy, fidelity code,
/// tolerance, envelope, temperature input. (The outputs depend on the current inputs only: no
/// solver history.)
const STATE_VALUES: usize = PARAMS.len() + 1 + 3 + 1 + 2 + 4 + 1;

/// Every output but the energy, from one evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// Friction torque on the pin (N·m), -sign(ω) μ R P_T (eq. 11), ramped inside the band.
    pub torque: f64,
    /// Friction coefficient μ (dimensionless, eq. 10).
    pub friction_coefficient: f64,
    /// Central film thickness h_c (m).
    pub film_thickness: f64,
    /// Lambda ratio h_c/√(σ² + σ_b²) (dimensionless, eq. 21).
    pub lambda_ratio: f64,
    /// Share of the load carried by the film, 1/γ₁ (dimensionless, eq. 9).
    pub fluid_load_fraction: f64,
    /// Share of the load carried by the asperities, 1/γ₂ (dimensionless, eq. 9).
    pub asperity_load_fraction: f64,
    /// Hertz mean contact pressure p_m (Pa, eq. 6).
    pub mean_pressure: f64,
    /// Sommerfeld number S (dimensionless, eq. 20).
    pub sommerfeld_number: f64,
    /// Frictional power loss |torque · ω| (W).
    pub power_loss: f64,
    /// Minimum film thickness h_min (m; extension beyond the paper).
    pub min_film_thickness: f64,
    /// Lambda ratio from the minimum film, h_min/√(σ² + σ_b²) (dimensionless).
    pub min_lambda_ratio: f64,
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
            Output::MinFilmThickness => self.min_film_thickness,
            Output::MinLambdaRatio => self.min_lambda_ratio,
            Output::DissipatedEnergy => unreachable!("the energy is a state"),
        }
    }
}

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
    let (op, _, mut first) = ev.evaluate_complete(load, omega).map_err(|e| e.to_string())?;
    let torque = if omega.abs() >= band {
        op.signed_torque()
    } else {
        ev.reset();
        let (edge, _, f) = ev.evaluate_complete(load, band).map_err(|e| e.to_string())?;
        first |= f;
        -edge.torque * (omega / band)
    };
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
        min_film_thickness: op.min_film_thickness,
        min_lambda_ratio: op.min_lambda_ratio,
    };
    Ok((out, first))
}

/// The fidelity settings of the FMU: the `fidelity` code, `tolerance` and the envelope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FidelitySettings {
    /// Integer code of the `fidelity` parameter: 0 full, 1 table, 2 boundary, 3 auto.
    pub code: i32,
    /// The `tolerance` parameter: the relative error a table level may have against full.
    pub tolerance: f64,
    /// load_min, load_max (N), speed_min, speed_max (rad/s).
    pub envelope: [f64; 4],
}

impl Default for FidelitySettings {
    fn default() -> Self {
        Self { code: var::DEFAULT_FIDELITY, tolerance: var::DEFAULT_TOLERANCE, envelope: var::DEFAULT_ENVELOPE }
    }
}

impl FidelitySettings {
    /// Build the evaluator; errors name the parameter, its value and unit.
    pub fn build(&self, params: &Params) -> ModelResult<Evaluator> {
        let level = fidelity_of_code(self.code).ok_or_else(|| {
            format!("parameter fidelity = {} is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)", self.code)
        })?;
        let env = crate::envelope_from_parameters(self.envelope)?;
        Ok(Evaluator::new(params, level, self.tolerance, env).map_err(|e| format!("parameter {e}"))?)
    }
}

/// What the log says about a built evaluator: the level (what auto picked) and its bound.
fn describe(ev: &Evaluator) -> String {
    let e = ev.envelope();
    format!(
        "fidelity {} -> {}: measured error bound {:e} (tolerance {:e}) over load {}..{} N, |omega| {}..{} rad/s",
        ev.requested(),
        ev.chosen(),
        ev.error_bound(),
        ev.tolerance(),
        e.load_min,
        e.load_max,
        e.speed_min,
        e.speed_max
    )
}

/// A PinJoint instance: the parameters, the held inputs, the dissipated energy and the
/// evaluator built from them; it implements the FMI layer's [`Model`].
#[derive(Debug, Clone)]
pub struct PinJointModel {
    params: Params,
    band: f64,
    angle: f64,
    omega: f64,
    load: f64,
    /// The `temperature` input (K): the lubricant temperature the evaluator is built with.
    temperature: f64,
    energy: f64,
    out: Outputs,
    fidelity: FidelitySettings,
    /// Built from `params` and `fidelity` on first use (at exit of initialization); dropped
    /// when a parameter changes.
    evaluator: Option<Evaluator>,
    /// For the host's log (fidelity chosen; first fallback).
    message: Option<String>,
}

impl PinJointModel {
    /// An instance at the start values of every variable (no evaluator built yet).
    pub fn new() -> Self {
        let mut m = PinJointModel {
            params: Params::default(),
            band: DEFAULT_SPEED_BAND,
            angle: 0.0,
            omega: 0.0,
            load: var::DEFAULT_LOAD,
            temperature: pinjoint::params::DEFAULT_TEMPERATURE,
            energy: 0.0,
            out: Outputs::default(),
            fidelity: FidelitySettings::default(),
            evaluator: None,
            message: None,
        };
        m.set_start_values();
        m
    }

    fn evaluator(&mut self) -> ModelResult<&mut Evaluator> {
        check_band(self.band)?;
        if self.evaluator.is_none() {
            // Every parameter is checked as set, `lubricant.temperature` too (the input replaces it).
            self.params.validate().map_err(|e| e.to_string())?;
            let params = self.effective_params();
            Joint::new(&params).map_err(|e| e.to_string())?;
            let ev = self.fidelity.build(&params)?;
            self.message = Some(describe(&ev));
            self.evaluator = Some(ev);
        }
        Ok(self.evaluator.as_mut().expect("just built"))
    }

    /// The parameters with the lubricant temperature taken from the `temperature` input.
    /// At the default input (293.15 K = the default reference) they equal the parameters,
    /// so the outputs are exactly the paper model's.
    fn effective_params(&self) -> Params {
        let mut p = self.params;
        p.lubricant.temperature = self.temperature;
        p
    }

    /// The evaluator in use (after initialization).
    pub fn current_evaluator(&self) -> Option<&Evaluator> {
        self.evaluator.as_ref()
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
        self.temperature = pinjoint::params::DEFAULT_TEMPERATURE;
        self.energy = 0.0;
        self.out = Outputs::default();
        self.fidelity = FidelitySettings::default();
        self.evaluator = None;
        self.message = None;
    }

    fn get_real(&self, i: usize) -> f64 {
        match i {
            ANGLE => self.angle,
            ANGULAR_VELOCITY => self.omega,
            LOAD => self.load,
            TEMPERATURE => self.temperature,
            SPEED_BAND => self.band,
            FIDELITY => f64::from(self.fidelity.code),
            TOLERANCE => self.fidelity.tolerance,
            i if (ENVELOPE_LOAD_MIN..=ENVELOPE_SPEED_MAX).contains(&i) => self.fidelity.envelope[i - ENVELOPE_LOAD_MIN],
            i if i >= FIRST_PARAM => (PARAMS[i - FIRST_PARAM].get)(&self.params),
            i => match Output::ALL[i - FIRST_OUTPUT] {
                Output::DissipatedEnergy => self.energy,
                o => self.out.get(o),
            },
        }
    }

    fn check_real(&self, i: usize, v: f64) -> ModelResult<()> {
        match i {
            ANGLE if !v.is_finite() => Err(format!("input angle = {} rad is not a finite number", show(v)).into()),
            ANGULAR_VELOCITY if !v.is_finite() => Err(format!("input angular_velocity = {} rad/s is not a finite number", show(v)).into()),
            LOAD if !v.is_finite() => Err(format!(
                "input load = {} N is invalid: it must be a finite number (a negative value is taken as its magnitude)",
                show(v)
            ).into()),
            // Beyond the asperity model's capacity (pinjoint::Joint::capacity) the load is
            // refused here, leaving the instance and its outputs as they were.
            LOAD if self.evaluator.as_ref().is_some_and(|e| v.abs() >= e.joint().capacity()) => Err(format!(
                "input load = {} N is beyond the asperity model's capacity of {:.6e} N for these parameters",
                show(v),
                self.evaluator.as_ref().map_or(f64::NAN, |e| e.joint().capacity())
            ).into()),
            TEMPERATURE if !(v > pinjoint::params::MIN_TEMPERATURE && v <= pinjoint::params::MAX_TEMPERATURE) => Err(format!(
                "input temperature = {} K is out of range: it must be in ({}, {}] K",
                show(v),
                pinjoint::params::MIN_TEMPERATURE,
                pinjoint::params::MAX_TEMPERATURE
            ).into()),
            FIDELITY if fidelity_of_code(v as i32).is_none() || v.fract() != 0.0 => Err(format!(
                "parameter fidelity = {} is out of range: it must be 0 (full), 1 (table), 2 (boundary) or 3 (auto)",
                show(v)
            ).into()),
            // Parameters are checked together at fmi2ExitInitializationMode.
            _ => Ok(()),
        }
    }

    fn set_real(&mut self, i: usize, v: f64) {
        match i {
            ANGLE => self.angle = v,
            ANGULAR_VELOCITY => self.omega = v,
            LOAD => self.load = v,
            TEMPERATURE => {
                // A new temperature is a new lubricant: rebuild the evaluator (on next use).
                if v.to_bits() != self.temperature.to_bits() {
                    self.evaluator = None;
                }
                self.temperature = v;
            }
            SPEED_BAND => self.band = v,
            FIDELITY => {
                self.fidelity.code = v as i32;
                self.evaluator = None;
            }
            TOLERANCE => {
                self.fidelity.tolerance = v;
                self.evaluator = None;
            }
            i if (ENVELOPE_LOAD_MIN..=ENVELOPE_SPEED_MAX).contains(&i) => {
                self.fidelity.envelope[i - ENVELOPE_LOAD_MIN] = v;
                self.evaluator = None;
            }
            i if i >= FIRST_PARAM => {
                (PARAMS[i - FIRST_PARAM].set)(&mut self.params, v);
                self.evaluator = None;
            }
            _ => unreachable!("the FMI layer never sets outputs"),
        }
    }

    fn take_message(&mut self) -> Option<String> {
        self.message.take()
    }

    fn exit_initialization(&mut self, _start_time: f64) -> ModelResult<()> {
        self.evaluator().map(|_| ())
    }

    fn compute_outputs(&mut self) -> ModelResult<()> {
        let (load, omega, band) = (self.load, self.omega, self.band);
        let (out, first_fallback) = outputs(self.evaluator()?, load, omega, band)?;
        if first_fallback {
            let ev = self.evaluator.as_ref().expect("built above");
            let e = ev.envelope();
            self.message = Some(format!(
                "fidelity {}: load = {} N, angular_velocity = {} rad/s is outside the envelope (load {}..{} N, |omega| {}..{} rad/s); \
                 the full solve answers there (said once)",
                ev.chosen(),
                show(load),
                show(omega),
                e.load_min,
                e.load_max,
                e.speed_min,
                e.speed_max
            ));
        }
        self.out = out;
        Ok(())
    }

    fn do_step(&mut self, _time: f64, step: f64) -> ModelResult<()> {
        let e = self.energy + self.out.power_loss * step;
        if !e.is_finite() {
            return Err(format!("dissipated_energy overflows ({e} J)").into());
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
        let f = &self.fidelity;
        for v in [self.band, self.angle, self.omega, self.load, self.energy, f64::from(f.code), f.tolerance] {
            w.f64(v);
        }
        for v in f.envelope {
            w.f64(v);
        }
        w.f64(self.temperature);
        out.extend_from_slice(&w.buf);
    }

    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()> {
        let mut r = ByteReader::new(bytes);
        let version = r.u8("PinJoint state version")?;
        if version != STATE_VERSION {
            return Err(format!("PinJoint state version {version}; this FMU reads version {STATE_VERSION}").into());
        }
        let n = r.u16("value count")? as usize;
        if n != STATE_VALUES {
            return Err(format!("PinJoint state holds {n} values; version {STATE_VERSION} has {STATE_VALUES}").into());
        }
        let mut params = Params::default();
        for s in PARAMS.iter() {
            (s.set)(&mut params, r.f64(&s.name())?);
        }
        let band = r.f64("zero_velocity.speed_band")?;
        let (angle, omega, load, energy) = (r.f64("angle")?, r.f64("angular_velocity")?, r.f64("load")?, r.f64("dissipated_energy")?);
        let code = r.f64("fidelity")?;
        let tolerance = r.f64("tolerance")?;
        let mut envelope = [0.0; 4];
        for (k, name) in ["envelope.load_min", "envelope.load_max", "envelope.speed_min", "envelope.speed_max"].iter().enumerate() {
            envelope[k] = r.f64(name)?;
        }
        if code.fract() != 0.0 || fidelity_of_code(code as i32).is_none() {
            return Err(format!("fidelity = {code} in the state is not a fidelity code (0..3)").into());
        }
        let temperature = r.f64("temperature")?;
        let fidelity = FidelitySettings { code: code as i32, tolerance, envelope };
        r.finish()?;
        // Every value passes the checks of the setters and of fmi2ExitInitializationMode
        // (parameters, band, fidelity settings, load capacity of the state's own joint)
        // before anything of this instance changes.
        let joint = Joint::new(&params).map_err(|e| format!("state: {e}"))?;
        check_band(band)?;
        pinjoint::fidelity::validate_tolerance(tolerance).map_err(|e| format!("state: parameter {e}"))?;
        crate::envelope_from_parameters(envelope)?;
        for (i, v) in [(ANGLE, angle), (ANGULAR_VELOCITY, omega), (LOAD, load), (TEMPERATURE, temperature)] {
            self.check_real(i, v)?;
        }
        let capacity = joint.capacity();
        if load.abs() >= capacity {
            return Err(format!("state: load = {} N is beyond the asperity model's capacity of {} N", show(load), show(capacity)).into());
        }
        if !(energy.is_finite() && energy >= 0.0) {
            return Err(format!("dissipated_energy = {} J is not a finite number >= 0", show(energy)).into());
        }
        // The same parameters keep the built evaluator (a table is not rebuilt on every restore).
        let same = params == self.params && fidelity == self.fidelity && band == self.band && temperature.to_bits() == self.temperature.to_bits();
        let evaluator = if same { self.evaluator.take() } else { None };
        *self = PinJointModel {
            params,
            band,
            angle,
            omega,
            load,
            temperature,
            energy,
            out: Outputs::default(),
            fidelity,
            evaluator,
            message: None,
        };
        Ok(())
    }
}
