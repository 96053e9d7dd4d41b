//! The `pinjoint` command line. The binary (`src/main.rs`) only calls [`main`]; this library
//! page is the command line's API documentation (the binary has none of its own: see
//! `docs/cli.md`).
//!
//! Layout:
//! - [`commands`]: one module per subcommand, a file for a single-file command
//!   (`commands/point.rs`) and a folder for one with parts (`commands/figures/`,
//!   `commands/cycle/`, `commands/sweep/`, `commands/calibrate/`, each with its command in
//!   `mod.rs` and its parts beside it);
//! - the pieces the commands share, at the top level (a command never imports another
//!   command: `tests/commands_independent.rs`): [`exact`] (round-trip numbers for CSV),
//!   [`numbers`] (numbers for people), [`plot`] (SVG charts, the crate `pinjoint-plot`),
//!   [`error`] (the commands' error type), [`common`] (the `--params` flag, speed flags, the
//!   CSV result columns, the rig's operating region), [`output`] (the rules every output file
//!   follows), [`fidelity_args`] (the `--fidelity` and envelope flags of `point` and `sweep`),
//!   [`curves`] (the speed sweeps, and the paper's Figures 3 and 4 that `stribeck`, `map` and
//!   `figures` write), [`rig_run`] (one rig simulation of whole strokes and its averages) and
//!   [`rig_plots`] (its charts), both used by `cycle` and `figures`;
//! - this file: the parsed arguments ([`Cli`], [`Command`]) and the dispatch ([`run`],
//!   [`main`]).
//!
//! A new subcommand is a module in [`commands`] and a variant of [`Command`]; a new figure of
//! `pinjoint figures` is a module in [`commands::figures`].

// In dependency order: each module uses only those above it (tests/module_graph.py).
// Shared pieces:
pub mod exact;
pub mod numbers;
/// SVG charts: the crate `pinjoint-plot` (axes, line charts, heat maps).
pub use pinjoint_plot as plot;
pub mod error;
pub mod common;
pub mod output;
pub mod columnar;
pub mod fidelity_args;
pub mod curves;
pub mod rig_run;
pub mod rig_plots;
// The subcommands:
pub mod commands;

use commands::{calibrate, cycle, figures, map, params, point, ranges, stribeck, sweep};
use clap::{Parser, Subcommand};
use std::process::ExitCode;

const LONG_ABOUT: &str = "\
Frictional torque of a grease-lubricated aircraft landing-gear pin joint: the mixed-lubrication \
model of the paper (Greenwood-Williamson asperity contact + Moes EHL film, load shared through \
γ1 and γ2), evaluated at any load and speed.

All inputs and outputs are SI (N, rad/s, m, Pa, N·m) unless a flag names another unit (--rpm). \
Model parameters default to the paper's rig (Tables 1-3, μ_c = 0.12); change them with a TOML \
file passed as --params (start from `pinjoint params`).

Examples:
  pinjoint figures --output figures/                the paper's figures 3, 4, 7-13 and an index.html
  pinjoint point --load 20000 --rpm 10              one operating point, as a table
  pinjoint point --load 20000 --speed 1.05 --json   the same as JSON
  pinjoint sweep --input pts.csv --output out.csv   many points (columns load,speed) in parallel
  pinjoint stribeck --load 20000 --output out/      the paper's Figure 3 (CSV + SVG)
  pinjoint map --output out/                        the paper's Figure 4 (CSV + SVG)
  pinjoint cycle --frequency 1 --amplitude 40 --load 20000 --cycles 3 --output out/
                                                    rig strokes (Figures 7, 11-13), eq. 11 average
  pinjoint calibrate --input rec.csv --output out/  fit μ_c to measured torque cycles (95 % intervals)
  pinjoint params > joint.toml                      a parameter file to edit
  pinjoint ranges                                   the declared ranges: checked, past the assumptions, refused

Run `pinjoint <command> --help` for each command's details.";

/// The `pinjoint` command line: the parsed arguments (its `--help` text is set by the
/// `#[command]` attributes, which take precedence over this comment).
#[derive(Parser, Debug)]
#[command(name = "pinjoint", version, about = "Friction torque of a grease-lubricated landing-gear pin joint (mixed lubrication)", long_about = LONG_ABOUT)]
pub struct Cli {
    /// The subcommand to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands; each variant holds its command's arguments and help text.
#[derive(Subcommand, Debug)]
// A variant's doc comment would replace its command's `about`/`long_about` in `--help`
// (clap applies it after the struct's); each command is documented on its struct instead.
#[allow(missing_docs)]
pub enum Command {
    Params(params::ParamsCmd),
    Ranges(ranges::RangesCmd),
    Point(point::PointCmd),
    Sweep(sweep::SweepCmd),
    Stribeck(stribeck::StribeckCmd),
    Map(map::MapCmd),
    Cycle(cycle::CycleCmd),
    Figures(figures::FiguresCmd),
    Calibrate(calibrate::CalibrateCmd),
}

/// Runs the parsed command; the error is what [`main`] prints.
pub fn run(cli: &Cli) -> error::Result<()> {
    match &cli.command {
        Command::Params(c) => params::run(c),
        Command::Ranges(c) => ranges::run(c),
        Command::Point(c) => point::run(c),
        Command::Sweep(c) => sweep::run(c),
        Command::Stribeck(c) => stribeck::run(c),
        Command::Map(c) => map::run(c),
        Command::Cycle(c) => cycle::run(c),
        Command::Figures(c) => figures::run(c),
        Command::Calibrate(c) => calibrate::run(c),
    }
}

/// Parse, run, report: exit 0 on success, 1 on an error (printed as `error: ...`),
/// 2 on a usage error (clap's message).
///
/// No message is longer than about [`pinjoint::fmt::MESSAGE_CHARS`] characters: clap's own
/// usage errors quote the argument, which may be 128 KiB long, and are cut as the
/// command's errors are ([`pinjoint::fmt::bounded_message`]).
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if matches!(e.kind(), clap::error::ErrorKind::DisplayHelp | clap::error::ErrorKind::DisplayVersion) => e.exit(),
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => e.exit(),
        Err(e) => {
            eprint!("{}", pinjoint::fmt::bounded_message(&e.render().to_string()));
            return ExitCode::from(2);
        }
    };
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", pinjoint::fmt::bounded_message(&pinjoint::fmt::short_numbers(&e.to_string())));
            ExitCode::FAILURE
        }
    }
}
