//! The command line's errors: each names the quantity, the value and the unit, or the
//! file and line, so the user can fix the input without reading the source.

use crate::plot::PlotError;
use pinjoint::fidelity::FidelityError;
use pinjoint::rig::RigError;
use pinjoint::{ModelError, ParamError};
use std::io;
use std::path::PathBuf;
use thiserror::Error;

/// Everything a `pinjoint` command can fail with; [`crate::main`] prints it as `error: ...` and
/// exits 1.
#[derive(Debug, Error)]
pub enum CliError {
    /// An input file (`path`) could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: io::Error,
    },
    /// An output file (`path`) could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: io::Error,
    },
    /// An output path names one of the command's input files (checked by device and inode).
    #[error("output {output} is the input file {input}: refusing to overwrite it (nothing was read or written)")]
    SameFile {
        /// The output path as given.
        output: PathBuf,
        /// The input file it names.
        input: PathBuf,
    },
    /// The parameter file `path` (--params) is not valid TOML or holds invalid values.
    #[error("parameter file {path}: {source}")]
    ParamFile {
        /// The parameter file.
        path: PathBuf,
        /// What is wrong in it.
        source: ParamError,
    },
    /// The parameters (without a file, e.g. after --temperature) are invalid.
    #[error("{0}")]
    Params(#[from] ParamError),
    /// The model could not be evaluated at an operating point (e.g. a non-positive load).
    #[error("{0}")]
    Model(#[from] ModelError),
    /// A bad row or header of an input file; `line` is 1-based, counting every line.
    #[error("{file}, line {line}: {message}")]
    Input {
        /// The input file's name as given (`-` for standard input).
        file: String,
        /// 1-based line number of the bad row.
        line: u64,
        /// What is wrong with the row.
        message: String,
    },
    /// A flag value outside its allowed range.
    #[error("{0}")]
    Invalid(String),
    /// A fidelity flag (--fidelity, --tolerance, the envelope) the library refuses, or a point
    /// a fidelity level cannot evaluate.
    #[error("{0}")]
    Fidelity(#[from] FidelityError),
    /// A scene (`figures`' cold-day scene) that could not be set up.
    #[error("{0}")]
    Scene(#[from] pinjoint::scene::SceneError),
    /// An SVG chart could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A rig simulation (`cycle`, `figures`) that could not go on.
    #[error("rig simulation: {0}")]
    Rig(#[from] RigError),
    /// Standard output could not be written; a broken pipe is not reported (see
    /// [`CliError::is_broken_pipe`]).
    #[error("writing to standard output: {0}")]
    Stdout(io::Error),
}

impl CliError {
    /// True when the reader of our standard output went away (e.g. `| head`): not an error.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, CliError::Stdout(e) if e.kind() == io::ErrorKind::BrokenPipe)
    }
}

/// The result of every command-line operation.
pub type Result<T> = std::result::Result<T, CliError>;
