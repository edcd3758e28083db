//! `animed check` end to end: the README's example suite passes, a broken
//! scene fails with readable files and reports, `--update` accepts, suite
//! mistakes are `path:line:col` with exit 2, and the single-file form.

use std::path::{Path, PathBuf};
use std::process::Command;

fn animed() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_animed"));
    c.env_remove("ANIMED_UPDATE");
    c
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let d = root().join("target").join("check-tests").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A copy of examples/suite (suite, scene and goldens) in a scratch folder.
fn copy_example(name: &str) -> PathBuf {
    let d = scratch(name);
    let src = root().join("examples/suite");
    std::fs::create_dir_all(d.join("goldens")).unwrap();
    for f in ["suite.toml", "spinner.wrl"] {
        std::fs::copy(src.join(f), d.join(f)).unwrap();
    }
    for e in std::fs::read_dir(src.join("goldens")).unwrap() {
        let e = e.unwrap();
        std::fs::copy(e.path(), d.join("goldens").join(e.file_name())).unwrap();
    }
    d
}

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn run(cmd: &mut Command) -> Run {
    let o = cmd.output().expect("animed runs");
    Run {
        code: o.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
    }
}

fn check(dir: &Path, extra: &[&str]) -> Run {
    run(animed()
        .arg("check")
        .arg(dir.join("suite.toml"))
        .arg("--out")
        .arg(dir.join("out"))
        .args(extra))
}

#[test]
fn the_readme_example_suite_passes_and_writes_reports() {
    let d = scratch("example");
    let out = run(animed()
        .current_dir(root())
        .args(["check", "examples/suite/suite.toml", "--out"])
        .arg(d.join("out"))
        .arg("--report")
        .arg(d.join("r.xml"))
        .arg("--report")
        .arg(d.join("r.json")));
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
    for shot in ["still", "turn@0", "turn@0.5", "turn@1", "top"] {
        assert!(
            out.stdout
                .lines()
                .any(|l| l.starts_with(shot) && l.contains("pass")),
            "{shot} not passed in\n{}",
            out.stdout
        );
    }
    assert!(out.stdout.contains("5 passed, 0 failed"), "{}", out.stdout);
    let xml = std::fs::read_to_string(d.join("r.xml")).unwrap();
    assert!(
        xml.contains("tests=\"5\" failures=\"0\" errors=\"0\""),
        "{xml}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("r.json")).unwrap()).unwrap();
    assert_eq!(json["passed"], 5);
    assert_eq!(json["exit_code"], 0);
    assert_eq!(json["shots"][2]["name"], "turn@0.5");
    // Nothing to look at when everything passes.
    assert!(!d.join("out").join("still.diff.png").exists());
}

#[test]
fn a_broken_scene_fails_with_diffs_and_junit_then_update_accepts_it() {
    let d = copy_example("broken");
    let scene = d.join("spinner.wrl");
    let text = std::fs::read_to_string(&scene).unwrap();
    // The box turns green instead of red.
    let broken = text.replace("diffuseColor 0.85 0.2 0.15", "diffuseColor 0.2 0.8 0.15");
    assert_ne!(broken, text);
    std::fs::write(&scene, broken).unwrap();
    let golden_before = std::fs::read(d.join("goldens/turn@0.5.png")).unwrap();

    let out = check(&d, &["--report", d.join("junit.xml").to_str().unwrap()]);
    assert_eq!(out.code, 1, "{}{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("FAIL"), "{}", out.stdout);
    for shot in ["still", "turn@0", "turn@0.5", "turn@1", "top"] {
        let diff = d.join("out").join(format!("{shot}.diff.png"));
        let actual = d.join("out").join(format!("{shot}.actual.png"));
        assert!(diff.exists() && actual.exists(), "{shot}: no diff/actual");
        let img = animed::Image::load_png(&diff).unwrap();
        let red = img
            .as_rgb()
            .chunks_exact(3)
            .filter(|p| p[0] >= 150 && p[1] == 0 && p[2] == 0)
            .count();
        assert!(red > 100, "{shot}: only {red} red pixels in the diff");
    }
    let xml = std::fs::read_to_string(d.join("junit.xml")).unwrap();
    assert!(xml.contains("failures=\"5\""), "{xml}");
    assert!(xml.contains("<failure type=\"differs\""), "{xml}");
    assert!(xml.contains("turn@0.5.diff.png"), "{xml}");
    // Goldens untouched without --update.
    assert_eq!(
        std::fs::read(d.join("goldens/turn@0.5.png")).unwrap(),
        golden_before
    );

    let out = check(&d, &["--update"]);
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("5 updated"), "{}", out.stdout);
    assert_ne!(
        std::fs::read(d.join("goldens/turn@0.5.png")).unwrap(),
        golden_before
    );
    assert!(
        !d.join("out/turn@0.5.diff.png").exists(),
        "stale diff left behind"
    );
    let out = check(&d, &[]);
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
}

#[test]
fn a_missing_golden_is_new_and_only_written_when_asked() {
    let d = copy_example("missing");
    let golden = d.join("goldens/top.png");
    std::fs::remove_file(&golden).unwrap();
    let out = check(&d, &[]);
    assert_eq!(out.code, 1, "{}{}", out.stdout, out.stderr);
    assert!(out
        .stdout
        .lines()
        .any(|l| l.starts_with("top") && l.contains("NEW")));
    assert!(
        !golden.exists(),
        "a missing golden was written without --update"
    );
    assert!(d.join("out/top.actual.png").exists());
    let out = run(animed()
        .env("ANIMED_UPDATE", "1")
        .arg("check")
        .arg(d.join("suite.toml"))
        .arg("--out")
        .arg(d.join("out")));
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
    assert!(out.stdout.contains("1 created"), "{}", out.stdout);
    assert!(golden.exists());
}

#[test]
fn suite_mistakes_are_reported_at_line_and_column_with_exit_2() {
    let d = copy_example("bad");
    let suite = d.join("suite.toml");
    let cases = [
        // (text, expected "line:col: message" fragment)
        (
            "[[case]]\nname = \"a\"\nfile = \"spinner.wrl\"\n  colour = \"red\"\n",
            ":4:3: unknown key \"colour\" in a case",
        ),
        (
            "[[case]]\nname = \"a\"\nfile = \"spinner.wrl\"\ntimes = 3\n",
            ":4:9: `times` must be a list",
        ),
        (
            "size = \"big\"\n[[case]]\nname = \"a\"\nfile = \"x.wrl\"\n",
            ":1:8: size \"big\"",
        ),
        (
            "[[case]]\nname = \"a\"\nfile = \"x.wrl\"\ntolerance = { channel = 300 }\n",
            ":4:25: `channel` must be in 0..=255",
        ),
        ("[[case]\nname = 1\n", ":1:"),
        (
            "[[case]]\nfile = \"spinner.wrl\"\n",
            ":1:1: this case has no `name`",
        ),
    ];
    for (text, want) in cases {
        std::fs::write(&suite, text).unwrap();
        let out = check(&d, &[]);
        assert_eq!(out.code, 2, "{text}\n{}{}", out.stdout, out.stderr);
        let want = format!("{}{want}", suite.display());
        assert!(
            out.stderr.contains(&want),
            "want {want:?} in {:?}",
            out.stderr
        );
    }
    // A scene that does not load is that case's error: exit 2, the others still run.
    std::fs::write(
        &suite,
        "size = \"160x120\"\ntolerance = { channel = 2, fraction = 0.001 }\n\
         [[case]]\nname = \"still\"\nfile = \"spinner.wrl\"\n\
         [[case]]\nname = \"gone\"\nfile = \"nothing-here.wrl\"\n",
    )
    .unwrap();
    let out = check(&d, &[]);
    assert_eq!(out.code, 2, "{}{}", out.stdout, out.stderr);
    assert!(out
        .stdout
        .lines()
        .any(|l| l.starts_with("still") && l.contains("pass")));
    assert!(out
        .stdout
        .lines()
        .any(|l| l.starts_with("gone") && l.contains("ERROR")));
}

#[test]
fn one_file_against_one_golden() {
    let d = copy_example("single");
    let golden = d.join("goldens/turn@0.5.png");
    let args = |time: &str| {
        let mut c = animed();
        c.arg("check")
            .arg(d.join("spinner.wrl"))
            .arg("--golden")
            .arg(&golden)
            .args(["--size", "160x120", "--channel", "2", "--fraction", "0.001"])
            .args(["--time", time, "--out"])
            .arg(d.join("out"));
        c
    };
    let out = run(&mut args("0.5"));
    assert_eq!(out.code, 0, "{}{}", out.stdout, out.stderr);
    let out = run(&mut args("0.25"));
    assert_eq!(out.code, 1, "{}{}", out.stdout, out.stderr);
    assert!(d.join("out/turn@0.5.diff.png").exists());
    // Render flags without --golden are a usage error.
    let out = run(animed()
        .arg("check")
        .arg(d.join("suite.toml"))
        .args(["--size", "10x10"]));
    assert_eq!(out.code, 2);
    assert!(
        out.stderr.contains("--size only apply with --golden"),
        "{}",
        out.stderr
    );
}
