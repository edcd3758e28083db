//! The editor's side of the key strip component (`keystrip_ui.rs`): the
//! context it sees, routing events to it and applying what it returns,
//! the key selection's memory across undo, and the strip's key commands.

use crate::editor::gesture::Drag;
use crate::editor::keyedit::copy;
#[allow(unused_imports)]
use crate::editor::keystrip::*;
use crate::editor::keystrip_ui::StripCtx;
use crate::editor::Editor;
use crate::input::{Event, Key as KeyName, Mods, MouseButton};
use crate::ui::{Painter, Rect};

impl Editor {
    // ----- state -----

    /// The selected keys that still exist on the selected node.
    pub fn selected_keys(&self) -> Vec<KeyRef> {
        self.keys
            .live_selection(&self.scene.animation, self.selection)
    }

    pub(in crate::internals::editor) fn set_key_selection(&mut self, keys: Vec<KeyRef>) {
        self.keys.selected = keys;
        self.remember_key_selection();
        self.side.keys.node_shown = false;
    }

    /// Notes the key selection for the current animation (nothing for an
    /// empty selection).
    pub(in crate::internals::editor) fn remember_key_selection(&mut self) {
        if self.keys.selected.is_empty() {
            return;
        }
        let anim = &self.scene.animation;
        let sel = self.keys.selected.clone();
        let memo = &mut self.keys.memo;
        match memo.iter().position(|(a, _)| a == anim) {
            Some(i) => {
                memo.remove(i);
            }
            None if memo.len() >= MEMO => {
                memo.remove(0);
            }
            None => {}
        }
        memo.push((anim.clone(), sel));
    }

    /// After any change to the scene (edits, undo, redo): a key selection
    /// that still exists is remembered with the animation; one whose keys
    /// went away is replaced by the selection remembered with the animation
    /// now shown (undo of a move selects the keys where they were), else
    /// the missing keys are dropped.
    pub(in crate::internals::editor) fn key_selection_after_change(&mut self) {
        let anim = &self.scene.animation;
        if self.keys.selected.iter().all(|k| k.get(anim).is_some()) {
            self.remember_key_selection();
            return;
        }
        let found = self
            .keys
            .memo
            .iter()
            .rev()
            .find(|(a, _)| a == anim)
            .map(|(_, s)| s.clone());
        self.keys.selected = match found {
            Some(s) => s,
            None => {
                let mut s = std::mem::take(&mut self.keys.selected);
                s.retain(|k| k.get(anim).is_some());
                s
            }
        };
    }

    /// Whether the key is selected.
    pub fn is_key_selected(&self, k: &KeyRef) -> bool {
        self.keys.is_selected(k)
    }

    /// What the strip sees: the animation, the selected object, the frame,
    /// the layout and the frames the ruler shows.
    pub fn strip_ctx(&self) -> StripCtx<'_> {
        StripCtx {
            keyed: self.keyed(),
            layout: self.layout(),
            span: self.time_span(),
        }
    }

    /// The visible rows with their rectangles.
    pub fn key_strip_layout(&self) -> Vec<(Row, Rect)> {
        self.keys.rows(&self.strip_ctx())
    }

    /// Rows in the strip: (first shown, all, how many fit).
    pub fn key_strip_scroll(&self) -> (usize, usize, usize) {
        self.keys.scroll_state(&self.strip_ctx())
    }

    /// The keys a row shows, grouped per marker: (frame, keys at it).
    pub fn row_markers(&self, row: Row) -> Vec<(f32, Vec<KeyRef>)> {
        self.keys.markers(&self.strip_ctx(), row)
    }

    /// Window point of the marker for `row` at `frame` (for tests and
    /// scripts that aim at keys).
    pub fn key_marker_at(&self, row: Row, frame: f32) -> Option<(f32, f32)> {
        self.keys.marker_at(&self.strip_ctx(), row, frame)
    }

    /// What is under (x, y) in the strip.
    pub fn key_strip_hit(&self, x: f32, y: f32) -> Option<Hit> {
        self.keys.hit(&self.strip_ctx(), x, y)
    }

    /// Whether `x` is on the current-frame line (within 2 px).
    pub(in crate::internals::editor) fn near_cursor(&self, x: f32) -> bool {
        let l = self.layout();
        let dur = self.scene.settings.duration;
        let cx = l
            .frame_to_x_in(self.frame.clamp(0.0, dur.max(0.0)), self.time_span())
            .floor();
        let (x0, x1) = l.ruler_span();
        // Zoomed or panned away from the cursor: there is none to grab.
        (x0 - 0.5..=x1 + 0.5).contains(&cx) && (x - (cx + 0.5)).abs() <= 2.5
    }

    // ----- mouse -----

    /// A press in the key rows: on the current-frame line it seeks, else
    /// the strip takes it.
    pub(in crate::internals::editor) fn key_strip_press(
        &mut self,
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
    ) {
        if matches!(self.key_strip_hit(x, y), Some(Hit::Empty)) && self.near_cursor(x) {
            // The current-frame line runs through the strip: grab it.
            self.drag = Drag::Seek;
            return;
        }
        self.strip_event(&Event::MouseDown { button, x, y, mods });
    }

    /// Offers `ev` to the key strip: `Some(redraw)` when it took it. A
    /// drag the strip runs is the editor's one gesture (`Drag::Keys`).
    pub(in crate::internals::editor) fn strip_event(&mut self, ev: &Event) -> Option<bool> {
        let mut strip = std::mem::take(&mut self.keys);
        let r = strip.handle(ev, &self.strip_ctx());
        let dragging = strip.is_dragging();
        self.keys = strip;
        match (dragging, matches!(self.drag, Drag::Keys)) {
            (true, false) => self.drag = Drag::Keys,
            (false, true) => self.drag = Drag::None,
            _ => {}
        }
        self.apply_response(r)
    }

    pub(in crate::internals::editor) fn draw_key_strip(&self, p: &mut Painter) {
        let ctx = self.strip_ctx();
        let hint = match self.selection {
            None => Some("Select an object to see its keys here".to_string()),
            Some(_) if self.keys.markers(&ctx, Row::Summary).is_empty() => {
                Some(self.material_keys_hint().unwrap_or_else(|| {
                    "No keys yet: K keys the selection, R records changes".to_string()
                }))
            }
            Some(_) => None,
        };
        self.keys.draw(p, &ctx, hint.as_deref());
    }

    // ----- keyboard -----

    /// Keys the strip handles (returns true when it used the key): Esc
    /// cancels a strip drag or clears the key selection, Delete removes
    /// selected keys, Ctrl+C copies them, Ctrl+V pastes at the current frame.
    /// Copies the selected keys to the strip's clipboard (Ctrl+C).
    pub(in crate::internals::editor) fn copy_selected_keys(&mut self) {
        self.keys.clipboard = copy(&self.scene.animation, &self.selected_keys());
        let n = self.keys.clipboard.keys.len();
        self.set_status(
            &format!("Copied {n} key{}", if n == 1 { "" } else { "s" }),
            false,
        );
    }

    /// Selects every key of `row` (the summary: every key of the selection).
    pub(in crate::internals::editor) fn select_row_keys(&mut self, row: Row) {
        let Some(sel) = self.selection else { return };
        let ks: Vec<KeyRef> = match row {
            Row::Track(p) => track_keys(&self.scene.animation, sel, p),
            _ => self
                .row_markers(Row::Summary)
                .into_iter()
                .flat_map(|(_, ks)| ks)
                .collect(),
        };
        let n = ks.len();
        self.set_key_selection(ks);
        self.set_status(&format!("Selected {n} keys on the row"), false);
    }

    /// Right click in the key strip: selects the key under the mouse when
    /// it is not selected yet, then opens the strip's context menu
    /// (interpolation, ease, delete, copy/paste, select the row).
    pub(in crate::internals::editor) fn open_strip_menu(&mut self, x: f32, y: f32) {
        use crate::editor::keyprops::KeyAction as K;
        use crate::editor::menu::Menu;
        use crate::editor::panel::Action;
        let row = self
            .key_strip_layout()
            .into_iter()
            .find(|(_, r)| r.contains(x, y))
            .map(|(row, _)| row);
        if let Some(Hit::Keys(ks)) = self.key_strip_hit(x, y) {
            let current = self.selected_keys();
            if !ks.iter().all(|k| current.iter().any(|c| c.same(k))) {
                self.set_key_selection(ks);
            }
        }
        let keys = self.selected_keys();
        let over = crate::editor::keymenu::Over {
            keys: !keys.is_empty(),
            rotation: keys
                .first()
                .is_some_and(|k| k.property.kind() == crate::anim::ValueKind::Rotation),
            paste_at: (!self.keys.clipboard.keys.is_empty()).then_some(self.frame),
            select_all: match row {
                Some(r @ (Row::Summary | Row::Track(_))) => {
                    Some(("Select all on row", Action::Key(K::SelectRow(r))))
                }
                _ => None,
            },
        };
        let items = crate::editor::keymenu::items(&over);
        if items.is_empty() {
            return;
        }
        self.menu = Some(Menu::new("Keys", items, (x as i32, y as i32)));
    }

    pub(in crate::internals::editor) fn key_strip_key(&mut self, key: KeyName, m: Mods) -> bool {
        if matches!(self.drag, Drag::Keys) {
            // The strip's drag takes every key (Esc cancels it).
            self.strip_event(&Event::KeyDown { key, mods: m });
            return true;
        }
        let has = !self.selected_keys().is_empty();
        match (key, m.ctrl) {
            (KeyName::Escape, _) if has => {
                self.set_key_selection(Vec::new());
                true
            }
            (KeyName::Delete, _) if has => {
                self.delete_selected_keys();
                true
            }
            (KeyName::Char('c'), true) if has => {
                self.copy_selected_keys();
                true
            }
            (KeyName::Char('v'), true) if !self.keys.clipboard.keys.is_empty() => {
                self.paste_keys();
                true
            }
            _ => false,
        }
    }
}
