//! The editor's side of `keyprops`: routes events to it and applies what it returns.

use crate::anim::{Animation, Interp, Key, Value, ValueKind};
use crate::editor::command::Command;
use crate::editor::fields::{format_fit, FieldId};
#[allow(unused_imports)]
use crate::editor::keyprops::*;
use crate::editor::keystrip::{row_name, KeyRef};
use crate::editor::panel::{button, label, w as widget, Action, Widget, WidgetKind};
use crate::editor::Editor;
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::Rect;

impl Editor {
    /// Whether the properties section shows the key panel.
    pub fn key_panel_shown(&self) -> bool {
        !self.keys.node_panel && !self.selected_keys().is_empty()
    }

    /// Rows the key panel needs (for the side panel split).
    pub(in crate::internals::editor) fn key_panel_rows(&self) -> i32 {
        7 + self.selected_keys().len().min(4) as i32
    }

    /// The number a key field shows (the primary key's).
    pub(in crate::internals::editor) fn key_field_number(
        &self,
        f: KeyField,
        anim: &Animation,
        keys: &[KeyRef],
    ) -> Option<f32> {
        let k = keys.first()?.get(anim)?;
        read(f, &k)
    }

    /// Text of a key panel field.
    pub(in crate::internals::editor) fn key_field_text(
        &self,
        f: KeyField,
        max_chars: usize,
    ) -> String {
        self.key_field_number(f, &self.scene.animation, &self.selected_keys())
            .map(|x| format_fit(x, max_chars))
            .unwrap_or_default()
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
        self.key_field_number(f, anim, keys)
    }

    /// A drag on a key field: previews `field` = start + dx · step.
    pub(in crate::internals::editor) fn drag_key_field(
        &mut self,
        id: FieldId,
        base: &Animation,
        keys: &[KeyRef],
        dx: f32,
    ) {
        let FieldId::Key(f) = id else { return };
        let Some(v0) = self.key_field_number(f, base, keys) else {
            return;
        };
        let v = v0 + dx * f.drag_step(keys[0].property);
        if let Ok((anim, refs)) = set_field(base, keys, f, v) {
            self.pending = None;
            self.scene.animation = anim;
            self.scene_rev += 1;
            self.keys.selected = refs;
        }
    }

    /// Release of a key field drag: one undo step.
    pub(in crate::internals::editor) fn finish_key_field_drag(
        &mut self,
        id: FieldId,
        before: Box<Animation>,
    ) {
        let after = Box::new(self.scene.animation.clone());
        self.push_applied(
            &format!("Drag key {id:?}"),
            Command::SetAnimation { before, after },
        );
    }

    /// Esc during a key field drag.
    pub(in crate::internals::editor) fn cancel_key_field_drag(
        &mut self,
        before: Animation,
        keys: Vec<KeyRef>,
    ) {
        self.scene.animation = before;
        self.scene_rev += 1;
        self.keys.selected = keys;
    }

    /// Enter in a key field: sets the typed number on the selected keys.
    pub(in crate::internals::editor) fn commit_key_field(&mut self, id: FieldId, x: f32) {
        let FieldId::Key(f) = id else { return };
        let keys = self.selected_keys();
        match set_field(&self.scene.animation, &keys, f, x) {
            Ok((anim, refs)) => {
                self.apply_key_edit(&format!("Set key {f:?}"), anim, Vec::new());
                self.set_key_selection(refs);
                let kept = keys.first().map(|k| f.clamp(k.property, x));
                let note = kept.and_then(|k| crate::editor::fields::clamp_note(&id.label(), x, k));
                if let Some(n) = note {
                    self.set_status(&n, false);
                }
            }
            Err(e) => self.set_status(&e, true),
        }
    }

    /// Key panel buttons.
    pub(in crate::internals::editor) fn key_action(&mut self, a: KeyAction) {
        let keys = self.selected_keys();
        match a {
            KeyAction::ShowNode => self.keys.node_panel = true,
            KeyAction::ShowKeys => self.keys.node_panel = false,
            KeyAction::Ease(e) => {
                let mut anim = self.scene.animation.clone();
                for k in &keys {
                    if let Some(t) = anim.track_mut(k.target()) {
                        if let Some(idx) = t.key_index_at(k.frame) {
                            if let Some(mut p) = t.key_params(idx) {
                                e.apply(&mut p);
                                // 0 and 1 are in range: cannot fail.
                                let _ = t.set_key_params(idx, p);
                            }
                        }
                    }
                }
                self.apply_key_edit(e.label(), anim, Vec::new());
            }
            KeyAction::Delete => self.delete_selected_keys(),
            KeyAction::Copy => self.copy_selected_keys(),
            KeyAction::Paste => self.paste_keys(),
            KeyAction::SelectRow(row) => self.select_row_keys(row),
            KeyAction::SelectChannel => self.graph_select_channel(),
            KeyAction::Interp(i) => {
                let mut anim = self.scene.animation.clone();
                for k in &keys {
                    if let Some(t) = anim.track_mut(k.target()) {
                        if let Some(idx) = t.key_index_at(k.frame) {
                            if let Some(mut p) = t.key_params(idx) {
                                p.interp = i;
                                // Ranges are unchanged: cannot fail.
                                let _ = t.set_key_params(idx, p);
                            }
                        }
                    }
                }
                let rot = keys
                    .first()
                    .is_some_and(|k| k.property.kind() == ValueKind::Rotation);
                self.apply_key_edit(&format!("Interpolation {}", i.name(rot)), anim, Vec::new());
            }
            KeyAction::Repeat(r) => {
                let mut anim = self.scene.animation.clone();
                for k in &keys {
                    if let Some(t) = anim.track_mut(k.target()) {
                        t.repeat = r;
                    }
                }
                let label = match r {
                    crate::anim::Repeat::Constant => "Track holds its end values",
                    crate::anim::Repeat::Loop => "Track loops its keys",
                };
                self.apply_key_edit(label, anim, Vec::new());
                self.set_status(label, false);
            }
            KeyAction::ToggleBool => {
                let Some(p) = keys.first() else { return };
                let Some(Value::Bool(b)) = p.get(&self.scene.animation).map(|k| k.value) else {
                    return;
                };
                let mut anim = self.scene.animation.clone();
                for k in keys.iter().filter(|k| k.property == p.property) {
                    let Some(key) = k.get(&anim) else { continue };
                    if let Some(t) = anim.track_mut(k.target()) {
                        let _ = t.insert_key(Key {
                            value: Value::Bool(!b),
                            ..key
                        });
                    }
                }
                self.apply_key_edit(if b { "Key off" } else { "Key on" }, anim, Vec::new());
            }
        }
    }

    /// The key panel's widgets in the properties section `r`.
    pub(in crate::internals::editor) fn key_panel_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        let keys = self.selected_keys();
        let Some(primary) = keys.first().copied() else {
            return;
        };
        let Some(pkey) = primary.get(&self.scene.animation) else {
            return;
        };
        let (h, body) = r.take_top(ROW);
        let bw = text::width("Object") + 6;
        let name = row_name(primary.property);
        let title = match keys.len() {
            1 if text::width(name) + text::width("Key: ") + bw + 12 <= h.w => {
                format!("Key: {name}")
            }
            1 => name.to_string(),
            n => format!("{n} keys"),
        };
        out.push(widget(h, WidgetKind::Header(title)));
        out.push(button(
            Rect::new(h.right() - bw - 2, h.y + 1, bw, h.h - 2),
            "Object",
            Action::Key(KeyAction::ShowNode),
            false,
        ));
        let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
        // The longest label ("Value", "Euler", "Frame") plus a gap, so a
        // label never runs into its value.
        let lw = 6 * CHAR_W;
        let mut y = body.y;
        let mut next = || {
            let r = (y + ROW <= body.bottom() + 1).then(|| Rect::new(body.x, y, body.w, ROW));
            y += ROW;
            r
        };
        if let Some(r) = next() {
            let (a, _) = r.take_left(r.w / 2 + lw / 2);
            field_row(out, a, "Frame", lw + CHAR_W, &[KeyField::Frame]);
        }
        let rotation = primary.property.kind() == ValueKind::Rotation;
        if let Some(r) = next() {
            match pkey.value {
                Value::Vec3(_) | Value::Rotation(_) => {
                    let name = match primary.property.kind() {
                        ValueKind::Color => "RGB",
                        ValueKind::Rotation => "Euler",
                        _ => "Value",
                    };
                    field_row(out, r, name, lw, &[0, 1, 2].map(KeyField::Value));
                }
                Value::Scalar(_) => field_row(out, r, "Value", lw, &[KeyField::Value(0)]),
                Value::Weights(w) => out.push(label(r, &format!("{} weights", w.len()), true)),
                Value::Bool(b) => {
                    let (a, rest) = r.take_left(lw);
                    out.push(label(a, "Value", true));
                    let bw = text::width("Off") + 10;
                    out.push(button(
                        Rect::new(rest.x, rest.y + 1, bw, rest.h - 2),
                        if b { "On" } else { "Off" },
                        Action::Key(KeyAction::ToggleBool),
                        b,
                    ));
                }
            }
        }
        if let Some(r) = next() {
            // Interpolation buttons use the whole row (no label).
            let rest = r;
            if matches!(pkey.value, Value::Bool(_)) {
                out.push(label(rest, "Steps (on/off)", true));
            } else {
                let n = 3;
                let bw = (rest.w - (n - 1) * 2) / n;
                for (i, it) in [Interp::Step, Interp::Linear, Interp::Tcb]
                    .into_iter()
                    .enumerate()
                {
                    out.push(button(
                        Rect::new(rest.x + i as i32 * (bw + 2), rest.y + 1, bw, rest.h - 2),
                        it.name(rotation),
                        Action::Key(KeyAction::Interp(it)),
                        pkey.interp == it,
                    ));
                }
            }
        }
        if let Some(r) = next() {
            field_row(
                out,
                r,
                "TCB",
                lw,
                &[KeyField::Tension, KeyField::Continuity, KeyField::Bias],
            );
        }
        if let Some(r) = next() {
            field_row(out, r, "Ease", lw, &[KeyField::EaseIn, KeyField::EaseOut]);
        }
        if let Some(r) = next() {
            // The track's repeat mode outside its keys (per track).
            use crate::anim::Repeat;
            let now = self
                .scene
                .animation
                .track(primary.target())
                .map(|t| t.repeat);
            let (a, rest) = r.take_left(lw);
            out.push(label(a, "After", true));
            let bw = (rest.w - 2) / 2;
            for (i, (name, rep)) in [("hold", Repeat::Constant), ("loop", Repeat::Loop)]
                .into_iter()
                .enumerate()
            {
                out.push(button(
                    Rect::new(rest.x + i as i32 * (bw + 2), rest.y + 1, bw, rest.h - 2),
                    name,
                    Action::Key(KeyAction::Repeat(rep)),
                    now == Some(rep),
                ));
            }
        }
        // The selected keys, one per row (frame and property).
        let shown = keys.len().min(4);
        for (i, k) in keys.iter().take(shown).enumerate() {
            let Some(r) = next() else { break };
            let more = keys.len() - shown;
            let s = if i + 1 == shown && more > 0 {
                format!("+{} more", more + 1)
            } else {
                format!(
                    "{:>5} {}",
                    crate::editor::fields::format_number(k.frame),
                    row_name(k.property)
                )
            };
            out.push(label(r, &s, i > 0));
        }
    }

    /// "Keys" at the right of the node properties header while keys are
    /// selected but the node is shown.
    pub(in crate::internals::editor) fn key_panel_switch(
        &self,
        header: Rect,
        out: &mut Vec<Widget>,
    ) {
        if self.keys.node_panel && !self.selected_keys().is_empty() {
            let bw = text::width("Keys") + 6;
            out.push(button(
                Rect::new(header.right() - bw - 2, header.y + 1, bw, header.h - 2),
                "Keys",
                Action::Key(KeyAction::ShowKeys),
                false,
            ));
        }
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

/// A label then equal fields for `ids` (the panel's row of key fields).
fn field_row(out: &mut Vec<Widget>, r: Rect, name: &str, label_w: i32, ids: &[KeyField]) {
    let ids: Vec<FieldId> = ids.iter().map(|k| FieldId::Key(*k)).collect();
    crate::editor::panel::field_row(out, r, name, label_w, &ids);
}
