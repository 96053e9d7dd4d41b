//! The committed modelDescription/*.xml must equal the generator's output, so that a
//! change of the variable table cannot go unnoticed. To accept a deliberate change:
//! `UPDATE_MODEL_DESCRIPTION=1 cargo test --test model_description`.

use pinjoint::fmi2::variables::Causality;
use pinjoint::fmi2::xml::model_description;
use pinjoint::fmu::registry;
use std::path::Path;

#[test]
fn committed_model_descriptions_match_the_generator() {
    for info in registry() {
        let generated = model_description(info).unwrap();
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("modelDescription").join(format!("{}.xml", info.model_identifier));
        if std::env::var_os("UPDATE_MODEL_DESCRIPTION").is_some() {
            std::fs::write(&path, &generated).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == generated,
            "{} differs from the generator's output; if the change is intended, run \
             UPDATE_MODEL_DESCRIPTION=1 cargo test --test model_description and commit the file",
            path.display()
        );
    }
}

#[test]
fn pin_joint_table_is_complete_and_consistent() {
    let info = &*pinjoint::fmu::pin_joint::INFO;
    let names: Vec<&str> = info.variables.iter().map(|v| v.name.as_str()).collect();
    for s in pinjoint::params::PARAMS.iter() {
        let v = &info.variables[info.index_by_name(&s.name()).unwrap_or_else(|| panic!("{} missing", s.name()))];
        assert_eq!(v.start, Some(s.default_value()), "{}", v.name);
        assert_eq!(v.causality, Causality::Parameter);
    }
    for n in ["angle", "angular_velocity", "load", "temperature"] {
        assert_eq!(info.variables[info.index_by_name(n).unwrap()].causality, Causality::Input, "{n}");
    }
    for n in [
        "torque", "friction_coefficient", "film_thickness", "lambda_ratio", "fluid_load_fraction",
        "asperity_load_fraction", "mean_pressure", "sommerfeld_number", "power_loss", "dissipated_energy",
        "min_film_thickness", "min_lambda_ratio",
    ] {
        assert_eq!(info.variables[info.index_by_name(n).unwrap()].causality, Causality::Output, "{n}");
    }
    assert!(names.contains(&"zero_velocity.speed_band"));
    let mut vrs: Vec<u32> = info.variables.iter().map(|v| v.value_reference).collect();
    vrs.sort();
    vrs.dedup();
    assert_eq!(vrs.len(), info.variables.len(), "value references are unique");
    for v in &info.variables {
        assert!(!v.description.is_empty(), "{} has no description", v.name);
        if let Some(u) = v.unit {
            assert!(info.unit(u).is_some(), "unit {u} of {} is not defined", v.name);
        }
    }
    // Every defined unit is used.
    for u in info.units {
        assert!(info.variables.iter().any(|v| v.unit == Some(u.name)), "unit {} unused", u.name);
    }
}

#[test]
fn output_dependencies_are_the_physical_ones() {
    let xml = model_description(&pinjoint::fmu::pin_joint::INFO).unwrap();
    let info = &*pinjoint::fmu::pin_joint::INFO;
    let idx = |n: &str| info.index_by_name(n).unwrap() + 1;
    let line = |n: &str| format!(r#"<Unknown index="{}" dependencies="#, idx(n));
    let deps = |n: &str| {
        let l = xml.lines().find(|l| l.contains(&line(n))).unwrap();
        l.split("dependencies=\"").nth(1).unwrap().split('"').next().unwrap().to_owned()
    };
    // The lubricant temperature input changes η0 and α: every friction output depends on it.
    let speed_load = format!("{} {} {}", idx("angular_velocity"), idx("load"), idx("temperature"));
    assert_eq!(deps("torque"), speed_load);
    assert_eq!(deps("power_loss"), speed_load);
    assert_eq!(deps("min_film_thickness"), speed_load);
    assert!(xml.contains(r#"<DisplayUnit name="degC" factor="1.0" offset="-273.15"/>"#), "temperature displayed in degC");
    assert_eq!(deps("mean_pressure"), idx("load").to_string());
    assert_eq!(deps("dissipated_energy"), "");
    assert!(!xml.contains(&format!(" {}\"", idx("angle"))), "no output depends on angle");
}
