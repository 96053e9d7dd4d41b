//! FMI 3.0 packaging: `target/fmu/fmi3/<model>.fmu` for every model of the registry, with the
//! FMI 3.0 modelDescription.xml (`fmi_layer::fmi3::xml`), the same shared library (it exports
//! both `fmi2*` and `fmi3*` functions) under the FMI 3.0 platform folder, the documentation,
//! the licences and `model.png`, one binary per FMI 3.0 platform tuple that `--platforms` built
//! (`x86_64-linux` alone for the default host build on Linux x86-64).

use crate::extras::Entry;
use fmi_layer::fmi2::variables::ModelInfo;
use fmi_layer::fmi3::xml::model_description;
use std::io::Write;
use std::path::{Path, PathBuf};
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipWriter};


/// Write `<out_dir>/fmi3/<modelIdentifier>.fmu` with `binaries`: (platform tuple, library path,
/// extension) per platform, and the shared `extras` (licences, model.png).
pub fn package(info: &ModelInfo, binaries: &[(&str, PathBuf, &str)], out_dir: &Path, extras: &[Entry]) -> Result<PathBuf, String> {
    let xml = model_description(info)?;
    let dir = out_dir.join("fmi3");
    std::fs::create_dir_all(&dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
    let path = dir.join(format!("{}.fmu", info.model_identifier));
    let file = std::fs::File::create(&path).map_err(|e| format!("creating {}: {e}", path.display()))?;
    let mut zip = ZipWriter::new(file);
    let opts = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated).last_modified_time(DateTime::default());
    let mut entries: Vec<(String, Vec<u8>, u32)> = vec![("modelDescription.xml".into(), xml.into_bytes(), 0o644)];
    for (platform, library, ext) in binaries {
        let bytes = std::fs::read(library).map_err(|e| format!("reading {}: {e}", library.display()))?;
        entries.push((format!("binaries/{platform}/{}.{ext}", info.model_identifier), bytes, 0o755));
    }
    entries.push(("documentation/index.html".into(), (info.documentation)().into_bytes(), 0o644));
    entries.extend(extras.iter().map(|(n, b)| (n.clone(), b.clone(), 0o644)));
    for (name, data, mode) in entries {
        zip.start_file(name.as_str(), opts.unix_permissions(mode)).map_err(|e| e.to_string())?;
        zip.write_all(&data).map_err(|e| e.to_string())?;
    }
    zip.finish().map_err(|e| e.to_string())?;
    Ok(path)
}

