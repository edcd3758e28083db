//! F1: the key reference drawn over the window, so a new user can find
//! record mode, the tools and the key strip without the README. The list
//! mirrors the README's Editor section; keep the two together.

use super::Editor;
use crate::ui::layout::ROW;
use crate::ui::text::CHAR_W;
use crate::ui::{theme, Painter, Rect};

/// (keys, what they do), grouped under headings (entries with empty keys).
pub const HELP: &[(&str, &str)] = &[
    ("", "Animate"),
    ("R / Rec", "record mode: a drag or typed value keys it"),
    ("W E T", "move / rotate / scale handles"),
    ("drag body", "move the selection in the view plane"),
    ("Ctrl (drag)", "snap: grid, 15 degrees, 0.1"),
    ("K", "key the changed properties"),
    ("O", "onion skin at the previous/next key"),
    ("M", "material panel: colours, shininess, texture"),
    ("", "Time"),
    ("Space, Ctrl+P", "play / stop"),
    ("Left / Right", "previous / next frame"),
    ("Up / Down", "next / previous key"),
    ("wheel, middle-drag", "zoom / pan the ruler and strip"),
    (
        "Shift+drag ruler",
        "preview range (loops); [ ] ends, Alt+P clears",
    ),
    ("", "Key strip"),
    (
        "click, Shift+click",
        "select keys; drag on empty space: box",
    ),
    ("drag / Alt+drag", "move keys / scale their timing"),
    ("Delete", "delete selected keys (else asks: object)"),
    ("drag its top edge", "strip height; wheel scrolls its rows"),
    ("Ctrl+C / Ctrl+V", "copy keys / paste at the current frame"),
    ("Shift+F6, Graph", "graph editor: curves, keys, tangents"),
    ("", "Create"),
    ("Shift+A, Add", "add a box, sphere, light, camera..."),
    ("Shift+D", "duplicate the selection with its keys"),
    (
        "drag a list row",
        "onto a row: parent; empty space: unparent",
    ),
    ("", "View and files"),
    ("Alt+drag, middle", "orbit; Shift+middle pans; wheel zooms"),
    ("F / Home", "frame the selection / everything"),
    ("Esc", "select mode / view mode"),
    ("G, L", "grid; light on/off"),
    ("Ctrl+Z / Ctrl+Y", "undo / redo"),
    ("Ctrl+O / S / I / N", "open, save, import, new"),
    ("F1 / F3", "this help / search every command by name"),
];

/// Width of the keys column, in characters.
const KEYS_CHARS: usize = 21;

impl Editor {
    pub fn help_shown(&self) -> bool {
        self.help
    }

    pub(super) fn set_help(&mut self, on: bool) {
        self.help = on;
    }

    /// The help box, centred in the window (clamped to it).
    pub fn help_rect(&self) -> Rect {
        let win = self.layout().window;
        let widest = HELP
            .iter()
            .map(|(k, d)| {
                if k.is_empty() {
                    d.len()
                } else {
                    KEYS_CHARS + d.len()
                }
            })
            .max()
            .unwrap_or(0) as i32;
        let w = (widest * CHAR_W + 16).min(win.w);
        let h = ((HELP.len() as i32 + 2) * ROW + 8).min(win.h);
        Rect::new((win.w - w) / 2, (win.h - h) / 2, w, h)
    }

    pub(super) fn draw_help(&self, p: &mut Painter) {
        if !self.help {
            return;
        }
        let win = self.layout().window;
        p.fill_rect_alpha(win, 0x000000, 110);
        let r = self.help_rect();
        p.fill_rect(r, theme::DIALOG);
        p.stroke_rect(r, theme::BORDER);
        p.set_clip(Some(r));
        let x = r.x + 8;
        let mut y = r.y + 4;
        p.text(x, y, "animed keys", theme::TEXT);
        y += ROW + 4;
        for (keys, what) in HELP {
            if keys.is_empty() {
                p.text(x, y, what, theme::ACCENT);
            } else {
                p.text(x + CHAR_W, y, keys, theme::TEXT);
                let dx = KEYS_CHARS as i32 * CHAR_W;
                p.text_clipped(x + dx, y, what, theme::TEXT_DIM, r.right() - x - dx - 4);
            }
            y += ROW;
        }
        p.set_clip(None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_fits_the_box_at_the_default_size() {
        let ed = Editor::new(crate::scene::Scene::new(), None, 1024, 640);
        let r = ed.help_rect();
        for (k, d) in HELP {
            assert!(k.len() + 2 <= KEYS_CHARS, "keys column too narrow for {k}");
            let w = (KEYS_CHARS + d.len()) as i32 * CHAR_W + 16;
            assert!(w <= r.w, "{d} does not fit");
        }
        assert!(r.h <= 640 && r.w <= 1024);
    }

    #[test]
    fn f1_shows_help_and_the_next_key_only_closes_it() {
        use crate::editor::{Event, Key, Mods};
        let mut ed = Editor::new(crate::scene::Scene::new(), None, 1024, 640);
        let press = |ed: &mut Editor, key| {
            ed.handle(Event::KeyDown {
                key,
                mods: Mods::NONE,
            })
        };
        press(&mut ed, Key::F(1));
        assert!(ed.help_shown());
        let grid = ed.grid_shown();
        press(&mut ed, Key::Char('g'));
        assert!(!ed.help_shown());
        assert_eq!(ed.grid_shown(), grid, "the closing key does nothing else");
        press(&mut ed, Key::F(1));
        ed.handle(Event::MouseDown {
            button: crate::editor::MouseButton::Left,
            x: 5.0,
            y: 5.0,
            mods: Mods::NONE,
        });
        assert!(!ed.help_shown(), "a click closes it");
    }
}
