//! The two-bone IK handle (issue 13 item 7): select an end joint (a
//! wrist, an ankle), press I, and drag the yellow target at the joint: its
//! parent and grandparent turn so the joint follows the mouse (in the
//! plane facing the viewer through the joint), bending the way the chain
//! is bent already (`anim::ik` solves it by the law of cosines).
//!
//! What a drag leaves follows the rotate handle: in record mode both
//! joints' rotations are keyed at the current frame — baked to FK keys,
//! together with the joint changes ONE undo step; without record mode
//! unanimated joints simply take the new rotations (one step), and
//! animated ones keep the pose pending (shown until the frame changes)
//! until K keys both. While dragging, the pose is shown the same pending
//! way, over the joints' tracks.

use crate::anim::ik::{self, Chain};
use crate::anim::{Property, Target, TargetRef};
use crate::editor::command::Command;
use crate::editor::gesture::Drag;
use crate::editor::manip::geom::{pixel_ray, ray_plane};
use crate::editor::record::with_keys;
use crate::editor::Editor;
use crate::scene::{Node, NodeId, Scene};
use crate::ui::{Painter, Rect};
use glam::{Quat, Vec3};

pub use super::state::{IkDrag, IkPending};

/// The target's colour (the IK handle).
const IK: u32 = 0xf0d040;
/// How close (pixels) a press must be to the end joint to grab the target.
const GRAB_PX: f32 = 9.0;

/// The rotation part of a world matrix (scale and shear ignored).
fn world_rotation(pose: &crate::anim::Pose, id: Option<NodeId>) -> Quat {
    id.and_then(|i| pose.world.get(i.0 as usize))
        .map_or(Quat::IDENTITY, |m| {
            let (_, r, _) = m.to_scale_rotation_translation();
            r.normalize()
        })
}

/// `local` turned by the world rotation `turn` about its own pivot, for a
/// node whose parent's world rotation is `parent`: P⁻¹·Δ·P·L (exact for
/// parents without non-uniform scale).
fn turned_local(parent: Quat, turn: Quat, local: Quat) -> Quat {
    (parent.inverse() * turn * parent * local).normalize()
}

impl Editor {
    /// The chain (grandparent, parent) above `end`, when it has both.
    fn ik_chain(&self, end: NodeId) -> Option<(NodeId, NodeId)> {
        let mid = self.scene.node(end).parent?;
        let root = self.scene.node(mid).parent?;
        Some((root, mid))
    }

    /// I: turns the IK handle on for the selected joint (or off).
    pub(in crate::internals::editor) fn toggle_ik(&mut self) {
        if self.rig.ik.is_some() {
            self.rig.ik = None;
            self.set_status("IK handle off", false);
            return;
        }
        let Some(end) = self.selection else {
            self.set_status(
                "Select the end joint of a chain (a hand, a foot) for IK",
                false,
            );
            return;
        };
        let Some((root, mid)) = self.ik_chain(end) else {
            self.set_status("IK needs a joint with a parent and a grandparent", true);
            return;
        };
        self.rig.ik = Some(end);
        let name = |id| crate::editor::ops::display_name(&self.scene, id);
        let msg = format!(
            "IK: drag the yellow target to turn {} and {} (I: off)",
            name(root),
            name(mid)
        );
        self.set_status(&msg, false);
    }

    /// The joint whose IK target shows (IK on and that joint selected).
    pub fn ik_end(&self) -> Option<NodeId> {
        self.rig
            .ik
            .filter(|&e| self.selection == Some(e) && (e.0 as usize) < self.scene.nodes.len())
    }

    /// Mouse down in the viewport: grabs the IK target when it is under
    /// the mouse. True when taken.
    pub(in crate::internals::editor) fn ik_press(&mut self, x: f32, y: f32) -> bool {
        let Some(end) = self.ik_end() else {
            return false;
        };
        let Some((root, mid)) = self.ik_chain(end) else {
            return false;
        };
        let pose = self.pose().clone();
        let at = |id| super::bones::pivot(&self.scene, &pose, id);
        let chain = Chain {
            root: at(root),
            mid: at(mid),
            end: at(end),
        };
        let proj = self.projector();
        let Some(p) = proj.point(chain.end) else {
            return false;
        };
        if (p.0 - x).hypot(p.1 - y) > GRAB_PX {
            return false;
        }
        let inv = proj.view.inverse();
        let forward = (-inv.z_axis.truncate()).normalize_or_zero();
        let up = inv.y_axis.truncate();
        let upper = chain.mid - chain.root;
        let line = (chain.end - chain.root).normalize_or_zero();
        let bend = upper - upper.dot(line) * line;
        let pole = if bend.length() > 1e-6 * upper.length().max(1e-6) {
            bend
        } else {
            up
        };
        let parent = self.scene.node(root).parent;
        self.drag = Drag::Ik(Box::new(IkDrag {
            root,
            mid,
            chain,
            pole,
            plane: (chain.end, forward),
            posed: [self.posed_node(root), self.posed_node(mid)],
            parent_rot: world_rotation(&pose, parent),
            root_rot: world_rotation(&pose, Some(root)),
            target: chain.end,
        }));
        self.stop_playback();
        true
    }

    /// The two joints' new local rotations for the target `t`.
    fn ik_solve(d: &IkDrag, t: Vec3) -> Option<[Node; 2]> {
        let s = ik::solve(d.chain, t, d.pole)?;
        let mut root = d.posed[0].clone();
        let mut mid = d.posed[1].clone();
        root.transform.rotation = turned_local(d.parent_rot, s.root_turn, root.transform.rotation);
        let root_after = (s.root_turn * d.root_rot).normalize();
        mid.transform.rotation = turned_local(root_after, s.mid_turn, mid.transform.rotation);
        Some([root, mid])
    }

    /// Mouse move during an IK drag: solves and shows. `None` when no IK
    /// drag runs.
    pub(in crate::internals::editor) fn ik_move(&mut self, x: f32, y: f32) -> Option<bool> {
        let Drag::Ik(d) = &self.drag else {
            return None;
        };
        let mut d = d.clone();
        let proj = self.projector();
        let (ro, rd) = pixel_ray(&proj, x, y);
        let Some(t) = ray_plane(d.plane.0, d.plane.1, ro, rd) else {
            return Some(false);
        };
        d.target = t;
        if let Some([root, mid]) = Self::ik_solve(&d, t) {
            self.rig.ik_pending = Some(IkPending {
                joints: [(d.root, root), (d.mid, mid)],
                frame: self.frame,
                revision: self.history.revision(),
            });
            self.pending = None;
            self.scene_rev += 1;
        }
        self.drag = Drag::Ik(d);
        Some(true)
    }

    /// Mouse up: ends an IK drag as described in the module doc. False
    /// when no IK drag ran.
    pub(in crate::internals::editor) fn ik_release(&mut self) -> bool {
        if self.drag.take_ik().is_none() {
            return false;
        }
        let Some(p) = self.ik_pending().cloned() else {
            return true;
        };
        let animated = p
            .joints
            .iter()
            .any(|(id, _)| self.is_animated(*id, Property::Rotation));
        if !self.record && animated {
            self.set_status(
                "IK pose pending: K keys both joints, a new frame drops it",
                false,
            );
            return true;
        }
        self.bake_ik(&p, "IK");
        true
    }

    /// The pending IK pose, if it still applies.
    pub fn ik_pending(&self) -> Option<&IkPending> {
        self.rig
            .ik_pending
            .as_ref()
            .filter(|p| p.frame == self.frame && p.revision == self.history.revision())
    }

    /// Records the IK pose: both joints' new rotations, plus (record mode
    /// or `key`) rotation keys for both at the current frame — one step.
    fn bake_ik(&mut self, p: &IkPending, verb: &str) {
        let key = self.record || verb == "Key IK";
        let mut steps = Vec::new();
        let mut anim = self.scene.animation.clone();
        for (id, node) in &p.joints {
            steps.push(Command::SetNode {
                id: *id,
                before: Box::new(self.scene.node(*id).clone()),
                after: Box::new(node.clone()),
            });
            if key {
                match with_keys(&anim, *id, node, &[Property::Rotation], self.frame) {
                    Ok(a) => anim = a,
                    Err(e) => {
                        self.set_status(&e, true);
                        return;
                    }
                }
            }
        }
        if key {
            steps.push(Command::SetAnimation {
                before: Box::new(self.scene.animation.clone()),
                after: Box::new(anim),
            });
        }
        self.rig.ik_pending = None;
        self.scene_rev += 1;
        let name = |id| crate::editor::ops::display_name(&self.scene, id);
        let label = format!("{verb} {} + {}", name(p.joints[0].0), name(p.joints[1].0));
        self.execute(&label, Command::Group(steps));
        let f = crate::editor::fields::format_number(self.frame);
        let msg = if key {
            format!("{label}: rotations keyed at frame {f}")
        } else {
            label
        };
        self.set_status(&msg, false);
    }

    /// K with a pending IK pose: keys both joints. False when none pends.
    pub(in crate::internals::editor) fn key_ik(&mut self) -> bool {
        let Some(p) = self.ik_pending().cloned() else {
            return false;
        };
        self.stop_playback();
        self.bake_ik(&p, "Key IK");
        true
    }

    /// `scene` as shown with a pending IK pose: the two joints' rotation
    /// tracks set aside and their nodes holding the new rotations.
    pub(in crate::internals::editor) fn ik_shown(&self, scene: &mut Scene) -> bool {
        let Some(p) = self.ik_pending() else {
            return false;
        };
        for (id, node) in &p.joints {
            scene.animation.remove_tracks(Target {
                of: TargetRef::Node(*id),
                property: Property::Rotation,
            });
            if let Some(slot) = scene.nodes.get_mut(id.0 as usize) {
                slot.transform = node.transform;
            }
        }
        true
    }

    /// The IK handle: the chain in yellow and a diamond at the target.
    pub(in crate::internals::editor) fn draw_ik(&mut self, p: &mut Painter, vp: Rect) {
        let Some(end) = self.ik_end() else {
            return;
        };
        let Some((root, mid)) = self.ik_chain(end) else {
            return;
        };
        let pose = self.pose().clone();
        let at = |id| super::bones::pivot(&self.scene, &pose, id);
        let pts = [at(root), at(mid), at(end)];
        let proj = self.projector();
        p.set_clip(Some(vp));
        for w in pts.windows(2) {
            if let Some((a, b)) = proj.segment(w[0], w[1]) {
                p.line(a, b, IK, 1.5);
            }
        }
        let target = match &self.drag {
            Drag::Ik(d) => d.target,
            _ => pts[2],
        };
        if let Some((x, y)) = proj.point(target) {
            let r = 6.0;
            p.fill_polygon(&[(x, y - r), (x + r, y), (x, y + r), (x - r, y)], IK, 220);
        }
        p.set_clip(None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_turn_in_world_space_becomes_the_local_one() {
        // Parent turned 90° about y: a world turn about z is a local turn
        // about the parent's local axis that maps to world z, i.e. −x.
        let parent = Quat::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let turn = Quat::from_rotation_z(0.3);
        let local = turned_local(parent, turn, Quat::IDENTITY);
        let want = Quat::from_rotation_x(-0.3);
        // (angle_between is an acos: about 3e-4 of noise near zero.)
        assert!(local.angle_between(want) < 1e-3, "{local:?}");
        // And back: parent · local = turn · parent.
        assert!((parent * local).angle_between(turn * parent) < 1e-3);
    }
}
