//! The grease's parameters fitted across temperature (issue 28 item 6) on the complete model:
//! rig records (`pinjoint cycle`'s simulation: breakaway peaks, servo, J = 0.05 kg·m²) made
//! with a known truth, the grease's parameters changed from their defaults (τ_y × 1.5, K × 0.7,
//! E_y/R × 1.25, E_K/R × 0.8), at 233.15, 243.15 and 293.15 K, 10 and 40 kN, 0.5 and 1.5 Hz,
//! 0.5 N·m of torque noise, a 0.3 N·m offset and a 17-bit encoder. With no key named, the
//! calibration fits μ_c and the grease's keys the records determine, each with its interval,
//! drops the flow index (the speeds span a factor 6, not a decade) with a warning naming it,
//! and the calibrated parameters predict the torque between the records' temperatures.
//!
//! The record temperatures avoid the rig's stick-slip. With the grease's oil supply (a starved
//! inlet fed by the bleed layer, src/film/cold_supply.rs) the torque falls steeply with speed
//! between about −25 and 5 °C: the layer, thick against the film when warm and thin when cold,
//! there lets the thickening oil lift the surfaces as the speed rises (at 40 kN, 0 °C, the
//! truth's torque falls from 114 to 85 N·m between 0.3 and 3 rad/s; at −20 °C from 108 to 35).
//! A falling friction–speed curve steeper than the servo's damping makes the rig stick and
//! slip: at 40 kN the records at 253.15 and 273.15 K (and 263.15 K at 10–40 kN, 0.5 Hz) move
//! irregularly, which the quasi-static model does not describe (the fit warns "stick-slip?").
//! At −40 and −30 °C the layer starves the contact at every speed (the torque rises with
//! speed, the grease's share large) and at 20 °C the slope is gentle: the fit is valid there.

mod common;
use common::*;
use pinjoint::rig::{run_cycles, RigConfig};
use pinjoint::Params;
use pinjoint_calibrate::{calibrate, Calibration, Estimate, Options, Record, MU_C};

const MU: f64 = 0.105;
const TEMPS: [f64; 3] = [233.15, 243.15, 293.15];

fn truth() -> Params {
    let mut p = Params::default();
    p.friction.boundary_friction_coefficient = MU;
    p.grease.yield_stress *= 1.5;
    p.grease.consistency *= 0.7;
    p.grease.yield_activation *= 1.25;
    p.grease.consistency_activation *= 0.8;
    p
}

/// A rig record of the truth at `t` K, `load` N, `f` Hz: 4 cycles of 400 samples.
fn rig_at(t: f64, load: f64, f: f64, noise: f64, seed: u64) -> Record {
    let mut cfg = RigConfig { model: truth(), ..RigConfig::default() };
    cfg.model.lubricant.temperature = t;
    cfg.rig.load = load;
    cfg.rig.frequency = f;
    cfg.rig.breakaway_factor = 1.3;
    let s = run_cycles(&cfg, 4.0, 400).expect("rig runs");
    let mut r = logged(&format!("rig {t} K {load} N {f} Hz"), &s, noise, 0.3, seed);
    r.temperature = Some(vec![t; r.len()]);
    r
}

fn records(temps: &[f64], seed: u64) -> Vec<Record> {
    let mut out = Vec::new();
    for &t in temps {
        for load in [10e3, 40e3] {
            for f in [0.5, 1.5] {
                out.push(rig_at(t, load, f, 0.5, seed + out.len() as u64));
            }
        }
    }
    out
}

fn get(p: &Params, key: &str) -> f64 {
    (pinjoint::params::spec_by_name(key).unwrap().get)(p)
}

fn est<'a>(c: &'a Calibration, key: &str) -> Option<&'a Estimate> {
    c.estimates.iter().find(|e| e.key == key)
}

#[test]
fn three_temperatures_fit_the_grease_with_mu_c_and_predict_between_them() {
    let c = calibrate(&records(&TEMPS, 1), &Options { resamples: 200, ..Options::default() }).unwrap();
    let t = truth();
    for e in &c.estimates {
        let k = if e.key == MU_C { MU } else { get(&t, &e.key) };
        println!("{} = {:.6e} [{:.6e}, {:.6e}] (se {:.3e}); truth {k}", e.key, e.value, e.ci95.0, e.ci95.1, e.standard_error);
    }
    for w in &c.warnings {
        println!("warning: {w}");
    }
    assert_eq!(c.temperatures, TEMPS.to_vec());
    // μ_c and the grease's keys the records determine, each interval holding the truth.
    assert_eq!(c.estimates[0].key, MU_C);
    let fitted: Vec<&str> = c.estimates[1..].iter().map(|e| e.key.as_str()).collect();
    for key in ["grease.yield_stress", "grease.yield_activation"] {
        assert!(fitted.contains(&key), "{key} not fitted: {fitted:?} {:?}", c.warnings);
    }
    for e in &c.estimates {
        let truth = if e.key == MU_C { MU } else { get(&t, &e.key) };
        assert!(e.ci95.0 <= truth && truth <= e.ci95.1, "{} = {} [{}, {}], truth {truth}", e.key, e.value, e.ci95.0, e.ci95.1);
        assert!(e.key.starts_with("grease.") || e.key == MU_C, "{}", e.key);
    }
    // Every default key not fitted is named in a warning, and keeps its given value.
    for key in pinjoint_calibrate::across::default_keys() {
        if est(&c, &key).is_none() {
            assert!(c.warnings.iter().any(|w| w.starts_with(&key) && w.contains("not fitted")), "{key}: {:?}", c.warnings);
            assert_eq!(get(&c.params, &key), get(&Params::default(), &key), "{key}");
        } else {
            assert_eq!(get(&c.params, &key), est(&c, &key).unwrap().value, "{key}");
        }
    }
    // The flow index: one frequency pair 3 apart, not a decade.
    assert!(est(&c, "grease.flow_index").is_none());
    // Between the records' temperatures, at their loads and speeds: the truth's torque within
    // the interval propagated from the fitted keys' 95 % intervals (|∂T/∂θ|·half-width summed
    // over the keys: the independent-errors bound, wider than the correlated one).
    for &temp in &[238.15, 268.15] {
        for &(load, w) in &[(10e3, 2.0), (40e3, 1.0), (25e3, 3.0)] {
            let (want, got) = (torque(&t, load, w, temp), torque(&c.params, load, w, temp));
            let mut bound = 0.0;
            for e in &c.estimates {
                let spec = pinjoint::params::spec_by_name(&e.key).unwrap();
                let at = |v: f64| {
                    let mut p = c.params;
                    (spec.set)(&mut p, v);
                    torque(&p, load, w, temp)
                };
                bound += (at(e.ci95.1) - at(e.ci95.0)).abs() / 2.0;
            }
            println!("{temp} K, {load} N, {w} rad/s: truth {want:.4} N.m, predicted {got:.4}, |diff| {:.3e}, interval +-{bound:.3e}", (got - want).abs());
            assert!((got - want).abs() <= bound, "{temp} K {load} N {w} rad/s: {got} vs {want} (+-{bound})");
            assert!((got / want - 1.0).abs() < 2e-3, "{temp} K: {got} vs {want}");
        }
    }
}

#[test]
fn two_temperatures_fit_mu_c_only_and_say_the_grease_needs_three() {
    let recs = records(&[253.15, 293.15], 7);
    let c = calibrate(&recs, &Options { resamples: 0, ..Options::default() }).unwrap();
    assert_eq!(c.estimates.len(), 1, "{:?}", c.estimates);
    let w = c.warnings.iter().find(|w| w.contains("2 temperatures")).expect("a warning");
    for k in ["grease.yield_activation", "grease.consistency_activation", "3 or more", "253.15, 293.15", "--fit"] {
        assert!(w.contains(k), "{w} lacks {k}");
    }
    assert_eq!(c.params.grease, Params::default().grease);
    // Named, the yield law (τ_y and its activation temperature) is fitted from two
    // temperatures, without the warning for one temperature. (The activation named alone, with
    // τ_y held at the default while the records' grease has 1.5× it, is not identifiable: the
    // yield torque τ_y(T)·2π·R²·B is the same at every load, so only the activation could take
    // up the room temperature's mismatch, which it cannot (it is 0 at T_ref); it drifts to its
    // bound and the fit says the normal matrix is singular.)
    let named = Options { fit: vec!["grease.yield_stress".into(), "grease.yield_activation".into()], resamples: 0, ..Options::default() };
    let c = calibrate(&recs, &named).unwrap();
    assert!(est(&c, "grease.yield_activation").is_some());
    assert!(!c.warnings.iter().any(|w| w.contains("one temperature")), "{:?}", c.warnings);
    // From one temperature it is warned about.
    let c = calibrate(&recs[..4], &named).unwrap();
    assert!(c.warnings.iter().any(|w| w.starts_with("grease.yield_activation") && w.contains("one temperature")), "{:?}", c.warnings);
}

/// Coverage over noise seeds (about 30 s a fit on this machine, so not in the default run:
/// `cargo test --release -p pinjoint-calibrate --test grease_fit -- --ignored`). Each seed new
/// noise and encoder phase on the same rig runs; every fitted key's interval must hold the
/// truth in at least 4 of 5 fits (a true 95 % does so with probability 0.977).
#[test]
#[ignore]
fn grease_intervals_cover_the_truth_over_seeds() {
    let t = truth();
    let n = 5;
    let mut tally: std::collections::BTreeMap<String, (usize, usize)> = Default::default();
    for seed in 0..n {
        let c = calibrate(&records(&TEMPS, 1000 * (seed + 1)), &Options { resamples: 200, ..Options::default() }).unwrap();
        for e in &c.estimates {
            let truth = if e.key == MU_C { MU } else { get(&t, &e.key) };
            let x = tally.entry(e.key.clone()).or_default();
            x.0 += usize::from(e.ci95.0 <= truth && truth <= e.ci95.1);
            x.1 += 1;
            println!("seed {seed}: {} = {:.5e} [{:.5e}, {:.5e}], truth {truth}", e.key, e.value, e.ci95.0, e.ci95.1);
        }
    }
    for (k, (covered, fits)) in &tally {
        println!("{k}: covered {covered}/{fits}");
    }
    for (k, (covered, fits)) in &tally {
        assert!(*fits >= 4 && *covered + 1 >= *fits, "{k}: {covered}/{fits}");
    }
}

#[test]
fn strokes_a_decade_apart_in_speed_fit_the_flow_index_too() {
    // Another truth (n = 0.6, K = 30 Pa·s^n, τ_y = 150 Pa, E_K/R = 3000 K), four temperatures
    // from -40 C, one load, strokes at 0.2 and 2 Hz: the speeds span more than a decade, so
    // every grease key is fitted, each interval holding the truth. The temperatures avoid the
    // stick-slip band between about -25 and 5 C (the module's comment; at 253.15 K the 0.2 Hz
    // strokes move irregularly): -40, -35 and -30 C, where the starved contact's torque rises
    // with speed and the grease carries much of it, and 20 C.
    let mut truth = Params::default();
    truth.friction.boundary_friction_coefficient = 0.11;
    (truth.grease.yield_stress, truth.grease.consistency, truth.grease.flow_index, truth.grease.consistency_activation) = (150.0, 30.0, 0.6, 3000.0);
    let mut recs = Vec::new();
    for t in [233.15, 238.15, 243.15, 293.15] {
        for f in [0.2, 2.0] {
            let mut cfg = RigConfig { model: truth, ..RigConfig::default() };
            cfg.model.lubricant.temperature = t;
            cfg.rig.load = 20e3;
            cfg.rig.frequency = f;
            let s = run_cycles(&cfg, 3.0, 400).expect("rig runs");
            let mut r = logged(&format!("rig {t} K {f} Hz"), &s, 0.2, 0.3, 77 + recs.len() as u64);
            r.temperature = Some(vec![t; r.len()]);
            recs.push(r);
        }
    }
    let c = calibrate(&recs, &Options { resamples: 200, ..Options::default() }).unwrap();
    for e in &c.estimates {
        println!("{} = {:.6e} [{:.6e}, {:.6e}]", e.key, e.value, e.ci95.0, e.ci95.1);
    }
    println!("{:?}", c.warnings);
    let keys: Vec<&str> = c.estimates.iter().map(|e| e.key.as_str()).collect();
    let mut want = vec![MU_C];
    want.extend(pinjoint_calibrate::across::GREASE_KEYS);
    assert_eq!(keys, want, "{:?}", c.warnings);
    for e in &c.estimates {
        let x = if e.key == MU_C { 0.11 } else { get(&truth, &e.key) };
        assert!(e.ci95.0 <= x && x <= e.ci95.1, "{} = {} [{}, {}], truth {x}", e.key, e.value, e.ci95.0, e.ci95.1);
    }
}
