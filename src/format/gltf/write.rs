//! The glTF writer: `animed convert IN out.gltf | out.glb`.
//!
//! One glTF node per scene node, in depth-first order, named by the
//! scene's node name (made unique with `_N`; unnamed nodes stay unnamed
//! unless the key note must address them). A light or camera whose own
//! location/direction or position/orientation is not the glTF default gets
//! a child node carrying that placement, marked `extras.animed = "part"`
//! so animed folds it back on reading. Meshes: one glTF mesh per (mesh,
//! material) pair with TRIANGLES, LINES and POINTS primitives over shared
//! float attributes and u32 indices. Materials: `material::pbr_from_phong`,
//! with the exact Phong values in `extras.animed` so animed reads them
//! back bit for bit. Lights: KHR_lights_punctual (`lights`). Every clip is
//! an animation (`write_anim`). The asset's `extras` carry the key note of
//! every clip, so export → import → export gives the same bytes.
//! `.gltf` embeds its buffer as a base64 `data:` URI (one file, saved
//! atomically); `.glb` holds it in the binary chunk.

use super::bin::{glb, num, nums, Bin};
use super::lights::{punctual_from_light, PunctualKind};
use super::material::{linear_exact, pbr_from_phong};
use super::uri::base64_encode;
use super::write_anim::{animations, NodeSlots};
use super::write_pointer::{PointerSlots, WrittenMaterial, EXTENSION as POINTER_EXTENSION};
use super::write_texture::{replaces_diffuse, TextureWriter};
use crate::anim::{Property, TargetRef};
use crate::format::export::channels::scene_diagonal;
use crate::format::export::keynote;
use crate::format::export::plan::WritePlan;
use crate::format::export::sampling::Tolerances;
use crate::format::export::{WriteOptions, WriteReport};
use crate::scene::{CameraKind, Material, NodeKind, Scene, TextureModel, Transform};
use glam::{Quat, Vec3};
use serde_json::{json, Map, Value as Json};
use std::collections::{BTreeMap, HashSet};

/// Unique names: the scene's own where it has one (white space made `_`,
/// as the key note needs single words); a generated one only for unnamed
/// nodes the key note must address.
fn node_names(scene: &Scene) -> Vec<String> {
    let mut needs = vec![false; scene.nodes.len()];
    for clip in scene.clip_refs() {
        for t in &clip.animation.tracks {
            if let TargetRef::Node(id) = t.target.of {
                if let Some(n) = needs.get_mut(id.0 as usize) {
                    *n = true;
                }
            }
        }
    }
    let mut used = HashSet::new();
    let mut names = vec![String::new(); scene.nodes.len()];
    for id in scene.walk() {
        let i = id.0 as usize;
        let node = scene.node(id);
        let hidden = !node.visible || node.style != crate::scene::RenderStyle::Filled;
        let base = if !node.name.is_empty() {
            // The key note separates words with spaces.
            node.name
                .chars()
                .map(|c| if c.is_whitespace() { '_' } else { c })
                .collect()
        } else if needs[i] || hidden {
            format!("node_{i}")
        } else {
            continue;
        };
        let mut name = base.clone();
        let mut k = 1;
        while !used.insert(name.clone()) {
            name = format!("{base}_{k}");
            k += 1;
        }
        names[i] = name;
    }
    names
}

/// A mesh's morph targets as glTF `targets` (POSITION and NORMAL deltas).
fn morph_targets(mesh: &crate::scene::Mesh, bin: &mut Bin) -> Option<Json> {
    let m = mesh.morph.as_deref()?;
    let flat = |v: &[Vec3]| -> Vec<f32> { v.iter().flat_map(|p| p.to_array()).collect() };
    Some(Json::Array(
        m.targets()
            .iter()
            .map(|t| {
                let mut o =
                    json!({ "POSITION": bin.floats(&flat(t.positions()), 3, true, Some(34962)) });
                if !t.normals().is_empty() && !mesh.normals.is_empty() {
                    o["NORMAL"] = json!(bin.floats(&flat(t.normals()), 3, false, Some(34962)));
                }
                o
            })
            .collect(),
    ))
}

/// glTF skins for the skinned shapes written (`(scene node, scene skin)`),
/// one per scene skin, and each shape node's `skin`. A skin whose joints
/// were not all written is left out (the shape is then drawn unskinned).
fn write_skins(
    scene: &Scene,
    skinned: &[(usize, usize)],
    slots: &NodeSlots,
    nodes: &mut [Json],
    bin: &mut Bin,
) -> Vec<Json> {
    let mut out = Vec::new();
    let mut made: BTreeMap<usize, usize> = BTreeMap::new();
    for &(node, k) in skinned {
        let Some(skin) = scene.skins.get(k) else {
            continue;
        };
        let gi = match made.get(&k) {
            Some(&g) => g,
            None => {
                let joints: Option<Vec<usize>> = skin
                    .joints()
                    .iter()
                    .map(|j| slots.node.get(j.0 as usize).copied().flatten())
                    .collect();
                let Some(joints) = joints else { continue };
                let ibm: Vec<f32> = skin
                    .inverse_bind()
                    .iter()
                    .flat_map(|m| m.to_cols_array())
                    .collect();
                let mut sj = json!({
                    "joints": joints,
                    "inverseBindMatrices": bin.floats(&ibm, 16, false, None),
                });
                if !skin.name.is_empty() {
                    sj["name"] = json!(skin.name);
                }
                if let Some(root) = skin
                    .skeleton
                    .and_then(|r| slots.node.get(r.0 as usize).copied().flatten())
                {
                    sj["skeleton"] = json!(root);
                }
                out.push(sj);
                made.insert(k, out.len() - 1);
                out.len() - 1
            }
        };
        if let Some(Json::Object(o)) = slots
            .node
            .get(node)
            .copied()
            .flatten()
            .and_then(|g| nodes.get_mut(g))
        {
            o.insert("skin".into(), json!(gi));
        }
    }
    out
}

fn is_trs(t: &Transform) -> bool {
    t.center == Vec3::ZERO && t.scale_orientation == Quat::IDENTITY && t.extra.is_none()
}

/// TRS (defaults omitted) or a matrix into a node object.
fn put_transform(node: &mut Map<String, Json>, t: &Transform) {
    if is_trs(t) {
        if t.translation != Vec3::ZERO {
            node.insert("translation".into(), nums(&t.translation.to_array()));
        }
        if t.rotation != Quat::IDENTITY {
            node.insert("rotation".into(), nums(&t.rotation.to_array()));
        }
        if t.scale != Vec3::ONE {
            node.insert("scale".into(), nums(&t.scale.to_array()));
        }
    } else {
        node.insert("matrix".into(), nums(&t.matrix().to_cols_array()));
    }
}

/// The exact Phong values, for `extras.animed` of a material (`unlit`
/// only when lighting is off, so lit materials keep their bytes).
fn phong_extras(m: &Material) -> Json {
    let mut extras = json!({
        "diffuse": nums(&m.diffuse.to_array()),
        "ambientIntensity": num(m.ambient_intensity),
        "specular": nums(&m.specular.to_array()),
        "emissive": nums(&m.emissive.to_array()),
        "shininess": num(m.shininess),
        "transparency": num(m.transparency),
    });
    if m.unlit {
        extras["unlit"] = json!(true);
    }
    extras
}

fn material_json(
    m: &Material,
    name: Option<&str>,
    double_sided: bool,
    white: bool,
    texture: Option<Json>,
    emissive_texture: Option<Json>,
) -> Json {
    let mut p = pbr_from_phong(m);
    if white {
        // Vertex colours carry the diffuse colour; glTF multiplies them by
        // the base colour, so that is white here.
        p.base_color = [1.0, 1.0, 1.0, p.base_color[3]];
    }
    let mut o = json!({
        "pbrMetallicRoughness": {
            "baseColorFactor": nums(&p.base_color),
            "metallicFactor": num(p.metallic),
            "roughnessFactor": num(p.roughness),
        },
        "extras": { "animed": phong_extras(m) },
    });
    if let Some(info) = texture {
        o["pbrMetallicRoughness"]["baseColorTexture"] = info;
    }
    if let Some(name) = name.filter(|n| !n.is_empty()) {
        o["name"] = json!(name);
    }
    if p.emissive != Vec3::ZERO {
        o["emissiveFactor"] = nums(&p.emissive.to_array());
    }
    if let Some(info) = emissive_texture.filter(|_| !p.unlit) {
        o["emissiveTexture"] = info;
    }
    if p.alpha_mode == gltf::material::AlphaMode::Blend {
        o["alphaMode"] = json!("BLEND");
    }
    if double_sided {
        o["doubleSided"] = json!(true);
    }
    if p.unlit {
        o["extensions"] = json!({ "KHR_materials_unlit": {} });
    }
    o
}

/// Materials (by index) whose `property` some clip animates.
fn animated_materials(scene: &Scene, property: Property) -> HashSet<u32> {
    scene
        .clip_refs()
        .iter()
        .flat_map(|c| c.animation.tracks.iter())
        .filter(|t| t.target.property == property)
        .filter_map(|t| match t.target.of {
            TargetRef::Material(m) => Some(m.0),
            _ => None,
        })
        .collect()
}

/// Writes `scene` as glTF JSON (`glb == false`) or a .glb.
pub fn write(scene: &Scene, opts: &WriteOptions, binary: bool) -> (Vec<u8>, WriteReport) {
    let mut report = WriteReport::default();
    let names = node_names(scene);
    // Material names as the key note spells them (unique, made for
    // animated or shared materials).
    let material_names = WritePlan::new(scene).materials;
    let order = scene.walk();
    let n = scene.nodes.len();
    let reference = scene_diagonal(scene) / 2.0;

    // Which lights/cameras need a placement child.
    let mut animated_part = vec![false; n];
    for clip in scene.clip_refs() {
        for t in &clip.animation.tracks {
            if let TargetRef::Node(id) = t.target.of {
                if matches!(
                    t.target.property,
                    Property::CameraPosition
                        | Property::CameraOrientation
                        | Property::LightLocation
                        | Property::LightDirection
                ) {
                    if let Some(a) = animated_part.get_mut(id.0 as usize) {
                        *a = true;
                    }
                }
            }
        }
    }
    let placement = |i: usize| -> Option<(Vec3, Quat)> {
        match &scene.nodes[i].kind {
            NodeKind::Light(l) => {
                let dir = l.direction.normalize_or(Vec3::NEG_Z);
                let q = Quat::from_rotation_arc(Vec3::NEG_Z, dir);
                let pos = if matches!(l.kind, crate::scene::LightKind::Directional) {
                    Vec3::ZERO
                } else {
                    l.location
                };
                (pos != Vec3::ZERO || q != Quat::IDENTITY || animated_part[i]).then_some((pos, q))
            }
            NodeKind::Camera(c) => {
                (c.position != Vec3::ZERO || c.orientation != Quat::IDENTITY || animated_part[i])
                    .then_some((c.position, c.orientation))
            }
            _ => None,
        }
    };

    // glTF node indices: depth-first, each placement child right after
    // its owner (the order animed's reader creates them in).
    let mut slots = NodeSlots {
        node: vec![None; n],
        part: vec![None; n],
        matrix: vec![false; n],
        morphed: (0..n)
            .map(|i| match &scene.nodes[i].kind {
                NodeKind::Shape(s) => scene
                    .meshes
                    .get(s.mesh.0 as usize)
                    .is_some_and(|m| m.morph.is_some()),
                _ => false,
            })
            .collect(),
    };
    let mut next = 0usize;
    for id in &order {
        let i = id.0 as usize;
        slots.node[i] = Some(next);
        next += 1;
        if placement(i).is_some() {
            slots.part[i] = Some(next);
            next += 1;
        }
        slots.matrix[i] = !is_trs(&scene.nodes[i].transform);
    }

    let mut bin = Bin::default();
    let mut nodes: Vec<Json> = vec![Json::Null; next];
    let mut meshes: Vec<Json> = Vec::new();
    let mut materials: Vec<Json> = Vec::new();
    let mut lights: Vec<Json> = Vec::new();
    let mut cameras: Vec<Json> = Vec::new();
    let mut pointers = PointerSlots {
        light: vec![None; n],
        camera: vec![None; n],
        material: vec![Vec::new(); scene.materials.len()],
        reference,
    };
    // Materials whose transparency is animated blend even when opaque at
    // rest (an OPAQUE material's alpha is ignored by every reader); an
    // animated emissive colour black at rest still needs its factor (a
    // pointer must name a property the document has).
    let see_through = animated_materials(scene, Property::Transparency);
    let glowing = animated_materials(scene, Property::Emissive);
    let mut mesh_cache: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    let mut material_cache: BTreeMap<(u32, bool, bool), usize> = BTreeMap::new();
    // Attributes and index accessors of a scene mesh, shared by every glTF
    // mesh made from it.
    let mut attr_cache: BTreeMap<(u32, bool), Json> = BTreeMap::new();
    let mut textures = TextureWriter::default();
    let mut index_cache: BTreeMap<u32, Vec<(usize, u32)>> = BTreeMap::new();
    let mut target_cache: BTreeMap<u32, Option<Json>> = BTreeMap::new();
    // (scene node, scene skin) of every skinned shape written.
    let mut skinned: Vec<(usize, usize)> = Vec::new();

    for id in &order {
        let i = id.0 as usize;
        let node = scene.node(*id);
        let mut o = Map::new();
        if !names[i].is_empty() {
            o.insert("name".into(), json!(names[i]));
        }
        put_transform(&mut o, &node.transform);
        let mut children: Vec<usize> = Vec::new();
        let mut content = Map::new();
        match &node.kind {
            NodeKind::Group => {}
            NodeKind::Shape(sh) => {
                let Some(mesh) = scene.meshes.get(sh.mesh.0 as usize) else {
                    continue;
                };
                let m = match mesh_cache.get(&(sh.mesh.0, sh.material.0)) {
                    Some(&m) => m,
                    None => {
                        let colored = !mesh.colors.is_empty();
                        let key = (sh.material.0, !mesh.solid, colored);
                        let mat = match material_cache.get(&key) {
                            Some(&k) => k,
                            None => {
                                let src = scene
                                    .materials
                                    .get(sh.material.0 as usize)
                                    .cloned()
                                    .unwrap_or_default();
                                let name = material_names
                                    .get(sh.material.0 as usize)
                                    .and_then(|n| n.as_deref());
                                let info = src.texture.as_ref().and_then(|t| {
                                    textures.info(scene, t, &mut bin, binary, &mut report)
                                });
                                // An unlit material's map is its base colour texture.
                                let emissive_info = src
                                    .emissive_texture
                                    .as_ref()
                                    .filter(|_| !pbr_from_phong(&src).unlit)
                                    .and_then(|t| {
                                        textures.info(scene, t, &mut bin, binary, &mut report)
                                    });
                                let white = colored
                                    || (info.is_some()
                                        && src
                                            .texture
                                            .as_ref()
                                            .is_some_and(|t| replaces_diffuse(scene, t)));
                                // A texture with alpha makes the surface see-through
                                // (OPAQUE would make readers ignore it).
                                let alpha = info.is_some()
                                    && src.texture.as_ref().is_some_and(|t| {
                                        t.model != TextureModel::Decal
                                            && scene.image(t.image).is_some_and(|i| {
                                                matches!(i.components(), 2 | 4) && i.has_alpha()
                                            })
                                    });
                                let mut mj = material_json(
                                    &src,
                                    name,
                                    !mesh.solid,
                                    white,
                                    info,
                                    emissive_info,
                                );
                                let cutoff = src.texture.as_ref().and_then(|t| t.alpha_cutoff);
                                match (alpha, cutoff) {
                                    (true, Some(c)) => {
                                        mj["alphaMode"] = json!("MASK");
                                        mj["alphaCutoff"] = num(c);
                                    }
                                    (true, None) => mj["alphaMode"] = json!("BLEND"),
                                    _ if see_through.contains(&sh.material.0) => {
                                        mj["alphaMode"] = json!("BLEND")
                                    }
                                    _ => {}
                                }
                                if glowing.contains(&sh.material.0)
                                    && !pbr_from_phong(&src).unlit
                                    && mj.get("emissiveFactor").is_none()
                                {
                                    mj["emissiveFactor"] = json!([0.0, 0.0, 0.0]);
                                }
                                materials.push(mj);
                                if let Some(w) = pointers.material.get_mut(sh.material.0 as usize) {
                                    w.push(WrittenMaterial {
                                        index: materials.len() - 1,
                                        white,
                                    });
                                }
                                material_cache.insert(key, materials.len() - 1);
                                materials.len() - 1
                            }
                        };
                        let textured = (materials[mat]["pbrMetallicRoughness"]
                            .get("baseColorTexture")
                            .is_some()
                            || materials[mat].get("emissiveTexture").is_some())
                            && mesh.texcoords.len() == mesh.positions.len();
                        let attrs = attr_cache
                            .entry((sh.mesh.0, textured))
                            .or_insert_with(|| {
                                let flat: Vec<f32> =
                                    mesh.positions.iter().flat_map(|p| p.to_array()).collect();
                                let mut a = json!({
                                    "POSITION": bin.floats(&flat, 3, true, Some(34962)),
                                });
                                if !mesh.normals.is_empty()
                                    && mesh.normals.len() == mesh.positions.len()
                                {
                                    let f: Vec<f32> =
                                        mesh.normals.iter().flat_map(|p| p.to_array()).collect();
                                    a["NORMAL"] = json!(bin.floats(&f, 3, false, Some(34962)));
                                }
                                if let Some(sw) = mesh.skin_weights.as_deref() {
                                    if sw.len() == mesh.positions.len() {
                                        a["JOINTS_0"] = json!(bin.joints(sw.joints()));
                                        let f: Vec<f32> =
                                            sw.weights().iter().flatten().copied().collect();
                                        a["WEIGHTS_0"] =
                                            json!(bin.floats(&f, 4, false, Some(34962)));
                                    }
                                }
                                if colored && mesh.colors.len() == mesh.positions.len() {
                                    let f: Vec<f32> = mesh
                                        .colors
                                        .iter()
                                        .flat_map(|c| linear_exact(*c).to_array())
                                        .collect();
                                    a["COLOR_0"] = json!(bin.floats(&f, 3, false, Some(34962)));
                                }
                                if textured {
                                    // glTF's v runs down the image.
                                    let f: Vec<f32> = mesh
                                        .texcoords
                                        .iter()
                                        .flat_map(|t| [t.x, 1.0 - t.y])
                                        .collect();
                                    a["TEXCOORD_0"] = json!(bin.floats(&f, 2, false, Some(34962)));
                                }
                                a
                            })
                            .clone();
                        let indexed = index_cache.entry(sh.mesh.0).or_insert_with(|| {
                            let tri: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
                            let lines: Vec<u32> = mesh.lines.iter().flatten().copied().collect();
                            [(tri, 4), (lines, 1), (mesh.points.clone(), 0)]
                                .into_iter()
                                .filter(|(data, _)| !data.is_empty())
                                .map(|(data, mode)| (bin.indices(&data), mode))
                                .collect()
                        });
                        let targets = target_cache
                            .entry(sh.mesh.0)
                            .or_insert_with(|| morph_targets(mesh, &mut bin))
                            .clone();
                        let prims: Vec<Json> = indexed
                            .iter()
                            .map(|&(idx, mode)| {
                                let mut p = json!({
                                    "attributes": attrs.clone(),
                                    "indices": idx,
                                    "material": mat,
                                    "mode": mode,
                                });
                                if let Some(t) = &targets {
                                    p["targets"] = t.clone();
                                }
                                p
                            })
                            .collect();
                        if prims.is_empty() {
                            continue;
                        }
                        let mut mj = json!({ "primitives": prims });
                        if !mesh.name.is_empty() {
                            mj["name"] = json!(mesh.name);
                        }
                        if let Some(m) = mesh.morph.as_deref() {
                            mj["weights"] = nums(m.default_weights());
                            let names: Vec<&str> =
                                m.targets().iter().map(|t| t.name.as_str()).collect();
                            mj["extras"] = json!({ "targetNames": names });
                        }
                        meshes.push(mj);
                        mesh_cache.insert((sh.mesh.0, sh.material.0), meshes.len() - 1);
                        meshes.len() - 1
                    }
                };
                content.insert("mesh".into(), json!(m));
                if let Some(k) = node.skin {
                    skinned.push((i, k.0 as usize));
                }
            }
            NodeKind::Light(l) => {
                let p = punctual_from_light(l, reference);
                let mut lj = json!({
                    "type": match p.kind {
                        PunctualKind::Directional => "directional",
                        PunctualKind::Point => "point",
                        PunctualKind::Spot { .. } => "spot",
                    },
                    "color": nums(&linear_exact(l.color).to_array()),
                    "intensity": num(p.intensity),
                    "extras": { "animed": {
                        "intensity": num(l.intensity),
                        "on": l.on,
                        "ambientIntensity": num(l.ambient_intensity),
                        "attenuation": nums(&l.attenuation.to_array()),
                        "radius": num(l.radius.min(f32::MAX)),
                        "scoped": l.scoped,
                        "direction": nums(&l.direction.to_array()),
                        "reference": num(reference),
                    }},
                });
                if let PunctualKind::Spot { inner, outer } = p.kind {
                    lj["spot"] = json!({
                        "innerConeAngle": num(inner.min(outer)),
                        "outerConeAngle": num(outer.max(1e-4)),
                    });
                }
                if let Some(r) = p.range {
                    lj["range"] = num(r.max(1e-6));
                }
                if !names[i].is_empty() {
                    lj["name"] = json!(names[i]);
                }
                lights.push(lj);
                pointers.light[i] = Some(lights.len() - 1);
                content.insert(
                    "extensions".into(),
                    json!({ "KHR_lights_punctual": { "light": lights.len() - 1 } }),
                );
            }
            NodeKind::Camera(c) => {
                let near = c.near.filter(|n| *n > 0.0).unwrap_or(0.1);
                let mut cj = match c.kind {
                    CameraKind::Perspective { height_angle } => {
                        let mut p = json!({ "yfov": num(height_angle), "znear": num(near) });
                        if let Some(f) = c.far.filter(|f| *f > near) {
                            p["zfar"] = num(f);
                        }
                        json!({ "type": "perspective", "perspective": p })
                    }
                    CameraKind::Orthographic { height } => {
                        let far = c.far.filter(|f| *f > near).unwrap_or(1000.0);
                        let m = num((height / 2.0).max(1e-6));
                        json!({ "type": "orthographic", "orthographic": {
                            "xmag": m.clone(), "ymag": m, "znear": num(near), "zfar": num(far),
                        }})
                    }
                };
                if !c.description.is_empty() {
                    cj["name"] = json!(c.description);
                }
                cameras.push(cj);
                pointers.camera[i] = Some(cameras.len() - 1);
                content.insert("camera".into(), json!(cameras.len() - 1));
            }
        }
        match (slots.part[i], placement(i)) {
            (Some(pi), Some((pos, rot))) => {
                let mut part = content;
                if pos != Vec3::ZERO {
                    part.insert("translation".into(), nums(&pos.to_array()));
                }
                if rot != Quat::IDENTITY {
                    part.insert("rotation".into(), nums(&rot.to_array()));
                }
                part.insert("extras".into(), json!({ "animed": "part" }));
                nodes[pi] = Json::Object(part);
                children.push(pi);
            }
            _ => o.extend(content),
        }
        children.extend(
            node.children
                .iter()
                .filter_map(|c| slots.node[c.0 as usize]),
        );
        if !children.is_empty() {
            o.insert("children".into(), json!(children));
        }
        if let Some(gi) = slots.node[i] {
            nodes[gi] = Json::Object(o);
        }
    }

    let skins = write_skins(scene, &skinned, &slots, &mut nodes, &mut bin);

    let tol = Tolerances::new(scene_diagonal(scene), opts.tolerance, opts.angle_tolerance);
    let clips = scene.clip_refs();
    let (anims, pointed) = animations(
        scene,
        &clips,
        &slots,
        &pointers,
        &names,
        &tol,
        &mut bin,
        &mut report,
    );

    // The key note of every clip, naming nodes as written here.
    let mut plan = WritePlan::new(scene);
    plan.wrapped = vec![false; n];
    plan.wrapper = vec![None; n];
    plan.content = names
        .iter()
        .map(|s| (!s.is_empty()).then(|| s.clone()))
        .collect();
    let notes: Vec<Json> = clips
        .iter()
        .map(|c| {
            let one = Scene {
                nodes: scene.nodes.clone(),
                roots: scene.roots.clone(),
                materials: scene.materials.clone(),
                settings: crate::scene::Settings {
                    duration: c.duration,
                    ..scene.settings.clone()
                },
                animation: c.animation.clone(),
                ..Scene::default()
            };
            json!({ "name": c.name, "keys": keynote::write(&one, &plan) })
        })
        .collect();

    let mut used = Vec::new();
    if !lights.is_empty() {
        used.push("KHR_lights_punctual");
    }
    if materials.iter().any(|m| m.get("extensions").is_some()) {
        used.push("KHR_materials_unlit");
    }
    if textures.transform_used {
        used.push("KHR_texture_transform");
    }
    if !pointed.is_empty() {
        used.push(POINTER_EXTENSION);
    }
    let roots: Vec<usize> = scene
        .roots
        .iter()
        .filter_map(|r| slots.node[r.0 as usize])
        .collect();
    let mut doc = json!({
        "asset": {
            "version": "2.0",
            "generator": "animed",
            "extras": { "animed-clips": notes, "animed-playing": scene.clips.active() },
        },
        "scene": 0,
        "scenes": [ { "nodes": roots } ],
    });
    let put = |doc: &mut Json, key: &str, v: Vec<Json>| {
        if !v.is_empty() {
            doc[key] = Json::Array(v);
        }
    };
    put(&mut doc, "nodes", nodes);
    put(&mut doc, "meshes", meshes);
    put(&mut doc, "skins", skins);
    put(&mut doc, "materials", materials);
    put(&mut doc, "cameras", cameras);
    put(&mut doc, "animations", anims);
    textures.finish(&mut doc);
    if !lights.is_empty() {
        doc["extensions"] = json!({ "KHR_lights_punctual": { "lights": lights } });
    }
    if !used.is_empty() {
        doc["extensionsUsed"] = json!(used);
    }
    let Bin {
        bytes,
        views,
        accessors,
    } = bin;
    put(&mut doc, "accessors", accessors);
    put(&mut doc, "bufferViews", views);
    if !bytes.is_empty() {
        let mut buffer = json!({ "byteLength": bytes.len() });
        if !binary {
            buffer["uri"] = json!(format!(
                "data:application/octet-stream;base64,{}",
                base64_encode(&bytes)
            ));
        }
        doc["buffers"] = json!([buffer]);
    }
    let text = serde_json::to_vec(&doc).unwrap_or_default();
    let out = if binary { glb(&text, &bytes) } else { text };
    (out, report)
}
