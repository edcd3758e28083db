//! The renderer's output does not depend on the thread count, nor on the
//! build profile.
//!
//! Build-profile check: `goldens/release_*.png` were written by the
//! *release* binary (`tests/release-goldens.sh`, which runs
//! `cargo run --release -- render …`). The tests here render the same
//! frames in the test profile (a different optimisation level) and through
//! the test-profile binary, and require the exact same bytes. Regenerate
//! them with that script whenever the renderer's output changes on purpose.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use animed::internals::render::Frame;
use animed::internals::scene::RenderStyle;
use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn same(a: &Frame, b: &Frame) -> bool {
    a.color == b.color
        && a.ids == b.ids
        && a.depth
            .iter()
            .map(|d| d.to_bits())
            .eq(b.depth.iter().map(|d| d.to_bits()))
}

/// The demo (three light types, transparency, specular) and the oak in
/// lines style, at a size that is not a multiple of the tile, drawn with
/// 1, 2 and 7 threads: byte-identical colour, depth and ids.
#[test]
fn thread_count_never_changes_the_picture() {
    let demo = animed::internals::format::demo()
        .expect("bundled demo loads")
        .scene;
    let oak = animed::internals::format::load(&root().join("tests/data/oak_leafless.obj"))
        .unwrap()
        .scene;
    let cases = [
        (&demo, None, 2.5f32, 1),
        (&oak, Some(RenderStyle::Lines), 0.0, 1),
        (&oak, Some(RenderStyle::Points), 0.0, 1),
        (&demo, None, 2.5f32, 4),
        (&oak, Some(RenderStyle::Lines), 0.0, 8),
    ];
    for (scene, style, time, aa) in cases {
        let spec = |threads| FrameSpec {
            width: 333,
            height: 201,
            style,
            threads,
            aa,
            ..FrameSpec::default()
        };
        let one = render_at(scene, &spec(1), time).unwrap();
        assert!(one.ids.iter().any(|&i| i != 0), "something was drawn");
        for threads in [2, 7] {
            let n = render_at(scene, &spec(threads), time).unwrap();
            assert!(
                same(&one, &n),
                "{threads} threads differ from 1 ({style:?}, aa {aa})"
            );
        }
    }
}

/// The frames `tests/release-goldens.sh` writes with the release binary.
fn release_cases() -> Vec<(&'static str, FrameSpec)> {
    let base = FrameSpec {
        width: 200,
        height: 150,
        headlight: Headlight::On,
        threads: 2,
        ..FrameSpec::default()
    };
    vec![
        ("release_oak", base.clone()),
        (
            "release_oak_lines",
            FrameSpec {
                style: Some(RenderStyle::Lines),
                ..base
            },
        ),
    ]
}

#[test]
fn test_profile_matches_release_binary_exactly() {
    let oak = animed::internals::format::load(&root().join("tests/data/oak_leafless.obj"))
        .unwrap()
        .scene;
    for (name, spec) in release_cases() {
        let frame = render_at(&oak, &spec, 0.0).unwrap();
        golden::check_exact_external(name, &frame);
    }
}

/// The CLI binary of this build writes the same bytes as the release one.
#[test]
fn cli_binary_matches_release_binary_exactly() {
    let out_dir = root().join("target").join("render-determinism");
    std::fs::create_dir_all(&out_dir).unwrap();
    for (name, style) in [("release_oak", "filled"), ("release_oak_lines", "lines")] {
        let out = out_dir.join(format!("{name}.png"));
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_animed"))
            .args(["render", "tests/data/oak_leafless.obj", "--size", "200x150"])
            .args([
                "--headlight",
                "on",
                "--threads",
                "2",
                "--style",
                style,
                "-o",
            ])
            .arg(&out)
            .current_dir(root())
            .status()
            .unwrap();
        assert!(status.success());
        let got = image::open(&out).unwrap().to_rgb8();
        let want = image::open(golden::golden_path(name)).unwrap().to_rgb8();
        assert!(
            got == want,
            "{name}: the CLI's picture differs from the release binary's"
        );
    }
}

/// The demo scene golden (tolerant). When `assets/demo.wrl` changes on
/// purpose, rerun with UPDATE_GOLDENS=1 and look at the picture.
#[test]
fn demo_scene() {
    let demo = animed::internals::format::demo()
        .expect("bundled demo loads")
        .scene;
    let spec = FrameSpec {
        width: 320,
        height: 240,
        ..FrameSpec::default()
    };
    golden::check("demo", &render_at(&demo, &spec, 0.0).unwrap());
    // `render --aa 4`: smooth silhouettes (zoom in on the golden).
    let aa = FrameSpec { aa: 4, ..spec };
    golden::check("demo_aa4", &render_at(&demo, &aa, 0.0).unwrap());
}

/// The SSE2, AVX and AVX-512-register shading paths (picked at run time
/// from the CPU; `ANIMED_SIMD=sse2` forces SSE2, `ANIMED_SIMD=avx` AVX
/// without AVX-512's registers) write the same bytes: the demo has all
/// three light kinds, a spot ramp, specular and transparency (also with 4x
/// AA); inventor.iv has textures of every kind (the eight-lane sampler and
/// its per-lane fallbacks); emissive.gltf has glTF emissive maps.
#[test]
fn simd_path_never_changes_the_picture() {
    #[cfg(target_arch = "x86_64")]
    if !std::arch::is_x86_feature_detected!("avx") {
        eprintln!("NOTE: this CPU has no AVX, so every run below takes the SSE2 path");
    }
    let out_dir = root().join("target").join("render-determinism");
    std::fs::create_dir_all(&out_dir).unwrap();
    let render = |file: &str, aa: &str, simd: Option<&str>, name: &str| {
        let out = out_dir.join(name);
        let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_animed"));
        cmd.args([
            "render", file, "--size", "333x201", "--time", "2.5", "--aa", aa, "-o",
        ])
        .arg(&out)
        .current_dir(root());
        match simd {
            Some(v) => cmd.env("ANIMED_SIMD", v),
            None => cmd.env_remove("ANIMED_SIMD"),
        };
        assert!(cmd.status().unwrap().success());
        image::open(&out).unwrap().to_rgb8()
    };
    for (file, aa) in [
        ("assets/demo.wrl", "1"),
        ("assets/demo.wrl", "4"),
        ("tests/data/textures/inventor.iv", "1"),
        // Emissive maps: a second sampler added after the lighting.
        ("tests/data/gltf/emissive.gltf", "4"),
    ] {
        let sse2 = render(file, aa, Some("sse2"), "simd_sse2.png");
        let avx = render(file, aa, Some("avx"), "simd_avx.png");
        let auto = render(file, aa, None, "simd_auto.png");
        assert!(
            sse2 == avx,
            "{file} --aa {aa}: the SSE2 and AVX paths differ"
        );
        assert!(
            auto == avx,
            "{file} --aa {aa}: the AVX-512 and AVX paths differ"
        );
    }
}
