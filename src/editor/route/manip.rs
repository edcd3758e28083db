//! The editor's side of the handles (`manip/handles.rs`, a part of the
//! viewport component): the tool, the context they see, and the points
//! tests and scripts aim at. Events reach them through the viewport
//! (`route/viewport.rs`).

use crate::editor::manip::handles::{targets, HandlesCtx};
#[allow(unused_imports)]
use crate::editor::manip::*;
use crate::editor::{ops, Editor};
use glam::{Mat4, Vec3};

impl Editor {
    /// The current tool.
    pub fn tool(&self) -> Tool {
        self.viewport.handles.tool
    }

    /// Picks the tool (W / E / T, toolbar).
    pub fn set_tool(&mut self, t: Tool) {
        self.viewport.handles.set_tool(t);
    }

    /// What each tool's handles act on for the selection, in
    /// [`Tool::ALL`] order.
    pub(in crate::internals::editor) fn targets(&mut self) -> [Option<Target>; 3] {
        let Some(id) = self.selection else {
            return [None; 3];
        };
        let pose = self.pose();
        let Some(world) = pose.world.get(id.0 as usize).copied() else {
            return [None; 3];
        };
        let n = self.posed_node(id);
        let parent = n
            .parent
            .and_then(|p| self.pose().world.get(p.0 as usize).copied())
            .unwrap_or(Mat4::IDENTITY);
        targets(id, world, parent, &n)
    }

    /// What `tool`'s handles act on for the selection.
    pub(in crate::internals::editor) fn target(&mut self, tool: Tool) -> Option<Target> {
        self.targets()[tool as usize]
    }

    /// What the handles see; `press`: the pixel of a press (the handles
    /// then ask whether it is on the selection).
    pub(in crate::internals::editor) fn handles_ctx(
        &mut self,
        press: Option<(f32, f32)>,
    ) -> HandlesCtx {
        let sel = self.selection;
        let on_selection = match (press, sel) {
            (Some((x, y)), Some(_)) => self.pick_at(x, y) == sel,
            _ => false,
        };
        HandlesCtx {
            proj: self.handle_projector(),
            back: self.camera.back(),
            viewport: self.layout().viewport,
            select_mode: self.mode == crate::editor::Mode::Select,
            targets: self.targets(),
            stored: sel.map(|s| self.scene.node(s).clone()),
            shown: sel.map(|s| self.posed_node(s)),
            radius: self.scene_radius().1,
            name: sel
                .map(|s| ops::display_name(&self.scene, s))
                .unwrap_or_default(),
            on_selection,
        }
    }

    /// Pixel positions of the pivot and of the three translate arrow tips
    /// (tests and scripts aim at them).
    pub fn handle_points(&mut self) -> Option<[(f32, f32); 4]> {
        let t = self.target(Tool::Translate)?;
        crate::editor::manip::translate::points(&self.handle_projector(), t.pivot)
    }

    /// Window pixel of world point `p` as the viewport shows it (`None`
    /// behind the eye); tests and scripts aim with it.
    pub fn pixel_of(&mut self, p: Vec3) -> Option<(f32, f32)> {
        self.projector().point(p)
    }

    /// Pixel positions of the scale pivot and the three scale boxes.
    pub fn scale_points(&mut self) -> Option<[(f32, f32); 4]> {
        let t = self.target(Tool::Scale)?;
        crate::editor::manip::scale::points(&self.handle_projector(), t.pivot, &t.frame)
    }

    /// Pixel of the point of ring `h` at angle `theta` (radians from the
    /// ring's first in-plane axis: y for the x ring, z for y, x for z, and
    /// screen right for the view ring; positive turns right-handed about
    /// the ring's axis, which for the view ring points at the eye).
    pub fn ring_pixel(&mut self, h: Handle, theta: f32) -> Option<(f32, f32)> {
        let t = self.target(Tool::Rotate)?;
        let proj = self.handle_projector();
        let w =
            crate::editor::manip::rotate::ring_point(&proj, h, t.pivot, self.camera.back(), theta)?;
        proj.point(w)
    }

    /// The handle of the current tool under window pixel (x, y).
    pub fn handle_at(&mut self, x: f32, y: f32) -> Option<Handle> {
        let ctx = self.handles_ctx(None);
        self.viewport.handles.hit(&ctx, x, y)
    }

    /// Whether a handle drag is running.
    pub fn handle_dragging(&self) -> bool {
        self.viewport.handles.dragging()
    }
}
