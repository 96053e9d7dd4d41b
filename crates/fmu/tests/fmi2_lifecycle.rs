//! Instantiation, the state machine (masks), logging and the functions this FMU
//! rejects, through the exported C functions.

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use pinjoint_fmu::fmi2Instantiate;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::fmi2::api::model_exchange::*;
use fmi_layer::fmi2::types::*;
use std::ffi::CStr;
use std::ptr::{null, null_mut};

const WARNING: i32 = 1;

#[test]
fn version_and_platform() {
    assert_eq!(unsafe { CStr::from_ptr(fmi2GetVersion()) }.to_str().unwrap(), "2.0");
    assert_eq!(unsafe { CStr::from_ptr(fmi2GetTypesPlatform()) }.to_str().unwrap(), "default");
}

#[test]
fn instantiate_rejects_bad_arguments_with_a_message() {
    let h = Host::new();
    // Wrong GUID.
    assert!(h.instantiate_with("a", FMI2_CO_SIMULATION, "{nope}", None, false).is_null());
    assert!(h.last().contains("{nope}") && h.last().contains("GUID"), "{}", h.last());
    // Not an fmi2Type.
    assert!(h.instantiate_with("a", 7, &guid(), None, false).is_null());
    assert!(h.last().contains("fmuType = 7"), "{}", h.last());
    // Empty instance name.
    assert!(h.instantiate_with("", FMI2_CO_SIMULATION, &guid(), None, false).is_null());
    assert!(h.last().contains("instanceName"), "{}", h.last());
    assert!(h.messages().iter().all(|m| m.status == ERROR && m.category == "logStatusError"));
    // NULL callbacks, NULL logger, NULL GUID.
    let g = std::ffi::CString::new(guid()).unwrap();
    let c = unsafe { fmi2Instantiate(c"a".as_ptr(), 1, g.as_ptr(), null(), null(), 0, 0) };
    assert!(c.is_null());
    let no_logger = Fmi2CallbackFunctions {
        logger: None,
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: null_mut(),
    };
    assert!(unsafe { fmi2Instantiate(c"a".as_ptr(), 1, g.as_ptr(), null(), &no_logger, 0, 0) }.is_null());
    h.clear();
    assert!(unsafe { fmi2Instantiate(c"a".as_ptr(), 1, null(), null(), &*h.callbacks, 0, 0) }.is_null());
    assert!(h.last().contains("fmuGUID is NULL"));
}

#[test]
fn null_or_empty_resource_location_is_fine_and_a_non_uri_only_a_warning() {
    let h = Host::new();
    // This FMU needs no resources: NULL and "" draw no message at all (issue 11).
    for loc in [None, Some("")] {
        h.clear();
        let c = h.instantiate_with("a", FMI2_CO_SIMULATION, &guid(), loc, true);
        assert!(!c.is_null());
        assert!(h.messages().iter().all(|m| m.status != WARNING && !m.text.contains("fmuResourceLocation")), "{:?}", loc);
        unsafe { fmi2FreeInstance(c) };
    }
    // Model Exchange is offered by PinJoint (issue 11).
    let c = h.instantiate_with("a", FMI2_MODEL_EXCHANGE, &guid(), None, false);
    assert!(!c.is_null());
    unsafe { fmi2FreeInstance(c) };
    let c = h.instantiate_with("a", FMI2_CO_SIMULATION, &guid(), Some("C:\\x"), true);
    assert!(!c.is_null());
    assert!(h.last().contains("not a URI") || h.messages().iter().any(|m| m.text.contains("not a URI")));
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn null_instance_is_an_error_everywhere() {
    let n = null_mut();
    assert_eq!(fmi2EnterInitializationMode(n), ERROR);
    assert_eq!(fmi2DoStep(n, 0.0, 0.1, 0), ERROR);
    assert_eq!(unsafe { fmi2GetReal(n, null(), 0, null_mut()) }, ERROR);
    assert_eq!(fmi2Reset(n), ERROR);
    assert_eq!(fmi2SetTime(n, 0.0), ERROR);
    unsafe { fmi2FreeInstance(n) }; // no-op
}

#[test]
fn illegal_call_sequences_are_refused_and_logged() {
    let h = Host::new();
    let c = h.instantiate();
    // Instantiated: no step, no exit, no get, no terminate.
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    assert!(h.last().contains("fmi2DoStep: illegal call sequence") && h.last().contains("instantiated"), "{}", h.last());
    assert_eq!(fmi2ExitInitializationMode(c), ERROR);
    assert_eq!(try_get(c, "torque"), Err(ERROR));
    assert_eq!(fmi2Terminate(c), ERROR);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    // Initialization mode: no setup, no second enter, no step; get works.
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), ERROR);
    assert_eq!(fmi2EnterInitializationMode(c), ERROR);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    assert!(get(c, "torque").is_finite());
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    // Step complete.
    assert_eq!(fmi2EnterInitializationMode(c), ERROR);
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    assert_eq!(fmi2Terminate(c), OK);
    // Terminated: get yes, set/step/terminate no.
    assert!(get(c, "torque").is_finite());
    assert_eq!(set(c, "load", 1e3), ERROR);
    assert_eq!(fmi2DoStep(c, 0.1, 0.1, 0), ERROR);
    assert_eq!(fmi2Terminate(c), ERROR, "terminate twice");
    assert!(h.last().contains("terminated"), "{}", h.last());
    // Reset returns to instantiated.
    assert_eq!(fmi2Reset(c), OK);
    assert_eq!(try_get(c, "torque"), Err(ERROR));
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn free_without_terminate_and_in_initialization_mode() {
    let (h, c) = ready_pin_joint();
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    unsafe { fmi2FreeInstance(c) };
    let c = h.instantiate();
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn reset_then_a_fresh_run_equals_the_first() {
    let h = Host::new();
    let c = h.ready(&[("load", 40e3), ("geometry.bush_length", 0.05)]);
    let run = |c| {
        let mut out = Vec::new();
        for k in 0..50 {
            let t = f64::from(k) * 0.01;
            assert_eq!(set(c, "angular_velocity", (3.0 * t).sin() * 0.3), OK);
            assert_eq!(fmi2DoStep(c, t, 0.01, 0), OK);
            out.extend(all_outputs(c));
        }
        out
    };
    let first = run(c);
    assert_eq!(fmi2Terminate(c), OK);
    assert_eq!(fmi2Reset(c), OK);
    // After reset the start values are back: the parameter change is gone.
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(get(c, "geometry.bush_length"), 59.4e-3);
    assert_eq!(get(c, "load"), 20e3);
    assert_eq!(set(c, "load", 40e3), OK);
    assert_eq!(set(c, "geometry.bush_length", 0.05), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    let second = run(c);
    assert_eq!(first.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), second.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
    unsafe { fmi2FreeInstance(c) };
}

/// Model Exchange (issues 11, 22, 29): one continuous state, `presliding_torque` (nominal
/// 100 N.m), no event indicators, step events; the outputs follow the inputs and the state at
/// every get: at the start state (0) equal to the Co-Simulation instance's at the same inputs
/// (which has not stepped, so its state is the start value too), at any state in stick the core
/// law's torque ([`Presliding::torque`]) and the stick rate ([`modes::rate`]) with the library's
/// sliding torque as the bound, bit for bit; fmi2CompletedIntegratorStep asks for an event
/// exactly when [`modes::event_due`] says, and the event iteration applies [`modes::update`];
/// the state arrays are checked; the ME state machine.
#[test]
fn model_exchange_outputs_follow_the_inputs_and_the_continuous_state() {
    use pinjoint::zero_velocity::modes::{self, Mode};
    use pinjoint::zero_velocity::presliding::Presliding;
    let h = Host::new();
    let me = h.instantiate_with("me", FMI2_MODEL_EXCHANGE, &guid(), None, false);
    assert!(!me.is_null());
    assert_eq!(fmi2EnterInitializationMode(me), OK);
    assert_eq!(fmi2ExitInitializationMode(me), OK);
    let mut info = [0i32; 8];
    assert_eq!(unsafe { fmi2NewDiscreteStates(me, info.as_mut_ptr().cast()) }, OK);
    assert_eq!(info[0], 0, "no discrete-state update");
    assert_eq!(fmi2EnterContinuousTimeMode(me), OK);
    let mut x = [f64::NAN; 1];
    assert_eq!(unsafe { fmi2GetContinuousStates(me, x.as_mut_ptr(), 1) }, OK);
    assert_eq!(x[0], 0.0, "the start value of presliding_torque");
    assert_eq!(unsafe { fmi2GetNominalsOfContinuousStates(me, x.as_mut_ptr(), 1) }, OK);
    assert_eq!(x[0], 100.0);
    let cs = h.ready(&[]);
    let law = Presliding::default();
    let joint = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap();
    let (w, p, t) = (vr("angular_velocity"), vr("load"), vr("torque"));
    for (k, (omega, load)) in [(0.5, 20e3), (-3.0, 40e3), (0.004, 20e3), (0.0, 5e3), (-1e-4, 60e3)].into_iter().enumerate() {
        assert_eq!(fmi2SetTime(me, 0.1 * k as f64), OK);
        assert_eq!(unsafe { fmi2SetContinuousStates(me, [0.0].as_ptr(), 1) }, OK);
        for c in [me, cs] {
            assert_eq!(unsafe { fmi2SetReal(c, [w, p].as_ptr(), 2, [omega, load].as_ptr()) }, OK);
        }
        let (mut a, mut b) = (0.0, 0.0);
        assert_eq!(unsafe { fmi2GetReal(me, &t, 1, &mut a) }, OK);
        assert_eq!(unsafe { fmi2GetReal(cs, &t, 1, &mut b) }, OK);
        assert_eq!(a.to_bits(), b.to_bits(), "omega = {omega}");
        // Across the presliding range: unloading, the elastic range, the elasto-plastic
        // transition, beyond the bound (clamped).
        let bound = joint.evaluate(load, omega).unwrap().torque;
        for tau in [0.0, 0.3 * bound, -0.5 * bound, 0.97 * bound, -0.99 * bound, 1.2 * bound] {
            assert_eq!(unsafe { fmi2SetContinuousStates(me, [tau].as_ptr(), 1) }, OK);
            let mut back = [f64::NAN];
            assert_eq!(unsafe { fmi2GetContinuousStates(me, back.as_mut_ptr(), 1) }, OK);
            assert_eq!(back[0].to_bits(), tau.to_bits());
            let mut der = [f64::NAN];
            assert_eq!(unsafe { fmi2GetDerivatives(me, der.as_mut_ptr(), 1) }, OK);
            assert_eq!(der[0].to_bits(), modes::rate(&law, Mode::Stick, tau, omega, bound).to_bits(), "rate at omega = {omega}, tau = {tau}");
            assert_eq!(get(me, "der(presliding_torque)").to_bits(), der[0].to_bits());
            assert_eq!(get(me, "torque").to_bits(), law.torque(tau, omega, bound).to_bits(), "torque at omega = {omega}, tau = {tau}");
            assert_eq!(get(me, "power_loss").to_bits(), law.dissipation(tau, omega, bound).to_bits());
            if omega != 0.0 && tau == 0.0 {
                assert!(der[0] * omega > 0.0, "the deflection follows the motion");
            }
        }
        // The last state, 1.2 T, is beyond the bound: a step event, and the event iteration
        // projects it (to the bound, or to slip at +-T along the motion).
        let (mut enter, mut stop) = (1, 1);
        assert_eq!(unsafe { fmi2CompletedIntegratorStep(me, 1, &mut enter, &mut stop) }, OK);
        let tau = 1.2 * bound;
        assert!(modes::event_due(&law, Mode::Stick, tau, omega, bound));
        assert_eq!((enter, stop), (1, 0));
        assert_eq!(fmi2EnterEventMode(me), OK);
        let mut info = [0i32; 8];
        assert_eq!(unsafe { fmi2NewDiscreteStates(me, info.as_mut_ptr().cast()) }, OK);
        assert_eq!((info[0], info[3]), (0, 1), "no further iteration; the state changed");
        let (mode, expected) = modes::update(&law, Mode::Stick, tau, omega, bound);
        assert_eq!(unsafe { fmi2GetContinuousStates(me, x.as_mut_ptr(), 1) }, OK);
        assert_eq!(x[0].to_bits(), expected.to_bits());
        assert_eq!(get(me, "presliding_mode"), mode.code());
        assert_eq!(unsafe { fmi2NewDiscreteStates(me, info.as_mut_ptr().cast()) }, OK);
        assert_eq!(info[3], 0, "a second iteration changes nothing");
        assert_eq!(fmi2EnterContinuousTimeMode(me), OK);
        assert_eq!(unsafe { fmi2CompletedIntegratorStep(me, 1, &mut enter, &mut stop) }, OK);
        assert_eq!((enter, stop), (0, 0), "no event due after the update");
        // Back to stick for the next case (a slip at omega = 0 returns to stick at its event).
        assert_eq!(fmi2EnterEventMode(me), OK);
        assert_eq!(set(me, "angular_velocity", 0.0), OK);
        assert_eq!(unsafe { fmi2NewDiscreteStates(me, info.as_mut_ptr().cast()) }, OK);
        assert_eq!(get(me, "presliding_mode"), 0.0);
        assert_eq!(fmi2EnterContinuousTimeMode(me), OK);
    }
    // The state arrays have the length nx = 1; a state the model refuses changes nothing.
    assert_eq!(unsafe { fmi2GetDerivatives(me, x.as_mut_ptr(), 0) }, ERROR);
    assert!(h.last().contains("nx = 0, but PinJoint has 1 continuous state"), "{}", h.last());
    let mut two = [0.0; 2];
    assert_eq!(unsafe { fmi2GetContinuousStates(me, two.as_mut_ptr(), 2) }, ERROR);
    assert_eq!(unsafe { fmi2SetContinuousStates(me, [1.0, 2.0].as_ptr(), 2) }, ERROR);
    assert_eq!(unsafe { fmi2SetContinuousStates(me, [f64::NAN].as_ptr(), 1) }, ERROR);
    assert!(h.last().contains("presliding_torque"), "{}", h.last());
    assert_eq!(unsafe { fmi2GetContinuousStates(me, x.as_mut_ptr(), 1) }, OK);
    // The last event ran at omega = 0 (back to stick): the state is 1.2 T projected onto the
    // bound there, the torque at rest (which, in the complete model, holds the grease's yield
    // torque and not its running torque at -1e-4 rad/s).
    assert_eq!(x[0], joint.evaluate(60e3, 0.0).unwrap().torque, "unchanged by the refused calls (the last event's state: 1.2 T projected onto T at rest)");
    assert_eq!(fmi2GetEventIndicators(me, x.as_mut_ptr(), 0), OK);
    assert_eq!(fmi2GetEventIndicators(me, x.as_mut_ptr(), 1), ERROR);
    // Parameters cannot be set in continuous-time mode; doStep is not a Model Exchange call.
    assert_eq!(fmi2DoStep(me, 0.0, 0.1, 1), ERROR);
    assert_eq!(fmi2EnterEventMode(me), OK);
    assert_eq!(fmi2Terminate(me), OK);
    unsafe { fmi2FreeInstance(me) };
    unsafe { fmi2FreeInstance(cs) };
}

/// Model Exchange with the band: the state exists (nx = 1) but the band does not use it: its
/// derivative is 0 and the torque is the Co-Simulation band instance's, whatever the state.
#[test]
fn model_exchange_with_the_band_is_a_stateless_map_of_the_inputs() {
    let h = Host::new();
    let me = h.instantiate_with("me", FMI2_MODEL_EXCHANGE, &guid(), None, false);
    assert_eq!(set(me, BAND.0, BAND.1), OK);
    assert_eq!(fmi2EnterInitializationMode(me), OK);
    assert_eq!(fmi2ExitInitializationMode(me), OK);
    assert_eq!(fmi2EnterContinuousTimeMode(me), OK);
    let cs = h.ready(&[BAND]);
    for (omega, load) in [(0.5, 20e3), (-3.0, 40e3), (0.004, 20e3), (0.0, 5e3)] {
        for c in [me, cs] {
            assert_eq!(set(c, "angular_velocity", omega), OK);
            assert_eq!(set(c, "load", load), OK);
        }
        for tau in [0.0, 50.0, -300.0] {
            assert_eq!(unsafe { fmi2SetContinuousStates(me, [tau].as_ptr(), 1) }, OK);
            let mut der = [f64::NAN];
            assert_eq!(unsafe { fmi2GetDerivatives(me, der.as_mut_ptr(), 1) }, OK);
            assert_eq!(der[0], 0.0);
            assert_eq!(get(me, "torque").to_bits(), get(cs, "torque").to_bits(), "omega = {omega}, tau = {tau}");
            assert_eq!(get(me, "power_loss").to_bits(), get(cs, "power_loss").to_bits());
        }
    }
    unsafe { fmi2FreeInstance(me) };
    unsafe { fmi2FreeInstance(cs) };
}

#[test]
fn model_exchange_and_unsupported_functions_return_error_with_a_message() {
    let (h, c) = ready_pin_joint();
    let mut x = [0.0; 2];
    let mut b = 0;
    let calls: Vec<(&str, i32)> = vec![
        ("fmi2EnterEventMode", fmi2EnterEventMode(c)),
        ("fmi2NewDiscreteStates", unsafe { fmi2NewDiscreteStates(c, null_mut()) }),
        ("fmi2EnterContinuousTimeMode", fmi2EnterContinuousTimeMode(c)),
        ("fmi2CompletedIntegratorStep", unsafe { fmi2CompletedIntegratorStep(c, 0, &mut b, &mut b) }),
        ("fmi2SetTime", fmi2SetTime(c, 1.0)),
        ("fmi2SetContinuousStates", unsafe { fmi2SetContinuousStates(c, x.as_ptr(), 0) }),
        ("fmi2GetDerivatives", unsafe { fmi2GetDerivatives(c, x.as_mut_ptr(), 0) }),
        ("fmi2GetEventIndicators", fmi2GetEventIndicators(c, x.as_mut_ptr(), 0)),
        ("fmi2GetContinuousStates", unsafe { fmi2GetContinuousStates(c, x.as_mut_ptr(), 0) }),
        ("fmi2GetNominalsOfContinuousStates", unsafe { fmi2GetNominalsOfContinuousStates(c, x.as_mut_ptr(), 0) }),
    ];
    for (name, status) in calls {
        assert_eq!(status, ERROR, "{name}");
        // A Co-Simulation instance: refused by the state mask (no Model Exchange state) or as
        // a Model Exchange function.
        assert!(
            h.messages().iter().any(|m| m.text.starts_with(name)
                && (m.text.contains("illegal call sequence") || m.text.contains("instantiated for Co-Simulation"))),
            "{name}"
        );
    }
    let r = [vr("torque")];
    let order = [1];
    // Directional derivatives are provided (issue 22), of outputs with respect to inputs only.
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, r.as_ptr(), 1, r.as_ptr(), 1, x.as_ptr(), x.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("continuous Real inputs (partials with respect to parameters are not provided)"), "{}", h.last());
    let known = [vr("geometry.pin_radius")];
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, r.as_ptr(), 1, known.as_ptr(), 1, [1.0].as_ptr(), x.as_mut_ptr()) }, ERROR);
    assert!(h.last().contains("geometry.pin_radius"), "{}", h.last());
    // Slow enough that the damping stays below the sliding torque (it is capped there).
    assert_eq!(set(c, "angular_velocity", 0.01), OK);
    let known = [vr("angular_velocity")];
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, r.as_ptr(), 1, known.as_ptr(), 1, [1.0].as_ptr(), x.as_mut_ptr()) }, OK);
    assert!(x[0].is_finite() && x[0] < 0.0, "the damping of the presliding deflection: {}", x[0]);
    assert_eq!(fmi2SetRealInputDerivatives(c, r.as_ptr(), 1, order.as_ptr(), x.as_ptr()), ERROR);
    assert!(h.last().contains("canInterpolateInputs"));
    assert_eq!(fmi2GetRealOutputDerivatives(c, r.as_ptr(), 1, order.as_ptr(), x.as_mut_ptr()), ERROR);
    assert_eq!(fmi2CancelStep(c), ERROR);
    // The instance is still usable.
    assert_eq!(fmi2DoStep(c, 0.0, 0.5, 0), OK);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn status_functions() {
    let (h, c) = ready_pin_joint();
    assert_eq!(fmi2DoStep(c, 0.0, 0.25, 0), OK);
    assert_eq!(fmi2DoStep(c, 0.25, 0.5, 0), OK);
    let mut t = 0.0;
    assert_eq!(unsafe { fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut t) }, OK);
    assert_eq!(t, 0.75);
    let mut b = 1;
    assert_eq!(unsafe { fmi2GetBooleanStatus(c, FMI2_TERMINATED, &mut b) }, OK);
    assert_eq!(b, FMI2_FALSE);
    let mut s = 0;
    assert_eq!(unsafe { fmi2GetStatus(c, FMI2_DO_STEP_STATUS, &mut s) }, ERROR);
    assert_eq!(unsafe { fmi2GetRealStatus(c, 99, &mut t) }, ERROR);
    assert!(h.last().contains("status kind 99"), "{}", h.last());
    let mut i = 0;
    assert_eq!(unsafe { fmi2GetIntegerStatus(c, 0, &mut i) }, ERROR);
    assert_eq!(unsafe { fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, null_mut()) }, ERROR);
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn debug_logging_categories() {
    let h = Host::new();
    let c = h.instantiate(); // logging off
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert!(h.messages().is_empty(), "no debug output with logging off: {:?}", h.messages());
    // Errors are reported with debug logging off.
    assert_eq!(fmi2EnterInitializationMode(c), ERROR);
    assert_eq!(h.messages().len(), 1);
    // Switch on logEvents only.
    let cats = [c"logEvents".as_ptr()];
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 1, 1, cats.as_ptr()) }, OK);
    h.clear();
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    assert!(h.messages().iter().any(|m| m.category == "logEvents" && m.text.contains("initialization done")));
    // logAll traces calls.
    let all = [c"logAll".as_ptr()];
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 1, 1, all.as_ptr()) }, OK);
    h.clear();
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), OK);
    assert!(h.messages().iter().any(|m| m.category == "logAll" && m.text.contains("fmi2DoStep")));
    // Everything off with nCategories = 0 still reports errors.
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 0, 0, null()) }, OK);
    h.clear();
    assert_eq!(fmi2DoStep(c, 0.1, 0.1, 0), OK);
    assert!(h.messages().is_empty());
    assert_eq!(fmi2DoStep(c, 5.0, 0.1, 0), ERROR);
    assert_eq!(h.messages().len(), 1);
    // Errors can be silenced explicitly.
    let err = [c"logStatusError".as_ptr()];
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 0, 1, err.as_ptr()) }, OK);
    h.clear();
    assert_eq!(fmi2DoStep(c, 5.0, 0.1, 0), ERROR);
    assert!(h.messages().is_empty());
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 1, 1, err.as_ptr()) }, OK);
    // Unknown category, NULL array.
    let bad = [c"logEverything".as_ptr()];
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 1, 1, bad.as_ptr()) }, ERROR);
    assert!(h.last().contains("logEverything") && h.last().contains("logEvents"), "{}", h.last());
    assert_eq!(unsafe { fmi2SetDebugLogging(c, 1, 2, null()) }, ERROR);
    assert!(h.last().contains("categories[] is NULL"), "{}", h.last());
    unsafe { fmi2FreeInstance(c) };
}

#[test]
fn invalid_parameter_at_exit_initialization_names_it_and_enters_error_state() {
    let h = Host::new();
    let c = h.instantiate();
    assert_eq!(set(c, "materials.pin_elastic_modulus", -5e9), OK, "parameters are checked at exit");
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    // A getter of an output in initialization mode already reports it.
    assert_eq!(try_get(c, "torque"), Err(ERROR));
    assert!(h.last().contains("materials.pin_elastic_modulus = -5000000000 Pa"), "{}", h.last());
    assert_eq!(fmi2ExitInitializationMode(c), ERROR);
    let m = h.last();
    assert!(m.starts_with("fmi2ExitInitializationMode") && m.contains("materials.pin_elastic_modulus = -5000000000 Pa") && m.contains("out of range"), "{m}");
    // Error state: step refused, parameters readable, reset allowed.
    assert_eq!(fmi2DoStep(c, 0.0, 0.1, 0), ERROR);
    assert!(h.last().contains("state error"), "{}", h.last());
    assert_eq!(get(c, "materials.pin_elastic_modulus"), -5e9);
    assert_eq!(fmi2Reset(c), OK);
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK);
    unsafe { fmi2FreeInstance(c) };

    for (name, v, expect) in [
        ("geometry.bush_radius", 0.027, "geometry.bush_radius"),
        ("materials.bush_poisson_ratio", 0.5, "materials.bush_poisson_ratio = 0.5"),
        ("lubricant.viscosity", f64::NAN, "lubricant.viscosity = NaN Pa.s"),
        ("zero_velocity.speed_band", -0.1, "zero_velocity.speed_band = -0.1 rad/s"),
        ("zero_velocity.speed_band", f64::INFINITY, "zero_velocity.speed_band = inf rad/s"),
    ] {
        let c = h.instantiate();
        assert_eq!(set(c, name, v), OK);
        assert_eq!(fmi2EnterInitializationMode(c), OK);
        assert_eq!(fmi2ExitInitializationMode(c), ERROR, "{name}");
        assert!(h.last().contains(expect), "{name}: {}", h.last());
        unsafe { fmi2FreeInstance(c) };
    }
}

/// At rest from a fresh start (presliding state 0, angle and angular velocity 0) the joint is
/// in the elastic range on both sides, where torque = -(tau + k delta + t_d k omega) is smooth.
/// With respect to the angle: the stiffness -k, k = T/phi_s.
#[test]
fn directional_derivative_with_respect_to_the_angle_at_rest_is_the_stiffness() {
    at_rest_partial("angle", |_, k| -k);
}

/// With respect to the angular velocity: the damping -t_d k (the law takes ω's partials at
/// rest in the unloading direction, where the range is elastic).
#[test]
fn directional_derivative_with_respect_to_the_angular_velocity_at_rest_is_the_damping() {
    at_rest_partial("angular_velocity", |law, k| -law.damping_time * k);
}

fn at_rest_partial(known: &str, expect: impl Fn(&pinjoint::zero_velocity::presliding::Presliding, f64) -> f64) {
    let (_h, c) = ready_pin_joint();
    let law = pinjoint::zero_velocity::presliding::Presliding::default();
    let bound = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap().evaluate(20e3, 0.0).unwrap().torque;
    let expect = expect(&law, bound / law.angle);
    let r = [vr("torque")];
    let mut d = [f64::NAN];
    assert_eq!(unsafe { fmi2GetDirectionalDerivative(c, r.as_ptr(), 1, [vr(known)].as_ptr(), 1, [1.0].as_ptr(), d.as_mut_ptr()) }, OK);
    assert!((d[0] - expect).abs() <= 1e-6 * expect.abs(), "d torque / d {known} = {} vs {expect}", d[0]);
    unsafe { fmi2FreeInstance(c) };
}
