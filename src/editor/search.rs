//! F3 command search: every action with its shortcut in one list; typing
//! filters it (each typed word must appear in the name, any case, so
//! `box` finds "Add Box"), Up/Down move, Enter runs the highlighted match
//! (the first one unless moved), Esc closes. A component like the menus
//! it is drawn with ([`Menu`]); a pick comes back as the item's
//! [`Action`].

use super::create::NewThing;
use super::manip::Tool;
use super::menu::{Menu, MenuItem, Reply};
use super::panel::Action;
use super::views::ViewCmd;
use crate::input::{Event, Key};
use crate::ui::layout::ROW;
use crate::ui::Rect;

/// The open search.
#[derive(Clone, Debug, PartialEq)]
pub struct Search {
    pub query: String,
    all: Vec<MenuItem>,
    /// The matches shown (as many as fit the window).
    pub menu: Menu,
}

/// Every command the search offers, in a stable order.
pub fn commands() -> Vec<MenuItem> {
    let mut v = vec![
        MenuItem::new("New scene", "Ctrl+N", Action::New),
        MenuItem::new("Open...", "Ctrl+O", Action::Open),
        MenuItem::new("Import a model...", "Ctrl+I", Action::Import),
        MenuItem::new("Save", "Ctrl+S", Action::Save),
        MenuItem::new("Save as...", "Ctrl+Shift+S", Action::SaveAs),
        MenuItem::new("Undo", "Ctrl+Z", Action::Undo),
        MenuItem::new("Redo", "Ctrl+Y", Action::Redo),
        MenuItem::new("Play / stop", "Space", Action::Play),
        MenuItem::new("Record mode", "R", Action::Record),
        MenuItem::new("Key the selection", "K", Action::KeySelection),
        MenuItem::new("Clear the selection's keys", "Alt+I", Action::ClearKeys),
        MenuItem::new("Move tool", "W", Action::Tool(Tool::Translate)),
        MenuItem::new("Rotate tool", "E", Action::Tool(Tool::Rotate)),
        MenuItem::new("Scale tool", "T", Action::Tool(Tool::Scale)),
        MenuItem::new("Duplicate", "Shift+D", Action::Duplicate),
        MenuItem::new("Delete", "Delete", Action::Delete),
        MenuItem::new("Rename", "", Action::Rename),
        MenuItem::new("Add menu", "Shift+A", Action::AddMenu),
    ];
    for t in NewThing::ALL {
        let label = format!("Add {}", t.label());
        v.push(MenuItem::new(&label, "Shift+A", Action::Add(t)));
    }
    for c in ViewCmd::ALL {
        let label = format!("View: {}", c.label());
        v.push(MenuItem::new(&label, c.shortcut(), Action::View(c)));
    }
    v.extend([
        MenuItem::new("Grid on/off", "G", Action::Grid),
        MenuItem::new("Onion skin", "O", Action::Onion),
        MenuItem::new("Graph editor", "Shift+F6", Action::ToggleGraph),
        MenuItem::new("Preview range: type its frames", "[ ]", Action::TypePreview),
        MenuItem::new(
            "Material panel",
            "M",
            Action::Material(super::material::MatAction::Open),
        ),
        MenuItem::new("Viewport render style", "", Action::ViewStyle),
        MenuItem::new("Select / view mode", "Esc", Action::Mode),
    ]);
    v
}

/// Whether every whitespace-separated word of `query` appears in `label`
/// (ignoring case).
pub fn matches(label: &str, query: &str) -> bool {
    let l = label.to_lowercase();
    query
        .split_whitespace()
        .all(|w| l.contains(&w.to_lowercase()))
}

impl Search {
    /// Opens the search over `window` with every command listed.
    pub fn new(window: Rect) -> Search {
        let at = (window.x + window.w / 2 - 150, window.y + 30);
        let mut s = Search {
            query: String::new(),
            all: commands(),
            menu: Menu::new("", Vec::new(), at),
        };
        s.refilter(window);
        s
    }

    fn refilter(&mut self, window: Rect) {
        let fit = ((window.h - 6) / ROW - 2).max(1) as usize;
        self.menu.items = self
            .all
            .iter()
            .filter(|i| matches(&i.label, &self.query))
            .take(fit)
            .cloned()
            .collect();
        self.menu.hover = (!self.menu.items.is_empty()).then_some(0);
        self.menu.title = if self.menu.items.is_empty() {
            format!("Search: {}_  (nothing matches)", self.query)
        } else {
            format!("Search: {}_", self.query)
        };
    }

    /// Takes every input event while open (modal).
    pub fn handle(&mut self, ev: &Event, window: Rect) -> Reply {
        match ev {
            Event::Text(t) => {
                self.query.push_str(t);
                self.refilter(window);
                Reply::Stay(true)
            }
            Event::KeyDown { key, .. } => match key {
                Key::Backspace => {
                    self.query.pop();
                    self.refilter(window);
                    Reply::Stay(true)
                }
                // Letters arrive as text: no first-letter picking here.
                Key::Char(_) | Key::Space => Reply::Stay(false),
                _ => self.menu.handle(ev, window),
            },
            _ => self.menu.handle(ev, window),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Mods;

    #[test]
    fn typing_filters_and_enter_runs_the_first_match() {
        let win = Rect::new(0, 0, 480, 320);
        let mut s = Search::new(win);
        assert!(!s.menu.items.is_empty());
        s.handle(&Event::Text("Box".into()), win);
        assert_eq!(s.menu.items[0].label, "Add Box");
        let enter = Event::KeyDown {
            key: Key::Enter,
            mods: Mods::NONE,
        };
        assert_eq!(
            s.handle(&enter, win),
            Reply::Pick(Action::Add(NewThing::Box))
        );
        // Two words, any order and case: "top view".
        let mut s = Search::new(win);
        s.handle(&Event::Text("TOP view".into()), win);
        assert_eq!(s.menu.items.len(), 1);
        assert_eq!(s.menu.items[0].shortcut, "Num 7");
        s.handle(&Event::Text("zz".into()), win);
        assert!(s.menu.items.is_empty() && s.menu.title.contains("nothing matches"));
        assert_eq!(s.handle(&enter, win), Reply::Close);
        let bs = Event::KeyDown {
            key: Key::Backspace,
            mods: Mods::NONE,
        };
        s.handle(&bs, win);
        s.handle(&bs, win);
        assert_eq!(s.menu.items.len(), 1);
        let esc = Event::KeyDown {
            key: Key::Escape,
            mods: Mods::NONE,
        };
        assert_eq!(s.handle(&esc, win), Reply::Close);
    }

    #[test]
    fn every_command_has_a_name_and_the_list_fits_the_window() {
        let all = commands();
        assert!(all.len() > 30);
        let win = Rect::new(0, 0, 480, 320);
        let s = Search::new(win);
        let r = s.menu.rect(win);
        assert!(r.bottom() <= win.bottom() && r.h >= ROW * 3);
        let last = s.menu.item_rect(win, s.menu.items.len() - 1);
        assert!(last.bottom() <= r.bottom(), "{last:?} inside {r:?}");
    }
}
