//! Get/set dispatch, argument checks, bad input values, stepping and the outputs
//! against the library, through the exported C functions.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use pinjoint::{Joint, Params};
use std::ptr::{null, null_mut};


#[test]
fn null_arrays_unknown_references_and_wrong_types() {
    let (h, c) = ready_pin_joint();
    let r = [vr("torque")];
    let mut v = [0.0];
    assert_eq!(unsafe { fmi2GetReal(c, null(), 1, v.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("vr[] is NULL but its length is 1"), "{}", h.last());
    assert_eq!(unsafe { fmi2GetReal(c, r.as_ptr(), 1, null_mut()) }, ERROR);
    assert!(h.last().contains("value[] is NULL"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetReal(c, r.as_ptr(), 1, null()) }, ERROR);
    // Zero-length arrays are fine, even NULL.
    assert_eq!(unsafe { fmi2GetReal(c, null(), 0, null_mut()) }, OK);
    assert_eq!(unsafe { fmi2SetReal(c, null(), 0, null()) }, OK);
    // Unknown value reference, in the middle of an array: nothing is set.
    let rs = [vr("load"), 999, vr("angular_velocity")];
    assert_eq!(unsafe { fmi2SetReal(c, rs.as_ptr(), 3, [1e3, 2.0, 3.0].as_ptr()) }, ERROR);
    assert!(h.last().contains("unknown value reference 999"), "{}", h.last());
    assert_eq!(get(c, "load"), 20e3, "a rejected call sets nothing");
    assert_eq!(unsafe { fmi2GetReal(c, [999].as_ptr(), 1, v.as_mut_ptr()) }, ERROR);
    // Other types.
    let mut i = [0];
    assert_eq!(unsafe { fmi2GetInteger(c, r.as_ptr(), 1, i.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("'torque'") && h.last().contains("Real variable, not Integer"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetBoolean(c, [5].as_ptr(), 1, [1].as_ptr()) }, ERROR);
    assert!(h.last().contains("unknown value reference 5"), "{}", h.last());
    assert_eq!(unsafe { fmi2GetString(c, null(), 0, null_mut()) }, OK);
    assert_eq!(unsafe { fmi2SetString(c, null(), 1, null()) }, ERROR);
    // Still usable.
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn outputs_and_fixed_parameters_cannot_be_set() {
    let h = Host::new();
    let c = h.instantiate();
    assert_eq!(set(c, "torque", 1.0), ERROR);
    assert!(h.last().contains("output 'torque' (value reference 10) cannot be set"), "{}", h.last());
    assert_eq!(set(c, "geometry.pin_radius", 0.02), OK, "parameters can be set when instantiated");
    assert_eq!(set(c, "geometry.bush_radius", 0.0201), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(set(c, "geometry.bush_length", 0.05), OK, "and in initialization mode");
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    assert_eq!(set(c, "geometry.pin_radius", 0.03), ERROR);
    assert!(h.last().contains("'geometry.pin_radius'") && h.last().contains("fixed"), "{}", h.last());
    assert_eq!(get(c, "geometry.pin_radius"), 0.02);
    assert_eq!(set(c, "dissipated_energy", 0.0), ERROR);
    assert_eq!(set(c, "load", 30e3), OK, "inputs can be set in step complete");
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn bad_input_values_are_rejected_with_name_value_and_unit() {
    let h = Host::new();
    let c = h.ready(&[("angular_velocity", 0.2)]);
    let before = all_outputs(c);
    for (name, v, expect) in [
        ("load", f64::NAN, "input load = NaN N"),
        ("load", f64::INFINITY, "input load = inf N"),
                ("load", f64::NEG_INFINITY, "input load = -inf N"),
        ("angular_velocity", f64::NAN, "input angular_velocity = NaN rad/s"),
        ("angular_velocity", f64::INFINITY, "input angular_velocity = inf rad/s"),
        ("angular_velocity", f64::NEG_INFINITY, "input angular_velocity = -inf rad/s"),
        ("angle", f64::NAN, "input angle = NaN rad"),
        ("angle", f64::INFINITY, "input angle = inf rad"),
        ("angle", f64::NEG_INFINITY, "input angle = -inf rad"),
    ] {
        assert_eq!(set(c, name, v), ERROR, "{name} = {v}");
        assert!(h.last().contains(expect), "{name}: {}", h.last());
    }
    assert_eq!(all_outputs(c), before, "rejected values change nothing");
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn extreme_but_valid_inputs_give_finite_outputs_or_an_error_never_nan() {
    let (h, c) = ready_pin_joint();
    // Zero load: unloaded, every output 0 (documented), energy unchanged.
    assert_eq!(set(c, "load", 0.0), OK);
    assert_eq!(set(c, "angular_velocity", 1.0), OK);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    assert!(all_outputs(c).iter().all(|&x| x == 0.0), "{:?}", all_outputs(c));
    let mut t = 0.1;
    // A load beyond the asperity model's capacity (5.05e8 N here) is refused, naming it,
    // and the instance goes on.
    let before = all_outputs(c);
    assert_ne!(set(c, "load", 1e9), OK);
    assert!(h.last().contains("load = 1000000000 N") && h.last().contains("capacity"), "{}", h.last());
    assert_eq!(all_outputs(c), before);
    // With the paper's model (model.paper = true), where the fluid's film would pass the
    // diametral clearance (1e-30 N at 1e6 rad/s: 1.9e33 m) the step fails naming the film and
    // the clearance (a fresh instance for each); the complete model answers there.
    let joint = Joint::new(&Params::paper()).unwrap();
    for (load, w) in [(20e3, 1e6), (5e8, 1e6), (1e-30, 1e6), (5e8, -1e6)] {
        assert!(matches!(joint.evaluate(load, w), Err(pinjoint::ModelError::FilmBeyondClearance { .. })), "{load} {w}");
        let c = h.ready(&[("model.paper", 1.0)]);
        assert_eq!(set(c, "load", load), OK);
        assert_eq!(set(c, "angular_velocity", w), OK);
        assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
        assert!(h.last().contains("film_thickness = ") && h.last().contains("diametral clearance"), "{}", h.last());
        assert!(h.last().len() < 600, "{}", h.last());
        unsafe { fmi2FreeInstance(c) };
    }
    for (load, w) in [(5e8, 1.0), (60e3, 1e-300), (1.0, 0.0)] {
        assert_eq!(set(c, "load", load), OK);
        assert_eq!(set(c, "angular_velocity", w), OK);
        assert_eq!(fmi2DoStep(c, t, 0.1, 0), OK, "load {load} w {w}: {}", h.last());
        t += 0.1;
        let out = all_outputs(c);
        assert!(out.iter().all(|x| x.is_finite()), "load {load} w {w}: {out:?}");
    }
    // A load of 1 N at rest is within the model's range (at 1e-300 N the film at the
    // zero-speed band's edge passes the clearance: below).
    assert_eq!(set(c, "load", 1.0), OK);
    assert_eq!(set(c, "angular_velocity", 0.0), OK);
    assert_eq!(fmi2DoStep(c, t, 0.1, 0), OK, "{}", h.last());
    t += 0.1;
    assert!(all_outputs(c).iter().all(|x| x.is_finite()), "{:?}", all_outputs(c));
    // A step whose energy would overflow fails instead of returning inf.
    assert_eq!(set(c, "load", 5e8), OK);
    assert_eq!(set(c, "angular_velocity", 1.0), OK);
    assert_eq!(fmi2DoStep(c, t, 1e308, 0), ERROR);
    assert!(h.last().starts_with("fmi2DoStep: step from") && h.last().contains("dissipated_energy overflows"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
    // A subnormal or tiny load under the band: the band-edge film thickness overflows f64 or
    // passes the clearance (the paper's model), or μ = T/(R·P) overflows with the grease's
    // finite yield torque over a vanishing load (the complete model); the step fails naming it.
    for load in [5e-324, 1e-300] {
        let c = h.ready(&[BAND]);
        assert_eq!(set(c, "load", load), OK);
        assert_eq!(set(c, "angular_velocity", 0.0), OK);
        match fmi2DoStep(c, 0.0, 0.1, 0) {
            OK => assert!(all_outputs(c).iter().all(|x| x.is_finite()), "{load}: {:?}", all_outputs(c)),
            status => {
                assert_eq!(status, ERROR);
                assert!(h.last().contains("film_thickness") || h.last().contains("friction_coefficient = inf"), "{}", h.last());
            }
        }
        unsafe { fmi2FreeInstance(c) };
    }
    // Presliding (the default) evaluates no band edge: with the paper's model at rest the same
    // load gives finite outputs (the torque is the held presliding torque, 0 from a fresh
    // start). The complete model's μ at rest, μ_c + (the grease's finite yield torque)/(R·P),
    // overflows at a subnormal load: the step fails naming it.
    let c = h.ready(&[("model.paper", 1.0)]);
    assert_eq!(set(c, "load", 5e-324), OK);
    assert_eq!(set(c, "angular_velocity", 0.0), OK);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK, "{}", h.last());
    assert!(all_outputs(c).iter().all(|x| x.is_finite()), "{:?}", all_outputs(c));
    assert_eq!(get(c, "torque"), 0.0);
    unsafe { fmi2FreeInstance(c) };
    let c = h.ready(&[]);
    assert_eq!(set(c, "load", 5e-324), OK);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    assert!(h.last().contains("friction_coefficient = inf"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn do_step_checks_its_arguments() {
    let h = Host::new();
    let c = h.ready(&[("angular_velocity", 0.3)]);
    for (t, dt, expect) in [
        (0.0, 0.0, "communicationStepSize = 0 s"),
        (0.0, -0.1, "communicationStepSize = -0.1 s"),
        (0.0, f64::NAN, "communicationStepSize = NaN s"),
        (0.0, f64::INFINITY, "communicationStepSize = inf s"),
        (f64::NAN, 0.1, "currentCommunicationPoint = NaN s"),
        (0.5, 0.1, "does not continue the last step, which ended at 0 s"),
        (-0.1, 0.1, "does not continue"),
    ] {
        assert_eq!(fmi2DoStep(c, t, dt, 0), ERROR, "t {t} dt {dt}");
        assert!(h.last().contains(expect), "{}", h.last());
    }
    // Still in step complete; rounding-level differences are accepted.
    let mut t = 0.0;
    for _ in 0..1000 {
        assert_eq!(fmi2DoStep(c, t, 0.001, 0), OK);
        t += 0.001;
    }
    assert_eq!(fmi2DoStep(c, 1.0, 0.001, 0), OK, "t = 1.0 vs accumulated {t}");
    assert_eq!(fmi2DoStep(c, 1.001 + 1e-3, 0.001, 0), ERROR, "a skipped step");
    // Variable step sizes.
    assert_eq!(fmi2DoStep(c, 1.001, 0.5, 0), OK);
    assert_eq!(fmi2DoStep(c, 1.501, 1e-6, 0), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn outputs_equal_the_library_exactly_and_energy_integrates_power() {
    let h = Host::new();
    let mut p = Params::default();
    p.surface.asperity_radius = 5e-6;
    p.lubricant.viscosity = 0.02;
    // The band: the stateless law, bit for bit the library's torque outside it, its ramp inside.
    let c = h.ready(&[("surface.asperity_radius", 5e-6), ("lubricant.viscosity", 0.02), BAND]);
    let j = Joint::new(&p).unwrap();
    // The FMU's full level is the library's complete solve, cold at every call: bit for bit.
    let mut energy = 0.0;
    let mut t = 0.0;
    for k in 0..400 {
        // Reversals; every other point slow enough to fall in the zero-velocity band.
        let w = if k % 2 == 0 { 0.05 } else { 2.0 } * (f64::from(k) * 0.05).sin();
        let load = if k < 200 { 5e3 } else { 60e3 };
        assert_eq!(set(c, "angular_velocity", w), OK);
        assert_eq!(set(c, "load", load), OK);
        assert_eq!(set(c, "angle", f64::from(k)), OK);
        let h_step = 0.01 + 0.001 * f64::from(k % 3);
        let op = j.evaluate(load, w).unwrap();
        let torque = if w.abs() >= 0.01 { op.signed_torque() } else { -j.evaluate(load, 0.01).unwrap().torque * (w / 0.01) };
        // Direct feedthrough: the outputs follow the inputs before the step.
        assert_eq!(get(c, "torque"), torque);
        assert_eq!(fmi2DoStep(c, t, h_step, 0), OK);
        t += h_step;
        energy += (torque * w).abs() * h_step;
        let out = all_outputs(c);
        let expect = [
            torque,
            op.friction_coefficient,
            op.film_thickness,
            op.lambda_ratio,
            op.fluid_load_fraction,
            op.asperity_load_fraction,
            op.mean_pressure,
            op.sommerfeld_number,
            (torque * w).abs(),
            energy,
        ];
        for (n, (a, b)) in OUTPUTS.iter().zip(out.iter().zip(expect)) {
            assert_eq!(a.to_bits(), b.to_bits(), "{n} at step {k}: {a} vs {b}");
        }
        if w.abs() >= 0.01 {
            assert_eq!(out[0], -w.signum() * op.torque, "outside the band the torque is the library's");
        }
    }
    unsafe { fmi2FreeInstance(c) };
}

/// Presliding (the default): the state starts at 0; once the joint has travelled 2 degrees
/// in one direction at one load (the presliding range is phi_s = 1.5e-3 rad; a load change
/// moves the sliding bound, which the state then approaches over the presliding range) the
/// torque is the library's -sign(omega) mu R P bit for bit at every load, and power_loss is |torque * omega|; before
/// that the torque stays within the sliding torque plus the documented damping term. The
/// energy sums power_loss * h over the steps, presliding ones included. The host drives the
/// state by the angle (set at every step start with the angular velocity).
#[test]
fn presliding_outputs_in_steady_sliding_equal_the_library_exactly_and_energy_integrates_power() {
    let h = Host::new();
    let mut p = Params::default();
    p.surface.asperity_radius = 5e-6;
    p.lubricant.viscosity = 0.02;
    let c = h.ready(&[("surface.asperity_radius", 5e-6), ("lubricant.viscosity", 0.02)]);
    let j = Joint::new(&p).unwrap();
    let law = pinjoint::zero_velocity::presliding::Presliding::default();
    let (mut angle, mut t, mut energy) = (0.0, 0.0, 0.0);
    let (mut travel, mut last_sign, mut exact) = (0.0, 0.0, 0);
    for k in 0..600 {
        // Three sliding phases with reversals, the load changing within each (up and down).
        let w: f64 = match k { 0..200 => 1.5, 200..400 => -0.4, _ => 3.0 };
        let load = [5e3, 60e3, 20e3, 33e3][k / 50 % 4];
        let h_step = 0.002 + 0.001 * (k % 3) as f64;
        if w.signum() != last_sign || k % 50 == 0 {
            (travel, last_sign) = (0.0, w.signum());
        }
        assert_eq!(set(c, "angular_velocity", w), OK);
        assert_eq!(set(c, "load", load), OK);
        assert_eq!(set(c, "angle", angle), OK);
        let op = j.evaluate(load, w).unwrap();
        let (torque, power) = (get(c, "torque"), get(c, "power_loss"));
        if travel >= 2f64.to_radians() {
            assert_eq!(torque.to_bits(), (-w.signum() * op.torque).to_bits(), "torque at step {k}: {torque} vs {} load {load} w {w} tau {}", -w.signum() * op.torque, get(c, "presliding_torque"));
            assert_eq!(power.to_bits(), (torque * w).abs().to_bits(), "power_loss at step {k}");
            exact += 1;
        } else {
            let damping = law.damping_time * op.torque * w.abs() / law.angle;
            assert!(torque.abs() <= op.torque + damping, "step {k}: {torque} vs {} + {damping}", op.torque);
            assert!(power >= 0.0);
        }
        assert_eq!(fmi2DoStep(c, t, h_step, 0), OK);
        t += h_step;
        energy += power * h_step;
        assert_eq!(get(c, "dissipated_energy").to_bits(), energy.to_bits(), "energy at step {k}");
        for (n, a, b) in [("friction_coefficient", get(c, "friction_coefficient"), op.friction_coefficient), ("film_thickness", get(c, "film_thickness"), op.film_thickness)] {
            assert_eq!(a.to_bits(), b.to_bits(), "{n} at step {k}");
        }
        angle += w * h_step;
        travel += (w * h_step).abs();
    }
    assert!(exact >= 400, "{exact} steps in steady sliding");
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn outputs_can_be_read_in_initialization_mode_with_the_start_values() {
    let h = Host::new();
    let op = Joint::new(&Params::default()).unwrap().evaluate(20e3, -0.5).unwrap();
    // The band: the library's torque.
    let c = h.instantiate();
    assert_eq!(set(c, BAND.0, BAND.1), OK);
    assert_eq!(set(c, "angular_velocity", -0.5), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(get(c, "torque"), op.torque);
    assert!(get(c, "torque") > 0.0, "opposes negative speed");
    assert_eq!(get(c, "dissipated_energy"), 0.0);
    unsafe { fmi2FreeInstance(c) };
    // Presliding (the default): the law at the start value of the state (0), the library's
    // sliding torque as its bound: the damping of the elastic deflection rate, opposing the motion.
    let c = h.instantiate();
    assert_eq!(set(c, "angular_velocity", -0.5), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(get(c, "presliding_torque"), 0.0);
    let law = pinjoint::zero_velocity::presliding::Presliding::default();
    assert_eq!(get(c, "torque").to_bits(), law.torque(0.0, -0.5, op.torque).to_bits());
    assert!(get(c, "torque") > 0.0, "opposes negative speed");
    assert_eq!(get(c, "dissipated_energy"), 0.0);
    unsafe { fmi2FreeInstance(c) };
}
