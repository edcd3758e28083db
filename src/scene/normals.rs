//! Building a drawable [`Mesh`] from polygon lists the way VRML97
//! IndexedFaceSet (ISO/IEC 14772-1 §6.23) and Inventor's IndexedFaceSet
//! describe them: arbitrary (possibly concave) polygons, `ccw`, `solid`,
//! `creaseAngle`, and colours/normals bound per face, per vertex or per
//! face-vertex.
//!
//! Readers call [`mesh_from_polygons`] with the raw index lists already split
//! at the `-1` separators; every index is checked, so hostile input gives a
//! [`MeshError`], never a panic.

use super::Mesh;
use glam::{Vec2, Vec3};
use std::collections::HashMap;

/// How colours or normals are bound to the polygons (VRML97 §6.23,
/// `colorPerVertex`/`colorIndex`, `normalPerVertex`/`normalIndex`).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Binding {
    /// Not given (normals are then computed with the crease angle; colours
    /// come from the material).
    #[default]
    None,
    /// One value per face: `values[index[f]]`, or `values[f]` when `index`
    /// is `None` (an empty VRML index list).
    PerFace {
        values: Vec<Vec3>,
        index: Option<Vec<u32>>,
    },
    /// One value per face corner: `values[index[f][k]]` where `index` has the
    /// same shape as the faces, or `values[faces[f][k]]` (the coordinate
    /// index) when `index` is `None`.
    PerVertex {
        values: Vec<Vec3>,
        index: Option<Vec<Vec<u32>>>,
    },
}

/// Everything about a polygon set besides positions and faces.
#[derive(Clone, Debug, PartialEq)]
pub struct PolyOptions {
    /// Vertices are listed counter-clockwise seen from the front. When false
    /// every triangle is flipped (and computed normals with it).
    pub ccw: bool,
    /// Back faces may be culled.
    pub solid: bool,
    /// Radians; adjacent faces whose normals differ by at most this share a
    /// smooth vertex normal. VRML97 default 0 (faceted), Inventor default 0.5.
    pub crease_angle: f32,
    pub normals: Binding,
    pub colors: Binding,
    pub name: String,
}

impl Default for PolyOptions {
    /// The VRML97 IndexedFaceSet defaults.
    fn default() -> Self {
        PolyOptions {
            ccw: true,
            solid: true,
            crease_angle: 0.0,
            normals: Binding::None,
            colors: Binding::None,
            name: String::new(),
        }
    }
}

/// A bad index in the input; `face` is the 0-based polygon it occurs in.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshError {
    pub face: usize,
    pub message: String,
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "face {}: {}", self.face, self.message)
    }
}

impl std::error::Error for MeshError {}

/// Polygons with more corners than this are fanned instead of ear-clipped
/// (ear clipping is quadratic; this bounds what a hostile file can cost).
const MAX_EAR_CLIP: usize = 1024;
/// Vertices shared by more faces than this get the plain average of all
/// their faces (the crease test is quadratic in the valence).
const MAX_CREASE_VALENCE: usize = 512;

/// Texture coordinates of polygons: `values[index[f][k]]` for corner `k`
/// of face `f`, or `values[faces[f][k]]` (the coordinate index) when
/// `index` is `None` (VRML97 `texCoordIndex`, Inventor
/// `textureCoordIndex`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TexCoords {
    pub values: Vec<Vec2>,
    pub index: Option<Vec<Vec<u32>>>,
}

/// Builds a mesh from polygons. Faces with fewer than 3 corners are skipped.
/// Output vertices are unwelded wherever normal or colour differ between the
/// faces that share a position, and welded back where they are equal.
pub fn mesh_from_polygons(
    positions: &[Vec3],
    faces: &[Vec<u32>],
    opts: &PolyOptions,
) -> Result<Mesh, MeshError> {
    mesh_from_polygons_textured(positions, faces, opts, None)
}

/// [`mesh_from_polygons`] with texture coordinates, which unweld vertices
/// like normals and colours do.
pub fn mesh_from_polygons_textured(
    positions: &[Vec3],
    faces: &[Vec<u32>],
    opts: &PolyOptions,
    texcoords: Option<&TexCoords>,
) -> Result<Mesh, MeshError> {
    mesh_from_polygons_corners(positions, faces, opts, texcoords).map(|(m, _)| m)
}

/// [`mesh_from_polygons_textured`] that also returns, for every face
/// corner in order (faces of fewer than 3 corners included), the output
/// vertex it became: what a morph needs to follow the file's points into
/// the welded mesh.
pub fn mesh_from_polygons_corners(
    positions: &[Vec3],
    faces: &[Vec<u32>],
    opts: &PolyOptions,
    texcoords: Option<&TexCoords>,
) -> Result<(Mesh, Vec<u32>), MeshError> {
    for (f, face) in faces.iter().enumerate() {
        check_indices(f, face, positions.len(), "coordinate")?;
    }
    let uvs = match texcoords {
        Some(t) => Some(resolve_uv(t, faces)?),
        None => None,
    };
    let colors = resolve(&opts.colors, faces, positions.len(), "color")?;
    let given_normals = resolve(&opts.normals, faces, positions.len(), "normal")?;

    // Face normals (Newell's method gives the best-fit plane of a polygon),
    // flipped when the polygons are clockwise.
    let sign = if opts.ccw { 1.0 } else { -1.0 };
    let face_normals: Vec<Vec3> = faces
        .iter()
        .map(|f| sign * newell(positions, f).normalize_or_zero())
        .collect();

    let corner_normals = match given_normals {
        Some(n) => n.into_iter().map(unit_as_given).collect(),
        None => crease_normals(positions.len(), faces, &face_normals, opts.crease_angle),
    };

    // Weld (position, normal, colour) triples into output vertices.
    let mut mesh = Mesh {
        name: opts.name.clone(),
        solid: opts.solid,
        ..Mesh::default()
    };
    type Key = (u32, [u32; 3], [u32; 3], [u32; 2]);
    let mut welded: HashMap<Key, u32> = HashMap::new();
    let mut corners: Vec<u32> = Vec::with_capacity(faces.iter().map(Vec::len).sum());
    let mut corner = 0usize;
    // Whether some face has more than 3 corners (else no outline is kept).
    let mut polygons = false;
    for face in faces {
        let n = face.len();
        let mut out = Vec::with_capacity(n);
        for (k, &p) in face.iter().enumerate() {
            let nrm = corner_normals[corner + k];
            let col = colors.as_ref().map(|c| c[corner + k]);
            let uv = uvs.as_ref().map(|t| t[corner + k]);
            let uv_bits = uv.map_or([0; 2], |v| [v.x.to_bits(), v.y.to_bits()]);
            let key = (p, bits(nrm), bits(col.unwrap_or(Vec3::ZERO)), uv_bits);
            let idx = *welded.entry(key).or_insert_with(|| {
                mesh.positions.push(positions[p as usize]);
                mesh.normals.push(nrm);
                if let Some(c) = col {
                    mesh.colors.push(c);
                }
                if let Some(t) = uv {
                    mesh.texcoords.push(t);
                }
                mesh.positions.len() as u32 - 1
            });
            out.push(idx);
        }
        corners.extend_from_slice(&out);
        corner += n;
        if n < 3 {
            continue;
        }
        polygons |= n > 3;
        mesh.edges
            .extend((0..n).map(|k| [out[k], out[(k + 1) % n]]));
        for [a, b, c] in triangulate(positions, face) {
            let t = [out[a], out[b], out[c]];
            mesh.triangles
                .push(if opts.ccw { t } else { [t[0], t[2], t[1]] });
        }
    }
    if !polygons {
        mesh.edges = Vec::new();
    }
    Ok((mesh, corners))
}

/// A line mesh from VRML IndexedLineSet polylines; `colors` is bound per
/// polyline (`PerFace`) or per vertex like [`mesh_from_polygons`].
pub fn mesh_from_polylines(
    positions: &[Vec3],
    polylines: &[Vec<u32>],
    colors: &Binding,
) -> Result<Mesh, MeshError> {
    for (f, line) in polylines.iter().enumerate() {
        check_indices(f, line, positions.len(), "coordinate")?;
    }
    let cols = resolve(colors, polylines, positions.len(), "color")?;
    let mut mesh = Mesh::default();
    let mut corner = 0;
    for line in polylines {
        let base = mesh.positions.len() as u32;
        for (k, &p) in line.iter().enumerate() {
            mesh.positions.push(positions[p as usize]);
            if let Some(c) = &cols {
                mesh.colors.push(c[corner + k]);
            }
        }
        for k in 1..line.len() as u32 {
            mesh.lines.push([base + k - 1, base + k]);
        }
        corner += line.len();
    }
    Ok(mesh)
}

/// One normal per polyline corner, in the order [`mesh_from_polylines`]
/// lays out its vertices (`None` when `normals` is [`Binding::None`]): an
/// Inventor line set with normals is lit, as Coin lights it.
pub fn polyline_normals(
    positions: usize,
    polylines: &[Vec<u32>],
    normals: &Binding,
) -> Result<Option<Vec<Vec3>>, MeshError> {
    resolve(normals, polylines, positions, "normal")
}

/// A point mesh (VRML PointSet); `colors`, when given, must be as long as
/// `positions` (extra colours are ignored, too few is an error).
pub fn mesh_from_points(positions: &[Vec3], colors: Option<&[Vec3]>) -> Result<Mesh, MeshError> {
    let mut mesh = Mesh {
        positions: positions.to_vec(),
        points: (0..positions.len() as u32).collect(),
        ..Mesh::default()
    };
    if let Some(c) = colors {
        if c.len() < positions.len() {
            return Err(MeshError {
                face: 0,
                message: format!("{} colours for {} points", c.len(), positions.len()),
            });
        }
        mesh.colors = c[..positions.len()].to_vec();
    }
    Ok(mesh)
}

fn bits(v: Vec3) -> [u32; 3] {
    [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]
}

fn check_indices(face: usize, idx: &[u32], len: usize, what: &str) -> Result<(), MeshError> {
    match idx.iter().find(|&&i| i as usize >= len) {
        Some(&i) => Err(MeshError {
            face,
            message: format!("{what} index {i} out of range (only {len} values)"),
        }),
        None => Ok(()),
    }
}

/// Expands a binding into one value per face corner (in face order).
fn resolve(
    b: &Binding,
    faces: &[Vec<u32>],
    _n_positions: usize,
    what: &str,
) -> Result<Option<Vec<Vec3>>, MeshError> {
    let corners: usize = faces.iter().map(|f| f.len()).sum();
    let mut out = Vec::with_capacity(corners);
    match b {
        Binding::None => return Ok(None),
        Binding::PerFace { values, index } => {
            for (f, face) in faces.iter().enumerate() {
                let i = match index {
                    Some(ix) => *ix.get(f).ok_or_else(|| MeshError {
                        face: f,
                        message: format!("{what} index list has only {} entries", ix.len()),
                    })? as usize,
                    None => f,
                };
                let v = *values.get(i).ok_or_else(|| MeshError {
                    face: f,
                    message: format!("{what} {i} out of range (only {} values)", values.len()),
                })?;
                out.extend(std::iter::repeat_n(v, face.len()));
            }
        }
        Binding::PerVertex { values, index } => {
            for (f, face) in faces.iter().enumerate() {
                let ix: &[u32] = match index {
                    Some(ix) => {
                        let row = ix.get(f).ok_or_else(|| MeshError {
                            face: f,
                            message: format!("{what} index list has only {} polygons", ix.len()),
                        })?;
                        if row.len() < face.len() {
                            return Err(MeshError {
                                face: f,
                                message: format!(
                                    "{what} index list has {} entries for {} vertices",
                                    row.len(),
                                    face.len()
                                ),
                            });
                        }
                        row
                    }
                    None => face,
                };
                check_indices(f, &ix[..face.len()], values.len(), what)?;
                out.extend(ix[..face.len()].iter().map(|&i| values[i as usize]));
            }
        }
    }
    Ok(Some(out))
}

/// Expands texture coordinates into one per face corner (in face order).
fn resolve_uv(t: &TexCoords, faces: &[Vec<u32>]) -> Result<Vec<Vec2>, MeshError> {
    let corners: usize = faces.iter().map(|f| f.len()).sum();
    let mut out = Vec::with_capacity(corners);
    for (f, face) in faces.iter().enumerate() {
        let ix: &[u32] = match &t.index {
            Some(ix) => {
                let row = ix.get(f).map(Vec::as_slice).unwrap_or(&[]);
                if row.len() < face.len() {
                    return Err(MeshError {
                        face: f,
                        message: format!(
                            "texture coordinate index list has {} entries for {} vertices",
                            row.len(),
                            face.len()
                        ),
                    });
                }
                row
            }
            None => face,
        };
        check_indices(f, &ix[..face.len()], t.values.len(), "texture coordinate")?;
        out.extend(ix[..face.len()].iter().map(|&i| t.values[i as usize]));
    }
    Ok(out)
}

/// Newell's normal: area-weighted normal of a (possibly non-planar) polygon.
fn newell(p: &[Vec3], face: &[u32]) -> Vec3 {
    let mut n = Vec3::ZERO;
    for k in 0..face.len() {
        let a = p[face[k] as usize];
        let b = p[face[(k + 1) % face.len()] as usize];
        n += Vec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n
}

/// Per-corner normals: each corner averages the (unit) normals of the faces
/// around its position that are within `crease` of its own face's normal.
fn crease_normals(n_pos: usize, faces: &[Vec<u32>], fnorm: &[Vec3], crease: f32) -> Vec<Vec3> {
    let mut incident: Vec<Vec<u32>> = vec![Vec::new(); n_pos];
    for (f, face) in faces.iter().enumerate() {
        for &p in face {
            let list = &mut incident[p as usize];
            if list.last() != Some(&(f as u32)) {
                list.push(f as u32);
            }
        }
    }
    // Compare cosines; a small slack keeps exactly coplanar faces together at crease 0.
    let cos_crease = libm::cosf(crease) - 1e-5;
    let mut out = Vec::with_capacity(faces.iter().map(|f| f.len()).sum());
    for (f, face) in faces.iter().enumerate() {
        let nf = fnorm[f];
        for &p in face {
            let around = &incident[p as usize];
            let mut sum = Vec3::ZERO;
            if crease <= 0.0 {
                sum = nf;
            } else {
                let big = around.len() > MAX_CREASE_VALENCE;
                for &g in around {
                    let ng = fnorm[g as usize];
                    if big || nf.dot(ng) >= cos_crease {
                        sum += ng;
                    }
                }
            }
            let n = sum.normalize_or_zero();
            out.push(if n == Vec3::ZERO { nf } else { n });
        }
    }
    out
}

/// A given normal made unit length; one that already is (within a few
/// ulps, as a written and re-read unit normal is) is kept bit for bit, so
/// that reading a file and writing it again is a fixed point.
fn unit_as_given(n: Vec3) -> Vec3 {
    if (n.length_squared() - 1.0).abs() <= 4.0 * f32::EPSILON {
        n
    } else {
        n.normalize_or_zero()
    }
}

/// Splits one polygon into triangles (indices into `face`), keeping its
/// winding. Ear clipping on the polygon's best-fit plane; falls back to a fan
/// for degenerate or very large polygons.
pub fn triangulate(positions: &[Vec3], face: &[u32]) -> Vec<[usize; 3]> {
    let n = face.len();
    let fan = || (1..n.saturating_sub(1)).map(|k| [0, k, k + 1]).collect();
    if n < 3 {
        return Vec::new();
    }
    if n == 3 {
        return vec![[0, 1, 2]];
    }
    let normal = newell(positions, face);
    if n > MAX_EAR_CLIP || normal.length_squared() == 0.0 || !normal.is_finite() {
        return fan();
    }
    // 2D coordinates in the plane, oriented so the polygon is counter-clockwise.
    let normal = normal.normalize();
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let pts: Vec<(f64, f64)> = face
        .iter()
        .map(|&i| {
            let p = positions[i as usize];
            (p.dot(u) as f64, p.dot(v) as f64)
        })
        .collect();
    let cross = |a: usize, b: usize, c: usize| {
        let (ax, ay) = pts[a];
        let (bx, by) = pts[b];
        let (cx, cy) = pts[c];
        (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    };
    let mut ring: Vec<usize> = (0..n).collect();
    let mut tris = Vec::with_capacity(n - 2);
    while ring.len() > 3 {
        let m = ring.len();
        let ear = (0..m).find(|&i| {
            let (a, b, c) = (ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]);
            if cross(a, b, c) <= 0.0 {
                return false; // reflex or degenerate corner
            }
            ring.iter().all(|&q| {
                q == a
                    || q == b
                    || q == c
                    || pts[q] == pts[a]
                    || pts[q] == pts[b]
                    || pts[q] == pts[c]
                    || !(cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 && cross(c, a, q) >= 0.0)
            })
        });
        match ear {
            Some(i) => {
                tris.push([ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]]);
                ring.remove(i);
            }
            None => {
                // Self-intersecting or degenerate remainder: fan what is left.
                for k in 1..ring.len() - 1 {
                    tris.push([ring[0], ring[k], ring[k + 1]]);
                }
                return tris;
            }
        }
    }
    tris.push([ring[0], ring[1], ring[2]]);
    tris
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri_normal(m: &Mesh, t: [u32; 3]) -> Vec3 {
        let [a, b, c] = t.map(|i| m.positions[i as usize]);
        (b - a).cross(c - a)
    }

    fn area(m: &Mesh) -> f32 {
        m.triangles
            .iter()
            .map(|&t| tri_normal(m, t).length() / 2.0)
            .sum()
    }

    #[test]
    fn concave_l_shape_is_ear_clipped_with_exact_area() {
        // An L: 2x2 square minus the top-right 1x1 quadrant, area 3.
        let p = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(2.0, 1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(0.0, 2.0, 0.0),
        ];
        let m = mesh_from_polygons(&p, &[vec![0, 1, 2, 3, 4, 5]], &PolyOptions::default()).unwrap();
        assert_eq!(m.triangles.len(), 4);
        assert!((area(&m) - 3.0).abs() < 1e-5, "area {}", area(&m));
        for &t in &m.triangles {
            assert!(tri_normal(&m, t).z > 0.0, "all triangles keep CCW winding");
        }
    }

    #[test]
    fn concave_polygon_starting_at_reflex_vertex() {
        // Arrow shape whose first vertex is reflex: a fan from it would cover
        // area outside the polygon.
        let p = [
            Vec3::new(1.0, 1.0, 0.0), // reflex
            Vec3::new(0.0, 2.0, 0.0),
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(2.0, 2.0, 0.0),
        ];
        // (1,1) → (2,2) → (0,2) → (0,0) → (2,0): counter-clockwise, area 3.
        let face = vec![0u32, 4, 1, 2, 3];
        let m = mesh_from_polygons(&p, &[face], &PolyOptions::default()).unwrap();
        assert_eq!(m.triangles.len(), 3);
        assert!((area(&m) - 3.0).abs() < 1e-5, "area {}", area(&m));
        assert!(m.triangles.iter().all(|&t| tri_normal(&m, t).z > 0.0));
    }

    #[test]
    fn cw_flag_flips_triangles_and_normals() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let opts = PolyOptions {
            ccw: false,
            ..Default::default()
        };
        let m = mesh_from_polygons(&p, &[vec![0, 1, 2]], &opts).unwrap();
        assert!(tri_normal(&m, m.triangles[0]).z < 0.0);
        assert!(m.normals.iter().all(|n| (*n - Vec3::NEG_Z).length() < 1e-6));
    }

    /// Two faces of a roof meeting at 90°: with crease 0 the shared edge
    /// has two normals per position; with crease > 90° one averaged normal.
    #[test]
    fn crease_angle_decides_smooth_or_faceted() {
        let p = [
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, -1.0),
            Vec3::new(-1.0, 0.0, -1.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, -1.0),
        ];
        let faces = [vec![0, 1, 2, 3], vec![1, 4, 5, 2]];
        let faceted = mesh_from_polygons(&p, &faces, &PolyOptions::default()).unwrap();
        assert_eq!(faceted.positions.len(), 8);
        let smooth = mesh_from_polygons(
            &p,
            &faces,
            &PolyOptions {
                crease_angle: 1.6,
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(smooth.positions.len(), 6);
        let ridge = smooth
            .positions
            .iter()
            .position(|q| *q == Vec3::new(0.0, 1.0, 0.0))
            .unwrap();
        assert!((smooth.normals[ridge] - Vec3::Y).length() < 1e-6);
        // 1.5 rad < 90°: still faceted.
        let sharp = mesh_from_polygons(
            &p,
            &faces,
            &PolyOptions {
                crease_angle: 1.5,
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(sharp.positions.len(), 8);
    }

    #[test]
    fn per_face_and_per_vertex_colours() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE];
        let faces = [vec![0, 1, 2], vec![1, 3, 2]];
        let red = Vec3::X;
        let green = Vec3::Y;
        let opts = PolyOptions {
            colors: Binding::PerFace {
                values: vec![red, green],
                index: Some(vec![1, 0]),
            },
            ..Default::default()
        };
        let m = mesh_from_polygons(&p, &faces, &opts).unwrap();
        assert_eq!(m.colors.len(), m.positions.len());
        assert_eq!(m.colors[m.triangles[0][0] as usize], green);
        assert_eq!(m.colors[m.triangles[1][0] as usize], red);

        let opts = PolyOptions {
            colors: Binding::PerVertex {
                values: vec![red, green, Vec3::Z, Vec3::ONE],
                index: None,
            },
            ..Default::default()
        };
        let m = mesh_from_polygons(&p, &faces, &opts).unwrap();
        for (i, q) in m.positions.iter().enumerate() {
            let src = p.iter().position(|x| x == q).unwrap();
            assert_eq!(m.colors[i], [red, green, Vec3::Z, Vec3::ONE][src]);
        }
    }

    #[test]
    fn bad_indices_are_errors() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let e = mesh_from_polygons(&p, &[vec![0, 1, 2], vec![0, 1, 7]], &PolyOptions::default())
            .unwrap_err();
        assert_eq!(e.face, 1);
        assert!(e.to_string().contains("7"));
        let opts = PolyOptions {
            normals: Binding::PerVertex {
                values: vec![Vec3::Z],
                index: Some(vec![vec![0, 0]]),
            },
            ..Default::default()
        };
        assert!(mesh_from_polygons(&p, &[vec![0, 1, 2]], &opts).is_err());
        let opts = PolyOptions {
            colors: Binding::PerFace {
                values: vec![Vec3::Z],
                index: None,
            },
            ..Default::default()
        };
        assert!(mesh_from_polygons(&p, &[vec![0, 1, 2], vec![2, 1, 0]], &opts).is_err());
        assert!(mesh_from_polylines(&p, &[vec![0, 3]], &Binding::None).is_err());
        assert!(mesh_from_points(&p, Some(&[Vec3::ONE])).is_err());
    }

    #[test]
    fn explicit_normals_are_used() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let opts = PolyOptions {
            normals: Binding::PerFace {
                values: vec![Vec3::new(0.0, 0.0, 2.0)],
                index: None,
            },
            ..Default::default()
        };
        let m = mesh_from_polygons(&p, &[vec![0, 1, 2]], &opts).unwrap();
        assert!(m.normals.iter().all(|n| *n == Vec3::Z));
    }

    #[test]
    fn degenerate_faces_do_not_panic() {
        let p = [Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::X];
        let m = mesh_from_polygons(
            &p,
            &[vec![0, 1, 2, 3], vec![0], vec![], vec![0, 3]],
            &PolyOptions {
                crease_angle: 1.0,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(m.normals.iter().all(|n| n.is_finite()));
        assert_eq!(m.triangles.len(), 2);
    }

    #[test]
    fn polylines_and_points() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let m = mesh_from_polylines(&p, &[vec![0, 1, 2], vec![2, 0]], &Binding::None).unwrap();
        assert_eq!(m.lines.len(), 3);
        let m = mesh_from_points(&p, None).unwrap();
        assert_eq!(m.points, vec![0, 1, 2]);
    }
}
