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

/// `animed info --strict tests/data/vrml97_bad/FILE` exits 3, warns at
/// `FILE:at:` with `what`, and says why it failed.
fn assert_flagged(file: &str, at: &str, what: &str) {
    assert_flagged_at(&format!("tests/data/vrml97_bad/{file}"), at, what);
}

/// [`assert_flagged`] for the file at `path`.
fn assert_flagged_at(path: &str, at: &str, what: &str) {
    let (code, out, err) = animed(&["info", "--strict", path]);
    assert_eq!(code, 3, "{path}: {out}{err}");
    let want = format!("{path}:{at}: ");
    assert!(
        out.lines().any(|l| l.contains(&want) && l.contains(what)),
        "{path}: no warning '{want}…{what}' in\n{out}"
    );
    assert!(err.contains("--strict"), "{err}");
}

/// OpenVRML's invalid VRML97 files: each is flagged with a warning at the
/// line and column of the offending statement, and `info --strict` turns
/// that into exit status 3. (Expected rule and position per file.)
#[test]
fn openvrml_bad_files_are_flagged_with_locations() {
    let cases = [
        ("exposedfield-in-script.wrl", "3:3", "exposedField"),
        ("is-outside-proto.wrl", "3:3", "outside a PROTO body"),
        ("is-value-type-mismatch.wrl", "3:11", "val is SFBool"),
        ("proto-eventin-conflict.wrl", "2:7", "'set_foo' clashes"),
        (
            "proto-eventout-conflict.wrl",
            "2:7",
            "'foo_changed' clashes",
        ),
        ("unrecognized-field.wrl", "3:8", "no field 'wrong'"),
        (
            "value-for-eventin-in-proto.wrl",
            "3:11",
            "'set_children' is an event",
        ),
    ];
    for (file, at, what) in cases {
        assert_flagged(file, at, what);
    }
    // A valid file passes --strict.
    let (code, out, err) = animed(&["info", "--strict", "assets/demo.wrl"]);
    assert_eq!(code, 0, "{out}{err}");
}

/// X3D files get the same checks against X3D's own node table
/// (`format/syntax/x3d_table.rs`), in both encodings: `info --strict`
/// exits 3 and names the place.
#[test]
fn x3d_routes_is_and_fields_are_checked_against_x3ds_nodes() {
    for (file, at, what) in [
        ("route-type-mismatch.x3dv", "7:1", "SFFloat to SFVec3f"),
        (
            "unknown-field.x3dv",
            "5:13",
            "Transform has no field 'translate'",
        ),
        (
            "route-to-field.x3d",
            "28:3",
            "'bboxCenter' is a field of Transform",
        ),
        (
            "route-to-field.x3d",
            "16:11",
            "children is MFNode but shown is SFBool",
        ),
        (
            "container-field.x3d",
            "10:12",
            "containerField 'translation': 'translation' of Transform is SFVec3f",
        ),
    ] {
        assert_flagged_at(&format!("tests/data/x3d_bad/{file}"), at, what);
    }
}

/// `animed info FILE | head` once panicked with "failed printing to stdout:
/// Broken pipe". With the reader gone before the first line, the command
/// must end without a panic message (killed by SIGPIPE, as text tools are).
#[cfg(unix)]
#[test]
fn printing_into_a_closed_pipe_ends_quietly() {
    use std::os::unix::process::ExitStatusExt;
    let (reader, writer) = std::io::pipe().expect("pipe");
    drop(reader);
    for args in [
        &["info", "assets/demo.wrl"][..],
        &["info", "assets/demo.wrl", "--json"][..],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_animed"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .stdout(writer.try_clone().expect("clone pipe"))
            .output()
            .expect("run animed");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(!err.contains("Broken pipe"), "{args:?}: {err}");
        assert_eq!(
            out.status.signal(),
            Some(SIGPIPE),
            "{args:?}: {:?}",
            out.status
        );
    }
}

/// SIGPIPE's number on Linux and the BSDs.
#[cfg(unix)]
const SIGPIPE: i32 = 13;

/// ROUTE and IS rules that need each built-in node's fields (ISO/IEC
/// 14772-1 §4.10.2, §4.8.3 table 4.4; the table is
/// `format/syntax/node_table.rs`), on files written for this test: each
/// warned at the ROUTE statement (or the IS field), `--strict` exits 3.
#[test]
fn routes_and_is_are_checked_against_node_interfaces() {
    let cases = [
        (
            "route-to-field.wrl",
            "7:1",
            "'bboxCenter' is a field of Transform",
        ),
        ("route-from-field.wrl", "4:1", "'size' is a field of Box"),
        (
            "route-type-mismatch.wrl",
            "5:1",
            "ROUTE T.fraction_changed TO X.set_translation: SFFloat to SFVec3f",
        ),
        (
            "route-unknown-event.wrl",
            "5:1",
            "TimeSensor has no eventOut 'fraction'",
        ),
        // A Script's declared eventOut and a PROTO's declared eventIn.
        (
            "route-script-proto-types.wrl",
            "15:1",
            "ROUTE S.done TO M.set_place: SFTime to SFVec3f",
        ),
        (
            "is-access-mismatch.wrl",
            "5:11",
            "set_middle is an eventIn but bboxCenter is a field of Group",
        ),
    ];
    for (file, at, what) in cases {
        assert_flagged(file, at, what);
    }
    // The Script's good ROUTE (SFFloat to its SFFloat eventIn) is not
    // flagged: one ROUTE warning in that file, not two.
    let (_, out, _) = animed(&["info", "tests/data/vrml97_bad/route-script-proto-types.wrl"]);
    assert_eq!(out.matches(": ROUTE ").count(), 1, "{out}");
}

/// A field VRML97's built-in node does not have (§6), or an event given a
/// value, is warned at the field's own line and column; `--strict` exits 3.
#[test]
fn unknown_fields_of_builtin_vrml97_nodes_are_flagged() {
    for (at, what) in [
        ("4:3", "Transform has no field 'translate'"),
        ("6:49", "Material has no field 'diffuseColour'"),
        ("7:31", "Box has no field 'radius'"),
        ("10:30", "'isActive' is an eventOut of TimeSensor"),
    ] {
        assert_flagged("unknown-builtin-fields.wrl", at, what);
    }
}

/// A value that does not fit the type a built-in node gives its field
/// (§5: a count of numbers, a word, a string, a fraction) is warned at the
/// value; `--strict` exits 3.
#[test]
fn values_that_do_not_fit_builtin_field_types_are_flagged() {
    for (at, what) in [
        (
            "4:25",
            "'translation' of Transform is SFVec3f and takes 3 numbers, found 2 numbers",
        ),
        (
            "5:25",
            "'loop' of TimeSensor is SFBool and takes TRUE or FALSE, found the number 1",
        ),
        (
            "6:19",
            "'title' of WorldInfo is SFString and takes one quoted string",
        ),
        (
            "7:23",
            "'type' of NavigationInfo is MFString and takes quoted strings, found 'EXAMINE'",
        ),
        (
            "8:22",
            "'whichChoice' of Switch is SFInt32 and takes a whole number, found the number 0.5",
        ),
    ] {
        assert_flagged("field-value-types.wrl", at, what);
    }
    let (_, out, _) = animed(&["info", "tests/data/vrml97_bad/field-value-types.wrl"]);
    assert_eq!(out.matches(" (§5)").count(), 5, "{out}");
}

/// `info --strict` fails on what the file breaks, not on what animed does
/// not support or cannot find (`format/warn_kind.rs`): a VRML97 file with
/// only a Script and a missing texture passes, its warnings still printed;
/// one more unknown field fails it, and the count says which is which.
#[test]
fn strict_counts_spec_breaks_not_animeds_limits() {
    let dir = std::env::temp_dir().join(format!("animed-strict-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let limits = "#VRML V2.0 utf8\nScript { }\nShape { appearance Appearance { \
                  texture ImageTexture { url \"gone.png\" } } geometry Box { } }\n";
    let ok = dir.join("limits.wrl");
    std::fs::write(&ok, limits).unwrap();
    let (code, out, err) = animed(&["info", "--strict", ok.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}{err}");
    let all = format!("{out}{err}");
    assert!(all.contains("Script is not supported"), "{all}");
    assert!(all.contains("gone.png"), "{all}");
    let bad = dir.join("bad.wrl");
    std::fs::write(&bad, format!("{limits}Transform {{ translate 1 0 0 }}\n")).unwrap();
    let (code, out, err) = animed(&["info", "--strict", bad.to_str().unwrap()]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(err.contains("--strict: 1 warning(s)"), "{err}");
    assert!(
        err.contains("(2 more about what animed does not support"),
        "{err}"
    );
}
