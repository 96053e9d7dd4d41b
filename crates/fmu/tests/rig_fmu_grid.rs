//! PinJointRig integrates across communication steps: results at shared points do
//! not depend on the host's grid, and equal the rig library's, bit for bit, for the
//! same held inputs.

use test_support::rig_host;
use pinjoint::rig::{Inputs, RigConfig, RigSim, Sample};
use rig_host::*;

/// The FMU's outputs (table order) from a library sample.
fn expected(s: &Sample, joint: &pinjoint::Joint, cfg: &RigConfig) -> Vec<f64> {
    let contact = s.load > 0.0;
    // h_min and λ_min from the library's joint at the sample's state (0 without contact).
    let h_min = if contact { joint.min_film(s.load, s.angular_velocity, s.film_thickness, s.fluid_load_fraction) } else { 0.0 };
    let validity = f64::from(
        pinjoint::validity::of_point(s.load, s.angular_velocity.abs() * cfg.model.geometry.pin_radius, cfg.model.lubricant.temperature, cfg.model.model.paper)
            .max(pinjoint::validity::of_stroke(cfg.rig.frequency, cfg.rig.amplitude))
            .code(),
    );
    vec![
        s.angle,
        s.angular_velocity,
        s.torque,
        s.friction_torque,
        s.friction_coefficient,
        if contact { s.film_thickness } else { 0.0 },
        if contact { s.fluid_load_fraction } else { 0.0 },
        f64::from(u8::from(s.stuck)),
        s.command_angle,
        s.actuator_work,
        s.friction_dissipation,
        s.kinetic_energy,
        h_min,
        h_min / joint.composite_roughness(),
        // validity and its Integer mirror validity_code: the sample's operating point and the
        // sine stroke (pinjoint::validity).
        validity,
        validity,
    ]
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Run the FMU on the grid `times` with `load(t)` set at each point before the step
/// (held over it); outputs at every point.
fn fmu_run(sets: &[(&str, f64)], times: &[f64], load: &dyn Fn(f64) -> f64) -> Vec<Vec<f64>> {
    let h = new_host();
    let c = ready(&h, sets);
    assert_eq!(set(c, "load", load(times[0])), OK);
    let mut rows = vec![outputs(c)];
    for w in times.windows(2) {
        assert_eq!(set(c, "load", load(w[0])), OK);
        rows.push(step(&h, c, w[0], w[1]));
    }
    free(c);
    rows
}

fn library_run(cfg: &RigConfig, times: &[f64], load: &dyn Fn(f64) -> f64) -> Vec<Vec<f64>> {
    let mut sim = RigSim::new(cfg).unwrap();
    let joint = pinjoint::Joint::new(&cfg.model).unwrap();
    let mut rows = Vec::new();
    let mut held = load(times[0]);
    for &t in times {
        sim.advance_to(t, &Inputs { load: Some(held), command_angle: None }).unwrap();
        rows.push(expected(&sim.sample().unwrap(), &joint, cfg));
        held = load(t);
    }
    rows
}

fn grid(h: f64, stop: f64) -> Vec<f64> {
    let n = (stop / h).round() as usize;
    (0..=n).map(|k| k as f64 * h).collect()
}

/// 5 -> 60 kN at t = 0.5 s (a point of both grids), through reversals at 1 Hz.
fn load_step(t: f64) -> f64 {
    if t < 0.5 { 5e3 } else { 60e3 }
}

#[test]
fn one_ms_and_100_ms_hosts_agree_at_shared_points() {
    let fine = grid(1e-3, 1.5);
    let coarse = grid(0.1, 1.5);
    let a = fmu_run(&[], &fine, &load_step);
    let b = fmu_run(&[], &coarse, &load_step);
    let mut worst: f64 = 0.0;
    let mut exact = 0;
    for (j, t) in coarse.iter().enumerate() {
        let k = fine.iter().position(|x| (x - t).abs() < 1e-9).unwrap();
        if fine[k] == *t {
            // The same time bits: the same numbers.
            assert_eq!(bits(&a[k]), bits(&b[j]), "t = {t}");
            exact += 1;
        }
        for (x, y) in a[k].iter().zip(&b[j]) {
            let scale = x.abs().max(1e-3);
            worst = worst.max((x - y).abs() / scale);
        }
    }
    // Points whose times differ in the last bit (e.g. 3 * 0.1 vs 300 * 0.001) agree to 1e-12.
    assert!(worst <= 1e-12, "worst relative difference {worst:e}");
    assert!(exact >= 8, "{exact} bitwise-equal shared times");
    eprintln!("1 ms vs 100 ms: {exact} of {} shared points bit-identical, worst relative difference {worst:e}", coarse.len());
}

#[test]
fn outputs_equal_the_library_bit_for_bit() {
    let times: Vec<f64> = grid(0.01, 1.6).into_iter().chain([1.6137, 1.7, 2.2]).collect();
    let sets = [("rig.breakaway_factor", 1.2), ("friction.boundary_friction_coefficient", 0.1), ("frequency", 0.8)];
    let mut cfg = RigConfig::default();
    cfg.rig.breakaway_factor = 1.2;
    cfg.model.friction.boundary_friction_coefficient = 0.1;
    cfg.rig.frequency = 0.8;
    let fmu = fmu_run(&sets, &times, &load_step);
    let lib = library_run(&cfg, &times, &load_step);
    for (k, (x, y)) in fmu.iter().zip(&lib).enumerate() {
        assert_eq!(bits(x), bits(y), "t = {}: {x:?} vs {y:?}", times[k]);
    }
    // The run covers stick phases and slip in both directions.
    assert!(fmu.iter().any(|r| r[7] == 1.0) && fmu.iter().any(|r| r[1] > 0.5) && fmu.iter().any(|r| r[1] < -0.5));
}

#[test]
fn host_steps_of_1e_5_s_and_of_1_s_work_and_agree() {
    // 1 s steps over 3 s, against 0.1 s steps: same numbers at 1, 2, 3 s.
    let a = fmu_run(&[], &grid(1.0, 3.0), &|_| 20e3);
    let b = fmu_run(&[], &grid(0.1, 3.0), &|_| 20e3);
    for (j, k) in [(1, 10), (2, 20), (3, 30)] {
        for (x, y) in a[j].iter().zip(&b[k]) {
            assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-3), "t = {j}: {x} vs {y}");
        }
    }
    // 1e-5 s steps over 0.12 s, against 0.01 s steps.
    let fine = grid(1e-5, 0.12);
    let c = fmu_run(&[], &fine, &|_| 20e3);
    let d = fmu_run(&[], &grid(0.01, 0.12), &|_| 20e3);
    for (j, row) in d.iter().enumerate() {
        let k = j * 1000;
        for (x, y) in c[k].iter().zip(row) {
            assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-3), "t = {}: {x} vs {y}", fine[k]);
        }
    }
    assert!(c.iter().all(|r| r.iter().all(|x| x.is_finite())));
}

/// rig.method = 3 (Dopri5 dense): the states between steps come from the continuous
/// extension of steps that do not depend on the grid, so shared points agree across hosts,
/// and the outputs equal the library's with the same method bit for bit.
#[test]
fn dense_method_is_grid_independent_and_equals_the_library() {
    let sets = [("rig.method", 3.0)];
    let fine = grid(1e-3, 1.5);
    let coarse = grid(0.1, 1.5);
    let a = fmu_run(&sets, &fine, &load_step);
    let b = fmu_run(&sets, &coarse, &load_step);
    let mut exact = 0;
    for (j, t) in coarse.iter().enumerate() {
        let k = fine.iter().position(|x| (x - t).abs() < 1e-9).unwrap();
        if fine[k] == *t {
            assert_eq!(bits(&a[k]), bits(&b[j]), "t = {t}");
            exact += 1;
        }
        for (x, y) in a[k].iter().zip(&b[j]) {
            assert!((x - y).abs() <= 1e-12 * x.abs().max(1e-3), "t = {t}: {x} vs {y}");
        }
    }
    assert!(exact >= 8, "{exact} bitwise-equal shared times");
    let mut cfg = RigConfig::default();
    cfg.rig.method = pinjoint::rig::Method::Dopri5Dense;
    let lib = library_run(&cfg, &coarse, &load_step);
    for (k, (x, y)) in b.iter().zip(&lib).enumerate() {
        assert_eq!(bits(x), bits(y), "t = {}: {x:?} vs {y:?}", coarse[k]);
    }
}

/// The cold day (issue 37, item 6): at −55 °C, 5 kN, 0.3 Hz (where the event logic chattered
/// and refused before) and at −40 °C with a grease 1.5× stiffer (consistency and yield stress),
/// the FMU steps two strokes without an error, sticks at the reversals, and equals the
/// library's rig bit for bit.
#[test]
fn the_cold_day_steps_and_equals_the_library() {
    let g = pinjoint::Params::default().grease;
    for (temperature, load, frequency, stiffer) in [(218.15, 5e3, 0.3, 1.0), (233.15, 20e3, 1.0, 1.5), (218.15, 60e3, 1.0, 1.5)] {
        let sets = [
            ("temperature", temperature),
            ("frequency", frequency),
            ("grease.consistency", stiffer * g.consistency),
            ("grease.yield_stress", stiffer * g.yield_stress),
        ];
        let mut cfg = RigConfig::default();
        cfg.model.lubricant.temperature = temperature;
        cfg.model.grease.consistency = stiffer * g.consistency;
        cfg.model.grease.yield_stress = stiffer * g.yield_stress;
        cfg.rig.frequency = frequency;
        let times = grid(0.02, 2.0 / frequency);
        let constant = move |_: f64| load;
        let fmu = fmu_run(&sets, &times, &constant);
        let lib = library_run(&cfg, &times, &constant);
        for (k, (x, y)) in fmu.iter().zip(&lib).enumerate() {
            assert_eq!(bits(x), bits(y), "{temperature} K, {load} N, {frequency} Hz, x{stiffer}: t = {}: {x:?} vs {y:?}", times[k]);
        }
        assert!(fmu.iter().any(|r| r[7] == 1.0) && fmu.iter().any(|r| r[1] > 0.1) && fmu.iter().any(|r| r[1] < -0.1), "{temperature} K: stick and both directions");
    }
}
