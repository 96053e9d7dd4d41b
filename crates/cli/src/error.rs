//! The command line's errors: each names the quantity, the value and the unit, or the
//! file and line, so the user can fix the input without reading the source.

use crate::plot::PlotError;
use pinjoint::rig::RigError;
use pinjoint::{ModelError, ParamError};
use std::io;
use std::path::PathBuf;
use thiserror::Error;

#[derive(Debug, Error)]
pub enum CliError {
    #[error("cannot read {path}: {source}")]
    Read { path: PathBuf, source: io::Error },
    #[error("cannot write {path}: {source}")]
    Write { path: PathBuf, source: io::Error },
    /// An output path names one of the command's input files (checked by device and inode).
    #[error("output {output} is the input file {input}: refusing to overwrite it (nothing was read or written)")]
    SameFile { output: PathBuf, input: PathBuf },
    #[error("parameter file {path}: {source}")]
    ParamFile { path: PathBuf, source: ParamError },
    #[error("{0}")]
    Params(#[from] ParamError),
    #[error("{0}")]
    Model(#[from] ModelError),
    /// A bad row or header of an input file; `line` is 1-based, counting every line.
    #[error("{file}, line {line}: {message}")]
    Input { file: String, line: u64, message: String },
    /// A flag value outside its allowed range.
    #[error("{0}")]
    Invalid(String),
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A rig simulation (`cycle`, `figures`) that could not go on.
    #[error("rig simulation: {0}")]
    Rig(#[from] RigError),
    #[error("writing to standard output: {0}")]
    Stdout(io::Error),
}

impl CliError {
    /// True when the reader of our standard output went away (e.g. `| head`): not an error.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, CliError::Stdout(e) if e.kind() == io::ErrorKind::BrokenPipe)
    }
}

pub type Result<T> = std::result::Result<T, CliError>;
