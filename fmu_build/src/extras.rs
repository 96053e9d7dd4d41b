//! Files every FMU carries besides its binaries and modelDescription (both standards):
//! `documentation/licenses/` (the licence notices of every crate in the FMU library's normal
//! dependency tree, `cargo tree -p pinjoint-fmu -e normal`, and of the Rust standard library,
//! which is linked statically) and `model.png` (a drawing of the pin joint, drawn here).

use crate::error::BuildError;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// One archive entry: path in the FMU, bytes.
pub type Entry = (String, Vec<u8>);

/// (name, version, licence expression, source folder if a registry crate) of every crate of
/// the FMU library's normal dependency tree.
// The row tuple is documented just above; a named type would be a refactor beyond this lint pass.
#[allow(clippy::type_complexity)]
fn crates(cargo: &str, root: &Path, package: &str) -> Result<Vec<(String, String, String, Option<PathBuf>)>, BuildError> {
    let out = Command::new(cargo)
        .args(["tree", "-p", package, "-e", "normal", "--prefix", "none", "-f", "{p}|{l}"])
        .current_dir(root)
        .output()
        .map_err(|source| BuildError::Spawn { program: "cargo tree".into(), source, hint: "" })?;
    if !out.status.success() {
        return Err(BuildError::CargoTree { stderr: String::from_utf8_lossy(&out.stderr).into_owned() });
    }
    let registry = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cargo")))
        .ok_or(BuildError::NoCargoHome)?
        .join("registry/src");
    let mut seen = BTreeSet::new();
    let mut rows = Vec::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let (p, l) = line.split_once('|').ok_or_else(|| BuildError::CargoTreeLine(line.to_owned()))?;
        let mut words = p.split_whitespace();
        let (Some(name), Some(version)) = (words.next(), words.next()) else { continue };
        let version = version.trim_start_matches('v').to_owned();
        let local = p.contains("(/");
        let licence = l.trim_end_matches(" (*)").trim().to_owned();
        if !seen.insert((name.to_owned(), version.clone())) {
            continue;
        }
        let dir = if local {
            None
        } else {
            let folder = format!("{name}-{version}");
            let found = std::fs::read_dir(&registry)
                .map_err(BuildError::io("reading", &registry))?
                .flatten()
                .map(|d| d.path().join(&folder))
                .find(|p| p.is_dir());
            Some(found.ok_or_else(|| BuildError::NoCrateSource { folder, registry: registry.clone() })?)
        };
        rows.push((name.to_owned(), version, licence, dir));
    }
    Ok(rows)
}

fn is_notice(file: &str) -> bool {
    let f = file.to_ascii_uppercase();
    ["LICENSE", "LICENCE", "COPYING", "NOTICE", "COPYRIGHT", "UNLICENSE"].iter().any(|k| f.starts_with(k))
}

/// `documentation/licenses/`: an index and the notice files of each crate.
pub fn licenses(cargo: &str, root: &Path, package: &str) -> Result<Vec<Entry>, BuildError> {
    let mut entries = Vec::new();
    let mut rows = String::new();
    for (name, version, licence, dir) in crates(cargo, root, package)? {
        let mut files = Vec::new();
        if let Some(dir) = &dir {
            let mut names: Vec<String> = std::fs::read_dir(dir)
                .map_err(BuildError::io("reading", dir))?
                .flatten()
                .filter(|d| d.path().is_file())
                .map(|d| d.file_name().to_string_lossy().into_owned())
                .filter(|f| is_notice(f))
                .collect();
            names.sort();
            for f in names {
                let bytes = std::fs::read(dir.join(&f)).map_err(|source| BuildError::Notice { file: f.clone(), krate: name.clone(), source })?;
                let path = format!("{name}-{version}/{f}");
                files.push(format!(r#"<a href="{path}">{f}</a>"#));
                entries.push((format!("documentation/licenses/{path}"), bytes));
            }
        }
        let note = match (&dir, files.is_empty()) {
            (None, _) => "this project (pinjoint), MIT".to_owned(),
            (Some(_), true) => "the crate ships no licence file; its licence is the SPDX expression on the left (texts in rust-std/)".to_owned(),
            (Some(_), false) => files.join(", "),
        };
        rows.push_str(&format!("<tr><td>{name}</td><td>{version}</td><td>{licence}</td><td>{note}</td></tr>\n"));
    }
    // The Rust standard library (core, alloc, std) is linked statically into every Rust cdylib.
    let sysroot = Command::new("rustc").args(["--print", "sysroot"]).output().map_err(BuildError::Rustc)?;
    let doc = PathBuf::from(String::from_utf8_lossy(&sysroot.stdout).trim()).join("share/doc/rust");
    let mut std_files = Vec::new();
    for (sub, prefix) in [(doc.join("licenses"), "rust-std/licenses"), (doc.clone(), "rust-std")] {
        let Ok(rd) = std::fs::read_dir(&sub) else { continue };
        let mut names: Vec<_> = rd.flatten().filter(|d| d.path().is_file()).map(|d| d.file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        for f in names.into_iter().filter(|f| f.ends_with(".txt") || f.starts_with("COPYRIGHT") || f.starts_with("LICENSE")) {
            let bytes = std::fs::read(sub.join(&f)).map_err(|source| BuildError::Notice { file: f.clone(), krate: String::new(), source })?;
            std_files.push(format!(r#"<a href="{prefix}/{f}">{f}</a>"#).replace("rust-std/", ""));
            entries.push((format!("documentation/licenses/{prefix}/{f}"), bytes));
        }
    }
    if std_files.is_empty() {
        return Err(BuildError::NoStdLicences(doc));
    }
    rows.push_str(&format!(
        "<tr><td>Rust standard library (core, alloc, std)</td><td>{}</td><td>MIT OR Apache-2.0</td><td>rust-std/: {}</td></tr>\n",
        String::from_utf8_lossy(&Command::new("rustc").arg("--version").output().map_err(BuildError::Rustc)?.stdout).trim(),
        std_files.join(", ")
    ));
    let index = format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Licences</title></head><body>\n\
         <h1>Licences of the code in this FMU's binaries</h1>\n\
         <p>The binaries are built from this project (MIT) and the Rust crates below, linked statically \
         (<code>cargo tree -p {package} -e normal</code>; crates marked proc-macro and their dependencies \
         run at compile time only and are listed for completeness). Each crate's own notice files are \
         in the folder named for it.</p>\n\
         <table border=\"1\"><tr><th>crate</th><th>version</th><th>licence (SPDX)</th><th>notices</th></tr>\n{rows}</table>\n</body></html>\n"
    );
    entries.insert(0, ("documentation/licenses/index.html".into(), index.into_bytes()));
    Ok(entries)
}

/// `model.png`: the pin (dark disc) in the bush (grey ring) with the clearance exaggerated,
/// the radial load P (red arrow, down) and the rotation omega (blue arc with arrow head).
/// 256 x 256 RGB, drawn from distance functions; written as a PNG with stored (uncompressed)
/// deflate blocks, so no image crate is needed.
pub fn model_png() -> Vec<u8> {
    const N: usize = 256;
    let c = (N as f64 / 2.0, N as f64 / 2.0 + 10.0);
    let mut img = vec![[255u8; 3]; N * N];
    let seg = |p: (f64, f64), a: (f64, f64), b: (f64, f64)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
    };
    for y in 0..N {
        for x in 0..N {
            let p = (x as f64 + 0.5, y as f64 + 0.5);
            let r = ((p.0 - c.0).powi(2) + (p.1 - c.1).powi(2)).sqrt();
            let ang = (p.1 - c.1).atan2(p.0 - c.0);
            let mut px = [255u8; 3];
            if (78.0..100.0).contains(&r) {
                px = [170, 170, 170]; // bush
            }
            if r < 70.0 {
                px = [60, 60, 70]; // pin
            }
            if (70.0..78.0).contains(&r) && (ang - std::f64::consts::FRAC_PI_2).abs() < 0.6 {
                px = [230, 200, 60]; // grease film in the loaded zone
            }
            // load arrow P: from above, through the pin centre, pointing down
            let tip = (c.0, c.1 + 40.0);
            if seg(p, (c.0, c.1 - 118.0), (c.0, tip.1 - 12.0)) < 3.0 || (tip.1 - p.1 >= 0.0 && tip.1 - p.1 < 18.0 && (p.0 - c.0).abs() < (tip.1 - p.1) * 0.6) {
                px = [200, 30, 30];
            }
            // omega: arc of radius 45 from -150 to -30 degrees with a head at -30
            let arc = (r - 45.0).abs();
            let deg = ang.to_degrees();
            if arc < 2.5 && (-150.0..-35.0).contains(&deg) {
                px = [40, 80, 210];
            }
            let h = (c.0 + 45.0 * (-30f64).to_radians().cos(), c.1 + 45.0 * (-30f64).to_radians().sin());
            if seg(p, h, (h.0 - 12.0, h.1 - 4.0)) < 2.5 || seg(p, h, (h.0 - 2.0, h.1 - 13.0)) < 2.5 {
                px = [40, 80, 210];
            }
            img[y * N + x] = px;
        }
    }
    let mut raw = Vec::with_capacity(N * (3 * N + 1));
    for row in img.chunks(N) {
        raw.push(0); // filter: none
        for px in row {
            raw.extend_from_slice(px);
        }
    }
    png(N as u32, N as u32, &raw)
}

/// A PNG of 8-bit RGB scanlines `raw` (each prefixed by its filter byte).
fn png(w: u32, h: u32, raw: &[u8]) -> Vec<u8> {
    use fmi_layer::core::bytes::crc32;
    let mut z = vec![0x78, 0x01];
    let blocks: Vec<&[u8]> = raw.chunks(65535).collect();
    for (i, b) in blocks.iter().enumerate() {
        z.push(u8::from(i + 1 == blocks.len()));
        let n = b.len() as u16;
        z.extend_from_slice(&n.to_le_bytes());
        z.extend_from_slice(&(!n).to_le_bytes());
        z.extend_from_slice(b);
    }
    let (mut a, mut b) = (1u32, 0u32);
    for &x in raw {
        a = (a + u32::from(x)) % 65521;
        b = (b + a) % 65521;
    }
    z.extend_from_slice(&((b << 16) | a).to_be_bytes());
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        out.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        out.extend_from_slice(&body);
        out.extend_from_slice(&crc32(&body).to_be_bytes());
    };
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&w.to_be_bytes());
    ihdr.extend_from_slice(&h.to_be_bytes());
    ihdr.extend_from_slice(&[8, 2, 0, 0, 0]);
    chunk(b"IHDR", &ihdr);
    chunk(b"IDAT", &z);
    chunk(b"IEND", &[]);
    out
}
