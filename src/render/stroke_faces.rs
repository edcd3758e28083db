//! Which edges and corners of a solid surface the Lines and Points styles
//! draw.
//!
//! Why: Coin draws these styles as OpenGL polygon modes (`glPolygonMode`
//! `GL_LINE` / `GL_POINT`), and OpenGL culls back faces before it turns a
//! polygon into its edges or corners (OpenGL 2.1 §3.5.1, "Polygon
//! Rasterization": culling, then §3.5.4 "Options Controlling Polygon
//! Rasterization"). So a solid shape (VRML97 `solid TRUE`, Inventor
//! `ShapeHints` SOLID with a known vertex ordering) shows only the edges
//! and corners of the polygons that face the eye, lit one-sided by the
//! normals as given; a shape that is not solid shows every edge, lit on the
//! side that faces the eye (`raster::facing`).

use super::clip::ClipVert;
use std::collections::HashSet;

/// Whether triangle `t` (counter-clockwise seen from its front) faces the
/// eye. The sign of det[x y w] of its clip-space vertices is the sign of
/// its window-space area whatever the signs of w (Olano & Greer,
/// "Triangle Scan Conversion using 2D Homogeneous Coordinates", 1997), so
/// triangles crossing the eye plane need no clipping first. A zero area is
/// back-facing, as OpenGL counts it (front is a > 0 for CCW).
fn faces_eye(t: [u32; 3], verts: &[ClipVert]) -> bool {
    let [a, b, c] = t.map(|i| verts[i as usize].clip);
    // Rows (x, y, w) of the three vertices; the determinant in f64 so that
    // large coordinates do not cancel to a wrong sign.
    let r = |v: glam::Vec4| [v.x as f64, v.y as f64, v.w as f64];
    let (a, b, c) = (r(a), r(b), r(c));
    let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0]);
    det > 0.0
}

fn key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    (u64::from(lo) << 32) | u64::from(hi)
}

/// The triangles that index only existing vertices.
fn valid<'a>(
    triangles: &'a [[u32; 3]],
    verts: &'a [ClipVert],
) -> impl Iterator<Item = [u32; 3]> + 'a {
    let n = verts.len();
    triangles
        .iter()
        .copied()
        .filter(move |t| t.iter().all(|&i| (i as usize) < n))
}

/// The `edges` a solid mesh draws in the Lines style: those of a triangle
/// facing the eye, and those no triangle has (line sets drawn with it).
pub fn front_edges(
    triangles: &[[u32; 3]],
    edges: &[[u32; 2]],
    verts: &[ClipVert],
) -> Vec<[u32; 2]> {
    let mut front = HashSet::new();
    let mut any = HashSet::new();
    for t in valid(triangles, verts) {
        let sides = [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]];
        let faces = faces_eye(t, verts);
        for [a, b] in sides {
            any.insert(key(a, b));
            if faces {
                front.insert(key(a, b));
            }
        }
    }
    edges
        .iter()
        .copied()
        .filter(|&[a, b]| front.contains(&key(a, b)) || !any.contains(&key(a, b)))
        .collect()
}

/// The vertices a solid mesh draws in the Points style, in index order:
/// the corners of triangles facing the eye, and every vertex no triangle
/// uses.
pub fn front_corners(triangles: &[[u32; 3]], verts: &[ClipVert]) -> Vec<u32> {
    // 0: no triangle uses it, 1: only back faces, 2: a front face.
    let mut state = vec![0u8; verts.len()];
    for t in valid(triangles, verts) {
        let s = if faces_eye(t, verts) { 2 } else { 1 };
        for i in t {
            let v = &mut state[i as usize];
            *v = (*v).max(s);
        }
    }
    (0..verts.len() as u32)
        .filter(|&i| state[i as usize] != 1)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::clip::ATTRS;
    use glam::Vec4;

    fn v(x: f32, y: f32, w: f32) -> ClipVert {
        ClipVert {
            clip: Vec4::new(x, y, 0.0, w),
            attr: [0.0; ATTRS],
        }
    }

    /// Two triangles sharing edge 1–2: 0,1,2 counter-clockwise (front),
    /// 1,3,2 clockwise on screen (back); a lone vertex 4 and a line 4–0.
    fn pair() -> (Vec<[u32; 3]>, Vec<ClipVert>) {
        let verts = vec![
            v(0.0, 0.0, 1.0),
            v(1.0, 0.0, 1.0),
            v(0.0, 1.0, 1.0),
            v(1.0, 1.0, 1.0),
            v(5.0, 5.0, 1.0),
        ];
        (vec![[0, 1, 2], [1, 2, 3]], verts)
    }

    #[test]
    fn back_faces_lose_their_own_edges_but_share_the_front_ones() {
        let (tris, verts) = pair();
        assert!(faces_eye(tris[0], &verts));
        assert!(!faces_eye(tris[1], &verts));
        let edges = [[0, 1], [1, 2], [2, 0], [1, 3], [3, 2], [4, 0]];
        // 1–3 and 3–2 belong to the back face only; 4–0 to no triangle.
        assert_eq!(
            front_edges(&tris, &edges, &verts),
            vec![[0, 1], [1, 2], [2, 0], [4, 0]]
        );
    }

    #[test]
    fn back_face_corners_go_unless_a_front_face_or_no_face_has_them() {
        let (tris, verts) = pair();
        assert_eq!(front_corners(&tris, &verts), vec![0, 1, 2, 4]);
    }

    #[test]
    fn facing_holds_for_negative_w_as_for_the_projected_area() {
        // Every clip coordinate negated and doubled: the same points on
        // screen, but the triangle mirrored through the eye, which sees it
        // from its other side; det[x y w] says so (three negations), where
        // the projected area alone would not.
        let (tris, verts) = pair();
        let neg: Vec<ClipVert> = verts
            .iter()
            .map(|c| v(-2.0 * c.clip.x, -2.0 * c.clip.y, -2.0 * c.clip.w))
            .collect();
        assert!(faces_eye(tris[0], &verts));
        assert!(!faces_eye(tris[0], &neg));
        // A face seen edge-on (zero area) is a back face, as in OpenGL.
        let flat = vec![v(0.0, 0.0, 1.0), v(1.0, 0.0, 1.0), v(2.0, 0.0, 1.0)];
        assert!(!faces_eye([0, 1, 2], &flat));
    }
}
