//! VRML97 geometry nodes → meshes: IndexedFaceSet, IndexedLineSet,
//! PointSet, ElevationGrid, Extrusion, and the four primitives.
//!
//! Polygons go through the shared builder (`scene::normals`), which
//! triangulates concave polygons and applies ccw/solid/creaseAngle.
//! Textured shapes get texture coordinates: the node's own, or the spec's
//! default mapping (IndexedFaceSet: the bounding box, §6.23; ElevationGrid:
//! the grid, §6.17; Extrusion: cross-section × spine, §6.18; primitives:
//! `scene::primitives`' textured builders).

use crate::format::corner_morph::Corners;
use crate::format::lexer::Pos;
use crate::format::limits;
use crate::format::polygons::{self, bbox_texcoords, split_index};
use crate::format::syntax::AstNode;
use crate::scene::normals::{
    mesh_from_points, mesh_from_polylines, Binding, PolyOptions, TexCoords,
};
use crate::scene::{Mesh, Morphs};
use glam::{Quat, Vec2, Vec3};

type Msgs = Vec<(Pos, String)>;

/// Builds the mesh of a geometry node, or `None` (with a message) when it
/// is unsupported or empty. `textured` asks for texture coordinates.
pub fn mesh(g: &AstNode, textured: bool, msgs: &mut Msgs) -> Option<Mesh> {
    let mut m = match g.kind.as_str() {
        "IndexedFaceSet" => indexed_face_set(g, textured, msgs),
        "IndexedLineSet" => indexed_line_set(g, msgs),
        "PointSet" => point_set(g, msgs),
        "ElevationGrid" => elevation_grid(g, textured, msgs),
        "Extrusion" => extrusion(g, textured, msgs),
        "Box" | "Sphere" | "Cone" | "Cylinder" => primitive(g, textured),
        "Text" => super::text::mesh(g, textured, msgs),
        k => {
            msgs.push((
                g.pos,
                format!("geometry node '{k}' is not supported; skipped"),
            ));
            None
        }
    }?;
    if let Some(d) = &g.def {
        m.name = d.clone();
    }
    Some(m)
}

fn vec3s(v: &[f64]) -> Vec<Vec3> {
    v.chunks_exact(3)
        .map(|c| Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32))
        .collect()
}

fn vec2s(v: &[f64]) -> Vec<Vec2> {
    v.chunks_exact(2)
        .map(|c| Vec2::new(c[0] as f32, c[1] as f32))
        .collect()
}

/// The values of a property node's field: `coord Coordinate { point [...] }`.
fn sub_values(g: &AstNode, field: &str, inner: &str) -> Option<Vec<Vec3>> {
    let n = g.node(field)?.effective();
    Some(vec3s(n.nums(inner)?))
}

fn indices(g: &AstNode, field: &str) -> Vec<i64> {
    g.nums(field)
        .map(|v| v.iter().map(|x| *x as i64).collect())
        .unwrap_or_default()
}

/// A colour or normal binding from VRML's `xxxPerVertex` + `xxxIndex` rules.
fn binding(values: Option<Vec<Vec3>>, index: &[i64], per_vertex: bool) -> Binding {
    let Some(values) = values else {
        return Binding::None;
    };
    if per_vertex {
        Binding::PerVertex {
            values,
            index: if index.is_empty() {
                None
            } else {
                Some(split_index(index))
            },
        }
    } else {
        Binding::PerFace {
            values,
            index: if index.is_empty() {
                None
            } else {
                Some(
                    index
                        .iter()
                        .filter(|&&i| i >= 0)
                        .map(|&i| i as u32)
                        .collect(),
                )
            },
        }
    }
}

/// The texture coordinates of a `texCoord TextureCoordinate { point }`.
fn texcoord_values(g: &AstNode) -> Option<Vec<Vec2>> {
    let n = g.node("texCoord")?.effective();
    Some(vec2s(n.nums("point")?))
}

fn indexed_face_set(g: &AstNode, textured: bool, msgs: &mut Msgs) -> Option<Mesh> {
    let positions = sub_values(g, "coord", "point").unwrap_or_default();
    let (faces, opts, texcoords) = ifs_parts(g, textured, &positions);
    polygons::build_textured(&positions, faces, opts, texcoords, g.pos, msgs)
}

/// An IndexedFaceSet's faces, options and texture coordinates (the
/// default mapping from `positions`' bounding box when it has none).
fn ifs_parts(
    g: &AstNode,
    textured: bool,
    positions: &[Vec3],
) -> (Vec<Vec<u32>>, PolyOptions, Option<TexCoords>) {
    let faces = split_index(&indices(g, "coordIndex"));
    let opts = PolyOptions {
        ccw: g.bool("ccw", true),
        solid: g.bool("solid", true),
        crease_angle: g.f32("creaseAngle", 0.0),
        normals: binding(
            sub_values(g, "normal", "vector"),
            &indices(g, "normalIndex"),
            g.bool("normalPerVertex", true),
        ),
        colors: binding(
            sub_values(g, "color", "color"),
            &indices(g, "colorIndex"),
            g.bool("colorPerVertex", true),
        ),
        name: String::new(),
    };
    let texcoords = textured.then(|| match texcoord_values(g) {
        Some(values) => {
            let index = indices(g, "texCoordIndex");
            TexCoords {
                values,
                index: (!index.is_empty()).then(|| split_index(&index)),
            }
        }
        None => TexCoords {
            values: bbox_texcoords(positions),
            index: None,
        },
    });
    (faces, opts, texcoords)
}

/// Morph targets that make an IndexedFaceSet's mesh (as `mesh` builds it)
/// take the point sets `keys` (each one point per `coord` point, as a
/// CoordinateInterpolator's keyValue holds them): target i moves every
/// vertex from its base point to key i's point, and its normal to the one
/// the same polygons get at key i (normals are recomputed, as VRML
/// browsers do when coordinates change, unless the node gives its own).
///
/// `normal_keys` (a NormalInterpolator moving with the points, one vector
/// list per key, as many as the Normal's) gives each key its own normals;
/// without it they are recomputed from the key's points.
pub fn ifs_morph(
    g: &AstNode,
    textured: bool,
    keys: &[Vec<Vec3>],
    normal_keys: Option<&[Vec<Vec3>]>,
) -> Result<Morphs, String> {
    let base_points = sub_values(g, "coord", "point").unwrap_or_default();
    let mut msgs = Vec::new();
    let (faces, opts, texcoords) = ifs_parts(g, textured, &base_points);
    let (base, corners) = polygons::build_textured_corners(
        &base_points,
        faces.clone(),
        opts.clone(),
        texcoords.clone(),
        g.pos,
        &mut msgs,
    )
    .ok_or("the IndexedFaceSet has no mesh")?;
    let first = Corners::new(base.positions.len(), &corners);
    let mut targets = Vec::with_capacity(keys.len());
    for (i, points) in keys.iter().enumerate() {
        if points.len() != base_points.len() {
            return Err(format!(
                "key {i} has {} points for the {} of the Coordinate",
                points.len(),
                base_points.len()
            ));
        }
        let mut key_opts = opts.clone();
        if let Some(normals) = normal_keys.and_then(|n| n.get(i)) {
            key_opts.normals = binding(
                Some(normals.clone()),
                &indices(g, "normalIndex"),
                g.bool("normalPerVertex", true),
            );
        }
        let (m, kc) = polygons::build_textured_corners(
            points,
            faces.clone(),
            key_opts,
            texcoords.clone(),
            g.pos,
            &mut msgs,
        )
        .ok_or(format!("key {i} makes no mesh"))?;
        targets.push(first.target(format!("key_{i}"), &base, &m, &kc)?);
    }
    Morphs::new(base.positions.len(), targets, Vec::new()).map_err(|e| e.to_string())
}

/// For every vertex of an IndexedFaceSet's mesh (as `mesh` builds it),
/// the index of the `coord` point it came from: per-point data such as
/// H-Anim skin weights (`skinCoordIndex`) follow the points into the mesh,
/// whose vertices are split where normals or texture coordinates differ.
pub fn ifs_vertex_points(g: &AstNode, textured: bool) -> Result<Vec<u32>, String> {
    let points = sub_values(g, "coord", "point").unwrap_or_default();
    let mut msgs = Vec::new();
    let (faces, opts, texcoords) = ifs_parts(g, textured, &points);
    // The builder clears faces that index past the points (it keeps them
    // as empty faces, so corners still line up with this flattening).
    let corner_points: Vec<u32> = polygons::drop_bad(faces.clone(), points.len())
        .into_iter()
        .flatten()
        .collect();
    let (mesh, corners) =
        polygons::build_textured_corners(&points, faces, opts, texcoords, g.pos, &mut msgs)
            .ok_or("the IndexedFaceSet has no mesh")?;
    if corners.len() != corner_points.len() {
        return Err("the mesh's corners do not follow the coordIndex".into());
    }
    let mut out = vec![u32::MAX; mesh.positions.len()];
    for (c, &v) in corners.iter().enumerate() {
        if let Some(slot) = out.get_mut(v as usize) {
            if *slot == u32::MAX {
                *slot = corner_points[c];
            }
        }
    }
    if out.contains(&u32::MAX) {
        return Err("a mesh vertex comes from no coordIndex corner".into());
    }
    Ok(out)
}

fn indexed_line_set(g: &AstNode, msgs: &mut Msgs) -> Option<Mesh> {
    let positions = sub_values(g, "coord", "point").unwrap_or_default();
    let lines = polygons::drop_bad(split_index(&indices(g, "coordIndex")), positions.len());
    let colors = binding(
        sub_values(g, "color", "color"),
        &indices(g, "colorIndex"),
        g.bool("colorPerVertex", true),
    );
    match mesh_from_polylines(&positions, &lines, &colors) {
        Ok(m) => Some(m),
        Err(_) if colors != Binding::None => {
            msgs.push((
                g.pos,
                "bad colour indices in IndexedLineSet; colours ignored".into(),
            ));
            mesh_from_polylines(&positions, &lines, &Binding::None).ok()
        }
        Err(e) => {
            msgs.push((g.pos, format!("IndexedLineSet skipped: {e}")));
            None
        }
    }
}

fn point_set(g: &AstNode, msgs: &mut Msgs) -> Option<Mesh> {
    let positions = sub_values(g, "coord", "point").unwrap_or_default();
    let colors = sub_values(g, "color", "color");
    match mesh_from_points(&positions, colors.as_deref()) {
        Ok(m) => Some(m),
        Err(e) => {
            msgs.push((g.pos, format!("PointSet colours ignored: {e}")));
            mesh_from_points(&positions, None).ok()
        }
    }
}

/// Asks the input budget, before allocating, for a grid of `points`
/// (at most 4 vertices per point once creases split them, 2 triangles).
/// The builder ends the load when this fails ([`limits::tripped`]).
fn fits(points: u64, g: &AstNode, msgs: &mut Msgs) -> bool {
    match limits::check_geometry(points.saturating_mul(6)) {
        Ok(()) => true,
        Err(e) => {
            msgs.push((g.pos, format!("{}: {e}", g.kind)));
            false
        }
    }
}

fn elevation_grid(g: &AstNode, textured: bool, msgs: &mut Msgs) -> Option<Mesh> {
    let nx = g.num("xDimension").unwrap_or(0.0).max(0.0) as usize;
    let nz = g.num("zDimension").unwrap_or(0.0).max(0.0) as usize;
    let (sx, sz) = (g.f32("xSpacing", 1.0), g.f32("zSpacing", 1.0));
    let heights = g.nums("height").unwrap_or(&[]);
    if nx < 2 || nz < 2 || nx.saturating_mul(nz) > heights.len() {
        msgs.push((
            g.pos,
            "ElevationGrid needs xDimension, zDimension ≥ 2 and that many heights; skipped".into(),
        ));
        return None;
    }
    if !fits(nx as u64 * nz as u64, g, msgs) {
        return None;
    }
    let mut positions = Vec::with_capacity(nx * nz);
    for j in 0..nz {
        for i in 0..nx {
            positions.push(Vec3::new(
                i as f32 * sx,
                heights[i + j * nx] as f32,
                j as f32 * sz,
            ));
        }
    }
    let mut faces = Vec::with_capacity((nx - 1) * (nz - 1));
    for j in 0..nz - 1 {
        for i in 0..nx - 1 {
            let at = |i: usize, j: usize| (i + j * nx) as u32;
            faces.push(vec![at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    let opts = PolyOptions {
        ccw: g.bool("ccw", true),
        solid: g.bool("solid", true),
        crease_angle: g.f32("creaseAngle", 0.0),
        normals: binding(
            sub_values(g, "normal", "vector"),
            &[],
            g.bool("normalPerVertex", true),
        ),
        colors: binding(
            sub_values(g, "color", "color"),
            &[],
            g.bool("colorPerVertex", true),
        ),
        name: String::new(),
    };
    // Default: s 0..1 along x, t 0..1 along z over the grid.
    let texcoords = textured.then(|| TexCoords {
        values: texcoord_values(g).unwrap_or_else(|| {
            (0..nz)
                .flat_map(|j| {
                    (0..nx).map(move |i| {
                        Vec2::new(i as f32 / (nx - 1) as f32, j as f32 / (nz - 1) as f32)
                    })
                })
                .collect()
        }),
        index: None,
    });
    polygons::build_textured(&positions, faces, opts, texcoords, g.pos, msgs)
}

/// Extrusion (VRML97 §6.18): cross-sections scaled, oriented and placed
/// along the spine in each spine point's SCP frame.
fn extrusion(g: &AstNode, textured: bool, msgs: &mut Msgs) -> Option<Mesh> {
    let cross = g.nums("crossSection").map(vec2s).unwrap_or_else(|| {
        vec![
            Vec2::new(1.0, 1.0),
            Vec2::new(1.0, -1.0),
            Vec2::new(-1.0, -1.0),
            Vec2::new(-1.0, 1.0),
            Vec2::new(1.0, 1.0),
        ]
    });
    let spine = g
        .nums("spine")
        .map(vec3s)
        .unwrap_or_else(|| vec![Vec3::ZERO, Vec3::Y]);
    let scales = g
        .nums("scale")
        .map(vec2s)
        .unwrap_or_else(|| vec![Vec2::ONE]);
    let orients: Vec<Quat> = g
        .nums("orientation")
        .map(|v| {
            v.chunks_exact(4)
                .map(|c| crate::format::syntax::axis_angle(c[0], c[1], c[2], c[3]))
                .collect()
        })
        .unwrap_or_else(|| vec![Quat::IDENTITY]);
    let (n, m) = (spine.len(), cross.len());
    if n < 2 || m < 2 {
        msgs.push((
            g.pos,
            "Extrusion needs ≥ 2 spine and cross-section points; skipped".into(),
        ));
        return None;
    }
    if !fits(n as u64 * m as u64, g, msgs) {
        return None;
    }
    let frames = scp_frames(&spine);
    let mut positions = Vec::with_capacity(n * m);
    for (i, (p, (x, y, z))) in spine.iter().zip(&frames).enumerate() {
        let s = scales
            .get(i)
            .or(scales.last())
            .copied()
            .unwrap_or(Vec2::ONE);
        let o = orients
            .get(i)
            .or(orients.last())
            .copied()
            .unwrap_or(Quat::IDENTITY);
        for c in &cross {
            let local = o * Vec3::new(c.x * s.x, 0.0, c.y * s.y);
            positions.push(*p + *x * local.x + *y * local.y + *z * local.z);
        }
    }
    let at = |i: usize, j: usize| (i * m + j) as u32;
    let mut faces = Vec::with_capacity((n - 1) * (m - 1) + 2);
    for i in 0..n - 1 {
        for j in 0..m - 1 {
            faces.push(vec![at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    let closed_cross = cross[0] == cross[m - 1];
    let cap_len = if closed_cross { m - 1 } else { m };
    let spine_closed = spine[0] == spine[n - 1];
    // Texture coordinates: the sides s along the cross-section, t along the
    // spine (by length, 0..1); the caps map the cross-section's bounding box.
    let mut tex = textured.then(|| extrusion_side_texcoords(&cross, &spine));
    let mut tex_index: Vec<Vec<u32>> = faces.clone();
    let cap_base = n * m;
    if let Some(t) = &mut tex {
        let flat: Vec<Vec3> = cross[..cap_len]
            .iter()
            .map(|c| Vec3::new(c.x, c.y, 0.0))
            .collect();
        t.extend(bbox_texcoords(&flat));
    }
    if g.bool("beginCap", true) && !spine_closed && cap_len >= 3 {
        faces.push((0..cap_len).rev().map(|j| at(0, j)).collect());
        tex_index.push((0..cap_len).rev().map(|j| (cap_base + j) as u32).collect());
    }
    if g.bool("endCap", true) && !spine_closed && cap_len >= 3 {
        faces.push((0..cap_len).map(|j| at(n - 1, j)).collect());
        tex_index.push((0..cap_len).map(|j| (cap_base + j) as u32).collect());
    }
    let opts = PolyOptions {
        ccw: g.bool("ccw", true),
        solid: g.bool("solid", true),
        crease_angle: g.f32("creaseAngle", 0.0),
        normals: Binding::None,
        colors: Binding::None,
        name: String::new(),
    };
    let texcoords = tex.map(|values| TexCoords {
        values,
        index: Some(tex_index),
    });
    polygons::build_textured(&positions, faces, opts, texcoords, g.pos, msgs)
}

/// Extrusion side texture coordinates, one per (spine point, cross-section
/// point) in position order: s by length along the cross-section, t by
/// length along the spine (by index when a curve has no length).
fn extrusion_side_texcoords(cross: &[Vec2], spine: &[Vec3]) -> Vec<Vec2> {
    fn params(lengths: impl Iterator<Item = f32>, n: usize) -> Vec<f32> {
        let mut acc = vec![0.0];
        for l in lengths {
            acc.push(acc.last().copied().unwrap_or(0.0) + l);
        }
        let total = acc.last().copied().unwrap_or(0.0);
        if total > 0.0 {
            acc.iter().map(|a| a / total).collect()
        } else {
            (0..n).map(|i| i as f32 / (n - 1).max(1) as f32).collect()
        }
    }
    let s = params(cross.windows(2).map(|w| w[0].distance(w[1])), cross.len());
    let t = params(spine.windows(2).map(|w| w[0].distance(w[1])), spine.len());
    t.iter()
        .flat_map(|&t| s.iter().map(move |&s| Vec2::new(s, t)))
        .collect()
}

/// The spine-aligned cross-section planes (X, Y, Z axes per spine point).
fn scp_frames(spine: &[Vec3]) -> Vec<(Vec3, Vec3, Vec3)> {
    let n = spine.len();
    let closed = spine[0] == spine[n - 1];
    let prev = |i: usize| -> Option<Vec3> {
        if i > 0 {
            Some(spine[i - 1])
        } else if closed && n > 2 {
            Some(spine[n - 2])
        } else {
            None
        }
    };
    let next = |i: usize| -> Option<Vec3> {
        if i + 1 < n {
            Some(spine[i + 1])
        } else if closed && n > 2 {
            Some(spine[1])
        } else {
            None
        }
    };
    let mut ys = Vec::with_capacity(n);
    let mut zs: Vec<Option<Vec3>> = Vec::with_capacity(n);
    for (i, &p) in spine.iter().enumerate() {
        let y = match (prev(i), next(i)) {
            (Some(a), Some(b)) => b - a,
            (None, Some(b)) => b - p,
            (Some(a), None) => p - a,
            (None, None) => Vec3::Y,
        };
        ys.push(y.normalize_or_zero());
        let z = match (prev(i), next(i)) {
            (Some(a), Some(b)) => (b - p).cross(a - p).normalize_or_zero(),
            _ => Vec3::ZERO,
        };
        zs.push(if z == Vec3::ZERO { None } else { Some(z) });
    }
    // Open ends take their neighbour's Z; collinear points the previous one's.
    if !closed && n > 1 {
        zs[0] = zs[1];
        zs[n - 1] = zs[n - 2];
    }
    let mut out = Vec::with_capacity(n);
    let mut last_z: Option<Vec3> = None;
    // Fill missing Y from neighbours (repeated spine points).
    let mut last_y = ys
        .iter()
        .copied()
        .find(|y| *y != Vec3::ZERO)
        .unwrap_or(Vec3::Y);
    for i in 0..n {
        let y = if ys[i] == Vec3::ZERO { last_y } else { ys[i] };
        last_y = y;
        let mut z = zs[i].or(last_z).unwrap_or_else(|| {
            // Entirely collinear spine: rotate (0,0,1) like (0,1,0) → Y.
            Quat::from_rotation_arc(Vec3::Y, y) * Vec3::Z
        });
        if let Some(lz) = last_z {
            if z.dot(lz) < 0.0 {
                z = -z;
            }
        }
        last_z = Some(z);
        let x = y.cross(z).normalize_or_zero();
        out.push((x, y, z));
    }
    out
}

/// Box, Sphere, Cone, Cylinder through the shared primitive builders.
fn primitive(g: &AstNode, textured: bool) -> Option<Mesh> {
    use crate::scene::primitives as p;
    let m = match g.kind.as_str() {
        "Box" => p::box_mesh(g.vec3("size", Vec3::splat(2.0))),
        "Sphere" if textured => p::sphere_textured(g.f32("radius", 1.0)),
        "Sphere" => p::sphere(g.f32("radius", 1.0)),
        "Cone" if textured => p::cone_textured(
            g.f32("bottomRadius", 1.0),
            g.f32("height", 2.0),
            g.bool("side", true),
            g.bool("bottom", true),
        ),
        "Cylinder" if textured => p::cylinder_textured(
            g.f32("radius", 1.0),
            g.f32("height", 2.0),
            g.bool("side", true),
            g.bool("top", true),
            g.bool("bottom", true),
        ),
        "Cone" => p::cone(
            g.f32("bottomRadius", 1.0),
            g.f32("height", 2.0),
            g.bool("side", true),
            g.bool("bottom", true),
        ),
        _ => p::cylinder(
            g.f32("radius", 1.0),
            g.f32("height", 2.0),
            g.bool("side", true),
            g.bool("top", true),
            g.bool("bottom", true),
        ),
    };
    Some(m)
}
