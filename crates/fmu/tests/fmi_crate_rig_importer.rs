//! The second importer for PinJointRig: the Rust `fmi` crate parses the
//! modelDescription (Real, Integer and Boolean variables), loads the binary under
//! its model identifier and steps it at uneven communication steps through a load
//! step; every output equals the rig library's for the same held inputs.
//!
//! The FMU is `$PINJOINT_RIG_FMU` when set (tests/fmu_harness/run.sh points it at
//! target/fmu/PinJointRig.fmu); otherwise the test packages the cdylib of this very
//! build, as crates/fmu/tests/fmi_crate_importer.rs does for PinJoint.

use test_support::packaged;
use fmi::fmi2::instance::{CoSimulation, Common};
use pinjoint_fmu::pin_joint_rig::INFO;
use pinjoint::rig::{Inputs, Method, RigConfig, RigSim};

#[test]
fn fmi_crate_loads_and_steps_the_rig_fmu_with_the_library_outputs() {
    let import = packaged::import("PINJOINT_RIG_FMU", &INFO, "rig-test");
    let mut inst = packaged::cs_instance(&import, "rig");
    let vr = |name: &str| packaged::vr(&INFO, name);
    inst.set_real(&[vr("frequency"), vr("rig.breakaway_factor")], &[0.6, 1.3]).unwrap();
    inst.set_integer(&[vr("rig.method")], &[1]).unwrap();
    inst.set_boolean(&[vr("use_command_input")], &[0]).unwrap();
    inst.enter_initialization_mode().unwrap();
    inst.exit_initialization_mode().unwrap();

    let mut cfg = RigConfig::default();
    cfg.rig.frequency = 0.6;
    cfg.rig.breakaway_factor = 1.3;
    cfg.rig.method = Method::Dop853;
    let mut sim = RigSim::new(&cfg).unwrap();

    let reals = ["angle", "angular_velocity", "torque", "friction_torque", "friction_coefficient", "actuator_work", "friction_dissipation"];
    let vrs: Vec<u32> = reals.iter().map(|n| vr(n)).collect();
    let mut t = 0.0;
    let (mut stuck_seen, mut slip_seen) = (false, false);
    for k in 0..400 {
        let h = [0.003, 0.011, 0.0007, 0.02][k % 4];
        let load = if t < 1.2 { 5e3 } else { 60e3 };
        inst.set_real(&[vr("load")], &[load]).unwrap();
        inst.do_step(t, h, true).unwrap();
        sim.advance_to(t + h, &Inputs { load: Some(load), command_angle: None }).unwrap();
        t += h;
        let mut v = vec![0.0; vrs.len()];
        inst.get_real(&vrs, &mut v).unwrap();
        let mut stuck = [7];
        inst.get_boolean(&[vr("stuck")], &mut stuck).unwrap();
        let s = sim.sample().unwrap();
        let expect = [s.angle, s.angular_velocity, s.torque, s.friction_torque, s.friction_coefficient, s.actuator_work, s.friction_dissipation];
        for (i, (a, b)) in v.iter().zip(expect).enumerate() {
            assert!((a - b).abs() <= 1e-12 * b.abs(), "{} at t = {t}: {a} vs {b}", reals[i]);
        }
        assert_eq!(stuck[0], i32::from(s.stuck), "stuck at t = {t}");
        stuck_seen |= s.stuck;
        slip_seen |= !s.stuck;
    }
    assert!(stuck_seen && slip_seen);
    assert!(inst.do_step(t + 1.0, 0.01, true).is_err(), "discontinuous communication point");
    assert!(inst.set_real(&[vr("load")], &[f64::NAN]).is_err(), "NaN load");
    inst.do_step(t, 0.01, true).unwrap();
    inst.terminate().unwrap();
}
