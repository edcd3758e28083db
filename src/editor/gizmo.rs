//! Light gizmos as world-space line segments: a three-ring sphere for point
//! lights, a cone for spot lights, an arrow for directional lights. They
//! exist only in the overlay; nothing here is part of the scene or exported.

use crate::scene::{Light, LightKind};
use glam::{Mat4, Vec3};

/// Segments of `light`'s gizmo, mounted on a node with world matrix
/// `world`, sized `size` world units (the caller keeps it a constant
/// number of pixels).
pub fn segments(light: &Light, world: &Mat4, size: f32) -> Vec<(Vec3, Vec3)> {
    let pos = world.transform_point3(light.location);
    let dir = world
        .transform_vector3(light.direction)
        .normalize_or(Vec3::NEG_Z);
    let mut out = Vec::new();
    match light.kind {
        LightKind::Point => {
            for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                ring(&mut out, pos, axis, size * 0.5, 16);
            }
        }
        LightKind::Spot { cut_off_angle, .. } => {
            let len = size * 1.5;
            let r = len * cut_off_angle.clamp(0.05, 1.5).tan().min(3.0);
            let base = pos + dir * len;
            let (u, v) = basis(dir);
            ring(&mut out, base, dir, r, 20);
            for k in 0..4 {
                let a = k as f32 * std::f32::consts::FRAC_PI_2;
                out.push((pos, base + (u * a.cos() + v * a.sin()) * r));
            }
            out.push((pos, base));
        }
        LightKind::Directional => {
            let len = size * 2.0;
            let tip = pos + dir * len;
            let (u, v) = basis(dir);
            out.push((pos, tip));
            for side in [u, -u, v, -v] {
                out.push((tip, tip - dir * size * 0.5 + side * size * 0.25));
            }
            ring(&mut out, pos, dir, size * 0.3, 12);
        }
    }
    out
}

/// Two unit vectors perpendicular to `n` and to each other.
fn basis(n: Vec3) -> (Vec3, Vec3) {
    let u = if n.x.abs() < 0.9 { Vec3::X } else { Vec3::Y };
    let u = n.cross(u).normalize_or(Vec3::X);
    (u, n.cross(u))
}

fn ring(out: &mut Vec<(Vec3, Vec3)>, c: Vec3, normal: Vec3, r: f32, n: usize) {
    let (u, v) = basis(normal.normalize_or(Vec3::Y));
    let p = |k: usize| {
        let a = k as f32 / n as f32 * std::f32::consts::TAU;
        c + (u * a.cos() + v * a.sin()) * r
    };
    for k in 0..n {
        out.push((p(k), p(k + 1)));
    }
}

/// Where the light "is" for picking and labels.
pub fn anchor(light: &Light, world: &Mat4) -> Vec3 {
    world.transform_point3(light.location)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spot_cone_opens_along_its_direction() {
        let mut l = Light::spot();
        l.location = Vec3::new(1.0, 2.0, 3.0);
        l.direction = Vec3::NEG_Y;
        let segs = segments(&l, &Mat4::IDENTITY, 1.0);
        // Every segment lies between the apex height and the base (y = 0).
        for (a, b) in &segs {
            for p in [a, b] {
                assert!(p.y <= 2.0 + 1e-5 && p.y >= -1e-5, "{p}");
            }
        }
        assert!(segs.iter().any(|(a, _)| *a == l.location));
    }

    #[test]
    fn gizmos_follow_the_node_transform() {
        let l = Light::new(LightKind::Point);
        let w = Mat4::from_translation(Vec3::new(5.0, 0.0, 0.0));
        assert_eq!(anchor(&l, &w), Vec3::new(5.0, 0.0, 0.0));
        let segs = segments(&l, &w, 2.0);
        assert_eq!(segs.len(), 48);
        for (a, _) in segs {
            assert!((a - Vec3::new(5.0, 0.0, 0.0)).length() <= 1.0 + 1e-4);
        }
    }
}
