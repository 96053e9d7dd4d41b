//! PinJointRig through the exported functions: life cycle, parameters (Real,
//! Integer, Boolean), rejection of bad values naming parameter, value and unit,
//! zero load, and misuse.

use test_support::rig_host;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::fmi2::types::*;
use rig_host::*;

#[test]
fn life_cycle_swings_the_pin_and_resets() {
    let h = new_host();
    let c = instantiate(&h);
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 1, 2.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    // Start values are readable in initialization mode.
    assert_eq!(get(c, "frequency"), 1.0);
    assert_eq!(get(c, "amplitude"), 40f64.to_radians());
    assert_eq!(get(c, "load"), 20e3);
    assert_eq!(get(c, "use_command_input"), 0.0);
    assert_eq!(get(c, "rig.method"), 0.0);
    assert_eq!(get(c, "rig.inertia"), 0.05);
    assert_eq!(get(c, "geometry.pin_radius"), 0.028);
    assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
    // At rest on the command at t = 0, stuck.
    assert_eq!(get(c, "angle"), 0.0);
    assert_eq!(get(c, "angular_velocity"), 0.0);
    assert_eq!(get(c, "stuck"), 1.0);
    let mut t = 0.0;
    let mut max_lag: f64 = 0.0;
    let mut max_speed: f64 = 0.0;
    let mut slipped = false;
    while t < 1.0 - 1e-12 {
        let o = step(&h, c, t, t + 0.01);
        t += 0.01;
        let (angle, speed, cmd) = (o[0], o[1], o[8]);
        max_lag = max_lag.max((angle - cmd).abs());
        if t > 0.5 {
            // After the start-up transient (the stroke starts at rest while the command
            // already moves at its peak rate).
            max_speed = max_speed.max(speed.abs());
        }
        slipped |= o[7] == 0.0;
        // Slipping, the friction torque opposes the motion.
        if o[7] == 0.0 && speed.abs() > 1e-6 {
            assert!(o[3] * speed < 0.0, "t = {t}: friction {} at speed {speed}", o[3]);
        }
        assert!(o.iter().all(|x| x.is_finite()));
    }
    assert!(slipped);
    let a = 40f64.to_radians();
    assert!(max_lag.to_degrees() < 3.0 && max_lag.to_degrees() > 0.2, "tracks within a few degrees: {}", max_lag.to_degrees());
    assert!((max_speed / (std::f64::consts::TAU * a) - 1.0).abs() < 0.05, "peak speed {max_speed} vs 2 pi f A");
    // Energy balance W - D = kinetic energy (from rest).
    let (w, d, k) = (get(c, "actuator_work"), get(c, "friction_dissipation"), get(c, "kinetic_energy"));
    assert!(d > 100.0, "a 1 Hz cycle at 20 kN dissipates about 4 * 67 N.m * 0.7 rad: {d}");
    assert!((w - d - k).abs() < 1e-6 * d, "W {w} D {d} K {k}");
    let mut last = 0.0;
    assert_eq!(unsafe { fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut last) }, OK);
    assert!((last - 1.0).abs() < 1e-12);
    assert_eq!(fmi2Terminate(c), OK);
    assert_eq!(fmi2Reset(c), OK);
    // A fresh run after reset starts again at rest, with the start values.
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(get(c, "frequency"), 1.0);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    assert_eq!(get(c, "actuator_work"), 0.0);
    free(c);
}

#[test]
fn parameters_of_every_type_take_effect() {
    let h = new_host();
    let run = |sets: &[(&str, f64)]| {
        let c = ready(&h, sets);
        let mut t = 0.0;
        let mut rows = Vec::new();
        for _ in 0..40 {
            rows.push(step(&h, c, t, t + 0.025));
            t += 0.025;
        }
        free(c);
        rows
    };
    let base = run(&[]);
    for sets in [
        vec![("frequency", 0.3)],
        vec![("amplitude", 0.2)],
        vec![("rig.inertia", 0.2)],
        vec![("rig.breakaway_factor", 1.5)],
        vec![("rig.formulation", 1.0)],
        vec![("rig.method", 1.0)],
        vec![("friction.boundary_friction_coefficient", 0.08)],
    ] {
        let other = run(&sets);
        assert_ne!(other, base, "{sets:?} changed nothing");
    }
    // Boolean and Integer parameters read back through their own getters.
    let c = ready(&h, &[("use_command_input", 1.0), ("rig.method", 2.0), ("command_angle", 0.1)]);
    assert_eq!(get(c, "use_command_input"), 1.0);
    assert_eq!(get(c, "rig.method"), 2.0);
    free(c);
}

#[test]
fn command_input_is_followed_when_selected() {
    let h = new_host();
    let c = ready(&h, &[("use_command_input", 1.0), ("command_angle", 0.3)]);
    assert_eq!(get(c, "commanded_angle"), 0.3);
    let mut t = 0.0;
    for _ in 0..50 {
        step(&h, c, t, t + 0.01);
        t += 0.01;
    }
    // The loop pulls the pin to the command; it stops within the breakaway band
    // |theta - 0.3| <= mu_c R P / K_p = 67.2/6000 rad.
    let angle = get(c, "angle");
    assert!((angle - 0.3).abs() < 67.3 / 6000.0 + 1e-9, "{angle}");
    // With the internal sine selected the input is ignored.
    let d = ready(&h, &[("command_angle", 0.3)]);
    assert_eq!(get(d, "commanded_angle"), 0.0);
    step(&h, d, 0.0, 0.25);
    assert!((get(d, "commanded_angle") - 40f64.to_radians()).abs() < 1e-12);
    free(c);
    free(d);
}

#[test]
fn bad_parameters_are_rejected_at_exit_initialization_by_name_value_and_unit() {
    let h = new_host();
    for (name, value, fragments) in [
        ("frequency", 0.0, vec!["frequency = 0 Hz", "> 0"]),
        ("amplitude", -0.1, vec!["amplitude = -0.1 rad", ">= 0"]),
        ("rig.inertia", -1.0, vec!["rig.inertia = -1 kg.m2"]),
        ("rig.velocity_gain", 10.0, vec!["rig.velocity_gain = 10", "Routh"]),
        ("rig.servo_time_constant", f64::NAN, vec!["rig.servo_time_constant = NaN s", "not a finite number"]),
        ("rig.formulation", 2.0, vec!["rig.formulation = 2", "0 (hybrid) or 1 (regularised)"]),
        ("rig.method", 5.0, vec!["rig.method = 5"]),
        ("geometry.bush_radius", 0.027, vec!["geometry.bush_radius = 0.027 m must exceed geometry.pin_radius = 0.028 m"]),
        ("lubricant.viscosity", 0.0, vec!["lubricant.viscosity = 0 Pa.s"]),
    ] {
        let c = instantiate(&h);
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
        assert_eq!(set(c, name, value), OK, "parameters are checked at exit, not when set");
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        h.clear();
        assert_eq!(fmi2ExitInitializationMode(c), ERROR, "{name} = {value} accepted");
        let msg = h.last();
        for f in fragments {
            assert!(msg.contains(f), "{name}: {f:?} not in {msg:?}");
        }
        // In the error state stepping is refused, freeing works.
        assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
        free(c);
    }
}

#[test]
fn bad_inputs_and_wrong_types_are_refused_without_change() {
    let (h, c) = ready_rig();
    for (name, v, fragment) in [
        ("load", f64::NAN, "input load = NaN N is invalid"),
        ("load", f64::INFINITY, "input load = inf N"),
        ("command_angle", f64::NAN, "input command_angle = NaN rad"),
    ] {
        assert_eq!(set(c, name, v), ERROR);
        assert!(h.last().contains(fragment), "{}", h.last());
    }
    assert_eq!(get(c, "load"), 20e3);
    // Type mismatches name the variable and its type.
    let mut x = [0.0];
    assert_eq!(unsafe { fmi2GetReal(c, [vr("stuck")].as_ptr(), 1, x.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("'stuck'") && h.last().contains("is a Boolean variable, not Real"), "{}", h.last());
    let mut i = [0];
    assert_eq!(unsafe { fmi2GetInteger(c, [vr("torque")].as_ptr(), 1, i.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("is a Real variable, not Integer"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetBoolean(c, [vr("rig.method")].as_ptr(), 1, [1].as_ptr()) }, ERROR);
    assert!(h.last().contains("is an Enumeration variable, not Boolean"), "{}", h.last());
    // Outputs and fixed parameters cannot be set after initialization.
    assert_eq!(unsafe { fmi2SetBoolean(c, [vr("stuck")].as_ptr(), 1, [1].as_ptr()) }, ERROR);
    assert_eq!(set(c, "use_command_input", 1.0), ERROR);
    assert!(h.last().contains("fixed"), "{}", h.last());
    // A step that does not continue the last one is refused; the instance stays usable.
    assert_eq!(fmi2DoStep(c, 0.5, 0.1, 0), ERROR);
    assert_eq!(fmi2DoStep(c, 0.0, -0.1, 0), ERROR);
    step(&h, c, 0.0, 0.1);
    free(c);
}

#[test]
fn zero_load_moves_freely_and_reports_zero_friction() {
    let h = new_host();
    let c = ready(&h, &[("load", 0.0)]);
    let mut t = 0.0;
    for _ in 0..30 {
        let o = step(&h, c, t, t + 0.01);
        t += 0.01;
        assert_eq!(o[3], 0.0, "friction_torque");
        assert_eq!(o[4], 0.0, "friction_coefficient");
        assert_eq!((o[5], o[6]), (0.0, 0.0), "film quantities at zero load");
        assert_eq!(o[7], 0.0, "not stuck without contact");
        assert_eq!(o[10], 0.0, "no dissipation");
    }
    assert!(get(c, "angle") > 0.5, "follows the sine: {}", get(c, "angle"));
    // Loading the joint mid-stroke brings the friction back at once.
    assert_eq!(set(c, "load", 60e3), OK);
    assert!(get(c, "friction_torque").abs() > 100.0, "{}", get(c, "friction_torque"));
    assert!(get(c, "film_thickness") > 0.0);
    free(c);
}

#[test]
fn start_time_shifts_the_stroke() {
    let h = new_host();
    let a = ready(&h, &[]);
    let b = ready_at(&h, 10.0, &[]);
    let ra = step(&h, a, 0.0, 0.3);
    let rb = step(&h, b, 10.0, 10.3);
    // The rig clock is t - t_start: equal up to the rounding of 10.3 - 10.
    for (x, y) in ra.iter().zip(&rb) {
        assert!((x - y).abs() <= 1e-9 * x.abs().max(1.0), "{x} vs {y}");
    }
    free(a);
    free(b);
}

#[test]
fn panic_inside_a_step_is_contained() {
    let (_h, c) = ready_rig();
    fmi_layer::fmi2::api::force_panic_in("fmi2DoStep");
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), Status::Fatal.c());
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    free(c);
}
