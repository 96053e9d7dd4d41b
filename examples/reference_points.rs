//! Library reference values for the FMU tests: reads `load,angular_velocity` lines
//! (N, rad/s) on stdin and writes, for each, the library's outputs as CSV with full
//! precision (`{:?}`, shortest text that reads back to the same f64).
//!
//! ```text
//! printf '20000,0.2\n60000,-1\n' | cargo run --release -p pinjoint --example reference_points
//! ```
//!
//! Optional first argument: a TOML parameter file (missing keys keep the defaults).

use pinjoint::{Joint, Params};
use std::io::{BufRead, Write};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let params = match std::env::args().nth(1) {
        Some(path) => Params::from_toml_str(&std::fs::read_to_string(path)?)?,
        None => Params::default(),
    };
    let joint = Joint::new(&params)?;
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    writeln!(
        out,
        "load,angular_velocity,torque,signed_torque,friction_coefficient,film_thickness,lambda_ratio,\
         fluid_load_fraction,asperity_load_fraction,mean_pressure,sommerfeld_number"
    )?;
    for (n, line) in std::io::stdin().lock().lines().enumerate() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let mut f = line.split(',').map(|s| s.trim().parse::<f64>());
        let (Some(Ok(load)), Some(Ok(omega)), None) = (f.next(), f.next(), f.next()) else {
            return Err(format!("line {}: expected 'load,angular_velocity', got '{line}'", n + 1).into());
        };
        let o = joint.evaluate(load, omega).map_err(|e| format!("line {}: {e}", n + 1))?;
        writeln!(
            out,
            "{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?}",
            load,
            omega,
            o.torque,
            o.signed_torque(),
            o.friction_coefficient,
            o.film_thickness,
            o.lambda_ratio,
            o.fluid_load_fraction,
            o.asperity_load_fraction,
            o.mean_pressure,
            o.sommerfeld_number
        )?;
    }
    Ok(())
}
