//! The Open Inventor writer: `#Inventor V2.1 ascii` with engine-driven
//! animation, or `#Inventor V1.0 ascii` (still scene only) for readers that
//! know just 1.0 (view3dscene, VRML 1.0 tools).
//!
//! Layout: every scene node with a transform, children or a shape is a
//! `Separator` (lights: `TransformSeparator`, so the light still reaches the
//! rest of the scene) holding `MatrixTransform`, `DEF NAME Transform`, its
//! content, then its children. The node's name sits on the Transform, since
//! an Inventor reader makes a named Transform the group that carries it. Lights are written before their siblings, because an
//! Inventor light only lights what follows it.
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

use super::keynote;
use super::sampling::{per_frame_keys, slerp_shortest, Sample, Tolerances};
use super::save::{ChannelReport, InventorVersion, WriteOptions, WriteReport};
use super::write_anim::{channels, scene_diagonal, Channel};
use super::write_plan::WritePlan;
use super::write_text::{num, quoted, rotation, rows, vec3, Out};
use crate::anim::{Property, TargetRef, Value};
use crate::scene::{
    Camera, CameraKind, Light, LightKind, Material, Mesh, NodeId, NodeKind, Scene, Shape, Transform,
};
use glam::{Quat, Vec3};

struct Writer<'a> {
    scene: &'a Scene,
    plan: WritePlan,
    out: Out,
    v1: bool,
    channels: Vec<Channel>,
    clock: Option<String>,
    clock_defined: bool,
    written_materials: Vec<bool>,
    /// Names of a named mesh's Coordinate3, Normal and face set once written.
    written_meshes: Vec<Option<[Option<String>; 3]>>,
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
        clock_defined: false,
        written_materials: vec![false; scene.materials.len()],
        written_meshes: vec![None; scene.meshes.len()],
        report: WriteReport::default(),
    };
    if !w.channels.is_empty() {
        w.clock = Some(w.plan.internal("_animed_clock"));
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
    for id in lights_first(scene, &scene.roots) {
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
    (w.out.text, w.report)
}

/// `ids` with the light nodes moved to the front (stable otherwise).
fn lights_first(scene: &Scene, ids: &[NodeId]) -> Vec<NodeId> {
    let is_light = |id: &NodeId| matches!(scene.node(*id).kind, NodeKind::Light(_));
    let mut v: Vec<NodeId> = ids.iter().copied().filter(is_light).collect();
    v.extend(ids.iter().copied().filter(|id| !is_light(id)));
    v
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
                .map(|f| played_at(&ch.samples, f as f32))
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
        let clock = self.clock.clone().unwrap_or_default();
        self.out.line(&format!("{name} {value} = SelectOne {{"));
        self.out.depth += 1;
        self.out.line(&format!("type {ty}"));
        self.out.list("input", rows(&items, 4, |v| v.clone(), ","));
        if self.clock_defined {
            self.out.line(&format!("index 0 = USE {clock} .oa"));
        } else {
            self.clock_defined = true;
            let fps = self.scene.settings.fps;
            let d = self.scene.settings.duration.floor().max(1.0);
            self.out
                .line(&format!("index 0 = DEF {clock} Calculator {{"));
            self.out.depth += 1;
            self.out.line("a 0 = ElapsedTime { } .timeOut");
            self.out.line(&format!(
                "expression \"oa = floor(fmod(a * {} + 0.001, {}))\"",
                num(fps),
                num(d)
            ));
            self.out.close("} .oa");
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
        if !self.plan.wrapped[i] {
            self.content(id);
        } else {
            let group = if matches!(node.kind, NodeKind::Light(_)) {
                "TransformSeparator"
            } else {
                "Separator"
            };
            // The name goes on the Transform: readers make a DEF'd Transform
            // the named group that holds what follows it.
            self.out.open(group);
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
            let of = TargetRef::Node(id);
            let animated = [Property::Translation, Property::Rotation, Property::Scale]
                .iter()
                .any(|p| self.channels.iter().any(|c| c.of == of && c.property == *p));
            let t = node.transform;
            let name = self.plan.wrapper[i].clone();
            if name.is_some()
                || animated
                || (Transform { extra: None, ..t }) != Transform::default()
            {
                self.out.open(&format!("{}Transform", def(&name)));
                self.transform_fields(of, &t);
                self.out.close("}");
            }
            if !matches!(node.kind, NodeKind::Group) {
                self.content(id);
            }
            for c in lights_first(self.scene, &node.children) {
                self.node(c);
            }
            self.out.close("}");
        }
        if hidden_v1 {
            self.out.close("}");
        }
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
        if t.scale_orientation != d.scale_orientation {
            self.out.line(&format!(
                "scaleOrientation {}",
                rotation(t.scale_orientation)
            ));
        }
        if t.center != d.center {
            self.out.line(&format!("center {}", vec3(t.center)));
        }
    }

    fn content(&mut self, id: NodeId) {
        let i = id.0 as usize;
        let name = self.plan.content[i].clone();
        let node = self.scene.node(id);
        let of = TargetRef::Node(id);
        match &node.kind {
            NodeKind::Group => {}
            NodeKind::Shape(s) => self.shape(s),
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

    fn shape(&mut self, s: &Shape) {
        let Some(mesh) = self.scene.meshes.get(s.mesh.0 as usize) else {
            self.report
                .warnings
                .push(format!("a shape refers to missing mesh {}", s.mesh.0));
            return;
        };
        self.material(s.material.0 as usize, mesh);
        let mi = s.mesh.0 as usize;
        let has_normals = !mesh.normals.is_empty() && mesh.normals.len() == mesh.positions.len();
        let shared = self.written_meshes[mi].clone();
        let hints = if mesh.solid {
            "ShapeHints { vertexOrdering COUNTERCLOCKWISE shapeType SOLID }"
        } else {
            "ShapeHints { vertexOrdering COUNTERCLOCKWISE }"
        };
        if let Some([coords, normals, faces]) = shared {
            // A mesh written before under a name: share its nodes.
            if let Some(c) = coords {
                self.out.line(&format!("USE {c}"));
            }
            if let Some(n) = normals {
                self.out.line(&format!("USE {n}"));
                self.out.line("NormalBinding { value PER_VERTEX_INDEXED }");
            }
            self.out.line(hints);
            if let Some(f) = faces {
                self.out.line(&format!("USE {f}"));
            }
        } else {
            let base = self.plan.meshes[mi].clone();
            let sub = |w: &mut Self, suffix: &str| {
                base.as_ref()
                    .map(|b| w.plan.internal(&format!("{b}_{suffix}")))
            };
            let coords = sub(self, "coords");
            self.out.open(&format!("{}Coordinate3", def(&coords)));
            self.out
                .list("point", rows(&mesh.positions, 4, |v| vec3(*v), ","));
            self.out.close("}");
            let mut normals = None;
            if has_normals {
                normals = sub(self, "normals");
                self.out.open(&format!("{}Normal", def(&normals)));
                self.out
                    .list("vector", rows(&mesh.normals, 4, |v| vec3(*v), ","));
                self.out.close("}");
                self.out.line("NormalBinding { value PER_VERTEX_INDEXED }");
            }
            self.out.line(hints);
            if !mesh.triangles.is_empty() {
                self.out.open(&format!("{}IndexedFaceSet", def(&base)));
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
            if base.is_some() {
                let faces = if mesh.triangles.is_empty() {
                    None
                } else {
                    base
                };
                self.written_meshes[mi] = Some([coords, normals, faces]);
            }
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
        self.out.line(&format!(
            "ambientColor {}",
            vec3(m.diffuse * m.ambient_intensity)
        ));
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
