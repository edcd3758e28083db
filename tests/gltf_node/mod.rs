//! Independent checks of the files animed writes: a small GLB/accessor
//! reader and the CUBICSPLINE formula written out here (not animed's), the
//! Khronos glTF validator, and three.js playing the file under node.
//! `tests/run-all.sh` installs the npm packages into `target/npm-gltf`;
//! without node or them these tests say so LOUDLY and check nothing else.

use glam::Vec3;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The JSON and BIN chunks of a .glb (the test's own reading of §4.4).
pub fn split_glb(b: &[u8]) -> (&[u8], &[u8]) {
    let u = |at: usize| u32::from_le_bytes(b[at..at + 4].try_into().unwrap()) as usize;
    assert_eq!(&b[..4], b"glTF");
    let json_len = u(12);
    let json = &b[20..20 + json_len];
    let at = 20 + json_len;
    let bin = if at + 8 <= b.len() {
        &b[at + 8..at + 8 + u(at)]
    } else {
        &[][..]
    };
    (json, bin)
}

/// A tightly packed float accessor's numbers.
pub fn floats(doc: &serde_json::Value, bin: &[u8], accessor: usize) -> Vec<f32> {
    let a = &doc["accessors"][accessor];
    assert_eq!(a["componentType"], 5126);
    let view = &doc["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize
        + a["byteOffset"].as_u64().unwrap_or(0) as usize;
    let n = match a["type"].as_str().unwrap() {
        "SCALAR" => 1,
        "VEC3" => 3,
        "VEC4" => 4,
        t => panic!("{t}"),
    };
    let count = a["count"].as_u64().unwrap() as usize * n;
    bin[start..start + 4 * count]
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
        .collect()
}

/// glTF 2.0 Appendix C: the CUBICSPLINE value of a VEC3 sampler at `t`
/// (clamped at both ends). `values` holds in-tangent, value, out-tangent
/// per key.
pub fn cubic_at(times: &[f32], values: &[f32], t: f32) -> Vec3 {
    let v = |k: usize, part: usize| {
        let at = (3 * k + part) * 3;
        Vec3::new(values[at], values[at + 1], values[at + 2])
    };
    let last = times.len() - 1;
    if t <= times[0] {
        return v(0, 1);
    }
    if t >= times[last] {
        return v(last, 1);
    }
    let k = times.iter().rposition(|&x| x <= t).unwrap();
    let (t0, t1) = (times[k] as f64, times[k + 1] as f64);
    let dt = t1 - t0;
    let s = (t as f64 - t0) / dt;
    let (s2, s3) = (s * s, s * s * s);
    let c = |x: f64| x as f32;
    v(k, 1) * c(2.0 * s3 - 3.0 * s2 + 1.0)
        + v(k, 2) * c(dt * (s3 - 2.0 * s2 + s))
        + v(k + 1, 1) * c(-2.0 * s3 + 3.0 * s2)
        + v(k + 1, 0) * c(dt * (s3 - s2))
}

/// The npm folder with gltf-validator and three, or `None` after saying
/// loudly why the check cannot run.
pub fn npm_dir(check: &str) -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/npm-gltf");
    let node = Command::new("node")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    let have =
        dir.join("node_modules/gltf-validator").is_dir() && dir.join("node_modules/three").is_dir();
    if node && have {
        return Some(dir);
    }
    eprintln!(
        "\n==================== {check}: NOT RUN ====================\n\
         needs node and the npm packages gltf-validator and three in {} \
         (tests/run-all.sh installs them: npm install --prefix target/npm-gltf gltf-validator three)\n\
         =========================================================\n",
        dir.display()
    );
    None
}

fn script(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/gltf")
        .join(name)
}

/// three.js's node transforms for `file`, clip `clip`, at `times`
/// (`tests/gltf/three_sample.mjs`).
pub fn three_sample(npm: &Path, file: &Path, clip: usize, times: &[f32]) -> serde_json::Value {
    let list: Vec<String> = times.iter().map(|t| t.to_string()).collect();
    let (ok, out, err) = node(
        npm,
        &[
            script("three_sample.mjs").to_str().unwrap(),
            file.to_str().unwrap(),
            &clip.to_string(),
            &list.join(","),
        ],
    );
    assert!(ok, "three.js on {}: {err}", file.display());
    serde_json::from_str(&out).unwrap()
}

/// animed's local transform equals three.js's within 1e-4 relative
/// (rotations: 1e-4 rad).
pub fn assert_same_trs(
    ours: &animed::internals::scene::Transform,
    tr: &serde_json::Value,
    what: &str,
) {
    let get = |k: &str| -> Vec<f32> {
        tr[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap() as f32)
            .collect()
    };
    let (t3, r3, s3) = (get("t"), get("r"), get("s"));
    let near = |a: f32, b: f32| (a - b).abs() <= 1e-4 * a.abs().max(b.abs()).max(1.0);
    let q = glam::Quat::from_xyzw(r3[0], r3[1], r3[2], r3[3]);
    // q and −q are one rotation; components within 1e-4 (f32 acos near 1
    // is too coarse to compare angles this small).
    let (a, b) = (glam::Vec4::from(ours.rotation), glam::Vec4::from(q));
    let same_rot = (a - b).abs().max_element() <= 1e-4 || (a + b).abs().max_element() <= 1e-4;
    assert!(
        (0..3).all(|k| near(ours.translation[k], t3[k]) && near(ours.scale[k], s3[k])) && same_rot,
        "{what} {}: animed {ours:?} three.js {tr}",
        tr["name"]
    );
}

fn node(npm: &Path, args: &[&str]) -> (bool, String, String) {
    let out = Command::new("node")
        .args(args)
        .env("NPM_DIR", npm)
        .output()
        .expect("run node");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Files animed writes for the checks: the demo and the hand-made
/// animated file, as .gltf and .glb.
fn written(dir: &Path) -> Vec<PathBuf> {
    std::fs::create_dir_all(dir).unwrap();
    let mut out = Vec::new();
    for (src, stem) in [
        ("assets/demo.wrl", "demo"),
        ("tests/data/gltf/animated.gltf", "animated"),
        // Skins and morph targets (with weights channels) written by animed.
        ("tests/data/gltf/corpus/Bunny.gltf", "bunny"),
        ("tests/data/gltf/corpus/monkey_morph.glb", "monkey"),
        // A track looping four times in its clip (unrolled in the file).
        ("tests/data/gltf/looping_track.wrl", "looping"),
    ] {
        for ext in ["gltf", "glb"] {
            let o = dir.join(format!("{stem}.{ext}"));
            let st = Command::new(env!("CARGO_BIN_EXE_animed"))
                .args(["convert", src, o.to_str().unwrap()])
                .current_dir(env!("CARGO_MANIFEST_DIR"))
                .output()
                .unwrap();
            assert!(
                st.status.success(),
                "{}",
                String::from_utf8_lossy(&st.stderr)
            );
            out.push(o);
        }
    }
    out
}

#[test]
fn khronos_validator_reports_no_errors_on_written_files() {
    let Some(npm) = npm_dir("glTF validator check") else {
        return;
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_validator");
    let mut files = written(&dir);
    // Textured files: inline Inventor images (embedded as PNG), a JPEG
    // file texture (referenced by the .gltf, embedded in the .glb) and
    // glTF's own textures with KHR_texture_transform and emissive maps.
    for (src, stem) in [
        ("tests/data/textures/inventor.iv", "inventor_tex"),
        ("tests/data/oak_leafless.obj", "oak_tex"),
        ("tests/data/gltf/textured.gltf", "textured"),
        // Emissive maps (emissiveTexture, unlit base colour texture).
        ("tests/data/gltf/emissive.gltf", "emissive"),
    ] {
        for ext in ["gltf", "glb"] {
            let o = dir.join(format!("{stem}.{ext}"));
            let st = Command::new(env!("CARGO_BIN_EXE_animed"))
                .args(["convert", src, o.to_str().unwrap()])
                .current_dir(env!("CARGO_MANIFEST_DIR"))
                .output()
                .unwrap();
            assert!(
                st.status.success(),
                "{}",
                String::from_utf8_lossy(&st.stderr)
            );
            files.push(o);
        }
    }
    let mut args = vec![script("validate.mjs").to_str().unwrap().to_string()];
    args.extend(files.iter().map(|f| f.to_str().unwrap().to_string()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (ok, out, err) = node(&npm, &args);
    eprintln!("{out}");
    assert!(ok, "validator errors:\n{out}\n{err}");
    assert_eq!(out.lines().count(), files.len());
    for line in out.lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        assert_eq!(v["errors"], 0, "{line}");
    }
}

/// three.js plays the written file; its node transforms at random times
/// match `animed sample` within 1e-4 relative.
#[test]
fn three_js_plays_written_files_like_animed() {
    let Some(npm) = npm_dir("three.js playback check") else {
        return;
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("gltf_three");
    let files = written(&dir);
    let mut rng = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut compared = 0usize;
    for file in &files {
        let loaded = animed::internals::format::load(file).unwrap();
        let scene = loaded.scene;
        for (clip_index, clip) in scene.clip_refs().iter().enumerate() {
            let mut s = scene.clone();
            s.play_clip_index(clip_index).unwrap();
            let seconds = clip.duration / s.settings.fps;
            let times: Vec<f32> = (0..8)
                .map(|_| (next() * seconds * 1000.0).round() / 1000.0)
                .collect();
            let v = three_sample(&npm, file, clip_index, &times);
            for (i, &t) in times.iter().enumerate() {
                let pose = animed::internals::anim::evaluate(&s, t);
                for tr in v[i]["nodes"].as_object().unwrap().values() {
                    let Some(id) = s.find_node(tr["name"].as_str().unwrap()) else {
                        continue;
                    };
                    compared += 1;
                    assert_same_trs(
                        &pose.transforms[id.0 as usize],
                        tr,
                        &format!("{} clip {clip_index} t={t}", file.display()),
                    );
                }
            }
        }
    }
    assert!(compared > 100, "only {compared} node transforms compared");
}
