//! The FMU the importer tests load: `$<env_var>` when set (tests/fmu_harness/run.sh points it at
//! `target/fmu/…`), else the cdylib of this very build packaged as an FMU. That cdylib is
//! `target/<profile>/deps/libpinjoint_fmu.so`, beside the test executable; `cargo test` does not
//! refresh the copy in `target/<profile>/`, which may be stale.

use fmi_layer::core::variables::ModelInfo;
use fmi_layer::fmi2::xml::model_description;
use std::io::Write;
use std::path::PathBuf;

/// The FMU of `info` to import: `$env_var` if set, else this build's cdylib packaged into a
/// temporary `.fmu` named with `tag`.
pub fn fmu_path(env_var: &str, info: &ModelInfo, tag: &str) -> PathBuf {
    if let Some(p) = std::env::var_os(env_var) {
        return PathBuf::from(p);
    }
    let exe = std::env::current_exe().unwrap();
    let lib = exe.parent().unwrap().join("libpinjoint_fmu.so");
    assert!(lib.is_file(), "{} not found (the cdylib of this build)", lib.display());
    let path = std::env::temp_dir().join(format!("pinjoint-{tag}-{}.fmu", std::process::id()));
    let mut zip = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
    let opts = zip::write::SimpleFileOptions::default();
    zip.start_file("modelDescription.xml", opts).unwrap();
    zip.write_all(model_description(info).unwrap().as_bytes()).unwrap();
    zip.start_file(format!("binaries/linux64/{}.so", info.model_identifier), opts).unwrap();
    zip.write_all(&std::fs::read(&lib).unwrap()).unwrap();
    zip.finish().unwrap();
    path
}

/// The value reference of `name` in `info`'s table.
// Not used by every test that includes this module.
#[allow(dead_code)]
pub fn vr(info: &ModelInfo, name: &str) -> u32 {
    info.variables[info.index_by_name(name).unwrap_or_else(|| panic!("no variable {name}"))].value_reference
}

/// The FMU of `info` (see [`fmu_path`]) imported by the `fmi` crate (which unpacks it), its
/// GUID checked; an archive packaged by the test is removed again.
pub fn import(env_var: &str, info: &ModelInfo, tag: &str) -> fmi::fmi2::import::Fmi2Import {
    use fmi::traits::FmiImport;
    let path = fmu_path(env_var, info, tag);
    let import: fmi::fmi2::import::Fmi2Import = fmi::import::from_path(&path).expect("the fmi crate imports the FMU");
    assert_eq!(import.model_description().guid, info.guid());
    if std::env::var_os(env_var).is_none() {
        let _ = std::fs::remove_file(&path);
    }
    import
}

/// A Co-Simulation instance `name` of `import` (logging on), its experiment set up at t = 0
/// without tolerance or stop time.
// Not used by every test that includes this module.
#[allow(dead_code)]
pub fn cs_instance(import: &fmi::fmi2::import::Fmi2Import, name: &str) -> fmi::fmi2::instance::InstanceCS {
    use fmi::fmi2::instance::Common;
    let mut inst = import.instantiate_cs(name, false, true).expect("instantiate");
    inst.setup_experiment(None, 0.0, None).unwrap();
    inst
}
