//! Issue 7's proof: `tests/data/proof/animate_demo.txt` animates the
//! bundled demo scene entirely through the editor's UI (select, record,
//! handle drags at three frames, TCB typed and dragged in the key panel, a
//! key moved in the key strip, undo/redo, the rotate rings on a spot light,
//! playback, save as .wrl). This test runs that script the way
//! `animed edit --script` does, compares two of its screenshots with
//! goldens, checks every key it should have made, and reads the saved
//! .wrl back. `tests/reference_viewers.sh` plays the same saved file in
//! view3dscene and Coin next to `animed render --time`.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::anim::{Interp, Property, Target, TargetRef, Track, Value};
use animed::internals::editor::script::{self, Step};
use animed::internals::editor::Editor;
use animed::internals::scene::{NodeId, Scene};
use glam::Vec3;
use std::path::{Path, PathBuf};

const W: u32 = 800;
const H: u32 = 500;

fn script_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/proof/animate_demo.txt")
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-proof-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn node(s: &Scene, name: &str) -> NodeId {
    NodeId(
        s.nodes
            .iter()
            .position(|n| n.name == name)
            .unwrap_or_else(|| panic!("no node {name}")) as u32,
    )
}

fn track<'a>(s: &'a Scene, name: &str, p: Property) -> &'a Track {
    let t = Target {
        of: TargetRef::Node(node(s, name)),
        property: p,
    };
    s.animation
        .track(t)
        .unwrap_or_else(|| panic!("no {name}.{p:?} track"))
}

fn vec3(v: Value) -> Vec3 {
    match v {
        Value::Vec3(v) => v,
        other => panic!("not a vector: {other:?}"),
    }
}

/// Runs the proof script on the demo in-process; screenshot steps are
/// compared with goldens (those named in `goldens`) instead of written.
fn run_session(dir: &Path, goldens: &[&str]) -> Editor {
    let path = script_path();
    let text = std::fs::read_to_string(&path).expect("proof script");
    let steps = script::parse(&text, &path).expect("proof script parses");
    let mut ed = Editor::with_demo(W, H);
    // Save-as starts in the working directory; the test's is `dir`.
    ed.set_start_dir(dir);
    let mut runner = script::Runner::default();
    let mut shots = Vec::new();
    for (line, step) in &steps {
        match step {
            Step::Screenshot(p) => {
                let name = p.file_stem().unwrap().to_string_lossy().to_string();
                shots.push(name.clone());
                if goldens.contains(&name.as_str()) {
                    golden::check(&format!("editor_{name}"), &ed.render_frame());
                }
            }
            s => runner
                .run(&mut ed, &[(*line, s.clone())], &path)
                .expect("step runs"),
        }
    }
    assert_eq!(shots.len(), 4, "the script's four screenshots ran");
    ed
}

/// Everything the session did, as keys.
fn check_keys(s: &Scene) {
    // Pyramid: keys at 0, 40 and (moved from 80) 90; left, up, right.
    let t = track(s, "Pyramid", Property::Translation);
    assert_eq!(
        t.keys.frames(),
        vec![0.0, 40.0, 90.0],
        "key moved 80→90, undo, redo"
    );
    let k: Vec<Vec3> = t.keys.frames().iter().map(|&f| vec3(t.sample(f))).collect();
    let start = Vec3::new(1.1, 0.0, 2.1); // the demo's pyramid position
    assert!(k[0].x < start.x - 1.0, "frame 0 dragged to -x: {}", k[0]);
    assert!((k[0].y - start.y).abs() < 1e-4 && (k[0].z - start.z).abs() < 1e-4);
    assert!(
        k[1].y > 1.0 && (k[1].x - k[0].x).abs() < 1e-4,
        "frame 40 up: {}",
        k[1]
    );
    assert!(
        k[2].x > start.x + 1.0 && (k[2].y - k[1].y).abs() < 1e-4,
        "frame 90 +x: {}",
        k[2]
    );
    // The middle key's TCB: typed tension and bias, dragged continuity.
    let mid = t.keys.key(1).expect("middle key");
    assert_eq!(mid.interp, Interp::Tcb);
    assert_eq!((mid.tension, mid.bias), (-0.6, 0.5));
    assert!(
        (mid.continuity - 0.3).abs() < 0.02,
        "continuity dragged 30 px: {}",
        mid.continuity
    );
    // The spot light's direction: three different keys from the rings.
    let d = track(s, "SpotLamp", Property::LightDirection);
    assert_eq!(d.keys.frames(), vec![0.0, 48.0, 96.0]);
    let v: Vec<Vec3> = d.keys.frames().iter().map(|&f| vec3(d.sample(f))).collect();
    for i in 0..3 {
        for j in i + 1..3 {
            assert!(
                v[i].angle_between(v[j]) > 0.3,
                "directions {i} and {j} differ"
            );
        }
    }
    // Turning keeps the vector's length (rings rotate, never scale).
    assert!((v[0].length() - v[2].length()).abs() < 1e-4);
    // The demo's own animation is untouched.
    assert_eq!(
        track(s, "SpotLamp", Property::LightIntensity).keys.frames(),
        vec![0.0, 48.0, 96.0]
    );
    assert_eq!(track(s, "Ball", Property::Translation).keys.len(), 5);
}

#[test]
fn proof_session_animates_the_demo_through_the_ui() {
    let dir = temp_dir("inproc");
    let ed = run_session(&dir, &["proof_2_tcb", "proof_4_played"]);
    // Played 30 frames from 96 in a 97-frame loop, then stopped.
    assert!(!ed.is_playing());
    assert_eq!(ed.current_frame(), 28.0);
    assert!(!ed.is_dirty(), "saved: {}", ed.status().text);
    check_keys(ed.scene());
    // The saved file brings every key back exactly.
    let saved = dir.join("proof.wrl");
    let loaded = animed::internals::format::load(&saved).expect("proof.wrl loads");
    check_keys(&loaded.scene);
    for t in &ed.scene().animation.tracks {
        let back = loaded
            .scene
            .animation
            .track(t.target)
            .unwrap_or_else(|| panic!("{:?} lost in the .wrl", t.target));
        assert_eq!(back.keys, t.keys, "{:?}", t.target);
    }
    // What `animed render --time` shows of the saved file is what the
    // editor shows at that frame (both evaluate the same keys).
    let a = animed::internals::anim::evaluate(ed.scene(), 1.5);
    let b = animed::internals::anim::evaluate(&loaded.scene, 1.5);
    let p = node(ed.scene(), "Pyramid").0 as usize;
    assert!((a.world[p].w_axis - b.world[p].w_axis).length() < 1e-5);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_cli_runs_the_same_session_and_saves_the_same_bytes() {
    let a = temp_dir("cli");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_animed"))
        .current_dir(&a)
        .args(["edit", "--size", "800x500", "--script"])
        .arg(script_path())
        .status()
        .expect("animed runs");
    assert!(status.success());
    for shot in [
        "proof_1_three_keys",
        "proof_2_tcb",
        "proof_3_light",
        "proof_4_played",
    ] {
        let img = image::open(a.join(format!("{shot}.png"))).expect("screenshot written");
        assert_eq!((img.width(), img.height()), (W, H));
    }
    let b = temp_dir("cli-inproc");
    run_session(&b, &[]);
    let cli = std::fs::read(a.join("proof.wrl")).expect("CLI saved proof.wrl");
    let inproc = std::fs::read(b.join("proof.wrl")).expect("in-process save");
    assert!(cli == inproc, "same session, same file");
    std::fs::remove_dir_all(&a).ok();
    std::fs::remove_dir_all(&b).ok();
}
