//! `pinjoint-bench`, per cycle simulation: wall time of 10 strokes of the 1 Hz rig at 20 kN
//! against the torque error versus a tight-tolerance reference, for Dopri5 and Dop853 over
//! tolerances, RK4 over steps, the regularised formulation, fewer output samples and the
//! table fidelity for the friction.
//!
//! Torque error: the largest |T − T_ref| over the run's samples (the actuator torque the rig
//! records, at the same times in both runs) divided by the reference's peak |T|. The
//! reference is Dop853 at rtol = atol = 1e-12 with the full solve, sampled at the finest grid
//! used, so every run's sample times are reference sample times. The eq. 11 cycle average is
//! reported beside it (relative error of the mean |T| over cycles 2..10).

use super::bench_error::Result;
use pinjoint::fidelity::Fidelity;
use pinjoint::rig::{cycle_average_friction_coefficient, Formulation, Method, RigConfig, RigError, RigSim, Sample, Stats};
use std::time::Instant;

/// One configuration of the rig run.
#[derive(Debug, Clone, PartialEq)]
pub struct RigCase {
    /// Group the case is plotted in (one curve per family).
    pub family: String,
    /// Human-readable name of the case (method, formulation, setting).
    pub label: String,
    /// ODE integrator of the rig.
    pub method: Method,
    /// How stick at stroke reversal is formulated (hybrid or regularised).
    pub formulation: Formulation,
    /// rtol = atol for the adaptive methods; the step for RK4.
    pub setting: f64,
    /// Output samples per stroke cycle.
    pub samples_per_cycle: usize,
    /// Friction fidelity: None = full solve; Some(tol) = table to that tolerance.
    pub table: Option<f64>,
}

/// What one case measured.
#[derive(Debug, Clone, PartialEq)]
pub struct RigResult {
    pub case: RigCase,
    /// Fastest of the repetitions, s (the table build excluded; see `build_seconds`).
    pub seconds: f64,
    /// Median of the repetitions, s.
    pub median_seconds: f64,
    /// Building the table (once per parameter set), s.
    pub build_seconds: f64,
    /// Largest |ΔT| of the recorded torque against the reference run, divided by the reference's
    /// peak |T| (dimensionless); NaN when the run failed.
    pub torque_error: f64,
    /// Relative error of the eq. 11 cycle-average friction coefficient against the reference run;
    /// NaN when the run failed.
    pub average_error: f64,
    /// Integrator steps taken.
    pub steps: u64,
    /// Right-hand-side evaluations (steps, rejected steps, re-integration to samples and events).
    pub evaluations: u64,
    /// Full friction solves (inside the equations of motion and one per sample).
    pub friction_solves: u64,
    /// Steps where the solver fell back (as counted by the rig's statistics).
    pub fallbacks: u64,
    /// Why the run failed, if it did (the errors are then NaN).
    pub error: Option<RigError>,
}

/// Stroke cycles each rig run simulates (at 1 Hz, 20 kN).
pub const CYCLES: f64 = 10.0;
/// Samples per cycle of the reference run the errors are measured against.
pub const REFERENCE_SAMPLES: usize = 2000;

/// The rig configuration of a case: the default rig at 1 Hz and 20 kN with the case's method,
/// formulation and tolerance (rtol = atol) or RK4 step.
pub fn config(case: &RigCase) -> RigConfig {
    let mut cfg = RigConfig::default();
    cfg.rig.frequency = 1.0;
    cfg.rig.load = 20e3;
    cfg.rig.method = case.method;
    cfg.rig.formulation = case.formulation;
    match case.method {
        Method::Rk4 => cfg.rig.rk4_step = case.setting,
        _ => (cfg.rig.rtol, cfg.rig.atol) = (case.setting, case.setting),
    }
    cfg
}

/// One run: (samples, stats, table build seconds, run seconds).
fn run_once(case: &RigCase) -> std::result::Result<(Vec<Sample>, Stats, f64, f64), RigError> {
    let cfg = config(case);
    let t0 = Instant::now();
    let mut sim = RigSim::new(&cfg)?;
    let mut build = 0.0;
    if let Some(tol) = case.table {
        let env = RigSim::drive_envelope(&cfg)?;
        let b = Instant::now();
        sim.set_fidelity(Fidelity::Table, tol, env)?;
        build = b.elapsed().as_secs_f64();
    }
    let period = cfg.rig.period();
    let samples = sim.run(CYCLES * period, period / case.samples_per_cycle as f64)?;
    let total = t0.elapsed().as_secs_f64() - build;
    Ok((samples, sim.stats(), build, total))
}

/// The cases of the report (`quick`: a few, with loose settings).
pub fn cases(quick: bool) -> Vec<RigCase> {
    let c = |family: &str, method, formulation, setting: f64, samples, table: Option<f64>| {
        let what = match method {
            Method::Rk4 => format!("h = {setting:.0e} s"),
            _ => format!("tol = {setting:.0e}"),
        };
        let extra = table.map_or(String::new(), |t| format!(", table {t:.0e}"));
        RigCase {
            family: family.into(),
            label: format!("{family}, {what}{extra}"),
            method,
            formulation,
            setting,
            samples_per_cycle: samples,
            table,
        }
    };
    use Formulation::{Hybrid, Regularised};
    use Method::{Dop853, Dopri5, Dopri5Dense, Rk4};
    if quick {
        return vec![
            c("Dopri5, 100 samples/cycle", Dopri5, Hybrid, 1e-6, 100, None),
            c("Dopri5 dense, 100 samples/cycle", Dopri5Dense, Hybrid, 1e-6, 100, None),
            c("RK4, 100 samples/cycle", Rk4, Hybrid, 1e-3, 100, None),
            c("Dopri5 + table, 100 samples/cycle", Dopri5, Hybrid, 1e-6, 100, Some(1e-5)),
        ];
    }
    let mut v = Vec::new();
    for tol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10] {
        v.push(c("Dopri5, 2000 samples/cycle", Dopri5, Hybrid, tol, 2000, None));
        v.push(c("Dop853, 2000 samples/cycle", Dop853, Hybrid, tol, 2000, None));
    }
    for h in [1e-3, 5e-4, 2e-4, 1e-4, 5e-5] {
        v.push(c("RK4, 2000 samples/cycle", Rk4, Hybrid, h, 2000, None));
    }
    for tol in [1e-5, 1e-7] {
        v.push(c("Dopri5 regularised, 2000 samples/cycle", Dopri5, Regularised, tol, 2000, None));
    }
    for tol in [3e-5, 5e-6, 3e-6] {
        v.push(c("Dopri5 dense, 100 samples/cycle", Dopri5Dense, Hybrid, tol, 100, None));
    }
    for tol in [1e-5, 1e-6, 1e-7, 1e-8] {
        v.push(c("Dopri5, 100 samples/cycle", Dopri5, Hybrid, tol, 100, None));
        v.push(c("Dopri5 dense, 100 samples/cycle", Dopri5Dense, Hybrid, tol, 100, None));
        v.push(c("Dop853, 100 samples/cycle", Dop853, Hybrid, tol, 100, None));
        v.push(c("Dopri5 + table, 100 samples/cycle", Dopri5, Hybrid, tol, 100, Some(1e-5)));
        v.push(c("Dop853 + table, 100 samples/cycle", Dop853, Hybrid, tol, 100, Some(1e-5)));
    }
    v
}

/// The reference run (Dop853, 1e-12, full solve, finest grid).
pub fn reference(quick: bool) -> Result<Vec<Sample>> {
    let tol = if quick { 1e-9 } else { 1e-12 };
    let case = RigCase {
        family: "reference".into(),
        label: "reference".into(),
        method: Method::Dop853,
        formulation: Formulation::Hybrid,
        setting: tol,
        samples_per_cycle: REFERENCE_SAMPLES,
        table: None,
    };
    run_once(&case).map(|r| r.0).map_err(|e| super::bench_error::BenchError::Invalid(format!("bench: the reference rig run failed: {e}")))
}

/// (largest |ΔT| / peak |T_ref|, relative error of the eq. 11 average).
pub fn errors(samples: &[Sample], reference: &[Sample], samples_per_cycle: usize) -> (f64, f64) {
    let stride = REFERENCE_SAMPLES / samples_per_cycle;
    let peak = reference.iter().map(|s| s.torque.abs()).fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (k, s) in samples.iter().enumerate() {
        match reference.get(k * stride) {
            Some(r) if (r.time - s.time).abs() <= 1e-9 => worst = worst.max((s.torque - r.torque).abs()),
            _ => return (f64::NAN, f64::NAN),
        }
    }
    let radius = RigConfig::default().model.geometry.pin_radius;
    let avg = |t: &[Sample]| cycle_average_friction_coefficient(t, 1.0, radius, 1).unwrap_or(f64::NAN);
    let (a, b) = (avg(samples), avg(reference));
    (worst / peak, ((a - b) / b).abs())
}

/// Run every case `reps` times (fastest and median kept) and measure its errors.
pub fn measure(cases: &[RigCase], reference: &[Sample], reps: usize, progress: &dyn Fn(&str)) -> Vec<RigResult> {
    cases
        .iter()
        .map(|case| {
            progress(&case.label);
            let mut times = Vec::new();
            let mut out = None;
            for _ in 0..reps.max(1) {
                match run_once(case) {
                    Ok(r) => {
                        times.push(r.3);
                        let slow = r.3 > 1.0;
                        out = Some(r);
                        if slow {
                            break; // a slow case (e.g. the stiff regularised one) is not repeated
                        }
                    }
                    Err(e) => {
                        return RigResult {
                            case: case.clone(),
                            seconds: f64::NAN,
                            median_seconds: f64::NAN,
                            build_seconds: f64::NAN,
                            torque_error: f64::NAN,
                            average_error: f64::NAN,
                            steps: 0,
                            evaluations: 0,
                            friction_solves: 0,
                            fallbacks: 0,
                            error: Some(e),
                        };
                    }
                }
            }
            let (samples, stats, build, _) = out.expect("at least one repetition");
            times.sort_by(f64::total_cmp);
            let (torque_error, average_error) = errors(&samples, reference, case.samples_per_cycle);
            RigResult {
                case: case.clone(),
                seconds: times[0],
                median_seconds: times[times.len() / 2],
                build_seconds: build,
                torque_error,
                average_error,
                steps: stats.steps,
                evaluations: stats.evaluations,
                friction_solves: stats.friction_solves,
                fallbacks: stats.fallbacks,
                error: None,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_against_itself_has_zero_error_and_a_coarser_one_does_not() {
        let mut case = cases(true)[0].clone();
        case.samples_per_cycle = 200;
        let cfg_samples = run_once(&case).unwrap().0;
        assert_eq!(errors(&cfg_samples, &cfg_samples, REFERENCE_SAMPLES).0, 0.0);
        // A 200/cycle run against a 2000/cycle one: times must line up every 10th sample.
        let fine = RigCase { samples_per_cycle: REFERENCE_SAMPLES, setting: 1e-9, ..case.clone() };
        let reference = run_once(&fine).unwrap().0;
        let (e, a) = errors(&cfg_samples, &reference, 200);
        assert!(e.is_finite() && e > 0.0 && e < 0.05, "{e}");
        assert!(a.is_finite());
    }
}
