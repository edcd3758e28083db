//! `animed render` from the outside: pictures are written atomically, bad
//! input gives a `path:line:column: message` error and a non-zero exit code,
//! never a panic.

use std::path::PathBuf;
use std::process::Command;

fn out_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/render-cli");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn animed(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn renders_the_demo_with_options() {
    let png = out_dir().join("demo.png");
    let _ = std::fs::remove_file(&png);
    let p = png.to_str().unwrap();
    let (code, err) = animed(&[
        "render",
        "-o",
        p,
        "--size",
        "96x64",
        "--viewpoint",
        "Main",
        "--time",
        "1.5",
        "--bg",
        "1,1,1",
        "--headlight",
        "on",
        "--threads",
        "1",
    ]);
    assert_eq!(code, 0, "{err}");
    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (96, 64));
    // --bg 1,1,1 replaces the demo's blue sky wherever no shape is drawn.
    assert!(img.pixels().any(|p| p.0 == [255, 255, 255]));
    assert!(!png.with_extension("png.partial").exists());
}

#[test]
fn broken_obj_reports_line_and_column() {
    let bad = out_dir().join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nf 1 2 3\n").unwrap();
    let (code, err) = animed(&["render", bad.to_str().unwrap(), "-o", "/dev/null"]);
    assert_eq!(code, 1);
    assert!(err.contains("bad.obj:3:7: "), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn unknown_viewpoint_and_missing_file_are_errors() {
    let png = out_dir().join("never.png");
    let (code, err) = animed(&[
        "render",
        "--viewpoint",
        "Nowhere",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("no viewpoint named \"Nowhere\""), "{err}");
    assert!(!png.exists());
    let (code, err) = animed(&["render", "does/not/exist.wrl", "-o", png.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("does/not/exist.wrl:0:0:"), "{err}");
    let (code, _) = animed(&["render", "--size", "0x10"]);
    assert_ne!(code, 0);
}
