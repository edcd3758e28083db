//! Per-pose deformation: the morph weights of every morphed shape, the joint
//! matrices of every skin, and the deformed positions/normals of every shape
//! whose mesh is morphed or skinned — written into buffers the [`Pose`] keeps
//! between frames, never into the scene.
//!
//! Morph first, then skin (glTF 2.0 §3.7.2.2). Skinned vertices come out in
//! world space (the joints place them, not the shape's own transform, as
//! glTF says); morph-only vertices stay in the mesh's local space.

use super::skinning::{self, JointMatrix, MorphInput};
use super::{Pose, Weights};
use crate::scene::{Mesh, NodeId, NodeKind, Scene};
use glam::{Mat4, Vec3};

/// The geometry a shape is drawn with after deformation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Deformed {
    pub positions: Vec<Vec3>,
    /// One per position, or empty when the mesh has no normals.
    pub normals: Vec<Vec3>,
    /// Positions/normals are in world space (skinned); otherwise in the
    /// shape's local space, to be placed by its world matrix.
    pub world_space: bool,
    // Morph result kept for skinning (morph + skin meshes only).
    morphed_p: Vec<Vec3>,
    morphed_n: Vec<Vec3>,
}

/// Default morph weights of every shape whose mesh has targets, in node
/// order (tracks then overwrite them).
pub(super) fn default_weights(scene: &Scene, out: &mut Vec<(NodeId, Weights)>) {
    out.clear();
    for i in 0..scene.nodes.len() {
        if let Some(m) = shape_mesh(scene, i).and_then(|m| m.morph.as_deref()) {
            out.push((
                NodeId(i as u32),
                Weights::from_slice_truncated(m.default_weights()),
            ));
        }
    }
}

/// The mesh of shape node `i`, if it is one.
fn shape_mesh(scene: &Scene, i: usize) -> Option<&Mesh> {
    match &scene.nodes.get(i)?.kind {
        NodeKind::Shape(s) => scene.meshes.get(s.mesh.0 as usize),
        _ => None,
    }
}

/// Fills `pose.joints` and `pose.deformed` from `pose.world` and
/// `pose.weights` (both already evaluated).
pub(super) fn deform(scene: &Scene, pose: &mut Pose) {
    // Joint matrices per skin: jointWorld · inverseBind.
    pose.joints.resize_with(scene.skins.len(), Vec::new);
    pose.joints.truncate(scene.skins.len());
    for (skin, out) in scene.skins.iter().zip(pose.joints.iter_mut()) {
        out.clear();
        out.extend(
            skin.joints()
                .iter()
                .zip(skin.inverse_bind())
                .map(|(j, ibm)| {
                    let w = pose
                        .world
                        .get(j.0 as usize)
                        .copied()
                        .unwrap_or(Mat4::IDENTITY);
                    JointMatrix::new(w * *ibm)
                }),
        );
    }

    let mut j = 0;
    for (i, node) in scene.nodes.iter().enumerate() {
        let Some(mesh) = shape_mesh(scene, i).filter(|m| m.deforms()) else {
            continue;
        };
        let id = NodeId(i as u32);
        if j == pose.deformed.len() {
            pose.deformed.push((id, Deformed::default()));
        }
        pose.deformed[j].0 = id;
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        let weights = pose
            .weights
            .binary_search_by_key(&id, |(n, _)| *n)
            .ok()
            .map(|k| pose.weights[k].1);
        let skin = node.skin.and_then(|s| {
            Some((
                pose.joints.get(s.0 as usize)?,
                mesh.skin_weights.as_deref()?,
            ))
        });
        deform_one(mesh, weights, skin, world, &mut pose.deformed[j].1);
        j += 1;
    }
    pose.deformed.truncate(j);
}

fn deform_one(
    mesh: &Mesh,
    weights: Option<Weights>,
    skin: Option<(&Vec<JointMatrix>, &crate::scene::SkinWeights)>,
    world: Mat4,
    out: &mut Deformed,
) {
    let has_normals = mesh.normals.len() == mesh.positions.len();
    let base_n: &[Vec3] = if has_normals { &mesh.normals } else { &[] };
    let morphed = mesh.morph.as_deref().map(|m| {
        let w = weights.unwrap_or_else(|| Weights::from_slice_truncated(m.default_weights()));
        m.targets()
            .iter()
            .zip(w.as_slice())
            .map(|(t, &weight)| MorphInput {
                weight,
                positions: t.positions(),
                normals: t.normals(),
            })
            .collect::<Vec<_>>()
    });
    match (morphed, skin) {
        (Some(targets), None) => {
            out.world_space = false;
            skinning::morph(
                &mesh.positions,
                base_n,
                &targets,
                &mut out.positions,
                &mut out.normals,
            );
        }
        (Some(targets), Some((mats, sw))) => {
            out.world_space = true;
            let (mut mp, mut mn) = (
                std::mem::take(&mut out.morphed_p),
                std::mem::take(&mut out.morphed_n),
            );
            skinning::morph(&mesh.positions, base_n, &targets, &mut mp, &mut mn);
            let rest = JointMatrix::new(world);
            skinning::skin(
                &mp,
                &mn,
                sw.joints(),
                sw.weights(),
                mats,
                &rest,
                &mut out.positions,
                &mut out.normals,
            );
            out.morphed_p = mp;
            out.morphed_n = mn;
        }
        (None, Some((mats, sw))) => {
            out.world_space = true;
            let rest = JointMatrix::new(world);
            skinning::skin(
                &mesh.positions,
                base_n,
                sw.joints(),
                sw.weights(),
                mats,
                &rest,
                &mut out.positions,
                &mut out.normals,
            );
        }
        (None, None) => {
            // Skin weights without a bound skin: drawn rigid.
            out.world_space = false;
            out.positions.clone_from(&mesh.positions);
            out.normals.clear();
            out.normals.extend_from_slice(base_n);
        }
    }
    // A mesh whose influences do not cover every vertex: the rest rigid.
    if out.positions.len() < mesh.positions.len() {
        let from = out.positions.len();
        if out.world_space {
            out.positions.extend(
                mesh.positions[from..]
                    .iter()
                    .map(|p| world.transform_point3(*p)),
            );
        } else {
            out.positions.extend_from_slice(&mesh.positions[from..]);
        }
    }
    if has_normals && out.normals.len() < mesh.normals.len() {
        let from = out.normals.len();
        let nm = JointMatrix::new(world).normal;
        if out.world_space {
            out.normals.extend(
                mesh.normals[from..]
                    .iter()
                    .map(|n| Vec3::from(nm * glam::Vec3A::from(*n)).normalize_or_zero()),
            );
        } else {
            out.normals.extend_from_slice(&mesh.normals[from..]);
        }
    }
}
