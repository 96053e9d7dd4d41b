//! The misuse and bad-input suite through the second importer, the Rust `fmi`
//! crate (issue 5, items 1, 2, 6, 7): wrong call sequences in every state the crate
//! can reach, bad arguments and values, bad serialized states, reset and re-run,
//! terminate twice, free without terminate, threads, state round-trips. Each
//! rejected call must come back as `Err(Fmi2Error::Error)`, log a message that says
//! what was wrong (captured through the `log` facade the crate logs to), and leave
//! the instance usable where the standard allows.
//!
//! NULL pointers, wrong GUIDs, Model Exchange instantiation and Model Exchange
//! calls on a Co-Simulation instance cannot be expressed through this crate's safe
//! API (it refuses them itself); `crates/fmu/tests/fmi2_*.rs` and the fmpy suite cover them.

use test_support::packaged;
use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common, InstanceCS};
use fmi::fmi2::Fmi2Error;
use fmi::traits::FmiStatus;
use fmi_layer::core::bytes::crc32;
use pinjoint_fmu::pin_joint::INFO;
use pinjoint::params::PARAMS;
use pinjoint::{Joint, Params};
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};

// --- the FMU and a logger that keeps the messages of each instance ------------------

/// `$PINJOINT_FMU`, or the cdylib of this very build packaged as an FMU (as in
/// crates/fmu/tests/fmi_crate_importer.rs), once per test process.
fn import() -> &'static Fmi2Import {
    static IMPORT: OnceLock<Fmi2Import> = OnceLock::new();
    IMPORT.get_or_init(|| packaged::import("PINJOINT_FMU", &INFO, "misuse"))
}

/// Messages by instance name (the crate logs each FMU message with the instance name as target).
struct Capture(Mutex<HashMap<String, Vec<(log::Level, String)>>>);

impl log::Log for Capture {
    fn enabled(&self, _: &log::Metadata) -> bool {
        true
    }
    fn log(&self, r: &log::Record) {
        self.0.lock().unwrap().entry(r.target().to_owned()).or_default().push((r.level(), r.args().to_string()));
    }
    fn flush(&self) {}
}

fn capture() -> &'static Capture {
    static CAPTURE: OnceLock<&'static Capture> = OnceLock::new();
    CAPTURE.get_or_init(|| {
        let c: &'static Capture = Box::leak(Box::new(Capture(Mutex::new(HashMap::new()))));
        log::set_logger(c).expect("no other logger in this test binary");
        log::set_max_level(log::LevelFilter::Trace);
        c
    })
}

/// A unique instance name, so that parallel tests do not see each other's messages.
fn unique(what: &str) -> String {
    static N: AtomicUsize = AtomicUsize::new(0);
    format!("{what}-{}", N.fetch_add(1, Ordering::Relaxed))
}

fn errors(name: &str) -> Vec<String> {
    capture().0.lock().unwrap().get(name).into_iter().flatten().filter(|m| m.0 == log::Level::Error).map(|m| m.1.clone()).collect()
}

fn vr(name: &str) -> u32 {
    INFO.variables[INFO.index_by_name(name).unwrap_or_else(|| panic!("no variable {name}"))].value_reference
}

fn outputs() -> Vec<u32> {
    (10..20).collect()
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum At {
    Instantiated,
    Init,
    Step,
    Terminated,
    Error,
}

/// An instance with its name, brought to a state.
fn instance(at: At) -> (InstanceCS, String) {
    capture();
    let name = unique("misuse");
    let mut i = import().instantiate_cs(&name, false, false).expect("instantiate");
    if at == At::Instantiated {
        return (i, name);
    }
    i.setup_experiment(None, 0.0, None).unwrap();
    if at == At::Error {
        i.set_real(&[vr("geometry.pin_radius")], &[-1.0]).unwrap();
    }
    i.enter_initialization_mode().unwrap();
    match at {
        At::Init => return (i, name),
        At::Error => {
            assert!(is_error(i.exit_initialization_mode()));
            return (i, name);
        }
        _ => {}
    }
    i.exit_initialization_mode().unwrap();
    i.set_real(&[vr("angular_velocity")], &[0.3]).unwrap();
    i.do_step(0.0, 0.1, true).unwrap();
    if at == At::Terminated {
        i.terminate().unwrap();
    }
    (i, name)
}

type Call = fn(&mut InstanceCS) -> Result<(), Fmi2Error>;

// Takes the call's result directly (`is_error(inst.do_step(..))`); a reference would clutter every call.
#[allow(clippy::needless_pass_by_value)]
fn is_error<T>(r: Result<T, Fmi2Error>) -> bool {
    matches!(r, Err(Fmi2Error::Error))
}

fn ok<T>(r: Result<T, Fmi2Error>) -> Result<(), Fmi2Error> {
    r.map(|_| ())
}

/// (state, what, call, fragment of the error message)
fn cases() -> Vec<(At, &'static str, Call, &'static str)> {
    use At::*;
    vec![
        // Call sequences the standard forbids.
        (Instantiated, "doStep before initialization", |i| ok(i.do_step(0.0, 0.1, true)), "fmi2DoStep: illegal call sequence"),
        (Instantiated, "exit before enter", |i| ok(i.exit_initialization_mode()), "fmi2ExitInitializationMode: illegal call sequence"),
        (Instantiated, "getReal before initialization", |i| ok(i.get_real(&[10], &mut [0.0])), "fmi2GetReal: illegal call sequence"),
        (Instantiated, "terminate before initialization", |i| ok(i.terminate()), "fmi2Terminate: illegal call sequence"),
        (Instantiated, "last successful time before initialization", |i| ok(i.last_successful_time()), "fmi2GetRealStatus: illegal call sequence"),
        (Init, "setupExperiment in initialization mode", |i| ok(i.setup_experiment(None, 0.0, None)), "fmi2SetupExperiment: illegal call sequence"),
        (Init, "enterInitializationMode twice", |i| ok(i.enter_initialization_mode()), "fmi2EnterInitializationMode: illegal call sequence"),
        (Init, "doStep in initialization mode", |i| ok(i.do_step(0.0, 0.1, true)), "fmi2DoStep: illegal call sequence"),
        (Init, "terminate in initialization mode", |i| ok(i.terminate()), "fmi2Terminate: illegal call sequence"),
        (Step, "enterInitializationMode after initialization", |i| ok(i.enter_initialization_mode()), "not allowed in state stepComplete"),
        (Step, "exitInitializationMode after initialization", |i| ok(i.exit_initialization_mode()), "fmi2ExitInitializationMode: illegal call sequence"),
        (Step, "setupExperiment after initialization", |i| ok(i.setup_experiment(None, 0.0, None)), "fmi2SetupExperiment: illegal call sequence"),
        (Terminated, "terminate twice", |i| ok(i.terminate()), "not allowed in state terminated"),
        (Terminated, "doStep after terminate", |i| ok(i.do_step(0.1, 0.1, true)), "fmi2DoStep: illegal call sequence"),
        (Terminated, "setReal after terminate", |i| ok(i.set_real(&[3], &[1e3])), "fmi2SetReal: illegal call sequence"),
        (Error, "doStep in the error state", |i| ok(i.do_step(0.0, 0.1, true)), "not allowed in state error"),
        (Error, "setReal in the error state", |i| ok(i.set_real(&[3], &[1e3])), "fmi2SetReal: illegal call sequence"),
        (Error, "terminate in the error state", |i| ok(i.terminate()), "fmi2Terminate: illegal call sequence"),
        (Error, "exitInitializationMode in the error state", |i| ok(i.exit_initialization_mode()), "fmi2ExitInitializationMode: illegal call sequence"),
        // Wrong value references and types.
        (Step, "unknown value reference in getReal", |i| ok(i.get_real(&[999], &mut [0.0])), "unknown value reference 999"),
        (Step, "unknown value reference in setReal", |i| ok(i.set_real(&[3, 12345], &[1.0, 2.0])), "unknown value reference 12345"),
        (Step, "set the torque output", |i| ok(i.set_real(&[10], &[5.0])), "output 'torque' (value reference 10) cannot be set"),
        (Step, "set the energy output", |i| ok(i.set_real(&[19], &[0.0])), "output 'dissipated_energy'"),
        (Step, "set a fixed parameter after initialization", |i| ok(i.set_real(&[100], &[0.03])), "variability 'fixed'"),
        (Step, "getInteger of a Real", |i| ok(i.get_integer(&[10], &mut [0])), "Real variable, not Integer"),
        (Step, "setInteger of a Real", |i| ok(i.set_integer(&[3], &[1])), "Real variable, not Integer"),
        (Step, "getBoolean of a Real", |i| ok(i.get_boolean(&[2], &mut [0])), "Real variable, not Boolean"),
        (Step, "setBoolean of an unknown reference", |i| ok(i.set_boolean(&[7], &[1])), "unknown value reference 7"),
        (Step, "setString of a Real", |i| ok(i.set_string(&[1], &[std::ffi::CString::new("x").unwrap()])), "Real variable, not String"),
        // Bad input values (every input, NaN and both infinities; negative load).
        (Step, "NaN load", |i| ok(i.set_real(&[3], &[f64::NAN])), "input load = NaN N"),
        (Step, "+inf load", |i| ok(i.set_real(&[3], &[f64::INFINITY])), "input load = inf N"),
        (Step, "-inf load", |i| ok(i.set_real(&[3], &[f64::NEG_INFINITY])), "input load = -inf N"),
        (Step, "NaN speed", |i| ok(i.set_real(&[2], &[f64::NAN])), "input angular_velocity = NaN rad/s"),
        (Step, "+inf speed", |i| ok(i.set_real(&[2], &[f64::INFINITY])), "input angular_velocity = inf rad/s"),
        (Step, "-inf speed", |i| ok(i.set_real(&[2], &[f64::NEG_INFINITY])), "input angular_velocity = -inf rad/s"),
        (Step, "NaN angle", |i| ok(i.set_real(&[1], &[f64::NAN])), "input angle = NaN rad"),
        (Step, "+inf angle", |i| ok(i.set_real(&[1], &[f64::INFINITY])), "input angle = inf rad"),
        (Step, "-inf angle", |i| ok(i.set_real(&[1], &[f64::NEG_INFINITY])), "input angle = -inf rad"),
        (Step, "a good and a bad value in one call", |i| ok(i.set_real(&[2, 3], &[1.0, f64::NAN])), "input load = NaN N"),
        // Communication points and step sizes.
        (Step, "negative step", |i| ok(i.do_step(0.1, -0.1, true)), "communicationStepSize = -0.1 s"),
        (Step, "zero step", |i| ok(i.do_step(0.1, 0.0, true)), "communicationStepSize = 0 s"),
        (Step, "NaN step", |i| ok(i.do_step(0.1, f64::NAN, true)), "communicationStepSize = NaN s"),
        (Step, "infinite step", |i| ok(i.do_step(0.1, f64::INFINITY, true)), "communicationStepSize = inf s"),
        (Step, "NaN communication point", |i| ok(i.do_step(f64::NAN, 0.1, true)), "currentCommunicationPoint = NaN s"),
        (Step, "-inf communication point", |i| ok(i.do_step(f64::NEG_INFINITY, 0.1, true)), "currentCommunicationPoint = -inf s"),
        (Step, "discontinuous communication point", |i| ok(i.do_step(0.5, 0.1, true)), "does not continue the last step, which ended at 0.1 s"),
        (Step, "communication point in the past", |i| ok(i.do_step(0.0, 0.1, true)), "does not continue"),
        // Functions this FMU does not provide.
        (Step, "unknown log category", |i| ok(i.set_debug_logging(true, &["logEverything"])), "unknown log category 'logEverything'"),
        (Step, "directional derivative with respect to a parameter", |i| ok(i.get_directional_derivative(&[10], &[100], &[1.0], &mut [0.0])), "partials with respect to parameters are not provided"),
        (Step, "directional derivative of an input", |i| ok(i.get_directional_derivative(&[2], &[3], &[1.0], &mut [0.0])), "continuous Real outputs"),
        (Step, "cancelStep", |i| ok(i.cancel_step()), "fmi2CancelStep: illegal call sequence"),
        (Step, "doStep status of a synchronous FMU", |i| ok(i.do_step_status()), "fmi2DoStepStatus is not available"),
        (Step, "pending status of a synchronous FMU", |i| ok(i.pending_status()), "fmi2PendingStatus is not available"),
        // Bad serialized states.
        (Step, "deserialize garbage", |i| ok(i.deserialize_fmu_state(&[1, 2, 3].repeat(40))), "bad magic"),
        (Step, "deserialize an empty buffer", |i| ok(i.deserialize_fmu_state(&[])), "truncated"),
        (Step, "deserialize a truncated state", |i| damaged(i, |b| b.truncate(b.len() - 5)), "truncated or extended"),
        (Step, "deserialize an extended state", |i| damaged(i, |b| b.push(0)), "truncated or extended"),
        (Step, "deserialize a corrupted state", |i| damaged(i, |b| { let n = b.len() / 2; b[n] ^= 0x10 }), "CRC-32 mismatch"),
        (Step, "deserialize a state of a newer format version", |i| damaged(i, |b| { b[8] = 2; fix_crc(b) }), "format version 2"),
        (Step, "deserialize a state of another model version", |i| damaged(i, |b| { let at = model_part(); b[at] = 10; fix_crc(b) }), "PinJoint state version 10"),
        (Step, "deserialize a state holding a NaN speed", |i| damaged(i, |b| {
            let at = model_part() + 3 + 8 * (PARAMS.len() + 2);
            b[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
            fix_crc(b);
        }), "input angular_velocity = NaN rad/s"),
        (Step, "deserialize a state of the layout before the presliding state", |i| damaged(i, |b| { let at = model_part(); b[at] = 4; fix_crc(b) }),
            "PinJoint state version 4; this FMU reads version 9"),
        (Step, "deserialize a state of the layout before the host conventions", |i| damaged(i, |b| { let at = model_part(); b[at] = 5; fix_crc(b) }),
            "PinJoint state version 5; this FMU reads version 9"),
        (Step, "deserialize a state holding a Model Exchange mode of 2", |i| damaged(i, |b| {
            let at = model_part() + 3 + 8 * (PARAMS.len() + 20);
            b[at..at + 8].copy_from_slice(&2.0f64.to_le_bytes());
            fix_crc(b);
        }), "presliding_mode = 2"),
        (Step, "deserialize a state holding a NaN presliding torque", |i| damaged(i, |b| {
            let at = model_part() + 3 + 8 * (PARAMS.len() + 16);
            b[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
            fix_crc(b);
        }), "presliding_torque = NaN"),
    ]
}

fn fix_crc(b: &mut [u8]) {
    let n = b.len();
    let crc = crc32(&b[..n - 4]);
    b[n - 4..].copy_from_slice(&crc.to_le_bytes());
}

/// Offset of the model's own part in a serialized state (src/fmi2/snapshot.rs layout).
fn model_part() -> usize {
    8 + 2 + 4 + 1 + INFO.guid().len() + 1 + 16 + 4
}

fn damaged(i: &mut InstanceCS, damage: fn(&mut Vec<u8>)) -> Result<(), Fmi2Error> {
    let s = i.get_fmu_state().unwrap();
    let mut b = i.serialize_fmu_state(&s).unwrap();
    damage(&mut b);
    ok(i.deserialize_fmu_state(&b))
}

#[test]
fn at_least_forty_misuse_cases_each_return_error_with_a_message_and_leave_the_instance_usable() {
    let cases = cases();
    assert!(cases.len() >= 40, "{} cases", cases.len());
    for (at, what, call, fragment) in cases {
        let (mut i, name) = instance(at);
        let before = if at != At::Step {
            vec![]
        } else {
            let mut v = vec![0.0; 13];
            let vrs: Vec<u32> = [1, 2, 3].into_iter().chain(outputs()).collect();
            i.get_real(&vrs, &mut v).unwrap();
            v
        };
        let n0 = errors(&name).len();
        assert!(is_error(call(&mut i)), "{what}");
        let new = errors(&name)[n0..].to_vec();
        assert!(new.iter().any(|m| m.contains(fragment)), "{what}: {fragment:?} not among the logged errors {new:?}");
        // The instance stays usable, unchanged, in its state.
        match at {
            At::Instantiated => {
                i.setup_experiment(None, 0.0, None).unwrap();
                i.enter_initialization_mode().unwrap();
                i.exit_initialization_mode().unwrap();
            }
            At::Init => i.exit_initialization_mode().map(|_| ()).unwrap(),
            At::Step => {
                let mut v = vec![0.0; 13];
                let vrs: Vec<u32> = [1, 2, 3].into_iter().chain(outputs()).collect();
                i.get_real(&vrs, &mut v).unwrap();
                assert_eq!(v.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), before.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), "{what} changed the instance");
                i.do_step(0.1, 0.1, true).unwrap();
            }
            At::Terminated => i.reset().map(|_| ()).unwrap(),
            At::Error => {
                // The error state allows getters and reset.
                let mut v = [0.0];
                i.get_real(&[vr("geometry.pin_radius")], &mut v).unwrap();
                assert_eq!(v[0], -1.0);
                i.reset().unwrap();
            }
        }
    }
}

#[test]
fn every_parameter_out_of_range_or_not_finite_is_refused_at_initialization_by_name() {
    let mut names: Vec<(String, f64)> = Vec::new();
    // The Real parameters (the switches model.paper and grease.enabled are Booleans: any
    // value a host can set is valid).
    for s in PARAMS.iter().filter(|s| s.kind == pinjoint::params::Kind::Real) {
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1.0] {
            names.push((s.name(), v));
        }
        if let (_, Some(hi)) = s.range.bounds() {
            names.push((s.name(), hi)); // all bounded ranges exclude their upper bound's neighbourhood or are half-open
        }
    }
    for v in [f64::NAN, f64::INFINITY, -1.0] {
        names.push(("zero_velocity.speed_band".into(), v));
    }
    let mut refused = 0;
    for (name, v) in &names {
        let (mut i, inst) = instance(At::Instantiated);
        i.setup_experiment(None, 0.0, None).unwrap();
        i.set_real(&[vr(name)], &[*v]).unwrap();
        i.enter_initialization_mode().unwrap();
        let mut p = Params::default();
        let valid = match pinjoint::params::spec_by_name(name) {
            Some(s) => {
                (s.set)(&mut p, *v);
                Joint::new(&p).is_ok()
            }
            None => v.is_finite() && *v >= 0.0,
        };
        if valid {
            // e.g. -1 is never valid, but an upper bound such as (0, 1] may be.
            // A valid set may still be refused where the start point's film (the zero-speed
            // band's edge at the start load) passes the clearance (eta_0 = 1e12 Pa.s: 78 km).
            if i.exit_initialization_mode().is_err() {
                assert!(errors(&inst).iter().any(|m| m.contains("film_thickness") && m.contains("diametral clearance")), "{name} = {v}: {:?}", errors(&inst));
                i.reset().unwrap();
            }
            continue;
        }
        assert!(is_error(i.exit_initialization_mode()), "{name} = {v}");
        let shown = fmi_layer::core::logging::show(*v);
        assert!(errors(&inst).iter().any(|m| m.contains(&format!("{name} = {shown}"))), "{name} = {v}: {:?}", errors(&inst));
        assert!(is_error(i.do_step(0.0, 0.1, true)), "no step in the error state");
        i.reset().unwrap();
        refused += 1;
    }
    assert!(refused >= 4 * 22, "{refused} of {} refused", names.len());
}

/// An instance past its first step (as [`instance`] `At::Step`) with `zero_velocity.model` = `model`.
fn stepped_with_model(model: i32) -> InstanceCS {
    capture();
    let mut i = import().instantiate_cs(&unique("extreme"), false, false).expect("instantiate");
    i.setup_experiment(None, 0.0, None).unwrap();
    i.set_integer(&[vr("zero_velocity.model")], &[model]).unwrap();
    i.enter_initialization_mode().unwrap();
    i.exit_initialization_mode().unwrap();
    i.set_real(&[vr("angular_velocity")], &[0.3]).unwrap();
    i.do_step(0.0, 0.1, true).unwrap();
    i
}

/// The band (set explicitly): outside it the torque is the library's, bit for bit.
#[test]
fn extreme_valid_inputs_give_the_library_values_never_nan() {
    let mut i = stepped_with_model(0);
    let joint = Joint::new(&Params::default()).unwrap();
    let mut t = 0.1;
    let mut v = vec![0.0; 10];
    // Zero load: unloaded, every output 0 but the energy.
    i.set_real(&[2, 3], &[1.0, 0.0]).unwrap();
    i.do_step(t, 0.1, true).unwrap();
    t += 0.1;
    i.get_real(&outputs(), &mut v).unwrap();
    assert!(v[..9].iter().all(|&x| x == 0.0), "{v:?}");
    // Beyond the asperity model's capacity (5.05e8 N for these parameters) a load is refused.
    assert!(i.set_real(&[3], &[1e9]).is_err());
    // (20e3, 1e6), (5e8, ±1e6) and (1e-30, 1e6) pass the film bound: crates/fmu/tests/fmi2_values.rs.
    for (load, w) in [(5e8, 1.0), (60e3, 1e-300), (1.0, 0.0)] {
        i.set_real(&[2, 3], &[w, load]).unwrap();
        i.do_step(t, 0.1, true).unwrap();
        t += 0.1;
        i.get_real(&outputs(), &mut v).unwrap();
        assert!(v.iter().all(|x| x.is_finite()), "load {load} w {w}: {v:?}");
        let op = joint.evaluate(load, w).unwrap();
        assert_eq!(v[1], op.friction_coefficient, "load {load} w {w}");
        assert_eq!(v[2], op.film_thickness, "load {load} w {w}");
        if w.abs() >= 0.01 {
            assert_eq!(v[0], op.signed_torque(), "load {load} w {w}");
        }
    }
}

/// Presliding (the default) on the same extreme inputs: finite, the library's friction
/// coefficient and film, and a torque opposing nothing beyond the documented bound: at most the
/// sliding torque plus the damping term t_d T |omega| / phi_s in magnitude.
#[test]
fn extreme_valid_inputs_under_presliding_are_finite_and_bounded() {
    let mut i = stepped_with_model(1);
    let joint = Joint::new(&Params::default()).unwrap();
    let law = pinjoint::zero_velocity::presliding::Presliding::default();
    let mut t = 0.1;
    let mut v = vec![0.0; 10];
    i.set_real(&[2, 3], &[1.0, 0.0]).unwrap();
    i.do_step(t, 0.1, true).unwrap();
    t += 0.1;
    i.get_real(&outputs(), &mut v).unwrap();
    assert!(v[..9].iter().all(|&x| x == 0.0), "{v:?}");
    // Extreme but inside the film bound (a film beyond the clearance is an error: crates/fmu/tests/ranges.rs).
    for (load, w) in [(5e8, 1.0), (5e8, -1e3), (60e3, 1e-300), (1e-300, 0.0)] {
        i.set_real(&[2, 3], &[w, load]).unwrap();
        i.do_step(t, 0.1, true).unwrap();
        t += 0.1;
        i.get_real(&outputs(), &mut v).unwrap();
        assert!(v.iter().all(|x| x.is_finite()), "load {load} w {w}: {v:?}");
        let op = joint.evaluate(load, w).unwrap();
        assert_eq!(v[1], op.friction_coefficient, "load {load} w {w}");
        assert_eq!(v[2], op.film_thickness, "load {load} w {w}");
        let bound = op.torque + law.damping_time * op.torque * w.abs() / law.angle;
        assert!(v[0].abs() <= bound * (1.0 + 1e-12), "load {load} w {w}: torque {} beyond {bound}", v[0]);
        assert!(v[8] >= 0.0, "power_loss {}", v[8]);
    }
}

fn run(i: &mut InstanceCS, k0: usize, k1: usize) -> Vec<u64> {
    let mut out = Vec::new();
    let mut v = vec![0.0; 10];
    for k in k0..k1 {
        let t = 0.01 * k as f64;
        i.set_real(&[1, 2, 3], &[(2.0 * t).cos(), 0.6 * (2.0 * t).sin(), 5e3 + 200.0 * k as f64]).unwrap();
        i.do_step(t, 0.01, true).unwrap();
        i.get_real(&outputs(), &mut v).unwrap();
        assert!(v.iter().all(|x| x.is_finite()));
        out.extend(v.iter().map(|x| x.to_bits()));
    }
    out
}

fn start(i: &mut InstanceCS) {
    i.setup_experiment(None, 0.0, None).unwrap();
    i.enter_initialization_mode().unwrap();
    i.exit_initialization_mode().unwrap();
}

#[test]
fn reset_then_a_fresh_run_equals_the_first_terminate_twice_and_free_without_terminate() {
    let (mut i, name) = instance(At::Instantiated);
    start(&mut i);
    let first = run(&mut i, 0, 200);
    i.terminate().unwrap();
    assert!(is_error(i.terminate()));
    assert!(errors(&name).last().unwrap().contains("fmi2Terminate: illegal call sequence"));
    i.reset().unwrap();
    start(&mut i);
    assert_eq!(run(&mut i, 0, 200), first);
    // Dropping the instance frees it without fmi2Terminate (stepComplete).
    drop(i);
    let (mut j, _) = instance(At::Instantiated);
    start(&mut j);
    assert_eq!(run(&mut j, 0, 200), first, "a new instance after a free without terminate");
}

#[test]
fn state_round_trips_bit_exactly_after_reversals_also_serialized() {
    let (mut i, _) = instance(At::Instantiated);
    start(&mut i);
    run(&mut i, 0, 320); // 0.6 sin(2t): two reversals by t = 3.2 s
    let s = i.get_fmu_state().unwrap();
    let bytes = i.serialize_fmu_state(&s).unwrap();
    let first = run(&mut i, 320, 480);
    i.set_fmu_state(&s).ok().unwrap();
    assert_eq!(run(&mut i, 320, 480), first, "get/set");
    let (mut j, _) = instance(At::Step);
    let d = j.deserialize_fmu_state(&bytes).unwrap();
    j.set_fmu_state(&d).ok().unwrap();
    assert_eq!(run(&mut j, 320, 480), first, "serialize/deserialize into another instance");
}

#[test]
fn eight_instances_on_eight_threads_equal_serial_runs() {
    capture();
    let imp = import();
    let one = |seed: usize| {
        let mut i = imp.instantiate_cs(&unique("thread"), false, false).unwrap();
        i.setup_experiment(None, 0.0, None).unwrap();
        i.set_real(&[vr("friction.boundary_friction_coefficient")], &[0.1 + 0.005 * seed as f64]).unwrap();
        i.enter_initialization_mode().unwrap();
        i.exit_initialization_mode().unwrap();
        let mut out = Vec::new();
        let mut v = vec![0.0; 10];
        for k in 0..400 {
            let t = 0.01 * f64::from(k);
            i.set_real(&[2, 3], &[(1.0 + seed as f64) * (3.0 * t).sin(), 5e3 * (1 + seed) as f64]).unwrap();
            i.do_step(t, 0.01, true).unwrap();
            i.get_real(&outputs(), &mut v).unwrap();
            out.extend(v.iter().map(|x| x.to_bits()));
        }
        out
    };
    let serial: Vec<Vec<u64>> = (0..8).map(one).collect();
    let parallel: Vec<Vec<u64>> = std::thread::scope(|s| {
        let hs: Vec<_> = (0..8).map(|k| s.spawn(move || one(k))).collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(serial, parallel);
    assert_ne!(serial[0], serial[1]);
}
