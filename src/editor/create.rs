//! What the Add menu (toolbar `Add`, Shift+A) makes: primitives, an empty
//! group, a camera at the current view, and the three lights. Pure scene
//! edits on a copy; the editor wraps them in one undoable command.

use super::ops::{self, NewLight};
use crate::scene::primitives::{box_mesh, cone, cylinder, sphere};
use crate::scene::{Camera, Material, Mesh, Node, NodeId, NodeKind, Scene, Shape, Transform};
use glam::{Mat4, Quat, Vec2, Vec3};

/// One entry of the Add menu.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NewThing {
    Box,
    Sphere,
    Cone,
    Cylinder,
    Plane,
    /// An empty group (a parent to animate things together).
    Empty,
    /// A camera where the view is now.
    Camera,
    Light(NewLight),
}

impl NewThing {
    /// Every entry, in menu order.
    pub const ALL: [NewThing; 10] = [
        NewThing::Box,
        NewThing::Sphere,
        NewThing::Cone,
        NewThing::Cylinder,
        NewThing::Plane,
        NewThing::Empty,
        NewThing::Camera,
        NewThing::Light(NewLight::Point),
        NewThing::Light(NewLight::Spot),
        NewThing::Light(NewLight::Directional),
    ];

    /// The menu label (and the base of the new node's name).
    pub fn label(self) -> &'static str {
        match self {
            NewThing::Box => "Box",
            NewThing::Sphere => "Sphere",
            NewThing::Cone => "Cone",
            NewThing::Cylinder => "Cylinder",
            NewThing::Plane => "Plane",
            NewThing::Empty => "Empty",
            NewThing::Camera => "Camera",
            NewThing::Light(NewLight::Point) => "Point light",
            NewThing::Light(NewLight::Spot) => "Spot light",
            NewThing::Light(NewLight::Directional) => "Directional light",
        }
    }
}

/// A size that suits what the user looks at: a tenth of the orbit
/// camera's `distance` (so a new thing shows at about the same size on
/// screen however far the view is zoomed), rounded to 1, 2 or 5 times a
/// power of ten so numbers typed later stay round; 1 in an empty scene
/// (`empty`), as the editor's default view is 10 units away.
pub fn size_for(distance: f32, empty: bool) -> f32 {
    if empty || !distance.is_finite() || distance <= 0.0 {
        return 1.0;
    }
    let x = distance * 0.1;
    let p = 10f32.powf(x.log10().floor());
    let m = x / p;
    let step = if m < 1.5 {
        1.0
    } else if m < 3.5 {
        2.0
    } else if m < 7.5 {
        5.0
    } else {
        10.0
    };
    step * p
}

/// A square of side `size` in the xz plane facing +y (two triangles).
pub fn plane_mesh(size: f32) -> Mesh {
    let h = size * 0.5;
    let mut m = Mesh {
        name: "Plane".into(),
        ..Mesh::default()
    };
    for (x, z) in [(-h, h), (h, h), (h, -h), (-h, -h)] {
        m.positions.push(Vec3::new(x, 0.0, z));
        m.normals.push(Vec3::Y);
        m.texcoords
            .push(Vec2::new((x / size) + 0.5, 0.5 - (z / size)));
    }
    m.triangles = vec![[0, 1, 2], [0, 2, 3]];
    m
}

/// Adds `what` to `scene` at `at` with size `size`; `eye` is where the
/// view is (for a camera). Returns the new node (a root, uniquely named).
pub fn add(scene: &mut Scene, what: NewThing, at: Vec3, size: f32, eye: Vec3) -> NodeId {
    let mesh = match what {
        NewThing::Box => Some(box_mesh(Vec3::splat(size))),
        NewThing::Sphere => Some(sphere(size * 0.5)),
        NewThing::Cone => Some(cone(size * 0.5, size, true, true)),
        NewThing::Cylinder => Some(cylinder(size * 0.5, size, true, true, true)),
        NewThing::Plane => Some(plane_mesh(size * 2.0)),
        NewThing::Empty | NewThing::Camera | NewThing::Light(_) => None,
    };
    let name = ops::unique_name(scene, what.label().split(' ').next().unwrap_or("Node"));
    match (what, mesh) {
        (NewThing::Light(which), _) => {
            let (c, r) = (at, size);
            let id = ops::add_light(scene, which, c, r);
            if which != NewLight::Directional {
                if let NodeKind::Light(l) = &mut scene.nodes[id.0 as usize].kind {
                    l.location = at;
                }
            }
            id
        }
        (NewThing::Camera, _) => {
            let dir = (at - eye).normalize_or(Vec3::NEG_Z);
            let cam = Camera {
                position: eye,
                orientation: look_rotation(dir),
                description: name.clone(),
                focal_distance: (at - eye).length().max(1e-3),
                ..Camera::default()
            };
            scene.add_node(None, Node::new(name, NodeKind::Camera(cam)))
        }
        (_, Some(mesh)) => {
            let mesh = scene.add_mesh(mesh);
            let material = scene.add_material(Material::default());
            let t = Transform::from_translation(at);
            let g = scene.add_node(None, Node::group(name).with_transform(t));
            let shape = NodeKind::Shape(Shape { mesh, material });
            scene.add_node(Some(g), Node::new("", shape));
            g
        }
        (_, None) => {
            let t = Transform::from_translation(at);
            scene.add_node(None, Node::group(name).with_transform(t))
        }
    }
}

/// The rotation that turns a camera's −z (its view direction) to `dir`,
/// keeping +y up (VRML's Viewpoint orientation).
pub fn look_rotation(dir: Vec3) -> Quat {
    let f = dir.normalize_or(Vec3::NEG_Z);
    let right = f.cross(Vec3::Y);
    let right = if right.length_squared() < 1e-8 {
        Vec3::X
    } else {
        right.normalize()
    };
    let up = right.cross(f);
    Quat::from_mat3(&glam::Mat3::from_cols(right, up, -f)).normalize()
}

/// Copies the subtree at `id` (nodes, their own materials, and every track
/// that animates them or those materials) beside the original, under the
/// same parent; the copy's top node gets a unique name. Returns it.
pub fn duplicate(scene: &mut Scene, id: NodeId) -> NodeId {
    use crate::anim::TargetRef;
    let nodes = ops::subtree(scene, id);
    let mut map = std::collections::HashMap::new();
    let mut mats = std::collections::HashMap::new();
    for &old in &nodes {
        let mut n = scene.node(old).clone();
        if old == id {
            n.name = ops::unique_name(scene, base_name(&n.name));
        }
        if let NodeKind::Shape(s) = &mut n.kind {
            let m = *mats.entry(s.material).or_insert_with(|| {
                let copy = scene.materials[s.material.0 as usize].clone();
                scene.add_material(copy)
            });
            s.material = m;
        }
        let parent = match scene.node(old).parent {
            Some(p) => map.get(&p).copied().or(Some(p)),
            None => None,
        };
        let parent = if old == id {
            scene.node(id).parent
        } else {
            parent
        };
        let new = scene.add_node(parent, n);
        map.insert(old, new);
    }
    let copies: Vec<_> = scene
        .animation
        .tracks
        .iter()
        .filter_map(|t| {
            let of = match t.target.of {
                TargetRef::Node(n) => TargetRef::Node(*map.get(&n)?),
                TargetRef::Material(m) => TargetRef::Material(*mats.get(&m)?),
            };
            let mut c = t.clone();
            c.target.of = of;
            Some(c)
        })
        .collect();
    scene.animation.tracks.extend(copies);
    map[&id]
}

/// "Box12" → "Box": the base a duplicate's number goes after.
fn base_name(name: &str) -> &str {
    let b = name.trim_end_matches(|c: char| c.is_ascii_digit());
    if b.is_empty() {
        "Object"
    } else {
        b
    }
}

/// Moves `id` under `parent` (`None`: to the top level), keeping its
/// local transform. Refuses to put a node under itself or its own
/// descendants.
pub fn reparent(scene: &mut Scene, id: NodeId, parent: Option<NodeId>) -> Result<(), String> {
    if let Some(p) = parent {
        if ops::subtree(scene, id).contains(&p) {
            return Err(format!(
                "cannot put {} under itself or its own child",
                scene.node(id).name
            ));
        }
    }
    if scene.node(id).parent == parent {
        return Ok(());
    }
    match scene.node(id).parent {
        Some(old) => scene.nodes[old.0 as usize].children.retain(|&c| c != id),
        None => scene.roots.retain(|&r| r != id),
    }
    scene.nodes[id.0 as usize].parent = parent;
    match parent {
        Some(p) => scene.nodes[p.0 as usize].children.push(id),
        None => scene.roots.push(id),
    }
    Ok(())
}

/// Moves `id` under `parent` as [`reparent`] does, but keeps where it is
/// in the world: `old_parent` and `new_parent` are the two parents' world
/// matrices (identity for the top level) at the frame shown, and the
/// correction C = new⁻¹·old is folded into the node. When C is a
/// similarity (rotation, uniform scale, translation — every parent made in
/// the editor) it goes into the translation, rotation and scale and into
/// every key of the node's tracks of those, so the keys still play where
/// they did; otherwise (a sheared parent) it goes into the node's extra
/// matrix, which the keys' values stay inside. Exact for still parents; an
/// animated parent is matched at the frame shown, as Blender does.
pub fn reparent_keeping_world(
    scene: &mut Scene,
    id: NodeId,
    parent: Option<NodeId>,
    old_parent: Mat4,
    new_parent: Mat4,
) -> Result<(), String> {
    use crate::anim::{Keys, Property, TargetRef};
    let before = scene.node(id).parent;
    reparent(scene, id, parent)?;
    if before == parent {
        return Ok(());
    }
    let c = new_parent.inverse() * old_parent;
    if !c.is_finite() {
        return Err("the new parent is scaled to nothing; cannot keep the position".into());
    }
    let sim = similarity(&c);
    let tr = &mut scene.nodes[id.0 as usize].transform;
    let Some((cs, cr, _)) = sim.filter(|_| tr.extra.is_none()) else {
        tr.extra = Some(c * tr.extra.unwrap_or(Mat4::IDENTITY));
        return Ok(());
    };
    let center = tr.center;
    let point = |t: Vec3| c.transform_point3(t + center) - center;
    tr.translation = point(tr.translation);
    tr.rotation = (cr * tr.rotation).normalize();
    tr.scale *= cs;
    for t in &mut scene.animation.tracks {
        if t.target.of != TargetRef::Node(id) {
            continue;
        }
        match (t.target.property, &mut t.keys) {
            (Property::Translation, Keys::Vec3(k)) => {
                k.iter_mut().for_each(|k| k.value = point(k.value))
            }
            (Property::Rotation, Keys::Rotation(k)) => k
                .iter_mut()
                .for_each(|k| k.value = (cr * k.value).normalize()),
            (Property::Scale, Keys::Vec3(k)) => k.iter_mut().for_each(|k| k.value *= cs),
            _ => {}
        }
    }
    Ok(())
}

/// `m` as (uniform scale, rotation, translation) when it is a similarity
/// (within 1e-4 relative), else `None`.
fn similarity(m: &Mat4) -> Option<(f32, glam::Quat, Vec3)> {
    let (s, r, t) = m.to_scale_rotation_translation();
    let k = (s.x + s.y + s.z) / 3.0;
    let uniform = k > 0.0 && (s - Vec3::splat(k)).abs().max_element() <= 1e-4 * k;
    let back = Mat4::from_scale_rotation_translation(Vec3::splat(k), r, t);
    let tol = 1e-4
        * (1.0
            + m.abs()
                .to_cols_array()
                .iter()
                .fold(0.0f32, |a, &b| a.max(b)));
    let same = (back - *m).abs().to_cols_array().iter().all(|&d| d <= tol);
    (uniform && same).then_some((k, r, t))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parenting_keeps_the_world_transform_and_the_keys_world_path() {
        use crate::anim::{Key, Keys, Property, Repeat, Target, TargetRef, Track};
        use glam::Quat;
        let mut s = Scene::new();
        let mut pt = crate::scene::Transform::from_translation(Vec3::new(3.0, 1.0, -2.0));
        pt.rotation = Quat::from_rotation_y(0.7);
        pt.scale = Vec3::splat(2.0);
        let p = s.add_node(None, Node::new("P", NodeKind::Group));
        s.nodes[p.0 as usize].transform = pt;
        let b = s.add_node(None, Node::new("B", NodeKind::Group));
        s.nodes[b.0 as usize].transform.translation = Vec3::new(1.0, 2.0, 3.0);
        s.nodes[b.0 as usize].transform.rotation = Quat::from_rotation_x(0.3);
        let keys = vec![
            Key::new(0.0, Vec3::ZERO),
            Key::new(10.0, Vec3::new(4.0, 0.0, 0.0)),
        ];
        let target = Target {
            of: TargetRef::Node(b),
            property: Property::Translation,
        };
        s.animation
            .tracks
            .push(Track::new(target, Repeat::Constant, Keys::Vec3(keys)).unwrap());
        let world_b = s.node(b).transform.matrix();
        reparent_keeping_world(&mut s, b, Some(p), Mat4::IDENTITY, pt.matrix()).unwrap();
        let now = pt.matrix() * s.node(b).transform.matrix();
        assert!(
            (now - world_b)
                .abs()
                .to_cols_array()
                .iter()
                .all(|d| *d < 1e-4),
            "{now} vs {world_b}"
        );
        assert_eq!(
            s.node(b).transform.extra,
            None,
            "a similarity goes into T/R/S"
        );
        // The key at frame 10 still puts B at world (4, 0, 0).
        let Keys::Vec3(k) = &s.animation.tracks[0].keys else {
            panic!()
        };
        let w = pt.matrix().transform_point3(k[1].value);
        assert!((w - Vec3::new(4.0, 0.0, 0.0)).length() < 1e-4, "{w}");
        // Back to the top level: where it was.
        reparent_keeping_world(&mut s, b, None, pt.matrix(), Mat4::IDENTITY).unwrap();
        assert!((s.node(b).transform.translation - Vec3::new(1.0, 2.0, 3.0)).length() < 1e-4);
        // Under a non-uniformly scaled, turned parent: the extra matrix.
        let shear = Mat4::from_scale(Vec3::new(1.0, 3.0, 1.0)) * Mat4::from_rotation_z(0.5);
        reparent_keeping_world(&mut s, b, Some(p), Mat4::IDENTITY, shear).unwrap();
        let now = shear * s.node(b).transform.matrix();
        assert!((now - world_b)
            .abs()
            .to_cols_array()
            .iter()
            .all(|d| *d < 1e-4));
        assert!(s.node(b).transform.extra.is_some());
    }

    #[test]
    fn sizes_are_round_and_follow_the_scene() {
        assert_eq!(size_for(10.0, true), 1.0);
        assert_eq!(size_for(10.0, false), 1.0);
        assert_eq!(size_for(25.0, false), 2.0);
        assert_eq!(size_for(50.0, false), 5.0);
        assert!((size_for(0.5, false) - 0.05).abs() < 1e-6);
    }

    #[test]
    fn new_things_are_named_uniquely_and_placed() {
        let mut s = Scene::new();
        let at = Vec3::new(1.0, 2.0, 3.0);
        let a = add(&mut s, NewThing::Box, at, 1.0, Vec3::Z * 10.0);
        let b = add(&mut s, NewThing::Box, at, 1.0, Vec3::Z * 10.0);
        assert_eq!(s.node(a).name, "Box1");
        assert_eq!(s.node(b).name, "Box2");
        assert_eq!(s.node(a).transform.translation, at);
        let m = &s.meshes[0];
        let (lo, hi) = m.bounds().unwrap();
        assert_eq!(hi - lo, Vec3::ONE, "a unit box");
        let c = add(
            &mut s,
            NewThing::Camera,
            Vec3::ZERO,
            1.0,
            Vec3::new(0.0, 0.0, 5.0),
        );
        let NodeKind::Camera(cam) = &s.node(c).kind else {
            panic!("a camera")
        };
        let view = cam.orientation * Vec3::NEG_Z;
        assert!((view - Vec3::NEG_Z).length() < 1e-5, "{view}");
        let l = add(&mut s, NewThing::Light(NewLight::Point), at, 1.0, Vec3::Z);
        assert_eq!(s.node(l).light().unwrap().location, at);
        assert_eq!(s.node(l).name, "Lamp1");
    }

    #[test]
    fn duplicates_carry_their_tracks_and_parenting_refuses_loops() {
        use crate::anim::{Property, Target, TargetRef};
        let mut s = Scene::new();
        let a = add(&mut s, NewThing::Box, Vec3::ZERO, 1.0, Vec3::Z);
        let t = Target {
            of: TargetRef::Node(a),
            property: Property::Translation,
        };
        s.animation
            .set_key(t, 5.0, crate::anim::Value::Vec3(Vec3::X))
            .unwrap();
        let n = s.nodes.len();
        let b = duplicate(&mut s, a);
        assert_eq!(s.nodes.len(), 2 * n, "group and shape copied");
        assert_eq!(s.node(b).name, "Box2");
        let tb = Target {
            of: TargetRef::Node(b),
            property: Property::Translation,
        };
        assert!(s.animation.track(tb).is_some(), "the copy is animated too");
        let child = s.node(a).children[0];
        assert!(reparent(&mut s, a, Some(child)).is_err());
        reparent(&mut s, b, Some(a)).unwrap();
        assert_eq!(s.node(b).parent, Some(a));
        assert!(!s.roots.contains(&b));
        reparent(&mut s, b, None).unwrap();
        assert!(s.roots.contains(&b) && !s.node(a).children.contains(&b));
    }
}
