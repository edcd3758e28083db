//! An Inventor `Sphere` under `DrawStyle { style LINES }`, drawn as Coin
//! 4.0 draws it: its latitude/longitude grid at the `Complexity` value's
//! density, without the diagonals a triangulation adds.
//!
//! Our filled sphere is fine-grained (`primitives::SEGMENTS`), which drawn
//! as lines fills a small sphere solid. Coin's grid was probed through
//! pivy (`SoCallbackAction` triangles of `Complexity { value c } Sphere {}`,
//! c = 0 … 1): with n = ⌊30·c⌋ (in f32, as Coin computes it) there are
//! max(n, 4) slices around the y axis and max(n − 1, 2) bands from pole to
//! pole, the poles on ±y; slice j sits at angle 2πj/slices from −z towards
//! −x. Coin renders each band as a quad strip, so LINES shows the quads'
//! sides: meridians and parallels (the 640×480 picture of
//! `rotTransDragger.iv` shows exactly these).

use crate::scene::Mesh;
use glam::Vec3;
use std::f32::consts::{PI, TAU};

/// Inventor's default `Complexity.value`.
pub const DEFAULT_COMPLEXITY: f32 = 0.5;

/// (slices, bands) of Coin's sphere at complexity `c` (clamped to 0…1).
pub fn sphere_divisions(c: f32) -> (u32, u32) {
    let c = if c.is_finite() {
        c.clamp(0.0, 1.0)
    } else {
        0.5
    };
    let n = (30.0f32 * c) as u32;
    (n.max(4), n.saturating_sub(1).max(2))
}

/// A sphere of `radius` as Coin's grid at complexity `c`: vertices ring by
/// ring from +y to −y, unit normals, triangles for anything that fills it,
/// and `edges` = the meridians and parallels LINES draws.
pub fn sphere(radius: f32, c: f32) -> Mesh {
    let (slices, bands) = sphere_divisions(c);
    let mut m = Mesh {
        name: "Sphere".into(),
        solid: true,
        ..Mesh::default()
    };
    // Ring i (0 = north pole … bands = south pole) holds `slices` vertices;
    // the poles hold one each.
    let ring_start = |i: u32| -> u32 {
        match i {
            0 => 0,
            _ => 1 + (i - 1) * slices,
        }
    };
    for i in 0..=bands {
        let phi = PI * i as f32 / bands as f32;
        let (s, y) = (libm::sinf(phi), libm::cosf(phi));
        let count = if i == 0 || i == bands { 1 } else { slices };
        for j in 0..count {
            let t = TAU * j as f32 / slices as f32;
            let n = if count == 1 {
                Vec3::new(0.0, y.signum(), 0.0)
            } else {
                Vec3::new(-libm::sinf(t) * s, y, -libm::cosf(t) * s)
            };
            m.positions.push(n * radius);
            m.normals.push(n);
        }
    }
    let at = |i: u32, j: u32| -> u32 {
        if i == 0 || i == bands {
            ring_start(i)
        } else {
            ring_start(i) + j % slices
        }
    };
    for i in 0..bands {
        for j in 0..slices {
            // Seen from outside, +j runs to the right (at the front, +z,
            // it moves towards +x) and ring i is above ring i + 1, so
            // (upper j, lower j, upper j+1) is counter-clockwise.
            let (a, b) = (at(i, j), at(i + 1, j));
            let (a1, b1) = (at(i, j + 1), at(i + 1, j + 1));
            if i != 0 {
                m.triangles.push([a, b, a1]);
            }
            if i != bands - 1 {
                m.triangles.push([a1, b, b1]);
            }
            // The meridian piece of this band, and the parallel on the
            // band's upper ring (none at the pole).
            m.edges.push([a, b]);
            if i != 0 {
                m.edges.push([a, a1]);
            }
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coin's counts, as probed: triangles = slices · (2·bands − 2).
    #[test]
    fn divisions_follow_coins_complexity_rule() {
        for (c, slices, bands, tris) in [
            (0.0, 4, 2, 8),
            (0.1, 4, 2, 8),
            (0.2, 6, 5, 48),
            (0.3, 9, 8, 126),
            (0.5, 15, 14, 390),
            (0.7, 21, 20, 798),
            (1.0, 30, 29, 1680),
        ] {
            assert_eq!(sphere_divisions(c), (slices, bands), "{c}");
            let m = sphere(1.0, c);
            assert_eq!(m.triangles.len(), tris, "{c}");
            // Meridians: slices per band; parallels: slices per inner ring.
            assert_eq!(m.edges.len() as u32, slices * bands + slices * (bands - 1));
        }
        assert_eq!(sphere_divisions(f32::NAN), sphere_divisions(0.5));
        assert_eq!(sphere_divisions(7.0), sphere_divisions(1.0));
    }

    /// The first ring below the pole at complexity 0.5 is where Coin puts
    /// it: y = cos(π/14), its first vertex at −z, the next towards −x.
    #[test]
    fn vertices_sit_where_coin_puts_them() {
        let m = sphere(1.0, 0.5);
        assert_eq!(m.positions[0], Vec3::Y);
        let p = m.positions[1];
        assert!(
            (p - Vec3::new(0.0, 0.974_927_9, -0.222_520_9)).length() < 1e-5,
            "{p}"
        );
        let q = m.positions[2];
        assert!(
            (q - Vec3::new(-0.090_507_4, 0.974_927_9, -0.203_283)).length() < 1e-5,
            "{q}"
        );
        assert_eq!(*m.positions.last().unwrap(), Vec3::NEG_Y);
        for (p, n) in m.positions.iter().zip(&m.normals) {
            assert!((p.length() - 1.0).abs() < 1e-5 && (*p - *n).length() < 1e-6);
        }
        // Every triangle faces outwards (counter-clockwise from outside).
        for t in &m.triangles {
            let [a, b, c] = t.map(|k| m.positions[k as usize]);
            let n = (b - a).cross(c - a);
            assert!(n.dot(a + b + c) > 0.0, "{t:?}");
        }
    }
}
