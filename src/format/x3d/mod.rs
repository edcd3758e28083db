//! X3D (ISO/IEC 19775-1, versions 3.0–4.0) in its two everyday encodings:
//! classic (`.x3dv`, ISO/IEC 19776-2: VRML97 syntax with a `#X3D` header
//! and PROFILE/COMPONENT/UNIT/META/IMPORT/EXPORT statements) and XML
//! (`.x3d`, ISO/IEC 19776-1).
//!
//! Both feed the same generic node tree ([`crate::format::syntax`]) the
//! VRML97 reader uses; X3D's own nodes are mapped onto VRML97's as they are
//! read ([`nodes`]), and the VRML97 scene builder does the rest, so DEF/USE,
//! PROTO expansion, ROUTEd animation and textures behave the same in all
//! three. META statements become scene info lines (`name: content`); UNIT
//! angle converts the angle fields, UNIT length scales the whole scene.

pub(crate) mod interp;
mod material;
mod nodes;
pub(crate) mod spline_keys;
pub mod write;
mod xml;
mod xml_checks;

#[cfg(test)]
mod check_tests;

pub use xml::is_xml;

use super::syntax::{self, AstNode, Field, NodeRef, Options, Parsed, Value};
use super::vrml97;
use super::{LoadError, Loaded};
use crate::scene::SourceFormat;
use std::path::Path;
use std::rc::Rc;

/// Reads an X3D classic-encoding file's bytes (already decompressed).
pub fn read_classic(bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    read_classic_nested(bytes, path, 0)
}

pub(crate) fn read_classic_nested(
    bytes: &[u8],
    path: &Path,
    depth: usize,
) -> Result<Loaded, LoadError> {
    let mut opts = Options::new(true);
    opts.x3d = true;
    opts.rewrite = Some(nodes::rewrite);
    let parsed = syntax::parse(bytes, opts);
    finish(parsed, path, depth)
}

/// Reads an X3D XML-encoding file's bytes (already decompressed).
pub fn read_xml(bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    read_xml_nested(bytes, path, 0)
}

pub(crate) fn read_xml_nested(
    bytes: &[u8],
    path: &Path,
    depth: usize,
) -> Result<Loaded, LoadError> {
    finish(xml::parse(bytes), path, depth)
}

/// Builds the scene of a parsed X3D file (either encoding).
fn finish(mut parsed: Parsed, path: &Path, depth: usize) -> Result<Loaded, LoadError> {
    let length = parsed.x3d.factor("length");
    if length != 1.0 && !parsed.roots.is_empty() {
        parsed.roots = vec![scaled(std::mem::take(&mut parsed.roots), length)];
    }
    let mut loaded = vrml97::build_parsed(&parsed, path, depth)?;
    loaded.scene.format = SourceFormat::X3d;
    let meta: Vec<String> = parsed
        .x3d
        .meta
        .iter()
        .map(|(name, content)| format!("{name}: {content}"))
        .collect();
    loaded.scene.info.splice(0..0, meta);
    Ok(loaded)
}

/// The roots under one Transform scaling file lengths to metres.
fn scaled(roots: Vec<NodeRef>, factor: f64) -> NodeRef {
    let pos = roots[0].pos;
    let fields = vec![
        Field {
            name: "scale".into(),
            value: Value::Nums(vec![factor; 3]),
            pos,
        },
        Field {
            name: "children".into(),
            value: Value::Nodes(roots),
            pos,
        },
    ];
    let height = AstNode::height_of(&fields, None);
    Rc::new(AstNode {
        kind: "Transform".into(),
        def: None,
        fields,
        pos,
        proto: None,
        height,
    })
}
