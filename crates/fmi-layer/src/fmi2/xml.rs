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

use super::variables::{ModelInfo, Variable, CAPABILITIES, ME_CAPABILITIES};
use crate::error::XmlError;
use crate::xml as common;
use std::fmt::Write;

pub use crate::xml::{escape, num};

/// The type element of a variable: `<Real .../>`, `<Integer .../>`, `<Boolean .../>` or
/// `<Enumeration .../>`.
fn type_element(info: &ModelInfo, v: &Variable) -> Result<String, XmlError> {
    Ok(format!("<{}{}/>", v.kind.as_str(), common::type_attributes(info, v)?))
}

/// The type definitions of FMI 2.0: one Real type per unit in use, named for its quantity
/// (`quantity` and `unit` on the type), and the enumeration types with their items.
/// Returns (type name, element) pairs; two units of one quantity are an error.
fn type_definitions(info: &ModelInfo) -> Result<Vec<(String, String)>, XmlError> {
    let mut out: Vec<(String, String)> = Vec::new();
    for u in common::used_units(info, &[])? {
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
pub fn model_description(info: &ModelInfo) -> Result<String, XmlError> {
    let mut x = String::new();
    let w = &mut x;
    common::root_element(w, "2.0", "guid", "fmi2", info, &[("numberOfEventIndicators", "0")]);
    if info.model_exchange {
        common::interface(w, "ModelExchange", info, ME_CAPABILITIES);
    }
    common::interface(w, "CoSimulation", info, CAPABILITIES);

    // The schema requires at least one <Unit> inside <UnitDefinitions>.
    if !info.units.is_empty() {
        writeln!(w, "  <UnitDefinitions>").unwrap();
        for u in info.units {
            common::unit(w, u);
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

    common::log_categories(w, "fmi2");
    common::default_experiment(w, info);

    writeln!(w, "  <ModelVariables>").unwrap();
    for (i, v) in info.variables.iter().enumerate() {
        let element = type_element(info, v)?;
        writeln!(w, "    <!-- index {} -->", i + 1).unwrap();
        writeln!(w, "    <ScalarVariable{}>", common::variable_attributes(v)).unwrap();
        writeln!(w, "      {element}").unwrap();
        writeln!(w, "    </ScalarVariable>").unwrap();
    }
    writeln!(w, "  </ModelVariables>").unwrap();

    // ModelStructure indices count the variables from 1.
    let outputs = common::output_dependencies(info)?;
    writeln!(w, "  <ModelStructure>").unwrap();
    writeln!(w, "    <Outputs>").unwrap();
    for (i, deps) in &outputs {
        let deps: Vec<String> = deps.iter().map(|j| (j + 1).to_string()).collect();
        writeln!(w, r#"      <Unknown index="{}" dependencies="{}"/>"#, i + 1, deps.join(" ")).unwrap();
    }
    writeln!(w, "    </Outputs>").unwrap();
    writeln!(w, "    <InitialUnknowns>").unwrap();
    for (i, _) in &outputs {
        writeln!(w, r#"      <Unknown index="{}"/>"#, i + 1).unwrap();
    }
    writeln!(w, "    </InitialUnknowns>").unwrap();
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
