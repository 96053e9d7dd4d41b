//! The PinJointRig variable table: complete (every `[rig]` key and every model
//! parameter, with the library's defaults), consistent (unique value references,
//! defined units, types) and with the physical output dependencies. The committed
//! modelDescription/PinJointRig.xml is checked by crates/fmu/tests/model_description.rs.

use fmi_layer::core::variables::{Causality, Kind, Variability};
use fmi_layer::fmi2::xml::model_description;
use pinjoint_fmu::pin_joint_rig::INFO;
use pinjoint::rig::{RigParams, RIG_PARAMS};

use test_support::model_table;

fn var(name: &str) -> &'static fmi_layer::core::variables::Variable {
    &INFO.variables[INFO.index_by_name(name).unwrap_or_else(|| panic!("{name} missing"))]
}

#[test]
fn every_rig_and_model_parameter_is_a_variable_with_its_default() {
    let d = RigParams::default();
    for s in RIG_PARAMS.iter() {
        let name = match s.key {
            "load" => {
                assert_eq!(var("load").causality, Causality::Input);
                assert_eq!(var("load").start, Some(d.load));
                continue;
            }
            "frequency" | "amplitude" => s.key.to_string(),
            _ => s.name(),
        };
        let v = var(&name);
        assert_eq!(v.causality, Causality::Parameter, "{name}");
        assert_eq!(v.variability, Variability::Fixed, "{name}");
        assert_eq!(v.start, Some((s.get)(&d)), "{name}");
        assert_eq!(v.unit, (s.unit != "1").then_some(s.unit), "{name}");
    }
    for s in pinjoint::params::PARAMS.iter() {
        assert_eq!(var(&s.name()).start, Some(s.default_value()), "{}", s.name());
    }
    assert!(matches!(var("rig.formulation").kind, Kind::Enumeration(t) if t.item(1) == Some("regularised")));
    assert!(matches!(var("rig.method").kind, Kind::Enumeration(t) if t.item(2) == Some("rk4")));
    assert_eq!(var("use_command_input").kind, Kind::Boolean);
    assert_eq!(var("amplitude").display_unit, Some("deg"));
}

#[test]
fn table_is_consistent() {
    model_table::assert_consistent(&INFO);
    for v in INFO.variables.iter().filter(|v| v.kind == Kind::Boolean && v.causality == Causality::Output) {
        assert_eq!(v.variability, Variability::Discrete, "{}", v.name);
    }
    // Neither model's GUID equals the other's; the binary serves both.
    assert_ne!(INFO.guid(), pinjoint_fmu::pin_joint::INFO.guid());
    assert_eq!(pinjoint_fmu::registry().len(), 3, "PinJoint, PinJointRig and the PassThrough benchmark baseline");
}

#[test]
fn output_dependencies_are_the_physical_ones() {
    let xml = model_description(&INFO).unwrap();
    let idx = |n: &str| INFO.index_by_name(n).unwrap() + 1;
    let deps = |n: &str| {
        let key = format!(r#"<Unknown index="{}" dependencies="#, idx(n));
        let l = xml.lines().find(|l| l.contains(&key)).unwrap();
        l.split("dependencies=\"").nth(1).unwrap().split('"').next().unwrap().to_owned()
    };
    for state in ["angle", "angular_velocity", "torque", "actuator_work", "friction_dissipation", "kinetic_energy"] {
        assert_eq!(deps(state), "", "{state} is a state");
    }
    // The lubricant temperature input changes the friction law at once, as the load does.
    for n in ["friction_torque", "friction_coefficient", "film_thickness", "fluid_load_fraction", "stuck", "min_film_thickness", "min_lambda_ratio"] {
        assert_eq!(deps(n), format!("{} {}", idx("load"), idx("temperature")), "{n}");
    }
    assert_eq!(deps("commanded_angle"), idx("command_angle").to_string());
    assert!(xml.contains(r#"<Boolean start="false"/>"#) && xml.contains(r#"<Enumeration declaredType="RigMethod" min="0" max="3" start="0"/>"#));
}
