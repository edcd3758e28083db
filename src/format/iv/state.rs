//! Inventor's traversal state: what property nodes set for the shapes that
//! follow them (until the enclosing Separator restores it).

use crate::format::syntax::{AstNode, NodeRef};
use crate::scene::{RenderStyle, TexTransform, TexTransformOrder};
use glam::{Affine2, Vec2, Vec3};
use std::rc::Rc;

/// MaterialBinding / NormalBinding values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Bind {
    Default,
    Overall,
    PerPart,
    PerPartIndexed,
    PerFace,
    PerFaceIndexed,
    PerVertex,
    PerVertexIndexed,
}

impl Bind {
    pub fn parse(word: &str) -> Bind {
        match word {
            "OVERALL" => Bind::Overall,
            "PER_PART" => Bind::PerPart,
            "PER_PART_INDEXED" => Bind::PerPartIndexed,
            "PER_FACE" => Bind::PerFace,
            "PER_FACE_INDEXED" => Bind::PerFaceIndexed,
            "PER_VERTEX" => Bind::PerVertex,
            "PER_VERTEX_INDEXED" => Bind::PerVertexIndexed,
            _ => Bind::Default,
        }
    }
}

/// The accumulated properties.
#[derive(Clone, Debug)]
pub struct State {
    pub coords: Option<NodeRef>,
    pub normals: Option<NodeRef>,
    pub material: Option<NodeRef>,
    /// BaseColor / PackedColor overriding the diffuse colours.
    pub base_color: Option<NodeRef>,
    pub material_binding: Bind,
    pub normal_binding: Bind,
    /// ShapeHints: `Some(true)` counter-clockwise, `Some(false)` clockwise.
    pub ccw: Option<bool>,
    pub solid_type: bool,
    pub crease_angle: f32,
    pub style: RenderStyle,
    /// DrawStyle lineWidth and pointSize in pixels (0: the default).
    pub line_width: f32,
    pub point_size: f32,
    /// Complexity's value (0…1): how finely a Sphere drawn as lines is
    /// divided (`coin_grid`).
    pub complexity: f32,
    /// The last Switch's whichChild (Coin's SoSwitchElement), what a
    /// Switch with whichChild −2 (SO_SWITCH_INHERIT) takes; −1 at first.
    pub switch_value: i64,
    /// LightModel BASE_COLOR: shapes are unlit.
    pub unlit: bool,
    /// Font (Inventor) or FontStyle (VRML 1.0) for the text nodes.
    pub font: Option<NodeRef>,
    /// ProfileCoordinate2 and LinearProfile: Text3's extrusion.
    pub profile: (Option<NodeRef>, Option<NodeRef>),
    /// The current Texture2 (one with neither `filename` nor `image`
    /// switches texturing off again).
    pub texture: Option<NodeRef>,
    /// The accumulated Texture2Transforms.
    pub tex_transform: TexXf,
    /// Where texture coordinates come from.
    pub tex_source: TexSource,
    pub texcoord_binding: Bind,
}

/// Accumulated Texture2Transform nodes. One node keeps its authored fields
/// (writers write them back); several are multiplied into one matrix,
/// which is then baked into the shape's texture coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TexXf {
    None,
    One(TexTransform),
    Baked(Affine2),
}

impl TexXf {
    /// Adds a later Texture2Transform: like geometry transforms, the later
    /// node applies to the coordinates first (`current × new`).
    pub fn then(self, t: TexTransform) -> TexXf {
        match self {
            TexXf::None => TexXf::One(t),
            TexXf::One(a) => TexXf::Baked(a.matrix() * t.matrix()),
            TexXf::Baked(m) => TexXf::Baked(m * t.matrix()),
        }
    }

    /// A hashable identity of the baked matrix (0 when nothing is baked).
    pub fn baked_key(&self) -> [u32; 6] {
        match self {
            TexXf::Baked(m) => m.to_cols_array().map(f32::to_bits),
            _ => [0; 6],
        }
    }
}

/// The texture coordinate element: explicit TextureCoordinate2 points, a
/// TextureCoordinatePlane function, or the shape's default mapping
/// (TextureCoordinateDefault, or nothing said).
#[derive(Clone, Debug)]
pub enum TexSource {
    Default,
    Points(NodeRef),
    Plane(NodeRef),
}

impl TexSource {
    pub fn ptr(&self) -> usize {
        match self {
            TexSource::Default => 0,
            TexSource::Points(n) | TexSource::Plane(n) => Rc::as_ptr(n) as usize,
        }
    }
}

impl State {
    pub fn new(vrml1: bool) -> Self {
        State {
            coords: None,
            normals: None,
            material: None,
            base_color: None,
            material_binding: Bind::Default,
            normal_binding: Bind::Default,
            ccw: None,
            solid_type: false,
            // VRML 1.0 §ShapeHints says 0.5; Coin's Inventor default is 0.
            crease_angle: if vrml1 { 0.5 } else { 0.0 },
            style: RenderStyle::Filled,
            line_width: 0.0,
            point_size: 0.0,
            complexity: super::coin_grid::DEFAULT_COMPLEXITY,
            switch_value: -1,
            unlit: false,
            font: None,
            profile: (None, None),
            texture: None,
            tex_transform: TexXf::None,
            tex_source: TexSource::Default,
            texcoord_binding: Bind::Default,
        }
    }

    /// Applies a property node; false if `n` is not one.
    pub fn apply(&mut self, n: &NodeRef) -> bool {
        match n.kind.as_str() {
            "Coordinate3" => self.coords = Some(n.clone()),
            "Normal" => self.normals = Some(n.clone()),
            "Material" => {
                self.material = Some(n.clone());
                self.base_color = None;
            }
            "BaseColor" | "PackedColor" => self.base_color = Some(n.clone()),
            "MaterialBinding" => {
                self.material_binding = Bind::parse(first_word(n, "value"));
            }
            "NormalBinding" => self.normal_binding = Bind::parse(first_word(n, "value")),
            "ShapeHints" => {
                if n.field("vertexOrdering").is_some() {
                    self.ccw = match first_word(n, "vertexOrdering") {
                        "CLOCKWISE" => Some(false),
                        "COUNTERCLOCKWISE" => Some(true),
                        _ => None,
                    };
                }
                if n.field("shapeType").is_some() {
                    self.solid_type = first_word(n, "shapeType") == "SOLID";
                }
                if let Some(a) = n.num("creaseAngle") {
                    self.crease_angle = a as f32;
                }
            }
            "DrawStyle" => {
                if n.field("style").is_some() {
                    self.style = match first_word(n, "style") {
                        "LINES" => RenderStyle::Lines,
                        "POINTS" => RenderStyle::Points,
                        "INVISIBLE" => RenderStyle::Hidden,
                        _ => RenderStyle::Filled,
                    };
                }
                if let Some(w) = n.num("lineWidth") {
                    self.line_width = w as f32;
                }
                if let Some(w) = n.num("pointSize") {
                    self.point_size = w as f32;
                }
            }
            "Complexity" => {
                if let Some(v) = n.num("value") {
                    self.complexity = v as f32;
                }
            }
            "Font" | "FontStyle" => self.font = Some(n.clone()),
            "ProfileCoordinate2" => self.profile.0 = Some(n.clone()),
            "LinearProfile" => self.profile.1 = Some(n.clone()),
            "LightModel" => self.unlit = first_word(n, "model") == "BASE_COLOR",
            "Texture2" => {
                let on = !n.strings("filename").iter().all(|f| f.trim().is_empty())
                    || n.nums("image").is_some_and(|v| v.len() > 3);
                self.texture = on.then(|| n.clone());
            }
            "Texture2Transform" => self.tex_transform = self.tex_transform.then(tex_transform(n)),
            "TextureCoordinate2" => self.tex_source = TexSource::Points(n.clone()),
            "TextureCoordinatePlane" => self.tex_source = TexSource::Plane(n.clone()),
            "TextureCoordinateDefault" => self.tex_source = TexSource::Default,
            "TextureCoordinateBinding" => {
                self.texcoord_binding = Bind::parse(first_word(n, "value"));
            }
            _ => return false,
        }
        true
    }

    pub fn ptr(n: &Option<NodeRef>) -> usize {
        n.as_ref().map_or(0, |n| Rc::as_ptr(n) as usize)
    }
}

/// A Texture2Transform's fields (Inventor order: scale and rotate about
/// the centre, then translate).
fn tex_transform(n: &AstNode) -> TexTransform {
    TexTransform {
        translation: vec2(n, "translation", Vec2::ZERO),
        rotation: n.f32("rotation", 0.0),
        scale: vec2(n, "scaleFactor", Vec2::ONE),
        center: vec2(n, "center", Vec2::ZERO),
        order: TexTransformOrder::Inventor,
    }
}

fn vec2(n: &AstNode, field: &str, default: Vec2) -> Vec2 {
    match n.nums(field) {
        Some([x, y, ..]) if x.is_finite() && y.is_finite() => Vec2::new(*x as f32, *y as f32),
        _ => default,
    }
}

/// Points of an MFVec2f field.
pub fn points2(n: &AstNode, field: &str) -> Vec<Vec2> {
    n.nums(field)
        .map(|v| {
            v.chunks_exact(2)
                .map(|c| Vec2::new(c[0] as f32, c[1] as f32))
                .collect()
        })
        .unwrap_or_default()
}

fn first_word<'a>(n: &'a AstNode, field: &str) -> &'a str {
    n.words(field).first().map_or("", |s| s.as_str())
}

/// Colours of an MFColor field.
pub fn colors(n: &AstNode, field: &str) -> Vec<Vec3> {
    n.nums(field)
        .map(|v| {
            v.chunks_exact(3)
                .map(|c| Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32))
                .collect()
        })
        .unwrap_or_default()
}

/// Inventor packed colours `0xRRGGBBAA` as (rgb, transparency).
pub fn packed(v: &[f64]) -> Vec<(Vec3, f32)> {
    v.iter()
        .map(|&x| {
            let u = x as u32;
            let c = |s: u32| ((u >> s) & 0xff) as f32 / 255.0;
            (Vec3::new(c(24), c(16), c(8)), 1.0 - c(0))
        })
        .collect()
}
