//! What each shim supplies for its standard, the core naming neither: the type rule of its
//! getters and setters, the capability message, its status names and (FMI 2.0) the codes of
//! the status kinds.

use crate::core::types::{Status, StatusKind};
use crate::core::variables::{EnumType, Kind};
use crate::{fmi2, fmi3};

static E: EnumType = EnumType { name: "E", description: "", items: &[] };

#[test]
fn each_standard_has_its_own_access_rule() {
    let kinds = [Kind::Real, Kind::Integer, Kind::Boolean, Kind::Enumeration(&E)];
    for variable in kinds {
        for requested in kinds {
            let same = std::mem::discriminant(&variable) == std::mem::discriminant(&requested);
            // FMI 3.0: each type through its own functions only (Enumeration as Int64).
            assert_eq!((fmi3::api::common::RULES.accessed_as)(variable, requested), same, "fmi3 {variable:?} as {requested:?}");
            // FMI 2.0: the same, and an Enumeration also through the Integer functions
            // (never the other way round).
            let fmi2 = same || (matches!(variable, Kind::Enumeration(_)) && requested == Kind::Integer);
            assert_eq!((fmi2::api::common::RULES.accessed_as)(variable, requested), fmi2, "fmi2 {variable:?} as {requested:?}");
        }
    }
    assert!(fmi2::api::common::RULES.no_directional_derivatives.ends_with("(providesDirectionalDerivative = false)"));
    assert!(fmi3::api::common::RULES.no_directional_derivatives.ends_with("(providesDirectionalDerivatives = false)"));
}

#[test]
fn status_names_differ_only_in_the_prefix() {
    for s in [Status::Ok, Status::Warning, Status::Discard, Status::Error, Status::Fatal] {
        let (a, b) = (fmi2::types::status_name(s), fmi3::types::status_name(s));
        assert!(a.starts_with("fmi2") && b.starts_with("fmi3"), "{a} {b}");
        assert_eq!(a[4..], b[4..]);
    }
    assert_eq!(fmi2::types::status_name(Status::Error), "fmi2Error");
    assert_eq!(fmi2::types::status_name(Status::Pending), "fmi2Pending");
}

#[test]
fn fmi2_status_kind_codes_map_to_the_core_kinds() {
    // fmi2StatusKind: fmi2DoStepStatus = 0 … fmi2Terminated = 3 (fmi2FunctionTypes.h).
    for (code, kind) in StatusKind::ALL.into_iter().enumerate() {
        assert_eq!(fmi2::types::status_kind(code as i32), Ok(kind));
    }
    for code in [-1, 4, 7, i32::MAX, i32::MIN] {
        assert_eq!(fmi2::types::status_kind(code), Err(code));
    }
}
