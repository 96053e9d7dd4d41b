//! The FMI 3.0 modelDescription.xml generator, from the same [`ModelInfo`] as the FMI 2.0
//! one: variables, units, display units, quantities, enumeration types, log categories,
//! default experiment. ModelStructure (FMI 3.0 §2.4.8): each output and each state derivative
//! with the value references of the inputs and continuous states it depends on directly, and
//! the initial unknowns (outputs, states and derivatives with `initial="calculated"`, without
//! `dependencies`: they may depend on every parameter at initialization).

use crate::error::XmlError;
use crate::core::variables::{Kind, ModelInfo, Variable};
use crate::core::xml::{self as common, escape};
use std::fmt::Write;

/// The value reference of the independent variable `time` FMI 3.0 requires (not in the
/// model's table; `fmi3GetFloat64` returns the instance's time for it).
pub const TIME_VR: u32 = 0;

/// The FMI 3.0 element name of a variable's type.
fn element(kind: Kind) -> &'static str {
    match kind {
        Kind::Real => "Float64",
        Kind::Integer => "Int32",
        Kind::Boolean => "Boolean",
        Kind::Enumeration(_) => "Enumeration",
    }
}

/// Capabilities common to both interfaces, then each interface's own.
const COMMON: &[(&str, &str)] = &[
    ("needsExecutionTool", "false"),
    ("canBeInstantiatedOnlyOncePerProcess", "false"),
    ("canGetAndSetFMUState", "true"),
    ("canSerializeFMUState", "true"),
    ("providesDirectionalDerivatives", "false"),
    ("providesAdjointDerivatives", "false"),
    ("providesPerElementDependencies", "false"),
];
const ME: &[(&str, &str)] = &[("needsCompletedIntegratorStep", "false"), ("providesEvaluateDiscreteStates", "false")];
const CS: &[(&str, &str)] = &[
    ("canHandleVariableCommunicationStepSize", "true"),
    ("maxOutputDerivativeOrder", "0"),
    ("providesIntermediateUpdate", "false"),
    ("mightReturnEarlyFromDoStep", "false"),
    ("canReturnEarlyAfterIntermediateUpdate", "false"),
    ("hasEventMode", "false"),
    ("providesEvaluateDiscreteStates", "false"),
];

/// One variable element, e.g. `<Float64 name=... unit=... start=.../>`; a state derivative
/// names its state by value reference (`derivative`, FMI 3.0 §2.4.7).
fn variable(info: &ModelInfo, v: &Variable) -> Result<String, XmlError> {
    let types = common::type_attributes(info, v)?;
    let mut derivative = String::new();
    if let Some(state) = v.derivative_of {
        let x = info.index_by_name(state).ok_or_else(|| XmlError::UnknownState { derivative: v.name.clone(), state })?;
        derivative = format!(r#" derivative="{}""#, info.variables[x].value_reference);
    }
    Ok(format!("<{}{}{types}{derivative}/>", element(v.kind), common::variable_attributes(v)))
}

/// The capabilities of an interface element, `providesDirectionalDerivatives` set to the
/// model's [`ModelInfo::directional_derivatives`].
fn capabilities<'a>(info: &ModelInfo, lists: impl IntoIterator<Item = &'a (&'static str, &'static str)>) -> Vec<(&'static str, &'static str)> {
    let provides = if info.directional_derivatives { "true" } else { "false" };
    let needed = if info.step_events { "true" } else { "false" };
    lists
        .into_iter()
        .map(|&(k, v)| match k {
            "providesDirectionalDerivatives" => (k, provides),
            "needsCompletedIntegratorStep" => (k, needed),
            _ => (k, v),
        })
        .collect()
}

/// The complete FMI 3.0 modelDescription.xml of `info` (Model Exchange if the model offers it,
/// and Co-Simulation).
pub fn model_description(info: &ModelInfo) -> Result<String, XmlError> {
    let mut x = String::new();
    let w = &mut x;
    common::root_element(w, "3.0", "instantiationToken", "fmi3", info, &[]);
    if info.model_exchange {
        common::interface(w, "ModelExchange", info, &capabilities(info, COMMON.iter().chain(ME)));
    }
    common::interface(w, "CoSimulation", info, &capabilities(info, COMMON.iter().chain(CS)));

    // The independent variable time needs the unit s and a type of quantity Time.
    let has_seconds = info.units.iter().any(|u| u.name == "s" && info.variables.iter().any(|v| v.unit == Some("s")));
    let used = common::used_units(info, if has_seconds { &[] } else { &["Time"] })?;
    if !used.is_empty() {
        writeln!(w, "  <UnitDefinitions>").unwrap();
        for u in &used {
            common::unit(w, u);
        }
        if !has_seconds {
            writeln!(w, r#"    <Unit name="s"><BaseUnit s="1"/></Unit>"#).unwrap();
        }
        writeln!(w, "  </UnitDefinitions>").unwrap();
    } else {
        writeln!(w, r#"  <UnitDefinitions><Unit name="s"><BaseUnit s="1"/></Unit></UnitDefinitions>"#).unwrap();
    }

    writeln!(w, "  <TypeDefinitions>").unwrap();
    if !has_seconds {
        writeln!(w, r#"    <Float64Type name="Time" quantity="Time" unit="s"/>"#).unwrap();
    }
    for u in &used {
        writeln!(w, r#"    <Float64Type name="{}" quantity="{}" unit="{}"/>"#, escape(u.quantity), escape(u.quantity), escape(u.name)).unwrap();
    }
    for t in info.enum_types() {
        writeln!(w, r#"    <EnumerationType name="{}" description="{}">"#, escape(t.name), escape(t.description)).unwrap();
        for (name, value, d) in t.items {
            writeln!(w, r#"      <Item name="{}" value="{value}" description="{}"/>"#, escape(name), escape(d)).unwrap();
        }
        writeln!(w, "    </EnumerationType>").unwrap();
    }
    writeln!(w, "  </TypeDefinitions>").unwrap();

    common::log_categories(w, super::types::status_name);
    common::default_experiment(w, info);

    writeln!(w, "  <ModelVariables>").unwrap();
    if info.index_of(TIME_VR).is_some() {
        return Err(XmlError::ReservedTimeVr(TIME_VR));
    }
    writeln!(
        w,
        r#"    <Float64 name="time" valueReference="{TIME_VR}" description="Simulation time" causality="independent" variability="continuous" declaredType="Time" unit="s"/>"#
    )
    .unwrap();
    for v in &info.variables {
        writeln!(w, "    {}", variable(info, v)?).unwrap();
    }
    writeln!(w, "  </ModelVariables>").unwrap();

    // ModelStructure (FMI 3.0 §2.4.8; schema order Output, ContinuousStateDerivative,
    // InitialUnknown) names variables by value reference.
    let outputs = common::output_dependencies(info)?;
    let derivatives = common::derivative_dependencies(info)?;
    let vr = |j: &usize| info.variables[*j].value_reference;
    writeln!(w, "  <ModelStructure>").unwrap();
    for (tag, list) in [("Output", &outputs), ("ContinuousStateDerivative", &derivatives)] {
        for (i, deps) in list {
            let deps: Vec<String> = deps.iter().map(|j| vr(j).to_string()).collect();
            writeln!(w, r#"    <{tag} valueReference="{}" dependencies="{}"/>"#, vr(i), deps.join(" ")).unwrap();
        }
    }
    for i in common::initial_unknowns(info)? {
        writeln!(w, r#"    <InitialUnknown valueReference="{}"/>"#, vr(&i)).unwrap();
    }
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
