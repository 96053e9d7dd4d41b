//! `pinjoint calibrate` run as a user would: records made by `pinjoint cycle` with a changed
//! μ_c, breakaway peaks and two loads; the JSON object, the files, the calibrated parameter file
//! read back by `pinjoint point`; and clear errors for bad files.

use std::path::{Path, PathBuf};

mod cli_support;
use cli_support::{ok, run, s};

fn fail(args: &[&str]) -> String {
    let o = run(args);
    assert_eq!(o.code, 1, "{args:?} should fail: {}", o.stdout);
    o.stderr
}

/// `pinjoint cycle` at `load` N and 1 Hz with μ_c = 0.105 and a breakaway factor of 1.3.
fn cycle(dir: &Path, name: &str, load: &str) -> PathBuf {
    let params = dir.join("truth.toml");
    std::fs::write(&params, "[friction]\nboundary_friction_coefficient = 0.105\n[rig]\nbreakaway_factor = 1.3\n").unwrap();
    let out = dir.join(name);
    ok(&["cycle", "--frequency", "1", "--load", load, "--cycles", "8", "--samples-per-cycle", "1000", "--params", params.to_str().unwrap(), "--output", out.to_str().unwrap()]);
    out.join("cycle.csv")
}

#[test]
fn calibrates_cycle_records_and_writes_every_file() {
    let tmp = tempfile::tempdir().unwrap();
    let (a, b) = (cycle(tmp.path(), "a", "20000"), cycle(tmp.path(), "b", "40000"));
    let out = tmp.path().join("cal");
    let o = ok(&["calibrate", "--input", s(&a), "--load", "20000", "--input", s(&b), "--load", "40000", "--output", s(&out), "--json"]);
    // Exactly one JSON object on stdout.
    let v: serde_json::Value = serde_json::from_str(o.stdout.trim()).expect("one JSON object");
    assert_eq!(o.stdout.trim().lines().count(), 1);
    let mu = &v["parameters"]["friction.boundary_friction_coefficient"];
    let (value, lo, hi) = (mu["value"].as_f64().unwrap(), mu["ci95"][0].as_f64().unwrap(), mu["ci95"][1].as_f64().unwrap());
    println!("{}", o.stdout);
    assert!((value - 0.105).abs() < 1e-3 && lo <= 0.105 && 0.105 <= hi, "{value} [{lo}, {hi}]");
    assert!(mu["standard_error"].as_f64().unwrap() > 0.0);
    assert!(v["rms_residual"].as_f64().unwrap() > 0.0);
    let (used, excluded) = (v["points_used"].as_u64().unwrap(), v["points_excluded"].as_u64().unwrap());
    assert_eq!(used + excluded, 2 * 8001);
    for f in ["calibrated.toml", "report.md", "report.html", "fit.csv", "torque_time.svg", "torque_angle.svg", "residuals.svg"] {
        assert!(out.join(f).metadata().unwrap().len() > 100, "{f}");
    }
    let csv = std::fs::read_to_string(out.join("fit.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * 8001);
    assert_eq!(csv.lines().filter(|l| l.ends_with(",1")).count() as u64, used);
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.matches("<svg").count() >= 3 && html.contains("Excluded samples"));
    // The calibrated file is a complete parameter file: `point` reads it and gives μ_c at rest
    // (the asperities' part; the complete model adds the grease's yield torque over R·P).
    let p = ok(&["point", "--load", "20000", "--speed", "0", "--json", "--params", s(&out.join("calibrated.toml"))]);
    let pv: serde_json::Value = serde_json::from_str(p.stdout.trim()).unwrap();
    assert!((pv["asperity_friction_coefficient"].as_f64().unwrap() - value).abs() < 1e-15, "{}", p.stdout);
    let yield_mu = pv["grease_yield_torque"].as_f64().unwrap() / (0.028 * 20e3);
    assert!((pv["friction_coefficient"].as_f64().unwrap() - (value + yield_mu)).abs() < 1e-15, "{}", p.stdout);
    // Without --json: a summary and the files written.
    let o = ok(&["calibrate", "--input", s(&a), "--load", "20000", "--output", s(&out)]);
    assert!(o.stdout.contains("friction.boundary_friction_coefficient = 0.10") && o.stdout.contains("wrote"), "{}", o.stdout);
}

#[test]
fn bad_files_are_named_with_line_column_and_unit() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let write = |name: &str, text: &str| {
        let p = tmp.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let e = fail(&["calibrate", "--input", s(&write("a.csv", "time,angle,load\n0,0,1\n")), "--output", s(&out)]);
    assert!(e.contains("a.csv, line 1") && e.contains("`torque`") && e.contains("N.m"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("b.csv", "time,torque,load\n0,0,1\n")), "--output", s(&out)]);
    assert!(e.contains("neither `angle` (rad) nor `angular_velocity` (rad/s)"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("c.csv", "time,angle,torque\n0,0,1\n")), "--output", s(&out)]);
    assert!(e.contains("`load`") && e.contains("--load"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("d.csv", "time,angle,torque,load\n0,0,1,5\n0.1,x,1,5\n")), "--output", s(&out)]);
    assert!(e.contains("d.csv, line 3") && e.contains("angle = `x` is not a number (rad)"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("e.csv", "time,angle,torque,load\n0,0,1,5\n0.1,0.1,NaN,5\n")), "--output", s(&out)]);
    assert!(e.contains("e.csv, line 3") && e.contains("torque = NaN N.m is not a finite number"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("f.csv", "time,angle,torque,load\n0,0,1,5\n0,0.1,1,5\n")), "--output", s(&out)]);
    assert!(e.contains("line 3") && e.contains("does not increase"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("g.csv", "time,angle,torque,load\n0,0,1,5\n0.1,0.1,1,5\n")), "--output", s(&out)]);
    assert!(e.contains("too short"), "{e}");
    // A --load beside a load column must agree with it.
    let e = fail(&["calibrate", "--input", s(&tmp.path().join("g.csv")), "--load", "7", "--output", s(&out)]);
    assert!(e.contains("line 2") && e.contains("column load = 5 N disagrees with --load 7 N"), "{e}");
    assert!(fail(&["calibrate", "--input", s(&tmp.path().join("g.csv")), "--load", "5", "--output", s(&out)]).contains("too short"));
    // Angle in degrees: a whole record of ±40°.
    let mut text = String::from("time,angle,torque\n");
    for i in 0..2000 {
        let t = f64::from(i) * 1e-3;
        text.push_str(&format!("{t},{},{}\n", 40.0 * (std::f64::consts::TAU * t).sin(), 60.0));
    }
    let e = fail(&["calibrate", "--input", s(&write("deg.csv", &text)), "--load", "20000", "--output", s(&out)]);
    assert!(e.contains("deg.csv") && e.contains("degrees"), "{e}");
    let e = fail(&["calibrate", "--input", s(&write("h.csv", &text)), "--load", "1", "--load", "2", "--output", s(&out)]);
    assert!(e.contains("2 --load values for 1 --input"), "{e}");
    assert!(fail(&["calibrate", "--input", s(&tmp.path().join("missing.csv")), "--output", s(&out)]).contains("missing.csv"));
    assert!(!out.join("calibrated.toml").exists(), "no output after a failure");
}

#[test]
fn model_rig_fits_the_breakaway_factor_through_the_rig_simulation() {
    let tmp = tempfile::tempdir().unwrap();
    let params = tmp.path().join("truth.toml");
    std::fs::write(&params, "[friction]\nboundary_friction_coefficient = 0.105\n[rig]\nbreakaway_factor = 1.3\n").unwrap();
    let rec = tmp.path().join("rec");
    ok(&["cycle", "--frequency", "1", "--load", "20000", "--cycles", "3", "--samples-per-cycle", "500", "--params", s(&params), "--output", s(&rec)]);
    let a = rec.join("cycle.csv");
    let out = tmp.path().join("cal");
    let o = ok(&["calibrate", "--input", s(&a), "--load", "20000", "--model", "rig", "--fit", "rig.breakaway_factor", "--output", s(&out), "--json"]);
    println!("{}", o.stdout);
    let v: serde_json::Value = serde_json::from_str(o.stdout.trim()).expect("one JSON object");
    for (key, truth, tol) in [("friction.boundary_friction_coefficient", 0.105, 1e-4), ("rig.breakaway_factor", 1.3, 1e-3)] {
        let e = &v["parameters"][key];
        let value = e["value"].as_f64().unwrap();
        assert!((value - truth).abs() < tol, "{key} = {value}");
        assert!(e["standard_error"].as_f64().unwrap() > 0.0 && e["ci95"][0].as_f64().unwrap() <= value, "{key}");
    }
    // The documented keys, the same shape as the quasi-static fit's.
    for k in ["parameters", "rms_residual", "points_used", "points_excluded", "torque_offset", "warnings"] {
        assert!(v.get(k).is_some(), "{k}");
    }
    // The calibrated file carries the fitted [rig] section and reads back.
    let toml = std::fs::read_to_string(out.join("calibrated.toml")).unwrap();
    let kb: f64 = toml.lines().find_map(|l| l.strip_prefix("breakaway_factor = ")).expect("a breakaway_factor line").parse().unwrap();
    assert!(toml.contains("[rig]") && (kb - 1.3).abs() < 1e-3, "{toml}");
    ok(&["cycle", "--frequency", "1", "--load", "20000", "--cycles", "1", "--params", s(&out.join("calibrated.toml")), "--output", s(&tmp.path().join("again"))]);
    // A rig key without --model rig, and a key that is not a rig property, are named.
    let e = fail(&["calibrate", "--input", s(&a), "--load", "20000", "--fit", "rig.breakaway_factor", "--output", s(&out)]);
    assert!(e.contains("rig.breakaway_factor") && e.contains("--model rig"), "{e}");
    let e = fail(&["calibrate", "--input", s(&a), "--load", "20000", "--model", "rig", "--fit", "rig.rtol", "--output", s(&out)]);
    assert!(e.contains("rig.rtol") && e.contains("integrator"), "{e}");
    assert!(ok(&["calibrate", "--help"]).stdout.contains("--model rig"));
}

#[test]
fn inertia_fitted_or_given_and_long_records_averaged() {
    let tmp = tempfile::tempdir().unwrap();
    let (a, b) = (cycle(tmp.path(), "a", "20000"), cycle(tmp.path(), "b", "40000"));
    let out = tmp.path().join("cal");
    let json = |extra: &[&str]| -> serde_json::Value {
        let mut args = vec!["calibrate", "--input", s(&a), "--load", "20000", "--input", s(&b), "--load", "40000", "--output", s(&out), "--json"];
        args.extend_from_slice(extra);
        serde_json::from_str(ok(&args).stdout.trim()).expect("one JSON object")
    };
    // Neither --inertia nor [rig] inertia: J is fitted (the rig's J is 0.05 kg·m²), with its interval.
    let v = json(&[]);
    let j = &v["inertia_estimate"];
    let (jv, lo, hi) = (j["value"].as_f64().unwrap(), j["ci95"][0].as_f64().unwrap(), j["ci95"][1].as_f64().unwrap());
    assert!(v["inertia_fitted"].as_bool().unwrap() && (jv - 0.05).abs() < 2.5e-3 && lo <= 0.05 && 0.05 <= hi, "{v}");
    assert_eq!(v["inertia"].as_f64().unwrap(), jv);
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("Inertia: rig.inertia = ") && report.contains("fitted"), "{report}");
    // --inertia gives it; so does [rig] inertia in --params (and --inertia wins over the file).
    let v = json(&["--inertia", "0.05"]);
    assert!(!v["inertia_fitted"].as_bool().unwrap() && v["inertia_estimate"].is_null() && v["inertia"].as_f64() == Some(0.05), "{v}");
    let params = tmp.path().join("j.toml");
    std::fs::write(&params, "[rig]\ninertia = 0.06\n").unwrap();
    let v = json(&["--params", s(&params)]);
    assert!(!v["inertia_fitted"].as_bool().unwrap() && v["inertia"].as_f64() == Some(0.06), "{v}");
    let v = json(&["--params", s(&params), "--inertia", "0.05"]);
    assert_eq!(v["inertia"].as_f64(), Some(0.05));
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("rig.inertia = 0.05 kg.m2 given (not fitted)"), "{report}");
    // A parameter file without [rig] inertia leaves J fitted.
    std::fs::write(&params, "[friction]\nboundary_friction_coefficient = 0.1\n").unwrap();
    assert!(json(&["--params", s(&params)])["inertia_fitted"].as_bool().unwrap());
    // The sample budget: 16002 rows over 4000 are averaged in blocks of 5; fit.csv thinned to
    // at most 1000 rows, or not written.
    let v = json(&["--max-samples", "4000", "--fit-csv-rows", "1000"]);
    assert_eq!((v["samples_read"].as_u64(), v["block_length"].as_u64()), (Some(16002), Some(5)), "{v}");
    let mu = v["parameters"]["friction.boundary_friction_coefficient"]["value"].as_f64().unwrap();
    assert!((mu - 0.105).abs() < 1e-3, "{mu}");
    let csv = std::fs::read_to_string(out.join("fit.csv")).unwrap();
    let rows = csv.lines().count() - 1;
    assert!((700..=1000).contains(&rows), "{rows}");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("averaged in blocks of 5") && report.contains("every 4-th of the"), "{report}");
    std::fs::remove_file(out.join("fit.csv")).unwrap();
    json(&["--fit-csv-rows", "0"]);
    assert!(!out.join("fit.csv").exists());
    let e = fail(&["calibrate", "--input", s(&a), "--load", "20000", "--output", s(&out), "--max-samples", "10"]);
    assert!(e.contains("--max-samples = 10"), "{e}");
}

/// `pinjoint cycle` at 20 kN, 1 Hz, at `temperature` K, with μ_c = 0.105 and Roelands'
/// temperature index S_0 = 1.3882 (10 % above its default).
fn cycle_at(dir: &Path, temperature: &str) -> PathBuf {
    let params = dir.join("truth_t.toml");
    std::fs::write(&params, "[friction]\nboundary_friction_coefficient = 0.105\n[lubricant]\nroelands_temperature_index = 1.3882\n").unwrap();
    let out = dir.join(format!("t{temperature}"));
    ok(&["cycle", "--frequency", "1", "--load", "20000", "--cycles", "6", "--samples-per-cycle", "1000", "--temperature", temperature, "--params", s(&params), "--output", s(&out)]);
    out.join("cycle.csv")
}

#[test]
fn temperature_per_input_evaluates_each_record_at_its_temperature() {
    let tmp = tempfile::tempdir().unwrap();
    let temps = ["293.15", "313.15", "333.15"];
    let files: Vec<PathBuf> = temps.iter().map(|t| cycle_at(tmp.path(), t)).collect();
    let out = tmp.path().join("cal");
    let mut args = vec!["calibrate", "--load", "20000", "--fit", "lubricant.roelands_temperature_index", "--output", s(&out), "--json"];
    for (f, t) in files.iter().zip(temps) {
        args.extend_from_slice(&["--input", s(f), "--temperature", t]);
    }
    let v: serde_json::Value = serde_json::from_str(ok(&args).stdout.trim()).expect("one JSON object");
    println!("{v}");
    assert_eq!(v["temperatures"], serde_json::json!([293.15, 313.15, 333.15]));
    let e = &v["parameters"]["lubricant.roelands_temperature_index"];
    let (value, lo, hi) = (e["value"].as_f64().unwrap(), e["ci95"][0].as_f64().unwrap(), e["ci95"][1].as_f64().unwrap());
    assert!(lo <= 1.3882 && 1.3882 <= hi && (value - 1.3882).abs() < 2e-3, "{e}");
    // The calibrated file predicts the torque between the records' temperatures: `point` at
    // 303.15 K against the truth's.
    let truth = tmp.path().join("truth_t.toml");
    let mu = |params: &Path| -> f64 {
        let p = ok(&["point", "--load", "20000", "--speed", "3", "--temperature", "303.15", "--json", "--params", s(params)]);
        serde_json::from_str::<serde_json::Value>(p.stdout.trim()).unwrap()["friction_coefficient"].as_f64().unwrap()
    };
    let (want, got) = (mu(&truth), mu(&out.join("calibrated.toml")));
    assert!((got / want - 1.0).abs() < 1e-3, "{got} vs {want}");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("Temperatures: the records are at 293.15, 313.15, 333.15 K"), "{report}");
    // Without the temperatures every record is taken at 20 C (where S_0 does nothing): a far
    // worse fit of mu_c alone.
    let mut args0 = vec!["calibrate", "--load", "20000", "--output", s(&out), "--json"];
    for f in &files {
        args0.extend_from_slice(&["--input", s(f)]);
    }
    let v0: serde_json::Value = serde_json::from_str(ok(&args0).stdout.trim()).unwrap();
    assert!(v0["rms_residual"].as_f64().unwrap() > 10.0 * v["rms_residual"].as_f64().unwrap(), "{v0}");
    // A temperature column is read as the load column is; a --temperature beside it must agree.
    let csv = std::fs::read_to_string(&files[1]).unwrap();
    let mut lines = csv.lines();
    let mut with = format!("{},temperature\n", lines.next().unwrap());
    for l in lines {
        with.push_str(&format!("{l},313.15\n"));
    }
    let col = tmp.path().join("col.csv");
    std::fs::write(&col, with).unwrap();
    let v1: serde_json::Value =
        serde_json::from_str(ok(&["calibrate", "--load", "20000", "--input", s(&col), "--output", s(&out), "--json"]).stdout.trim()).unwrap();
    assert_eq!(v1["temperatures"], serde_json::json!([313.15]));
    let e = fail(&["calibrate", "--load", "20000", "--input", s(&col), "--temperature", "293.15", "--output", s(&out)]);
    assert!(e.contains("col.csv, line 2") && e.contains("column temperature = 313.15 K disagrees with --temperature 293.15 K"), "{e}");
    // Bad temperatures: the quantity, value, unit, and the hint for degrees Celsius.
    let bad = |t: &str| fail(&["calibrate", "--load", "20000", "--input", s(&files[0]), "--temperature", t, "--output", s(&out)]);
    let e = bad("20");
    assert!(e.contains("--temperature = 20 K is invalid") && e.contains("kelvin?") && e.contains("293.15 K"), "{e}");
    let e = bad("-5");
    assert!(e.contains("--temperature = -5 K") && e.contains("> 0 K") && e.contains("kelvin?"), "{e}");
    let e = bad("NaN");
    assert!(e.contains("--temperature = NaN K") && e.contains("finite"), "{e}");
    let e = bad("200");
    assert!(e.contains("temperature = 200 K") && e.contains("lubricant.temperature"), "{e}");
    let e = fail(&["calibrate", "--load", "20000", "--input", s(&files[0]), "--temperature", "293.15", "--temperature", "313.15", "--output", s(&out)]);
    assert!(e.contains("2 --temperature values for 1 --input"), "{e}");
    std::fs::write(&col, "time,angle,torque,temperature\n0,0,1,20\n0.1,0.1,1,20\n").unwrap();
    let e = fail(&["calibrate", "--load", "20000", "--input", s(&col), "--output", s(&out)]);
    assert!(e.contains("col.csv, line 2") && e.contains("column temperature = 20 K") && e.contains("kelvin?"), "{e}");
}

/// The cycle-average friction coefficient `pinjoint cycle` prints (eq. 11: mean |T| / (R·P)).
fn cycle_mu(stdout: &str) -> f64 {
    let line = stdout.lines().find(|l| l.starts_with("cycle-average friction coefficient")).unwrap_or_else(|| panic!("{stdout}"));
    line.rsplit(' ').next().unwrap().parse().unwrap()
}

/// The rig on the cold day (issue 37, item 6): records made by `pinjoint cycle` at −40, −20, 0
/// and 20 °C (5 and 10 kN, 0.3 Hz at −40 °C or 0.5 Hz, and 1 Hz) of a joint with μ_c = 0.11 and a grease 1.5× stiffer
/// than the default (at −40 °C and 0.3 Hz such a grease made the rig's event logic refuse before), 0.5 N·m of torque noise added to
/// the CSV, fitted by `pinjoint calibrate` with one `--temperature` per input; the calibrated
/// file run by `pinjoint cycle` at −30 °C gives the truth's stroke torque within 5 %. Not 40 kN,
/// nor 0.3 Hz above −40 °C: there the rig sticks and slips at −20 and 0 °C (the grease's supply
/// layer makes the torque fall steeply with speed; crates/calibrate/tests/cold_rig.rs), which
/// the quasi-static fit does not describe.
#[test]
fn cold_rig_records_predict_minus_30_celsius_within_5_percent() {
    let tmp = tempfile::tempdir().unwrap();
    let g = pinjoint::Params::default().grease;
    let truth = tmp.path().join("truth_cold.toml");
    std::fs::write(
        &truth,
        format!("[friction]\nboundary_friction_coefficient = 0.11\n[grease]\nyield_stress = {:?}\nconsistency = {:?}\n", 1.5 * g.yield_stress, 1.5 * g.consistency),
    )
    .unwrap();
    let temps = ["233.15", "253.15", "273.15", "293.15"];
    let mut args: Vec<String> = ["calibrate", "--json", "--output"].iter().map(ToString::to_string).collect();
    args.push(s(&tmp.path().join("cal")).into());
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    for t in temps {
        let slow = if t == "233.15" { "0.3" } else { "0.5" };
        for (load, f) in [("5000", slow), ("5000", "1"), ("10000", slow), ("10000", "1")] {
            let out = tmp.path().join(format!("c{t}-{load}-{f}"));
            ok(&["cycle", "--frequency", f, "--load", load, "--cycles", "4", "--samples-per-cycle", "400", "--temperature", t, "--params", s(&truth), "--output", s(&out)]);
            // 0.5 N·m of Gaussian noise on the torque column (a 64-bit LCG, Box–Muller).
            let csv = std::fs::read_to_string(out.join("cycle.csv")).unwrap();
            let mut lines = csv.lines();
            let header = lines.next().unwrap();
            let col = header.split(',').position(|c| c == "torque").unwrap();
            let mut noisy = format!("{header}\n");
            for l in lines {
                let mut uniform = || {
                    seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
                    ((seed >> 11) as f64 + 0.5) / (1u64 << 53) as f64
                };
                let z = (-2.0 * uniform().ln()).sqrt() * (std::f64::consts::TAU * uniform()).cos();
                let mut f: Vec<String> = l.split(',').map(ToString::to_string).collect();
                f[col] = format!("{:?}", f[col].parse::<f64>().unwrap() + 0.5 * z);
                noisy.push_str(&f.join(","));
                noisy.push('\n');
            }
            let rec = tmp.path().join(format!("r{t}-{load}-{f}.csv"));
            std::fs::write(&rec, noisy).unwrap();
            args.extend(["--input".to_string(), s(&rec).to_string(), "--load".into(), load.into(), "--temperature".into(), t.into()]);
        }
    }
    let argv: Vec<&str> = args.iter().map(String::as_str).collect();
    let v: serde_json::Value = serde_json::from_str(ok(&argv).stdout.trim()).expect("one JSON object");
    println!("{v}");
    assert_eq!(v["temperatures"], serde_json::json!([233.15, 253.15, 273.15, 293.15]));
    assert!(v["parameters"]["grease.consistency"]["value"].as_f64().is_some(), "the grease is fitted across temperature: {v}");
    let calibrated = tmp.path().join("cal").join("calibrated.toml");
    let mut worst: f64 = 0.0;
    for load in ["5000", "20000", "40000"] {
        for f in ["0.3", "1"] {
            let mu = |params: &Path| {
                let out = tmp.path().join("predict");
                cycle_mu(&ok(&["cycle", "--frequency", f, "--load", load, "--cycles", "2", "--temperature", "243.15", "--params", s(params), "--output", s(&out)]).stdout)
            };
            let (want, got) = (mu(&truth), mu(&calibrated));
            println!("-30 C, {load} N, {f} Hz: truth {want}, calibrated {got}");
            worst = worst.max((got / want - 1.0).abs());
        }
    }
    println!("worst relative error of the -30 C stroke torque: {worst:.2e}");
    assert!(worst < 0.05, "{worst}");
}
