//! FMI 3.0 packaging: `target/fmu/fmi3/<model>.fmu` for every model of the registry, with the
//! FMI 3.0 modelDescription.xml (`fmi_layer::fmi3::xml`), the same shared library (it exports
//! both `fmi2*` and `fmi3*` functions) under the FMI 3.0 platform folder, the documentation,
//! the licences and `model.png`, one binary per FMI 3.0 platform tuple that `--platforms` built
//! (`x86_64-linux` alone for the default host build on Linux x86-64).

use crate::error::BuildError;
use crate::extras::Entry;
use fmi_layer::core::variables::ModelInfo;
use fmi_layer::fmi3::xml::model_description;
use std::path::{Path, PathBuf};


/// Write `<out_dir>/fmi3/<modelIdentifier>.fmu` with `binaries`: (platform tuple, library path,
/// extension) per platform, and the shared `extras` (licences, model.png).
pub fn package(info: &ModelInfo, binaries: &[(&str, PathBuf, &str)], out_dir: &Path, extras: &[Entry]) -> Result<PathBuf, BuildError> {
    let xml = model_description(info)?;
    let dir = out_dir.join("fmi3");
    std::fs::create_dir_all(&dir).map_err(BuildError::io("creating", &dir))?;
    let path = dir.join(format!("{}.fmu", info.model_identifier));
    let libraries = binaries.iter().map(|(platform, library, ext)| (*platform, library.as_path(), *ext));
    crate::archive::write_fmu(&path, info, xml, libraries, extras)?;
    Ok(path)
}

