//! Deforming meshes (issue 13): morph targets blended by animated weights
//! (M = B + Σ wᵢ·Mᵢ) and linear blend skinning, checked against values
//! worked out by hand, by properties, and by goldens of a bending skinned
//! cylinder and a morphing shape (160×120, looked at).

#[path = "common/golden.rs"]
mod golden;
#[path = "common/skinned_tube.rs"]
mod skinned_tube;

mod anim_hanim;

use animed::internals::anim::{
    evaluate, Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Weights,
};
use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use animed::internals::scene::primitives::sphere;
use animed::internals::scene::{
    Camera, Light, LightKind, Material, Mesh, MorphTarget, Morphs, Node, NodeId, NodeKind, Scene,
    Shape, Skin, SkinWeights, Transform,
};
use glam::{Mat4, Quat, Vec3};
use proptest::prelude::*;

fn close(a: Vec3, b: Vec3, eps: f32) -> bool {
    (a - b).abs().max_element() <= eps
}

fn shape(s: &mut Scene, parent: Option<NodeId>, name: &str, mesh: Mesh) -> NodeId {
    let mesh = s.add_mesh(mesh);
    let material = s.add_material(Material::default());
    s.add_node(
        parent,
        Node::new(name, NodeKind::Shape(Shape { mesh, material })),
    )
}

fn weights_track(id: NodeId, keys: Vec<Key<Weights>>) -> Track {
    Track::new(
        Target {
            of: TargetRef::Node(id),
            property: Property::MorphWeights,
        },
        Repeat::Constant,
        Keys::Weights(keys),
    )
    .expect("valid weights track")
}

fn w(v: &[f32]) -> Weights {
    Weights::from_slice(v).expect("few weights")
}

/// Two vertices, two targets, hand-computed blends.
fn morph_scene() -> (Scene, NodeId) {
    let mut s = Scene::new();
    let mut m = Mesh {
        positions: vec![Vec3::ZERO, Vec3::X],
        normals: vec![Vec3::Y, Vec3::Y],
        ..Mesh::default()
    };
    let t0 = MorphTarget::new(
        "up",
        vec![Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 2.0, 0.0)],
        vec![Vec3::ZERO, Vec3::new(1.0, 0.0, 0.0)],
    );
    let t1 = MorphTarget::new(
        "side",
        vec![Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -1.0)],
        vec![],
    );
    m.morph = Some(Box::new(
        Morphs::new(2, vec![t0, t1], vec![0.5, -0.25]).unwrap(),
    ));
    let id = shape(&mut s, None, "Face", m);
    s.node_mut(id).transform = Transform::from_translation(Vec3::new(0.0, 0.0, 3.0));
    (s, id)
}

#[test]
fn morph_formula_matches_hand_computed_vertices() {
    // Default weights (0.5, -0.25), no track:
    // v0 = (0,0,0) + 0.5·(0,1,0) − 0.25·(1,0,0) = (−0.25, 0.5, 0)
    // v1 = (1,0,0) + 0.5·(0,2,0) − 0.25·(0,0,−1) = (1, 1, 0.25)
    let (s, id) = morph_scene();
    let pose = evaluate(&s, 0.0);
    assert_eq!(pose.weights(id).unwrap().as_slice(), &[0.5, -0.25]);
    let d = pose
        .deformed(id)
        .expect("morphed shape has deformed buffers");
    assert!(!d.world_space, "morph-only meshes stay in local space");
    assert!(
        close(d.positions[0], Vec3::new(-0.25, 0.5, 0.0), 1e-6),
        "{:?}",
        d.positions
    );
    assert!(
        close(d.positions[1], Vec3::new(1.0, 1.0, 0.25), 1e-6),
        "{:?}",
        d.positions
    );
    // Normals: n1 = normalise((0,1,0) + 0.5·(1,0,0)) = (2,4,0)/√20.
    let n1 = Vec3::new(0.5, 1.0, 0.0).normalize();
    assert!(close(d.normals[1], n1, 1e-6), "{:?}", d.normals);
    assert!(close(d.normals[0], Vec3::Y, 1e-6));
    // The scene is untouched.
    assert_eq!(s.meshes[0].positions, vec![Vec3::ZERO, Vec3::X]);
}

#[test]
fn animated_weights_interpolate_per_component_and_extrapolate() {
    let (mut s, id) = morph_scene();
    s.settings.fps = 10.0;
    s.animation.tracks.push(weights_track(
        id,
        vec![
            Key::new(0.0, w(&[0.0, 0.0])).with_interp(Interp::Linear),
            Key::new(10.0, w(&[1.0, 2.0])).with_interp(Interp::Step),
            Key::new(20.0, w(&[-1.0, 1.5])),
        ],
    ));
    // t = 0.5 s = frame 5: linear half way → (0.5, 1.0).
    let pose = evaluate(&s, 0.5);
    assert_eq!(pose.weights(id).unwrap().as_slice(), &[0.5, 1.0]);
    let d = pose.deformed(id).unwrap();
    // v0 = 0.5·(0,1,0) + 1·(1,0,0) = (1, 0.5, 0)
    assert!(close(d.positions[0], Vec3::new(1.0, 0.5, 0.0), 1e-6));
    // Step segment: frame 15 holds (1, 2); weights beyond 1 extrapolate:
    // v1 = (1,0,0) + 1·(0,2,0) + 2·(0,0,−1) = (1, 2, −2)
    let pose = evaluate(&s, 1.5);
    assert_eq!(pose.weights(id).unwrap().as_slice(), &[1.0, 2.0]);
    assert!(close(
        pose.deformed(id).unwrap().positions[1],
        Vec3::new(1.0, 2.0, -2.0),
        1e-6
    ));
    // After the last key: held; a negative weight pulls the other way.
    let pose = evaluate(&s, 5.0);
    assert_eq!(pose.weights(id).unwrap().as_slice(), &[-1.0, 1.5]);
    assert!(close(
        pose.deformed(id).unwrap().positions[0],
        Vec3::new(1.5, -1.0, 0.0),
        1e-6
    ));
}

#[test]
fn tcb_weights_are_the_vector_spline_per_component() {
    // Three TCB keys: each component must equal the scalar TCB track with
    // the same keys (the same curve maths, component by component).
    let (mut s, id) = morph_scene();
    let ks = [(0.0, [0.0, 1.0]), (8.0, [1.0, -0.5]), (20.0, [0.25, 0.75])];
    s.animation.tracks.push(weights_track(
        id,
        ks.iter()
            .map(|(f, v)| Key::new(*f, w(v)).with_tcb(0.3, -0.2, 0.1))
            .collect(),
    ));
    for c in 0..2 {
        let scalar = Track::new(
            Target {
                of: TargetRef::Node(id),
                property: Property::LightIntensity,
            },
            Repeat::Constant,
            Keys::Scalar(
                ks.iter()
                    .map(|(f, v)| Key::new(*f, v[c]).with_tcb(0.3, -0.2, 0.1))
                    .collect(),
            ),
        )
        .unwrap();
        for i in 0..40 {
            let frame = i as f32 * 0.5;
            let pose = evaluate(&s, frame / s.settings.fps);
            let animed::internals::anim::Value::Scalar(want) = scalar.sample(frame) else {
                panic!("scalar track")
            };
            assert_eq!(
                pose.weights(id).unwrap().as_slice()[c],
                want,
                "frame {frame}"
            );
        }
    }
}

/// A strip of vertices along x bound to two joints: J0 at the origin, J1 at
/// x = 1 (child of J0). `bend` rotates J1 about z.
fn two_joint_scene(bend: f32) -> (Scene, NodeId) {
    let mut s = Scene::new();
    let j0 = s.add_node(None, Node::group("J0"));
    let j1 = s.add_node(
        Some(j0),
        Node::group("J1").with_transform(Transform {
            translation: Vec3::X,
            rotation: Quat::from_rotation_z(bend),
            ..Transform::default()
        }),
    );
    let mut m = Mesh {
        positions: vec![
            Vec3::new(0.5, 0.0, 0.0),
            Vec3::new(1.5, 0.2, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(3.0, 0.0, 0.0),
        ],
        normals: vec![Vec3::Y; 4],
        ..Mesh::default()
    };
    let sw = SkinWeights::new(
        vec![[0, 0, 0, 0], [0, 1, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0]],
        vec![
            [1.0, 0.0, 0.0, 0.0],
            [0.25, 0.75, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0], // no influence: stays at its bind position
        ],
    )
    .unwrap();
    m.skin_weights = Some(Box::new(sw));
    let id = shape(&mut s, None, "Strip", m);
    // The skinned shape's own transform does not move skinned vertices
    // (glTF §3.7.3); it places the zero-weight one.
    s.node_mut(id).transform = Transform::from_translation(Vec3::new(0.0, 0.0, 5.0));
    let skin = Skin::new(
        "rig",
        vec![j0, j1],
        vec![Mat4::IDENTITY, Mat4::from_translation(-Vec3::X)],
    )
    .unwrap();
    let sk = s.add_skin(skin).unwrap();
    s.node_mut(id).skin = Some(sk);
    (s, id)
}

#[test]
fn two_joint_bend_matches_hand_computed_vertices() {
    let (s, id) = two_joint_scene(std::f32::consts::FRAC_PI_2);
    let pose = evaluate(&s, 0.0);
    let d = pose.deformed(id).expect("skinned shape deforms");
    assert!(d.world_space);
    // J1·IBM1 = T(1,0,0)·Rz(90°)·T(−1,0,0): (x, y) → (1 − y, x − 1).
    // v0 on J0 only: unchanged.
    assert!(
        close(d.positions[0], Vec3::new(0.5, 0.0, 0.0), 1e-6),
        "{:?}",
        d.positions
    );
    // v1 = 0.25·(1.5, 0.2) + 0.75·(0.8, 0.5) = (0.975, 0.425)
    assert!(
        close(d.positions[1], Vec3::new(0.975, 0.425, 0.0), 1e-6),
        "{:?}",
        d.positions
    );
    // v2 on J1 only: (2,0) → (1, 1)
    assert!(
        close(d.positions[2], Vec3::new(1.0, 1.0, 0.0), 1e-6),
        "{:?}",
        d.positions
    );
    // v3 has no weights: bind position placed by the shape's transform.
    assert!(
        close(d.positions[3], Vec3::new(3.0, 0.0, 5.0), 1e-6),
        "{:?}",
        d.positions
    );
    assert!(d.positions.iter().all(|p| p.is_finite()));
    // Normal of v1: normalise(0.25·(0,1,0) + 0.75·(−1,0,0)).
    let n = Vec3::new(-0.75, 0.25, 0.0).normalize();
    assert!(close(d.normals[1], n, 1e-6), "{:?}", d.normals);
    assert!(close(d.normals[2], Vec3::new(-1.0, 0.0, 0.0), 1e-6));
    assert!(close(d.normals[3], Vec3::Y, 1e-6));
    // Scene untouched.
    assert_eq!(s.meshes[0].positions[2], Vec3::new(2.0, 0.0, 0.0));
}

#[test]
fn unbent_skin_is_the_bind_pose() {
    let (s, id) = two_joint_scene(0.0);
    let pose = evaluate(&s, 0.0);
    let d = pose.deformed(id).unwrap();
    for (got, want) in d.positions.iter().zip(&s.meshes[0].positions).take(3) {
        assert!(close(*got, *want, 1e-6), "{got} vs {want}");
    }
}

#[test]
fn more_than_four_influences_keep_the_four_largest() {
    // Joint k moves its vertices by +k along y. Six influences: the two
    // smallest (joints 0 and 5) are dropped and the rest renormalised.
    let mut s = Scene::new();
    let joints: Vec<NodeId> = (0..6)
        .map(|k| {
            s.add_node(
                None,
                Node::group(format!("J{k}"))
                    .with_transform(Transform::from_translation(Vec3::new(0.0, k as f32, 0.0))),
            )
        })
        .collect();
    let (sw, report) = SkinWeights::from_influences(1, |_, out| {
        out.extend([
            (0, 0.05),
            (1, 0.3),
            (2, 0.2),
            (3, 0.25),
            (4, 0.15),
            (5, 0.05),
        ])
    })
    .unwrap();
    assert_eq!(report.over_four, 1);
    let m = Mesh {
        positions: vec![Vec3::ZERO],
        skin_weights: Some(Box::new(sw)),
        ..Mesh::default()
    };
    let id = shape(&mut s, None, "V", m);
    let sk = s
        .add_skin(Skin::new("rig", joints, vec![]).unwrap())
        .unwrap();
    s.node_mut(id).skin = Some(sk);
    let pose = evaluate(&s, 0.0);
    // y = (0.3·1 + 0.2·2 + 0.25·3 + 0.15·4) / 0.9
    let y = (0.3 + 0.4 + 0.75 + 0.6) / 0.9;
    let got = pose.deformed(id).unwrap().positions[0];
    assert!((got.y - y).abs() < 1e-5, "{got} vs {y}");
}

fn identity_rig(n_joints: usize, verts: &[(Vec3, [u16; 4], [f32; 4])]) -> (Scene, NodeId) {
    let mut s = Scene::new();
    let joints: Vec<NodeId> = (0..n_joints)
        .map(|k| s.add_node(None, Node::group(format!("J{k}"))))
        .collect();
    let (sw, _) = SkinWeights::from_influences(verts.len(), |v, out| {
        let (_, j, w) = verts[v];
        out.extend(j.iter().zip(w).map(|(j, w)| (*j, w)));
    })
    .unwrap();
    let m = Mesh {
        positions: verts.iter().map(|v| v.0).collect(),
        normals: verts
            .iter()
            .map(|v| (v.0 + Vec3::splat(0.1)).normalize())
            .collect(),
        skin_weights: Some(Box::new(sw)),
        ..Mesh::default()
    };
    let id = shape(&mut s, None, "M", m);
    let sk = s
        .add_skin(Skin::new("rig", joints, vec![]).unwrap())
        .unwrap();
    s.node_mut(id).skin = Some(sk);
    (s, id)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Identity joints (and identity inverse binds) leave every vertex and
    /// normal where it was, whatever the weights (zero sums included).
    #[test]
    fn identity_joints_leave_the_mesh_unchanged(
        verts in prop::collection::vec(
            (
                (-100.0f32..100.0, -100.0f32..100.0, -100.0f32..100.0),
                prop::array::uniform4(0u16..5),
                prop::array::uniform4(prop_oneof![Just(0.0f32), 0.0f32..10.0]),
            ),
            1..300,
        )
    ) {
        let verts: Vec<(Vec3, [u16; 4], [f32; 4])> = verts
            .into_iter()
            .map(|((x, y, z), j, w)| (Vec3::new(x, y, z), j, w))
            .collect();
        let (s, id) = identity_rig(5, &verts);
        let pose = evaluate(&s, 0.0);
        let d = pose.deformed(id).unwrap();
        for (k, (p, n)) in d.positions.iter().zip(&d.normals).enumerate() {
            let want = s.meshes[0].positions[k];
            prop_assert!(close(*p, want, 1e-4 * want.abs().max_element().max(1.0)), "{p} vs {want}");
            prop_assert!(close(*n, s.meshes[0].normals[k], 1e-5));
        }
    }
}

#[test]
fn skinning_gives_the_same_bytes_for_any_thread_count() {
    // Enough vertices for several parallel chunks.
    let verts: Vec<(Vec3, [u16; 4], [f32; 4])> = (0..20_000)
        .map(|i| {
            let f = i as f32;
            (
                Vec3::new(f * 0.001, (f * 0.37).sin(), (f * 0.11).cos()),
                [(i % 3) as u16, ((i + 1) % 3) as u16, 2, 0],
                [0.2 + (i % 7) as f32 * 0.1, 0.3, 0.1, 0.0],
            )
        })
        .collect();
    let (mut s, id) = identity_rig(3, &verts);
    let j = s.skins[0].joints().to_vec();
    s.node_mut(j[1]).transform = Transform {
        translation: Vec3::new(0.3, -1.0, 2.0),
        rotation: Quat::from_rotation_y(0.7),
        scale: Vec3::new(1.0, 2.0, 0.5),
        ..Transform::default()
    };
    s.node_mut(j[2]).transform.rotation = Quat::from_rotation_x(-1.1);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let p = evaluate(&s, 0.0);
            let d = p.deformed(id).unwrap();
            (d.positions.clone(), d.normals.clone())
        })
    };
    let one = run(1);
    for t in [2, 3, 8] {
        let other = run(t);
        let bits = |v: &[Vec3]| {
            v.iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect::<Vec<_>>()
        };
        assert_eq!(
            bits(&one.0),
            bits(&other.0),
            "positions differ with {t} threads"
        );
        assert_eq!(
            bits(&one.1),
            bits(&other.1),
            "normals differ with {t} threads"
        );
    }
}

/// A lit scene around `build`'s shapes, seen from +z.
fn staged(build: impl FnOnce(&mut Scene)) -> Scene {
    let mut s = Scene::new();
    s.settings.fps = 24.0;
    s.settings.duration = 48.0;
    s.settings.background = Vec3::new(0.1, 0.1, 0.15);
    let cam = Camera {
        position: Vec3::new(0.0, 0.3, 6.0),
        ..Camera::default()
    };
    s.add_node(None, Node::new("cam", NodeKind::Camera(cam)));
    s.add_node(
        None,
        Node::new(
            "lamp",
            NodeKind::Light(Light {
                direction: Vec3::new(-0.4, -0.6, -1.0),
                ..Light::new(LightKind::Directional)
            }),
        ),
    );
    build(&mut s);
    s
}

fn spec() -> FrameSpec {
    FrameSpec {
        width: 160,
        height: 120,
        headlight: Headlight::Off,
        threads: 2,
        ..FrameSpec::default()
    }
}

/// A tube of radius 0.35 from y = −1.5 to 1.5 (20 rings × 16 sides) with
/// outward normals, skinned to J0 (at y = −1.5) and J1 (at y = 0, child of
/// J0); the weights blend smoothly over the middle third. J1 bends 70°
/// one way, then the other.
fn bending_cylinder() -> Scene {
    staged(|s| {
        let m = skinned_tube::tube((20, 16), 0.35, (-1.5, 1.5), |y| {
            let w1 = ((y + 0.5) / 1.0).clamp(0.0, 1.0);
            w1 * w1 * (3.0 - 2.0 * w1)
        });
        let j0 = s.add_node(
            None,
            Node::group("J0")
                .with_transform(Transform::from_translation(Vec3::new(0.0, -1.5, 0.0))),
        );
        let j1 = s.add_node(
            Some(j0),
            Node::group("J1").with_transform(Transform::from_translation(Vec3::new(0.0, 1.5, 0.0))),
        );
        let mesh = s.add_mesh(m);
        let material = s.add_material(Material {
            diffuse: Vec3::new(0.85, 0.6, 0.3),
            ..Material::default()
        });
        let shape = s.add_node(
            None,
            Node::new("Tube", NodeKind::Shape(Shape { mesh, material })),
        );
        let skin = Skin::new(
            "rig",
            vec![j0, j1],
            vec![
                Mat4::from_translation(Vec3::new(0.0, 1.5, 0.0)),
                Mat4::IDENTITY,
            ],
        )
        .unwrap();
        let sk = s.add_skin(skin).unwrap();
        s.node_mut(shape).skin = Some(sk);
        let deg = |d: f32| Quat::from_rotation_z(d.to_radians());
        s.animation.tracks.push(
            Track::new(
                Target {
                    of: TargetRef::Node(j1),
                    property: Property::Rotation,
                },
                Repeat::Constant,
                Keys::Rotation(vec![
                    Key::new(0.0, deg(0.0)).with_interp(Interp::Linear),
                    Key::new(24.0, deg(70.0)).with_interp(Interp::Linear),
                    Key::new(48.0, deg(-70.0)),
                ]),
            )
            .unwrap(),
        );
    })
}

fn differ(a: &animed::internals::render::Frame, b: &animed::internals::render::Frame) -> usize {
    a.color.iter().zip(&b.color).filter(|(x, y)| x != y).count()
}

#[test]
fn bending_skinned_cylinder_at_three_times_matches_goldens() {
    let s = bending_cylinder();
    let frames: Vec<_> = [0.0f32, 1.0, 2.0]
        .iter()
        .map(|&t| render_at(&s, &spec(), t).expect("scene has a camera"))
        .collect();
    for i in 0..3 {
        for j in i + 1..3 {
            let d = differ(&frames[i], &frames[j]);
            assert!(d > 300, "t{i} and t{j} differ in only {d} pixels");
        }
    }
    // The bend shows: at t = 1 the top of the tube leans to −x (a positive
    // z rotation), at t = 2 to +x.
    let top = |t: f32| {
        let p = evaluate(&s, t);
        let d = p.deformed(NodeId(4)).expect("tube deforms");
        d.positions[d.positions.len() - 8]
    };
    assert!(
        top(1.0).x < -1.0 && top(2.0).x > 1.0,
        "{} {}",
        top(1.0),
        top(2.0)
    );
    for (i, f) in frames.iter().enumerate() {
        golden::check(&format!("deform_tube_t{i}"), f);
    }
}

/// A sphere with two morph targets: "tall" stretches it along y, "wide"
/// bulges it along x. Weights (0, 0), (1, 0) and (0.6, 1.2) at t = 0, 1, 2
/// (step keys).
fn morphing_sphere() -> Scene {
    staged(|s| {
        let mut m = sphere(1.0);
        let tall: Vec<Vec3> = m
            .positions
            .iter()
            .map(|p| Vec3::new(0.0, p.y * 0.6, 0.0))
            .collect();
        let wide: Vec<Vec3> = m
            .positions
            .iter()
            .map(|p| Vec3::new(p.x * 0.7, 0.0, 0.0))
            .collect();
        let n = m.positions.len();
        m.morph = Some(Box::new(
            Morphs::new(
                n,
                vec![
                    MorphTarget::new("tall", tall, vec![]),
                    MorphTarget::new("wide", wide, vec![]),
                ],
                vec![],
            )
            .unwrap(),
        ));
        let id = shape(s, None, "Blob", m);
        s.materials[0].diffuse = Vec3::new(0.3, 0.7, 0.4);
        s.animation.tracks.push(weights_track(
            id,
            vec![
                Key::new(0.0, w(&[0.0, 0.0])).with_interp(Interp::Step),
                Key::new(24.0, w(&[1.0, 0.0])).with_interp(Interp::Step),
                Key::new(48.0, w(&[0.6, 1.2])),
            ],
        ));
    })
}

#[test]
fn morphing_sphere_at_three_weights_matches_goldens() {
    let s = morphing_sphere();
    let frames: Vec<_> = [0.0f32, 1.0, 2.0]
        .iter()
        .map(|&t| render_at(&s, &spec(), t).expect("scene has a camera"))
        .collect();
    for i in 0..3 {
        for j in i + 1..3 {
            let d = differ(&frames[i], &frames[j]);
            assert!(d > 300, "t{i} and t{j} differ in only {d} pixels");
        }
    }
    for (i, f) in frames.iter().enumerate() {
        golden::check(&format!("deform_morph_w{i}"), f);
    }
}

/// A quad whose four points a CoordinateInterpolator moves (keys at 0,
/// 0.3 and 1 of a 2 s looping cycle).
const COORD_WRL: &str = "#VRML V2.0 utf8
DEF T TimeSensor { cycleInterval 2 loop TRUE }
DEF Quad Shape { appearance Appearance { material Material {} }
  geometry IndexedFaceSet { coord DEF C Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0] }
    coordIndex [0 1 2 3 -1] } }
DEF CI CoordinateInterpolator { key [0, 0.3, 1]
  keyValue [0 0 0, 1 0 0, 1 1 0, 0 1 0,
            0 0 0.5, 2 0 0, 1 2 0, 0 1 -1,
            0 0 0, 1 0 0, 1 1 0, 0 1 0] }
ROUTE T.fraction_changed TO CI.set_fraction
ROUTE CI.value_changed TO C.set_point
";

#[test]
fn coordinate_interpolator_plays_the_spec_linear_interpolation() {
    let loaded =
        animed::internals::format::load_bytes(COORD_WRL.as_bytes(), std::path::Path::new("q.wrl"))
            .unwrap_or_else(|e| panic!("{e}"));
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    let s = loaded.scene;
    let id = s.find_node("Quad").expect("the shape");
    let points = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    assert_eq!(
        s.meshes[0].positions, points,
        "one vertex per point, in order"
    );
    let keys = [0.0f32, 0.3, 1.0];
    let kv: [[Vec3; 4]; 3] = [
        points,
        [
            Vec3::new(0.0, 0.0, 0.5),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(0.0, 1.0, -1.0),
        ],
        points,
    ];
    // VRML97 §4.6.8: linear interpolation of keyValue at the cycle fraction.
    let spec = |t: f32| -> [Vec3; 4] {
        let f = (t / 2.0).fract();
        let i = if f < keys[1] { 0 } else { 1 };
        let s = (f - keys[i]) / (keys[i + 1] - keys[i]);
        [0, 1, 2, 3].map(|p| kv[i][p].lerp(kv[i + 1][p], s))
    };
    for t in [0.0f32, 0.13, 0.6, 0.61, 0.9, 1.37, 1.99, 2.5, 3.3] {
        let pose = evaluate(&s, t);
        let d = pose.deformed(id).expect("the quad is morphed");
        for (p, want) in d.positions.iter().zip(spec(t)) {
            assert!(close(*p, want, 1e-5), "t={t}: {p} vs {want}");
        }
    }
}

#[test]
fn vrml97_writer_plays_morphs_and_skins_as_coordinate_interpolators() {
    use animed::internals::format::save::{to_bytes, OutputFormat};
    for (name, s) in [("blob", morphing_sphere()), ("tube", bending_cylinder())] {
        let (bytes, report) = to_bytes(
            &s,
            OutputFormat::Vrml97,
            &animed::internals::format::WriteOptions::default(),
        );
        let text = String::from_utf8(bytes.clone()).unwrap();
        assert!(
            text.contains("CoordinateInterpolator") && text.contains("NormalInterpolator"),
            "{name}"
        );
        assert!(
            text.contains(".set_point") && text.contains(".set_vector"),
            "{name}"
        );
        assert!(
            report.warnings.iter().all(|w| !w.contains("weights")),
            "{:?}",
            report.warnings
        );
        let back = animed::internals::format::load_bytes(&bytes, std::path::Path::new("x.wrl"))
            .unwrap_or_else(|e| panic!("{e}"));
        let r = back.scene;
        // Inside the cycle: the written TimeSensor loops, so at 2 s it is
        // back at the start where animed's hold keeps the last key.
        for t in [0.0f32, 0.5, 1.0, 1.5, 1.9] {
            // Each shape's drawn vertices in world space, both sides.
            let world_points = |sc: &Scene| -> Vec<Vec3> {
                let p = evaluate(sc, t);
                let (i, _) = sc
                    .nodes
                    .iter()
                    .enumerate()
                    .find(|(_, n)| matches!(n.kind, NodeKind::Shape(_)))
                    .unwrap();
                let d = p.deformed(NodeId(i as u32)).expect("deformed");
                if d.world_space {
                    d.positions.clone()
                } else {
                    d.positions
                        .iter()
                        .map(|v| p.world[i].transform_point3(*v))
                        .collect()
                }
            };
            let (a, b) = (world_points(&s), world_points(&r));
            // The reader drops vertices no face uses, so match by place:
            // every vertex read back lies on one written (within the export
            // tolerance, 0.1% of the diagonal, sampled per frame; the blob's
            // step keys become one-frame ramps, and 0, 1, 2 s are key
            // times), and the boxes agree.
            assert!(a.len().abs_diff(b.len()) <= 4, "{} vs {}", a.len(), b.len());
            let worst = b
                .iter()
                .map(|y| {
                    a.iter()
                        .map(|x| (*x - *y).length())
                        .fold(f32::MAX, f32::min)
                })
                .fold(0.0, f32::max);
            assert!(worst < 0.02, "{name} t={t}: worst {worst}");
            let bx = |v: &[Vec3]| {
                v.iter()
                    .fold((Vec3::MAX, Vec3::MIN), |(l, h), p| (l.min(*p), h.max(*p)))
            };
            let ((la, ha), (lb, hb)) = (bx(&a), bx(&b));
            assert!(
                close(la, lb, 0.02) && close(ha, hb, 0.02),
                "{name} t={t}: {la} {ha} vs {lb} {hb}"
            );
        }
    }
}
