//! Wavefront OBJ import through `tobj`, with MTL materials mapped onto the
//! VRML97 material model. Polygons go through `scene::normals` (ear
//! clipping; smooth normals with a crease angle when the file has none).
//!
//! tobj reports what went wrong but not where, so a failed load is followed
//! by our own scan of the text that finds the line and column of the first
//! statement tobj would reject.

use super::{obj_lines, LoadError, Loaded};
use crate::scene::{
    mesh_from_polygons_textured, normals, Binding, Material, Node, NodeKind, PolyOptions, Scene,
    Shape, SourceFormat, TexCoords,
};
use glam::{Vec2, Vec3};
use std::cell::RefCell;
use std::path::Path;

/// Crease angle for OBJ files without normals (radians): smooth across
/// gently curved surfaces, sharp at real corners (Inventor's default).
pub const OBJ_CREASE_ANGLE: f32 = 0.5;

/// True for paths that name an OBJ file.
pub fn is_obj_path(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

/// Reads an OBJ file's bytes; `path` names it in messages and is where
/// `mtllib` files are looked up (relative to its folder).
pub fn read(bytes: &[u8], path: &Path) -> Result<Loaded, LoadError> {
    // tobj silently accepts some broken references (an index to a texture
    // coordinate that was never defined); check first, with positions.
    if let Some((line, column, why)) = find_bad_statement(bytes) {
        return Err(LoadError::new(
            path,
            line,
            column,
            format!("not a valid OBJ file: {why}"),
        ));
    }
    let warnings = RefCell::new(Vec::new());
    // The material libraries' texts, kept to place warnings about them.
    let libraries = RefCell::new(Vec::new());
    let dir = path.parent().unwrap_or(Path::new("")).to_path_buf();
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: false,
        ignore_lines: false,
    };
    let loaded = tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |mtl| {
        let full = dir.join(mtl);
        let (line, column) =
            obj_lines::find(bytes, "mtllib", &mtl.to_string_lossy()).unwrap_or((1, 1));
        match crate::format::limits::read_file(&full) {
            Ok(data) => {
                let read = tobj::load_mtl_buf(&mut std::io::Cursor::new(&data)).inspect_err(|e| {
                    warnings.borrow_mut().push(format!(
                        "{}:{line}:{column}: material library {}: {e}",
                        path.display(),
                        full.display()
                    ));
                });
                libraries.borrow_mut().push((full, data));
                read
            }
            Err(e) => {
                warnings.borrow_mut().push(format!(
                    "{}:{line}:{column}: cannot read material library {}: {e}",
                    path.display(),
                    full.display()
                ));
                Err(tobj::LoadError::OpenFileFailed)
            }
        }
    });
    let (models, materials) = match loaded {
        Ok(m) => m,
        Err(e) => {
            return Err(LoadError::new(
                path,
                0,
                0,
                format!("not a valid OBJ file: {e}"),
            ))
        }
    };
    let mut warnings = warnings.into_inner();
    let libraries = libraries.into_inner();
    let mtl = materials.unwrap_or_default();

    let mut scene = Scene::new();
    scene.format = SourceFormat::Obj;
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("obj")
        .to_string();
    let root = scene.add_node(None, Node::group(stem));
    let mut material_ids = Vec::with_capacity(mtl.len());
    let mut loader = super::textures::Loader::new(path);
    for m in &mtl {
        let mut material = convert_material(m);
        let mut msgs = Vec::new();
        material.texture =
            super::obj_texture::material_texture(m, &mut scene, &mut loader, &mut msgs);
        for (statement, w) in msgs {
            let place = libraries
                .iter()
                .find_map(|(lib, text)| {
                    let (line, column) = obj_lines::find_in_material(text, &m.name, statement)?;
                    Some(format!("{}:{line}:{column}", lib.display()))
                })
                .unwrap_or_else(|| format!("{}:1:1", path.display()));
            warnings.push(format!("{place}: material {:?}: {w}", m.name));
        }
        material_ids.push(scene.add_material(material));
    }
    let mut default_material = None;

    for (k, model) in models.iter().enumerate() {
        let m = &model.mesh;
        let pos = triples(&m.positions);
        let arities: Vec<u32> = if m.face_arities.is_empty() {
            vec![3; m.indices.len() / 3]
        } else {
            m.face_arities.clone()
        };
        let mut faces: Vec<Vec<u32>> = Vec::with_capacity(arities.len());
        let mut normal_faces: Vec<Vec<u32>> = Vec::new();
        let has_normals = !m.normals.is_empty() && m.normal_indices.len() == m.indices.len();
        // Texture coordinates only for a textured material (they unweld
        // vertices).
        let textured = m
            .material_id
            .and_then(|i| material_ids.get(i))
            .is_some_and(|id| scene.materials[id.0 as usize].texture.is_some());
        let has_uv =
            textured && !m.texcoords.is_empty() && m.texcoord_indices.len() == m.indices.len();
        let mut uv_faces: Vec<Vec<u32>> = Vec::new();
        let mut at = 0usize;
        for &n in &arities {
            let end = (at + n as usize).min(m.indices.len());
            faces.push(m.indices[at..end].to_vec());
            if has_normals {
                normal_faces.push(m.normal_indices[at..end].to_vec());
            }
            if has_uv {
                uv_faces.push(m.texcoord_indices[at..end].to_vec());
            }
            at = end;
        }
        let colors = triples(&m.vertex_color);
        let opts = PolyOptions {
            ccw: true,
            solid: false,
            crease_angle: OBJ_CREASE_ANGLE,
            normals: if has_normals {
                Binding::PerVertex {
                    values: triples(&m.normals),
                    index: Some(normal_faces),
                }
            } else {
                Binding::None
            },
            colors: if colors.len() == pos.len() && !colors.is_empty() {
                Binding::PerVertex {
                    values: colors,
                    index: None,
                }
            } else {
                Binding::None
            },
            name: model.name.clone(),
        };
        // Faces of 1 or 2 vertices are OBJ points and lines.
        let uv_rows: Vec<Vec<u32>> = if has_uv {
            faces
                .iter()
                .zip(&uv_faces)
                .filter(|(f, _)| f.len() >= 3)
                .map(|(_, t)| t.clone())
                .collect()
        } else {
            Vec::new()
        };
        let (polys, others): (Vec<Vec<u32>>, Vec<Vec<u32>>) =
            faces.into_iter().partition(|f| f.len() >= 3);
        let opts = if others.is_empty() {
            opts
        } else {
            PolyOptions {
                normals: Binding::None,
                colors: Binding::None,
                ..opts
            }
        };
        let texcoords = has_uv.then(|| TexCoords {
            values: m
                .texcoords
                .chunks_exact(2)
                .map(|c| Vec2::new(c[0], c[1]))
                .collect(),
            index: Some(uv_rows),
        });
        let mut mesh = mesh_from_polygons_textured(&pos, &polys, &opts, texcoords.as_ref())
            .map_err(|e| LoadError::new(path, 0, 0, format!("object {:?}: {e}", model.name)))?;
        if !others.is_empty() {
            let lines: Vec<Vec<u32>> = others.iter().filter(|f| f.len() == 2).cloned().collect();
            let extra = normals::mesh_from_polylines(&pos, &lines, &Binding::None)
                .map_err(|e| LoadError::new(path, 0, 0, format!("object {:?}: {e}", model.name)))?;
            append_unlit(&mut mesh, &extra);
            for f in others.iter().filter(|f| f.len() == 1) {
                if let Some(&p) = pos.get(f[0] as usize) {
                    mesh.points.push(mesh.positions.len() as u32);
                    mesh.positions.push(p);
                    if !mesh.normals.is_empty() {
                        mesh.normals.push(Vec3::ZERO);
                    }
                    if !mesh.texcoords.is_empty() {
                        mesh.texcoords.push(Vec2::ZERO);
                    }
                }
            }
        }
        if mesh.triangles.is_empty() && mesh.lines.is_empty() && mesh.points.is_empty() {
            continue;
        }
        let material = match m.material_id.and_then(|i| material_ids.get(i)) {
            Some(&id) => id,
            None => {
                if let Some(i) = m.material_id {
                    let (line, column) = obj_lines::find(bytes, "usemtl", "").unwrap_or((1, 1));
                    warnings.push(format!(
                        "{}:{line}:{column}: object {:?} uses material {i}, which no material library defines",
                        path.display(),
                        model.name
                    ));
                }
                *default_material.get_or_insert_with(|| scene.add_material(Material::default()))
            }
        };
        let cost = (mesh.positions.len() + mesh.triangles.len()) as u64;
        crate::format::limits::charge_geometry(cost)
            .and_then(|()| crate::format::limits::charge_nodes(1))
            .map_err(|e| LoadError::new(path, 0, 0, e.to_string()))?;
        let mesh_id = scene.add_mesh(mesh);
        let name = if model.name.is_empty() || model.name == "unnamed_object" {
            format!("object{k}")
        } else {
            model.name.clone()
        };
        scene.add_node(
            Some(root),
            Node::new(
                name,
                NodeKind::Shape(Shape {
                    mesh: mesh_id,
                    material,
                }),
            ),
        );
    }
    Ok(Loaded { scene, warnings })
}

/// Lines appended to a triangle mesh keep its vertex arrays parallel.
fn append_unlit(mesh: &mut crate::scene::Mesh, extra: &crate::scene::Mesh) {
    let base = mesh.positions.len() as u32;
    mesh.positions.extend(&extra.positions);
    if !mesh.normals.is_empty() {
        mesh.normals
            .extend(std::iter::repeat_n(Vec3::ZERO, extra.positions.len()));
    }
    if !mesh.colors.is_empty() {
        mesh.colors
            .extend(std::iter::repeat_n(Vec3::ONE, extra.positions.len()));
    }
    if !mesh.texcoords.is_empty() {
        mesh.texcoords
            .extend(std::iter::repeat_n(Vec2::ZERO, extra.positions.len()));
    }
    mesh.lines
        .extend(extra.lines.iter().map(|l| [l[0] + base, l[1] + base]));
}

fn triples(v: &[f32]) -> Vec<Vec3> {
    v.chunks_exact(3)
        .map(|c| Vec3::new(c[0], c[1], c[2]))
        .collect()
}

/// MTL → VRML97 material: Kd → diffuse, Ka → ambientIntensity (as the
/// fraction of the diffuse colour it amounts to), Ks → specular,
/// Ns (0..1000, usually ≤ 128) → shininess = Ns/128, d or Tr → transparency,
/// Ke → emissive.
pub fn convert_material(m: &tobj::Material) -> Material {
    let mut out = Material {
        name: m.name.clone(),
        ..Material::default()
    };
    if let Some(kd) = m.diffuse {
        out.diffuse = Vec3::from_array(kd).clamp(Vec3::ZERO, Vec3::ONE);
    }
    if let Some(ka) = m.ambient {
        let ka = Vec3::from_array(ka).clamp(Vec3::ZERO, Vec3::ONE);
        let kd = out.diffuse.element_sum();
        out.ambient_intensity = if kd > 0.0 {
            (ka.element_sum() / kd).clamp(0.0, 1.0)
        } else {
            ka.element_sum() / 3.0
        };
    }
    if let Some(ks) = m.specular {
        out.specular = Vec3::from_array(ks).clamp(Vec3::ZERO, Vec3::ONE);
    }
    if let Some(ns) = m.shininess {
        out.shininess = (ns / 128.0).clamp(0.0, 1.0);
    }
    if let Some(ke) = m.emissive {
        out.emissive = Vec3::from_array(ke).clamp(Vec3::ZERO, Vec3::ONE);
    }
    if let Some(d) = m.dissolve {
        out.transparency = (1.0 - d).clamp(0.0, 1.0);
    } else if let Some(tr) = m
        .unknown_param
        .get("Tr")
        .and_then(|t| t.trim().parse::<f32>().ok())
    {
        out.transparency = tr.clamp(0.0, 1.0);
    }
    out
}

/// Finds the first statement tobj would reject: `(line, column, reason)`,
/// 1-based. Checks UTF-8, numbers in `v`/`vt`/`vn`, and that face, line and
/// point indices are integers that refer to elements defined before them.
pub fn find_bad_statement(bytes: &[u8]) -> Option<(u32, u32, String)> {
    let (mut nv, mut nvt, mut nvn) = (0i64, 0i64, 0i64);
    for (i, raw) in bytes.split(|&b| b == b'\n').enumerate() {
        let line = (i + 1) as u32;
        let Ok(text) = std::str::from_utf8(raw) else {
            return Some((line, 1, "the line is not UTF-8 text".into()));
        };
        let text = text.split('#').next().unwrap_or("");
        let mut words = text
            .split_whitespace()
            .map(|w| (w, (w.as_ptr() as usize - text.as_ptr() as usize + 1) as u32));
        let Some((keyword, _)) = words.next() else {
            continue;
        };
        let args: Vec<(&str, u32)> = words.collect();
        let floats = |min: usize, what: &str| -> Option<(u32, u32, String)> {
            if args.len() < min {
                return Some((line, 1, format!("{what} needs {min} numbers")));
            }
            args.iter()
                .find(|(w, _)| w.parse::<f32>().is_err())
                .map(|(w, c)| (line, *c, format!("{w:?} is not a number")))
        };
        match keyword {
            "v" => {
                if let Some(e) = floats(3, "a vertex") {
                    return Some(e);
                }
                nv += 1;
            }
            "vt" => {
                if let Some(e) = floats(1, "a texture coordinate") {
                    return Some(e);
                }
                nvt += 1;
            }
            "vn" => {
                if let Some(e) = floats(3, "a normal") {
                    return Some(e);
                }
                nvn += 1;
            }
            "f" | "l" | "p" => {
                if keyword == "f" && args.len() < 3 {
                    return Some((line, 1, "a face needs at least 3 vertices".into()));
                }
                for (w, col) in &args {
                    for (k, part) in w.split('/').enumerate() {
                        if part.is_empty() && k > 0 {
                            continue;
                        }
                        let count = [nv, nvt, nvn].get(k).copied().unwrap_or(0);
                        let what = ["vertex", "texture coordinate", "normal"]
                            .get(k)
                            .copied()
                            .unwrap_or("index");
                        let Ok(idx) = part.parse::<i64>() else {
                            return Some((
                                line,
                                *col,
                                format!("{what} index {part:?} is not a whole number"),
                            ));
                        };
                        let resolved = if idx < 0 { count + idx + 1 } else { idx };
                        if idx == 0 || resolved < 1 || resolved > count {
                            return Some((
                                line,
                                *col,
                                format!("{what} index {idx} refers to none of the {count} defined so far"),
                            ));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    const CUBE_QUADS: &str = "\
v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

    #[test]
    fn reads_quads_with_outward_normals() {
        let l = read(CUBE_QUADS.as_bytes(), Path::new("cube.obj")).unwrap();
        assert_eq!(l.scene.meshes.len(), 1);
        let m = &l.scene.meshes[0];
        assert_eq!(m.triangles.len(), 12);
        // Every triangle's normal points away from the cube's centre.
        let c = Vec3::splat(0.5);
        for t in &m.triangles {
            let [a, b, d] = t.map(|i| m.positions[i as usize]);
            let g = (b - a).cross(d - a);
            assert!(g.dot((a + b + d) / 3.0 - c) > 0.0);
        }
        assert_eq!(l.scene.format, SourceFormat::Obj);
        // No mtllib: default material, no warning.
        assert!(l.warnings.is_empty());
    }

    #[test]
    fn missing_mtl_is_a_warning() {
        let src = format!("mtllib nowhere.mtl\nusemtl red\n{CUBE_QUADS}");
        let l = read(src.as_bytes(), Path::new("/nonexistent/cube.obj")).unwrap();
        assert!(!l.warnings.is_empty());
        assert!(l.warnings[0].contains("nowhere.mtl"), "{:?}", l.warnings);
        assert_eq!(l.scene.meshes[0].triangles.len(), 12);
    }

    #[test]
    fn broken_files_name_line_and_column() {
        let e = read(
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
            Path::new("bad.obj"),
        )
        .unwrap_err();
        assert_eq!((e.line, e.column), (4, 7), "{e}");
        assert!(e.to_string().starts_with("bad.obj:4:7: "), "{e}");
        let e = read(b"v 0 0 0\nv 1 x 0\n", Path::new("bad.obj")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 5), "{e}");
        let e = read(b"v 0 0 0\nf 1/1 1 1\n", Path::new("bad.obj")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 3), "{e}");
        assert!(e.message.contains("texture coordinate"), "{e}");
    }

    #[test]
    fn mtl_maps_onto_vrml_material() {
        let m = tobj::Material {
            name: "m".into(),
            diffuse: Some([0.5, 0.5, 0.5]),
            ambient: Some([0.25, 0.25, 0.25]),
            specular: Some([1.0, 0.0, 0.0]),
            shininess: Some(64.0),
            dissolve: Some(0.25),
            emissive: Some([0.0, 0.1, 0.0]),
            ..Default::default()
        };
        let v = convert_material(&m);
        assert_eq!(v.diffuse, Vec3::splat(0.5));
        assert_eq!(v.ambient_intensity, 0.5);
        assert_eq!(v.specular, Vec3::X);
        assert_eq!(v.shininess, 0.5);
        assert_eq!(v.transparency, 0.75);
        assert_eq!(v.emissive, Vec3::new(0.0, 0.1, 0.0));
    }
}
