//! The `.fmu` archive of either standard, written reproducibly (fixed time stamps).

use crate::error::BuildError;
use crate::extras;
use fmi_layer::core::variables::ModelInfo;
use std::io::Write;
use std::path::Path;
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipWriter};

/// Write the archive `path` of either standard: `modelDescription.xml` (`xml`), each
/// `(platform folder, library, extension)` as `binaries/<folder>/<modelIdentifier>.<ext>`,
/// `documentation/index.html` and the shared `extras` (licences, model.png). A fixed time
/// stamp keeps the archive reproducible.
pub(crate) fn write_fmu<'a>(
    path: &Path,
    info: &ModelInfo,
    xml: String,
    libraries: impl Iterator<Item = (&'a str, &'a Path, &'a str)>,
    extras: &[extras::Entry],
) -> Result<(), BuildError> {
    let file = std::fs::File::create(path).map_err(BuildError::io("creating", path))?;
    let mut zip = ZipWriter::new(file);
    let opts = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Deflated)
        .last_modified_time(DateTime::default());
    let mut entries: Vec<(String, Vec<u8>, u32)> = vec![("modelDescription.xml".into(), xml.into_bytes(), 0o644)];
    for (folder, library, ext) in libraries {
        let binary = std::fs::read(library).map_err(BuildError::io("reading", library))?;
        entries.push((format!("binaries/{folder}/{}.{ext}", info.model_identifier), binary, 0o755));
    }
    entries.push(("documentation/index.html".into(), (info.documentation)().into_bytes(), 0o644));
    entries.extend(extras.iter().map(|(n, b)| (n.clone(), b.clone(), 0o644)));
    for (name, data, mode) in entries {
        let zip_error = |source| BuildError::Zip { path: path.to_path_buf(), source };
        zip.start_file(name.as_str(), opts.unix_permissions(mode)).map_err(zip_error)?;
        zip.write_all(&data).map_err(|e| zip_error(e.into()))?;
    }
    zip.finish().map_err(|source| BuildError::Zip { path: path.to_path_buf(), source })?;
    Ok(())
}
