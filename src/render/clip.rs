//! Clipping in homogeneous clip space (before the divide by w), so triangles
//! that cross the eye plane come out right: Sutherland–Hodgman against the
//! near plane `z ≥ −w` and a guard band `|x|, |y| ≤ G·w` that keeps screen
//! coordinates small enough for the fixed-point rasteriser. Sides of the
//! screen inside the guard band are handled by the rasteriser's bounding box.

use glam::Vec4;

/// Number of per-vertex attributes carried through clipping and
/// interpolated per pixel: world position (3), normal (3), colour (3),
/// texture coordinates (2; zero when the mesh has none, and interpolated
/// per pixel only for textured items).
pub const ATTRS: usize = 11;
/// Where each attribute starts in the array.
pub const A_POS: usize = 0;
pub const A_NORMAL: usize = 3;
pub const A_COLOR: usize = 6;
pub const A_UV: usize = 9;

/// A vertex in clip space with its attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVert {
    pub clip: Vec4,
    pub attr: [f32; ATTRS],
}

impl ClipVert {
    fn lerp(&self, other: &ClipVert, t: f32) -> ClipVert {
        let mut attr = [0.0; ATTRS];
        for (k, a) in attr.iter_mut().enumerate() {
            *a = self.attr[k] + (other.attr[k] - self.attr[k]) * t;
        }
        ClipVert {
            clip: self.clip + (other.clip - self.clip) * t,
            attr,
        }
    }
}

/// The planes as `dot(plane, clip) ≥ 0`: near, then the guard band.
fn planes(guard: f32) -> [Vec4; 5] {
    [
        Vec4::new(0.0, 0.0, 1.0, 1.0),
        Vec4::new(-1.0, 0.0, 0.0, guard),
        Vec4::new(1.0, 0.0, 0.0, guard),
        Vec4::new(0.0, -1.0, 0.0, guard),
        Vec4::new(0.0, 1.0, 0.0, guard),
    ]
}

/// True when every vertex is strictly inside every plane (the common case:
/// no clipping work needed). Set-up asks [`sides`] once per vertex; this is
/// the per-triangle form the tests check it against.
#[cfg(test)]
pub fn inside_all(v: &[ClipVert], guard: f32) -> bool {
    let ps = planes(guard);
    v.iter().all(|v| ps.iter().all(|p| p.dot(v.clip) > 0.0))
}

/// True when all vertices are outside one plane (nothing to draw); see
/// [`inside_all`].
#[cfg(test)]
pub fn outside_one(v: &[ClipVert], guard: f32) -> bool {
    planes(guard)
        .iter()
        .any(|p| v.iter().all(|v| p.dot(v.clip) < 0.0))
}

/// Which sides of the clip planes a vertex is on: bit p when it is
/// strictly inside plane p, bit 8 + p when strictly outside (the tests
/// [`inside_all`] and [`outside_one`] make, once per vertex: a triangle
/// is inside all when the AND of its vertices' bits has all five low
/// bits, outside one when it has any high bit).
pub fn sides(clip: Vec4, guard: f32) -> u16 {
    let mut s = 0;
    for (k, p) in planes(guard).iter().enumerate() {
        let d = p.dot(clip);
        s |= ((d > 0.0) as u16) << k | ((d < 0.0) as u16) << (8 + k);
    }
    s
}

/// [`sides`] bits of a vertex inside every plane.
pub const INSIDE_ALL: u16 = 0x1F;

/// Clips a convex polygon; returns the clipped polygon (maybe empty).
pub fn clip_polygon(poly: &[ClipVert], guard: f32) -> Vec<ClipVert> {
    let mut cur: Vec<ClipVert> = poly.to_vec();
    let mut next = Vec::with_capacity(poly.len() + 5);
    for p in planes(guard) {
        if cur.is_empty() {
            break;
        }
        next.clear();
        for i in 0..cur.len() {
            let a = &cur[i];
            let b = &cur[(i + 1) % cur.len()];
            let (da, db) = (p.dot(a.clip), p.dot(b.clip));
            if da >= 0.0 {
                next.push(*a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                next.push(a.lerp(b, da / (da - db)));
            }
        }
        std::mem::swap(&mut cur, &mut next);
    }
    cur
}

/// Clips a segment; `None` when nothing is left.
pub fn clip_segment(a: &ClipVert, b: &ClipVert, guard: f32) -> Option<(ClipVert, ClipVert)> {
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for p in planes(guard) {
        let (da, db) = (p.dot(a.clip), p.dot(b.clip));
        if da < 0.0 && db < 0.0 {
            return None;
        }
        if da < 0.0 {
            t0 = t0.max(da / (da - db));
        } else if db < 0.0 {
            t1 = t1.min(da / (da - db));
        }
    }
    if t0 > t1 {
        return None;
    }
    Some((a.lerp(b, t0), a.lerp(b, t1)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::internals::render::test_rng::XorShift;

    fn v(x: f32, y: f32, z: f32, w: f32) -> ClipVert {
        ClipVert {
            clip: Vec4::new(x, y, z, w),
            attr: [z; ATTRS],
        }
    }

    #[test]
    fn triangle_crossing_near_plane_becomes_quad_on_the_plane() {
        // One vertex behind the near plane (z < −w).
        let tri = [
            v(0.0, 0.0, -3.0, 1.0),
            v(1.0, 0.0, 0.0, 1.0),
            v(0.0, 1.0, 0.0, 1.0),
        ];
        assert!(!inside_all(&tri, 100.0));
        let out = clip_polygon(&tri, 100.0);
        assert_eq!(out.len(), 4);
        for o in &out {
            assert!(o.clip.z + o.clip.w >= -1e-6, "{:?}", o.clip);
        }
        // The two new vertices lie exactly on the plane; attributes interpolated.
        let on_plane: Vec<_> = out
            .iter()
            .filter(|o| (o.clip.z + o.clip.w).abs() < 1e-6)
            .collect();
        assert_eq!(on_plane.len(), 2);
        assert!(on_plane.iter().all(|o| (o.attr[0] + 1.0).abs() < 1e-6));
    }

    #[test]
    fn fully_behind_is_dropped_and_inside_is_kept() {
        let behind = [
            v(0.0, 0.0, -3.0, 1.0),
            v(1.0, 0.0, -2.0, 1.0),
            v(0.0, 1.0, -5.0, 1.0),
        ];
        assert!(outside_one(&behind, 100.0));
        assert!(clip_polygon(&behind, 100.0).is_empty());
        let inside = [
            v(0.0, 0.0, 0.0, 1.0),
            v(0.5, 0.0, 0.0, 1.0),
            v(0.0, 0.5, 0.0, 1.0),
        ];
        assert!(inside_all(&inside, 100.0));
        assert_eq!(clip_polygon(&inside, 100.0), inside.to_vec());
    }

    /// The per-vertex `sides` bits answer both triangle tests as they do,
    /// on vertices on, inside and outside every plane.
    #[test]
    fn sides_per_vertex_agree_with_the_triangle_tests() {
        let coords = [-2.0f32, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 150.0, -150.0];
        let mut rng = XorShift::new(0x2545_F491_4F6C_DD1D);
        let mut pick = || coords[(rng.next_u64() % coords.len() as u64) as usize];
        let (mut inside, mut outside) = (0, 0);
        for _ in 0..20_000 {
            let tri = [0, 1, 2].map(|_| v(pick(), pick(), pick(), pick().abs()));
            let both = tri.iter().fold(!0u16, |a, t| a & sides(t.clip, 100.0));
            assert_eq!(
                both & INSIDE_ALL == INSIDE_ALL,
                inside_all(&tri, 100.0),
                "{tri:?}"
            );
            assert_eq!(both >> 8 != 0, outside_one(&tri, 100.0), "{tri:?}");
            inside += inside_all(&tri, 100.0) as u32;
            outside += outside_one(&tri, 100.0) as u32;
        }
        assert!(inside > 100 && outside > 100, "{inside} {outside}");
    }

    #[test]
    fn guard_band_bounds_coordinates() {
        let huge = [
            v(-1e6, 0.0, 0.0, 1.0),
            v(1e6, 0.0, 0.0, 1.0),
            v(0.0, 1.0, 0.0, 1.0),
        ];
        for o in clip_polygon(&huge, 50.0) {
            assert!(o.clip.x.abs() <= 50.0 * o.clip.w + 1e-3);
        }
    }

    #[test]
    fn segment_clipping() {
        let (a, b) = clip_segment(&v(0.0, 0.0, -3.0, 1.0), &v(0.0, 0.0, 1.0, 1.0), 10.0).unwrap();
        assert!((a.clip.z + 1.0).abs() < 1e-6);
        assert_eq!(b.clip.z, 1.0);
        assert!(clip_segment(&v(0.0, 0.0, -3.0, 1.0), &v(0.0, 0.0, -2.0, 1.0), 10.0).is_none());
    }
}
