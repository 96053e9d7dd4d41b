//! The layer's shape, checked on its sources: `fmi2/` and `fmi3/` are symmetric shims over the
//! version-neutral `core/`. Neither shim defines a function of the other standard or names
//! the other's module or types, and the core names neither shim nor exports an FMI function of
//! its own. A file that breaks this (an `fmi3*` export written under `fmi2/`, a `use
//! crate::fmi3::…` in `fmi2/`, a core file reaching into a shim) fails here with its line.

use std::fs;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`, recursively, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap_or_else(|e| panic!("cannot read {}: {e}", d.display())) {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The code of a line: what precedes a `//` comment (doc comments included). Good enough
/// for these sources, which have no `//` inside string literals on the lines that matter.
fn code(line: &str) -> &str {
    line.find("//").map_or(line, |i| &line[..i])
}

/// Whether `text` holds `word` as a whole identifier-prefixed token at `i`: the character
/// before it is not part of an identifier.
fn starts_token(text: &str, i: usize) -> bool {
    text[..i].chars().next_back().is_none_or(|c| !(c.is_alphanumeric() || c == '_'))
}

/// The ways `line` (of a file in a shim or the core) reaches `version` (`"fmi2"` or
/// `"fmi3"`): a path into its module (`fmi3::`, in code or in a doc link), a function of that
/// standard defined here (`fn fmi3GetFMUState`), its macro (`export_fmi3!`) or one of its C types
/// (`Fmi3…`) in code.
fn reaches(line: &str, version: &str) -> Vec<String> {
    let mut found = Vec::new();
    let path = format!("{version}::");
    for (i, _) in line.match_indices(&path) {
        if starts_token(line, i) {
            found.push(format!("names the module `{path}`"));
        }
    }
    let c = code(line);
    // The standards' functions are camel case (`fmi3GetFMUState`); a helper such as
    // `fmi2_accessed_as` is not one.
    let func = format!("fn {version}");
    if c.match_indices(&func).any(|(i, _)| starts_token(c, i) && c[i + func.len()..].starts_with(|ch: char| ch.is_ascii_uppercase())) {
        found.push(format!("defines an `{version}*` function"));
    }
    if c.contains(&format!("export_{version}!")) {
        found.push(format!("uses `export_{version}!`"));
    }
    let ty = format!("F{}", &version[1..]);
    if c.match_indices(&ty).any(|(i, _)| starts_token(c, i) && c[i + ty.len()..].starts_with(|ch: char| ch.is_ascii_uppercase())) {
        found.push(format!("uses a `{ty}…` type"));
    }
    found
}

/// Each line under `dir` that reaches one of `versions`, as `file:line: what`.
fn violations(dir: &Path, versions: &[&str]) -> Vec<String> {
    let mut out = Vec::new();
    for file in rust_files(dir) {
        let text = fs::read_to_string(&file).unwrap_or_else(|e| panic!("cannot read {}: {e}", file.display()));
        for (n, line) in text.lines().enumerate() {
            for v in versions {
                for what in reaches(line, v) {
                    out.push(format!("{}:{}: {what}: {}", file.display(), n + 1, line.trim()));
                }
            }
        }
    }
    out
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn the_fmi2_shim_names_nothing_of_fmi3() {
    let v = violations(&src().join("fmi2"), &["fmi3"]);
    assert!(v.is_empty(), "fmi2/ reaches into FMI 3.0:\n{}", v.join("\n"));
}

#[test]
fn the_fmi3_shim_names_nothing_of_fmi2() {
    let v = violations(&src().join("fmi3"), &["fmi2"]);
    assert!(v.is_empty(), "fmi3/ reaches into FMI 2.0:\n{}", v.join("\n"));
}

/// The core names neither shim in code and defines no exported function of either standard
/// (the exports are the shims'); its doc comments may mention functions by name.
#[test]
fn the_core_names_neither_shim() {
    let mut v = Vec::new();
    for file in rust_files(&src().join("core")) {
        let text = fs::read_to_string(&file).expect("a core file");
        for (n, line) in text.lines().enumerate() {
            let c = code(line);
            for version in ["fmi2", "fmi3"] {
                let hits = reaches(c, version);
                if !hits.is_empty() {
                    v.push(format!("{}:{}: {}: {}", file.display(), n + 1, hits.join(", "), line.trim()));
                }
            }
        }
    }
    assert!(v.is_empty(), "core/ depends on a version shim:\n{}", v.join("\n"));
}

/// Both shims hold the same parts: `api` (one file per interface and the common functions),
/// `types` and `xml`, and nothing else.
#[test]
fn the_shims_are_symmetric() {
    let layout = |version: &str| -> Vec<String> {
        let root = src().join(version);
        let mut files: Vec<String> =
            rust_files(&root).iter().map(|p| p.strip_prefix(&root).expect("under the root").to_string_lossy().replace('\\', "/")).collect();
        files.sort();
        files
    };
    let expected = ["api/common.rs", "api/cosim.rs", "api/fmu_state.rs", "api/mod.rs", "api/model_exchange.rs", "mod.rs", "types.rs", "xml.rs"];
    assert_eq!(layout("fmi2"), expected, "fmi2/");
    assert_eq!(layout("fmi3"), expected, "fmi3/");
}

/// The model crate implements the core's trait, once per model, and takes nothing of the
/// model side from a shim.
#[test]
fn the_fmu_crate_implements_the_core_trait() {
    let fmu = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fmu/src");
    let mut impls: Vec<String> = Vec::new();
    let mut v = Vec::new();
    for file in rust_files(&fmu) {
        let text = fs::read_to_string(&file).expect("an fmu file");
        for (n, line) in text.lines().enumerate() {
            let c = code(line);
            for head in ["impl Model for ", "impl fmi_layer::core::Model for ", "impl fmi_layer::core::model::Model for "] {
                if let Some(i) = c.find(head) {
                    let ty: String = c[i + head.len()..].chars().take_while(|ch| ch.is_alphanumeric() || *ch == '_').collect();
                    impls.push(ty);
                }
            }
            for m in ["model", "variables", "bytes", "logging", "interface", "snapshot"] {
                if c.contains(&format!("fmi_layer::fmi2::{m}")) || c.contains(&format!("fmi_layer::fmi3::{m}")) {
                    v.push(format!("{}:{}: {}", file.display(), n + 1, line.trim()));
                }
            }
            if c.contains("impl fmi_layer::fmi2") || c.contains("impl fmi_layer::fmi3") {
                v.push(format!("{}:{}: {}", file.display(), n + 1, line.trim()));
            }
        }
    }
    assert!(v.is_empty(), "pinjoint-fmu takes the model side from a shim, not the core:\n{}", v.join("\n"));
    // PinJoint, PinJointRig and the PassThrough baseline (at least): each model type
    // implements the trait once, for both standards.
    assert!(impls.len() >= 3, "the models' `impl Model for`: {impls:?}");
    let mut distinct = impls.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), impls.len(), "a model type implements the trait twice: {impls:?}");
}

/// The checker itself flags what it is meant to flag, and passes what it must pass.
#[test]
fn the_checker_flags_a_crossing() {
    assert_eq!(reaches("use crate::fmi3::types::{Fmi3Instance};", "fmi3").len(), 2);
    assert_eq!(reaches("    unsafe fn fmi3GetFMUState(instance: *mut c_void) -> i32: FMU_STATE => body;", "fmi3").len(), 1);
    assert_eq!(reaches("pub use super::super::fmi3::api::fmi3DoStep;", "fmi3").len(), 1);
    assert_eq!(reaches("/// as [`crate::fmi3::api::fmi3DoStep`]", "fmi3").len(), 1);
    assert_eq!(reaches("fmi_layer::export_fmi3!(crate::registry);", "fmi3").len(), 1);
    // Mentions in prose, and names that only contain the version, are not crossings.
    assert!(reaches("/// as `fmi3GetFMUState` does through FMI 3.0", "fmi3").is_empty());
    assert!(reaches("let my_fmi3_flag = Fmi3ish;", "fmi3").is_empty());
    assert!(reaches("pub fn fmi3_accessed_as(self) -> bool {", "fmi3").is_empty());
    assert_eq!(reaches("fn fmi2SetReal(c: Fmi2Component) -> Fmi2StatusC: SET_VALUE => body;", "fmi2").len(), 2);
    assert!(reaches("use crate::core::fmu_state::{get_state};", "fmi3").is_empty());
}
