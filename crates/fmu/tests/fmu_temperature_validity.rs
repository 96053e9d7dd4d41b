//! PinJoint FMU (FMI 2.0 Co-Simulation, through the Rust test host): a changing
//! `temperature` input gives, at every step, bit for bit the outputs of an instance started
//! at that temperature (random temperatures, loads, speeds and step patterns, every
//! fidelity's full path); the `validity` output at each boundary of the envelope and on
//! both sides; one log message per excursion; bad temperatures refused by name.

use test_support::fmi2_host as common;
use common::*;
use pinjoint::validity::{self, Validity};
use proptest::prelude::*;
use test_support::strategies::log10_uniform as log_uniform;

/// Every output but the accumulated energy, as bits.
fn outputs_bits(c: fmi_layer::fmi2::types::Fmi2Component) -> Vec<u64> {
    let info = &pinjoint_fmu::pin_joint::INFO;
    info.variables
        .iter()
        .filter(|v| v.causality == fmi_layer::core::variables::Causality::Output && v.name != "dissipated_energy")
        .map(|v| try_get_in(info, c, &v.name).unwrap().to_bits())
        .collect()
}

fn temperature() -> impl Strategy<Value = f64> {
    prop_oneof![238.15f64..673.15, 240.0f64..380.0, prop::sample::select(vec![273.15, 288.15, 293.15, 298.15])]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A run whose temperature changes (slow drifts and jumps) steps to the outputs of a
    /// fresh instance initialized at that temperature and those inputs, bit for bit.
    #[test]
    fn a_changing_temperature_gives_a_fresh_instances_outputs(
        steps in prop::collection::vec((temperature(), log_uniform(1e3, 2e5), prop_oneof![Just(0.0), -6.0f64..6.0, log_uniform(1e-4, 100.0)], 1usize..4), 1..6),
    ) {
        // The friction model's temperature path, not the presliding state's history: the band
        // (stateless) in both instances.
        let h = Host::new();
        let c = h.ready(&[BAND]);
        let mut t = 0.0;
        for (temp, load, w, drift_steps) in steps {
            // A drift of 1e-3 K per step ending at `temp`, then the comparison.
            for k in (0..drift_steps).rev() {
                let tk = (temp - 1e-3 * k as f64).max(238.15);
                prop_assert_eq!(set(c, "temperature", tk), OK);
                prop_assert_eq!(set(c, "load", load), OK);
                prop_assert_eq!(set(c, "angular_velocity", w), OK);
                let st = fmi_layer::fmi2::api::cosim::fmi2DoStep(c, t, 1e-3, 0);
                t += 1e-3;
                if st != OK {
                    // Near Roelands' pole a fresh instance refuses the same temperature.
                    let f = h.initialize(&[BAND, ("temperature", tk), ("load", load), ("angular_velocity", w)]).1;
                    prop_assert_ne!(f, OK);
                    return Ok(());
                }
            }
            let fresh = Host::new();
            let (f, status) = fresh.initialize(&[BAND, ("temperature", temp), ("load", load), ("angular_velocity", w)]);
            prop_assert_eq!(status, OK, "{}", fresh.last());
            fresh.step(f, 0.0, 1e-3);
            prop_assert_eq!(outputs_bits(c), outputs_bits(f), "T = {} K, P = {} N, omega = {} rad/s", temp, load, w);
            let expect = validity::of_point(load, w.abs() * 0.028, temp, false);
            prop_assert_eq!(get(c, "validity"), f64::from(expect.code()));
            free(f);
        }
        free(c);
    }
}

/// The `validity` output at each boundary of the envelope and one ulp either side, and
/// the log: one message per excursion.
#[test]
fn validity_output_at_every_boundary_and_one_log_per_excursion() {
    let w_max = validity::SLIDING_SPEED.hi / 0.028;
    let cases = [
        (5e3, 1.0, 293.15, Validity::Checked),
        (5e3f64.next_down(), 1.0, 293.15, Validity::Extrapolation),
        (60e3, 1.0, 293.15, Validity::Checked),
        (60e3f64.next_up(), 1.0, 293.15, Validity::Extrapolation),
        (-20e3, 0.0, 293.15, Validity::Checked),
        (20e3, -w_max, 293.15, Validity::Checked),
        (20e3, w_max * (1.0 + 1e-12), 293.15, Validity::Extrapolation),
        (20e3, 1.0, 288.15, Validity::Checked),
        (20e3, 1.0, 288.15f64.next_down(), Validity::Extrapolation),
        (20e3, 1.0, 298.15, Validity::Checked),
        (20e3, 1.0, 298.15f64.next_up(), Validity::Extrapolation),
        (20e3, 1.0, 273.15, Validity::Extrapolation),
        // The complete model (default): below 0 C an extrapolation, not known-wrong.
        (20e3, 1.0, 273.15f64.next_down(), Validity::Extrapolation),
        (20e3, 0.21, 243.15, Validity::Extrapolation),
        (0.0, 1.0, 293.15, Validity::Extrapolation),
    ];
    let h = Host::new();
    let c = logged(&h, &[]);
    let mut t = 0.0;
    let mut was_outside = false;
    for (k, (load, w, temp, expect)) in cases.into_iter().enumerate() {
        h.clear();
        for (n, v) in [("load", load), ("angular_velocity", w), ("temperature", temp)] {
            assert_eq!(set(c, n, v), OK, "{}", h.last());
        }
        h.step(c, t, t + 0.01);
        t += 0.01;
        assert_eq!(get(c, "validity"), f64::from(expect.code()), "case {k}: {load} N, {w} rad/s, {temp} K");
        let said: Vec<String> = h.messages().into_iter().filter(|m| m.text.starts_with("validity")).map(|m| m.text).collect();
        let outside = expect != Validity::Checked;
        assert_eq!(said.len(), usize::from(outside && !was_outside), "case {k}: {said:?}");
        if let Some(m) = said.first() {
            assert!(m.contains(&format!("validity {}", expect.code())), "{m}");
        }
        was_outside = outside;
        // Staying outside for more steps says nothing more.
        h.clear();
        h.step(c, t, t + 0.01);
        t += 0.01;
        assert!(h.messages().iter().all(|m| !m.text.starts_with("validity")));
    }
    free(c);
}

/// The cold soak through the FMU with the paper's model: the known-wrong flag and its message
/// say μ is too low.
#[test]
fn cold_soak_is_said_known_wrong() {
    let h = Host::new();
    let c = logged(&h, &[("model.paper", 1.0), ("temperature", 243.15), ("angular_velocity", 0.21)]);
    h.step(c, 0.0, 0.01);
    assert_eq!(get(c, "validity"), 2.0);
    let m = h.messages().into_iter().find(|m| m.text.starts_with("validity")).expect("logged");
    assert!(m.text.contains("too LOW") && m.text.contains("temperature = 243.15 K"), "{}", m.text);
    free(c);
}

/// Bad temperatures keep their clear error, and the instance keeps its outputs.
#[test]
fn bad_temperatures_are_refused() {
    let h = Host::new();
    let c = h.ready(&[]);
    h.step(c, 0.0, 0.01);
    let before = outputs_bits(c);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 138.15, 673.16] {
        h.clear();
        assert_ne!(set(c, "temperature", bad), OK, "{bad}");
        assert!(h.last().contains("input temperature = ") && h.last().contains(" K"), "{}", h.last());
        assert_eq!(get(c, "temperature"), 293.15);
    }
    h.step(c, 0.01, 0.02);
    assert_eq!(outputs_bits(c), before);
    free(c);
}

