//! The one trait through which a model plugs into the generic FMI layer, for both standards
//! (FMI 2.0 and 3.0) and both interfaces: a model implements it once.
//!
//! The layer owns everything the standard prescribes (state machine, argument
//! checks, value-reference lookup, logging, FMU state format); a model only
//! stores values, computes its outputs and advances over a communication step.
//! Variables are addressed by their index in the model's [`ModelInfo::variables`](crate::core::variables::ModelInfo::variables)
//! table (`super::variables::ModelInfo`), never by value reference.

use std::error::Error;
use std::fmt;

/// Why a model refused a value, a state or a computation; the layer logs its
/// [`Display`](fmt::Display) form and returns `fmi2Error` / `fmi3Error`.
#[derive(Debug)]
pub enum ModelError {
    /// A value a variable cannot take, named with its causality, value (short round-trip
    /// form) and unit: `"{role} {name} = {value} {unit} {rule}"`, e.g. `input load = NaN N is
    /// invalid: it must be a finite number`.
    InvalidValue {
        /// `input`, `parameter`, or empty (a value read from a state).
        role: &'static str,
        /// The variable's name.
        name: String,
        /// The rejected value, in `unit`.
        value: f64,
        /// The value's unit as the message shows it (empty for none).
        unit: &'static str,
        /// What is wrong, as a predicate: `is not a finite number`, `is out of range: …`.
        rule: String,
    },
    /// A rejected serialized state: the reason (wrong version or count, a value no instance
    /// could hold, a truncated or over-long byte form).
    RejectedState(String),
    /// A computation of the model's library failed; `context` prefixes the library's own
    /// message (e.g. `parameter `, `state: `, `fidelity table: `).
    Failed {
        /// What was being done, written before the source's message.
        context: String,
        /// The library's typed error.
        source: Box<dyn Error + Send + Sync>,
    },
    /// A computed quantity that is not finite (an overflow): `what` names it with its value,
    /// unit and the inputs it came from.
    NotFinite(String),
    /// A capability the model does not implement (the message says which).
    Unsupported(&'static str),
}

impl ModelError {
    /// A [`ModelError::InvalidValue`].
    pub fn invalid(role: &'static str, name: impl Into<String>, value: f64, unit: &'static str, rule: impl Into<String>) -> Self {
        ModelError::InvalidValue { role, name: name.into(), value, unit, rule: rule.into() }
    }

    /// A [`ModelError::Failed`] with `context` before the library error's message.
    pub fn failed(context: impl Into<String>, source: impl Error + Send + Sync + 'static) -> Self {
        ModelError::Failed { context: context.into(), source: Box::new(source) }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::InvalidValue { role, name, value, unit, rule } => {
                if !role.is_empty() {
                    write!(f, "{role} ")?;
                }
                write!(f, "{name} = {}", super::logging::show(*value))?;
                if !unit.is_empty() {
                    write!(f, " {unit}")?;
                }
                write!(f, " {rule}")
            }
            ModelError::RejectedState(m) | ModelError::NotFinite(m) => f.write_str(m),
            ModelError::Unsupported(m) => f.write_str(m),
            ModelError::Failed { context, source } => write!(f, "{context}{source}"),
        }
    }
}

impl Error for ModelError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            ModelError::Failed { source, .. } => Some(source.as_ref()),
            _ => None,
        }
    }
}

/// A model error, reported through the logger with status `fmi2Error`.
pub type ModelResult<T> = Result<T, ModelError>;

/// A model behind the generic layer: it holds its variables (addressed by index in its
/// [`ModelInfo::variables`](crate::core::variables::ModelInfo::variables) table), computes its outputs and advances over a step; every
/// FMI rule (states, value references, C types, logging) is the layer's.
pub trait Model {
    /// Restore every variable to its start value (called at instantiation and by `fmi2Reset`).
    fn set_start_values(&mut self);

    /// The interface the host instantiated (called after creation and after every
    /// [`Model::set_start_values`]): a model with continuous states integrates them itself
    /// under Co-Simulation and leaves them to the host under Model Exchange. Default: ignored.
    fn set_interface(&mut self, interface: super::interface::Interface) {
        let _ = interface;
    }

    /// The current value of variable `index` (Integer and Boolean variables as f64,
    /// a Boolean as 0.0 or 1.0). Outputs are read after
    /// [`Model::compute_outputs`] has run for the current inputs, and after
    /// [`Model::prepare_read`] for that output.
    fn get_real(&self, index: usize) -> f64;

    /// The layer is about to read output (or local variable) `index` for the host: a model
    /// whose [`Model::compute_outputs`] leaves some outputs to be computed when they are read
    /// (what a host does not read, it does not pay for) computes them now. Default: nothing.
    fn prepare_read(&mut self, index: usize) {
        let _ = index;
    }

    /// Check a value before it is stored; the layer calls this for every element of
    /// an `fmi2SetReal` array before storing any, so a rejected call changes nothing.
    /// The message names the variable, the value and its unit.
    fn check_real(&self, index: usize, value: f64) -> ModelResult<()>;

    /// Store a value that passed [`Model::check_real`].
    fn set_real(&mut self, index: usize, value: f64);

    /// A message for the host's log (category logEvents), taken once; the layer asks after
    /// [`Model::exit_initialization`], [`Model::compute_outputs`] and [`Model::do_step`] (e.g. which fidelity
    /// level was built, a first evaluation outside its envelope).
    fn take_message(&mut self) -> Option<String> {
        None
    }

    /// Validate the parameters at `fmi2ExitInitializationMode`; `start_time` is the
    /// experiment's start time (`fmi2SetupExperiment`, 0 if it was not called).
    fn exit_initialization(&mut self, start_time: f64) -> ModelResult<()>;

    /// Recompute the outputs from the current inputs and parameters.
    fn compute_outputs(&mut self) -> ModelResult<()>;

    /// Advance from `time` over `step` (> 0) with the inputs held; outputs are current.
    fn do_step(&mut self, time: f64, step: f64) -> ModelResult<()>;

    /// Model Exchange, at `fmi2CompletedIntegratorStep` (outputs current): whether the model
    /// asks for an event (a step event: `enterEventMode`). Default: never. A model that asks
    /// sets [`ModelInfo::step_events`](crate::core::variables::ModelInfo::step_events).
    fn completed_integrator_step(&mut self) -> ModelResult<bool> {
        Ok(false)
    }

    /// Model Exchange, in event mode (`fmi2NewDiscreteStates`, `fmi3UpdateDiscreteStates`;
    /// outputs current): update the discrete states; returns whether the continuous states
    /// changed (`valuesOfContinuousStatesChanged`). Default: nothing to update.
    fn update_discrete_states(&mut self) -> ModelResult<bool> {
        Ok(false)
    }

    /// The partial derivatives of variables `unknowns` with respect to variables `knowns` at
    /// the current values: `out[i * knowns.len() + j] = ∂ variable unknowns[i] / ∂ variable
    /// knowns[j]` (indices into the variable table, row-major, `out.len() == unknowns.len() *
    /// knowns.len()`), each in the unit of the unknown per unit of the known.
    ///
    /// The layer calls it for `fmi2GetDirectionalDerivative` (FMI 2.0 §2.1.9) and
    /// `fmi3GetDirectionalDerivative` (FMI 3.0 §2.2.12), which return `J · seed`, only when
    /// [`ModelInfo::directional_derivatives`](crate::core::variables::ModelInfo::directional_derivatives)
    /// is true, after it has checked the value references and brought the outputs up to date
    /// ([`Model::compute_outputs`], as for a getter). Unknowns are outputs or (Model Exchange)
    /// state derivatives; knowns are inputs or (Model Exchange) continuous states. The default
    /// refuses: a model that declares the capability must implement it.
    fn jacobian(&mut self, unknowns: &[usize], knowns: &[usize], out: &mut [f64]) -> ModelResult<()> {
        let _ = (unknowns, knowns, out);
        Err(ModelError::Unsupported("directional derivatives are not provided by this model"))
    }

    /// Append the model's complete state (parameters, inputs, internal states) in a
    /// self-describing, versioned byte form of the model's own.
    fn serialize(&self, out: &mut Vec<u8>);

    /// Replace the state by one written by [`Model::serialize`]; reject anything
    /// else (wrong version, wrong length, values the model could never hold)
    /// without changing the model.
    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()>;
}

#[cfg(test)]
mod tests {
    use super::ModelError;

    #[test]
    fn invalid_values_name_role_quantity_short_value_and_unit() {
        let e = ModelError::invalid("input", "load", 1e308, "N", "is too large");
        assert_eq!(e.to_string(), "input load = 1e308 N is too large");
        let e = ModelError::invalid("", "fidelity", 0.5, "", "is not a code");
        assert_eq!(e.to_string(), "fidelity = 0.5 is not a code");
    }
}
