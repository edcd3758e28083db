//! `evaluate` / `evaluate_into`: every target kind, hierarchy, visibility,
//! seconds → frames, repeat modes, and no scene mutation.

use animed::internals::anim::{
    evaluate, evaluate_into, Interp, Key, Keys, Pose, Property, Repeat, Target, TargetRef, Track,
};
use animed::internals::scene::{
    Camera, CameraKind, Light, LightKind, Material, Node, NodeId, NodeKind, Scene, Transform,
};
use glam::{Quat, Vec3};

fn track(of: TargetRef, property: Property, repeat: Repeat, keys: Keys) -> Track {
    Track::new(Target { of, property }, repeat, keys).expect("valid test track")
}

fn lin<V>(f: f32, v: V) -> Key<V> {
    Key::new(f, v).with_interp(Interp::Linear)
}

struct Ids {
    root: NodeId,
    child: NodeId,
    light: NodeId,
    cam: NodeId,
}

fn scene() -> (Scene, Ids) {
    let mut s = Scene::new();
    s.settings.fps = 10.0;
    let root = s.add_node(None, Node::group("root"));
    let child = s.add_node(
        Some(root),
        Node::group("child").with_transform(Transform::from_translation(Vec3::new(0.0, 1.0, 0.0))),
    );
    let light = s.add_node(
        Some(child),
        Node::new("spot", NodeKind::Light(Light::spot())),
    );
    let cam = s.add_node(None, Node::new("cam", NodeKind::Camera(Camera::default())));
    s.add_material(Material::default());
    let n = TargetRef::Node;
    let tracks = vec![
        track(
            n(root),
            Property::Translation,
            Repeat::Constant,
            Keys::Vec3(vec![
                lin(0.0, Vec3::ZERO),
                lin(10.0, Vec3::new(10.0, 0.0, 0.0)),
            ]),
        ),
        track(
            n(child),
            Property::Rotation,
            Repeat::Constant,
            Keys::Rotation(vec![
                lin(0.0, Quat::IDENTITY),
                lin(10.0, Quat::from_rotation_z(1.0)),
            ]),
        ),
        track(
            n(root),
            Property::Visibility,
            Repeat::Loop,
            Keys::Bool(vec![
                Key::new(0.0, true),
                Key::new(5.0, false),
                Key::new(10.0, true),
            ]),
        ),
        track(
            n(light),
            Property::LightIntensity,
            Repeat::Constant,
            Keys::Scalar(vec![lin(0.0, 0.0), lin(20.0, 1.0)]),
        ),
        track(
            n(light),
            Property::LightColor,
            Repeat::Constant,
            Keys::Vec3(vec![lin(0.0, Vec3::X), lin(10.0, Vec3::Y)]),
        ),
        track(
            n(light),
            Property::LightCutOff,
            Repeat::Constant,
            Keys::Scalar(vec![lin(0.0, 0.2), lin(10.0, 0.4)]),
        ),
        track(
            n(light),
            Property::LightOn,
            Repeat::Constant,
            Keys::Bool(vec![Key::new(0.0, true), Key::new(7.0, false)]),
        ),
        track(
            n(cam),
            Property::CameraFov,
            Repeat::Loop,
            Keys::Scalar(vec![lin(0.0, 0.5), lin(4.0, 1.0)]),
        ),
        track(
            n(cam),
            Property::CameraPosition,
            Repeat::Constant,
            Keys::Vec3(vec![lin(0.0, Vec3::Z), lin(10.0, Vec3::Z * 3.0)]),
        ),
        track(
            TargetRef::Material(animed::internals::scene::MaterialId(0)),
            Property::Diffuse,
            Repeat::Constant,
            Keys::Vec3(vec![lin(0.0, Vec3::ZERO), lin(10.0, Vec3::ONE)]),
        ),
        track(
            TargetRef::Material(animed::internals::scene::MaterialId(0)),
            Property::Transparency,
            Repeat::Constant,
            Keys::Scalar(vec![lin(0.0, 0.0), lin(10.0, 0.5)]),
        ),
        // A light property on a group and an out-of-range node are ignored.
        track(
            n(child),
            Property::LightIntensity,
            Repeat::Constant,
            Keys::Scalar(vec![Key::new(0.0, 9.0)]),
        ),
        track(
            n(NodeId(99)),
            Property::Translation,
            Repeat::Constant,
            Keys::Vec3(vec![Key::new(0.0, Vec3::ONE)]),
        ),
    ];
    s.animation.tracks = tracks;
    (
        s,
        Ids {
            root,
            child,
            light,
            cam,
        },
    )
}

fn near(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-5
}

#[test]
fn evaluates_every_kind_of_target() {
    let (s, ids) = scene();
    // 0.6 s at 10 fps = frame 6.
    let p = evaluate(&s, 0.6);
    assert!(near(
        p.transforms[ids.root.0 as usize].translation,
        Vec3::new(6.0, 0.0, 0.0)
    ));
    let r = p.transforms[ids.child.0 as usize].rotation;
    assert!(r.angle_between(Quat::from_rotation_z(0.6)) < 1e-5);
    // World of the light: root translation · child (translate y 1, rotate).
    let w = p.world[ids.light.0 as usize];
    assert!(near(
        w.transform_point3(Vec3::ZERO),
        Vec3::new(6.0, 1.0, 0.0)
    ));
    assert!(near(
        w.transform_vector3(Vec3::X),
        Quat::from_rotation_z(0.6) * Vec3::X
    ));
    // Visibility: the root's key at 5 hides the subtree, not the camera.
    assert!(!p.visible[ids.root.0 as usize] && !p.visible[ids.light.0 as usize]);
    assert!(p.visible[ids.cam.0 as usize]);
    let l = p.light(ids.light).expect("light in pose");
    assert!((l.intensity - 0.3).abs() < 1e-6);
    assert!(near(l.color, Vec3::new(0.4, 0.6, 0.0)));
    assert!(l.on);
    let LightKind::Spot { cut_off_angle, .. } = l.kind else {
        panic!("spot expected")
    };
    assert!((cut_off_angle - 0.32).abs() < 1e-6);
    let c = p.camera(ids.cam).expect("camera in pose");
    // Loop of period 4: frame 6 → 2 → 0.75.
    let CameraKind::Perspective { height_angle } = c.kind else {
        panic!("perspective expected")
    };
    assert!((height_angle - 0.75).abs() < 1e-6);
    assert!(near(c.position, Vec3::Z * 2.2));
    assert!(near(p.materials[0].diffuse, Vec3::splat(0.6)));
    assert!((p.materials[0].transparency - 0.3).abs() < 1e-6);
    // Later: light off (step at 7), visible again (loop of 10).
    let p = evaluate(&s, 1.2);
    assert!(!p.light(ids.light).expect("light").on);
    assert!(p.visible[ids.light.0 as usize]);
    assert!(near(
        p.transforms[ids.root.0 as usize].translation,
        Vec3::new(10.0, 0.0, 0.0)
    ));
}

#[test]
fn evaluate_does_not_mutate_the_scene_and_into_matches() {
    let (s, _) = scene();
    let nodes = s.nodes.clone();
    let materials = s.materials.clone();
    let anim = s.animation.clone();
    let mut pose = Pose::default();
    for i in 0..30 {
        let t = i as f32 * 0.07;
        evaluate_into(&s, t, &mut pose);
        let fresh = evaluate(&s, t);
        assert_eq!(pose.world, fresh.world);
        assert_eq!(pose.visible, fresh.visible);
        assert_eq!(pose.transforms, fresh.transforms);
        assert_eq!(pose.lights, fresh.lights);
        assert_eq!(pose.cameras, fresh.cameras);
        assert_eq!(pose.materials, fresh.materials);
    }
    assert_eq!(s.nodes, nodes);
    assert_eq!(s.materials, materials);
    assert_eq!(s.animation, anim);
}

#[test]
fn children_before_parents_in_the_arena_still_work() {
    // Build a child at index 0 whose parent is index 1 by hand.
    let mut s = Scene::new();
    let mut child = Node::group("child");
    child.transform = Transform::from_translation(Vec3::X);
    child.parent = Some(NodeId(1));
    let mut parent = Node::group("parent");
    parent.transform = Transform::from_translation(Vec3::Y);
    parent.children = vec![NodeId(0)];
    parent.visible = false;
    s.nodes = vec![child, parent];
    s.roots = vec![NodeId(1)];
    let p = evaluate(&s, 0.0);
    assert!(near(
        p.world[0].transform_point3(Vec3::ZERO),
        Vec3::new(1.0, 1.0, 0.0)
    ));
    assert!(!p.visible[0]);
}
