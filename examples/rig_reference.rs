//! Library reference for the PinJointRig FMU tests: the rig simulator driven the
//! way a co-simulation host drives the FMU. Reads lines `time,load` or
//! `time,load,command_angle` (s, N, rad) on stdin: each advances the simulator to
//! `time` with those inputs held over the step that ends there (a command angle
//! makes the position loop follow it instead of the internal sine), then writes
//! the sample as CSV with full precision (`{:?}`: the shortest text that reads
//! back to the same f64).
//!
//! ```text
//! printf '0,20000\n0.1,20000\n0.2,60000\n' | cargo run --release -p pinjoint --example rig_reference
//! ```
//!
//! Optional first argument: a TOML parameter file with the model's sections and
//! `[rig]` (missing keys keep the defaults).

use pinjoint::rig::{Inputs, RigConfig, RigSim};
use std::io::{BufRead, Write};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let cfg = match std::env::args().nth(1) {
        Some(path) => RigConfig::from_toml_str(&std::fs::read_to_string(path)?)?,
        None => RigConfig::default(),
    };
    let mut sim = RigSim::new(&cfg)?;
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    writeln!(
        out,
        "time,command_angle,angle,angular_velocity,torque,friction_torque,friction_coefficient,film_thickness,\
         fluid_load_fraction,stuck,load,actuator_work,friction_dissipation,kinetic_energy"
    )?;
    for (n, line) in std::io::stdin().lock().lines().enumerate() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let f: Vec<f64> = line.split(',').map(|s| s.trim().parse::<f64>()).collect::<Result<_, _>>()
            .map_err(|e| format!("line {}: {e} in '{line}'", n + 1))?;
        let inputs = match f[..] {
            [_, load] => Inputs { load: Some(load), command_angle: None },
            [_, load, angle] => Inputs { load: Some(load), command_angle: Some(angle) },
            _ => return Err(format!("line {}: expected 'time,load[,command_angle]', got '{line}'", n + 1).into()),
        };
        sim.advance_to(f[0], &inputs).map_err(|e| format!("line {}: {e}", n + 1))?;
        let s = sim.sample()?;
        writeln!(
            out,
            "{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{},{:?},{:?},{:?},{:?}",
            s.time,
            s.command_angle,
            s.angle,
            s.angular_velocity,
            s.torque,
            s.friction_torque,
            s.friction_coefficient,
            s.film_thickness,
            s.fluid_load_fraction,
            u8::from(s.stuck),
            s.load,
            s.actuator_work,
            s.friction_dissipation,
            s.kinetic_energy
        )?;
    }
    Ok(())
}
