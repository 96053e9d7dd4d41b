//! `pinjoint-bench --output DIR`: the work-precision report of issue 6, measured in one run on
//! this machine: `DIR/BENCHMARKS.md`, its SVG plots in `DIR/benches/results/`.

use super::bench_eval::{self, EvalResult};
use super::bench_calibrate;
use super::bench_batch;
use super::bench_report::{write_calibration_only, write_report, FmuSection, Report};
use super::bench_rig::{self, RigResult};
use super::bench_throughput;
use super::bench_error::{BenchError, Result};
use super::bench_output::{output_dir, report_written};
use clap::Parser;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

#[derive(Parser, Debug)]
#[command(
    about = "Measure speed against error (per evaluation, per rig cycle run, per FMU step) into DIR/BENCHMARKS.md",
    long_about = "Measure, in one run on this machine, and write DIR/BENCHMARKS.md with its SVG plots in DIR/benches/results/:\n  \
per evaluation: ns against the largest relative error in μ and torque for full (cold, warm), table at \
several tolerances and boundary, over two envelopes spanning the regimes;\n  \
per cycle simulation: wall time of 10 strokes of the 1 Hz rig at 20 kN against the torque error versus a \
Dop853 1e-12 reference, for Dopri5/Dop853 over tolerances, RK4 over steps, the regularised formulation, \
fewer output samples and the table fidelity;\n  \
throughput: a whole `pinjoint sweep` process over 1e6 rows (wall time, peak memory, and at 1e5 rows), the \
library's cold evaluation per point, and the SciPy implementation of the model (benches/scipy_reference.py, \
run by the same Python) per point, as ratios;\n  \
calibration of long records: a whole `pinjoint calibrate` process on a record of 1e6 and of 1e7 rows \
(wall time, peak memory, fit.csv size, the fitted μ_c and J against the truth; --only-calibration runs it alone);\n  \
scenes at scale: 1e4 presliding joints x 1e4 steps at table fidelity on 2 threads, full against table per joint-step, \
the batch's memory, and PreslidingBatch against Joint.evaluate and a Presliding loop in Python (--only-batch runs it alone);\n  \
per FMU step through fmpy: set inputs + doStep + get outputs per fidelity as a ratio to the PassThrough \
FMU in the same loop (needs target/fmu/*.fmu from `cargo run --release -p fmu_build` and a Python with \
fmpy, by default .venv/bin/python; without them the report says so).\n\
Timings are never asserted; the machine's load shows in them (fastest and median repeats are given).\n\n\
Examples:\n  pinjoint-bench --output .\n  pinjoint-bench --output /tmp/b --quick"
)]
pub struct BenchCmd {
    /// Output directory (BENCHMARKS.md; its plots bench_*.svg in DIR/benches/results)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// A few cases, few repetitions: every file, no meaningful figures (for a smoke test)
    #[arg(long)]
    pub quick: bool,
    /// Directory holding PinJoint.fmu and PassThrough.fmu
    #[arg(long, value_name = "DIR", default_value = "target/fmu")]
    pub fmu_dir: PathBuf,
    /// Python interpreter with fmpy
    #[arg(long, value_name = "FILE", default_value = ".venv/bin/python")]
    pub python: PathBuf,
    /// Skip the FMU section
    #[arg(long)]
    pub no_fmu: bool,
    /// Run only the long-record calibration case and write its section alone to
    /// DIR/BENCHMARKS_calibration.md (BENCHMARKS.md is written by the whole run only)
    #[arg(long)]
    pub only_calibration: bool,
    /// Python interpreter with the `pinjoint` package (the batch section's Python part)
    #[arg(long, value_name = "FILE", default_value = ".venv-python/bin/python")]
    pub package_python: PathBuf,
    /// Run only the scenes-at-scale (batch) section and replace it in DIR/BENCHMARKS.md in
    /// place (appended when absent); the rest of the file is left as it was
    #[arg(long)]
    pub only_batch: bool,
}

fn progress(what: &str) {
    eprintln!("bench: {what}");
}

/// The fmpy loop script: in the working directory, else in the source tree this was built from.
fn script() -> Option<PathBuf> {
    [Path::new("benches/fmu_step.py").to_path_buf(), Path::new(env!("CARGO_MANIFEST_DIR")).join("../../benches/fmu_step.py")]
        .into_iter()
        .find(|p| p.is_file())
}

fn fmu_section(cmd: &BenchCmd) -> FmuSection {
    if cmd.no_fmu {
        return FmuSection::Unavailable("skipped (--no-fmu)".into());
    }
    let (pin, pass) = (cmd.fmu_dir.join("PinJoint.fmu"), cmd.fmu_dir.join("PassThrough.fmu"));
    for f in [&pin, &pass] {
        if !f.is_file() {
            return FmuSection::Unavailable(format!("{} not found: run `cargo run --release -p fmu_build` first", f.display()));
        }
    }
    if !cmd.python.is_file() {
        return FmuSection::Unavailable(format!(
            "no Python at {}: create it with `python3 -m venv .venv && .venv/bin/pip install -r requirements-test.txt`",
            cmd.python.display()
        ));
    }
    let Some(script) = script() else { return FmuSection::Unavailable("benches/fmu_step.py not found".into()) };
    // 15 interleaved repeats, the fastest kept: with 7, the table step's ratio to the
    // pass-through scattered over 1.03–1.15 across four runs of one build on this noisy
    // machine (its instruction count, callgrind, moves by nothing between them).
    let (steps, reps) = if cmd.quick { ("500", "1") } else { ("20000", "15") };
    progress("per FMU step (fmpy)");
    let out = Command::new(&cmd.python).arg(&script).arg(&pin).arg(&pass).args(["--steps", steps, "--repeats", reps]).output();
    match out {
        Err(e) => FmuSection::Unavailable(format!("running {}: {e}", cmd.python.display())),
        Ok(o) if !o.status.success() => {
            FmuSection::Unavailable(format!("{} failed: {}", script.display(), String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("")))
        }
        Ok(o) => match serde_json::from_slice::<serde_json::Value>(&o.stdout) {
            Ok(mut v) => {
                let steps: usize = steps.parse().unwrap_or(20_000);
                v["solve_ns"] = serde_json::json!(solve_floor_ns(steps, v["step_size"].as_f64().unwrap_or(1e-3)));
                FmuSection::Measured(v)
            }
            Err(e) => FmuSection::Unavailable(format!("unreadable output of {}: {e}", script.display())),
        },
    }
}

/// The complete solve a full-fidelity PinJoint step makes, in this process on one thread: ns
/// per step, the fastest of 7 passes over the fmpy loop's inputs (benches/fmu_step.py: the
/// 1 Hz ±40° stroke at 20 kN ± 10 %, `steps` steps of `h` s from t = 0), each a cold
/// [`pinjoint::Joint::evaluate`] at the FMU's default parameters, as the FMU evaluates (cold
/// every step, so that its outputs are a function of its inputs). The FMU step can cost no
/// less than the pass-through's plus this.
fn solve_floor_ns(steps: usize, h: f64) -> f64 {
    use std::f64::consts::PI;
    let Ok(joint) = pinjoint::Joint::new(&pinjoint::Params::default()) else { return f64::NAN };
    let a = 40f64.to_radians();
    let inputs: Vec<(f64, f64)> = (0..steps)
        .map(|k| {
            let t = k as f64 * h;
            (20e3 * (1.0 + 0.1 * (0.3 * t).sin()), a * 2.0 * PI * (2.0 * PI * t).cos())
        })
        .collect();
    (0..7)
        .map(|_| {
            let t0 = Instant::now();
            let mut acc = 0.0;
            for &(p, w) in &inputs {
                acc += joint.evaluate(std::hint::black_box(p), std::hint::black_box(w)).map_or(f64::NAN, |o| o.torque);
            }
            std::hint::black_box(acc);
            t0.elapsed().as_secs_f64() * 1e9 / steps as f64
        })
        .fold(f64::INFINITY, f64::min)
}

pub fn run(cmd: &BenchCmd) -> Result<()> {
    let started = Instant::now();
    let dir = output_dir(&cmd.output)?;
    let work = tempfile::tempdir().map_err(|source| BenchError::Write { path: std::env::temp_dir(), source })?;
    if cmd.only_calibration {
        let calibration = bench_calibrate::measure(cmd.quick, work.path(), &progress);
        let path = write_calibration_only(&dir, &calibration, cmd.quick, started.elapsed().as_secs_f64())?;
        return report_written(&[path]);
    }
    if cmd.only_batch {
        let b = bench_batch::measure(cmd.quick, &cmd.package_python, &progress);
        let path = super::bench_report::write_batch_only(&dir, &b, cmd.quick, started.elapsed().as_secs_f64())?;
        return report_written(&[path]);
    }
    let eval: Vec<EvalResult> = bench_eval::measure(cmd.quick, &progress);
    progress("per cycle simulation: reference run");
    let reference = bench_rig::reference(cmd.quick)?;
    let reps = if cmd.quick { 1 } else { 5 };
    let rig: Vec<RigResult> = bench_rig::measure(&bench_rig::cases(cmd.quick), &reference, reps, &|l| progress(&format!("rig: {l}")));
    // The sweep and calibrate children run before any Python child: their peak memory is read
    // per child.
    let throughput = bench_throughput::measure(cmd.quick, &cmd.python, &cmd.package_python, work.path(), &progress);
    let calibration = bench_calibrate::measure(cmd.quick, work.path(), &progress);
    let fmu = fmu_section(cmd);
    let batch = bench_batch::measure(cmd.quick, &cmd.package_python, &progress);
    let report = Report { quick: cmd.quick, eval, rig, fmu, throughput, calibration, batch, seconds: started.elapsed().as_secs_f64() };
    let paths = write_report(&dir, &report)?;
    if paths.is_empty() {
        return Err(BenchError::Invalid("bench: nothing written".into()));
    }
    report_written(&paths)
}
