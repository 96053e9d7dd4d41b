//! The description of a model's interface: its variables and units. One table per
//! model feeds both modelDescription.xml generators (over the shared writer [`super::xml`]) and the
//! get/set dispatch of the instance, so the two cannot drift apart.

use super::model::Model;

/// A variable's `causality` attribute: how the host may use it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// Set by the host before or during initialization (and, if tunable, between steps).
    Parameter,
    /// Set by the host at any communication point; the outputs depend on it.
    Input,
    /// Computed by the model; the host only reads it.
    Output,
    /// Internal to the model (FMI 2.0 §2.2.7, FMI 3.0 §2.4.7 `causality="local"`): the host
    /// may read it but not set it (`fmi2SetReal`/`fmi3SetFloat64` refuse it). Continuous states
    /// and their derivatives are local variables unless the model exposes them as outputs;
    /// under Model Exchange the host sets the states with `fmi2SetContinuousStates`.
    Local,
}

/// A variable's `variability` attribute: when its value may change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variability {
    /// Set before `fmi2ExitInitializationMode` only.
    Fixed,
    /// May also be set in `stepComplete`.
    Tunable,
    /// Changes only at communication points (FMI 2.0: required for Integer and
    /// Boolean outputs, which may not be continuous).
    Discrete,
    /// May change at any time (Real variables only).
    Continuous,
}

/// The FMI type of a variable. The model stores every value as an f64; the layer
/// converts at the C boundary (Integer as the exact integer value, Boolean as 0.0
/// or 1.0), so the [`Model`] trait has one getter and one setter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// FMI 2.0 `Real` / FMI 3.0 `Float64`.
    Real,
    /// FMI 2.0 `Integer` / FMI 3.0 `Int32`, held as the exact integer value.
    Integer,
    /// `Boolean`, held as 0.0 (false) or 1.0 (true).
    Boolean,
    /// Named integer choices (FMI 2.0 `<Enumeration>`, read and written with
    /// `fmi2GetInteger`/`fmi2SetInteger`; FMI 3.0 `<Enumeration>`, with `fmi3GetInt64`/`fmi3SetInt64`).
    Enumeration(&'static EnumType),
}

impl Kind {
    /// The FMI 2.0 element name of the type, e.g. `Real`, for the XML and messages.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Real => "Real",
            Kind::Integer => "Integer",
            Kind::Boolean => "Boolean",
            Kind::Enumeration(_) => "Enumeration",
        }
    }
}

/// An enumeration type: named choices with their integer codes.
#[derive(Debug, PartialEq)]
pub struct EnumType {
    /// Type name in `<TypeDefinitions>`, e.g. `Fidelity`.
    pub name: &'static str,
    /// The type's `description` attribute.
    pub description: &'static str,
    /// (item name, value code, description), in value order.
    pub items: &'static [(&'static str, i64, &'static str)],
}

impl EnumType {
    /// The item name of `code`, if `code` is one of the choices.
    pub fn item(&self, code: i64) -> Option<&'static str> {
        self.items.iter().find(|i| i.1 == code).map(|i| i.0)
    }
}

/// A variable's `initial` attribute: where its first value comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Initial {
    /// The start value is the value (inputs, parameters).
    Exact,
    /// Computed from other variables during initialization (outputs).
    Calculated,
}

impl Causality {
    /// The attribute value in the modelDescription, e.g. `input`.
    pub fn as_str(self) -> &'static str {
        match self {
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
            Causality::Local => "local",
        }
    }
}
impl Variability {
    /// The attribute value in the modelDescription, e.g. `tunable`.
    pub fn as_str(self) -> &'static str {
        match self {
            Variability::Fixed => "fixed",
            Variability::Tunable => "tunable",
            Variability::Discrete => "discrete",
            Variability::Continuous => "continuous",
        }
    }
}
impl Initial {
    /// The attribute value in the modelDescription, e.g. `exact`.
    pub fn as_str(self) -> &'static str {
        match self {
            Initial::Exact => "exact",
            Initial::Calculated => "calculated",
        }
    }
}

/// One scalar variable (Real, Integer or Boolean; no model of this crate has String
/// variables, so the String getters and setters reject every value reference).
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// Structured name, e.g. `geometry.pin_radius`.
    pub name: String,
    /// The FMI type.
    pub kind: Kind,
    /// The value reference that names the variable in the FMI calls (unique per model).
    pub value_reference: u32,
    /// The `causality` attribute.
    pub causality: Causality,
    /// The `variability` attribute.
    pub variability: Variability,
    /// The `initial` attribute.
    pub initial: Initial,
    /// SI unit name from the model's unit table; `None` for dimensionless.
    pub unit: Option<&'static str>,
    /// The display unit offered to the host (one of the unit's [`DisplayUnit`]s), if any.
    pub display_unit: Option<&'static str>,
    /// Start value (required for inputs and parameters, absent for calculated outputs);
    /// for a Boolean 0.0 (false) or 1.0 (true).
    pub start: Option<f64>,
    /// Smallest allowed value, in the variable's unit; `None` for no bound.
    pub min: Option<f64>,
    /// Largest allowed value, in the variable's unit; `None` for no bound.
    pub max: Option<f64>,
    /// What the variable is, for the modelDescription and messages.
    pub description: String,
    /// Outputs and state derivatives: the names of the inputs and continuous states the
    /// variable depends on directly (ModelStructure `dependencies`, FMI 2.0 §2.2.8, FMI 3.0
    /// §2.4.8); empty for every other variable.
    pub depends_on: Vec<&'static str>,
    /// The NAME of the continuous state this variable is the time derivative of (FMI 2.0
    /// `<Real derivative=...>`, FMI 3.0 `<Float64 derivative=...>`), or `None`. A variable named
    /// here is a continuous state ([`ModelInfo::continuous_states`]); the derivative must be a
    /// continuous Real with `initial="calculated"`.
    pub derivative_of: Option<&'static str>,
    /// The `nominal` attribute of a Real (its typical magnitude, in its unit); for a
    /// continuous state it is what `fmi2GetNominalsOfContinuousStates` reports (1.0 if `None`).
    pub nominal: Option<f64>,
}

impl Variable {
    /// The unit for messages: "N", "rad/s", or "(dimensionless)".
    pub fn unit_text(&self) -> &'static str {
        self.unit.unwrap_or("(dimensionless)")
    }
}

/// A display unit: `value_display = factor * value + offset`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DisplayUnit {
    /// The display unit's name, e.g. `deg` or `degC`.
    pub name: &'static str,
    /// Factor from the unit to the display unit.
    pub factor: f64,
    /// Offset added after the factor, in the display unit.
    pub offset: f64,
}

/// A unit with its SI base-unit exponents (kg, m, s, A, K, mol, cd, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitDef {
    /// The unit's name, e.g. `N.m`.
    pub name: &'static str,
    /// The physical quantity of the variables with this unit (`quantity` of the type
    /// definition the generators write for it), e.g. `Torque`.
    pub quantity: &'static str,
    /// Exponent of the kilogram.
    pub kg: i32,
    /// Exponent of the metre.
    pub m: i32,
    /// Exponent of the second.
    pub s: i32,
    /// Exponent of the radian.
    pub rad: i32,
    /// Exponent of the kelvin (temperature) base unit.
    pub k: i32,
    /// The display units of this unit (`<DisplayUnit>` elements).
    pub display: &'static [DisplayUnit],
}

/// Co-Simulation capabilities written to the modelDescription. The generic layer
/// implements exactly these: variable step size, get/set and serialized FMU state.
/// `providesDirectionalDerivative` is written with the model's
/// [`ModelInfo::directional_derivatives`] instead of the value here.
pub const CAPABILITIES: &[(&str, &str)] = &[
    ("needsExecutionTool", "false"),
    ("canHandleVariableCommunicationStepSize", "true"),
    ("canInterpolateInputs", "false"),
    ("maxOutputDerivativeOrder", "0"),
    ("canRunAsynchronuously", "false"),
    ("canBeInstantiatedOnlyOncePerProcess", "false"),
    ("canNotUseMemoryManagementFunctions", "true"),
    ("canGetAndSetFMUstate", "true"),
    ("canSerializeFMUstate", "true"),
    ("providesDirectionalDerivative", "false"),
];

/// Model Exchange capabilities (FMI 2.0 `<ModelExchange>`): no event indicators; the host's
/// `fmi2CompletedIntegratorStep` is not needed unless the model asks for step events
/// (`completedIntegratorStepNotNeeded` is written from [`ModelInfo::step_events`]).
/// `providesDirectionalDerivative` is written with the model's
/// [`ModelInfo::directional_derivatives`] instead of the value here.
pub const ME_CAPABILITIES: &[(&str, &str)] = &[
    ("needsExecutionTool", "false"),
    ("completedIntegratorStepNotNeeded", "true"),
    ("canBeInstantiatedOnlyOncePerProcess", "false"),
    ("canNotUseMemoryManagementFunctions", "true"),
    ("canGetAndSetFMUstate", "true"),
    ("canSerializeFMUstate", "true"),
    ("providesDirectionalDerivative", "false"),
];

/// Who made the model and under which terms (the `author`, `copyright` and `license`
/// attributes of both standards' modelDescription).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Legal {
    /// The `author` attribute.
    pub author: &'static str,
    /// The `copyright` attribute.
    pub copyright: &'static str,
    /// The `license` attribute.
    pub license: &'static str,
}

/// Everything the FMI layer needs to know about one model.
pub struct ModelInfo {
    /// The `modelName` attribute, also used in messages.
    pub model_name: &'static str,
    /// The shared library's base name and the `modelIdentifier`.
    pub model_identifier: &'static str,
    /// The `description` attribute of the modelDescription.
    pub description: &'static str,
    /// The `version` attribute, the model's version (part of the GUID).
    pub version: &'static str,
    /// The units the variables use (`<UnitDefinitions>`).
    pub units: &'static [UnitDef],
    /// The variable table, in modelDescription order; the index in it is how the layer
    /// addresses a variable in the [`Model`] trait.
    pub variables: Vec<Variable>,
    /// (startTime, stopTime, stepSize) of `<DefaultExperiment>`.
    pub default_experiment: (f64, f64, f64),
    /// A fresh model with its start values set.
    pub create: fn() -> Box<dyn Model>,
    /// The FMU's `documentation/index.html`.
    pub documentation: fn() -> String,
    /// The model is also offered as Model Exchange: the host's integrator owns the continuous
    /// states ([`ModelInfo::continuous_states`], possibly none), there are no event indicators,
    /// and [`Model::do_step`] is never called.
    pub model_exchange: bool,
    /// The model implements [`Model::jacobian`]: both interfaces write
    /// `providesDirectionalDerivative="true"` (FMI 2.0) / `providesDirectionalDerivatives="true"`
    /// (FMI 3.0) and `fmi2GetDirectionalDerivative`/`fmi3GetDirectionalDerivative` call it.
    /// When false those functions are refused without asking the model.
    pub directional_derivatives: bool,
    /// Model Exchange: the model asks for step events ([`Model::completed_integrator_step`]) and
    /// updates discrete states in event mode ([`Model::update_discrete_states`]), so the host
    /// must call `fmi2CompletedIntegratorStep`/`fmi3CompletedIntegratorStep`
    /// (`completedIntegratorStepNotNeeded="false"`, `needsCompletedIntegratorStep="true"`).
    pub step_events: bool,
    /// Author, copyright and licence of the model.
    pub legal: Legal,
}

impl ModelInfo {
    /// The GUID: a hash of everything that defines the interface (name, identifier, version,
    /// and each variable's name, value reference, causality, variability, unit,
    /// for a non-Real variable its type, and for a derivative its state), so
    /// that any change of the interface changes the GUID and a stale
    /// modelDescription.xml is refused by `fmi2Instantiate`.
    pub fn guid(&self) -> String {
        let mut text = format!("{}|{}|{}", self.model_name, self.model_identifier, self.version);
        for v in &self.variables {
            text.push_str(&format!(
                "|{}:{}:{}:{}:{}",
                v.name,
                v.value_reference,
                v.causality.as_str(),
                v.variability.as_str(),
                v.unit.unwrap_or("")
            ));
            if v.kind != Kind::Real {
                text.push_str(&format!(":{}", v.kind.as_str()));
            }
            if let Kind::Enumeration(t) = v.kind {
                text.push_str(&format!(":{}", t.name));
            }
            // Which variable is a state's derivative changes the state vector (not written
            // when absent, so the GUID of a table without states is what it always was).
            if let Some(state) = v.derivative_of {
                text.push_str(&format!(":der({state})"));
            }
        }
        let a = fnv1a64(text.as_bytes(), 0xcbf2_9ce4_8422_2325);
        let b = fnv1a64(text.as_bytes(), 0x6c62_272e_07bb_0142);
        format!(
            "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
            a >> 32,
            (a >> 16) & 0xffff,
            a & 0xffff,
            b >> 48,
            b & 0xffff_ffff_ffff
        )
    }

    /// Index of the variable with value reference `vr`.
    pub fn index_of(&self, vr: u32) -> Option<usize> {
        self.variables.iter().position(|v| v.value_reference == vr)
    }

    /// Index of the variable named `name`.
    pub fn index_by_name(&self, name: &str) -> Option<usize> {
        self.variables.iter().position(|v| v.name == name)
    }

    /// The unit definition named `name`, if the model declares it.
    pub fn unit(&self, name: &str) -> Option<&UnitDef> {
        self.units.iter().find(|u| u.name == name)
    }

    /// The continuous states as (state index, derivative index) pairs, in the table order of
    /// the derivative variables (the order of the state vector of `fmi2GetContinuousStates`
    /// and of `<Derivatives>`, FMI 2.0 §2.2.8 / FMI 3.0 §2.4.8). A state is a variable named by
    /// some variable's [`Variable::derivative_of`]; a name the table does not have is skipped
    /// here (the XML generators refuse such a table).
    pub fn continuous_states(&self) -> Vec<(usize, usize)> {
        self.variables
            .iter()
            .enumerate()
            .filter_map(|(d, v)| v.derivative_of.and_then(|name| self.index_by_name(name)).map(|x| (x, d)))
            .collect()
    }

    /// The distinct enumeration types of the variables, in order of first use.
    pub fn enum_types(&self) -> Vec<&'static EnumType> {
        let mut out: Vec<&'static EnumType> = Vec::new();
        for v in &self.variables {
            if let Kind::Enumeration(t) = v.kind
                && !out.iter().any(|o| o.name == t.name)
            {
                out.push(t);
            }
        }
        out
    }
}

fn fnv1a64(bytes: &[u8], seed: u64) -> u64 {
    let mut h = seed;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}
