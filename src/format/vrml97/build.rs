//! Turns the parsed VRML97 node tree into the scene tree: grouping nodes,
//! shapes (with shared meshes and materials), lights, viewpoints and the
//! world settings (NavigationInfo, Background, WorldInfo).

use super::{animation, geometry, hanim};
use crate::format::build_log::BuildLog;
use crate::format::inline;
use crate::format::lexer::Pos;
use crate::format::limits::{self, LimitError};
use crate::format::syntax::{AstNode, NodeRef, Parsed};
use crate::format::textures;
use crate::format::LoadError;
use crate::format::Loaded;
use crate::scene::{
    Camera, CameraKind, ImageId, Light, LightKind, Material, MaterialId, MeshId, Node, NodeId,
    NodeKind, Scene, Shape, Texture, Transform,
};
use glam::{Quat, Vec3};
use std::collections::HashMap;
use std::path::Path;
use std::rc::Rc;

/// Deepest scene tree built: the parser already bounds the expanded
/// depth by the input budget, whose largest setting this is.
const MAX_BUILD_DEPTH: usize = limits::DEPTH_CEILING as usize;

/// Nodes that are read but do nothing in animed (warned once per type).
const IGNORED: &[&str] = &[
    "TouchSensor",
    "PlaneSensor",
    "SphereSensor",
    "CylinderSensor",
    "ProximitySensor",
    "VisibilitySensor",
    "Sound",
    "AudioClip",
    "Fog",
    "FontStyle",
];

pub struct Builder {
    /// Warnings and the first input limit passed (shared with the
    /// Inventor builder).
    pub(super) log: BuildLog,
    depth: usize,
    pub(super) scene: Scene,
    /// Scene nodes made from each AST node (several when USEd).
    pub(super) instances: HashMap<*const AstNode, Vec<NodeId>>,
    pub(super) materials: HashMap<*const AstNode, MaterialId>,
    /// Textured materials per Appearance node.
    textured_materials: HashMap<*const AstNode, MaterialId>,
    /// Textured copies of each Material node (animation drives them too).
    pub(super) material_copies: HashMap<*const AstNode, Vec<MaterialId>>,
    /// Each texture node's image (`None`: it did not load).
    pub(super) texture_images: HashMap<*const AstNode, Option<ImageId>>,
    pub(super) loader: textures::Loader,
    /// Meshes per geometry node, with and without texture coordinates.
    meshes: HashMap<(*const AstNode, bool), Option<MeshId>>,
    /// IndexedFaceSets (and whether textured, and their mesh) per
    /// Coordinate node: what a CoordinateInterpolator on it morphs.
    pub(super) coord_users: HashMap<*const AstNode, Vec<(NodeRef, bool, MeshId)>>,
    unlit: Option<MaterialId>,
    saw_navigation: bool,
    saw_background: bool,
    build_depth: usize,
    inlines: inline::Cache,
    /// Non-zero while adding a Switch choice that is not shown: its shapes are
    /// kept (hidden) but its lights, viewpoints and bindable nodes are not.
    hidden: usize,
}

impl Builder {
    pub fn new(path: &Path, depth: usize) -> Self {
        Builder {
            log: BuildLog::new(path),
            depth,
            scene: Scene::new(),
            instances: HashMap::new(),
            materials: HashMap::new(),
            textured_materials: HashMap::new(),
            material_copies: HashMap::new(),
            texture_images: HashMap::new(),
            loader: textures::Loader::new(path),
            meshes: HashMap::new(),
            coord_users: HashMap::new(),
            unlit: None,
            saw_navigation: false,
            saw_background: false,
            build_depth: 0,
            inlines: inline::Cache::new(),
            hidden: 0,
        }
    }

    pub fn build(&mut self, parsed: &Parsed) {
        for root in &parsed.roots {
            self.add(root, None);
        }
        hanim::import(self, &parsed.roots);
        animation::import(self, &parsed.routes);
    }

    /// The scene, or the input limit the build passed.
    pub fn finish(self) -> Result<Loaded, LoadError> {
        self.log.finish(self.scene)
    }

    /// Ends the build with a passed input limit (the first one is kept).
    fn stop(&mut self, pos: Pos, e: LimitError) {
        self.log.stop(pos, e);
    }

    pub(super) fn warn(&mut self, pos: Pos, msg: &str) {
        self.log.warn(pos, msg);
    }

    /// Warns once per `key` (e.g. once per unknown node type).
    pub(super) fn warn_once(&mut self, key: &str, pos: Pos, msg: &str) {
        self.log.warn_once(key, pos, msg);
    }

    fn push(&mut self, ast: &NodeRef, parent: Option<NodeId>, node: Node) -> Option<NodeId> {
        if self.log.full() || !self.log.charge(ast.pos, &self.scene, &node) {
            return None;
        }
        let id = self.scene.add_node(parent, node);
        self.instances.entry(Rc::as_ptr(ast)).or_default().push(id);
        Some(id)
    }

    /// Adds the scene nodes for one AST node under `parent`.
    pub(super) fn add(&mut self, n: &NodeRef, parent: Option<NodeId>) {
        if self.build_depth >= MAX_BUILD_DEPTH {
            self.warn_once(
                "depth",
                n.pos,
                "scene nested too deeply; deeper nodes skipped",
            );
            return;
        }
        self.build_depth += 1;
        self.add_inner(n, parent);
        self.build_depth -= 1;
    }

    fn add_inner(&mut self, n: &NodeRef, parent: Option<NodeId>) {
        let eff = n.effective();
        let name = n
            .def
            .clone()
            .or_else(|| eff.def.clone())
            .unwrap_or_default();
        let ids_before = self.scene.nodes.len();
        match eff.kind.as_str() {
            "Transform" => {
                let t = Transform {
                    translation: eff.vec3("translation", Vec3::ZERO),
                    rotation: eff.rotation("rotation").unwrap_or(Quat::IDENTITY),
                    scale: eff.vec3("scale", Vec3::ONE),
                    scale_orientation: eff.rotation("scaleOrientation").unwrap_or(Quat::IDENTITY),
                    center: eff.vec3("center", Vec3::ZERO),
                    extra: None,
                };
                if let Some(id) = self.push(&eff, parent, Node::group(name).with_transform(t)) {
                    self.children(&eff, "children", id);
                }
            }
            "Group" | "Collision" | "Billboard" | "Anchor" => {
                if let Some(id) = self.push(&eff, parent, Node::group(name)) {
                    self.children(&eff, "children", id);
                }
            }
            "Switch" => {
                if let Some(id) = self.push(&eff, parent, Node::group(name)) {
                    let which = eff.num("whichChoice").unwrap_or(-1.0);
                    let choices: Vec<NodeRef> = eff.nodes("choice").to_vec();
                    for (i, c) in choices.iter().enumerate() {
                        let first = self.scene.nodes.len();
                        let shown = i as f64 == which;
                        if !shown {
                            self.hidden += 1;
                        }
                        self.add(c, Some(id));
                        if !shown {
                            self.hidden -= 1;
                        }
                        if !shown {
                            for k in first..self.scene.nodes.len() {
                                if self.scene.nodes[k].parent == Some(id) {
                                    self.scene.nodes[k].visible = false;
                                }
                            }
                        }
                    }
                }
            }
            "LOD" => {
                if let Some(id) = self.push(&eff, parent, Node::group(name)) {
                    let level = eff.nodes("level").first().cloned();
                    if let Some(c) = level {
                        self.add(&c, Some(id));
                    }
                }
            }
            "Inline" => {
                if let Some(id) = self.push(&eff, parent, Node::group(name)) {
                    let urls = eff.strings("url");
                    let r = inline::load_into(
                        &mut self.scene,
                        &mut self.log.warnings,
                        &mut self.inlines,
                        &self.log.path,
                        eff.pos,
                        &urls,
                        id,
                        self.depth,
                        self.build_depth,
                    );
                    if let Err(e) = r {
                        self.stop(eff.pos, e);
                    }
                }
            }
            "Shape" => self.shape(&eff, parent, name),
            "DirectionalLight" | "PointLight" | "SpotLight" | "Viewpoint" | "OrthoViewpoint"
            | "NavigationInfo" | "Background"
                if self.hidden > 0 => {}
            "DirectionalLight" | "PointLight" | "SpotLight" => {
                let light = light(&eff);
                self.push(&eff, parent, Node::new(name, NodeKind::Light(light)));
            }
            "Viewpoint" | "OrthoViewpoint" => {
                let cam = Camera {
                    kind: camera_kind(&eff),
                    position: eff.vec3("position", Vec3::new(0.0, 0.0, 10.0)),
                    orientation: eff.rotation("orientation").unwrap_or(Quat::IDENTITY),
                    description: eff
                        .strings("description")
                        .first()
                        .cloned()
                        .unwrap_or_default(),
                    fov_smaller_side: true,
                    focal_distance: 10.0,
                    near: None,
                    far: None,
                };
                let name = if name.is_empty() {
                    cam.description.clone()
                } else {
                    name
                };
                self.push(&eff, parent, Node::new(name, NodeKind::Camera(cam)));
            }
            "NavigationInfo" => {
                if !self.saw_navigation {
                    self.saw_navigation = true;
                    self.scene.settings.headlight = Some(eff.bool("headlight", true));
                }
            }
            "Background" => {
                if !self.saw_background {
                    self.saw_background = true;
                    let bg = self.background(&eff);
                    self.scene.settings.background = bg.flat_color();
                    if !bg.is_flat() {
                        self.scene.settings.sky = Some(Box::new(bg));
                    }
                }
            }
            "WorldInfo" => {
                let title = eff.strings("title");
                for t in title.into_iter().filter(|t| !t.is_empty()) {
                    self.scene.info.push(t);
                }
                for s in eff.strings("info") {
                    self.scene.info.push(s);
                }
            }
            k if k == "TimeSensor" || k.ends_with("Interpolator") || k == "EaseInEaseOut" => {}
            "Script" => self.warn(eff.pos, "Script is not supported; skipped"),
            k if IGNORED.contains(&k) => {
                let msg = format!("{k} is not supported; skipped");
                self.warn_once(k, eff.pos, &msg);
            }
            k => {
                let msg = if n.proto.is_none() && !is_vrml97_node(k) {
                    format!("unknown node '{k}' skipped")
                } else {
                    format!("node '{k}' is not supported here; skipped")
                };
                self.warn_once(k, eff.pos, &msg);
            }
        }
        // A PROTO instance answers to its own DEF name as well as its root's.
        if !Rc::ptr_eq(n, &eff) && self.scene.nodes.len() > ids_before {
            self.instances
                .entry(Rc::as_ptr(n))
                .or_default()
                .push(NodeId(ids_before as u32));
        }
    }

    fn children(&mut self, n: &NodeRef, field: &str, id: NodeId) {
        for c in n.nodes(field).to_vec() {
            self.add(&c, Some(id));
        }
    }

    fn shape(&mut self, n: &NodeRef, parent: Option<NodeId>, name: String) {
        let Some(geom) = n.node("geometry").map(|g| g.effective()) else {
            return;
        };
        let appearance = n.node("appearance").map(|a| a.effective());
        let texture = appearance.as_ref().and_then(|a| self.texture(a));
        let textured = texture.is_some();
        let mesh = match self.meshes.get(&(Rc::as_ptr(&geom), textured)) {
            Some(m) => *m,
            None => {
                let mut msgs = Vec::new();
                let m = geometry::mesh(&geom, textured, &mut msgs).map(|m| self.scene.add_mesh(m));
                if let Some(e) = limits::tripped() {
                    self.stop(geom.pos, e);
                    return;
                }
                for (pos, msg) in msgs {
                    let key = format!("{}:{msg}", geom.kind);
                    self.warn_once(&key, pos, &msg);
                }
                self.meshes.insert((Rc::as_ptr(&geom), textured), m);
                if let (Some(id), true) = (m, geom.kind == "IndexedFaceSet") {
                    if let Some(coord) = geom.node("coord").map(|c| c.effective()) {
                        self.coord_users
                            .entry(Rc::as_ptr(&coord))
                            .or_default()
                            .push((geom.clone(), textured, id));
                    }
                }
                m
            }
        };
        let Some(mesh) = mesh else { return };
        let mat_node = appearance
            .as_ref()
            .and_then(|a| a.node("material").map(|m| m.effective()));
        let material = match (&appearance, &mat_node, texture) {
            (Some(a), m, Some(t)) => self.textured_material(a, m.as_ref(), t),
            (_, Some(m), _) => self.material(m),
            // §4.14.2 (table 4.5): no Material, lighting off: the Color
            // node's colours or white (a textured shape keeps its texture
            // model instead).
            (_, None, _) => self.unlit(),
        };
        self.push(
            n,
            parent,
            Node::new(name, NodeKind::Shape(Shape { mesh, material })),
        );
    }

    fn material(&mut self, m: &NodeRef) -> MaterialId {
        if let Some(id) = self.materials.get(&Rc::as_ptr(m)) {
            return *id;
        }
        let mat = material_fields(m);
        let id = self.scene.add_material(mat);
        self.materials.insert(Rc::as_ptr(m), id);
        id
    }

    /// A material carrying a texture (one per Appearance node): the
    /// Material node's fields, or the unlit white of a Shape without one,
    /// plus the texture.
    fn textured_material(&mut self, app: &NodeRef, m: Option<&NodeRef>, t: Texture) -> MaterialId {
        if let Some(id) = self.textured_materials.get(&Rc::as_ptr(app)) {
            return *id;
        }
        let mut mat = match m {
            Some(m) => material_fields(m),
            None => unlit_fields(),
        };
        mat.texture = Some(t);
        let id = self.scene.add_material(mat);
        if let Some(m) = m {
            self.material_copies
                .entry(Rc::as_ptr(m))
                .or_default()
                .push(id);
        }
        self.textured_materials.insert(Rc::as_ptr(app), id);
        id
    }

    /// VRML97 §4.14: a Shape without Material is unlit and white.
    fn unlit(&mut self) -> MaterialId {
        if let Some(id) = self.unlit {
            return id;
        }
        let id = self.scene.add_material(Material {
            unlit: true,
            ..unlit_fields()
        });
        self.unlit = Some(id);
        id
    }
}

/// VRML97 §4.14: a Shape without Material is unlit and white.
fn unlit_fields() -> Material {
    Material {
        name: String::new(),
        diffuse: Vec3::ZERO,
        ambient_intensity: 0.0,
        ambient_color: None,
        specular: Vec3::ZERO,
        emissive: Vec3::ONE,
        shininess: 0.0,
        transparency: 0.0,
        texture: None,
        emissive_texture: None,
        unlit: false,
    }
}

/// A VRML97 Material node's fields (§6.27).
fn material_fields(m: &NodeRef) -> Material {
    let d = Material::default();
    Material {
        name: m.def.clone().unwrap_or_default(),
        diffuse: m.vec3("diffuseColor", d.diffuse),
        ambient_intensity: m.f32("ambientIntensity", d.ambient_intensity),
        ambient_color: None,
        specular: m.vec3("specularColor", d.specular),
        emissive: m.vec3("emissiveColor", d.emissive),
        shininess: m.f32("shininess", d.shininess),
        transparency: m.f32("transparency", d.transparency),
        texture: None,
        emissive_texture: None,
        unlit: false,
    }
}

fn light(n: &AstNode) -> Light {
    let mut l = match n.kind.as_str() {
        "DirectionalLight" => {
            let mut l = Light::new(LightKind::Directional);
            // VRML97 §6.16: a DirectionalLight lights only its siblings.
            l.scoped = true;
            l
        }
        "PointLight" => Light::new(LightKind::Point),
        _ => Light::new(LightKind::Spot {
            beam_width: n.f32("beamWidth", std::f32::consts::FRAC_PI_2),
            cut_off_angle: n.f32("cutOffAngle", std::f32::consts::FRAC_PI_4),
            drop_off_rate: 0.0,
        }),
    };
    l.on = n.bool("on", true);
    l.intensity = n.f32("intensity", 1.0);
    l.ambient_intensity = n.f32("ambientIntensity", 0.0);
    l.color = n.vec3("color", Vec3::ONE);
    l.location = n.vec3("location", Vec3::ZERO);
    l.direction = n.vec3("direction", Vec3::new(0.0, 0.0, -1.0));
    l.attenuation = n.vec3("attenuation", Vec3::new(1.0, 0.0, 0.0));
    l.radius = n.f32("radius", 100.0);
    // X3D `global` (ISO/IEC 19775-1 §17.2.1); its defaults are VRML97's
    // scoping: DirectionalLight lights its siblings, the others everything.
    l.scoped = !n.bool("global", !l.scoped);
    l
}

/// Viewpoint: perspective with VRML97's fieldOfView. X3D OrthoViewpoint
/// (§23.4.5): fieldOfView is the (minX, minY, maxX, maxY) rectangle; the
/// view volume's height is its larger extent, as it applies to the
/// smaller window side like Viewpoint's angle.
fn camera_kind(n: &AstNode) -> CameraKind {
    if n.kind == "OrthoViewpoint" {
        let r = match n.nums("fieldOfView") {
            Some(v) if v.len() >= 4 => [v[0], v[1], v[2], v[3]],
            _ => [-1.0, -1.0, 1.0, 1.0],
        };
        let h = (r[2] - r[0]).abs().max((r[3] - r[1]).abs()) as f32;
        return CameraKind::Orthographic {
            height: if h.is_finite() && h > 0.0 { h } else { 2.0 },
        };
    }
    CameraKind::Perspective {
        height_angle: n.f32("fieldOfView", std::f32::consts::FRAC_PI_4),
    }
}

/// Standard VRML97 node names (anything else is unknown, not unsupported).
fn is_vrml97_node(k: &str) -> bool {
    const ALL: &[&str] = &[
        "Anchor",
        "Appearance",
        "AudioClip",
        "Background",
        "Billboard",
        "Box",
        "Collision",
        "Color",
        "ColorInterpolator",
        "Cone",
        "Coordinate",
        "CoordinateInterpolator",
        "Cylinder",
        "CylinderSensor",
        "DirectionalLight",
        "ElevationGrid",
        "Extrusion",
        "Fog",
        "FontStyle",
        "Group",
        "ImageTexture",
        "IndexedFaceSet",
        "IndexedLineSet",
        "Inline",
        "LOD",
        "Material",
        "MovieTexture",
        "NavigationInfo",
        "Normal",
        "NormalInterpolator",
        "OrientationInterpolator",
        "PixelTexture",
        "PlaneSensor",
        "PointLight",
        "PointSet",
        "PositionInterpolator",
        "ProximitySensor",
        "ScalarInterpolator",
        "Script",
        "Shape",
        "Sound",
        "Sphere",
        "SphereSensor",
        "SpotLight",
        "Switch",
        "Text",
        "TextureCoordinate",
        "TextureTransform",
        "TimeSensor",
        "TouchSensor",
        "Transform",
        "Viewpoint",
        "VisibilitySensor",
        "WorldInfo",
    ];
    ALL.contains(&k)
}
