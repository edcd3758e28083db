//! The golden-image harness every animed test uses: a thin wrapper over the
//! public [`animed::check::verify`] / [`animed::compare`] (one harness for
//! our tests, `animed check` and users).
//!
//! Use it from a test file with
//! `#[path = "common/golden.rs"] mod golden;` and call
//! `golden::check("name", &frame)`: it compares with `goldens/name.png`
//! within [`MAX_CHANNEL_DIFF`] / [`MAX_DIFF_FRACTION`] (the one place the
//! tolerance is stated), and on failure writes
//! `target/golden-diff/name.actual.png` and `name.diff.png` (differences in
//! red over a dimmed golden, a cyan frame around them).
//! `UPDATE_GOLDENS=1 cargo test` (or `ANIMED_UPDATE=1`) rewrites failing
//! goldens instead; look at every rewritten PNG before committing it. A
//! missing golden is a failure, never a silent pass.
//!
//! Determinism across builds (tests/run-all.sh): `GOLDEN_RECORD=DIR` also
//! saves every picture a golden test draws as `DIR/name.png`; a second
//! build run with `GOLDEN_EXACT=DIR` (CI: `-C target-cpu=x86-64-v3`)
//! compares each picture byte for byte with that recording instead of the
//! golden, and never updates anything.
#![allow(dead_code)]

use animed::check::{verify, Options, Status};
use animed::internals::render::Frame;
use animed::{Allowance, Image, Tolerance};
use std::path::PathBuf;

/// Largest difference allowed in one colour channel (0..255) of one pixel…
pub const MAX_CHANNEL_DIFF: u8 = 2;
/// …and the fraction of pixels allowed to exceed it (0.1 %).
pub const MAX_DIFF_FRACTION: f64 = 0.001;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn golden_path(name: &str) -> PathBuf {
    root().join("goldens").join(format!("{name}.png"))
}

fn diff_dir() -> PathBuf {
    root().join("target").join("golden-diff")
}

fn env_on(name: &str) -> bool {
    std::env::var(name).is_ok_and(|v| !v.is_empty() && v != "0")
}

/// Compares with tolerance; panics with a useful message on failure.
pub fn check(name: &str, frame: &Frame) {
    run(
        name,
        frame,
        Tolerance::new(MAX_CHANNEL_DIFF, Allowance::Fraction(MAX_DIFF_FRACTION)),
        true,
    );
}

/// Byte-for-byte comparison (for determinism goldens).
pub fn check_exact(name: &str, frame: &Frame) {
    run(name, frame, Tolerance::exact(), true);
}

/// Byte-for-byte comparison with a golden that another tool writes (e.g.
/// the release binary): `UPDATE_GOLDENS` does not rewrite it.
pub fn check_exact_external(name: &str, frame: &Frame) {
    run(name, frame, Tolerance::exact(), false);
}

fn env_dir(name: &str) -> Option<PathBuf> {
    let v = std::env::var_os(name).filter(|v| !v.is_empty())?;
    Some(root().join(v))
}

fn run(name: &str, frame: &Frame, tolerance: Tolerance, may_update: bool) {
    let actual = Image::from(frame);
    if let Some(dir) = env_dir("GOLDEN_RECORD") {
        actual
            .save_png(dir.join(format!("{name}.png")))
            .unwrap_or_else(|e| panic!("golden {name}: cannot record: {e}"));
    }
    let mut options = Options::new(diff_dir());
    options.update = may_update && (options.update || env_on("UPDATE_GOLDENS"));
    let (path, tolerance) = match env_dir("GOLDEN_EXACT") {
        Some(dir) => {
            options.update = false;
            options.out_dir = diff_dir().join("exact");
            (dir.join(format!("{name}.png")), Tolerance::exact())
        }
        None => (golden_path(name), tolerance),
    };
    let verdict = verify(&actual, &path, name, &tolerance, &options)
        .unwrap_or_else(|e| panic!("golden {name}: {e}"));
    match verdict.status {
        Status::Passed => {}
        Status::Updated | Status::Created => {
            eprintln!("golden: rewrote {} — look at it", path.display())
        }
        Status::New => panic!(
            "golden {name}: there is no {}; the actual picture is in \
             target/golden-diff/{name}.actual.png — run with UPDATE_GOLDENS=1 to create it",
            path.display()
        ),
        _ => panic!(
            "golden {name}: {}; see target/golden-diff/{name}.actual.png and {name}.diff.png",
            verdict
                .comparison
                .map(|c| c.summary())
                .unwrap_or_else(|| "no comparison".into())
        ),
    }
}
