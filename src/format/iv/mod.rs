//! The Open Inventor (ASCII 2.0/2.1) and VRML 1.0 reader: Inventor's
//! traversal state (property nodes affect later siblings, Separators save
//! and restore) turned into the scene tree.

mod animated;
mod binary;
mod binary_fields;
mod build;
mod coin_grid;
mod copies;
mod file_node;
mod kits;
mod morph;
mod shapes;
mod state;
mod text;
mod texture;
pub mod write;
mod write_morph;
mod write_text;

use super::build_log::fmt_warning;
use super::syntax::{self, Options};
use super::{LoadError, Loaded};
use crate::scene::SourceFormat;
use std::path::Path;

/// Reads an Inventor or VRML 1.0 file (`vrml1` picks the dialect's defaults).
pub fn read_nested(
    bytes: &[u8],
    path: &Path,
    depth: usize,
    vrml1: bool,
) -> Result<Loaded, LoadError> {
    let parsed = syntax::parse(bytes, Options::new(false));
    let mut warnings = Vec::new();
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
    build(&parsed, path, depth, vrml1, warnings)
}

/// Reads a binary Inventor file (`binary`); errors name the byte offset.
pub fn read_binary_nested(bytes: &[u8], path: &Path, depth: usize) -> Result<Loaded, LoadError> {
    let parsed = binary::parse(bytes)
        .map_err(|(at, msg)| LoadError::new(path, 0, 0, format!("byte {at}: {msg}")))?;
    build(&parsed, path, depth, false, Vec::new())
}

/// Builds the scene of parsed nodes; `warnings` (the parser's) come first.
fn build(
    parsed: &syntax::Parsed,
    path: &Path,
    depth: usize,
    vrml1: bool,
    mut warnings: Vec<String>,
) -> Result<Loaded, LoadError> {
    let mut b = build::Builder::new(path, depth, vrml1);
    b.build(parsed);
    let mut loaded = b.finish()?;
    loaded.scene.format = if vrml1 {
        SourceFormat::Vrml1
    } else {
        SourceFormat::Inventor
    };
    warnings.append(&mut loaded.warnings);
    loaded.warnings = warnings;
    Ok(loaded)
}

#[cfg(test)]
mod binary_tests;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod texture_tests;
