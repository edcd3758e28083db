//! The editor's side of `onion`: routes events to it and applies what it returns.

#[allow(unused_imports)]
use crate::editor::onion::*;
use crate::editor::{ops, Editor};
use crate::render::{self, Frame, View};
use crate::scene::NodeKind;
use crate::ui::Rect;

impl Editor {
    /// Whether the onion skin is on.
    pub fn onion_shown(&self) -> bool {
        self.onion.on
    }

    /// O / toolbar: shows or hides the onion skin.
    pub(in crate::internals::editor) fn toggle_onion(&mut self) {
        self.onion.on = !self.onion.on;
        let s = if self.onion.on { "on" } else { "off" };
        self.set_status(&format!("Onion skin {s}"), false);
    }

    /// The frames the onion skin shows copies at for the selection.
    pub fn onion_frames(&self) -> (Option<f32>, Option<f32>) {
        match self.selection {
            Some(id) => neighbour_keys(&self.scene.animation, id, self.frame),
            None => (None, None),
        }
    }

    /// Re-renders the copies when their inputs changed.
    pub(in crate::internals::editor) fn update_onion(&mut self, w: u32, h: u32) {
        let Some(sel) = self.selection.filter(|_| self.onion.on) else {
            self.onion.ghosts.clear();
            self.onion.key = None;
            return;
        };
        let key = OnionKey {
            rev: self.scene_rev,
            keys: self.onion_frames(),
            camera: self.camera,
            w,
            h,
            sel,
            style: self.view_style,
        };
        if self.onion.key == Some(key) {
            return;
        }
        self.onion.key = Some(key);
        self.onion.ghosts.clear();
        if matches!(self.scene.node(sel).kind, NodeKind::Light(_)) {
            return;
        }
        let proj = self.projector();
        let view = View {
            view: proj.view,
            proj: proj.proj,
            eye: self.camera.eye(),
        };
        let opts = self.layer_options(w, h);
        let mut mine = vec![false; self.scene.nodes.len()];
        for id in ops::subtree(&self.scene, sel) {
            mine[id.0 as usize] = true;
        }
        let (before, after) = key.keys;
        let fps = self.scene.settings.fps.max(1e-6);
        for (f, tint) in [(before, BEFORE), (after, AFTER)] {
            let Some(f) = f else { continue };
            let mut pose = crate::anim::evaluate(&self.scene, f / fps);
            for (i, n) in self.scene.nodes.iter().enumerate() {
                if !mine[i] && matches!(n.kind, NodeKind::Shape(_)) {
                    pose.visible[i] = false;
                }
            }
            let ghost = render::render(&self.scene, &pose, &view, &opts);
            if ghost.width == w && ghost.height == h {
                covered(&ghost, tint, &mut self.onion.ghosts);
            }
        }
    }

    /// Blends the copies over the viewport part of `frame` (after the
    /// viewport layer was copied there).
    pub(in crate::internals::editor) fn blit_onion(&mut self, frame: &mut Frame, vp: Rect) {
        let (w, h) = (self.layer.frame.width, self.layer.frame.height);
        self.update_onion(w, h);
        self.onion.blend(&self.layer.frame, frame, vp);
    }
}
