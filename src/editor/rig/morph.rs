//! The morph panel: one slider per morph target weight of the selected
//! shape (issue 13 item 7), keyable like any field.
//!
//! A slider is a panel field (`FieldId::Morph(i)`: drag sideways or type a
//! number; a bar under the number shows the weight in 0..1, weights may
//! leave that range as M3G allows). What a change does follows the other
//! fields: in record mode it keys `NAME.weights` at the current frame
//! (one undo step); without record mode an animated weights track keeps
//! the change pending — shown until the frame changes, K keys it — and
//! an unanimated mesh takes it as its default weights (undoable).
//! While a slider is dragged the new weights are shown the same pending
//! way, so the mesh deforms live. The sliders themselves (layout, paint,
//! their press) are a component, `morph_ui.rs`; this file applies what
//! they ask for.

use crate::anim::{Animation, Property, Target, TargetRef, Value, Weights};
use crate::editor::command::Command;
use crate::editor::fields::FieldId;
use crate::editor::panel::Widget;
use crate::editor::Editor;
use crate::scene::{Morphs, NodeId, Scene};
use crate::ui::Rect;

use super::morph_ui::{MorphCtx, MorphRows};
pub use super::state::{MorphBase, MorphPending};
use super::targets::morph_mesh;
use super::targets::{morph_of, target_names};

fn weights_target(id: NodeId) -> Target {
    Target {
        of: TargetRef::Node(id),
        property: Property::MorphWeights,
    }
}

/// `scene` with `shape`'s mesh taking `w` as its default weights; `None`
/// when the shape has no morph targets.
fn with_defaults(scene: &Scene, shape: NodeId, w: &Weights) -> Option<Scene> {
    let (mesh, m) = morph_mesh(scene, shape)?;
    let vertex_count = scene.meshes[mesh.0 as usize].positions.len();
    let morphs = Morphs::new(vertex_count, m.targets().to_vec(), w.as_slice().to_vec()).ok()?;
    let mut out = scene.clone();
    out.meshes[mesh.0 as usize].morph = Some(Box::new(morphs));
    Some(out)
}

/// `anim` with a weights key for `target` at `frame`.
fn with_key(anim: &Animation, target: NodeId, frame: f32, w: Weights) -> Result<Animation, String> {
    let mut out = anim.clone();
    out.set_key(weights_target(target), frame, Value::Weights(w))
        .map_err(|e| format!("cannot key the morph weights: {e}"))?;
    Ok(out)
}

impl Editor {
    /// Morph slider rows the selection needs (0 without morph targets).
    pub(in crate::internals::editor) fn morph_rows(&self) -> usize {
        self.selection
            .and_then(|s| morph_of(&self.scene, s))
            .map_or(0, |(_, shape)| target_names(&self.scene, shape).len())
    }

    /// The pending morph change, if it still applies.
    pub fn morph_pending(&self) -> Option<&MorphPending> {
        self.rig
            .morph_pending
            .as_ref()
            .filter(|p| p.frame == self.frame && p.revision == self.history.revision())
    }

    /// The selection's shown morph weights (a pending change included).
    pub fn shown_weights(&self) -> Option<(NodeId, NodeId, Weights)> {
        let (target, shape) = morph_of(&self.scene, self.selection?)?;
        if let Some(p) = self.morph_pending().filter(|p| p.shape == shape) {
            return Some((target, shape, p.weights));
        }
        // The cached pose when it is current (drawing refreshes it first).
        let w = match &self.pose {
            Some((r, f, pose)) if *r == self.scene_rev && *f == self.frame => {
                *pose.weights(shape)?
            }
            _ => {
                let t = self.frame / self.scene.settings.fps.max(1e-6);
                *self.evaluate_shown(t).weights(shape)?
            }
        };
        Some((target, shape, w))
    }

    /// The scene as shown with a pending morph change: its weights track
    /// set aside and the weights as the mesh's defaults (`evaluate_shown`).
    pub(in crate::internals::editor) fn morph_shown_scene(&self) -> Option<Scene> {
        let p = self.morph_pending()?;
        let mut s = with_defaults(&self.scene, p.shape, &p.weights)?;
        s.animation.remove_tracks(weights_target(p.target));
        Some(s)
    }

    /// Shows `w` as a pending change (live while dragging).
    fn show_morph(&mut self, target: NodeId, shape: NodeId, w: Weights) {
        self.rig.morph_pending = Some(MorphPending {
            target,
            shape,
            frame: self.frame,
            weights: w,
            revision: self.history.revision(),
        });
        self.pending = None;
        self.scene_rev += 1;
        self.stop_playback();
    }

    /// Start of a slider drag or typed value.
    pub(in crate::internals::editor) fn morph_base(&self) -> Option<MorphBase> {
        let (target, shape, start) = self.shown_weights()?;
        Some(MorphBase {
            target,
            shape,
            start,
        })
    }

    /// Live drag: shows the weights with slider `id` at `v`.
    pub(in crate::internals::editor) fn drag_morph(
        &mut self,
        id: FieldId,
        base: &MorphBase,
        v: f32,
    ) {
        let FieldId::Morph(i) = id else { return };
        let mut w = base.start;
        if let Some(x) = w.as_mut_slice().get_mut(i as usize) {
            *x = v;
            self.show_morph(base.target, base.shape, w);
        }
    }

    /// Typed value or end of a drag: records the change as the module doc
    /// says. `v` is the slider's new value.
    pub(in crate::internals::editor) fn set_morph(
        &mut self,
        id: FieldId,
        base: &MorphBase,
        v: f32,
    ) {
        let FieldId::Morph(i) = id else { return };
        if !v.is_finite() {
            self.set_status("A morph weight must be a finite number", true);
            return;
        }
        let mut w = base.start;
        let Some(x) = w.as_mut_slice().get_mut(i as usize) else {
            return;
        };
        *x = v;
        let names = target_names(&self.scene, base.shape);
        let what = names.get(i as usize).cloned().unwrap_or_default();
        let node = crate::editor::ops::display_name(&self.scene, base.target);
        let animated = self
            .scene
            .animation
            .track(weights_target(base.target))
            .is_some();
        self.rig.morph_pending = None;
        self.scene_rev += 1;
        if self.record {
            self.key_weights(base.target, w, &format!("Key {node}.weights ({what})"));
        } else if animated {
            self.show_morph(base.target, base.shape, w);
            self.set_status(
                "Pending: K keys the morph weights, new frame drops them",
                false,
            );
        } else if let Some(after) = with_defaults(&self.scene, base.shape, &w) {
            let before = Box::new(self.scene.clone());
            self.execute(
                &format!("Set {node} {what}"),
                Command::ReplaceScene {
                    before,
                    after: Box::new(after),
                },
            );
            let f = crate::editor::fields::format_number(v);
            self.set_status(
                &format!("{node}: {what} = {f} (not animated; Rec or K keys it)"),
                false,
            );
        }
    }

    /// Keys the weights of `target` at the current frame, one undo step.
    fn key_weights(&mut self, target: NodeId, w: Weights, label: &str) {
        match with_key(&self.scene.animation, target, self.frame, w) {
            Ok(after) => {
                let before = Box::new(self.scene.animation.clone());
                self.execute(
                    label,
                    Command::SetAnimation {
                        before,
                        after: Box::new(after),
                    },
                );
                let f = crate::editor::fields::format_number(self.frame);
                self.set_status(&format!("{label} at frame {f}"), false);
            }
            Err(e) => self.set_status(&e, true),
        }
    }

    /// K with a pending morph change, or with the mouse over a morph
    /// slider: keys the selection's weights. Returns false when K should
    /// key the transform as usual.
    pub(in crate::internals::editor) fn key_morph(&mut self) -> bool {
        let over_slider = matches!(
            self.widget_at(self.mouse.0, self.mouse.1).map(|w| w.kind),
            Some(crate::editor::panel::WidgetKind::Field(FieldId::Morph(_)))
        );
        let pending = self.morph_pending().cloned();
        let Some((target, _, w)) = self.shown_weights() else {
            return false;
        };
        if pending.is_none() && !over_slider {
            return false;
        }
        self.rig.morph_pending = None;
        self.stop_playback();
        let node = crate::editor::ops::display_name(&self.scene, target);
        self.key_weights(target, w, &format!("Key {node}.weights"));
        true
    }

    /// What the morph sliders see (`rig/morph_ui.rs`).
    pub(in crate::internals::editor) fn morph_ctx(&self) -> MorphCtx {
        let Some(base) = self.morph_base() else {
            return MorphCtx::default();
        };
        MorphCtx {
            names: target_names(&self.scene, base.shape),
            base: Some(base),
        }
    }

    /// One slider row: the target's name, then its weight field (the
    /// component lays it out).
    pub(in crate::internals::editor) fn morph_row(&self, i: u8, r: Rect, out: &mut Vec<Widget>) {
        MorphRows::row(i, r, &self.morph_ctx(), out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Mesh, MorphTarget, Node, NodeKind, Shape};
    use glam::Vec3;

    fn morphed() -> (Scene, NodeId, NodeId) {
        let mut s = Scene::new();
        let mut mesh = Mesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
            ..Mesh::default()
        };
        let t = MorphTarget::new("smile", vec![Vec3::Z; 3], Vec::new());
        mesh.morph = Some(Box::new(Morphs::new(3, vec![t], vec![0.25]).unwrap()));
        let mesh = s.add_mesh(mesh);
        let g = s.add_node(None, Node::group("Face"));
        let shape = Node::new(
            "",
            NodeKind::Shape(Shape {
                mesh,
                material: crate::scene::MaterialId(0),
            }),
        );
        let sh = s.add_node(Some(g), shape);
        (s, g, sh)
    }

    #[test]
    fn a_group_edits_its_morphed_child() {
        let (s, g, sh) = morphed();
        assert_eq!(morph_of(&s, g), Some((g, sh)));
        assert_eq!(morph_of(&s, sh), Some((sh, sh)));
        assert_eq!(target_names(&s, sh), ["smile"]);
        let w = Weights::from_slice(&[0.75]).unwrap();
        let d = with_defaults(&s, sh, &w).unwrap();
        let (m, _) = morph_mesh(&d, sh).unwrap();
        let got = d.meshes[m.0 as usize]
            .morph
            .as_ref()
            .unwrap()
            .default_weights();
        assert_eq!(got, [0.75]);
    }
}
