//! `animed info` and `animed sample` on the bundled demo, through the binary.

use std::process::Command;

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

#[test]
fn info_json_lists_the_demo() {
    let (code, out, err) = animed(&["info", "assets/demo.wrl", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["format"], "VRML97");
    assert_eq!(v["lights"].as_array().unwrap().len(), 3);
    assert_eq!(v["cameras"][0]["description"], "Main");
    let targets: Vec<&str> = v["tracks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t["target"].as_str().unwrap())
        .collect();
    assert_eq!(
        targets,
        vec![
            "Ball.translation",
            "Spinner.rotation",
            "Lamp.color",
            "SpotLamp.intensity"
        ]
    );
    assert_eq!(v["tracks"][0]["end"], 4.0);
    assert!(v["triangles"].as_u64().unwrap() > 100);
}

#[test]
fn sample_json_prints_time_value_pairs() {
    let (code, out, err) = animed(&[
        "sample",
        "assets/demo.wrl",
        "--target",
        "Ball.translation",
        "--times",
        "0,1,2",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        v,
        serde_json::json!([
            {"time": 0.0, "value": [-2.0, 0.6, 0.0]},
            {"time": 1.0, "value": [0.0, 1.6, 1.5]},
            {"time": 2.0, "value": [2.0, 0.6, 0.0]},
        ])
    );
}

#[test]
fn errors_are_positioned_and_exit_nonzero() {
    let dir = std::env::temp_dir().join(format!("animed-read-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("bad.wrl");
    std::fs::write(&f, "#VRML V2.0 utf8\nTransform {\n  translation 1 2\n  children [ Shape { geometry Box { size 1 1 1 } ]\n}\n").unwrap();
    let (code, _, err) = animed(&["info", f.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("bad.wrl:4:"), "{err}");
    let (code, _, err) = animed(&[
        "sample",
        "assets/demo.wrl",
        "--target",
        "Nobody.translation",
        "--times",
        "0",
    ]);
    assert_ne!(code, 0);
    assert!(err.contains("Nobody"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A file with one animation behaves as before: `--animation 0` is that one
/// clip, anything else is a clear error on every command that takes it.
#[test]
fn animation_flag_on_a_one_clip_file() {
    let (code, out, err) = animed(&[
        "sample",
        "assets/demo.wrl",
        "--target",
        "Ball.translation",
        "--times",
        "1",
        "--animation",
        "0",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.trim(), "1\t0 1.6 1.5");
    let (code, out, err) = animed(&["info", "assets/demo.wrl", "--json", "--animation", "0"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["animations"].as_array().unwrap().len(), 1);
    assert_eq!(v["animations"][0]["playing"], true);
    assert_eq!(v["animations"][0]["tracks"], 4);
    for cmd in [
        vec!["info", "assets/demo.wrl", "--animation", "Walk"],
        vec![
            "sample",
            "assets/demo.wrl",
            "--target",
            "Ball.translation",
            "--times",
            "0",
            "--animation",
            "1",
        ],
        vec![
            "render",
            "assets/demo.wrl",
            "-o",
            "target/never.png",
            "--animation",
            "Walk",
        ],
        vec!["key", "list", "assets/demo.wrl", "--animation", "2"],
    ] {
        let (code, _, err) = animed(&cmd);
        assert_ne!(code, 0, "{cmd:?} should fail");
        assert!(err.contains("there is no animation"), "{cmd:?}: {err}");
    }
}
