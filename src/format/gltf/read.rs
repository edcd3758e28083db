//! The glTF reader's entry: container → document → buffers → the chosen
//! scene's node tree (with meshes, materials, lights, cameras) → clips.
//!
//! Node mapping: each glTF node of the scene becomes one animed node with
//! the glTF name (empty when it has none; `info` shows `#N`) and its TRS
//! (a `matrix` is split into TRS when it has no shear, else kept whole).
//! A node whose only content is one drawable primitive, one camera or one
//! light holds it itself; otherwise it is a group whose unnamed children
//! hold its primitives, camera and light, so animating the glTF node
//! moves all of them. Morph targets and skins map one to one onto the
//! model (`deform.rs`): a skinned node's shapes get `Node::skin`, its
//! morph weights (node `weights`, else mesh `weights`) are the mesh's
//! defaults, and `weights` channels on a multi-primitive node drive all of
//! its shapes (the track sits on the group).

use super::anim::{all_times, choose_fps, node_target, read_clips};
use super::container::{is_glb, parse_document, split_glb, Buffers, GltfError, Result};
use super::deform::{read_skin, target_names};
use super::lights::{camera_from_gltf, light_from_extras, light_from_punctual, Punctual};
use super::material::{phong_from_extras, phong_from_pbr, Pbr};
use super::mesh::primitive_mesh;
use super::pointer::pointer;
use super::pointer_anim;
use super::texture;
use crate::format::{LoadError, Loaded};
use crate::scene::{
    Image, ImageId, Light, Material, MaterialId, MeshId, Node, NodeId, NodeKind, Scene, Shape,
    SourceFormat, Transform,
};
use glam::{Mat4, Quat, Vec3};
use std::collections::HashMap;
use std::path::Path;

/// What the caller may choose about a glTF load.
#[derive(Clone, Debug, Default)]
pub struct ReadOptions {
    /// Which scene (`--scene N`); default: the file's `scene`, else 0.
    pub scene: Option<usize>,
}

/// Whether bytes or a name look like glTF: the `.glb` magic, or a
/// `.gltf`/`.glb` name.
pub fn is_gltf(bytes: &[u8], path: &Path) -> bool {
    is_glb(bytes)
        || path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// Reads a .gltf or .glb file's bytes. Files it references are read with
/// `read_file` (relative to `path`'s folder).
pub fn read(
    bytes: &[u8],
    path: &Path,
    opts: &ReadOptions,
    read_file: &dyn Fn(&Path) -> std::result::Result<Vec<u8>, String>,
) -> std::result::Result<Loaded, LoadError> {
    read_inner(bytes, path, opts, read_file)
        .map_err(|e| LoadError::new(path, e.line, e.column, e.to_string()))
}

fn read_inner(
    bytes: &[u8],
    path: &Path,
    opts: &ReadOptions,
    read_file: &dyn Fn(&Path) -> std::result::Result<Vec<u8>, String>,
) -> Result<Loaded> {
    let mut warnings = Vec::new();
    let (json, bin) = if is_glb(bytes) {
        split_glb(bytes)?
    } else {
        (bytes, None)
    };
    // KHR_animation_pointer channels the gltf crate cannot parse are taken
    // out first (pointer_anim.rs) and mapped after the animations.
    let taken = pointer_anim::take(json)?;
    let json = taken.as_ref().map_or(json, |(j, _)| j.as_slice());
    let doc = parse_document(json, &mut warnings)?;
    let base = path.parent().unwrap_or(Path::new("."));
    let buffers = Buffers::load(&doc, bin, base, read_file)?;
    let mut scene = Scene::new();
    let images = texture::load_images(&doc, &buffers, base, read_file, &mut scene, &mut warnings);
    let mut b = Builder {
        images,
        opaque_images: HashMap::new(),
        nodes: doc.nodes().collect(),
        gltf_materials: doc.materials().collect(),
        buffers: &buffers,
        scene,
        warnings: Vec::new(),
        materials: HashMap::new(),
        uv_sets: HashMap::new(),
        meshes: HashMap::new(),
        node_ids: vec![None; doc.nodes().len()],
        part_of: vec![None; doc.nodes().len()],
        skinned: Vec::new(),
        lights: Vec::new(),
        cameras: Vec::new(),
    };
    b.scene.format = SourceFormat::Gltf;
    let scene_index = pick_scene(&doc, opts.scene)?;
    if doc.scenes().len() > 1 {
        let list: Vec<String> = doc
            .scenes()
            .map(|s| format!("{} `{}`", s.index(), s.name().unwrap_or_default()))
            .collect();
        warnings.push(format!(
            "the file has {} scenes ({}); showing scene {} (choose one with --scene N)",
            list.len(),
            list.join(", "),
            scene_index.unwrap_or(0)
        ));
    }
    let roots: Vec<usize> = match scene_index {
        Some(i) => doc
            .scenes()
            .nth(i)
            .map(|s| s.nodes().map(|n| n.index()).collect())
            .unwrap_or_default(),
        None => Vec::new(),
    };
    b.build_tree(&roots)?;
    b.bind_skins(&doc)?;
    let fps = choose_fps(&all_times(&doc, &buffers));
    b.scene.settings.fps = fps;
    let target_of = |i: usize, path: gltf::animation::Property| {
        use crate::anim::Property as Q;
        use gltf::animation::Property as P;
        match b.part_of.get(i).copied().flatten() {
            None => node_target(&b.node_ids, i, path),
            Some(id) => {
                let camera = b.scene.node(id).camera().is_some();
                let p = match (path, camera) {
                    (P::Translation, true) => Q::CameraPosition,
                    (P::Rotation, true) => Q::CameraOrientation,
                    (P::Translation, false) => Q::LightLocation,
                    _ => return None,
                };
                Some((id, p))
            }
        }
    };
    let mut clip_warnings = Vec::new();
    let mut clips = read_clips(&doc, &buffers, &target_of, fps, &mut clip_warnings)?;
    if let Some((_, channels)) = &taken {
        let targets = pointer_anim::Targets {
            fps,
            lights: &b.lights,
            cameras: &b.cameras,
            materials: &b.materials,
        };
        pointer_anim::add_tracks(
            &doc,
            &buffers,
            channels,
            &targets,
            &mut b.scene,
            &mut clips,
            &mut clip_warnings,
        )?;
    }
    let static_duration = b.scene.settings.duration;
    b.scene.set_clips(clips, 0);
    if b.scene.clips.is_empty() {
        b.scene.settings.duration = static_duration;
    }
    // glTF has no headlight; light the model with one when it brings none.
    let has_lights = b.scene.nodes.iter().any(|n| n.light().is_some());
    b.scene.settings.headlight = Some(!has_lights);
    // animed's own key notes replace the animations read above (and what
    // reading them had to say).
    match asset_notes(&doc).map(|notes| apply_notes(&mut b.scene, &notes)) {
        Some(Ok(())) => {}
        Some(Err(e)) => {
            b.warnings.extend(clip_warnings);
            b.warnings.push(format!(
                "/asset/extras: ignored the animed key notes ({e}); using the file's animations"
            ));
        }
        None => b.warnings.extend(clip_warnings),
    }
    warnings.extend(b.warnings);
    let warnings = warnings
        .into_iter()
        .map(|w| format!("{}: {w}", path.display()))
        .collect();
    Ok(Loaded {
        scene: b.scene,
        warnings,
    })
}

/// The key notes animed's writer puts in the asset's `extras`: one per
/// clip, `[(clip name, note text)]`.
fn asset_notes(doc: &gltf::Document) -> Option<Vec<(String, String)>> {
    let raw = doc.as_json().asset.extras.as_ref()?;
    let v: serde_json::Value = serde_json::from_str(raw.get()).ok()?;
    let list = v.get("animed-clips")?.as_array()?;
    list.iter()
        .map(|c| {
            Some((
                c.get("name")?.as_str()?.to_string(),
                c.get("keys")?.as_str()?.to_string(),
            ))
        })
        .collect()
}

/// Replaces the scene's clips with the notes' exact keys. A single
/// unnamed clip is the scene's own animation (no named clips), as it was
/// before writing.
fn apply_notes(scene: &mut Scene, notes: &[(String, String)]) -> std::result::Result<(), String> {
    use crate::format::export::keynote;
    let mut work = scene.clone();
    // The note says whether the scene had a headlight setting.
    work.settings.headlight = None;
    let mut clips = Vec::with_capacity(notes.len());
    for (name, text) in notes {
        let note = keynote::parse(text).map_err(|e| e.to_string())?;
        keynote::apply(&note, &mut work)?;
        clips.push(crate::scene::Clip {
            name: name.clone(),
            animation: std::mem::take(&mut work.animation),
            duration: work.settings.duration,
        });
    }
    work.clips = Default::default();
    if clips.len() == 1 && clips[0].name.is_empty() {
        let only = clips.remove(0);
        work.animation = only.animation;
        work.settings.duration = only.duration;
    } else if !clips.is_empty() {
        work.set_clips(clips, 0);
    }
    *scene = work;
    Ok(())
}

fn pick_scene(doc: &gltf::Document, wanted: Option<usize>) -> Result<Option<usize>> {
    let count = doc.scenes().len();
    match wanted {
        Some(i) if i < count => Ok(Some(i)),
        Some(i) => Err(GltfError::at(
            "/scenes",
            format!(
                "there is no scene {i}: the file has {count}{}",
                if count > 0 {
                    format!(" (0..{})", count - 1)
                } else {
                    String::new()
                }
            ),
        )),
        None => Ok(doc
            .default_scene()
            .map(|s| s.index())
            .or((count > 0).then_some(0))),
    }
}

struct Builder<'a, 'b> {
    /// Indexed once: the crate's iterators have no O(1) `nth`.
    nodes: Vec<gltf::Node<'a>>,
    gltf_materials: Vec<gltf::Material<'a>>,
    buffers: &'a Buffers<'b>,
    scene: Scene,
    warnings: Vec<String>,
    /// glTF material index (None = the default material) → ours.
    materials: HashMap<Option<usize>, MaterialId>,
    /// The TEXCOORD set each textured material's textures read.
    uv_sets: HashMap<MaterialId, u32>,
    /// What a primitive reads (accessors, mode, sidedness, colour base) →
    /// ours (None: skipped primitive).
    meshes: HashMap<String, Option<MeshId>>,
    node_ids: Vec<Option<NodeId>>,
    /// glTF placement nodes folded into their parent's light or camera.
    part_of: Vec<Option<NodeId>>,
    /// (glTF skin index, animed shape node) for every skinned shape.
    skinned: Vec<(usize, NodeId)>,
    /// (glTF light / camera index, the animed node holding it), for
    /// KHR_animation_pointer channels.
    lights: Vec<(usize, NodeId)>,
    cameras: Vec<(usize, NodeId)>,
    /// Decoded images by glTF image index (None: unused or unreadable).
    images: Vec<Option<ImageId>>,
    /// An image without its alpha, for OPAQUE materials.
    opaque_images: HashMap<ImageId, ImageId>,
}

/// A node's local transform: TRS as given, a matrix split into TRS when it
/// recomposes exactly enough, else kept as a raw matrix.
fn node_transform(node: &gltf::Node) -> Transform {
    match node.transform() {
        gltf::scene::Transform::Decomposed {
            translation,
            rotation,
            scale,
        } => Transform {
            translation: Vec3::from(translation),
            rotation: unit_quat(rotation),
            scale: Vec3::from(scale),
            ..Transform::default()
        },
        gltf::scene::Transform::Matrix { matrix } => {
            let m = Mat4::from_cols_array_2d(&matrix);
            let (s, r, t) = m.to_scale_rotation_translation();
            let back = Mat4::from_scale_rotation_translation(s, r, t);
            let size = m.to_cols_array().iter().fold(1.0f32, |a, v| a.max(v.abs()));
            let exact = m
                .to_cols_array()
                .iter()
                .zip(back.to_cols_array())
                .all(|(a, b)| (a - b).abs() <= 1e-6 * size);
            if exact && s.is_finite() && r.is_finite() && t.is_finite() {
                Transform {
                    translation: t,
                    rotation: r.normalize(),
                    scale: s,
                    ..Transform::default()
                }
            } else {
                Transform {
                    extra: Some(m),
                    ..Transform::default()
                }
            }
        }
    }
}

impl<'a> Builder<'a, '_> {
    fn material(&mut self, index: Option<usize>) -> MaterialId {
        if let Some(&id) = self.materials.get(&index) {
            return id;
        }
        let mut uv_set = None;
        let m = match index.and_then(|i| self.gltf_materials.get(i).cloned()) {
            Some(m) => {
                let pbr = Pbr::from_gltf(&m);
                let mut phong = phong_from_extras(&m, &pbr).unwrap_or_else(|| phong_from_pbr(&pbr));
                let base = self.texture(&m);
                let emissive = self.emissive_texture(&m, index.unwrap_or(0), &pbr, base.as_ref());
                uv_set = base.as_ref().or(emissive.as_ref()).map(|(_, set)| *set);
                phong.texture = base.map(|(t, _)| t);
                phong.emissive_texture = emissive.map(|(t, _)| t);
                phong
            }
            None => Material {
                name: String::new(),
                ..Material::default()
            },
        };
        let id = self.scene.add_material(m);
        self.materials.insert(index, id);
        if let Some(set) = uv_set {
            self.uv_sets.insert(id, set);
        }
        id
    }

    /// The emissive map of material `i` and its TEXCOORD set (§3.9.3):
    /// its emissiveTexture; none for KHR_materials_unlit, which ignores it
    /// (the unlit colour is base colour × base colour texture). Meshes keep one coordinate set, so an emissive texture
    /// reading another set than the base colour texture is left out with
    /// a warning at its JSON pointer.
    fn emissive_texture(
        &mut self,
        m: &gltf::Material,
        i: usize,
        pbr: &Pbr,
        base: Option<&(crate::scene::Texture, u32)>,
    ) -> Option<(crate::scene::Texture, u32)> {
        if pbr.unlit {
            return None;
        }
        let (t, set) = texture::emissive_texture(m, &self.images)?;
        match base {
            Some((_, b)) if *b != set => {
                self.warnings.push(format!(
                    "{}: the emissive texture reads TEXCOORD_{set} but the base colour texture reads TEXCOORD_{b}; animed keeps one set per mesh, so the emissive texture is not drawn",
                    pointer(&[&"materials", &i, &"emissiveTexture"])
                ));
                None
            }
            _ => Some((t, set)),
        }
    }

    /// A material's base colour texture and its TEXCOORD set. OPAQUE
    /// materials ignore the texture's alpha (§3.9.4), so they get a copy of
    /// the image without it (made once).
    fn texture(&mut self, m: &gltf::Material) -> Option<(crate::scene::Texture, u32)> {
        let (mut t, set) = texture::base_color_texture(m, &self.images)?;
        let opaque = m.alpha_mode() == gltf::material::AlphaMode::Opaque;
        if m.alpha_mode() == gltf::material::AlphaMode::Mask {
            // §3.9.4: drawn opaque where alpha ≥ alphaCutoff (default 0.5).
            t.alpha_cutoff = Some(m.alpha_cutoff().unwrap_or(0.5));
        }
        let img = self.scene.image(t.image)?;
        if opaque && img.has_alpha() {
            t.image = match self.opaque_images.get(&t.image) {
                Some(id) => *id,
                None => {
                    let base = img.base();
                    let px = base
                        .pixels()
                        .iter()
                        .map(|p| [p[0], p[1], p[2], 255])
                        .collect();
                    let comps = if img.components() == 2 { 1 } else { 3 };
                    let copy = Image::new(
                        img.name.clone(),
                        img.source.clone(),
                        base.width(),
                        base.height(),
                        comps,
                        px,
                    )
                    .ok()
                    .and_then(|c| self.scene.add_image(c).ok())?;
                    self.opaque_images.insert(t.image, copy);
                    copy
                }
            };
        }
        Some((t, set))
    }

    /// The mesh of one primitive (made once, shared by every node using it).
    fn primitive(
        &mut self,
        mesh: &gltf::Mesh,
        prim: &gltf::Primitive,
        weights: &[f32],
    ) -> Result<Option<Shape>> {
        let material = self.material(prim.material().index());
        let base = match prim.material().index() {
            Some(_) => {
                let c = prim.material().pbr_metallic_roughness().base_color_factor();
                Vec3::new(c[0], c[1], c[2])
            }
            None => Vec3::ONE,
        };
        // Primitives reading the same accessors the same way share one mesh
        // (what animed's writer makes of one mesh under several materials).
        let mut attrs: Vec<(String, usize)> = prim
            .attributes()
            .map(|(sem, acc)| (sem.to_string(), acc.index()))
            .collect();
        attrs.sort();
        let colored = prim.get(&gltf::Semantic::Colors(0)).is_some();
        // The TEXCOORD set of the material's textures, when one loaded.
        let uv_set = self.uv_sets.get(&material).copied();
        let key = format!(
            "{attrs:?} {:?} {:?} {} {:?} {:?} {:?} {uv_set:?}",
            prim.indices().map(|a| a.index()),
            prim.mode(),
            prim.material().double_sided(),
            colored.then(|| base.to_array().map(f32::to_bits)),
            prim.morph_targets()
                .map(|t| [t.positions(), t.normals()].map(|a| a.map(|a| a.index())))
                .collect::<Vec<_>>(),
            weights.iter().map(|w| w.to_bits()).collect::<Vec<_>>(),
        );
        let id = match self.meshes.get(&key) {
            Some(&id) => id,
            None => {
                let made = primitive_mesh(
                    mesh.index(),
                    prim,
                    self.buffers,
                    base,
                    uv_set,
                    weights,
                    &mut self.warnings,
                )?;
                let names = target_names(mesh);
                let id = made.map(|mut m| {
                    m.solid = !prim.material().double_sided();
                    m.name = mesh.name().unwrap_or_default().to_string();
                    if let Some(morph) = m.morph.as_mut() {
                        morph.set_names(&names);
                    }
                    self.scene.add_mesh(m)
                });
                self.meshes.insert(key, id);
                id
            }
        };
        Ok(id.map(|mesh| Shape { mesh, material }))
    }

    /// Makes the skins the loaded shapes use and binds them (after the
    /// tree, so every joint node exists).
    fn bind_skins(&mut self, doc: &gltf::Document) -> Result<()> {
        let skins: Vec<gltf::Skin> = doc.skins().collect();
        let mut made: HashMap<usize, crate::scene::SkinId> = HashMap::new();
        for (k, shape) in std::mem::take(&mut self.skinned) {
            let Some(gskin) = skins.get(k) else {
                return Err(GltfError::at("/skins", format!("no skin {k}")));
            };
            let id = match made.get(&k) {
                Some(&id) => id,
                None => {
                    let ids = &self.node_ids;
                    let skin = read_skin(gskin, self.buffers, &|i| ids.get(i).copied().flatten())?;
                    let id = self
                        .scene
                        .add_skin(skin)
                        .map_err(|e| GltfError::at(pointer(&[&"skins", &k]), e.to_string()))?;
                    made.insert(k, id);
                    id
                }
            };
            let joints = self.scene.skins[id.0 as usize].joints().len();
            if let NodeKind::Shape(s) = &self.scene.node(shape).kind {
                let span = self.scene.meshes[s.mesh.0 as usize]
                    .skin_weights
                    .as_ref()
                    .map_or(0, |w| w.joint_span());
                if span > joints {
                    return Err(GltfError::at(
                        pointer(&[&"skins", &k, &"joints"]),
                        format!(
                            "a vertex uses joint {} but the skin has {joints} joints",
                            span - 1
                        ),
                    ));
                }
            }
            self.scene.node_mut(shape).skin = Some(id);
        }
        Ok(())
    }

    /// Adds the node tree under `roots`, parents before children.
    fn build_tree(&mut self, roots: &[usize]) -> Result<()> {
        let mut stack: Vec<(usize, Option<NodeId>)> =
            roots.iter().rev().map(|&i| (i, None)).collect();
        let mut seen = vec![false; self.nodes.len()];
        while let Some((index, parent)) = stack.pop() {
            let Some(gnode) = self.nodes.get(index).cloned() else {
                return Err(GltfError::at("/scenes", format!("no node {index}")));
            };
            if std::mem::replace(&mut seen[index], true) {
                return Err(GltfError::at(
                    pointer(&[&"nodes", &index]),
                    "the node is reached twice: the node hierarchy must be a tree (spec §3.5.3)",
                ));
            }
            let part = self.part_child(&gnode);
            let id = self.add_node(&gnode, parent, part.as_ref())?;
            self.node_ids[index] = Some(id);
            for child in gnode.children().collect::<Vec<_>>().into_iter().rev() {
                if part.as_ref().is_some_and(|p| p.index() == child.index()) {
                    seen[child.index()] = true;
                    self.part_of[child.index()] = Some(id);
                    continue;
                }
                stack.push((child.index(), Some(id)));
            }
        }
        Ok(())
    }

    /// The placement child animed's writer gives a light or camera
    /// (`extras.animed = "part"`), when `g` has no content of its own.
    fn part_child(&self, g: &gltf::Node<'a>) -> Option<gltf::Node<'a>> {
        if g.mesh().is_some() || g.camera().is_some() || g.light().is_some() {
            return None;
        }
        g.children().find(|c| {
            c.children().next().is_none()
                && c.mesh().is_none()
                && (c.camera().is_some() != c.light().is_some())
                && matches!(c.transform(), gltf::scene::Transform::Decomposed { .. })
                && c.extras().as_ref().is_some_and(|e| {
                    serde_json::from_str::<serde_json::Value>(e.get())
                        .is_ok_and(|v| v.get("animed").and_then(|a| a.as_str()) == Some("part"))
                })
        })
    }

    fn add_node(
        &mut self,
        g: &gltf::Node,
        parent: Option<NodeId>,
        part: Option<&gltf::Node>,
    ) -> Result<NodeId> {
        let name = g.name().unwrap_or_default().to_string();
        let mut parts: Vec<NodeKind> = Vec::new();
        if let Some(mesh) = g.mesh() {
            // Node weights override the mesh's (§3.7.2.2).
            let weights: Vec<f32> = g
                .weights()
                .or_else(|| mesh.weights())
                .map(<[f32]>::to_vec)
                .unwrap_or_default();
            for prim in mesh.primitives() {
                if let Some(shape) = self.primitive(&mesh, &prim, &weights)? {
                    parts.push(NodeKind::Shape(shape));
                }
            }
        }
        if let Some(c) = g.camera() {
            parts.push(NodeKind::Camera(camera_from_gltf(&c)));
        }
        if let Some(l) = g.light() {
            parts.push(NodeKind::Light(light_of(&l, None)));
        }
        if let Some(p) = part {
            let (t, r) = match p.transform() {
                gltf::scene::Transform::Decomposed {
                    translation,
                    rotation,
                    ..
                } => (Vec3::from(translation), unit_quat(rotation)),
                _ => (Vec3::ZERO, Quat::IDENTITY),
            };
            if let Some(c) = p.camera() {
                let mut cam = camera_from_gltf(&c);
                cam.position = t;
                cam.orientation = r;
                parts.push(NodeKind::Camera(cam));
            }
            if let Some(l) = p.light() {
                parts.push(NodeKind::Light(light_of(&l, Some((t, r)))));
            }
        }
        let transform = node_transform(g);
        let light_index = g
            .light()
            .or_else(|| part.and_then(|p| p.light()))
            .map(|l| l.index());
        let camera_index = g
            .camera()
            .or_else(|| part.and_then(|p| p.camera()))
            .map(|c| c.index());
        let own = if parts.len() == 1 {
            parts.pop().unwrap_or(NodeKind::Group)
        } else {
            NodeKind::Group
        };
        let own_shape = matches!(own, NodeKind::Shape(_));
        let (own_light, own_camera) = (
            matches!(own, NodeKind::Light(_)),
            matches!(own, NodeKind::Camera(_)),
        );
        let id = self
            .scene
            .add_node(parent, Node::new(name, own).with_transform(transform));
        let skin = g.skin().map(|s| s.index());
        if let (Some(k), true) = (skin, own_shape) {
            self.skinned.push((k, id));
        }
        let mut place = |light: bool, camera: bool, at: NodeId| {
            if let (true, Some(l)) = (light, light_index) {
                self.lights.push((l, at));
            }
            if let (true, Some(c)) = (camera, camera_index) {
                self.cameras.push((c, at));
            }
        };
        place(own_light, own_camera, id);
        for kind in parts {
            let shape = matches!(kind, NodeKind::Shape(_));
            let (light, camera) = (
                matches!(kind, NodeKind::Light(_)),
                matches!(kind, NodeKind::Camera(_)),
            );
            let child = self.scene.add_node(Some(id), Node::new("", kind));
            place(light, camera, child);
            if let (Some(k), true) = (skin, shape) {
                self.skinned.push((k, child));
            }
        }
        Ok(id)
    }
}

/// A quaternion from glTF, normalised only when it is not unit already
/// (so values animed wrote read back bit for bit).
fn unit_quat(q: [f32; 4]) -> Quat {
    let q = Quat::from_array(q);
    if (q.length_squared() - 1.0).abs() <= 1e-6 {
        q
    } else {
        let l = q.length();
        if l > 1e-12 && l.is_finite() {
            q / l
        } else {
            Quat::IDENTITY
        }
    }
}

/// A light, exact from animed's extras when they still apply; `placement`
/// is the translation and rotation of the node animed placed it on.
fn light_of(l: &gltf::khr_lights_punctual::Light, placement: Option<(Vec3, Quat)>) -> Light {
    let read = Punctual::from_gltf(l);
    let mut light = light_from_extras(l, &read).unwrap_or_else(|| light_from_punctual(&read));
    if let Some((t, r)) = placement {
        light.location = t;
        light.direction = r * Vec3::NEG_Z;
        if let Some(d) = placed_direction(l, r) {
            light.direction = d;
        }
    }
    light
}

/// The exact direction animed wrote, when the rotation still encodes it.
fn placed_direction(l: &gltf::khr_lights_punctual::Light, r: Quat) -> Option<Vec3> {
    let raw = l.extras().as_ref()?;
    let v: serde_json::Value = serde_json::from_str(raw.get()).ok()?;
    let d: Vec<f32> = v
        .get("animed")?
        .get("direction")?
        .as_array()?
        .iter()
        .filter_map(|x| x.as_f64().map(|x| x as f32))
        .collect();
    let d = Vec3::new(*d.first()?, *d.get(1)?, *d.get(2)?);
    (Quat::from_rotation_arc(Vec3::NEG_Z, d.normalize_or(Vec3::NEG_Z)) == r).then_some(d)
}
