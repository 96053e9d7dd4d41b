//! Convergence study: the torque trace converges as the tolerance (or step) tightens. On the
//! paper's model (`model.paper = true`), whose torque is smooth in ω: the complete model's
//! grease adds K·|ω|^n (n = 0.4) in the clearance, not differentiable at ω = 0, and a fixed-step
//! RK4 through the stroke's reversals then converges at order ≈ 2 (measured: the error falls
//! ×3.4–3.6 per halving instead of ×16), the adaptive methods at their tolerance.

use pinjoint::rig::{Method, RigConfig, RigSim, Sample};

/// 1.5 strokes at 1 Hz, 20 kN: start-up, a stick with breakaway, the servo ringing, mid-stroke.
fn trace(method: Method, rtol: f64, step: f64) -> Vec<Sample> {
    let mut c = RigConfig::default();
    c.model.model.paper = true;
    c.rig.method = method;
    if method == Method::Rk4 {
        c.rig.rk4_step = step;
    } else {
        c.rig.rtol = rtol;
        c.rig.atol = 0.1 * rtol;
    }
    let mut sim = RigSim::new(&c).unwrap();
    sim.run(1.5, 1e-3).unwrap()
}

fn max_error(a: &[Sample], reference: &[Sample]) -> f64 {
    a.iter().zip(reference).map(|(x, r)| (x.torque - r.torque).abs()).fold(0.0, f64::max)
}

#[test]
fn torque_trace_converges_as_the_tolerance_tightens() {
    let reference = trace(Method::Dop853, 1e-13, 0.0);
    // The two adaptive methods agree with each other at tight tolerance.
    let dopri_tight = trace(Method::Dopri5, 1e-12, 0.0);
    assert!(max_error(&dopri_tight, &reference) < 1e-6);
    for method in [Method::Dopri5, Method::Dop853, Method::Dopri5Dense] {
        let tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
        let errs: Vec<f64> = tols.iter().map(|&t| max_error(&trace(method, t, 0.0), &reference)).collect();
        for (t, e) in tols.iter().zip(&errs) {
            println!("{method:?} rtol {t:.0e}: max |T - T_ref| = {e:.3e} N.m");
        }
        for w in errs.windows(2) {
            assert!(w[1] < w[0], "{method:?}: {errs:?}");
        }
        // From the loosest to the tightest tolerance the error falls by more than 4 decades.
        assert!(errs[errs.len() - 1] < 1e-4 * errs[0], "{method:?}: {errs:?}");
    }
    let steps = [4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5];
    let errs: Vec<f64> = steps.iter().map(|&h| max_error(&trace(Method::Rk4, 0.0, h), &reference)).collect();
    for (h, e) in steps.iter().zip(&errs) {
        println!("Rk4 step {h:.1e}: max |T - T_ref| = {e:.3e} N.m");
    }
    for w in errs.windows(2) {
        // Halving the step divides the error by more than 12 (order 4: 16; observed ≈ 16).
        assert!(w[1] < w[0] / 12.0, "RK4: {errs:?}");
    }
}
