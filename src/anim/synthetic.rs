//! Synthetic tracks and scenes for benchmarks (`benches/anim.rs`,
//! `animed bench`): deterministic pseudo-random keys, no I/O.

use super::{Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track};
use crate::scene::{Node, NodeId, Scene};
use glam::{Quat, Vec3};
use std::hint::black_box;
use std::time::Instant;

/// A small deterministic generator (64-bit LCG, Knuth's MMIX constants).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        // Top 24 bits → [0, 1).
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

fn frames(rng: &mut Lcg, keys: usize) -> Vec<f32> {
    let mut f = 0.0;
    (0..keys)
        .map(|_| {
            let now = f;
            f += rng.range(4.0, 16.0);
            now
        })
        .collect()
}

fn tcb<V>(k: Key<V>, rng: &mut Lcg) -> Key<V> {
    k.with_tcb(
        rng.range(-0.5, 0.5),
        rng.range(-0.5, 0.5),
        rng.range(-0.5, 0.5),
    )
}

/// A TCB translation track on `node` with `keys` unevenly spaced keys.
pub fn vec3_track(node: u32, keys: usize, seed: u64) -> Track {
    let mut rng = Lcg(seed);
    let ks = frames(&mut rng, keys.max(1))
        .into_iter()
        .map(|f| {
            let v = Vec3::new(
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
            );
            tcb(Key::new(f, v), &mut rng)
        })
        .collect();
    Track {
        target: Target {
            of: TargetRef::Node(NodeId(node)),
            property: Property::Translation,
        },
        repeat: Repeat::Loop,
        keys: Keys::Vec3(ks),
    }
}

/// A squad-TCB rotation track on `node` with `keys` unevenly spaced keys.
pub fn squad_track(node: u32, keys: usize, seed: u64) -> Track {
    let mut rng = Lcg(seed ^ 0x9e37_79b9);
    let ks = frames(&mut rng, keys.max(1))
        .into_iter()
        .map(|f| {
            let axis = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0).normalize();
            let q = Quat::from_axis_angle(axis, rng.range(-3.0, 3.0));
            tcb(Key::new(f, q).with_interp(Interp::Tcb), &mut rng)
        })
        .collect();
    Track {
        target: Target {
            of: TargetRef::Node(NodeId(node)),
            property: Property::Rotation,
        },
        repeat: Repeat::Loop,
        keys: Keys::Rotation(ks),
    }
}

/// A flat scene of `nodes` groups, each with a TCB translation and a squad
/// rotation track of `keys` keys (2·nodes tracks).
pub fn scene(nodes: usize, keys: usize) -> Scene {
    let mut s = Scene::new();
    let root = s.add_node(None, Node::group("root"));
    for i in 0..nodes {
        let id = s.add_node(Some(root), Node::group(format!("n{i}")));
        s.animation.tracks.push(vec3_track(id.0, keys, i as u64));
        s.animation.tracks.push(squad_track(id.0, keys, i as u64));
    }
    s
}

/// Animation speed on this machine (for `animed bench`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnimBench {
    /// Tracks per kind sampled.
    pub tracks: usize,
    /// TCB Vec3 samples per second.
    pub vec3_samples_per_s: f64,
    /// Squad-TCB rotation samples per second.
    pub squad_samples_per_s: f64,
    /// Milliseconds for one `evaluate_into` of a scene with `tracks` nodes
    /// (2·tracks tracks).
    pub evaluate_ms: f64,
}

/// Samples `tracks` at frames spread over their range until `min_secs` has
/// passed; returns samples per second.
fn rate(tracks: &[Track], min_secs: f64) -> f64 {
    let start = Instant::now();
    let mut samples = 0u64;
    let mut round = 0u32;
    loop {
        for (i, t) in tracks.iter().enumerate() {
            // A different frame per track and round, stepping through the loop.
            let f = ((i as u32).wrapping_mul(7) + round * 13) as f32 * 0.37;
            black_box(t.sample(black_box(f)));
        }
        samples += tracks.len() as u64;
        round += 1;
        let secs = start.elapsed().as_secs_f64();
        if secs >= min_secs {
            return samples as f64 / secs;
        }
    }
}

/// Measures sampling and whole-scene evaluation with `n` tracks of each
/// kind (8 keys each), spending about `min_secs` on each figure.
pub fn bench_tracks(n: usize, min_secs: f64) -> AnimBench {
    let n = n.max(1);
    let v: Vec<Track> = (0..n).map(|i| vec3_track(i as u32, 8, i as u64)).collect();
    let q: Vec<Track> = (0..n).map(|i| squad_track(i as u32, 8, i as u64)).collect();
    let vec3_samples_per_s = rate(&v, min_secs);
    let squad_samples_per_s = rate(&q, min_secs);

    let scene = scene(n, 8);
    let mut pose = super::Pose::default();
    let start = Instant::now();
    let mut runs = 0u32;
    while runs == 0 || start.elapsed().as_secs_f64() < min_secs {
        super::evaluate_into(&scene, black_box(runs as f32 * 0.04), &mut pose);
        black_box(&pose);
        runs += 1;
    }
    let evaluate_ms = start.elapsed().as_secs_f64() * 1000.0 / runs as f64;
    AnimBench {
        tracks: n,
        vec3_samples_per_s,
        squad_samples_per_s,
        evaluate_ms,
    }
}

impl AnimBench {
    /// Human-readable lines for `animed bench`.
    pub fn lines(&self) -> Vec<String> {
        vec![
            format!(
                "TCB vec3 tracks ({} × 8 keys): {:.2} M samples/s",
                self.tracks,
                self.vec3_samples_per_s / 1e6
            ),
            format!(
                "squad-TCB rotation tracks ({} × 8 keys): {:.2} M samples/s",
                self.tracks,
                self.squad_samples_per_s / 1e6
            ),
            format!(
                "evaluate scene ({} nodes, {} tracks): {:.3} ms",
                self.tracks,
                2 * self.tracks,
                self.evaluate_ms
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn synthetic_tracks_are_valid() {
        for i in 0..20 {
            vec3_track(i, 8, i as u64).validate().expect("vec3 track");
            squad_track(i, 8, i as u64).validate().expect("squad track");
        }
        let s = scene(3, 5);
        assert_eq!(s.animation.tracks.len(), 6);
        assert_eq!(s.nodes.len(), 4);
    }

    #[test]
    fn bench_reports_positive_figures() {
        let b = bench_tracks(10, 0.001);
        assert!(b.vec3_samples_per_s > 0.0 && b.squad_samples_per_s > 0.0);
        assert!(b.evaluate_ms > 0.0);
        assert_eq!(b.lines().len(), 3);
        assert!(b.lines()[2].contains("20 tracks"));
    }
}
