//! Writing results, by one set of rules for every command:
//!
//! - an output equal to one of the command's input files (same device and inode, however the
//!   path is spelled: another name, a hard link, a symlink) is refused before anything is read
//!   or written ([`refuse_inputs`], called first by each command, and again by the writer);
//! - a regular file, or a path that does not exist yet, is replaced atomically: the content goes
//!   to a temporary file in the same directory, flushed to disk and renamed over the target only
//!   when complete; an existing file keeps its permission bits (and, where allowed, its owner);
//! - a symlink is followed: its target is written by these rules and the link stays a link;
//! - anything that is not a regular file (a FIFO, a character device such as `/dev/null`,
//!   `/dev/stdout` and other `/proc/self/fd` links) is opened and written in place, streaming;
//!   it is never removed or replaced.
//!
//! Standard output tolerates a closed pipe.

use super::common::csv_table;
use super::error::{CliError, Result};
use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// The identity of a file: (device, inode) on Unix.
#[cfg(unix)]
fn identity(meta: &fs::Metadata) -> (u64, u64) {
    use std::os::unix::fs::MetadataExt;
    (meta.dev(), meta.ino())
}

/// The metadata of an input path (`-`: whatever standard input is).
#[cfg(unix)]
fn input_metadata(input: &Path) -> Option<fs::Metadata> {
    if input.as_os_str() == "-" {
        use std::os::fd::AsFd;
        let fd = io::stdin().as_fd().try_clone_to_owned().ok()?;
        return fs::File::from(fd).metadata().ok();
    }
    fs::metadata(input).ok()
}

/// Refuse any output that is the same file as one of `inputs` (device and inode compared, so
/// any spelling of the path, a hard link or a symlink is caught). Call it before reading.
pub fn refuse_inputs(outputs: &[&Path], inputs: &[&Path]) -> Result<()> {
    #[cfg(unix)]
    for out in outputs {
        let Ok(out_meta) = fs::metadata(out) else { continue };
        for input in inputs {
            if let Some(in_meta) = input_metadata(input)
                && identity(&in_meta) == identity(&out_meta)
            {
                return Err(CliError::SameFile { output: out.to_path_buf(), input: input.to_path_buf() });
            }
        }
    }
    Ok(())
}

/// Where and how a path is written.
enum Target {
    /// Replace this regular file (or create it) atomically.
    Replace(PathBuf),
    /// Open and write in place (FIFO, device, `/proc/self/fd/N`).
    InPlace,
}

/// Follow symlinks (at most 40) to the file that is really written.
fn resolve(path: &Path) -> io::Result<Target> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        if p.starts_with("/proc") || p.starts_with("/dev/fd") {
            // /dev/stdout -> /proc/self/fd/1 -> wherever the shell pointed it: never replace.
            return Ok(Target::InPlace);
        }
        match fs::symlink_metadata(&p) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Target::Replace(p)),
            Err(e) => return Err(e),
            Ok(m) if m.file_type().is_symlink() => {
                let link = fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            Ok(m) if m.is_file() => return Ok(Target::Replace(p)),
            Ok(_) => return Ok(Target::InPlace),
        }
    }
    Err(io::Error::other("too many levels of symbolic links"))
}

/// Write `path` by the module's rules, `fill` producing the content; `inputs` are the command's
/// input files, which are never overwritten. On any error a temporary file is removed and a
/// replaced file keeps its old content.
pub fn write_atomic(path: &Path, inputs: &[&Path], fill: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<()> {
    write_atomic_send(path, inputs, |w| fill(w))
}

/// [`write_atomic`] for a `fill` that needs a writer it may send to another thread (the
/// Parquet writer's bound): the same rules.
pub fn write_atomic_send(path: &Path, inputs: &[&Path], fill: impl FnOnce(&mut (dyn Write + Send)) -> io::Result<()>) -> Result<()> {
    refuse_inputs(&[path], inputs)?;
    let werr = |source: io::Error| CliError::Write { path: path.to_path_buf(), source };
    let target = match resolve(path).map_err(werr)? {
        Target::InPlace => {
            let file = fs::OpenOptions::new().write(true).truncate(true).open(path).map_err(werr)?;
            let mut w = BufWriter::new(file);
            fill(&mut w).map_err(werr)?;
            return w.flush().map_err(werr);
        }
        Target::Replace(target) => target,
    };
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let old = fs::metadata(&target).ok();
    let mut builder = tempfile::Builder::new();
    builder.prefix(".pinjoint-").suffix(".part");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        // Like an ordinary new file: 0666 minus the umask (tempfile's default is 0600).
        builder.permissions(fs::Permissions::from_mode(0o666));
    }
    let mut tmp = builder.tempfile_in(dir).map_err(werr)?;
    #[cfg(unix)]
    if let Some(old) = &old {
        use std::os::unix::fs::MetadataExt;
        // Keep the replaced file's owner (only root may give a file away; else it is ours
        // already or the call fails harmlessly) and its permission bits (chmod ignores umask).
        let _ = std::os::unix::fs::fchown(tmp.as_file(), Some(old.uid()), Some(old.gid()));
        tmp.as_file().set_permissions(old.permissions()).map_err(werr)?;
    }
    {
        let mut early = EarlyWriteback::new(tmp.as_file_mut(), WRITEBACK_BYTES);
        {
            let mut w = BufWriter::new(&mut early);
            fill(&mut w).map_err(werr)?;
            w.flush().map_err(werr)?;
        }
        early.finish().map_err(werr)?;
    }
    tmp.as_file().sync_all().map_err(werr)?;
    tmp.persist(&target).map_err(|e| werr(e.error))?;
    Ok(())
}

/// Bytes written between two early writebacks of a large output ([`EarlyWriteback`]).
const WRITEBACK_BYTES: u64 = 8 << 20;

/// A file being written that, every `every` bytes, has a helper thread push what was written
/// so far to the disk (`fdatasync` on a duplicate of its handle) while the command goes on:
/// the final `sync_all` of [`write_atomic`] then waits for the last few MiB only, not for a
/// whole large output (a million-row sweep's 340 MB took 0.15-0.2 s alone). A writeback
/// still running is not waited for: the next one is skipped. An error of the helper's is
/// returned by [`EarlyWriteback::finish`] (it may be the only report of a failed write).
struct EarlyWriteback<'a> {
    file: &'a mut fs::File,
    every: u64,
    /// Bytes written since the last writeback was asked for.
    since: u64,
    helper: Option<(std::sync::mpsc::SyncSender<()>, std::thread::JoinHandle<io::Result<()>>)>,
}

impl<'a> EarlyWriteback<'a> {
    fn new(file: &'a mut fs::File, every: u64) -> Self {
        Self { file, every, since: 0, helper: None }
    }

    /// Ask the helper (started the first time) for a writeback, unless one is running.
    fn ask(&mut self) {
        if self.helper.is_none() {
            // Without a duplicate handle or a thread, the final sync does it all (as before).
            let Ok(dup) = self.file.try_clone() else { return };
            let (tx, rx) = std::sync::mpsc::sync_channel::<()>(1);
            let spawned = std::thread::Builder::new().name("writeback".into()).spawn(move || -> io::Result<()> {
                for () in rx {
                    dup.sync_data()?;
                }
                Ok(())
            });
            let Ok(handle) = spawned else { return };
            self.helper = Some((tx, handle));
        }
        if let Some((tx, _)) = &self.helper {
            let _ = tx.try_send(());
        }
    }

    /// Stop the helper, waiting for its writeback; its error if it had one.
    fn finish(mut self) -> io::Result<()> {
        match self.helper.take() {
            Some((tx, handle)) => {
                drop(tx);
                handle.join().unwrap_or_else(|_| Err(io::Error::other("the writeback thread panicked")))
            }
            None => Ok(()),
        }
    }
}

impl Write for EarlyWriteback<'_> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = self.file.write(buf)?;
        self.since += n as u64;
        if self.since >= self.every {
            self.since = 0;
            self.ask();
        }
        Ok(n)
    }
    fn flush(&mut self) -> io::Result<()> {
        self.file.flush()
    }
}

/// Write a whole text file by the rules of [`write_atomic`].
pub fn write_text(path: &Path, inputs: &[&Path], text: &str) -> Result<()> {
    write_atomic(path, inputs, |w| w.write_all(text.as_bytes()))
}

/// Write a CSV table ([`crate::common::csv_table`]: `header`, then `rows`) to `path` by the
/// rules of [`write_atomic`].
pub fn write_csv<H, R>(path: &Path, inputs: &[&Path], header: H, rows: impl IntoIterator<Item = R>) -> Result<()>
where
    H: IntoIterator,
    H::Item: AsRef<[u8]>,
    R: IntoIterator,
    R::Item: AsRef<[u8]>,
{
    write_atomic(path, inputs, |w| csv_table(w, header, rows))
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

/// The optional input file as a list for [`write_atomic`].
pub fn inputs_of(path: Option<&PathBuf>) -> Vec<&Path> {
    path.map(|p| vec![p.as_path()]).unwrap_or_default()
}

/// Refuse, before anything is read, a command whose output directory `dir` would receive one
/// of the files `names` that is the same file as its optional input `input`.
pub fn refuse_files(dir: &Path, names: &[&str], input: Option<&PathBuf>) -> Result<()> {
    let outs: Vec<PathBuf> = names.iter().map(|n| dir.join(n)).collect();
    let outs: Vec<&Path> = outs.iter().map(PathBuf::as_path).collect();
    refuse_inputs(&outs, &inputs_of(input))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every byte reaches the file in order through [`EarlyWriteback`], whatever the sizes of
    /// the writes against its period; the helper starts once the period is passed (not before)
    /// and `finish` waits for it.
    #[test]
    fn early_writeback_keeps_every_byte() {
        for (every, piece, pieces) in [(1000u64, 7usize, 3usize), (1000, 100, 50), (1000, 1000, 4), (64, 5000, 3), (1 << 20, 100, 20)] {
            let mut file = tempfile::tempfile().unwrap();
            let want: Vec<u8> = (0..piece * pieces).map(|i| (i * 31 % 251) as u8).collect();
            let mut early = EarlyWriteback::new(&mut file, every);
            for p in want.chunks(piece) {
                early.write_all(p).unwrap();
            }
            let started = early.helper.is_some();
            assert_eq!(started, (piece * pieces) as u64 >= every, "every {every}, {pieces} writes of {piece}");
            early.finish().unwrap();
            let mut got = Vec::new();
            use std::io::{Read, Seek};
            file.rewind().unwrap();
            file.read_to_end(&mut got).unwrap();
            assert_eq!(got, want);
        }
    }
}
