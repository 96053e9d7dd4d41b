//! Issue 23 through the `pinjoint` command line: the declared box's corners give an answer
//! inside the invariants or an error naming the quantity (item 1); huge inputs give short
//! messages (item 3); the load is a magnitude, as `--help` says (item 4, docs/conventions.md).

mod cli_support;
use cli_support::{run, s, temp_file};
use pinjoint::fmt::MESSAGE_CHARS;
use pinjoint::params::{Range, MAX_TEMPERATURE, MIN_TEMPERATURE, PARAMS};
use pinjoint::{Joint, Params};

fn json(stdout: &str) -> serde_json::Map<String, serde_json::Value> {
    match serde_json::from_str(stdout).unwrap() {
        serde_json::Value::Object(m) => m,
        v => panic!("not an object: {v}"),
    }
}

/// `pinjoint point` at (load, speed) with `params` (TOML text) and `extra` flags: the JSON
/// answer checked against the invariants, or an error that is short and names a quantity.
fn check_point(params: &str, load: f64, speed: f64, extra: &[&str]) -> bool {
    let (d, pf) = temp_file("p.toml", params);
    let (l, w) = (format!("--load={load:e}"), format!("--speed={speed:e}"));
    let mut args = vec!["point", &l, &w, "--params", s(&pf), "--json"];
    args.extend(extra);
    let o = run(&args);
    drop(d);
    if o.code != 0 {
        assert_eq!(o.code, 1, "{args:?}: {}", o.stderr);
        assert!(o.stderr.starts_with("error: ") && o.stderr.chars().count() <= MESSAGE_CHARS + 10, "{args:?}: {}", o.stderr);
        assert!(o.stderr.contains(" = "), "unnamed: {}", o.stderr);
        return false;
    }
    let m = json(&o.stdout);
    let n = |k: &str| m[k].as_f64().unwrap_or_else(|| panic!("{k}: {}", o.stdout));
    let p = Params::from_toml_str(params).unwrap();
    let j = Joint::new(&p).unwrap();
    let (mu, film, fluid, asperity) = (n("friction_coefficient"), n("film_thickness"), n("fluid_load_fraction"), n("asperity_load_fraction"));
    let slack = if extra.is_empty() { 1e-12 } else { 1e-3 };
    assert!(mu <= j.max_friction_coefficient(load) * (1.0 + slack), "{args:?}: {}", o.stdout);
    assert!((n("torque") - mu * p.geometry.pin_radius * load.abs()).abs() <= 1e-9 * n("torque").abs().max(1e-300), "{}", o.stdout);
    for s in [fluid, asperity] {
        assert!((-slack..=1.0 + slack).contains(&s), "{}", o.stdout);
    }
    assert!(film > 0.0 && film.is_finite() && n("lambda_ratio").is_finite());
    // The paper's model refuses a film beyond the clearance; the complete model's is composite.
    assert!(!j.is_paper() || film <= j.max_film_thickness() || fluid < pinjoint::joint::REGIME_SHARE, "{}", o.stdout);
    true
}

#[test]
fn corners_of_the_declared_box_answer_inside_the_invariants_or_name_the_quantity() {
    // Each parameter at each end of its declared range (one at a time), at the paper's
    // 20 kN and 0.2 rad/s, full and auto; then the temperature ends and load/speed corners.
    let mut answered = 0;
    let mut cases = 0;
    for spec in PARAMS.iter() {
        let ends: Vec<f64> = match spec.range {
            Range::Positive => vec![1e-300, 1e300],
            Range::NonNegative => vec![0.0, 1e300],
            Range::HalfOpen(lo, hi) => vec![lo, hi - (hi - lo) * 1e-9],
            Range::OpenClosed(lo, hi) => vec![lo + (hi - lo) * 1e-9, hi],
            Range::Closed(lo, hi) => vec![lo, hi],
        };
        for v in ends {
            let text = match spec.kind {
                pinjoint::params::Kind::Real => format!("[{}]\n{} = {v:e}\n", spec.section, spec.key),
                pinjoint::params::Kind::Boolean => format!("[{}]\n{} = {}\n", spec.section, spec.key, v != 0.0),
            };
            if Params::from_toml_str(&text).is_err() {
                // The cross-checks (clearance, eta_0(T)): the CLI names the key.
                let (_d, pf) = temp_file("p.toml", &text);
                let o = run(&["point", "--load", "20000", "--speed", "0.2", "--params", s(&pf)]);
                assert!(o.code == 1 && o.stderr.contains(spec.section), "{text}: {}", o.stderr);
                continue;
            }
            for extra in [&[][..], &["--fidelity", "auto", "--tolerance", "1e-3"][..]] {
                cases += 1;
                answered += usize::from(check_point(&text, 20e3, 0.2, extra));
            }
        }
    }
    for t in [MIN_TEMPERATURE, MAX_TEMPERATURE] {
        let text = format!("[lubricant]\ntemperature = {t}\n");
        for (load, w) in [(20e3, 0.2), (20e3, 4.4), (-60e3, -1.0), (1.0, 1.0), (5e8, 1e-3), (20e3, 1e6)] {
            cases += 1;
            answered += usize::from(check_point(&text, load, w, &[]));
        }
    }
    assert!(answered * 2 > cases, "{answered} of {cases} answered");
}

#[test]
fn huge_inputs_give_short_messages() {
    let junk = "x".repeat(10_000_000);
    let (d, big) = temp_file("big.toml", &format!("[geometry]\n{}\n", &junk[..900_000]));
    let csv = d.path().join("in.csv");
    std::fs::write(&csv, format!("load,speed\n20000,{}\n", &junk[..900_000])).unwrap();
    let arg = &junk[..100_000]; // under Linux's 128 KiB limit for one argument
    let cases: Vec<Vec<&str>> = vec![
        vec!["point", "--load", "20000", "--speed", "1", "--params", s(&big)],
        vec!["sweep", "--input", s(&csv)],
        vec!["point", "--load", arg, "--speed", "1"],
        vec!["point", "--load", "20000", "--speed", "1", "--fidelity", arg],
        vec!["point", "--load", "20000", "--speed", "1", "--params", arg],
        vec![arg],
    ];
    for args in cases {
        let o = run(&args);
        assert_ne!(o.code, 0);
        let n = o.stderr.chars().count();
        assert!(n <= MESSAGE_CHARS + 10, "{} characters for {:?}: {}", n, &args[..1], &o.stderr[..300]);
        assert!(!o.stderr.contains(&junk[..1000]), "echoes 1000 characters of the input");
    }
}

#[test]
fn the_load_is_a_magnitude_as_the_help_says() {
    for cmd in ["point", "cycle"] {
        let o = run(&[cmd, "--help"]);
        assert!(o.stdout.contains("its magnitude is used"), "{cmd} --help: {}", o.stdout);
    }
    let a = run(&["point", "--load", "20000", "--speed", "0.3", "--json"]);
    let b = run(&["point", "--load=-20000", "--speed", "0.3", "--json"]);
    let (a, b) = (json(&a.stdout), json(&b.stdout));
    for k in ["friction_coefficient", "torque", "film_thickness", "fluid_load_fraction"] {
        assert_eq!(a[k], b[k], "{k}");
    }
    let o = run(&["point", "--load", "0", "--speed", "0.3"]);
    assert!(o.code == 1 && o.stderr.contains("load = 0 N"), "{}", o.stderr);
}
