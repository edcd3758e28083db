//! Scene operations behind the editor's commands: bounds for framing,
//! the object and light lists, picking targets, deleting a subtree and
//! grafting an imported scene. Pure functions on `Scene`.

use crate::anim::{Pose, TargetRef};
use crate::scene::{Light, LightKind, MaterialId, MeshId, Node, NodeId, NodeKind, Scene};
use glam::{Mat4, Vec3};

/// Nodes of the subtree rooted at `id` (itself first).
pub fn subtree(scene: &Scene, id: NodeId) -> Vec<NodeId> {
    let mut out = Vec::new();
    let mut stack = vec![id];
    while let Some(n) = stack.pop() {
        if n.0 as usize >= scene.nodes.len() {
            continue;
        }
        out.push(n);
        stack.extend(scene.node(n).children.iter().rev().copied());
    }
    out
}

fn grow(b: &mut Option<(Vec3, Vec3)>, p: Vec3) {
    *b = Some(match *b {
        Some((lo, hi)) => (lo.min(p), hi.max(p)),
        None => (p, p),
    });
}

/// World-space bounds of the visible shapes (and lights) among `nodes`.
pub fn bounds_of(scene: &Scene, pose: &Pose, nodes: &[NodeId]) -> Option<(Vec3, Vec3)> {
    let mut b = None;
    for &id in nodes {
        let i = id.0 as usize;
        let world = pose.world.get(i).copied().unwrap_or(Mat4::IDENTITY);
        match &scene.node(id).kind {
            NodeKind::Shape(s) => {
                if !pose.visible.get(i).copied().unwrap_or(true) {
                    continue;
                }
                let Some((lo, hi)) = scene.meshes.get(s.mesh.0 as usize).and_then(|m| m.bounds())
                else {
                    continue;
                };
                for k in 0..8 {
                    let c = Vec3::new(
                        if k & 1 == 0 { lo.x } else { hi.x },
                        if k & 2 == 0 { lo.y } else { hi.y },
                        if k & 4 == 0 { lo.z } else { hi.z },
                    );
                    grow(&mut b, world.transform_point3(c));
                }
            }
            NodeKind::Light(l) => {
                let l = pose.light(id).unwrap_or(l);
                grow(&mut b, world.transform_point3(l.location));
            }
            _ => {}
        }
    }
    b
}

/// Bounds of everything in the scene.
pub fn scene_bounds(scene: &Scene, pose: &Pose) -> Option<(Vec3, Vec3)> {
    bounds_of(scene, pose, &scene.walk())
}

/// A bounding sphere (centre, radius) of optional bounds, with a default
/// for empty scenes.
pub fn sphere(b: Option<(Vec3, Vec3)>) -> (Vec3, f32) {
    match b {
        Some((lo, hi)) => ((lo + hi) * 0.5, ((hi - lo).length() * 0.5).max(0.5)),
        None => (Vec3::ZERO, 3.0),
    }
}

/// What clicking a drawn node selects: the nearest named node at or above
/// it (a VRML `DEF Box Transform { Shape … }` selects `Box`), else itself.
pub fn pick_target(scene: &Scene, id: NodeId) -> NodeId {
    let mut cur = Some(id);
    while let Some(c) = cur {
        if c.0 as usize >= scene.nodes.len() {
            break;
        }
        if !scene.node(c).name.is_empty() {
            return c;
        }
        cur = scene.node(c).parent;
    }
    id
}

/// The objects list: (node, depth) in tree order. Lists named nodes and
/// shapes; lights and cameras have their own lists or none; unnamed groups
/// are passed through (their children are listed at their depth).
pub fn objects(scene: &Scene) -> Vec<(NodeId, usize)> {
    let mut out = Vec::new();
    let mut stack: Vec<(NodeId, usize)> = scene.roots.iter().rev().map(|&r| (r, 0)).collect();
    while let Some((id, depth)) = stack.pop() {
        let n = scene.node(id);
        let listed = match n.kind {
            NodeKind::Light(_) | NodeKind::Camera(_) => false,
            NodeKind::Group => !n.name.is_empty(),
            NodeKind::Shape(_) => {
                !n.name.is_empty() || n.parent.is_none_or(|p| scene.node(p).name.is_empty())
            }
        };
        if listed {
            out.push((id, depth));
        }
        let d = if listed { depth + 1 } else { depth };
        // An object's unnamed shapes are part of it, not separate rows.
        let children: Vec<NodeId> = n
            .children
            .iter()
            .rev()
            .copied()
            .filter(|&c| {
                let cn = scene.node(c);
                !(listed && cn.name.is_empty() && matches!(cn.kind, NodeKind::Shape(_)))
            })
            .collect();
        stack.extend(children.into_iter().map(|c| (c, d)));
    }
    out
}

/// Every light node in tree order.
pub fn lights(scene: &Scene) -> Vec<NodeId> {
    scene
        .walk()
        .into_iter()
        .filter(|&id| matches!(scene.node(id).kind, NodeKind::Light(_)))
        .collect()
}

/// A label for lists: the node's name, or its kind and index.
pub fn display_name(scene: &Scene, id: NodeId) -> String {
    let n = scene.node(id);
    if !n.name.is_empty() {
        return n.name.clone();
    }
    let kind = match &n.kind {
        NodeKind::Group => "Group",
        NodeKind::Shape(_) => "Shape",
        NodeKind::Camera(_) => "Camera",
        NodeKind::Light(l) => light_kind_name(l),
    };
    format!("{kind} #{}", id.0)
}

pub fn light_kind_name(l: &Light) -> &'static str {
    match l.kind {
        LightKind::Directional => "DirectionalLight",
        LightKind::Point => "PointLight",
        LightKind::Spot { .. } => "SpotLight",
    }
}

/// A name not yet used in the scene: `base1`, `base2`, …
pub fn unique_name(scene: &Scene, base: &str) -> String {
    (1..)
        .map(|i| format!("{base}{i}"))
        .find(|n| scene.find_node(n).is_none())
        .unwrap_or_else(|| base.to_string())
}

/// Which new light to add.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NewLight {
    Directional,
    Point,
    Spot,
}

/// Adds a light placed to light the scene of bounding sphere (c, r) from
/// above and in front; returns its node.
pub fn add_light(scene: &mut Scene, which: NewLight, center: Vec3, r: f32) -> NodeId {
    let (mut light, base) = match which {
        NewLight::Directional => (Light::new(LightKind::Directional), "Sun"),
        NewLight::Point => (Light::new(LightKind::Point), "Lamp"),
        NewLight::Spot => (Light::spot(), "Spot"),
    };
    let loc = center + Vec3::new(0.6, 1.2, 1.0) * r.max(1.0);
    light.location = if which == NewLight::Directional {
        Vec3::ZERO
    } else {
        loc
    };
    light.direction = (center - loc).normalize_or(Vec3::NEG_Y);
    light.radius = (r * 20.0).max(100.0);
    let name = unique_name(scene, base);
    scene.add_node(None, Node::new(name, NodeKind::Light(light)))
}

/// A point the orbit camera sees for sure: above, right of and in front
/// of its `target` by fractions of the eye `distance` (at 45° field of view
/// the visible half-height there is about 0.3·distance).
pub fn in_view_spot(target: Vec3, back: Vec3, distance: f32) -> Vec3 {
    let right = Vec3::Y.cross(back).normalize_or(Vec3::X);
    let up = back.cross(right);
    target + (up * 0.2 + right * 0.15 + back * 0.25) * distance
}

/// The scene without the subtree at `id`: the arena is compacted, ids in
/// the tree and in tracks are remapped, tracks of removed nodes dropped.
pub fn remove_subtree(scene: &Scene, id: NodeId) -> Scene {
    let gone: std::collections::HashSet<NodeId> = subtree(scene, id).into_iter().collect();
    let mut map = vec![None; scene.nodes.len()];
    let mut next = 0u32;
    for (i, m) in map.iter_mut().enumerate() {
        if !gone.contains(&NodeId(i as u32)) {
            *m = Some(NodeId(next));
            next += 1;
        }
    }
    let remap = |n: NodeId| map.get(n.0 as usize).copied().flatten();
    let mut out = scene.clone();
    out.nodes = scene
        .nodes
        .iter()
        .enumerate()
        .filter(|(i, _)| map[*i].is_some())
        .map(|(_, n)| {
            let mut n = n.clone();
            n.parent = n.parent.and_then(remap);
            n.children = n.children.iter().filter_map(|&c| remap(c)).collect();
            n
        })
        .collect();
    out.roots = scene.roots.iter().filter_map(|&r| remap(r)).collect();
    out.animation.tracks.retain_mut(|t| match t.target.of {
        TargetRef::Node(n) => match remap(n) {
            Some(m) => {
                t.target.of = TargetRef::Node(m);
                true
            }
            None => false,
        },
        TargetRef::Material(_) => true,
    });
    out.remap_skins(remap);
    out
}

/// Adds all of `other` under a new root group called `name` (its meshes,
/// materials, nodes and tracks are appended with their ids shifted).
/// Returns the new group.
pub fn graft(scene: &mut Scene, other: &Scene, name: &str) -> NodeId {
    let mesh_off = scene.meshes.len() as u32;
    let mat_off = scene.materials.len() as u32;
    let skin_off = scene.skins.len() as u32;
    scene.meshes.extend(other.meshes.iter().cloned());
    scene.materials.extend(other.materials.iter().cloned());
    let group = scene.add_node(None, Node::group(unique_or(scene, name)));
    let node_off = scene.nodes.len() as u32;
    let shift = |n: NodeId| NodeId(n.0 + node_off);
    for n in &other.nodes {
        let mut n = n.clone();
        n.parent = Some(n.parent.map_or(group, shift));
        n.children = n.children.iter().map(|&c| shift(c)).collect();
        if let NodeKind::Shape(s) = &mut n.kind {
            s.mesh = MeshId(s.mesh.0 + mesh_off);
            s.material = MaterialId(s.material.0 + mat_off);
        }
        n.skin = n.skin.map(|k| crate::scene::SkinId(k.0 + skin_off));
        scene.nodes.push(n);
    }
    // The file's skins, their joints shifted like the nodes.
    scene.skins.extend(
        other
            .skins
            .iter()
            .filter_map(|s| s.with_joints_mapped(|j| Some(shift(j)))),
    );
    let new_roots: Vec<NodeId> = other.roots.iter().map(|&r| shift(r)).collect();
    scene.node_mut(group).children = new_roots;
    for t in &other.animation.tracks {
        let mut t = t.clone();
        t.target.of = match t.target.of {
            TargetRef::Node(n) => TargetRef::Node(shift(n)),
            TargetRef::Material(m) => TargetRef::Material(MaterialId(m.0 + mat_off)),
        };
        scene.animation.tracks.push(t);
    }
    group
}

fn unique_or(scene: &Scene, name: &str) -> String {
    if name.is_empty() || scene.find_node(name).is_some() {
        unique_name(scene, if name.is_empty() { "Import" } else { name })
    } else {
        name.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::evaluate;
    use crate::scene::{Material, Mesh, Shape, Transform};

    fn cube_scene() -> Scene {
        let mut s = Scene::new();
        let mesh = s.add_mesh(Mesh {
            positions: vec![Vec3::splat(-1.0), Vec3::splat(1.0), Vec3::X],
            triangles: vec![[0, 1, 2]],
            ..Mesh::default()
        });
        let mat = s.add_material(Material::default());
        let g = s.add_node(
            None,
            Node::group("Box")
                .with_transform(Transform::from_translation(Vec3::new(10.0, 0.0, 0.0))),
        );
        s.add_node(
            Some(g),
            Node::new(
                "",
                NodeKind::Shape(Shape {
                    mesh,
                    material: mat,
                }),
            ),
        );
        s
    }

    #[test]
    fn bounds_follow_world_transforms() {
        let s = cube_scene();
        let pose = evaluate(&s, 0.0);
        let (lo, hi) = scene_bounds(&s, &pose).unwrap();
        assert_eq!(lo, Vec3::new(9.0, -1.0, -1.0));
        assert_eq!(hi, Vec3::new(11.0, 1.0, 1.0));
    }

    #[test]
    fn picking_a_shape_selects_its_named_object() {
        let s = cube_scene();
        assert_eq!(pick_target(&s, NodeId(1)), NodeId(0));
        assert_eq!(objects(&s), vec![(NodeId(0), 0)]);
    }

    #[test]
    fn remove_and_graft_keep_ids_consistent() {
        let mut s = cube_scene();
        let l = add_light(&mut s, NewLight::Point, Vec3::ZERO, 1.0);
        assert_eq!(lights(&s), vec![l]);
        let other = cube_scene();
        let g = graft(&mut s, &other, "Box");
        assert_eq!(s.node(g).name, "Box1");
        assert_eq!(s.nodes.len(), 6);
        let inner = s.node(g).children[0];
        assert_eq!(s.node(inner).parent, Some(g));
        assert_eq!(s.meshes.len(), 2);
        let shape = s.node(inner).children[0];
        match &s.node(shape).kind {
            NodeKind::Shape(sh) => assert_eq!(sh.mesh, MeshId(1)),
            _ => panic!("expected the grafted shape"),
        }
        // Remove the first box: everything after it shifts down by two.
        let r = remove_subtree(&s, NodeId(0));
        assert_eq!(r.nodes.len(), 4);
        assert_eq!(r.roots.len(), 2);
        assert_eq!(r.node(r.roots[0]).name, "Lamp1");
        let g2 = r.roots[1];
        assert_eq!(r.node(g2).name, "Box1");
        for id in r.walk() {
            for &c in &r.node(id).children {
                assert_eq!(r.node(c).parent, Some(id));
            }
        }
    }
}
