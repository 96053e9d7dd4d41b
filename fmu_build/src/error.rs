//! [`BuildError`]: everything that can stop `fmu_build`, each variant naming what failed.
//! `main` prints it as `fmu_build: error: <message>` on stderr and exits with status 1.

use std::path::PathBuf;
use std::process::ExitStatus;

/// Why `fmu_build` could not build or package the FMUs.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// `--platforms` was the last argument.
    #[error("--platforms needs a value: all, host or a list of platforms")]
    MissingPlatforms,
    /// An argument `fmu_build` does not know.
    #[error("unknown argument '{0}' (usage: fmu_build [--platforms host|all|<dir>,...])")]
    UnknownArgument(String),
    /// A `--platforms` name that is none of `all`, `host` or a [`Platform::dir`](crate::platforms::Platform::dir).
    #[error("--platforms: unknown platform '{name}' (known: all, host, {known})")]
    UnknownPlatform {
        /// The name given.
        name: String,
        /// The known platform folder names, comma-separated (`platforms::ALL`).
        known: String,
    },
    /// `--platforms host` on an OS/architecture with no FMI platform folder.
    #[error("no FMI platform folder for {os}/{arch}")]
    UnsupportedHost {
        /// `std::env::consts::OS`.
        os: &'static str,
        /// `std::env::consts::ARCH`.
        arch: &'static str,
    },
    /// The manifest folder of `fmu_build` has no parent (the workspace root).
    #[error("no workspace root")]
    NoWorkspaceRoot,
    /// A path with no parent folder where one was needed.
    #[error("no parent folder of {}", .0.display())]
    NoParent(PathBuf),
    /// Neither `CARGO_HOME` nor `HOME` is set (the cargo registry's sources are not found).
    #[error("neither CARGO_HOME nor HOME is set")]
    NoCargoHome,
    /// An I/O error on a file or folder: `action` is what was being done to `path`.
    #[error("{action} {}: {source}", path.display())]
    Io {
        /// What was being done: "creating", "reading".
        action: &'static str,
        /// The file or folder.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// Copying a built library to where it is kept failed.
    #[error("copying {} to {}: {source}", from.display(), to.display())]
    Copy {
        /// The library cargo wrote.
        from: PathBuf,
        /// Where it was to be kept.
        to: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A program could not be started; `hint` says how to install it (empty if none).
    #[error("running {program}: {source}{hint}")]
    Spawn {
        /// The program (and subcommand) started.
        program: String,
        /// The operating system's error.
        source: std::io::Error,
        /// How to install the program, with a leading space, or empty.
        hint: &'static str,
    },
    /// `rustc` (asked for its sysroot or version) could not be started.
    #[error("rustc: {0}")]
    Rustc(#[source] std::io::Error),
    /// Cargo ran but failed to build the FMU library for a platform.
    #[error(
        "building {package} for {} failed ({status}); the Rust target needs `rustup target add {}`{}",
        build_for(.triple),
        rustup_targets(.triple),
        linker_hint(.triple)
    )]
    Build {
        /// The Cargo package built.
        package: &'static str,
        /// The Rust target triple, empty for the host.
        triple: &'static str,
        /// Cargo's exit status.
        status: ExitStatus,
    },
    /// `cargo tree` ran but failed; its stderr.
    #[error("cargo tree failed: {stderr}")]
    CargoTree {
        /// What cargo tree wrote on stderr.
        stderr: String,
    },
    /// A line of `cargo tree`'s output without the `|` between package and licence.
    #[error("unexpected cargo tree line {0}")]
    CargoTreeLine(String),
    /// A registry crate of the dependency tree whose source folder is not in the registry.
    #[error("no source of {folder} under {}", registry.display())]
    NoCrateSource {
        /// `<name>-<version>`.
        folder: String,
        /// The cargo registry's `src` folder searched.
        registry: PathBuf,
    },
    /// A notice file of a crate (or of the standard library, `krate` empty) could not be read.
    #[error("reading {file}{}{krate}: {source}", of(.krate))]
    Notice {
        /// The file's name.
        file: String,
        /// The crate's name, or empty for the Rust standard library.
        krate: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The Rust toolchain's `share/doc/rust` folder holds no licence file.
    #[error("no licence files of the Rust standard library under {}", .0.display())]
    NoStdLicences(PathBuf),
    /// The model's variable table gives no valid modelDescription.xml.
    #[error(transparent)]
    Xml(#[from] fmi_layer::XmlError),
    /// Writing the FMU archive failed.
    #[error("writing {}: {source}", path.display())]
    Zip {
        /// The FMU being written.
        path: PathBuf,
        /// The zip writer's error (I/O errors included).
        source: zip::result::ZipError,
    },
}

/// What [`BuildError::Build`] built for: `triple`, or "the host" if it is empty.
fn build_for(triple: &str) -> &str {
    if triple.is_empty() { "the host" } else { triple }
}

/// The `rustup target add` arguments that `triple` needs.
fn rustup_targets(triple: &str) -> &str {
    if triple.starts_with("universal2") { "x86_64-apple-darwin aarch64-apple-darwin" } else { triple }
}

/// The linker a Windows GNU target needs besides its Rust target, or nothing.
fn linker_hint(triple: &str) -> &'static str {
    if triple.contains("windows-gnu") { " and MinGW-w64's gcc (Debian: gcc-mingw-w64-x86-64)" } else { "" }
}

/// " of " before a crate's name, nothing for the standard library's files (`krate` empty).
fn of(krate: &str) -> &'static str {
    if krate.is_empty() { "" } else { " of " }
}

impl BuildError {
    /// An [`BuildError::Io`] for `action` on `path`, for `map_err`.
    pub fn io(action: &'static str, path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> Self {
        let path = path.into();
        move |source| Self::Io { action, path, source }
    }
}

#[cfg(test)]
mod tests {
    use super::BuildError;
    use std::path::PathBuf;

    /// The messages are the ones `fmu_build` printed when its errors were strings.
    #[test]
    fn messages_name_what_failed() {
        let not_found = || std::io::Error::from(std::io::ErrorKind::NotFound);
        let e = BuildError::io("creating", "/x/fmu")(not_found());
        assert_eq!(e.to_string(), format!("creating /x/fmu: {}", not_found()));
        let e = BuildError::Notice { file: "LICENSE".into(), krate: "zip".into(), source: not_found() };
        assert_eq!(e.to_string(), format!("reading LICENSE of zip: {}", not_found()));
        let e = BuildError::Notice { file: "COPYRIGHT".into(), krate: String::new(), source: not_found() };
        assert_eq!(e.to_string(), format!("reading COPYRIGHT: {}", not_found()));
        let e = BuildError::Spawn { program: "cargo tree".into(), source: not_found(), hint: "" };
        assert_eq!(e.to_string(), format!("running cargo tree: {}", not_found()));
        let e = BuildError::Copy { from: PathBuf::from("/a"), to: PathBuf::from("/b"), source: not_found() };
        assert_eq!(e.to_string(), format!("copying /a to /b: {}", not_found()));
        assert_eq!(
            BuildError::UnknownPlatform { name: "mars".into(), known: "x86_64-linux, win".into() }.to_string(),
            "--platforms: unknown platform 'mars' (known: all, host, x86_64-linux, win)"
        );
        assert_eq!(BuildError::UnsupportedHost { os: "plan9", arch: "mips" }.to_string(), "no FMI platform folder for plan9/mips");
    }

    /// The failed-build message names the target to add, and MinGW for Windows.
    #[cfg(unix)]
    #[test]
    fn build_failure_says_what_to_install() {
        use std::os::unix::process::ExitStatusExt;
        let status = std::process::ExitStatus::from_raw(101 << 8);
        let e = BuildError::Build { package: "pinjoint-fmu", triple: "x86_64-pc-windows-gnu", status };
        assert_eq!(
            e.to_string(),
            "building pinjoint-fmu for x86_64-pc-windows-gnu failed (exit status: 101); the Rust target needs \
             `rustup target add x86_64-pc-windows-gnu` and MinGW-w64's gcc (Debian: gcc-mingw-w64-x86-64)"
        );
        let e = BuildError::Build { package: "pinjoint-fmu", triple: "universal2-apple-darwin", status };
        assert!(e.to_string().contains("`rustup target add x86_64-apple-darwin aarch64-apple-darwin`"), "{e}");
        let e = BuildError::Build { package: "pinjoint-fmu", triple: "", status };
        assert!(e.to_string().starts_with("building pinjoint-fmu for the host failed"), "{e}");
    }
}
