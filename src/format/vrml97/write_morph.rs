//! Deforming shapes in VRML97 (morph targets, skins): VRML97 has neither,
//! so the writer plays the deformation as a CoordinateInterpolator (and a
//! NormalInterpolator) driving the shape's DEF'd Coordinate and Normal.
//! Both are sampled from the evaluated poses: every frame (and every key)
//! is a candidate, and keys are kept so that linear interpolation between
//! them stays within the position tolerance for every vertex (the same rule
//! `export::sampling` uses for positions).

use crate::anim::{evaluate_into, Interp, Keys, Pose, Property, Repeat, TargetRef};
use crate::scene::{MeshId, NodeId, NodeKind, Scene};
use glam::{Mat3, Vec3};

/// Most candidate times tried per shape (long animations are strided).
const MAX_CANDIDATES: usize = 600;
/// Bound on candidates² × vertices, the worst cost of the key selection.
const WORK_BUDGET: f64 = 2e8;

/// A shape the writer animates vertex by vertex: its node and mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deforming {
    pub node: NodeId,
    pub mesh: MeshId,
}

/// Shapes whose mesh is morphed or skinned, in an animated scene, when the
/// mesh is drawn by that one shape only (a shared mesh cannot carry one
/// shape's deformation). The others are returned as warnings.
pub fn deforming(scene: &Scene) -> (Vec<Deforming>, Vec<String>) {
    let mut out = Vec::new();
    let mut warnings = Vec::new();
    if scene.animation.tracks.is_empty() {
        return (out, warnings);
    }
    for (i, node) in scene.nodes.iter().enumerate() {
        let NodeKind::Shape(s) = &node.kind else {
            continue;
        };
        let Some(mesh) = scene.meshes.get(s.mesh.0 as usize) else {
            continue;
        };
        if !mesh.deforms() || mesh.triangles.is_empty() {
            continue;
        }
        let users = scene
            .nodes
            .iter()
            .filter(|n| matches!(&n.kind, NodeKind::Shape(t) if t.mesh == s.mesh))
            .count();
        if users > 1 {
            warnings.push(format!(
                "mesh {} is morphed or skinned but drawn by {users} shapes: written undeformed",
                s.mesh.0
            ));
            continue;
        }
        out.push(Deforming {
            node: NodeId(i as u32),
            mesh: s.mesh,
        });
    }
    (out, warnings)
}

/// Sampled deformation of one shape: key frames and, per key, the vertex
/// positions and normals in the shape's own space (what its Coordinate and
/// Normal hold).
pub struct Sampled {
    pub frames: Vec<f32>,
    pub positions: Vec<Vec<Vec3>>,
    pub normals: Vec<Vec<Vec3>>,
    /// Candidate times looked at.
    pub candidates: usize,
}

/// The shape's vertices at `frame`, in its own space.
fn local_at(scene: &Scene, d: Deforming, frame: f32, pose: &mut Pose) -> (Vec<Vec3>, Vec<Vec3>) {
    let fps = scene.settings.fps.max(1e-6);
    evaluate_into(scene, frame / fps, pose);
    let mesh = &scene.meshes[d.mesh.0 as usize];
    let Some(def) = pose.deformed(d.node) else {
        return (mesh.positions.clone(), mesh.normals.clone());
    };
    if !def.world_space {
        return (def.positions.clone(), def.normals.clone());
    }
    // Skinned: world space back into the shape's space.
    let world = pose
        .world
        .get(d.node.0 as usize)
        .copied()
        .unwrap_or_default();
    let inv = world.inverse();
    let to_local_n = Mat3::from_mat4(world).transpose();
    (
        def.positions
            .iter()
            .map(|p| inv.transform_point3(*p))
            .collect(),
        def.normals
            .iter()
            .map(|n| (to_local_n * *n).normalize_or_zero())
            .collect(),
    )
}

/// The frames at which shape `d`'s vertices are exactly piecewise linear
/// in time, when they are: a morph (not a skin) whose weights tracks all
/// have linear keys without ease, inside [0, duration] (holding, or keyed
/// at both ends when looping). Positions are affine in the weights, so
/// keying every weights key reproduces the deformation exactly — and a
/// morph read from a CoordinateInterpolator is written back with its own
/// keys (the key note's weights then fit the targets read back).
fn exact_frames(scene: &Scene, d: Deforming) -> Option<Vec<f32>> {
    if scene.node(d.node).skin.is_some() {
        return None;
    }
    let duration = scene.settings.duration.max(0.0);
    // A weights track on the shape, or on a group above it, drives it.
    let drives = |of: TargetRef| {
        let TargetRef::Node(at) = of else {
            return false;
        };
        let mut on = Some(d.node);
        while let Some(n) = on {
            if n == at {
                return true;
            }
            on = scene.node(n).parent;
        }
        false
    };
    let mut frames = vec![0.0, duration];
    let mut any = false;
    for t in &scene.animation.tracks {
        if t.target.property != Property::MorphWeights || !drives(t.target.of) {
            continue;
        }
        let Keys::Weights(keys) = &t.keys else {
            return None;
        };
        let (first, last) = (keys.first()?.frame, keys.last()?.frame);
        let inside = first >= 0.0 && last <= duration;
        let ends_keyed = first == 0.0 && last == duration;
        let linear = keys[..keys.len() - 1]
            .iter()
            .all(|k| k.interp == Interp::Linear && k.ease_in == 0.0 && k.ease_out == 0.0);
        if !inside || !linear || (t.repeat != Repeat::Constant && !ends_keyed) {
            return None;
        }
        frames.extend(keys.iter().map(|k| k.frame));
        any = true;
    }
    if !any {
        return None;
    }
    frames.sort_by(f32::total_cmp);
    frames.dedup();
    (frames.len() <= MAX_CANDIDATES).then_some(frames)
}

/// Samples shape `d` over the scene's duration within `tolerance` (a
/// distance in the shape's space); exactly at its weights keys when those
/// say everything (see [`exact_frames`]).
pub fn sample(scene: &Scene, d: Deforming, tolerance: f32) -> Sampled {
    if let Some(frames) = exact_frames(scene, d) {
        let mut pose = Pose::default();
        let (positions, normals) = frames
            .iter()
            .map(|&f| local_at(scene, d, f, &mut pose))
            .unzip();
        return Sampled {
            candidates: frames.len(),
            frames,
            positions,
            normals,
        };
    }
    let duration = scene.settings.duration.max(0.0);
    let mut frames: Vec<f32> = (0..=duration.ceil() as usize).map(|f| f as f32).collect();
    for t in &scene.animation.tracks {
        frames.extend(
            t.keys
                .frames()
                .into_iter()
                .filter(|f| (0.0..=duration).contains(f)),
        );
    }
    frames.retain(|f| *f <= duration);
    frames.push(duration);
    frames.sort_by(f32::total_cmp);
    frames.dedup_by(|a, b| (*a - *b).abs() < 1e-4);
    let vertices = scene.meshes[d.mesh.0 as usize].positions.len().max(1);
    let most = ((WORK_BUDGET / vertices as f64).sqrt() as usize).clamp(8, MAX_CANDIDATES);
    if frames.len() > most {
        let step = frames.len() as f32 / most as f32;
        let mut picked: Vec<f32> = (0..most)
            .map(|i| frames[(i as f32 * step) as usize])
            .collect();
        picked.push(duration);
        picked.dedup();
        frames = picked;
    }
    let mut pose = Pose::default();
    let at: Vec<(Vec<Vec3>, Vec<Vec3>)> = frames
        .iter()
        .map(|&f| local_at(scene, d, f, &mut pose))
        .collect();
    // Greedy: from each kept key, go as far as linear interpolation holds
    // every skipped candidate within the tolerance.
    let fits = |i: usize, j: usize| -> bool {
        (i + 1..j).all(|k| {
            let s = (frames[k] - frames[i]) / (frames[j] - frames[i]);
            at[i]
                .0
                .iter()
                .zip(&at[j].0)
                .zip(&at[k].0)
                .all(|((a, b), c)| (a.lerp(*b, s) - *c).length() <= tolerance)
        })
    };
    let mut keep = vec![0usize];
    let mut i = 0;
    while i + 1 < frames.len() {
        let mut j = i + 1;
        while j + 1 < frames.len() && fits(i, j + 1) {
            j += 1;
        }
        keep.push(j);
        i = j;
    }
    let candidates = frames.len();
    let mut out = Sampled {
        frames: Vec::with_capacity(keep.len()),
        positions: Vec::with_capacity(keep.len()),
        normals: Vec::with_capacity(keep.len()),
        candidates,
    };
    let mut at = at;
    for &k in &keep {
        out.frames.push(frames[k]);
        let (p, n) = std::mem::take(&mut at[k]);
        out.positions.push(p);
        out.normals.push(n);
    }
    out
}
