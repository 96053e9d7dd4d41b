//! `--fidelity`, `--tolerance` and the envelope flags of `point` and `sweep`: the answers stay
//! within the bound the command reports, auto says what it picked, a point outside the envelope
//! is said once, and bad values are named with their unit.

use pinjoint::{Joint, Params};
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_pinjoint")).args(args).output().unwrap();
    (o.status.code().unwrap(), String::from_utf8(o.stdout).unwrap(), String::from_utf8(o.stderr).unwrap())
}

fn json(stdout: &str) -> serde_json::Value {
    serde_json::from_str(stdout.trim()).unwrap()
}

/// The measured bound printed on standard error.
fn bound(stderr: &str) -> f64 {
    let s = stderr.split("measured error bound ").nth(1).expect("bound reported");
    s.split([',', ' ']).next().unwrap().parse().unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn point_table_and_auto_stay_within_the_reported_bound() {
    let j = Joint::new(&Params::default()).unwrap();
    for (level, tol, load, speed) in [("table", "1e-3", 33000.0, 1.7), ("auto", "1e-4", 12345.0, -0.37), ("table", "1e-2", 8000.0, 6.5)] {
        let (l, w) = (format!("{load}"), format!("{speed}"));
        let (code, out, err) = run(&[
            "point", "--load", &l, "--speed", &w, "--json", "--fidelity", level, "--tolerance", tol,
            "--envelope-load", "5000:60000", "--envelope-speed", "0.01:10",
        ]);
        assert_eq!(code, 0, "{err}");
        let b = bound(&err);
        let t: f64 = tol.parse().unwrap();
        assert!(b <= t, "{err}");
        assert!(err.contains(&format!("fidelity: {level} -> ")), "{err}");
        let v = json(&out);
        let r = j.evaluate(load, speed).unwrap();
        let mu = v["friction_coefficient"].as_f64().unwrap();
        let torque = v["torque"].as_f64().unwrap();
        assert!(rel(mu, r.friction_coefficient) <= b && rel(torque, r.torque) <= b, "{level} {tol}: {mu} vs {}", r.friction_coefficient);
        if level == "table" {
            // A table is not the full solve: the value must differ (else the flag did nothing).
            assert_ne!(mu, r.friction_coefficient);
        }
    }
}

#[test]
fn auto_reports_its_choice_and_boundary_is_mu_c() {
    // Deep in boundary (low speed, high load): auto picks boundary at a loose tolerance.
    let (code, out, err) = run(&[
        "point", "--load", "50000", "--speed", "0.002", "--json", "--fidelity", "auto", "--tolerance", "0.05",
        "--envelope-load", "40000:60000", "--envelope-speed", "0.001:0.003",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("auto -> boundary"), "{err}");
    // The boundary level is the rest state: μ_c plus the grease's yield torque over R·P.
    let v = json(&out);
    assert_eq!(v["asperity_friction_coefficient"].as_f64().unwrap(), 0.12);
    let rest = Joint::new(&pinjoint::Params::default()).unwrap().boundary_torque(50e3) / (0.028 * 50e3);
    assert!((v["friction_coefficient"].as_f64().unwrap() - rest).abs() < 1e-15, "{out}");
    // Wide envelope, tight tolerance: boundary is rejected and the reason is printed.
    let (_, _, err) = run(&["point", "--load", "20000", "--speed", "2", "--fidelity", "auto", "--tolerance", "1e-4"]);
    assert!(err.contains("auto -> table") && err.contains("rejected: boundary"), "{err}");
}

#[test]
fn a_point_outside_the_envelope_falls_back_and_says_so_once() {
    let csv = "load,speed\n20000,50\n20000,60\n20000,0.2\n";
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("p.csv");
    std::fs::write(&input, csv).unwrap();
    let (code, out, err) = run(&[
        "sweep", "--input", input.to_str().unwrap(), "--fidelity", "table", "--envelope-load", "5000:60000", "--envelope-speed", "0.01:10",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(err.matches("outside the envelope").count(), 1, "{err}");
    assert!(err.contains("speed = 50 rad/s") || err.contains("speed = 60 rad/s"), "{err}");
    // The fallback rows are the full solve itself.
    let j = Joint::new(&Params::default()).unwrap();
    let row: Vec<&str> = out.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(row[2].parse::<f64>().unwrap(), j.evaluate(20000.0, 50.0).unwrap().friction_coefficient);
}

#[test]
fn sweep_envelope_comes_from_the_input_and_rows_meet_the_bound() {
    let j = Joint::new(&Params::default()).unwrap();
    let pts: Vec<(f64, f64)> = (0..40).map(|i| (5000.0 + 1375.0 * f64::from(i), 0.05 * 1.15f64.powi(i) * if i % 2 == 0 { 1.0 } else { -1.0 })).collect();
    let csv: String = std::iter::once("load,speed".to_string()).chain(pts.iter().map(|(p, w)| format!("{p},{w}"))).collect::<Vec<_>>().join("\n");
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("p.csv");
    std::fs::write(&input, csv).unwrap();
    let (code, out, err) = run(&["sweep", "--input", input.to_str().unwrap(), "--fidelity", "auto", "--tolerance", "1e-3"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("over load 5000..58625 N"), "{err}");
    assert!(!err.contains("outside the envelope"), "{err}");
    let b = bound(&err);
    assert!(b <= 1e-3);
    for (line, (p, w)) in out.lines().skip(1).zip(&pts) {
        let f: Vec<&str> = line.split(',').collect();
        let r = j.evaluate(*p, *w).unwrap();
        assert!(rel(f[2].parse().unwrap(), r.friction_coefficient) <= b, "{line}");
        assert!(rel(f[3].parse().unwrap(), r.torque) <= b, "{line}");
    }
}

#[test]
fn bad_fidelity_flags_name_quantity_value_and_unit() {
    let base = ["point", "--load", "20000", "--speed", "1"];
    let cases: [(&[&str], &[&str]); 6] = [
        (&["--fidelity", "tabel"], &["fidelity = \"tabel\"", "full, table, boundary, auto"]),
        (&["--tolerance", "-1"], &["tolerance = -1", "relative error"]),
        (&["--tolerance", "0", "--fidelity", "table"], &["tolerance = 0"]),
        (&["--fidelity", "table", "--envelope-load", "60000:5000"], &["--envelope-load", "60000 N", "below"]),
        (&["--fidelity", "auto", "--envelope-speed", "0:10"], &["--envelope-speed", "minimum = 0 rad/s"]),
        (&["--fidelity", "table", "--envelope-speed", "fast"], &["--envelope-speed", "MIN:MAX", "rad/s"]),
    ];
    for (extra, needles) in cases {
        let args: Vec<&str> = base.iter().chain(extra).copied().collect();
        let (code, _, err) = run(&args);
        assert_eq!(code, 1, "{args:?}: {err}");
        for n in needles {
            assert!(err.contains(n), "{args:?}: {err} lacks {n}");
        }
    }
}

/// The eq. 11 average printed by `cycle`.
fn average(stdout: &str) -> f64 {
    let line = stdout.lines().find(|l| l.starts_with("cycle-average friction coefficient")).expect("average printed");
    line.rsplit(' ').next().unwrap().parse().unwrap()
}

#[test]
fn cycle_with_the_table_level_agrees_with_full_and_reports_the_level() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("full"), dir.path().join("table"));
    let base = ["cycle", "--cycles", "2", "--samples-per-cycle", "200", "--output"];
    let (code, full_out, err) = run(&[&base[..], &[a.to_str().unwrap()]].concat());
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("fidelity:"), "{err}");
    let (code, table_out, err) = run(&[&base[..], &[b.to_str().unwrap(), "--fidelity", "table", "--tolerance", "1e-5"]].concat());
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("fidelity: table -> table") && err.contains("over load 18000..22000 N"), "{err}");
    let (f, t) = (average(&full_out), average(&table_out));
    assert!(f != t && rel(t, f) < 1e-4, "{f} vs {t}");
    let (code, _, err) = run(&[&base[..], &[b.to_str().unwrap(), "--fidelity", "table", "--envelope-load", "1:0.5"]].concat());
    assert_eq!(code, 1);
    assert!(err.contains("--envelope-load") && err.contains(" N"), "{err}");
}
