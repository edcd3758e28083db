//! glTF 2.0 reading and writing (issue 14): hand-made files in
//! `tests/data/gltf/` (made by `make.py` there), round trips, the exactness
//! of exported TCB curves, and checks against independent implementations
//! (the Khronos validator and three.js under node; see `gltf_node.rs`).

mod gltf_corpus;
mod gltf_emissive;
mod gltf_node;
mod gltf_pointer;

use animed::internals::anim::{
    evaluate, Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Value,
};
use animed::internals::format::gltf::{read, to_bytes, ReadOptions};
use animed::internals::format::{self, WriteOptions};
use animed::internals::scene::{
    Clip, ImageSource, LightKind, Node, NodeKind, Scene, TextureModel, Wrap,
};
use glam::{Quat, Vec3};
use std::path::{Path, PathBuf};
use std::process::Command;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/gltf")
        .join(name)
}

fn load(name: &str) -> format::Loaded {
    format::load(&data(name)).unwrap_or_else(|e| panic!("{e}"))
}

fn read_with(name: &str, opts: &ReadOptions) -> Result<format::Loaded, format::LoadError> {
    let p = data(name);
    let bytes = std::fs::read(&p).unwrap();
    read(&bytes, &p, opts, &|q: &Path| {
        std::fs::read(q).map_err(|e| e.to_string())
    })
}

fn animed(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run animed");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn translation(s: &Scene, name: &str, t: f32) -> Vec3 {
    evaluate(s, t).transforms[s.find_node(name).unwrap().0 as usize].translation
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).abs().max_element() < 1e-5
}

#[test]
fn gltf_and_glb_read_the_same_scene() {
    let a = load("animated.gltf").scene;
    let b = load("animated.glb").scene;
    let names: Vec<&str> = a.nodes.iter().map(|n| n.name.as_str()).collect();
    assert_eq!(names, ["Box", "Cam", "Lamp"], "the default scene only");
    assert_eq!(a.nodes, b.nodes);
    assert_eq!(a.meshes, b.meshes);
    assert_eq!(a.materials, b.materials);
    assert_eq!(a.clips_owned(), b.clips_owned());
}

#[test]
fn every_animation_is_a_clip_and_the_first_plays() {
    let mut s = load("animated.gltf").scene;
    let names: Vec<&str> = s.clips.names().collect();
    assert_eq!(names, ["Walk", "Spin"]);
    assert_eq!(s.settings.fps, 24.0, "key times on whole frames at 24 fps");
    assert_eq!(s.settings.duration, 48.0);
    // Walk: LINEAR translation, STEP rotation.
    assert!(close(translation(&s, "Box", 0.5), Vec3::new(1.0, 0.0, 0.0)));
    assert!(close(translation(&s, "Box", 1.5), Vec3::new(2.0, 2.0, 0.0)));
    let box_ = s.find_node("Box").unwrap().0 as usize;
    let rot = |s: &Scene, t: f32| evaluate(s, t).transforms[box_].rotation;
    assert_eq!(
        rot(&s, 0.99),
        Quat::IDENTITY,
        "step holds until the next key"
    );
    assert!(rot(&s, 1.0).angle_between(Quat::from_rotation_z(std::f32::consts::FRAC_PI_2)) < 1e-5);
    // Spin: CUBICSPLINE scale (1 → 3, out-tangent 2/s, in-tangent 0, Δt 2 s):
    // at s = 1/2, p = ½·1 + ⅛·2·2 + ½·3 − ⅛·2·0 = 2.5; slerp rotation.
    s.play_clip("Spin").unwrap();
    let scale = evaluate(&s, 1.0).transforms[box_].scale;
    assert!(close(scale, Vec3::splat(2.5)), "{scale}");
    assert!(rot(&s, 0.5).angle_between(Quat::from_rotation_y(std::f32::consts::FRAC_PI_4)) < 1e-5);
}

#[test]
fn materials_lights_and_cameras_map_as_documented() {
    let s = load("animated.gltf").scene;
    let red = &s.materials[s.find_material("Red").unwrap().0 as usize];
    // sRGB(0.5) = 0.7354; roughness 0.5 → Blinn-Phong 30 → shininess 30/128.
    assert!((red.diffuse.x - 0.735_36).abs() < 1e-4 && red.diffuse.y == 0.0);
    assert!((red.shininess - 30.0 / 128.0).abs() < 1e-6);
    let lamp = s.node(s.find_node("Lamp").unwrap()).light().unwrap();
    assert_eq!(lamp.kind, LightKind::Point);
    // 100 cd: 1/max(π/100·d², 1).
    assert!((lamp.attenuation.z - std::f32::consts::PI / 100.0).abs() < 1e-7);
    assert_eq!(lamp.radius, 20.0);
    let cam = s.node(s.find_node("Cam").unwrap()).camera().unwrap();
    assert_eq!(cam.description, "Front");
    assert_eq!(cam.near, Some(0.5));
    assert!(
        matches!(cam.kind, animed::internals::scene::CameraKind::Perspective { height_angle } if height_angle == 0.8)
    );
    assert_eq!(
        s.settings.headlight,
        Some(false),
        "the file brings its own light"
    );
}

#[test]
fn scene_option_picks_another_scene_and_rejects_missing_ones() {
    let l = read_with("animated.gltf", &ReadOptions { scene: Some(1) }).unwrap();
    let names: Vec<&str> = l.scene.nodes.iter().map(|n| n.name.as_str()).collect();
    assert_eq!(names, ["Other"]);
    let e = read_with("animated.gltf", &ReadOptions { scene: Some(5) }).unwrap_err();
    assert!(e.to_string().contains("no scene 5"), "{e}");
}

#[test]
fn topologies_colours_sparse_and_matrix() {
    let s = load("topologies.gltf").scene;
    let root = s.node(s.find_node("Shapes").unwrap());
    let t = root.transform;
    assert_eq!(
        (t.translation, t.scale),
        (Vec3::new(1.0, 2.0, 3.0), Vec3::splat(2.0))
    );
    let meshes: Vec<_> = s
        .nodes
        .iter()
        .filter_map(|n| match &n.kind {
            NodeKind::Shape(sh) => Some(&s.meshes[sh.mesh.0 as usize]),
            _ => None,
        })
        .collect();
    assert_eq!(meshes.len(), 7);
    let counts: Vec<(usize, usize, usize)> = meshes
        .iter()
        .map(|m| (m.points.len(), m.lines.len(), m.triangles.len()))
        .collect();
    // POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLE_STRIP, TRIANGLE_FAN, sparse POINTS.
    assert_eq!(
        counts,
        [
            (4, 0, 0),
            (0, 2, 0),
            (0, 4, 0),
            (0, 3, 0),
            (0, 0, 2),
            (0, 0, 2),
            (4, 0, 0)
        ]
    );
    // Strip triangle 1 is (v1, v3, v2) (§3.7.2.1: every other one
    // reversed so all keep the first one's winding).
    let strip = meshes[4];
    // No normals in the file: flat ones, the triangles unwelded.
    assert_eq!(strip.positions.len(), 6);
    assert!(
        strip.normals.iter().all(|n| *n == Vec3::Z),
        "{:?}",
        strip.normals
    );
    assert_eq!(
        strip.positions[3..6],
        [Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y]
    );
    // u8-normalised RGBA colours (alpha dropped): red, green, blue, white.
    assert_eq!(meshes[0].colors, [Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE]);
    // Sparse: zeros with vertex 2 replaced.
    assert_eq!(
        meshes[6].positions,
        [Vec3::ZERO, Vec3::ZERO, Vec3::new(0.0, 2.0, 0.0), Vec3::ZERO]
    );
}

#[test]
fn errors_name_the_json_pointer() {
    let e = format::load(&data("requires_meshopt.gltf"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("/extensionsRequired/0") && e.contains("EXT_meshopt_compression"),
        "{e}"
    );
    let e = format::load(&data("accessor_overrun.gltf"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("/meshes/0/primitives/0/attributes/POSITION"),
        "{e}"
    );
    assert!(e.contains("past the end"), "{e}");
    for bad in [
        &b"glTF\x02\0\0\0\xff\xff\xff\x7f"[..],
        b"glTF\x01\0\0\0\x0c\0\0\0",
        b"{\"asset\":{}}",
        b"{",
    ] {
        let r = format::load_bytes(bad, Path::new("bad.glb"));
        assert!(r.is_err(), "{bad:?}");
    }
}

#[test]
fn cli_takes_gltf_with_animation_names() {
    let f = data("animated.gltf");
    let f = f.to_str().unwrap();
    let (code, out, err) = animed(&["info", f, "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["format"], "glTF 2.0");
    assert_eq!(v["animations"][1]["name"], "Spin");
    let (code, out, err) = animed(&[
        "sample",
        f,
        "--target",
        "Box.scale",
        "--times",
        "1",
        "--animation",
        "Spin",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.trim(), "1\t2.5 2.5 2.5");
    let (code, _, err) = animed(&[
        "sample",
        f,
        "--target",
        "Box.scale",
        "--times",
        "1",
        "--animation",
        "Run",
    ]);
    assert_ne!(code, 0);
    assert!(err.contains("0 `Walk`, 1 `Spin`"), "{err}");
}

/// A little scene with TCB, linear, step and squad keys in two clips.
fn authored() -> Scene {
    let mut s = format::demo().unwrap().scene;
    let ball = s.find_node("Ball").unwrap();
    let t = |p| Target {
        of: TargetRef::Node(ball),
        property: p,
    };
    let tcb = Keys::Vec3(vec![
        Key::new(0.0, Vec3::ZERO).with_tcb(0.3, -0.2, 0.5),
        Key::new(7.0, Vec3::new(1.0, 2.0, 0.5)).with_tcb(-0.5, 0.4, 0.1),
        Key::new(20.0, Vec3::new(-1.0, 0.5, 2.0)),
        Key::new(31.0, Vec3::new(0.0, 1.0, -1.0)).with_interp(Interp::Linear),
        Key::new(40.0, Vec3::new(2.0, 0.0, 0.0)),
    ]);
    let hop = Clip {
        name: "Hop".into(),
        animation: animed::internals::anim::Animation {
            tracks: vec![
                Track::new(t(Property::Translation), Repeat::Constant, tcb).unwrap(),
                Track::new(
                    t(Property::Scale),
                    Repeat::Constant,
                    Keys::Vec3(vec![
                        Key::new(0.0, Vec3::ONE).with_interp(Interp::Step),
                        Key::new(12.0, Vec3::splat(2.0)).with_interp(Interp::Step),
                    ]),
                )
                .unwrap(),
            ],
        },
        duration: 48.0,
    };
    let mut clips = vec![Clip {
        name: "Demo".into(),
        animation: s.animation.clone(),
        duration: s.settings.duration,
    }];
    clips.push(hop);
    s.set_clips(clips, 0);
    s
}

#[test]
fn export_import_export_is_byte_identical_with_every_key() {
    let s = authored();
    for binary in [false, true] {
        let (a, _) = to_bytes(&s, &WriteOptions::default(), binary);
        let path = Path::new(if binary { "x.glb" } else { "x.gltf" });
        let back = format::load_bytes(&a, path).unwrap_or_else(|e| panic!("{e}"));
        assert!(back.warnings.is_empty(), "{:?}", back.warnings);
        assert_eq!(
            back.scene.clips_owned(),
            s.clips_owned(),
            "every key bit for bit"
        );
        let (b, _) = to_bytes(&back.scene, &WriteOptions::default(), binary);
        assert!(
            a == b,
            "binary={binary}: the second export differs from the first"
        );
    }
}

/// The written CUBICSPLINE curve (evaluated here from the file's own
/// numbers, Appendix C) equals the authored TCB track at random times.
#[test]
fn tcb_tracks_export_exactly_as_cubicsplines() {
    let s = authored();
    let (bytes, report) = to_bytes(&s, &WriteOptions::default(), true);
    assert!(
        report
            .channels
            .iter()
            .any(|c| c.name == "Ball.translation (CUBICSPLINE exact)"),
        "{:?}",
        report.channels
    );
    let (json, bin) = gltf_node::split_glb(&bytes);
    let doc: serde_json::Value = serde_json::from_slice(json).unwrap();
    let hop = doc["animations"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["name"] == "Hop")
        .unwrap();
    let ch = hop["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["target"]["path"] == "translation")
        .unwrap();
    let sampler = &hop["samplers"][ch["sampler"].as_u64().unwrap() as usize];
    assert_eq!(sampler["interpolation"], "CUBICSPLINE");
    let times = gltf_node::floats(&doc, bin, sampler["input"].as_u64().unwrap() as usize);
    let values = gltf_node::floats(&doc, bin, sampler["output"].as_u64().unwrap() as usize);
    let mut s = s;
    s.play_clip("Hop").unwrap();
    let ball = s.find_node("Ball").unwrap().0 as usize;
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..500 {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let t = (rng >> 11) as f32 / (1u64 << 53) as f32 * 40.0 / 24.0;
        let ours = evaluate(&s, t).transforms[ball].translation;
        let theirs = gltf_node::cubic_at(&times, &values, t);
        assert!(
            (ours - theirs).abs().max_element() < 2e-5,
            "t={t}: {ours} vs {theirs}"
        );
    }
}

#[test]
fn convert_writes_gltf_and_glb() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_convert");
    std::fs::create_dir_all(&dir).unwrap();
    for ext in ["gltf", "glb"] {
        let out = dir.join(format!("demo.{ext}"));
        let (code, table, err) = animed(&[
            "convert",
            "assets/demo.wrl",
            out.to_str().unwrap(),
            "--verbose",
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(table.contains("Ball.translation"), "{table}");
        let back = format::load(&out).unwrap();
        let demo = format::demo().unwrap().scene;
        assert_eq!(
            back.scene.animation, demo.animation,
            "keys come back from the note"
        );
        for t in [0.0, 0.7, 1.9, 3.3] {
            assert!(close(
                translation(&back.scene, "Ball", t),
                translation(&demo, "Ball", t)
            ));
        }
    }
}

#[test]
fn a_static_light_and_camera_keep_their_placement() {
    let mut s = Scene::new();
    let mut light = animed::internals::scene::Light::new(LightKind::Point);
    light.location = Vec3::new(1.0, 2.0, 3.0);
    s.add_node(None, Node::new("Bulb", NodeKind::Light(light.clone())));
    let cam = animed::internals::scene::Camera {
        position: Vec3::new(0.0, 1.0, 5.0),
        orientation: Quat::from_rotation_x(-0.3),
        ..Default::default()
    };
    s.add_node(None, Node::new("View", NodeKind::Camera(cam.clone())));
    let (bytes, _) = to_bytes(&s, &WriteOptions::default(), false);
    let back = format::load_bytes(&bytes, Path::new("p.gltf"))
        .unwrap()
        .scene;
    assert_eq!(back.nodes.len(), 2, "placement nodes fold back");
    assert_eq!(
        back.node(back.find_node("Bulb").unwrap()).light(),
        Some(&light)
    );
    let c = back.node(back.find_node("View").unwrap()).camera().unwrap();
    assert_eq!((c.position, c.orientation), (cam.position, cam.orientation));
    let _ = Value::Scalar(0.0);
}

/// Hostile inputs: every hand-made file with bytes flipped, cut short or
/// numbers swapped for huge ones loads or fails with a message (the fuzz
/// target `fuzz/fuzz_targets/gltf.rs` does the same without end).
#[test]
fn mangled_files_never_panic() {
    let mut rng = 0x1234_5678_9abc_def1u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    for name in ["animated.gltf", "animated.glb", "topologies.gltf"] {
        let bytes = std::fs::read(data(name)).unwrap();
        let path = Path::new(name);
        for round in 0..300 {
            let mut b = bytes.clone();
            match round % 3 {
                0 => {
                    for _ in 0..1 + next() % 8 {
                        let i = (next() as usize) % b.len();
                        b[i] = next() as u8;
                    }
                }
                1 => b.truncate((next() as usize) % b.len()),
                _ => {
                    let text = String::from_utf8_lossy(&b).replace(
                        [
                            "\"count\": 4",
                            "\"count\": 6",
                            "\"byteOffset\": 0",
                            "\"count\": 3",
                        ][(next() % 4) as usize],
                        "\"count\": 4294967295",
                    );
                    b = text.into_bytes();
                }
            }
            let _ = format::load_bytes(&b, path);
        }
    }
}

/// The texture of the shape named `name` and its mesh's texture coordinate
/// at the vertex placed at `p`.
fn texture_at(s: &Scene, name: &str, p: Vec3) -> (animed::internals::scene::Texture, glam::Vec2) {
    let id = s.find_node(name).unwrap();
    let NodeKind::Shape(sh) = &s.node(id).kind else {
        panic!("{name} is not a shape")
    };
    let m = &s.meshes[sh.mesh.0 as usize];
    let k = m
        .positions
        .iter()
        .position(|q| (*q - p).length() < 1e-6)
        .unwrap();
    let t = s.materials[sh.material.0 as usize].texture.clone().unwrap();
    (t, m.texcoords[k])
}

#[test]
fn base_color_textures_samplers_and_transform() {
    // tests/data/gltf/textured.gltf (make.py): a PNG in a buffer view, a PNG
    // file beside it with CLAMP_TO_EDGE and KHR_texture_transform.
    let l = load("textured.gltf");
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    // Left: glTF v runs down, ours t up: the top-left corner is t = 1.
    let (t, uv) = texture_at(s, "Left", Vec3::new(-2.2, 1.0, 0.0));
    assert_eq!(uv, glam::Vec2::new(0.0, 1.0));
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Repeat, Wrap::Repeat));
    assert_eq!(t.model, TextureModel::MultiplyDiffuse);
    let img = s.image(t.image).unwrap();
    assert_eq!(img.source, ImageSource::Inline);
    // Top-left texel red, bottom-right white (rows top first).
    assert_eq!(img.base().texel(0, 0), [255, 0, 0, 255]);
    assert_eq!(img.base().texel(1, 1), [255, 255, 255, 255]);
    // Right: the file, clamped, its alpha kept (BLEND), and the transform
    // takes the right half: glTF uv (0, 0) → (0.5, 0), i.e. ours (0.5, 1).
    let (t, uv) = texture_at(s, "Right", Vec3::new(0.2, 1.0, 0.0));
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Clamp, Wrap::Clamp));
    let img = s.image(t.image).unwrap();
    assert!(matches!(&img.source, ImageSource::File { url, .. } if url == "tex_2x2.png"));
    assert_eq!(img.components(), 4);
    let mapped = t.transform.matrix().transform_point2(uv);
    assert!(
        (mapped - glam::Vec2::new(0.5, 1.0)).length() < 1e-6,
        "{mapped}"
    );
    let (t, uv) = texture_at(s, "Right", Vec3::new(2.2, -1.0, 0.0));
    let mapped = t.transform.matrix().transform_point2(uv);
    assert!(
        (mapped - glam::Vec2::new(1.0, 0.0)).length() < 1e-6,
        "{mapped}"
    );
}

#[test]
fn sampler_modes_mirror_nearest_and_mask_are_read_and_written_back() {
    use animed::internals::scene::{Filter, MipMode};
    // tests/data/gltf/sampler_modes.gltf (make.py): NEAREST filters,
    // MIRRORED_REPEAT, alphaMode MASK with alphaCutoff 0.5 — no warnings.
    let l = load("sampler_modes.gltf");
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let (t, _) = texture_at(&l.scene, "Mirrored", Vec3::new(-2.2, 1.0, 0.0));
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Mirror, Wrap::Clamp));
    let nearest_no_mip = Filter {
        mag_nearest: true,
        min_nearest: true,
        mip: MipMode::None,
    };
    assert_eq!((t.filter, t.alpha_cutoff), (nearest_no_mip, None));
    let (t, _) = texture_at(&l.scene, "Masked", Vec3::new(0.2, 1.0, 0.0));
    let mip_nearest = Filter {
        mip: MipMode::Nearest,
        ..nearest_no_mip
    };
    assert_eq!((t.filter, t.alpha_cutoff), (mip_nearest, Some(0.5)));
    // Written back: the same sampler codes and MASK + alphaCutoff.
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_sampler_modes");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("modes.gltf");
    let report = format::save(&l.scene, &out, &WriteOptions::default()).unwrap();
    assert!(report.warnings.is_empty(), "{:?}", report.warnings);
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    let samplers = json["samplers"].as_array().unwrap();
    let codes: Vec<[u64; 4]> = samplers
        .iter()
        .map(|s| ["wrapS", "wrapT", "magFilter", "minFilter"].map(|k| s[k].as_u64().unwrap()))
        .collect();
    assert!(codes.contains(&[33648, 33071, 9728, 9728]), "{codes:?}");
    assert!(codes.contains(&[33071, 33071, 9728, 9984]), "{codes:?}");
    let masked = json["materials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["alphaMode"] == "MASK")
        .expect("a MASK material");
    assert_eq!(masked["alphaCutoff"], 0.5);
    let back = animed::internals::format::load(&out).unwrap();
    assert!(back.warnings.is_empty(), "{:?}", back.warnings);
    for (name, p) in [
        ("Mirrored", Vec3::new(-2.2, 1.0, 0.0)),
        ("Masked", Vec3::new(0.2, 1.0, 0.0)),
    ] {
        let (a, _) = texture_at(&l.scene, name, p);
        let (b, _) = texture_at(&back.scene, name, p);
        assert_eq!(
            (a.wrap_s, a.wrap_t, a.filter, a.alpha_cutoff),
            (b.wrap_s, b.wrap_t, b.filter, b.alpha_cutoff)
        );
    }
}

#[test]
fn textures_survive_gltf_and_glb_round_trips() {
    let src = load("textured.gltf").scene;
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_textures");
    std::fs::create_dir_all(&dir).unwrap();
    for ext in ["gltf", "glb"] {
        let out = dir.join(format!("textured.{ext}"));
        let report = format::save(&src, &out, &WriteOptions::default()).unwrap();
        assert!(report.warnings.is_empty(), "{:?}", report.warnings);
        let text = std::fs::read(&out).unwrap();
        let json: serde_json::Value = if ext == "glb" {
            serde_json::from_slice(gltf_node::split_glb(&text).0).unwrap()
        } else {
            serde_json::from_slice(&text).unwrap()
        };
        // .gltf references the file (relative to the output), .glb embeds it.
        let image1 = &json["images"][1];
        if ext == "gltf" {
            assert!(
                image1["uri"].as_str().unwrap().ends_with("tex_2x2.png"),
                "{image1}"
            );
        } else {
            assert_eq!(image1["mimeType"], "image/png", "{image1}");
        }
        assert!(json["extensionsUsed"]
            .as_array()
            .unwrap()
            .contains(&serde_json::json!("KHR_texture_transform")));
        let back = animed::internals::format::load(&out).unwrap();
        assert!(back.warnings.is_empty(), "{:?}", back.warnings);
        for (name, p) in [
            ("Left", Vec3::new(-2.2, 1.0, 0.0)),
            ("Right", Vec3::new(0.2, 1.0, 0.0)),
            ("Right", Vec3::new(2.2, -1.0, 0.0)),
        ] {
            let (a, uva) = texture_at(&src, name, p);
            let (b, uvb) = texture_at(&back.scene, name, p);
            assert_eq!((a.wrap_s, a.wrap_t, a.model), (b.wrap_s, b.wrap_t, b.model));
            let (ma, mb) = (a.transform.matrix(), b.transform.matrix());
            assert!(
                (ma.transform_point2(uva) - mb.transform_point2(uvb)).length() < 1e-5,
                "{name} {p}"
            );
            let (ia, ib) = (
                src.image(a.image).unwrap(),
                back.scene.image(b.image).unwrap(),
            );
            assert_eq!(ia.base().pixels(), ib.base().pixels(), "{name}");
        }
    }
}

/// KHR_animation_pointer (a file the gltf crate alone would refuse):
/// pointers at a node's TRS play as ordinary channels; light colour and
/// intensity, spot cone, camera yfov and base colour (BLEND: alpha →
/// transparency) become animed tracks with the static mappings' units;
/// an unknown pointer is a warning naming it.
#[test]
fn animation_pointer_channels_drive_lights_cameras_and_materials() {
    let f = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    // Accessors: 0 times [0, 1]; 1 vec3 colours; 2 scalars (intensity);
    // 3 scalars (angles); 4 vec4 base colours; 5 vec3 translations; 6 positions.
    let parts: [Vec<u8>; 7] = [
        f(&[0.0, 1.0]),
        f(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0]),
        f(&[10.0, 40.0]),
        f(&[0.5, 0.25]),
        f(&[1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.5]),
        f(&[0.0, 0.0, 0.0, 2.0, 0.0, 0.0]),
        f(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
    ];
    let (types, counts) = (
        ["SCALAR", "VEC3", "SCALAR", "SCALAR", "VEC4", "VEC3", "VEC3"],
        [2, 2, 2, 2, 2, 2, 3],
    );
    let mut buffer = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        views.push(
            serde_json::json!({"buffer": 0, "byteOffset": buffer.len(), "byteLength": p.len()}),
        );
        let mut a = serde_json::json!({"bufferView": i, "componentType": 5126, "count": counts[i], "type": types[i]});
        if i == 0 {
            a["min"] = serde_json::json!([0.0]);
            a["max"] = serde_json::json!([1.0]);
        }
        if i == 6 {
            a["min"] = serde_json::json!([0.0, 0.0, 0.0]);
            a["max"] = serde_json::json!([1.0, 1.0, 0.0]);
        }
        accessors.push(a);
        buffer.extend_from_slice(p);
    }
    let ptr = |p: &str, sampler: usize| {
        serde_json::json!({"sampler": sampler, "target": {"path": "pointer",
            "extensions": {"KHR_animation_pointer": {"pointer": p}}}})
    };
    let doc = serde_json::json!({
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual", "KHR_animation_pointer"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "spot", "color": [1, 1, 1], "intensity": 20.0,
             "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.7}}]}},
        "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": "Lamp", "extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 3]},
            {"name": "Cam", "camera": 0, "translation": [0, 0, 5]},
            {"name": "Tri", "mesh": 0}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
        "materials": [{"alphaMode": "BLEND", "pbrMetallicRoughness": {"metallicFactor": 0.0}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 6}, "material": 0}]}],
        "animations": [{"name": "pointers", "samplers": [
            {"input": 0, "output": 1}, {"input": 0, "output": 2}, {"input": 0, "output": 3},
            {"input": 0, "output": 4}, {"input": 0, "output": 5}],
          "channels": [
            ptr("/extensions/KHR_lights_punctual/lights/0/color", 0),
            ptr("/extensions/KHR_lights_punctual/lights/0/intensity", 1),
            ptr("/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle", 2),
            ptr("/cameras/0/perspective/yfov", 2),
            ptr("/materials/0/pbrMetallicRoughness/baseColorFactor", 3),
            ptr("/nodes/2/translation", 4),
            ptr("/materials/0/alphaCutoff", 2)]}],
        "buffers": [{"byteLength": buffer.len(), "uri": "pointers.bin"}],
        "bufferViews": views,
        "accessors": accessors,
    });
    let path = Path::new("pointers.gltf");
    let loaded = read(
        doc.to_string().as_bytes(),
        path,
        &ReadOptions::default(),
        &|_| Ok(buffer.clone()),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert!(
        loaded
            .warnings
            .iter()
            .any(|w| w.contains("/materials/0/alphaCutoff")
                && w.contains("/animations/0/channels/6")),
        "{:?}",
        loaded.warnings
    );
    assert!(
        !loaded.warnings.iter().any(|w| w.contains("not supported")),
        "{:?}",
        loaded.warnings
    );
    let s = &loaded.scene;
    assert_eq!(s.settings.fps, 24.0);
    let light_node = |s: &Scene| {
        s.nodes
            .iter()
            .position(|n| n.light().is_some())
            .map(|i| animed::internals::scene::NodeId(i as u32))
            .unwrap()
    };
    let cam_node = s
        .nodes
        .iter()
        .position(|n| n.camera().is_some())
        .map(|i| animed::internals::scene::NodeId(i as u32))
        .unwrap();
    let (l, c) = (light_node(s), cam_node);
    let at = |t: f32| evaluate(s, t);
    let (p0, p1, p_half) = (at(0.0), at(1.0), at(0.5));
    // Colour: linear red → blue, shown in sRGB.
    assert_eq!(p0.light(l).unwrap().color, Vec3::X);
    assert_eq!(p1.light(l).unwrap().color, Vec3::Z);
    // Intensity: 10 → 40 cd with the largest (40) as the reference:
    // brightness I/(π d²) at every time.
    let light = p0.light(l).unwrap();
    assert!((light.attenuation.z - std::f32::consts::PI / 40.0).abs() < 1e-6);
    assert!((light.intensity - 0.25).abs() < 1e-6, "{}", light.intensity);
    assert!((p1.light(l).unwrap().intensity - 1.0).abs() < 1e-6);
    let LightKind::Spot { cut_off_angle, .. } = p_half.light(l).unwrap().kind else {
        panic!("a spot light")
    };
    assert!((cut_off_angle - 0.375).abs() < 1e-6, "{cut_off_angle}");
    let fov = |p: &animed::internals::anim::Pose| match p.camera(c).unwrap().kind {
        animed::internals::scene::CameraKind::Perspective { height_angle } => height_angle,
        _ => panic!("perspective"),
    };
    assert!((fov(&p0) - 0.5).abs() < 1e-6 && (fov(&p1) - 0.25).abs() < 1e-6);
    // Base colour white → black with alpha 1 → 0.5 (BLEND: transparency).
    let m0 = &p0.materials[0];
    let m1 = &p1.materials[0];
    assert!(
        m0.diffuse.x > 0.99 && m1.diffuse.x == 0.0,
        "{:?} {:?}",
        m0.diffuse,
        m1.diffuse
    );
    assert_eq!((m0.transparency, m1.transparency), (0.0, 0.5));
    // A node pointer is an ordinary translation channel.
    assert_eq!(translation(s, "Tri", 1.0), Vec3::new(2.0, 0.0, 0.0));
}
