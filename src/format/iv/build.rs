//! Inventor traversal → scene tree.
//!
//! Separators become group nodes and save/restore the state. Unnamed
//! transform nodes accumulate into a pending matrix that later siblings
//! carry (as `Transform::extra`); a DEF'd transform becomes a group that
//! holds the siblings after it, so it keeps its name for animation.
//! Group, Switch and LOD do not separate state in Inventor, so their chosen
//! children are traversed in place.

use super::shapes;
use super::state::State;
use crate::format::build_log::BuildLog;
use crate::format::inline;
use crate::format::lexer::Pos;
use crate::format::limits::{self, LimitError};
use crate::format::syntax::{AstNode, NodeRef, Parsed};
use crate::format::textures;
use crate::format::LoadError;
use crate::format::Loaded;
use crate::scene::{
    Camera, CameraKind, ImageId, Light, LightKind, Material, MaterialId, Mesh, MeshId, Node,
    NodeId, NodeKind, Scene, Shape, Texture, Transform,
};
use glam::{Mat4, Quat, Vec3};
use std::collections::HashMap;
use std::path::Path;
use std::rc::Rc;

/// Deepest scene tree built: the parser already bounds the expanded
/// depth by the input budget, whose largest setting this is.
const MAX_BUILD_DEPTH: usize = limits::DEPTH_CEILING as usize;

/// Nodes read and deliberately ignored (no effect on geometry here).
const IGNORED: &[&str] = &[
    "Font",
    "FontStyle",
    "PickStyle",
    "Label",
    "Callback",
    "EventCallback",
    "Units",
    "NormalBinding_",
    "ElapsedTime",
];

/// Where new nodes go.
#[derive(Clone, Copy)]
pub(super) struct Cursor {
    parent: Option<NodeId>,
    /// Unnamed transforms since `parent`, applied to each node added.
    pending: Mat4,
    /// World matrix of `parent` (for ResetTransform).
    world: Mat4,
    /// Inside a Separator (lights there are scoped).
    pub(super) separated: bool,
    /// Scene depth of `parent` (0 at the top).
    depth: u32,
}

/// The child a Switch traverses (−1 none, −3 all): SO_SWITCH_INHERIT
/// (−2) takes the last Switch's value from the state, wrapped into range
/// as Coin does (chessboard.iv picks its kings and queens that way); any
/// other value becomes that state value (SoSwitch::doAction).
fn switch_child(which: f64, children: usize, st: &mut State) -> i64 {
    let which = which as i64;
    if which != -2 {
        st.switch_value = which;
        return which;
    }
    match st.switch_value {
        v if v >= 0 && children > 0 => v % children as i64,
        v => v,
    }
}

/// How deep named transforms may nest the scene when they follow each other
/// as siblings (each moves what follows, so each nests the rest). Beyond it
/// their matrices are merged into what follows, so the scene stays shallow
/// enough to write back and to walk on a small stack.
const MAX_CHAIN_DEPTH: u32 = 128;

impl Cursor {
    /// Where the children of group `id` (just added here) go: the pending
    /// transforms are folded into the world matrix.
    pub(super) fn inside(&self, id: NodeId, separated: bool) -> Cursor {
        Cursor {
            parent: Some(id),
            pending: Mat4::IDENTITY,
            world: self.world * self.pending,
            separated,
            depth: self.depth + 1,
        }
    }
}

#[derive(Hash, PartialEq, Eq)]
struct MeshKey {
    shape: usize,
    coords: usize,
    normals: usize,
    material: usize,
    base: usize,
    bindings: (super::state::Bind, super::state::Bind),
    hints: (Option<bool>, bool, u32),
    /// LightModel BASE_COLOR: the mesh is built without normals (unlit).
    unlit: bool,
    /// Texture coordinates: (wanted, source, binding, baked transform).
    tex: (bool, usize, super::state::Bind, [u32; 6]),
    /// A Sphere drawn as lines is Coin's grid at this complexity (bits).
    grid: Option<u32>,
}

pub struct Builder {
    /// Warnings and the first input limit passed (shared with the VRML97
    /// builder).
    pub(super) log: BuildLog,
    pub(super) depth: usize,
    vrml1: bool,
    pub(super) scene: Scene,
    /// By (Material, BaseColor, unlit, Texture2, texture transform).
    materials: HashMap<(usize, usize, bool, usize, [u32; 7]), MaterialId>,
    meshes: HashMap<MeshKey, Option<MeshId>>,
    coords: HashMap<usize, Rc<Vec<Vec3>>>,
    pub(super) build_depth: usize,
    pub(super) inlines: inline::Cache,
    /// Files read by `File` nodes (`file_node`).
    pub(super) files: super::file_node::Files,
    pub(super) loader: textures::Loader,
    /// Each Texture2 node's image (None: it did not load).
    pub(super) texture_images: HashMap<usize, Option<ImageId>>,
}

impl Builder {
    pub fn new(path: &Path, depth: usize, vrml1: bool) -> Self {
        Builder {
            log: BuildLog::new(path),
            depth,
            vrml1,
            scene: {
                // OpenGL's light-model ambient, which Inventor viewers (and
                // VRML 1.0 browsers) light with unless an Environment says.
                let mut s = Scene::new();
                s.settings.ambient = Vec3::splat(0.2);
                s
            },
            materials: HashMap::new(),
            meshes: HashMap::new(),
            coords: HashMap::new(),
            build_depth: 0,
            inlines: inline::Cache::new(),
            files: super::file_node::Files::new(),
            loader: textures::Loader::new(path),
            texture_images: HashMap::new(),
        }
    }

    pub fn build(&mut self, parsed: &Parsed) {
        let mut st = State::new(self.vrml1);
        let mut cur = Cursor {
            parent: None,
            pending: Mat4::IDENTITY,
            world: Mat4::IDENTITY,
            separated: false,
            depth: 0,
        };
        for n in &parsed.roots {
            self.node(n, &mut st, &mut cur);
        }
        for r in &parsed.routes {
            self.warn_once("route", r.pos, "ROUTE in an Inventor file ignored");
        }
    }

    /// The scene, or the input limit the build passed.
    pub fn finish(self) -> Result<Loaded, LoadError> {
        let mut scene = self.scene;
        super::text::size_text2(&mut scene);
        self.log.finish(scene)
    }

    /// Ends the build with a passed input limit (the first one is kept).
    pub(super) fn stop(&mut self, pos: Pos, e: LimitError) {
        self.log.stop(pos, e);
    }

    pub(super) fn warn(&mut self, pos: Pos, msg: &str) {
        self.log.warn(pos, msg);
    }

    fn warn_once(&mut self, key: &str, pos: Pos, msg: &str) {
        self.log.warn_once(key, pos, msg);
    }

    /// Adds a scene node at the cursor (carrying the pending transforms).
    pub(super) fn add(&mut self, pos: Pos, cur: &Cursor, mut node: Node) -> Option<NodeId> {
        if self.log.full() || !self.log.charge(pos, &self.scene, &node) {
            return None;
        }
        if cur.pending != Mat4::IDENTITY {
            node.transform.extra = Some(match node.transform.extra {
                Some(e) => cur.pending * e,
                None => cur.pending,
            });
        }
        Some(self.scene.add_node(cur.parent, node))
    }

    fn children(&mut self, n: &AstNode, st: &mut State, cur: &mut Cursor) {
        for c in n.nodes("children").to_vec() {
            self.node(&c, st, cur);
        }
    }

    pub(super) fn node(&mut self, n: &NodeRef, st: &mut State, cur: &mut Cursor) {
        if self.build_depth >= MAX_BUILD_DEPTH || self.log.full() {
            self.warn_once(
                "depth",
                n.pos,
                "scene nested too deeply; deeper nodes skipped",
            );
            return;
        }
        self.build_depth += 1;
        self.node_inner(n, st, cur);
        self.build_depth -= 1;
    }

    fn node_inner(&mut self, n: &NodeRef, st: &mut State, cur: &mut Cursor) {
        if st.apply(n) {
            return;
        }
        let name = n.def.clone().unwrap_or_default();
        let kind = n.kind.as_str();
        if let Some(t) = transform_of(n, cur) {
            self.transform(n, name, t, cur);
            return;
        }
        if shapes::is_shape(kind) {
            self.shape(n, st, cur, name);
            return;
        }
        match kind {
            "Separator" | "Selection" | "Annotation" | "WWWAnchor" | "SoSeparator" => {
                if let Some(id) = self.add(n.pos, cur, Node::group(name)) {
                    let mut inner = cur.inside(id, true);
                    let mut saved = st.clone();
                    self.children(n, &mut saved, &mut inner);
                }
            }
            "Array" | "MultipleCopy" => self.copies(n, st, cur, name),
            k if super::kits::is_kit(k) => self.kit(n, st, cur, name),
            "TransformSeparator" => {
                let mut inner = *cur;
                self.children(n, st, &mut inner);
            }
            "Group" => {
                if name.is_empty() {
                    self.children(n, st, cur);
                } else if let Some(id) = self.add(n.pos, cur, Node::group(name)) {
                    let mut inner = cur.inside(id, cur.separated);
                    self.children(n, st, &mut inner);
                    if inner.parent == Some(id) {
                        // Only static transforms inside (or none): later
                        // siblings take them as pending instead of nesting
                        // under the group. Exporters write thousands of
                        // sibling DEF'd Groups (graz.wrl: 4,167), which
                        // nested that deep and could not be written back.
                        cur.pending *= inner.pending;
                    } else {
                        // A named (animatable) transform inside moves what
                        // follows: keep following it.
                        *cur = inner;
                    }
                }
            }
            "Switch" | "Blinker" => {
                let kids = n.nodes("children").to_vec();
                let which = switch_child(n.num("whichChild").unwrap_or(-1.0), kids.len(), st);
                if which == -3 {
                    for c in &kids {
                        self.node(c, st, cur);
                    }
                } else if which >= 0 {
                    if let Some(c) = kids.get(which as usize) {
                        self.node(c, st, cur);
                    }
                }
            }
            "LOD" | "LevelOfDetail" => {
                if let Some(c) = n.nodes("children").first().cloned() {
                    self.node(&c, st, cur);
                }
            }
            "File" => self.file(n, st, cur, name),
            "WWWInline" => {
                if let Some(id) = self.add(n.pos, cur, Node::group(name)) {
                    self.graft(n.pos, &n.strings("name"), id);
                }
            }
            "Environment" => {
                // The global ambient for the whole scene (the renderer has
                // one); fog and light attenuation are not drawn.
                let ambient = n.f32("ambientIntensity", 0.2).clamp(0.0, 1.0)
                    * n.vec3("ambientColor", Vec3::ONE)
                        .clamp(Vec3::ZERO, Vec3::ONE);
                if ambient.is_finite() {
                    self.scene.settings.ambient = ambient;
                }
            }
            "DirectionalLight" | "PointLight" | "SpotLight" => {
                let mut l = light(n);
                // An Inventor light lights what follows it inside its Separator.
                l.scoped = cur.separated;
                self.add(n.pos, cur, Node::new(name, NodeKind::Light(l)));
            }
            "PerspectiveCamera" | "OrthographicCamera" => {
                let cam = camera(n);
                self.add(n.pos, cur, Node::new(name, NodeKind::Camera(cam)));
            }
            "Info" => {
                for s in n.strings("string") {
                    self.scene.info.push(s);
                }
            }
            "TextureCoordinateEnvironment"
            | "TextureCoordinateFunction"
            | "TextureCoordinateSphere"
            | "TextureCoordinateCylinder"
            | "TextureCoordinateCube" => {
                let msg = format!("{kind} is not supported; the default texture mapping is used");
                self.warn_once(kind, n.pos, &msg);
            }
            "AsciiText" | "Text2" | "Text3" => self.text(n, st, cur, name),
            k if IGNORED.contains(&k) => {}
            // Inventor 2.1 node classes animed does not draw (The Inventor
            // Mentor ch. 15 draggers and manipulators, ch. 8 NURBS): a
            // valid file, only not supported here.
            k if k.ends_with("Dragger")
                || k.ends_with("Manip")
                || k.starts_with("Nurbs")
                || k.starts_with("IndexedNurbs") =>
            {
                let msg = format!("{k} is not supported; skipped");
                self.warn_once(k, n.pos, &msg);
            }
            k => {
                let declared = n.field("fields").is_some();
                let msg = if declared {
                    format!("unknown node '{k}' (declared with fields [...]) skipped")
                } else {
                    format!("unknown node '{k}' skipped")
                };
                self.warn_once(k, n.pos, &msg);
            }
        }
    }

    fn transform(&mut self, n: &NodeRef, name: String, t: Transform, cur: &mut Cursor) {
        let animated = super::animated::is_animated(&n.kind);
        if name.is_empty() && !animated {
            cur.pending *= t.matrix();
            return;
        }
        if cur.depth >= MAX_CHAIN_DEPTH {
            self.warn_once(
                "chain",
                n.pos,
                &format!(
                    "more than {MAX_CHAIN_DEPTH} nested levels of named transforms: \
                     '{name}' and later ones are merged into what follows (not animated)"
                ),
            );
            cur.pending *= t.matrix();
            return;
        }
        if let Some(id) = self.add(n.pos, cur, Node::group(name).with_transform(t)) {
            cur.world *= self.scene.node(id).transform.matrix();
            cur.parent = Some(id);
            cur.depth += 1;
            cur.pending = Mat4::IDENTITY;
            if animated {
                if let Err(e) = super::animated::add_track(&mut self.scene, n, id) {
                    self.warn(n.pos, &format!("{} not animated: {e}", n.kind));
                }
            }
        }
    }

    fn shape(&mut self, n: &NodeRef, st: &State, cur: &Cursor, name: String) {
        let coords = match &st.coords {
            Some(c) => {
                let key = Rc::as_ptr(c) as usize;
                self.coords
                    .entry(key)
                    .or_insert_with(|| Rc::new(super::state::colors(c, "point")))
                    .clone()
            }
            // Inventor's coordinate element starts as one point at the
            // origin (Coin's SoCoordinateElement default): a PointSet
            // without Coordinate3 draws it, a LineSet counts it in its box.
            None => Rc::new(vec![Vec3::ZERO]),
        };
        // Texture coordinates only when a texture actually loads.
        let texture = self.texture(st);
        let textured = texture.is_some();
        let tex = if textured {
            (
                true,
                st.tex_source.ptr(),
                st.texcoord_binding,
                st.tex_transform.baked_key(),
            )
        } else {
            (false, 0, super::state::Bind::Default, [0; 6])
        };
        let key = MeshKey {
            tex,
            shape: Rc::as_ptr(n) as usize,
            coords: State::ptr(&st.coords),
            normals: State::ptr(&st.normals),
            material: State::ptr(&st.material),
            base: State::ptr(&st.base_color),
            bindings: (st.material_binding, st.normal_binding),
            hints: (st.ccw, st.solid_type, st.crease_angle.to_bits()),
            unlit: st.unlit,
            grid: shapes::lines_grid(n, st, textured).map(f32::to_bits),
        };
        let mesh = match self.meshes.get(&key) {
            Some(m) => *m,
            None => {
                let mut inp = shapes::inputs(n, st, coords);
                inp.textured = textured;
                let mut msgs = Vec::new();
                let m = shapes::mesh(n, st, &inp, &mut msgs).map(|mut m| {
                    m.name = name.clone();
                    if st.unlit && !textured {
                        // BASE_COLOR: no lighting, so the shape shows its
                        // colours (per-vertex ones too) as they are; a mesh
                        // without normals is what the renderer draws unlit.
                        m.normals.clear();
                    }
                    self.read_morph(n, st, &inp, &mut m);
                    self.scene.add_mesh(m)
                });
                for (pos, msg) in msgs {
                    let k = format!("{}:{msg}", n.kind);
                    self.warn_once(&k, pos, &msg);
                }
                self.meshes.insert(key, m);
                m
            }
        };
        let Some(mesh) = mesh else { return };
        // Lines and points without normals are drawn unlit by Inventor
        // (Coin, SGI) in their base colour: the diffuse colour, as under
        // LightModel BASE_COLOR (drawn black by the lighting model
        // otherwise). A line set with normals (`shapes::mesh`) is lit.
        let lit_lines = self
            .scene
            .meshes
            .get(mesh.0 as usize)
            .is_some_and(|m| !m.normals.is_empty() && m.normals.len() == m.positions.len());
        let material = if matches!(n.kind.as_str(), "IndexedLineSet" | "LineSet" | "PointSet")
            && !st.unlit
            && !lit_lines
        {
            let mut unlit = st.clone();
            unlit.unlit = true;
            self.material(&unlit, texture)
        } else {
            self.material(st, texture)
        };
        // Coin culls no primitive: a closed one is drawn culled only because
        // its back faces cannot show; through a see-through material or
        // texture they do, so such a primitive is two-sided.
        if matches!(n.kind.as_str(), "Cube" | "Cone" | "Sphere" | "Cylinder")
            && self.see_through(material)
        {
            if let Some(m) = self.scene.meshes.get_mut(mesh.0 as usize) {
                m.solid = false;
            }
        }
        let mut node = Node::new(name, NodeKind::Shape(Shape { mesh, material }));
        (node.style, node.line_width, node.point_size) = (st.style, st.line_width, st.point_size);
        self.add(n.pos, cur, node);
    }

    /// Morph targets carried by engines connected to the state's
    /// Coordinate3 (and Normal), see `iv::morph`, set on the shape's mesh.
    fn read_morph(&mut self, n: &NodeRef, st: &State, inp: &shapes::Inputs, m: &mut Mesh) {
        let Some(coords) = st
            .coords
            .as_ref()
            .filter(|_| n.node("vertexProperty").is_none())
        else {
            return;
        };
        let targets = match super::morph::targets(coords, "point", inp.coords.len()) {
            Ok(Some(t)) => t,
            Ok(None) => return,
            Err(e) => {
                self.warn(coords.pos, &format!("morph targets not read: {e}"));
                return;
            }
        };
        let normals = match st.normals.as_ref().filter(|_| !m.normals.is_empty()) {
            Some(nn) => match super::morph::targets(nn, "vector", inp.normals.len()) {
                Ok(t) => t.filter(|t| t.offsets.len() == targets.offsets.len()),
                Err(e) => {
                    self.warn(nn.pos, &format!("morph normals not read: {e}"));
                    None
                }
            },
            None => None,
        };
        let lit = !m.normals.is_empty();
        match shapes::morph(n, st, inp, &targets, normals.as_ref(), lit) {
            Ok(morphs) => m.morph = Some(Box::new(morphs)),
            Err(e) => self.warn(n.pos, &format!("morph targets not read: {e}")),
        }
    }

    /// `Array` / `MultipleCopy`: a group holding one group per copy, each
    /// placed by its matrix and traversed like a Separator.
    fn copies(&mut self, n: &NodeRef, st: &State, cur: &Cursor, name: String) {
        let (matrices, cut) = super::copies::copies(n);
        if cut {
            self.warn(
                n.pos,
                &format!(
                    "{}: only the first {} copies are made",
                    n.kind,
                    super::copies::MAX_COPIES
                ),
            );
        }
        let Some(id) = self.add(n.pos, cur, Node::group(name)) else {
            return;
        };
        let outer = cur.inside(id, true);
        for m in matrices {
            let mut copy = Node::group(String::new());
            copy.transform.extra = Some(m);
            let Some(cid) = self.add(n.pos, &outer, copy) else {
                return;
            };
            // The copy's matrix is pending for what goes inside it.
            let mut inner = Cursor {
                pending: m,
                ..outer
            }
            .inside(cid, true);
            let mut saved = st.clone();
            self.children(n, &mut saved, &mut inner);
        }
    }

    /// A node kit: its parts in catalog order (`kits`), inside a group of
    /// its own when the kit separates (else in place, like a Group).
    fn kit(&mut self, n: &NodeRef, st: &mut State, cur: &mut Cursor, name: String) {
        let parts = super::kits::parts(n);
        if !super::kits::separates(&n.kind) {
            for p in &parts {
                self.node(p, st, cur);
            }
            return;
        }
        let Some(id) = self.add(n.pos, cur, Node::group(name)) else {
            return;
        };
        let mut inner = cur.inside(id, true);
        let mut saved = st.clone();
        for p in &parts {
            self.node(p, &mut saved, &mut inner);
        }
    }

    /// A text node: its mesh is built per instance (the font is state).
    fn text(&mut self, n: &NodeRef, st: &State, cur: &Cursor, name: String) {
        let mut msgs = Vec::new();
        let m = super::text::mesh(n, st, &mut msgs);
        if let Some(e) = limits::tripped() {
            self.stop(n.pos, e);
            return;
        }
        for (pos, msg) in msgs {
            let k = format!("{}:{msg}", n.kind);
            self.warn_once(&k, pos, &msg);
        }
        let Some(mut m) = m else { return };
        m.name = name.clone();
        let mesh = self.scene.add_mesh(m);
        // Text carries no texture coordinates: drawn untextured.
        let material = self.material(st, None);
        // Coin culls no primitive: a closed one is drawn culled only because
        // its back faces cannot show; through a see-through material or
        // texture they do, so such a primitive is two-sided.
        if matches!(n.kind.as_str(), "Cube" | "Cone" | "Sphere" | "Cylinder")
            && self.see_through(material)
        {
            if let Some(m) = self.scene.meshes.get_mut(mesh.0 as usize) {
                m.solid = false;
            }
        }
        let mut node = Node::new(name, NodeKind::Shape(Shape { mesh, material }));
        (node.style, node.line_width, node.point_size) = (st.style, st.line_width, st.point_size);
        self.add(n.pos, cur, node);
    }

    /// The scene material for the state's first material values.
    /// Whether a shape drawn with `material` lets its back faces show: some
    /// transparency, or a texture with a see-through texel.
    fn see_through(&self, material: MaterialId) -> bool {
        let Some(m) = self.scene.materials.get(material.0 as usize) else {
            return false;
        };
        m.transparency > 0.0
            || m.texture
                .as_ref()
                .and_then(|t| self.scene.image(t.image))
                .is_some_and(|i| i.has_alpha())
    }

    fn material(&mut self, st: &State, texture: Option<Texture>) -> MaterialId {
        let key = (
            State::ptr(&st.material),
            State::ptr(&st.base_color),
            st.unlit,
            if texture.is_some() {
                State::ptr(&st.texture)
            } else {
                0
            },
            match st.tex_transform {
                super::state::TexXf::One(t) if texture.is_some() => [
                    t.translation.x,
                    t.translation.y,
                    t.rotation,
                    t.scale.x,
                    t.scale.y,
                    t.center.x,
                    t.center.y,
                ]
                .map(f32::to_bits),
                _ => [0; 7],
            },
        );
        if let Some(id) = self.materials.get(&key) {
            return *id;
        }
        let first = |m: &Option<NodeRef>, f: &str, d: Vec3| -> Vec3 {
            m.as_ref()
                .and_then(|m| super::state::colors(m, f).first().copied())
                .unwrap_or(d)
        };
        let scalar = |m: &Option<NodeRef>, f: &str, d: f32| -> f32 {
            m.as_ref().and_then(|m| m.num(f)).map_or(d, |v| v as f32)
        };
        let m = &st.material;
        let mut diffuse = first(m, "diffuseColor", Vec3::splat(0.8));
        let mut transparency = scalar(m, "transparency", 0.0);
        if let Some(b) = &st.base_color {
            if b.kind == "PackedColor" {
                if let Some((c, t)) = super::state::packed(b.nums("rgba").unwrap_or(&[])).first() {
                    diffuse = *c;
                    transparency = *t;
                }
            } else if let Some(c) = super::state::colors(b, "rgb").first() {
                diffuse = *c;
            }
        }
        let ambient = first(m, "ambientColor", Vec3::splat(0.2));
        let mut mat = Material {
            name: m.as_ref().and_then(|m| m.def.clone()).unwrap_or_default(),
            diffuse,
            ambient_intensity: ((ambient.x + ambient.y + ambient.z) / 3.0).clamp(0.0, 1.0),
            // Coin's ambient term: this colour × the Environment's, whatever
            // the diffuse colour (per-vertex colours included: Coin keeps
            // the first ambientColor for every vertex).
            ambient_color: Some(ambient.clamp(Vec3::ZERO, Vec3::ONE)),
            specular: first(m, "specularColor", Vec3::ZERO),
            emissive: first(m, "emissiveColor", Vec3::ZERO),
            shininess: scalar(m, "shininess", 0.2),
            transparency,
            texture,
            emissive_texture: None,
            unlit: false,
        };
        if st.unlit {
            mat.emissive = mat.diffuse;
            mat.diffuse = Vec3::ZERO;
            mat.specular = Vec3::ZERO;
            mat.ambient_intensity = 0.0;
            mat.ambient_color = None;
        }
        let id = self.scene.add_material(mat);
        self.materials.insert(key, id);
        id
    }
}

/// The transform a transform node stands for (None if `n` is not one).
fn transform_of(n: &AstNode, cur: &Cursor) -> Option<Transform> {
    let kind = n.kind.as_str();
    let rot = |f: &str| n.rotation(f).unwrap_or(Quat::IDENTITY);
    let t = match kind {
        "Transform" => Transform {
            translation: n.vec3("translation", Vec3::ZERO),
            rotation: rot("rotation"),
            scale: n.vec3("scaleFactor", Vec3::ONE),
            scale_orientation: rot("scaleOrientation"),
            center: n.vec3("center", Vec3::ZERO),
            extra: None,
        },
        k if k.ends_with("Manip") && k != "Manip" => Transform {
            translation: n.vec3("translation", Vec3::ZERO),
            rotation: rot("rotation"),
            scale: n.vec3("scaleFactor", Vec3::ONE),
            scale_orientation: rot("scaleOrientation"),
            center: n.vec3("center", Vec3::ZERO),
            extra: None,
        },
        "Translation" => Transform::from_translation(n.vec3("translation", Vec3::ZERO)),
        "Rotation" | "Rotor" | "Pendulum" => Transform {
            rotation: if kind == "Pendulum" {
                rot("rotation0")
            } else {
                rot("rotation")
            },
            ..Default::default()
        },
        "Shuttle" => Transform::from_translation(n.vec3("translation0", Vec3::ZERO)),
        "RotationXYZ" => {
            let a = n.f32("angle", 0.0);
            let q = match n.words("axis").first().map(|s| s.as_str()) {
                Some("Y") => Quat::from_rotation_y(a),
                Some("Z") => Quat::from_rotation_z(a),
                _ => Quat::from_rotation_x(a),
            };
            Transform {
                rotation: q,
                ..Default::default()
            }
        }
        "Scale" => Transform {
            scale: n.vec3("scaleFactor", Vec3::ONE),
            ..Default::default()
        },
        "MatrixTransform" => {
            let m = n.nums("matrix").unwrap_or(&[]);
            if m.len() < 16 {
                return Some(Transform::default());
            }
            let mut a = [0f32; 16];
            for (d, s) in a.iter_mut().zip(m) {
                *d = *s as f32;
            }
            // Inventor matrices are row-vector (translation in the last
            // row); read as columns they are the column-vector matrix.
            Transform {
                extra: Some(Mat4::from_cols_array(&a)),
                ..Default::default()
            }
        }
        "ResetTransform" => {
            let what = n.words("whatToReset");
            if what.is_empty() || what.iter().any(|w| w == "TRANSFORM") {
                let acc = cur.world * cur.pending;
                Transform {
                    extra: Some(acc.inverse()),
                    ..Default::default()
                }
            } else {
                Transform::default()
            }
        }
        _ => return None,
    };
    Some(t)
}

fn light(n: &AstNode) -> Light {
    let mut l = match n.kind.as_str() {
        "DirectionalLight" => Light::new(LightKind::Directional),
        "PointLight" => Light::new(LightKind::Point),
        _ => {
            let cut = n.f32("cutOffAngle", std::f32::consts::FRAC_PI_4);
            Light::new(LightKind::Spot {
                beam_width: cut,
                cut_off_angle: cut,
                drop_off_rate: n.f32("dropOffRate", 0.0),
            })
        }
    };
    l.on = n.bool("on", true);
    l.intensity = n.f32("intensity", 1.0);
    l.color = n.vec3("color", Vec3::ONE);
    l.location = n.vec3("location", Vec3::ZERO);
    l.direction = n.vec3("direction", Vec3::new(0.0, 0.0, -1.0));
    // Inventor lights have no range.
    l.radius = f32::MAX;
    l
}

fn camera(n: &AstNode) -> Camera {
    let kind = if n.kind == "OrthographicCamera" {
        CameraKind::Orthographic {
            height: n.f32("height", 2.0),
        }
    } else {
        CameraKind::Perspective {
            height_angle: n.f32("heightAngle", std::f32::consts::FRAC_PI_4),
        }
    };
    Camera {
        kind,
        position: n.vec3("position", Vec3::new(0.0, 0.0, 1.0)),
        orientation: n.rotation("orientation").unwrap_or(Quat::IDENTITY),
        description: n.def.clone().unwrap_or_default(),
        // Inventor's heightAngle is for the window height.
        fov_smaller_side: false,
        focal_distance: n.f32("focalDistance", 5.0),
        near: n.num("nearDistance").map(|v| v as f32),
        far: n.num("farDistance").map(|v| v as f32),
    }
}
