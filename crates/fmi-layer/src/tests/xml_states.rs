//! The modelDescription.xml of a model with a continuous state (FMI 2.0 §2.2.7-§2.2.8, FMI
//! 3.0 §2.4.7-§2.4.8), and the table errors the generators refuse. Set
//! `FMI_LAYER_DUMP_XML=<dir>` to write the two files there (for validation against the
//! standards' XSDs with an external tool).

use super::linear::*;
use crate::error::XmlError;
use crate::core::variables::{Causality, Initial, Kind, ModelInfo, Variability};

/// A change of a model table.
type Edit = Box<dyn Fn(&mut ModelInfo)>;

fn dump(name: &str, xml: &str) {
    if let Some(dir) = std::env::var_os("FMI_LAYER_DUMP_XML") {
        std::fs::write(std::path::Path::new(&dir).join(name), xml).unwrap();
    }
}

/// The text between `<tag>` and `</tag>` (or of the whole `<tag>` block for FMI 3.0).
fn between<'a>(xml: &'a str, open: &str, close: &str) -> &'a str {
    let a = xml.find(open).unwrap_or_else(|| panic!("{open} missing in\n{xml}"));
    let b = xml[a..].find(close).unwrap_or_else(|| panic!("{close} missing")) + a;
    &xml[a + open.len()..b]
}

fn lines(block: &str) -> Vec<&str> {
    block.lines().map(str::trim).filter(|l| !l.is_empty()).collect()
}

#[test]
fn fmi2_model_structure_lists_outputs_derivatives_and_initial_unknowns() {
    let xml = crate::fmi2::xml::model_description(&LINEAR).unwrap();
    dump("fmi2.xml", &xml);
    // x is variable 1, der(x) variable 3 (derivative of 1), y variable 4; both depend on x and u.
    assert!(xml.contains(r#"name="x" valueReference="1" description="x of the linear test system" causality="local" variability="continuous" initial="exact""#));
    assert!(xml.contains(r#"<Real nominal="10.0" start="2.0"/>"#), "{xml}");
    assert!(xml.contains(r#"<Real derivative="1"/>"#), "{xml}");
    assert_eq!(lines(between(&xml, "<Outputs>", "</Outputs>")), [r#"<Unknown index="4" dependencies="1 2"/>"#]);
    assert_eq!(lines(between(&xml, "<Derivatives>", "</Derivatives>")), [r#"<Unknown index="3" dependencies="1 2"/>"#]);
    // Outputs and derivatives with initial="calculated", ascending; x is exact, so a known.
    assert_eq!(lines(between(&xml, "<InitialUnknowns>", "</InitialUnknowns>")), [r#"<Unknown index="3"/>"#, r#"<Unknown index="4"/>"#]);
    assert!(xml.find("</Outputs>") < xml.find("<Derivatives>") && xml.find("</Derivatives>") < xml.find("<InitialUnknowns>"));
    assert_eq!(xml.matches(r#"providesDirectionalDerivative="true""#).count(), 2, "ModelExchange and CoSimulation");
    let without = crate::fmi2::xml::model_description(&LINEAR_NO_DD).unwrap();
    assert_eq!(without.matches(r#"providesDirectionalDerivative="false""#).count(), 2);
}

#[test]
fn fmi3_model_structure_lists_outputs_derivatives_and_initial_unknowns() {
    let xml = crate::fmi3::xml::model_description(&LINEAR).unwrap();
    dump("fmi3.xml", &xml);
    assert!(xml.contains(r#"<Float64 name="der(x)" valueReference="3" description="der(x) of the linear test system" causality="local" variability="continuous" initial="calculated" derivative="1"/>"#), "{xml}");
    assert!(xml.contains(r#"initial="exact" nominal="10.0" start="2.0"/>"#), "{xml}");
    assert_eq!(
        lines(between(&xml, "<ModelStructure>", "</ModelStructure>")),
        [
            r#"<Output valueReference="4" dependencies="1 2"/>"#,
            r#"<ContinuousStateDerivative valueReference="3" dependencies="1 2"/>"#,
            r#"<InitialUnknown valueReference="3"/>"#,
            r#"<InitialUnknown valueReference="4"/>"#,
        ]
    );
    assert_eq!(xml.matches(r#"providesDirectionalDerivatives="true""#).count(), 2);
    assert_eq!(xml.matches(r#"providesAdjointDerivatives="false""#).count(), 2);
}

/// A copy of the linear model's table changed by `edit`, through both generators.
fn generated(edit: impl Fn(&mut ModelInfo)) -> [Result<String, XmlError>; 2] {
    let mut info = ModelInfo { variables: table(), ..super::linear::info_for_tests() };
    edit(&mut info);
    [crate::fmi2::xml::model_description(&info), crate::fmi3::xml::model_description(&info)]
}

#[test]
fn tables_no_valid_state_can_be_written_from_are_refused() {
    let cases: Vec<(Edit, &str)> = vec![
        (Box::new(|i| i.variables[DX].derivative_of = Some("z")), "der(x) is declared the derivative of unknown variable z"),
        (Box::new(|i| i.variables[DX].derivative_of = Some("a")), "continuous state a must have variability \"continuous\""),
        (Box::new(|i| i.variables[DX].derivative_of = Some("u")), "continuous state u must have causality \"local\" or \"output\""),
        (Box::new(|i| i.variables[X].kind = Kind::Integer), "continuous state x must be a Real variable"),
        (Box::new(|i| i.variables[DX].initial = Initial::Exact), "state derivative der(x) must have initial \"calculated\""),
        (Box::new(|i| i.variables[DX].variability = Variability::Discrete), "state derivative der(x) must have variability \"continuous\""),
        (Box::new(|i| i.variables[DX].causality = Causality::Input), "state derivative der(x) must have causality \"local\" or \"output\""),
        (Box::new(|i| i.variables[Y].derivative_of = Some("x")), "x has two derivatives, der(x) and y"),
        (Box::new(|i| i.variables[Y].depends_on = vec!["a"]), "y may only depend on inputs and continuous states, not on a"),
        (Box::new(|i| i.variables[DX].depends_on = vec!["y"]), "der(x) may only depend on inputs and continuous states, not on y"),
    ];
    for (edit, text) in cases {
        for r in generated(edit) {
            assert_eq!(r.map(|_| ()).unwrap_err().to_string(), text);
        }
    }
    // The unchanged table is fine. Without derivative_of nothing is a state, so nothing may
    // depend on x any more.
    assert!(generated(|_| {}).iter().all(Result::is_ok));
    let [a, _] = generated(|i| i.variables[DX].derivative_of = None);
    assert_eq!(a.unwrap_err().to_string(), "y may only depend on inputs and continuous states, not on x");
    let [a, b] = generated(|i| {
        i.variables[DX].derivative_of = None;
        i.variables[Y].depends_on = vec!["u"];
    });
    assert!(!a.unwrap().contains("<Derivatives>") && !b.unwrap().contains("<ContinuousStateDerivative"));
}

#[test]
fn continuous_states_pair_each_state_with_its_derivative_in_derivative_order() {
    assert_eq!(LINEAR.continuous_states(), [(X, DX)]);
    let mut info = super::linear::info_for_tests();
    // A second state declared before the first one's derivative: order follows the derivatives.
    info.variables[Y].causality = Causality::Local;
    info.variables[Y].initial = Initial::Exact;
    info.variables[A].derivative_of = Some("y");
    assert_eq!(info.continuous_states(), [(X, DX), (Y, A)]);
    info.variables.swap(DX, A);
    assert_eq!(info.continuous_states(), [(Y, DX), (X, A)]);
}
