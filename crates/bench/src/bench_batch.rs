//! `pinjoint-bench`, scenes at scale (issue 30): n presliding joints stepped together
//! (`pinjoint::batch`).
//!
//! In Rust: 10⁴ joints × 10⁴ steps at table fidelity on a pool of 2 threads (wall time);
//! the cost of a joint-step at full and at table fidelity over the same inputs (their ratio;
//! the table's envelope covers the scene's loads and speeds down to 1e-3 rad/s, [`ENVELOPE`];
//! also from 0.01 rad/s and over the default envelope; the ratios paired within each repeat);
//! the memory the batch holds beyond the caller's outputs (peak heap bytes counted by the
//! bench's allocator, [`crate::alloc_count`]). In Python (`benches/batch_step.py`, run by the
//! package's interpreter): `PreslidingBatch` at full fidelity against the vectorised
//! `Joint.evaluate` of as many points and against n `Presliding` objects in a Python loop.
//! Every figure is from one run; timings are never asserted.

use crate::alloc_count;
use pinjoint::batch::{BatchParams, Inputs, PreslidingBatch, Settings};
use pinjoint::fidelity::{Envelope, Fidelity};
use pinjoint::zero_velocity::Presliding;
use pinjoint::Params;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Input frames cycled through (each step sees other inputs than the one before).
const FRAMES: usize = 16;
/// Step of the scene (s).
const STEP: f64 = 1e-3;

/// The envelope of the table and boundary levels: the scene's loads (5–50 kN ± 20 %: 4–60 kN)
/// and speeds down to 1e-3 rad/s (the PinJointRig FMU's default for strokes that reverse) up
/// to 10 rad/s. Below 1e-3 rad/s (a joint reversing) the table's low speeds answer, down to rest.
pub const ENVELOPE: Envelope = Envelope { load_min: 4e3, load_max: 60e3, speed_min: 1e-3, speed_max: 10.0 };

/// [`ENVELOPE`] from 0.01 rad/s (the default speeds): a joint reversing spends ten times as
/// many steps below the table's range.
pub const ENVELOPE_FROM_0_01: Envelope = Envelope { speed_min: 0.01, ..ENVELOPE };

/// The inputs of `FRAMES` consecutive steps of n joints: each joint swings ±A_i at f_i
/// (0.2–2 Hz, 0.05–0.5 rad) under a load of 5–50 kN varying by ±20 %; one joint in ten held at
/// rest (ω = 0).
fn frames(n: usize) -> Vec<[Vec<f64>; 3]> {
    let mut u = crate::rng::uniform(0x6261_7463_6821);
    let joints: Vec<(f64, f64, f64, bool)> = (0..n).map(|_| (0.05 + 0.45 * u(), 0.2 + 1.8 * u(), 5e3 * 10f64.powf(u()), u() < 0.1)).collect();
    (0..FRAMES)
        .map(|k| {
            let t = 0.37 + k as f64 * STEP;
            let mut f = [Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n)];
            for &(a, hz, p, rest) in &joints {
                let w = std::f64::consts::TAU * hz;
                let (sn, cs) = (w * t).sin_cos();
                f[0].push(if rest { 1e-5 * sn } else { a * sn });
                f[1].push(if rest { 0.0 } else { a * w * cs });
                f[2].push(p * (1.0 + 0.2 * sn));
            }
            f
        })
        .collect()
}

fn batch(n: usize, fidelity: Fidelity, envelope: Envelope) -> PreslidingBatch {
    batch_at(n, fidelity, envelope, Params::default())
}

fn batch_at(n: usize, fidelity: Fidelity, envelope: Envelope, params: Params) -> PreslidingBatch {
    PreslidingBatch::new(n, BatchParams::Shared(params), Presliding::default(), Settings { fidelity, envelope, ..Settings::default() }).expect("valid settings")
}

/// The cold day's lubricant temperature (K): −54 °C, the grease in the clearance.
pub const COLD: f64 = 219.15;

/// The share of the moving joint-steps of `frames` outside `envelope` (answered by the
/// complete solve at table fidelity).
fn outside_share(frames: &[[Vec<f64>; 3]], envelope: &Envelope) -> f64 {
    let (mut outside, mut all) = (0usize, 0usize);
    for f in frames {
        for (&w, &p) in f[1].iter().zip(&f[2]) {
            all += 1;
            outside += usize::from(w != 0.0 && !envelope.contains(p, w));
        }
    }
    outside as f64 / all as f64
}

/// The kinds of host-driven scenes ([`scene`]): joints under a drive torque D = r·T_s (T_s
/// each joint's sliding torque at rest, its breakaway), integrated by the host.
pub const SCENES: [(&str, &str); 6] = [
    ("held", "constant drive 0.3–0.8 × T_s: the joints stick (presliding, ω → 0)"),
    ("creeping", "constant drive 0.8–0.99 × T_s: presliding near breakaway, creeping"),
    ("reversing", "drive 1.2–3 × T_s · sin(2π f t), f 0.5–2 Hz: sticking, breaking away and reversing twice a cycle"),
    ("sliding", "constant drive 1.6–3 × T_s: sliding at 0.3–5 rad/s after breakaway"),
    ("mixed", "drive 0.3–3 × T_s (log-uniform), half constant, half reversing at 0.5–2 Hz: most joints held"),
    ("service", "as `mixed`, loads 1–100 kN, over the default envelope (Envelope::SERVICE, no envelope given)"),
];

/// The scene kind run over the batch's default envelope ([`Settings::default`]) instead of
/// [`ENVELOPE`], with loads of 1–100 kN.
const SERVICE_SCENE: usize = 5;

/// Host inertia of the scenes (kg·m²) and their host's viscous damping, as a speed: a joint
/// driven at r·T_s slides at most at (r − 1)·[`SCENE_SPEED`] (rad/s) once broken away.
const SCENE_INERTIA: f64 = 20.0;
const SCENE_SPEED: f64 = 2.5;

/// One joint of a scene: (load N, drive ratio r, drive frequency Hz (0: constant), T_s N·m).
fn scene_joints(kind: usize, n: usize) -> Vec<(f64, f64, f64, f64)> {
    let joint = pinjoint::Joint::new(&Params::default()).expect("default parameters");
    let mut u = crate::rng::uniform(0x7363_656e_6500 + kind as u64);
    (0..n)
        .map(|_| {
            let p = if kind == SERVICE_SCENE { 1e3 * 10f64.powf(2.0 * u()) } else { 5e3 * 10f64.powf(u()) };
            let (r, f) = match kind {
                0 => (0.3 + 0.5 * u(), 0.0),
                1 => (0.8 + 0.19 * u(), 0.0),
                2 => (1.2 + 1.8 * u(), 0.5 + 1.5 * u()),
                3 => (1.6 + 1.4 * u(), 0.0),
                _ => {
                    let r = 0.3 * 10f64.powf(u());
                    (r, if u() < 0.5 { 0.0 } else { 0.5 + 1.5 * u() })
                }
            };
            (p, r, f, joint.boundary_torque(p))
        })
        .collect()
}

/// Run scene `kind` of n joints at `fidelity` over [`ENVELOPE`] for `warm` steps, then `steps`
/// timed ones: the host integrates J·dω/dt = D + T − c·ω (explicit, 1 ms; the batch knows
/// the host's inertia and step). Returns (ns a joint-step of the batch's calls alone, the
/// share of the timed joint-steps with 0 < |ω| < the envelope's lowest speed).
fn scene(kind: usize, n: usize, fidelity: Fidelity, warm: usize, steps: usize) -> (f64, f64) {
    let joints = scene_joints(kind, n);
    let envelope = if kind == SERVICE_SCENE { Settings::default().envelope } else { ENVELOPE };
    let mut b = batch(n, fidelity, envelope);
    b.set_host_inertia(Some(&vec![SCENE_INERTIA; n])).expect("a valid inertia");
    let (mut theta, mut omega, mut torque) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let load: Vec<f64> = joints.iter().map(|j| j.0).collect();
    let h = vec![STEP; n];
    let (mut spent, mut slow) = (0.0, 0usize);
    for k in 0..warm + steps {
        let t = k as f64 * STEP;
        let inputs = Inputs { angle: &theta, angular_velocity: &omega, load: &load, temperature: None };
        let t0 = Instant::now();
        b.step_with(&inputs, &h, &mut torque).expect("inputs inside the model's range");
        if k >= warm {
            spent += t0.elapsed().as_secs_f64();
            slow += omega.iter().filter(|w| **w != 0.0 && w.abs() < envelope.speed_min).count();
        }
        for (i, &(_, r, f, ts)) in joints.iter().enumerate() {
            let shape = if f == 0.0 { 1.0 } else { (std::f64::consts::TAU * f * t).sin() };
            let damping = ts / SCENE_SPEED;
            let accel = (r * ts * shape + torque[i] - damping * omega[i]) / SCENE_INERTIA;
            omega[i] += STEP * accel;
            theta[i] += STEP * omega[i];
        }
    }
    (spent * 1e9 / (n * steps) as f64, slow as f64 / (n * steps) as f64)
}

/// One scene's measurement.
#[derive(Debug, Clone)]
pub struct SceneBench {
    /// Its name ([`SCENES`]).
    pub name: &'static str,
    /// ns a joint-step at full and at table fidelity (fastest repeats).
    pub full_ns: f64,
    /// See `full_ns`.
    pub table_ns: f64,
    /// Table / full: the median over the repeats of each repeat's ratio.
    pub ratio: f64,
    /// Share of the joint-steps moving below the envelope's lowest speed (1e-3 rad/s), at table
    /// fidelity.
    pub slow: f64,
}

/// Every scene of [`SCENES`], table against full, paired within each repeat.
fn scenes(quick: bool) -> Vec<SceneBench> {
    let (n, warm, steps, reps) = if quick { (1_000, 100, 50, 1) } else { (2_000, 300, 100, 3) };
    SCENES
        .iter()
        .enumerate()
        .map(|(kind, &(name, _))| {
            let (mut full_ns, mut table_ns, mut ratios, mut slow) = (f64::INFINITY, f64::INFINITY, Vec::new(), 0.0);
            for _ in 0..reps {
                let (f, _) = scene(kind, n, Fidelity::Full, warm, steps);
                let (t, s) = scene(kind, n, Fidelity::Table, warm, steps);
                full_ns = full_ns.min(f);
                table_ns = table_ns.min(t);
                ratios.push(t / f);
                slow = s;
            }
            SceneBench { name, full_ns, table_ns, ratio: median(&mut ratios), slow }
        })
        .collect()
}

/// The median of `v` (not empty).
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let m = v.len() / 2;
    if v.len() % 2 == 1 { v[m] } else { 0.5 * (v[m - 1] + v[m]) }
}

/// Run `steps` steps of `b` over `frames`; seconds.
fn run(b: &mut PreslidingBatch, frames: &[[Vec<f64>; 3]], steps: usize, out: &mut [f64]) -> f64 {
    let t0 = Instant::now();
    for k in 0..steps {
        let f = &frames[k % frames.len()];
        let inputs = Inputs { angle: &f[0], angular_velocity: &f[1], load: &f[2], temperature: None };
        b.step(&inputs, out).expect("inputs inside the model's range");
    }
    t0.elapsed().as_secs_f64()
}

/// What the section measured.
#[derive(Debug, Clone)]
pub struct BatchBench {
    /// Joints and steps of the long table run, and its threads.
    pub joints: usize,
    /// Steps of the long run.
    pub steps: usize,
    /// Threads of the pool.
    pub threads: usize,
    /// Wall time of the long run (s), building the table included.
    pub table_seconds: f64,
    /// Time to build the batch's table (s).
    pub table_build_seconds: f64,
    /// ns per joint-step (wall time / joints / steps, 2 threads): full and table, the fastest
    /// of the repeats, over the same inputs.
    pub full_ns: f64,
    /// See `full_ns` ([`ENVELOPE`]).
    pub table_ns: f64,
    /// See `full_ns`: the table over [`ENVELOPE_FROM_0_01`].
    pub table_0_01_ns: f64,
    /// See `full_ns`: the table over the default envelope (`Envelope::SERVICE`), which the
    /// scene's lightest loads leave.
    pub table_default_ns: f64,
    /// The ratios table / full: the median over the repeats of each repeat's own ratio (the
    /// two measured back to back, so a busy moment of the machine weighs on both): over
    /// [`ENVELOPE`], [`ENVELOPE_FROM_0_01`] and the default envelope.
    pub ratios: (f64, f64, f64),
    /// The repeats.
    pub reps: usize,
    /// Shares of the joint-steps answered by the complete solve at table fidelity (moving,
    /// outside the envelope): over [`ENVELOPE`], [`ENVELOPE_FROM_0_01`] and the default
    /// envelope.
    pub outside: (f64, f64, f64),
    /// Peak heap bytes the batch held beyond the caller's output array, at table and full
    /// fidelity.
    pub peak_bytes_table: usize,
    /// See `peak_bytes_table`.
    pub peak_bytes_full: usize,
    /// The cold day (−54 °C, [`COLD`]): ns per joint-step at full and at table fidelity
    /// (fastest repeats, [`ENVELOPE`]), and the table cells answered by the complete solve out
    /// of all.
    pub cold_ns: (f64, f64),
    /// See `cold_ns`.
    pub cold_cells: (usize, usize),
    /// The host-driven scenes ([`SCENES`]) in Rust.
    pub scenes: Vec<SceneBench>,
    /// The default envelope's table built at several temperatures: (K, s, cells, bytes).
    pub default_builds: Vec<(f64, f64, usize, usize)>,
    /// The table's build at the batch's first step (s, the long run's table): its cells, and
    /// the speed floor below which the rest state answers (rad/s, 0: none).
    pub table_cells: (usize, usize, f64),
    /// The Python measurements (JSON of `benches/batch_step.py`), or why not.
    pub python: Result<serde_json::Value, String>,
}

/// The Python script: in the working directory, else in the source tree.
fn script() -> Option<PathBuf> {
    [Path::new("benches/batch_step.py").to_path_buf(), Path::new(env!("CARGO_MANIFEST_DIR")).join("../../benches/batch_step.py")].into_iter().find(|p| p.is_file())
}

fn python_part(python: &Path, quick: bool) -> Result<serde_json::Value, String> {
    if !python.is_file() {
        return Err(format!("no Python at {}: run `python/run_tests.sh` once (it makes .venv-python with the package)", python.display()));
    }
    let script = script().ok_or("benches/batch_step.py not found")?;
    let mut cmd = Command::new(python);
    cmd.arg(&script);
    if quick {
        cmd.arg("--quick");
    }
    let o = cmd.output().map_err(|e| format!("running {}: {e}", python.display()))?;
    if !o.status.success() {
        return Err(format!("{} failed: {}", script.display(), String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("")));
    }
    serde_json::from_slice(&o.stdout).map_err(|e| format!("unreadable output of {}: {e}", script.display()))
}

/// Measure the section. `python`: the interpreter with the `pinjoint` package.
pub fn measure(quick: bool, python: &Path, progress: &dyn Fn(&str)) -> BatchBench {
    let (joints, steps, short, reps) = if quick { (2_000, 200, 20, 1) } else { (10_000, 10_000, 200, 5) };
    let threads = 2;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("a thread pool");
    let frames = frames(joints);
    let mut out = vec![0.0; joints];
    progress("batch: full against table per joint-step");
    let default_envelope = Settings::default().envelope;
    let levels = [(Fidelity::Full, ENVELOPE), (Fidelity::Table, ENVELOPE), (Fidelity::Table, ENVELOPE_FROM_0_01), (Fidelity::Table, default_envelope)];
    // Per level: the fastest repeat, and each repeat's time (for the paired ratios).
    let mut best = [f64::INFINITY; 4];
    let mut each = vec![[0.0; 4]; reps];
    let (mut peak_full, mut peak_table) = (0, 0);
    pool.install(|| {
        for rep in each.iter_mut() {
            for (l, &(fid, env)) in levels.iter().enumerate() {
                let base = alloc_count::reset_peak();
                let mut b = batch(joints, fid, env);
                run(&mut b, &frames, 1, &mut out); // builds the model (the table)
                let s = run(&mut b, &frames, short, &mut out);
                let peak = alloc_count::peak() - base;
                let ns = s * 1e9 / (joints * short) as f64;
                rep[l] = ns;
                best[l] = best[l].min(ns);
                match l {
                    0 => peak_full = peak_full.max(peak),
                    1 => peak_table = peak_table.max(peak),
                    _ => {}
                }
            }
        }
    });
    let ratio = |l: usize| median(&mut each.iter().map(|r| r[l] / r[0]).collect::<Vec<_>>());
    let ratios = (ratio(1), ratio(2), ratio(3));
    let [full_ns, table_ns, table_0_01_ns, table_default_ns] = best;
    let outside = (outside_share(&frames, &ENVELOPE), outside_share(&frames, &ENVELOPE_FROM_0_01), outside_share(&frames, &default_envelope));
    progress("batch: the cold day (-54 °C), full against table per joint-step");
    let mut cold = Params::default();
    cold.lubricant.temperature = COLD;
    let cold_short = short.div_ceil(4);
    let (mut cold_full, mut cold_table, mut cold_cells) = (f64::INFINITY, f64::INFINITY, (0, 0));
    pool.install(|| {
        for _ in 0..reps {
            for fid in [Fidelity::Full, Fidelity::Table] {
                let mut b = batch_at(joints, fid, ENVELOPE, cold);
                run(&mut b, &frames, 1, &mut out);
                let ns = run(&mut b, &frames, cold_short, &mut out) * 1e9 / (joints * cold_short) as f64;
                if fid == Fidelity::Full {
                    cold_full = cold_full.min(ns);
                } else {
                    cold_table = cold_table.min(ns);
                }
            }
        }
    });
    if let Ok(ev) = pinjoint::fidelity::Evaluator::new(&cold, Fidelity::Table, Settings::default().tolerance, ENVELOPE) {
        let s = ev.table().map(|t| *t.stats());
        cold_cells = s.map_or((0, 0), |s| (s.solved_cells, s.load_cells * s.speed_cells));
    }
    progress(&format!("batch: {joints} joints x {steps} steps at table fidelity, {threads} threads"));
    let (table_seconds, table_build_seconds) = pool.install(|| {
        let t0 = Instant::now();
        let base = alloc_count::reset_peak();
        let mut b = batch(joints, Fidelity::Table, ENVELOPE);
        run(&mut b, &frames, 1, &mut out);
        let build = t0.elapsed().as_secs_f64();
        run(&mut b, &frames, steps - 1, &mut out);
        peak_table = peak_table.max(alloc_count::peak() - base);
        (t0.elapsed().as_secs_f64(), build)
    });
    progress("batch: host-driven scenes (held, creeping, reversing, sliding, mixed), table against full");
    let scenes = pool.install(|| scenes(quick));
    // The default envelope's table (no envelope given), built at the cold day, the cold and
    // warm rooms and the hot end of the service range: seconds (one build on the bench's pool),
    // cells and size.
    let default_builds: Vec<(f64, f64, usize, usize)> = pool.install(|| {
        [COLD, 253.15, 293.15, 318.15, 393.15]
            .iter()
            .filter_map(|&t| {
                let mut p = Params::default();
                p.lubricant.temperature = t;
                let t0 = Instant::now();
                let ev = pinjoint::fidelity::Evaluator::new(&p, Fidelity::Table, Settings::default().tolerance, Settings::default().envelope).ok()?;
                let seconds = t0.elapsed().as_secs_f64();
                let table = ev.table()?;
                let st = table.stats();
                Some((t, seconds, st.load_cells * st.speed_cells, table.size_bytes()))
            })
            .collect()
    });
    let table_cells = match pinjoint::fidelity::Evaluator::new(&Params::default(), Fidelity::Table, Settings::default().tolerance, ENVELOPE) {
        Ok(ev) => ev.table().map_or((0, 0, 0.0), |t| {
            let s = t.stats();
            (s.load_cells * s.speed_cells, s.low_speed_cells, s.speed_floor)
        }),
        Err(_) => (0, 0, 0.0),
    };
    progress("batch: Python (PreslidingBatch, Joint.evaluate, Presliding loop)");
    let python = python_part(python, quick);
    BatchBench { joints, steps, threads, table_seconds, table_build_seconds, full_ns, table_ns, table_0_01_ns, table_default_ns, ratios, reps, outside, cold_ns: (cold_full, cold_table), cold_cells, peak_bytes_table: peak_table, peak_bytes_full: peak_full, scenes, table_cells, default_builds, python }
}

fn met(ok: bool) -> &'static str {
    if ok { "**met**" } else { "**missed**" }
}

/// The section's targets (target, result) and its text.
pub fn section(b: &BatchBench) -> (Vec<(String, String)>, String) {
    let mut t = Vec::new();
    let mut body = String::new();
    let steps_total = (b.joints * b.steps) as f64;
    t.push((
        format!("{} scenes × {} steps at table fidelity ≤ 60 s on {} cores (Rust `pinjoint::batch`)", b.joints, b.steps, b.threads),
        format!("{} — {:.1} s = {:.2} × the target ({:.0} ns a joint-step; the table built in {:.3} s)", met(b.table_seconds <= 60.0), b.table_seconds, b.table_seconds / 60.0, b.table_seconds * 1e9 / steps_total, b.table_build_seconds),
    ));
    let r = b.ratios.0;
    t.push((
        "table fidelity costs ≤ 0.1 × full, per joint-step (batch, Rust)".into(),
        format!(
            "{} — {:.3} × (the median over {} repeats of each repeat's ratio; fastest repeats: table {:.1} ns, full {:.0} ns a joint-step, {} threads; {:.3} % of the joint-steps below the envelope's 1e-3 rad/s, answered by the table's low speeds). Over 4–60 kN × 0.01–10 rad/s ({:.2} % below): {:.3} × ({}; table {:.1} ns); over the default envelope ({}: {:.2} % outside) {:.3} × (table {:.1} ns)",
            met(r <= 0.1),
            r,
            b.reps,
            b.table_ns,
            b.full_ns,
            b.threads,
            100.0 * b.outside.0,
            100.0 * b.outside.1,
            b.ratios.1,
            if b.ratios.1 <= 0.1 { "within 0.1" } else { "above 0.1" },
            b.table_0_01_ns,
            {
                let e = Settings::default().envelope;
                format!("{}–{} kN × {}–{} rad/s", e.load_min / 1e3, e.load_max / 1e3, e.speed_min, e.speed_max)
            },
            100.0 * b.outside.2,
            b.ratios.2,
            b.table_default_ns
        ),
    ));
    for sc in &b.scenes {
        t.push((
            format!("a `{}` scene at table ≤ 0.1 × full, per joint-step (Rust, {} joints)", sc.name, if b.joints >= 10_000 { 2_000 } else { 1_000 }),
            format!("{} — {:.3} × (fastest repeats: table {:.1} ns, full {:.0} ns a joint-step; {:.1} % of the joint-steps moving below the envelope's lowest speed)", met(sc.ratio <= 0.1), sc.ratio, sc.table_ns, sc.full_ns, 100.0 * sc.slow),
        ));
    }
    t.push((
        "the table's build, counted (Rust, the long run's first step)".into(),
        format!(
            "{:.3} s for {} joints sharing one table ({} cells over the envelope, {} cells below it down to {:.1e} rad/s, the rest state under that); {:.2} % of the long run",
            b.table_build_seconds,
            b.joints,
            b.table_cells.0,
            b.table_cells.1,
            b.table_cells.2,
            100.0 * b.table_build_seconds / b.table_seconds
        ),
    ));
    t.push((
        "the default envelope's table (no envelope given: 1–100 kN, 0.01–100 rad/s and down to rest), its build by temperature".into(),
        b.default_builds
            .iter()
            .map(|(k, s, cells, bytes)| format!("{:.0} °C: {:.3} s, {} cells, {:.1} MiB", k - 273.15, s, cells, *bytes as f64 / 1048576.0))
            .collect::<Vec<_>>()
            .join("; "),
    ));
    let (cf, ct) = b.cold_ns;
    t.push((
        format!("the cold day ({} K, −54 °C, the grease in the clearance): table against full, per joint-step (Rust)", COLD),
        format!("{:.3} × (table {:.0} ns, full {:.0} ns a joint-step; {} of the table's {} cells answered by the complete solve)", ct / cf, ct, cf, b.cold_cells.0, b.cold_cells.1),
    ));
    let mib = |x: usize| x as f64 / (1024.0 * 1024.0);
    let worst = b.peak_bytes_table.max(b.peak_bytes_full);
    t.push((
        format!("memory of a batch of {} joints ≤ 64 MiB beyond the outputs", b.joints),
        format!("{} — peak {:.1} MiB at table fidelity, {:.1} MiB at full (heap bytes counted by the bench's allocator)", met(mib(worst) <= 64.0), mib(b.peak_bytes_table), mib(b.peak_bytes_full)),
    ));
    match &b.python {
        Ok(v) => {
            let f = |k: &str| v[k].as_f64().unwrap_or(f64::NAN);
            let floor = f("batch_step_ns") / f("evaluate_ns");
            t.push((
                "`PreslidingBatch` at full fidelity ≤ 1.5 × `Joint.evaluate` of as many points (Python)".into(),
                format!("{} — {:.3} × (a step {:.0} ns, evaluate {:.0} ns a joint; torque + commit {:.3} ×)", met(floor <= 1.5), floor, f("batch_step_ns"), f("evaluate_ns"), f("batch_torque_commit_ns") / f("evaluate_ns")),
            ));
            let gain = f("loop_ns") / f("batch_torque_commit_ns");
            t.push((
                "`PreslidingBatch` ≥ 2.5 × faster than `Presliding` objects in a Python loop".into(),
                format!("{} — {:.1} × (loop {:.0} ns a joint-step: torque + commit; batch torque + commit {:.0} ns)", met(gain >= 2.5), gain, f("loop_ns"), f("batch_torque_commit_ns")),
            ));
            t.push((
                "table fidelity ≤ 0.1 × full through Python (`PreslidingBatch.step`)".into(),
                format!(
                    "{} — {:.3} × (the median of the repeats' ratios; fastest repeats: table {:.0} ns, full {:.0} ns a joint-step; over the default envelope {:.3} ×)",
                    met(f("table_ratio") <= 0.1),
                    f("table_ratio"),
                    f("batch_table_ns"),
                    f("batch_step_ns"),
                    f("table_default_ratio")
                ),
            ));
            if let Some(sc) = v["scenes"].as_object() {
                for (name, _) in SCENES {
                    let Some(x) = sc.get(name) else { continue };
                    let g = |k: &str| x[k].as_f64().unwrap_or(f64::NAN);
                    t.push((
                        format!("a `{name}` scene at table ≤ 0.1 × full through Python (`PreslidingBatch.step`, {} joints)", x["n"]),
                        format!("{} — {:.3} × (fastest repeats: table {:.0} ns, full {:.0} ns a joint-step)", met(g("ratio") <= 0.1), g("ratio"), g("table_ns"), g("full_ns")),
                    ));
                }
            }
        }
        Err(why) => t.push(("`PreslidingBatch` against `Joint.evaluate` and a `Presliding` loop (Python)".into(), format!("not measured ({why})"))),
    }
    writeln!(body, "## Scenes at scale: `pinjoint::batch` and `PreslidingBatch`\n").unwrap();
    writeln!(
        body,
        "n presliding joints stepped together (`src/batch/`), each bit for bit the scalar law. The inputs: {} frames of \
         {} joints each swinging ±0.05–0.5 rad at 0.2–2 Hz under 5–50 kN ±20 % (one in ten held at rest), cycled, \
         a `step` (torque, then commit) a frame, default parameters, tolerance 1e-4, the table's envelope 4–60 kN × 1e-3–10 rad/s \
         (the scene's loads and speeds; a joint reversing passes below 1e-3 rad/s, where the table's low speeds answer, down to rest; \
         the table over 0.01–10 rad/s too, as measured before). \
         Time per joint-step = wall time / joints / steps on a pool of {} threads; memory = peak heap bytes from building \
         the batch to the end of its run, the caller's output array excluded.\n",
        FRAMES, b.joints, b.threads
    )
    .unwrap();
    writeln!(
        body,
        "The host-driven scenes: n joints of 5–50 kN, each under a drive torque r·T_s (T_s its sliding torque at rest), \
         J = {SCENE_INERTIA} kg·m² and a host damping T_s/{SCENE_SPEED} rad/s, integrated explicitly at 1 ms with `step_with` \
         (the batch knows the host's inertia and step); only the batch's calls are timed (100 steps), after 300 untimed steps (the held joints settle). \
         At table fidelity the table covers the speeds below its envelope down to rest (the rest state below a measured floor, \
         a second table above it), so a held or creeping joint needs no complete solve. The scenes:\n"
    )
    .unwrap();
    for (name, what) in SCENES {
        writeln!(body, "- `{name}`: {what}").unwrap();
    }
    writeln!(body).unwrap();
    writeln!(body, "| target | result |\n|---|---|").unwrap();
    for (a, r) in &t {
        writeln!(body, "| {a} | {r} |").unwrap();
    }
    if let Ok(v) = &b.python {
        writeln!(
            body,
            "\nPython: {} joints, {} steps a repeat, {} repeats interleaved, fastest repeat; NumPy {}, Python {}; the loop over \
             `Presliding` objects timed on {} joints. `evaluate_ns` is `Joint.evaluate(load, speed)` of n points (every output \
             column) per point.",
            v["n"], v["steps"], v["repeats"], v["numpy"].as_str().unwrap_or("?"), v["python"].as_str().unwrap_or("?"), v["loop_joints"]
        )
        .unwrap();
    }
    writeln!(body).unwrap();
    (t, body)
}

/// Markers of the section inside BENCHMARKS.md (so `--only-batch` can replace it in place).
pub const BEGIN: &str = "<!-- batch section: pinjoint-bench (--only-batch replaces it) -->";
/// See [`BEGIN`].
pub const END: &str = "<!-- end of batch section -->";
