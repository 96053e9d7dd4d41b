//! The report's files: created directories, whole files replaced at once (a reader never sees
//! half a BENCHMARKS.md), and the `wrote PATH` lines.

use super::bench_error::{BenchError, Result};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Create the output directory (and its parents) if needed.
pub fn output_dir(dir: &Path) -> Result<PathBuf> {
    std::fs::create_dir_all(dir).map_err(|source| BenchError::Write { path: dir.to_path_buf(), source })?;
    Ok(dir.to_path_buf())
}

/// Write `text` to `path` through a temporary file in the same directory, renamed over it:
/// the old file stays whole until the new one is.
pub fn write_text(path: &Path, text: &str) -> Result<()> {
    let werr = |source: io::Error| BenchError::Write { path: path.to_path_buf(), source };
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".pinjoint-bench-").suffix(".part");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // Like an ordinary new file: 0666 minus the umask (tempfile's default is 0600).
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut tmp = builder.tempfile_in(dir).map_err(werr)?;
    tmp.write_all(text.as_bytes()).map_err(werr)?;
    tmp.as_file().sync_all().map_err(werr)?;
    tmp.persist(path).map_err(|e| werr(e.error))?;
    Ok(())
}

/// Tell the user which files were written (one `wrote PATH` line each, on standard output).
pub fn report_written(paths: &[PathBuf]) -> Result<()> {
    let out = io::stdout();
    let mut w = out.lock();
    paths.iter().try_for_each(|p| writeln!(w, "wrote {}", p.display())).and_then(|()| w.flush()).map_err(BenchError::Stdout)
}
