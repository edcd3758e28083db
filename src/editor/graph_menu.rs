//! The graph editor's context menu (a right click in its plot): the same
//! key edits as the key strip's (`keymenu.rs`), with "Select all on
//! channel" for the curve whose key was clicked. The graph component asks
//! for it with `Intent::ContextMenu`; the picks run as key actions.

use crate::editor::keymenu::{items, Over};
use crate::editor::keyprops::KeyAction;
use crate::editor::menu::Menu;
use crate::editor::panel::Action;
use crate::editor::Editor;

impl Editor {
    /// Opens the keys' menu at `at` for the graph's selected keys.
    pub(in crate::internals::editor) fn open_graph_menu(&mut self, at: (f32, f32)) {
        let keys = self.selected_keys();
        let channel = self.graph.as_ref().and_then(|g| g.menu_channel());
        let over = Over {
            keys: !keys.is_empty(),
            rotation: keys
                .first()
                .is_some_and(|k| k.property.kind() == crate::anim::ValueKind::Rotation),
            paste_at: (!self.keys.clipboard.keys.is_empty()).then_some(self.frame),
            select_all: channel.map(|_| {
                let a = Action::Key(KeyAction::SelectChannel);
                ("Select all on channel", a)
            }),
        };
        let list = items(&over);
        if list.is_empty() {
            return;
        }
        let title = match channel {
            Some(c) => format!("Keys: {}", c.name()),
            None => "Keys".into(),
        };
        self.menu = Some(Menu::new(&title, list, (at.0 as i32, at.1 as i32)));
    }

    /// "Select all on channel" from the graph's menu.
    pub(in crate::internals::editor) fn graph_select_channel(&mut self) {
        let Some(mut g) = self.graph.take() else {
            return;
        };
        let r = g.select_channel(&self.graph_ctx());
        self.graph = Some(g);
        let n = r.intents.len();
        self.apply_response(r);
        if n > 0 {
            let k = self.selected_keys().len();
            self.set_status(&format!("Selected {k} keys on the channel"), false);
        }
    }
}
