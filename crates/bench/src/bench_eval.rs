//! `pinjoint-bench`, per evaluation: ns per call against the largest relative error in μ and
//! torque for `full` (cold, warm), `table` at several tolerances and `boundary`.
//!
//! Timing points: a Lissajous path through the envelope in (ln P, ln |ω|), consecutive points
//! close as in a time-stepping host (so the warm start has a neighbour), crossing the regimes;
//! the time is the median over repetitions of the whole path. Errors: against the cold full
//! solve on the path and on random points of the envelope (a seed of this module, not used by
//! the tests).

use crate::eval_path::{ns_per_eval, path};
use pinjoint::fidelity::{Envelope, ErrorReport, Evaluator, Fidelity};
use pinjoint::{Joint, Params};
use std::time::Instant;

/// The seed of the random error points (not used by the tests).
const SEED: u64 = 0x6265_6e63_6802;

fn errors(ev: &mut Evaluator, j: &Joint, pts: &[(f64, f64)], random: usize) -> ErrorReport {
    crate::eval_path::errors(ev, j, pts, random, SEED)
}

/// What one fidelity level (or cold/warm full solve) measured along the benchmark path of one envelope.
#[derive(Debug, Clone, PartialEq)]
pub struct EvalResult {
    /// The model: [`COMPLETE`] (the default parameters) or [`PAPER`] (`model.paper = true`).
    pub model: &'static str,
    /// Name of the envelope (load and speed range) the path runs through, e.g. "rig: 5-60 kN, 0.01-10 rad/s".
    pub envelope: &'static str,
    /// The configuration measured: fidelity level, tolerance, cold or warm.
    pub label: String,
    /// Median ns per evaluation along the path.
    pub ns: f64,
    /// Largest relative error max |Δμ|/μ of the friction coefficient against the full solve, on the
    /// path and random points of the envelope.
    pub mu_error: f64,
    /// Largest relative error max |ΔT|/T of the friction torque against the full solve (see
    /// [`pinjoint::fidelity::ErrorReport`]).
    pub torque_error: f64,
    /// The level's advertised bound (None for cold/warm full: the solver's own).
    pub bound: Option<f64>,
    /// Build time (s), cells and size of a table.
    pub build_seconds: f64,
    /// Of a table: (load cells, speed cells, size in bytes); None for levels without a table.
    pub cells: Option<(usize, usize, usize)>,
}

/// The two envelopes measured, with their names: the rig's (5-60 kN, 0.01-10 rad/s) and a wide
/// one reaching 30 rad/s (from 10 kN: the table reaches beyond its envelope, and from 5 kN
/// to 100 rad/s it reached 1.85 kN x 62 rad/s, where the film passes the diametral clearance,
/// `pinjoint::ModelError::FilmBeyondClearance`).
pub fn envelopes() -> [(&'static str, Envelope); 2] {
    [
        ("rig: 5-60 kN, 0.01-10 rad/s", Envelope::new(5e3, 60e3, 0.01, 10.0).expect("valid")),
        ("wide: 10-60 kN, 0.01-30 rad/s", Envelope::new(10e3, 60e3, 0.01, 30.0).expect("valid")),
    ]
}

/// The default parameters' model (the journal bearing, the grease in the clearance, the cold supply).
pub const COMPLETE: &str = "complete";
/// The paper's model (`[model] paper = true`), on which the earlier targets were set.
pub const PAPER: &str = "model.paper";

/// Measure every level over both envelopes, for the complete model and the paper's.
/// `quick`: fewer points and repetitions.
pub fn measure(quick: bool, progress: &dyn Fn(&str)) -> Vec<EvalResult> {
    let mut paper = Params::default();
    paper.model.paper = true;
    let mut out = measure_model(COMPLETE, Params::default(), quick, progress);
    out.extend(measure_model(PAPER, paper, quick, progress));
    out
}

fn measure_model(model: &'static str, params: Params, quick: bool, progress: &dyn Fn(&str)) -> Vec<EvalResult> {
    let j = Joint::new(&params).expect("default parameters are valid");
    let (n, reps, random) = if quick { (256, 3, 500) } else { (1024, 21, 20_000) };
    let tolerances: &[f64] = if quick { &[1e-3] } else { &[1e-2, 1e-3, 1e-4, 1e-5] };
    let mut out = Vec::new();
    for (name, env) in envelopes() {
        let pts = path(&env, n);
        progress(&format!("per evaluation, {model}, {name}"));
        let row = |label: String, ns: f64, r: &ErrorReport, bound: Option<f64>, build: f64, cells| EvalResult {
            model,
            envelope: name,
            label,
            ns,
            mu_error: r.friction_coefficient,
            torque_error: r.torque,
            bound,
            build_seconds: build,
            cells,
        };
        let cold = ns_per_eval(|p, w| j.evaluate(p, w).map_or(f64::NAN, |o| o.torque), &pts, reps);
        out.push(row("full, cold".into(), cold, &ErrorReport::default(), None, 0.0, None));
        let mut full = Evaluator::new(&params, Fidelity::Full, 1e-4, env).expect("valid");
        let r = errors(&mut full, &j, &pts, random);
        let ns = ns_per_eval(|p, w| full.evaluate(p, w).map_or(f64::NAN, |e| e.torque), &pts, reps);
        out.push(row("full, warm".into(), ns, &r, None, 0.0, None));
        for &tol in tolerances {
            let t0 = Instant::now();
            let Ok(mut ev) = Evaluator::new(&params, Fidelity::Table, tol, env) else { continue };
            let build = t0.elapsed().as_secs_f64();
            let cells = ev.table().map(|t| (t.stats().load_cells, t.stats().speed_cells, t.size_bytes()));
            let r = errors(&mut ev, &j, &pts, random);
            let ns = ns_per_eval(|p, w| ev.evaluate(p, w).map_or(f64::NAN, |e| e.torque), &pts, reps);
            out.push(row(format!("table {tol:.0e}"), ns, &r, Some(ev.error_bound()), build, cells));
        }
        let mut b = Evaluator::new(&params, Fidelity::Boundary, 1e-4, env).expect("valid");
        let r = errors(&mut b, &j, &pts, random);
        let ns = ns_per_eval(|p, w| b.evaluate(p, w).map_or(f64::NAN, |e| e.torque), &pts, reps);
        out.push(row("boundary".into(), ns, &r, Some(b.error_bound()), 0.0, None));
    }
    out
}
