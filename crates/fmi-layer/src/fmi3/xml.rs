//! The FMI 3.0 modelDescription.xml generator, from the same [`ModelInfo`] as the FMI 2.0
//! one: variables, units, display units, quantities, enumeration types, log categories,
//! default experiment. ModelStructure: each output with the value references of the inputs
//! it depends on directly, and every output as an initial unknown (no `dependencies`: it may
//! depend on every parameter at initialization).

use crate::error::XmlError;
use crate::fmi2::variables::{Kind, ModelInfo, Variable};
use crate::xml::{self as common, escape};
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

/// One variable element, e.g. `<Float64 name=... unit=... start=.../>`.
fn variable(info: &ModelInfo, v: &Variable) -> Result<String, XmlError> {
    let types = common::type_attributes(info, v)?;
    Ok(format!("<{}{}{types}/>", element(v.kind), common::variable_attributes(v)))
}

/// The complete FMI 3.0 modelDescription.xml of `info` (Model Exchange if the model offers it,
/// and Co-Simulation).
pub fn model_description(info: &ModelInfo) -> Result<String, XmlError> {
    let mut x = String::new();
    let w = &mut x;
    common::root_element(w, "3.0", "instantiationToken", "fmi3", info, &[]);
    if info.model_exchange {
        common::interface(w, "ModelExchange", info, COMMON.iter().chain(ME));
    }
    common::interface(w, "CoSimulation", info, COMMON.iter().chain(CS));

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

    common::log_categories(w, "fmi3");
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

    // ModelStructure names variables by value reference.
    let outputs = common::output_dependencies(info)?;
    let vr = |j: &usize| info.variables[*j].value_reference;
    writeln!(w, "  <ModelStructure>").unwrap();
    for (i, deps) in &outputs {
        let deps: Vec<String> = deps.iter().map(|j| vr(j).to_string()).collect();
        writeln!(w, r#"    <Output valueReference="{}" dependencies="{}"/>"#, vr(i), deps.join(" ")).unwrap();
    }
    for (i, _) in &outputs {
        writeln!(w, r#"    <InitialUnknown valueReference="{}"/>"#, vr(i)).unwrap();
    }
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
