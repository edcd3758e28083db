//! Golden pictures of corpus files read by the Inventor, VRML 1.0 and
//! VRML97 readers (copies in `tests/data/readers/`, licences in
//! `tests/data/LICENSES.md`), drawn the way `animed render` draws them.
//! Each was compared side by side with Coin 4 (pivy) before it was kept.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use std::path::Path;

fn draw(file: &str, time: f32) -> animed::internals::render::Frame {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/readers")
        .join(file);
    let loaded = animed::internals::format::load(&path).expect("test file loads");
    let spec = FrameSpec {
        width: 240,
        height: 180,
        viewpoint: None,
        style: None,
        background: Some(glam::Vec3::new(0.2, 0.2, 0.3)),
        headlight: Headlight::Auto,
        threads: 0,
        aa: 1,
    };
    render_at(&loaded.scene, &spec, time).expect("renders")
}

/// Inventor: Cube with PER_PART materials (blue front), MatrixTransforms.
#[test]
fn golden_inventor_simple_monitor() {
    golden::check("read_iv_simple_monitor", &draw("simpleMonitor.iv", 0.0));
}

/// VRML 1.0: Cone/Cylinder/Cube parts and per-part materials.
#[test]
fn golden_vrml1_materials_parts_primitives() {
    golden::check(
        "read_vrml1_materials_parts",
        &draw("materials_parts_primitives.wrl", 0.0),
    );
}

/// VRML97: an OrientationInterpolator on a box, at t = 1 s.
#[test]
fn golden_vrml97_orientation_interpolator_at_1s() {
    golden::check(
        "read_vrml97_alum_box_t1",
        &draw("orientation_interpolator_alum_box.wrl", 1.0),
    );
}
