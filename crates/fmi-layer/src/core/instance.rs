//! One FMU instance: life-cycle state, time, logger and the model behind the
//! [`Model`] trait. The methods here hold the standard's rules in safe Rust; the
//! `extern "C"` functions of the shims (each in its `api`) only convert pointers and
//! call them.
//!
//! Errors: a method returns a [`CallError`]; the caller logs it with status
//! `fmi2Error`. Argument errors (NULL arrays, unknown value references, a set on an
//! output, a non-finite input, a discontinuous communication point) leave the
//! instance exactly as it was, so the host may correct the call. A failure of the
//! model itself (invalid parameters at `fmi2ExitInitializationMode`, a step that
//! cannot be computed) moves the instance to the `error` state, from which the
//! standard allows getters, `fmi2SetFMUstate`, `fmi2Reset` and `fmi2FreeInstance`.

use super::logging::{Category, Logger};
use super::lookup::{Lookup, OutputCheck};
use smallvec::SmallVec;
use crate::error::{CallError, NotSettable, OutputBound, VariableName};
use super::model::Model;
use super::snapshot::Snapshot;
use super::state::State;
use super::types::Status;
use super::variables::{Causality, Kind, ModelInfo, Variability};

const TAG: u64 = 0x504a_464d_4932_4f4b;

/// Value references a get or set call holds inline (more spill to the heap).
const INLINE: usize = 8;

/// The outcome of an instance method: the status to return, or the error that the caller
/// logs and returns as `fmi2Error`.
pub type CallResult = Result<Status, CallError>;

pub use super::interface::Interface;

/// What the standards define differently for an instance, given by the shim that creates it:
/// the core names no standard, so every such difference is a value here, not a branch on a
/// version.
#[derive(Debug)]
pub struct Rules {
    /// Whether a variable of kind `variable` (the first argument) is read and written by the
    /// getter/setter of kind `requested` (the second).
    pub accessed_as: fn(Kind, Kind) -> bool,
    /// Why a directional derivative is refused when the model does not provide them (the
    /// message names the standard's capability attribute).
    pub no_directional_derivatives: &'static str,
}

/// One FMU instance, the object behind an `fmi2Component`/`fmi3Instance`.
pub struct Instance {
    tag: u64,
    /// The model's variable table, units and capabilities.
    pub info: &'static ModelInfo,
    /// The model's GUID (FMI 2.0) or instantiation token (FMI 3.0).
    pub guid: String,
    /// The instance name the host gave at instantiation, used in log messages.
    pub name: String,
    /// The host's logger with the categories currently switched on.
    pub logger: Logger,
    /// The life-cycle state, checked against each function's mask.
    pub state: State,
    /// End of the last communication step (or the start time).
    pub time: f64,
    /// The experiment's start time (`fmi2SetupExperiment`), in s; 0 if not set.
    pub start_time: f64,
    model: Box<dyn Model>,
    /// The model's outputs match its current inputs and parameters.
    outputs_current: bool,
    /// The interface the instance was created for.
    pub interface: Interface,
    /// The continuous states as (state index, derivative index), from
    /// [`ModelInfo::continuous_states`] (computed once: Model Exchange reads it every step).
    states: Vec<(usize, usize)>,
    /// The variable of each value reference and the outputs (computed once: every get, set
    /// and step reads them).
    lookup: Lookup,
    /// The rules of the standard whose functions created the instance (its type rules and
    /// messages).
    pub rules: &'static Rules,
}

impl Instance {
    /// A Co-Simulation instance of the model `info` under `rules`, every variable at its start
    /// value, in the `instantiated` state.
    pub fn new(info: &'static ModelInfo, name: &str, logger: Logger, rules: &'static Rules) -> Self {
        Instance {
            tag: TAG,
            info,
            guid: info.guid(),
            name: name.to_owned(),
            logger,
            state: State::Instantiated,
            time: 0.0,
            start_time: 0.0,
            model: (info.create)(),
            outputs_current: false,
            interface: Interface::CoSimulation,
            states: info.continuous_states(),
            lookup: Lookup::new(info),
            rules,
        }
    }

    /// An instance of `interface`, created by the functions of the standard whose `rules` are
    /// given.
    pub fn with_interface(info: &'static ModelInfo, name: &str, logger: Logger, interface: Interface, rules: &'static Rules) -> Self {
        let mut inst = Instance { interface, ..Instance::new(info, name, logger, rules) };
        inst.model.set_interface(interface);
        inst
    }

    /// False for memory that is not (or no longer) a live instance.
    pub fn is_live(&self) -> bool {
        self.tag == TAG
    }

    /// Clear the tag before the memory is released, so that a second free is noticed.
    pub fn kill(&mut self) {
        self.tag = 0;
    }

    /// Log `message` with `status`, in the category of that status.
    pub fn log(&self, status: Status, message: &str) {
        self.logger.log(status, Category::for_status(status), message);
    }

    /// Log a life-cycle `message` in category `logEvents` (status OK).
    pub fn event(&self, message: &str) {
        self.logger.log(Status::Ok, Category::Events, message);
    }

    fn lookup(&self, vr: u32) -> Result<usize, CallError> {
        self.lookup.index_of(vr).ok_or_else(|| CallError::UnknownValueReference { vr, model: self.info.model_name })
    }

    fn describe(&self, i: usize) -> VariableName {
        let v = &self.info.variables[i];
        VariableName { causality: v.causality.as_str(), name: v.name.clone(), value_reference: v.value_reference }
    }

    fn check_settable(&self, i: usize) -> Result<(), CallError> {
        let v = &self.info.variables[i];
        let why = match (v.causality, v.variability) {
            (Causality::Output, _) => NotSettable::Output,
            (Causality::Local, _) => NotSettable::Local,
            (Causality::Parameter, Variability::Fixed)
                if !matches!(self.state, State::Instantiated | State::InitializationMode) =>
            {
                NotSettable::Fixed { state: self.state.name() }
            }
            (Causality::Parameter, _) if self.state == State::ContinuousTimeMode => NotSettable::ParameterInContinuousTime,
            _ => return Ok(()),
        };
        Err(CallError::NotSettable { variable: self.describe(i), why })
    }

    /// The index of `vr`, which must be a variable of type `kind` (FMI 2.0: an Enumeration
    /// through the Integer functions; FMI 3.0: Integer as Int32, Enumeration as Int64).
    fn lookup_kind(&self, vr: u32, kind: Kind) -> Result<usize, CallError> {
        let i = self.lookup(vr)?;
        let k = self.info.variables[i].kind;
        if !(self.rules.accessed_as)(k, kind) {
            let article = if matches!(k, Kind::Integer | Kind::Enumeration(_)) { "n" } else { "" };
            return Err(CallError::WrongType { variable: self.describe(i), article, actual: k.as_str(), requested: kind.as_str() });
        }
        Ok(i)
    }

    /// `fmi2SetReal`/`Integer`/`Boolean` (values as f64, Booleans as 0.0/1.0): all
    /// values are checked before any is stored.
    pub fn set_values(&mut self, kind: Kind, vrs: &[u32], values: &[f64]) -> CallResult {
        let n = vrs.len().min(values.len());
        self.set_values_by(kind, &vrs[..n], |k| Ok(values[k]))
    }

    /// As [`Instance::set_values`], the k-th value given by `value(k)`, which may refuse it
    /// (a C value the type cannot hold). Every value is converted, then every variable looked
    /// up and checked, before any is stored. A host's few values are held inline: no call
    /// allocates.
    pub fn set_values_by(&mut self, kind: Kind, vrs: &[u32], value: impl Fn(usize) -> Result<f64, CallError>) -> CallResult {
        let vals = (0..vrs.len()).map(&value).collect::<Result<SmallVec<[f64; INLINE]>, _>>()?;
        let mut idx: SmallVec<[usize; INLINE]> = SmallVec::with_capacity(vrs.len());
        for (&vr, &x) in vrs.iter().zip(&vals) {
            let i = self.lookup_kind(vr, kind)?;
            self.check_settable(i)?;
            self.model.check_real(i, x)?;
            idx.push(i);
        }
        for (&i, &x) in idx.iter().zip(&vals) {
            self.model.set_real(i, x);
        }
        if !idx.is_empty() {
            self.outputs_current = false;
        }
        Ok(Status::Ok)
    }

    /// `fmi2SetReal`: set Real variables by value reference (see [`Instance::set_values`]).
    pub fn set_real(&mut self, vrs: &[u32], values: &[f64]) -> CallResult {
        self.set_values(Kind::Real, vrs, values)
    }

    fn update_outputs(&mut self) -> Result<(), CallError> {
        if !self.outputs_current {
            self.compute_outputs_unchecked()?;
            self.check_derivatives()?;
            self.outputs_current = true;
        }
        Ok(())
    }

    /// The model's outputs at its current inputs, if they are not current, not yet checked
    /// (the caller checks the derivatives, [`Instance::check_derivatives`], and marks them
    /// current; outputs are checked as they are read).
    fn compute_outputs_unchecked(&mut self) -> Result<(), CallError> {
        if !self.outputs_current {
            let r = self.model.compute_outputs();
            self.log_model_message();
            r?;
        }
        Ok(())
    }

    /// Every state derivative is finite: the host's integrator would take it.
    fn check_derivatives(&self) -> Result<(), CallError> {
        for &(_, d) in &self.states {
            let x = self.model.get_real(d);
            if !x.is_finite() {
                let v = &self.info.variables[d];
                return Err(CallError::DerivativeNotFinite { name: v.name.clone(), value: x, unit: v.unit_text() });
            }
        }
        Ok(())
    }

    /// An output's value `x` is finite and within the min/max its modelDescription declares:
    /// a model that computes anything else (e.g. a negative film thickness, found by fuzzing,
    /// fuzz/README.md) fails the read with a message naming the output, instead of handing
    /// the host a value the interface rules out. Outputs are checked as the host reads them
    /// (every value handed over is checked; what is not read is not computed,
    /// [`Model::prepare_read`]).
    fn check_output(&self, o: &OutputCheck, x: f64) -> Result<(), CallError> {
        let bound = if !x.is_finite() {
            Some(OutputBound::NotFinite)
        } else if let Some(m) = o.min.filter(|m| x < *m) {
            Some(OutputBound::BelowMin(m))
        } else {
            o.max.filter(|m| x > *m).map(OutputBound::AboveMax)
        };
        match bound {
            Some(bound) => {
                let v = &self.info.variables[o.index];
                Err(CallError::OutputOutOfRange { name: v.name.clone(), value: x, unit: v.unit_text(), bound })
            }
            None => Ok(()),
        }
    }

    /// The first output (in table order) out of range, every output computed: what a failed
    /// step names as its cause when the outputs already were.
    fn first_output_out_of_range(&mut self) -> Option<CallError> {
        let lookup = &self.lookup;
        for o in lookup.outputs() {
            self.model.prepare_read(o.index);
            if let Err(e) = self.check_output(o, self.model.get_real(o.index)) {
                return Some(e);
            }
        }
        None
    }

    /// Log what the model has to say ([`Model::take_message`]) under logEvents.
    fn log_model_message(&mut self) {
        if let Some(m) = self.model.take_message() {
            self.event(&m);
        }
    }

    /// `fmi2GetReal`/`Integer`/`Boolean` (values as f64): outputs (and local variables, such
    /// as state derivatives) are brought up to date with the inputs first.
    pub fn get_values(&mut self, kind: Kind, vrs: &[u32], values: &mut [f64]) -> CallResult {
        let n = vrs.len().min(values.len());
        self.get_values_by(kind, &vrs[..n], |k, x| values[k] = x)
    }

    /// As [`Instance::get_values`], the k-th value handed to `put(k, value)` (after every
    /// value reference was found and every output read checked: on an error nothing is put).
    /// A host's few values are held inline: no call allocates.
    pub fn get_values_by(&mut self, kind: Kind, vrs: &[u32], mut put: impl FnMut(usize, f64)) -> CallResult {
        // Each variable's index, and whether the model computes it (output or local).
        let mut idx: SmallVec<[(usize, bool); INLINE]> = SmallVec::with_capacity(vrs.len());
        for &vr in vrs {
            let i = self.lookup_kind(vr, kind)?;
            idx.push((i, matches!(self.info.variables[i].causality, Causality::Output | Causality::Local)));
        }
        if idx.iter().any(|&(_, computed)| computed) {
            self.update_outputs()?;
        }
        // Outputs the model deferred are computed, and every output read is checked, before
        // any value is put.
        let mut vals: SmallVec<[f64; INLINE]> = SmallVec::with_capacity(idx.len());
        for &(i, computed) in &idx {
            if computed {
                self.model.prepare_read(i);
            }
            let x = self.model.get_real(i);
            if let Some(o) = self.lookup.output(i) {
                self.check_output(o, x)?;
            }
            vals.push(x);
        }
        for (k, x) in vals.into_iter().enumerate() {
            put(k, x);
        }
        Ok(Status::Ok)
    }

    /// `fmi2GetReal`: read Real variables by value reference (see [`Instance::get_values`]).
    pub fn get_real(&mut self, vrs: &[u32], values: &mut [f64]) -> CallResult {
        self.get_values(Kind::Real, vrs, values)
    }

    /// Getters and setters of the types this layer's models do not have.
    pub fn reject_type(&self, type_name: &'static str, vrs: &[u32]) -> CallResult {
        match vrs.first() {
            None => Ok(Status::Ok),
            Some(&vr) => Err(match self.info.index_of(vr) {
                Some(i) => CallError::WrongType {
                    variable: self.describe(i),
                    article: "",
                    actual: self.info.variables[i].kind.as_str(),
                    requested: type_name,
                },
                None => CallError::NoVariablesOfType { vr, model: self.info.model_name, type_name },
            }),
        }
    }

    /// `fmi2SetupExperiment`: record the start time and the optional stop time, both in s;
    /// an error for a non-finite time or a stop time before the start.
    pub fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> CallResult {
        if !start.is_finite() {
            return Err(CallError::NotFinite { what: "startTime", value: start });
        }
        if let Some(stop) = stop
            && !(stop.is_finite() && stop >= start)
        {
            return Err(CallError::StopTime { stop, start });
        }
        self.start_time = start;
        self.time = start;
        Ok(Status::Ok)
    }

    /// `fmi2EnterInitializationMode`: to initialization mode.
    pub fn enter_initialization_mode(&mut self) -> CallResult {
        self.state = State::InitializationMode;
        self.event("entered initialization mode");
        Ok(Status::Ok)
    }

    /// Model Exchange: the host's solver time. The [`Model`] trait passes no time to the model
    /// under Model Exchange (its outputs and state derivatives depend on its states, inputs and
    /// parameters only), so this only records it; a time that is not finite, or a
    /// Co-Simulation instance, is refused.
    pub fn set_time(&mut self, t: f64) -> CallResult {
        self.require_model_exchange()?;
        if !t.is_finite() {
            return Err(CallError::NotFinite { what: "time", value: t });
        }
        self.time = t;
        Ok(Status::Ok)
    }

    /// Model Exchange: to event mode (`fmi2EnterEventMode`, `fmi3EnterEventMode`).
    pub fn enter_event_mode(&mut self) -> CallResult {
        self.require_model_exchange()?;
        self.state = State::EventMode;
        Ok(Status::Ok)
    }

    /// Model Exchange: to continuous-time mode.
    pub fn enter_continuous_time_mode(&mut self) -> CallResult {
        self.require_model_exchange()?;
        self.state = State::ContinuousTimeMode;
        Ok(Status::Ok)
    }

    /// Model Exchange: the outputs at the current states and inputs, checked against their
    /// ranges (what a completed integrator step or event iteration needs of the model).
    pub fn refresh_outputs(&mut self) -> Result<(), CallError> {
        self.update_outputs()
    }

    /// Model Exchange, at the end of an integrator step: the outputs at the current states and
    /// inputs, checked, then whether the model asks for a step event.
    pub fn completed_integrator_step(&mut self) -> Result<bool, CallError> {
        self.update_outputs()?;
        let due = self.model.completed_integrator_step();
        self.log_model_message();
        Ok(due?)
    }

    /// Model Exchange, the event iteration: the outputs current, then the model's discrete
    /// update; returns whether the continuous states changed (the outputs are then recomputed
    /// at the next getter).
    pub fn update_discrete_states(&mut self) -> Result<bool, CallError> {
        self.update_outputs()?;
        let changed = self.model.update_discrete_states();
        self.log_model_message();
        let changed = changed?;
        if changed {
            self.outputs_current = false;
            self.update_outputs()?;
        }
        Ok(changed)
    }

    /// An error unless the instance was created for Model Exchange (guards the Model Exchange
    /// functions).
    pub fn require_model_exchange(&self) -> Result<(), CallError> {
        if self.interface != Interface::ModelExchange {
            return Err(CallError::NotModelExchange);
        }
        Ok(())
    }

    /// Model Exchange arrays of event indicators: this layer's models have none, so the length
    /// must be 0.
    pub fn require_none(&self, what: &'static str, n: usize) -> Result<(), CallError> {
        self.require_model_exchange()?;
        if n != 0 {
            let model = self.info.model_name;
            return Err(if self.states.is_empty() {
                CallError::NoContinuousStates { what, n, model }
            } else {
                CallError::NoEventIndicators { what, n, model }
            });
        }
        Ok(())
    }

    /// The number of continuous states (`fmi3GetNumberOfContinuousStates`).
    pub fn number_of_continuous_states(&self) -> usize {
        self.states.len()
    }

    /// Model Exchange arrays of continuous states (FMI 2.0 §3.2.1, FMI 3.0 §3.2): the length
    /// `n` (the argument `what`) must be the number of states.
    pub fn require_state_count(&self, what: &'static str, n: usize) -> Result<(), CallError> {
        self.require_model_exchange()?;
        let expected = self.states.len();
        if n != expected {
            let model = self.info.model_name;
            return Err(if expected == 0 {
                CallError::NoContinuousStates { what, n, model }
            } else {
                CallError::StateCount { what, given: n, expected, model }
            });
        }
        Ok(())
    }

    /// `fmi2SetContinuousStates`/`fmi3SetContinuousStates` (`x` of the length
    /// [`Instance::require_state_count`] checked): every value passes [`Model::check_real`]
    /// before any is stored, so a refused call changes nothing; the outputs are stale afterwards.
    pub fn set_continuous_states(&mut self, x: &[f64]) -> CallResult {
        for (&(state, _), &value) in self.states.iter().zip(x) {
            self.model.check_real(state, value)?;
        }
        for (&(state, _), &value) in self.states.iter().zip(x) {
            self.model.set_real(state, value);
        }
        if !x.is_empty() {
            self.outputs_current = false;
        }
        Ok(Status::Ok)
    }

    /// `fmi2GetContinuousStates`/`fmi3GetContinuousStates`: the state vector into `out`.
    pub fn get_continuous_states(&self, out: &mut [f64]) -> CallResult {
        for (&(state, _), o) in self.states.iter().zip(out.iter_mut()) {
            *o = self.model.get_real(state);
        }
        Ok(Status::Ok)
    }

    /// `fmi2GetDerivatives`/`fmi3GetContinuousStateDerivatives`: the outputs (and derivatives)
    /// are brought up to date first, then the derivative of each state is written to `out`.
    pub fn get_derivatives(&mut self, out: &mut [f64]) -> CallResult {
        if !self.states.is_empty() {
            self.update_outputs()?;
        }
        for (&(_, der), o) in self.states.iter().zip(out.iter_mut()) {
            *o = self.model.get_real(der);
        }
        Ok(Status::Ok)
    }

    /// `fmi2GetNominalsOfContinuousStates`/`fmi3GetNominalsOfContinuousStates`: each state's
    /// declared `nominal`, or 1.0 (FMI 2.0 §3.2.2: 1.0 when the FMU has no better value).
    pub fn nominals_of_continuous_states(&self, out: &mut [f64]) -> CallResult {
        for (&(state, _), o) in self.states.iter().zip(out.iter_mut()) {
            *o = self.info.variables[state].nominal.unwrap_or(1.0);
        }
        Ok(Status::Ok)
    }

    /// Whether variable `i` is a continuous state.
    fn is_state(&self, i: usize) -> bool {
        self.states.iter().any(|&(x, _)| x == i)
    }

    /// `fmi2GetDirectionalDerivative` (FMI 2.0 §2.1.9) / `fmi3GetDirectionalDerivative` (FMI
    /// 3.0 §2.2.12): `out = J · seed` with `J[i][j]` the partial derivative of `unknowns[i]`
    /// with respect to `knowns[j]` at the current values ([`Model::jacobian`], after the
    /// outputs are brought up to date). Unknowns must be continuous Real outputs or, under
    /// Model Exchange, state derivatives; knowns continuous Real inputs or, under Model
    /// Exchange, continuous states (in initialization mode too: the standards also allow
    /// partials with respect to parameters there, which this layer refuses with this message).
    /// Refused without asking the model when the model does not declare the capability. An
    /// empty `unknowns` or `knowns` writes nothing. `seed` has the length of `knowns`, `out`
    /// that of `unknowns` (the callers check).
    pub fn directional_derivative(&mut self, unknowns: &[u32], knowns: &[u32], seed: &[f64], out: &mut [f64]) -> CallResult {
        if !self.info.directional_derivatives {
            return Err(CallError::Unsupported(self.rules.no_directional_derivatives));
        }
        let me = self.interface == Interface::ModelExchange;
        let continuous_real = |v: &super::variables::Variable| v.kind == Kind::Real && v.variability == Variability::Continuous;
        let mut ui = Vec::with_capacity(unknowns.len());
        for &vr in unknowns {
            let i = self.lookup(vr)?;
            let v = &self.info.variables[i];
            let ok = continuous_real(v) && (v.causality == Causality::Output || (me && v.derivative_of.is_some()));
            if !ok {
                let allowed = if me { "continuous Real outputs and state derivatives" } else { "continuous Real outputs" };
                return Err(CallError::NotAnUnknown { variable: self.describe(i), allowed });
            }
            ui.push(i);
        }
        let mut ki = Vec::with_capacity(knowns.len());
        for &vr in knowns {
            let i = self.lookup(vr)?;
            let v = &self.info.variables[i];
            let ok = continuous_real(v) && (v.causality == Causality::Input || (me && self.is_state(i)));
            if !ok {
                let allowed = if me {
                    "continuous Real inputs and continuous states (partials with respect to parameters are not provided)"
                } else {
                    "continuous Real inputs (partials with respect to parameters are not provided)"
                };
                return Err(CallError::NotAKnown { variable: self.describe(i), allowed });
            }
            ki.push(i);
        }
        if ui.is_empty() || ki.is_empty() {
            return Ok(Status::Ok);
        }
        self.update_outputs()?;
        let nk = ki.len();
        let mut jac = vec![0.0; ui.len() * nk];
        self.model.jacobian(&ui, &ki, &mut jac)?;
        if let Some(k) = jac.iter().position(|x| !x.is_finite()) {
            let (unknown, known) = (self.info.variables[ui[k / nk]].name.clone(), self.info.variables[ki[k % nk]].name.clone());
            return Err(CallError::PartialNotFinite { unknown, known, value: jac[k] });
        }
        for (row, o) in jac.chunks_exact(nk).zip(out.iter_mut()) {
            *o = row.iter().zip(seed).map(|(a, b)| a * b).sum();
        }
        Ok(Status::Ok)
    }

    /// `fmi2ExitInitializationMode`: the model validates its parameters and computes its first
    /// outputs; on success to step mode (Co-Simulation) or event mode (Model Exchange), on
    /// failure to the `error` state.
    pub fn exit_initialization_mode(&mut self) -> CallResult {
        let init = self.model.exit_initialization(self.start_time);
        self.log_model_message();
        let checked = init.map_err(CallError::Model).and_then(|()| {
            self.outputs_current = false;
            self.update_outputs()
        });
        if let Err(e) = checked {
            self.state = State::Error;
            return Err(e);
        }
        self.state = match self.interface {
            Interface::CoSimulation => State::StepComplete,
            Interface::ModelExchange => State::EventMode,
        };
        self.event(&format!("initialization done at t = {} s", self.time));
        Ok(Status::Ok)
    }

    /// `fmi2DoStep`: the step must be positive and continue the previous one.
    pub fn do_step(&mut self, t: f64, h: f64) -> CallResult {
        if !t.is_finite() {
            return Err(CallError::NotFinite { what: "currentCommunicationPoint", value: t });
        }
        if !(h.is_finite() && h > 0.0) {
            return Err(CallError::StepSize(h));
        }
        // An end that is not a finite number is refused before anything changes.
        if !(t + h).is_finite() {
            return Err(CallError::StepEnd { t, h });
        }
        // The host's time may differ from the sum of its steps by rounding only.
        let tol = 1e-6 * h + 16.0 * f64::EPSILON * t.abs().max(self.time.abs());
        if (t - self.time).abs() > tol {
            return Err(CallError::Discontinuous { t, last: self.time, tol });
        }
        // The outputs at the step's start (the inputs just set) are an intermediate the host
        // never reads; the outputs at its end are checked as the host reads them. When the
        // model's step fails, outputs that were already out of range are the cause named.
        let stepped = self.compute_outputs_unchecked().and_then(|()| match self.model.do_step(t, h) {
            Ok(()) => self.check_derivatives(),
            Err(e) => Err(self.check_derivatives().err().or_else(|| self.first_output_out_of_range()).unwrap_or(CallError::Model(e))),
        });
        self.log_model_message();
        if let Err(e) = stepped {
            self.state = State::Error;
            return Err(CallError::StepFailed { t, h, source: Box::new(e) });
        }
        self.outputs_current = true;
        self.time = t + h;
        Ok(Status::Ok)
    }

    /// `fmi2Terminate`: to the `terminated` state.
    pub fn terminate(&mut self) -> CallResult {
        self.state = State::Terminated;
        self.logger.flush_repeats();
        self.event(&format!("terminated at t = {} s", self.time));
        Ok(Status::Ok)
    }

    /// `fmi2Reset`: every variable back to its start value, time and start time 0, to the
    /// `instantiated` state.
    pub fn reset(&mut self) -> CallResult {
        self.logger.flush_repeats();
        self.model.set_start_values();
        self.model.set_interface(self.interface);
        self.state = State::Instantiated;
        self.time = 0.0;
        self.start_time = 0.0;
        self.outputs_current = false;
        self.event("reset to the start values");
        Ok(Status::Ok)
    }

    /// The current state as an FMU state object.
    pub fn snapshot(&self) -> Snapshot {
        let mut model = Vec::new();
        self.model.serialize(&mut model);
        Snapshot::new(&self.guid, self.state, self.time, self.start_time, model)
    }

    /// `fmi2SetFMUstate`: the model checks its part before anything changes.
    pub fn restore(&mut self, s: &Snapshot) -> CallResult {
        if s.guid != self.guid {
            return Err(CallError::ForeignState { state_guid: s.guid.clone(), guid: self.guid.clone() });
        }
        let me_state = matches!(s.state, State::EventMode | State::ContinuousTimeMode);
        let cs_state = matches!(s.state, State::StepComplete | State::StepFailed | State::StepCanceled);
        if (me_state && self.interface != Interface::ModelExchange) || (cs_state && self.interface != Interface::CoSimulation) {
            return Err(CallError::StateForInterface { state: s.state.name(), interface: self.interface });
        }
        self.model.deserialize(&s.model).map_err(CallError::StateRejected)?;
        self.state = s.state;
        self.time = s.time;
        self.start_time = s.start_time;
        self.outputs_current = false;
        self.event(&format!("FMU state restored: {} at t = {} s", s.state.name(), s.time));
        Ok(Status::Ok)
    }

    /// `fmi2DeSerializeFMUstate`: the container and the model part are both checked
    /// (the latter on a scratch model, so that this instance is not touched).
    pub fn decode_state(&self, bytes: &[u8]) -> Result<Snapshot, CallError> {
        let s = Snapshot::decode(bytes, &self.guid)?;
        let mut scratch = (self.info.create)();
        scratch.set_interface(self.interface);
        scratch.deserialize(&s.model).map_err(CallError::SerializedStateRejected)?;
        Ok(s)
    }
}
