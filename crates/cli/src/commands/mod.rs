//! The subcommands of `pinjoint`, one module each: a file for a command that fits in one
//! ([`params`], [`ranges`], [`point`], [`stribeck`], [`map`]), a folder for one with parts ([`sweep`],
//! [`cycle`], [`calibrate`], [`figures`]: the command in its `mod.rs`, each part in a file
//! beside it). Every command module holds its clap arguments (`…Cmd`, whose doc comments and
//! `#[command]` attributes are its `--help`) and its `run`; the pieces they share (parameter
//! files, output files, numbers, plots, the Figure 3 and 4 writers, a rig run) are the crate's
//! top-level modules or the library's. A command never imports another command
//! (`tests/commands_independent.rs` checks it).
//!
//! A new command is a new module here (a file, or a folder once it has parts), plus a variant
//! of [`crate::Command`] and its arm in [`crate::run`].

// Independent of each other (tests/commands_independent.rs), listed as `pinjoint --help` lists them.
pub mod params;
pub mod ranges;
pub mod point;
pub mod sweep;
pub mod stribeck;
pub mod map;
pub mod cycle;
pub mod calibrate;
pub mod figures;
