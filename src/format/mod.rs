//! Readers and writers for scene files. Every reader reports errors as
//! `path:line:column: message` and never panics.

mod error;
pub mod obj;
pub use error::LoadError;

use crate::scene::Scene;
use std::path::Path;

/// A loaded scene plus what the reader could not fully use.
#[derive(Debug, Default)]
pub struct Loaded {
    pub scene: Scene,
    /// Non-fatal problems (unknown node, unsupported feature), each already
    /// formatted as `path:line:column: message`.
    pub warnings: Vec<String>,
}

/// Loads any supported file from disk, detecting the format by content.
pub fn load(path: &Path) -> Result<Loaded, LoadError> {
    let bytes = std::fs::read(path).map_err(|e| LoadError::new(path, 0, 0, e.to_string()))?;
    load_bytes(&bytes, path)
}

/// Loads a file's contents; `path` names it in messages and resolves
/// relative references (Inline, File, mtllib).
pub fn load_bytes(_bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    // OBJ has no header line to detect it by: go by the name.
    if obj::is_obj_path(path) {
        return obj::read(_bytes, path);
    }
    Err(LoadError::new(path, 0, 0, "no reader for this file yet"))
}

/// The demo scene bundled in the binary (`assets/demo.wrl`).
pub fn demo() -> Result<Loaded, LoadError> {
    load_bytes(
        include_bytes!("../../assets/demo.wrl"),
        Path::new("assets/demo.wrl"),
    )
}
