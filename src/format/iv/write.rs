//! The Open Inventor writer: `#Inventor V2.1 ascii` with engine-driven
//! animation, or `#Inventor V1.0 ascii` (still scene only) for readers that
//! know just 1.0 (view3dscene, VRML 1.0 tools).
//!
//! Layout (chosen so that reading the file back and writing it again gives
//! the same bytes): a node with a transform, children or hidden state is a
//! `Separator` holding `MatrixTransform`, `DEF NAME Transform`, then its
//! content and children; the name sits on the Transform because a reader
//! makes a DEF'd Transform the named group holding what follows it. A named
//! node whose first item is a light uses `TransformSeparator`, so the light
//! still reaches the rest of the scene; lights are written before their
//! siblings, since an Inventor light only lights what follows it. A plain
//! shape is `Separator { state… DEF NAME IndexedFaceSet }`. Equal point and
//! normal lists are shared (DEF/USE `_coords`, `_normals`). An unnamed
//! identity group around one such Separator is that Separator.
//!
//! Animation (2.1): one `Calculator`, fed by an `ElapsedTime` engine, turns
//! the time into a frame index `oa = floor(fmod(t·fps + 0.001, duration))`;
//! each animated field is connected to a `SelectOne` engine whose input
//! holds the field's value at every frame 0…duration (the played linear
//! curve of the VRML97 export, sampled per frame), so the animation steps at
//! the scene's frame rate and loops. Visibility plays as scale 0 and light
//! `on` as intensity 0, as in the VRML97 export.
//!
//! Lost in Inventor: Background colour, headlight setting, light
//! ambientIntensity/attenuation/radius, spot beamWidth, viewpoint
//! descriptions, VRML field-of-view-on-the-smaller-side (written as
//! heightAngle). Version 1.0 also loses all animation playback (no engines)
//! and vertex colours need a per-vertex Material. The key note (an `Info`
//! node) keeps every authored key, fps, duration, background and headlight.

use super::write_morph;
use crate::anim::{Property, TargetRef, Value};
use crate::format::export::channels::{channels, scene_diagonal, Channel};
use crate::format::export::keynote;
use crate::format::export::options::{ChannelReport, InventorVersion, WriteOptions, WriteReport};
use crate::format::export::plan::WritePlan;
use crate::format::export::sampling::{per_frame_keys, slerp_shortest, Sample, Tolerances};
use crate::format::export::text::{num, pivot_fields, quoted, rotation, rows, vec3, Out};
use crate::format::export::textures::image_field;
use crate::scene::{
    Camera, CameraKind, ImageSource, Light, LightKind, Material, Mesh, Morphs, NodeId, NodeKind,
    Scene, Shape, TextureModel, Transform, Wrap,
};
use glam::{Quat, Vec3};
use std::collections::HashMap;

struct Writer<'a> {
    scene: &'a Scene,
    plan: WritePlan,
    out: Out,
    v1: bool,
    channels: Vec<Channel>,
    clock: Option<FrameClock>,
    written_materials: Vec<bool>,
    /// Whether any material has a texture (then every shape states its own).
    textured_scene: bool,
    /// How many shapes use each set of points + normals.
    coord_uses: HashMap<Vec<u32>, usize>,
    /// DEF names of shared Coordinate3 / Normal nodes once written.
    coord_names: HashMap<Vec<u32>, (String, Option<String>)>,
    report: WriteReport,
}

/// Prints `scene` as an Inventor file of the version in `opts`.
pub fn write(scene: &Scene, opts: &WriteOptions) -> (String, WriteReport) {
    let v1 = opts.inventor_version == InventorVersion::V1_0;
    let tol = Tolerances::new(scene_diagonal(scene), opts.tolerance, opts.angle_tolerance);
    let duration = scene.settings.duration;
    let animate = !v1 && duration > 0.0 && scene.settings.fps > 0.0;
    let chans = if animate {
        channels(scene, &tol)
    } else {
        Vec::new()
    };
    let mut w = Writer {
        scene,
        plan: WritePlan::inventor(scene),
        out: Out::default(),
        v1,
        channels: chans,
        clock: None,
        written_materials: vec![false; scene.materials.len()],
        textured_scene: scene.materials.iter().any(|m| m.texture.is_some()),
        coord_uses: coord_uses(scene),
        coord_names: HashMap::new(),
        report: WriteReport::default(),
    };
    if !w.channels.is_empty() || (animate && morphs_animated(scene)) {
        w.clock = Some(FrameClock {
            name: w.plan.internal("_animed_clock"),
            defined: false,
            fps: scene.settings.fps,
            frames: duration.floor().max(1.0),
        });
    }
    if v1 {
        w.out.line("#Inventor V1.0 ascii");
    } else {
        w.out.line("#Inventor V2.1 ascii");
    }
    w.out.line("# Written by animed.");
    if v1 {
        w.out
            .line("# Inventor 1.0 has no engines: this file is the still scene; the");
        w.out
            .line("# animation is kept only in the animed key note (the Info node).");
        if !scene.animation.tracks.is_empty() {
            w.report
                .warnings
                .push("Inventor 1.0 cannot play animation: only the key note keeps it".into());
        }
        w.out.open("Separator");
    } else {
        w.out
            .line("# Animation: an ElapsedTime engine drives a Calculator that gives the");
        w.out
            .line("# frame index; each animated field is connected to a SelectOne engine");
        w.out
            .line("# holding its value at every frame (visibility = scale 0, light off =");
        w.out
            .line("# intensity 0). The authored keys are in the Info node (animed key note).");
    }
    for s in scene.info.iter().filter(|s| !keynote::is_note(s)) {
        w.out.line(&format!("Info {{ string {} }}", quoted(s)));
    }
    let note = keynote::write(scene, &w.plan);
    w.out.line(&format!("Info {{ string {} }}", quoted(&note)));
    environment(&mut w.out, scene.settings.ambient, v1);
    // Bare cameras first: an Inventor camera sets the view only of what
    // follows it (Coin drew warbird's shapes before its camera, through no
    // view at all); one inside a Separator (with a transform) sets nobody's,
    // and stays in place so the file reads back in the same order. Then
    // lights (and groups that start with one), as inside groups.
    let camera = |r: &NodeId| {
        matches!(scene.node(*r).kind, NodeKind::Camera(_)) && !w.plan.wrapped[r.0 as usize]
    };
    let mut roots: Vec<NodeId> = scene.roots.iter().copied().filter(camera).collect();
    roots.extend(
        scene
            .roots
            .iter()
            .copied()
            .filter(|r| !camera(r) && w.lightish(*r)),
    );
    roots.extend(
        scene
            .roots
            .iter()
            .copied()
            .filter(|r| !camera(r) && !w.lightish(*r)),
    );
    for id in roots {
        w.node(id);
    }
    if v1 {
        w.out.close("}");
    }
    if scene.settings.background != Vec3::ZERO || scene.settings.headlight.is_some() {
        w.report
            .warnings
            .push("Inventor has no background or headlight node: kept in the key note only".into());
    }
    w.report_channels();
    // VRML 1.0 has no DrawStyle: widths are lost there only.
    w.report
        .warnings
        .extend(crate::format::export::dropped::dropped_parts(scene, !v1));
    (w.out.text, w.report)
}

/// The grey `ambientColor` that reads back as `ambient_intensity` exactly:
/// readers take the channels' mean, and `(b + b + b) / 3` is not always `b`
/// in f32, so look a few ulps around for a `b` that gives `a` back.
fn ambient_grey(a: f32) -> f32 {
    let mean = |b: f32| (b + b + b) / 3.0;
    if !a.is_finite() || a <= 0.0 || mean(a) == a {
        return a;
    }
    (1..=8u32)
        .flat_map(|d| [a.to_bits() + d, a.to_bits() - d])
        .map(f32::from_bits)
        .find(|&b| mean(b) == a)
        .unwrap_or(a)
}

/// The identity of a mesh's Coordinate3 + Normal: their bits.
fn mesh_key(m: &Mesh) -> Vec<u32> {
    let mut k: Vec<u32> = m
        .positions
        .iter()
        .flat_map(|p| p.to_array())
        .map(f32::to_bits)
        .collect();
    k.push(u32::MAX);
    k.extend(
        m.normals
            .iter()
            .flat_map(|p| p.to_array())
            .map(f32::to_bits),
    );
    k
}

/// How many shape nodes use each mesh key.
fn coord_uses(scene: &Scene) -> HashMap<Vec<u32>, usize> {
    let mut uses = HashMap::new();
    for n in &scene.nodes {
        if let NodeKind::Shape(s) = &n.kind {
            if let Some(m) = scene.meshes.get(s.mesh.0 as usize) {
                *uses.entry(mesh_key(m)).or_insert(0) += 1;
            }
        }
    }
    uses
}

/// The frame index every animated field is selected by: an `ElapsedTime`
/// engine through a Calculator, DEF'd where it is first used.
struct FrameClock {
    name: String,
    defined: bool,
    fps: f32,
    /// Frames in one cycle (the index runs 0 ..= frames − 1).
    frames: f32,
}

impl FrameClock {
    /// The `index` line of a SelectOne playing one value per frame.
    fn index(&mut self, out: &mut Out) {
        let name = &self.name;
        if self.defined {
            out.line(&format!("index 0 = USE {name} .oa"));
            return;
        }
        self.defined = true;
        out.line(&format!("index 0 = DEF {name} Calculator {{"));
        out.depth += 1;
        out.line("a 0 = ElapsedTime { } .timeOut");
        out.line(&format!(
            "expression \"oa = floor(fmod(a * {} + 0.001, {}))\"",
            num(self.fps),
            num(self.frames)
        ));
        out.close("} .oa");
    }
}

/// Whether a weights track drives some morphed mesh (then the morph's
/// weights need the frame clock even when nothing else is animated).
fn morphs_animated(scene: &Scene) -> bool {
    let morphed = scene.meshes.iter().any(|m| m.morph.is_some());
    morphed
        && scene
            .animation
            .tracks
            .iter()
            .any(|t| t.target.property == Property::MorphWeights)
}

/// Inventor's global ambient when it is not the 0.2 grey every reader
/// (ours, Coin) assumes: an `Environment` (2.1 only) before the scene, so
/// a scene from a VRML97 file (no global ambient) stays as dark in Coin.
fn environment(out: &mut Out, ambient: Vec3, v1: bool) {
    if v1 || ambient == Vec3::splat(0.2) {
        return;
    }
    let grey = ambient.x == ambient.y && ambient.y == ambient.z;
    let (intensity, color) = if grey {
        (ambient.x, Vec3::ONE)
    } else {
        (1.0, ambient)
    };
    out.line(&format!(
        "Environment {{ ambientIntensity {} ambientColor {} }}",
        num(intensity),
        vec3(color)
    ));
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

/// The value a linear interpolator over `s` plays at `frame` (right-hand
/// value at a repeated key).
fn played_at(s: &[Sample], frame: f32) -> Value {
    let j = s.partition_point(|k| k.0 <= frame);
    if j == 0 {
        return s[0].1;
    }
    if j >= s.len() {
        return s[s.len() - 1].1;
    }
    let (a, b) = (s[j - 1], s[j]);
    let f = (frame - a.0) / (b.0 - a.0);
    match (a.1, b.1) {
        (Value::Scalar(x), Value::Scalar(y)) => Value::Scalar(x + (y - x) * f),
        (Value::Vec3(x), Value::Vec3(y)) => Value::Vec3(x.lerp(y, f)),
        (Value::Rotation(x), Value::Rotation(y)) => Value::Rotation(slerp_shortest(x, y, f)),
        _ => a.1,
    }
}

impl Writer<'_> {
    fn frames(&self) -> usize {
        // Frames 0 ..= floor(duration): what the Calculator's index reaches.
        self.scene.settings.duration.floor().max(0.0) as usize + 1
    }

    fn report_channels(&mut self) {
        let n = self.frames();
        for ch in &self.channels {
            let Some((_, name)) = self.plan.target_name(ch.of, ch.property) else {
                continue;
            };
            self.report.channels.push(ChannelReport {
                name: format!("{name}.{}", ch.property.name()),
                authored_keys: ch.authored_keys,
                written_keys: n,
                per_frame_keys: per_frame_keys(self.scene.settings.duration),
            });
        }
    }

    /// `field value` or, when a channel drives it, `field value = SelectOne {…} .output`.
    fn field(&mut self, of: TargetRef, property: Property, name: &str, value: &str) {
        let ch = self
            .channels
            .iter()
            .position(|c| c.of == of && c.property == property);
        let Some(ci) = ch else {
            self.out.line(&format!("{name} {value}"));
            return;
        };
        let (ty, items): (&str, Vec<String>) = {
            let ch = &self.channels[ci];
            let vals: Vec<Value> = (0..self.frames())
                .map(|f| played_at(&ch.samples, ch.local_frame(f as f32)))
                .collect();
            match vals[0] {
                Value::Rotation(_) => (
                    "MFRotation",
                    vals.iter()
                        .map(|v| match v {
                            Value::Rotation(q) => rotation(*q),
                            _ => rotation(Quat::IDENTITY),
                        })
                        .collect(),
                ),
                Value::Vec3(_) => (
                    if is_color(property) {
                        "MFColor"
                    } else {
                        "MFVec3f"
                    },
                    vals.iter()
                        .map(|v| match v {
                            Value::Vec3(x) => vec3(*x),
                            _ => vec3(Vec3::ZERO),
                        })
                        .collect(),
                ),
                _ => (
                    "MFFloat",
                    vals.iter()
                        .map(|v| match v {
                            Value::Scalar(x) => num(*x),
                            _ => num(0.0),
                        })
                        .collect(),
                ),
            }
        };
        self.out.line(&format!("{name} {value} = SelectOne {{"));
        self.out.depth += 1;
        self.out.line(&format!("type {ty}"));
        self.out.list("input", rows(&items, 4, |v| v.clone(), ","));
        if let Some(clock) = &mut self.clock {
            clock.index(&mut self.out);
        }
        self.out.close("} .output");
    }

    fn node(&mut self, id: NodeId) {
        let i = id.0 as usize;
        let node = self.scene.node(id);
        let hidden_v1 = self.v1 && !node.visible;
        if hidden_v1 {
            self.out.open("Switch");
            self.out.line("whichChild -1");
        }
        if self.collapsible(id) {
            // An unnamed identity group around one node that brings its own
            // Separator: that Separator is the group (a reader turns it back
            // into exactly this group), so writing both would nest deeper on
            // every round trip.
            self.node(node.children[0]);
        } else if !self.plan.wrapped[i] {
            match &node.kind {
                NodeKind::Shape(s) => {
                    self.out.open("Separator");
                    let name = self.plan.content[i].clone();
                    self.shape(id, s, &name);
                    self.out.close("}");
                }
                _ => self.content(id),
            }
        } else {
            // The node's own content reads back as its first child, so it
            // is ordered with the children (lights first) to keep the file
            // the same on every round trip. `None` stands for the content.
            let is_light = |c: Option<NodeId>| match c {
                Some(c) => self.lightish(c),
                None => matches!(node.kind, NodeKind::Light(_)),
            };
            let mut items: Vec<Option<NodeId>> = Vec::new();
            if !matches!(node.kind, NodeKind::Group) {
                items.push(None);
            }
            items.extend(node.children.iter().map(|&c| Some(c)));
            let mut sorted: Vec<Option<NodeId>> =
                items.iter().copied().filter(|c| is_light(*c)).collect();
            sorted.extend(items.iter().copied().filter(|c| !is_light(*c)));
            // An unnamed TransformSeparator leaves no node behind when read,
            // so only a named node (its DEF'd Transform becomes the group)
            // may use one; unnamed groups keep their lights inside.
            let light_first =
                self.plan.wrapper[i].is_some() && sorted.first().is_some_and(|c| is_light(*c));
            self.out.open(if light_first {
                "TransformSeparator"
            } else {
                "Separator"
            });
            if let Some(m) = node.transform.extra {
                let c = m.to_cols_array();
                self.out.open("MatrixTransform");
                self.out.list(
                    "matrix",
                    c.chunks(4)
                        .map(|r| format!("{} {} {} {}", num(r[0]), num(r[1]), num(r[2]), num(r[3])))
                        .collect::<Vec<_>>(),
                );
                self.out.close("}");
            }
            // The name goes on the Transform: readers make a DEF'd Transform
            // the named group that holds what follows it.
            let of = TargetRef::Node(id);
            let name = self.plan.wrapper[i].clone();
            if name.is_some() {
                self.out.open(&format!("{}Transform", def(&name)));
                self.transform_fields(of, &node.transform);
                self.out.close("}");
            }
            let alone = sorted.len() == 1;
            for item in sorted {
                match item {
                    None => match &node.kind {
                        NodeKind::Shape(s) if alone => self.shape(id, s, &None),
                        NodeKind::Shape(s) => {
                            self.out.open("Separator");
                            self.shape(id, s, &None);
                            self.out.close("}");
                        }
                        _ => self.content(id),
                    },
                    Some(c) => match &self.scene.node(c).kind {
                        NodeKind::Shape(s) if alone && self.is_plain_shape(c) => {
                            let name = self.plan.content[c.0 as usize].clone();
                            self.shape(c, s, &name)
                        }
                        _ => self.node(c),
                    },
                }
            }
            self.out.close("}");
        }
        if hidden_v1 {
            self.out.close("}");
        }
    }

    /// Whether `id` is written as a light or a `TransformSeparator` whose
    /// first item is one (such nodes go first among their siblings, so the
    /// light reaches them; a reader keeps that order).
    fn lightish(&self, id: NodeId) -> bool {
        let node = self.scene.node(id);
        match node.kind {
            NodeKind::Light(_) => true,
            _ if self.collapsible(id) => self.lightish(node.children[0]),
            _ if self.plan.wrapper[id.0 as usize].is_none() => false,
            _ if !self.plan.wrapped[id.0 as usize] => false,
            NodeKind::Group => node.children.iter().any(|&c| self.lightish(c)),
            // Content first unless a child is light-ish.
            _ => node.children.iter().any(|&c| self.lightish(c)),
        }
    }

    /// A shape node with nothing but its shape (written as a bare Separator
    /// with the shape state, or inline in a parent that holds only it).
    fn is_plain_shape(&self, id: NodeId) -> bool {
        matches!(self.scene.node(id).kind, NodeKind::Shape(_)) && !self.plan.wrapped[id.0 as usize]
    }

    /// See [`Writer::node`]: an unnamed, identity, un-animated, visible group
    /// with one child that writes its own `Separator`.
    fn collapsible(&self, id: NodeId) -> bool {
        let i = id.0 as usize;
        let node = self.scene.node(id);
        if !matches!(node.kind, NodeKind::Group)
            || self.plan.wrapper[i].is_some()
            || node.transform != Transform::default()
            || !node.visible
            || node.style != crate::scene::RenderStyle::Filled
            || node.children.len() != 1
            || self
                .scene
                .animation
                .tracks
                .iter()
                .any(|t| t.target.of == TargetRef::Node(id))
        {
            return false;
        }
        let c = node.children[0];
        let ci = c.0 as usize;
        let child = self.scene.node(c);
        if !self.plan.wrapped[ci] {
            return matches!(child.kind, NodeKind::Shape(_));
        }
        !self.lightish(c)
    }

    fn transform_fields(&mut self, of: TargetRef, t: &Transform) {
        let d = Transform::default();
        let anim = |w: &Self, p: Property| w.channels.iter().any(|c| c.of == of && c.property == p);
        if t.translation != d.translation || anim(self, Property::Translation) {
            self.field(
                of,
                Property::Translation,
                "translation",
                &vec3(t.translation),
            );
        }
        if t.rotation != d.rotation || anim(self, Property::Rotation) {
            self.field(of, Property::Rotation, "rotation", &rotation(t.rotation));
        }
        if t.scale != d.scale || anim(self, Property::Scale) {
            self.field(of, Property::Scale, "scaleFactor", &vec3(t.scale));
        }
        pivot_fields(&mut self.out, t);
    }

    fn content(&mut self, id: NodeId) {
        let i = id.0 as usize;
        let name = self.plan.content[i].clone();
        let node = self.scene.node(id);
        let of = TargetRef::Node(id);
        match &node.kind {
            NodeKind::Group => {}
            NodeKind::Shape(s) => self.shape(id, s, &None),
            NodeKind::Light(l) => {
                let force_on = self
                    .scene
                    .animation
                    .tracks
                    .iter()
                    .any(|t| t.target.of == of && t.target.property == Property::LightOn);
                self.light(of, &name, l, force_on)
            }
            NodeKind::Camera(c) => self.camera(of, &name, c),
        }
    }

    fn shape(&mut self, id: NodeId, s: &Shape, faces_name: &Option<String>) {
        let Some(mesh) = self.scene.meshes.get(s.mesh.0 as usize) else {
            self.report
                .warnings
                .push(format!("a shape refers to missing mesh {}", s.mesh.0));
            return;
        };
        self.material(s.material.0 as usize, mesh);
        let tex_coords = self.texture(s.material.0 as usize, mesh);
        if let Some(t) = super::write_text::writable(mesh).filter(|_| !self.v1) {
            super::write_text::write(&mut self.out, &def(faces_name), t);
            return;
        }
        let has_normals = !mesh.normals.is_empty() && mesh.normals.len() == mesh.positions.len();
        // Faces without normals, or with an unlit material (a VRML97 Shape
        // without Material), are drawn unlit (in their colours, else the
        // material's emissive colour): Inventor says so with LightModel
        // BASE_COLOR, whose base colour is the diffuse one (1.0 has no
        // LightModel: lit there).
        let unlit_material = self
            .scene
            .materials
            .get(s.material.0 as usize)
            .is_some_and(|m| m.unlit);
        let unlit =
            !self.v1 && !mesh.triangles.is_empty() && (mesh.normals.is_empty() || unlit_material);
        if unlit {
            self.out.line("LightModel { model BASE_COLOR }");
            if mesh.colors.len() != mesh.positions.len() {
                let base = self
                    .scene
                    .materials
                    .get(s.material.0 as usize)
                    .map_or(Vec3::ONE, |m| m.emissive);
                self.out
                    .line(&format!("BaseColor {{ rgb {} }}", vec3(base)));
            }
        }
        // DrawStyle's widths (Inventor 2.x; VRML 1.0 has no DrawStyle),
        // set back to the defaults after the shape like the LightModel.
        let node = self.scene.node(id);
        let widths = !self.v1 && (node.line_width != 0.0 || node.point_size != 0.0);
        if widths {
            self.out.line(&format!(
                "DrawStyle {{ lineWidth {} pointSize {} }}",
                num(node.line_width),
                num(node.point_size)
            ));
        }
        let key = mesh_key(mesh);
        let hints = if mesh.solid {
            "ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID }"
        } else {
            "ShapeHints { vertexOrdering COUNTERCLOCKWISE }"
        };
        let morphs = mesh.morph.as_deref().filter(|_| !self.v1);
        if let Some(morphs) = morphs {
            // Its own points, whatever else shares them: the engines move them.
            self.morph_coords(id, mesh, morphs, has_normals);
        } else if let Some((coords, normals)) = self.coord_names.get(&key).cloned() {
            // The same points (and normals) written before: share them.
            self.out.line(&format!("USE {coords}"));
            if let Some(n) = normals {
                self.out.line(&format!("USE {n}"));
                self.out.line("NormalBinding { value PER_VERTEX_INDEXED }");
            }
        } else {
            // Named only when another shape uses the same points: the names
            // then come from the geometry itself, so a re-read scene (which
            // may hold two copies of one mesh) writes the same file.
            let shared = self.coord_uses.get(&key).copied().unwrap_or(0) > 1;
            let coords = shared.then(|| self.plan.internal("_coords"));
            self.out.open(&format!("{}Coordinate3", def(&coords)));
            self.out
                .list("point", rows(&mesh.positions, 4, |v| vec3(*v), ","));
            self.out.close("}");
            let mut normals = None;
            if has_normals {
                normals = if shared {
                    Some(self.plan.internal("_normals"))
                } else {
                    None
                };
                self.out.open(&format!("{}Normal", def(&normals)));
                self.out
                    .list("vector", rows(&mesh.normals, 4, |v| vec3(*v), ","));
                self.out.close("}");
                self.out.line("NormalBinding { value PER_VERTEX_INDEXED }");
            }
            if let Some(c) = coords {
                self.coord_names.insert(key, (c, normals));
            }
        }
        self.out.line(hints);
        if mesh.triangles.is_empty() && mesh.lines.is_empty() && mesh.points.is_empty() {
            // An empty mesh stays a shape node (without a shape node the
            // Separator reads back as an empty group).
            self.out
                .line(&format!("{}IndexedFaceSet {{ }}", def(faces_name)));
        }
        if !mesh.triangles.is_empty() {
            self.out.open(&format!("{}IndexedFaceSet", def(faces_name)));
            self.out.list(
                "coordIndex",
                rows(
                    &mesh.triangles,
                    4,
                    |t| format!("{}, {}, {}, -1", t[0], t[1], t[2]),
                    ",",
                ),
            );
            if tex_coords && self.v1 {
                // 1.0 has no TextureCoordinateBinding: the coordinates are
                // bound through their own index (the same as coordIndex).
                self.out.list(
                    "textureCoordIndex",
                    rows(
                        &mesh.triangles,
                        4,
                        |t| format!("{}, {}, {}, -1", t[0], t[1], t[2]),
                        ",",
                    ),
                );
            }
            self.out.close("}");
        }
        if !mesh.lines.is_empty() {
            self.out.open("IndexedLineSet");
            self.out.list(
                "coordIndex",
                rows(&mesh.lines, 6, |l| format!("{}, {}, -1", l[0], l[1]), ","),
            );
            self.out.close("}");
        }
        if !mesh.points.is_empty() {
            let pts: Vec<Vec3> = mesh
                .points
                .iter()
                .filter_map(|&i| mesh.positions.get(i as usize).copied())
                .collect();
            self.out.open("Coordinate3");
            self.out.list("point", rows(&pts, 4, |v| vec3(*v), ","));
            self.out.close("}");
            self.out
                .line(&format!("PointSet {{ numPoints {} }}", pts.len()));
        }
        if unlit {
            self.out.line("LightModel { model PHONG }");
        }
        if widths {
            self.out.line("DrawStyle { lineWidth 0 pointSize 0 }");
        }
    }

    /// A morphed mesh's Coordinate3 (and Normal), connected from the
    /// Calculators that add its targets (`write_morph`).
    fn morph_coords(&mut self, id: NodeId, mesh: &Mesh, morphs: &Morphs, has_normals: bool) {
        let frames = if self.clock.is_some() {
            self.frames()
        } else {
            1
        };
        let plan = &mut self.plan;
        let mut name = || plan.internal("_animed_weight");
        let mut weights = write_morph::weights(self.scene, id, morphs, frames, &mut name);
        let offsets: Vec<&[Vec3]> = morphs.targets().iter().map(|t| t.positions()).collect();
        let (out, clock) = (&mut self.out, &mut self.clock);
        let mut index = |o: &mut Out| {
            if let Some(c) = clock.as_mut() {
                c.index(o);
            }
        };
        out.open("Coordinate3");
        write_morph::connected_field(
            out,
            "point",
            &mesh.positions,
            &offsets,
            &mut weights,
            &mut index,
        );
        out.close("}");
        if !has_normals {
            return;
        }
        out.open("Normal");
        if morphs.has_normal_deltas() {
            let zeros = vec![Vec3::ZERO; mesh.normals.len()];
            let offsets: Vec<&[Vec3]> = morphs
                .targets()
                .iter()
                .map(|t| {
                    if t.normals().is_empty() {
                        &zeros[..]
                    } else {
                        t.normals()
                    }
                })
                .collect();
            write_morph::connected_field(
                out,
                "vector",
                &mesh.normals,
                &offsets,
                &mut weights,
                &mut index,
            );
        } else {
            out.list("vector", rows(&mesh.normals, 4, |v| vec3(*v), ","));
        }
        out.close("}");
        out.line("NormalBinding { value PER_VERTEX_INDEXED }");
    }

    /// Texture state for one shape. Inventor's Texture2 is inherited by
    /// every later shape in the Separator and Texture2Transform accumulates,
    /// so in a scene with any texture each shape states its own (`Texture2 {}`
    /// switches texturing off), and the texture transform is baked into the
    /// shape's TextureCoordinate2 points instead of written as a node.
    /// True when it wrote texture coordinates for the shape's vertices.
    fn texture(&mut self, mi: usize, mesh: &Mesh) -> bool {
        if !self.textured_scene {
            return false;
        }
        let has_coords = !mesh.texcoords.is_empty() && mesh.texcoords.len() == mesh.positions.len();
        let tex = self
            .scene
            .materials
            .get(mi)
            .and_then(|m| m.texture.as_ref());
        let image = tex.and_then(|t| self.scene.image(t.image));
        let (Some(t), Some(image), true) = (tex, image, has_coords) else {
            self.out.line("Texture2 { }");
            return false;
        };
        self.out.open("Texture2");
        match &image.source {
            ImageSource::File { url, .. } => self.out.line(&format!("filename {}", quoted(url))),
            ImageSource::Inline => {
                image_field(&mut self.out, image);
            }
        }
        if t.wrap_s == Wrap::Clamp {
            self.out.line("wrapS CLAMP");
        }
        if t.wrap_t == Wrap::Clamp {
            self.out.line("wrapT CLAMP");
        }
        match t.model {
            // MODULATE multiplies the lit colour rather than the diffuse one:
            // the same picture but for specular highlights.
            TextureModel::Modulate | TextureModel::MultiplyDiffuse => {}
            TextureModel::Vrml97 => {
                let diffuse = self.scene.materials[mi].diffuse;
                if image.components() >= 3 && diffuse != Vec3::ONE {
                    self.report.warnings.push(format!(
                        "texture {:?}: VRML97 replaces the diffuse colour by an RGB texture; Inventor's MODULATE multiplies it",
                        image.name
                    ));
                }
            }
            TextureModel::Decal | TextureModel::Replace => self.out.line("model DECAL"),
            TextureModel::Blend => {
                self.out.line("model BLEND");
                self.out
                    .line(&format!("blendColor {}", vec3(t.blend_color)));
            }
        }
        self.out.close("}");
        let m = t.transform.matrix();
        let coords: Vec<glam::Vec2> = mesh
            .texcoords
            .iter()
            .map(|&c| m.transform_point2(c))
            .collect();
        self.out.open("TextureCoordinate2");
        self.out.list(
            "point",
            rows(&coords, 6, |c| format!("{} {}", num(c.x), num(c.y)), ","),
        );
        self.out.close("}");
        if !self.v1 {
            self.out
                .line("TextureCoordinateBinding { value PER_VERTEX_INDEXED }");
        }
        true
    }

    fn material(&mut self, mi: usize, mesh: &Mesh) {
        let Some(m) = self.scene.materials.get(mi) else {
            return;
        };
        let of = TargetRef::Material(crate::scene::MaterialId(mi as u32));
        let name = self.plan.materials[mi].clone();
        match (&name, self.written_materials[mi]) {
            (Some(n), true) => self.out.line(&format!("USE {n}")),
            _ => {
                self.written_materials[mi] = true;
                self.out.open(&format!("{}Material", def(&name)));
                self.material_fields(of, m);
                self.out.close("}");
            }
        }
        let colors = !mesh.colors.is_empty() && mesh.colors.len() == mesh.positions.len();
        if colors {
            if self.v1 {
                // 1.0 has no BaseColor: a second Material with per-vertex diffuse.
                self.out.open("Material");
                self.out
                    .list("diffuseColor", rows(&mesh.colors, 4, |v| vec3(*v), ","));
                self.out
                    .line(&format!("specularColor {}", vec3(m.specular)));
                self.out
                    .line(&format!("emissiveColor {}", vec3(m.emissive)));
                self.out.line(&format!("shininess {}", num(m.shininess)));
                self.out
                    .line(&format!("transparency {}", num(m.transparency)));
                self.out.close("}");
            } else {
                self.out.open("BaseColor");
                self.out
                    .list("rgb", rows(&mesh.colors, 4, |v| vec3(*v), ","));
                self.out.close("}");
            }
            self.out
                .line("MaterialBinding { value PER_VERTEX_INDEXED }");
        } else {
            self.out.line("MaterialBinding { value OVERALL }");
        }
    }

    fn material_fields(&mut self, of: TargetRef, m: &Material) {
        // Inventor's own ambient colour as read; a VRML97 material's
        // intensity as the grey that reads back as it.
        let a = m
            .ambient_color
            .unwrap_or_else(|| Vec3::splat(ambient_grey(m.ambient_intensity)));
        self.out.line(&format!("ambientColor {}", vec3(a)));
        self.field(of, Property::Diffuse, "diffuseColor", &vec3(m.diffuse));
        self.field(of, Property::Specular, "specularColor", &vec3(m.specular));
        self.field(of, Property::Emissive, "emissiveColor", &vec3(m.emissive));
        self.field(of, Property::Shininess, "shininess", &num(m.shininess));
        self.field(
            of,
            Property::Transparency,
            "transparency",
            &num(m.transparency),
        );
    }

    fn light(&mut self, of: TargetRef, name: &Option<String>, l: &Light, force_on: bool) {
        let kind = match l.kind {
            LightKind::Directional => "DirectionalLight",
            LightKind::Point => "PointLight",
            LightKind::Spot { .. } => "SpotLight",
        };
        self.out.open(&format!("{}{kind}", def(name)));
        self.out
            .line(&format!("on {}", bool_word(l.on || force_on)));
        self.field(of, Property::LightIntensity, "intensity", &num(l.intensity));
        self.field(of, Property::LightColor, "color", &vec3(l.color));
        if !matches!(l.kind, LightKind::Directional) {
            self.field(of, Property::LightLocation, "location", &vec3(l.location));
        }
        if !matches!(l.kind, LightKind::Point) {
            self.field(
                of,
                Property::LightDirection,
                "direction",
                &vec3(l.direction),
            );
        }
        if let LightKind::Spot {
            cut_off_angle,
            drop_off_rate,
            ..
        } = l.kind
        {
            self.field(
                of,
                Property::LightDropOff,
                "dropOffRate",
                &num(drop_off_rate),
            );
            self.field(
                of,
                Property::LightCutOff,
                "cutOffAngle",
                &num(cut_off_angle),
            );
        }
        self.out.close("}");
    }

    fn camera(&mut self, of: TargetRef, name: &Option<String>, c: &Camera) {
        let kind = match c.kind {
            CameraKind::Perspective { .. } => "PerspectiveCamera",
            CameraKind::Orthographic { .. } => "OrthographicCamera",
        };
        self.out.open(&format!("{}{kind}", def(name)));
        self.field(of, Property::CameraPosition, "position", &vec3(c.position));
        self.field(
            of,
            Property::CameraOrientation,
            "orientation",
            &rotation(c.orientation),
        );
        self.out
            .line(&format!("focalDistance {}", num(c.focal_distance)));
        match c.kind {
            CameraKind::Perspective { height_angle } => {
                self.field(of, Property::CameraFov, "heightAngle", &num(height_angle))
            }
            CameraKind::Orthographic { height } => {
                self.out.line(&format!("height {}", num(height)))
            }
        }
        self.out.close("}");
    }
}

fn is_color(p: Property) -> bool {
    matches!(
        p,
        Property::LightColor | Property::Diffuse | Property::Emissive | Property::Specular
    )
}
