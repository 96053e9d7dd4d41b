//! `pinjoint cycle`: whole articulation strokes on the simulated rig (the paper's Figures 7,
//! 11–13): the trace as CSV, torque against time and angle as SVG, and the paper's
//! cycle-average friction coefficient (eq. 11).
//!
//! This folder holds the command and its part [`stream`], a rig simulation streamed to the CSV
//! with bounded memory. One rig simulation with its averages and CSV columns
//! ([`crate::rig_run`]) and its SVG charts ([`crate::rig_plots`]) are the crate's, shared with
//! `pinjoint figures`. This file holds the command's arguments and [`run`].

pub mod stream;

use crate::common::{load_rig_config, positive, readable, RAD_S_PER_RPM};
use crate::rig_plots::{torque_angle_svg, torque_time_svg};
use crate::rig_run::{default_skip, CycleRun};
use self::stream::stream_cycles;
use crate::error::{CliError, Result};
use crate::fidelity_args::{describe, FidelityArgs};
use crate::output::{inputs_of, output_dir, refuse_files, report_written, to_stdout, write_atomic, write_text};
use clap::{Args, ValueEnum};
use pinjoint::rig::{Formulation, Method, RigConfig};
use pinjoint::Joint;
use std::path::PathBuf;

#[derive(Args, Debug)]
#[command(
    about = "Simulate whole strokes on the paper's torsion-actuator rig (Figures 7, 11-13): CSV, SVG, eq. 11 average",
    long_about = "Swing the pin through sine strokes θ_cmd = A·sin(2πft) on the simulated rig (servo-hydraulic \
torsional actuator in angle control, stick at reversal, the friction core at each speed) and write:\n  \
DIR/cycle.csv         every sample: time [s], command_angle [rad], angle [rad], angular_velocity [rad/s], \
torque [N·m] (the actuator's transducer), friction_torque [N·m] (on the pin, signed), \
friction_coefficient [-] (the core's μ(P,|ω|)), film_thickness [m] (h_c), fluid_load_fraction [-] (1/γ1), \
stuck [0/1]\n  \
DIR/torque_time.svg   recorded torque against time (Figures 11-13), the core's quasi-static torque dashed \
(beyond 100,000 samples, every k-th sample is drawn)\n  \
DIR/torque_angle.svg  recorded torque against the pin angle over the averaged cycles (Figure 7d)\n\
and print the cycle-average friction coefficient the paper's way (section 5, eq. 11: mean |torque| over \
whole cycles divided by R·P), leaving out the first (start-up) stroke when there is more than one, \
beside the core's quasi-static μ at the stroke's peak speed 2πfA.\n\
The run starts from rest at θ = 0 at t = 0. Rig constants come from the [rig] section of --params \
(`pinjoint params --rig` prints a complete file to start from); the flags override the file.\n\n\
Examples:\n  \
pinjoint cycle --frequency 1 --amplitude 40 --load 20000 --cycles 3 --output out/1Hz\n  \
pinjoint cycle --frequency 0.03 --amplitude 40 --load 60000 --cycles 2 --method dop853 --output out/slow"
)]
/// Arguments of `pinjoint cycle` (its `--help` text is the `#[command]` attribute's).
// The field docs are the --help text, where `[rig]`/`[lubricant]` name TOML sections, not
// intra-doc links; rewording them would change --help.
#[allow(rustdoc::broken_intra_doc_links)]
pub struct CycleCmd {
    /// Stroke frequency f, in Hz [default: the file's rig.frequency, else 1 Hz]
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub frequency: Option<f64>,
    /// Stroke amplitude A, in degrees (±A) [default: the file's rig.amplitude, else 40°]
    #[arg(long, value_name = "DEG", allow_negative_numbers = true)]
    pub amplitude: Option<f64>,
    /// Radial load P on the pin, in N; its magnitude is used (|P| > 0) [default: the file's rig.load, else 20000 N]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub load: Option<f64>,
    /// Number of whole strokes to simulate (>= 1)
    #[arg(long, value_name = "COUNT", default_value_t = 3)]
    pub cycles: usize,
    /// Strokes left out of the average at the start [default: 1 if --cycles >= 2, else 0]
    #[arg(long, value_name = "COUNT")]
    pub skip_cycles: Option<usize>,
    /// Samples written per stroke (>= 8)
    #[arg(long, value_name = "COUNT", default_value_t = 2000)]
    pub samples_per_cycle: usize,
    /// Stick/slip hybrid system, or one smooth regularised ODE [default: the file's, else hybrid]
    #[arg(long, value_enum)]
    pub formulation: Option<FormulationArg>,
    /// ODE integrator [default: the file's, else dopri5]
    #[arg(long, value_enum)]
    pub method: Option<MethodArg>,
    /// Parameter file (TOML): the model's sections and [rig], any subset of keys
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// Output directory (created if needed)
    #[arg(long, value_name = "DIR")]
    pub output: PathBuf,
    /// Lubricant temperature, in K (overrides the file's [lubricant] temperature; η0 and α
    /// follow Roelands' temperature relation from [lubricant] reference_temperature)
    #[arg(long, value_name = "K", allow_negative_numbers = true)]
    pub temperature: Option<f64>,
    /// Friction fidelity (table/boundary/auto over the envelope, by default the stroke's:
    /// load ±10 %, 1e-3 rad/s to twice the peak command speed; slower speeds near reversals
    /// fall back to the full solve)
    #[command(flatten)]
    pub fidelity: FidelityArgs,
}

/// `--formulation`: how stick at stroke reversal is modelled (see
/// [`pinjoint::rig::Formulation`]).
#[derive(Debug, Clone, Copy, ValueEnum)]
// Variant docs would become the possible values' help in `pinjoint cycle --help` (clap's
// ValueEnum), changing its text; the values are named after the `pinjoint::rig` types.
#[allow(missing_docs)]
pub enum FormulationArg {
    Hybrid,
    Regularised,
}

/// `--method`: the ODE integrator of the rig (see [`pinjoint::rig::Method`]).
#[derive(Debug, Clone, Copy, ValueEnum)]
// Variant docs would become the possible values' help in `pinjoint cycle --help` (clap's
// ValueEnum), changing its text; the values are named after the `pinjoint::rig` types.
#[allow(missing_docs)]
pub enum MethodArg {
    Dopri5,
    Dop853,
    Rk4,
    Dopri5Dense,
}

/// Most strokes and samples one run may compute (the samples are streamed to cycle.csv; at
/// most [`stream::PLOT_SAMPLES`] are kept for the plots).
pub const MAX_CYCLES: usize = 100_000;
/// Most samples one run may write (see [`MAX_CYCLES`]).
pub const MAX_SAMPLES: usize = 20_000_000;

/// The configuration of this run: the file, overridden by the flags, validated.
fn config(cmd: &CycleCmd) -> Result<RigConfig> {
    let mut cfg = load_rig_config(cmd.params.as_ref())?;
    if let Some(f) = cmd.frequency {
        cfg.rig.frequency = positive("frequency", f, "Hz")?;
    }
    if let Some(a) = cmd.amplitude {
        if !(a.is_finite() && a >= 0.0) {
            return Err(CliError::Invalid(format!("amplitude = {a} deg is invalid: it must be a finite number >= 0 deg")));
        }
        cfg.rig.amplitude = a.to_radians();
    }
    if let Some(p) = cmd.load {
        cfg.rig.load = positive("load magnitude", p.abs(), "N")?;
    }
    crate::common::set_temperature(&mut cfg.model, cmd.temperature)?;
    if let Some(m) = cmd.formulation {
        cfg.rig.formulation = match m {
            FormulationArg::Hybrid => Formulation::Hybrid,
            FormulationArg::Regularised => Formulation::Regularised,
        };
    }
    if let Some(m) = cmd.method {
        cfg.rig.method = match m {
            MethodArg::Dopri5 => Method::Dopri5,
            MethodArg::Dop853 => Method::Dop853,
            MethodArg::Rk4 => Method::Rk4,
            MethodArg::Dopri5Dense => Method::Dopri5Dense,
        };
    }
    if cfg.rig.load <= 0.0 {
        return Err(CliError::Invalid(format!(
            "load = {} N is invalid: the cycle-average friction coefficient needs a load > 0 N",
            cfg.rig.load
        )));
    }
    cfg.validate()?;
    Ok(cfg)
}

/// Stroke and sample counts: (cycles, skip, samples per cycle).
fn counts(cmd: &CycleCmd) -> Result<(usize, usize, usize)> {
    let n = cmd.cycles;
    if !(1..=MAX_CYCLES).contains(&n) {
        return Err(CliError::Invalid(format!("cycles = {n} is invalid: it must be between 1 and {MAX_CYCLES}")));
    }
    let skip = cmd.skip_cycles.unwrap_or_else(|| default_skip(n));
    if skip >= n {
        return Err(CliError::Invalid(format!("skip-cycles = {skip} is invalid: it must be < cycles = {n}")));
    }
    let k = cmd.samples_per_cycle;
    if k < 8 || k.saturating_mul(n) > MAX_SAMPLES {
        return Err(CliError::Invalid(format!(
            "samples-per-cycle = {k} is invalid: it must be >= 8, and cycles × samples-per-cycle <= {MAX_SAMPLES}"
        )));
    }
    Ok((n, skip, k))
}

/// Runs `pinjoint cycle`: simulates the strokes, streams cycle.csv, draws the plots and prints
/// the eq. 11 cycle-average friction coefficient. Fails on invalid flags or parameters, or when
/// the rig simulation cannot go on.
pub fn run(cmd: &CycleCmd) -> Result<()> {
    refuse_files(&cmd.output, &["cycle.csv", "torque_time.svg", "torque_angle.svg"], cmd.params.as_ref())?;
    let cfg = config(cmd)?;
    let (cycles, skip, per_cycle) = counts(cmd)?;
    let joint = Joint::new(&cfg.model)?;
    let mut sim = pinjoint::rig::RigSim::new(&cfg)?;
    if !cmd.fidelity.is_full()? {
        let d = pinjoint::rig::RigSim::drive_envelope(&cfg)?;
        let env = cmd.fidelity.envelope((d.load_min, d.load_max), (d.speed_min, d.speed_max))?;
        eprintln!("{}", describe(sim.set_fidelity(cmd.fidelity.level()?, cmd.fidelity.tolerance, env)?));
    }
    let dir = output_dir(&cmd.output)?;
    let paths = [dir.join("cycle.csv"), dir.join("torque_time.svg"), dir.join("torque_angle.svg")];
    let inputs = inputs_of(cmd.params.as_ref());
    // The samples go to cycle.csv as they are computed (memory independent of the strokes);
    // a simulation error is kept here and returned as itself (the file is then not written).
    let mut failure: Option<CliError> = None;
    let mut streamed: Option<CycleRun> = None;
    let written = write_atomic(&paths[0], &inputs, |w| match stream_cycles(&mut sim, &cfg, (cycles, per_cycle, skip), w) {
        Ok(r) => {
            streamed = Some(r);
            Ok(())
        }
        Err(e) => {
            let message = e.to_string();
            failure = Some(e);
            Err(std::io::Error::other(message))
        }
    });
    if let Some(e) = failure {
        return Err(e);
    }
    written?;
    let run = streamed.ok_or_else(|| CliError::Invalid("cycle: the simulation did not run".into()))?;
    if let Some(ev) = sim.fidelity() {
        let n = sim.stats().fallbacks;
        if n > 0 {
            eprintln!(
                "fidelity: {n} friction evaluations fell outside the envelope (e.g. speeds below {} rad/s around reversals) \
                 and were answered by the full solve",
                ev.envelope().speed_min
            );
        }
    }
    let peak = run.peak_command_speed();
    let mu_peak = run.quasi_static_at_peak(&joint)?;
    let (time_svg, angle_svg) = (torque_time_svg(&run)?, torque_angle_svg(&run)?);
    write_text(&paths[1], &inputs, &time_svg)?;
    write_text(&paths[2], &inputs, &angle_svg)?;
    report_written(&paths)?;
    to_stdout(|w| {
        writeln!(
            w,
            "cycle-average friction coefficient (eq. 11: mean |torque| over cycles {}-{} / (R·P)): {:?}",
            skip + 1,
            cycles,
            run.average_friction_coefficient
        )?;
        writeln!(
            w,
            "quasi-static core friction coefficient at the stroke's peak speed {} rad/s ({} rpm): {}",
            readable(peak),
            readable(peak / RAD_S_PER_RPM),
            readable(mu_peak)
        )?;
        writeln!(w, "mean |ω| over those cycles: {} rad/s", readable(run.mean_speed))
    })
}
