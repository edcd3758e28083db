//! The editor's side of `record`: routes events to it and applies what it returns.

use crate::anim::{Property, Target, TargetRef};
use crate::editor::command::Command;
#[allow(unused_imports)]
use crate::editor::record::*;
use crate::editor::Editor;
use crate::scene::{Node, NodeId};

impl Editor {
    /// The pending change, if it still applies.
    pub fn pending(&self) -> Option<&Pending> {
        self.pending.as_ref().filter(|p| {
            p.frame == self.frame && self.scene.nodes.get(p.id.0 as usize) == Some(&*p.node)
        })
    }

    /// Node `id` as shown at the current frame (a pending change included).
    pub fn posed_node(&self, id: NodeId) -> Node {
        if let Some(p) = self.pending().filter(|p| p.id == id) {
            return (*p.node).clone();
        }
        posed(&self.scene.animation, id, self.scene.node(id), self.frame)
    }

    /// The pose at `t` seconds with a pending change shown over its tracks.
    pub(in crate::internals::editor) fn evaluate_shown(&self, t: f32) -> crate::anim::Pose {
        if let Some(s) = self.rig_shown_scene() {
            return crate::anim::evaluate(&s, t);
        }
        if let Some(s) = self.material_shown_scene() {
            return crate::anim::evaluate(&s, t);
        }
        let Some(p) = self.pending() else {
            return crate::anim::evaluate(&self.scene, t);
        };
        let mut s = self.scene.clone();
        for &prop in &p.props {
            s.animation.remove_tracks(Target {
                of: TargetRef::Node(p.id),
                property: prop,
            });
        }
        crate::anim::evaluate(&s, t)
    }

    /// Turns a node change into what is recorded: in record mode the change
    /// plus keys at the current frame for `props`, as one command. The
    /// change's `before` becomes the node as stored (not as posed), so undo
    /// restores exactly what was there.
    pub(in crate::internals::editor) fn recorded(
        &mut self,
        c: Command,
        props: &[Property],
    ) -> Command {
        let Command::SetNode { id, after, .. } = c else {
            return c;
        };
        let before = Box::new(self.scene.node(id).clone());
        let set = Command::SetNode {
            id,
            before,
            after: after.clone(),
        };
        let animated: Vec<Property> = props
            .iter()
            .copied()
            .filter(|&p| self.is_animated(id, p))
            .collect();
        if !self.record {
            if !animated.is_empty() {
                self.pending = Some(Pending {
                    id,
                    props: animated,
                    frame: self.frame,
                    node: after,
                });
                self.set_status("Pending: K keys it, new frame drops it", false);
            }
            return set;
        }
        match with_keys(&self.scene.animation, id, &after, props, self.frame) {
            Ok(anim) => Command::Group(vec![
                set,
                Command::SetAnimation {
                    before: Box::new(self.scene.animation.clone()),
                    after: Box::new(anim),
                },
            ]),
            Err(e) => {
                self.set_status(&e, true);
                set
            }
        }
    }

    /// Whether a track drives property `p` of node `id`.
    pub fn is_animated(&self, id: NodeId, p: Property) -> bool {
        self.scene
            .animation
            .track(Target {
                of: TargetRef::Node(id),
                property: p,
            })
            .is_some()
    }

    /// K: keys the selection's changed properties at the current frame
    /// with the values shown. "Changed" is the pending change on animated
    /// properties; with nothing pending, K keys the whole transform
    /// (objects) or all light fields (lights), as Blender's default keying
    /// set does.
    pub(in crate::internals::editor) fn insert_keys(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status("Select something to key (K)", false);
            return;
        };
        if self.key_ik() || self.key_morph() || self.key_material() {
            return;
        }
        let n = self.posed_node(sel);
        let props = match self.pending().filter(|p| p.id == sel) {
            Some(p) => p.props.clone(),
            None => keyable(&n),
        };
        match with_keys(&self.scene.animation, sel, &n, &props, self.frame) {
            Ok(after) => {
                let before = Box::new(self.scene.animation.clone());
                self.pending = None;
                self.stop_playback();
                let name = crate::editor::ops::display_name(&self.scene, sel);
                self.execute(
                    &format!("Key {name}"),
                    Command::SetAnimation {
                        before,
                        after: Box::new(after),
                    },
                );
                let f = crate::editor::fields::format_number(self.frame);
                self.set_status(&format!("Keyed {name} at frame {f}"), false);
            }
            Err(e) => self.set_status(&e, true),
        }
    }

    /// Up / Down: the next (`dir` > 0) or previous key of the selection
    /// (of any track with nothing selected).
    pub(in crate::internals::editor) fn jump_key(&mut self, dir: i32) {
        let frames = key_frames(&self.scene.animation, self.selection);
        let eps = crate::anim::KEY_EPS;
        let f = self.frame;
        let next = if dir > 0 {
            frames.iter().copied().find(|&k| k > f + eps)
        } else {
            frames.iter().rev().copied().find(|&k| k < f - eps)
        };
        match next {
            Some(k) => {
                self.stop_playback();
                self.frame = k.clamp(0.0, self.scene.settings.duration);
            }
            None => self.set_status("No more keys that way", false),
        }
    }
}
