//! The platforms the FMU binary is built for, and the one function that builds it for
//! a platform: [`build_library`] (target triple in, path of the shared library out).
//!
//! Linux and macOS libraries are linked by `cargo zigbuild` (zig as the linker: glibc
//! 2.17 symbol versions, LLVM's libunwind linked in instead of libgcc_s, macOS dylibs
//! without an SDK); Windows by cargo with MinGW-w64's gcc, Rust's default linker for
//! `x86_64-pc-windows-gnu` (libgcc's unwinder and winpthreads linked statically).
//! Every built library is copied to `target/fmu/platforms/<dir>/<file>` for packaging.

use crate::error::BuildError;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The Cargo package whose cdylib is the FMU binary (every model of the registry).
pub const FMU_PACKAGE: &str = "pinjoint-fmu";

/// How a platform's library is linked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Linker {
    /// `cargo build --target <triple>` with Rust's default linker for the target.
    Cargo,
    /// `cargo zigbuild --target <triple><zig suffix>` (cargo-zigbuild and ziglang on PATH).
    Zig,
}

/// One shared library to build, and where it goes in the FMUs.
#[derive(Clone, Copy, Debug)]
pub struct Platform {
    /// The folder under `target/fmu/platforms/` that keeps the built library; the name
    /// `--platforms` accepts.
    pub dir: &'static str,
    /// The Rust target triple; cargo writes to `target/<triple>/release/`.
    pub triple: &'static str,
    /// How it is linked.
    pub linker: Linker,
    /// Appended to the triple for cargo-zigbuild (`.2.17`: link against glibc 2.17).
    pub zig_suffix: &'static str,
    /// FMI 2.0 platform folder (`binaries/<folder>/`), if FMI 2.0 FMUs carry this library.
    pub fmi2: Option<&'static str>,
    /// FMI 3.0 platform tuple (`binaries/<tuple>/`), if FMI 3.0 FMUs carry this library.
    pub fmi3: Option<&'static str>,
    /// File name of the library cargo writes (`lib<crate>.so`, `<crate>.dll`, …).
    pub file: &'static str,
    /// Extension of the binary in the FMU (`binaries/<platform>/<modelIdentifier>.<ext>`).
    pub ext: &'static str,
}

/// The oldest macOS the dylibs load on, for both architectures: 11.0, the first macOS for
/// Apple silicon (one value, so that the universal build's members equal the
/// single-architecture builds). Without it zig would stamp its own default (macOS 13.0).
pub const MACOS_DEPLOYMENT_TARGET: &str = "11.0";

/// The library file name cargo gives the cdylib of [`FMU_PACKAGE`] on each kind of OS.
const SO: &str = "libpinjoint_fmu.so";
const DLL: &str = "pinjoint_fmu.dll";
const DYLIB: &str = "libpinjoint_fmu.dylib";

/// Every platform of `--platforms all`, in build order. The universal macOS library is
/// built last: cargo-zigbuild makes it from the two single-architecture builds (already
/// up to date by then) and merges them.
pub const ALL: [Platform; 6] = [
    Platform { dir: "x86_64-linux", triple: "x86_64-unknown-linux-gnu", linker: Linker::Zig, zig_suffix: ".2.17", fmi2: Some("linux64"), fmi3: Some("x86_64-linux"), file: SO, ext: "so" },
    Platform { dir: "aarch64-linux", triple: "aarch64-unknown-linux-gnu", linker: Linker::Zig, zig_suffix: ".2.17", fmi2: None, fmi3: Some("aarch64-linux"), file: SO, ext: "so" },
    Platform { dir: "x86_64-windows", triple: "x86_64-pc-windows-gnu", linker: Linker::Cargo, zig_suffix: "", fmi2: Some("win64"), fmi3: Some("x86_64-windows"), file: DLL, ext: "dll" },
    Platform { dir: "x86_64-darwin", triple: "x86_64-apple-darwin", linker: Linker::Zig, zig_suffix: "", fmi2: None, fmi3: Some("x86_64-darwin"), file: DYLIB, ext: "dylib" },
    Platform { dir: "aarch64-darwin", triple: "aarch64-apple-darwin", linker: Linker::Zig, zig_suffix: "", fmi2: None, fmi3: Some("aarch64-darwin"), file: DYLIB, ext: "dylib" },
    Platform { dir: "universal-darwin", triple: "universal2-apple-darwin", linker: Linker::Zig, zig_suffix: "", fmi2: Some("darwin64"), fmi3: None, file: DYLIB, ext: "dylib" },
];

/// The platform of `--platforms host` (the default): this machine's, built by plain
/// `cargo build` into `target/release/` (fast; on Linux it needs the build machine's
/// glibc and libgcc_s).
pub fn host() -> Result<Platform, BuildError> {
    let (fmi2, fmi3, file, ext) = match (std::env::consts::OS, std::env::consts::ARCH) {
        ("linux", "x86_64") => (Some("linux64"), Some("x86_64-linux"), SO, "so"),
        ("linux", "x86") => (Some("linux32"), Some("x86-linux"), SO, "so"),
        ("linux", "aarch64") => (None, Some("aarch64-linux"), SO, "so"),
        ("macos", "x86_64") => (Some("darwin64"), Some("x86_64-darwin"), DYLIB, "dylib"),
        ("macos", "aarch64") => (Some("darwin64"), Some("aarch64-darwin"), DYLIB, "dylib"),
        ("windows", "x86_64") => (Some("win64"), Some("x86_64-windows"), DLL, "dll"),
        (os, arch) => return Err(BuildError::UnsupportedHost { os, arch }),
    };
    Ok(Platform { dir: "host", triple: "", linker: Linker::Cargo, zig_suffix: "", fmi2, fmi3, file, ext })
}

/// The platforms named by `--platforms`: `all`, `host`, or a comma-separated list of
/// [`Platform::dir`] names.
pub fn select(spec: &str) -> Result<Vec<Platform>, BuildError> {
    match spec {
        "host" => Ok(vec![host()?]),
        "all" => Ok(ALL.to_vec()),
        list => list
            .split(',')
            .map(|name| {
                ALL.iter().copied().find(|p| p.dir == name.trim()).ok_or_else(|| BuildError::UnknownPlatform {
                    name: name.to_owned(),
                    known: ALL.iter().map(|p| p.dir).collect::<Vec<_>>().join(", "),
                })
            })
            .collect(),
    }
}

/// Where [`build_library`] leaves the library of `p`: `target/fmu/platforms/<dir>/<file>`.
pub fn kept_library(target: &Path, p: &Platform) -> PathBuf {
    target.join("fmu").join("platforms").join(p.dir).join(p.file)
}

/// Build the FMU cdylib of [`FMU_PACKAGE`] for the platform `p` in release, copy it to
/// [`kept_library`] and return that path. `root` is the workspace, `target` its target
/// directory. Cargo's own up-to-date check makes a repeated call cheap.
pub fn build_library(root: &Path, target: &Path, p: &Platform) -> Result<PathBuf, BuildError> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let zig_target = format!("{}{}", p.triple, p.zig_suffix);
    let (program, mut args): (String, Vec<&str>) = match (p.linker, p.triple.is_empty()) {
        (Linker::Cargo, true) => (cargo, vec!["build"]),
        (Linker::Cargo, false) => (cargo, vec!["build", "--target", p.triple]),
        // Called directly (not as `cargo zigbuild`): the first argument is the subcommand.
        (Linker::Zig, _) => ("cargo-zigbuild".into(), vec!["zigbuild", "--target", &zig_target]),
    };
    // --locked: the FMU is built from the dependency versions in Cargo.lock, never re-resolved.
    args.extend(["--locked", "--release", "--lib", "-p", FMU_PACKAGE]);
    eprintln!("fmu_build: {program} {}", args.join(" "));
    let mut command = Command::new(&program);
    command.args(&args).current_dir(root).env("CARGO_TARGET_DIR", target);
    if p.triple.contains("apple-darwin") {
        command.env("MACOSX_DEPLOYMENT_TARGET", MACOS_DEPLOYMENT_TARGET);
    }
    let status = command.status().map_err(|source| BuildError::Spawn {
        program: program.clone(),
        source,
        hint: if p.linker == Linker::Zig {
            " (install the pinned cargo-zigbuild and ziglang: \
             pip install -r tests/platforms/requirements.txt into a venv and put its bin/ on PATH; \
             tests/platforms/run.sh does)"
        } else {
            ""
        },
    })?;
    if !status.success() {
        return Err(BuildError::Build { package: FMU_PACKAGE, triple: p.triple, status });
    }
    let built = if p.triple.is_empty() { target.join("release") } else { target.join(p.triple).join("release") }.join(p.file);
    if p.triple.is_empty() {
        // The host build is packaged from where cargo wrote it (no copy kept).
        return Ok(built);
    }
    let kept = kept_library(target, p);
    let dir = kept.parent().ok_or_else(|| BuildError::NoParent(kept.clone()))?;
    std::fs::create_dir_all(dir).map_err(BuildError::io("creating", dir))?;
    std::fs::copy(&built, &kept).map_err(|source| BuildError::Copy { from: built.clone(), to: kept.clone(), source })?;
    Ok(kept)
}

#[cfg(test)]
mod tests {
    use super::select;

    /// An unknown name is refused, naming it and every known platform.
    #[test]
    fn unknown_platform_lists_the_known_ones() {
        let Err(e) = select("x86_64-linux,mars") else { panic!("mars is no platform") };
        let e = e.to_string();
        assert_eq!(
            e,
            "--platforms: unknown platform 'mars' (known: all, host, x86_64-linux, aarch64-linux, x86_64-windows, \
             x86_64-darwin, aarch64-darwin, universal-darwin)"
        );
    }
}
