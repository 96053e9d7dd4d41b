//! `cargo run --release -p fmu_build`: builds the shared library (the FMU binary)
//! and writes one FMU per model of `pinjoint_fmu::registry()` to `target/fmu/`:
//! `modelDescription.xml`, `binaries/<platform>/<modelIdentifier>.<ext>` and
//! `documentation/index.html` (with the licence notices and `model.png`), and the FMI 3.0
//! FMUs to `target/fmu/fmi3/`. Packaging only: the XML and the documentation come from the
//! library's variable tables.
//!
//! `-- --platforms host` (the default) builds for this machine only. `-- --platforms all`
//! builds every platform of [`platforms::ALL`] (cross-compiled; see `tests/platforms/run.sh`
//! for the tools) and the FMUs carry FMI 2.0 `binaries/linux64` (glibc 2.17, no
//! libgcc_s), `win64` and `darwin64` (universal x86-64 + arm64); the libraries of every
//! platform, FMI 3.0 ones included, are kept in `target/fmu/platforms/<dir>/`.
//! `-- --platforms x86_64-linux,x86_64-windows` builds the named ones only.

// In dependency order: each module uses only those above it (tests/module_graph.py).
mod error;
mod platforms;
mod extras;
mod archive;
mod fmi3;

use error::BuildError;
use fmi_layer::core::variables::ModelInfo;
use fmi_layer::fmi2::xml::model_description;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Write `<out_dir>/<modelIdentifier>.fmu` carrying, for each `(FMI 2.0 folder, extension,
/// library)`, the library as `binaries/<folder>/<modelIdentifier>.<extension>`.
fn package(info: &ModelInfo, binaries: &[(&str, &str, PathBuf)], out_dir: &Path, extras: &[extras::Entry]) -> Result<PathBuf, BuildError> {
    let path = out_dir.join(format!("{}.fmu", info.model_identifier));
    let libraries = binaries.iter().map(|(folder, ext, library)| (*folder, library.as_path(), *ext));
    archive::write_fmu(&path, info, model_description(info)?, libraries, extras)?;
    Ok(path)
}

/// The value of `--platforms` (default `host`).
fn platforms_arg() -> Result<String, BuildError> {
    let mut args = std::env::args().skip(1);
    let mut spec = "host".to_owned();
    while let Some(a) = args.next() {
        match a.as_str() {
            "--platforms" => spec = args.next().ok_or(BuildError::MissingPlatforms)?,
            s if s.starts_with("--platforms=") => spec = s["--platforms=".len()..].to_owned(),
            "-h" | "--help" => {
                println!("usage: fmu_build [--platforms host|all|<dir>,<dir>...]");
                std::process::exit(0);
            }
            other => return Err(BuildError::UnknownArgument(other.to_owned())),
        }
    }
    Ok(spec)
}

fn run() -> Result<(), BuildError> {
    let selected = platforms::select(&platforms_arg()?)?;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().ok_or(BuildError::NoWorkspaceRoot)?.to_path_buf();
    let target = std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|| root.join("target"));
    let target = if target.is_relative() { root.join(target) } else { target };
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    // (FMI 2.0 folder, extension, library) and (FMI 3.0 tuple, library, extension).
    let (mut fmi2_binaries, mut fmi3_binaries) = (Vec::new(), Vec::new());
    for p in &selected {
        let library = platforms::build_library(&root, &target, p)?;
        if let Some(tuple) = p.fmi3 {
            fmi3_binaries.push((tuple, library.clone(), p.ext));
        }
        if let Some(folder) = p.fmi2 {
            fmi2_binaries.push((folder, p.ext, library));
        }
    }
    let out_dir = target.join("fmu");
    std::fs::create_dir_all(&out_dir).map_err(BuildError::io("creating", &out_dir))?;
    // Licence notices and model.png: the same in every FMU, both standards.
    let mut extras = extras::licenses(&cargo, &root, platforms::FMU_PACKAGE)?;
    extras.push(("model.png".into(), extras::model_png()));
    for info in pinjoint_fmu::registry() {
        println!("{}", package(info, &fmi2_binaries, &out_dir, &extras)?.display());
        // FMI 3.0: the same libraries, target/fmu/fmi3/ (fmi3.rs).
        println!("{}", fmi3::package(info, &fmi3_binaries, &out_dir, &extras)?.display());
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("fmu_build: error: {e}");
            ExitCode::FAILURE
        }
    }
}
