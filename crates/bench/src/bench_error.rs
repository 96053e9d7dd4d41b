//! [`ThroughputError`]: why the throughput section (the `pinjoint sweep` process, the library
//! per point, the SciPy reference) could not be measured. The report prints it as the reason
//! ("not measured (…)"); the rest of the benchmark goes on.

use std::path::PathBuf;

/// Why a throughput measurement, or the SciPy reference within it, could not be made.
#[derive(Debug, thiserror::Error)]
pub enum ThroughputError {
    /// The path of this executable is unknown (the `pinjoint` binary is looked for beside it).
    #[error("own executable: {0}")]
    OwnExecutable(#[source] std::io::Error),
    /// The `pinjoint` binary of the same build is not beside `pinjoint-bench`.
    #[error("{} not found: build it with `cargo build --release`", .0.display())]
    NoPinjoint(PathBuf),
    /// A sweep input file could not be written.
    #[error("writing {}: {source}", path.display())]
    Write {
        /// The CSV file.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A program (`pinjoint`, Python) could not be started.
    #[error("running {}: {source}", program.display())]
    Spawn {
        /// The executable.
        program: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// `pinjoint sweep` ran but did not exit with status 0 (its stderr is not kept).
    #[error("pinjoint sweep over {rows} rows failed (status {status})")]
    Sweep {
        /// Rows of the input.
        rows: usize,
        /// The raw `wait4` status word.
        status: i32,
    },
    /// `pinjoint calibrate` ran but did not exit with status 0 or printed no JSON (status -2).
    #[error("pinjoint calibrate over {rows} rows failed (status {status})")]
    Calibrate {
        /// Rows of the record.
        rows: usize,
        /// The raw `wait4` status word (-2: unreadable JSON).
        status: i32,
    },
    /// The library rejected its default parameters.
    #[error(transparent)]
    Params(#[from] pinjoint::ParamError),
    /// `benches/scipy_reference.py` is neither under the current folder nor the crate's.
    #[error("benches/scipy_reference.py not found")]
    NoScipyScript,
    /// The `--python` interpreter does not exist.
    #[error("no Python at {}", .0.display())]
    NoPython(PathBuf),
    /// The SciPy script ran and failed: the last line of its stderr.
    #[error("{} failed: {stderr_tail}", script.display())]
    Scipy {
        /// The script.
        script: PathBuf,
        /// The last line of its stderr (a Python exception's message), or empty.
        stderr_tail: String,
    },
    /// The SciPy script's stdout is not JSON.
    #[error("unreadable output of {}: {source}", script.display())]
    ScipyOutput {
        /// The script.
        script: PathBuf,
        /// The JSON parser's error.
        source: serde_json::Error,
    },
}

#[cfg(test)]
mod tests {
    use super::ThroughputError;
    use std::path::PathBuf;

    /// The reasons read as they did when they were strings (the report prints them).
    #[test]
    fn reasons_read_as_before() {
        assert_eq!(ThroughputError::NoPython(PathBuf::from("/nonexistent")).to_string(), "no Python at /nonexistent");
        assert_eq!(ThroughputError::Sweep { rows: 10_000, status: 256 }.to_string(), "pinjoint sweep over 10000 rows failed (status 256)");
        let e = ThroughputError::Scipy { script: PathBuf::from("benches/scipy_reference.py"), stderr_tail: "ImportError: no scipy".into() };
        assert_eq!(e.to_string(), "benches/scipy_reference.py failed: ImportError: no scipy");
        let e = ThroughputError::NoPinjoint(PathBuf::from("/t/pinjoint"));
        assert_eq!(e.to_string(), "/t/pinjoint not found: build it with `cargo build --release`");
        let source = std::io::Error::from(std::io::ErrorKind::PermissionDenied);
        let expected = format!("writing /t/in.csv: {source}");
        assert_eq!(ThroughputError::Write { path: PathBuf::from("/t/in.csv"), source }.to_string(), expected);
    }
}

/// What ends a benchmark run ([`crate::main`] prints it as `error: ...` and exits 1); the
/// sections that can go unmeasured say so in the report instead ([`ThroughputError`]).
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// An output file or directory (`path`) could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// The file or directory.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// Standard output could not be written (a closed pipe ends the run quietly).
    #[error("cannot write to standard output: {0}")]
    Stdout(#[source] std::io::Error),
    /// A plot could not be rendered.
    #[error(transparent)]
    Plot(#[from] pinjoint_plot::PlotError),
    /// Anything else, said in words.
    #[error("{0}")]
    Invalid(String),
}

impl BenchError {
    /// True for a write to a closed standard output (`pinjoint-bench ... | head`).
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, BenchError::Stdout(e) if e.kind() == std::io::ErrorKind::BrokenPipe)
    }
}

/// The benchmark's result type.
pub type Result<T> = std::result::Result<T, BenchError>;
