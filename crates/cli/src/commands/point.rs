//! `pinjoint point`: one operating point as a table or one JSON object.

use crate::common::{finite, readable, ParamsArg, RAD_S_PER_RPM};
use crate::error::Result;
use crate::fidelity_args::{note_fallback, FidelityArgs};
use crate::output::to_stdout;
use clap::Args;
use pinjoint::record::{Record, Value, LUBRICANT};
use pinjoint::OperatingPoint;

#[derive(Args, Debug)]
#[command(
    about = "Evaluate the model at one load and speed",
    long_about = "Evaluate the mixed-lubrication model at one operating point and print every \
quantity (SI units) as a table, or with --json as one JSON object.\n\
The speed is the pin's angular velocity, in rad/s (--speed) or rpm (--rpm); the model \
depends on its magnitude.\n\n\
Examples:\n  \
pinjoint point --load 20000 --speed 0.2\n  \
pinjoint point --load 60000 --rpm 42 --json\n  \
pinjoint point --load 5000 --rpm 800 --params my-joint.toml\n  \
pinjoint point --load 20000 --speed 0.2 --fidelity auto --tolerance 1e-3 --envelope-load 5000:60000 --envelope-speed 0.01:10\n\n\
With --fidelity other than full, the level is built over the envelope (by default [P/2, 2P] x \
[|ω|/2, 2|ω|] around the point) and standard error says which level answered and its measured \
error bound."
)]
/// Arguments of `pinjoint point` (its `--help` text is the `#[command]` attribute's).
pub struct PointCmd {
    /// Normal load on the joint P_T, in N (newtons; 20000 = 20 kN); its magnitude is used
    /// (a signed reaction component: -P gives the answer at +P); |P_T| must be > 0
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub load: f64,
    /// --speed or --rpm: the pin's angular velocity.
    #[command(flatten)]
    pub speed: SpeedArg,
    /// --params and --temperature.
    #[command(flatten)]
    pub params: ParamsArg,
    /// --fidelity, --tolerance and the envelope.
    #[command(flatten)]
    pub fidelity: FidelityArgs,
    /// Print one JSON object (keys in SI units) instead of the table
    #[arg(long)]
    pub json: bool,
}

/// The pin's angular velocity, given as exactly one of --speed (rad/s) and --rpm.
#[derive(Args, Debug, Clone)]
#[group(required = true, multiple = false)]
pub struct SpeedArg {
    /// Angular velocity of the pin, in rad/s (the model uses its magnitude)
    #[arg(long, value_name = "RAD/S", allow_negative_numbers = true)]
    pub speed: Option<f64>,
    /// Angular velocity of the pin, in rpm (revolutions per minute; 1 rpm = 2π/60 rad/s)
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub rpm: Option<f64>,
}

impl SpeedArg {
    /// The angular velocity in rad/s.
    pub fn rad_per_s(&self) -> Result<f64> {
        match (self.speed, self.rpm) {
            (Some(w), _) => finite("speed", w, "rad/s"),
            (None, Some(n)) => Ok(finite("speed", n, "rpm")? * RAD_S_PER_RPM),
            (None, None) => unreachable!("clap requires one of --speed and --rpm"),
        }
    }
}

/// The rows of the table, in order: a label for people and the [`pinjoint::record::POINT`]
/// quantity it shows (value and unit come from the record). `speed` is followed by its value
/// in rpm.
pub const TABLE: [(&str, &str); 24] = [
    ("load P_T", "load"),
    ("angular velocity ω", "speed"),
    ("sliding speed u = |ω|R", "sliding_speed"),
    ("friction coefficient μ (eq. 10)", "friction_coefficient"),
    ("  lubricant part (eq. 3, + clearance)", "fluid_friction_coefficient"),
    ("  asperity part μ_c/γ2 (eq. 8)", "asperity_friction_coefficient"),
    ("torque T = μRP_T (eq. 11)", "torque"),
    ("  clearance torque (complete model)", "clearance_torque"),
    ("  grease yield torque (part of it)", "grease_yield_torque"),
    ("central film thickness h_c", "film_thickness"),
    ("lambda ratio h_c/√(σ²+σ_b²) (eq. 21)", "lambda_ratio"),
    ("minimum film thickness h_min (Pan–Hamrock)", "min_film_thickness"),
    ("lambda ratio h_min/√(σ²+σ_b²) (eq. 21)", "min_lambda_ratio"),
    ("fluid load fraction 1/γ1", "fluid_load_fraction"),
    ("asperity load fraction 1/γ2", "asperity_load_fraction"),
    ("Hertz mean pressure p_m (eq. 6)", "mean_pressure"),
    ("Hertz peak pressure p0 (eq. 6)", "peak_pressure"),
    ("contact half-width a (eq. 6)", "contact_half_width"),
    ("viscosity at p_m (Roelands, eq. 5)", "contact_viscosity"),
    ("Sommerfeld number S (eq. 20)", "sommerfeld_number"),
    ("journal bearing weight w (complete model)", "journal_weight"),
    ("eccentricity ratio 1 - h_c/c", "eccentricity_ratio"),
    ("regime", "regime"),
    ("validity (checked, extrapolation, known-wrong, outside)", "validity"),
];

/// The labels of the lubricant rows after [`TABLE`], in [`pinjoint::record::LUBRICANT`] order.
pub const LUBRICANT_LABELS: [&str; 3] = ["lubricant temperature T", "inlet viscosity η0 at T", "pressure-viscosity coefficient α at T"];

/// A record unit as the table shows it: `-` for a pure number, nothing for the regime's name,
/// middle dots in products.
pub fn display_unit(unit: &'static str) -> &'static str {
    match unit {
        "1" => "-",
        "-" => "",
        "N.m" => "N·m",
        "Pa.s" => "Pa·s",
        u => u,
    }
}

/// The table rows: quantity, value, unit.
pub fn table(o: &OperatingPoint) -> Vec<(&'static str, String, &'static str)> {
    let mut rows = Vec::with_capacity(TABLE.len() + 1);
    for (label, name) in &TABLE {
        let c = pinjoint::record::column(name).expect("every table row names a record quantity");
        let value = match c.value {
            Value::Number(f) => readable(f(o)),
            Value::Regime => o.regime.as_str().to_string(),
            Value::Validity => o.validity.as_str().to_string(),
        };
        rows.push((*label, value, display_unit(c.unit)));
        if *name == "speed" {
            rows.push(("  (in rpm)", readable(o.angular_velocity / RAD_S_PER_RPM), "rpm"));
        }
    }
    rows
}

/// Runs `pinjoint point`: evaluates the model at one load and speed and prints the table or
/// JSON to standard output. Fails on invalid flags or parameters, or if the model cannot be
/// evaluated there.
pub fn run(cmd: &PointCmd) -> Result<()> {
    let joint = cmd.params.joint()?;
    let omega = cmd.speed.rad_per_s()?;
    let op = if cmd.fidelity.is_full()? {
        joint.evaluate(cmd.load, omega)?
    } else {
        let p = crate::common::positive("load magnitude", cmd.load.abs(), "N")?;
        let w = omega.abs();
        let speeds = if w > 0.0 { (0.5 * w, 2.0 * w) } else { (1e-3, 1.0) };
        let mut ev = cmd.fidelity.build(&cmd.params.load()?, (0.5 * p, 2.0 * p), speeds)?;
        let e = ev.evaluate(cmd.load, omega)?;
        note_fallback(&e, &ev, &Default::default());
        eprintln!("fidelity: answered by {}", e.source.as_str());
        ev.operating_point(&e)
    };
    if cmd.json {
        let record = Record { point: &op, lubricant: joint.lubricant() };
        let text = serde_json::to_string(&record).expect("a map of numbers and names serialises");
        return to_stdout(|w| writeln!(w, "{text}"));
    }
    let mut rows = table(&op);
    for (label, c) in LUBRICANT_LABELS.into_iter().zip(&LUBRICANT) {
        rows.push((label, readable((c.value)(joint.lubricant())), display_unit(c.unit)));
    }
    let width = rows.iter().map(|r| r.0.chars().count()).max().unwrap_or(0);
    let vwidth = rows.iter().map(|r| r.1.len()).max().unwrap_or(0);
    to_stdout(|w| {
        writeln!(w, "{:width$}  {:>vwidth$}  unit", "quantity", "value")?;
        for (name, value, unit) in &rows {
            // Pad by characters (names hold non-ASCII symbols).
            let pad = width - name.chars().count();
            writeln!(w, "{name}{:pad$}  {value:>vwidth$}  {unit}", "")?;
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_keys_follow_the_record_and_the_table_shows_every_quantity() {
        let j = pinjoint::Joint::new(&pinjoint::Params::default()).unwrap();
        let op = j.evaluate(20e3, 0.2).unwrap();
        let text = serde_json::to_string(&Record { point: &op, lubricant: j.lubricant() }).unwrap();
        let names = pinjoint::record::POINT.iter().map(|c| c.name).chain(LUBRICANT.iter().map(|c| c.name));
        let at: Vec<usize> = names.map(|n| text.find(&format!("\"{n}\":")).unwrap()).collect();
        assert!(at.windows(2).all(|w| w[0] < w[1]), "{text}");
        let mut shown: Vec<&str> = TABLE.iter().map(|r| r.1).collect();
        shown.sort_unstable();
        let mut all: Vec<&str> = pinjoint::record::POINT.iter().map(|c| c.name).collect();
        all.sort_unstable();
        assert_eq!(shown, all);
        assert_eq!(table(&op).len(), TABLE.len() + 1);
    }
}
