//! Bones of a skeleton as the viewport shows them: which skins are
//! "active" for the selection, a bone per joint pair in world space, the
//! octahedron each bone is drawn as, and picking a joint by its bone.
//!
//! A bone runs from a joint to each child joint (Blender's convention: the
//! bone belongs to the joint at its head, whose rotation swings it). A
//! joint with no child joint gets a short stub along its parent's bone so
//! it can still be seen and clicked. Joints are ordinary nodes, so their
//! world positions come straight from the pose.

use crate::anim::Pose;
use crate::editor::manip::geom::seg_dist;
use crate::input::camera::Projector;
use crate::scene::{NodeId, Scene};
use glam::Vec3;

/// A joint shown as a bone from `head` (its pivot) to `tail`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bone {
    /// The joint whose rotation swings this bone.
    pub joint: NodeId,
    pub head: Vec3,
    pub tail: Vec3,
}

/// How close (pixels) a click must be to a joint's ball or its bone.
pub const PICK_PX: f32 = 6.0;

/// Whether `anc` is `id` or one of its ancestors.
fn is_ancestor_or_self(scene: &Scene, anc: NodeId, id: NodeId) -> bool {
    let mut cur = Some(id);
    let mut guard = 0;
    while let Some(c) = cur {
        if c == anc {
            return true;
        }
        guard += 1;
        if guard > scene.nodes.len() {
            return false;
        }
        cur = scene.node(c).parent;
    }
    false
}

/// Skins whose bones the viewport shows for `selection`: those with a
/// joint or a skinned shape at or below the selected node, or with the
/// selected node among their joints. Nothing selected: none (the mesh is
/// clicked first, then its bones).
pub fn active_skins(scene: &Scene, selection: Option<NodeId>) -> Vec<usize> {
    let Some(sel) = selection else {
        return Vec::new();
    };
    if sel.0 as usize >= scene.nodes.len() {
        return Vec::new();
    }
    (0..scene.skins.len())
        .filter(|&k| {
            let joints = scene.skins[k].joints();
            let joint_hit = joints
                .iter()
                .any(|&j| j == sel || is_ancestor_or_self(scene, sel, j));
            joint_hit
                || scene.nodes.iter().enumerate().any(|(i, n)| {
                    n.skin.is_some_and(|s| s.0 as usize == k)
                        && is_ancestor_or_self(scene, sel, NodeId(i as u32))
                })
        })
        .collect()
}

/// Whether `id` is a joint of any skin.
pub fn is_joint(scene: &Scene, id: NodeId) -> bool {
    scene.skins.iter().any(|s| s.joints().contains(&id))
}

/// A joint's pivot in world space (its rotation centre).
pub fn pivot(scene: &Scene, pose: &Pose, id: NodeId) -> Vec3 {
    let c = scene.node(id).transform.center;
    pose.world
        .get(id.0 as usize)
        .map_or(Vec3::ZERO, |m| m.transform_point3(c))
}

/// The bones of skins `skins` at `pose`, one per joint → child-joint pair
/// plus a stub for each joint without a child joint.
pub fn bones(scene: &Scene, pose: &Pose, skins: &[usize]) -> Vec<Bone> {
    let mut joints: Vec<NodeId> = skins
        .iter()
        .filter_map(|&k| scene.skins.get(k))
        .flat_map(|s| s.joints().iter().copied())
        .filter(|j| (j.0 as usize) < scene.nodes.len())
        .collect();
    joints.sort();
    joints.dedup();
    let mut out = Vec::new();
    for &j in &joints {
        let head = pivot(scene, pose, j);
        let kids: Vec<NodeId> = scene
            .node(j)
            .children
            .iter()
            .copied()
            .filter(|c| joints.binary_search(c).is_ok())
            .collect();
        for &c in &kids {
            out.push(Bone {
                joint: j,
                head,
                tail: pivot(scene, pose, c),
            });
        }
        if kids.is_empty() {
            // A stub: a quarter of the parent joint's bone, continued.
            let dir = scene
                .node(j)
                .parent
                .filter(|p| joints.binary_search(p).is_ok())
                .map(|p| head - pivot(scene, pose, p))
                .filter(|d| d.length() > 1e-6);
            let tail = match dir {
                Some(d) => head + d * 0.25,
                None => head + Vec3::Y * 0.05 * bone_scale(scene, pose, &joints),
            };
            out.push(Bone {
                joint: j,
                head,
                tail,
            });
        }
    }
    out
}

/// A length typical of the skeleton (its extent), for stubs of lone joints.
fn bone_scale(scene: &Scene, pose: &Pose, joints: &[NodeId]) -> f32 {
    let pts: Vec<Vec3> = joints.iter().map(|&j| pivot(scene, pose, j)).collect();
    let (lo, hi) = pts.iter().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let d = (hi - lo).length();
    if d.is_finite() && d > 1e-6 {
        d
    } else {
        1.0
    }
}

/// The 12 edges of a bone drawn as Blender's octahedron: a square ring of
/// half-width 0.1·length at a tenth of the way from head to tail, joined
/// to both ends.
pub fn octahedron(head: Vec3, tail: Vec3) -> Vec<(Vec3, Vec3)> {
    let d = tail - head;
    let len = d.length();
    if len < 1e-9 || !len.is_finite() {
        return Vec::new();
    }
    let u = d / len;
    let (v, w) = u.any_orthonormal_pair();
    let c = head + u * (0.1 * len);
    let r = 0.1 * len;
    let ring = [c + v * r, c + w * r, c - v * r, c - w * r];
    let mut out = Vec::with_capacity(12);
    for i in 0..4 {
        out.push((head, ring[i]));
        out.push((ring[i], ring[(i + 1) % 4]));
        out.push((ring[i], tail));
    }
    out
}

/// The joint under pixel (x, y): a joint's ball (head) within
/// [`PICK_PX`] first, nearest wins; else the nearest bone within it.
pub fn pick(bones: &[Bone], proj: &Projector, x: f32, y: f32) -> Option<NodeId> {
    let mut best: Option<(f32, NodeId)> = None;
    for b in bones {
        if let Some(h) = proj.point(b.head) {
            let d = ((h.0 - x).powi(2) + (h.1 - y).powi(2)).sqrt();
            if d <= PICK_PX && best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, b.joint));
            }
        }
    }
    if let Some((_, j)) = best {
        return Some(j);
    }
    for b in bones {
        if let Some((pa, pb)) = proj.segment(b.head, b.tail) {
            let d = seg_dist((x, y), pa, pb);
            if d <= PICK_PX && best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, b.joint));
            }
        }
    }
    best.map(|(_, j)| j)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Node, Skin, Transform};

    /// Root at the origin, an arm of two 1-unit bones along +y, and a
    /// mesh-less "Body" group holding the skeleton.
    fn rig() -> (Scene, [NodeId; 4]) {
        let mut s = Scene::new();
        let body = s.add_node(None, Node::group("Body"));
        let a = s.add_node(Some(body), Node::group("Upper"));
        let mut n = Node::group("Lower");
        n.transform = Transform::from_translation(Vec3::Y);
        let b = s.add_node(Some(a), n);
        let mut n = Node::group("Hand");
        n.transform = Transform::from_translation(Vec3::Y);
        let c = s.add_node(Some(b), n);
        let skin = Skin::new("Arm", vec![a, b, c], Vec::new()).unwrap();
        s.add_skin(skin).unwrap();
        (s, [body, a, b, c])
    }

    #[test]
    fn bones_run_from_each_joint_to_its_child_with_a_stub_at_the_end() {
        let (s, [body, a, b, c]) = rig();
        let pose = crate::anim::evaluate(&s, 0.0);
        assert!(active_skins(&s, None).is_empty());
        assert_eq!(active_skins(&s, Some(body)), vec![0]);
        assert_eq!(active_skins(&s, Some(c)), vec![0]);
        let bones = bones(&s, &pose, &[0]);
        assert_eq!(bones.len(), 3);
        assert_eq!(
            (bones[0].joint, bones[0].head, bones[0].tail),
            (a, Vec3::ZERO, Vec3::Y)
        );
        assert_eq!((bones[1].joint, bones[1].tail), (b, 2.0 * Vec3::Y));
        assert_eq!(bones[2].joint, c);
        assert!((bones[2].tail - 2.25 * Vec3::Y).length() < 1e-6, "stub");
        assert!(is_joint(&s, b) && !is_joint(&s, body));
    }

    #[test]
    fn octahedron_has_twelve_edges_ending_at_head_and_tail() {
        let e = octahedron(Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0));
        assert_eq!(e.len(), 12);
        for (p, q) in &e {
            for x in [p, q] {
                let on_ring = (x.z - 0.2).abs() < 1e-6
                    && ((x.x.powi(2) + x.y.powi(2)).sqrt() - 0.2).abs() < 1e-6;
                assert!(*x == Vec3::ZERO || x.z == 2.0 || on_ring, "{x}");
            }
        }
        assert!(octahedron(Vec3::ONE, Vec3::ONE).is_empty());
    }
}
