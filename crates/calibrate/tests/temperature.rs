//! Calibration across temperature (issue 28 item 6): records at known lubricant temperatures,
//! each evaluated by the joint at its temperature; records at three or more temperatures fit
//! the temperature-dependent keys by default ([`Options::across_temperature`]) with intervals,
//! a key the records cannot determine is dropped with a warning naming it, and the calibrated
//! parameters predict the torque at a temperature between the records.
//!
//! The truth changes a temperature relation's parameter from its default: here Roelands'
//! temperature–viscosity index S_0 (`lubricant.roelands_temperature_index`), through which the
//! base oil's viscosity, hence the film and the load shares, follow the temperature.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint::Params;
use pinjoint_calibrate::{calibrate, CalibrationError, Options, Record};

const S0: &str = "lubricant.roelands_temperature_index";
const MU: f64 = 0.105;
/// The truth's S_0: 10 % above the default 1.262.
const S0_TRUTH: f64 = 1.3882;
const LOAD: f64 = 20e3;

fn truth() -> Params {
    let mut p = Params::default();
    p.friction.boundary_friction_coefficient = MU;
    p.lubricant.roelands_temperature_index = S0_TRUTH;
    p
}

/// A rig record (`pinjoint cycle`'s simulation, breakaway factor 1.3, J = 0.05 kg·m²) at
/// `temperature` K, 1 Hz ±40°, 6 cycles of 1000 samples, with `noise` N·m of torque noise, a
/// 0.3 N·m offset and a 17-bit encoder; the record carries its temperature.
fn rig_at(temperature: f64, noise: f64, seed: u64) -> Record {
    let mut cfg = RigConfig { model: truth(), ..RigConfig::default() };
    cfg.model.lubricant.temperature = temperature;
    cfg.rig.load = LOAD;
    cfg.rig.frequency = 1.0;
    cfg.rig.breakaway_factor = 1.3;
    let s = run_cycles(&cfg, 6.0, 1000).expect("rig runs");
    let mut r = logged(&format!("rig {temperature} K"), &s, noise, 0.3, seed);
    r.temperature = Some(vec![temperature; r.len()]);
    r
}

/// The options of these tests: the default set across temperature is S_0 (the grease keys are
/// the library's default once the parameter table has them), J fitted.
fn options(across: &[&str]) -> Options {
    Options { across_temperature: across.iter().map(ToString::to_string).collect(), resamples: 200, ..Options::default() }
}

fn est<'a>(c: &'a pinjoint_calibrate::Calibration, key: &str) -> Option<&'a pinjoint_calibrate::Estimate> {
    c.estimates.iter().find(|e| e.key == key)
}

#[test]
fn three_temperatures_fit_the_temperature_relation_with_mu_c_and_drop_what_they_cannot_see() {
    let temps = [293.15, 313.15, 333.15];
    let records: Vec<Record> = temps.iter().enumerate().map(|(i, &t)| rig_at(t, 0.5, 11 + i as u64)).collect();
    // S_0, and a key the records cannot tell anything of: the grease's supply layer
    // h_oil(T) = h_oil(T_ref)·(η_b(T_ref)/η_b(T))^m (src/film/cold_supply.rs) is at or above its
    // 50 µm at T_ref at every record's temperature (20 to 60 °C, the oil thinner), tens of times
    // the film, so the contact is flooded and the exponent m moves the torque by less than
    // 1e-4 N·m per unit ln m: its standard error would be many times its value.
    let across = [S0, "grease.supply_exponent"];
    let c = calibrate(&records, &options(&across)).unwrap();
    for e in &c.estimates {
        println!("{} = {} [{}, {}] (se {:.3e})", e.key, e.value, e.ci95.0, e.ci95.1, e.standard_error);
    }
    for w in &c.warnings {
        println!("warning: {w}");
    }
    assert_eq!(c.temperatures, temps.to_vec());
    let s0 = est(&c, S0).expect("S_0 fitted by default");
    assert!(s0.ci95.0 <= S0_TRUTH && S0_TRUTH <= s0.ci95.1, "S_0 {s0:?}");
    assert!((s0.value / S0_TRUTH - 1.0).abs() < 0.01, "S_0 {}", s0.value);
    let mu = &c.estimates[0];
    assert!(mu.ci95.0 <= MU && MU <= mu.ci95.1 && (mu.value / MU - 1.0).abs() < 1e-3, "mu_c {mu:?}");
    // The exponent is dropped, named in a warning, and keeps its given value.
    for k in &across[1..] {
        assert!(c.warnings.iter().any(|w| w.starts_with(k) && w.contains("not fitted")), "{:?}", c.warnings);
        assert!(est(&c, k).is_none(), "{k} dropped and fitted");
        // A dropped key keeps its given value in the calibrated parameters.
        let spec = pinjoint::params::spec_by_name(k).unwrap();
        assert_eq!((spec.get)(&c.params), (spec.get)(&Params::default()), "{k}");
    }
    assert!(!c.warnings.iter().any(|w| w.starts_with(S0) && w.contains("not fitted")), "{:?}", c.warnings);
}

#[test]
fn two_temperatures_fit_mu_c_only_and_say_why() {
    let records = [rig_at(313.15, 0.5, 3), rig_at(333.15, 0.5, 4)];
    let c = calibrate(&records, &options(&[S0])).unwrap();
    assert_eq!(c.estimates.len(), 1, "{:?}", c.estimates);
    let w = c.warnings.iter().find(|w| w.contains("2 temperatures")).expect("a warning");
    assert!(w.contains(S0) && w.contains("3 or more") && w.contains("313.15, 333.15"), "{w}");
    // Named, S_0 is fitted from two temperatures (one relation, two unknowns with η_ref fixed).
    let named = Options { fit: vec![S0.into()], ..options(&[S0]) };
    let c = calibrate(&records, &named).unwrap();
    let s0 = est(&c, S0).expect("named");
    assert!(s0.ci95.0 <= S0_TRUTH && S0_TRUTH <= s0.ci95.1, "{s0:?}");
    assert!(!c.warnings.iter().any(|w| w.contains("one temperature")), "{:?}", c.warnings);
}

#[test]
fn a_temperature_relation_named_from_one_temperature_is_warned_about() {
    let records = [rig_at(313.15, 0.5, 5)];
    let named = Options { fit: vec![S0.into()], ..options(&[S0]) };
    let c = calibrate(&records, &named).unwrap();
    assert!(c.warnings.iter().any(|w| w.starts_with(S0) && w.contains("one temperature") && w.contains("313.15")), "{:?}", c.warnings);
    // Without any temperature given, nothing changes: no warning about temperatures.
    let mut r = rig_at(293.15, 0.5, 5);
    r.temperature = None;
    let c = calibrate(&[r], &options(&[S0])).unwrap();
    assert!(c.temperatures.is_empty() && !c.warnings.iter().any(|w| w.contains("temperature")), "{:?}", c.warnings);
    // The lubricant temperature itself cannot be fitted to records that give theirs.
    let e = calibrate(&records, &Options { fit: vec!["lubricant.temperature".into()], ..Options::default() }).unwrap_err();
    assert!(e.to_string().contains("lubricant.temperature") && e.to_string().contains("cannot be fitted"), "{e}");
}

#[test]
fn bad_temperatures_are_named_with_value_unit_and_a_hint() {
    let base = rig_at(293.15, 0.5, 6);
    let with = |t: f64, row: usize| {
        let mut r = base.clone();
        r.temperature.as_mut().unwrap()[row] = t;
        calibrate(&[r], &Options::default()).unwrap_err()
    };
    let e = with(f64::NAN, 17);
    assert!(matches!(e, CalibrationError::NonFinite { column: "temperature", row: 17, .. }), "{e}");
    assert!(e.to_string().contains("temperature = NaN K"), "{e}");
    for (t, words) in [
        (20.0, &["temperature = 20 K", "kelvin?", "293.15 K"][..]),
        (-5.0, &["temperature = -5 K", "> 0 K", "kelvin?", "268.15 K"][..]),
        (0.0, &["temperature = 0 K", "kelvin?"][..]),
        (120.0, &["temperature = 120 K", "kelvin?"][..]),
        // Plausible kelvin, outside the model's range: the model's own message.
        (200.0, &["temperature = 200 K", "lubricant.temperature"][..]),
        (900.0, &["temperature = 900 K", "lubricant.temperature"][..]),
    ] {
        let e = with(t, 3);
        let m = e.to_string();
        assert!(matches!(e, CalibrationError::Temperature { row: 3, .. }), "{m}");
        assert!(m.contains("rig 293.15 K") && words.iter().all(|w| m.contains(w)), "{m} lacks one of {words:?}");
    }
    let mut r = base.clone();
    r.temperature.as_mut().unwrap().pop();
    let e = calibrate(&[r], &Options::default()).unwrap_err();
    assert!(matches!(e, CalibrationError::Length { column: "temperature", .. }), "{e}");
}

#[test]
fn the_calibrated_parameters_predict_the_torque_between_the_temperatures() {
    let temps = [293.15, 313.15, 333.15];
    let records: Vec<Record> = temps.iter().enumerate().map(|(i, &t)| rig_at(t, 0.5, 21 + i as u64)).collect();
    let c = calibrate(&records, &options(&[S0])).unwrap();
    let fitted = c.params;
    let s0 = est(&c, S0).expect("fitted").clone();
    let mu = c.estimates[0].clone();
    // Between the records' temperatures, over the records' speeds and beyond their load: the
    // truth's torque within the interval propagated from the fitted keys' 95 % intervals
    // (|∂T/∂θ|·half-width summed over μ_c and S_0: the fit's correlation is left out, so this
    // is the wider, independent-errors bound).
    let mut worst: f64 = 0.0;
    for &t in &[303.15, 323.15] {
        for &(load, w) in &[(20e3, 1.5), (20e3, 4.0), (30e3, 3.0)] {
            let (want, got) = (torque(&truth(), load, w, t), torque(&fitted, load, w, t));
            let mut bound = 0.0;
            for (e, set) in [(&mu, 0usize), (&s0, 1)] {
                let at = |v: f64| {
                    let mut p = fitted;
                    if set == 0 { p.friction.boundary_friction_coefficient = v } else { p.lubricant.roelands_temperature_index = v }
                    torque(&p, load, w, t)
                };
                bound += (at(e.ci95.1) - at(e.ci95.0)).abs() / 2.0;
            }
            println!("T {t} K, {load} N, {w} rad/s: truth {want:.5} N.m, predicted {got:.5}, |diff| {:.2e}, interval +-{bound:.2e}", (got - want).abs());
            assert!((got - want).abs() <= bound, "{t} K {load} N {w} rad/s: {got} vs {want} (+-{bound})");
            worst = worst.max((got / want - 1.0).abs());
        }
    }
    assert!(worst < 2e-3, "relative error {worst}");
}

#[test]
fn the_intervals_of_s0_and_mu_c_cover_the_truth_over_seeds() {
    // Eight noise seeds, 0.5 N·m torque noise, three temperatures: the 95 % intervals must
    // cover the truth in at least 6 of 8 fits each (a true 95 % does so with probability 0.994).
    let temps = [293.15, 313.15, 333.15];
    let (mut cover_s0, mut cover_mu, mut z2) = (0, 0, 0.0);
    let n = 8;
    for seed in 0..n {
        let records: Vec<Record> = temps.iter().enumerate().map(|(i, &t)| rig_at(t, 0.5, 100 * seed + i as u64)).collect();
        let c = calibrate(&records, &options(&[S0])).unwrap();
        let s0 = est(&c, S0).unwrap();
        let mu = &c.estimates[0];
        cover_s0 += usize::from(s0.ci95.0 <= S0_TRUTH && S0_TRUTH <= s0.ci95.1);
        cover_mu += usize::from(mu.ci95.0 <= MU && MU <= mu.ci95.1);
        z2 += ((s0.value - S0_TRUTH) / s0.standard_error).powi(2);
        println!("seed {seed}: S_0 {} [{}, {}], mu_c {} [{}, {}]", s0.value, s0.ci95.0, s0.ci95.1, mu.value, mu.ci95.0, mu.ci95.1);
    }
    println!("S_0 covered {cover_s0}/{n}, mu_c {cover_mu}/{n}, rms z of S_0 {:.2}", (z2 / n as f64).sqrt());
    assert!(cover_s0 >= 6 && cover_mu >= 6, "S_0 {cover_s0}/{n}, mu_c {cover_mu}/{n}");
}

#[test]
fn the_same_fit_gives_the_same_bits() {
    // Parallel model evaluation and the two-way clusters' sums must not depend on timing or
    // on a hash map's order: the same records, fitted three times, give identical estimates.
    let records: Vec<Record> = [293.15, 313.15, 333.15].iter().enumerate().map(|(i, &t)| rig_at(t, 0.5, 40 + i as u64)).collect();
    let o = options(&[S0]);
    let a = calibrate(&records, &o).unwrap();
    for _ in 0..2 {
        let b = calibrate(&records, &o).unwrap();
        assert_eq!(a.estimates, b.estimates);
        assert_eq!((&a.inertia_estimate, &a.offset), (&b.inertia_estimate, &b.offset));
    }
}
