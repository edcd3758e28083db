//! The container: `.glb` chunks or `.gltf` JSON, parsed and validated by
//! the `gltf` crate, plus the buffers the accessors read from (the GLB
//! binary chunk, `data:` URIs, files beside the `.gltf`).
//!
//! The GLB header is split here rather than by the crate: the spec (§4.4)
//! says unknown chunk types after the binary chunk must be ignored and the
//! header's length is authoritative, and a hand-checked split cannot
//! overflow on a hostile length.

use super::pointer::{from_crate_path, pointer};
use super::uri;
use gltf::Document;
use std::path::Path;

/// A problem with its JSON pointer (`/meshes/3/...`), or `"/"` for the
/// file as a whole; `line`/`column` are known only for JSON syntax errors.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfError {
    pub pointer: String,
    pub message: String,
    pub line: u32,
    pub column: u32,
}

impl GltfError {
    pub fn at(pointer: impl Into<String>, message: impl Into<String>) -> Self {
        GltfError {
            pointer: pointer.into(),
            message: message.into(),
            line: 0,
            column: 0,
        }
    }

    pub fn whole(message: impl Into<String>) -> Self {
        GltfError::at("/", message)
    }
}

impl std::fmt::Display for GltfError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.pointer == "/" {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.pointer, self.message)
        }
    }
}

pub type Result<T> = std::result::Result<T, GltfError>;

/// Extensions whose meaning animed implements (the rest are ignored with a
/// warning when only used, and refused when required).
pub const SUPPORTED_EXTENSIONS: &[&str] = &[
    "KHR_lights_punctual",
    "KHR_materials_unlit",
    "KHR_materials_emissive_strength",
    "KHR_texture_transform",
    "KHR_mesh_quantization",
    super::pointer_anim::EXTENSION,
];

/// Whether `bytes` look like a .glb (magic `glTF`).
pub fn is_glb(bytes: &[u8]) -> bool {
    bytes.starts_with(b"glTF")
}

/// The JSON chunk and the optional BIN chunk of a .glb (spec §4.4).
pub fn split_glb(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>)> {
    let u32_at = |at: usize| -> Option<u32> {
        let b = bytes.get(at..at.checked_add(4)?)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let header = |what: &str| GltfError::whole(format!("not a valid .glb: {what}"));
    let version = u32_at(4).ok_or_else(|| header("the 12-byte header is cut short"))?;
    if version != 2 {
        return Err(header(&format!(
            "container version {version} (only glTF 2.0 is supported)"
        )));
    }
    let length = u32_at(8).ok_or_else(|| header("the 12-byte header is cut short"))? as usize;
    if length > bytes.len() {
        return Err(header(&format!(
            "the header says {length} bytes but the file has {}",
            bytes.len()
        )));
    }
    let body = &bytes[..length];
    let mut at = 12usize;
    let mut json = None;
    let mut bin = None;
    let mut index = 0;
    while at < body.len() {
        let (Some(len), Some(kind)) = (
            u32_at(at).filter(|_| at + 8 <= body.len()),
            u32_at(at + 4).filter(|_| at + 8 <= body.len()),
        ) else {
            return Err(header(&format!("chunk {index} has a cut-short header")));
        };
        let start = at + 8;
        let end = start
            .checked_add(len as usize)
            .filter(|&e| e <= body.len())
            .ok_or_else(|| {
                header(&format!(
                    "chunk {index} says {len} bytes but only {} are left",
                    body.len() - start
                ))
            })?;
        let data = &body[start..end];
        match (&kind.to_le_bytes(), index) {
            (b"JSON", 0) => json = Some(data),
            (_, 0) => return Err(header("the first chunk is not JSON")),
            (b"BIN\0", 1) => bin = Some(data),
            _ => {} // Unknown chunks are skipped (spec §4.4.3.1).
        }
        index += 1;
        // Chunks are 4-byte aligned; a missing final pad is tolerated.
        at = end.saturating_add(3) & !3;
    }
    let json = json.ok_or_else(|| header("there is no JSON chunk"))?;
    Ok((json, bin))
}

/// A JSON syntax error, placed at its line and column.
pub fn json_error(e: &serde_json::Error) -> GltfError {
    let mut err = GltfError::whole(format!("not valid glTF JSON: {e}"));
    err.line = e.line() as u32;
    err.column = e.column() as u32;
    err
}

/// Parses and validates the JSON document. Required extensions animed does
/// not implement fail here, naming them; the crate's own validation errors
/// are reported with their JSON pointer.
pub fn parse_document(json: &[u8], warnings: &mut Vec<String>) -> Result<Document> {
    let root: gltf::json::Root =
        gltf::json::deserialize::from_slice(json).map_err(|e| json_error(&e))?;
    for (i, ext) in root.extensions_required.iter().enumerate() {
        if !SUPPORTED_EXTENSIONS.contains(&ext.as_str()) {
            return Err(GltfError::at(
                pointer(&[&"extensionsRequired", &i]),
                format!(
                    "the file requires the extension {ext}, which animed does not support \
                     (supported: {})",
                    SUPPORTED_EXTENSIONS.join(", ")
                ),
            ));
        }
    }
    for ext in &root.extensions_used {
        if !SUPPORTED_EXTENSIONS.contains(&ext.as_str()) {
            warnings.push(format!(
                "extension {ext} is not supported; the file is shown without it"
            ));
        }
    }
    let version = root.asset.version.as_str();
    if !version.starts_with("2.") {
        return Err(GltfError::at(
            "/asset/version",
            format!("glTF version {version} (only 2.x is supported)"),
        ));
    }
    use gltf::json::validation::Validate;
    let mut errors = Vec::new();
    root.validate(&root, gltf::json::Path::new, &mut |path, e| {
        // Extensions animed supports beyond the crate's list were let
        // through above; every other problem is fatal.
        let ext = matches!(e, gltf::json::validation::Error::Unsupported)
            && path().as_str().starts_with("extensionsRequired");
        if !ext {
            errors.push((path(), e));
        }
    });
    if let Some((path, e)) = errors.first() {
        let more = if errors.len() > 1 {
            format!(" (and {} more problems)", errors.len() - 1)
        } else {
            String::new()
        };
        return Err(GltfError::at(
            from_crate_path(path.as_str()),
            format!("{}{more}", describe(e)),
        ));
    }
    check_gaps(&root)?;
    Ok(Document::from_json_without_validation(root))
}

/// What the crate's validation leaves out (version 1.4.1) and its accessors
/// would unwrap: animation channel targets are not validated at all.
fn check_gaps(root: &gltf::json::Root) -> Result<()> {
    use gltf::json::validation::Checked;
    for (a, anim) in root.animations.iter().enumerate() {
        for (c, ch) in anim.channels.iter().enumerate() {
            let at = pointer(&[&"animations", &a, &"channels", &c, &"target"]);
            if ch.target.node.value() >= root.nodes.len() {
                return Err(GltfError::at(format!("{at}/node"), "index out of bounds"));
            }
            if matches!(ch.target.path, Checked::Invalid) {
                return Err(GltfError::at(
                    format!("{at}/path"),
                    "not one of translation, rotation, scale, weights",
                ));
            }
        }
    }
    Ok(())
}

fn describe(e: &gltf::json::validation::Error) -> &'static str {
    use gltf::json::validation::Error as E;
    match e {
        E::IndexOutOfBounds => "index out of bounds",
        E::Invalid => "invalid value",
        E::Missing => "required property missing",
        E::Oversize => "size or offset too large",
        E::Unsupported => "unsupported",
    }
}

/// The bytes of every buffer, in order. `glb_bin` is the binary chunk;
/// `base` is the folder external URIs are relative to.
pub struct Buffers<'a> {
    pub data: Vec<std::borrow::Cow<'a, [u8]>>,
}

impl<'a> Buffers<'a> {
    pub fn load(
        doc: &Document,
        glb_bin: Option<&'a [u8]>,
        base: &Path,
        read_file: &dyn Fn(&Path) -> std::result::Result<Vec<u8>, String>,
    ) -> Result<Buffers<'a>> {
        let mut data = Vec::with_capacity(doc.buffers().len());
        for b in doc.buffers() {
            let here = pointer(&[&"buffers", &b.index()]);
            let bytes: std::borrow::Cow<'a, [u8]> = match b.source() {
                gltf::buffer::Source::Bin => match glb_bin {
                    Some(bin) => bin.into(),
                    None => {
                        return Err(GltfError::at(
                            here,
                            "the buffer has no uri and the file has no binary chunk",
                        ))
                    }
                },
                gltf::buffer::Source::Uri(u) => uri::resolve(u, base, read_file)
                    .map_err(|m| GltfError::at(format!("{here}/uri"), m))?
                    .into(),
            };
            if bytes.len() < b.length() {
                return Err(GltfError::at(
                    format!("{here}/byteLength"),
                    format!(
                        "the buffer says {} bytes but its data has only {}",
                        b.length(),
                        bytes.len()
                    ),
                ));
            }
            data.push(bytes);
        }
        Ok(Buffers { data })
    }
}
