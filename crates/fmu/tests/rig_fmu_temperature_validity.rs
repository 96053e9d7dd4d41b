//! PinJointRig FMU (through the Rust test host): a temperature change continues bit for
//! bit as a rig restored at that temperature from the same state; the `validity` output
//! follows the sample and the stroke (frequency, amplitude) on both sides of every boundary;
//! one log message per excursion.

use test_support::rig_host;
use fmi_layer::fmi2::api::common::*;
use pinjoint::validity::{self, Validity};
use proptest::prelude::*;
use rig_host::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Run to t1, set a new temperature; a second instance gets the state at that moment
    /// (serialized and deserialized, so its rig is built afresh at the new temperature).
    /// Both then step on with the same pattern: the same outputs bit for bit.
    #[test]
    fn a_temperature_change_continues_as_a_fresh_rig(
        t1 in 0.05f64..0.8,
        temps in prop::collection::vec(prop_oneof![255.0f64..360.0, Just(293.15)], 1..4),
        step in prop::sample::select(vec![1e-3, 7e-3, 0.02]),
        fidelity in prop::sample::select(vec![0.0, 2.0]),
    ) {
        let h = new_host();
        let sets = [("fidelity", fidelity), ("tolerance", 1.0)];
        let a = ready(&h, &sets);
        let mut t = 0.0;
        while t < t1 {
            step_to(&h, a, &mut t, step);
        }
        for temp in temps {
            prop_assert_eq!(set(a, "temperature", temp), OK);
            let state = get_state(a);
            let bytes = serialize(a, state);
            let b = ready(&h, &sets);
            let restored = deserialize(b, &bytes).unwrap();
            prop_assert_eq!(unsafe { fmi2SetFMUstate(b, restored) }, OK);
            let mut tb = t;
            for _ in 0..20 {
                let oa = step_to(&h, a, &mut t, step);
                let ob = step_to(&h, b, &mut tb, step);
                prop_assert_eq!(oa.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), ob.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), "T = {} K at t = {} s", temp, t);
            }
            free(b);
        }
        free(a);
    }
}

fn new_host() -> Host {
    Host::for_model(&pinjoint_fmu::pin_joint_rig::INFO)
}

fn step_to(h: &Host, c: fmi_layer::fmi2::types::Fmi2Component, t: &mut f64, dt: f64) -> Vec<f64> {
    let o = step(h, c, *t, *t + dt);
    *t += dt;
    o
}

/// The validity of a sample, from its outputs, as the documentation defines it.
fn expected(c: fmi_layer::fmi2::types::Fmi2Component, temp: f64, frequency: f64, amplitude: f64) -> Validity {
    let (load, w) = (get(c, "load"), get(c, "angular_velocity"));
    validity::of_point(load, w.abs() * 0.028, temp, false).max(validity::of_stroke(frequency, amplitude))
}

/// The stroke's boundaries (frequency and amplitude) and the temperature's, both sides,
/// with a checked load: the output is the sample's and the stroke's validity at every step.
#[test]
fn validity_follows_the_sample_and_the_stroke() {
    let a40 = 40f64.to_radians();
    let cases = [
        (0.03, a40, 293.15),
        (0.03f64.next_down(), a40, 293.15),
        (0.3, a40, 293.15),
        (1.0f64.next_up(), a40, 293.15),
        (0.3, a40 * (1.0 + 2e-6), 293.15),
        (0.3, a40 * (1.0 - 2e-6), 293.15),
        (0.3, a40, 298.15),
        (0.3, a40, 298.15f64.next_up()),
        (0.3, a40, 273.15f64.next_down()),
    ];
    let h = new_host();
    for (k, (f, a, temp)) in cases.into_iter().enumerate() {
        let c = ready(&h, &[("frequency", f), ("amplitude", a), ("load", 20e3), ("temperature", temp)]);
        let mut t = 0.0;
        let mut seen = [false; 3];
        for _ in 0..200 {
            step_to(&h, c, &mut t, 0.01);
            let v = expected(c, temp, f, a);
            assert_eq!(get(c, "validity"), f64::from(v.code()), "case {k} at t = {t}");
            seen[usize::from(v.code())] = true;
        }
        let stroke_ok = validity::of_stroke(f, a) == Validity::Checked;
        if !stroke_ok || !(288.15..=298.15).contains(&temp) {
            assert!(!seen[0], "case {k}: never checked");
        }
        free(c);
    }
}

/// A load leaving 5-60 kN and coming back, twice: two validity messages, one per excursion.
#[test]
fn one_log_message_per_excursion() {
    let h = new_host();
    let c = logged(&h, &[("frequency", 0.3), ("load", 20e3)]);
    let mut t = 0.0;
    h.clear();
    for load in [20e3, 70e3, 80e3, 20e3, 30e3, 4e3, 3e3, 20e3] {
        assert_eq!(set(c, "load", load), OK);
        for _ in 0..5 {
            step_to(&h, c, &mut t, 0.01);
        }
    }
    let said: Vec<String> = h.messages().into_iter().filter(|m| m.text.starts_with("validity")).map(|m| m.text).collect();
    assert_eq!(said.len(), 2, "{said:?}");
    assert!(said[0].contains("load = 70000 N") && said[1].contains("load = 4000 N"), "{said:?}");
    free(c);
}

