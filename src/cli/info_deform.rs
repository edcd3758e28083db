//! The deformation part of `animed info`: morph targets per mesh and skins
//! (joint count, influences, the shapes they deform), as JSON and text.

use super::info::{node_label, short};
use crate::scene::{NodeKind, Scene};
use serde_json::{json, Value as Json};

/// Shapes (labels) whose mesh is `mesh`.
fn shapes_of_mesh(s: &Scene, mesh: usize) -> Vec<String> {
    s.walk()
        .into_iter()
        .filter(|&id| matches!(&s.node(id).kind, NodeKind::Shape(sh) if sh.mesh.0 as usize == mesh))
        .map(|id| node_label(s, id))
        .collect()
}

/// One entry per mesh with morph targets: its targets' names, default
/// weights and the shapes that draw it (`NAME.weights` animates them).
pub fn morphs_json(s: &Scene) -> Json {
    s.meshes
        .iter()
        .enumerate()
        .filter_map(|(i, m)| {
            let morph = m.morph.as_deref()?;
            Some(json!({
                "mesh": i,
                "name": m.name,
                "targets": morph.targets().iter().map(|t| t.name.clone()).collect::<Vec<_>>(),
                "default_weights": morph.default_weights().iter().map(|w| short(*w)).collect::<Vec<_>>(),
                "normal_deltas": morph.has_normal_deltas(),
                "shapes": shapes_of_mesh(s, i),
            }))
        })
        .collect()
}

/// One entry per skin: joint count and names, the largest number of
/// influences on one vertex, skinned vertices, and the shapes it deforms.
pub fn skins_json(s: &Scene) -> Json {
    s.skins
        .iter()
        .enumerate()
        .map(|(k, skin)| {
            let shapes: Vec<_> = s
                .walk()
                .into_iter()
                .filter(|&id| s.node(id).skin.is_some_and(|x| x.0 as usize == k))
                .collect();
            let (mut influences, mut vertices) = (0, 0);
            for &id in &shapes {
                if let NodeKind::Shape(sh) = &s.node(id).kind {
                    if let Some(w) = s
                        .meshes
                        .get(sh.mesh.0 as usize)
                        .and_then(|m| m.skin_weights.as_deref())
                    {
                        influences = influences.max(w.max_influences());
                        vertices += w.len();
                    }
                }
            }
            json!({
                "index": k,
                "name": skin.name,
                "joints": skin.joints().len(),
                "joint_names": skin.joints().iter().map(|&j| node_label(s, j)).collect::<Vec<_>>(),
                "influences": influences,
                "vertices": vertices,
                "shapes": shapes.iter().map(|&id| node_label(s, id)).collect::<Vec<_>>(),
            })
        })
        .collect()
}

/// The text lines for `morphs` and `skins` of [`morphs_json`]/[`skins_json`].
pub fn print_text(d: &Json) {
    let list = |k: &str| d[k].as_array().cloned().unwrap_or_default();
    let strs = |v: &Json| -> String {
        v.as_array()
            .map(|a| {
                a.iter()
                    .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_string))
                    .collect::<Vec<_>>()
                    .join(", ")
            })
            .unwrap_or_default()
    };
    let morphs = list("morphs");
    if !morphs.is_empty() {
        println!("morphs:     {}", morphs.len());
        for m in &morphs {
            println!(
                "  mesh {} `{}`: {} targets [{}], default weights [{}]; shapes: {}",
                m["mesh"],
                m["name"].as_str().unwrap_or(""),
                m["targets"].as_array().map_or(0, Vec::len),
                strs(&m["targets"]),
                strs(&m["default_weights"]),
                strs(&m["shapes"])
            );
        }
    }
    let skins = list("skins");
    if !skins.is_empty() {
        println!("skins:      {}", skins.len());
        for k in &skins {
            println!("{}", skin_line(k, &strs(&k["shapes"])));
        }
    }
}

/// One skin's text line; a skin no shape uses (a skeleton only, such as
/// an H-Anim humanoid without skinCoord) says so instead of an empty
/// shape list.
fn skin_line(k: &Json, shapes: &str) -> String {
    let head = format!(
        "  {} `{}`: {} joints",
        k["index"],
        k["name"].as_str().unwrap_or(""),
        k["joints"]
    );
    if shapes.is_empty() {
        return format!("{head}; skeleton only (no skinned shapes)");
    }
    format!(
        "{head}, up to {} influences per vertex, {} skinned vertices; shapes: {shapes}",
        k["influences"], k["vertices"]
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_skeleton_without_shapes_says_so() {
        let k = json!({"index": 0, "name": "nancy", "joints": 17, "influences": 0, "vertices": 0, "shapes": []});
        assert_eq!(
            skin_line(&k, ""),
            "  0 `nancy`: 17 joints; skeleton only (no skinned shapes)"
        );
        let k = json!({"index": 1, "name": "s", "joints": 2, "influences": 4, "vertices": 9, "shapes": ["Arm"]});
        assert_eq!(
            skin_line(&k, "Arm"),
            "  1 `s`: 2 joints, up to 4 influences per vertex, 9 skinned vertices; shapes: Arm"
        );
    }
}
