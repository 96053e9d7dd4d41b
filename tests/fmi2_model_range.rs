//! Found by fuzzing (fuzz/README.md): parameters that `Params::validate` accepts but for
//! which the load-sharing solve gives a negative film (too few, too small asperities to
//! carry the load above the mean plane). The FMU declares film_thickness and
//! lambda_ratio with min = 0, so it must not return such a value with fmi2OK: the
//! step (or initialization) fails with fmi2Error naming the output and its bound.

mod common;
use common::*;
use pinjoint::fmi2::api::common::*;
use pinjoint::fmi2::api::cosim::*;
use pinjoint::{Joint, Params};

const OK: i32 = 0;
const ERROR: i32 = 3;

/// fuzz/findings/core/negative-film-at-rest: the library's value at rest, 20 kN.
fn sparse_asperities() -> [(&'static str, f64); 4] {
    [
        ("surface.asperity_density", 2.79296875e7),
        ("surface.asperity_radius", 1.328125e-8),
        ("surface.summit_height_std", 1.8331541852530975e-6),
        ("lubricant.viscosity", 6.593932009391239e-5),
    ]
}

#[test]
fn an_output_below_its_declared_minimum_is_an_error_not_a_value() {
    let mut p = Params::default();
    for (n, v) in sparse_asperities() {
        p.set_by_name(n, v).unwrap();
    }
    let film = Joint::new(&p).unwrap().evaluate(20e3, 0.0).unwrap().film_thickness;
    // The trigger: open core finding 2 of fuzz/README.md. When the core no longer
    // returns a negative film here, replace the trigger by another out-of-range output.
    assert!(film < 0.0, "the core gives film_thickness = {film} here now; pick another trigger for this test");
    let h = Host::new();
    let c = h.instantiate();
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    for (n, v) in sparse_asperities() {
        assert_eq!(set(c, n, v), OK);
    }
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), ERROR);
    let m = h.last();
    assert!(m.contains("film_thickness = -") && m.contains("below its declared minimum 0"), "{m}");
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR, "error state");
    assert_eq!(fmi2Reset(c), OK);
    unsafe { fmi2FreeInstance(c) };

    // The same parameters at a speed where the film is positive initialize and step;
    // stepping into the bad point then fails the step and enters the error state.
    let c = h.instantiate();
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    for (n, v) in sparse_asperities() {
        assert_eq!(set(c, n, v), OK);
    }
    assert_eq!(set(c, "load", 1.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    let j = Joint::new(&p).unwrap();
    let light = j.evaluate(1.0, 0.0).unwrap();
    assert!(light.film_thickness >= 0.0, "{}", light.film_thickness);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    assert_eq!(get(c, "film_thickness"), light.film_thickness);
    assert_eq!(set(c, "load", 20e3), OK);
    assert_eq!(fmi2DoStep(c, 0.1, 0.1, 0), ERROR);
    assert!(h.last().contains("film_thickness") && h.last().contains("minimum"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}
