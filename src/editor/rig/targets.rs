//! Which morph targets a selection drives: pure scene lookups shared by
//! the morph sliders (`morph`) and the graph editor's weight curves, kept
//! apart from the `Editor` so both can use them without an import cycle.

use crate::scene::{MeshId, MorphTarget, Morphs, NodeId, NodeKind, Scene};

/// The mesh of shape node `id` when it has morph targets.
pub fn morph_mesh(scene: &Scene, id: NodeId) -> Option<(MeshId, &Morphs)> {
    match &scene.nodes.get(id.0 as usize)?.kind {
        NodeKind::Shape(s) => {
            let m = scene.meshes.get(s.mesh.0 as usize)?.morph.as_deref()?;
            Some((s.mesh, m))
        }
        _ => None,
    }
}

/// The (track target, morphed shape) a selection edits: a morphed shape
/// itself, or a group whose first morphed child shape it drives (glTF
/// meshes of several primitives are a group of shapes).
pub fn morph_of(scene: &Scene, sel: NodeId) -> Option<(NodeId, NodeId)> {
    if morph_mesh(scene, sel).is_some() {
        return Some((sel, sel));
    }
    let n = scene.nodes.get(sel.0 as usize)?;
    if !matches!(n.kind, NodeKind::Group) {
        return None;
    }
    n.children
        .iter()
        .copied()
        .find(|&c| morph_mesh(scene, c).is_some())
        .map(|c| (sel, c))
}

/// The morph targets a selection's weights drive (see [`morph_of`]);
/// empty when it drives none.
pub fn targets_of(scene: &Scene, sel: NodeId) -> &[MorphTarget] {
    morph_of(scene, sel)
        .and_then(|(_, shape)| morph_mesh(scene, shape))
        .map(|(_, m)| m.targets())
        .unwrap_or(&[])
}

/// Names of the shape's morph targets ("target 2" when unnamed).
pub fn target_names(scene: &Scene, shape: NodeId) -> Vec<String> {
    morph_mesh(scene, shape)
        .map(|(_, m)| {
            m.targets()
                .iter()
                .enumerate()
                .map(|(i, t)| match t.name.is_empty() {
                    true => format!("target {i}"),
                    false => t.name.clone(),
                })
                .collect()
        })
        .unwrap_or_default()
}
