//! The file browser as a component: it lays out its own widgets in the box
//! the editor gives it and answers events itself ([`Browser::handle`]),
//! returning a [`Reply`] — a path to use, or closing — that the editor
//! turns into file requests. It never names the `Editor` (the folder
//! listing and typed path are `browser.rs`).

use super::browser::Browser;
use super::panel::{button, label, w, Action, Widget, WidgetKind};
use super::widget_paint;
use crate::input::{Event, Key, MouseButton};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{theme, widgets, Painter, Rect};
use std::path::PathBuf;

/// The browser's answer to one event.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// Not the browser's event (the editor routes it on).
    Ignored,
    /// Taken; true when the picture changed.
    Taken(bool),
    /// The chosen file: the editor opens, imports or saves it.
    Use(PathBuf),
    /// Closed without a choice.
    Cancel,
}

impl Browser {
    /// The widgets of the browser in its box `r`.
    pub fn widgets(&self, r: Rect) -> Vec<Widget> {
        let mut out = Vec::new();
        let (title, rest) = r.take_top(ROW + 2);
        out.push(w(title, WidgetKind::Header(self.purpose.title().into())));
        let inner = rest.inset(4);
        let (path_row, rest) = inner.take_top(ROW + 2);
        out.push(w(path_row, WidgetKind::PathInput));
        let (list, buttons) = rest.take_top(rest.h - ROW - 6);
        let list = Rect::new(list.x, list.y + 3, list.w, list.h - 3);
        let cap = (list.h / ROW).max(0) as usize;
        for (i, _) in self.entries.iter().enumerate().skip(self.scroll).take(cap) {
            let y = list.y + (i - self.scroll) as i32 * ROW;
            out.push(w(Rect::new(list.x, y, list.w, ROW), WidgetKind::Entry(i)));
        }
        let by = buttons.y + 4;
        let cw = text::width("Cancel") + 10;
        let aw = text::width(self.purpose.verb()) + 10;
        let uw = text::width("Up") + 10;
        out.push(button(
            Rect::new(buttons.right() - cw, by, cw, ROW + 2),
            "Cancel",
            Action::BrowserCancel,
            false,
        ));
        out.push(button(
            Rect::new(buttons.right() - cw - aw - 4, by, aw, ROW + 2),
            self.purpose.verb(),
            Action::BrowserAccept,
            true,
        ));
        out.push(button(
            Rect::new(buttons.x, by, uw, ROW + 2),
            "Up",
            Action::BrowserUp,
            false,
        ));
        if let Some(m) = &self.message {
            let x = buttons.x + uw + 6;
            let mw = buttons.right() - cw - aw - 10 - x;
            out.push(label(Rect::new(x, by + 1, mw, ROW), m, true));
        }
        out
    }

    /// One event while the browser is open (it is modal: every press,
    /// key, typed text and wheel turn is its own); `r` is its box.
    pub fn handle(&mut self, ev: &Event, r: Rect) -> Reply {
        match ev {
            Event::KeyDown { key, .. } => self.key(*key, r),
            Event::Text(s) => {
                self.type_text(s);
                Reply::Taken(true)
            }
            Event::Wheel { delta, .. } => {
                let steps = (delta.abs().ceil() as usize).max(1) * 3;
                self.scroll = if *delta > 0.0 {
                    self.scroll.saturating_sub(steps)
                } else {
                    (self.scroll + steps).min(self.entries.len().saturating_sub(1))
                };
                Reply::Taken(true)
            }
            Event::MouseDown { button, x, y, .. } => match button {
                MouseButton::Left => self.click(*x, *y, r),
                _ => Reply::Taken(true),
            },
            _ => Reply::Ignored,
        }
    }

    /// Enter or the accept button: a folder is entered, a file is used.
    pub fn choose(&mut self) -> Reply {
        match self.accept() {
            Some(p) => Reply::Use(p),
            None => Reply::Taken(true),
        }
    }

    /// The Up button: the parent folder.
    pub fn up(&mut self) {
        if let Some(p) = self.dir.parent().map(|p| p.to_path_buf()) {
            self.enter(&p);
        }
    }

    /// Draws the browser in its box `r` over the dimmed window `win`;
    /// `mouse` lights the row or button under it (`None` during a drag).
    pub fn draw(&self, p: &mut Painter, r: Rect, win: Rect, mouse: Option<(f32, f32)>) {
        p.fill_rect_alpha(win, 0x000000, 110);
        p.fill_rect(r, theme::DIALOG);
        p.stroke_rect(r, theme::BORDER);
        for w in self.widgets(r) {
            match &w.kind {
                WidgetKind::PathInput => {
                    widgets::field(p, w.rect, &self.input, false, true);
                }
                WidgetKind::Entry(i) => {
                    let e = &self.entries[*i];
                    let label = if e.is_dir {
                        format!("{}/", e.name)
                    } else {
                        e.name.clone()
                    };
                    let selected = self.highlight == Some(*i);
                    let hot = mouse.is_some_and(|(x, y)| w.rect.contains(x, y));
                    widgets::list_row(p, w.rect, &label, 0, selected, hot);
                    if e.is_dir {
                        let x = w.rect.right() - 4 * CHAR_W;
                        p.text(x, w.rect.y, "dir", theme::TEXT_DIM);
                    }
                }
                _ => {
                    widget_paint::plain(p, &w, mouse);
                }
            }
        }
        if self.entries.is_empty() {
            p.text(
                r.x + 8,
                r.y + 3 * ROW + 4,
                "(empty folder)",
                theme::TEXT_DIM,
            );
        }
    }

    fn key(&mut self, key: Key, r: Rect) -> Reply {
        let rows = ((r.h - 3 * 16 - 20) / 16).max(1) as usize;
        match key {
            Key::Escape => return Reply::Cancel,
            Key::Enter => return self.choose(),
            Key::Tab => self.complete(),
            Key::Backspace => {
                self.input.pop();
                self.message = None;
            }
            Key::Up | Key::Down => {
                self.step(if key == Key::Up { -1 } else { 1 });
                self.scroll_to_highlight(rows);
            }
            _ => {}
        }
        Reply::Taken(true)
    }

    fn click(&mut self, x: f32, y: f32, r: Rect) -> Reply {
        let hit = self.widgets(r).into_iter().find(|w| w.rect.contains(x, y));
        match hit.map(|w| w.kind) {
            Some(WidgetKind::Button { action, .. }) => match action {
                Action::BrowserAccept => return self.choose(),
                Action::BrowserCancel => return Reply::Cancel,
                Action::BrowserUp => self.up(),
                _ => {}
            },
            Some(WidgetKind::Entry(i)) => {
                let Some(e) = self.entries.get(i).cloned() else {
                    return Reply::Taken(true);
                };
                if e.is_dir {
                    match e.name.as_str() {
                        ".." => self.up(),
                        name => {
                            let t = self.dir.join(name);
                            self.enter(&t);
                        }
                    }
                } else if self.highlight == Some(i) {
                    // A second click on the same file accepts it.
                    return self.choose();
                } else {
                    self.highlight = Some(i);
                    self.input = self.entry_path_text(i);
                }
            }
            _ => {}
        }
        Reply::Taken(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::editor::browser::tests::settle;
    use crate::editor::browser::Purpose;
    use crate::input::Mods;

    fn press(b: &mut Browser, key: Key, r: Rect) -> Reply {
        b.handle(
            &Event::KeyDown {
                key,
                mods: Mods::NONE,
            },
            r,
        )
    }

    fn click(b: &mut Browser, kind: &WidgetKind, r: Rect) -> Reply {
        let at = b
            .widgets(r)
            .into_iter()
            .find(|w| &w.kind == kind)
            .expect("widget shown");
        let (x, y) = (at.rect.x as f32 + 4.0, at.rect.y as f32 + 4.0);
        let button = MouseButton::Left;
        let reply = b.handle(
            &Event::MouseDown {
                button,
                x,
                y,
                mods: Mods::NONE,
            },
            r,
        );
        settle(b);
        reply
    }

    /// Driven by events alone, without an editor: folders are entered,
    /// a file is highlighted by one click and chosen by the second, Up and
    /// Esc answer as the editor expects.
    #[test]
    fn the_browser_answers_events_by_itself() {
        let d = std::env::temp_dir().join(format!("animed-browser-ui-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(d.join("models")).unwrap();
        std::fs::write(d.join("models/walk.wrl"), b"x").unwrap();
        let r = Rect::new(0, 0, 400, 300);
        let mut b = Browser::new(Purpose::Open, &d, None);
        settle(&mut b);
        let models = b.entries.iter().position(|e| e.name == "models").unwrap();
        assert_eq!(
            click(&mut b, &WidgetKind::Entry(models), r),
            Reply::Taken(true)
        );
        assert!(b.dir.ends_with("models"), "{}", b.dir.display());
        let walk = b.entries.iter().position(|e| e.name == "walk.wrl").unwrap();
        assert_eq!(
            click(&mut b, &WidgetKind::Entry(walk), r),
            Reply::Taken(true)
        );
        assert_eq!(b.highlight, Some(walk));
        let chosen = click(&mut b, &WidgetKind::Entry(walk), r);
        assert_eq!(chosen, Reply::Use(d.join("models/walk.wrl")));
        let up = WidgetKind::Button {
            label: "Up".into(),
            action: Action::BrowserUp,
            on: false,
        };
        click(&mut b, &up, r);
        assert_eq!(b.dir, d);
        // Typing a missing file and Enter: refused with a message.
        b.handle(&Event::Text("nothing.wrl".into()), r);
        assert!(b.input.ends_with("nothing.wrl"), "{}", b.input);
        assert_eq!(press(&mut b, Key::Enter, r), Reply::Taken(true));
        assert_eq!(settle(&mut b), None);
        assert!(b.message.as_deref().is_some_and(|m| m.contains("no file")));
        assert_eq!(press(&mut b, Key::Escape, r), Reply::Cancel);
        assert_eq!(b.handle(&Event::Tick { time: 1.0 }, r), Reply::Ignored);
        std::fs::remove_dir_all(&d).unwrap();
    }
}
