//! Property-based round trips: random scenes with random tracks (every
//! property kind, interpolation, TCB, ease, repeat mode, fractional frames)
//! → export → import gives every key back bit for bit, and re-export is
//! byte-identical (VRML97 and Inventor).
mod writers_common;

use animed::internals::anim::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use animed::internals::format::save::{to_bytes, OutputFormat};
use animed::internals::format::{load_bytes, WriteOptions};
use animed::internals::scene::{Camera, Light, LightKind, Material, Node, NodeKind, Scene, Shape};
use glam::{Quat, Vec3};
use proptest::prelude::*;
use std::path::Path;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn f(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * ((self.next() >> 40) as f32 / (1u64 << 24) as f32)
    }
    fn pick(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

fn random_keys<V: Copy>(r: &mut Rng, value: impl Fn(&mut Rng) -> V, boolean: bool) -> Vec<Key<V>> {
    let n = 1 + r.pick(5);
    let mut frame = r.f(-5.0, 10.0);
    (0..n)
        .map(|_| {
            let mut k = Key::new(frame, value(r));
            k.interp = if boolean {
                Interp::Step
            } else {
                [Interp::Step, Interp::Linear, Interp::Tcb][r.pick(3)]
            };
            k.tension = r.f(-1.0, 1.0);
            k.continuity = r.f(-1.0, 1.0);
            k.bias = r.f(-1.0, 1.0);
            k.ease_in = r.f(0.0, 1.0);
            k.ease_out = r.f(0.0, 1.0);
            frame += r.f(0.01, 30.0);
            k
        })
        .collect()
}

fn random_scene(seed: u64) -> Scene {
    let mut r = Rng(seed | 1);
    let mut s = Scene::new();
    s.settings.fps = [24.0, 25.0, 30.0, 12.5][r.pick(4)];
    s.settings.duration = r.f(10.0, 120.0);
    let mesh = s.add_mesh(writers_common::cube(""));
    let names = ["A", "B", "A", "", "light", "x y"];
    let mut nodes = Vec::new();
    let mut materials = Vec::new();
    for i in 0..(2 + r.pick(5)) {
        let name = names[r.pick(names.len())].to_string();
        let parent = if nodes.is_empty() || r.pick(2) == 0 {
            None
        } else {
            Some(nodes[r.pick(nodes.len())])
        };
        let kind = match r.pick(5) {
            0 => NodeKind::Group,
            1 | 2 => {
                let m = s.add_material(Material {
                    name: ["", "Mat", "Mat"][r.pick(3)].into(),
                    diffuse: Vec3::new(r.f(0.0, 1.0), r.f(0.0, 1.0), r.f(0.0, 1.0)),
                    ..Default::default()
                });
                materials.push(m);
                NodeKind::Shape(Shape { mesh, material: m })
            }
            3 => NodeKind::Light(if r.pick(2) == 0 {
                Light::spot()
            } else {
                Light::new(if r.pick(2) == 0 {
                    LightKind::Point
                } else {
                    LightKind::Directional
                })
            }),
            _ => NodeKind::Camera(Camera::default()),
        };
        let mut node = Node::new(name, kind);
        if r.pick(2) == 0 {
            node.transform.translation = Vec3::new(r.f(-5.0, 5.0), r.f(-5.0, 5.0), i as f32);
        }
        node.visible = r.pick(6) != 0;
        nodes.push(s.add_node(parent, node));
    }
    for _ in 0..(1 + r.pick(8)) {
        let id = nodes[r.pick(nodes.len())];
        let candidates: Vec<Property> = Property::ALL
            .iter()
            .copied()
            .filter(|p| match (p.owner(), &s.node(id).kind) {
                ("node", _) => true,
                ("light", NodeKind::Light(_)) => true,
                ("camera", NodeKind::Camera(_)) => true,
                ("material", _) => !materials.is_empty(),
                _ => false,
            })
            .collect();
        let property = candidates[r.pick(candidates.len())];
        let of = if property.owner() == "material" {
            TargetRef::Material(materials[r.pick(materials.len())])
        } else {
            TargetRef::Node(id)
        };
        // One track per target/property, as the editor keeps them.
        if s.animation
            .tracks
            .iter()
            .any(|t| t.target.of == of && t.target.property == property)
        {
            continue;
        }
        use animed::internals::anim::ValueKind as K;
        let keys = match property.kind() {
            K::Scalar => Keys::Scalar(random_keys(&mut r, |r| r.f(0.0, 1.0), false)),
            K::Vec3 | K::Color => Keys::Vec3(random_keys(
                &mut r,
                |r| Vec3::new(r.f(-3.0, 3.0), r.f(0.0, 1.0), r.f(-10.0, 10.0)),
                false,
            )),
            K::Rotation => Keys::Rotation(random_keys(
                &mut r,
                |r| {
                    Quat::from_axis_angle(
                        Vec3::new(r.f(-1.0, 1.0), r.f(-1.0, 1.0), r.f(0.1, 1.0)).normalize(),
                        r.f(-7.0, 7.0),
                    )
                },
                false,
            )),
            K::Bool => Keys::Bool(random_keys(&mut r, |r| r.pick(2) == 0, true)),
            // Morph weights need a morphed mesh; the generator makes none.
            K::Weights => continue,
        };
        let repeat = [Repeat::Constant, Repeat::Loop][r.pick(2)];
        s.animation.tracks.push(Track {
            target: Target { of, property },
            repeat,
            keys,
        });
    }
    s
}

fn reimport(bytes: &[u8], name: &str) -> Scene {
    let loaded = load_bytes(bytes, Path::new(name)).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        !loaded.warnings.iter().any(|w| w.contains("key note")),
        "{:?}",
        loaded.warnings
    );
    loaded.scene
}

/// Same tracks (keys bit for bit), matched by position.
fn same_tracks(a: &Scene, b: &Scene) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.animation.tracks.len(), b.animation.tracks.len());
    for (x, y) in a.animation.tracks.iter().zip(&b.animation.tracks) {
        prop_assert_eq!(x.target.property, y.target.property);
        prop_assert_eq!(x.repeat, y.repeat);
        prop_assert_eq!(&x.keys, &y.keys);
    }
    prop_assert_eq!(a.settings.fps.to_bits(), b.settings.fps.to_bits());
    prop_assert_eq!(a.settings.duration.to_bits(), b.settings.duration.to_bits());
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn vrml97_keys_survive_and_reexport_is_identical(seed in any::<u64>()) {
        let s = random_scene(seed);
        let opts = WriteOptions::default();
        let (a, _) = to_bytes(&s, OutputFormat::Vrml97, &opts);
        let t = reimport(&a, "random.wrl");
        same_tracks(&s, &t)?;
        let (b, _) = to_bytes(&t, OutputFormat::Vrml97, &opts);
        if a != b {
            std::fs::write("/tmp/prop_a.wrl", &a).unwrap();
            std::fs::write("/tmp/prop_b.wrl", &b).unwrap();
        }
        prop_assert!(a == b, "re-export differs (seed {}, /tmp/prop_a.wrl vs /tmp/prop_b.wrl)", seed);
    }

    #[test]
    fn inventor_keys_survive_and_reexport_is_identical(seed in any::<u64>()) {
        let s = random_scene(seed);
        let opts = WriteOptions::default();
        let (a, _) = to_bytes(&s, OutputFormat::Inventor, &opts);
        let t = reimport(&a, "random.iv");
        same_tracks(&s, &t)?;
        let (b, _) = to_bytes(&t, OutputFormat::Inventor, &opts);
        if a != b {
            std::fs::write("/tmp/prop_a.iv", &a).unwrap();
            std::fs::write("/tmp/prop_b.iv", &b).unwrap();
        }
        prop_assert!(a == b, "re-export differs (seed {}, /tmp/prop_a.iv vs /tmp/prop_b.iv)", seed);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// glTF (.gltf and .glb): the key note in the asset's extras brings
    /// every key back bit for bit, and re-export is byte-identical.
    #[test]
    fn gltf_keys_survive_and_reexport_is_identical(seed in any::<u64>()) {
        let s = random_scene(seed);
        let opts = WriteOptions::default();
        for (format, name) in [(OutputFormat::Gltf, "random.gltf"), (OutputFormat::Glb, "random.glb")] {
            let (a, _) = to_bytes(&s, format, &opts);
            let t = reimport(&a, name);
            same_tracks(&s, &t)?;
            let (b, _) = to_bytes(&t, format, &opts);
            if a != b {
                std::fs::write(format!("/tmp/prop_a_{name}"), &a).unwrap();
                std::fs::write(format!("/tmp/prop_b_{name}"), &b).unwrap();
            }
            prop_assert!(a == b, "re-export differs (seed {}, /tmp/prop_a_{} vs /tmp/prop_b_{})", seed, name, name);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// X3D 4.0 in both encodings (and gzipped XML): the key note in the
    /// WorldInfo brings every key back bit for bit, and re-export is
    /// byte-identical.
    #[test]
    fn x3d_keys_survive_and_reexport_is_identical(seed in any::<u64>()) {
        let s = random_scene(seed);
        let opts = WriteOptions::default();
        for (format, name) in [
            (OutputFormat::X3dClassic, "random.x3dv"),
            (OutputFormat::X3dXml, "random.x3d"),
            (OutputFormat::X3dXmlGz, "random.x3dz"),
        ] {
            let (a, _) = to_bytes(&s, format, &opts);
            let t = reimport(&a, name);
            same_tracks(&s, &t)?;
            let (b, _) = to_bytes(&t, format, &opts);
            if a != b {
                std::fs::write(format!("/tmp/prop_a_{name}"), &a).unwrap();
                std::fs::write(format!("/tmp/prop_b_{name}"), &b).unwrap();
            }
            prop_assert!(a == b, "re-export differs (seed {}, /tmp/prop_a_{} vs /tmp/prop_b_{})", seed, name, name);
        }
    }
}
