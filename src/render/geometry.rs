//! Which vertices a shape is drawn with: the mesh's own, or the pose's
//! deformed buffers (morph targets, skinning). The one place the renderer
//! and the framing code choose between them.

use crate::anim::Pose;
use crate::scene::{Mesh, NodeId};
use glam::{Mat4, Vec3};

/// The vertex positions and normals a shape is drawn with and the matrix
/// that places them: the mesh's own, or the pose's deformed buffers
/// (skinned ones are already in world space).
pub(crate) struct Geometry<'a> {
    pub positions: &'a [Vec3],
    pub normals: &'a [Vec3],
    pub world: Mat4,
}

impl<'a> Geometry<'a> {
    pub(crate) fn of(mesh: &'a Mesh, pose: &'a Pose, id: NodeId, world: Mat4) -> Geometry<'a> {
        match pose.deformed(id) {
            Some(d) if d.positions.len() == mesh.positions.len() => Geometry {
                positions: &d.positions,
                normals: if d.normals.len() == d.positions.len() {
                    &d.normals
                } else {
                    &mesh.normals
                },
                world: if d.world_space { Mat4::IDENTITY } else { world },
            },
            _ => Geometry {
                positions: &mesh.positions,
                normals: &mesh.normals,
                world,
            },
        }
    }
}
