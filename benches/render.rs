//! `cargo bench --bench render`: the same scenes as `animed bench`, at
//! 1280×720 with all cores, and per-stage figures (setup, raster, shade,
//! resolve) on one thread.

use animed::internals::anim::{evaluate, Pose};
use animed::internals::render::job::{find_camera, view_for};
use animed::internals::render::stages::Stages;
use animed::internals::render::{bench_scenes, render_into, Frame, RenderOptions, View};
use animed::internals::scene::Scene;
use criterion::{criterion_group, criterion_main, Criterion};

const W: u32 = 1280;
const H: u32 = 720;

fn frame(c: &mut Criterion, name: &str, scene: &Scene) {
    frame_aa(c, name, scene, 1);
}

/// The pose at time 0, the scene's camera and the options of a 1280×720
/// frame with `aa` samples per pixel on `threads` threads (0 = all).
fn setup(scene: &Scene, aa: u32, threads: usize) -> (Pose, View, RenderOptions) {
    let pose = evaluate(scene, 0.0);
    let camera = find_camera(scene, None).ok().flatten();
    let view = view_for(scene, &pose, camera, W as f32 / H as f32);
    let opts = RenderOptions {
        width: W,
        height: H,
        headlight: false,
        threads,
        aa,
        ..RenderOptions::default()
    };
    (pose, view, opts)
}

/// One whole frame with `aa` samples per pixel (the frame reused, as the
/// editor and `animed bench` do).
fn frame_aa(c: &mut Criterion, name: &str, scene: &Scene, aa: u32) {
    let (pose, view, opts) = setup(scene, aa, 0);
    let mut out = Frame::new(W, H, opts.background);
    c.bench_function(name, |b| {
        b.iter(|| render_into(scene, &pose, &view, &opts, &mut out))
    });
}

/// The pipeline's stages one at a time on one thread (see
/// `render::stages`): setup (prepare + binning), raster (depth pass),
/// raster+shade (the shading pass needs its tile's depth pass; subtract
/// raster for the shading alone), resolve.
fn stages(c: &mut Criterion, name: &str, scene: &Scene, aa: u32) {
    let (pose, view, opts) = setup(scene, aa, 1);
    let mut s = Stages::new(scene, &pose, &view, &opts);
    c.bench_function(&format!("{name}/setup"), |b| {
        b.iter(|| s.setup(scene, &pose))
    });
    c.bench_function(&format!("{name}/raster"), |b| b.iter(|| s.raster()));
    c.bench_function(&format!("{name}/raster+shade"), |b| {
        b.iter(|| s.raster_and_shade())
    });
    c.bench_function(&format!("{name}/resolve"), |b| b.iter(|| s.resolve()));
    criterion::black_box(s.frame());
}

fn benches(c: &mut Criterion) {
    let aspect = W as f32 / H as f32;
    stages(c, "stages_layers_1", &bench_scenes::layers(1, aspect), 1);
    stages(
        c,
        "stages_small_triangles_100k",
        &bench_scenes::small_triangles(100_000, aspect),
        1,
    );
    stages(
        c,
        "stages_textured_1",
        &bench_scenes::layers_textured(1, aspect),
        1,
    );
    frame(c, "layers_1_3lights", &bench_scenes::layers(1, aspect));
    frame(c, "layers_8_3lights", &bench_scenes::layers(8, aspect));
    frame(
        c,
        "small_triangles_100k",
        &bench_scenes::small_triangles(100_000, aspect),
    );
    if let Ok(demo) = animed::internals::format::demo() {
        frame(c, "demo", &demo.scene);
        // Multisampling: depth/coverage per sample plus the resolve.
        frame_aa(c, "demo_aa4", &demo.scene, 4);
    }
}

criterion_group! {
    name = render_benches;
    config = Criterion::default().sample_size(10);
    targets = benches
}
criterion_main!(render_benches);
