//! The editor's side of the handles component (`manip/handles.rs`): the
//! context it sees, routing presses, moves, releases and keys to it and
//! applying what it returns, and the points tests and scripts aim at.

use crate::editor::component::Response;
use crate::editor::gesture::Drag;
use crate::editor::manip::handles::{targets, HandlesCtx};
#[allow(unused_imports)]
use crate::editor::manip::*;
use crate::editor::{ops, Editor};
use crate::input::{Event, Key, Mods, MouseButton};
use crate::ui::Painter;
use glam::{Mat4, Vec3};

impl Editor {
    /// The current tool.
    pub fn tool(&self) -> Tool {
        self.manip.tool
    }

    /// Picks the tool (W / E / T, toolbar).
    pub fn set_tool(&mut self, t: Tool) {
        self.manip.set_tool(t);
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

    /// Hands `ev` to the handles and applies their answer; the editor's
    /// gesture follows the handles' (a drag running, a press armed).
    fn handles_event(&mut self, ev: &Event, press: Option<(f32, f32)>) -> Option<bool> {
        let ctx = self.handles_ctx(press);
        let r: Response = self.manip.handle(ev, &ctx);
        if self.manip.dragging() {
            self.drag = Drag::Handle;
        } else if let Drag::Handle = self.drag {
            self.drag = Drag::None;
        } else if let Drag::Pick { at, armed } = self.drag {
            let now = self.manip.armed();
            if armed != now {
                self.drag = Drag::Pick { at, armed: now };
            }
        }
        self.apply_response(r)
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
        self.manip.hit(&ctx, x, y)
    }

    /// Mouse down in the viewport (left, select mode): the handles start a
    /// drag when one is hit, or, on the selection's body (or inside the
    /// rotate rings), arm one for when the mouse moves past the slop (a
    /// click still picks on release). True when the press is the handles'.
    pub(in crate::internals::editor) fn handles_press(&mut self, x: f32, y: f32) -> bool {
        let ev = Event::MouseDown {
            button: MouseButton::Left,
            x,
            y,
            mods: Mods::NONE,
        };
        let taken = self.handles_event(&ev, Some((x, y))).is_some();
        if taken && !self.manip.dragging() {
            self.drag = Drag::Pick {
                at: (x, y),
                armed: true,
            };
        }
        taken
    }

    /// Mouse move: drags the active handle, or updates the hover highlight.
    /// `Some(redraw)` when the handles took the event.
    pub(in crate::internals::editor) fn handles_move(
        &mut self,
        x: f32,
        y: f32,
        mods: Mods,
    ) -> Option<bool> {
        self.handles_event(&Event::MouseMove { x, y, mods }, None)
    }

    /// Mouse up: ends a handle drag as one undo step (with a key in record
    /// mode). False when no handle drag was running.
    pub(in crate::internals::editor) fn handles_release(&mut self) -> bool {
        let ev = Event::MouseUp {
            button: MouseButton::Left,
            x: self.mouse.0,
            y: self.mouse.1,
            mods: Mods::NONE,
        };
        self.handles_event(&ev, None).is_some()
    }

    /// Mouse up on a press the handles armed and the mouse never moved
    /// past the slop: it stays a click (the editor picks).
    pub(in crate::internals::editor) fn handles_disarm(&mut self) {
        let ev = Event::MouseUp {
            button: MouseButton::Left,
            x: self.mouse.0,
            y: self.mouse.1,
            mods: Mods::NONE,
        };
        self.handles_event(&ev, None);
    }

    /// Keys for the handles: during a drag Esc cancels it and other keys
    /// are ignored; otherwise W / E / T pick the tool and O toggles the
    /// onion skin. True when the key was taken.
    pub(in crate::internals::editor) fn handles_key(&mut self, key: Key, mods: Mods) -> bool {
        let dragging = self.manip.dragging();
        if !dragging && (mods.ctrl || mods.alt) {
            return false;
        }
        if dragging || Tool::ALL.iter().any(|t| key == Key::Char(t.key())) {
            return self
                .handles_event(&Event::KeyDown { key, mods }, None)
                .is_some();
        }
        if key == Key::Char('o') {
            self.toggle_onion();
            return true;
        }
        false
    }

    /// Whether a handle drag is running.
    pub fn handle_dragging(&self) -> bool {
        self.manip.dragging()
    }

    /// Draws the current tool's handles for the selection over the viewport.
    pub(in crate::internals::editor) fn draw_handles(&mut self, p: &mut Painter) {
        if self.mode != crate::editor::Mode::Select {
            return;
        }
        let ctx = self.handles_ctx(None);
        self.manip.draw(p, &ctx);
    }
}
