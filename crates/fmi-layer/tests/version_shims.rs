//! The layer's shape, checked on its sources: `fmi2/` and `fmi3/` are symmetric shims over the
//! version-neutral `core/`. Neither shim defines a function of the other standard or names
//! the other's module or types, and the core names neither shim nor exports an FMI function of
//! its own. The core names nothing of one standard only in code (no identifier containing
//! `fmi2`/`fmi3`: the shims supply what their standards define differently), and each of its
//! state masks serves both standards. A file that breaks this (an `fmi3*` export written under
//! `fmi2/`, a `use crate::fmi3::…` in `fmi2/`, a core file reaching into a shim, a core
//! `fmi2_…` rule or `…_FMI3` mask) fails here with its line.

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

/// `text` (a whole Rust file) with its comments and the contents of its string, byte-string,
/// raw-string and char literals blanked to spaces (newlines kept, so line numbers still hold):
/// what is left is code. Lifetimes (`'a`) are code.
fn code_of(text: &str) -> String {
    let b: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |out: &mut String, c: char| out.push(if c == '\n' { '\n' } else { ' ' });
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < b.len() && b[i] != '\n' {
                blank(&mut out, b[i]);
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < b.len() {
                if b[i] == '/' && b.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if b[i] == '*' && b.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, b[i]);
                    i += 1;
                }
            }
        } else if (c == 'r' || (c == 'b' && next == Some('r'))) && !b[..i].last().is_some_and(|p| p.is_alphanumeric() || *p == '_') && {
            let j = if c == 'b' { i + 2 } else { i + 1 };
            let hashes = b[j..].iter().take_while(|ch| **ch == '#').count();
            b.get(j + hashes) == Some(&'"')
        } {
            // A raw string: r"…", r#"…"#, br"…".
            let j = if c == 'b' { i + 2 } else { i + 1 };
            let hashes = b[j..].iter().take_while(|ch| **ch == '#').count();
            let open = j + hashes + 1;
            for ch in &b[i..open] {
                out.push(*ch);
            }
            i = open;
            let closes = |k: usize| b[k] == '"' && (1..=hashes).all(|h| b.get(k + h) == Some(&'#'));
            while i < b.len() && !closes(i) {
                blank(&mut out, b[i]);
                i += 1;
            }
            let end = (i + 1 + hashes).min(b.len());
            for ch in &b[i..end] {
                out.push(*ch);
            }
            i = end;
        } else if c == '"' {
            out.push('"');
            i += 1;
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    blank(&mut out, b[i]);
                    i += 1;
                }
                if i < b.len() {
                    blank(&mut out, b[i]);
                    i += 1;
                }
            }
            if i < b.len() {
                out.push('"');
                i += 1;
            }
        } else if c == '\'' && (next == Some('\\') || b.get(i + 2) == Some(&'\'')) {
            // A char literal ('x', '\n', '\u{1F600}'); a lifetime ('a) has no closing quote.
            out.push('\'');
            i += 1;
            while i < b.len() && b[i] != '\'' {
                if b[i] == '\\' {
                    blank(&mut out, b[i]);
                    i += 1;
                }
                if i < b.len() {
                    blank(&mut out, b[i]);
                    i += 1;
                }
            }
            if i < b.len() {
                out.push('\'');
                i += 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// The identifiers (maximal runs of letters, digits and `_`) of a line of code.
fn identifiers(code: &str) -> impl Iterator<Item = &str> {
    code.split(|c: char| !(c.is_alphanumeric() || c == '_')).filter(|w| w.starts_with(|c: char| c.is_alphabetic() || c == '_'))
}

/// The ways a file that must be version-neutral breaks that, as `what` per line (1-based):
///
/// - a path into a shim anywhere, comments and doc links included: `fmi2::…`, `crate::fmi3`,
///   `super::fmi2` (a prose mention of a function, `fmi2DoStep`, is no path);
/// - if `identifiers_too`, an identifier in code (comments and literals blanked) that contains
///   `fmi2` or `fmi3` in any case: a shim's C type (`Fmi2Component`), constant
///   (`FMI2_TERMINATED`), function (`fmi3GetFMUState`, `export_fmi2!`), or a version's own rule
///   or variant given a version's name (`fmi2_accessed_as`, `GET_DIRECTIONAL_DERIVATIVE_FMI3`,
///   `Version::Fmi3`). Messages (string literals) may quote a standard's function names.
fn version_specifics(text: &str, identifiers_too: bool) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        for v in ["fmi2", "fmi3"] {
            let as_path = line.match_indices(v).any(|(i, _)| {
                starts_token(line, i) && (line[i + v.len()..].starts_with("::") || line[..i].ends_with("::"))
                    && !line[i + v.len()..].starts_with(|ch: char| ch.is_alphanumeric() || ch == '_')
            });
            if as_path {
                found.push((n + 1, format!("names the module `{v}`")));
            }
        }
    }
    if identifiers_too {
        for (n, line) in code_of(text).lines().enumerate() {
            for id in identifiers(line) {
                let lower = id.to_ascii_lowercase();
                if lower.contains("fmi2") || lower.contains("fmi3") {
                    found.push((n + 1, format!("identifier `{id}` names a standard")));
                }
            }
        }
    }
    found.sort();
    found
}

/// The core names neither shim nor anything of one standard only: no path into `fmi2`/`fmi3`
/// (code, comments or doc links) and, in code, no identifier containing `fmi2`/`fmi3` in any
/// case (see [`version_specifics`]). What the standards define differently the shims supply
/// (`core::Rules`, their own masks, status names and status-kind codes). `error.rs`, which the
/// core uses, is held to the same rule, so the core reaches no shim through it; an error of
/// one standard's argument takes that standard's words from the shim that raises it.
#[test]
fn the_core_names_neither_shim() {
    let mut v = Vec::new();
    let mut check = |file: &Path, identifiers_too: bool| {
        let text = fs::read_to_string(file).expect("a core file");
        let lines: Vec<&str> = text.lines().collect();
        for (n, what) in version_specifics(&text, identifiers_too) {
            v.push(format!("{}:{n}: {what}: {}", file.display(), lines[n - 1].trim()));
        }
    };
    for file in rust_files(&src().join("core")) {
        check(&file, true);
    }
    check(&src().join("error.rs"), true);
    assert!(v.is_empty(), "core/ (or error.rs) names a version shim or one standard's specifics:\n{}", v.join("\n"));
}

/// The names of the `pub const NAME: Mask` of `state_rs` (the core's state masks).
fn core_masks(state_rs: &str) -> Vec<String> {
    code_of(state_rs)
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub const ")?.split_once(": Mask")).map(|(name, _)| name.trim().to_owned())
        .collect()
}

/// Whether the code of `text` uses the identifier `name`.
fn uses(text: &str, name: &str) -> bool {
    code_of(text).lines().any(|l| identifiers(l).any(|id| id == name))
}

/// The core's masks that exactly one of the shims' sources uses: a mask of one standard's own
/// function, which belongs in that shim.
fn one_sided_masks(state_rs: &str, fmi2: &[String], fmi3: &[String]) -> Vec<String> {
    core_masks(state_rs)
        .into_iter()
        .filter(|m| fmi2.iter().any(|t| uses(t, m)) != fmi3.iter().any(|t| uses(t, m)))
        .collect()
}

/// The core's state masks are those of functions both standards have: each is used by both
/// shims or by neither (`FREE_INSTANCE`, `GET_VERSION`, … document state sets the layer
/// handles without a guard). A mask only one shim uses (`fmi3EnterStepMode`'s,
/// `fmi2SetupExperiment`'s) is defined in that shim.
#[test]
fn the_core_masks_serve_both_standards() {
    let read_all = |dir: &str| -> Vec<String> { rust_files(&src().join(dir)).iter().map(|f| fs::read_to_string(f).expect("a shim file")).collect() };
    let state = fs::read_to_string(src().join("core/state.rs")).expect("core/state.rs");
    let masks = core_masks(&state);
    assert!(masks.len() >= 10 && masks.iter().any(|m| m == "DO_STEP"), "the core's masks as read: {masks:?}");
    let one_sided = one_sided_masks(&state, &read_all("fmi2"), &read_all("fmi3"));
    assert!(one_sided.is_empty(), "core masks used by one shim only (move them to that shim): {one_sided:?}");
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

/// The core's rule flags each kind of version specific it names, and passes prose and
/// messages.
#[test]
fn the_core_rule_flags_version_specifics() {
    let flagged = |text: &str| !version_specifics(text, true).is_empty();
    // What the core held before the shims supplied it.
    assert!(flagged("use crate::fmi2::types::{FMI2_DO_STEP_STATUS};"));
    assert!(flagged("        use crate::fmi2::types::{FMI2_TERMINATED};\n"));
    assert!(flagged("pub const GET_DIRECTIONAL_DERIVATIVE_FMI3: Mask = Mask::of(&[EventMode]);"));
    assert!(flagged("let ok = if self.version == Version::Fmi3 { a } else { k.fmi2_accessed_as(kind) };"));
    assert!(flagged("pub(crate) const FMI2: Arrays = Arrays { vr: \"vr[]\" };"));
    assert!(flagged("    Fmi2CoSimulationOnly(&'static str),"));
    assert!(flagged("fn fmi3GetFMUState(c: *mut c_void) {}"));
    assert!(flagged("//! The version shims ([`crate::fmi2`], [`crate::fmi3`])"));
    assert!(flagged("/// see `super::fmi3::types`"));
    // Prose, messages and byte formats may quote a standard.
    assert!(!flagged("/// as `fmi2DoStep` and `fmi3DoStep` do (FMI 2.0 §4.2.2)"));
    assert!(!flagged("#[error(\"it can only be set before fmi2ExitInitializationMode (state is {state})\")]"));
    assert!(!flagged("pub const MAGIC: [u8; 8] = *b\"FMI2STAT\";"));
    assert!(!flagged("let s = r#\"fmi2Error \"quoted\" fmi3Error\"#; let c = 'f'; fn f<'a>(x: &'a str) {}"));
    assert!(!flagged("/* fmi2Component */ let x = 1; // Fmi3Instance"));
    // A literal spanning lines is blanked on every line; code after it is still read.
    assert!(flagged("let m = \"first line\n  fmi2Error\";\nlet y = Fmi2Component::default();"));
    assert_eq!(version_specifics("let m = \"a\n fmi2Error\";\nlet y = Fmi2Component::default();", true)[0].0, 3);
    // Paths only: a standard's identifier passes, a path into a shim does not.
    assert!(version_specifics("    Fmi2CoSimulationOnly(&'static str),", false).is_empty());
    assert!(!version_specifics("use crate::fmi2::types::FMI2_TERMINATED;", false).is_empty());
}

/// The mask rule flags a core mask one shim uses and passes one both or neither use.
#[test]
fn the_mask_rule_flags_a_one_sided_mask() {
    let state = "pub const DO_STEP: Mask = Mask::of(&[StepComplete]);\npub const ENTER_STEP_MODE: Mask = Mask::of(&[EventMode]);\npub const FREE_INSTANCE: Mask = Mask(1);\n// pub const OLD: Mask\n";
    assert_eq!(core_masks(state), ["DO_STEP", "ENTER_STEP_MODE", "FREE_INSTANCE"]);
    let fmi2 = ["fn fmi2DoStep(c: C) -> S: DO_STEP => body;".to_owned()];
    let fmi3 = ["fn fmi3DoStep(c: C) -> S: DO_STEP => body;\nfn fmi3EnterStepMode(c: C) -> S: ENTER_STEP_MODE => refuse(\"x\");".to_owned()];
    assert_eq!(one_sided_masks(state, &fmi2, &fmi3), ["ENTER_STEP_MODE"]);
    // A mention in a comment or message is no use.
    let fmi2_mention = ["// not ENTER_STEP_MODE\nlet s = \"ENTER_STEP_MODE\"; fn fmi2DoStep(c: C) -> S: DO_STEP => body;".to_owned()];
    assert_eq!(one_sided_masks(state, &fmi2_mention, &fmi3), ["ENTER_STEP_MODE"]);
    let fmi2_both = ["fn a() -> S: DO_STEP => b; fn c() -> S: ENTER_STEP_MODE => d;".to_owned()];
    assert!(one_sided_masks(state, &fmi2_both, &fmi3).is_empty());
}

/// The lines of `text` before its `#[cfg(test)]` whose string literals name one standard's
/// function (`"… fmi2Terminate …"`): a message the core sends reaches hosts of both versions,
/// so it names a call by its common part (`Terminate`), never by one version's name.
fn version_named_in_messages(text: &str) -> Vec<(usize, String)> {
    let shipped = text.split("#[cfg(test)]").next().unwrap_or("");
    let mut found = Vec::new();
    for (n, line) in shipped.lines().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("//") {
            continue;
        }
        // The literals of the line: the text between its unescaped double quotes.
        for (k, part) in line.split('"').enumerate() {
            if k % 2 == 1 {
                for v in ["fmi2", "fmi3"] {
                    if part.match_indices(v).any(|(i, _)| part[i + 4..].starts_with(|c: char| c.is_ascii_uppercase())) {
                        found.push((n + 1, line.trim().to_string()));
                    }
                }
            }
        }
    }
    found
}

#[test]
fn the_cores_messages_name_no_versions_function() {
    let mut bad = Vec::new();
    for f in rust_files(&src().join("core")) {
        let text = std::fs::read_to_string(&f).unwrap();
        bad.extend(version_named_in_messages(&text).into_iter().map(|(n, l)| format!("{}:{n}: {l}", f.display())));
    }
    assert!(bad.is_empty(), "the core's messages name one version's function:\n{}", bad.join("\n"));
    // The check itself finds one.
    let probe = "fn f() { log(\"summary at fmi2Terminate\"); }\n#[cfg(test)]\nmod tests { const X: &str = \"fmi3DoStep\"; }";
    assert_eq!(version_named_in_messages(probe).len(), 1);
}
