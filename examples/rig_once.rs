//! One rig run (10 strokes at 1 Hz, 20 kN, 100 samples a stroke) for instruction counts:
//! `valgrind --tool=callgrind target/release/examples/rig_once [dopri5|dop853|dopri5-dense] [TOL]`.
//! Prints the sample count and the run's statistics (steps, evaluations, friction solves).
use pinjoint::rig::{Method, RigConfig, RigSim};

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let mut cfg = RigConfig::default();
    cfg.rig.method = match a.first().map(String::as_str).unwrap_or("dopri5-dense") {
        "dopri5" => Method::Dopri5,
        "dop853" => Method::Dop853,
        _ => Method::Dopri5Dense,
    };
    let tol: f64 = a.get(1).map_or(2e-5, |s| s.parse().expect("TOL must be a number"));
    (cfg.rig.rtol, cfg.rig.atol) = (tol, tol);
    let mut sim = RigSim::new(&cfg).expect("valid configuration");
    let samples = sim.run(10.0, 0.01).expect("the rig runs");
    println!("{} samples, {:?}", samples.len(), sim.stats());
}
