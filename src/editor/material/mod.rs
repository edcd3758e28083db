//! The material panel (issue 12): which material the selection shows,
//! the panel's fields and buttons, and the state kept between events.
//!
//! A shape has one material; a group shows the first shape of its subtree
//! (in list order) and says how many shapes it holds when their materials
//! differ, so a user is never misled into thinking one edit recolours all
//! of them. Every field is a property tracks can drive (`anim::Property`:
//! diffuse, specular and emissive colours, shininess, transparency), so
//! each is keyable like a transform field. The texture row is not
//! animatable: its wrap toggles are plain undoable edits.
//!
//! This file is pure data and rules (it never names the `Editor`);
//! `thumb.rs` makes the texture thumbnail, `rows_ui.rs` is the rows'
//! component (layout, painting, its field press) and `route.rs` holds
//! the editor's side (its snapshot, edits, keys).

pub mod route;
pub mod rows_ui;
pub mod texture;
pub mod thumb;

use crate::anim::{Property, Target, TargetRef, Value};
use crate::scene::{Material, MaterialId, NodeId, NodeKind, Scene, Wrap};
use glam::Vec3;

/// Which value a material field edits (colour channels are 0..3 = r, g, b).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatField {
    Diffuse(u8),
    Specular(u8),
    Emissive(u8),
    Shininess,
    Transparency,
}

impl MatField {
    /// The five rows' fields, in panel order.
    pub const ROWS: [&'static [MatField]; 4] = [
        &[
            MatField::Diffuse(0),
            MatField::Diffuse(1),
            MatField::Diffuse(2),
        ],
        &[
            MatField::Specular(0),
            MatField::Specular(1),
            MatField::Specular(2),
        ],
        &[
            MatField::Emissive(0),
            MatField::Emissive(1),
            MatField::Emissive(2),
        ],
        &[MatField::Shininess, MatField::Transparency],
    ];

    /// The track property that drives this field.
    pub fn property(self) -> Property {
        match self {
            MatField::Diffuse(_) => Property::Diffuse,
            MatField::Specular(_) => Property::Specular,
            MatField::Emissive(_) => Property::Emissive,
            MatField::Shininess => Property::Shininess,
            MatField::Transparency => Property::Transparency,
        }
    }

    /// The field's name in messages ("Diffuse g", "Shininess").
    pub fn label(self) -> String {
        let rgb = |i: u8| ["r", "g", "b"][(i as usize).min(2)];
        match self {
            MatField::Diffuse(i) => format!("Diffuse {}", rgb(i)),
            MatField::Specular(i) => format!("Specular {}", rgb(i)),
            MatField::Emissive(i) => format!("Emissive {}", rgb(i)),
            MatField::Shininess => "Shininess".into(),
            MatField::Transparency => "Transparency".into(),
        }
    }

    /// Every material value is 0..1 (VRML97 §6.27; the exponent is
    /// shininess × 128).
    pub fn clamp(self, v: f32) -> f32 {
        v.clamp(0.0, 1.0)
    }

    pub fn read(self, m: &Material) -> f32 {
        match self {
            MatField::Diffuse(i) => m.diffuse[(i as usize).min(2)],
            MatField::Specular(i) => m.specular[(i as usize).min(2)],
            MatField::Emissive(i) => m.emissive[(i as usize).min(2)],
            MatField::Shininess => m.shininess,
            MatField::Transparency => m.transparency,
        }
    }

    /// Writes `v` (clamped) into `m`.
    pub fn write(self, m: &mut Material, v: f32) {
        let v = self.clamp(v);
        match self {
            MatField::Diffuse(i) => m.diffuse[(i as usize).min(2)] = v,
            MatField::Specular(i) => m.specular[(i as usize).min(2)] = v,
            MatField::Emissive(i) => m.emissive[(i as usize).min(2)] = v,
            MatField::Shininess => m.shininess = v,
            MatField::Transparency => m.transparency = v,
        }
    }
}

/// The value a key of `p` takes from material `m`.
pub fn property_value(m: &Material, p: Property) -> Option<Value> {
    Some(match p {
        Property::Diffuse => Value::Vec3(m.diffuse),
        Property::Specular => Value::Vec3(m.specular),
        Property::Emissive => Value::Vec3(m.emissive),
        Property::Shininess => Value::Scalar(m.shininess),
        Property::Transparency => Value::Scalar(m.transparency),
        _ => return None,
    })
}

/// The track target of property `p` of material `id`.
pub fn target(id: MaterialId, p: Property) -> Target {
    Target {
        of: TargetRef::Material(id),
        property: p,
    }
}

/// What the panel shows for a selection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shown {
    /// The shape whose material is shown (the first in the subtree).
    pub shape: NodeId,
    pub material: MaterialId,
    /// Shapes in the selection's subtree.
    pub shapes: usize,
    /// Their materials are not all alike (then the panel says so).
    pub differ: bool,
}

/// The material the selection `sel` shows, `None` without shapes.
pub fn shown(scene: &Scene, sel: NodeId) -> Option<Shown> {
    let shapes: Vec<(NodeId, MaterialId)> = crate::editor::ops::subtree(scene, sel)
        .into_iter()
        .filter_map(|n| match &scene.node(n).kind {
            NodeKind::Shape(s) if (s.material.0 as usize) < scene.materials.len() => {
                Some((n, s.material))
            }
            _ => None,
        })
        .collect();
    let &(shape, material) = shapes.first()?;
    let first = &scene.materials[material.0 as usize];
    let differ = shapes
        .iter()
        .any(|&(_, m)| m != material && !alike(first, &scene.materials[m.0 as usize]));
    Some(Shown {
        shape,
        material,
        shapes: shapes.len(),
        differ,
    })
}

/// Same look (the name aside): two copies of one material read from a
/// file are the same to the user.
fn alike(a: &Material, b: &Material) -> bool {
    Material {
        name: String::new(),
        ..a.clone()
    } == Material {
        name: String::new(),
        ..b.clone()
    }
}

/// Buttons of the panel (`panel::Action::Material`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatAction {
    /// Show the material panel in the properties' place.
    Open,
    /// Back to the object's properties.
    Close,
    /// Toggle the texture's wrap across (S) or up (T).
    WrapS,
    WrapT,
    /// Take the texture off the material.
    RemoveTexture,
    /// Choose an image file for the texture (file browser).
    LoadTexture,
}

/// The wrap a toggle click gives: repeat ⇄ clamp (mirror, which only glTF
/// says, goes to repeat).
pub fn next_wrap(w: Wrap) -> Wrap {
    match w {
        Wrap::Repeat => Wrap::Clamp,
        Wrap::Clamp | Wrap::Mirror => Wrap::Repeat,
    }
}

pub fn wrap_name(w: Wrap) -> &'static str {
    match w {
        Wrap::Repeat => "Repeat",
        Wrap::Clamp => "Clamp",
        Wrap::Mirror => "Mirror",
    }
}

/// The texture's image as the user knows it: the file name it was read
/// from (not the whole path), else the image's name, else "inline WxH".
pub fn texture_name(scene: &Scene, m: &Material) -> Option<String> {
    m.texture.as_ref().and_then(|t| image_name(scene, t))
}

/// The name shown for texture `t`'s image: the file name, else the
/// image's name, else `inline WxH`.
pub fn image_name(scene: &Scene, t: &crate::scene::Texture) -> Option<String> {
    let Some(img) = scene.image(t.image) else {
        return Some("(missing image)".into());
    };
    if let crate::scene::ImageSource::File { url, .. } = &img.source {
        let file = url.rsplit(['/', '\\']).next().unwrap_or(url);
        if !file.is_empty() {
            return Some(file.to_string());
        }
    }
    if !img.name.is_empty() {
        return Some(img.name.clone());
    }
    Some(format!("inline {}x{}", img.width(), img.height()))
}

/// A pending change on animated material properties (record mode off):
/// shown until the frame or the scene changes, K keys it.
#[derive(Clone, Debug, PartialEq)]
pub struct MatPending {
    pub material: MaterialId,
    /// The material as shown (the posed one with the change).
    pub value: Material,
    /// The changed properties (their tracks are set aside while shown).
    pub props: Vec<Property>,
    pub frame: f32,
    /// History revision when made (any command drops it).
    pub revision: u64,
}

/// What a field drag or typed value starts from.
#[derive(Clone, Debug, PartialEq)]
pub struct MatBase {
    pub material: MaterialId,
    /// The material as shown at press (posed, a pending change included).
    pub start: Material,
}

/// The panel's state kept by the editor.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MatState {
    /// The panel is shown in the properties' place (when the selection
    /// has a shape).
    pub open: bool,
    pub pending: Option<MatPending>,
}

/// A colour as the overlay's 0x00RRGGBB.
pub fn swatch(c: Vec3) -> u32 {
    crate::ui::theme::rgb(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Mesh, Node, Shape};

    fn two_shapes(same: bool) -> (Scene, NodeId) {
        let mut s = Scene::new();
        let mesh = s.add_mesh(Mesh::default());
        let a = s.add_material(Material::default());
        let b = s.add_material(Material {
            name: "other".into(),
            diffuse: if same { Vec3::splat(0.8) } else { Vec3::X },
            ..Material::default()
        });
        let g = s.add_node(None, Node::group("Pair"));
        for m in [a, b] {
            let shape = Shape { mesh, material: m };
            s.add_node(Some(g), Node::new("", NodeKind::Shape(shape)));
        }
        (s, g)
    }

    #[test]
    fn a_group_shows_its_first_shape_and_says_when_others_differ() {
        let (s, g) = two_shapes(false);
        let sh = shown(&s, g).unwrap();
        assert_eq!(
            (sh.material, sh.shapes, sh.differ),
            (MaterialId(0), 2, true)
        );
        let (s, g) = two_shapes(true);
        assert!(!shown(&s, g).unwrap().differ, "names alone do not differ");
        let mut e = Scene::new();
        let empty = e.add_node(None, Node::group("Empty"));
        assert_eq!(shown(&e, empty), None);
    }

    #[test]
    fn fields_read_write_and_clamp() {
        let mut m = Material::default();
        MatField::Specular(1).write(&mut m, 0.5);
        MatField::Transparency.write(&mut m, 3.0);
        assert_eq!(m.specular, Vec3::new(0.0, 0.5, 0.0));
        assert_eq!(MatField::Transparency.read(&m), 1.0);
        assert_eq!(
            property_value(&m, MatField::Specular(2).property()),
            Some(Value::Vec3(m.specular))
        );
        assert_eq!(MatField::Emissive(2).label(), "Emissive b");
        assert_eq!(next_wrap(Wrap::Repeat), Wrap::Clamp);
        assert_eq!(next_wrap(Wrap::Mirror), Wrap::Repeat);
    }
}
