//! The committed modelDescription/*.xml must equal the generator's output, so that a
//! change of the variable table cannot go unnoticed. To accept a deliberate change:
//! `UPDATE_MODEL_DESCRIPTION=1 cargo test --test model_description`.

use fmi_layer::core::variables::Causality;
use fmi_layer::fmi2::xml::model_description;
use pinjoint_fmu::registry;

use test_support::model_table;

#[test]
fn committed_model_descriptions_match_the_generator() {
    for info in registry() {
        let generated = model_description(info).unwrap();
        let path = test_support::paths::workspace_root().join("modelDescription").join(format!("{}.xml", info.model_identifier));
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

/// The FMI 3.0 modelDescription of each model, from the same table, committed under
/// modelDescription/fmi3/ (same update switch).
#[test]
fn committed_fmi3_model_descriptions_match_the_generator() {
    for info in registry() {
        let generated = fmi_layer::fmi3::xml::model_description(info).unwrap();
        let dir = test_support::paths::workspace_root().join("modelDescription").join("fmi3");
        let path = dir.join(format!("{}.xml", info.model_identifier));
        if std::env::var_os("UPDATE_MODEL_DESCRIPTION").is_some() {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&path, &generated).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(committed == generated, "{} differs from the FMI 3.0 generator's output (UPDATE_MODEL_DESCRIPTION=1 to accept)", path.display());
        // Same token as the FMI 2.0 GUID; ME only where the model offers it; ASCII only.
        assert!(generated.contains(&format!("instantiationToken=\"{}\"", info.guid())));
        assert_eq!(generated.contains("<ModelExchange"), info.model_exchange);
        assert!(generated.is_ascii(), "{}: non-ASCII text", info.model_identifier);
    }
}

/// Vendor expectations (issue 11): no min="0.0" on a value that must be > 0; quantity on
/// every unit type; Enumeration for the choice parameters; ASCII display units.
#[test]
fn declared_ranges_and_types_follow_the_values_the_model_accepts() {
    for info in registry() {
        let xml = model_description(info).unwrap();
        assert!(xml.is_ascii(), "{}: non-ASCII text in the FMI 2.0 XML", info.model_identifier);
        assert_eq!(xml.contains("<ModelExchange"), info.model_exchange);
        for v in &info.variables {
            if v.description.contains("must be > 0") || v.description.contains("(> 0") || v.description.contains("must be positive") {
                assert!(v.min != Some(0.0), "{} {}: min 0 although it must be > 0", info.model_identifier, v.name);
            }
            if let Some(u) = v.unit {
                assert!(!info.unit(u).unwrap().quantity.is_empty());
                assert!(xml.contains(&format!(r#"<Real quantity="{}" unit="{u}"/>"#, info.unit(u).unwrap().quantity)));
            }
        }
    }
    let pj = &*pinjoint_fmu::pin_joint::INFO;
    for name in ["tolerance", "envelope.load_min", "pin_asperities.radius", "lubricant.viscosity"] {
        if let Some(i) = pj.index_by_name(name) {
            assert_eq!(pj.variables[i].min, None, "{name}");
        }
    }
    let fid = &pj.variables[pj.index_by_name("fidelity").unwrap()];
    assert!(matches!(fid.kind, fmi_layer::core::variables::Kind::Enumeration(t) if t.item(0) == Some("full") && t.item(3) == Some("auto")));
}

#[test]
fn pin_joint_table_is_complete_and_consistent() {
    let info = &*pinjoint_fmu::pin_joint::INFO;
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
        "min_film_thickness", "min_lambda_ratio", "validity",
    ] {
        assert_eq!(info.variables[info.index_by_name(n).unwrap()].causality, Causality::Output, "{n}");
    }
    assert!(names.contains(&"zero_velocity.speed_band"));
    model_table::assert_consistent(info);
}

#[test]
fn output_dependencies_are_the_physical_ones() {
    let xml = model_description(&pinjoint_fmu::pin_joint::INFO).unwrap();
    let info = &*pinjoint_fmu::pin_joint::INFO;
    let idx = |n: &str| info.index_by_name(n).unwrap() + 1;
    let line = |n: &str| format!(r#"<Unknown index="{}" dependencies="#, idx(n));
    let deps = |n: &str| {
        let l = xml.lines().find(|l| l.contains(&line(n))).unwrap();
        l.split("dependencies=\"").nth(1).unwrap().split('"').next().unwrap().to_owned()
    };
    // The lubricant temperature input changes η0 and α: every friction output depends on it.
    let speed_load = format!("{} {} {}", idx("angular_velocity"), idx("load"), idx("temperature"));
    // The friction outputs also depend on the presliding state and, under Co-Simulation, on
    // the angle (its increment since the last step deflects the state).
    let friction = format!("{} {} {} {} {}", idx("angle"), idx("angular_velocity"), idx("load"), idx("temperature"), idx("presliding_torque"));
    assert_eq!(deps("torque"), friction);
    assert_eq!(deps("power_loss"), friction);
    assert_eq!(deps("min_film_thickness"), speed_load);
    assert_eq!(deps("friction_coefficient"), speed_load);
    assert!(xml.contains(r#"<DisplayUnit name="degC" factor="1.0" offset="-273.15"/>"#), "temperature displayed in degC");
    assert_eq!(deps("mean_pressure"), idx("load").to_string());
    assert_eq!(deps("dissipated_energy"), "");
    // Only the friction outputs depend on the angle.
    let angle = idx("angle").to_string();
    let on_angle: Vec<&str> = xml
        .lines()
        .filter(|l| l.contains("<Unknown index=") && l.split("dependencies=\"").nth(1).is_some_and(|d| d.split('"').next().unwrap().split(' ').any(|x| x == angle)))
        .map(str::trim)
        .collect();
    let expect = [format!("{}\"{friction}\"/>", line("torque")), format!("{}\"{friction}\"/>", line("power_loss"))];
    assert_eq!(on_angle, expect);
    // One continuous state: der(presliding_torque), of the state, omega, P and T (not the
    // angle: under Model Exchange the host's state replaces it), the state's derivative.
    let state = format!("{} {} {} {}", idx("angular_velocity"), idx("load"), idx("temperature"), idx("presliding_torque"));
    let der = format!(r#"<Derivatives>
      <Unknown index="{}" dependencies="{state}"/>
    </Derivatives>"#, idx("der(presliding_torque)"));
    assert!(xml.contains(&der), "{der}");
    assert!(xml.contains(&format!(r#"derivative="{}""#, idx("presliding_torque"))));
    assert!(xml.matches("providesDirectionalDerivative=\"true\"").count() == 2, "ME and CS");
}
