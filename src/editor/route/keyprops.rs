//! The editor's side of the key panel component (`keypanel.rs`): the
//! context it sees, routing its buttons and field gestures to it and
//! applying what it returns; the keys' menu commands it leaves go to the
//! key strip and graph editor.

use crate::anim::Animation;
use crate::editor::component::{Intent, Response};
use crate::editor::fields::FieldId;
use crate::editor::keypanel::{KeyEvent, KeyPanelCtx};
use crate::editor::keyprops::{KeyAction, KeyField};
use crate::editor::keystrip::KeyRef;
use crate::editor::panel::{label, Widget};
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

    /// Hands `ev` to the key panel and applies its answer (a key edit drops
    /// a change not yet keyed, as every key edit does). Whether it was the
    /// panel's.
    fn key_panel_event(&mut self, ev: KeyEvent) -> bool {
        let mut panel = self.key_panel;
        let r: Response = panel.handle(ev, &self.key_panel_ctx());
        self.key_panel = panel;
        let edits = |i: &Intent| matches!(i, Intent::Preview(_) | Intent::Commit { .. });
        if r.intents.iter().any(edits) {
            self.pending = None;
        }
        self.apply_response(r).is_some()
    }

    /// Whether the properties section shows the key panel.
    pub fn key_panel_shown(&self) -> bool {
        self.key_panel.shown(&self.key_panel_ctx())
    }

    /// Rows the key panel needs (for the side panel split).
    pub(in crate::internals::editor) fn key_panel_rows(&self) -> i32 {
        self.key_panel.rows(&self.key_panel_ctx())
    }

    /// Text of a key panel field.
    pub(in crate::internals::editor) fn key_field_text(
        &self,
        f: KeyField,
        max_chars: usize,
    ) -> String {
        self.key_panel
            .field_text(f, max_chars, &self.key_panel_ctx())
    }

    /// The base of a key field drag or edit: the animation and the keys.
    pub(in crate::internals::editor) fn key_field_base(
        &self,
    ) -> Option<(Box<Animation>, Vec<KeyRef>)> {
        let keys = self.selected_keys();
        (!keys.is_empty()).then(|| (Box::new(self.scene.animation.clone()), keys))
    }

    /// The value a field started from.
    pub(in crate::internals::editor) fn key_field_start(
        &self,
        id: FieldId,
        anim: &Animation,
        keys: &[KeyRef],
    ) -> Option<f32> {
        let FieldId::Key(f) = id else { return None };
        crate::editor::keypanel::KeyPanel::number(f, anim, keys)
    }

    /// A drag on a key field: previews `field` = start + dx · step.
    pub(in crate::internals::editor) fn drag_key_field(
        &mut self,
        id: FieldId,
        base: &Animation,
        keys: &[KeyRef],
        dx: f32,
    ) {
        if let FieldId::Key(field) = id {
            self.key_panel_event(KeyEvent::Drag {
                field,
                base,
                keys,
                dx,
            });
        }
    }

    /// Release of a key field drag: one undo step.
    pub(in crate::internals::editor) fn finish_key_field_drag(
        &mut self,
        id: FieldId,
        before: Box<Animation>,
    ) {
        if let FieldId::Key(field) = id {
            self.key_panel_event(KeyEvent::Release {
                field,
                before: &before,
            });
        }
    }

    /// Esc during a key field drag.
    pub(in crate::internals::editor) fn cancel_key_field_drag(
        &mut self,
        before: Animation,
        keys: Vec<KeyRef>,
    ) {
        self.key_panel_event(KeyEvent::Cancel {
            before: &before,
            keys: &keys,
        });
    }

    /// Enter in a key field: sets the typed number on the selected keys.
    pub(in crate::internals::editor) fn commit_key_field(&mut self, id: FieldId, x: f32) {
        if let FieldId::Key(field) = id {
            self.key_panel_event(KeyEvent::Typed { field, value: x });
        }
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
        self.key_panel.widgets(r, &self.key_panel_ctx(), out);
    }

    /// "Keys" at the right of the node properties header while keys are
    /// selected but the node is shown.
    pub(in crate::internals::editor) fn key_panel_switch(
        &self,
        header: Rect,
        out: &mut Vec<Widget>,
    ) {
        self.key_panel.switch(header, &self.key_panel_ctx(), out);
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

    /// Line `i` of the node panel's list of the selection's key frames.
    pub(in crate::internals::editor) fn key_list_row(
        &self,
        i: usize,
        r: Rect,
        out: &mut Vec<Widget>,
    ) {
        let lines = self.key_list_lines();
        let Some(line) = lines.get(i) else { return };
        let (a, b) = r.take_left(5 * CHAR_W);
        if i == 0 {
            out.push(label(a, "Keys", true));
        }
        out.push(label(b, line, false));
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
