//! glTF load time: a generated ~50 MB .glb (a 920 × 920 grid mesh with
//! normals and vertex colours, written by animed's own writer) read back
//! with `format::load_bytes`, the whole reader from container to scene.
//! `cargo bench --bench gltf_load`.

use animed::internals::format::{self, WriteOptions};
use animed::internals::scene::{Material, Mesh, Node, NodeKind, Scene, Shape};
use criterion::{criterion_group, criterion_main, Criterion};
use glam::Vec3;
use std::path::Path;

/// A grid of `n × n` quads: (n+1)² vertices, 2n² triangles.
fn grid(n: u32) -> Scene {
    let mut s = Scene::new();
    let w = n + 1;
    let mut m = Mesh::default();
    for y in 0..w {
        for x in 0..w {
            let (fx, fy) = (x as f32 / n as f32, y as f32 / n as f32);
            m.positions
                .push(Vec3::new(fx, fy, (fx * 9.0).sin() * (fy * 7.0).cos() * 0.1));
            m.normals.push(Vec3::Z);
            m.colors.push(Vec3::new(fx, fy, 0.5));
        }
    }
    for y in 0..n {
        for x in 0..n {
            let i = y * w + x;
            m.triangles.push([i, i + 1, i + w + 1]);
            m.triangles.push([i, i + w + 1, i + w]);
        }
    }
    m.solid = true;
    let mesh = s.add_mesh(m);
    let material = s.add_material(Material::default());
    s.add_node(
        None,
        Node::new("Grid", NodeKind::Shape(Shape { mesh, material })),
    );
    s
}

fn bench(c: &mut Criterion) {
    let (bytes, _) = format::gltf::to_bytes(&grid(920), &WriteOptions::default(), true);
    eprintln!("gltf_load: the .glb is {:.1} MB", bytes.len() as f64 / 1e6);
    let mut g = c.benchmark_group("gltf");
    g.sample_size(10);
    g.bench_function("load_50mb_glb", |b| {
        b.iter(|| format::load_bytes(&bytes, Path::new("grid.glb")).expect("loads"))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
