//! Mesh primitives (spec §3.7.2) → [`Mesh`]: every topology (points, lines,
//! line loops and strips, triangles, strips and fans), indexed or not;
//! normals as given or, when missing, flat per triangle as the spec
//! requires (§3.7.2.1: the triangle's vertices are unwelded so each
//! carries its face normal); `COLOR_0` (RGB or RGBA, float or normalised
//! integers) multiplied by the material's base colour, because animed's
//! vertex colours replace the diffuse colour rather than modulate it.

use super::accessor::{read_f32, read_indices};
use super::container::{Buffers, GltfError, Result};
use super::material::srgb_from_linear;
use super::pointer::pointer;
use crate::scene::Mesh;
use glam::{Vec2, Vec3};
use gltf::mesh::Mode;
use gltf::Semantic;

/// Where a primitive is, for messages.
pub fn here(mesh: usize, prim: usize) -> String {
    pointer(&[&"meshes", &mesh, &"primitives", &prim])
}

pub(super) fn vec3s(flat: &[f32], comps: usize) -> Vec<Vec3> {
    flat.chunks_exact(comps.max(1))
        .map(|c| Vec3::new(c[0], *c.get(1).unwrap_or(&0.0), *c.get(2).unwrap_or(&0.0)))
        .collect()
}

/// Builds the mesh of one primitive, or `None` (with a warning) for a
/// primitive without positions, which the spec says to skip.
/// `base_color` is the material's linear base colour factor; `uv_set` the
/// TEXCOORD set its texture reads (stored with t = 1 − v, see `texture`).
pub fn primitive_mesh(
    mesh_index: usize,
    prim: &gltf::Primitive,
    buffers: &Buffers,
    base_color: Vec3,
    uv_set: Option<u32>,
    default_weights: &[f32],
    warnings: &mut Vec<String>,
) -> Result<Option<Mesh>> {
    let at = here(mesh_index, prim.index());
    let attr = |name: &str| format!("{at}/attributes/{name}");
    let Some(pos_acc) = prim.get(&Semantic::Positions) else {
        warnings.push(format!(
            "{at}: no POSITION attribute; the primitive is skipped"
        ));
        return Ok(None);
    };
    if pos_acc.dimensions() != gltf::accessor::Dimensions::Vec3 {
        return Err(GltfError::at(
            attr("POSITION"),
            "POSITION must be a VEC3 accessor",
        ));
    }
    let in_attr = |name: &str, e: GltfError| GltfError::at(attr(name), e.to_string());
    let positions = vec3s(
        &read_f32(&pos_acc, buffers).map_err(|e| in_attr("POSITION", e))?,
        3,
    );
    let n = positions.len();
    let count_check = |name: &str, got: usize| -> Result<()> {
        if got != n {
            return Err(GltfError::at(
                attr(name),
                format!("{got} values for {n} positions"),
            ));
        }
        Ok(())
    };
    let normals = match prim.get(&Semantic::Normals) {
        Some(a) => {
            let v = vec3s(&read_f32(&a, buffers).map_err(|e| in_attr("NORMAL", e))?, 3);
            count_check("NORMAL", v.len())?;
            // Unit already (as the spec requires): kept bit for bit.
            v.into_iter()
                .map(|v| {
                    if (v.length_squared() - 1.0).abs() <= 1e-5 {
                        v
                    } else {
                        v.try_normalize().unwrap_or(Vec3::Z)
                    }
                })
                .collect()
        }
        None => Vec::new(),
    };
    let colors = match prim.get(&Semantic::Colors(0)) {
        Some(a) => {
            let comps = super::accessor::components(a.dimensions());
            if comps != 3 && comps != 4 {
                return Err(GltfError::at(
                    attr("COLOR_0"),
                    "COLOR_0 must be VEC3 or VEC4",
                ));
            }
            let v = vec3s(
                &read_f32(&a, buffers).map_err(|e| in_attr("COLOR_0", e))?,
                comps,
            );
            count_check("COLOR_0", v.len())?;
            v.into_iter()
                .map(|c| srgb_from_linear(c * base_color))
                .collect()
        }
        None => Vec::new(),
    };
    let texcoords = match uv_set.and_then(|k| prim.get(&Semantic::TexCoords(k)).map(|a| (k, a))) {
        Some((k, a)) => {
            let name = format!("TEXCOORD_{k}");
            if a.dimensions() != gltf::accessor::Dimensions::Vec2 {
                return Err(GltfError::at(
                    attr(&name),
                    format!("{name} must be a VEC2 accessor"),
                ));
            }
            let v: Vec<Vec2> = read_f32(&a, buffers)
                .map_err(|e| in_attr(&name, e))?
                .chunks_exact(2)
                .map(|c| Vec2::new(c[0], 1.0 - c[1]))
                .collect();
            count_check(&name, v.len())?;
            v
        }
        None => {
            if let Some(k) = uv_set {
                warnings.push(format!(
                    "{at}: the material's texture reads TEXCOORD_{k}, which the primitive lacks; drawn untextured"
                ));
            }
            Vec::new()
        }
    };
    let indices: Vec<u32> = match prim.indices() {
        Some(a) => {
            let idx = read_indices(&a, buffers)
                .map_err(|e| GltfError::at(format!("{at}/indices"), e.to_string()))?;
            if let Some(bad) = idx.iter().find(|&&i| i as usize >= n) {
                return Err(GltfError::at(
                    format!("{at}/indices"),
                    format!("index {bad} is not below the vertex count {n}"),
                ));
            }
            idx
        }
        None => (0..n as u32).collect(),
    };
    let morph =
        super::deform::read_morphs(mesh_index, prim, buffers, n, default_weights, warnings)?;
    let skin_weights = super::deform::read_skin_weights(mesh_index, prim, buffers, n, warnings)?;
    let mut mesh = Mesh {
        name: String::new(),
        positions,
        normals,
        colors,
        texcoords,
        solid: true,
        morph: morph.map(Box::new),
        skin_weights: skin_weights.map(Box::new),
        ..Mesh::default()
    };
    let idx = &indices;
    match prim.mode() {
        Mode::Points => mesh.points = idx.clone(),
        Mode::Lines => mesh.lines = idx.chunks_exact(2).map(|l| [l[0], l[1]]).collect(),
        Mode::LineStrip => mesh.lines = idx.windows(2).map(|l| [l[0], l[1]]).collect(),
        Mode::LineLoop => {
            mesh.lines = idx.windows(2).map(|l| [l[0], l[1]]).collect();
            if idx.len() > 2 {
                mesh.lines.push([idx[idx.len() - 1], idx[0]]);
            }
        }
        Mode::Triangles => {
            mesh.triangles = idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect()
        }
        // §3.7.2.1: strip triangle i is (i, i+1+i%2, i+2-i%2): every other
        // one is reversed so all keep the first one's winding.
        Mode::TriangleStrip => {
            mesh.triangles = (0..idx.len().saturating_sub(2))
                .map(|i| [idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]])
                .collect()
        }
        Mode::TriangleFan => {
            mesh.triangles = (1..idx.len().saturating_sub(1))
                .map(|i| [idx[i], idx[i + 1], idx[0]])
                .collect()
        }
    }
    if mesh.normals.is_empty() && !mesh.triangles.is_empty() {
        flat_normals(&mut mesh);
    }
    Ok(Some(mesh))
}

/// Gives every triangle its own three vertices carrying its face normal
/// (morph targets and skin influences follow their vertices; normal deltas
/// are dropped with the smooth normals they applied to).
fn flat_normals(mesh: &mut Mesh) {
    let tris = std::mem::take(&mut mesh.triangles);
    let mut positions = Vec::with_capacity(tris.len() * 3);
    let mut normals = Vec::with_capacity(tris.len() * 3);
    let mut colors = Vec::with_capacity(if mesh.colors.is_empty() {
        0
    } else {
        tris.len() * 3
    });
    let mut texcoords = Vec::with_capacity(if mesh.texcoords.is_empty() {
        0
    } else {
        tris.len() * 3
    });
    for t in &tris {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let normal = (b - a).cross(c - a).try_normalize().unwrap_or(Vec3::Z);
        for &i in t {
            positions.push(mesh.positions[i as usize]);
            normals.push(normal);
            if !mesh.colors.is_empty() {
                colors.push(mesh.colors[i as usize]);
            }
            if !mesh.texcoords.is_empty() {
                texcoords.push(mesh.texcoords[i as usize]);
            }
        }
    }
    mesh.triangles = (0..tris.len() as u32)
        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
        .collect();
    mesh.positions = positions;
    mesh.normals = normals;
    mesh.colors = colors;
    mesh.texcoords = texcoords;
    if mesh.deforms() {
        let src: Vec<u32> = tris.iter().flatten().copied().collect();
        if let Some(m) = mesh.morph.as_mut() {
            **m = m.remap(&src, false);
        }
        if let Some(sw) = mesh.skin_weights.as_mut() {
            **sw = sw.remap(&src);
        }
    }
}
