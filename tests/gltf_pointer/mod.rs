//! What other glTF players see of animation core glTF channels cannot
//! carry: KHR_animation_pointer channels for lights, cameras and materials,
//! and tracks that loop with their own period unrolled over the clip. The
//! file is read here with the test's own GLB/accessor reader (`gltf_node`)
//! and a linear sampler written out below, so animed's reader is not the
//! judge; a second test reads the file back without animed's key notes, so
//! only the written channels (through `pointer_anim`) carry the motion.

use super::gltf_node::{floats, split_glb};
use animed::internals::anim::{
    evaluate, Animation, Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track,
};
use animed::internals::format::gltf::to_bytes;
use animed::internals::format::{self, WriteOptions};
use animed::internals::scene::{Clip, MaterialId, NodeKind, Scene};
use glam::Vec3;
use serde_json::Value as Json;
use std::f32::consts::PI;
use std::path::Path;

fn linear<V>(keys: &[(f32, V)]) -> Vec<Key<V>>
where
    V: Copy,
{
    keys.iter()
        .map(|&(f, v)| Key::new(f, v).with_interp(Interp::Linear))
        .collect()
}

fn track(of: TargetRef, property: Property, repeat: Repeat, keys: Keys) -> Track {
    Track::new(Target { of, property }, repeat, keys).unwrap()
}

/// The material of the first shape at or under `name`.
fn shape_material(s: &Scene, name: &str) -> MaterialId {
    let mut stack = vec![s.find_node(name).unwrap()];
    while let Some(id) = stack.pop() {
        let n = s.node(id);
        if let NodeKind::Shape(sh) = &n.kind {
            return sh.material;
        }
        stack.extend(n.children.iter().rev());
    }
    panic!("no shape under {name}")
}

/// The demo with a light, the camera and the ball's material animated, and
/// the ball's translation looping every second of the 4-second clip.
fn animated() -> Scene {
    let mut s = format::demo().unwrap().scene;
    let node = |n: &str| TargetRef::Node(s.find_node(n).unwrap());
    let mat = TargetRef::Material(shape_material(&s, "Ball"));
    let mut tracks = s.animation.tracks.clone();
    tracks.retain(|t| t.target.property != Property::Translation);
    tracks.extend([
        track(
            node("Ball"),
            Property::Translation,
            Repeat::Loop,
            Keys::Vec3(linear(&[
                (0.0, Vec3::ZERO),
                (24.0, Vec3::new(2.0, 1.0, 0.0)),
            ])),
        ),
        track(
            node("Sun"),
            Property::LightIntensity,
            Repeat::Constant,
            Keys::Scalar(linear(&[(0.0, 0.2), (48.0, 1.0), (96.0, 0.5)])),
        ),
        track(
            node("Sun"),
            Property::LightColor,
            Repeat::Constant,
            Keys::Vec3(linear(&[(0.0, Vec3::X), (96.0, Vec3::new(0.2, 0.4, 1.0))])),
        ),
        track(
            node("Main"),
            Property::CameraFov,
            Repeat::Constant,
            Keys::Scalar(linear(&[(0.0, 0.6), (96.0, 1.2)])),
        ),
        track(
            mat,
            Property::Diffuse,
            Repeat::Constant,
            Keys::Vec3(linear(&[
                (0.0, Vec3::new(1.0, 0.5, 0.0)),
                (96.0, Vec3::new(0.0, 0.5, 1.0)),
            ])),
        ),
        track(
            mat,
            Property::Transparency,
            Repeat::Constant,
            Keys::Scalar(linear(&[(0.0, 0.0), (96.0, 0.5)])),
        ),
        track(
            mat,
            Property::Emissive,
            Repeat::Constant,
            Keys::Vec3(linear(&[
                (0.0, Vec3::ZERO),
                (48.0, Vec3::new(0.5, 0.5, 0.0)),
            ])),
        ),
        track(
            mat,
            Property::Shininess,
            Repeat::Constant,
            Keys::Scalar(linear(&[(0.0, 0.2), (96.0, 0.9)])),
        ),
    ]);
    let duration = s.settings.duration;
    s.set_clips(
        vec![Clip {
            name: "Show".into(),
            animation: Animation { tracks },
            duration,
        }],
        0,
    );
    s
}

/// A LINEAR sampler's value at `t` seconds, `width` floats per key,
/// clamped at both ends (glTF 2.0 §3.11.2, linear interpolation).
fn linear_at(times: &[f32], values: &[f32], width: usize, t: f32) -> Vec<f32> {
    let row = |k: usize| &values[k * width..(k + 1) * width];
    if t <= times[0] {
        return row(0).to_vec();
    }
    let last = times.len() - 1;
    if t >= times[last] {
        return row(last).to_vec();
    }
    let k = times.partition_point(|&x| x <= t) - 1;
    let u = (t - times[k]) / (times[k + 1] - times[k]);
    (0..width)
        .map(|c| row(k)[c] + (row(k + 1)[c] - row(k)[c]) * u)
        .collect()
}

/// sRGB → linear light (IEC 61966-2-1), written out here.
fn to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

struct Written {
    doc: Json,
    bin: Vec<u8>,
}

impl Written {
    fn of(s: &Scene) -> (Written, animed::internals::format::WriteReport) {
        let (bytes, report) = to_bytes(s, &WriteOptions::default(), true);
        let (json, bin) = split_glb(&bytes);
        let doc = serde_json::from_slice(json).unwrap();
        (
            Written {
                doc,
                bin: bin.to_vec(),
            },
            report,
        )
    }

    /// The sampler of the channel whose target satisfies `is`, played at
    /// `t` seconds.
    fn at(&self, is: &dyn Fn(&Json) -> bool, t: f32) -> Vec<f32> {
        let anim = &self.doc["animations"][0];
        let ch = anim["channels"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| is(&c["target"]))
            .unwrap_or_else(|| panic!("no such channel in {}", anim["channels"]));
        let sampler = &anim["samplers"][ch["sampler"].as_u64().unwrap() as usize];
        assert_eq!(sampler["interpolation"], "LINEAR");
        let input = sampler["input"].as_u64().unwrap() as usize;
        let output = sampler["output"].as_u64().unwrap() as usize;
        let times = floats(&self.doc, &self.bin, input);
        let values = floats(&self.doc, &self.bin, output);
        let width = values.len() / times.len();
        linear_at(&times, &values, width, t)
    }

    fn pointer(&self, p: &str, t: f32) -> Vec<f32> {
        self.at(
            &|target| {
                target["path"] == "pointer"
                    && target["extensions"]["KHR_animation_pointer"]["pointer"] == p
            },
            t,
        )
    }

    /// Index of the entry of `list` (a JSON pointer) named `name`.
    fn index(&self, list: &str, name: &str) -> usize {
        self.doc
            .pointer(list)
            .and_then(Json::as_array)
            .unwrap()
            .iter()
            .position(|x| x["name"] == name)
            .unwrap_or_else(|| panic!("no {name} in {list}"))
    }
}

fn near(a: &[f32], b: &[f32], tol: f32, what: &str) {
    assert!(
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol),
        "{what}: written {a:?}, expected {b:?}"
    );
}

const TIMES: [f32; 6] = [0.0, 0.3, 1.1, 1.9, 2.5, 3.7];

#[test]
fn a_looping_track_plays_through_the_whole_clip() {
    let s = animated();
    let (w, _) = Written::of(&s);
    let ball = w.index("/nodes", "Ball");
    for t in TIMES {
        let ours = evaluate(&s, t).transforms[s.find_node("Ball").unwrap().0 as usize].translation;
        let file = w.at(
            &|target| target["node"] == ball && target["path"] == "translation",
            t,
        );
        near(&file, &ours.to_array(), 1e-3, &format!("Ball at {t} s"));
    }
    // Past the first period the ball is still moving (it would hold at the
    // end of one period if the loop were written once).
    let a = w.at(&|g| g["node"] == ball && g["path"] == "translation", 2.25);
    assert!((a[0] - 0.5).abs() < 1e-3, "{a:?}");
}

#[test]
fn lights_cameras_and_materials_animate_through_pointers() {
    let s = animated();
    let (w, report) = Written::of(&s);
    let used: Vec<&str> = w.doc["extensionsUsed"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(Json::as_str)
        .collect();
    assert!(used.contains(&"KHR_animation_pointer"), "{used:?}");
    let sun = w.index("/extensions/KHR_lights_punctual/lights", "Sun");
    let main = w.index("/cameras", "Main");
    let mat = shape_material(&s, "Ball");
    let ball_mat = w.doc["meshes"][w.doc["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|n| n["name"] == "Ball")
        .and_then(|n| n["mesh"].as_u64())
        .unwrap_or_else(|| {
            // The ball's shape is its own node (child of the transform).
            let ball = w.index("/nodes", "Ball");
            let child = w.doc["nodes"][ball]["children"][0].as_u64().unwrap() as usize;
            w.doc["nodes"][child]["mesh"].as_u64().unwrap()
        }) as usize]["primitives"][0]["material"]
        .as_u64()
        .unwrap();
    assert_eq!(
        w.doc["materials"][ball_mat as usize]["alphaMode"], "BLEND",
        "animated transparency needs a blending material"
    );
    for t in TIMES {
        let pose = evaluate(&s, t);
        let light = |name: &str| {
            let id = s.find_node(name).unwrap();
            pose.lights
                .iter()
                .find(|(n, _)| *n == id)
                .unwrap()
                .1
                .clone()
        };
        let l = light("Sun");
        let at = format!("/extensions/KHR_lights_punctual/lights/{sun}");
        near(
            &w.pointer(&format!("{at}/intensity"), t),
            &[l.intensity.clamp(0.0, 1.0) * PI],
            0.01,
            &format!("Sun intensity at {t}"),
        );
        near(
            &w.pointer(&format!("{at}/color"), t),
            &l.color.to_array().map(to_linear),
            0.01,
            &format!("Sun colour at {t}"),
        );
        let cam = pose.cameras.iter().map(|(_, c)| c).next().unwrap();
        let animed::internals::scene::CameraKind::Perspective { height_angle } = cam.kind else {
            panic!("the demo's camera is perspective")
        };
        near(
            &w.pointer(&format!("/cameras/{main}/perspective/yfov"), t),
            &[height_angle],
            1e-3,
            &format!("Main fov at {t}"),
        );
        let m = &pose.materials[mat.0 as usize];
        let d = m.diffuse.to_array().map(to_linear);
        near(
            &w.pointer(
                &format!("/materials/{ball_mat}/pbrMetallicRoughness/baseColorFactor"),
                t,
            ),
            &[d[0], d[1], d[2], 1.0 - m.transparency],
            0.01,
            &format!("BallMat base colour at {t}"),
        );
        near(
            &w.pointer(&format!("/materials/{ball_mat}/emissiveFactor"), t),
            &m.emissive.to_array().map(to_linear),
            0.01,
            &format!("BallMat emissive at {t}"),
        );
    }
    // Shininess has no core glTF target: said, not dropped silently.
    assert!(
        report
            .warnings
            .iter()
            .any(|w| w.contains("shininess") && w.contains("key note")),
        "{:?}",
        report.warnings
    );
}

#[test]
fn without_the_key_notes_animed_reads_the_pointer_channels_back() {
    let s = animed_scene_without_notes();
    let (back, original) = s;
    let mat = shape_material(&original, "Ball");
    let back_mat = shape_material(&back, "Ball");
    for t in TIMES {
        let (a, b) = (evaluate(&original, t), evaluate(&back, t));
        let light = |s: &Scene, p: &animed::internals::anim::Pose, name: &str| {
            let id = s.find_node(name).unwrap();
            p.lights.iter().find(|(n, _)| *n == id).unwrap().1.clone()
        };
        let (la, lb) = (light(&original, &a, "Sun"), light(&back, &b, "Sun"));
        near(
            &[lb.intensity],
            &[la.intensity],
            0.01,
            &format!("Sun intensity at {t}"),
        );
        near(
            &lb.color.to_array(),
            &la.color.to_array(),
            0.01,
            &format!("Sun colour at {t}"),
        );
        // The demo's own tracks: a spot light's intensity (its attenuation
        // kept, not re-derived) and a point light's looping colour.
        let (sa, sb) = (
            light(&original, &a, "SpotLamp"),
            light(&back, &b, "SpotLamp"),
        );
        assert_eq!(sb.attenuation, sa.attenuation);
        near(
            &[sb.intensity],
            &[sa.intensity],
            0.01,
            &format!("SpotLamp intensity at {t}"),
        );
        let (pa, pb) = (light(&original, &a, "Lamp"), light(&back, &b, "Lamp"));
        near(
            &pb.color.to_array(),
            &pa.color.to_array(),
            0.01,
            &format!("Lamp colour at {t}"),
        );
        let (ma, mb) = (
            &a.materials[mat.0 as usize],
            &b.materials[back_mat.0 as usize],
        );
        near(
            &mb.diffuse.to_array(),
            &ma.diffuse.to_array(),
            0.01,
            &format!("diffuse at {t}"),
        );
        near(
            &[mb.transparency],
            &[ma.transparency],
            0.01,
            &format!("transparency at {t}"),
        );
        near(
            &mb.emissive.to_array(),
            &ma.emissive.to_array(),
            0.01,
            &format!("emissive at {t}"),
        );
    }
}

/// The written .gltf read back with `asset.extras` (the key notes) removed,
/// and the scene it was written from.
fn animed_scene_without_notes() -> (Scene, Scene) {
    let s = animated();
    let (bytes, _) = to_bytes(&s, &WriteOptions::default(), false);
    let mut doc: Json = serde_json::from_slice(&bytes).unwrap();
    doc["asset"].as_object_mut().unwrap().remove("extras");
    let bytes = serde_json::to_vec(&doc).unwrap();
    let back =
        format::load_bytes(&bytes, Path::new("pointers.gltf")).unwrap_or_else(|e| panic!("{e}"));
    (back.scene, s)
}
