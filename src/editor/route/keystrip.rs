//! The editor's side of `keystrip`: routes events to it and applies what it returns.

use crate::anim::{Animation, KEY_EPS};
use crate::editor::command::Command;
use crate::editor::gesture::Drag;
use crate::editor::keyedit::{copy, retime};
#[allow(unused_imports)]
use crate::editor::keystrip::*;
use crate::editor::Editor;
use crate::input::{Key as KeyName, Mods};
use crate::ui::layout::KEY_ROW_H;
use crate::ui::Rect;

impl Editor {
    // ----- state -----

    /// The selected keys that still exist on the selected node.
    pub fn selected_keys(&self) -> Vec<KeyRef> {
        let Some(sel) = self.selection else {
            return Vec::new();
        };
        let anim = &self.scene.animation;
        let mut out: Vec<KeyRef> = Vec::new();
        for k in &self.keys.selected {
            if k.node == sel && k.get(anim).is_some() && !out.iter().any(|o| o.same(k)) {
                out.push(*k);
            }
        }
        out
    }

    pub(in crate::internals::editor) fn set_key_selection(&mut self, keys: Vec<KeyRef>) {
        self.keys.selected = keys;
        self.remember_key_selection();
        self.keys.node_panel = false;
        // The properties section changes size: show the selection's row
        // in the lists again.
        self.revealed = None;
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
        self.keys.selected.iter().any(|s| s.same(k))
    }

    /// Rows the strip wants (0 when the selection is not animated).
    pub(in crate::internals::editor) fn key_strip_rows(&self) -> usize {
        let Some(sel) = self.selection else { return 0 };
        let props = animated_properties(&self.scene.animation, sel);
        match (props.len(), self.keys.collapsed) {
            (0, _) => 0,
            (_, true) => 1,
            (n, false) => n + 1,
        }
    }

    /// The visible rows with their rectangles (the last one says how many
    /// did not fit when the strip is too short).
    pub fn key_strip_layout(&self) -> Vec<(Row, Rect)> {
        let l = self.layout();
        let Some(sel) = self.selection else {
            return Vec::new();
        };
        let mut rows = vec![Row::Summary];
        if !self.keys.collapsed {
            rows.extend(
                animated_properties(&self.scene.animation, sel)
                    .into_iter()
                    .map(Row::Track),
            );
        }
        let cap = (l.key_rows.h / KEY_ROW_H).max(0) as usize;
        let first = self.keys.scroll.min(rows.len().saturating_sub(cap));
        rows.into_iter()
            .skip(first)
            .take(cap)
            .enumerate()
            .map(|(i, r)| {
                let y = l.key_rows.y + i as i32 * KEY_ROW_H;
                (r, Rect::new(l.key_rows.x, y, l.key_rows.w, KEY_ROW_H))
            })
            .collect()
    }

    /// Rows in the strip: (first shown, all, how many fit).
    pub fn key_strip_scroll(&self) -> (usize, usize, usize) {
        let all = self.key_strip_rows();
        let cap = (self.layout().key_rows.h / KEY_ROW_H).max(0) as usize;
        (self.keys.scroll.min(all.saturating_sub(cap)), all, cap)
    }

    /// Wheel over the strip: scrolls its rows when they do not all fit.
    pub(in crate::internals::editor) fn scroll_key_rows(&mut self, delta: f32) -> bool {
        let (first, all, cap) = self.key_strip_scroll();
        if all <= cap {
            return false;
        }
        let n = (delta.abs().ceil() as usize).max(1);
        self.keys.scroll = if delta > 0.0 {
            first.saturating_sub(n)
        } else {
            (first + n).min(all - cap)
        };
        true
    }

    /// The keys a row shows, grouped per marker: (frame, keys at it).
    pub fn row_markers(&self, row: Row) -> Vec<(f32, Vec<KeyRef>)> {
        let Some(sel) = self.selection else {
            return Vec::new();
        };
        let anim = &self.scene.animation;
        let keys = match row {
            Row::Summary => node_keys(anim, sel),
            Row::Track(p) => track_keys(anim, sel, p),
            Row::More(_) => Vec::new(),
        };
        let mut out: Vec<(f32, Vec<KeyRef>)> = Vec::new();
        for k in keys {
            match out.iter_mut().find(|(f, _)| (f - k.frame).abs() <= KEY_EPS) {
                Some((_, v)) => v.push(k),
                None => out.push((k.frame, vec![k])),
            }
        }
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        out
    }

    /// Window point of the marker for `row` at `frame` (for tests and
    /// scripts that aim at keys).
    pub fn key_marker_at(&self, row: Row, frame: f32) -> Option<(f32, f32)> {
        let (_, r) = self
            .key_strip_layout()
            .into_iter()
            .find(|(rr, _)| *rr == row)?;
        let l = self.layout();
        let x = l.frame_to_x_in(frame, self.time_span());
        Some((x, r.y as f32 + r.h as f32 / 2.0))
    }

    /// What is under (x, y) in the strip.
    pub fn key_strip_hit(&self, x: f32, y: f32) -> Option<Hit> {
        let l = self.layout();
        if !l.key_rows.contains(x, y) {
            return None;
        }
        let Some((row, r)) = self
            .key_strip_layout()
            .into_iter()
            .find(|(_, r)| r.contains(x, y))
        else {
            return Some(Hit::Empty);
        };
        if x < (r.x + l.key_names_w()) as f32 {
            return Some(Hit::Name(row));
        }
        let span = self.time_span();
        let best = self
            .row_markers(row)
            .into_iter()
            .map(|(f, ks)| ((l.frame_to_x_in(f, span) - x).abs(), ks))
            .filter(|(d, _)| *d <= MARKER_R + 1.0)
            .min_by(|a, b| a.0.total_cmp(&b.0));
        Some(match best {
            Some((_, ks)) => Hit::Keys(ks),
            None => Hit::Empty,
        })
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

    /// Keys whose markers lie in the box between two window points.
    pub(in crate::internals::editor) fn keys_in_box(
        &self,
        a: (f32, f32),
        b: (f32, f32),
    ) -> Vec<KeyRef> {
        let l = self.layout();
        let span = self.time_span();
        let (x0, x1) = (a.0.min(b.0), a.0.max(b.0));
        let (y0, y1) = (a.1.min(b.1), a.1.max(b.1));
        let mut out: Vec<KeyRef> = Vec::new();
        for (row, r) in self.key_strip_layout() {
            let cy = r.y as f32 + r.h as f32 / 2.0;
            if cy < y0 - MARKER_R || cy > y1 + MARKER_R {
                continue;
            }
            for (f, ks) in self.row_markers(row) {
                let x = l.frame_to_x_in(f, span);
                if x >= x0 - MARKER_R && x <= x1 + MARKER_R {
                    add_unique(&mut out, ks);
                }
            }
        }
        out
    }

    /// The selection box being dragged, if any (for drawing).
    pub(in crate::internals::editor) fn key_box(&self) -> Option<Rect> {
        match &self.drag {
            Drag::Keys(StripDrag::Box { from, to, .. }) => {
                let x = from.0.min(to.0) as i32;
                let y = from.1.min(to.1) as i32;
                let w = (from.0 - to.0).abs() as i32 + 1;
                let h = (from.1 - to.1).abs() as i32 + 1;
                Some(Rect::new(x, y, w, h))
            }
            _ => None,
        }
    }

    // ----- mouse -----

    /// A left press in the key rows.
    pub(in crate::internals::editor) fn key_strip_press(&mut self, x: f32, y: f32, mods: Mods) {
        let Some(hit) = self.key_strip_hit(x, y) else {
            return;
        };
        match hit {
            Hit::Name(Row::Summary) => self.keys.collapsed = !self.keys.collapsed,
            Hit::Name(Row::Track(p)) => {
                let Some(sel) = self.selection else { return };
                let ks = track_keys(&self.scene.animation, sel, p);
                let mut now = if mods.shift {
                    self.selected_keys()
                } else {
                    Vec::new()
                };
                add_unique(&mut now, ks);
                self.set_key_selection(now);
            }
            Hit::Name(Row::More(_)) => {}
            Hit::Keys(ks) => {
                let current = self.selected_keys();
                let all_in = ks.iter().all(|k| current.iter().any(|c| c.same(k)));
                let mut narrow_to = None;
                let now: Vec<KeyRef> = if mods.shift {
                    if all_in {
                        current
                            .into_iter()
                            .filter(|c| !ks.iter().any(|k| k.same(c)))
                            .collect()
                    } else {
                        let mut v = current;
                        add_unique(&mut v, ks.iter().copied());
                        v
                    }
                } else if all_in {
                    narrow_to = Some(ks.clone());
                    current
                } else {
                    ks.clone()
                };
                let grabbed = now.iter().any(|c| ks.iter().any(|k| k.same(c)));
                self.set_key_selection(now.clone());
                if grabbed {
                    self.drag = Drag::Keys(StripDrag::Keys {
                        x0: x,
                        base: Box::new(self.scene.animation.clone()),
                        keys: now,
                        scale: mods.alt,
                        moved: false,
                        narrow_to,
                    });
                }
            }
            Hit::Empty if self.near_cursor(x) => {
                // The current-frame line runs through the strip: grab it.
                self.drag = Drag::Seek;
            }
            Hit::Empty => {
                self.drag = Drag::Keys(StripDrag::Box {
                    from: (x, y),
                    to: (x, y),
                    add: mods.shift,
                    before: self.selected_keys(),
                });
            }
        }
    }

    /// Mouse move during a strip drag (`None` when no strip drag runs).
    pub(in crate::internals::editor) fn key_strip_move(&mut self, x: f32, y: f32) -> Option<bool> {
        // Taken out so `self` can be borrowed; put back changed in place.
        let mut drag = self.drag.take_keys()?;
        let redraw = match &mut drag {
            StripDrag::Box {
                from,
                to,
                add,
                before,
            } => {
                let mut now = if *add { before.clone() } else { Vec::new() };
                add_unique(&mut now, self.keys_in_box(*from, (x, y)));
                self.keys.selected = now;
                *to = (x, y);
                true
            }
            StripDrag::Keys { x0, moved, .. } if !*moved && (x - *x0).abs() < 3.0 => false,
            StripDrag::Keys {
                x0,
                base,
                keys,
                scale,
                moved,
                narrow_to,
            } => {
                if !*moved {
                    self.stop_playback();
                    self.pending = None;
                }
                self.retime_preview(*x0, x, base, keys, *scale);
                *moved = true;
                *narrow_to = None;
                true
            }
        };
        self.drag = Drag::Keys(drag);
        Some(redraw)
    }

    /// Shows `keys` moved (or scaled) for a drag from `x0` to `x`.
    pub(in crate::internals::editor) fn retime_preview(
        &mut self,
        x0: f32,
        x: f32,
        base: &Animation,
        keys: &[KeyRef],
        scale: bool,
    ) {
        let l = self.layout();
        let span = self.time_span();
        let ppf = (l.frame_to_x_in(1.0, span) - l.frame_to_x_in(0.0, span)).max(1e-3);
        let result = if scale {
            let pivot = self.frame;
            let px = l.frame_to_x_in(pivot, span);
            let f = if (x0 - px).abs() >= 3.0 {
                (x - px) / (x0 - px)
            } else {
                1.0 + (x - x0) / 100.0
            };
            let f = f.max(0.0);
            retime(base, keys, |k| (pivot + (k - pivot) * f).round())
        } else {
            let first = keys.iter().map(|k| k.frame).fold(f32::INFINITY, f32::min);
            let delta = ((x - x0) / ppf).round().max(-first.max(0.0).floor());
            retime(base, keys, |k| k + delta)
        };
        match result {
            Ok((anim, refs)) => {
                self.scene.animation = anim;
                self.scene_rev += 1;
                self.keys.selected = refs;
            }
            Err(e) => self.set_status(&e, true),
        }
    }

    /// Release of a strip drag; false when none ran.
    pub(in crate::internals::editor) fn key_strip_release(&mut self) -> bool {
        let Some(drag) = self.drag.take_keys() else {
            return false;
        };
        match drag {
            StripDrag::Box { from, to, add, .. } => {
                let tiny = (from.0 - to.0).abs() < 3.0 && (from.1 - to.1).abs() < 3.0;
                if tiny && !add {
                    // A click on empty strip space clears the key selection.
                    self.set_key_selection(Vec::new());
                }
            }
            StripDrag::Keys {
                base,
                moved,
                narrow_to,
                scale,
                ..
            } => {
                if moved {
                    let after = Box::new(self.scene.animation.clone());
                    let n = self.keys.selected.len();
                    let what = if scale { "Scale" } else { "Move" };
                    let label = format!("{what} {n} key{}", if n == 1 { "" } else { "s" });
                    self.push_applied(
                        &label,
                        Command::SetAnimation {
                            before: base,
                            after,
                        },
                    );
                    self.set_status(&label, false);
                } else if let Some(ks) = narrow_to {
                    self.set_key_selection(ks);
                }
            }
        }
        true
    }

    /// Esc during a strip drag: puts back what it changed.
    pub(in crate::internals::editor) fn cancel_strip_drag(&mut self) {
        match self.drag.take_keys() {
            Some(StripDrag::Keys { base, keys, .. }) => {
                self.scene.animation = *base;
                self.scene_rev += 1;
                self.keys.selected = keys;
            }
            Some(StripDrag::Box { before, .. }) => self.keys.selected = before,
            None => {}
        }
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
        if matches!(self.drag, Drag::Keys(_)) {
            if key == KeyName::Escape {
                self.cancel_strip_drag();
            }
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
