//! The one trait through which a model plugs into the generic FMI 2.0 layer.
//!
//! The layer owns everything the standard prescribes (state machine, argument
//! checks, value-reference lookup, logging, FMU state format); a model only
//! stores values, computes its outputs and advances over a communication step.
//! Variables are addressed by their index in the model's [`ModelInfo::variables`](crate::fmi2::variables::ModelInfo::variables)
//! table (`super::variables::ModelInfo`), never by value reference.

use std::fmt;

/// Why a model refused a value, a state or a computation; the layer logs its
/// [`Display`](fmt::Display) form and returns `fmi2Error` / `fmi3Error`.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelError {
    /// A message built by the model (transitional: being replaced by typed variants).
    Message(String),
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::Message(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for ModelError {}

impl From<String> for ModelError {
    fn from(m: String) -> Self {
        ModelError::Message(m)
    }
}

impl From<ModelError> for String {
    fn from(e: ModelError) -> Self {
        e.to_string()
    }
}

/// A model error, reported through the logger with status `fmi2Error`.
pub type ModelResult<T> = Result<T, ModelError>;

/// A model behind the generic layer: it holds its variables (addressed by index in its
/// [`ModelInfo::variables`](crate::fmi2::variables::ModelInfo::variables) table), computes its outputs and advances over a step; every
/// FMI rule (states, value references, C types, logging) is the layer's.
pub trait Model {
    /// Restore every variable to its start value (called at instantiation and by `fmi2Reset`).
    fn set_start_values(&mut self);

    /// The current value of variable `index` (Integer and Boolean variables as f64,
    /// a Boolean as 0.0 or 1.0). Outputs are read after
    /// [`Model::compute_outputs`] has run for the current inputs.
    fn get_real(&self, index: usize) -> f64;

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

    /// Append the model's complete state (parameters, inputs, internal states) in a
    /// self-describing, versioned byte form of the model's own.
    fn serialize(&self, out: &mut Vec<u8>);

    /// Replace the state by one written by [`Model::serialize`]; reject anything
    /// else (wrong version, wrong length, values the model could never hold)
    /// without changing the model.
    fn deserialize(&mut self, bytes: &[u8]) -> ModelResult<()>;
}
