//! Scenes built in code for the writer tests (no reader needed).
#![allow(dead_code)]

use animed::internals::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use animed::internals::scene::{
    Camera, Light, LightKind, Material, Mesh, Node, NodeId, NodeKind, Scene, Shape, Transform,
};
use glam::{Quat, Vec3};

/// A unit cube (side 1, centred) with flat per-face normals.
pub fn cube(name: &str) -> Mesh {
    let mut m = Mesh {
        name: name.into(),
        solid: true,
        ..Default::default()
    };
    let faces = [
        (Vec3::X, Vec3::Y, Vec3::Z),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::Z, Vec3::X),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::Y, Vec3::X),
    ];
    for (n, u, v) in faces {
        let base = m.positions.len() as u32;
        let c = n * 0.5;
        for (a, b) in [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
            m.positions.push(c + u * a + v * b);
            m.normals.push(n);
        }
        m.triangles.push([base, base + 1, base + 2]);
        m.triangles.push([base, base + 2, base + 3]);
    }
    m
}

pub fn track<V>(of: TargetRef, property: Property, repeat: Repeat, keys: Vec<Key<V>>) -> Track
where
    Vec<Key<V>>: Into<KeysOf>,
{
    Track {
        target: Target { of, property },
        repeat,
        keys: keys.into().0,
    }
}

pub struct KeysOf(pub Keys);
impl From<Vec<Key<f32>>> for KeysOf {
    fn from(k: Vec<Key<f32>>) -> Self {
        KeysOf(Keys::Scalar(k))
    }
}
impl From<Vec<Key<Vec3>>> for KeysOf {
    fn from(k: Vec<Key<Vec3>>) -> Self {
        KeysOf(Keys::Vec3(k))
    }
}
impl From<Vec<Key<Quat>>> for KeysOf {
    fn from(k: Vec<Key<Quat>>) -> Self {
        KeysOf(Keys::Rotation(k))
    }
}
impl From<Vec<Key<bool>>> for KeysOf {
    fn from(k: Vec<Key<bool>>) -> Self {
        KeysOf(Keys::Bool(k))
    }
}

/// The writers' demo: a spinning, moving red cube, a blinking cube, a point
/// light that dims and switches off, a spot light, and a camera.
pub fn demo_scene() -> Scene {
    let mut s = Scene::new();
    s.settings.fps = 24.0;
    s.settings.duration = 48.0;
    s.settings.background = Vec3::new(0.1, 0.1, 0.2);
    let cube_mesh = s.add_mesh(cube("CubeMesh"));
    let red = s.add_material(Material {
        name: "Red".into(),
        diffuse: Vec3::new(0.8, 0.1, 0.1),
        specular: Vec3::splat(0.5),
        shininess: 0.4,
        ..Default::default()
    });
    let grey = s.add_material(Material::default());

    let cam = Camera {
        position: Vec3::new(0.0, 1.5, 6.0),
        orientation: Quat::from_rotation_x(-0.25),
        description: "Front".into(),
        ..Default::default()
    };
    let cam_id = s.add_node(None, Node::new("Cam", NodeKind::Camera(cam)));

    let mut lamp = Light::new(LightKind::Point);
    lamp.location = Vec3::new(2.0, 3.0, 4.0);
    lamp.intensity = 0.8;
    let lamp_id = s.add_node(None, Node::new("Lamp", NodeKind::Light(lamp)));

    let mut spot = Light::spot();
    spot.location = Vec3::new(-3.0, 3.0, 3.0);
    spot.direction = Vec3::new(1.0, -1.0, -1.0).normalize();
    let spot_id = s.add_node(None, Node::new("Spot", NodeKind::Light(spot)));

    let spinner = s.add_node(
        None,
        Node::group("Spinner")
            .with_transform(Transform::from_translation(Vec3::new(-1.0, 0.0, 0.0))),
    );
    s.add_node(
        Some(spinner),
        Node::new(
            "Cube",
            NodeKind::Shape(Shape {
                mesh: cube_mesh,
                material: red,
            }),
        ),
    );
    let blinker = s.add_node(
        None,
        Node::new(
            "Blinker",
            NodeKind::Shape(Shape {
                mesh: cube_mesh,
                material: grey,
            }),
        )
        .with_transform(Transform {
            translation: Vec3::new(1.5, 0.0, 0.0),
            scale: Vec3::splat(0.6),
            ..Default::default()
        }),
    );

    let node = |id: NodeId| TargetRef::Node(id);
    s.animation.tracks = vec![
        track(
            node(spinner),
            Property::Rotation,
            Repeat::Constant,
            vec![
                Key::new(0.0, Quat::IDENTITY),
                Key::new(24.0, Quat::from_rotation_y(150f32.to_radians())),
                Key::new(48.0, Quat::from_rotation_y(300f32.to_radians())),
            ],
        ),
        track(
            node(spinner),
            Property::Translation,
            Repeat::Constant,
            vec![
                Key::new(0.0, Vec3::new(-1.0, 0.0, 0.0)).with_interp(Interp::Linear),
                Key::new(12.0, Vec3::new(-1.0, 1.0, 0.0)).with_tcb(0.3, 0.0, 0.0),
                Key::new(36.0, Vec3::new(-1.0, -0.5, 0.5)),
                Key::new(48.0, Vec3::new(-1.0, 0.0, 0.0)),
            ],
        ),
        track(
            TargetRef::Material(red),
            Property::Diffuse,
            Repeat::Constant,
            vec![
                Key::new(0.0, Vec3::new(0.8, 0.1, 0.1)).with_interp(Interp::Linear),
                Key::new(48.0, Vec3::new(0.1, 0.2, 0.9)),
            ],
        ),
        track(
            node(blinker),
            Property::Visibility,
            Repeat::Loop,
            vec![
                Key::new(0.0, true).with_interp(Interp::Step),
                Key::new(8.0, false).with_interp(Interp::Step),
                Key::new(16.0, true).with_interp(Interp::Step),
            ],
        ),
        track(
            node(lamp_id),
            Property::LightIntensity,
            Repeat::Constant,
            vec![
                Key::new(0.0, 1.0f32).with_interp(Interp::Linear),
                Key::new(30.0, 0.3f32),
            ],
        ),
        track(
            node(lamp_id),
            Property::LightOn,
            Repeat::Constant,
            vec![
                Key::new(0.0, true).with_interp(Interp::Step),
                Key::new(40.0, false).with_interp(Interp::Step),
            ],
        ),
        track(
            node(spot_id),
            Property::LightCutOff,
            Repeat::Constant,
            vec![
                Key::new(0.0, 0.3f32),
                Key::new(24.0, 0.7f32),
                Key::new(48.0, 0.4f32),
            ],
        ),
        track(
            node(cam_id),
            Property::CameraPosition,
            Repeat::Constant,
            vec![
                Key::new(0.0, Vec3::new(0.0, 1.5, 6.0)).with_interp(Interp::Linear),
                Key::new(48.0, Vec3::new(0.5, 1.5, 7.0)),
            ],
        ),
    ];
    s
}

/// Two textured quads: `Tiled` uses a file texture (`brick.png`, clamped in
/// t, turned by a VRML97 texture transform), `Decal` a 2x1 inline RGBA image
/// with Inventor's DECAL model; plus an untextured cube after them.
pub fn textured_scene(brick: &std::path::Path) -> Scene {
    use animed::internals::scene::{Image, ImageSource, TexTransform, Texture, TextureModel, Wrap};
    use glam::Vec2;
    let mut s = Scene::new();
    let quad = |name: &str| {
        let mut m = Mesh {
            name: name.into(),
            ..Default::default()
        };
        m.positions = vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ];
        m.normals = vec![Vec3::Z; 4];
        m.texcoords = vec![
            Vec2::new(0.0, 0.0),
            Vec2::new(2.0, 0.0),
            Vec2::new(2.0, 1.0),
            Vec2::new(0.0, 1.0),
        ];
        m.triangles = vec![[0, 1, 2], [0, 2, 3]];
        m
    };
    let file = s
        .add_image(
            Image::new(
                "brick.png",
                ImageSource::File {
                    url: "brick.png".into(),
                    path: brick.to_path_buf(),
                },
                1,
                1,
                3,
                vec![[200, 40, 40, 255]],
            )
            .unwrap(),
        )
        .unwrap();
    let inline = s
        .add_image(
            Image::new(
                "",
                ImageSource::Inline,
                2,
                1,
                4,
                vec![[255, 0, 0, 255], [0, 0, 255, 128]],
            )
            .unwrap(),
        )
        .unwrap();
    let tiled = s.add_material(Material {
        name: "TiledMat".into(),
        texture: Some(Texture {
            wrap_t: Wrap::Clamp,
            transform: TexTransform {
                rotation: 0.5,
                scale: Vec2::splat(2.0),
                center: Vec2::splat(0.5),
                ..TexTransform::default()
            },
            ..Texture::new(file)
        }),
        ..Material::default()
    });
    let decal = s.add_material(Material {
        name: "DecalMat".into(),
        texture: Some(Texture {
            model: TextureModel::Decal,
            ..Texture::new(inline)
        }),
        ..Material::default()
    });
    let plain = s.add_material(Material::default());
    for (name, mat, mesh, x) in [
        ("Tiled", tiled, quad("TiledQuad"), -1.5),
        ("Decal", decal, quad("DecalQuad"), 1.5),
        ("Plain", plain, cube("PlainCube"), 0.0),
    ] {
        let mesh = s.add_mesh(mesh);
        s.add_node(
            None,
            Node::new(
                name,
                NodeKind::Shape(Shape {
                    mesh,
                    material: mat,
                }),
            )
            .with_transform(Transform {
                translation: Vec3::new(x, 0.0, 0.0),
                ..Transform::default()
            }),
        );
    }
    s
}
