//! Quick look at a rig run: `cargo run --release -p pinjoint --example rig_probe -- <freq Hz> <load N> <cycles> [k_b [J tau_s K_p K_d]]`.
//! Prints the tracking error, the torque at mid-stroke, event counts and the energy residual,
//! and writes `rig_probe.csv` (time, command, angle, speed, torque, friction torque, stuck).
use pinjoint::rig::{cycle_average_friction_coefficient, energy_residual, RigConfig, RigSim};
use std::io::Write;

fn main() {
    let a: Vec<f64> = std::env::args().skip(1).map(|s| s.parse().unwrap()).collect();
    let mut cfg = RigConfig::default();
    cfg.rig.frequency = *a.first().unwrap_or(&1.0);
    cfg.rig.load = *a.get(1).unwrap_or(&20e3);
    let cycles = *a.get(2).unwrap_or(&3.0);
    if let Some(k) = a.get(3) {
        cfg.rig.breakaway_factor = *k;
    }
    if a.len() >= 8 {
        (cfg.rig.inertia, cfg.rig.servo_time_constant, cfg.rig.position_gain, cfg.rig.velocity_gain) = (a[4], a[5], a[6], a[7]);
    }
    let period = 1.0 / cfg.rig.frequency;
    let t0 = std::time::Instant::now();
    let mut sim = RigSim::new(&cfg).unwrap();
    let tr = sim.run(cycles * period, period / 2000.0).unwrap();
    let el = t0.elapsed();
    let track = tr.iter().filter(|s| s.time > period).map(|s| (s.angle - s.command_angle).abs()).fold(0.0, f64::max);
    let mu = cycle_average_friction_coefficient(&tr, cfg.rig.frequency, cfg.model.geometry.pin_radius, 1);
    let res = energy_residual(&tr[0], tr.last().unwrap());
    println!("time {el:?} stats {:?}", sim.stats());
    println!("max tracking error after 1st cycle {:.3} deg, mu_avg {:?}, energy residual {res:.3e} J of D = {:.3} J", track.to_degrees(), mu, tr.last().unwrap().friction_dissipation);
    let mut f = std::fs::File::create("rig_probe.csv").unwrap();
    for s in &tr {
        writeln!(f, "{},{},{},{},{},{},{}", s.time, s.command_angle, s.angle, s.angular_velocity, s.torque, s.friction_torque, u8::from(s.stuck)).unwrap();
    }
}
