//! The FMI 3.0 modelDescription.xml generator, from the same [`ModelInfo`] as the FMI 2.0
//! one: variables, units, display units, quantities, enumeration types, log categories,
//! default experiment. ModelStructure: each output with the value references of the inputs
//! it depends on directly, and every output as an initial unknown (no `dependencies`: it may
//! depend on every parameter at initialization).

use crate::fmi2::logging::Category;
use crate::fmi2::variables::{Causality, Kind, ModelInfo, Variable};
use crate::fmi2::xml::{escape, num};
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

fn variable(info: &ModelInfo, v: &Variable) -> Result<String, String> {
    let mut a = format!(
        r#"<{} name="{}" valueReference="{}" description="{}" causality="{}" variability="{}""#,
        element(v.kind),
        escape(&v.name),
        v.value_reference,
        escape(&v.description),
        v.causality.as_str(),
        v.variability.as_str()
    );
    if v.causality != Causality::Input {
        write!(a, r#" initial="{}""#, v.initial.as_str()).unwrap();
    }
    if let Kind::Enumeration(t) = v.kind {
        write!(a, r#" declaredType="{}""#, escape(t.name)).unwrap();
    }
    if v.kind != Kind::Real && (v.unit.is_some() || v.display_unit.is_some()) {
        return Err(format!("variable {}: only Real variables have units", v.name));
    }
    if let Some(u) = v.unit {
        let def = info.unit(u).ok_or_else(|| format!("variable {}: unit {u} is not in the unit table", v.name))?;
        write!(a, r#" declaredType="{}" unit="{}""#, escape(def.quantity), escape(u)).unwrap();
        if let Some(d) = v.display_unit {
            if !def.display.iter().any(|x| x.name == d) {
                return Err(format!("variable {}: display unit {d} is not defined for unit {u}", v.name));
            }
            write!(a, r#" displayUnit="{}""#, escape(d)).unwrap();
        }
    }
    let value = |x: f64| match v.kind {
        Kind::Real => num(x),
        Kind::Integer | Kind::Enumeration(_) => format!("{}", x as i64),
        Kind::Boolean => (x != 0.0).to_string(),
    };
    if v.kind != Kind::Boolean {
        if let Some(m) = v.min {
            write!(a, r#" min="{}""#, value(m)).unwrap();
        }
        if let Some(m) = v.max {
            write!(a, r#" max="{}""#, value(m)).unwrap();
        }
    }
    if let Some(s) = v.start {
        write!(a, r#" start="{}""#, value(s)).unwrap();
    }
    a.push_str("/>");
    Ok(a)
}

/// The complete FMI 3.0 modelDescription.xml of `info` (Model Exchange if the model offers it,
/// and Co-Simulation).
pub fn model_description(info: &ModelInfo) -> Result<String, String> {
    let mut x = String::new();
    let w = &mut x;
    writeln!(w, r#"<?xml version="1.0" encoding="UTF-8"?>"#).unwrap();
    writeln!(w, "<fmiModelDescription").unwrap();
    writeln!(w, r#"  fmiVersion="3.0""#).unwrap();
    writeln!(w, r#"  modelName="{}""#, escape(info.model_name)).unwrap();
    writeln!(w, r#"  instantiationToken="{}""#, info.guid()).unwrap();
    writeln!(w, r#"  description="{}""#, escape(info.description)).unwrap();
    writeln!(w, r#"  author="{}""#, escape(info.legal.author)).unwrap();
    writeln!(w, r#"  version="{}""#, escape(info.version)).unwrap();
    writeln!(w, r#"  copyright="{}""#, escape(info.legal.copyright)).unwrap();
    writeln!(w, r#"  license="{}""#, escape(info.legal.license)).unwrap();
    writeln!(w, r#"  generationTool="pinjoint fmi3 layer {}""#, env!("CARGO_PKG_VERSION")).unwrap();
    writeln!(w, r#"  variableNamingConvention="structured">"#).unwrap();

    let mut iface = |tag: &str, own: &[(&str, &str)]| {
        write!(w, r#"  <{tag} modelIdentifier="{}""#, escape(info.model_identifier)).unwrap();
        for (k, v) in COMMON.iter().chain(own) {
            write!(w, "\n    {k}=\"{v}\"").unwrap();
        }
        writeln!(w, "/>").unwrap();
    };
    if info.model_exchange {
        iface("ModelExchange", ME);
    }
    iface("CoSimulation", CS);

    let used: Vec<_> = info.units.iter().filter(|u| info.variables.iter().any(|v| v.unit == Some(u.name))).collect();
    let has_seconds = used.iter().any(|u| u.name == "s");
    if !used.is_empty() {
        writeln!(w, "  <UnitDefinitions>").unwrap();
        for u in &used {
            writeln!(w, r#"    <Unit name="{}">"#, escape(u.name)).unwrap();
            let mut b = String::new();
            for (k, e) in [("kg", u.kg), ("m", u.m), ("s", u.s), ("K", u.k), ("rad", u.rad)] {
                if e != 0 {
                    write!(b, r#" {k}="{e}""#).unwrap();
                }
            }
            writeln!(w, "      <BaseUnit{b}/>").unwrap();
            for d in u.display {
                let off = if d.offset != 0.0 { format!(r#" offset="{}""#, num(d.offset)) } else { String::new() };
                writeln!(w, r#"      <DisplayUnit name="{}" factor="{}"{off}/>"#, escape(d.name), num(d.factor)).unwrap();
            }
            writeln!(w, "    </Unit>").unwrap();
        }
        if !has_seconds {
            writeln!(w, r#"    <Unit name="s"><BaseUnit s="1"/></Unit>"#).unwrap();
        }
        writeln!(w, "  </UnitDefinitions>").unwrap();
    } else {
        writeln!(w, r#"  <UnitDefinitions><Unit name="s"><BaseUnit s="1"/></Unit></UnitDefinitions>"#).unwrap();
    }

    let enums = info.enum_types();
    {
        writeln!(w, "  <TypeDefinitions>").unwrap();
        let mut names: Vec<&str> = Vec::new();
        if !has_seconds {
            writeln!(w, r#"    <Float64Type name="Time" quantity="Time" unit="s"/>"#).unwrap();
            names.push("Time");
        }
        for u in &used {
            if names.contains(&u.quantity) {
                return Err(format!("two units have quantity {}: type names must be unique", u.quantity));
            }
            names.push(u.quantity);
            writeln!(w, r#"    <Float64Type name="{}" quantity="{}" unit="{}"/>"#, escape(u.quantity), escape(u.quantity), escape(u.name)).unwrap();
        }
        for t in &enums {
            writeln!(w, r#"    <EnumerationType name="{}" description="{}">"#, escape(t.name), escape(t.description)).unwrap();
            for (name, value, d) in t.items {
                writeln!(w, r#"      <Item name="{}" value="{value}" description="{}"/>"#, escape(name), escape(d)).unwrap();
            }
            writeln!(w, "    </EnumerationType>").unwrap();
        }
        writeln!(w, "  </TypeDefinitions>").unwrap();
    }

    writeln!(w, "  <LogCategories>").unwrap();
    for c in Category::ALL {
        writeln!(w, r#"    <Category name="{}" description="{}"/>"#, c.name(), escape(&c.description().replace("fmi2", "fmi3"))).unwrap();
    }
    writeln!(w, "  </LogCategories>").unwrap();

    let (t0, t1, dt) = info.default_experiment;
    writeln!(w, r#"  <DefaultExperiment startTime="{}" stopTime="{}" stepSize="{}"/>"#, num(t0), num(t1), num(dt)).unwrap();

    writeln!(w, "  <ModelVariables>").unwrap();
    if info.index_of(TIME_VR).is_some() {
        return Err(format!("value reference {TIME_VR} is reserved for the independent variable time in FMI 3.0"));
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

    writeln!(w, "  <ModelStructure>").unwrap();
    let outputs: Vec<&Variable> = info.variables.iter().filter(|v| v.causality == Causality::Output).collect();
    for v in &outputs {
        let mut deps = Vec::new();
        for name in &v.depends_on {
            let j = info.index_by_name(name).ok_or_else(|| format!("{} depends on unknown variable {name}", v.name))?;
            if info.variables[j].causality != Causality::Input {
                return Err(format!("{} may only depend on inputs, not on {name}", v.name));
            }
            deps.push(info.variables[j].value_reference.to_string());
        }
        writeln!(w, r#"    <Output valueReference="{}" dependencies="{}"/>"#, v.value_reference, deps.join(" ")).unwrap();
    }
    for v in &outputs {
        writeln!(w, r#"    <InitialUnknown valueReference="{}"/>"#, v.value_reference).unwrap();
    }
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
