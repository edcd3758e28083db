//! Inline (VRML97), WWWInline (VRML 1.0) and File (Inventor): loading a
//! local file named relative to the including one and grafting its scene
//! under a node. Remote URLs are not fetched.

use crate::anim::{Keys, TargetRef};
use crate::format::lexer::Pos;
use crate::format::limits::{self, LimitError};
use crate::scene::{MaterialId, MeshId, NodeId, NodeKind, Scene};
use std::path::{Path, PathBuf};

/// Deepest chain of files including files.
pub const MAX_DEPTH: usize = 8;

/// Resolves the first usable local URL of `urls` against `base`.
pub fn resolve(base: &Path, urls: &[String]) -> Option<PathBuf> {
    urls.iter().find_map(|u| {
        let u = u.trim();
        let u = u.strip_prefix("file://").unwrap_or(u);
        if u.is_empty() || u.contains("://") {
            return None;
        }
        let u = u.split('#').next().unwrap_or(u);
        let p = Path::new(u);
        Some(if p.is_absolute() {
            p.to_path_buf()
        } else {
            base.parent().unwrap_or(Path::new("")).join(p)
        })
    })
}

/// Scenes already loaded by this file's Inline/File nodes, by path, so a
/// file inlined many times is read once (and warned about once).
pub type Cache = std::collections::HashMap<PathBuf, Option<Scene>>;

/// Loads the file named by `urls` and adds its scene under `parent`;
/// problems become warnings (`path:line:column: message`), except a passed
/// input limit, which ends the whole load. `levels` is the nesting depth of
/// the Inline node: the included file's nesting counts on top of it.
#[allow(clippy::too_many_arguments)]
pub fn load_into(
    scene: &mut Scene,
    warnings: &mut Vec<String>,
    cache: &mut Cache,
    base: &Path,
    pos: Pos,
    urls: &[String],
    parent: NodeId,
    depth: usize,
    levels: usize,
) -> Result<(), LimitError> {
    let at = |m: String| format!("{}:{}:{}: {m}", base.display(), pos.line, pos.column);
    if depth + 1 > MAX_DEPTH {
        warnings.push(at(format!(
            "inline files nested deeper than {MAX_DEPTH}; skipped"
        )));
        return Ok(());
    }
    let Some(file) = resolve(base, urls) else {
        warnings.push(at(format!(
            "no local file among inline URLs {urls:?}; skipped"
        )));
        return Ok(());
    };
    if !cache.contains_key(&file) {
        let got = limits::deeper(levels as u64 + 1, || {
            crate::format::load_nested(&file, depth + 1)
        });
        // A passed limit is not the included file's fault: stop the load.
        if let Some(l) = limits::tripped() {
            return Err(l);
        }
        let loaded = match got {
            Ok(mut loaded) => {
                warnings.append(&mut loaded.warnings);
                Some(loaded.scene)
            }
            Err(e) => {
                warnings.push(at(format!("inline file not loaded: {e}")));
                None
            }
        };
        cache.insert(file.clone(), loaded);
    }
    if let Some(Some(src)) = cache.get(&file) {
        graft(scene, src, parent)?;
    }
    Ok(())
}

/// Copies `src`'s nodes, meshes, materials and tracks under `parent`; the
/// copies count against the input budget (an inline used many times costs
/// as much as its copies).
pub fn graft(dst: &mut Scene, src: &Scene, parent: NodeId) -> Result<(), LimitError> {
    limits::charge_nodes(src.nodes.len() as u64)?;
    let geometry: u64 = src
        .nodes
        .iter()
        .map(|n| match &n.kind {
            NodeKind::Shape(s) => src
                .meshes
                .get(s.mesh.0 as usize)
                .map_or(0, |m| (m.positions.len() + m.triangles.len()) as u64),
            _ => 0,
        })
        .sum();
    limits::charge_geometry(geometry)?;
    let mesh_base = dst.meshes.len() as u32;
    let mat_base = dst.materials.len() as u32;
    dst.meshes.extend(src.meshes.iter().cloned());
    // Images join the including scene's (shared when grafted again); one
    // that does not fit its budget leaves its materials untextured.
    let images: Vec<_> = src
        .images
        .iter()
        .map(|i| dst.add_image(i.clone()).ok())
        .collect();
    dst.materials
        .extend(src.materials.iter().cloned().map(|mut m| {
            for slot in m.texture_slots_mut() {
                let id = slot
                    .as_ref()
                    .and_then(|t| images.get(t.image.0 as usize).copied().flatten());
                match (slot.as_mut(), id) {
                    (Some(t), Some(id)) => t.image = id,
                    _ => *slot = None,
                }
            }
            m
        }));
    let mut map = vec![None; src.nodes.len()];
    for id in src.walk() {
        let n = src.node(id);
        let p = n.parent.and_then(|p| map[p.0 as usize]).unwrap_or(parent);
        let mut copy = n.clone();
        if let NodeKind::Shape(s) = &mut copy.kind {
            s.mesh = MeshId(s.mesh.0 + mesh_base);
            s.material = MaterialId(s.material.0 + mat_base);
        }
        map[id.0 as usize] = Some(dst.add_node(Some(p), copy));
    }
    let scale = dst.settings.fps / src.settings.fps.max(1e-6);
    for t in &src.animation.tracks {
        let mut t = t.clone();
        t.target.of = match t.target.of {
            TargetRef::Node(n) => match map.get(n.0 as usize).copied().flatten() {
                Some(m) => TargetRef::Node(m),
                None => continue,
            },
            TargetRef::Material(m) => TargetRef::Material(MaterialId(m.0 + mat_base)),
        };
        if scale != 1.0 {
            match &mut t.keys {
                Keys::Scalar(k) => k.iter_mut().for_each(|k| k.frame *= scale),
                Keys::Vec3(k) => k.iter_mut().for_each(|k| k.frame *= scale),
                Keys::Rotation(k) => k.iter_mut().for_each(|k| k.frame *= scale),
                Keys::Bool(k) => k.iter_mut().for_each(|k| k.frame *= scale),
                Keys::Weights(k) => k.iter_mut().for_each(|k| k.frame *= scale),
            }
        }
        dst.animation.tracks.push(t);
    }
    if !src.animation.tracks.is_empty() {
        let d = src.settings.duration * scale;
        if dst.animation.tracks.len() == src.animation.tracks.len() || d > dst.settings.duration {
            dst.settings.duration = d;
        }
    }
    Ok(())
}
