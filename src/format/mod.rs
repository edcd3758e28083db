//! Readers and writers for scene files. Every reader reports errors as
//! `path:line:column: message` and never panics.

//!
//! Layout: one folder per format, each owning its reader and writer
//! (`iv/` Inventor + VRML 1.0, `vrml97/`, `x3d/` (both encodings, onto
//! the VRML97 builder), `gltf/`, `obj`), the shared reading pieces
//! (`limits`: the input budget every read goes through; `lexer`, `syntax/`
//! with PROTO expansion, `polygons`, `inline`, `gzip`, `sgi_image`, `textures`,
//! `hsv`) and the shared export code (`export/`: write plan, channels,
//! sampling, key note, options, atomic save) beside them.

mod build_log;
mod corner_morph;
mod error;
pub mod export;
pub mod gltf;
pub mod gzip;
pub mod hsv;
pub mod inline;
pub mod iv;
pub mod lexer;
pub mod limits;
mod loaded;
pub mod obj;
mod obj_lines;
mod obj_texture;
pub mod polygons;
pub mod sgi_image;
pub mod syntax;
pub mod text;
pub mod textures;
pub mod vrml97;
pub mod warn_kind;
pub mod x3d;

pub use error::LoadError;
pub use export::{
    keynote, sampling, save, InventorVersion, OutputFormat, SaveError, WriteOptions, WriteReport,
};
pub use loaded::Loaded;

use std::path::Path;

/// Loads any supported file from disk, detecting the format by content,
/// within the default input budget ([`limits::defaults`]).
pub fn load(path: &Path) -> Result<Loaded, LoadError> {
    load_with(path, limits::defaults())
}

/// [`load`] within the given limits.
pub fn load_with(path: &Path, lim: limits::Limits) -> Result<Loaded, LoadError> {
    limits::scope_with(lim, || {
        let mut loaded = load_nested(path, 0)?;
        // animed's own key note, if the file has one, replaces the sampled tracks.
        keynote::apply_to_loaded(&mut loaded, path);
        Ok(loaded)
    })
}

/// Loads a file included `depth` levels deep (Inline / File / WWWInline).
pub(crate) fn load_nested(path: &Path, depth: usize) -> Result<Loaded, LoadError> {
    let bytes = limits::read_file(path).map_err(|e| LoadError::new(path, 0, 0, e.to_string()))?;
    load_bytes_nested(&bytes, path, depth)
}

/// Loads a file's contents; `path` names it in messages and resolves
/// relative references (Inline, File, mtllib).
pub fn load_bytes(bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    load_bytes_with(bytes, path, limits::defaults())
}

/// [`load_bytes`] within the given limits.
pub fn load_bytes_with(
    bytes: &[u8],
    path: &Path,
    lim: limits::Limits,
) -> Result<Loaded, LoadError> {
    limits::scope_with(lim, || {
        limits::charge_bytes(bytes.len() as u64)
            .map_err(|e| LoadError::new(path, 0, 0, e.to_string()))?;
        let mut loaded = load_bytes_nested(bytes, path, 0)?;
        // animed's own key note, if the file has one, replaces the sampled tracks.
        keynote::apply_to_loaded(&mut loaded, path);
        Ok(loaded)
    })
}

fn load_bytes_nested(bytes: &[u8], path: &Path, depth: usize) -> Result<Loaded, LoadError> {
    // A UTF-8 byte-order mark (some Windows editors write one) is not text.
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    if gzip::is_gzip(bytes) {
        let plain = gzip::decompress(bytes).map_err(|m| LoadError::new(path, 0, 0, m))?;
        return load_bytes_nested(&plain, path, depth);
    }
    if gltf::is_gltf(bytes, path) {
        return gltf::read(bytes, path, &gltf::ReadOptions::default(), &read_beside);
    }
    // OBJ has no header line to detect it by: go by the name.
    if obj::is_obj_path(path) {
        return obj::read(bytes, path);
    }
    if x3d::is_xml(bytes) {
        return x3d::read_xml_nested(bytes, path, depth);
    }
    let header = lexer::read_header(bytes)
        .map_err(|e| LoadError::new(path, e.pos.line, e.pos.column, e.message))?;
    match header {
        lexer::Header::Vrml97 => vrml97::read_nested(bytes, path, depth),
        lexer::Header::X3dClassic => x3d::read_classic_nested(bytes, path, depth),
        lexer::Header::Vrml1 => iv::read_nested(bytes, path, depth, true),
        lexer::Header::Inventor2 | lexer::Header::Inventor1 => {
            iv::read_nested(bytes, path, depth, false)
        }
        lexer::Header::InventorBinary => iv::read_binary_nested(bytes, path, depth),
    }
}

/// Reads a file a scene file references (glTF buffers and images) through
/// the input budget.
fn read_beside(path: &Path) -> Result<Vec<u8>, String> {
    limits::read_file(path).map_err(|e| e.to_string())
}

/// What the caller may choose about a load (`--scene`).
#[derive(Clone, Debug, Default)]
pub struct LoadOptions {
    /// glTF: which of the file's scenes to load (default: its `scene`).
    pub scene: Option<usize>,
}

/// [`load`] with options; `scene` applies to glTF files only.
pub fn load_with_options(path: &Path, opts: &LoadOptions) -> Result<Loaded, LoadError> {
    let Some(scene) = opts.scene else {
        return load(path);
    };
    let bytes = limits::read_file(path).map_err(|e| LoadError::new(path, 0, 0, e.to_string()))?;
    if !gltf::is_gltf(&bytes, path) {
        return Err(LoadError::new(
            path,
            0,
            0,
            "--scene applies to glTF files only",
        ));
    }
    gltf::read(
        &bytes,
        path,
        &gltf::ReadOptions { scene: Some(scene) },
        &read_beside,
    )
}

/// The demo scene bundled in the binary (`assets/demo.wrl`).
pub fn demo() -> Result<Loaded, LoadError> {
    load_bytes(
        include_bytes!("../../assets/demo.wrl"),
        Path::new("assets/demo.wrl"),
    )
}
