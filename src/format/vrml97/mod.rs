//! The VRML97 reader (ISO/IEC 14772-1): the node tree, geometry, lights,
//! viewpoints, PROTO expansion, and TimeSensor → interpolator → ROUTE chains
//! imported as animation tracks.

mod animation;
mod appearance;
mod build;
mod geometry;
mod hanim;
mod text;
mod touch_clips;
pub mod write;
mod write_morph;
mod write_text;

use super::syntax::{self, Options, Parsed};
use super::{LoadError, Loaded};
use crate::scene::SourceFormat;
use std::path::Path;

/// Reads a VRML97 file's bytes (already decompressed).
pub fn read(bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    read_nested(bytes, path, 0)
}

pub(crate) fn read_nested(bytes: &[u8], path: &Path, depth: usize) -> Result<Loaded, LoadError> {
    let parsed = syntax::parse(bytes, Options::new(true));
    let mut loaded = build_parsed(&parsed, path, depth)?;
    loaded.scene.format = SourceFormat::Vrml97;
    Ok(loaded)
}

/// Builds the scene of a parsed VRML97-style node tree (VRML97, and both
/// X3D encodings once their nodes are mapped): the parse's error and
/// warnings become the load's, positioned in `path`.
pub(crate) fn build_parsed(
    parsed: &Parsed,
    path: &Path,
    depth: usize,
) -> Result<Loaded, LoadError> {
    let mut warnings: Vec<String> = Vec::new();
    if let Some((pos, msg)) = &parsed.error {
        // A passed input limit fails the load, as does an error before any node.
        if parsed.roots.is_empty() || super::limits::tripped().is_some() {
            return Err(LoadError::new(path, pos.line, pos.column, msg.clone()));
        }
        warnings.push(fmt_warning(
            path,
            *pos,
            &format!("{msg} (the rest of the file is skipped)"),
        ));
    }
    for (pos, msg) in &parsed.warnings {
        warnings.push(fmt_warning(path, *pos, msg));
    }
    let mut b = build::Builder::new(path, depth);
    b.build(parsed);
    let mut loaded = b.finish()?;
    warnings.append(&mut loaded.warnings);
    loaded.warnings = warnings;
    Ok(loaded)
}

pub(crate) use super::build_log::fmt_warning;

#[cfg(test)]
mod tests;
