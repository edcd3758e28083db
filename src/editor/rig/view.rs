//! The editor's side of `bones`: draws the active skeleton's bones over
//! the viewport and picks joints by them.
//!
//! Bones are drawn on top of the mesh (the overlay has no depth test) but
//! only while the skeleton is active — its mesh, a joint or an ancestor
//! selected — so a scene does not drown in lines; the selected joint is
//! drawn in the selection colour, its chain's joints as balls.

use super::bones::{self, Bone};
use crate::editor::Editor;
use crate::scene::NodeId;
use crate::ui::{theme, Painter};

/// Bone colour (a cool grey that reads on dark and light meshes).
const BONE: u32 = 0xa8b4cc;
/// Outline width of bones in pixels.
const BONE_W: f32 = 1.2;

impl Editor {
    /// Bones of the skins the selection makes active, at the shown pose.
    pub(in crate::internals::editor) fn shown_bones(&mut self) -> Vec<Bone> {
        let skins = bones::active_skins(&self.scene, self.selection);
        if skins.is_empty() {
            return Vec::new();
        }
        let pose = self.pose().clone();
        bones::bones(&self.scene, &pose, &skins)
    }

    /// Draws the active skeleton: octahedral bones, a ball at each joint.
    pub(in crate::internals::editor) fn draw_bones(&mut self, p: &mut Painter) {
        let bones = self.shown_bones();
        if bones.is_empty() {
            return;
        }
        let vp = self.layout().viewport;
        let proj = self.projector();
        p.set_clip(Some(vp));
        // Unselected first, so the selected joint's bone is on top.
        let sel = self.selection;
        let mut order: Vec<&Bone> = bones.iter().collect();
        order.sort_by_key(|b| Some(b.joint) == sel);
        for b in order {
            let selected = Some(b.joint) == sel;
            let color = if selected { theme::SELECTED } else { BONE };
            let width = if selected { 2.0 } else { BONE_W };
            for (a, c) in bones::octahedron(b.head, b.tail) {
                if let Some((pa, pc)) = proj.segment(a, c) {
                    p.line(pa, pc, color, width);
                }
            }
            if let Some(h) = proj.point(b.head) {
                p.fill_circle(h, if selected { 3.5 } else { 2.5 }, color);
            }
        }
        p.set_clip(None);
    }

    /// Where joint `id`'s ball is drawn in the window, if it shows (tests
    /// and scripts aim clicks with it).
    pub fn joint_on_screen(&mut self, id: NodeId) -> Option<(f32, f32)> {
        let bones = self.shown_bones();
        let b = bones.iter().find(|b| b.joint == id)?;
        self.projector().point(b.head)
    }

    /// Where world point `p` shows in the window (tests aim drags with it).
    pub fn world_on_screen(&mut self, p: glam::Vec3) -> Option<(f32, f32)> {
        self.projector().point(p)
    }

    /// The joint whose ball or bone is under (x, y), if a skeleton shows.
    pub(in crate::internals::editor) fn pick_joint(&mut self, x: f32, y: f32) -> Option<NodeId> {
        let bones = self.shown_bones();
        if bones.is_empty() {
            return None;
        }
        let proj = self.projector();
        bones::pick(&bones, &proj, x, y)
    }
}
