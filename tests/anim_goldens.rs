//! The renderer draws animated poses: one small scene rendered at three
//! times (`render_at`, the path `animed render --time` takes). A box flies
//! along a TCB path while turning 270° about y with squad (three rotation
//! keys), a sphere's material fades from red to blue, and a point light
//! dims. Goldens: `anim_t0`, `anim_t1`, `anim_t2` (160×120).

#[path = "common/golden.rs"]
mod golden;

use animed::internals::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use animed::internals::scene::primitives::{box_mesh, sphere};
use animed::internals::scene::{
    Camera, Light, LightKind, Material, Node, NodeKind, Scene, Shape, Transform,
};
use glam::{Quat, Vec3};

fn track(target: Target, keys: Keys) -> Track {
    Track::new(target, Repeat::Constant, keys).expect("valid test track")
}

fn scene() -> Scene {
    let mut s = Scene::new();
    s.settings.fps = 24.0;
    s.settings.duration = 48.0;
    s.settings.background = Vec3::new(0.1, 0.1, 0.15);
    let cube = s.add_mesh(box_mesh(Vec3::new(1.0, 1.0, 1.0)));
    let ball = s.add_mesh(sphere(0.6));
    let grey = s.add_material(Material {
        diffuse: Vec3::new(0.8, 0.8, 0.7),
        ..Material::default()
    });
    let paint = s.add_material(Material::default());
    let cam = Camera {
        position: Vec3::new(0.0, 1.5, 7.0),
        orientation: Quat::from_rotation_x(-0.2),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(cam)));
    let lamp = s.add_node(
        None,
        Node::new(
            "lamp",
            NodeKind::Light(Light {
                location: Vec3::new(2.0, 3.0, 3.0),
                ..Light::new(LightKind::Point)
            }),
        ),
    );
    let boxn = s.add_node(
        None,
        Node::new(
            "box",
            NodeKind::Shape(Shape {
                mesh: cube,
                material: grey,
            }),
        ),
    );
    s.add_node(
        None,
        Node::new(
            "ball",
            NodeKind::Shape(Shape {
                mesh: ball,
                material: paint,
            }),
        )
        .with_transform(Transform::from_translation(Vec3::new(0.0, -1.0, 0.0))),
    );
    let node = |id, property| Target {
        of: TargetRef::Node(id),
        property,
    };
    let deg = |d: f32| Quat::from_rotation_y(d.to_radians());
    s.animation.tracks = vec![
        track(
            node(boxn, Property::Translation),
            Keys::Vec3(vec![
                Key::new(0.0, Vec3::new(-2.0, 0.5, 0.0)),
                Key::new(24.0, Vec3::new(0.0, 1.5, -1.0)).with_tcb(0.0, 0.0, 0.5),
                Key::new(48.0, Vec3::new(2.0, 0.5, 0.0)),
            ]),
        ),
        track(
            node(boxn, Property::Rotation),
            Keys::Rotation(vec![
                Key::new(0.0, deg(0.0)),
                Key::new(24.0, deg(135.0)),
                Key::new(48.0, deg(270.0)),
            ]),
        ),
        track(
            node(lamp, Property::LightIntensity),
            Keys::Scalar(vec![
                Key::new(0.0, 1.0).with_interp(Interp::Linear),
                Key::new(48.0, 0.3),
            ]),
        ),
        track(
            Target {
                of: TargetRef::Material(paint),
                property: Property::Diffuse,
            },
            Keys::Vec3(vec![
                Key::new(0.0, Vec3::new(0.9, 0.1, 0.1)).with_interp(Interp::Linear),
                Key::new(48.0, Vec3::new(0.1, 0.2, 0.9)),
            ]),
        ),
    ];
    s
}

fn spec() -> FrameSpec {
    FrameSpec {
        width: 160,
        height: 120,
        headlight: Headlight::Off,
        threads: 1,
        ..FrameSpec::default()
    }
}

#[test]
fn animated_scene_at_three_times_matches_goldens() {
    let s = scene();
    let frames: Vec<_> = [0.0f32, 1.0, 2.0]
        .iter()
        .map(|&t| render_at(&s, &spec(), t).expect("scene has a camera"))
        .collect();
    // The animation shows: every pair of times gives a different picture.
    for i in 0..3 {
        for j in i + 1..3 {
            let differ = frames[i]
                .color
                .iter()
                .zip(&frames[j].color)
                .filter(|(a, b)| a != b)
                .count();
            assert!(differ > 200, "t{i} and t{j} differ in only {differ} pixels");
        }
    }
    // Same time, same bytes (evaluation is pure).
    let again = render_at(&s, &spec(), 1.0).expect("camera");
    assert_eq!(again.color, frames[1].color);
    for (i, f) in frames.iter().enumerate() {
        golden::check(&format!("anim_t{i}"), f);
    }
}
