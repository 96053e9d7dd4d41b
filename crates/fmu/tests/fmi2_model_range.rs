//! Found by fuzzing (fuzz/README.md): parameters that `Params::validate` accepts but for
//! which the load-sharing solve gave a negative film (too few, too small asperities to
//! carry the load above the mean plane). The core now refuses loads beyond the asperity
//! model's capacity; the FMU still checks every output against its declared min/max.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use pinjoint::{Joint, Params};


/// fuzz/findings/core/negative-film-at-rest: the library's value at rest, 20 kN.
fn sparse_asperities() -> [(&'static str, f64); 4] {
    [
        ("surface.asperity_density", 2.79296875e7),
        ("surface.asperity_radius", 1.328125e-8),
        ("surface.summit_height_std", 1.8331541852530975e-6),
        ("lubricant.viscosity", 6.593932009391239e-5),
    ]
}

/// [`sparse_asperities`] and the start load `load` (N).
fn sparse_asperities_at(load: f64) -> Vec<(&'static str, f64)> {
    let mut sets = sparse_asperities().to_vec();
    sets.push(("load", load));
    sets
}

#[test]
fn loads_beyond_the_asperity_capacity_are_refused_naming_it() {
    // Fuzz finding 2 is fixed in the core: with these parameters the asperities can carry
    // at most Joint::capacity() (≈ 723 N); beyond it the library returns an error instead
    // of a negative film, and the FMU refuses such a load.
    let mut p = Params::default();
    for (n, v) in sparse_asperities() {
        p.set_by_name(n, v).unwrap();
    }
    let j = Joint::new(&p).unwrap();
    let cap = j.capacity();
    assert!(cap > 1.0 && cap < 20e3, "capacity {cap}");
    let e = j.evaluate(20e3, 0.0).unwrap_err().to_string();
    assert!(e.contains("capacity"), "{e}");

    // Initialization at the start load 20 kN fails, naming the load and the capacity.
    let h = Host::new();
    let (c, status) = h.initialize(&sparse_asperities_at(20e3));
    assert_eq!(status, ERROR);
    assert!(h.last().contains("load = 20000 N") && h.last().contains("capacity"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };

    // Initialized at 1 N, a later load beyond the capacity is refused at fmi2SetReal and
    // the instance steps on with its previous inputs.
    let c = h.ready(&sparse_asperities_at(1.0));
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    let light = j.evaluate(1.0, 0.0).unwrap();
    assert_eq!(get(c, "film_thickness"), light.film_thickness);
    assert_eq!(set(c, "load", 20e3), ERROR);
    assert!(h.last().contains("capacity"), "{}", h.last());
    assert_eq!(fmi2DoStep(c, 0.1, 0.1, 0), OK);
    assert_eq!(get(c, "film_thickness"), light.film_thickness);
    unsafe { fmi2FreeInstance(c) };
}
