//! Panic containment (test-only hook) and thread independence of instances.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::fmi2::api::force_panic_in;
use fmi_layer::fmi2::types::*;

const FATAL: i32 = 4;

#[test]
fn a_panic_inside_a_call_returns_fatal_and_is_logged() {
    let (h, c) = ready_pin_joint();
    force_panic_in("fmi2DoStep");
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), FATAL);
    let m = h.messages().into_iter().last().unwrap();
    assert_eq!(m.status, FATAL);
    assert_eq!(m.category, "logStatusFatal");
    assert!(m.text.contains("forced panic in fmi2DoStep"), "{}", m.text);
    // Fatal: everything but fmi2FreeInstance is refused.
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    assert_eq!(try_get(c, "torque"), Err(ERROR));
    assert_eq!(fmi2Reset(c), ERROR);
    unsafe { fmi2FreeInstance(c) };

    for f in ["fmi2GetReal", "fmi2SetReal", "fmi2ExitInitializationMode"] {
        let c = h.instantiate();
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        force_panic_in(f);
        let st = match f {
            "fmi2GetReal" => try_get(c, "torque").err().unwrap_or(OK),
            "fmi2SetReal" => set(c, "load", 1.0),
            _ => fmi2ExitInitializationMode(c),
        };
        assert_eq!(st, FATAL, "{f}");
        unsafe { fmi2FreeInstance(c) };
    }
}

#[test]
fn a_panic_in_instantiate_returns_null() {
    let h = Host::new();
    force_panic_in("fmi2Instantiate");
    assert!(h.instantiate_with("x", FMI2_CO_SIMULATION, &guid(), None, false).is_null());
    // The hook fired once; the next instantiation works.
    let c = h.instantiate();
    unsafe { fmi2FreeInstance(c) };
}

fn run(seed: usize) -> Vec<u64> {
    let h = Host::new();
    let c = h.ready(&[("load", 5e3 + 5e3 * seed as f64)]);
    let mut out = Vec::new();
    for k in 0..300 {
        let t = f64::from(k) * 0.01;
        assert_eq!(set(c, "angular_velocity", (1.0 + seed as f64) * (t * 3.0).sin()), OK);
        assert_eq!(fmi2DoStep(c, t, 0.01, 0), OK);
        out.extend(all_outputs(c).iter().map(|x| x.to_bits()));
    }
    unsafe { fmi2FreeInstance(c) };
    out
}

#[test]
fn eight_instances_on_eight_threads_equal_serial_runs() {
    let serial: Vec<Vec<u64>> = (0..8).map(run).collect();
    let threads: Vec<_> = (0..8).map(|i| std::thread::spawn(move || run(i))).collect();
    let parallel: Vec<Vec<u64>> = threads.into_iter().map(|t| t.join().unwrap()).collect();
    assert_eq!(serial, parallel);
    assert_ne!(serial[0], serial[1]);
}

#[test]
fn many_instantiate_step_free_cycles() {
    let h = Host::new();
    for k in 0..200 {
        let c = h.ready(&[("angular_velocity", 0.1 * f64::from(k))]);
        assert_eq!(fmi2DoStep(c, 0.0, 0.01, 0), OK);
        let mut s = get_state(c);
        assert_eq!(unsafe { fmi2FreeFMUstate(c, &mut s) }, OK);
        unsafe { fmi2FreeInstance(c) };
    }
}
