//! `pinjoint point`: one operating point as a table or one JSON object.

use super::common::{finite, readable, ParamsArg, RAD_S_PER_RPM};
use super::error::Result;
use super::fidelity_args::{note_fallback, FidelityArgs};
use super::output::to_stdout;
use clap::Args;
use pinjoint::OperatingPoint;
use serde::Serialize;

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

/// The JSON form of a point: the documented keys first, then extras (all SI).
#[derive(Serialize)]
pub struct PointJson {
    /// Normal load P_T, in N.
    pub load: f64,
    /// rad/s, as given (the model uses |speed|).
    pub speed: f64,
    /// Friction coefficient μ (eq. 10), dimensionless.
    pub friction_coefficient: f64,
    /// Friction torque magnitude T = μ·R·P_T (eq. 11), in N·m.
    pub torque: f64,
    /// Central film thickness h_c, in m.
    pub film_thickness: f64,
    /// Film parameter λ = h_c/√(σ² + σ_b²) (eq. 21 with the central film), dimensionless.
    pub lambda_ratio: f64,
    /// Share of the load carried by the fluid film, 1/γ1.
    pub fluid_load_fraction: f64,
    /// Share of the load carried by the asperities, 1/γ2.
    pub asperity_load_fraction: f64,
    /// Hertz mean pressure p_m (eq. 6), in Pa.
    pub mean_pressure: f64,
    /// Hertz contact half-width a (eq. 6), in m.
    pub contact_half_width: f64,
    /// Sommerfeld number S (eq. 20), dimensionless.
    pub sommerfeld_number: f64,
    /// Lubrication regime: "boundary", "mixed" or "full-film".
    pub regime: &'static str,
    /// Sliding speed u = |ω|·R, in m/s.
    pub sliding_speed: f64,
    /// Hertz peak pressure p0 (eq. 6), in Pa.
    pub peak_pressure: f64,
    /// Roelands viscosity at p_m (eq. 5), in Pa·s (+∞ where eq. 5 overflows).
    pub contact_viscosity: f64,
    /// The fluid (Bair–Winer, eq. 3) part of μ, Q_H/P_T.
    pub fluid_friction_coefficient: f64,
    /// The asperity (eq. 8) part of μ, μ_c/γ2.
    pub asperity_friction_coefficient: f64,
    /// h_min (m), Pan–Hamrock ratio on h_c (extension; `pinjoint::min_film`).
    pub min_film_thickness: f64,
    /// h_min/√(σ² + σ_b²) (eq. 21 as printed).
    pub min_lambda_ratio: f64,
    /// Lubricant temperature (K) and the viscosity η0 and α at it.
    pub temperature: f64,
    /// Inlet (ambient-pressure) viscosity η0 at `temperature`, in Pa·s.
    pub inlet_viscosity: f64,
    /// Pressure-viscosity coefficient α at `temperature`, in 1/Pa.
    pub pressure_viscosity_coefficient: f64,
}

impl PointJson {
    /// The JSON form of `o`, with the lubricant state of `joint`.
    pub fn new(o: &OperatingPoint, joint: &pinjoint::Joint) -> Self {
        let l = joint.lubricant();
        Self { temperature: l.temperature, inlet_viscosity: l.viscosity, pressure_viscosity_coefficient: l.pressure_viscosity_coefficient, ..Self::from(o) }
    }
}

impl From<&OperatingPoint> for PointJson {
    fn from(o: &OperatingPoint) -> Self {
        Self {
            load: o.load,
            speed: o.angular_velocity,
            friction_coefficient: o.friction_coefficient,
            torque: o.torque,
            film_thickness: o.film_thickness,
            lambda_ratio: o.lambda_ratio,
            fluid_load_fraction: o.fluid_load_fraction,
            asperity_load_fraction: o.asperity_load_fraction,
            mean_pressure: o.mean_pressure,
            contact_half_width: o.contact_half_width,
            sommerfeld_number: o.sommerfeld_number,
            regime: o.regime.as_str(),
            sliding_speed: o.sliding_speed,
            peak_pressure: o.peak_pressure,
            contact_viscosity: o.contact_viscosity,
            fluid_friction_coefficient: o.fluid_friction_coefficient,
            asperity_friction_coefficient: o.asperity_friction_coefficient,
            min_film_thickness: o.min_film_thickness,
            min_lambda_ratio: o.min_lambda_ratio,
            temperature: f64::NAN,
            inlet_viscosity: f64::NAN,
            pressure_viscosity_coefficient: f64::NAN,
        }
    }
}

/// The table rows: quantity, value, unit.
pub fn table(o: &OperatingPoint) -> Vec<(&'static str, String, &'static str)> {
    let r = readable;
    vec![
        ("load P_T", r(o.load), "N"),
        ("angular velocity ω", r(o.angular_velocity), "rad/s"),
        ("  (in rpm)", r(o.angular_velocity / RAD_S_PER_RPM), "rpm"),
        ("sliding speed u = |ω|R", r(o.sliding_speed), "m/s"),
        ("friction coefficient μ (eq. 10)", r(o.friction_coefficient), "-"),
        ("  fluid part Q_H/P_T (eq. 3)", r(o.fluid_friction_coefficient), "-"),
        ("  asperity part μ_c/γ2 (eq. 8)", r(o.asperity_friction_coefficient), "-"),
        ("torque T = μRP_T (eq. 11)", r(o.torque), "N·m"),
        ("central film thickness h_c", r(o.film_thickness), "m"),
        ("lambda ratio h_c/√(σ²+σ_b²) (eq. 21)", r(o.lambda_ratio), "-"),
        ("minimum film thickness h_min (Pan–Hamrock)", r(o.min_film_thickness), "m"),
        ("lambda ratio h_min/√(σ²+σ_b²) (eq. 21)", r(o.min_lambda_ratio), "-"),
        ("fluid load fraction 1/γ1", r(o.fluid_load_fraction), "-"),
        ("asperity load fraction 1/γ2", r(o.asperity_load_fraction), "-"),
        ("Hertz mean pressure p_m (eq. 6)", r(o.mean_pressure), "Pa"),
        ("Hertz peak pressure p0 (eq. 6)", r(o.peak_pressure), "Pa"),
        ("contact half-width a (eq. 6)", r(o.contact_half_width), "m"),
        ("viscosity at p_m (Roelands, eq. 5)", r(o.contact_viscosity), "Pa·s"),
        ("Sommerfeld number S (eq. 20)", r(o.sommerfeld_number), "-"),
        ("regime", o.regime.as_str().to_string(), ""),
    ]
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
        let p = super::common::positive("load magnitude", cmd.load.abs(), "N")?;
        let w = omega.abs();
        let speeds = if w > 0.0 { (0.5 * w, 2.0 * w) } else { (1e-3, 1.0) };
        let mut ev = cmd.fidelity.build(&cmd.params.load()?, (0.5 * p, 2.0 * p), speeds)?;
        let e = ev.evaluate(cmd.load, omega).map_err(|e| super::error::CliError::Invalid(e.to_string()))?;
        note_fallback(&e, &ev, &Default::default());
        eprintln!("fidelity: answered by {}", e.source.as_str());
        ev.operating_point(&e)
    };
    if cmd.json {
        let text = serde_json::to_string(&PointJson::new(&op, &joint)).expect("plain struct of numbers serialises");
        return to_stdout(|w| writeln!(w, "{text}"));
    }
    let mut rows = table(&op);
    let l = joint.lubricant();
    rows.push(("lubricant temperature T", readable(l.temperature), "K"));
    rows.push(("inlet viscosity η0 at T", readable(l.viscosity), "Pa·s"));
    rows.push(("pressure-viscosity coefficient α at T", readable(l.pressure_viscosity_coefficient), "1/Pa"));
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
