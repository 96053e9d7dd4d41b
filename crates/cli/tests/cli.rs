//! The `pinjoint` binary, run as a user would: every command, its outputs against the
//! library, and every error path (message, exit code, no partial files).

use pinjoint::{Joint, OperatingPoint, Params};
use std::collections::BTreeSet;
use std::f64::consts::PI;
use std::path::Path;
use std::process::{Command, Stdio};

mod cli_support;
use cli_support::{fails, ok, parse_csv, run, run_with, temp_file};

fn joint() -> Joint {
    Joint::new(&Params::default()).unwrap()
}

fn dir_names(d: &Path) -> BTreeSet<String> {
    std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect()
}

const RESULT_COLUMNS: [&str; 17] = [
    "friction_coefficient",
    "torque",
    "film_thickness",
    "lambda_ratio",
    "fluid_load_fraction",
    "asperity_load_fraction",
    "mean_pressure",
    "contact_half_width",
    "sommerfeld_number",
    "regime",
    "min_film_thickness",
    "min_lambda_ratio",
    "clearance_torque",
    "journal_weight",
    "eccentricity_ratio",
    "grease_yield_torque",
    "validity",
];

/// The numeric result columns of a point with the library's values: (position among the
/// result columns, name, value), read through the library's record table
/// (`pinjoint::record::COLUMNS`, whose own test checks that each column reads its own field).
fn lib_values(op: &OperatingPoint) -> Vec<(usize, &'static str, f64)> {
    pinjoint::record::COLUMNS
        .iter()
        .enumerate()
        .filter_map(|(i, c)| match c.value {
            pinjoint::record::Value::Number(f) => Some((i, c.name, f(op))),
            pinjoint::record::Value::Regime | pinjoint::record::Value::Validity => None,
        })
        .collect()
}

// ---------------------------------------------------------------- help and usage

#[test]
fn help_explains_units_and_shows_examples() {
    let o = run(&["--help"]);
    assert_eq!(o.code, 0);
    for s in ["Examples:", "pinjoint point", "pinjoint sweep", "pinjoint stribeck", "pinjoint map", "pinjoint params", "SI"] {
        assert!(o.stdout.contains(s), "top help lacks {s}");
    }
    let o = run(&["point", "--help"]);
    for s in ["--load <N>", "in N", "--speed <RAD/S>", "rad/s", "--rpm <RPM>", "--json", "--params <FILE>", "Examples:"] {
        assert!(o.stdout.contains(s), "point help lacks {s}:\n{}", o.stdout);
    }
    let o = run(&["sweep", "--help"]);
    for s in ["`load` (N", "`speed`", "rad/s", "friction_coefficient", "regime", "line", "Examples:"] {
        assert!(o.stdout.contains(s), "sweep help lacks {s}");
    }
    let o = run(&["stribeck", "--help"]);
    for s in ["--load <N>", "--min-speed <RAD/S>", "--max-rpm <RPM>", "--points", "--output <DIR>", "Sommerfeld"] {
        assert!(o.stdout.contains(s), "stribeck help lacks {s}");
    }
    let o = run(&["map", "--help"]);
    for s in ["--min-load <N>", "--max-rpm <RPM>", "41.9 rpm", "map_lambda.svg", "--output <DIR>"] {
        assert!(o.stdout.contains(s), "map help lacks {s}");
    }
}

#[test]
fn usage_errors_exit_2() {
    fails(&["frobnicate"], None, 2, &["frobnicate"]);
    fails(&[], None, 2, &["Usage"]);
    fails(&["point", "--load", "20000"], None, 2, &["--speed", "--rpm"]);
    fails(&["point", "--load", "20000", "--speed", "1", "--rpm", "10"], None, 2, &["cannot be used with"]);
    fails(&["point", "--load", "abc", "--speed", "1"], None, 2, &["abc", "--load <N>"]);
    fails(&["point", "--load", "1", "--speed", "fast"], None, 2, &["fast", "--speed <RAD/S>"]);
    fails(&["sweep"], None, 2, &["--input"]);
    fails(&["map"], None, 2, &["--output"]);
}

// ---------------------------------------------------------------- params

#[test]
fn params_prints_the_full_default_file_and_it_loads_back() {
    let o = run(&["params"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(Params::from_toml_str(&o.stdout).unwrap(), Params::default());
    assert_eq!(o.stdout, Params::default().to_toml_string());
    for s in ["[geometry]", "[materials]", "[surface]", "[lubricant]", "[friction]", "boundary_friction_coefficient"] {
        assert!(o.stdout.contains(s), "{s}");
    }
}

#[test]
fn params_fills_a_partial_file_and_rejects_a_bad_one() {
    let (_d, f) = temp_file("p.toml", "[friction]\nboundary_friction_coefficient = 0.1\n");
    let o = ok(&["params", "--params", f.to_str().unwrap()]);
    let p = Params::from_toml_str(&o.stdout).unwrap();
    assert_eq!(p.friction.boundary_friction_coefficient, 0.1);
    assert_eq!(p.geometry, Params::default().geometry);

    std::fs::write(&f, "[materials]\npin_elastic_modulus = -5.0\n").unwrap();
    fails(&["params", "--params", f.to_str().unwrap()], None, 1, &["p.toml", "materials.pin_elastic_modulus", "-5", "Pa"]);
    std::fs::write(&f, "[geometry]\npin_radiuss = 0.02\n").unwrap();
    fails(&["point", "--load", "1", "--speed", "1", "--params", f.to_str().unwrap()], None, 1, &["pin_radiuss"]);
    fails(&["params", "--params", "/no/such/file.toml"], None, 1, &["cannot read /no/such/file.toml"]);
}

// ---------------------------------------------------------------- point

fn point_json(args: &[&str]) -> serde_json::Map<String, serde_json::Value> {
    let o = run(args);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(o.stdout.trim().lines().count(), 1, "one JSON object on one line");
    match serde_json::from_str(&o.stdout).unwrap() {
        serde_json::Value::Object(m) => m,
        v => panic!("not an object: {v}"),
    }
}

fn num(m: &serde_json::Map<String, serde_json::Value>, k: &str) -> f64 {
    m[k].as_f64().unwrap_or_else(|| panic!("{k} is not a number"))
}

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs())
}

#[test]
fn point_json_has_exactly_the_documented_keys_and_the_library_values() {
    let m = point_json(&["point", "--load", "20000", "--speed", "0.2", "--json"]);
    // load, speed, then the result columns up to and with regime.
    let required: Vec<&str> = ["load", "speed"].iter().chain(&RESULT_COLUMNS[..10]).copied().collect();
    let extras = [
        "sliding_speed",
        "peak_pressure",
        "contact_viscosity",
        "fluid_friction_coefficient",
        "asperity_friction_coefficient",
        "min_film_thickness",
        "min_lambda_ratio",
        "clearance_torque",
        "journal_weight",
        "eccentricity_ratio",
        "grease_yield_torque",
        "validity",
        "temperature",
        "inlet_viscosity",
        "pressure_viscosity_coefficient",
    ];
    let keys: BTreeSet<&str> = m.keys().map(String::as_str).collect();
    let expected: BTreeSet<&str> = required.iter().chain(&extras).copied().collect();
    assert_eq!(keys, expected);

    let op = joint().evaluate(20000.0, 0.2).unwrap();
    assert_eq!(num(&m, "load"), 20000.0);
    assert_eq!(num(&m, "speed"), 0.2);
    assert_eq!(m["regime"], op.regime.as_str());
    assert_eq!(m["validity"], "checked");
    for (_, k, v) in lib_values(&op) {
        assert!(close(num(&m, k), v), "{k}: {} vs {v}", num(&m, k));
    }
    assert!(close(num(&m, "peak_pressure"), op.peak_pressure));
    assert!(close(num(&m, "min_film_thickness"), op.min_film_thickness));
    assert!(close(num(&m, "min_lambda_ratio"), op.min_lambda_ratio));
    assert_eq!(num(&m, "temperature"), 293.15);
    assert_eq!(num(&m, "inlet_viscosity"), 12.45e-3);
}

#[test]
fn point_rpm_is_converted_to_rad_per_s_and_sign_kept() {
    let a = point_json(&["point", "--load", "60000", "--rpm", "42", "--json"]);
    let w = 42.0 * 2.0 * PI / 60.0;
    assert!(close(num(&a, "speed"), w));
    let op = joint().evaluate(60000.0, w).unwrap();
    assert!(close(num(&a, "friction_coefficient"), op.friction_coefficient));
    let b = point_json(&["point", "--load", "60000", "--rpm", "-42", "--json"]);
    assert!(close(num(&b, "speed"), -w));
    assert_eq!(num(&a, "torque"), num(&b, "torque"), "the model uses |speed|");
}

#[test]
fn point_table_lists_quantities_values_and_units() {
    let o = run(&["point", "--load", "20000", "--rpm", "10"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let lines: Vec<&str> = o.stdout.lines().collect();
    assert!(lines[0].starts_with("quantity") && lines[0].ends_with("unit"));
    for (name, unit) in [
        ("load P_T", "N"),
        ("friction coefficient μ", "-"),
        ("torque T", "N·m"),
        ("central film thickness", "m"),
        ("Hertz mean pressure", "Pa"),
        ("Sommerfeld number", "-"),
        ("(in rpm)", "rpm"),
    ] {
        let l = lines.iter().find(|l| l.trim_start().starts_with(name)).unwrap_or_else(|| panic!("no row {name}"));
        assert!(l.trim_end().ends_with(unit), "{l}");
    }
    let op = joint().evaluate(20000.0, 10.0 * 2.0 * PI / 60.0).unwrap();
    let torque_row = lines.iter().find(|l| l.starts_with("torque")).unwrap();
    let shown: f64 = torque_row.split_whitespace().rev().nth(1).unwrap().parse().unwrap();
    assert!((shown - op.torque).abs() < 1e-5 * op.torque, "{torque_row} vs {}", op.torque);
    assert!(lines.iter().any(|l| l.starts_with("regime") && l.contains(op.regime.as_str())));
}

#[test]
fn point_errors_name_quantity_value_and_unit() {
    fails(&["point", "--load", "0", "--speed", "1"], None, 1, &["load = 0 N"]);
    fails(&["point", "--load", "nan", "--speed", "1"], None, 1, &["load = NaN N"]);
    fails(&["point", "--load", "1", "--speed", "inf"], None, 1, &["speed = inf rad/s"]);
    fails(&["point", "--load", "1", "--rpm=-inf"], None, 1, &["speed = -inf rpm"]);
}

// ---------------------------------------------------------------- sweep

/// Points over every regime: rest, creeping, boundary, mixed, full film; 1 N to 1 MN.
fn regime_points() -> Vec<(f64, f64)> {
    let mut v = Vec::new();
    // Every point inside the film bound (the fluid's film within the diametral clearance,
    // ModelError::FilmBeyondClearance): light loads at slow speeds, 1 MN up to 1e4 rad/s.
    let joint = Joint::new(&Params::default()).unwrap();
    for &p in &[1.0, 500.0, 5e3, 20e3, 60e3, 1e6] {
        for &w in &[0.0, 1e-12, -0.01, 0.2, 1.0, -4.39, 6.3, 20.0, 83.8, 1000.0, 1e4] {
            if joint.evaluate(p, w).is_ok() {
                v.push((p, w));
            }
        }
    }
    assert!(v.len() >= 40, "{} points inside the bound", v.len());
    // Many more rows so that the parallel chunks are exercised and order must be kept.
    for i in 0..3000 {
        let t = f64::from(i) / 2999.0;
        v.push((5e3 + 55e3 * f64::from((i * 7919) % 3000) / 3000.0, -100.0 + 200.0 * t));
    }
    v
}

fn points_csv(points: &[(f64, f64)]) -> String {
    let mut s = String::from("case,load,speed\n");
    for (i, (p, w)) in points.iter().enumerate() {
        s.push_str(&format!("c{i},{p:?},{w:?}\n"));
    }
    s
}

fn check_sweep_output(text: &str, points: &[(f64, f64)], joint: &Joint) {
    let (h, rows) = parse_csv(text);
    let mut expected = vec!["case".to_string(), "load".into(), "speed".into()];
    expected.extend(RESULT_COLUMNS.iter().map(std::string::ToString::to_string));
    assert_eq!(h, expected);
    assert_eq!(rows.len(), points.len());
    let mut regimes = BTreeSet::new();
    for (i, (row, &(p, w))) in rows.iter().zip(points).enumerate() {
        assert_eq!(row[0], format!("c{i}"), "row order");
        assert_eq!(row[1].parse::<f64>().unwrap().to_bits(), p.to_bits());
        assert_eq!(row[2].parse::<f64>().unwrap().to_bits(), w.to_bits());
        let op = joint.evaluate(p, w).unwrap();
        for (k, name, v) in lib_values(&op) {
            assert_eq!(h[3 + k], name);
            let got: f64 = row[3 + k].parse().unwrap();
            assert_eq!(got.to_bits(), v.to_bits(), "row {i} column {name}: {got} vs {v}");
        }
        assert_eq!(row[12], op.regime.as_str());
        regimes.insert(row[12].clone());
        // The h_min columns, appended after regime.
        assert_eq!(row[13].parse::<f64>().unwrap().to_bits(), op.min_film_thickness.to_bits());
        assert_eq!(row[14].parse::<f64>().unwrap().to_bits(), op.min_lambda_ratio.to_bits());
        assert_eq!(row[row.len() - 1], op.validity.as_str());
    }
    assert_eq!(regimes.len(), 3, "the points span every regime: {regimes:?}");
}

#[test]
fn sweep_temperature_column_and_flag_match_the_library() {
    let (_d, input) = temp_file("t.csv", "load,speed,temperature\n20000,0.5,253.15\n20000,0.5,293.15\n20000,0.5,333.15\n");
    let o = ok(&["sweep", "--input", input.to_str().unwrap()]);
    let (h, rows) = parse_csv(&o.stdout);
    let mu_col = h.iter().position(|c| c == "friction_coefficient").unwrap();
    for (row, t) in rows.iter().zip([253.15, 293.15, 333.15]) {
        let mut p = Params::default();
        p.lubricant.temperature = t;
        let op = Joint::new(&p).unwrap().evaluate(20000.0, 0.5).unwrap();
        assert_eq!(row[mu_col].parse::<f64>().unwrap().to_bits(), op.friction_coefficient.to_bits(), "T = {t}");
    }
    // At the reference temperature the row equals the default model bit for bit.
    let op = joint().evaluate(20000.0, 0.5).unwrap();
    assert_eq!(rows[1][mu_col].parse::<f64>().unwrap().to_bits(), op.friction_coefficient.to_bits());
    // --temperature on point: same as the library at that temperature.
    let m = point_json(&["point", "--load", "20000", "--speed", "0.5", "--temperature", "253.15", "--json"]);
    let mut p = Params::default();
    p.lubricant.temperature = 253.15;
    let op = Joint::new(&p).unwrap().evaluate(20000.0, 0.5).unwrap();
    assert_eq!(num(&m, "friction_coefficient"), op.friction_coefficient);
    assert_eq!(num(&m, "temperature"), 253.15);
    // A bad temperature is a typed error naming the quantity, value and unit.
    let o = run(&["point", "--load", "20000", "--speed", "0.5", "--temperature", "-5"]);
    assert_ne!(o.code, 0);
    assert!(o.stderr.contains("lubricant.temperature = -5 K"), "{}", o.stderr);
}

#[test]
fn sweep_output_equals_the_library_bit_for_bit_in_input_order() {
    let d = tempfile::tempdir().unwrap();
    let pts = regime_points();
    let input = d.path().join("pts.csv");
    std::fs::write(&input, points_csv(&pts)).unwrap();
    let output = d.path().join("out.csv");
    let o = run(&["sweep", "--input", input.to_str().unwrap(), "--output", output.to_str().unwrap()]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(o.stdout, "");
    let text = std::fs::read_to_string(&output).unwrap();
    check_sweep_output(&text, &pts, &joint());
    assert_eq!(dir_names(d.path()), ["out.csv", "pts.csv"].iter().map(std::string::ToString::to_string).collect());

    // Without --output, the same bytes on standard output.
    let o = run(&["sweep", "--input", input.to_str().unwrap()]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(o.stdout, text);
}

#[test]
fn sweep_reads_standard_input_skips_blank_and_comment_lines_and_trims() {
    let o = run_with(&["sweep", "--input", "-"], Some("# my points\nspeed , load\n\n 0.2 , 20000 \n# another\n-3,5e3\n"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let (h, rows) = parse_csv(&o.stdout);
    assert_eq!(&h[..2], &["speed", "load"]);
    assert_eq!(rows.len(), 2);
    assert_eq!(&rows[1][..2], &["-3", "5e3"], "input fields are copied as given (trimmed)");
    let op = joint().evaluate(5e3, -3.0).unwrap();
    assert_eq!(rows[1][2].parse::<f64>().unwrap(), op.friction_coefficient);
}

#[test]
fn sweep_uses_the_parameter_file() {
    // The paper's model: at rest μ = μ_c exactly (the complete model adds the grease's yield).
    let (d, pf) = temp_file("p.toml", "[model]\npaper = true\n[friction]\nboundary_friction_coefficient = 0.08\n[lubricant]\nviscosity = 0.05\n");
    let pts = vec![(20e3, 0.0), (20e3, 5.0), (5e3, 10.0)];
    let input = d.path().join("pts.csv");
    std::fs::write(&input, points_csv(&pts)).unwrap();
    let o = run(&["sweep", "--input", input.to_str().unwrap(), "--params", pf.to_str().unwrap()]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let (_, rows) = parse_csv(&o.stdout);
    let mut p = Params::paper();
    p.friction.boundary_friction_coefficient = 0.08;
    p.lubricant.viscosity = 0.05;
    let j = Joint::new(&p).unwrap();
    for (row, &(l, w)) in rows.iter().zip(&pts) {
        assert_eq!(row[3].parse::<f64>().unwrap(), j.evaluate(l, w).unwrap().friction_coefficient);
    }
    assert_eq!(rows[0][3].parse::<f64>().unwrap(), 0.08);
}

#[test]
fn sweep_malformed_rows_name_line_column_value_and_unit_and_leave_no_file() {
    let cases: &[(&str, &[&str])] = &[
        ("load,speed\n20000,0.2\n\n# c\n60000,abc\n", &["line 5", "speed", "`abc`", "rad/s"]),
        ("load,speed\n20000,0.2\n5\n", &["line 3", "missing column(s) speed"]),
        ("load,speed\n20000,0.2,7\n", &["line 2", "more field"]),
        ("load,speed\n1000,2\n0,2\n", &["line 3", "load = 0 N", "> 0 N"]),
        // A negative load is its magnitude (issue 9); -0 is still no load.
        ("load,speed\n-0,2\n", &["line 2", "load = -0 N"]),
        ("load,speed\r\n1000,2\r\n\r\n1,inf\r\n", &["line 4", "speed = inf rad/s", "not a finite number"]),
        ("load,speed\nNaN,2\n", &["line 2", "load = NaN N"]),
        ("load,speed\n1,\n", &["line 2", "speed (rad/s) is empty"]),
        ("load,speeed\n1,2\n", &["line 1", "no `speed` column"]),
        ("speed\n1\n", &["line 1", "no `load` column"]),
        ("load,speed,load\n1,2,3\n", &["line 1", "`load` more than once"]),
        ("load,speed,torque\n1,2,3\n", &["line 1", "`torque`", "output column"]),
        ("", &["line 1", "no header"]),
        ("load,speed\n1000,1\n\u{0}\u{ff}x,2\n", &["line 3"]),
    ];
    for (input, needles) in cases {
        let d = tempfile::tempdir().unwrap();
        let inp = d.path().join("in.csv");
        std::fs::write(&inp, input.as_bytes()).unwrap();
        let out = d.path().join("out.csv");
        let o = fails(&["sweep", "--input", inp.to_str().unwrap(), "--output", out.to_str().unwrap()], None, 1, needles);
        assert!(o.stderr.contains("in.csv"), "{}", o.stderr);
        assert_eq!(dir_names(d.path()), BTreeSet::from(["in.csv".to_string()]), "no partial or temporary file for {input:?}");
        assert_eq!(o.stdout, "");
    }
    // With the paper's model a row whose film would pass the clearance (1 N at 1 rad/s:
    // 1.9 mm) is named; the complete model answers it (the journal bearing).
    let d = tempfile::tempdir().unwrap();
    let (inp, out, paper) = (d.path().join("in.csv"), d.path().join("out.csv"), d.path().join("paper.toml"));
    std::fs::write(&inp, "load,speed\n1,1\n").unwrap();
    std::fs::write(&paper, "[model]\npaper = true\n").unwrap();
    let o = fails(&["sweep", "--input", inp.to_str().unwrap(), "--output", out.to_str().unwrap(), "--params", paper.to_str().unwrap()], None, 1, &["line 2", "film_thickness = 0.00194983", "diametral clearance"]);
    assert_eq!(o.stdout, "");
    ok(&["sweep", "--input", inp.to_str().unwrap(), "--output", out.to_str().unwrap()]);
}

#[test]
fn sweep_failure_keeps_an_existing_output_file_intact() {
    let (d, inp) = temp_file("in.csv", "load,speed\n1000,1\n2,x\n");
    let out = d.path().join("out.csv");
    std::fs::write(&out, "precious\n").unwrap();
    fails(&["sweep", "--input", inp.to_str().unwrap(), "--output", out.to_str().unwrap()], None, 1, &["line 3"]);
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "precious\n");
    assert_eq!(dir_names(d.path()).len(), 2);
}

#[test]
fn sweep_io_errors_name_the_path() {
    fails(&["sweep", "--input", "/no/such/in.csv"], None, 1, &["cannot read /no/such/in.csv"]);
    let (_d, inp) = temp_file("in.csv", "load,speed\n1,1\n");
    fails(&["sweep", "--input", inp.to_str().unwrap(), "--output", "/no/such/dir/out.csv"], None, 1, &["cannot write /no/such/dir/out.csv"]);
}

// ---------------------------------------------------------------- stribeck

#[test]
fn stribeck_writes_figure_3_csv_and_svg_from_the_library() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path().join("fig3");
    // The paper's model, whose film leaves the clearance at the fast end (the complete model
    // answers there: tests/complete.rs).
    let paper = d.path().join("paper.toml");
    std::fs::write(&paper, "[model]\npaper = true\n").unwrap();
    let o = run(&["stribeck", "--load", "20000", "--min-speed", "0.01", "--max-rpm", "8000", "--points", "31", "--output", dir.to_str().unwrap(), "--params", paper.to_str().unwrap()]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.contains("stribeck.csv") && o.stdout.contains("stribeck.svg"));
    let (h, rows) = parse_csv(&std::fs::read_to_string(dir.join("stribeck.csv")).unwrap());
    assert_eq!(&h[..3], &["load", "speed", "speed_rpm"]);
    assert_eq!(&h[3..], &RESULT_COLUMNS);
    // The curve ends before the film passes the diametral clearance (at 20 kN above about
    // 500 rad/s): 29 of the 31 speeds up to 8000 rpm, said on standard error.
    assert_eq!(rows.len(), 29);
    assert!(o.stderr.contains("note: the curve at 20000 N ends at 29 of 31 speeds") && o.stderr.contains("diametral clearance"), "{}", o.stderr);
    let w: Vec<f64> = rows.iter().map(|r| r[1].parse().unwrap()).collect();
    assert_eq!(w[0], 0.01);
    let ratio = (8000.0 * 2.0 * PI / 60.0 / 0.01f64).powf(1.0 / 30.0);
    assert!((w[28] / (0.01 * ratio.powi(28)) - 1.0).abs() < 1e-9);
    let paper_joint = Joint::new(&Params::paper()).unwrap();
    assert!(paper_joint.evaluate(20000.0, 0.01 * ratio.powi(29)).is_err());
    for k in 1..29 {
        let ratio = w[k] / w[k - 1];
        assert!((ratio - (w[1] / w[0])).abs() < 1e-9, "log-spaced");
    }
    let j = paper_joint;
    let mut s_prev = 0.0;
    for r in &rows {
        let op = j.evaluate(20000.0, r[1].parse().unwrap()).unwrap();
        assert_eq!(r[3].parse::<f64>().unwrap(), op.friction_coefficient);
        let s: f64 = r[11].parse().unwrap();
        assert!(s > s_prev);
        s_prev = s;
    }
    assert_eq!(rows[0][12], "boundary");
    assert_eq!(rows[28][12], "full-film");
    let svg = std::fs::read_to_string(dir.join("stribeck.svg")).unwrap();
    for s in ["Sommerfeld number S", "μ [-]", "1/γ1 (fluid film)", "1/γ2 (asperities)", "λ (eq. 21", "20 kN", "rig experiments", "1 and 800 rpm"] {
        assert!(svg.contains(s), "svg lacks {s}");
    }
}

#[test]
fn stribeck_rejects_bad_ranges() {
    rejects(&[
        (&["stribeck", "--load", "0"], 1, &["load = 0 N"]),
        (&["stribeck", "--load", "1", "--min-speed", "10", "--max-speed", "1"], 1, &["10 rad/s", "1 rad/s"]),
        (&["stribeck", "--load", "1", "--min-rpm", "-1"], 1, &["min-rpm = -1 rpm"]),
        (&["stribeck", "--load", "1", "--points", "1"], 1, &["points = 1"]),
        (&["stribeck", "--load", "1", "--min-speed", "1", "--min-rpm", "1"], 2, &["cannot be used with"]),
    ]);
}

/// Runs each case's arguments with `--output` a path in a fresh directory: each fails with
/// its exit code and every one of its messages, and nothing is written at that path.
fn rejects(cases: &[(&[&str], i32, &[&str])]) {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("x");
    for (args, code, needles) in cases {
        let mut args = args.to_vec();
        args.extend(["--output", out.to_str().unwrap()]);
        fails(&args, None, *code, needles);
    }
    assert!(!out.exists(), "nothing written on error");
}

// ---------------------------------------------------------------- map

#[test]
fn map_writes_figure_4_csv_and_plots_from_the_library() {
    let d = tempfile::tempdir().unwrap();
    let dir = d.path().join("fig4");
    let o = run(&["map", "--loads", "3", "--speeds", "4", "--output", dir.to_str().unwrap()]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(
        dir_names(&dir),
        ["map.csv", "map_curves.svg", "map_friction.svg", "map_lambda.svg", "map_min_lambda.svg"].iter().map(std::string::ToString::to_string).collect()
    );
    let (h, rows) = parse_csv(&std::fs::read_to_string(dir.join("map.csv")).unwrap());
    assert_eq!(&h[..3], &["load", "speed", "speed_rpm"]);
    assert_eq!(rows.len(), 12);
    let loads: Vec<f64> = rows.iter().map(|r| r[0].parse().unwrap()).collect();
    assert_eq!(loads, [5e3, 5e3, 5e3, 5e3, 32.5e3, 32.5e3, 32.5e3, 32.5e3, 60e3, 60e3, 60e3, 60e3]);
    let rpm: Vec<f64> = rows[..4].iter().map(|r| r[2].parse().unwrap()).collect();
    assert!((rpm[0] - 1.0).abs() < 1e-12 && (rpm[3] - 800.0).abs() < 1e-9, "{rpm:?}");
    let j = joint();
    for r in &rows {
        let op = j.evaluate(r[0].parse().unwrap(), r[1].parse().unwrap()).unwrap();
        assert_eq!(r[6].parse::<f64>().unwrap(), op.lambda_ratio);
        assert_eq!(r[3].parse::<f64>().unwrap(), op.friction_coefficient);
    }
    let lambda = std::fs::read_to_string(dir.join("map_lambda.svg")).unwrap();
    let friction = std::fs::read_to_string(dir.join("map_friction.svg")).unwrap();
    let curves = std::fs::read_to_string(dir.join("map_curves.svg")).unwrap();
    for svg in [&lambda, &friction] {
        for s in ["speed [rpm]", "load P_T [kN]", "rig experiments: 5-60 kN, up to 41.9 rpm"] {
            assert!(svg.contains(s), "map lacks {s}");
        }
    }
    assert!(lambda.contains("λ [-]") && friction.contains("μ [-]"));
    for s in ["5 kN", "60 kN", "speed [rpm]", "rig experiments"] {
        assert!(curves.contains(s), "curves lack {s}");
    }
}

#[test]
fn map_rejects_bad_grids() {
    rejects(&[
        (&["map", "--min-load", "60000", "--max-load", "5000"], 1, &["min-load 60000 N", "max-load 5000 N"]),
        (&["map", "--min-rpm", "0"], 1, &["min-rpm = 0 rpm"]),
        (&["map", "--speeds", "1"], 1, &["speeds = 1"]),
    ]);
    fails(&["map", "--output", "/proc/no-such-place/x"], None, 1, &["cannot write /proc/no-such-place/x"]);
}

#[test]
fn sweep_into_a_closed_pipe_ends_quietly() {
    use std::io::{BufRead, BufReader};
    let d = tempfile::tempdir().unwrap();
    let inp = d.path().join("in.csv");
    std::fs::write(&inp, points_csv(&regime_points())).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_pinjoint"))
        .args(["sweep", "--input", inp.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut first).unwrap(); // then the pipe closes
    let o = child.wait_with_output().unwrap();
    assert!(first.starts_with("case,load,speed,friction_coefficient"));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8_lossy(&o.stderr), "");
}

/// `sweep --output X.parquet` and back: a Parquet sweep read as the input of another sweep
/// answers the same rows as the CSV sweep (load, speed and temperature as doubles, the
/// results bit for bit: the CSV prints the shortest text of each double); the file is
/// Parquet (PAR1 at both ends); `map --format parquet` too; a bad format or Parquet to
/// standard output is refused by name.
#[test]
fn sweep_and_map_write_and_read_parquet() {
    let mut csv = String::from("load,speed,temperature\n");
    for i in 0..300 {
        let w = if i % 7 == 0 { 0.0 } else { (if i % 2 == 0 { 1.0 } else { -1.0 }) * 1e-5 * 1.07f64.powi(i) };
        csv.push_str(&format!("{:?},{:?},{:?}\n", 4e3 + 190.0 * f64::from(i), w, 253.15 + f64::from(i % 3) * 30.0));
    }
    let (dir, input) = temp_file("pts.csv", &csv);
    let d = |n: &str| dir.path().join(n).to_str().unwrap().to_string();
    let (a, pq, b) = (d("a.csv"), d("a.parquet"), d("b.csv"));
    for fidelity in ["full", "boundary", "table"] {
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", &a, "--fidelity", fidelity]);
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", &pq, "--fidelity", fidelity]);
        let bytes = std::fs::read(&pq).unwrap();
        assert!(bytes.starts_with(b"PAR1") && bytes.ends_with(b"PAR1"), "{fidelity}");
        // The Parquet file's numbers through a second sweep (at full, whatever the first's
        // fidelity) equal the CSV's input columns; the results of a full sweep are the CSV's.
        ok(&["sweep", "--input", &pq, "--output", &b]);
        let (ta, tb) = (std::fs::read_to_string(&a).unwrap(), std::fs::read_to_string(&b).unwrap());
        let (la, lb): (Vec<&str>, Vec<&str>) = (ta.lines().collect(), tb.lines().collect());
        assert_eq!(la.len(), 301);
        assert_eq!(la[0], lb[0]);
        for (x, y) in la.iter().zip(&lb).skip(1) {
            let (x, y): (Vec<&str>, Vec<&str>) = (x.split(',').collect(), y.split(',').collect());
            for k in 0..3 {
                assert_eq!(x[k].parse::<f64>().unwrap().to_bits(), y[k].parse::<f64>().unwrap().to_bits(), "{fidelity}");
            }
            if fidelity == "full" {
                assert_eq!(x[3..], y[3..]);
            }
        }
    }
    fails(&["sweep", "--input", input.to_str().unwrap(), "--format", "xml"], None, 1, &["--format xml", "csv or parquet"]);
    fails(&["sweep", "--input", input.to_str().unwrap(), "--format", "parquet"], None, 1, &["Parquet output needs a file"]);
    fails(&["sweep", "--input", &a, "--output", &d("x.parquet")], None, 1, &["output column"]);
    std::fs::write(d("bad.parquet"), "load,speed\n1,2\n").unwrap();
    fails(&["sweep", "--input", &d("bad.parquet")], None, 1, &["bad.parquet", "Parquet"]);
    let m = d("map");
    ok(&["map", "--loads", "3", "--speeds", "4", "--format", "parquet", "--output", &m]);
    let bytes = std::fs::read(dir.path().join("map").join("map.parquet")).unwrap();
    assert!(bytes.starts_with(b"PAR1") && bytes.ends_with(b"PAR1"));
    assert!(!dir.path().join("map").join("map.csv").exists());
    fails(&["map", "--format", "json", "--output", &m], None, 1, &["--format json"]);
}

/// The Parquet columns of `pq` equal the CSV sweep `csv` (header, rows) bit for bit: numbers as
/// the doubles the CSV prints, regime and validity as their text.
fn parquet_is_csv(pq: &Path, csv: &str, what: &str) {
    use arrow_array::cast::AsArray;
    use arrow_array::types::Float64Type;
    let (header, rows) = parse_csv(csv);
    let f = std::fs::File::open(pq).unwrap();
    let builder = parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder::try_new(f).unwrap();
    let names: Vec<String> = builder.schema().fields().iter().map(|f| f.name().clone()).collect();
    assert_eq!(names, header, "{what}");
    let mut row = 0;
    for batch in builder.build().unwrap() {
        let batch = batch.unwrap();
        for (k, name) in header.iter().enumerate() {
            let col = batch.column(k);
            for i in 0..batch.num_rows() {
                let want = &rows[row + i][k];
                if matches!(name.as_str(), "regime" | "validity") {
                    assert_eq!(col.as_string::<i32>().value(i), want, "{what} {name} row {}", row + i);
                } else {
                    let got = col.as_primitive::<Float64Type>().value(i);
                    assert_eq!(got.to_bits(), want.parse::<f64>().unwrap().to_bits(), "{what} {name} row {}", row + i);
                }
            }
        }
        row += batch.num_rows();
    }
    assert_eq!(row, rows.len(), "{what}");
}

/// A Parquet sweep at a level built over the input's own ranges reads the CSV once (the first
/// pass keeps the rows' numbers for the second): whatever the columns' order, with a
/// temperature column, comments, blank lines, quoted and padded fields, it holds the CSV
/// sweep's columns bit for bit; a malformed row anywhere, or a row the model refuses, fails
/// naming its line and leaves no file, as the CSV sweep does.
#[test]
fn a_parquet_sweep_parsed_once_is_the_csv_sweep_and_fails_as_it() {
    let mut csv = String::from("# a comment\nspeed, temperature ,load\n\n");
    for i in 0..1500 {
        let w = if i % 11 == 0 { 0.0 } else { (if i % 2 == 0 { 1.0 } else { -1.0 }) * 1e-4 * 1.009f64.powi(i) };
        let t = 263.15 + f64::from(i % 4) * 15.0;
        let p = 4e3 + 37.0 * f64::from(i);
        match i % 5 {
            0 => csv.push_str(&format!("\"{w:?}\",{t:?},{p:?}\n")),
            1 => csv.push_str(&format!(" {w:e} ,\t{t:?},{p:e}\r\n")),
            2 => csv.push_str(&format!("{w:?},{t:?},{p:?}\n# between\n")),
            _ => csv.push_str(&format!("{w:?},{t:?},{p:?}\n")),
        }
    }
    let (dir, input) = temp_file("once.csv", &csv);
    let (a, pq) = (dir.path().join("a.csv"), dir.path().join("a.parquet"));
    for fidelity in ["boundary", "table"] {
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", a.to_str().unwrap(), "--fidelity", fidelity]);
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", pq.to_str().unwrap(), "--fidelity", fidelity]);
        parquet_is_csv(&pq, &std::fs::read_to_string(&a).unwrap(), fidelity);
        // From standard input too.
        let o = run_with(&["sweep", "--input", "-", "--output", pq.to_str().unwrap(), "--fidelity", fidelity], Some(&csv));
        assert_eq!(o.code, 0, "{}", o.stderr);
        parquet_is_csv(&pq, &std::fs::read_to_string(&a).unwrap(), fidelity);
        // Where no temporary file can be made, the input is read twice: the same file.
        std::fs::remove_file(&pq).unwrap();
        let o = Command::new(env!("CARGO_BIN_EXE_pinjoint"))
            .args(["sweep", "--input", input.to_str().unwrap(), "--output", pq.to_str().unwrap(), "--fidelity", fidelity])
            .env("TMPDIR", dir.path().join("no such directory"))
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        parquet_is_csv(&pq, &std::fs::read_to_string(&a).unwrap(), fidelity);
    }
    // Malformed rows: the same error, naming the same line, for CSV and Parquet; no file left.
    let lines: Vec<&str> = csv.lines().collect();
    for (bad, needle) in [("1,2,x", "is not a number"), ("1,293.15,0", "must be > 0 N"), ("1,293.15", "missing column"), ("1,nan,5000", "not a finite number")] {
        let at = 900;
        let text: String = lines[..at].iter().chain(std::iter::once(&bad)).chain(&lines[at..]).map(|l| format!("{l}\n")).collect();
        let (d, input) = temp_file("bad.csv", &text);
        let line = format!("line {}", at + 1);
        for out in ["x.csv", "x.parquet"] {
            let o = d.path().join(out);
            fails(&["sweep", "--input", input.to_str().unwrap(), "--output", o.to_str().unwrap(), "--fidelity", "boundary"], None, 1, &[&line, needle]);
            assert!(!o.exists(), "{out}");
        }
    }
    // A row the model refuses (a temperature below absolute zero is checked by the model, not
    // the parser): found in the second pass, named by its line in both outputs.
    let text = format!("{}\n0.5,-5,20000\n", lines.join("\n"));
    let (d, input) = temp_file("refused.csv", &text);
    let line = format!("line {}", lines.len() + 1);
    let mut said = Vec::new();
    for out in ["x.csv", "x.parquet"] {
        let o = d.path().join(out);
        let r = fails(&["sweep", "--input", input.to_str().unwrap(), "--output", o.to_str().unwrap(), "--fidelity", "boundary"], None, 1, &[&line]);
        assert!(!o.exists(), "{out}");
        said.push(r.stderr.lines().last().unwrap_or("").to_string());
    }
    assert_eq!(said[0], said[1]);
}

/// A Parquet sweep of more rows than a row group (and than a batch, ending in a part-filled
/// chunk) holds the CSV sweep's columns in order, every number bit for bit the double the CSV
/// prints, the text columns as text, in row groups of at most 65536 rows; at boundary and table
/// fidelity (whose columns the round trip above does not compare).
#[test]
fn a_parquet_sweep_is_the_csv_sweep_bit_for_bit_across_row_groups() {
    let rows = 70_001;
    let mut csv = String::from("load,speed\n");
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..rows {
        let p = (5e3f64.ln() + 12f64.ln() * next()).exp();
        let w = (1e-3f64.ln() + 1e5f64.ln() * next()).exp() * if next() < 0.5 { -1.0 } else { 1.0 };
        csv.push_str(&format!("{p:?},{w:?}\n"));
    }
    let (dir, input) = temp_file("many.csv", &csv);
    let (a, pq) = (dir.path().join("a.csv"), dir.path().join("a.parquet"));
    for fidelity in ["boundary", "table"] {
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", a.to_str().unwrap(), "--fidelity", fidelity]);
        ok(&["sweep", "--input", input.to_str().unwrap(), "--output", pq.to_str().unwrap(), "--fidelity", fidelity]);
        let text = std::fs::read_to_string(&a).unwrap();
        assert_eq!(text.lines().count(), rows + 1, "{fidelity}");
        let f = std::fs::File::open(&pq).unwrap();
        let builder = parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder::try_new(f).unwrap();
        let groups = builder.metadata().row_groups();
        assert_eq!(groups.iter().map(parquet::file::metadata::RowGroupMetaData::num_rows).sum::<i64>(), rows as i64);
        assert!(groups.len() >= 2 && groups.iter().all(|g| g.num_rows() <= 65_536), "{fidelity}: {} row groups", groups.len());
        parquet_is_csv(&pq, &text, fidelity);
    }
}

/// Rows `n` of `load,speed,id` text whose cost varies from row to row (1 N to 90 kN, every
/// regime, both signs of speed).
fn pipeline_rows(n: usize) -> Vec<String> {
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut u = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|i| {
            let load = 10f64.powf(u() * 5.0 - 0.05);
            let speed = 10f64.powf(u() * 4.7 - 3.0) * if u() < 0.5 { -1.0 } else { 1.0 };
            format!("{load},{speed},r{i}")
        })
        .collect()
}

/// The sweep's pipeline (batches of 16384 rows; the chunks of two batches queued at once, in
/// any order on the cores) keeps the rows' order and answers: a sweep over three and a half
/// batches equals, row for row and byte for byte, the sweeps of its parts, each a single
/// batch; at a fidelity level too.
#[test]
fn sweep_rows_keep_their_order_and_answers_across_batches() {
    let rows = pipeline_rows(57_000);
    for fidelity in ["full", "boundary"] {
        // The level is built over the envelope given, so that each part's is the whole's.
        let args = ["sweep", "--input", "-", "--fidelity", fidelity, "--envelope-load", "1:1e5", "--envelope-speed", "1e-3:60"];
        let whole = run_with(&args, Some(&format!("load,speed,id\n{}\n", rows.join("\n"))));
        assert_eq!(whole.code, 0, "{}", whole.stderr);
        let mut lines = whole.stdout.lines();
        let header = lines.next().unwrap();
        let mut parts = Vec::new();
        for part in rows.chunks(5_000) {
            let o = run_with(&args, Some(&format!("load,speed,id\n{}\n", part.join("\n"))));
            assert_eq!(o.code, 0, "{}", o.stderr);
            let mut l = o.stdout.lines();
            assert_eq!(l.next(), Some(header));
            parts.extend(l.map(str::to_string));
        }
        let got: Vec<&str> = lines.collect();
        assert_eq!(got.len(), rows.len(), "{fidelity}");
        for (i, (g, p)) in got.iter().zip(&parts).enumerate() {
            assert!(g.starts_with(&rows[i]), "{fidelity}: row {i} is {g}, not the input's {}", rows[i]);
            assert_eq!(g, p, "{fidelity}: row {i}");
        }
    }
}

/// With several batches in flight, the first error in input order is the one reported: a bad
/// row in the second batch before a bad row in the fourth, or before a record too long to read
/// in the third (the read error waits for the batches before it).
#[test]
fn sweep_reports_the_first_error_in_input_order_across_batches() {
    let rows = pipeline_rows(60_000);
    let long = "1".repeat((1 << 20) + 10);
    for (second, later) in [(20_000, (50_000, "7,x,r".to_string())), (20_000, (40_000, long.clone())), (16_384, (32_768, long))] {
        let mut r = rows.clone();
        r[second] = "abc,1,r".into();
        r[later.0] = later.1;
        for fidelity in ["full", "boundary"] {
            // A file: the run stops at the error without reading the rest.
            let (_d, input) = temp_file("in.csv", &format!("load,speed,id\n{}\n", r.join("\n")));
            let o = run(&["sweep", "--input", input.to_str().unwrap(), "--fidelity", fidelity]);
            assert_eq!(o.code, 1, "{}", o.stderr);
            let line = second + 2;
            assert!(o.stderr.contains(&format!("line {line}:")) && o.stderr.contains("`abc`"), "{fidelity}, bad row at line {line}: {}", o.stderr);
        }
    }
}
