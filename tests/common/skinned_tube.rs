//! A tube skinned to two joints, shared by the deformation tests
//! (`anim_deform`) and the editor's rig tests (`editor_rig`): `rings`
//! rings of `sides` vertices from y = `y0` to `y1` with outward unit
//! normals, each ring weighted `1 − w1(y)` to joint 0 and `w1(y)` to
//! joint 1. The caller makes the joints and binds the skin.

use animed::internals::scene::{Mesh, SkinWeights};
use glam::Vec3;

pub fn tube(
    (rings, sides): (usize, usize),
    radius: f32,
    (y0, y1): (f32, f32),
    w1: impl Fn(f32) -> f32,
) -> Mesh {
    let mut m = Mesh {
        solid: true,
        ..Mesh::default()
    };
    let mut joints = Vec::new();
    let mut weights = Vec::new();
    for r in 0..rings {
        let y = y0 + (y1 - y0) * r as f32 / (rings - 1) as f32;
        let w = w1(y);
        for k in 0..sides {
            let a = std::f32::consts::TAU * k as f32 / sides as f32;
            let n = Vec3::new(a.cos(), 0.0, -a.sin());
            m.positions.push(n * radius + Vec3::Y * y);
            m.normals.push(n);
            joints.push([0, 1, 0, 0]);
            weights.push([1.0 - w, w, 0.0, 0.0]);
        }
    }
    for r in 0..rings as u32 - 1 {
        for k in 0..sides as u32 {
            let (a, b) = (
                r * sides as u32 + k,
                r * sides as u32 + (k + 1) % sides as u32,
            );
            let (c, d) = (a + sides as u32, b + sides as u32);
            m.triangles.push([a, b, d]);
            m.triangles.push([a, d, c]);
        }
    }
    m.skin_weights = Some(Box::new(SkinWeights::new(joints, weights).unwrap()));
    m
}
