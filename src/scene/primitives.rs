//! The built-in VRML97 / Inventor primitives as meshes: Box, Sphere, Cone,
//! Cylinder (ISO/IEC 14772-1 §6.4, §6.42, §6.12, §6.14). All are centred at
//! the origin with their axis along +y, wound counter-clockwise seen from
//! outside, with outward unit normals, and `solid` (back faces culled).
//!
//! Texture coordinates follow the spec's default mappings (§6.4 Box: the
//! whole image upright on each face; §6.42 Sphere, §6.14 Cylinder, §6.12
//! Cone: wrapped counter-clockwise seen from above starting at the back
//! (−Z) seam; caps as a disc cut from the image, upright with the top
//! tilted toward +Z). Curved shapes get them from the `_textured` builders,
//! which start the ring at the back so the seam is where the spec puts it.
//!
//! Curved ones use [`SEGMENTS`] around the axis: at 1280×720 a sphere filling
//! the screen height then has edges of about 45 px along a 2 px-deep chord,
//! which per-pixel smooth normals make look round.

use super::Mesh;
use glam::{Vec2, Vec3};
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
            m.texcoords
                .push(Vec2::new((su + 1.0) * 0.5, (sv + 1.0) * 0.5));
        }
        m.triangles.push([base, base + 1, base + 2]);
        m.triangles.push([base, base + 2, base + 3]);
        // The face's outline, for drawing as lines (a Cube shows 6 squares).
        m.edges
            .extend((0..4).map(|k| [base + k, base + (k + 1) % 4]));
    }
    m
}

/// VRML97 Sphere of `radius`.
pub fn sphere(radius: f32) -> Mesh {
    sphere_with(radius, false)
}

/// A Sphere with the default texture mapping.
pub fn sphere_textured(radius: f32) -> Mesh {
    sphere_with(radius, true)
}

fn sphere_with(radius: f32, textured: bool) -> Mesh {
    let mut m = named("Sphere");
    let cols = SEGMENTS + 1;
    for i in 0..=STACKS {
        let phi = PI * i as f32 / STACKS as f32;
        for j in 0..=SEGMENTS {
            let n = around_from(j, libm::sinf(phi), libm::cosf(phi), textured);
            m.positions.push(n * radius);
            m.normals.push(n);
            if textured {
                // Pole vertices sit in the middle of the one triangle using them.
                let s = match i {
                    0 => j as f32 - 0.5,
                    _ if i == STACKS => j as f32 + 0.5,
                    _ => j as f32,
                };
                let t = 1.0 - i as f32 / STACKS as f32;
                m.texcoords.push(Vec2::new(s / SEGMENTS as f32, t));
            }
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
    cylinder_with(radius, height, [side, top, bottom], false)
}

/// A Cylinder with the default texture mapping.
pub fn cylinder_textured(radius: f32, height: f32, side: bool, top: bool, bottom: bool) -> Mesh {
    cylinder_with(radius, height, [side, top, bottom], true)
}

fn cylinder_with(radius: f32, height: f32, parts: [bool; 3], textured: bool) -> Mesh {
    let [side, top, bottom] = parts;
    let mut m = named("Cylinder");
    let y = height * 0.5;
    if side {
        let base = m.positions.len() as u32;
        for j in 0..=SEGMENTS {
            let n = around_from(j, 1.0, 0.0, textured);
            m.positions.push(n * radius - Vec3::Y * y);
            m.positions.push(n * radius + Vec3::Y * y);
            m.normals.extend([n, n]);
            if textured {
                let s = j as f32 / SEGMENTS as f32;
                m.texcoords.extend([Vec2::new(s, 0.0), Vec2::new(s, 1.0)]);
            }
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
        cap(&mut m, radius, y, true, textured);
    }
    if bottom {
        cap(&mut m, radius, -y, false, textured);
    }
    m
}

/// VRML97 Cone: apex at `+height/2`, base disc of `bottom_radius` at `-height/2`.
pub fn cone(bottom_radius: f32, height: f32, side: bool, bottom: bool) -> Mesh {
    cone_with(bottom_radius, height, side, bottom, false)
}

/// A Cone with the default texture mapping.
pub fn cone_textured(bottom_radius: f32, height: f32, side: bool, bottom: bool) -> Mesh {
    cone_with(bottom_radius, height, side, bottom, true)
}

fn cone_with(bottom_radius: f32, height: f32, side: bool, bottom: bool, textured: bool) -> Mesh {
    let mut m = named("Cone");
    let y = height * 0.5;
    if side {
        // Outward normal of the slanted side at angle θ: (h·sinθ, r, h·cosθ), normalised.
        let slant = Vec3::new(height, bottom_radius, height);
        let start = if textured { PI } else { 0.0 };
        let normal_at = |j: f32| {
            let t = TAU * j / SEGMENTS as f32 + start;
            (Vec3::new(libm::sinf(t), 1.0, libm::cosf(t)) * slant).normalize_or_zero()
        };
        for j in 0..SEGMENTS {
            let base = m.positions.len() as u32;
            let r0 = around_from(j, 1.0, 0.0, textured);
            let r1 = around_from(j + 1, 1.0, 0.0, textured);
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
            if textured {
                let s = |k: f32| k / SEGMENTS as f32;
                let j = j as f32;
                m.texcoords.extend([
                    Vec2::new(s(j), 0.0),
                    Vec2::new(s(j + 1.0), 0.0),
                    Vec2::new(s(j + 0.5), 1.0),
                ]);
            }
        }
    }
    if bottom {
        cap(&mut m, bottom_radius, -y, false, textured);
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
/// With `from_back` the angle starts at −z instead: the textured shapes'
/// seam.
fn around_from(j: u32, ring: f32, y: f32, from_back: bool) -> Vec3 {
    let start = if from_back { PI } else { 0.0 };
    let t = TAU * (j % SEGMENTS) as f32 / SEGMENTS as f32 + start;
    Vec3::new(ring * libm::sinf(t), y, ring * libm::cosf(t))
}

/// A flat disc at height `y` facing +y (`up`) or −y; `textured` adds the
/// disc cut from the image (upright seen from outside with the top tilted
/// toward +z for the top cap, toward −z for the bottom one).
fn cap(m: &mut Mesh, radius: f32, y: f32, up: bool, textured: bool) {
    let n = if up { Vec3::Y } else { Vec3::NEG_Y };
    let centre = m.positions.len() as u32;
    m.positions.push(Vec3::Y * y);
    m.normals.push(n);
    let flip = if up { -1.0 } else { 1.0 };
    if textured {
        m.texcoords.push(Vec2::splat(0.5));
    }
    for j in 0..=SEGMENTS {
        let p = around_from(j, radius, y, textured);
        m.positions.push(p);
        m.normals.push(n);
        if textured {
            let r = 0.5 / radius.abs().max(f32::MIN_POSITIVE);
            m.texcoords
                .push(Vec2::new(0.5 + p.x * r, 0.5 + flip * p.z * r));
        }
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

    /// The texture coordinate of the vertex nearest `p` among those with
    /// normal `n`.
    fn uv_near(m: &Mesh, p: Vec3, n: Vec3) -> Vec2 {
        let k = (0..m.positions.len())
            .filter(|&k| m.normals[k].dot(n) > 0.99)
            .min_by(|&a, &b| {
                let da = m.positions[a].distance(p);
                let db = m.positions[b].distance(p);
                da.total_cmp(&db)
            })
            .unwrap();
        m.texcoords[k]
    }

    #[test]
    fn textured_primitives_follow_the_default_mappings() {
        let b = box_mesh(Vec3::splat(2.0));
        assert_eq!(b.texcoords.len(), b.positions.len());
        // Front face: lower-left corner (−x, −y) is (0, 0); top face: the
        // back-left corner (−x, −z) is (0, 1) (upright with −z up).
        assert_eq!(uv_near(&b, Vec3::new(-1.0, -1.0, 1.0), Vec3::Z), Vec2::ZERO);
        assert_eq!(uv_near(&b, Vec3::new(1.0, 1.0, 1.0), Vec3::Z), Vec2::ONE);
        assert_eq!(
            uv_near(&b, Vec3::new(-1.0, 1.0, -1.0), Vec3::Y),
            Vec2::new(0.0, 1.0)
        );
        // Right face seen from +x: −z is right.
        assert_eq!(
            uv_near(&b, Vec3::new(1.0, -1.0, -1.0), Vec3::X),
            Vec2::new(1.0, 0.0)
        );

        let s = sphere_textured(1.0);
        check(&s, Vec3::splat(-1.0), Vec3::splat(1.0));
        assert_eq!(s.texcoords.len(), s.positions.len());
        // Front (+z) is the middle of the image; −x a quarter; seam at −z.
        let front = uv_near(&s, Vec3::Z, Vec3::Z);
        assert!((front - Vec2::new(0.5, 0.5)).length() < 1e-5, "{front}");
        let left = uv_near(&s, Vec3::NEG_X, Vec3::NEG_X);
        assert!((left - Vec2::new(0.25, 0.5)).length() < 1e-5, "{left}");
        // The untextured sphere is unchanged and has none.
        assert!(sphere(1.0).texcoords.is_empty());

        let c = cylinder_textured(1.0, 2.0, true, true, true);
        check(&c, Vec3::splat(-1.0), Vec3::splat(1.0));
        assert_eq!(c.texcoords.len(), c.positions.len());
        let top_front = uv_near(&c, Vec3::new(0.0, 1.0, 1.0), Vec3::Y);
        assert!(
            (top_front - Vec2::new(0.5, 0.0)).length() < 1e-5,
            "{top_front}"
        );
        let bottom_front = uv_near(&c, Vec3::new(0.0, -1.0, 1.0), Vec3::NEG_Y);
        assert!(
            (bottom_front - Vec2::new(0.5, 1.0)).length() < 1e-5,
            "{bottom_front}"
        );
        let k = cone_textured(1.0, 2.0, true, true);
        check(&k, Vec3::splat(-1.0), Vec3::splat(1.0));
        assert_eq!(k.texcoords.len(), k.positions.len());
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
