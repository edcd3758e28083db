//! Synthetic deforming scenes for `animed bench --only skinning` (timed in
//! `cli/bench.rs`): a skinned
//! mesh (4 influences per vertex, positions and normals) under 64 animated
//! joints, and a morphed mesh with 4 live targets. Deterministic, no I/O.

use super::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Weights};
use crate::scene::{
    Material, Mesh, MorphTarget, Morphs, Node, NodeId, NodeKind, Scene, Shape, Skin, SkinWeights,
    Transform,
};
use glam::{Mat4, Quat, Vec3};

/// Joints in the synthetic skeleton (a chain).
pub const JOINTS: usize = 64;

/// Cheap deterministic hash → [0, 1).
fn unit(i: usize, salt: u32) -> f32 {
    let mut x = (i as u32).wrapping_mul(0x9E37_79B9) ^ salt.wrapping_mul(0x85EB_CA6B);
    x ^= x >> 15;
    x = x.wrapping_mul(0x2C1B_3C6D);
    x ^= x >> 12;
    (x >> 8) as f32 / (1u32 << 24) as f32
}

fn grid_mesh(vertices: usize) -> Mesh {
    let positions: Vec<Vec3> = (0..vertices)
        .map(|i| {
            Vec3::new(
                unit(i, 1) - 0.5,
                unit(i, 2) * JOINTS as f32,
                unit(i, 3) - 0.5,
            )
        })
        .collect();
    let normals = (0..vertices)
        .map(|i| Vec3::new(unit(i, 4) - 0.5, unit(i, 5) - 0.5, 0.5).normalize())
        .collect();
    Mesh {
        positions,
        normals,
        ..Mesh::default()
    }
}

fn add_shape(s: &mut Scene, mesh: Mesh) -> NodeId {
    let mesh = s.add_mesh(mesh);
    let material = s.add_material(Material::default());
    s.add_node(
        None,
        Node::new("m", NodeKind::Shape(Shape { mesh, material })),
    )
}

/// A chain of [`JOINTS`] joints one unit apart along y, each turning with a
/// two-key slerp track, and a mesh of `vertices` vertices with 4 influences
/// each (neighbouring joints, weights summing to 1).
pub fn skinned_scene(vertices: usize) -> Scene {
    let mut s = Scene::new();
    let mut joints = Vec::with_capacity(JOINTS);
    let mut parent = None;
    for j in 0..JOINTS {
        let t = if j == 0 { Vec3::ZERO } else { Vec3::Y };
        let id = s.add_node(
            parent,
            Node::group(format!("J{j}")).with_transform(Transform::from_translation(t)),
        );
        s.animation.tracks.push(Track {
            target: Target {
                of: TargetRef::Node(id),
                property: Property::Rotation,
            },
            repeat: Repeat::Loop,
            keys: Keys::Rotation(vec![
                Key::new(0.0, Quat::IDENTITY).with_interp(Interp::Linear),
                Key::new(24.0, Quat::from_rotation_z(0.05 + 0.001 * j as f32)),
            ]),
        });
        joints.push(id);
        parent = Some(id);
    }
    let mut mesh = grid_mesh(vertices);
    let (sw, _) = SkinWeights::from_influences(vertices, |v, out| {
        let y = mesh.positions[v].y as usize;
        for k in 0..4 {
            let j = (y + k).min(JOINTS - 1) as u16;
            out.push((j, 0.1 + unit(v, 10 + k as u32)));
        }
    })
    .unwrap_or_default();
    mesh.skin_weights = Some(Box::new(sw));
    let shape = add_shape(&mut s, mesh);
    let ibm = (0..JOINTS)
        .map(|j| Mat4::from_translation(Vec3::new(0.0, -(j as f32), 0.0)))
        .collect();
    if let Ok(skin) = Skin::new("chain", joints, ibm) {
        if let Ok(id) = s.add_skin(skin) {
            s.node_mut(shape).skin = Some(id);
        }
    }
    s
}

/// A mesh of `vertices` vertices with 4 morph targets (position and normal
/// deltas), all weights animated and non-zero.
pub fn morphed_scene(vertices: usize) -> Scene {
    let mut s = Scene::new();
    let mut mesh = grid_mesh(vertices);
    let targets = (0..4u32)
        .map(|t| {
            let d = |salt| {
                (0..vertices)
                    .map(|i| Vec3::new(unit(i, salt), unit(i, salt + 1), unit(i, salt + 2)) * 0.1)
                    .collect()
            };
            MorphTarget::new(format!("t{t}"), d(20 + 4 * t), d(40 + 4 * t))
        })
        .collect();
    if let Ok(m) = Morphs::new(vertices, targets, vec![0.25; 4]) {
        mesh.morph = Some(Box::new(m));
    }
    let shape = add_shape(&mut s, mesh);
    let w = |x: f32| Weights::from_slice(&[x, 0.5 * x, 0.3, 1.0 - x]).unwrap_or_default();
    s.animation.tracks.push(Track {
        target: Target {
            of: TargetRef::Node(shape),
            property: Property::MorphWeights,
        },
        repeat: Repeat::Loop,
        keys: Keys::Weights(vec![Key::new(0.0, w(0.2)), Key::new(24.0, w(0.9))]),
    });
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn synthetic_scenes_deform() {
        let s = skinned_scene(1000);
        let p = super::super::evaluate(&s, 0.5);
        let d = &p.deformed[0].1;
        assert_eq!(d.positions.len(), 1000);
        assert!(d.positions.iter().all(|v| v.is_finite()));
        assert_ne!(d.positions, s.meshes[0].positions);
        let m = morphed_scene(1000);
        let p = super::super::evaluate(&m, 0.5);
        assert_ne!(p.deformed[0].1.positions, m.meshes[0].positions);
    }
}
