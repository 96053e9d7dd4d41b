//! Running the `pinjoint` binary as a user would, for the CLI test suites (cli.rs,
//! cli_adversarial.rs, cli_cycle.rs, cli_calibrate.rs, ...): every run has a time limit, must
//! exit (not be killed by a signal) and must not panic (exit code 101 or "panicked" on
//! standard error).
#![allow(dead_code)]

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What a run printed and its exit code.
pub struct Out {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// The time limit of [`run`] and [`run_with`].
pub const LIMIT: Duration = Duration::from_secs(120);

/// Run the binary with `stdin` as its standard input (none: an empty one) and a time limit
/// (killed and failed beyond it).
pub fn run_limited(args: &[&str], stdin: Option<&str>, limit: Duration) -> Out {
    let mut child = Command::new(env!("CARGO_BIN_EXE_pinjoint"))
        .args(args)
        .stdin(if stdin.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let read = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = String::new();
            r.read_to_string(&mut s).ok();
            s
        })
    };
    let ho = read(Box::new(child.stdout.take().unwrap()));
    let he = read(Box::new(child.stderr.take().unwrap()));
    if let Some(text) = stdin {
        let mut input = child.stdin.take().unwrap();
        input.write_all(text.as_bytes()).unwrap();
    }
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > limit {
            child.kill().ok();
            child.wait().ok();
            panic!("{args:?} ran longer than {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let out = Out {
        code: status.code().unwrap_or_else(|| panic!("{args:?} killed by a signal")),
        stdout: ho.join().unwrap(),
        stderr: he.join().unwrap(),
    };
    assert!(!out.stderr.contains("panicked"), "{args:?}: {}", out.stderr);
    assert_ne!(out.code, 101, "{args:?}: {}", out.stderr);
    out
}

/// Run with `stdin` as standard input, within [`LIMIT`].
pub fn run_with(args: &[&str], stdin: Option<&str>) -> Out {
    run_limited(args, stdin, LIMIT)
}

/// Run with an empty standard input, within [`LIMIT`].
pub fn run(args: &[&str]) -> Out {
    run_with(args, None)
}

/// Runs and expects success (exit code 0).
pub fn ok(args: &[&str]) -> Out {
    let o = run(args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    o
}

/// Runs and expects failure with exit code `code` and every `needles` in standard error.
pub fn fails(args: &[&str], stdin: Option<&str>, code: i32, needles: &[&str]) -> Out {
    let o = run_with(args, stdin);
    assert_eq!(o.code, code, "{args:?}: stdout {} stderr {}", o.stdout, o.stderr);
    for n in needles {
        assert!(o.stderr.contains(n), "{args:?}: stderr lacks {n:?}:\n{}", o.stderr);
    }
    o
}

/// A path as a command-line argument.
pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A temporary directory holding the file `name` with `contents`, and that file's path.
pub fn temp_file(name: &str, contents: &str) -> (tempfile::TempDir, PathBuf) {
    let d = tempfile::tempdir().unwrap();
    let f = d.path().join(name);
    std::fs::write(&f, contents).unwrap();
    (d, f)
}

/// A CSV text's header and rows, as strings.
pub fn parse_csv(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut r = csv::Reader::from_reader(text.as_bytes());
    let h = r.headers().unwrap().iter().map(str::to_string).collect();
    let rows = r.records().map(|x| x.unwrap().iter().map(str::to_string).collect()).collect();
    (h, rows)
}
