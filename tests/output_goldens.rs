//! Goldens of animation frames as `animed render --range` draws them
//! (`render::job::render_color_at`, the function the sequence writer calls):
//! the demo animation and a castle-engine OrientationInterpolator test.
//! `UPDATE_GOLDENS=1` rewrites them; look at every one.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::output::FrameRange;
use animed::internals::render::job::{render_color_at, FrameSpec};
use std::path::PathBuf;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn spec() -> FrameSpec {
    FrameSpec {
        width: 160,
        height: 120,
        ..FrameSpec::default()
    }
}

fn check_range(file: &str, golden_prefix: &str, range: &str) {
    let scene = animed::internals::format::load(&data(file))
        .unwrap_or_else(|e| panic!("{file}: {e}"))
        .scene;
    assert!(
        !scene.animation.tracks.is_empty(),
        "{file} should be animated"
    );
    let r = FrameRange::parse(range).unwrap();
    let mut frames = Vec::new();
    for i in 0..r.count {
        let f = render_color_at(&scene, &spec(), r.time(i)).expect("render");
        golden::check(&format!("{golden_prefix}_{i}"), &f);
        frames.push(f);
    }
    // The goldens show motion: consecutive frames differ.
    for w in frames.windows(2) {
        assert!(
            w[0].color != w[1].color,
            "{file}: two frames are the same picture"
        );
    }
}

#[test]
fn demo_animation_frames() {
    // The demo loops over 4 s: the sphere bounces, the box turns and the
    // spot light changes colour.
    check_range("output_demo.wrl", "anim_demo", "0:1.25:4");
}

#[test]
fn castle_orientation_interpolator_frames() {
    // A box turning 0° → 120° → 240° → 360° about y over a 4 s loop
    // (keys at 0, .33, .66, 1), seen from its Viewpoint, headlight off.
    check_range(
        "orientation_interpolator_alum_box.wrl",
        "anim_castle_orientation",
        "0:0.5:4",
    );
}
