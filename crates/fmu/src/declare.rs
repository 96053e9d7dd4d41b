//! The one constructor of a variable declaration for both FMUs' tables.

use fmi_layer::core::variables::{Causality, Initial, Kind, Variability, Variable};

/// A declaration with no start value, range, nominal, dependencies or derivative: parameters are `fixed`,
/// Boolean and Integer outputs `discrete`, everything else `continuous`; outputs are
/// `calculated`, inputs and parameters `exact`.
pub fn declare(
    name: &str,
    value_reference: u32,
    kind: Kind,
    causality: Causality,
    unit: Option<&'static str>,
    display_unit: Option<&'static str>,
    description: impl Into<String>,
) -> Variable {
    let variability = match (causality, kind) {
        (Causality::Parameter, _) => Variability::Fixed,
        (_, Kind::Real) => Variability::Continuous,
        _ => Variability::Discrete,
    };
    Variable {
        name: name.into(),
        kind,
        value_reference,
        causality,
        variability,
        initial: if causality == Causality::Output { Initial::Calculated } else { Initial::Exact },
        unit,
        display_unit,
        start: None,
        min: None,
        max: None,
        description: description.into(),
        depends_on: vec![],
        derivative_of: None,
        nominal: None,
    }
}
