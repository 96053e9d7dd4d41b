//! The modelDescription.xml generator: everything in it comes from a model's
//! [`ModelInfo`] (variable table, units, default experiment) and this layer's
//! capabilities and log categories, so the file and the FMU's behaviour agree.
//!
//! ModelStructure: `<Outputs>` lists each output with the inputs it depends on
//! directly (the model's `depends_on`; an empty list means it depends on no input
//! at the same instant, as for an integral). `<InitialUnknowns>` lists the outputs
//! (all `initial="calculated"`) without a `dependencies` attribute, which the
//! standard reads as "depends on every known" — exact here, since at
//! initialization every output may depend on every parameter.

use super::logging::Category;
use super::variables::{Causality, Kind, ModelInfo, Variable, CAPABILITIES, ME_CAPABILITIES};
use std::fmt::Write;

/// Escape text for an XML attribute value.
pub fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            c => o.push(c),
        }
    }
    o
}

/// Shortest text that reads back to the same f64 (an xs:double).
pub fn num(v: f64) -> String {
    format!("{v:?}")
}

/// The type element of a variable: `<Real .../>`, `<Integer .../>` or `<Boolean .../>`.
fn type_element(info: &ModelInfo, v: &Variable) -> String {
    let mut a = String::new();
    if let Kind::Enumeration(t) = v.kind {
        write!(a, " declaredType=\"{}\"", escape(t.name)).unwrap();
    }
    if v.kind == Kind::Real {
        if let Some(q) = v.unit.and_then(|u| info.unit(u)).map(|u| u.quantity) {
            write!(a, " declaredType=\"{}\"", escape(q)).unwrap();
        }
        if let Some(u) = v.unit {
            write!(a, " unit=\"{}\"", escape(u)).unwrap();
        }
        if let Some(d) = v.display_unit {
            write!(a, " displayUnit=\"{}\"", escape(d)).unwrap();
        }
    }
    let value = |x: f64| match v.kind {
        Kind::Real => num(x),
        Kind::Integer | Kind::Enumeration(_) => format!("{}", x as i64),
        Kind::Boolean => (x != 0.0).to_string(),
    };
    if v.kind != Kind::Boolean {
        if let Some(m) = v.min {
            write!(a, " min=\"{}\"", value(m)).unwrap();
        }
        if let Some(m) = v.max {
            write!(a, " max=\"{}\"", value(m)).unwrap();
        }
    }
    if let Some(s) = v.start {
        write!(a, " start=\"{}\"", value(s)).unwrap();
    }
    format!("<{}{a}/>", v.kind.as_str())
}

/// The type definitions of FMI 2.0: one Real type per unit in use, named for its quantity
/// (`quantity` and `unit` on the type), and the enumeration types with their items.
/// Returns (type name, element) pairs; two units of one quantity are an error.
fn type_definitions(info: &ModelInfo) -> Result<Vec<(String, String)>, String> {
    let mut out: Vec<(String, String)> = Vec::new();
    for u in info.units {
        if !info.variables.iter().any(|v| v.unit == Some(u.name)) {
            continue;
        }
        if out.iter().any(|(n, _)| n == u.quantity) {
            return Err(format!("two units have quantity {}: type names must be unique", u.quantity));
        }
        out.push((u.quantity.into(), format!(r#"<Real quantity="{}" unit="{}"/>"#, escape(u.quantity), escape(u.name))));
    }
    for t in info.enum_types() {
        let mut e = String::from("<Enumeration>");
        for (name, value, d) in t.items {
            write!(e, r#"<Item name="{}" value="{value}" description="{}"/>"#, escape(name), escape(d)).unwrap();
        }
        e.push_str("</Enumeration>");
        out.push((t.name.into(), e));
    }
    Ok(out)
}

/// The complete modelDescription.xml of `info`.
pub fn model_description(info: &ModelInfo) -> Result<String, String> {
    let mut x = String::new();
    let w = &mut x;
    writeln!(w, r#"<?xml version="1.0" encoding="UTF-8"?>"#).unwrap();
    writeln!(w, "<fmiModelDescription").unwrap();
    writeln!(w, r#"  fmiVersion="2.0""#).unwrap();
    writeln!(w, r#"  modelName="{}""#, escape(info.model_name)).unwrap();
    writeln!(w, r#"  guid="{}""#, info.guid()).unwrap();
    writeln!(w, r#"  description="{}""#, escape(info.description)).unwrap();
    writeln!(w, r#"  author="{}""#, escape(info.legal.author)).unwrap();
    writeln!(w, r#"  version="{}""#, escape(info.version)).unwrap();
    writeln!(w, r#"  copyright="{}""#, escape(info.legal.copyright)).unwrap();
    writeln!(w, r#"  license="{}""#, escape(info.legal.license)).unwrap();
    writeln!(w, r#"  generationTool="pinjoint fmi2 layer {}""#, env!("CARGO_PKG_VERSION")).unwrap();
    writeln!(w, r#"  variableNamingConvention="structured""#).unwrap();
    writeln!(w, r#"  numberOfEventIndicators="0">"#).unwrap();

    if info.model_exchange {
        write!(w, r#"  <ModelExchange modelIdentifier="{}""#, escape(info.model_identifier)).unwrap();
        for (k, v) in ME_CAPABILITIES {
            write!(w, "\n    {k}=\"{v}\"").unwrap();
        }
        writeln!(w, "/>").unwrap();
    }
    write!(w, r#"  <CoSimulation modelIdentifier="{}""#, escape(info.model_identifier)).unwrap();
    for (k, v) in CAPABILITIES {
        write!(w, "\n    {k}=\"{v}\"").unwrap();
    }
    writeln!(w, "/>").unwrap();

    // The schema requires at least one <Unit> inside <UnitDefinitions>.
    if !info.units.is_empty() {
        writeln!(w, "  <UnitDefinitions>").unwrap();
        for u in info.units {
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
        writeln!(w, "  </UnitDefinitions>").unwrap();
    }

    let types = type_definitions(info)?;
    if !types.is_empty() {
        writeln!(w, "  <TypeDefinitions>").unwrap();
        for (name, body) in types {
            writeln!(w, r#"    <SimpleType name="{}">"#, escape(&name)).unwrap();
            writeln!(w, "      {body}").unwrap();
            writeln!(w, "    </SimpleType>").unwrap();
        }
        writeln!(w, "  </TypeDefinitions>").unwrap();
    }

    writeln!(w, "  <LogCategories>").unwrap();
    for c in Category::ALL {
        writeln!(w, r#"    <Category name="{}" description="{}"/>"#, c.name(), escape(c.description())).unwrap();
    }
    writeln!(w, "  </LogCategories>").unwrap();

    let (t0, t1, dt) = info.default_experiment;
    writeln!(w, r#"  <DefaultExperiment startTime="{}" stopTime="{}" stepSize="{}"/>"#, num(t0), num(t1), num(dt)).unwrap();

    writeln!(w, "  <ModelVariables>").unwrap();
    for (i, v) in info.variables.iter().enumerate() {
        if v.kind != Kind::Real && (v.unit.is_some() || v.display_unit.is_some()) {
            return Err(format!("variable {}: only Real variables have units", v.name));
        }
        if let Some(u) = v.unit {
            let def = info.unit(u).ok_or_else(|| format!("variable {}: unit {u} is not in the unit table", v.name))?;
            if let Some(d) = v.display_unit
                && !def.display.iter().any(|x| x.name == d)
            {
                return Err(format!("variable {}: display unit {d} is not defined for unit {u}", v.name));
            }
        }
        let initial = match v.causality {
            Causality::Input => String::new(),
            _ => format!(r#" initial="{}""#, v.initial.as_str()),
        };
        writeln!(w, "    <!-- index {} -->", i + 1).unwrap();
        writeln!(
            w,
            r#"    <ScalarVariable name="{}" valueReference="{}" description="{}" causality="{}" variability="{}"{initial}>"#,
            escape(&v.name),
            v.value_reference,
            escape(&v.description),
            v.causality.as_str(),
            v.variability.as_str()
        )
        .unwrap();
        writeln!(w, "      {}", type_element(info, v)).unwrap();
        writeln!(w, "    </ScalarVariable>").unwrap();
    }
    writeln!(w, "  </ModelVariables>").unwrap();

    writeln!(w, "  <ModelStructure>").unwrap();
    writeln!(w, "    <Outputs>").unwrap();
    let outputs: Vec<usize> =
        info.variables.iter().enumerate().filter(|(_, v)| v.causality == Causality::Output).map(|(i, _)| i).collect();
    for &i in &outputs {
        let mut deps = Vec::new();
        for name in &info.variables[i].depends_on {
            let j = info.index_by_name(name).ok_or_else(|| format!("{} depends on unknown variable {name}", info.variables[i].name))?;
            if info.variables[j].causality != Causality::Input {
                return Err(format!("{} may only depend on inputs, not on {name}", info.variables[i].name));
            }
            deps.push((j + 1).to_string());
        }
        writeln!(w, r#"      <Unknown index="{}" dependencies="{}"/>"#, i + 1, deps.join(" ")).unwrap();
    }
    writeln!(w, "    </Outputs>").unwrap();
    writeln!(w, "    <InitialUnknowns>").unwrap();
    for &i in &outputs {
        writeln!(w, r#"      <Unknown index="{}"/>"#, i + 1).unwrap();
    }
    writeln!(w, "    </InitialUnknowns>").unwrap();
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
