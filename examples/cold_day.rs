//! The cold-day scene: a main gear's free-fall extension at +20, −20, −40 and −54 °C with the
//! default (illustrative) scene and the default joint parameters, and once more without trunnion
//! friction for comparison.
//!
//! ```text
//! cargo run --release -p pinjoint --example cold_day [-- out.csv]
//! ```
//!
//! Prints, per temperature, the time to lock, the speed at lock, the lock margin, the trunnion's
//! friction energy and how it splits between the joint model's mechanisms (the asperities'
//! boundary friction μ_c/γ2 and the film's shear, eq. 10, weighted by the angle turned), and the
//! time to lock without trunnion friction; writes them to `out/cold_day.csv` (or the path given). A
//! temperature the joint model refuses is printed and written with the model's reason: it is
//! not an error of the example.

use pinjoint::scene::{free_fall::joint_at, simulate, FreeFallOutcome, FreeFallParams, SceneError};
use pinjoint::Params;
use std::io::Write;

/// The temperatures of the scene (°C).
const TEMPERATURES_C: [f64; 4] = [20.0, -20.0, -40.0, -54.0];

/// The share of the friction energy from the asperities' boundary friction: Σ μ_asp|Δφ| / Σ μ|Δφ|
/// along the run, the model re-evaluated at each step's load and speed.
fn boundary_share(o: &FreeFallOutcome, params: &Params) -> Result<f64, Box<dyn std::error::Error>> {
    let joint = joint_at(params, o.temperature)?;
    let (mut asperity, mut total) = (0.0, 0.0);
    for w in o.series.windows(2) {
        let op = joint.evaluate(w[0].load, w[0].angular_velocity)?;
        let turn = (w[1].angle - w[0].angle).abs() * w[0].load;
        asperity += op.asperity_friction_coefficient * turn;
        total += op.friction_coefficient * turn;
    }
    Ok(asperity / total)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = match std::env::args().nth(1) {
        Some(p) => p,
        None => {
            std::fs::create_dir_all("out")?;
            "out/cold_day.csv".into()
        }
    };
    let params = Params::default();
    let scene = FreeFallParams::default();
    let frictionless = FreeFallParams { trunnion_joints: 0, ..scene };
    let mut csv = std::fs::File::create(&path)?;
    writeln!(
        csv,
        "temperature_C,temperature_K,status,time_to_lock_s,speed_at_lock_rad_s,lock_margin,breakaway_torque_N_m,friction_energy_J,boundary_share,time_to_lock_without_friction_s,reason"
    )?;
    println!(
        "{:>6} {:>10} {:>10} {:>10} {:>8} {:>9} {:>9} {:>11}",
        "T [C]", "status", "t_lock [s]", "w [rad/s]", "margin", "E_f [J]", "boundary", "t_lock free"
    );
    for c in TEMPERATURES_C {
        // (100 c + 27315)/100: 233.15 for -40, where c + 273.15 gives 233.14999999999998.
        let kelvin = (100.0 * c + 27315.0) / 100.0;
        match (simulate(&scene, &params, kelvin), simulate(&frictionless, &params, kelvin)) {
            (Ok(o), Ok(f)) => {
                let status = if o.locked { "locked" } else { "not locked" };
                let speed = o.speed_at_lock.map_or(String::new(), |w| w.to_string());
                let share = boundary_share(&o, &params)?;
                println!(
                    "{c:>6} {status:>10} {:>10.4} {:>10.4} {:>8.4} {:>9.3} {:>8.1}% {:>11.4}",
                    o.time_to_lock,
                    o.speed_at_lock.unwrap_or(f64::NAN),
                    o.lock_margin,
                    o.friction_energy,
                    100.0 * share,
                    f.time_to_lock
                );
                // `{}` of +∞ is `inf`, as the CSV wants it.
                writeln!(csv, "{c},{kelvin},{status},{},{speed},{},{},{},{share},{},", o.time_to_lock, o.lock_margin, o.breakaway_torque, o.friction_energy, f.time_to_lock)?;
            }
            (Err(e @ (SceneError::Temperature { .. } | SceneError::Joint { .. } | SceneError::Breakaway { .. })), _)
            | (_, Err(e @ (SceneError::Temperature { .. } | SceneError::Joint { .. } | SceneError::Breakaway { .. }))) => {
                println!("{c:>6} {:>10}  {e}", "not run");
                writeln!(csv, "{c},{kelvin},not run,,,,,,,,\"{}\"", e.to_string().replace('"', "'"))?;
            }
            (Err(e), _) | (_, Err(e)) => return Err(e.into()),
        }
    }
    println!("written: {path}");
    Ok(())
}
