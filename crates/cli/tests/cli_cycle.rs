//! `pinjoint cycle` and `pinjoint figures` run as a user would: the CSV's columns and units,
//! quasi-static agreement with the friction core at 0.03 Hz, the printed eq. 11 average against
//! a recomputation from the CSV, parameter files and flags, error paths without partial output,
//! and every file of `figures`.

use pinjoint::{Joint, Params};
use std::collections::BTreeSet;
use std::f64::consts::TAU;
use std::path::Path;

mod cli_support;
use cli_support::{ok, run};

const COLUMNS: [&str; 10] = [
    "time",
    "command_angle",
    "angle",
    "angular_velocity",
    "torque",
    "friction_torque",
    "friction_coefficient",
    "film_thickness",
    "fluid_load_fraction",
    "stuck",
];

/// The rows of cycle.csv as numbers, after checking the header.
fn read_cycle(dir: &Path) -> Vec<[f64; 10]> {
    let mut rdr = csv::Reader::from_path(dir.join("cycle.csv")).unwrap();
    let header: Vec<String> = rdr.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header, COLUMNS);
    rdr.records()
        .map(|r| {
            let r = r.unwrap();
            let mut row = [0.0; 10];
            for (i, v) in r.iter().enumerate() {
                row[i] = v.parse().unwrap_or_else(|_| panic!("column {} = {v:?} is not a number", COLUMNS[i]));
            }
            row
        })
        .collect()
}

/// The number after the last ": " of the stdout line that starts with `prefix`.
fn printed(stdout: &str, prefix: &str) -> f64 {
    let line = stdout.lines().find(|l| l.starts_with(prefix)).unwrap_or_else(|| panic!("no {prefix:?} line in {stdout}"));
    line.rsplit(": ").next().unwrap().split_whitespace().next().unwrap().parse().unwrap()
}

fn joint() -> Joint {
    Joint::new(&Params::default()).unwrap()
}

const R: f64 = 0.028;

#[test]
fn cycle_csv_has_the_columns_in_si_units() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    let d = dir.to_str().unwrap();
    let o = ok(&["cycle", "--frequency", "1", "--amplitude", "40", "--load", "20000", "--cycles", "2", "--samples-per-cycle", "500", "--output", d]);
    for f in ["cycle.csv", "torque_time.svg", "torque_angle.svg"] {
        assert!(o.stdout.contains(&format!("wrote {}", dir.join(f).display())), "{}", o.stdout);
    }
    let rows = read_cycle(&dir);
    assert_eq!(rows.len(), 2 * 500 + 1);
    let amplitude = 40f64.to_radians();
    for (k, r) in rows.iter().enumerate() {
        // time [s] on the sample grid; the command A·sin(2πft) in rad.
        assert!((r[0] - k as f64 / 500.0).abs() < 1e-9, "{r:?}");
        assert!((r[1] - amplitude * (TAU * r[0]).sin()).abs() < 1e-9, "{r:?}");
        // the pin follows within a few degrees (rad, not degrees)
        assert!((r[2] - r[1]).abs() < 3f64.to_radians(), "{r:?}");
        // After the start-up stroke (from rest at the command's peak speed): speed in rad/s
        // within the command's peak 2πfA plus ringing, torque in N·m near μ_c R P = 67.2 N·m.
        if r[0] >= 1.0 {
            assert!(r[3].abs() < 1.2 * TAU * amplitude, "{r:?}");
            assert!(r[4].abs() < 100.0, "{r:?}");
        }
        // At most the rest value: μ_c plus the grease's yield torque over R·P (complete model).
        assert!(r[6] > 0.05 && r[6] <= joint().boundary_torque(20e3) / (0.028 * 20e3) + 1e-12, "{r:?}");
        // film thickness in m (µm scale), 1/γ1 a fraction, stuck 0 or 1
        assert!(r[7] > 1e-7 && r[7] < 1e-4, "{r:?}");
        assert!((0.0..=1.0).contains(&r[8]), "{r:?}");
        assert!(r[9] == 0.0 || r[9] == 1.0, "{r:?}");
        // friction opposes the motion outside stick
        if r[9] == 0.0 && r[3].abs() > 1e-6 {
            assert!(r[5] * r[3] < 0.0, "{r:?}");
        }
    }
    assert!(rows.iter().any(|r| r[9] == 1.0), "the joint sticks at the reversals");
    let svg = std::fs::read_to_string(dir.join("torque_time.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("torque [N·m]") && svg.contains("time t [s]"));
    let svg = std::fs::read_to_string(dir.join("torque_angle.svg")).unwrap();
    assert!(svg.contains("pin angle θ [deg]"));
}

#[test]
fn slow_stroke_is_quasi_static_against_the_core() {
    let j = joint();
    for load in ["5000", "20000", "60000"] {
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().to_str().unwrap();
        ok(&["cycle", "--frequency", "0.03", "--amplitude", "40", "--load", load, "--cycles", "2", "--samples-per-cycle", "400", "--output", d]);
        let rows = read_cycle(tmp.path());
        let p: f64 = load.parse().unwrap();
        // Mid-stroke (θ_cmd = 0) of both strokes of the second cycle, and a quarter way either side.
        for k in [400, 450, 550, 600, 650, 750] {
            let r = rows[k];
            assert_eq!(r[9], 0.0, "sliding at row {k}");
            let q = j.evaluate(p, r[3].abs()).unwrap().friction_coefficient * R * p;
            let err = (r[4].abs() - q).abs() / q;
            assert!(err < 0.01, "{load} N, t = {} s: |T| = {} N·m, core {q} N·m ({err:e})", r[0], r[4].abs());
            // and the friction_coefficient column is the core's at that speed
            assert!((r[6] - q / (R * p)).abs() < 1e-9, "{r:?}");
        }
    }
}

#[test]
fn printed_cycle_average_is_eq_11_of_the_csv() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path().to_str().unwrap();
    let o = ok(&["cycle", "--frequency", "1", "--load", "40000", "--cycles", "3", "--samples-per-cycle", "800", "--output", d]);
    let mu = printed(&o.stdout, "cycle-average friction coefficient");
    assert!(o.stdout.contains("over cycles 2-3"), "{}", o.stdout);
    let rows = read_cycle(tmp.path());
    // Trapezoidal mean of |torque| over t in [1 s, 3 s] (cycles 2 and 3), divided by R·P.
    let w: Vec<&[f64; 10]> = rows.iter().filter(|r| r[0] >= 1.0 - 1e-9).collect();
    let (mut sum, mut span) = (0.0, 0.0);
    for p in w.windows(2) {
        let dt = p[1][0] - p[0][0];
        sum += 0.5 * dt * (p[0][4].abs() + p[1][4].abs());
        span += dt;
    }
    assert!((span - 2.0).abs() < 1e-9);
    let again = sum / span / (R * 40000.0);
    assert!((mu - again).abs() < 1e-12 * mu, "printed {mu}, from the CSV {again}");
    // Between the core at the stroke's peak speed and μ_c (plus the dip the reversals make).
    let peak = printed(&o.stdout, "quasi-static core friction coefficient");
    let core_peak = joint().evaluate(40000.0, TAU * 40f64.to_radians()).unwrap().friction_coefficient;
    assert!((peak - core_peak).abs() < 1e-5, "{peak} vs {core_peak}");
    assert!(mu > peak && mu < 0.12, "{mu}");
}

#[test]
fn parameter_file_rig_section_and_flags_override_it() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("rig.toml");
    // The paper's model, so that μ_c bounds μ (the complete model adds the grease's yield).
    std::fs::write(&file, "[model]\npaper = true\n[friction]\nboundary_friction_coefficient = 0.1\n[rig]\nfrequency = 0.5\nload = 10000.0\n").unwrap();
    let f = file.to_str().unwrap();
    let a = tmp.path().join("a");
    let o = ok(&["cycle", "--params", f, "--cycles", "1", "--samples-per-cycle", "100", "--output", a.to_str().unwrap()]);
    let rows = read_cycle(&a);
    // 0.5 Hz from the file: one cycle is 2 s.
    assert!((rows.last().unwrap()[0] - 2.0).abs() < 1e-12);
    // μ_c = 0.1 from the file bounds the coefficient.
    assert!(rows.iter().all(|r| r[6] <= 0.1 + 1e-12));
    assert!(printed(&o.stdout, "cycle-average") < 0.1);
    // --frequency overrides the file.
    let b = tmp.path().join("b");
    ok(&["cycle", "--params", f, "--frequency", "2", "--cycles", "1", "--samples-per-cycle", "100", "--output", b.to_str().unwrap()]);
    assert!((read_cycle(&b).last().unwrap()[0] - 0.5).abs() < 1e-12);
}

#[test]
fn formulations_and_methods_agree_on_the_average() {
    let mut mus = Vec::new();
    for extra in [&[][..], &["--formulation", "regularised"], &["--method", "dop853"], &["--method", "rk4"], &["--method", "dopri5-dense"]] {
        let tmp = tempfile::tempdir().unwrap();
        let mut args = vec!["cycle", "--frequency", "1", "--load", "20000", "--cycles", "2", "--samples-per-cycle", "500", "--output"];
        args.push(tmp.path().to_str().unwrap());
        args.extend_from_slice(extra);
        mus.push(printed(&ok(&args).stdout, "cycle-average"));
    }
    for m in &mus {
        assert!((m - mus[0]).abs() < 0.005 * mus[0], "{mus:?}");
    }
}

/// Fails with exit code `code`, the message naming every `needles`, and nothing written.
fn fails(args: &[&str], code: i32, needles: &[&str]) {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    let mut all = args.to_vec();
    all.extend(["--output", dir.to_str().unwrap()]);
    let o = run(&all);
    assert_eq!(o.code, code, "{all:?}: {} {}", o.stdout, o.stderr);
    for n in needles {
        assert!(o.stderr.contains(n), "{all:?}: stderr lacks {n:?}: {}", o.stderr);
    }
    assert!(!o.stderr.contains("panicked"), "{}", o.stderr);
    let left: BTreeSet<String> = std::fs::read_dir(&dir).map_or(BTreeSet::new(), |d| d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect());
    assert!(left.is_empty(), "{all:?} left {left:?}");
}

#[test]
fn cycle_errors_name_quantity_value_unit_and_write_nothing() {
    fn with<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let base = ["cycle", "--cycles", "1", "--samples-per-cycle", "50"];
        [&base[..], extra].concat()
    }
    fails(&with(&["--frequency", "0"]), 1, &["frequency = 0 Hz"]);
    fails(&with(&["--frequency", "-1"]), 1, &["frequency = -1 Hz"]);
    fails(&with(&["--frequency", "nan"]), 1, &["frequency = NaN Hz"]);
    fails(&with(&["--amplitude", "-5"]), 1, &["amplitude = -5 deg"]);
    fails(&with(&["--amplitude", "inf"]), 1, &["amplitude = inf deg"]);
    fails(&with(&["--load", "0"]), 1, &["load magnitude = 0 N"]);
    fails(&["cycle", "--cycles", "0"], 1, &["cycles = 0"]);
    fails(&["cycle", "--cycles", "2", "--skip-cycles", "2"], 1, &["skip-cycles = 2", "cycles = 2"]);
    fails(&["cycle", "--cycles", "1", "--samples-per-cycle", "3"], 1, &["samples-per-cycle = 3"]);
    fails(&["cycle", "--cycles", "two"], 2, &["--cycles"]);
    fails(&with(&["--method", "euler"]), 2, &["euler"]);

    let tmp = tempfile::tempdir().unwrap();
    let bad_key = tmp.path().join("bad_key.toml");
    std::fs::write(&bad_key, "[rig]\nintertia = 0.1\n").unwrap();
    fails(&with(&["--params", bad_key.to_str().unwrap()]), 1, &["bad_key.toml", "intertia"]);
    let bad_value = tmp.path().join("bad_value.toml");
    std::fs::write(&bad_value, "[rig]\ninertia = -1.0\n").unwrap();
    fails(&with(&["--params", bad_value.to_str().unwrap()]), 1, &["rig.inertia", "-1", "kg.m2"]);
    let zero_load = tmp.path().join("zero_load.toml");
    std::fs::write(&zero_load, "[rig]\nload = 0.0\n").unwrap();
    fails(&with(&["--params", zero_load.to_str().unwrap()]), 1, &["load = 0 N"]);
    let missing = tmp.path().join("missing.toml");
    fails(&with(&["--params", missing.to_str().unwrap()]), 1, &["missing.toml"]);
}

#[test]
fn figures_quick_writes_every_file_and_the_index_shows_them() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("figs");
    let o = ok(&["figures", "--quick", "--output", dir.to_str().unwrap()]);
    let svgs = [
        "stribeck.svg",
        "map_lambda.svg",
        "map_friction.svg",
        "map_curves.svg",
        "fig07_cycle_1Hz_20kN.svg",
        "fig08_mu_sommerfeld.svg",
        "fig09_mu_sliding_speed.svg",
        "fig10_mu_load.svg",
        "fig11_torque_0.03Hz.svg",
        "fig12_torque_0.3Hz.svg",
        "fig13_torque_1Hz.svg",
        "starvation_stribeck.svg",
        "starvation_cycle_1Hz.svg",
        "at_rest_hold.svg",
        "at_rest_loop.svg",
        "cold_day.svg",
    ];
    let csvs = [
        "stribeck.csv",
        "map.csv",
        "fig07_cycle_1Hz_20kN.csv",
        "rig_averages.csv",
        "core_curves.csv",
        "fig11_torque_0.03Hz.csv",
        "fig12_torque_0.3Hz.csv",
        "fig13_torque_1Hz.csv",
        "starvation_stribeck.csv",
        "starvation_cycle_1Hz.csv",
        "starvation_summary.csv",
        "at_rest_hold.csv",
        "at_rest_loop.csv",
        "cold_day.csv",
        "cold_day_series.csv",
    ];
    let names: BTreeSet<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    let expected: BTreeSet<String> = svgs.iter().chain(&csvs).chain(&["index.html", "README.md"]).map(std::string::ToString::to_string).collect();
    assert_eq!(names, expected);
    for f in &expected {
        assert!(o.stdout.contains(&format!("wrote {}", dir.join(f).display())), "{f}: {}", o.stdout);
    }
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    for s in svgs {
        let svg = std::fs::read_to_string(dir.join(s)).unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"), "{s}");
        assert!(html.contains(&format!("<img src=\"{s}\"")), "index.html lacks {s}");
        assert!(readme.contains(&format!("]({s})")), "README.md lacks {s}");
    }
    for c in csvs {
        assert!(html.contains(&format!("href=\"{c}\"")), "index.html lacks {c}");
    }
    for fig in [3, 4, 7, 8, 9, 10, 11, 12, 13] {
        assert!(html.contains(&format!("<h2>Figure {fig} ")), "index.html lacks Figure {fig}");
    }
    assert!(!html.contains("NaN") && !readme.contains("NaN"), "a caption quotes NaN");

    // 15 runs: every paper load at every paper frequency, averages between the core and μ_c.
    let mut rdr = csv::Reader::from_path(dir.join("rig_averages.csv")).unwrap();
    let h: Vec<String> = rdr.headers().unwrap().iter().map(String::from).collect();
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    let rows: Vec<Vec<f64>> = rdr.records().map(|r| r.unwrap().iter().map(|v| v.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 15);
    let mut seen = BTreeSet::new();
    for r in &rows {
        let (f, p, mu) = (r[col("frequency")], r[col("load")], r[col("cycle_average_friction_coefficient")]);
        seen.insert(((f * 100.0) as i64, p as i64));
        assert!(mu > 0.07 && mu < 0.12, "{f} Hz, {p} N: {mu}");
        // The characteristic speed is the mean |ω|: 4·A·f for a rig that tracks its command
        // and never sticks, a little less with the stick at the reversals.
        let (mean, ideal) = (r[col("mean_speed")], 4.0 * 40f64.to_radians() * f);
        let stuck = r[col("stuck_fraction")];
        assert!(mean < ideal && mean > (1.0 - stuck - 0.02) * ideal, "{f} Hz, {p} N: {mean} vs {ideal}, stuck {stuck}");
    }
    assert_eq!(seen.len(), 15);

    // The 1 Hz, 20 kN run agrees with `pinjoint cycle` on the same condition (the figures
    // run the paper's model).
    let r = rows.iter().find(|r| r[col("frequency")] == 1.0 && r[col("load")] == 20000.0).unwrap();
    let c = tmp.path().join("c");
    let paper = tmp.path().join("paper.toml");
    std::fs::write(&paper, "[model]\npaper = true\n").unwrap();
    let o = ok(&["cycle", "--frequency", "1", "--load", "20000", "--cycles", "2", "--samples-per-cycle", "400", "--output", c.to_str().unwrap(), "--params", paper.to_str().unwrap()]);
    let mu = printed(&o.stdout, "cycle-average");
    assert!((mu - r[col("cycle_average_friction_coefficient")]).abs() < 1e-3 * mu, "{mu} vs {r:?}");
}

#[test]
fn params_rig_prints_a_file_that_cycle_reads_back() {
    let text = ok(&["params", "--rig"]).stdout;
    assert!(text.contains("[rig]") && text.contains("position_gain") && text.contains("[friction]"), "{text}");
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("rig.toml");
    std::fs::write(&file, text.replace("frequency = 1.0", "frequency = 4.0")).unwrap();
    let out = tmp.path().join("o");
    ok(&["cycle", "--params", file.to_str().unwrap(), "--cycles", "1", "--samples-per-cycle", "40", "--output", out.to_str().unwrap()]);
    assert!((read_cycle(&out).last().unwrap()[0] - 0.25).abs() < 1e-12, "the file's frequency (4 Hz) was not used");
}

/// The cold-day scene in `figures`: the figure is written and linked, its CSV has one row for
/// each of +20, −20, −40 and −54 °C, each either run (locked with a finite time, speed and margin,
/// or not locked with `inf`) or marked not run with the model's reason, which the caption and the
/// figure's legend repeat; the series CSV has the runs that ran.
#[test]
fn figures_cold_day_scene_has_every_temperature() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("figs");
    ok(&["figures", "--quick", "--output", dir.to_str().unwrap()]);
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    let svg = std::fs::read_to_string(dir.join("cold_day.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(html.contains("<img src=\"cold_day.svg\"") && readme.contains("](cold_day.svg)"));
    assert!(html.contains("href=\"cold_day.csv\"") && html.contains("href=\"cold_day_series.csv\""));

    let mut rdr = csv::Reader::from_path(dir.join("cold_day.csv")).unwrap();
    let h: Vec<String> = rdr.headers().unwrap().iter().map(String::from).collect();
    let col = |name: &str| h.iter().position(|c| c == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows: Vec<csv::StringRecord> = rdr.records().map(Result::unwrap).collect();
    let temperatures: Vec<f64> = rows.iter().map(|r| r[col("temperature_C")].parse().unwrap()).collect();
    assert_eq!(temperatures, [20.0, -20.0, -40.0, -54.0]);
    let mut ran = BTreeSet::new();
    for r in &rows {
        let c: f64 = r[col("temperature_C")].parse().unwrap();
        let k: f64 = r[col("temperature_K")].parse().unwrap();
        assert!((k - c - 273.15).abs() < 1e-9);
        assert!(!r.iter().any(|v| v.contains("NaN")), "{r:?}");
        let label = format!("{c:+} °C");
        assert!(html.contains(&label), "the caption lacks {label}");
        match &r[col("status")] {
            "not run" => {
                let reason = &r[col("reason")];
                assert!(reason.contains("K") && !reason.is_empty(), "{r:?}");
                assert!(r[col("time_to_lock")].is_empty() && r[col("lock_margin")].is_empty());
                assert!(html.contains(&format!("{label}: not run")), "the caption does not say {label} was not run");
                assert!(svg.contains(&label), "the figure does not show {label}");
            }
            status @ ("locked" | "not locked") => {
                let t: f64 = r[col("time_to_lock")].parse().unwrap();
                let margin: f64 = r[col("lock_margin")].parse().unwrap();
                let energy: f64 = r[col("friction_energy")].parse().unwrap();
                assert!(margin.is_finite() && energy >= 0.0, "{r:?}");
                if status == "locked" {
                    let w: f64 = r[col("speed_at_lock")].parse().unwrap();
                    assert!(t.is_finite() && t > 0.0 && w > 0.0, "{r:?}");
                } else {
                    assert!(t == f64::INFINITY && r[col("speed_at_lock")].is_empty(), "{r:?}");
                }
                ran.insert(label);
            }
            other => panic!("status {other:?}"),
        }
    }
    let mut rdr = csv::Reader::from_path(dir.join("cold_day_series.csv")).unwrap();
    let series: BTreeSet<String> = rdr.records().map(|r| format!("{:+} °C", r.unwrap()[0].parse::<f64>().unwrap())).collect();
    assert_eq!(series, ran);
}

/// The cold day (issue 37, item 6): the points where `pinjoint cycle` refused with "stick/slip
/// chattering" (−55 °C at 5 kN, 0.3 Hz and at 60 kN, 0.03 Hz; −40 °C with a grease 1.5×
/// stiffer) run: the joint sticks at the reversals, stuck rows hold ω = 0 and a torque within
/// the breakaway torque, slipping rows oppose the motion, and the printed average is eq. 11 of
/// the CSV's second stroke.
#[test]
fn the_cold_day_runs_where_the_events_chattered() {
    let tmp = tempfile::tempdir().unwrap();
    let g = Params::default().grease;
    let stiff = tmp.path().join("stiff.toml");
    std::fs::write(&stiff, format!("[grease]\nyield_stress = {:?}\nconsistency = {:?}\n", 1.5 * g.yield_stress, 1.5 * g.consistency)).unwrap();
    for (t, load, f, params) in [("218.15", 5e3, "0.3", None), ("218.15", 60e3, "0.03", None), ("233.15", 20e3, "1", Some(&stiff))] {
        let dir = tmp.path().join(format!("c{t}-{load}-{f}"));
        let d = dir.to_str().unwrap();
        let l = load.to_string();
        let mut args = vec!["cycle", "--temperature", t, "--load", &l, "--frequency", f, "--cycles", "2", "--samples-per-cycle", "400", "--output", d];
        if let Some(p) = params {
            args.extend(["--params", p.to_str().unwrap()]);
        }
        let o = ok(&args);
        let mut p = Params::default();
        p.lubricant.temperature = t.parse().unwrap();
        if params.is_some() {
            (p.grease.yield_stress, p.grease.consistency) = (1.5 * g.yield_stress, 1.5 * g.consistency);
        }
        let breakaway = Joint::new(&p).unwrap().boundary_torque(load);
        let rows = read_cycle(&dir);
        assert!(rows.iter().any(|r| r[9] == 1.0), "{t} K: the joint sticks at the reversals");
        for r in &rows {
            if r[9] == 1.0 {
                assert!(r[3] == 0.0 && r[5].abs() <= breakaway * (1.0 + 1e-9), "{t} K: {r:?}");
            } else if r[3].abs() > 1e-6 {
                assert!(r[5] * r[3] < 0.0, "{t} K: {r:?}");
            }
        }
        let second = &rows[400..=800];
        let mean = second[..400].iter().map(|r| r[4].abs()).sum::<f64>() / 400.0;
        let mu = printed(&o.stdout, "cycle-average friction coefficient");
        assert!((mu - mean / (R * load)).abs() <= 1e-9 * mu, "{t} K: printed {mu}, CSV {}", mean / (R * load));
    }
}
