//! `pinjoint-bench`, throughput: a whole `pinjoint sweep` process over 1e6 rows (wall time and
//! peak memory, and the peak at 1e5 rows to show it does not grow with the rows), the
//! library's cold evaluation per point on the same rows, and the SciPy implementation of the
//! model (benches/scipy_reference.py) per point on the first rows of the sweep's output,
//! with its largest difference from the library. Every figure from one run.

use crate::bench_error::ThroughputError;
use pinjoint::{Joint, Params};
use std::hint::black_box;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// A `pinjoint sweep` child process: wall time and peak resident memory.
#[derive(Debug, Clone, Copy)]
pub struct SweepRun {
    /// Rows the sweep evaluated.
    pub rows: usize,
    /// Wall time of the process, in s.
    pub seconds: f64,
    /// Peak resident memory of the process, in MiB (from `getrusage`).
    pub peak_rss_mib: f64,
    /// CPU time of the process, user + system, in s (from `wait4`'s rusage): what the work
    /// costs whatever else the machine runs (the wall time grows with the load, this less).
    pub cpu_seconds: f64,
}

/// The SciPy reference on the first rows of the sweep's output.
#[derive(Debug, Clone)]
pub struct Scipy {
    /// Points SciPy evaluated.
    pub points: usize,
    /// SciPy's time per point, in s.
    pub seconds_per_point: f64,
    /// Largest relative difference from the library in μ, torque, h_c; absolute in the shares.
    pub max_difference: serde_json::Value,
    /// Python, NumPy and SciPy versions used, as the script reported them.
    pub versions: String,
}

/// The throughput section of the report: the sweep process, the library per point, SciPy.
#[derive(Debug)]
pub struct Throughput {
    /// Fastest of the repeats, at the full row count.
    pub sweep: SweepRun,
    /// At a tenth of the rows (memory must not depend on the row count).
    pub small: SweepRun,
    /// Library cold evaluation (`Joint::evaluate`), one thread, ns per point on the sweep's rows.
    pub model_ns: f64,
    /// Library cold evaluation in the mixed regime (20 kN, 6 rad/s), ns, median of repeats.
    pub mixed_cold_ns: f64,
    /// Worker threads of the rayon pool (the sweep's parallelism).
    pub threads: usize,
    /// The same sweep at `--fidelity boundary` (μ = μ_c: the sweep's floor), fastest of the repeats.
    pub boundary_sweep: SweepRun,
    /// The boundary sweep written as Parquet (`--output X.parquet`), fastest of the repeats,
    /// interleaved with the CSV one.
    pub parquet_sweep: SweepRun,
    /// Each repeat's Parquet / CSV wall time ratio at boundary fidelity, their median.
    pub parquet_ratio: f64,
    /// pyarrow's `read_table` of that Parquet file (s, best of 3), or why not.
    pub pyarrow_read: Result<f64, String>,
    /// Each repeat's Parquet / CSV CPU-time ratio at boundary fidelity, their median.
    pub parquet_cpu_ratio: f64,
    /// What both boundary sweeps do whatever their output, measured in this process on one
    /// thread over the same rows: [`SharedFloor`].
    pub shared_floor: SharedFloor,
    /// The same sweep with `[model] paper = true` (the model the SciPy reference implements),
    /// fastest of the repeats.
    pub paper_sweep: SweepRun,
    /// Library cold evaluation of the paper's model, one thread, ns per point on the rows.
    pub paper_model_ns: f64,
    /// Library cold evaluation of the paper's model in the mixed regime, ns, median.
    pub paper_mixed_cold_ns: f64,
    /// The SciPy reference on the paper model's sweep output, or why it could not run.
    pub scipy: Result<Scipy, ThroughputError>,
}

/// The part of a boundary sweep that does not depend on its output format, in CPU seconds for
/// all the rows, one thread (its CPU time, the fastest of three passes): a lower bound of what
/// either output's sweep costs in CPU.
#[derive(Debug, Clone, Copy)]
pub struct SharedFloor {
    /// The level's answer and its operating point (every output column) per row: the boundary
    /// level built as the sweep builds it (over the rows' own ranges), `evaluate` then
    /// `operating_point`.
    pub evaluate: f64,
    /// Reading the input's two numbers per row: split at the comma and parsed (`str::parse`),
    /// from text in memory; the sweep also reads the file and checks each field, so this is a
    /// lower bound of its parse. The Parquet sweep parses once (its first pass, which finds
    /// the envelope, keeps the numbers for the second); the CSV sweep twice (it copies the
    /// input's fields as written, so its second pass reads the text again).
    pub parse: f64,
}

/// This thread's CPU time, s (`CLOCK_THREAD_CPUTIME_ID`): what its work cost, whatever else
/// the machine runs meanwhile (compared with the sweeps' CPU time).
fn thread_cpu() -> f64 {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: clock_gettime writes the timespec it is given.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// Measure [`SharedFloor`] over `pts` as the sweep's input holds them, in CPU time of this
/// thread (the fastest of three passes).
fn shared_floor(pts: &[(f64, f64)]) -> SharedFloor {
    use pinjoint::fidelity::{Envelope, Evaluator, Fidelity};
    let (mut lo, mut hi) = ((f64::INFINITY, f64::INFINITY), (0.0f64, 0.0f64));
    for &(p, w) in pts {
        (lo.0, hi.0, lo.1, hi.1) = (lo.0.min(p.abs()), hi.0.max(p.abs()), lo.1.min(w.abs()), hi.1.max(w.abs()));
    }
    let env = Envelope { load_min: lo.0, load_max: hi.0, speed_min: lo.1, speed_max: hi.1 };
    let evaluate = match Evaluator::new(&Params::default(), Fidelity::Boundary, 1e-4, env) {
        Ok(mut ev) => (0..3)
            .map(|_| {
                let t = thread_cpu();
                let mut acc = 0.0;
                for &(p, w) in pts {
                    if let Ok(e) = ev.evaluate(black_box(p), black_box(w)) {
                        let op = ev.operating_point(&e);
                        acc += op.torque + op.clearance_torque + op.min_film_thickness;
                    }
                }
                black_box(acc);
                thread_cpu() - t
            })
            .fold(f64::INFINITY, f64::min),
        Err(_) => f64::NAN,
    };
    let mut text = String::with_capacity(pts.len() * 40);
    for (p, w) in pts {
        text.push_str(&format!("{p:?},{w:?}\n"));
    }
    let parse = (0..3)
        .map(|_| {
            let t = thread_cpu();
            let mut acc = 0.0;
            for line in black_box(&text).lines() {
                let mut f = line.split(',');
                let p: f64 = f.next().and_then(|x| x.parse().ok()).unwrap_or(0.0);
                let w: f64 = f.next().and_then(|x| x.parse().ok()).unwrap_or(0.0);
                acc += p + w;
            }
            black_box(acc);
            thread_cpu() - t
        })
        .fold(f64::INFINITY, f64::min);
    SharedFloor { evaluate, parse }
}

/// Deterministic rows over 5–60 kN and 1e-3–100 rad/s (both signs), log-uniform.
fn points(n: usize) -> Vec<(f64, f64)> {
    let mut next = crate::rng::uniform(0x7377_6565_7031);
    (0..n)
        .map(|_| {
            let p = (5e3f64.ln() + (60e3f64 / 5e3).ln() * next()).exp();
            let w = (1e-3f64.ln() + (100.0f64 / 1e-3).ln() * next()).exp();
            (p, if next() < 0.5 { -w } else { w })
        })
        .collect()
}

fn write_points(path: &Path, pts: &[(f64, f64)]) -> std::io::Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(w, "load,speed")?;
    for (p, s) in pts {
        writeln!(w, "{p:?},{s:?}")?;
    }
    w.flush()
}

/// Run `exe sweep` on `input` into `output`; its wall time and peak RSS (wait4's rusage).
fn sweep_child(exe: &Path, input: &Path, output: &Path, rows: usize, extra: &[&std::ffi::OsStr]) -> Result<SweepRun, ThroughputError> {
    let t0 = Instant::now();
    let mut cmd = Command::new(exe);
    cmd.args(["sweep", "--input"]).arg(input).arg("--output").arg(output).args(extra);
    let child = cmd
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .map_err(|source| ThroughputError::Spawn { program: exe.to_path_buf(), source })?;
    let pid = child.id() as libc::pid_t;
    let mut status: libc::c_int = 0;
    // SAFETY: rusage is plain data, zero is a valid value; wait4 reaps our own child by pid.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let seconds = t0.elapsed().as_secs_f64();
    if r != pid || !libc::WIFEXITED(status) || libc::WEXITSTATUS(status) != 0 {
        return Err(ThroughputError::Sweep { rows, status });
    }
    // ru_maxrss is in KiB on Linux.
    let tv = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    Ok(SweepRun { rows, seconds, peak_rss_mib: usage.ru_maxrss as f64 / 1024.0, cpu_seconds: tv(usage.ru_utime) + tv(usage.ru_stime) })
}

fn scipy(python: &Path, sweep_output: &Path, points: usize) -> Result<Scipy, ThroughputError> {
    let script = [PathBuf::from("benches/scipy_reference.py"), Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/scipy_reference.py")]
        .into_iter()
        .find(|p| p.is_file())
        .ok_or(ThroughputError::NoScipyScript)?;
    if !python.is_file() {
        return Err(ThroughputError::NoPython(python.to_path_buf()));
    }
    let o = Command::new(python)
        .arg(&script)
        .arg(sweep_output)
        .args(["--limit", &points.to_string()])
        .output()
        .map_err(|source| ThroughputError::Spawn { program: python.to_path_buf(), source })?;
    if !o.status.success() {
        let stderr_tail = String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("").to_owned();
        return Err(ThroughputError::Scipy { script, stderr_tail });
    }
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).map_err(|source| ThroughputError::ScipyOutput { script, source })?;
    Ok(Scipy {
        points: v["points"].as_u64().unwrap_or(0) as usize,
        seconds_per_point: v["seconds_per_point"].as_f64().unwrap_or(f64::NAN),
        max_difference: v["max_difference"].clone(),
        versions: format!(
            "SciPy {}, NumPy {}, Python {}",
            v["scipy"].as_str().unwrap_or("?"),
            v["numpy"].as_str().unwrap_or("?"),
            v["python"].as_str().unwrap_or("?")
        ),
    })
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The `pinjoint` binary of the same build, beside this one (target/release/).
pub fn pinjoint_exe() -> Result<PathBuf, ThroughputError> {
    let own = std::env::current_exe().map_err(ThroughputError::OwnExecutable)?;
    let exe = own.with_file_name(format!("pinjoint{}", std::env::consts::EXE_SUFFIX));
    if !exe.is_file() {
        return Err(ThroughputError::NoPinjoint(exe));
    }
    Ok(exe)
}

/// Measure. `quick`: 1e4 rows, few SciPy points. `work` is a scratch directory.
/// pyarrow's `read_table` of `path` in the package's Python (s, best of 3), or why not.
fn pyarrow_read(python: &Path, path: &Path) -> Result<f64, String> {
    if !python.is_file() {
        return Err(format!("no Python at {}", python.display()));
    }
    let code = "import sys, time, pyarrow.parquet as pq\nb = 1e9\nfor _ in range(3):\n    t = time.perf_counter(); pq.read_table(sys.argv[1]); b = min(b, time.perf_counter() - t)\nprint(b)";
    let o = Command::new(python).args(["-c", code]).arg(path).output().map_err(|e| e.to_string())?;
    if !o.status.success() {
        return Err(String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("pyarrow failed").to_string());
    }
    String::from_utf8_lossy(&o.stdout).trim().parse().map_err(|e| format!("{e}"))
}

pub fn measure(quick: bool, python: &Path, package_python: &Path, work: &Path, progress: &dyn Fn(&str)) -> Result<Throughput, ThroughputError> {
    let exe = pinjoint_exe()?;
    let rows = if quick { 10_000 } else { 1_000_000 };
    // Five interleaved repeats: the sweep against its floor is a ratio of two ~1 s processes on
    // a noisy machine (three gave 1.07× and 1.27× within the hour).
    let reps = if quick { 1 } else { 5 };
    let pts = points(rows);
    let (big_in, small_in, out) = (work.join("sweep_in.csv"), work.join("sweep_in_small.csv"), work.join("sweep_out.csv"));
    write_points(&big_in, &pts).map_err(|source| ThroughputError::Write { path: big_in.clone(), source })?;
    write_points(&small_in, &pts[..rows / 10]).map_err(|source| ThroughputError::Write { path: small_in.clone(), source })?;
    progress(&format!("throughput: pinjoint sweep over {} and {} rows", rows / 10, rows));
    let small = sweep_child(&exe, &small_in, &out, rows / 10, &[])?;
    let paper_toml = work.join("paper_model.toml");
    std::fs::write(&paper_toml, "[model]\npaper = true\n").map_err(|source| ThroughputError::Write { path: paper_toml.clone(), source })?;
    // Interleaved: the complete model's sweep, at boundary fidelity (its floor), and the
    // paper's, repeat by repeat.
    let (mut runs, mut boundary_runs, mut paper_runs, mut parquet_runs, mut parquet_ratios) = (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut parquet_cpu_ratios = Vec::new();
    let out_parquet = work.join("sweep_out.parquet");
    let boundary: [&std::ffi::OsStr; 2] = ["--fidelity".as_ref(), "boundary".as_ref()];
    let paper_args: [&std::ffi::OsStr; 2] = ["--params".as_ref(), paper_toml.as_os_str()];
    for _ in 0..reps {
        runs.push(sweep_child(&exe, &big_in, &out, rows, &[])?);
        boundary_runs.push(sweep_child(&exe, &big_in, &out, rows, &boundary)?);
        parquet_runs.push(sweep_child(&exe, &big_in, &out_parquet, rows, &boundary)?);
        let (b, q) = (boundary_runs[boundary_runs.len() - 1].seconds, parquet_runs[parquet_runs.len() - 1].seconds);
        parquet_ratios.push(q / b);
        let (b, q) = (boundary_runs[boundary_runs.len() - 1].cpu_seconds, parquet_runs[parquet_runs.len() - 1].cpu_seconds);
        parquet_cpu_ratios.push(q / b);
        paper_runs.push(sweep_child(&exe, &big_in, &out, rows, &paper_args)?);
    }
    let fastest = |runs: &[SweepRun]| {
        let f = *runs.iter().min_by(|a, b| a.seconds.total_cmp(&b.seconds)).expect("at least one run");
        SweepRun { peak_rss_mib: runs.iter().map(|r| r.peak_rss_mib).fold(0.0, f64::max), ..f }
    };
    let (sweep, boundary_sweep, paper_sweep) = (fastest(&runs), fastest(&boundary_runs), fastest(&paper_runs));
    let (parquet_sweep, parquet_ratio) = (fastest(&parquet_runs), median(parquet_ratios));
    let pyarrow_read = pyarrow_read(package_python, &out_parquet);
    progress("throughput: the boundary sweep's shared floor (evaluation, parse), one thread");
    let shared_floor = shared_floor(&pts);
    let parquet_cpu_ratio = median(parquet_cpu_ratios);
    progress("throughput: library cold evaluation per point");
    let mut paper = Params::default();
    paper.model.paper = true;
    let (model_ns, mixed_cold_ns) = cold_evaluation(&Joint::new(&Params::default())?, &pts, reps);
    let (paper_model_ns, paper_mixed_cold_ns) = cold_evaluation(&Joint::new(&paper)?, &pts, reps);
    progress("throughput: SciPy reference (model.paper)");
    // The last sweep written was the paper model's: its output is what SciPy checks.
    let scipy = scipy(python, &out, if quick { 20 } else { 300 });
    let _ = [big_in, small_in, out, paper_toml, out_parquet].iter().try_for_each(std::fs::remove_file);
    Ok(Throughput { sweep, small, model_ns, mixed_cold_ns, threads: rayon::current_num_threads(), boundary_sweep, parquet_sweep, parquet_ratio, pyarrow_read, parquet_cpu_ratio, shared_floor, paper_sweep, paper_model_ns, paper_mixed_cold_ns, scipy })
}

/// The library's cold evaluation of `j`, one thread: (ns per point over the first rows of
/// `pts`, median of `reps`; ns in the mixed regime, 20 kN and 6 rad/s, median of 21).
fn cold_evaluation(j: &Joint, pts: &[(f64, f64)], reps: usize) -> (f64, f64) {
    let n = pts.len().min(100_000);
    let model_ns = median(
        (0..reps.max(3))
            .map(|_| {
                let t = Instant::now();
                let mut acc = 0.0;
                for &(p, w) in &pts[..n] {
                    acc += j.evaluate(black_box(p), black_box(w)).map_or(f64::NAN, |o| o.torque);
                }
                black_box(acc);
                t.elapsed().as_secs_f64() * 1e9 / n as f64
            })
            .collect(),
    );
    let mixed_cold_ns = median(
        (0..21)
            .map(|_| {
                let t = Instant::now();
                for _ in 0..20_000 {
                    black_box(j.evaluate(black_box(20e3), black_box(6.0)).map_or(f64::NAN, |o| o.torque));
                }
                t.elapsed().as_secs_f64() * 1e9 / 20_000.0
            })
            .collect(),
    );
    (model_ns, mixed_cold_ns)
}
