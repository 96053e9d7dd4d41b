//! The PinJoint FMU's co-simulation step (`fmi2SetReal` of the inputs, `fmi2DoStep`,
//! `fmi2GetReal` of the outputs) allocates nothing once the instance runs: no heap
//! allocation, so no string formatting or collected vectors, per step, at every fidelity, with
//! the temperature input held or changing at every step (full fidelity), presliding or band.
//! And its torque is the library's, bit for bit, at every step (full fidelity, band: the
//! library's torque outside the band).

use test_support::fmi2_host as common;
use common::*;
use fmi_layer::fmi2::api::common::*;
use fmi_layer::fmi2::api::cosim::*;
use fmi_layer::fmi2::types::Fmi2Component;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Counts allocations made by the thread that switched counting on (the test's own).
struct Counting;

static COUNTING: AtomicBool = AtomicBool::new(false);
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);
static SERIAL: Mutex<()> = Mutex::new(());

thread_local! {
    static OWN: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

fn note() {
    if COUNTING.load(Ordering::Relaxed) && OWN.try_with(std::cell::Cell::get).unwrap_or(false) {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
    }
}

// SAFETY: every call is forwarded to the system allocator unchanged; counting has no effect
// on the memory handed out.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note();
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note();
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note();
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations made by `f` on this thread.
fn allocations(f: impl FnOnce()) -> usize {
    OWN.with(|o| o.set(true));
    ALLOCATIONS.store(0, Ordering::SeqCst);
    COUNTING.store(true, Ordering::SeqCst);
    f();
    COUNTING.store(false, Ordering::SeqCst);
    OWN.with(|o| o.set(false));
    ALLOCATIONS.load(Ordering::SeqCst)
}

/// `steps` steps of the fmpy benchmark's loop (benches/fmu_step.py: a 1 Hz ±40° stroke at
/// 20 kN ± 10 %, 1 ms steps) from step `from`, the temperature set too when `warming` (rising
/// 1e-3 K a step from 308.15 K); the torques read.
fn run(c: Fmi2Component, from: usize, steps: usize, warming: bool, torques: &mut [f64]) {
    let (vin, vt) = ([vr("angular_velocity"), vr("load")], [vr("temperature")]);
    let vout = [vr("torque"), vr("friction_coefficient")];
    let (h, a) = (1e-3, 40f64.to_radians());
    let mut y = [0.0; 2];
    for k in from..from + steps {
        let t = k as f64 * h;
        let u = [a * 2.0 * std::f64::consts::PI * (2.0 * std::f64::consts::PI * t).cos(), 20e3 * (1.0 + 0.1 * (0.3 * t).sin())];
        assert_eq!(unsafe { fmi2SetReal(c, vin.as_ptr(), 2, u.as_ptr()) }, OK);
        if warming {
            let temp = [308.15 + 1e-3 * k as f64];
            assert_eq!(unsafe { fmi2SetReal(c, vt.as_ptr(), 1, temp.as_ptr()) }, OK);
        }
        assert_eq!(fmi2DoStep(c, t, h, 1), OK);
        assert_eq!(unsafe { fmi2GetReal(c, vout.as_ptr(), 2, y.as_mut_ptr()) }, OK);
        torques[k - from] = y[0];
    }
}

fn instance(h: &Host, fidelity: i32, sets: &[(&str, f64)]) -> Fmi2Component {
    let c = h.instantiate();
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    let r = [vr("fidelity")];
    assert_eq!(unsafe { fmi2SetInteger(c, r.as_ptr(), 1, [fidelity].as_ptr()) }, OK);
    for (n, v) in sets {
        assert_eq!(set(c, n, *v), OK, "{n}: {}", h.last());
    }
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
    c
}

#[test]
fn a_running_step_allocates_nothing() {
    let _g = SERIAL.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let env = [("envelope.load_min", 15e3), ("envelope.load_max", 25e3), ("envelope.speed_min", 1e-3), ("envelope.speed_max", 6.0)];
    type Case<'a> = (&'a str, i32, &'a [(&'a str, f64)], bool);
    let cases: [Case; 6] = [
        ("full", 0, &[], false),
        ("table", 1, &env, false),
        ("boundary", 2, &env, false),
        ("auto", 3, &env, false),
        ("full, band", 0, &[], false),
        ("full, warming", 0, &[], true),
    ];
    for (name, fidelity, sets, warming) in cases {
        let h = Host::new();
        let c = if name == "full, band" {
            // The band is an Integer parameter.
            let c = h.instantiate();
            assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
            let r = [vr("zero_velocity.model")];
            assert_eq!(unsafe { fmi2SetInteger(c, r.as_ptr(), 1, [0].as_ptr()) }, OK, "{}", h.last());
            assert_eq!(fmi2EnterInitializationMode(c), OK);
            assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
            c
        } else {
            instance(&h, fidelity, sets)
        };
        let mut torques = vec![0.0; 2000];
        // The first stroke may log once (a level's first fallback outside its envelope, near
        // the reversals, is said once: a message is formatted then) and set up what the
        // instance keeps; every later step allocates nothing.
        run(c, 0, 1000, warming, &mut torques);
        let n = allocations(|| run(c, 1000, 2000, warming, &mut torques));
        assert_eq!(n, 0, "{name}: {n} allocations in 2000 steps");
        assert!(torques.iter().all(|t| t.is_finite()) && torques.iter().any(|t| *t != 0.0), "{name}");
        free(c);
    }
}

/// At full fidelity with the band the step's torque outside the band is the library's cold
/// evaluation at the step's inputs, bit for bit, at every step (no work carried between steps
/// changes an answer).
#[test]
fn a_full_step_outside_the_band_is_the_library_bit_for_bit() {
    let _g = SERIAL.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let h = Host::new();
    let c = h.instantiate();
    assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), OK);
    let r = [vr("zero_velocity.model")];
    assert_eq!(unsafe { fmi2SetInteger(c, r.as_ptr(), 1, [0].as_ptr()) }, OK, "{}", h.last());
    assert_eq!(fmi2EnterInitializationMode(c), OK);
    assert_eq!(fmi2ExitInitializationMode(c), OK, "{}", h.last());
    let band = get(c, "zero_velocity.speed_band");
    let joint = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap();
    let n = 1500;
    let mut torques = vec![0.0; n];
    run(c, 0, n, false, &mut torques);
    let (h_step, a) = (1e-3, 40f64.to_radians());
    let mut compared = 0;
    for (k, t) in torques.iter().enumerate() {
        let time = k as f64 * h_step;
        let (w, p) = (a * 2.0 * std::f64::consts::PI * (2.0 * std::f64::consts::PI * time).cos(), 20e3 * (1.0 + 0.1 * (0.3 * time).sin()));
        if w.abs() > band {
            // The torque opposes the motion; its magnitude is the library's.
            let want = joint.evaluate(p, w).unwrap().torque;
            assert_eq!(t.abs().to_bits(), want.to_bits(), "step {k}: {t} against the library's {want}");
            assert!(t * w < 0.0, "step {k}: {t} at {w} rad/s");
            compared += 1;
        }
    }
    assert!(compared > n / 2, "{compared}");
    free(c);
}
