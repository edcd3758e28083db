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
    assert!(err.contains("does/not/exist.wrl: "), "{err}");
    let (code, _) = animed(&["render", "--size", "0x10"]);
    assert_ne!(code, 0);
}

/// The view-all camera against Coin 4.0's `SoCamera::viewAll` (Debian's
/// libcoin80 through pivy, 640x480 viewport, probed 2026-11-30 with these
/// four scenes): rotated, non-uniformly scaled, moved and two-part scenes.
/// Coin bounds each shape by its local box carried through the transform,
/// as `scene_bounds` does, so the cameras agree.
#[test]
fn view_all_matches_coin_for_rotated_and_scaled_scenes() {
    let cases = [
        (
            "Separator { Transform { rotation 0 0 1 0.785398 scaleFactor 2 1 1 } Sphere { radius 1 } }",
            [0.0, 0.0, 7.63441],
            (4.47214, 10.79669),
        ),
        (
            "Separator { Transform { rotation 1 1 0 0.6 } Cube { width 2 height 1 depth 3 } }",
            [0.0, 0.0, 6.43213],
            (3.76786, 9.09641),
        ),
        (
            "Separator { Transform { translation 3 -1 2 scaleFactor 1 3 0.5 } Cone { } }",
            [3.0, -1.0, 9.72925],
            (4.52769, 10.93082),
        ),
        (
            "Separator { Cube {} Transform { translation 5 0 0 rotation 0 1 0 1.2 } Cylinder { radius 0.5 height 4 } }",
            [2.32360, 0.0, 9.67082],
            (5.66504, 13.67661),
        ),
    ];
    for (body, pos, (near, far)) in cases {
        let text = format!("#Inventor V2.1 ascii\n{body}\n");
        let loaded = animed::internals::format::load_bytes(
            text.as_bytes(),
            std::path::Path::new("probe.iv"),
        )
        .unwrap();
        let pose = animed::internals::anim::evaluate(&loaded.scene, 0.0);
        let (_, cam) =
            animed::internals::render::View::view_all_camera(&loaded.scene, &pose, 640.0 / 480.0);
        let close = |a: f32, b: f32| (a - b).abs() <= 2e-3 * b.abs().max(1.0);
        assert!(
            close(cam.position.x, pos[0])
                && close(cam.position.y, pos[1])
                && close(cam.position.z, pos[2]),
            "{body}: camera at {} vs Coin's {pos:?}",
            cam.position
        );
        let (n, f) = (cam.near.unwrap(), cam.far.unwrap());
        assert!(
            close(n, near) && close(f, far),
            "{body}: near/far {n} {f} vs Coin's {near} {far}"
        );
    }
}
