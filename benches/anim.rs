//! Animation speed: samples per second of TCB Vec3 and squad-TCB rotation
//! tracks (1000 tracks × 8 unevenly spaced keys, looping), and one whole
//! `evaluate_into` of a scene with 5000 tracks on 2500 nodes.
//!
//! Run: `cargo bench --bench anim` (about 15 s).

use animed::internals::anim::{evaluate_into, synthetic, Pose, Track};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;
use std::time::Duration;

fn sample_all(c: &mut Criterion, name: &str, tracks: &[Track]) {
    let mut g = c.benchmark_group("sample");
    g.throughput(Throughput::Elements(tracks.len() as u64));
    g.bench_function(name, |b| {
        let mut f = 0.0f32;
        b.iter(|| {
            // Step through the loops so every segment gets sampled.
            f = (f + 0.37) % 200.0;
            for t in tracks {
                black_box(t.sample(black_box(f)));
            }
        })
    });
    g.finish();
}

fn bench(c: &mut Criterion) {
    let v: Vec<Track> = (0..1000)
        .map(|i| synthetic::vec3_track(i, 8, i as u64))
        .collect();
    let q: Vec<Track> = (0..1000)
        .map(|i| synthetic::squad_track(i, 8, i as u64))
        .collect();
    sample_all(c, "tcb_vec3_1000_tracks_8_keys", &v);
    sample_all(c, "squad_tcb_1000_tracks_8_keys", &q);

    let scene = synthetic::scene(2500, 8);
    let mut g = c.benchmark_group("evaluate");
    g.throughput(Throughput::Elements(scene.animation.tracks.len() as u64));
    g.bench_function("scene_2500_nodes_5000_tracks", |b| {
        let mut pose = Pose::default();
        let mut t = 0.0f32;
        b.iter(|| {
            t = (t + 0.013) % 8.0;
            evaluate_into(&scene, black_box(t), &mut pose);
            black_box(&pose);
        })
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(20);
    targets = bench
}
criterion_main!(benches);
