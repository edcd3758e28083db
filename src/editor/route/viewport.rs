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

#[cfg(test)]
mod tests {
    use crate::editor::gesture::Drag;
    use crate::editor::Editor;
    use crate::input::{Event, Mods, MouseButton};

    fn press(ed: &mut Editor, button: MouseButton, at: (f32, f32)) {
        let (x, y) = at;
        ed.handle(Event::MouseDown {
            button,
            x,
            y,
            mods: Mods::NONE,
        });
    }
    fn release(ed: &mut Editor, button: MouseButton, at: (f32, f32)) {
        let (x, y) = at;
        ed.handle(Event::MouseUp {
            button,
            x,
            y,
            mods: Mods::NONE,
        });
    }
    fn to(ed: &mut Editor, at: (f32, f32)) -> bool {
        let (x, y) = at;
        ed.handle(Event::MouseMove {
            x,
            y,
            mods: Mods::NONE,
        })
    }

    #[test]
    fn the_viewports_gesture_is_the_editors_one_gesture_until_the_release() {
        let mut ed = Editor::with_demo(480, 320);
        let vp = ed.layout().viewport;
        let side = ed.layout().side;
        let mid = ((vp.x + vp.w / 2) as f32, (vp.y + vp.h / 2) as f32);
        // A right drag pans, even once the mouse leaves the viewport: the
        // move goes to the gesture's owner, not to what is under it.
        press(&mut ed, MouseButton::Right, mid);
        assert!(matches!(ed.drag, Drag::Viewport));
        let cam = *ed.camera();
        assert!(to(&mut ed, (mid.0 + 20.0, mid.1)));
        let panned = *ed.camera();
        assert_ne!(panned, cam);
        let over_side = ((side.x + 10) as f32, mid.1);
        assert!(to(&mut ed, over_side));
        assert_ne!(*ed.camera(), panned, "still panning over the side panel");
        release(&mut ed, MouseButton::Right, over_side);
        assert!(matches!(ed.drag, Drag::None));
        assert!(ed.menu().is_none(), "a drag opens no menu");
        // A right click opens the viewport's menu where it was released.
        press(&mut ed, MouseButton::Right, mid);
        release(&mut ed, MouseButton::Right, mid);
        assert_eq!(ed.menu().map(|m| m.title.as_str()), Some("Viewport"));
    }
}
