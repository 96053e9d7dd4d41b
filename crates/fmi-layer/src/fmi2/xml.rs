//! The modelDescription.xml generator: everything in it comes from a model's
//! [`ModelInfo`] (variable table, units, default experiment) and this layer's
//! capabilities and log categories, so the file and the FMU's behaviour agree.
//!
//! ModelStructure (FMI 2.0 §2.2.8): `<Outputs>` lists each output with the inputs and
//! continuous states it depends on directly (the model's `depends_on`; an empty list means it
//! depends on none at the same instant, as for an integral). `<Derivatives>` (only when the
//! model has continuous states) lists each state derivative, in state order, with its direct
//! dependencies. `<InitialUnknowns>` lists the outputs, states and state derivatives with
//! `initial="calculated"`, in ascending index order, without a `dependencies` attribute, which
//! the standard reads as "depends on every known" — exact here, since at initialization every
//! unknown may depend on every parameter.

use crate::core::variables::{ModelInfo, Variable, CAPABILITIES, ME_CAPABILITIES};
use crate::error::XmlError;
use crate::core::xml as common;
use std::fmt::Write;

pub use crate::core::xml::{escape, num};

/// The type element of a variable: `<Real .../>`, `<Integer .../>`, `<Boolean .../>` or
/// `<Enumeration .../>`; a state derivative's `<Real>` names its state by 1-based index
/// (`derivative`, FMI 2.0 §2.2.7).
fn type_element(info: &ModelInfo, v: &Variable) -> Result<String, XmlError> {
    let mut derivative = String::new();
    if let Some(state) = v.derivative_of {
        let x = info.index_by_name(state).ok_or_else(|| XmlError::UnknownState { derivative: v.name.clone(), state })?;
        derivative = format!(r#" derivative="{}""#, x + 1);
    }
    Ok(format!("<{}{}{derivative}/>", v.kind.as_str(), common::type_attributes(info, v)?))
}

/// The capabilities of an interface element, `providesDirectionalDerivative` set to the
/// model's [`ModelInfo::directional_derivatives`].
fn capabilities(info: &ModelInfo, list: &'static [(&'static str, &'static str)]) -> Vec<(&'static str, &'static str)> {
    let provides = if info.directional_derivatives { "true" } else { "false" };
    let not_needed = if info.step_events { "false" } else { "true" };
    list.iter()
        .map(|&(k, v)| match k {
            "providesDirectionalDerivative" => (k, provides),
            "completedIntegratorStepNotNeeded" => (k, not_needed),
            _ => (k, v),
        })
        .collect()
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
        common::interface(w, "ModelExchange", info, &capabilities(info, ME_CAPABILITIES));
    }
    common::interface(w, "CoSimulation", info, &capabilities(info, CAPABILITIES));

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

    common::log_categories(w, super::types::status_name);
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

    // ModelStructure (FMI 2.0 §2.2.8; schema order Outputs, Derivatives, InitialUnknowns):
    // indices count the variables from 1.
    let outputs = common::output_dependencies(info)?;
    let derivatives = common::derivative_dependencies(info)?;
    let unknown = |w: &mut String, (i, deps): &(usize, Vec<usize>)| {
        let deps: Vec<String> = deps.iter().map(|j| (j + 1).to_string()).collect();
        writeln!(w, r#"      <Unknown index="{}" dependencies="{}"/>"#, i + 1, deps.join(" ")).unwrap();
    };
    writeln!(w, "  <ModelStructure>").unwrap();
    writeln!(w, "    <Outputs>").unwrap();
    outputs.iter().for_each(|u| unknown(w, u));
    writeln!(w, "    </Outputs>").unwrap();
    if !derivatives.is_empty() {
        writeln!(w, "    <Derivatives>").unwrap();
        derivatives.iter().for_each(|u| unknown(w, u));
        writeln!(w, "    </Derivatives>").unwrap();
    }
    writeln!(w, "    <InitialUnknowns>").unwrap();
    for i in common::initial_unknowns(info)? {
        writeln!(w, r#"      <Unknown index="{}"/>"#, i + 1).unwrap();
    }
    writeln!(w, "    </InitialUnknowns>").unwrap();
    writeln!(w, "  </ModelStructure>").unwrap();
    writeln!(w, "</fmiModelDescription>").unwrap();
    Ok(x)
}
