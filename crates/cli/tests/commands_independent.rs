//! Commands never import commands (as cargo's don't): what two commands share lives at the
//! crate's top level (`crates/cli/src/*.rs`, e.g. `rig_run`, `curves`) or in the library.
//!
//! Every file of a command (`commands/NAME.rs`, or every file under `commands/NAME/`) is read
//! with its comments left out; a path naming another command is a finding:
//! `commands::OTHER` (also `crate::commands::OTHER` and `crate::commands::{…, OTHER}`), and
//! `super::OTHER` from a command's own level (`commands/NAME.rs`, `commands/NAME/mod.rs`) or
//! `super::super::OTHER` from a part (`commands/NAME/PART.rs`). `#[cfg(test)]` modules count
//! too.

use std::fs;
use std::path::{Path, PathBuf};

/// A command's name and its files, each with its depth below `commands/`: 0 for
/// `commands/NAME.rs` and `commands/NAME/mod.rs`, 1 for a part `commands/NAME/PART.rs`, and
/// one more per folder below that.
fn commands(dir: &Path) -> Vec<(String, Vec<(PathBuf, usize)>)> {
    let mut out = Vec::new();
    for entry in fs::read_dir(dir).expect("commands/ readable") {
        let path = entry.expect("entry").path();
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            let mut files = Vec::new();
            collect(&path, 1, &mut files);
            out.push((name, files));
        } else if path.extension().is_some_and(|e| e == "rs") && name != "mod" {
            out.push((name, vec![(path, 0)]));
        }
    }
    out.sort();
    out
}

fn collect(dir: &Path, depth: usize, files: &mut Vec<(PathBuf, usize)>) {
    for entry in fs::read_dir(dir).expect("folder readable") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            collect(&path, depth + 1, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let d = if path.file_stem().is_some_and(|s| s == "mod") { depth - 1 } else { depth };
            files.push((path, d));
        }
    }
}

/// `text` without its comments (`//…` to the end of the line and `/* … */`) and with string
/// literals emptied, so that prose and messages naming a command are not paths.
fn code_only(text: &str) -> String {
    let (mut out, b) = (String::with_capacity(text.len()), text.as_bytes());
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            let end = text[i + 2..].find("*/").map_or(b.len(), |k| i + 2 + k + 2);
            i = end;
        } else if b[i] == b'"' {
            out.push('"');
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            out.push('"');
            i += 1;
        } else {
            let c = text[i..].chars().next().unwrap();
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// The identifiers a path prefix names right after it: `PREFIX::name` and every top-level
/// name of `PREFIX::{a, b::c, d as e}`.
fn named_after(code: &str, prefix: &str) -> Vec<String> {
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    let mut names = Vec::new();
    let pat = format!("{prefix}::");
    let mut from = 0;
    while let Some(k) = code[from..].find(&pat) {
        let at = from + k;
        from = at + pat.len();
        // A whole path segment: not the tail of a longer name (`my_commands::`).
        if code[..at].chars().next_back().is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let rest = code[from..].trim_start();
        if let Some(inner) = rest.strip_prefix('{') {
            let (mut depth, mut item_start) = (0usize, true);
            for (j, c) in inner.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => item_start = true,
                    c if c.is_whitespace() => {}
                    _ if item_start && depth == 0 => {
                        names.push(ident(&inner[j..]));
                        item_start = false;
                    }
                    _ => {}
                }
            }
        } else {
            names.push(ident(rest));
        }
    }
    names
}

/// The other commands that the code of a file of command `own` at `depth` names.
fn findings(own: &str, depth: usize, text: &str, all: &[&str]) -> Vec<String> {
    let code = code_only(text);
    let up = vec!["super"; depth + 1].join("::");
    let mut named = named_after(&code, "commands");
    named.extend(named_after(&code, &up));
    let mut out: Vec<String> = named.into_iter().filter(|n| n != own && all.contains(&n.as_str())).collect();
    out.sort();
    out.dedup();
    out
}

#[test]
fn no_command_imports_another_command() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/commands");
    let cmds = commands(&dir);
    let names: Vec<&str> = cmds.iter().map(|(n, _)| n.as_str()).collect();
    for expected in ["cycle", "figures", "map", "stribeck", "sweep", "point"] {
        assert!(names.contains(&expected), "command {expected} not found among {names:?}");
    }
    let mut problems = Vec::new();
    for (own, files) in &cmds {
        for (path, depth) in files {
            let text = fs::read_to_string(path).expect("source readable");
            for other in findings(own, *depth, &text, &names) {
                problems.push(format!("{}: command {own} uses command {other}", path.strip_prefix(&dir).unwrap().display()));
            }
        }
    }
    assert!(problems.is_empty(), "commands import commands (move what they share to the crate's top level or the library):\n{}", problems.join("\n"));
}

/// The scanner finds each way one command can name another, and nothing else.
#[test]
fn the_scanner_finds_every_form_and_only_those() {
    let all = ["cycle", "figures", "map", "stribeck"];
    // Figures' part (depth 1) naming other commands in each form.
    let part = "use crate::commands::cycle::simulation::stroke_average;\n\
                use crate::commands::{map::Grid, stribeck as s};\n\
                use super::super::cycle::plots;\n\
                fn f() { let _ = crate::commands::figures::plots::X; }\n";
    assert_eq!(findings("figures", 1, part, &all), ["cycle", "map", "stribeck"]);
    // A single-file command (depth 0) through `super::`.
    assert_eq!(findings("stribeck", 0, "use super::map::write_map;\n", &all), ["map"]);
    // The command's own parts, the crate's shared modules, comments, strings, longer names.
    let clean = "use super::rig::{at_frequency, find};\n\
                 use crate::rig_run::CycleRun;\n\
                 use crate::curves::map::{write_map, Grid};\n\
                 // crate::commands::cycle::simulation was used here\n\
                 /* super::super::map */\n\
                 const S: &str = \"commands::map\";\n\
                 use my_commands::map;\n";
    assert_eq!(findings("figures", 1, clean, &all), Vec::<String>::new());
    // From a part, one `super::` is the command's own folder, not another command.
    assert_eq!(findings("figures", 1, "use super::map::Local;\n", &all), Vec::<String>::new());
}
