//! The built-in VRML97 / Inventor primitives as meshes: Box, Sphere, Cone,
//! Cylinder (ISO/IEC 14772-1 §6.4, §6.42, §6.12, §6.14). All are centred at
//! the origin with their axis along +y, wound counter-clockwise seen from
//! outside, with outward unit normals, and `solid` (back faces culled).
//!
//! Curved ones use [`SEGMENTS`] around the axis: at 1280×720 a sphere filling
//! the screen height then has edges of about 45 px along a 2 px-deep chord,
//! which per-pixel smooth normals make look round.

use super::Mesh;
use glam::Vec3;
use std::f32::consts::{PI, TAU};

/// Segments around the y axis for sphere, cone and cylinder.
pub const SEGMENTS: u32 = 48;
/// Latitude bands of the sphere.
pub const STACKS: u32 = 24;

/// VRML97 Box: `size` is the full extent along x, y and z.
pub fn box_mesh(size: Vec3) -> Mesh {
    let h = size * 0.5;
    let mut m = named("Box");
    // (normal, u, v) with u × v = normal, so corners -u-v, u-v, u+v, -u+v are CCW.
    let faces = [
        (Vec3::X, Vec3::NEG_Z, Vec3::Y),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::X, Vec3::NEG_Z),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::NEG_X, Vec3::Y),
    ];
    for (n, u, v) in faces {
        let base = m.positions.len() as u32;
        for (su, sv) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            m.positions.push((n + su * u + sv * v) * h);
            m.normals.push(n);
        }
        m.triangles.push([base, base + 1, base + 2]);
        m.triangles.push([base, base + 2, base + 3]);
    }
    m
}

/// VRML97 Sphere of `radius`.
pub fn sphere(radius: f32) -> Mesh {
    let mut m = named("Sphere");
    let cols = SEGMENTS + 1;
    for i in 0..=STACKS {
        let phi = PI * i as f32 / STACKS as f32;
        for j in 0..=SEGMENTS {
            let n = around(j, libm::sinf(phi), libm::cosf(phi));
            m.positions.push(n * radius);
            m.normals.push(n);
        }
    }
    for i in 0..STACKS {
        for j in 0..SEGMENTS {
            let (a, b) = (i * cols + j, (i + 1) * cols + j);
            // a = upper-left, b = lower-left; going +j moves toward +x at the front.
            if i != 0 {
                m.triangles.push([a, b, a + 1]);
            }
            if i != STACKS - 1 {
                m.triangles.push([a + 1, b, b + 1]);
            }
        }
    }
    m
}

/// VRML97 Cylinder; `side`, `top`, `bottom` choose the parts.
pub fn cylinder(radius: f32, height: f32, side: bool, top: bool, bottom: bool) -> Mesh {
    let mut m = named("Cylinder");
    let y = height * 0.5;
    if side {
        let base = m.positions.len() as u32;
        for j in 0..=SEGMENTS {
            let n = around(j, 1.0, 0.0);
            m.positions.push(n * radius - Vec3::Y * y);
            m.positions.push(n * radius + Vec3::Y * y);
            m.normals.extend([n, n]);
        }
        for j in 0..SEGMENTS {
            let (b0, t0, b1, t1) = (
                base + 2 * j,
                base + 2 * j + 1,
                base + 2 * j + 2,
                base + 2 * j + 3,
            );
            m.triangles.push([b0, b1, t1]);
            m.triangles.push([b0, t1, t0]);
        }
    }
    if top {
        cap(&mut m, radius, y, true);
    }
    if bottom {
        cap(&mut m, radius, -y, false);
    }
    m
}

/// VRML97 Cone: apex at `+height/2`, base disc of `bottom_radius` at `-height/2`.
pub fn cone(bottom_radius: f32, height: f32, side: bool, bottom: bool) -> Mesh {
    let mut m = named("Cone");
    let y = height * 0.5;
    if side {
        // Outward normal of the slanted side at angle θ: (h·sinθ, r, h·cosθ), normalised.
        let slant = Vec3::new(height, bottom_radius, height);
        let normal_at = |j: f32| {
            let t = TAU * j / SEGMENTS as f32;
            (Vec3::new(libm::sinf(t), 1.0, libm::cosf(t)) * slant).normalize_or_zero()
        };
        for j in 0..SEGMENTS {
            let base = m.positions.len() as u32;
            let (r0, r1) = (around(j, 1.0, 0.0), around(j + 1, 1.0, 0.0));
            m.positions.extend([
                r0 * bottom_radius - Vec3::Y * y,
                r1 * bottom_radius - Vec3::Y * y,
                Vec3::Y * y,
            ]);
            // The apex gets the normal half-way round its segment.
            m.normals.extend([
                normal_at(j as f32),
                normal_at(j as f32 + 1.0),
                normal_at(j as f32 + 0.5),
            ]);
            m.triangles.push([base, base + 1, base + 2]);
        }
    }
    if bottom {
        cap(&mut m, bottom_radius, -y, false);
    }
    m
}

fn named(name: &str) -> Mesh {
    Mesh {
        name: name.to_string(),
        solid: true,
        ..Mesh::default()
    }
}

/// Direction at segment `j` around +y: angle 0 at +z, increasing toward +x;
/// `ring` scales x/z, `y` is the height.
fn around(j: u32, ring: f32, y: f32) -> Vec3 {
    let t = TAU * (j % SEGMENTS) as f32 / SEGMENTS as f32;
    Vec3::new(ring * libm::sinf(t), y, ring * libm::cosf(t))
}

/// A flat disc at height `y` facing +y (`up`) or −y.
fn cap(m: &mut Mesh, radius: f32, y: f32, up: bool) {
    let n = if up { Vec3::Y } else { Vec3::NEG_Y };
    let centre = m.positions.len() as u32;
    m.positions.push(Vec3::Y * y);
    m.normals.push(n);
    for j in 0..=SEGMENTS {
        m.positions.push(around(j, radius, y));
        m.normals.push(n);
    }
    for j in 0..SEGMENTS {
        let (a, b) = (centre + 1 + j, centre + 2 + j);
        m.triangles
            .push(if up { [centre, a, b] } else { [centre, b, a] });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every triangle faces away from the origin and agrees with its
    /// vertex normals; every normal is unit length; bounds match VRML sizes.
    fn check(m: &Mesh, lo: Vec3, hi: Vec3) {
        assert_eq!(m.positions.len(), m.normals.len());
        assert!(!m.triangles.is_empty());
        for n in &m.normals {
            assert!((n.length() - 1.0).abs() < 1e-5, "unit normal {n}");
        }
        for &[a, b, c] in &m.triangles {
            let [pa, pb, pc] = [a, b, c].map(|i| m.positions[i as usize]);
            let g = (pb - pa).cross(pc - pa);
            assert!(g.length() > 0.0, "degenerate triangle in {}", m.name);
            let centroid = (pa + pb + pc) / 3.0;
            assert!(g.dot(centroid) > 0.0, "{} triangle faces inward", m.name);
            for i in [a, b, c] {
                assert!(
                    g.dot(m.normals[i as usize]) > 0.0,
                    "{} normal disagrees",
                    m.name
                );
            }
        }
        let (blo, bhi) = m.bounds().unwrap();
        assert!(
            (blo - lo).abs().max_element() < 1e-5,
            "{} low {blo}",
            m.name
        );
        assert!(
            (bhi - hi).abs().max_element() < 1e-5,
            "{} high {bhi}",
            m.name
        );
    }

    #[test]
    fn box_is_outward_and_sized() {
        let m = box_mesh(Vec3::new(2.0, 4.0, 6.0));
        check(&m, Vec3::new(-1.0, -2.0, -3.0), Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(m.triangles.len(), 12);
    }

    #[test]
    fn sphere_is_outward_and_round() {
        let m = sphere(2.0);
        check(&m, Vec3::splat(-2.0), Vec3::splat(2.0));
        for (p, n) in m.positions.iter().zip(&m.normals) {
            assert!((p.length() - 2.0).abs() < 1e-5);
            assert!((*p / 2.0 - *n).length() < 1e-5);
        }
    }

    #[test]
    fn cylinder_and_cone_are_outward_and_sized() {
        let m = cylinder(1.0, 2.0, true, true, true);
        check(&m, Vec3::new(-1.0, -1.0, -1.0), Vec3::new(1.0, 1.0, 1.0));
        let m = cone(1.0, 2.0, true, true);
        check(&m, Vec3::new(-1.0, -1.0, -1.0), Vec3::new(1.0, 1.0, 1.0));
        // Cone side normals lean up by atan(r/h).
        let side_n = m.normals[0];
        assert!((side_n.y - (1.0f32 / 5.0f32.sqrt())).abs() < 1e-5);
        // Parts can be switched off.
        let only_side = cylinder(1.0, 2.0, true, false, false);
        assert_eq!(only_side.triangles.len(), 2 * SEGMENTS as usize);
        assert!(cone(1.0, 2.0, false, false).triangles.is_empty());
    }
}
