//! The smaller holes, each with its fix: CLI values checked, BOM read,
//! NaN/inf refused, words in number fields warned at their column,
//! key/keyValue mismatch warned, one warning per kind.

use animed::internals::format::load_bytes;
use std::path::Path;
use std::process::Command;

fn animed(args: &[&str]) -> (i32, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .current_dir(std::env::temp_dir())
        .output()
        .expect("run animed");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn cli_values_out_of_range_are_errors() {
    let (code, e) = animed(&["render", "--threads", "100000", "-o", "x.png"]);
    assert_eq!(code, 2, "{e}");
    assert!(e.contains("256"), "{e}");
    let (code, e) = animed(&["render", "--style", "bogus", "-o", "x.png"]);
    assert_eq!(code, 2, "{e}");
    assert!(e.contains("bogus"), "{e}");
    let (code, e) = animed(&["render", "--size", "32x24", "-o", "animed-hostile-x.jpg"]);
    assert_ne!(code, 0, "{e}");
    assert!(e.contains(".jpg") && e.contains(".png"), "{e}");
    assert!(!std::env::temp_dir().join("animed-hostile-x.jpg").exists());
}

#[test]
fn huge_frames_are_drawn_fewer_at_a_time() {
    use animed::internals::render::job::FrameSpec;
    let spec = FrameSpec {
        width: 8192,
        height: 8192,
        threads: 8,
        ..FrameSpec::default()
    };
    assert_eq!(animed::internals::output::frames_at_once(&spec), 1);
    let small = FrameSpec {
        width: 320,
        height: 240,
        threads: 8,
        ..FrameSpec::default()
    };
    assert_eq!(animed::internals::output::frames_at_once(&small), 8);
}

#[test]
fn a_utf8_byte_order_mark_is_read() {
    let l = load_bytes(
        b"\xEF\xBB\xBF#VRML V2.0 utf8\nShape { geometry Box {} }\n",
        Path::new("bom.wrl"),
    )
    .unwrap();
    assert_eq!(l.scene.meshes.len(), 1);
}

#[test]
fn nan_and_infinity_are_refused_where_they_stand() {
    for (src, col) in [
        ("DEF T TimeSensor { cycleInterval nan loop TRUE }", 34),
        ("Transform { translation 0 NaN 0 }", 27),
        ("Transform { scale 1e999 1 1 }", 19),
        ("Transform { translation inf 0 0 }", 25),
    ] {
        let text = format!("#VRML V2.0 utf8\nGroup {{}}\n{src}\n");
        let l = load_bytes(text.as_bytes(), Path::new("n.wrl")).unwrap();
        let w = l.warnings.join("\n");
        assert!(w.contains(&format!("n.wrl:3:{col}:")), "{src}: {w}");
        assert!(w.contains("finite"), "{src}: {w}");
    }
}

#[test]
fn key_and_key_value_counts_that_differ_are_warned() {
    let text = "#VRML V2.0 utf8
DEF T Transform { children Shape { geometry Box {} } }
DEF I PositionInterpolator { key [0 0.5 1] keyValue [0 0 0 1 1 1] }
DEF S TimeSensor { loop TRUE }
ROUTE S.fraction_changed TO I.set_fraction
ROUTE I.value_changed TO T.set_translation
";
    let l = load_bytes(text.as_bytes(), Path::new("k.wrl")).unwrap();
    let w = l.warnings.join("\n");
    assert!(
        w.contains("k.wrl:3:7:") && w.contains("3 key times but 2 keyValues"),
        "{w}"
    );
}

#[test]
fn a_lossy_matrix_is_warned_once_with_the_nodes_path() {
    let mut text = String::from("#Inventor V2.1 ascii\nDEF Root Separator {\n");
    for _ in 0..50 {
        text += "Separator { MatrixTransform { matrix 1 0 0 0  0.5 1 0 0  0 0 1 0  0 0 0 1 } Cube {} }\n";
    }
    text += "}\n";
    let l = load_bytes(text.as_bytes(), Path::new("m.iv")).unwrap();
    let (_, report) = animed::internals::format::save::to_bytes(
        &l.scene,
        animed::internals::format::OutputFormat::Vrml97,
        &animed::internals::format::WriteOptions::default(),
    );
    let shear: Vec<&String> = report
        .warnings
        .iter()
        .filter(|w| w.contains("shear"))
        .collect();
    assert_eq!(shear.len(), 1, "{:?}", report.warnings);
    assert!(
        shear[0].contains("50 node") && shear[0].contains("Root/"),
        "{}",
        shear[0]
    );
}

#[test]
fn a_word_or_string_in_a_number_field_is_warned_at_its_column() {
    for (src, col) in [
        ("DEF T TimeSensor { cycleInterval \"x\" loop TRUE }", 34),
        ("Transform { scale TRUE }", 19),
        ("Shape { geometry Sphere { radius big } }", 34),
    ] {
        let text = format!("#VRML V2.0 utf8\nGroup {{}}\n{src}\n");
        let l = load_bytes(text.as_bytes(), Path::new("w.wrl")).unwrap();
        let w = l.warnings.join("\n");
        assert!(w.contains(&format!("w.wrl:3:{col}:")), "{src}: {w}");
        assert!(w.contains("takes numbers"), "{src}: {w}");
    }
}

#[test]
fn a_huge_duration_on_a_looping_track_writes_a_bounded_file() {
    let dir = std::env::temp_dir().join(format!("animed-holes-dur-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("loop.wrl");
    let fs = f.to_str().unwrap();
    let (code, e) = animed(&["key", "new", fs, "--box", "B"]);
    assert_eq!(code, 0, "{e}");
    for (frame, x) in [("0", "0,0,0"), ("12", "1,0,0"), ("24", "0,0,0")] {
        let (code, e) = animed(&[
            "key",
            "set",
            fs,
            "--target",
            "B.translation",
            "--frame",
            frame,
            "--value",
            x,
            "--repeat",
            "loop",
        ]);
        assert_eq!(code, 0, "{e}");
    }
    // The first wave wrote 683 MB here: the duration is refused, the file
    // left as it was.
    let before = std::fs::read(&f).unwrap();
    let (code, e) = animed(&["key", "settings", fs, "--duration", "1e30"]);
    assert_eq!(code, 1, "{e}");
    assert!(e.contains("at most 100000 frames"), "{e}");
    assert_eq!(std::fs::read(&f).unwrap(), before);
    // The longest duration allowed still writes a bounded file.
    let (code, e) = animed(&["key", "settings", fs, "--duration", "100000"]);
    assert_eq!(code, 0, "{e}");
    let len = std::fs::metadata(&f).unwrap().len();
    assert!(len < 8 << 20, "{len} bytes");
    let l = animed::internals::format::load(&f).unwrap();
    assert_eq!(l.scene.animation.tracks.len(), 1);
    std::fs::remove_dir_all(&dir).ok();
}
