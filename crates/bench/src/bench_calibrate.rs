//! `pinjoint-bench`, calibration of long records: a whole `pinjoint calibrate` process on one
//! record of 1e7 rows (an hour at 2.78 kHz: a 1 Hz, ±40° sine at 20 kN with J = 0.05 kg·m²,
//! μ_c = 0.105, 0.5 N·m of torque noise and a 17-bit angle encoder) and on 1e6 rows of the same
//! kind (ten times shorter): wall time, peak resident memory, the size of fit.csv, the block
//! length the sample budget set, and the fitted μ_c and J against the truth. Every figure from
//! one run.

use crate::bench_error::ThroughputError;
use pinjoint::{Joint, Params};
use std::f64::consts::TAU;
use std::io::Write;
use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The truth of the synthetic records.
pub const MU_C: f64 = 0.105;
/// Their rotating inertia (kg·m²).
pub const INERTIA: f64 = 0.05;
/// Their load (N).
pub const LOAD: f64 = 20e3;
/// Samples a second (an hour holds 1e7).
pub const RATE: f64 = 1e7 / 3600.0;

/// One `pinjoint calibrate` child process.
#[derive(Debug, Clone)]
pub struct CalibrateRun {
    /// Rows of the record.
    pub rows: usize,
    /// Wall time of the process, s.
    pub seconds: f64,
    /// Peak resident memory of the process, MiB (`getrusage`).
    pub peak_rss_mib: f64,
    /// Size of the record's CSV, MiB.
    pub input_mib: f64,
    /// Size of fit.csv, MiB.
    pub fit_csv_mib: f64,
    /// Block length of the averaging (1: none).
    pub block_length: usize,
    /// Fitted μ_c and its 95 % interval.
    pub mu_c: (f64, f64, f64),
    /// Fitted J and its 95 % interval (kg·m²).
    pub inertia: (f64, f64, f64),
}

/// Seconds to write the records (not part of the calibration's time).
#[derive(Debug)]
pub struct CalibrationBench {
    /// The runs, shortest record first.
    pub runs: Vec<CalibrateRun>,
    /// Wall time to make and write the records, s.
    pub generate_seconds: f64,
}

/// Write a record of `rows` rows: time, angle, torque (the model's friction + J·α + noise).
fn write_record(path: &Path, rows: usize) -> std::io::Result<()> {
    let mut p = Params::default();
    p.friction.boundary_friction_coefficient = MU_C;
    let joint = Joint::new(&p).map_err(std::io::Error::other)?;
    let (a, w) = (40f64.to_radians(), TAU);
    let q = TAU / 131072.0;
    let mut uniform = crate::rng::uniform(0x6361_6c69_6272);
    let mut f = std::io::BufWriter::with_capacity(1 << 20, std::fs::File::create(path)?);
    writeln!(f, "time,angle,torque")?;
    let mut guess = None;
    for i in 0..rows {
        let t = i as f64 / RATE;
        let (sn, cs) = (w * t).sin_cos();
        let omega = a * w * cs;
        let alpha = -a * w * w * sn;
        let op = joint.evaluate_from(LOAD, omega, guess).map_err(std::io::Error::other)?;
        guess = op.logit.is_finite().then_some(op.logit);
        // Box–Muller noise of 0.5 N·m.
        let noise = 0.5 * (-2.0 * (uniform() + 1e-300).ln()).sqrt() * (TAU * uniform()).cos();
        let torque = INERTIA * alpha - op.signed_torque() + noise;
        let angle = (a * sn / q).round() * q;
        writeln!(f, "{t:.7},{angle:.9},{torque:.6}")?;
    }
    f.flush()
}

fn mib(path: &Path) -> f64 {
    std::fs::metadata(path).map_or(0.0, |m| m.len() as f64 / (1024.0 * 1024.0))
}

/// Run `exe calibrate` on `input`; wall time, peak RSS, and the JSON it prints.
fn calibrate_child(exe: &Path, input: &Path, out: &Path, rows: usize) -> Result<CalibrateRun, ThroughputError> {
    let t0 = Instant::now();
    let child = Command::new(exe)
        .args(["calibrate", "--load", "20000", "--json"])
        .arg("--input")
        .arg(input)
        .arg("--output")
        .arg(out)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map_err(|source| ThroughputError::Spawn { program: exe.to_path_buf(), source })?;
    let pid = child.id() as libc::pid_t;
    // The JSON is one short line: read it before reaping (the pipe cannot fill).
    let mut stdout = child.stdout.ok_or(ThroughputError::Calibrate { rows, status: -1 })?;
    let mut text = String::new();
    std::io::Read::read_to_string(&mut stdout, &mut text).map_err(|source| ThroughputError::Spawn { program: exe.to_path_buf(), source })?;
    let mut status: libc::c_int = 0;
    // SAFETY: rusage is plain data, zero is a valid value; wait4 reaps our own child by pid.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let seconds = t0.elapsed().as_secs_f64();
    if r != pid || !libc::WIFEXITED(status) || libc::WEXITSTATUS(status) != 0 {
        return Err(ThroughputError::Calibrate { rows, status });
    }
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|_| ThroughputError::Calibrate { rows, status: -2 })?;
    let est = |e: &serde_json::Value| {
        (e["value"].as_f64().unwrap_or(f64::NAN), e["ci95"][0].as_f64().unwrap_or(f64::NAN), e["ci95"][1].as_f64().unwrap_or(f64::NAN))
    };
    Ok(CalibrateRun {
        rows,
        seconds,
        peak_rss_mib: usage.ru_maxrss as f64 / 1024.0,
        input_mib: mib(input),
        fit_csv_mib: mib(&out.join("fit.csv")),
        block_length: v["block_length"].as_u64().unwrap_or(0) as usize,
        mu_c: est(&v["parameters"]["friction.boundary_friction_coefficient"]),
        inertia: est(&v["inertia_estimate"]),
    })
}

/// Measure: records of 1e6 and 1e7 rows (1e4 and 1e5 when `quick`) in `work`.
pub fn measure(quick: bool, work: &Path, progress: &dyn Fn(&str)) -> Result<CalibrationBench, ThroughputError> {
    let exe = crate::bench_throughput::pinjoint_exe()?;
    let sizes: &[usize] = if quick { &[10_000, 100_000] } else { &[1_000_000, 10_000_000] };
    let t0 = Instant::now();
    let mut inputs = Vec::new();
    for &n in sizes {
        progress(&format!("calibration: writing a record of {n} rows"));
        let path = work.join(format!("record_{n}.csv"));
        write_record(&path, n).map_err(|source| ThroughputError::Write { path: path.clone(), source })?;
        inputs.push((n, path));
    }
    let generate_seconds = t0.elapsed().as_secs_f64();
    let mut runs = Vec::new();
    for (n, path) in &inputs {
        progress(&format!("calibration: pinjoint calibrate on {n} rows"));
        let out = work.join(format!("cal_{n}"));
        runs.push(calibrate_child(&exe, path, &out, *n)?);
        // The record is not needed any more: free the disk (PINJOINT_BENCH_KEEP=DIR keeps it
        // there, for a run under another tool such as `/usr/bin/time -v`).
        match std::env::var_os("PINJOINT_BENCH_KEEP") {
            Some(keep) => {
                let _ = std::fs::rename(path, Path::new(&keep).join(path.file_name().unwrap_or_default()));
            }
            None => {
                let _ = std::fs::remove_file(path);
            }
        }
    }
    Ok(CalibrationBench { runs, generate_seconds })
}
