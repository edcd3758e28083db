//! The glTF files of `../shared/corpus-next` (castle-engine demo models:
//! Blender exports, Quaternius animals, an animated camera, punctual
//! lights): every one loads, renders and plays; three.js (under node)
//! samples the same node transforms animed does; goldens of a few, copied
//! into `tests/data/gltf/corpus/`, at several times.
//! Without the corpus or node these tests say so LOUDLY.

#[path = "../common/golden.rs"]
mod golden;

use animed::internals::anim::evaluate;
use animed::internals::format;
use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use animed::internals::scene::Scene;
use std::path::{Path, PathBuf};

fn corpus() -> Option<PathBuf> {
    // `shared/` sits beside the clone (CI) or beside the worktrees' folder.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("../shared/corpus-next");
    for d in [&dir, &root.join("../../shared/corpus-next")] {
        if d.is_dir() {
            return Some(d.clone());
        }
    }
    eprintln!(
        "\n==================== glTF corpus checks: NOT RUN ====================\n\
         {} is missing\n\
         ====================================================================\n",
        dir.display()
    );
    None
}

fn gltf_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = rd.flatten().map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            gltf_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "gltf" || e == "glb") {
            out.push(p);
        }
    }
}

fn spec(width: u32, height: u32) -> FrameSpec {
    FrameSpec {
        width,
        height,
        headlight: Headlight::Auto,
        ..FrameSpec::default()
    }
}

#[test]
fn every_corpus_gltf_loads_renders_and_plays() {
    let Some(dir) = corpus() else { return };
    let mut files = Vec::new();
    gltf_files(&dir, &mut files);
    assert!(files.len() >= 20, "{} glTF files found", files.len());
    for f in &files {
        let loaded = format::load(f).unwrap_or_else(|e| panic!("{e}"));
        let mut s = loaded.scene;
        assert!(!s.nodes.is_empty(), "{}", f.display());
        for clip in 0..s.clip_refs().len().min(3) {
            s.play_clip_index(clip).unwrap();
            let end = s.duration_seconds();
            for t in [0.0, end / 2.0] {
                let frame = render_at(&s, &spec(48, 36), t).unwrap();
                assert_eq!(frame.color.len(), 48 * 36);
            }
        }
    }
}

/// Node transforms three.js's AnimationMixer plays, against animed's, for
/// every animated corpus file and up to three clips each.
#[test]
fn corpus_animations_match_three_js() {
    let Some(dir) = corpus() else { return };
    let Some(npm) = crate::gltf_node::npm_dir("glTF corpus three.js check") else {
        return;
    };
    let mut files = Vec::new();
    gltf_files(&dir, &mut files);
    let mut compared = 0usize;
    for f in &files {
        let scene: Scene = format::load(f).unwrap().scene;
        let clips = scene.clip_refs().len();
        if scene.clips.is_empty() {
            continue;
        }
        for clip in 0..clips.min(3) {
            let mut s = scene.clone();
            s.play_clip_index(clip).unwrap();
            let end = s.duration_seconds();
            let times: Vec<f32> = [0.0, 0.21, 0.5, 0.77, 0.999]
                .iter()
                .map(|k| k * end)
                .collect();
            let v = crate::gltf_node::three_sample(&npm, f, clip, &times);
            for (i, &t) in times.iter().enumerate() {
                let pose = evaluate(&s, t);
                for tr in v[i]["nodes"].as_object().unwrap().values() {
                    let name = tr["name"].as_str().unwrap();
                    // Only names that pick one node (find_node takes the first).
                    if s.nodes.iter().filter(|n| n.name == name).count() != 1 {
                        continue;
                    }
                    let Some(id) = s.find_node(name) else {
                        continue;
                    };
                    compared += 1;
                    crate::gltf_node::assert_same_trs(
                        &pose.transforms[id.0 as usize],
                        tr,
                        &format!("{} clip {clip} t={t}", f.display()),
                    );
                }
            }
        }
    }
    assert!(compared > 1000, "only {compared} node transforms compared");
}

fn corpus_copy(name: &str) -> Scene {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/gltf/corpus")
        .join(name);
    format::load(&p).unwrap_or_else(|e| panic!("{e}")).scene
}

#[test]
fn chopper_rotor_golden_at_three_times() {
    let s = corpus_copy("chopper/chopper.gltf");
    for (t, name) in [
        (0.0, "gltf_chopper_t0"),
        (0.3, "gltf_chopper_t03"),
        (1.0, "gltf_chopper_t1"),
    ] {
        golden::check(name, &render_at(&s, &spec(160, 120), t).unwrap());
    }
}

#[test]
fn animated_camera_golden_at_three_times() {
    let s = corpus_copy("camera_animation.glb");
    for (t, name) in [
        (0.0, "gltf_camera_anim_t0"),
        (1.0, "gltf_camera_anim_t1"),
        (2.5, "gltf_camera_anim_t25"),
    ] {
        golden::check(name, &render_at(&s, &spec(160, 120), t).unwrap());
    }
}

#[test]
fn vertex_colours_golden() {
    let s = corpus_copy("vertex_paint.glb");
    golden::check(
        "gltf_vertex_paint",
        &render_at(&s, &spec(160, 120), 0.0).unwrap(),
    );
}
