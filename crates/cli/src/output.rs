//! Writing results: files appear complete or not at all (temp file in the same directory,
//! renamed on success), and standard output tolerates a closed pipe.

use super::error::{CliError, Result};
use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Write `path` atomically: `fill` writes into a temporary file beside it, which is renamed
/// onto `path` only if `fill` and the flush succeed. On any error the temporary file is removed.
pub fn write_atomic(path: &Path, fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<()> {
    let werr = |source: io::Error| CliError::Write { path: path.to_path_buf(), source };
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".pinjoint-").suffix(".part");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // Like an ordinary file: 0666 minus the umask (tempfile's default is 0600).
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    let mut tmp = builder.tempfile_in(dir).map_err(werr)?;
    {
        let mut w = BufWriter::new(tmp.as_file_mut());
        fill(&mut w).map_err(werr)?;
        w.flush().map_err(werr)?;
    }
    tmp.persist(path).map_err(|e| werr(e.error))?;
    Ok(())
}

/// Write a whole text file atomically.
pub fn write_text(path: &Path, text: &str) -> Result<()> {
    write_atomic(path, |w| w.write_all(text.as_bytes()))
}

/// Create the output directory (and its parents) if needed.
pub fn output_dir(dir: &Path) -> Result<PathBuf> {
    fs::create_dir_all(dir).map_err(|source| CliError::Write { path: dir.to_path_buf(), source })?;
    Ok(dir.to_path_buf())
}

/// Write to standard output through a buffer; a closed pipe ends quietly (see `CliError::is_broken_pipe`).
pub fn to_stdout(fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<()> {
    let out = io::stdout();
    let mut w = BufWriter::new(out.lock());
    fill(&mut w).map_err(CliError::Stdout)?;
    w.flush().map_err(CliError::Stdout)
}

/// Tell the user which files were written (one `wrote PATH` line each, on standard output).
pub fn report_written(paths: &[PathBuf]) -> Result<()> {
    to_stdout(|w| paths.iter().try_for_each(|p| writeln!(w, "wrote {}", p.display())))
}
