//! The editor's side of the viewport component (`viewport_ui.rs`): builds
//! what it sees, routes events to it, keeps the editor's one gesture
//! (`Drag::Viewport`) in step with the component's, and draws it; what it
//! returns is applied in `route/intents.rs`.

use crate::editor::gesture::Drag;
use crate::editor::viewport_ui::ViewportCtx;
use crate::editor::{Editor, Mode};
use crate::input::{Event, Key, Mods};
use crate::ui::Painter;

impl Editor {
    /// What the viewport sees for `ev` (the handles' context only when
    /// the event reaches them; the IK drag a press would start only for a
    /// press; `draw`: whether the IK target shows).
    fn viewport_ctx(&mut self, ev: Option<&Event>, draw: bool) -> ViewportCtx {
        let select_mode = self.mode == Mode::Select;
        let wants = match ev {
            Some(e) => self.viewport.wants_handles(e, select_mode),
            None => select_mode,
        };
        let press = match ev {
            Some(&Event::MouseDown { x, y, .. }) if wants => Some((x, y)),
            _ => None,
        };
        let handles = wants.then(|| self.handles_ctx(press));
        let is_press = matches!(ev, Some(Event::MouseDown { .. }));
        ViewportCtx {
            viewport: self.layout().viewport,
            select_mode,
            camera: self.camera,
            proj: self.projector(),
            handles,
            ik: self.ik_ctx(is_press, draw),
        }
    }

    /// Hands `ev` to the viewport and applies its answer; `Some(redraw)`
    /// when it took the event. The editor's gesture follows the
    /// viewport's.
    pub(in crate::internals::editor) fn viewport_event(&mut self, ev: &Event) -> Option<bool> {
        let ctx = self.viewport_ctx(Some(ev), false);
        let r = self.viewport.handle(ev, &ctx);
        match (self.viewport.busy(), matches!(self.drag, Drag::Viewport)) {
            (true, false) => self.drag = Drag::Viewport,
            (false, true) => self.drag = Drag::None,
            _ => {}
        }
        self.apply_response(r)
    }

    /// Keys for the viewport: its handles' (W / E / T; during a handle
    /// drag Esc cancels it and other keys are ignored), and O toggles the
    /// onion skin. True when the key was taken.
    pub(in crate::internals::editor) fn viewport_key(&mut self, key: Key, mods: Mods) -> bool {
        if self.viewport_event(&Event::KeyDown { key, mods }).is_some() {
            return true;
        }
        // (During a handle drag the handles took every key above.)
        if !(mods.ctrl || mods.alt) && key == Key::Char('o') {
            self.toggle_onion();
            return true;
        }
        false
    }

    /// Esc during the viewport's gesture (not a handle drag, whose Esc the
    /// handles take): it ends where it is.
    pub(in crate::internals::editor) fn cancel_viewport(&mut self) {
        self.viewport.cancel();
    }

    /// Draws the viewport's own overlays (IK target, handles).
    pub(in crate::internals::editor) fn draw_viewport_ui(&mut self, p: &mut Painter) {
        let ctx = self.viewport_ctx(None, true);
        self.viewport.draw(p, &ctx);
    }
}
