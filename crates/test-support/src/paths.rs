//! The workspace's folders, for tests that read committed files outside their own crate.

use std::path::{Path, PathBuf};

/// The workspace root (the folder of the top-level Cargo.toml).
pub fn workspace_root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// `relative` (a path with `/` separators) under the workspace root.
pub fn in_workspace(relative: &str) -> PathBuf {
    workspace_root().join(relative)
}
