//! The golden-image harness every animed test uses.
//!
//! Use it from a test file with
//! `#[path = "common/golden.rs"] mod golden;` and call
//! `golden::check("name", &frame)`: it compares with `goldens/name.png`
//! within [`MAX_CHANNEL_DIFF`] / [`MAX_DIFF_FRACTION`] (the one place the
//! tolerance is stated), and on failure writes
//! `target/golden-diff/name.actual.png` and `name.diff.png` (differing pixels
//! red, brighter = larger difference, the rest a dim copy of the golden).
//! `UPDATE_GOLDENS=1 cargo test` rewrites the goldens instead; look at every
//! rewritten PNG before committing it. A missing golden is a failure, never a
//! silent pass.
#![allow(dead_code)]

use animed::render::Frame;
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

fn updating() -> bool {
    std::env::var("UPDATE_GOLDENS").is_ok_and(|v| !v.is_empty() && v != "0")
}

fn rgb(frame: &Frame) -> image::RgbImage {
    let mut img = image::RgbImage::new(frame.width, frame.height);
    for (p, &c) in img.pixels_mut().zip(&frame.color) {
        *p = image::Rgb([(c >> 16) as u8, (c >> 8) as u8, c as u8]);
    }
    img
}

fn save(img: &image::RgbImage, path: &PathBuf) {
    std::fs::create_dir_all(path.parent().expect("golden paths have a parent"))
        .expect("create golden directory");
    img.save(path)
        .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
}

/// Compares with tolerance; panics with a useful message on failure.
pub fn check(name: &str, frame: &Frame) {
    compare(name, frame, MAX_CHANNEL_DIFF, MAX_DIFF_FRACTION, true);
}

/// Byte-for-byte comparison (for determinism goldens).
pub fn check_exact(name: &str, frame: &Frame) {
    compare(name, frame, 0, 0.0, true);
}

/// Byte-for-byte comparison with a golden that another tool writes (e.g.
/// the release binary): `UPDATE_GOLDENS` does not rewrite it.
pub fn check_exact_external(name: &str, frame: &Frame) {
    compare(name, frame, 0, 0.0, false);
}

fn compare(name: &str, frame: &Frame, max_channel: u8, max_fraction: f64, may_update: bool) {
    let actual = rgb(frame);
    let path = golden_path(name);
    if may_update && updating() {
        save(&actual, &path);
        eprintln!("golden: rewrote {} — look at it", path.display());
        return;
    }
    let expected = match image::open(&path) {
        Ok(img) => img.to_rgb8(),
        Err(e) => {
            save(&actual, &diff_dir().join(format!("{name}.actual.png")));
            panic!(
                "golden {name}: cannot read {} ({e}); the actual picture is in \
                 target/golden-diff/{name}.actual.png — run with UPDATE_GOLDENS=1 to create it",
                path.display()
            );
        }
    };
    if expected.dimensions() != actual.dimensions() {
        save(&actual, &diff_dir().join(format!("{name}.actual.png")));
        panic!(
            "golden {name}: size {:?} but the golden is {:?}",
            actual.dimensions(),
            expected.dimensions()
        );
    }
    let mut diff = image::RgbImage::new(actual.width(), actual.height());
    let mut bad = 0usize;
    let mut worst = 0u8;
    for ((a, e), d) in actual
        .pixels()
        .zip(expected.pixels())
        .zip(diff.pixels_mut())
    {
        let m = (0..3).map(|k| a[k].abs_diff(e[k])).max().unwrap_or(0);
        worst = worst.max(m);
        if m > max_channel {
            bad += 1;
            *d = image::Rgb([128u8.saturating_add(m / 2).max(160), 0, 0]);
        } else {
            *d = image::Rgb([e[0] / 4, e[1] / 4, e[2] / 4]);
        }
    }
    let n = (actual.width() * actual.height()).max(1) as f64;
    let allowed = (n * max_fraction).floor() as usize;
    if bad > allowed {
        save(&actual, &diff_dir().join(format!("{name}.actual.png")));
        save(&diff, &diff_dir().join(format!("{name}.diff.png")));
        panic!(
            "golden {name}: {bad} pixels differ by more than {max_channel} (allowed {allowed}), \
             worst {worst}; see target/golden-diff/{name}.actual.png and {name}.diff.png"
        );
    }
}
