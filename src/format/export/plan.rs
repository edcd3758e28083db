//! What the writers decide before printing a single byte: which DEF name
//! every node, material and mesh gets, and which nodes need a Transform
//! around their content.
//!
//! Both writers and the key note use the same plan, so a track's target in
//! the note names exactly the node the reader will create for it.
//!
//! Layout of one scene node `N` in a file:
//! * a `Group` node is one Transform (`DEF <wrapper>`),
//! * a Shape/Light/Camera node with an identity, un-animated transform, no
//!   children and nothing hidden is just its content (`DEF <content>`),
//! * otherwise it is `DEF <wrapper> Transform { children [ <content> … ] }`;
//!   the wrapper takes the node's own name, the content gets a generated
//!   name (`<name>_light`, `<name>_camera`) only when a track drives it.
//!
//! Names are made valid identifiers for both VRML97 and Inventor and unique
//! over the whole file, deterministically: nodes in depth-first order, then
//! materials, then meshes; a clash gets the smallest free `_N` suffix.

use crate::anim::{Property, TargetRef};
use crate::scene::{NodeId, NodeKind, RenderStyle, Scene, Transform};
use std::collections::HashSet;

/// Names and layout decisions for one scene.
#[derive(Clone, Debug, Default)]
pub struct WritePlan {
    /// DEF name of the Transform a node is written as (`None`: no wrapper,
    /// or a wrapper without a name).
    pub wrapper: Vec<Option<String>>,
    /// Whether the node is written inside its own Transform.
    pub wrapped: Vec<bool>,
    /// DEF name of the node's content (light, camera, shape).
    pub content: Vec<Option<String>>,
    pub materials: Vec<Option<String>>,
    pub meshes: Vec<Option<String>>,
    used: HashSet<String>,
}

/// Node-level properties: written on the wrapper Transform.
pub fn is_transform_property(p: Property) -> bool {
    matches!(
        p,
        Property::Translation | Property::Rotation | Property::Scale | Property::Visibility
    )
}

/// Words that cannot be DEF names in VRML97 or Inventor.
const RESERVED: &[&str] = &[
    "DEF",
    "USE",
    "ROUTE",
    "TO",
    "IS",
    "PROTO",
    "EXTERNPROTO",
    "TRUE",
    "FALSE",
    "NULL",
    "eventIn",
    "eventOut",
    "field",
    "exposedField",
];

/// Turns any string into a valid identifier: ASCII letters, digits and `_`,
/// not starting with a digit, not a reserved word. Empty stays empty.
pub fn sanitize(name: &str) -> String {
    let mut s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if s.starts_with(|c: char| c.is_ascii_digit()) || RESERVED.contains(&s.as_str()) {
        s.insert(0, '_');
    }
    s
}

impl WritePlan {
    /// Plans names and wrappers for `scene` (VRML97 layout).
    pub fn new(scene: &Scene) -> WritePlan {
        Self::build(scene, false)
    }

    /// The Inventor layout: as VRML97, except that a wrapped node with a
    /// transform always gets a name (an Inventor reader keeps a transform
    /// on a node only when the Transform is DEF'd), and meshes are not
    /// named (face sets carry their shape node's name).
    pub fn inventor(scene: &Scene) -> WritePlan {
        Self::build(scene, true)
    }

    fn build(scene: &Scene, inventor: bool) -> WritePlan {
        let n = scene.nodes.len();
        let mut plan = WritePlan {
            wrapper: vec![None; n],
            wrapped: vec![false; n],
            content: vec![None; n],
            materials: vec![None; scene.materials.len()],
            meshes: vec![None; scene.meshes.len()],
            used: HashSet::new(),
        };
        // What the tracks drive.
        let mut transform_animated = vec![false; n];
        let mut content_animated = vec![false; n];
        let mut material_animated = vec![false; scene.materials.len()];
        for t in &scene.animation.tracks {
            match t.target.of {
                TargetRef::Node(id) if (id.0 as usize) < n => {
                    if is_transform_property(t.target.property) {
                        transform_animated[id.0 as usize] = true;
                    } else {
                        content_animated[id.0 as usize] = true;
                    }
                }
                TargetRef::Material(id) if (id.0 as usize) < material_animated.len() => {
                    material_animated[id.0 as usize] = true;
                }
                _ => {}
            }
        }
        for id in scene.walk() {
            let i = id.0 as usize;
            let node = scene.node(id);
            let needs_note = !node.visible || node.style != RenderStyle::Filled;
            let wrapped = match node.kind {
                NodeKind::Group => true,
                _ => {
                    !node.transform.is_identity()
                        || transform_animated[i]
                        || !node.children.is_empty()
                        || needs_note
                }
            };
            plan.wrapped[i] = wrapped;
            let transformed = node.transform != Transform::default();
            let wants_name = !node.name.is_empty()
                || (inventor && wrapped && (transformed || !matches!(node.kind, NodeKind::Group)))
                || transform_animated[i]
                || needs_note
                || (!wrapped && content_animated[i]);
            if wrapped {
                if wants_name {
                    plan.wrapper[i] = Some(plan.claim(&node.name, "node"));
                }
                if content_animated[i] && !matches!(node.kind, NodeKind::Group) {
                    let base = match (&node.kind, plan.wrapper[i].as_deref()) {
                        (NodeKind::Light(_), Some(w)) => format!("{w}_light"),
                        (NodeKind::Camera(_), Some(w)) => format!("{w}_camera"),
                        (NodeKind::Light(_), None) => "light".to_string(),
                        (NodeKind::Camera(_), None) => "camera".to_string(),
                        (_, Some(w)) => format!("{w}_shape"),
                        (_, None) => "shape".to_string(),
                    };
                    plan.content[i] = Some(plan.claim(&base, "node"));
                }
            } else if wants_name {
                plan.content[i] = Some(plan.claim(&node.name, "node"));
            }
        }
        // Shared materials and meshes need a name so USE can share them.
        let mut material_uses = vec![0usize; scene.materials.len()];
        let mut mesh_uses = vec![0usize; scene.meshes.len()];
        for node in &scene.nodes {
            if let NodeKind::Shape(sh) = &node.kind {
                if let Some(u) = material_uses.get_mut(sh.material.0 as usize) {
                    *u += 1;
                }
                if let Some(u) = mesh_uses.get_mut(sh.mesh.0 as usize) {
                    *u += 1;
                }
            }
        }
        for (i, m) in scene.materials.iter().enumerate() {
            if !m.name.is_empty() || material_animated[i] || material_uses[i] > 1 {
                plan.materials[i] = Some(plan.claim(&m.name, "material"));
            }
        }
        for (i, m) in scene.meshes.iter().enumerate() {
            if !inventor && (!m.name.is_empty() || mesh_uses[i] > 1) {
                plan.meshes[i] = Some(plan.claim(&m.name, "mesh"));
            }
        }
        plan
    }

    /// Reserves a unique identifier based on `name` (or `fallback` when empty).
    fn claim(&mut self, name: &str, fallback: &str) -> String {
        let base = match sanitize(name) {
            s if s.is_empty() => fallback.to_string(),
            s => s,
        };
        let mut candidate = base.clone();
        let mut k = 1u32;
        while self.used.contains(&candidate) {
            candidate = format!("{base}_{k}");
            k += 1;
        }
        self.used.insert(candidate.clone());
        candidate
    }

    /// Reserves an internal name (interpolators, the clock) that cannot
    /// clash with a scene name.
    pub fn internal(&mut self, base: &str) -> String {
        self.claim(base, "_animed")
    }

    /// The name a track's target is written under, as the key note spells it:
    /// `("node" | "material", name)`.
    pub fn target_name(&self, of: TargetRef, property: Property) -> Option<(&'static str, &str)> {
        match of {
            TargetRef::Node(NodeId(i)) => {
                let i = i as usize;
                let name = if is_transform_property(property) || !*self.wrapped.get(i)? {
                    self.wrapper
                        .get(i)?
                        .as_deref()
                        .or(self.content.get(i)?.as_deref())
                } else {
                    self.content.get(i)?.as_deref()
                };
                name.map(|n| ("node", n))
            }
            TargetRef::Material(m) => self
                .materials
                .get(m.0 as usize)?
                .as_deref()
                .map(|n| ("material", n)),
        }
    }

    /// The name a node is known by in the file (wrapper first).
    pub fn node_name(&self, id: NodeId) -> Option<&str> {
        let i = id.0 as usize;
        self.wrapper
            .get(i)?
            .as_deref()
            .or(self.content.get(i)?.as_deref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Repeat, Target, Track};
    use crate::scene::{Light, LightKind, Node};

    #[test]
    fn sanitize_makes_identifiers() {
        assert_eq!(sanitize("my box.1"), "my_box_1");
        assert_eq!(sanitize("3d"), "_3d");
        assert_eq!(sanitize("TRUE"), "_TRUE");
        assert_eq!(sanitize(""), "");
    }

    #[test]
    fn duplicates_and_empty_names_get_suffixes() {
        let mut s = Scene::new();
        let a = s.add_node(None, Node::group("a"));
        let b = s.add_node(None, Node::group("a"));
        let c = s.add_node(None, Node::group(""));
        let d = s.add_node(None, Node::group("a_1"));
        s.animation.tracks.push(Track {
            target: Target {
                of: TargetRef::Node(c),
                property: Property::Translation,
            },
            repeat: Repeat::Constant,
            keys: Keys::Vec3(vec![Key::new(0.0, glam::Vec3::ZERO)]),
        });
        let p = WritePlan::new(&s);
        assert_eq!(p.node_name(a), Some("a"));
        assert_eq!(p.node_name(b), Some("a_1"));
        assert_eq!(p.node_name(c), Some("node"));
        assert_eq!(p.node_name(d), Some("a_1_1"));
    }

    #[test]
    fn light_tracks_name_the_content_inside_a_wrapper() {
        let mut s = Scene::new();
        let mut n = Node::new("Lamp", NodeKind::Light(Light::new(LightKind::Point)));
        n.transform.translation = glam::Vec3::X;
        let id = s.add_node(None, n);
        s.animation.tracks.push(Track {
            target: Target {
                of: TargetRef::Node(id),
                property: Property::LightIntensity,
            },
            repeat: Repeat::Constant,
            keys: Keys::Scalar(vec![Key::new(0.0, 1.0)]),
        });
        let p = WritePlan::new(&s);
        assert!(p.wrapped[0]);
        assert_eq!(
            p.target_name(TargetRef::Node(id), Property::LightIntensity),
            Some(("node", "Lamp_light"))
        );
        assert_eq!(
            p.target_name(TargetRef::Node(id), Property::Translation),
            Some(("node", "Lamp"))
        );
    }
}
