//! The selected object's motion path: its world position at every frame
//! of the scene as a polyline with a dot per frame, a larger marker per
//! key, and the key under the current frame highlighted.
//!
//! Positions come from the node's ancestor chain posed per frame (only
//! the tracks on that chain are sampled, not the whole scene).

use super::record::{key_frames, posed};
use super::Editor;
use crate::anim::{Animation, KEY_EPS};
use crate::scene::{NodeId, NodeKind, Scene};
use crate::ui::Painter;
use glam::{Mat4, Vec3};

/// Most frames sampled for one path (longer scenes are sampled sparser).
const MAX_SAMPLES: usize = 2000;
const PATH: u32 = 0xe8c04c;
const KEY: u32 = 0xffffff;
const KEY_NOW: u32 = 0xff9a1f;

/// World matrix of `id` at `frame` from its posed ancestor chain.
pub fn world_at(scene: &Scene, anim: &Animation, id: NodeId, frame: f32) -> Mat4 {
    let mut m = Mat4::IDENTITY;
    let mut cur = Some(id);
    let mut guard = 0;
    while let Some(n) = cur {
        let Some(node) = scene.nodes.get(n.0 as usize) else {
            break;
        };
        m = posed(anim, n, node, frame).transform.matrix() * m;
        cur = node.parent;
        guard += 1;
        if guard > scene.nodes.len() {
            break; // a cycle would be a bug elsewhere; never loop forever
        }
    }
    m
}

/// The point of `id` that moves: a light's location, else the origin.
fn local_point(scene: &Scene, anim: &Animation, id: NodeId, frame: f32) -> Vec3 {
    match &posed(anim, id, scene.node(id), frame).kind {
        NodeKind::Light(l) => l.location,
        _ => Vec3::ZERO,
    }
}

/// Frames sampled for a path over `0..=duration` (every frame when short).
pub fn sample_frames(duration: f32) -> Vec<f32> {
    let d = duration.max(0.0);
    let n = (d.floor() as usize + 1).min(MAX_SAMPLES);
    if n <= 1 {
        return vec![0.0];
    }
    (0..n).map(|i| d * i as f32 / (n - 1) as f32).collect()
}

/// World positions of `id` at `frames`.
pub fn path(scene: &Scene, id: NodeId, frames: &[f32]) -> Vec<Vec3> {
    let anim = &scene.animation;
    frames
        .iter()
        .map(|&f| world_at(scene, anim, id, f).transform_point3(local_point(scene, anim, id, f)))
        .collect()
}

/// Whether a path drawn at these screen points goes anywhere: it spans
/// at least [`TRAVEL_PX`] pixels.
fn travels(pts: &[(f32, f32)]) -> bool {
    let Some(&(x0, y0)) = pts.first() else {
        return false;
    };
    pts.iter()
        .any(|&(x, y)| (x - x0).abs() >= TRAVEL_PX || (y - y0).abs() >= TRAVEL_PX)
}

/// Smallest on-screen travel that gets a path drawn.
const TRAVEL_PX: f32 = 4.0;

impl Editor {
    /// Draws the selection's motion path when it (or an ancestor) is animated.
    pub(super) fn draw_motion_path(&mut self, p: &mut Painter) {
        let Some(id) = self.selection else { return };
        let chain_animated = {
            let mut cur = Some(id);
            let mut any = false;
            let mut guard = 0;
            while let Some(n) = cur {
                any |= self
                    .scene
                    .animation
                    .tracks_of(crate::anim::TargetRef::Node(n))
                    .next()
                    .is_some();
                cur = self.scene.nodes.get(n.0 as usize).and_then(|x| x.parent);
                guard += 1;
                if guard > self.scene.nodes.len() {
                    break;
                }
            }
            any
        };
        if !chain_animated {
            return;
        }
        let frames = sample_frames(self.scene.settings.duration);
        let pts = path(&self.scene, id, &frames);
        let keys = key_frames(&self.scene.animation, Some(id));
        let key_pts = path(&self.scene, id, &keys);
        let proj = self.projector();
        let on_screen: Vec<(f32, f32)> = pts.iter().filter_map(|&q| proj.point(q)).collect();
        if !travels(&on_screen) {
            // Keys that only turn or scale it (the Spinner): a path of one
            // point would sit on the object and hide it.
            return;
        }
        p.set_clip(Some(self.layout().viewport));
        for w in pts.windows(2) {
            if let Some((a, b)) = proj.segment(w[0], w[1]) {
                p.line(a, b, PATH, 1.0);
            }
        }
        for &q in &pts {
            if let Some(c) = proj.point(q) {
                p.fill_circle(c, 1.5, PATH);
            }
        }
        for (&f, &q) in keys.iter().zip(&key_pts) {
            if let Some(c) = proj.point(q) {
                let now = (f - self.frame).abs() <= KEY_EPS;
                let color = if now { KEY_NOW } else { KEY };
                let r = if now { 5.0 } else { 4.0 };
                crate::ui::widgets::diamond(p, c, r, color);
            }
        }
        p.set_clip(None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Property, Target, TargetRef, Value};
    use crate::scene::{Node, Transform};

    #[test]
    fn path_follows_parent_and_own_keys() {
        let mut s = Scene::new();
        let parent = s.add_node(
            None,
            Node::group("p").with_transform(Transform::from_translation(Vec3::new(0.0, 2.0, 0.0))),
        );
        let child = s.add_node(Some(parent), Node::group("c"));
        let t = Target {
            of: TargetRef::Node(child),
            property: Property::Translation,
        };
        s.animation
            .set_key(t, 0.0, Value::Vec3(Vec3::ZERO))
            .unwrap();
        s.animation
            .set_key(t, 10.0, Value::Vec3(Vec3::new(4.0, 0.0, 0.0)))
            .unwrap();
        let pts = path(&s, child, &[0.0, 5.0, 10.0]);
        assert!((pts[0] - Vec3::new(0.0, 2.0, 0.0)).length() < 1e-5);
        assert!((pts[1] - Vec3::new(2.0, 2.0, 0.0)).length() < 1e-4);
        assert!((pts[2] - Vec3::new(4.0, 2.0, 0.0)).length() < 1e-5);
    }

    #[test]
    fn a_path_that_stays_in_place_is_not_drawn() {
        assert!(!travels(&[]));
        assert!(!travels(&[(10.0, 10.0), (11.5, 12.0), (9.0, 13.9)]));
        assert!(travels(&[(10.0, 10.0), (10.0, 14.0)]));
    }

    #[test]
    fn frames_cover_the_duration() {
        assert_eq!(sample_frames(4.0), vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        let long = sample_frames(100_000.0);
        assert_eq!(long.len(), MAX_SAMPLES);
        assert_eq!(*long.last().unwrap(), 100_000.0);
    }
}
