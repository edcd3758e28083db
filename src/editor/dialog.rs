//! The modal question ("Save changes first?", "Delete the object?", the
//! recovery offers) as a component: it lays itself out in the window,
//! maps keys and clicks to an [`Answer`] and draws itself. It never names
//! the `Editor`; the editor applies the answer (`route/dialog.rs`), so what
//! a question does lives in one place and what it looks like in another.

use super::panel::{button, label, w, Action, Widget, WidgetKind};
use super::request::After;
use super::widget_paint;
use crate::input::{Event, Key, MouseButton};
use crate::ui::layout::ROW;
use crate::ui::{text, theme, Painter, Rect};

/// A modal question.
#[derive(Clone, Debug, PartialEq)]
pub struct Dialog {
    pub message: String,
    /// What the question is about (and what a yes continues with).
    pub then: After,
    /// It lists untitled sessions to choose from (Up/Down, 1-9).
    pub list: bool,
}

/// The dialog's answer to one event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Answer {
    /// Not the dialog's event (the editor routes it on).
    Ignored,
    /// Taken (the dialog is modal); true when the picture changed.
    Taken(bool),
    /// The default button: Save, Delete or Recover.
    Yes,
    /// Discard (changes or the recovery copy).
    Discard,
    /// Cancel, Not now or Open saved.
    Cancel,
    /// Move the mark in the list up (-1) or down (+1).
    Step(i32),
    /// Choose the list's row `i` (0-based) and recover it.
    Pick(usize),
}

impl Dialog {
    pub fn new(message: impl Into<String>, then: After) -> Dialog {
        Dialog {
            message: message.into(),
            then,
            list: false,
        }
    }

    /// The box in the window `win`: wide enough for the longest line.
    pub fn rect(&self, win: Rect) -> Rect {
        let widest = self.message.lines().map(text::width).max().unwrap_or(0) + 16;
        let bw = widest.clamp(360, 640).min(win.w - 20).max(100);
        let lines = self.message.lines().count();
        let bh = (2 + lines.max(1) as i32) * ROW + 20;
        Rect::new((win.w - bw) / 2, (win.h - bh) / 2, bw, bh)
    }

    /// Heading and the button labels (Cancel, Discard, Yes; empty: none).
    fn words(&self) -> (&'static str, [&'static str; 3]) {
        match self.then {
            After::Recover if self.list => {
                ("Recovery copies", ["Not now", "Discard copy", "Recover"])
            }
            After::Recover => ("Recovery copy", ["Open saved", "Discard copy", "Recover"]),
            After::DeleteObject => ("Delete", ["Cancel", "", "Delete"]),
            _ => ("Unsaved changes", ["Cancel", "Discard", "Save"]),
        }
    }

    /// Its widgets in the window `win`: heading, message lines, buttons.
    pub fn widgets(&self, win: Rect) -> Vec<Widget> {
        let r = self.rect(win);
        let mut out = Vec::new();
        let (heading, labels) = self.words();
        let (title, rest) = r.take_top(ROW + 2);
        out.push(w(title, WidgetKind::Header(heading.into())));
        for (i, line) in self.message.lines().enumerate() {
            out.push(label(
                Rect::new(rest.x + 6, rest.y + 4 + i as i32 * ROW, rest.w - 12, ROW),
                line,
                false,
            ));
        }
        let by = rest.bottom() - ROW - 8;
        let mut x = rest.right() - 6;
        for (l, a) in labels.into_iter().zip([
            Action::DialogCancel,
            Action::DialogDiscard,
            Action::DialogSave,
        ]) {
            if l.is_empty() {
                continue;
            }
            let bw = text::width(l) + 10;
            x -= bw;
            out.push(button(
                Rect::new(x, by, bw, ROW + 2),
                l,
                a,
                a == Action::DialogSave,
            ));
            x -= 4;
        }
        out
    }

    /// One event while the dialog is open. It is modal: every key, click,
    /// typed text and wheel turn is its own; moves and releases are not
    /// (a drag under it still ends).
    pub fn handle(&self, ev: &Event, win: Rect) -> Answer {
        match ev {
            Event::KeyDown { key, .. } => self.key(*key),
            Event::MouseDown { button, x, y, .. } => match button {
                MouseButton::Left => self.click(*x, *y, win),
                _ => Answer::Taken(true),
            },
            Event::Text(_) | Event::Wheel { .. } => Answer::Taken(false),
            _ => Answer::Ignored,
        }
    }

    fn key(&self, key: Key) -> Answer {
        if self.then != After::Recover {
            return match key {
                Key::Escape => Answer::Cancel,
                Key::Enter | Key::Char('s') => Answer::Yes,
                Key::Char('d') | Key::Char('n') => Answer::Discard,
                _ => Answer::Taken(true),
            };
        }
        // Recovery: Enter or R recovers, D discards the copy, O or Esc
        // opens the saved file (Not now for untitled work).
        match key {
            Key::Up if self.list => Answer::Step(-1),
            Key::Down if self.list => Answer::Step(1),
            Key::Char(d @ '1'..='9') if self.list => Answer::Pick(d as usize - '1' as usize),
            Key::Enter | Key::Char('r') => Answer::Yes,
            Key::Char('d') => Answer::Discard,
            Key::Escape | Key::Char('o') => Answer::Cancel,
            _ => Answer::Taken(true),
        }
    }

    fn click(&self, x: f32, y: f32, win: Rect) -> Answer {
        let hit = self
            .widgets(win)
            .into_iter()
            .rev()
            .find_map(|w| match w.kind {
                WidgetKind::Button { action, .. } if w.rect.contains(x, y) => Some(action),
                _ => None,
            });
        match hit {
            Some(Action::DialogSave) => Answer::Yes,
            Some(Action::DialogDiscard) => Answer::Discard,
            Some(Action::DialogCancel) => Answer::Cancel,
            _ => Answer::Taken(true),
        }
    }

    /// Draws the dialog over a dimmed window; `mouse` lights the button
    /// under it (`None` while a drag is held).
    pub fn draw(&self, p: &mut Painter, win: Rect, mouse: Option<(f32, f32)>) {
        p.fill_rect_alpha(win, 0x000000, 110);
        let r = self.rect(win);
        p.fill_rect(r, theme::DIALOG);
        p.stroke_rect(r, theme::ACCENT);
        for w in self.widgets(win) {
            widget_paint::plain(p, &w, mouse);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Mods;

    fn win() -> Rect {
        Rect::new(0, 0, 640, 400)
    }

    fn click_on(d: &Dialog, action: Action) -> Answer {
        let b = d
            .widgets(win())
            .into_iter()
            .find(|w| matches!(w.kind, WidgetKind::Button { action: a, .. } if a == action))
            .expect("button shown");
        let (x, y) = (b.rect.x as f32 + 2.0, b.rect.y as f32 + 2.0);
        d.handle(
            &Event::MouseDown {
                button: MouseButton::Left,
                x,
                y,
                mods: Mods::default(),
            },
            win(),
        )
    }

    fn key(d: &Dialog, key: Key) -> Answer {
        d.handle(
            &Event::KeyDown {
                key,
                mods: Mods::default(),
            },
            win(),
        )
    }

    #[test]
    fn the_dialog_answers_keys_and_clicks_by_itself() {
        let d = Dialog::new("Save changes first?", After::Quit);
        assert_eq!(key(&d, Key::Enter), Answer::Yes);
        assert_eq!(key(&d, Key::Char('n')), Answer::Discard);
        assert_eq!(key(&d, Key::Escape), Answer::Cancel);
        assert_eq!(key(&d, Key::Char('x')), Answer::Taken(true));
        assert_eq!(click_on(&d, Action::DialogSave), Answer::Yes);
        assert_eq!(click_on(&d, Action::DialogDiscard), Answer::Discard);
        assert_eq!(click_on(&d, Action::DialogCancel), Answer::Cancel);
        // Modal: a click beside the buttons and typed text are its own,
        // a move is not.
        let off = Event::MouseDown {
            button: MouseButton::Left,
            x: 1.0,
            y: 1.0,
            mods: Mods::default(),
        };
        assert_eq!(d.handle(&off, win()), Answer::Taken(true));
        assert_eq!(
            d.handle(&Event::Text("s".into()), win()),
            Answer::Taken(false)
        );
        let mv = Event::MouseMove {
            x: 1.0,
            y: 1.0,
            mods: Mods::default(),
        };
        assert_eq!(d.handle(&mv, win()), Answer::Ignored);
    }

    #[test]
    fn delete_has_no_discard_button_and_the_list_is_chosen_by_keys() {
        let d = Dialog::new("Delete the object Ball?", After::DeleteObject);
        let has = |d: &Dialog, a: Action| {
            d.widgets(win())
                .iter()
                .any(|w| matches!(w.kind, WidgetKind::Button { action, .. } if action == a))
        };
        assert!(!has(&d, Action::DialogDiscard));
        assert!(has(&d, Action::DialogSave));
        let mut r = Dialog::new("Untitled work was autosaved", After::Recover);
        // A single copy: the arrows and digits mean nothing.
        assert_eq!(key(&r, Key::Down), Answer::Taken(true));
        assert_eq!(key(&r, Key::Char('o')), Answer::Cancel);
        r.list = true;
        assert_eq!(key(&r, Key::Down), Answer::Step(1));
        assert_eq!(key(&r, Key::Up), Answer::Step(-1));
        assert_eq!(key(&r, Key::Char('3')), Answer::Pick(2));
        assert_eq!(key(&r, Key::Char('r')), Answer::Yes);
        assert_eq!(key(&r, Key::Char('d')), Answer::Discard);
    }
}
