//! `cargo run --release -p fmu_build`: builds the shared library (the FMU binary)
//! and writes one FMU per model of `pinjoint_fmu::registry()` to `target/fmu/`:
//! `modelDescription.xml`, `binaries/<platform>/<modelIdentifier>.<ext>` and
//! `documentation/index.html`. Packaging only: the XML and the documentation come
//! from the library's variable tables.

mod extras;
mod fmi3;

use fmi_layer::fmi2::variables::ModelInfo;
use fmi_layer::fmi2::xml::model_description;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipWriter};

/// The crate whose cdylib is the FMU binary.
const FMU_PACKAGE: &str = "pinjoint-fmu";

/// FMI 2.0 platform folder and shared-library names for this host.
fn platform() -> Result<(&'static str, &'static str, &'static str), String> {
    match (std::env::consts::OS, std::env::consts::ARCH) {
        ("linux", "x86_64") => Ok(("linux64", "libpinjoint_fmu.so", "so")),
        ("linux", "x86") => Ok(("linux32", "libpinjoint_fmu.so", "so")),
        ("macos", "x86_64" | "aarch64") => Ok(("darwin64", "libpinjoint_fmu.dylib", "dylib")),
        ("windows", "x86_64") => Ok(("win64", "pinjoint_fmu.dll", "dll")),
        (os, arch) => Err(format!("no FMI 2.0 platform folder for {os}/{arch}")),
    }
}

fn package(info: &ModelInfo, library: &Path, out_dir: &Path, folder: &str, ext: &str, extras: &[extras::Entry]) -> Result<PathBuf, String> {
    let xml = model_description(info)?;
    let binary = std::fs::read(library).map_err(|e| format!("reading {}: {e}", library.display()))?;
    let path = out_dir.join(format!("{}.fmu", info.model_identifier));
    let file = std::fs::File::create(&path).map_err(|e| format!("creating {}: {e}", path.display()))?;
    let mut zip = ZipWriter::new(file);
    // A fixed time stamp keeps the archive reproducible.
    let opts = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Deflated)
        .last_modified_time(DateTime::default());
    let entries: [(String, &[u8], u32); 3] = [
        ("modelDescription.xml".into(), xml.as_bytes(), 0o644),
        (format!("binaries/{folder}/{}.{ext}", info.model_identifier), &binary, 0o755),
        ("documentation/index.html".into(), (info.documentation)().into_bytes().leak(), 0o644),
    ];
    let extra = extras.iter().map(|(n, b)| (n.clone(), b.as_slice(), 0o644));
    for (name, data, mode) in entries.into_iter().chain(extra) {
        zip.start_file(name.as_str(), opts.unix_permissions(mode)).map_err(|e| e.to_string())?;
        zip.write_all(data).map_err(|e| e.to_string())?;
    }
    zip.finish().map_err(|e| e.to_string())?;
    Ok(path)
}

fn run() -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().ok_or("no workspace root")?.to_path_buf();
    let target = std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|| root.join("target"));
    let target = if target.is_relative() { root.join(target) } else { target };
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    eprintln!("fmu_build: cargo build --release --lib -p {FMU_PACKAGE}");
    let status = Command::new(&cargo)
        .args(["build", "--release", "--lib", "-p", FMU_PACKAGE])
        .current_dir(&root)
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .map_err(|e| format!("running {cargo}: {e}"))?;
    if !status.success() {
        return Err(format!("cargo build failed ({status})"));
    }
    let (folder, lib_name, ext) = platform()?;
    let library = target.join("release").join(lib_name);
    let out_dir = target.join("fmu");
    std::fs::create_dir_all(&out_dir).map_err(|e| format!("creating {}: {e}", out_dir.display()))?;
    // Licence notices and model.png: the same in every FMU, both standards.
    let mut extras = extras::licenses(&cargo, &root, FMU_PACKAGE)?;
    extras.push(("model.png".into(), extras::model_png()));
    for info in pinjoint_fmu::registry() {
        let path = package(info, &library, &out_dir, folder, ext, &extras)?;
        println!("{}", path.display());
    }
    // FMI 3.0: the same library, target/fmu/fmi3/ (fmi3.rs).
    for path in fmi3::package_host(&pinjoint_fmu::registry(), &library, ext, &out_dir, &extras)? {
        println!("{}", path.display());
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
