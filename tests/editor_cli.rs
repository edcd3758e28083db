//! `animed edit` from the command line: headless sessions, errors, and the
//! message without a display.

use std::path::PathBuf;
use std::process::Command;

fn animed() -> Command {
    Command::new(env!("CARGO_BIN_EXE_animed"))
}

fn tmp(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("editor-cli");
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

#[test]
fn headless_session_writes_a_screenshot_of_the_requested_size() {
    let script = tmp("grid.txt");
    std::fs::write(
        &script,
        "# hide the grid, then resize\nkey g\nresize 320 200\n",
    )
    .unwrap();
    let out = tmp("grid.png");
    let _ = std::fs::remove_file(&out);
    let o = animed()
        .args(["edit", "--script"])
        .arg(&script)
        .arg("--screenshot")
        .arg(&out)
        .args(["--size", "480x320"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&out).expect("a PNG was written").to_rgb8();
    assert_eq!(img.dimensions(), (320, 200), "the script's resize wins");
}

#[test]
fn script_errors_name_the_line_and_column() {
    let script = tmp("bad.txt");
    std::fs::write(&script, "key g\nclick 10 ten\n").unwrap();
    let o = animed()
        .args(["edit", "--script"])
        .arg(&script)
        .arg("--screenshot")
        .arg(tmp("bad.png"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains(&format!("{}:2:10: 'ten' is not a number", script.display())),
        "{err}"
    );
}

#[test]
fn the_status_line_says_which_file_was_opened() {
    // `animed edit FILE` used to start with an empty status line.
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let run = |text: &str| {
        let script = tmp("opened.txt");
        std::fs::write(&script, text).unwrap();
        let o = animed()
            .arg("edit")
            .arg(&scene)
            .arg("--script")
            .arg(&script)
            .env("XDG_STATE_HOME", tmp("opened-state"))
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).to_string(),
            script,
        )
    };
    let opened = format!("expect-status Opened {}\n", scene.display());
    let (code, err, _) = run(&opened);
    assert_eq!(code, Some(0), "{err}");
    // The check can fail: after a key the status says something else.
    let (code, err, script) = run("key g\nexpect-status Saved\n");
    assert_eq!(code, Some(1));
    assert!(
        err.contains(&format!("{}:2:1: the status line says", script.display()))
            && err.contains("not 'Saved'"),
        "{err}"
    );
}

#[test]
fn a_missing_scene_file_is_an_error_not_a_panic() {
    let o = animed()
        .args(["edit", "/nonexistent/scene.wrl", "--screenshot"])
        .arg(tmp("none.png"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("/nonexistent/scene.wrl"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn without_a_display_the_editor_points_at_animed_render() {
    for args in [vec![], vec!["edit"]] {
        let o = animed()
            .args(&args)
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY")
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "args {args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("animed render"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn a_display_that_does_not_exist_is_reported_too() {
    let o = animed()
        .arg("edit")
        .env("DISPLAY", ":9871")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("cannot open a window"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
