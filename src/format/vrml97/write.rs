//! The VRML97 writer (ISO/IEC 14772-1): the whole scene, its animation as
//! one looping TimeSensor driving linear interpolators through ROUTEs, and
//! the authored keys in a WorldInfo key note (see `keynote`).
//!
//! * Each scene node is a `Transform` (or just its content when the
//!   transform is the identity and nothing animates it; see `export::plan`).
//! * Shapes: `IndexedFaceSet` with per-vertex normals and colours,
//!   `IndexedLineSet`, `PointSet`, `Text` (`write_text`); shared meshes
//!   and materials are DEF/USE.
//! * The clock: `TimeSensor { cycleInterval = duration / fps, loop TRUE }`;
//!   key fractions are `frame / duration`. A track that loops with a period
//!   the duration is a whole multiple of gets a clock of its own
//!   (`cycleInterval = period / fps`) and one period of keys, so loops are
//!   not unrolled over the whole duration (`Channel::period`).
//! * Interpolators are sampled adaptively (`sampling`), visibility and light
//!   `on` are folded into scale and intensity (`export::channels`).
//! * Morphed and skinned shapes: their Coordinate and Normal are DEF'd and
//!   driven by a CoordinateInterpolator and a NormalInterpolator sampled
//!   from the poses (`write_morph`), so the deformation plays elsewhere.
//! * Not in VRML97, so kept only in the key note: spot `dropOffRate`,
//!   render styles, orthographic cameras (written as a Viewpoint).

use super::write_morph::{self, Deforming};
use crate::anim::{Keys, Property, TargetRef, Value};
use crate::format::export::channels::{channels, scene_diagonal, Channel};
use crate::format::export::keynote;
use crate::format::export::options::{ChannelReport, WriteOptions, WriteReport};
use crate::format::export::plan::WritePlan;
use crate::format::export::sampling::{per_frame_keys, Tolerances};
use crate::format::export::text::{num, pivot_fields, quoted, rotation, rows, vec3, Out};
use crate::format::export::textures::{image_field, transform_in};
use crate::format::export::vertex_order;
use crate::scene::{
    Camera, CameraKind, ImageSource, Light, LightKind, Material, Mesh, NodeId, NodeKind, Scene,
    Shape, TexTransformOrder, Texture, TextureModel, Transform, Wrap,
};
use glam::{Quat, Vec2, Vec3};

struct Writer<'a> {
    scene: &'a Scene,
    plan: WritePlan,
    out: Out,
    written_materials: Vec<bool>,
    written_meshes: Vec<bool>,
    /// Meshes that a shape with a texture uses. A reader keeps texture
    /// coordinates only under a texture, so writing them for an untextured
    /// mesh (a primitive's default mapping) would not survive a re-read and
    /// a second export would differ from the first.
    textured_meshes: Vec<bool>,
    report: WriteReport,
    /// Raw matrices that lost shear when written: how many, and the path
    /// of the first (warned once at the end, not once per node).
    lossy_matrices: (usize, Option<String>),
    /// Deforming shapes and the DEF names of their Coordinate and Normal,
    /// by mesh index.
    deforming: Vec<(Deforming, String, String)>,
    /// X3D 4.0 classic encoding: its header and profile, OrthoViewpoint.
    x3d: bool,
}

/// Prints `scene` as a VRML97 file.
pub fn write(scene: &Scene, opts: &WriteOptions) -> (String, WriteReport) {
    write_dialect(scene, opts, false)
}

/// Prints `scene` as an X3D 4.0 classic-encoding file: the same nodes,
/// sampling and key note, X3D's header, orthographic cameras as
/// OrthoViewpoint (`format::x3d::write` uses it for both X3D encodings).
pub fn write_x3d(scene: &Scene, opts: &WriteOptions) -> (String, WriteReport) {
    write_dialect(scene, opts, true)
}

fn write_dialect(scene: &Scene, opts: &WriteOptions, x3d: bool) -> (String, WriteReport) {
    let mut w = Writer {
        scene,
        plan: WritePlan::new(scene),
        out: Out::default(),
        written_materials: vec![false; scene.materials.len()],
        written_meshes: vec![false; scene.meshes.len()],
        textured_meshes: textured_meshes(scene),
        report: WriteReport::default(),
        lossy_matrices: (0, None),
        deforming: Vec::new(),
        x3d,
    };
    let (deforming, warnings) = write_morph::deforming(scene);
    w.report.warnings.extend(warnings);
    for d in deforming {
        let base = scene.node(d.node).name.clone();
        let base = if base.is_empty() {
            format!("shape{}", d.node.0)
        } else {
            base
        };
        let coord = w.plan.internal(&format!("{base}_coord"));
        let normal = w.plan.internal(&format!("{base}_normal"));
        w.deforming.push((d, coord, normal));
    }
    if x3d {
        w.out.line("#X3D V4.0 utf8");
        w.out.line("PROFILE Immersive");
    } else {
        w.out.line("#VRML V2.0 utf8");
    }
    w.out
        .line("# Written by animed. The animation plays from one looping TimeSensor");
    w.out
        .line("# through linear interpolators sampled from the authored curves; node");
    w.out
        .line("# visibility is played as scale 0, light on/off as intensity 0. The");
    w.out
        .line("# authored keys are in the WorldInfo below (the animed key note).");
    w.world_info();
    if let Some(h) = scene.settings.headlight {
        w.out.line(&format!(
            "NavigationInfo {{ headlight {} }}",
            if h { "TRUE" } else { "FALSE" }
        ));
    }
    w.out.line(&format!(
        "Background {{ skyColor [ {} ] }}",
        vec3(scene.settings.background)
    ));
    for &root in &scene.roots {
        w.node(root);
    }
    w.animation(opts);
    w.report
        .warnings
        .extend(crate::format::export::dropped::dropped_parts(scene, false));
    if let (n, Some(first)) = &w.lossy_matrices {
        w.report.warnings.push(format!(
            "{n} node(s) had a matrix with shear, written as translation/rotation/scale \
             (the shear is lost), first `{first}`"
        ));
    }
    (w.out.text, w.report)
}

/// Per mesh: whether a shape whose material has a texture uses it.
fn textured_meshes(scene: &Scene) -> Vec<bool> {
    let mut out = vec![false; scene.meshes.len()];
    for n in &scene.nodes {
        if let NodeKind::Shape(sh) = &n.kind {
            let textured = scene
                .materials
                .get(sh.material.0 as usize)
                .is_some_and(|m| m.texture.is_some());
            if let (true, Some(t)) = (textured, out.get_mut(sh.mesh.0 as usize)) {
                *t = true;
            }
        }
    }
    out
}

/// `Root/Arm/Hand`: the names from the root down (`#N` for unnamed nodes).
fn node_path(scene: &Scene, id: NodeId) -> String {
    let mut parts = Vec::new();
    let mut cur = Some(id);
    while let Some(c) = cur {
        let n = scene.node(c);
        parts.push(if n.name.is_empty() {
            format!("#{}", c.0)
        } else {
            n.name.clone()
        });
        cur = n.parent;
    }
    parts.reverse();
    parts.join("/")
}

fn def(name: &Option<String>) -> String {
    match name {
        Some(n) => format!("DEF {n} "),
        None => String::new(),
    }
}

fn bool_word(b: bool) -> &'static str {
    if b {
        "TRUE"
    } else {
        "FALSE"
    }
}

impl Writer<'_> {
    fn world_info(&mut self) {
        let note = keynote::write(self.scene, &self.plan);
        let mut strings: Vec<String> = self
            .scene
            .info
            .iter()
            .filter(|s| !keynote::is_note(s))
            .map(|s| quoted(s))
            .collect();
        strings.push(quoted(&note));
        self.out.open("WorldInfo");
        self.out.list("info", strings);
        self.out.close("}");
    }

    fn has_track(&self, id: NodeId, p: Property) -> bool {
        self.scene
            .animation
            .tracks
            .iter()
            .any(|t| t.target.of == TargetRef::Node(id) && t.target.property == p)
    }

    fn node(&mut self, id: NodeId) {
        let i = id.0 as usize;
        let node = self.scene.node(id);
        if !self.plan.wrapped[i] {
            self.content(id);
            return;
        }
        let mut closes = 0;
        let mut own = node.transform;
        // A raw matrix on a node with no transform of its own, not driven
        // by a track, becomes that node's Transform: no extra level (a
        // chain of Inventor Translations would otherwise nest twice as deep).
        let merged = match node.transform.extra {
            Some(m) if self.transform_is_free(id) => {
                let (s, r, t) = m.to_scale_rotation_translation();
                self.raw_matrix(id, &m);
                own = Transform {
                    translation: t,
                    rotation: r,
                    scale: s,
                    ..Default::default()
                };
                true
            }
            _ => false,
        };
        if let (Some(m), false) = (node.transform.extra, merged) {
            // VRML97 has no matrix node: an outer Transform with the
            // matrix's scale, rotation and translation (shear is lost).
            let (s, r, t) = m.to_scale_rotation_translation();
            self.raw_matrix(id, &m);
            self.out.open("Transform");
            self.transform_fields(&Transform {
                translation: t,
                rotation: r,
                scale: s,
                ..Default::default()
            });
            self.out.line("children [");
            self.out.depth += 1;
            closes += 1;
        }
        let head = format!("{}Transform", def(&self.plan.wrapper[i]));
        self.out.open(&head);
        self.transform_fields(&own);
        let has_content = !matches!(node.kind, NodeKind::Group);
        if has_content || !node.children.is_empty() {
            self.out.line("children [");
            self.out.depth += 1;
            if has_content {
                self.content(id);
            }
            for &c in &self.scene.node(id).children {
                self.node(c);
            }
            self.out.close("]");
        }
        self.out.close("}");
        for _ in 0..closes {
            self.out.close("]");
            self.out.close("}");
        }
    }

    /// Notes a raw matrix written as translation/rotation/scale if that
    /// loses something (shear).
    fn raw_matrix(&mut self, id: NodeId, m: &glam::Mat4) {
        let (s, r, t) = m.to_scale_rotation_translation();
        let back = glam::Mat4::from_scale_rotation_translation(s, r, t);
        let tol = 1e-4 * m.to_cols_array().iter().fold(1.0f32, |a, v| a.max(v.abs()));
        if !back.abs_diff_eq(*m, tol) {
            self.lossy_matrices.0 += 1;
            if self.lossy_matrices.1.is_none() {
                self.lossy_matrices.1 = Some(node_path(self.scene, id));
            }
        }
    }

    /// True if `id` has the default transform (besides a raw matrix) and
    /// no track drives its translation, rotation or scale.
    fn transform_is_free(&self, id: NodeId) -> bool {
        let t = &self.scene.node(id).transform;
        let d = Transform::default();
        t.translation == d.translation
            && t.rotation == d.rotation
            && t.scale == d.scale
            && t.scale_orientation == d.scale_orientation
            && t.center == d.center
            && ![Property::Translation, Property::Rotation, Property::Scale]
                .into_iter()
                .any(|p| self.has_track(id, p))
    }

    fn transform_fields(&mut self, t: &Transform) {
        let d = Transform::default();
        if t.translation != d.translation {
            self.out
                .line(&format!("translation {}", vec3(t.translation)));
        }
        if t.rotation != d.rotation {
            self.out.line(&format!("rotation {}", rotation(t.rotation)));
        }
        if t.scale != d.scale {
            self.out.line(&format!("scale {}", vec3(t.scale)));
        }
        pivot_fields(&mut self.out, t);
    }

    fn content(&mut self, id: NodeId) {
        let i = id.0 as usize;
        let name = self.plan.content[i].clone();
        let node = self.scene.node(id);
        match &node.kind {
            NodeKind::Group => {}
            NodeKind::Shape(s) => self.shape(&name, s),
            NodeKind::Light(l) => {
                let force_on = self.has_track(id, Property::LightOn);
                self.light(&name, l, force_on);
            }
            NodeKind::Camera(c) => self.viewpoint(&name, c, &node.name),
        }
    }

    fn shape(&mut self, name: &Option<String>, s: &Shape) {
        let Some(mesh) = self.scene.meshes.get(s.mesh.0 as usize) else {
            self.report
                .warnings
                .push(format!("a shape refers to missing mesh {}", s.mesh.0));
            return;
        };
        let parts = [
            !mesh.triangles.is_empty(),
            !mesh.lines.is_empty(),
            !mesh.points.is_empty(),
        ];
        let many = parts.iter().filter(|p| **p).count() > 1;
        if many {
            self.out.open(&format!("{}Group", def(name)));
            self.out.line("children [");
            self.out.depth += 1;
        }
        let mut kinds: Vec<usize> = (0..3).filter(|&k| parts[k]).collect();
        if kinds.is_empty() {
            kinds.push(0);
        }
        for (n, k) in kinds.into_iter().enumerate() {
            let head = if many {
                "Shape".to_string()
            } else {
                format!("{}Shape", def(name))
            };
            self.out.open(&head);
            self.appearance(s);
            match k {
                0 if !mesh.triangles.is_empty() => self.face_set(s, mesh, n == 0),
                1 => self.line_set(mesh),
                2 => self.point_set(mesh),
                // An empty mesh (a face set without faces, a PointSet without
                // points) stays a shape: a Shape without geometry reads back
                // as nothing, and the node would be lost.
                _ => self.out.line("geometry IndexedFaceSet { }"),
            }
            self.out.close("}");
        }
        if many {
            self.out.close("]");
            self.out.close("}");
        }
    }

    fn appearance(&mut self, s: &Shape) {
        let mi = s.material.0 as usize;
        let Some(m) = self.scene.materials.get(mi) else {
            return;
        };
        let name = self.plan.materials[mi].clone();
        // VRML97 draws a texture unlit exactly when the Appearance has no
        // Material (§4.14.3), so an unlit texture drops the Material unless
        // a track animates it.
        let animated = self
            .scene
            .animation
            .tracks
            .iter()
            .any(|t| t.target.of == TargetRef::Material(crate::scene::MaterialId(mi as u32)));
        // An unlit material (lighting off, §4.14.2) is an Appearance
        // without Material too — white, or the Color node's colours. An
        // unlit colour that is neither (glTF KHR_materials_unlit) keeps a
        // Material with only that emissive colour, which draws the same.
        let colored = self
            .scene
            .meshes
            .get(s.mesh.0 as usize)
            .is_some_and(|mesh| !mesh.colors.is_empty());
        let unlit_white = m.emissive == Vec3::ONE || colored || m.texture.is_some();
        let unlit = (m.unlit && unlit_white
            || m.texture
                .as_ref()
                .is_some_and(|t| t.model == TextureModel::Replace))
            && !animated;
        let reuse = name.is_some() && self.written_materials[mi];
        if reuse && m.texture.is_none() && !unlit {
            let n = name.as_deref().unwrap_or_default();
            self.out
                .line(&format!("appearance Appearance {{ material USE {n} }}"));
            return;
        }
        self.out.open("appearance Appearance");
        if unlit {
        } else if reuse {
            let n = name.as_deref().unwrap_or_default();
            self.out.line(&format!("material USE {n}"));
        } else {
            self.written_materials[mi] = true;
            self.out.open(&format!("material {}Material", def(&name)));
            material_fields(&mut self.out, m);
            self.out.close("}");
        }
        if let Some(t) = &m.texture {
            self.texture(t);
        }
        self.out.close("}");
    }

    fn texture(&mut self, t: &Texture) {
        let Some(image) = self.scene.image(t.image) else {
            self.report
                .warnings
                .push(format!("a material refers to missing image {}", t.image.0));
            return;
        };
        match &image.source {
            ImageSource::File { url, .. } => {
                self.out.open("texture ImageTexture");
                self.out.line(&format!("url {}", quoted(url)));
            }
            ImageSource::Inline => {
                self.out.open("texture PixelTexture");
                image_field(&mut self.out, image);
            }
        }
        if t.wrap_s == Wrap::Clamp {
            self.out.line("repeatS FALSE");
        }
        if t.wrap_t == Wrap::Clamp {
            self.out.line("repeatT FALSE");
        }
        self.out.close("}");
        if !t.transform.is_identity() {
            match transform_in(&t.transform, TexTransformOrder::Vrml97) {
                Some(x) => {
                    self.out.open("textureTransform TextureTransform");
                    if x.center != Vec2::ZERO {
                        self.out.line(&format!("center {} {}", num(x.center.x), num(x.center.y)));
                    }
                    if x.rotation != 0.0 {
                        self.out.line(&format!("rotation {}", num(x.rotation)));
                    }
                    if x.scale != Vec2::ONE {
                        self.out.line(&format!("scale {} {}", num(x.scale.x), num(x.scale.y)));
                    }
                    if x.translation != Vec2::ZERO {
                        self.out.line(&format!(
                            "translation {} {}",
                            num(x.translation.x),
                            num(x.translation.y)
                        ));
                    }
                    self.out.close("}");
                }
                None => self.report.warnings.push(format!(
                    "texture {:?}: a rotated, non-uniformly scaled Inventor texture transform has no VRML97 form; written without it",
                    image.name
                )),
            }
        }
        if t.model == TextureModel::MultiplyDiffuse && image.components() >= 3 {
            self.report.warnings.push(format!(
                "texture {:?}: VRML97 replaces the diffuse colour by an RGB texture instead of multiplying it",
                image.name
            ));
        }
        if matches!(
            t.model,
            TextureModel::Modulate | TextureModel::Decal | TextureModel::Blend
        ) {
            self.report.warnings.push(format!(
                "texture {:?}: Inventor's {:?} model has no VRML97 form; VRML97 lights the texture by its own rule",
                image.name, t.model
            ));
        }
    }

    fn face_set(&mut self, s: &Shape, mesh: &Mesh, can_def: bool) {
        let mi = s.mesh.0 as usize;
        let name = if can_def {
            self.plan.meshes[mi].clone()
        } else {
            None
        };
        if let (Some(n), true) = (&name, self.written_meshes[mi]) {
            self.out.line(&format!("geometry USE {n}"));
            return;
        }
        if can_def {
            self.written_meshes[mi] = true;
        }
        if let Some(t) = super::write_text::writable(mesh) {
            super::write_text::write(&mut self.out, &def(&name), t);
            return;
        }
        let morph = self
            .deforming
            .iter()
            .find(|(d, _, _)| d.mesh.0 as usize == mi)
            .map(|(_, c, n)| (c.clone(), n.clone()));
        // Vertices as a reader numbers them (not for a deforming mesh: its
        // interpolators' values follow the mesh's own order).
        let ordered = match morph {
            None => vertex_order::first_use_order(mesh),
            Some(_) => None,
        };
        let mesh = ordered.as_ref().unwrap_or(mesh);
        self.out
            .open(&format!("geometry {}IndexedFaceSet", def(&name)));
        if !mesh.solid {
            self.out.line("solid FALSE");
        }
        match &morph {
            Some((c, _)) => {
                self.out.open(&format!("coord DEF {c} Coordinate"));
                self.out
                    .list("point", rows(&mesh.positions, 4, |v| vec3(*v), ","));
                self.out.close("}");
            }
            None => self.coords(&mesh.positions),
        }
        if !mesh.normals.is_empty() && mesh.normals.len() == mesh.positions.len() {
            match &morph {
                Some((_, n)) => self.out.open(&format!("normal DEF {n} Normal")),
                None => self.out.open("normal Normal"),
            }
            self.out
                .list("vector", rows(&mesh.normals, 4, |v| vec3(*v), ","));
            self.out.close("}");
        }
        self.colors(mesh);
        if !mesh.texcoords.is_empty()
            && mesh.texcoords.len() == mesh.positions.len()
            && self.textured_meshes.get(mi).copied().unwrap_or(false)
        {
            // No texCoordIndex: coordIndex then indexes the coordinates too.
            self.out.open("texCoord TextureCoordinate");
            self.out.list(
                "point",
                rows(
                    &mesh.texcoords,
                    6,
                    |t| format!("{} {}", num(t.x), num(t.y)),
                    ",",
                ),
            );
            self.out.close("}");
        }
        self.out.list(
            "coordIndex",
            rows(
                &mesh.triangles,
                4,
                |t| format!("{}, {}, {}, -1", t[0], t[1], t[2]),
                ",",
            ),
        );
        self.out.close("}");
    }

    fn line_set(&mut self, mesh: &Mesh) {
        self.out.open("geometry IndexedLineSet");
        self.coords(&mesh.positions);
        self.colors(mesh);
        self.out.list(
            "coordIndex",
            rows(&mesh.lines, 6, |l| format!("{}, {}, -1", l[0], l[1]), ","),
        );
        self.out.close("}");
    }

    fn point_set(&mut self, mesh: &Mesh) {
        let pick = |v: &[Vec3]| -> Vec<Vec3> {
            mesh.points
                .iter()
                .filter_map(|&i| v.get(i as usize).copied())
                .collect()
        };
        self.out.open("geometry PointSet");
        self.coords(&pick(&mesh.positions));
        if !mesh.colors.is_empty() {
            self.out.open("color Color");
            self.out
                .list("color", rows(&pick(&mesh.colors), 4, |v| vec3(*v), ","));
            self.out.close("}");
        }
        self.out.close("}");
    }

    fn coords(&mut self, p: &[Vec3]) {
        self.out.open("coord Coordinate");
        self.out.list("point", rows(p, 4, |v| vec3(*v), ","));
        self.out.close("}");
    }

    fn colors(&mut self, mesh: &Mesh) {
        if !mesh.colors.is_empty() && mesh.colors.len() == mesh.positions.len() {
            self.out.open("color Color");
            self.out
                .list("color", rows(&mesh.colors, 4, |v| vec3(*v), ","));
            self.out.close("}");
        }
    }

    fn light(&mut self, name: &Option<String>, l: &Light, force_on: bool) {
        let kind = match l.kind {
            LightKind::Directional => "DirectionalLight",
            LightKind::Point => "PointLight",
            LightKind::Spot { .. } => "SpotLight",
        };
        self.out.open(&format!("{}{kind}", def(name)));
        self.out
            .line(&format!("on {}", bool_word(l.on || force_on)));
        self.out.line(&format!("intensity {}", num(l.intensity)));
        self.out
            .line(&format!("ambientIntensity {}", num(l.ambient_intensity)));
        self.out.line(&format!("color {}", vec3(l.color)));
        if !matches!(l.kind, LightKind::Directional) {
            self.out.line(&format!("location {}", vec3(l.location)));
        }
        if !matches!(l.kind, LightKind::Point) {
            self.out.line(&format!("direction {}", vec3(l.direction)));
        }
        if !matches!(l.kind, LightKind::Directional) {
            self.out
                .line(&format!("attenuation {}", vec3(l.attenuation)));
            self.out.line(&format!("radius {}", num(l.radius)));
        }
        if let LightKind::Spot {
            beam_width,
            cut_off_angle,
            drop_off_rate,
        } = l.kind
        {
            self.out.line(&format!("beamWidth {}", num(beam_width)));
            self.out
                .line(&format!("cutOffAngle {}", num(cut_off_angle)));
            if drop_off_rate != 0.0 {
                self.report.warnings.push(format!(
                    "spot light {}: dropOffRate {} has no VRML97 field (other viewers use beamWidth)",
                    name.as_deref().unwrap_or("(unnamed)"),
                    drop_off_rate
                ));
            }
        }
        self.out.close("}");
    }

    fn viewpoint(&mut self, name: &Option<String>, c: &Camera, node_name: &str) {
        if let (true, &CameraKind::Orthographic { height }) = (self.x3d, &c.kind) {
            // X3D OrthoViewpoint: the view rectangle, its height the camera's.
            let h = num(height / 2.0);
            let m = num(-height / 2.0);
            self.out.open(&format!("{}OrthoViewpoint", def(name)));
            self.out.line(&format!("position {}", vec3(c.position)));
            self.out
                .line(&format!("orientation {}", rotation(c.orientation)));
            self.out.line(&format!("fieldOfView [ {m} {m} {h} {h} ]"));
            if !c.description.is_empty() {
                self.out
                    .line(&format!("description {}", quoted(&c.description)));
            }
            self.out.close("}");
            return;
        }
        self.out.open(&format!("{}Viewpoint", def(name)));
        self.out.line(&format!("position {}", vec3(c.position)));
        self.out
            .line(&format!("orientation {}", rotation(c.orientation)));
        match c.kind {
            CameraKind::Perspective { height_angle } => {
                self.out.line(&format!("fieldOfView {}", num(height_angle)));
            }
            CameraKind::Orthographic { .. } => self.report.warnings.push(format!(
                "camera `{node_name}` is orthographic; VRML97 has only perspective viewpoints"
            )),
        }
        if !c.description.is_empty() {
            self.out
                .line(&format!("description {}", quoted(&c.description)));
        }
        self.out.close("}");
    }

    fn animation(&mut self, opts: &WriteOptions) {
        let scene = self.scene;
        let duration = scene.settings.duration;
        let fps = scene.settings.fps;
        if scene.animation.tracks.is_empty() && !scene.nodes.iter().any(|n| !n.visible) {
            return;
        }
        let tol = Tolerances::new(scene_diagonal(scene), opts.tolerance, opts.angle_tolerance);
        let chans = channels(scene, &tol);
        if chans.is_empty() && self.deforming.is_empty() {
            return;
        }
        if !(duration > 0.0 && fps > 0.0) {
            self.report.warnings.push(
                "duration or fps is not positive: no interpolators written (keys are in the note)"
                    .into(),
            );
            return;
        }
        let clock = self.plan.internal("_animed_clock");
        self.out.line(&format!(
            "DEF {clock} TimeSensor {{ cycleInterval {} loop TRUE }}",
            num(duration / fps)
        ));
        let mut routes = Vec::new();
        // Channels of loops played by a clock of their own, one per period.
        let mut loop_clocks: Vec<(u32, String)> = Vec::new();
        for ch in &chans {
            let Some(field) = self.route_field(ch) else {
                continue;
            };
            let Some((_, target)) = self.plan.target_name(ch.of, ch.property) else {
                continue;
            };
            let target = target.to_string();
            if self.x3d && opts.x3d_splines && self.spline(ch, &target, field, &clock, &mut routes)
            {
                continue;
            }
            let (kind, values): (&str, Vec<String>) = match ch.samples[0].1 {
                Value::Rotation(_) => (
                    "OrientationInterpolator",
                    ch.samples
                        .iter()
                        .map(|s| match s.1 {
                            Value::Rotation(q) => rotation(q),
                            _ => rotation(Quat::IDENTITY),
                        })
                        .collect(),
                ),
                Value::Vec3(_) => (
                    if is_color(ch.property) {
                        "ColorInterpolator"
                    } else {
                        "PositionInterpolator"
                    },
                    ch.samples
                        .iter()
                        .map(|s| match s.1 {
                            Value::Vec3(v) => vec3(v),
                            _ => vec3(Vec3::ZERO),
                        })
                        .collect(),
                ),
                Value::Scalar(_) => (
                    "ScalarInterpolator",
                    ch.samples
                        .iter()
                        .map(|s| match s.1 {
                            Value::Scalar(x) => num(x),
                            _ => num(0.0),
                        })
                        .collect(),
                ),
                Value::Bool(_) | Value::Weights(_) => continue,
            };
            let (span, clock) = match ch.period {
                Some(p) => {
                    let known = loop_clocks.iter().find(|(b, _)| *b == p.to_bits());
                    let name = match known {
                        Some((_, n)) => n.clone(),
                        None => {
                            let n = self.plan.internal("_animed_loop_clock");
                            self.out.line(&format!(
                                "DEF {n} TimeSensor {{ cycleInterval {} loop TRUE }}",
                                num(p / fps)
                            ));
                            loop_clocks.push((p.to_bits(), n.clone()));
                            n
                        }
                    };
                    (p, name)
                }
                None => (duration, clock.clone()),
            };
            let interp = self.plan.internal(&format!("{target}_{field}"));
            let keys: Vec<f32> = ch.samples.iter().map(|s| s.0 / span).collect();
            let values = rows(&values, 4, |v| v.clone(), ",");
            let ends = (clock.as_str(), target.as_str(), field);
            self.interpolator(kind, &interp, &keys, values, ends, &mut routes);
            self.report.channels.push(ChannelReport {
                name: format!("{target}.{field}"),
                authored_keys: ch.authored_keys,
                written_keys: ch.samples.len(),
                per_frame_keys: per_frame_keys(duration),
            });
        }
        for (d, coord, normal) in self.deforming.clone() {
            // The position rule, but against the shape's own size too: a
            // small flapping wing in a large world must still flap.
            let size = scene.meshes[d.mesh.0 as usize]
                .bounds()
                .map_or(0.0, |(lo, hi)| (hi - lo).length());
            let s = write_morph::sample(scene, d, tol.distance.min(tol.relative * size));
            let keys: Vec<f32> = s.frames.iter().map(|f| f / duration).collect();
            let base = coord.trim_end_matches("_coord").to_string();
            for (kind, values, target, field) in [
                ("CoordinateInterpolator", &s.positions, &coord, "point"),
                ("NormalInterpolator", &s.normals, &normal, "vector"),
            ] {
                if values.iter().any(|v| v.is_empty()) {
                    continue;
                }
                let interp = self.plan.internal(&format!("{base}_{field}_morph"));
                let flat: Vec<Vec3> = values.iter().flatten().copied().collect();
                let values = rows(&flat, 4, |v| vec3(*v), ",");
                let ends = (clock.as_str(), target.as_str(), field);
                self.interpolator(kind, &interp, &keys, values, ends, &mut routes);
            }
            self.report.channels.push(ChannelReport {
                name: format!("{coord}.point"),
                authored_keys: s.candidates,
                written_keys: s.frames.len(),
                per_frame_keys: per_frame_keys(duration),
            });
        }
        for r in routes {
            self.out.line(&r);
        }
    }

    /// `DEF interp kind { key … keyValue … }` and the two routes that play
    /// it: `ends` = (the clock, the target node, the target's field).
    fn interpolator(
        &mut self,
        kind: &str,
        interp: &str,
        keys: &[f32],
        values: Vec<String>,
        (clock, target, field): (&str, &str, &str),
        routes: &mut Vec<String>,
    ) {
        self.out.open(&format!("DEF {interp} {kind}"));
        self.out.list("key", rows(keys, 8, |k| num(*k), ","));
        self.out.list("keyValue", values);
        self.out.close("}");
        routes.push(format!(
            "ROUTE {clock}.fraction_changed TO {interp}.set_fraction"
        ));
        routes.push(format!(
            "ROUTE {interp}.value_changed TO {target}.set_{field}"
        ));
    }

    /// The VRML97 field a channel drives, or `None` (with a warning) when
    /// the target has no such field.
    /// X3D: a channel whose one track X3D's Spline*/Squad interpolator
    /// plays exactly (`x3d::spline_keys`) is written as that node with the
    /// track's own keys; false when it is sampled instead.
    fn spline(
        &mut self,
        ch: &Channel,
        target: &str,
        field: &str,
        clock: &str,
        routes: &mut Vec<String>,
    ) -> bool {
        let scene = self.scene;
        let duration = scene.settings.duration;
        // Scale also carries visibility, intensity `on`: those stay sampled.
        let merged = |p: Property| match ch.property {
            Property::Scale => p == Property::Visibility,
            Property::LightIntensity => p == Property::LightOn,
            _ => false,
        };
        let own: Vec<&crate::anim::Track> = scene
            .animation
            .tracks
            .iter()
            .filter(|t| t.target.of == ch.of)
            .filter(|t| t.target.property == ch.property || merged(t.target.property))
            .collect();
        let [track] = own.as_slice() else {
            return false;
        };
        if track.target.property != ch.property {
            return false;
        }
        let Some(kind) = crate::format::x3d::spline_keys::exact_node(track, duration) else {
            return false;
        };
        let (frames, values): (Vec<f32>, Vec<String>) = match &track.keys {
            Keys::Scalar(k) => k.iter().map(|k| (k.frame, num(k.value))).unzip(),
            Keys::Vec3(k) => k.iter().map(|k| (k.frame, vec3(k.value))).unzip(),
            Keys::Rotation(k) => k.iter().map(|k| (k.frame, rotation(k.value))).unzip(),
            _ => return false,
        };
        let interp = self.plan.internal(&format!("{target}_{field}"));
        let keys: Vec<f32> = frames.iter().map(|f| f / duration).collect();
        let values = rows(&values, 4, |v| v.clone(), ",");
        self.interpolator(kind, &interp, &keys, values, (clock, target, field), routes);
        self.report.channels.push(ChannelReport {
            name: format!("{target}.{field} ({kind}, exact)"),
            authored_keys: ch.authored_keys,
            written_keys: frames.len(),
            per_frame_keys: per_frame_keys(duration),
        });
        true
    }

    fn route_field(&mut self, ch: &Channel) -> Option<&'static str> {
        let kind = match ch.of {
            TargetRef::Node(id) => Some(&self.scene.node(id).kind),
            TargetRef::Material(_) => None,
        };
        let spot = matches!(
            kind,
            Some(NodeKind::Light(Light {
                kind: LightKind::Spot { .. },
                ..
            }))
        );
        let light = matches!(kind, Some(NodeKind::Light(_)));
        let directional = matches!(
            kind,
            Some(NodeKind::Light(Light {
                kind: LightKind::Directional,
                ..
            }))
        );
        let point = matches!(
            kind,
            Some(NodeKind::Light(Light {
                kind: LightKind::Point,
                ..
            }))
        );
        let perspective = matches!(
            kind,
            Some(NodeKind::Camera(Camera {
                kind: CameraKind::Perspective { .. },
                ..
            }))
        );
        let camera = matches!(kind, Some(NodeKind::Camera(_)));
        let f = match ch.property {
            Property::Translation => Some("translation"),
            Property::Rotation => Some("rotation"),
            Property::Scale => Some("scale"),
            Property::LightIntensity if light => Some("intensity"),
            Property::LightColor if light => Some("color"),
            Property::LightLocation if light && !directional => Some("location"),
            Property::LightDirection if light && !point => Some("direction"),
            Property::LightCutOff if spot => Some("cutOffAngle"),
            Property::LightBeamWidth if spot => Some("beamWidth"),
            Property::CameraPosition if camera => Some("position"),
            Property::CameraOrientation if camera => Some("orientation"),
            Property::CameraFov if perspective => Some("fieldOfView"),
            Property::Diffuse => Some("diffuseColor"),
            Property::Emissive => Some("emissiveColor"),
            Property::Specular => Some("specularColor"),
            Property::Transparency => Some("transparency"),
            Property::Shininess => Some("shininess"),
            _ => None,
        };
        // Morph weights play through the CoordinateInterpolator instead.
        if f.is_none() && ch.property != Property::MorphWeights {
            let who = self
                .plan
                .target_name(ch.of, ch.property)
                .map_or("(unnamed)".to_string(), |(_, n)| n.to_string());
            self.report.warnings.push(format!(
                "{who}.{}: no VRML97 field plays it (kept in the key note only)",
                ch.property.name()
            ));
        }
        f
    }
}

fn is_color(p: Property) -> bool {
    matches!(
        p,
        Property::LightColor | Property::Diffuse | Property::Emissive | Property::Specular
    )
}

fn material_fields(out: &mut Out, m: &Material) {
    out.line(&format!("diffuseColor {}", vec3(m.diffuse)));
    out.line(&format!("ambientIntensity {}", num(m.ambient_intensity)));
    out.line(&format!("specularColor {}", vec3(m.specular)));
    out.line(&format!("emissiveColor {}", vec3(m.emissive)));
    out.line(&format!("shininess {}", num(m.shininess)));
    out.line(&format!("transparency {}", num(m.transparency)));
}
