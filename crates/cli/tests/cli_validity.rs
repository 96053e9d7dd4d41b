//! The `pinjoint` binary's `validity` column and temperatures: `sweep` with a `temperature`
//! column at every fidelity level (random loads, speeds, temperatures and their order; the
//! envelope's boundaries and both sides), `stribeck`, `map` and `point` (table and JSON).

use pinjoint::validity::{self, Validity};
use pinjoint::{Joint, Params};

mod cli_support;
use cli_support::{ok, parse_csv, temp_file};

fn at(t: f64) -> Joint {
    let mut p = Params::default();
    p.lubricant.temperature = t;
    Joint::new(&p).unwrap()
}

/// A small deterministic generator (xorshift64*), so the rows differ from any the library's
/// tests use and the run repeats.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
    }
}

/// The rows: the envelope's boundaries and both sides, then random points over 5-200 kN,
/// 1e-4-3 rad/s (both signs; inside the film bound down to 250 K) and a handful of temperatures in random order.
fn rows(seed: u64) -> Vec<(f64, f64, f64)> {
    let w_max = validity::SLIDING_SPEED.hi / 0.028;
    let mut v = vec![
        (5e3, 1.0, 293.15),
        (5e3f64.next_down(), 1.0, 293.15),
        (60e3, -1.0, 293.15),
        (60e3f64.next_up(), -1.0, 293.15),
        (20e3, w_max * (1.0 - 1e-12), 288.15),
        (20e3, w_max * (1.0 + 1e-12), 298.15),
        (20e3, 0.5, 288.15f64.next_down()),
        (20e3, 0.5, 298.15f64.next_up()),
        (20e3, 0.5, 273.15),
        (20e3, 0.5, 273.15f64.next_down()),
    ];
    let mut r = Rng(seed);
    let temps: Vec<f64> = (0..4).map(|_| 250.0 + 100.0 * r.next()).chain([293.15, 253.15]).collect();
    for _ in 0..120 {
        // Inside the film bound (crates/fmu/tests/ranges.rs) down to 250 K: loads from 5 kN, speeds to 3 rad/s.
        let load = r.log_uniform(5e3, 2e5);
        let w = r.log_uniform(1e-4, 3.0) * if r.next() < 0.5 { -1.0 } else { 1.0 };
        let t = temps[(r.next() * temps.len() as f64) as usize % temps.len()];
        v.push((load, w, t));
    }
    v
}

fn csv_of(rows: &[(f64, f64, f64)]) -> String {
    let mut s = String::from("load,speed,temperature\n");
    for (p, w, t) in rows {
        s.push_str(&format!("{p:?},{w:?},{t:?}\n"));
    }
    s
}

/// At every fidelity: the validity column is the envelope's for the row's load, speed and
/// temperature; at full every number is the library's at that temperature bit for bit; at
/// table, boundary and auto the friction coefficient inside the level's envelope is within
/// the tolerance of full at that temperature (the level is built at each temperature).
#[test]
fn sweep_with_temperatures_at_every_fidelity() {
    let pts = rows(0x5eed_2025);
    let (_d, input) = temp_file("pts.csv", &csv_of(&pts));
    let tol = 1e-3;
    // A table envelope whose margins stay inside the film bound at the rows' coldest temperature (250 K).
    let env = ["--envelope-load", "10000:60000", "--envelope-speed", "0.01:1"];
    let joints: std::collections::HashMap<u64, Joint> = pts.iter().map(|&(_, _, t)| (t.to_bits(), at(t))).collect();
    for fidelity in ["full", "table", "boundary", "auto"] {
        let mut args = vec!["sweep", "--input", input.to_str().unwrap(), "--fidelity", fidelity, "--tolerance", "1e-3"];
        args.extend(env);
        let o = ok(&args);
        let (h, out) = parse_csv(&o.stdout);
        assert_eq!(h.last().map(String::as_str), Some("validity"));
        let (mu, torque, col_v) = (h.iter().position(|c| c == "friction_coefficient").unwrap(), h.iter().position(|c| c == "torque").unwrap(), h.len() - 1);
        assert_eq!(out.len(), pts.len());
        for (k, (row, &(p, w, t))) in out.iter().zip(&pts).enumerate() {
            let expect = validity::of_point(p, w.abs() * 0.028, t, false);
            assert_eq!(row[col_v], expect.as_str(), "{fidelity} row {k}: {p} N, {w} rad/s, {t} K");
            let op = joints[&t.to_bits()].evaluate(p, w).unwrap();
            let got: f64 = row[mu].parse().unwrap();
            if fidelity == "full" {
                assert_eq!(got.to_bits(), op.friction_coefficient.to_bits(), "row {k}");
                assert_eq!(row[torque].parse::<f64>().unwrap().to_bits(), op.torque.to_bits(), "row {k}");
            } else if (5e3..=60e3).contains(&p) && (0.01..=10.0).contains(&w.abs()) && fidelity != "boundary" {
                let rel = ((got - op.friction_coefficient) / op.friction_coefficient).abs();
                assert!(rel <= tol, "{fidelity} row {k} at {t} K: mu {got} vs {} (rel {rel:e})", op.friction_coefficient);
            }
        }
    }
}

/// `stribeck` and `map` carry the column; `--temperature` below 0 C makes it known-wrong.
#[test]
fn stribeck_and_map_carry_the_validity_column() {
    let d = tempfile::tempdir().unwrap();
    for (t, load) in [("293.15", "20000"), ("253.15", "20000"), ("293.15", "70000")] {
        let dir = d.path().join(format!("s{t}{load}"));
        ok(&["stribeck", "--load", load, "--min-speed", "0.01", "--max-rpm", "800", "--points", "25", "--temperature", t, "--output", dir.to_str().unwrap()]);
        let (h, rows) = parse_csv(&std::fs::read_to_string(dir.join("stribeck.csv")).unwrap());
        assert_eq!(h.last().map(String::as_str), Some("validity"));
        let tk: f64 = t.parse().unwrap();
        let mut seen = std::collections::BTreeSet::new();
        for r in &rows {
            let (p, w): (f64, f64) = (r[0].parse().unwrap(), r[1].parse().unwrap());
            assert_eq!(r[h.len() - 1], validity::of_point(p, w * 0.028, tk, false).as_str());
            seen.insert(r[h.len() - 1].clone());
        }
        let expect: Vec<&str> = match (t, load) {
            ("253.15", _) => vec!["extrapolation"], // the complete model: modelled, not known-wrong
            (_, "70000") => vec!["extrapolation"],
            _ => vec!["checked", "extrapolation"], // 800 rpm is beyond the rig's speeds
        };
        assert_eq!(seen.iter().map(String::as_str).collect::<Vec<_>>(), expect, "T {t}, P {load}");
        // The figure marks the checked speeds and says when load or temperature is outside.
        let svg = std::fs::read_to_string(dir.join("stribeck.svg")).unwrap();
        assert!(svg.contains("validity: checked") || svg.contains("outside 5-60 kN"), "T {t}, P {load}");
        assert_eq!(svg.contains("outside 5-60 kN: extrapolation"), load == "70000");
        assert!(!svg.contains("too LOW"), "T {t}: the complete model is not known to be wrong");
    }
    let dir = d.path().join("map");
    ok(&["map", "--loads", "3", "--speeds", "4", "--output", dir.to_str().unwrap()]);
    let (h, rows) = parse_csv(&std::fs::read_to_string(dir.join("map.csv")).unwrap());
    assert_eq!(h.last().map(String::as_str), Some("validity"));
    for r in &rows {
        let (p, w): (f64, f64) = (r[0].parse().unwrap(), r[1].parse().unwrap());
        assert_eq!(r[h.len() - 1], validity::of_point(p, w * 0.028, 293.15, false).as_str());
    }
    let svgs: Vec<String> = std::fs::read_dir(&dir).unwrap().filter_map(|e| {
        let p = e.unwrap().path();
        (p.extension().is_some_and(|x| x == "svg")).then(|| std::fs::read_to_string(p).unwrap())
    }).collect();
    assert!(svgs.iter().any(|s| s.contains("validity checked; outside extrapolation")), "the map marks the checked region");
}

/// `point`'s table and JSON say the validity, on both sides of the cold-soak boundary.
#[test]
fn point_says_the_validity() {
    // The complete model (default): below 0 C an extrapolation; the paper's model known-wrong.
    let d = tempfile::tempdir().unwrap();
    let paper = d.path().join("paper.toml");
    std::fs::write(&paper, "[model]\npaper = true\n").unwrap();
    let o = ok(&["point", "--load", "20000", "--speed", "0.21", "--temperature", "273.1499", "--json", "--params", paper.to_str().unwrap()]);
    let m: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(m["validity"], Validity::KnownWrong.as_str());
    for (t, expect) in [("273.15", Validity::Extrapolation), ("273.1499", Validity::Extrapolation), ("293.15", Validity::Checked), ("298.16", Validity::Extrapolation)] {
        let o = ok(&["point", "--load", "20000", "--speed", "0.21", "--temperature", t, "--json"]);
        let m: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
        assert_eq!(m["validity"], expect.as_str(), "T = {t}");
        let o = ok(&["point", "--load", "20000", "--speed", "0.21", "--temperature", t]);
        let line = o.stdout.lines().find(|l| l.starts_with("validity")).unwrap_or_else(|| panic!("{}", o.stdout));
        assert!(line.contains(expect.as_str()), "{line}");
    }
}
