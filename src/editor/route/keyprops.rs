//! The editor's side of the key panel component (`keypanel.rs`, a face
//! of the side panel): the context it sees, routing its buttons to it
//! and applying what it returns; the keys' menu commands it leaves go to
//! the key strip and graph editor. The mouse on its fields goes through
//! the side panel's faces (`route/faces.rs`).

use crate::editor::component::Response;
use crate::editor::keypanel::{KeyEvent, KeyPanelCtx};
use crate::editor::keyprops::KeyAction;
use crate::editor::panel::Widget;
use crate::editor::Editor;
use crate::ui::text::CHAR_W;
use crate::ui::Rect;

impl Editor {
    /// What the key panel sees.
    pub(in crate::internals::editor) fn key_panel_ctx(&self) -> KeyPanelCtx<'_> {
        KeyPanelCtx {
            anim: &self.scene.animation,
            keys: self.selected_keys(),
        }
    }

    /// Hands a button's `ev` to the key panel and applies its answer.
    /// Whether it was the panel's.
    fn key_panel_event(&mut self, ev: KeyEvent) -> bool {
        let mut panel = std::mem::take(&mut self.side.keys);
        let r: Response = panel.handle(ev, &self.key_panel_ctx());
        self.side.keys = panel;
        self.apply_response(r).is_some()
    }

    /// Whether the properties section shows the key panel.
    pub fn key_panel_shown(&self) -> bool {
        self.side.keys.shown(&self.key_panel_ctx())
    }

    /// Rows the key panel needs (for the side panel split).
    pub(in crate::internals::editor) fn key_panel_rows(&self) -> i32 {
        self.side.keys.rows(&self.key_panel_ctx())
    }

    /// Key panel buttons and the keys' menu: the panel answers its own;
    /// delete, copy, paste and selecting a row or channel are the key
    /// strip's and graph editor's.
    pub(in crate::internals::editor) fn key_action(&mut self, a: KeyAction) {
        if self.key_panel_event(KeyEvent::Button(a)) {
            return;
        }
        match a {
            KeyAction::Delete => self.delete_selected_keys(),
            KeyAction::Copy => self.copy_selected_keys(),
            KeyAction::Paste => self.paste_keys(),
            KeyAction::SelectRow(row) => self.select_row_keys(row),
            KeyAction::SelectChannel => self.graph_select_channel(),
            _ => {}
        }
    }

    /// The key panel's widgets in the properties section `r`.
    pub(in crate::internals::editor) fn key_panel_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        self.side.keys.widgets(r, &self.key_panel_ctx(), out);
    }

    /// "Keys" at the right of the node properties header while keys are
    /// selected but the node is shown.
    pub(in crate::internals::editor) fn key_panel_switch(
        &self,
        header: Rect,
        out: &mut Vec<Widget>,
    ) {
        self.side.keys.switch(header, &self.key_panel_ctx(), out);
    }

    /// The selection's key frames as lines that fit the side panel after
    /// the "Keys" label (wrapped, never cut).
    pub(in crate::internals::editor) fn key_list_lines(&self) -> Vec<String> {
        let Some(sel) = self.selection else {
            return Vec::new();
        };
        let frames = crate::editor::record::key_frames(&self.scene.animation, Some(sel));
        let chars = ((self.layout().side.w - 4 - 5 * CHAR_W) / CHAR_W).max(4) as usize;
        let mut lines: Vec<String> = Vec::new();
        for f in frames {
            let s = crate::editor::fields::format_number(f);
            match lines.last_mut() {
                Some(l) if l.len() + 1 + s.len() <= chars => {
                    l.push(' ');
                    l.push_str(&s);
                }
                _ => lines.push(s),
            }
        }
        lines
    }
}

impl Editor {
    /// Rows of the properties section: the key panel's, or the node's plus
    /// its key list row.
    pub(in crate::internals::editor) fn section_rows(&self) -> i32 {
        if let Some(n) = self.material_rows() {
            return n;
        }
        if self.key_panel_shown() {
            self.key_panel_rows()
        } else {
            self.prop_rows() + self.key_list_lines().len() as i32
        }
    }
}
