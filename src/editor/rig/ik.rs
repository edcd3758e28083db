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
//!
//! The drag itself is the viewport component's (`viewport_ui.rs`, with
//! the pure `ik_drag.rs`); here the editor builds what it sees
//! ([`IkCtx`]) and applies what it returns (`show_ik`, `ik_released`).

use crate::anim::ik::Chain;
use crate::anim::{Property, Target, TargetRef};
use crate::editor::command::Command;
use crate::editor::record::with_keys;
use crate::editor::viewport_ui::IkCtx;
use crate::editor::Editor;
use crate::scene::{NodeId, Scene};
use glam::Quat;

pub use super::state::{IkDrag, IkPending};

/// The rotation part of a world matrix (scale and shear ignored).
fn world_rotation(pose: &crate::anim::Pose, id: Option<NodeId>) -> Quat {
    id.and_then(|i| pose.world.get(i.0 as usize))
        .map_or(Quat::IDENTITY, |m| {
            let (_, r, _) = m.to_scale_rotation_translation();
            r.normalize()
        })
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

    /// What the viewport sees of the IK target (`None`: IK is off or the
    /// selection is not its joint). `press`: build the drag a press would
    /// start; `drawn`: find out whether the target shows (its skeleton
    /// does), for drawing.
    pub(in crate::internals::editor) fn ik_ctx(
        &mut self,
        press: bool,
        drawn: bool,
    ) -> Option<IkCtx> {
        let end = self.ik_end()?;
        let (root, mid) = self.ik_chain(end)?;
        let pose = self.pose().clone();
        let at = |id| super::bones::pivot(&self.scene, &pose, id);
        let chain = Chain {
            root: at(root),
            mid: at(mid),
            end: at(end),
        };
        let grab = press.then(|| Box::new(self.ik_grab(root, mid, chain, &pose)));
        let drawn = drawn && !self.shown_bones().is_empty();
        Some(IkCtx {
            chain: [chain.root, chain.mid, chain.end],
            drawn,
            grab,
        })
    }

    /// The drag a press on the target starts: the chain as it is, bending
    /// the way it bends, in the plane facing the viewer through the end.
    fn ik_grab(
        &mut self,
        root: NodeId,
        mid: NodeId,
        chain: Chain,
        pose: &crate::anim::Pose,
    ) -> IkDrag {
        let proj = self.projector();
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
        IkDrag {
            root,
            mid,
            chain,
            pole,
            plane: (chain.end, forward),
            posed: [self.posed_node(root), self.posed_node(mid)],
            parent_rot: world_rotation(pose, parent),
            root_rot: world_rotation(pose, Some(root)),
            target: chain.end,
        }
    }

    /// An IK drag moved: shows the two joints posed so, pending over
    /// their tracks.
    pub(in crate::internals::editor) fn show_ik(
        &mut self,
        joints: [(NodeId, crate::scene::Node); 2],
    ) {
        self.rig.ik_pending = Some(IkPending {
            joints,
            frame: self.frame,
            revision: self.history.revision(),
        });
        self.pending = None;
        self.scene_rev += 1;
    }

    /// The IK drag ended, as described in the module doc.
    pub(in crate::internals::editor) fn ik_released(&mut self) {
        let Some(p) = self.ik_pending().cloned() else {
            return;
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
            return;
        }
        self.bake_ik(&p, "IK");
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
}
