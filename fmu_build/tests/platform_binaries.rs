//! What every cross-built FMU binary exports and needs, read from the files themselves
//! (the `object` crate parses ELF, PE and Mach-O): the 44 functions of the FMI 2.0 API,
//! the dynamic libraries each one loads (no libgcc_s, no MinGW runtime DLL; only
//! libSystem on macOS), glibc symbol versions at most 2.17, the architecture, and for
//! macOS the load commands (a dylib with its install name and minimum OS version) and
//! that the universal darwin64 binary holds exactly the two single-architecture builds.
//! The macOS binaries cannot be run on this Linux machine: this is their only check.
//!
//! Needs `cargo run --release -p fmu_build -- --platforms all` first (tests/platforms/run.sh
//! runs it, then this test with `--ignored`); `PINJOINT_PLATFORMS_DIR` overrides
//! `target/fmu/platforms`.

use object::macho::{LC_BUILD_VERSION, LC_ID_DYLIB, LC_LOAD_DYLIB, LC_VERSION_MIN_MACOSX, MH_DYLIB};
use object::read::elf::ElfFile64;
use object::read::macho::{FatArch, LoadCommandVariant, MachOFatFile32, MachOFile64};
use object::{Architecture, BinaryFormat, Endianness, Object};
use std::collections::BTreeSet;
use std::path::PathBuf;

/// The FMI 2.0 API (standard 2.0.x, section 2.1 common, 3.2 Model Exchange, 4.2 Co-Simulation).
const FMI2_FUNCTIONS: [&str; 44] = [
    "fmi2GetTypesPlatform", "fmi2GetVersion", "fmi2SetDebugLogging", "fmi2Instantiate", "fmi2FreeInstance",
    "fmi2SetupExperiment", "fmi2EnterInitializationMode", "fmi2ExitInitializationMode", "fmi2Terminate", "fmi2Reset",
    "fmi2GetReal", "fmi2GetInteger", "fmi2GetBoolean", "fmi2GetString", "fmi2SetReal", "fmi2SetInteger",
    "fmi2SetBoolean", "fmi2SetString", "fmi2GetFMUstate", "fmi2SetFMUstate", "fmi2FreeFMUstate",
    "fmi2SerializedFMUstateSize", "fmi2SerializeFMUstate", "fmi2DeSerializeFMUstate", "fmi2GetDirectionalDerivative",
    // Model Exchange
    "fmi2EnterEventMode", "fmi2NewDiscreteStates", "fmi2EnterContinuousTimeMode", "fmi2CompletedIntegratorStep",
    "fmi2SetTime", "fmi2SetContinuousStates", "fmi2GetDerivatives", "fmi2GetEventIndicators",
    "fmi2GetContinuousStates", "fmi2GetNominalsOfContinuousStates",
    // Co-Simulation
    "fmi2SetRealInputDerivatives", "fmi2GetRealOutputDerivatives", "fmi2DoStep", "fmi2CancelStep", "fmi2GetStatus",
    "fmi2GetRealStatus", "fmi2GetIntegerStatus", "fmi2GetBooleanStatus", "fmi2GetStringStatus",
];

/// The C-linkage test hook tests/platforms/host.c calls (panic containment).
const TEST_HOOK: &str = "pinjoint_test_force_panic";

fn platforms_dir() -> PathBuf {
    std::env::var_os("PINJOINT_PLATFORMS_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/fmu/platforms"))
}

fn read(dir: &str, file: &str) -> Vec<u8> {
    let path = platforms_dir().join(dir).join(file);
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e} (run `cargo run --release -p fmu_build -- --platforms all`)", path.display()))
}

/// The exported names (Mach-O's leading underscore removed) that start with `fmi2` or
/// are the test hook.
fn fmi_exports(file: &object::File, strip_underscore: bool) -> BTreeSet<String> {
    file.exports()
        .unwrap()
        .filter_map(|e| match e.unwrap().name() {
            object::NameOrOrdinal::Name(n) => Some(String::from_utf8_lossy(n).into_owned()),
            object::NameOrOrdinal::Ordinal(_) => None,
        })
        .map(|n| if strip_underscore { n.strip_prefix('_').map(str::to_owned).unwrap_or(n) } else { n })
        .filter(|n| n.starts_with("fmi2") || n == TEST_HOOK)
        .collect()
}

fn expected_exports() -> BTreeSet<String> {
    FMI2_FUNCTIONS.iter().chain([&TEST_HOOK]).map(|s| s.to_string()).collect()
}

/// DT_NEEDED entries and the highest GLIBC_x.y version required, of an ELF shared library.
fn elf_needs(data: &[u8]) -> (Vec<String>, BTreeSet<String>) {
    let elf = ElfFile64::<Endianness>::parse(data).unwrap();
    let endian = elf.endian();
    let sections = elf.elf_section_table();
    let dynamic = sections.dynamic_table(endian, data).unwrap();
    let needed = dynamic
        .iter()
        .filter(|d| d.tag == object::elf::DT_NEEDED)
        .map(|d| String::from_utf8_lossy(dynamic.string(d).unwrap()).into_owned())
        .collect();
    let mut versions = BTreeSet::new();
    if let Some((mut needs, link)) = sections.gnu_verneed(endian, data).unwrap() {
        let strings = sections.strings(endian, data, link).unwrap();
        while let Some((_, mut aux)) = needs.next().unwrap() {
            while let Some(a) = aux.next().unwrap() {
                versions.insert(String::from_utf8_lossy(a.name(endian, strings).unwrap()).into_owned());
            }
        }
    }
    (needed, versions)
}

/// (major, minor) of "GLIBC_2.17"-like names.
fn glibc_version(v: &str) -> Option<(u32, u32)> {
    let mut it = v.strip_prefix("GLIBC_")?.split('.').map(|x| x.parse::<u32>().ok());
    Some((it.next()??, it.next().flatten().unwrap_or(0)))
}

fn check_linux(dir: &str, arch: Architecture) {
    let data = read(dir, "libpinjoint_fmu.so");
    let file = object::File::parse(&*data).unwrap();
    assert_eq!((file.format(), file.architecture()), (BinaryFormat::Elf, arch), "{dir}");
    assert_eq!(fmi_exports(&file, false), expected_exports(), "{dir}: exports");
    let (needed, versions) = elf_needs(&data);
    let allowed = ["libc.so.6", "libm.so.6", "libpthread.so.0", "libdl.so.2", "librt.so.1", "ld-linux-x86-64.so.2", "ld-linux-aarch64.so.1"];
    for lib in &needed {
        assert!(allowed.contains(&lib.as_str()), "{dir}: needs {lib} (allowed: glibc's libraries only; no libgcc_s)");
    }
    assert!(needed.iter().any(|l| l == "libc.so.6"), "{dir}: {needed:?}");
    let glibc: Vec<(u32, u32)> = versions.iter().filter_map(|v| glibc_version(v)).collect();
    let newest = glibc.iter().max().copied().unwrap();
    assert!(newest <= (2, 17), "{dir}: needs GLIBC_{}.{} (baseline 2.17); all: {versions:?}", newest.0, newest.1);
    for v in &versions {
        assert!(v.starts_with("GLIBC_"), "{dir}: needs symbol version {v} (not glibc's)");
    }
    println!("{dir}: needs {needed:?}, newest symbol version GLIBC_{}.{}", newest.0, newest.1);
}

#[test]
#[ignore = "needs `fmu_build --platforms all` (tests/platforms/run.sh)"]
fn linux_x86_64_needs_glibc_2_17_only_and_no_libgcc_s() {
    check_linux("x86_64-linux", Architecture::X86_64);
}

#[test]
#[ignore = "needs `fmu_build --platforms all` (tests/platforms/run.sh)"]
fn linux_aarch64_needs_glibc_2_17_only_and_no_libgcc_s() {
    check_linux("aarch64-linux", Architecture::Aarch64);
}

#[test]
#[ignore = "needs `fmu_build --platforms all` (tests/platforms/run.sh)"]
fn windows_dll_exports_fmi2_and_imports_no_mingw_runtime() {
    let data = read("x86_64-windows", "pinjoint_fmu.dll");
    let file = object::File::parse(&*data).unwrap();
    assert_eq!((file.format(), file.architecture()), (BinaryFormat::Pe, Architecture::X86_64));
    assert_eq!(fmi_exports(&file, false), expected_exports(), "exports");
    let dlls: BTreeSet<String> =
        file.imports().unwrap().map(|i| String::from_utf8_lossy(i.unwrap().library()).to_ascii_lowercase()).collect();
    // Windows' own DLLs only: no libgcc_s_seh-1.dll, libwinpthread-1.dll or libstdc++-6.dll
    // (they are not on a user's machine). bcryptprimitives.dll is part of Windows 10+.
    let system = ["kernel32.dll", "ntdll.dll", "msvcrt.dll", "advapi32.dll", "bcryptprimitives.dll", "ws2_32.dll", "userenv.dll", "ucrtbase.dll"];
    for dll in &dlls {
        assert!(system.contains(&dll.as_str()) || dll.starts_with("api-ms-win-"), "imports {dll}: not a Windows system DLL");
    }
    assert!(dlls.contains("kernel32.dll"), "{dlls:?}");
    println!("x86_64-windows: imports {dlls:?}");
}

/// Checks one thin Mach-O dylib; returns its minimum macOS version (major, minor).
fn check_macho(what: &str, data: &[u8], arch: Architecture) -> (u32, u32) {
    let file = object::File::parse(data).unwrap();
    assert_eq!((file.format(), file.architecture()), (BinaryFormat::MachO, arch), "{what}");
    assert_eq!(fmi_exports(&file, true), expected_exports(), "{what}: exports");
    let macho = MachOFile64::<Endianness>::parse(data).unwrap();
    let endian = macho.endian();
    assert_eq!(object::read::macho::MachHeader::filetype(macho.macho_header(), endian), MH_DYLIB, "{what}: not a dylib");
    let (mut id, mut dylibs, mut min_os) = (None, Vec::new(), None);
    let mut commands = macho.macho_load_commands().unwrap();
    while let Some(cmd) = commands.next().unwrap() {
        match (cmd.cmd(), cmd.variant().unwrap()) {
            (LC_ID_DYLIB, LoadCommandVariant::IdDylib(d)) => id = Some(String::from_utf8_lossy(cmd.string(endian, d.dylib.name).unwrap()).into_owned()),
            (LC_LOAD_DYLIB, LoadCommandVariant::Dylib(d)) => dylibs.push(String::from_utf8_lossy(cmd.string(endian, d.dylib.name).unwrap()).into_owned()),
            (LC_BUILD_VERSION, LoadCommandVariant::BuildVersion(b, _)) => min_os = Some(b.minos.get(endian)),
            (LC_VERSION_MIN_MACOSX, LoadCommandVariant::VersionMin(v)) => min_os = Some(v.version.get(endian)),
            _ => {}
        }
    }
    let id = id.unwrap_or_else(|| panic!("{what}: no LC_ID_DYLIB"));
    assert!(id.ends_with("libpinjoint_fmu.dylib"), "{what}: install name {id}");
    assert!(!dylibs.is_empty(), "{what}: loads no library");
    for d in &dylibs {
        assert_eq!(d, "/usr/lib/libSystem.B.dylib", "{what}: loads {d} (only libSystem expected)");
    }
    let v = min_os.unwrap_or_else(|| panic!("{what}: no minimum OS version load command"));
    let (major, minor) = (v.0 >> 16, (v.0 >> 8) & 0xff);
    // fmu_build's MACOS_DEPLOYMENT_TARGET (11.0, the first macOS for Apple silicon), on both.
    assert_eq!((major, minor), (11, 0), "{what}: needs macOS {major}.{minor}, expected 11.0");
    println!("{what}: install name {id}, loads {dylibs:?}, minimum macOS {major}.{minor}");
    (major, minor)
}

#[test]
#[ignore = "needs `fmu_build --platforms all` (tests/platforms/run.sh)"]
fn macos_single_architecture_dylibs() {
    check_macho("x86_64-darwin", &read("x86_64-darwin", "libpinjoint_fmu.dylib"), Architecture::X86_64);
    check_macho("aarch64-darwin", &read("aarch64-darwin", "libpinjoint_fmu.dylib"), Architecture::Aarch64);
}

#[test]
#[ignore = "needs `fmu_build --platforms all` (tests/platforms/run.sh)"]
fn macos_universal_dylib_holds_both_architectures() {
    let data = read("universal-darwin", "libpinjoint_fmu.dylib");
    let fat = MachOFatFile32::parse(&*data).expect("a universal (fat) Mach-O");
    let mut arches: Vec<Architecture> = Vec::new();
    for a in fat.arches() {
        let member = a.data(&*data).unwrap();
        let arch = a.architecture();
        check_macho(&format!("universal-darwin/{arch:?}"), member, arch);
        // The member is the single-architecture build of the same sources.
        let thin = read(if arch == Architecture::X86_64 { "x86_64-darwin" } else { "aarch64-darwin" }, "libpinjoint_fmu.dylib");
        assert!(member == thin.as_slice(), "universal-darwin/{arch:?} differs from the single-architecture build");
        arches.push(arch);
    }
    arches.sort_by_key(|a| format!("{a:?}"));
    assert_eq!(arches, [Architecture::Aarch64, Architecture::X86_64]);
}
