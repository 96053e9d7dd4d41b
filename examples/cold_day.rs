//! The cold-day scene: a main gear's free-fall extension at +20, −20, −40 and −54 °C with the
//! default (illustrative) scene and the default joint parameters, and once more with the
//! trunnion friction off for comparison.
//!
//! ```text
//! cargo run --release -p pinjoint --example cold_day [-- out.csv]
//! ```
//!
//! Prints, per temperature, the time to lock, the speed at lock, the lock margin and the
//! trunnion's friction energy, and writes them to `cold_day.csv` (or the path given). A
//! temperature the joint model refuses is printed and written with the model's reason; it is
//! not an error of the example.

use pinjoint::scene::{simulate, FreeFallParams, SceneError};
use pinjoint::Params;
use std::io::Write;

/// The temperatures of the scene (°C).
const TEMPERATURES_C: [f64; 4] = [20.0, -20.0, -40.0, -54.0];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).unwrap_or_else(|| "cold_day.csv".into());
    let params = Params::default();
    let scene = FreeFallParams::default();
    let frictionless = FreeFallParams { trunnion_joints: 0, ..scene };
    let mut csv = std::fs::File::create(&path)?;
    writeln!(csv, "temperature_C,temperature_K,trunnion_friction,status,time_to_lock_s,speed_at_lock_rad_s,lock_margin,breakaway_torque_N_m,friction_energy_J,error")?;
    println!("{:>7} {:>9} {:>10} {:>14} {:>12} {:>12} {:>12}", "T [C]", "friction", "status", "t_lock [s]", "w_lock", "margin", "E_f [J]");
    for c in TEMPERATURES_C {
        // (100 c + 27315)/100: 233.15 for -40, where c + 273.15 gives 233.14999999999998.
        let kelvin = (100.0 * c + 27315.0) / 100.0;
        for (label, s) in [("on", &scene), ("off", &frictionless)] {
            match simulate(s, &params, kelvin) {
                Ok(o) => {
                    let status = if o.locked { "locked" } else { "not locked" };
                    let speed = o.speed_at_lock.map_or(String::new(), |w| format!("{w:.4}"));
                    println!("{c:>7} {label:>9} {status:>10} {:>14.4} {speed:>12} {:>12.4} {:>12.2}", o.time_to_lock, o.lock_margin, o.friction_energy);
                    writeln!(
                        csv,
                        "{c},{kelvin},{label},{status},{},{},{},{},{},",
                        if o.locked { format!("{}", o.time_to_lock) } else { "inf".into() },
                        o.speed_at_lock.map_or(String::new(), |w| w.to_string()),
                        o.lock_margin,
                        o.breakaway_torque,
                        o.friction_energy
                    )?;
                }
                Err(e @ (SceneError::Temperature { .. } | SceneError::Joint { .. })) => {
                    println!("{c:>7} {label:>9} {:>10}  {e}", "not run");
                    writeln!(csv, "{c},{kelvin},{label},not run,,,,,,\"{}\"", e.to_string().replace('"', "'"))?;
                }
                Err(e) => return Err(e.into()),
            }
        }
    }
    println!("written: {path}");
    Ok(())
}
