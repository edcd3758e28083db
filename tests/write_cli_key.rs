//! `animed key` and `animed convert` end to end from the command line:
//! build an animation from nothing, list it, convert it, read it back.

use std::path::{Path, PathBuf};
use std::process::Command;

fn animed(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .output()
        .expect("run animed");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn ok(args: &[&str]) -> String {
    let (success, out, err) = animed(args);
    assert!(success, "animed {args:?} failed: {err}");
    out
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-keycli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn build_an_animation_from_nothing() {
    let d = dir("build");
    let f = d.join("scene.wrl");
    let f = s(&f);
    // A key on a file that does not exist is an error that says what to do.
    let (success, _, err) = animed(&[
        "key",
        "set",
        f,
        "--target",
        "Box.translation",
        "--frame",
        "0",
        "--value",
        "0,0,0",
    ]);
    assert!(!success);
    assert!(err.contains("key new"), "{err}");

    ok(&[
        "key",
        "new",
        f,
        "--box",
        "Box",
        "--light",
        "Lamp",
        "--fps",
        "25",
        "--duration",
        "50",
    ]);
    ok(&[
        "key",
        "set",
        f,
        "--target",
        "Box.translation",
        "--frame",
        "0",
        "--value",
        "0,0,0",
        "--interp",
        "linear",
    ]);
    ok(&[
        "key",
        "set",
        f,
        "--target",
        "Box.translation",
        "--time",
        "1",
        "--value",
        "0,2,-1.5",
        "--tcb",
        "0.5,-0.25,0",
        "--ease",
        "0.3,0.7",
    ]);
    ok(&[
        "key",
        "set",
        f,
        "--target",
        "Box.rotation",
        "--frame",
        "50",
        "--value",
        "0,1,0,3",
        "--interp",
        "squad",
    ]);
    ok(&[
        "key", "set", f, "--target", "Lamp.on", "--frame", "10", "--value", "false",
    ]);
    ok(&[
        "key",
        "set",
        f,
        "--target",
        "Box.diffuseColor",
        "--frame",
        "5",
        "--value",
        "1,0.5,0",
        "--repeat",
        "loop",
    ]);

    let json: serde_json::Value = serde_json::from_str(&ok(&["key", "list", f, "--json"])).unwrap();
    assert_eq!(json["fps"], 25.0);
    assert_eq!(json["duration"], 50.0);
    let tracks = json["tracks"].as_array().unwrap();
    assert_eq!(tracks.len(), 4, "{json}");
    let tr = &tracks[0];
    assert_eq!(tr["target"], "Box.translation");
    let k = &tr["keys"][1];
    assert_eq!(k["frame"], 25.0);
    assert_eq!(k["value"], serde_json::json!([0.0, 2.0, -1.5]));
    // Not given: copied from the key before, as the editor does.
    assert_eq!(k["interp"], "linear");
    assert_eq!(k["tcb"], serde_json::json!([0.5, -0.25, 0.0]));
    assert_eq!(
        k["ease"],
        serde_json::json!([0.30000001192092896, 0.699999988079071])
    );
    assert_eq!(tracks[1]["keys"][0]["interp"], "squad");
    assert_eq!(tracks[2]["target"], "Lamp.on");
    assert_eq!(tracks[2]["keys"][0]["value"], serde_json::json!([0.0]));
    assert_eq!(tracks[3]["repeat"], "loop");

    // Remove a key; write elsewhere; the original stays.
    let g = d.join("less.wrl");
    ok(&[
        "key",
        "rm",
        f,
        "--target",
        "Box.translation",
        "--frame",
        "25",
        "-o",
        s(&g),
    ]);
    let less: serde_json::Value =
        serde_json::from_str(&ok(&["key", "list", s(&g), "--json"])).unwrap();
    assert_eq!(less["tracks"][0]["keys"].as_array().unwrap().len(), 1);
    let (success, _, err) = animed(&[
        "key",
        "rm",
        s(&g),
        "--target",
        "Box.translation",
        "--frame",
        "25",
    ]);
    assert!(!success && err.contains("no key at frame"), "{err}");

    // Settings.
    ok(&["key", "settings", f, "--fps", "30"]);
    assert!(ok(&["key", "settings", f]).contains("fps 30"));

    // Convert to every format and back: the listing (every key) is unchanged.
    let before = ok(&["key", "list", f]);
    for ext in ["iv", "wrl.gz", "wrl"] {
        let out = d.join(format!("copy.{ext}"));
        let table = ok(&["convert", f, s(&out), "--verbose"]);
        assert!(table.contains("per-frame"), "{table}");
        assert_eq!(ok(&["key", "list", s(&out)]), before, "through .{ext}");
    }
    let v1 = d.join("old.iv");
    ok(&["convert", f, s(&v1), "--inventor-version", "1.0"]);
    assert!(std::fs::read_to_string(&v1)
        .unwrap()
        .starts_with("#Inventor V1.0 ascii"));

    // Bad input: clear errors, no file written.
    let (success, _, err) = animed(&[
        "key",
        "set",
        f,
        "--target",
        "Box.translation",
        "--frame",
        "3",
        "--value",
        "1,2",
    ]);
    assert!(!success && err.contains("3 comma-separated"), "{err}");
    let (success, _, err) = animed(&[
        "key",
        "set",
        f,
        "--target",
        "Box.wobble",
        "--frame",
        "3",
        "--value",
        "1",
    ]);
    assert!(!success && err.contains("unknown property"), "{err}");
    let (success, _, err) = animed(&["convert", f, s(&d.join("x.obj"))]);
    assert!(!success && err.contains("output format"), "{err}");
    let left: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp"))
        .collect();
    assert!(left.is_empty(), "temporary files left: {left:?}");
    std::fs::remove_dir_all(&d).unwrap();
}
