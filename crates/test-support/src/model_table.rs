//! The consistency every model's variable table must have (model_description.rs for
//! PinJoint, rig_model_description.rs for PinJointRig).

use fmi_layer::core::variables::ModelInfo;

/// Value references are unique, every variable has a description and a defined unit (if
/// any), and every defined unit is used.
pub fn assert_consistent(info: &ModelInfo) {
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
    for u in info.units {
        assert!(info.variables.iter().any(|v| v.unit == Some(u.name)), "unit {} unused", u.name);
    }
}
