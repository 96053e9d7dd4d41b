//! The errors of the FMI layer, one type per boundary:
//!
//! - [`CallError`]: why an exported function returns `fmi2Error`/`fmi3Error` (an unknown value
//!   reference, a variable not settable in this state, a wrong count or a NULL argument, a
//!   time the standard rules out, an FMU state that does not fit, the model's own
//!   [`ModelError`]). The guard logs its [`Display`](std::fmt::Display) form after the
//!   function's name; the texts are those hosts and tests have always seen.
//! - [`StateFormatError`]: a serialized FMU state (or a model's part of one) that is not a
//!   well-formed byte stream: what was being read and where.
//! - [`XmlError`]: a model table from which no valid modelDescription.xml can be written.

use crate::core::interface::Interface;
use crate::core::model::ModelError;
use crate::core::types::StatusKind;
use crate::fmt::Num;
use std::ffi::c_int;
use std::fmt;

/// A variable as messages name it: `input 'load' (value reference 3)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VariableName {
    /// The causality attribute, e.g. `input`.
    pub causality: &'static str,
    /// The variable's structured name.
    pub name: String,
    /// Its value reference.
    pub value_reference: u32,
}

impl fmt::Display for VariableName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} '{}' (value reference {})", self.causality, self.name, self.value_reference)
    }
}

/// Why a variable cannot be set now.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NotSettable {
    /// Outputs are computed by the model.
    #[error("cannot be set: outputs are computed by the FMU")]
    Output,
    /// A fixed parameter after initialization (`state`: the instance's state name).
    #[error("has variability 'fixed': it can only be set before fmi2ExitInitializationMode (state is {state})")]
    Fixed {
        /// The state the instance is in.
        state: &'static str,
    },
    /// A parameter in continuous-time mode (Model Exchange).
    #[error("is a parameter: in continuousTimeMode only continuous inputs may be set (enter event mode first)")]
    ParameterInContinuousTime,
    /// A local variable (`causality="local"`): computed by the model, read-only for the host.
    #[error("cannot be set: local variables are computed by the FMU (under Model Exchange continuous states are set with SetContinuousStates)")]
    Local,
}

/// Which declared range an output left.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum OutputBound {
    /// NaN or infinite.
    #[error("is not a finite number")]
    NotFinite,
    /// Below the declared `min`.
    #[error("is below its declared minimum {}", Num(*.0))]
    BelowMin(f64),
    /// Above the declared `max`.
    #[error("is above its declared maximum {}", Num(*.0))]
    AboveMax(f64),
}

/// A status kind as the host passed it, for messages in the words of the standard whose
/// C names start with `prefix`: `fmi2DoStepStatus`, or `status kind 7 (not an
/// fmi2StatusKind)` for a code that is no status kind.
struct StatusKindName {
    kind: Result<StatusKind, c_int>,
    prefix: &'static str,
}

impl fmt::Display for StatusKindName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.kind {
            Ok(k) => write!(f, "{}{}", self.prefix, k.name()),
            Err(code) => write!(f, "status kind {code} (not an {}StatusKind)", self.prefix),
        }
    }
}

/// Why an FMI call failed; logged as `<function>: <message>` with status `fmi2Error`
/// (`fmi3Error`). Argument errors leave the instance as it was; a [`CallError::Model`] from
/// initialization or a step moves it to the `error` state (see the instance module, `core::instance`).
#[derive(Debug, thiserror::Error)]
pub enum CallError {
    /// An instantiation without an instance name.
    #[error("instanceName must be a non-empty string")]
    EmptyInstanceName,
    /// `fmi2Instantiate` with an `fmuType` that is no `fmi2Type`.
    #[error("fmuType = {0} is not an fmi2Type (0 = Model Exchange, 1 = Co-Simulation)")]
    FmuType(c_int),
    /// A GUID (instantiation token) of no model of this library.
    #[error("{arg} {token} matches no model of this binary (known: {known}); the modelDescription.xml does not belong to this binary")]
    UnknownToken {
        /// The argument, `fmuGUID` or `instantiationToken`.
        arg: &'static str,
        /// The token the host passed.
        token: String,
        /// The models of the library with their GUIDs.
        known: String,
    },
    /// A Model Exchange instantiation of a Co-Simulation-only model, in the words of the
    /// standard of the instantiating function: FMI 2.0's `fmi2Instantiate` names its
    /// `fmuType` values (`asked` = `fmuType = 0 (Model Exchange): `, `offered` =
    /// ` (fmuType = 1)`), FMI 3.0's `fmi3InstantiateModelExchange` needs neither (both empty).
    #[error("{asked}{model} implements Co-Simulation{offered} only")]
    CoSimulationOnly {
        /// The model's name.
        model: &'static str,
        /// What was asked for, as a prefix of the message (may be empty).
        asked: &'static str,
        /// How the standard names the interface the model offers (may be empty).
        offered: &'static str,
    },
    /// `fmi3InstantiateCoSimulation` with `eventModeUsed`.
    #[error("eventModeUsed = true, but this FMU's Co-Simulation has no event mode (hasEventMode = false)")]
    EventModeUsed,
    /// A value reference the model does not declare.
    #[error("unknown value reference {vr}: {model} has no variable with this value reference")]
    UnknownValueReference {
        /// The value reference the host passed.
        vr: u32,
        /// The model's name.
        model: &'static str,
    },
    /// A value reference passed to the getter or setter of a type the model has no variables of.
    #[error("unknown value reference {vr}: {model} has no {type_name} variables")]
    NoVariablesOfType {
        /// The value reference the host passed.
        vr: u32,
        /// The model's name.
        model: &'static str,
        /// The type of the function, e.g. `String`.
        type_name: &'static str,
    },
    /// An output whose dependency names no variable of the table.
    #[error("{output} depends on unknown {name}")]
    UnknownInput {
        /// The output.
        output: String,
        /// The missing variable.
        name: &'static str,
    },
    /// A value reference unknown to `fmi3Get[NumberOf]VariableDependencies`.
    #[error("unknown value reference {0}")]
    UnknownDependent(u32),
    /// A variable of another type than the function's.
    #[error("{variable} is a{article} {actual} variable, not {requested}")]
    WrongType {
        /// The variable.
        variable: VariableName,
        /// `"n"` before a vowel where the message has always said so, else `""`.
        article: &'static str,
        /// The variable's type, e.g. `Real`.
        actual: &'static str,
        /// The function's type.
        requested: &'static str,
    },
    /// A variable that may not be set in the current state.
    #[error("{variable} {why}")]
    NotSettable {
        /// The variable.
        variable: VariableName,
        /// Why not.
        why: NotSettable,
    },
    /// A NULL array with a positive length.
    #[error("{what} is NULL but its length is {len}")]
    NullArray {
        /// The argument, e.g. `vr[]`.
        what: &'static str,
        /// The length the host passed.
        len: usize,
    },
    /// A NULL pointer where the function needs one (`what`, e.g. `FMUstate`).
    #[error("{0} is NULL")]
    Null(&'static str),
    /// FMI 3.0: `nValues` differs from `nValueReferences` (every variable is a scalar).
    #[error("nValues = {n_values} but nValueReferences = {nvr}: every variable of this FMU is a scalar")]
    NotScalar {
        /// `nValueReferences`.
        nvr: usize,
        /// `nValues`.
        n_values: usize,
    },
    /// `fmi3GetVariableDependencies` with another count than the variable has.
    #[error("nDependencies = {given}, but value reference {vr} has {actual} dependencies")]
    DependencyCount {
        /// `nDependencies`.
        given: usize,
        /// The dependent variable.
        vr: u32,
        /// How many it has.
        actual: usize,
    },
    /// A serialization buffer of the wrong size.
    #[error("size = {given} bytes, but this FMU state serializes to {actual} bytes (see fmi2SerializedFMUstateSize)")]
    StateSize {
        /// The size the host passed.
        given: usize,
        /// The serialized length.
        actual: usize,
    },
    /// A non-zero count of continuous states or event indicators (`what`, e.g. `nx`).
    #[error("{what} = {n}, but {model} has no continuous states and no event indicators (0)")]
    NoContinuousStates {
        /// The argument's name.
        what: &'static str,
        /// Its value.
        n: usize,
        /// The model's name.
        model: &'static str,
    },
    /// A non-zero count of event indicators of a model with continuous states (`what`, e.g.
    /// `ni`); a model without states reports [`CallError::NoContinuousStates`] as it always has.
    #[error("{what} = {n}, but {model} has no event indicators (0)")]
    NoEventIndicators {
        /// The argument's name.
        what: &'static str,
        /// Its value.
        n: usize,
        /// The model's name.
        model: &'static str,
    },
    /// A count of continuous states other than the model's (`what`, e.g. `nx`).
    #[error("{what} = {given}, but {model} has {expected} continuous state{}", if *.expected == 1 { "" } else { "s" })]
    StateCount {
        /// The argument's name.
        what: &'static str,
        /// Its value.
        given: usize,
        /// The model's number of continuous states.
        expected: usize,
        /// The model's name.
        model: &'static str,
    },
    /// A directional derivative of a variable that is no unknown of the call (FMI 2.0 §2.1.9,
    /// FMI 3.0 §2.2.12): `allowed` says what is.
    #[error("{variable} cannot be an unknown of a directional derivative: unknowns are {allowed}")]
    NotAnUnknown {
        /// The variable.
        variable: VariableName,
        /// What may be an unknown here.
        allowed: &'static str,
    },
    /// A directional derivative with respect to a variable that is no known of the call.
    #[error("{variable} cannot be a known of a directional derivative: knowns are {allowed}")]
    NotAKnown {
        /// The variable.
        variable: VariableName,
        /// What may be a known here.
        allowed: &'static str,
    },
    /// FMI 3.0: a seed or sensitivity array whose length is not that of its value references
    /// (every variable is a scalar).
    #[error("{what} = {given}, but {of} = {expected}: every variable of this FMU is a scalar")]
    ArrayLength {
        /// The length argument, e.g. `nSeed`.
        what: &'static str,
        /// Its value.
        given: usize,
        /// The count it must equal, e.g. `nKnowns`.
        of: &'static str,
        /// That count.
        expected: usize,
    },
    /// A partial derivative the model computed that is not a finite number.
    #[error("the model gives the partial derivative of {unknown} with respect to {known} = {}, which is not a finite number", Num(*.value))]
    PartialNotFinite {
        /// The unknown's name.
        unknown: String,
        /// The known's name.
        known: String,
        /// The value the model gave.
        value: f64,
    },
    /// A log category the FMU does not declare.
    #[error("unknown log category '{name}' (known: {known})")]
    UnknownCategory {
        /// The name the host passed.
        name: String,
        /// The declared ones, comma-separated.
        known: String,
    },
    /// An FMU state handle that is freed or foreign (`handle`: `FMUstate` or `*FMUstate`).
    #[error("{handle} is not a live FMU state of this FMU (freed or foreign)")]
    NotLiveState {
        /// How the argument is named.
        handle: &'static str,
    },
    /// `fmi2GetFMUstate` with a `*FMUstate` to reuse that is no FMU state.
    #[error("*FMUstate is neither NULL nor an FMU state of this FMU")]
    NotReusableState,
    /// A time that must be finite (`what` = `value` s; `time`, `currentCommunicationPoint`, …).
    #[error("{what} = {} s is not a finite number", Num(*.value))]
    NotFinite {
        /// The argument's name.
        what: &'static str,
        /// Its value, in s.
        value: f64,
    },
    /// A stop time that is not finite or before the start.
    #[error("stopTime = {stop} s must be a finite number >= startTime = {start} s")]
    StopTime {
        /// `stopTime`, s.
        stop: f64,
        /// `startTime`, s.
        start: f64,
    },
    /// A communication step size that is not a finite number > 0.
    #[error("communicationStepSize = {} s must be a finite number > 0 s", Num(*.0))]
    StepSize(f64),
    /// A step whose end is not a finite number.
    #[error("currentCommunicationPoint + communicationStepSize = {} s + {} s is not a finite number", Num(*.t), Num(*.h))]
    StepEnd {
        /// The communication point, s.
        t: f64,
        /// The step size, s.
        h: f64,
    },
    /// A communication point that does not continue the last step.
    #[error(
        "currentCommunicationPoint = {} s does not continue the last step, which ended at {} s \
         (difference {:e} s exceeds the tolerance {tol:e} s)",
        Num(*.t), Num(*.last), .t - .last
    )]
    Discontinuous {
        /// The communication point, s.
        t: f64,
        /// Where the last step ended, s.
        last: f64,
        /// The tolerance, s.
        tol: f64,
    },
    /// A step the model could not complete (the instance is now in the `error` state).
    #[error("step from t = {} s over {} s failed: {source}", Num(*.t), Num(*.h))]
    StepFailed {
        /// The communication point, s.
        t: f64,
        /// The step size, s.
        h: f64,
        /// Why.
        source: Box<CallError>,
    },
    /// An output outside its declared range (or not finite).
    #[error(
        "the model gives output {name} = {} {unit} which {bound}: the inputs or parameters are outside the range in which the model is defined",
        Num(*.value)
    )]
    OutputOutOfRange {
        /// The output's name.
        name: String,
        /// The value the model gave.
        value: f64,
        /// Its unit for messages.
        unit: &'static str,
        /// Which bound it left.
        bound: OutputBound,
    },
    /// A state derivative that is not a finite number.
    #[error(
        "the model gives state derivative {name} = {} {unit}, which is not a finite number: the states, inputs or parameters are outside the range in which the model is defined",
        Num(*.value)
    )]
    DerivativeNotFinite {
        /// The derivative's name.
        name: String,
        /// The value the model gave.
        value: f64,
        /// Its unit for messages.
        unit: &'static str,
    },
    /// A Model Exchange function on a Co-Simulation instance.
    #[error("this is a Model Exchange function and the instance was instantiated for Co-Simulation")]
    NotModelExchange,
    /// A part of the standard this layer does not provide (the message says which and why).
    #[error("{0}")]
    Unsupported(&'static str),
    /// A status kind not available through a `Get*Status` function.
    #[error("{} is not available through {func} (this FMU steps synchronously)", StatusKindName { kind: *.kind, prefix })]
    StatusKind {
        /// The status kind the host passed, or its C code if that is no status kind.
        kind: Result<StatusKind, c_int>,
        /// The prefix of the standard's C names (`fmi2`), for the kind's name.
        prefix: &'static str,
        /// The function.
        func: &'static str,
    },
    /// An Int64 that no enumeration item of this FMU has.
    #[error("value {0} is no item of an enumeration of this FMU")]
    NotAnEnumerationItem(i64),
    /// An FMU state of another model.
    #[error("FMU state belongs to GUID {state_guid} but this instance is {guid}")]
    ForeignState {
        /// The state's GUID.
        state_guid: String,
        /// The instance's GUID.
        guid: String,
    },
    /// An FMU state in a mode of the other interface.
    #[error("FMU state is in state {state}, which an instance of this interface ({interface:?}) cannot take")]
    StateForInterface {
        /// The state's life-cycle state name.
        state: &'static str,
        /// The instance's interface.
        interface: Interface,
    },
    /// The model refused its part of an FMU state (`fmi2SetFMUstate`).
    #[error("FMU state rejected: {0}")]
    StateRejected(ModelError),
    /// The model refused its part of a serialized FMU state (`fmi2DeSerializeFMUstate`).
    #[error("serialized FMU state rejected: {0}")]
    SerializedStateRejected(ModelError),
    /// A serialized FMU state that is not well formed.
    #[error(transparent)]
    StateFormat(#[from] StateFormatError),
    /// The model's own error (a value, its parameters, a computation).
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// A serialized FMU state that is not a well-formed byte stream of this FMU.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StateFormatError {
    /// Fewer bytes remain than the next field needs.
    #[error("truncated: {what} needs {needed} bytes at offset {offset} but only {remaining} remain")]
    Truncated {
        /// The field being read.
        what: String,
        /// Its length in bytes.
        needed: usize,
        /// Where it starts.
        offset: usize,
        /// How many bytes are left.
        remaining: usize,
    },
    /// Bytes left after the last field.
    #[error("{0} unexpected trailing bytes")]
    Trailing(usize),
    /// Not the magic bytes of this layer's format.
    #[error("not a serialized FMU state of this FMU (bad magic bytes)")]
    BadMagic,
    /// Another format version.
    #[error("serialized FMU state has format version {found}; this FMU reads version {reads}")]
    Version {
        /// The version in the bytes.
        found: u16,
        /// The version this layer reads.
        reads: u16,
    },
    /// A length other than the header says.
    #[error("serialized FMU state is {actual} bytes but its header says {header} (truncated or extended)")]
    Length {
        /// The length passed.
        actual: usize,
        /// The length in the header.
        header: usize,
    },
    /// The CRC-32 does not match.
    #[error("serialized FMU state is corrupted (CRC-32 mismatch)")]
    Crc,
    /// A state of another model.
    #[error("serialized FMU state belongs to GUID {found} but this instance is {guid}")]
    OtherGuid {
        /// The GUID in the bytes.
        found: String,
        /// The instance's GUID.
        guid: String,
    },
    /// A life-cycle state code no state (allowed for FMU states) has.
    #[error("serialized FMU state holds an invalid life-cycle state code {0}")]
    LifeCycleCode(u8),
    /// Times that are not finite or out of order.
    #[error(
        "serialized FMU state holds an invalid time ({} s, start {} s): both must be finite, time >= start",
        Num(*.time), Num(*.start)
    )]
    Time {
        /// The time, s.
        time: f64,
        /// The start time, s.
        start: f64,
    },
}

/// A model's part of a serialized FMU state that is not well formed is the model's error
/// (what the model's `deserialize` returns when a read of the layer's byte reader (`core::bytes`) fails).
impl From<StateFormatError> for ModelError {
    fn from(e: StateFormatError) -> Self {
        ModelError::RejectedState(e.to_string())
    }
}

/// A model table from which no valid modelDescription.xml can be written.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum XmlError {
    /// Two units of one quantity (type names must be unique).
    #[error("two units have quantity {0}: type names must be unique")]
    DuplicateQuantity(&'static str),
    /// A unit or display unit on a variable that is not Real.
    #[error("variable {0}: only Real variables have units")]
    UnitOnNonReal(String),
    /// A unit missing from the unit table.
    #[error("variable {variable}: unit {unit} is not in the unit table")]
    UnknownUnit {
        /// The variable.
        variable: String,
        /// Its unit.
        unit: &'static str,
    },
    /// A display unit its unit does not define.
    #[error("variable {variable}: display unit {display} is not defined for unit {unit}")]
    UnknownDisplayUnit {
        /// The variable.
        variable: String,
        /// Its display unit.
        display: &'static str,
        /// Its unit.
        unit: &'static str,
    },
    /// An output depending on a variable the table does not have.
    #[error("{output} depends on unknown variable {name}")]
    UnknownDependency {
        /// The output.
        output: String,
        /// The missing variable.
        name: &'static str,
    },
    /// An output or state derivative depending on a variable that is neither an input nor a
    /// continuous state.
    #[error("{output} may only depend on inputs and continuous states, not on {name}")]
    DependsOnNonInput {
        /// The output.
        output: String,
        /// The variable that is not an input.
        name: &'static str,
    },
    /// A derivative naming a state the table does not have.
    #[error("{derivative} is declared the derivative of unknown variable {state}")]
    UnknownState {
        /// The derivative variable.
        derivative: String,
        /// The missing state.
        state: &'static str,
    },
    /// A continuous state that cannot be one (FMI 2.0 §2.2.8, FMI 3.0 §2.4.8).
    #[error("continuous state {state} {why}")]
    InvalidState {
        /// The state.
        state: String,
        /// What is wrong, e.g. `must be a Real variable`.
        why: &'static str,
    },
    /// A state derivative that cannot be one.
    #[error("state derivative {derivative} {why}")]
    InvalidDerivative {
        /// The derivative variable.
        derivative: String,
        /// What is wrong, e.g. `must have initial="calculated"`.
        why: &'static str,
    },
    /// Two derivatives of one state.
    #[error("{state} has two derivatives, {first} and {second}")]
    DuplicateDerivative {
        /// The state.
        state: &'static str,
        /// The first derivative in table order.
        first: String,
        /// The second.
        second: String,
    },
    /// A variable using the value reference FMI 3.0 reserves for `time`.
    #[error("value reference {0} is reserved for the independent variable time in FMI 3.0")]
    ReservedTimeVr(u32),
}

#[cfg(test)]
mod tests {
    use super::*;

    fn var() -> VariableName {
        VariableName { causality: "input", name: "load".into(), value_reference: 3 }
    }

    #[test]
    fn call_errors_read_as_the_host_has_always_seen_them() {
        let cases: Vec<(CallError, &str)> = vec![
            (CallError::UnknownValueReference { vr: 99, model: "M" }, "unknown value reference 99: M has no variable with this value reference"),
            (
                CallError::WrongType { variable: var(), article: "n", actual: "Integer", requested: "Real" },
                "input 'load' (value reference 3) is an Integer variable, not Real",
            ),
            (
                CallError::NotSettable { variable: var(), why: NotSettable::Fixed { state: "stepComplete" } },
                "input 'load' (value reference 3) has variability 'fixed': it can only be set before fmi2ExitInitializationMode (state is stepComplete)",
            ),
            (CallError::NullArray { what: "vr[]", len: 2 }, "vr[] is NULL but its length is 2"),
            (CallError::Null("FMUstate"), "FMUstate is NULL"),
            (CallError::NotLiveState { handle: "*FMUstate" }, "*FMUstate is not a live FMU state of this FMU (freed or foreign)"),
            (CallError::StepSize(-1e308), "communicationStepSize = -1e308 s must be a finite number > 0 s"),
            (
                CallError::Discontinuous { t: 1.5, last: 1.0, tol: 1e-6 },
                "currentCommunicationPoint = 1.5 s does not continue the last step, which ended at 1 s (difference 5e-1 s exceeds the tolerance 1e-6 s)",
            ),
            (
                CallError::StepFailed { t: 0.0, h: 0.5, source: Box::new(CallError::NotFinite { what: "x", value: f64::NAN }) },
                "step from t = 0 s over 0.5 s failed: x = NaN s is not a finite number",
            ),
            (
                CallError::OutputOutOfRange { name: "h".into(), value: -1e-9, unit: "m", bound: OutputBound::BelowMin(0.0) },
                "the model gives output h = -1e-9 m which is below its declared minimum 0: the inputs or parameters are outside the range in which the model is defined",
            ),
            (CallError::StatusKind { kind: Err(7), prefix: "fmi2", func: "fmi2GetStatus" }, "status kind 7 (not an fmi2StatusKind) is not available through fmi2GetStatus (this FMU steps synchronously)"),
            (CallError::StatusKind { kind: Ok(StatusKind::DoStepStatus), prefix: "fmi2", func: "fmi2GetRealStatus" }, "fmi2DoStepStatus is not available through fmi2GetRealStatus (this FMU steps synchronously)"),
            (
                CallError::CoSimulationOnly { model: "PinJointRig", asked: "fmuType = 0 (Model Exchange): ", offered: " (fmuType = 1)" },
                "fmuType = 0 (Model Exchange): PinJointRig implements Co-Simulation (fmuType = 1) only",
            ),
            (CallError::CoSimulationOnly { model: "PinJointRig", asked: "", offered: "" }, "PinJointRig implements Co-Simulation only"),
            (CallError::StateRejected(ModelError::RejectedState("bad".to_owned())), "FMU state rejected: bad"),
            (CallError::StateFormat(StateFormatError::Crc), "serialized FMU state is corrupted (CRC-32 mismatch)"),
        ];
        for (e, text) in cases {
            assert_eq!(e.to_string(), text);
        }
    }

    #[test]
    fn state_and_xml_errors_name_what_and_where() {
        let e = StateFormatError::Truncated { what: "GUID".into(), needed: 38, offset: 15, remaining: 2 };
        assert_eq!(e.to_string(), "truncated: GUID needs 38 bytes at offset 15 but only 2 remain");
        assert_eq!(
            StateFormatError::Time { time: 1.0, start: 2.0 }.to_string(),
            "serialized FMU state holds an invalid time (1 s, start 2 s): both must be finite, time >= start"
        );
        assert_eq!(
            XmlError::UnknownDisplayUnit { variable: "angle".into(), display: "deg", unit: "m" }.to_string(),
            "variable angle: display unit deg is not defined for unit m"
        );
        // A model's part that is not well formed is the model's error, with the same text.
        assert_eq!(ModelError::from(StateFormatError::Trailing(3)).to_string(), "3 unexpected trailing bytes");
    }
}
