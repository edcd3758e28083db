//! Inventor / VRML 1.0 shape nodes → meshes, using the coordinates,
//! normals, material bindings and shape hints of the traversal state.

use super::morph::Targets;
use super::state::{colors, packed, points2, Bind, State, TexSource, TexXf};
use crate::format::corner_morph::Corners;
use crate::format::lexer::Pos;
use crate::format::polygons::{self, split_index};
use crate::format::syntax::{AstNode, NodeRef};
use crate::scene::normals::{
    mesh_from_points, mesh_from_polylines, polyline_normals, Binding, PolyOptions, TexCoords,
};
use crate::scene::{primitives, Mesh, Morphs, RenderStyle};
use glam::{Vec2, Vec3};
use std::rc::Rc;

type Msgs = Vec<(Pos, String)>;

/// Shape node types this reader draws.
pub fn is_shape(kind: &str) -> bool {
    matches!(
        kind,
        "IndexedFaceSet"
            | "FaceSet"
            | "IndexedTriangleStripSet"
            | "TriangleStripSet"
            | "QuadMesh"
            | "IndexedLineSet"
            | "LineSet"
            | "PointSet"
            | "Cube"
            | "Sphere"
            | "Cone"
            | "Cylinder"
    )
}

/// What a shape needs from the state, resolved to values.
pub struct Inputs {
    pub coords: Rc<Vec<Vec3>>,
    pub normals: Vec<Vec3>,
    /// Diffuse colours for per-face / per-vertex material binding.
    pub colors: Vec<Vec3>,
    pub material_binding: Bind,
    pub normal_binding: Bind,
    /// Texture coordinates asked for (a texture is on).
    pub textured: bool,
    /// How texture coordinates are made when `textured`.
    pub tex: TexInput,
    pub texcoord_binding: Bind,
    /// Several Texture2Transforms multiplied together, baked into the
    /// coordinates.
    pub tex_baked: TexXf,
}

/// Where a textured shape's texture coordinates come from.
#[derive(Clone)]
pub enum TexInput {
    /// The shape's default mapping (bounding box, or the primitive's own).
    Default,
    /// TextureCoordinate2 points (or VertexProperty `texCoord`).
    Points(Vec<Vec2>),
    /// TextureCoordinatePlane: s = directionS·p, t = directionT·p.
    Plane(Vec3, Vec3),
}

/// Reads coordinates, normals and colours, letting a `vertexProperty`
/// field (Inventor 2.1) override the state.
pub fn inputs(n: &AstNode, st: &State, coords: Rc<Vec<Vec3>>) -> Inputs {
    let mut i = Inputs {
        coords,
        normals: st
            .normals
            .as_ref()
            .map(|n| colors(n, "vector"))
            .unwrap_or_default(),
        colors: diffuse_list(st),
        material_binding: st.material_binding,
        normal_binding: st.normal_binding,
        textured: st.texture.is_some(),
        tex: match &st.tex_source {
            TexSource::Default => TexInput::Default,
            TexSource::Points(p) => TexInput::Points(points2(p, "point")),
            TexSource::Plane(p) => {
                TexInput::Plane(p.vec3("directionS", Vec3::X), p.vec3("directionT", Vec3::Y))
            }
        },
        texcoord_binding: st.texcoord_binding,
        tex_baked: st.tex_transform,
    };
    if let Some(vp) = n.node("vertexProperty").map(|v| v.effective()) {
        if vp.kind == "VertexProperty" {
            let v = colors(&vp, "vertex");
            if !v.is_empty() {
                i.coords = Rc::new(v);
            }
            let nv = colors(&vp, "normal");
            if !nv.is_empty() {
                i.normals = nv;
                i.normal_binding = bind_word(&vp, "normalBinding", Bind::PerVertexIndexed);
            }
            let tc = points2(&vp, "texCoord");
            if !tc.is_empty() {
                i.tex = TexInput::Points(tc);
            }
            if let Some(rgba) = vp.nums("orderedRGBA") {
                if !rgba.is_empty() {
                    i.colors = packed(rgba).into_iter().map(|(c, _)| c).collect();
                    i.material_binding = bind_word(&vp, "materialBinding", Bind::Overall);
                }
            }
        }
    }
    i
}

fn bind_word(n: &AstNode, field: &str, default: Bind) -> Bind {
    match n.words(field).first() {
        Some(w) => Bind::parse(w),
        None => default,
    }
}

/// The diffuse colours the material binding indexes.
pub fn diffuse_list(st: &State) -> Vec<Vec3> {
    if let Some(b) = &st.base_color {
        if b.kind == "PackedColor" {
            return packed(b.nums("rgba").unwrap_or(&[]))
                .into_iter()
                .map(|(c, _)| c)
                .collect();
        }
        return colors(b, "rgb");
    }
    st.material
        .as_ref()
        .map(|m| colors(m, "diffuseColor"))
        .unwrap_or_default()
}

fn ints(n: &AstNode, field: &str) -> Vec<i64> {
    n.nums(field)
        .map(|v| v.iter().map(|x| *x as i64).collect())
        .unwrap_or_default()
}

/// An index list that is empty or just `[-1]` means "use the default".
fn given(idx: &[i64]) -> bool {
    !(idx.is_empty() || idx == [-1])
}

/// Turns an Inventor binding into the mesh builder's binding.
/// `parts[f]` is the part (strip) face `f` belongs to; `corner_ids` maps each
/// face corner to its vertex number for PER_VERTEX.
fn binding(
    b: Bind,
    values: &[Vec3],
    index: &[i64],
    faces: &[Vec<u32>],
    parts: Option<&[u32]>,
    corner_ids: &[Vec<u32>],
) -> Binding {
    if values.is_empty() {
        return Binding::None;
    }
    let values = values.to_vec();
    match b {
        Bind::Default | Bind::Overall => Binding::None,
        Bind::PerPart | Bind::PerFace => Binding::PerFace {
            values,
            index: match (b, parts) {
                (Bind::PerPart, Some(p)) => Some(p.to_vec()),
                _ => None,
            },
        },
        Bind::PerPartIndexed | Bind::PerFaceIndexed => {
            let flat: Vec<u32> = index
                .iter()
                .filter(|&&i| i >= 0)
                .map(|&i| i as u32)
                .collect();
            let index = match (given(index), b, parts) {
                (true, Bind::PerPartIndexed, Some(p)) => Some(
                    p.iter()
                        .map(|&part| flat.get(part as usize).copied().unwrap_or(u32::MAX))
                        .collect(),
                ),
                (true, _, _) => Some(flat),
                (false, _, _) => None,
            };
            Binding::PerFace { values, index }
        }
        Bind::PerVertex => Binding::PerVertex {
            values,
            index: Some(corner_ids.to_vec()),
        },
        Bind::PerVertexIndexed => Binding::PerVertex {
            values,
            index: if given(index) {
                Some(split_index(index))
            } else {
                let _ = faces;
                None
            },
        },
    }
}

/// [`binding`] for normals: OVERALL with normals given is the first normal
/// at every corner (Coin lights the whole shape with it), not normals
/// computed from the faces as when none are given.
fn normal_binding(
    b: Bind,
    values: &[Vec3],
    index: &[i64],
    faces: &[Vec<u32>],
    parts: Option<&[u32]>,
    corner_ids: &[Vec<u32>],
) -> Binding {
    match (b, values.first()) {
        (Bind::Overall, Some(&n)) => Binding::PerFace {
            values: vec![n],
            index: Some(vec![0; faces.len()]),
        },
        _ => binding(b, values, index, faces, parts, corner_ids),
    }
}

fn options(st: &State) -> PolyOptions {
    PolyOptions {
        ccw: st.ccw.unwrap_or(true),
        solid: st.ccw.is_some() && st.solid_type,
        crease_angle: st.crease_angle,
        normals: Binding::None,
        colors: Binding::None,
        name: String::new(),
    }
}

/// Consecutive vertex numbers for each corner (PER_VERTEX binding).
fn consecutive(faces: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let mut k = 0u32;
    faces
        .iter()
        .map(|f| {
            f.iter()
                .map(|_| {
                    k += 1;
                    k - 1
                })
                .collect()
        })
        .collect()
}

/// Builds the mesh for shape `n` (its kind is one `is_shape` accepts).
pub fn mesh(n: &NodeRef, st: &State, inp: &Inputs, msgs: &mut Msgs) -> Option<Mesh> {
    let kind = n.kind.as_str();
    let mut m = mesh_of(n, kind, st, inp, msgs)?;
    // Coin culls no primitive of its own accord: only ShapeHints SOLID with
    // a known vertex ordering turns culling on (for every shape). Filled, a
    // closed primitive looks the same either way; drawn as lines or points
    // its back edges and corners show unless the hints cull them
    // (`render::stroke_faces`).
    if matches!(kind, "Cube" | "Sphere" | "Cone" | "Cylinder")
        && matches!(st.style, RenderStyle::Lines | RenderStyle::Points)
    {
        m.solid &= options(st).solid;
    }
    if inp.textured && !m.triangles.is_empty() {
        if let TexInput::Plane(ds, dt) = inp.tex {
            m.texcoords = m
                .positions
                .iter()
                .map(|p| Vec2::new(ds.dot(*p), dt.dot(*p)))
                .collect();
        }
        if let TexXf::Baked(x) = inp.tex_baked {
            for c in &mut m.texcoords {
                *c = x.transform_point2(*c);
            }
        }
    }
    // Per-part materials of the primitives (VRML 1.0 / Inventor part order).
    let per_part = matches!(
        inp.material_binding,
        Bind::PerPart | Bind::PerPartIndexed | Bind::PerFace | Bind::PerFaceIndexed
    );
    if per_part
        && inp.colors.len() > 1
        && matches!(kind, "Cube" | "Cylinder" | "Cone")
        && m.normals.len() == m.positions.len()
    {
        m.colors = m
            .normals
            .iter()
            .map(|nm| part_color(kind, *nm, &inp.colors))
            .collect();
    }
    Some(m)
}

/// The complexity a Sphere is divided at when it is drawn as lines,
/// untextured (Coin's grid, `coin_grid`); `None` for every other shape,
/// which keeps our fine tessellation.
pub fn lines_grid(n: &AstNode, st: &State, textured: bool) -> Option<f32> {
    (n.kind == "Sphere" && st.style == RenderStyle::Lines && !textured).then_some(st.complexity)
}

fn mesh_of(n: &NodeRef, kind: &str, st: &State, inp: &Inputs, msgs: &mut Msgs) -> Option<Mesh> {
    match kind {
        "Cube" => Some(primitives::box_mesh(Vec3::new(
            n.f32("width", 2.0),
            n.f32("height", 2.0),
            n.f32("depth", 2.0),
        ))),
        "Sphere" if lines_grid(n, st, inp.textured).is_some() => Some(super::coin_grid::sphere(
            n.f32("radius", 1.0),
            st.complexity,
        )),
        "Sphere" if inp.textured => Some(primitives::sphere_textured(n.f32("radius", 1.0))),
        "Sphere" => Some(primitives::sphere(n.f32("radius", 1.0))),
        "Cone" => {
            let (all, parts) = parts(n);
            let cone = if inp.textured {
                primitives::cone_textured
            } else {
                primitives::cone
            };
            let (side, bottom) = (
                all || parts.iter().any(|p| p == "SIDES"),
                all || parts.iter().any(|p| p == "BOTTOM"),
            );
            let mut m = cone(
                n.f32("bottomRadius", 1.0),
                n.f32("height", 2.0),
                side,
                bottom,
            );
            // An open cone shows its inside (Coin culls no primitive).
            m.solid = side && bottom;
            Some(m)
        }
        "Cylinder" => {
            let (all, parts) = parts(n);
            let cylinder = if inp.textured {
                primitives::cylinder_textured
            } else {
                primitives::cylinder
            };
            let has = |w: &str| all || parts.iter().any(|p| p == w);
            let (side, top, bottom) = (has("SIDES"), has("TOP"), has("BOTTOM"));
            let mut m = cylinder(
                n.f32("radius", 1.0),
                n.f32("height", 2.0),
                side,
                top,
                bottom,
            );
            m.solid = side && top && bottom;
            Some(m)
        }
        "IndexedFaceSet" | "IndexedTriangleStripSet" => {
            let (faces, o, texcoords) = indexed_faces(n, kind, st, inp);
            polygons::build_textured(&inp.coords, faces, o, texcoords, n.pos, msgs)
        }
        "FaceSet" | "TriangleStripSet" | "QuadMesh" => {
            let start = n.num("startIndex").unwrap_or(0.0).max(0.0) as usize;
            let (faces, parts) = match kind {
                "QuadMesh" => quad_mesh(n, start),
                _ => {
                    let counts = vertex_counts(n, "numVertices", inp.coords.len(), start);
                    let mut runs = Vec::new();
                    let mut at = start as u32;
                    for c in counts {
                        runs.push((at..at + c).collect::<Vec<u32>>());
                        at += c;
                    }
                    if kind == "TriangleStripSet" {
                        let ids = runs.clone();
                        let (f, p, _) = strip_triangles(&runs, &ids);
                        (f, p)
                    } else {
                        let p = (0..runs.len() as u32).collect();
                        (runs, p)
                    }
                }
            };
            let corner_ids: Vec<Vec<u32>> = faces
                .iter()
                .map(|f| f.iter().map(|&i| i.saturating_sub(start as u32)).collect())
                .collect();
            let mut o = options(st);
            if kind == "QuadMesh" && inp.normals.is_empty() {
                // Coin and SGI Inventor smooth a QuadMesh's own normals over
                // the whole grid, whatever the crease angle.
                o.crease_angle = std::f32::consts::PI;
            }
            o.colors = binding(
                inp.material_binding,
                &inp.colors,
                &[],
                &faces,
                Some(&parts),
                &corner_ids,
            );
            let nb = if inp.normal_binding == Bind::Default {
                Bind::PerVertex
            } else {
                inp.normal_binding
            };
            o.normals = normal_binding(nb, &inp.normals, &[], &faces, Some(&parts), &corner_ids);
            // Non-indexed shapes take texture coordinates by vertex number
            // counted from startIndex (Coin's SoQuadMesh::generatePrimitives).
            let texcoords = inp.textured.then(|| {
                let t = texcoords(inp, &faces, None);
                match &inp.tex {
                    TexInput::Points(_) => TexCoords {
                        index: Some(corner_ids.clone()),
                        ..t
                    },
                    _ => t,
                }
            });
            polygons::build_textured(&inp.coords, faces, o, texcoords, n.pos, msgs)
        }
        "IndexedLineSet" | "LineSet" => {
            let lines = if kind == "LineSet" {
                let start = n.num("startIndex").unwrap_or(0.0).max(0.0) as usize;
                let mut at = start as u32;
                vertex_counts(n, "numVertices", inp.coords.len(), start)
                    .into_iter()
                    .map(|c| {
                        let r = (at..at + c).collect::<Vec<u32>>();
                        at += c;
                        r
                    })
                    .collect()
            } else {
                split_index(&ints(n, "coordIndex"))
            };
            let lines = polygons::drop_bad(lines, inp.coords.len());
            // Normals as for faces (DEFAULT: per vertex, indexed for the
            // indexed set); a line set with normals is lit (Coin), one
            // without is drawn in its base colour (`Builder::shape`).
            let nb = match inp.normal_binding {
                Bind::Default if kind == "LineSet" => Bind::PerVertex,
                Bind::Default => Bind::PerVertexIndexed,
                b => b,
            };
            // A line set's part is one segment (SoIndexedLineSet: PER_PART
            // colours each segment, PER_FACE each polyline): per-part
            // colours or normals take the polylines apart into their segments.
            let per_part = |b: Bind| matches!(b, Bind::PerPart | Bind::PerPartIndexed);
            let lines =
                if per_part(inp.material_binding) || (per_part(nb) && !inp.normals.is_empty()) {
                    lines
                        .iter()
                        .flat_map(|l| l.windows(2).map(<[u32]>::to_vec))
                        .collect()
                } else {
                    lines
                };
            let corner_ids = consecutive(&lines);
            let cb = binding(
                inp.material_binding,
                &inp.colors,
                &ints(n, "materialIndex"),
                &lines,
                None,
                &corner_ids,
            );
            let nbind = normal_binding(
                nb,
                &inp.normals,
                &ints(n, "normalIndex"),
                &lines,
                None,
                &corner_ids,
            );
            let mut mesh = mesh_from_polylines(&inp.coords, &lines, &cb)
                .or_else(|_| mesh_from_polylines(&inp.coords, &lines, &Binding::None))
                .map_err(|e| msgs.push((n.pos, format!("{kind} skipped: {e}"))))
                .ok()?;
            match polyline_normals(inp.coords.len(), &lines, &nbind) {
                Ok(normals) => mesh.normals = normals.unwrap_or_default(),
                Err(e) => msgs.push((n.pos, format!("{kind}: normals ignored (drawn unlit): {e}"))),
            }
            Some(mesh)
        }
        "PointSet" => {
            let start = n.num("startIndex").unwrap_or(0.0).max(0.0) as usize;
            let count = match n.num("numPoints") {
                Some(c) if c >= 0.0 => c as usize,
                _ => inp.coords.len().saturating_sub(start),
            };
            let end = start.saturating_add(count).min(inp.coords.len());
            let pts = inp.coords.get(start..end).unwrap_or(&[]);
            let cols = match inp.material_binding {
                Bind::PerVertex | Bind::PerVertexIndexed | Bind::PerPart | Bind::PerFace
                    if inp.colors.len() >= pts.len() =>
                {
                    Some(&inp.colors[..pts.len()])
                }
                _ => None,
            };
            let mut mesh = mesh_from_points(pts, cols).ok()?;
            match point_normals(inp.normal_binding, &inp.normals, pts.len()) {
                Ok(normals) => mesh.normals = normals,
                Err(e) => msgs.push((
                    n.pos,
                    format!("PointSet: normals ignored (drawn unlit): {e}"),
                )),
            }
            Some(mesh)
        }
        _ => None,
    }
}

/// The normals of a PointSet's `count` points (none: drawn unlit in its
/// base colour, `Builder::shape`). As Coin draws them (probed through
/// pivy): OVERALL gives every point the first normal; any other binding
/// one normal per point, counted from the first normal whatever the
/// `startIndex`; a point whose normal faces away from the light gets the
/// ambient term only.
fn point_normals(bind: Bind, normals: &[Vec3], count: usize) -> Result<Vec<Vec3>, String> {
    match bind {
        _ if normals.is_empty() || count == 0 => Ok(Vec::new()),
        Bind::Overall => Ok(vec![normals[0]; count]),
        _ if normals.len() < count => Err(format!("{} normals for {count} points", normals.len())),
        _ => Ok(normals[..count].to_vec()),
    }
}

/// Texture coordinates of a textured polygon shape: the given points
/// (through `index`, or by coordinate index), or — for a plane function or
/// the default mapping — one per coordinate (the plane is applied later, to
/// the built mesh; the default maps the bounding box of the coordinates the
/// faces use, see [`polygons::bbox_texcoords_inventor`]).
/// The faces, build options and texture coordinates of an
/// IndexedFaceSet / IndexedTriangleStripSet under state `st`.
fn indexed_faces(
    n: &AstNode,
    kind: &str,
    st: &State,
    inp: &Inputs,
) -> (Vec<Vec<u32>>, PolyOptions, Option<TexCoords>) {
    let strips = kind == "IndexedTriangleStripSet";
    let raw = split_index(&ints(n, "coordIndex"));
    let corner_ids = consecutive(&raw);
    let tex_index = ints(n, "textureCoordIndex");
    let tex_rows = given(&tex_index).then(|| split_index(&tex_index));
    let (faces, parts, corner_ids, tex_rows) = if strips {
        let tex_rows = tex_rows.map(|r| strip_triangles(&r, &r).2);
        let (f, p, c) = strip_triangles(&raw, &corner_ids);
        (f, p, c, tex_rows)
    } else {
        let p: Vec<u32> = (0..raw.len() as u32).collect();
        (raw, p, corner_ids, tex_rows)
    };
    let texcoords = inp.textured.then(|| {
        let per_vertex = inp.texcoord_binding == Bind::PerVertex;
        let index = if per_vertex {
            Some(corner_ids.clone())
        } else {
            tex_rows
        };
        texcoords(inp, &faces, index)
    });
    let mut o = options(st);
    o.colors = binding(
        inp.material_binding,
        &inp.colors,
        &ints(n, "materialIndex"),
        &faces,
        Some(&parts),
        &corner_ids,
    );
    let nb = if inp.normal_binding == Bind::Default {
        Bind::PerVertexIndexed
    } else {
        inp.normal_binding
    };
    o.normals = normal_binding(
        nb,
        &inp.normals,
        &ints(n, "normalIndex"),
        &faces,
        Some(&parts),
        &corner_ids,
    );
    (faces, o, texcoords)
}

/// The morph targets of an IndexedFaceSet whose points (and normals) are
/// moved by `targets` (`iv::morph`): each target's mesh is built from the
/// moved inputs and followed corner by corner (`corner_morph`). `lit`:
/// whether the shape's mesh keeps its normals.
pub fn morph(
    n: &AstNode,
    st: &State,
    inp: &Inputs,
    targets: &Targets,
    normals: Option<&Targets>,
    lit: bool,
) -> Result<Morphs, String> {
    if n.kind != "IndexedFaceSet" {
        return Err(format!("morph targets on {} are not read", n.kind));
    }
    let mut msgs = Vec::new();
    let (faces, o, tex) = indexed_faces(n, &n.kind, st, inp);
    let (mut base, corners) =
        polygons::build_textured_corners(&inp.coords, faces, o, tex, n.pos, &mut msgs)
            .ok_or("the IndexedFaceSet has no mesh")?;
    if !lit {
        base.normals.clear();
    }
    let first = Corners::new(base.positions.len(), &corners);
    let mut out = Vec::with_capacity(targets.offsets.len());
    for (i, offsets) in targets.offsets.iter().enumerate() {
        let moved = |at: &[Vec3], by: &[Vec3]| at.iter().zip(by).map(|(a, b)| *a + *b).collect();
        let key_inputs = Inputs {
            coords: Rc::new(moved(&inp.coords, offsets)),
            normals: match normals.and_then(|t| t.offsets.get(i)) {
                Some(by) => moved(&inp.normals, by),
                None => inp.normals.clone(),
            },
            colors: inp.colors.clone(),
            tex: inp.tex.clone(),
            ..*inp
        };
        let (faces, o, tex) = indexed_faces(n, &n.kind, st, &key_inputs);
        let (key, kc) =
            polygons::build_textured_corners(&key_inputs.coords, faces, o, tex, n.pos, &mut msgs)
                .ok_or(format!("morph target {i} makes no mesh"))?;
        out.push(first.target(format!("target_{i}"), &base, &key, &kc)?);
    }
    Morphs::new(base.positions.len(), out, targets.weights.clone()).map_err(|e| e.to_string())
}

fn texcoords(inp: &Inputs, faces: &[Vec<u32>], index: Option<Vec<Vec<u32>>>) -> TexCoords {
    match &inp.tex {
        TexInput::Points(values) => TexCoords {
            values: values.clone(),
            index,
        },
        TexInput::Plane(..) => TexCoords {
            values: vec![Vec2::ZERO; inp.coords.len()],
            index: None,
        },
        TexInput::Default => TexCoords {
            values: polygons::bbox_texcoords_inventor(&inp.coords, faces),
            index: None,
        },
    }
}

/// `parts` bit mask of Cone/Cylinder: (ALL given or field absent, names).
fn parts(n: &AstNode) -> (bool, Vec<String>) {
    let w = n.words("parts");
    (w.is_empty() || w.iter().any(|p| p == "ALL"), w.to_vec())
}

/// `numVertices` (−1 = all the rest) as counts, clamped to the coordinates.
fn vertex_counts(n: &AstNode, field: &str, len: usize, start: usize) -> Vec<u32> {
    let mut left = len.saturating_sub(start);
    let mut out = Vec::new();
    let nums = n.nums(field).unwrap_or(&[-1.0]);
    let nums: &[f64] = if nums.is_empty() { &[-1.0] } else { nums };
    for &c in nums {
        let c = if c < 0.0 {
            left
        } else {
            (c as usize).min(left)
        };
        out.push(c as u32);
        left -= c;
    }
    out
}

/// Triangles of triangle strips (alternate ones flipped to keep the winding),
/// the strip each came from, and the corner ids carried along.
fn strip_triangles(
    strips: &[Vec<u32>],
    ids: &[Vec<u32>],
) -> (Vec<Vec<u32>>, Vec<u32>, Vec<Vec<u32>>) {
    let mut faces = Vec::new();
    let mut parts = Vec::new();
    let mut corner = Vec::new();
    for (s, (strip, id)) in strips.iter().zip(ids).enumerate() {
        for k in 2..strip.len() {
            let (a, b, c) = if k % 2 == 0 {
                (k - 2, k - 1, k)
            } else {
                (k - 1, k - 2, k)
            };
            faces.push(vec![strip[a], strip[b], strip[c]]);
            corner.push(vec![id[a], id[b], id[c]]);
            parts.push(s as u32);
        }
    }
    (faces, parts, corner)
}

/// QuadMesh: `verticesPerColumn` rows of `verticesPerRow` vertices.
fn quad_mesh(n: &AstNode, start: usize) -> (Vec<Vec<u32>>, Vec<u32>) {
    let cols = n.num("verticesPerRow").unwrap_or(0.0).max(0.0) as usize;
    let rows = n.num("verticesPerColumn").unwrap_or(0.0).max(0.0) as usize;
    let mut faces = Vec::new();
    let mut parts = Vec::new();
    if cols < 2 || rows < 2 || cols.saturating_mul(rows) > 50_000_000 {
        return (faces, parts);
    }
    let at = |r: usize, c: usize| (start + r * cols + c) as u32;
    for r in 0..rows - 1 {
        for c in 0..cols - 1 {
            // Coin draws each row as a GL_QUAD_STRIP, which Mesa splits
            // along (r, c)–(r+1, c+1); starting the quad at (r+1, c) makes
            // the triangulation cut the same diagonal (it clips the first
            // corner's ear), so a bent quad has Coin's silhouette.
            faces.push(vec![at(r + 1, c), at(r + 1, c + 1), at(r, c + 1), at(r, c)]);
            parts.push(r as u32);
        }
    }
    (faces, parts)
}

/// The material index of a primitive's part, told apart by the normal:
/// Cube front, back, left, right, top, bottom; Cylinder sides, top, bottom;
/// Cone sides, bottom.
fn part_color(kind: &str, normal: Vec3, colors: &[Vec3]) -> Vec3 {
    let part = match kind {
        "Cube" => {
            if normal.z > 0.5 {
                0
            } else if normal.z < -0.5 {
                1
            } else if normal.x < -0.5 {
                2
            } else if normal.x > 0.5 {
                3
            } else if normal.y > 0.5 {
                4
            } else {
                5
            }
        }
        "Cylinder" if normal.y > 0.99 => 1,
        "Cylinder" if normal.y < -0.99 => 2,
        "Cone" if normal.y < -0.99 => 1,
        _ => 0,
    };
    colors[part % colors.len()]
}
