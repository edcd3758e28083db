//! Helpers shared by the Inventor and VRML97 readers for polygon input:
//! splitting `-1`-separated index lists and calling the shared mesh builder
//! so that one bad index costs one face (or the colours), not the shape.

use crate::format::lexer::Pos;
use crate::scene::normals::{mesh_from_polygons_corners, Binding, PolyOptions, TexCoords};
use crate::scene::Mesh;
use glam::{Vec2, Vec3};

/// Splits an index list at negative entries (VRML's `-1` separators); a
/// trailing list without a separator counts too.
pub fn split_index(idx: &[i64]) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for &i in idx {
        if i < 0 {
            out.push(std::mem::take(&mut cur));
        } else {
            cur.push(i.min(u32::MAX as i64) as u32);
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// Empties faces that index past `len` (kept as empty faces so per-face
/// bindings stay aligned).
pub fn drop_bad(mut faces: Vec<Vec<u32>>, len: usize) -> Vec<Vec<u32>> {
    for f in &mut faces {
        if f.iter().any(|&i| i as usize >= len) {
            f.clear();
        }
    }
    faces
}

/// Builds a polygon mesh; bad coordinate indices drop their faces, bad
/// normal/colour bindings are dropped with a message.
pub fn build(
    positions: &[Vec3],
    faces: Vec<Vec<u32>>,
    opts: PolyOptions,
    pos: Pos,
    msgs: &mut Vec<(Pos, String)>,
) -> Option<Mesh> {
    build_textured(positions, faces, opts, None, pos, msgs)
}

/// [`build`] with texture coordinates; bad ones are dropped with a message
/// (the shape is then drawn untextured).
pub fn build_textured(
    positions: &[Vec3],
    faces: Vec<Vec<u32>>,
    opts: PolyOptions,
    texcoords: Option<TexCoords>,
    pos: Pos,
    msgs: &mut Vec<(Pos, String)>,
) -> Option<Mesh> {
    build_textured_corners(positions, faces, opts, texcoords, pos, msgs).map(|(m, _)| m)
}

/// [`build_textured`] that also returns the output vertex of every face
/// corner (see `scene::mesh_from_polygons_corners`).
pub fn build_textured_corners(
    positions: &[Vec3],
    faces: Vec<Vec<u32>>,
    mut opts: PolyOptions,
    mut texcoords: Option<TexCoords>,
    pos: Pos,
    msgs: &mut Vec<(Pos, String)>,
) -> Option<(Mesh, Vec<u32>)> {
    let n_before = faces.iter().filter(|f| !f.is_empty()).count();
    let faces = drop_bad(faces, positions.len());
    let dropped = n_before - faces.iter().filter(|f| !f.is_empty()).count();
    if dropped > 0 {
        msgs.push((
            pos,
            format!(
                "{dropped} faces index past the {} coordinates; skipped",
                positions.len()
            ),
        ));
    }
    for _ in 0..4 {
        match mesh_from_polygons_corners(positions, &faces, &opts, texcoords.as_ref()) {
            Ok(m) => return Some(m),
            Err(e) => {
                if texcoords.is_some() {
                    msgs.push((pos, format!("texture coordinates ignored: {e}")));
                    texcoords = None;
                } else if opts.colors != Binding::None {
                    msgs.push((pos, format!("colours ignored: {e}")));
                    opts.colors = Binding::None;
                } else if opts.normals != Binding::None {
                    msgs.push((pos, format!("normals ignored (recomputed): {e}")));
                    opts.normals = Binding::None;
                } else {
                    msgs.push((pos, format!("geometry skipped: {e}")));
                    return None;
                }
            }
        }
    }
    None
}

/// The default texture coordinates of a polygon set without any (VRML97
/// §6.23, Inventor's default the same): s runs 0..1 along the longest side
/// of the bounding box, t along the second longest from 0 to that side's
/// share of the longest (ties prefer x, then y, then z). One per position.
pub fn bbox_texcoords(positions: &[Vec3]) -> Vec<Vec2> {
    let Some((lo, hi)) = bounds(positions.iter()) else {
        return Vec::new();
    };
    bbox_map(positions, lo, hi)
}

/// Inventor's default texture coordinates (SGI Open Inventor 2.1
/// `SoTextureCoordinateBundle::setUpDefaultCoordSpace`, which Coin follows
/// in its axis choice): as [`bbox_texcoords`], but over the box of only the
/// positions `faces` use (a Coordinate3 shared by several shapes), and
/// with ties between sides going to the later axis (z before y before x).
/// One per position.
pub fn bbox_texcoords_inventor(positions: &[Vec3], faces: &[Vec<u32>]) -> Vec<Vec2> {
    let used = faces
        .iter()
        .flatten()
        .filter_map(|&i| positions.get(i as usize));
    let Some((lo, hi)) = bounds(used) else {
        return vec![Vec2::ZERO; positions.len()];
    };
    let size = hi - lo;
    let (s_axis, t_axis) = if size.x > size.y && size.x > size.z {
        (0, if size.y > size.z { 1 } else { 2 })
    } else if size.y > size.z {
        (1, if size.x > size.z { 0 } else { 2 })
    } else {
        (2, if size.x > size.y { 0 } else { 1 })
    };
    map_axes(positions, lo, size, s_axis, t_axis)
}

fn bounds<'a>(mut it: impl Iterator<Item = &'a Vec3>) -> Option<(Vec3, Vec3)> {
    let first = *it.next()?;
    Some(it.fold((first, first), |(lo, hi), p| (lo.min(*p), hi.max(*p))))
}

fn bbox_map(positions: &[Vec3], lo: Vec3, hi: Vec3) -> Vec<Vec2> {
    let size = hi - lo;
    let mut axes = [0usize, 1, 2];
    // Stable sort by decreasing size keeps x before y before z on ties.
    axes.sort_by(|&a, &b| size[b].total_cmp(&size[a]));
    map_axes(positions, lo, size, axes[0], axes[1])
}

/// s = (p − lo)/size along `s_axis`, t the same scale along `t_axis` (a
/// square texture stays square).
fn map_axes(positions: &[Vec3], lo: Vec3, size: Vec3, s_axis: usize, t_axis: usize) -> Vec<Vec2> {
    let scale = if size[s_axis] > 0.0 {
        1.0 / size[s_axis]
    } else {
        0.0
    };
    positions
        .iter()
        .map(|p| {
            Vec2::new(
                (p[s_axis] - lo[s_axis]) * scale,
                (p[t_axis] - lo[t_axis]) * scale,
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_handles_missing_trailing_separator() {
        assert_eq!(
            split_index(&[0, 1, 2, -1, 2, 3, 0]),
            vec![vec![0, 1, 2], vec![2, 3, 0]]
        );
        assert_eq!(split_index(&[0, 1, 2, -1]), vec![vec![0, 1, 2]]);
    }

    #[test]
    fn bad_faces_are_emptied_not_removed() {
        let f = drop_bad(vec![vec![0, 1, 2], vec![0, 9, 1], vec![2, 1, 0]], 3);
        assert_eq!(f, vec![vec![0, 1, 2], vec![], vec![2, 1, 0]]);
    }
}
