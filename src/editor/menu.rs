//! Pop-up menus (the Add menu, context menus, the View menu): a component
//! that owns its items, hover and position, takes events with
//! [`Menu::handle`] and draws itself with [`Menu::draw`]. It never names
//! the editor: a pick comes back as the item's [`Action`] for the editor
//! to run.

use super::panel::Action;
use crate::input::{Event, Key, MouseButton};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{theme, Painter, Rect};

/// One line of a menu: what it says, its shortcut (shown at the right,
/// may be empty) and what choosing it does.
#[derive(Clone, Debug, PartialEq)]
pub struct MenuItem {
    pub label: String,
    pub shortcut: String,
    pub action: Action,
}

impl MenuItem {
    pub fn new(label: &str, shortcut: &str, action: Action) -> MenuItem {
        MenuItem {
            label: label.into(),
            shortcut: shortcut.into(),
            action,
        }
    }
}

/// An open menu.
#[derive(Clone, Debug, PartialEq)]
pub struct Menu {
    pub title: String,
    pub items: Vec<MenuItem>,
    /// Top-left corner asked for (kept inside the window when drawn).
    pub at: (i32, i32),
    /// The highlighted item (mouse or Up/Down).
    pub hover: Option<usize>,
}

/// What a menu did with an event.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// Taken; the menu stays open (redraw when `true`).
    Stay(bool),
    /// An item was chosen: close and run it.
    Pick(Action),
    /// Closed without a choice (Esc, a click outside).
    Close,
}

impl Menu {
    pub fn new(title: &str, items: Vec<MenuItem>, at: (i32, i32)) -> Menu {
        Menu {
            title: title.into(),
            items,
            at,
            hover: Some(0),
        }
    }

    /// The menu's box inside `window`.
    pub fn rect(&self, window: Rect) -> Rect {
        let wide = |i: &MenuItem| {
            let s = if i.shortcut.is_empty() {
                0
            } else {
                text::width(&i.shortcut) + 2 * CHAR_W
            };
            text::width(&i.label) + s
        };
        let w = self.items.iter().map(wide).max().unwrap_or(0);
        let w = (w.max(text::width(&self.title)) + 16).min(window.w);
        let h = ((self.items.len() as i32 + 1) * ROW + 6).min(window.h);
        let x = self
            .at
            .0
            .clamp(window.x, (window.right() - w).max(window.x));
        let y = self
            .at
            .1
            .clamp(window.y, (window.bottom() - h).max(window.y));
        Rect::new(x, y, w, h)
    }

    /// Item `i`'s row.
    pub fn item_rect(&self, window: Rect, i: usize) -> Rect {
        let r = self.rect(window);
        Rect::new(r.x + 1, r.y + ROW + 4 + i as i32 * ROW, r.w - 2, ROW)
    }

    /// The item under (x, y).
    pub fn item_at(&self, window: Rect, x: f32, y: f32) -> Option<usize> {
        (0..self.items.len()).find(|&i| self.item_rect(window, i).contains(x, y))
    }

    /// Takes every event while open (it is modal).
    pub fn handle(&mut self, ev: &Event, window: Rect) -> Reply {
        let n = self.items.len();
        match ev {
            Event::MouseMove { x, y, .. } => {
                let h = self.item_at(window, *x, *y).or(self.hover);
                let changed = h != self.hover;
                self.hover = h;
                Reply::Stay(changed)
            }
            Event::MouseDown { button, x, y, .. } => match self.item_at(window, *x, *y) {
                Some(i) if *button != MouseButton::Middle => Reply::Pick(self.items[i].action),
                _ if self.rect(window).contains(*x, *y) => Reply::Stay(false),
                _ => Reply::Close,
            },
            Event::KeyDown { key, .. } => match key {
                Key::Escape => Reply::Close,
                Key::Enter | Key::Space => match self.hover {
                    Some(i) if i < n => Reply::Pick(self.items[i].action),
                    _ => Reply::Close,
                },
                Key::Up | Key::Down if n > 0 => {
                    let h = self.hover.unwrap_or(0);
                    self.hover = Some(match key {
                        Key::Up => (h + n - 1) % n,
                        _ => (h + 1) % n,
                    });
                    Reply::Stay(true)
                }
                // A letter picks the first item starting with it.
                Key::Char(c) => {
                    let hit = self.items.iter().find(|i| {
                        i.label
                            .chars()
                            .next()
                            .is_some_and(|f| f.to_ascii_lowercase() == *c)
                    });
                    match hit {
                        Some(i) => Reply::Pick(i.action),
                        None => Reply::Stay(false),
                    }
                }
                _ => Reply::Stay(false),
            },
            _ => Reply::Stay(false),
        }
    }

    pub fn draw(&self, p: &mut Painter, window: Rect) {
        let r = self.rect(window);
        p.fill_rect(r, theme::DIALOG);
        p.stroke_rect(r, theme::ACCENT);
        p.text_clipped(r.x + 6, r.y + 3, &self.title, theme::TEXT_DIM, r.w - 12);
        p.fill_rect(Rect::new(r.x + 1, r.y + ROW + 2, r.w - 2, 1), theme::BORDER);
        for (i, item) in self.items.iter().enumerate() {
            let ir = self.item_rect(window, i);
            if self.hover == Some(i) {
                p.fill_rect(ir, theme::BUTTON_ON);
            }
            p.text_clipped(ir.x + 6, ir.y, &item.label, theme::TEXT, ir.w - 12);
            if !item.shortcut.is_empty() {
                let sw = text::width(&item.shortcut);
                p.text(ir.right() - sw - 6, ir.y, &item.shortcut, theme::TEXT_DIM);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Mods;

    fn menu() -> Menu {
        Menu::new(
            "Add",
            vec![
                MenuItem::new("Box", "", Action::Undo),
                MenuItem::new("Sphere", "", Action::Redo),
            ],
            (300, 300),
        )
    }

    #[test]
    fn keys_move_pick_and_close() {
        let win = Rect::new(0, 0, 320, 240);
        let mut m = menu();
        let r = m.rect(win);
        assert!(r.right() <= 320 && r.bottom() <= 240, "kept inside: {r:?}");
        let down = Event::KeyDown {
            key: Key::Down,
            mods: Mods::NONE,
        };
        assert_eq!(m.handle(&down, win), Reply::Stay(true));
        let enter = Event::KeyDown {
            key: Key::Enter,
            mods: Mods::NONE,
        };
        assert_eq!(m.handle(&enter, win), Reply::Pick(Action::Redo));
        let b = Event::KeyDown {
            key: Key::Char('b'),
            mods: Mods::NONE,
        };
        assert_eq!(m.handle(&b, win), Reply::Pick(Action::Undo));
        let c = m.item_rect(win, 1);
        let click = Event::MouseDown {
            button: MouseButton::Left,
            x: (c.x + 3) as f32,
            y: (c.y + 3) as f32,
            mods: Mods::NONE,
        };
        assert_eq!(m.handle(&click, win), Reply::Pick(Action::Redo));
        let outside = Event::MouseDown {
            button: MouseButton::Left,
            x: 2.0,
            y: 2.0,
            mods: Mods::NONE,
        };
        assert_eq!(m.handle(&outside, win), Reply::Close);
    }
}
