//! The key strip as a component: it lays out its rows in the area the
//! editor gives it, finds what is under the mouse, and answers presses,
//! drags, releases, Esc and the wheel itself ([`KeyStrip::handle`]),
//! returning a [`Response`] whose intents (select keys, preview or commit
//! an animation, a status line) the editor applies. Its own state — fold,
//! row scroll, the keys it shows selected and the drag it runs — is in
//! [`KeyStrip`]; it never names the `Editor`. Drawing is `keystrip_draw.rs`.

use super::component::{Intent, Keyed, Response};
use super::keyedit::retime;
use super::keystrip::*;
use crate::anim::{Animation, KEY_EPS};
use crate::input::{Event, Key, Mods, MouseButton};
use crate::scene::NodeId;
use crate::ui::layout::KEY_ROW_H;
use crate::ui::{Layout, Rect};

/// What the strip sees of the editor.
pub struct StripCtx<'a> {
    /// The animation, selected object, frame (Alt+drag scales timing about
    /// it) and length (later keys are drawn greyed): `ctx.anim`, ...
    pub keyed: Keyed<'a>,
    /// The window's layout (the strip is `key_rows`).
    pub layout: Layout,
    /// The frames the ruler shows.
    pub span: (f32, f32),
}

impl<'a> std::ops::Deref for StripCtx<'a> {
    type Target = Keyed<'a>;
    fn deref(&self) -> &Keyed<'a> {
        &self.keyed
    }
}

impl StripCtx<'_> {
    fn x_of(&self, frame: f32) -> f32 {
        self.layout.frame_to_x_in(frame, self.span)
    }
}

impl KeyStrip {
    /// The selected keys that still exist on `node`.
    pub fn live_selection(&self, anim: &Animation, node: Option<NodeId>) -> Vec<KeyRef> {
        let Some(sel) = node else {
            return Vec::new();
        };
        let mut out: Vec<KeyRef> = Vec::new();
        for k in &self.selected {
            if k.node == sel && k.get(anim).is_some() && !out.iter().any(|o| o.same(k)) {
                out.push(*k);
            }
        }
        out
    }

    /// Rows the strip wants (0 when the selection is not animated).
    pub fn rows_wanted(&self, ctx: &StripCtx) -> usize {
        let Some(sel) = ctx.node else { return 0 };
        match (animated_properties(ctx.anim, sel).len(), self.collapsed) {
            (0, _) => 0,
            (_, true) => 1,
            (n, false) => n + 1,
        }
    }

    /// The visible rows with their rectangles.
    pub fn rows(&self, ctx: &StripCtx) -> Vec<(Row, Rect)> {
        let Some(sel) = ctx.node else {
            return Vec::new();
        };
        let area = ctx.layout.key_rows;
        let mut rows = vec![Row::Summary];
        if !self.collapsed {
            rows.extend(
                animated_properties(ctx.anim, sel)
                    .into_iter()
                    .map(Row::Track),
            );
        }
        let cap = (area.h / KEY_ROW_H).max(0) as usize;
        let first = self.scroll.min(rows.len().saturating_sub(cap));
        rows.into_iter()
            .skip(first)
            .take(cap)
            .enumerate()
            .map(|(i, r)| {
                let y = area.y + i as i32 * KEY_ROW_H;
                (r, Rect::new(area.x, y, area.w, KEY_ROW_H))
            })
            .collect()
    }

    /// Rows in the strip: (first shown, all, how many fit).
    pub fn scroll_state(&self, ctx: &StripCtx) -> (usize, usize, usize) {
        let all = self.rows_wanted(ctx);
        let cap = (ctx.layout.key_rows.h / KEY_ROW_H).max(0) as usize;
        (self.scroll.min(all.saturating_sub(cap)), all, cap)
    }

    /// The keys a row shows, grouped per marker: (frame, keys at it).
    pub fn markers(&self, ctx: &StripCtx, row: Row) -> Vec<(f32, Vec<KeyRef>)> {
        let Some(sel) = ctx.node else {
            return Vec::new();
        };
        let keys = match row {
            Row::Summary => node_keys(ctx.anim, sel),
            Row::Track(p) => track_keys(ctx.anim, sel, p),
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

    /// Window point of the marker for `row` at `frame`.
    pub fn marker_at(&self, ctx: &StripCtx, row: Row, frame: f32) -> Option<(f32, f32)> {
        let (_, r) = self.rows(ctx).into_iter().find(|(rr, _)| *rr == row)?;
        Some((ctx.x_of(frame), r.y as f32 + r.h as f32 / 2.0))
    }

    /// What is under (x, y) in the strip.
    pub fn hit(&self, ctx: &StripCtx, x: f32, y: f32) -> Option<Hit> {
        let l = &ctx.layout;
        if !l.key_rows.contains(x, y) {
            return None;
        }
        let Some((row, r)) = self.rows(ctx).into_iter().find(|(_, r)| r.contains(x, y)) else {
            return Some(Hit::Empty);
        };
        if x < (r.x + l.key_names_w()) as f32 {
            return Some(Hit::Name(row));
        }
        let best = self
            .markers(ctx, row)
            .into_iter()
            .map(|(f, ks)| ((ctx.x_of(f) - x).abs(), ks))
            .filter(|(d, _)| *d <= MARKER_R + 1.0)
            .min_by(|a, b| a.0.total_cmp(&b.0));
        Some(match best {
            Some((_, ks)) => Hit::Keys(ks),
            None => Hit::Empty,
        })
    }

    /// Keys whose markers lie in the box between two window points.
    fn keys_in_box(&self, ctx: &StripCtx, a: (f32, f32), b: (f32, f32)) -> Vec<KeyRef> {
        let (x0, x1) = (a.0.min(b.0), a.0.max(b.0));
        let (y0, y1) = (a.1.min(b.1), a.1.max(b.1));
        let mut out: Vec<KeyRef> = Vec::new();
        for (row, r) in self.rows(ctx) {
            let cy = r.y as f32 + r.h as f32 / 2.0;
            if cy < y0 - MARKER_R || cy > y1 + MARKER_R {
                continue;
            }
            for (f, ks) in self.markers(ctx, row) {
                let x = ctx.x_of(f);
                if x >= x0 - MARKER_R && x <= x1 + MARKER_R {
                    add_unique(&mut out, ks);
                }
            }
        }
        out
    }

    /// The selection box being dragged, if any (for drawing).
    pub fn key_box(&self) -> Option<Rect> {
        match &self.drag {
            Some(StripDrag::Box { from, to, .. }) => {
                let x = from.0.min(to.0) as i32;
                let y = from.1.min(to.1) as i32;
                let w = (from.0 - to.0).abs() as i32 + 1;
                let h = (from.1 - to.1).abs() as i32 + 1;
                Some(Rect::new(x, y, w, h))
            }
            _ => None,
        }
    }

    /// A drag the strip runs (the editor's one gesture while it does).
    pub fn is_dragging(&self) -> bool {
        self.drag.is_some()
    }

    /// One event: a left press in the rows, the move, release and Esc of
    /// the strip's own drag, the wheel over rows that overflow.
    pub fn handle(&mut self, ev: &Event, ctx: &StripCtx) -> Response {
        match *ev {
            Event::MouseDown {
                button: MouseButton::Left,
                x,
                y,
                mods,
            } if ctx.layout.key_rows.contains(x, y) => self.press(ctx, x, y, mods),
            Event::MouseMove { x, y, .. } if self.drag.is_some() => self.drag_to(ctx, x, y),
            Event::MouseUp { .. } if self.drag.is_some() => self.release(ctx),
            Event::KeyDown { key, .. } if self.drag.is_some() => {
                if key == Key::Escape {
                    return self.cancel();
                }
                Response::taken()
            }
            Event::Wheel { delta, x, y, mods }
                if ctx.layout.key_rows.contains(x, y) && !mods.ctrl =>
            {
                match self.scroll_rows(ctx, delta) {
                    true => Response::redraw(),
                    false => Response::ignored(),
                }
            }
            _ => Response::ignored(),
        }
    }

    /// Wheel over the strip: scrolls its rows when they do not all fit.
    fn scroll_rows(&mut self, ctx: &StripCtx, delta: f32) -> bool {
        let (first, all, cap) = self.scroll_state(ctx);
        if all <= cap {
            return false;
        }
        let n = (delta.abs().ceil() as usize).max(1);
        self.scroll = if delta > 0.0 {
            first.saturating_sub(n)
        } else {
            (first + n).min(all - cap)
        };
        true
    }

    /// A left press in the key rows (the editor took presses on the
    /// current-frame line before: they seek).
    fn press(&mut self, ctx: &StripCtx, x: f32, y: f32, mods: Mods) -> Response {
        let Some(hit) = self.hit(ctx, x, y) else {
            return Response::ignored();
        };
        let current = self.live_selection(ctx.anim, ctx.node);
        match hit {
            Hit::Name(Row::Summary) => {
                self.collapsed = !self.collapsed;
                Response::redraw()
            }
            Hit::Name(Row::Track(p)) => {
                let Some(sel) = ctx.node else {
                    return Response::redraw();
                };
                let mut now = if mods.shift { current } else { Vec::new() };
                add_unique(&mut now, track_keys(ctx.anim, sel, p));
                Response::redraw().with(Intent::SelectKeys(now))
            }
            Hit::Name(Row::More(_)) => Response::redraw(),
            Hit::Keys(ks) => {
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
                if grabbed {
                    self.drag = Some(StripDrag::Keys {
                        x0: x,
                        base: Box::new(ctx.anim.clone()),
                        keys: now.clone(),
                        scale: mods.alt,
                        moved: false,
                        narrow_to,
                    });
                }
                Response::redraw().with(Intent::SelectKeys(now))
            }
            Hit::Empty => {
                self.drag = Some(StripDrag::Box {
                    from: (x, y),
                    to: (x, y),
                    add: mods.shift,
                    before: current,
                });
                Response::redraw()
            }
        }
    }

    /// A move during the strip's drag: the box selects live; keys move (or
    /// scale) live once past 3 px.
    fn drag_to(&mut self, ctx: &StripCtx, x: f32, y: f32) -> Response {
        let Some(mut drag) = self.drag.take() else {
            return Response::ignored();
        };
        let r = match &mut drag {
            StripDrag::Box {
                from,
                to,
                add,
                before,
            } => {
                let mut now = if *add { before.clone() } else { Vec::new() };
                add_unique(&mut now, self.keys_in_box(ctx, *from, (x, y)));
                self.selected = now;
                *to = (x, y);
                Response::redraw()
            }
            StripDrag::Keys { x0, moved, .. } if !*moved && (x - *x0).abs() < 3.0 => {
                Response::taken()
            }
            StripDrag::Keys {
                x0,
                base,
                keys,
                scale,
                moved,
                narrow_to,
            } => {
                *moved = true;
                *narrow_to = None;
                self.retimed(ctx, *x0, x, base, keys, *scale)
            }
        };
        self.drag = Some(drag);
        r
    }

    /// `keys` moved (or scaled about the current frame) for a drag from
    /// `x0` to `x`, as a preview; a refused step keeps the last valid one.
    fn retimed(
        &mut self,
        ctx: &StripCtx,
        x0: f32,
        x: f32,
        base: &Animation,
        keys: &[KeyRef],
        scale: bool,
    ) -> Response {
        let ppf = (ctx.x_of(1.0) - ctx.x_of(0.0)).max(1e-3);
        let result = if scale {
            let pivot = ctx.frame;
            let px = ctx.x_of(pivot);
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
                self.selected = refs;
                Response::redraw().with(Intent::Preview(anim))
            }
            Err(e) => Response::redraw().with(Intent::Status(e, true)),
        }
    }

    /// The release: a moved key drag is one undo step; a click on empty
    /// space clears the key selection; a click on a selected key selects
    /// just it.
    fn release(&mut self, ctx: &StripCtx) -> Response {
        let r = Response::redraw();
        match self.drag.take() {
            Some(StripDrag::Box { from, to, add, .. }) => {
                let tiny = (from.0 - to.0).abs() < 3.0 && (from.1 - to.1).abs() < 3.0;
                match tiny && !add {
                    true => r.with(Intent::SelectKeys(Vec::new())),
                    false => r,
                }
            }
            Some(StripDrag::Keys {
                base,
                moved: true,
                scale,
                ..
            }) => {
                let n = self.selected.len();
                let what = if scale { "Scale" } else { "Move" };
                let label = format!("{what} {n} key{}", if n == 1 { "" } else { "s" });
                r.with(Intent::Commit {
                    label: label.clone(),
                    before: *base,
                    after: ctx.anim.clone(),
                })
                .with(Intent::Status(label, false))
            }
            Some(StripDrag::Keys {
                narrow_to: Some(ks),
                ..
            }) => r.with(Intent::SelectKeys(ks)),
            _ => r,
        }
    }

    /// Esc during the drag: puts back what it changed.
    fn cancel(&mut self) -> Response {
        let r = Response::redraw();
        match self.drag.take() {
            Some(StripDrag::Keys {
                base, keys, moved, ..
            }) => {
                self.selected = keys;
                match moved {
                    true => r.with(Intent::Preview(*base)),
                    false => r,
                }
            }
            Some(StripDrag::Box { before, .. }) => {
                self.selected = before;
                r
            }
            None => r,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key as AnimKey, Keys, Property, Repeat, Target, TargetRef, Track};
    use glam::Vec3;

    fn anim() -> Animation {
        let keys = vec![
            AnimKey::new(0.0, Vec3::ZERO),
            AnimKey::new(10.0, Vec3::Y),
            AnimKey::new(30.0, Vec3::X),
        ];
        let target = Target {
            of: TargetRef::Node(NodeId(1)),
            property: Property::Translation,
        };
        let t = Track::new(target, Repeat::Constant, Keys::Vec3(keys)).unwrap();
        Animation { tracks: vec![t] }
    }

    fn ctx(anim: &Animation) -> StripCtx<'_> {
        StripCtx {
            keyed: Keyed {
                anim,
                node: Some(NodeId(1)),
                node_name: "Ball".into(),
                morph_targets: &[],
                frame: 0.0,
                duration: 48.0,
            },
            layout: Layout::with_strip(480, 320, 3 * KEY_ROW_H),
            span: (0.0, 48.0),
        }
    }

    fn mouse(kind: &str, (x, y): (f32, f32)) -> Event {
        let (button, mods) = (MouseButton::Left, Mods::NONE);
        match kind {
            "down" => Event::MouseDown { button, x, y, mods },
            "move" => Event::MouseMove { x, y, mods },
            _ => Event::MouseUp { button, x, y, mods },
        }
    }

    /// The strip, the animation's one track row, and the strip's state.
    fn setup() -> (Animation, KeyStrip, Row) {
        let track = Row::Track(Property::Translation);
        (anim(), KeyStrip::default(), track)
    }

    /// Driven by events alone, without an editor: a press on a marker
    /// selects its key and starts a drag, a move previews the key moved by
    /// whole frames, the release asks for one undo step.
    #[test]
    fn the_strip_moves_a_key_by_itself() {
        let (a, mut s, track) = setup();
        let c = ctx(&a);
        let at = s.marker_at(&c, track, 10.0).expect("the key's marker");
        let r = s.handle(&mouse("down", at), &c);
        let k10 = track_keys(&a, NodeId(1), Property::Translation)[1];
        assert_eq!(r.intents, vec![Intent::SelectKeys(vec![k10])]);
        assert!(s.is_dragging());
        s.selected = vec![k10];
        let per_frame = c.x_of(1.0) - c.x_of(0.0);
        let to = (at.0 + 5.0 * per_frame, at.1);
        let r = s.handle(&mouse("move", to), &c);
        let Some(Intent::Preview(moved)) = r.intents.first() else {
            panic!("a preview: {:?}", r.intents)
        };
        let frames = moved.tracks[0].keys.frames();
        assert_eq!(frames, vec![0.0, 15.0, 30.0]);
        assert_eq!(s.selected[0].frame, 15.0, "the selection follows the key");
        let r = s.handle(&mouse("up", to), &ctx(moved));
        assert!(!s.is_dragging());
        assert!(
            matches!(&r.intents[0], Intent::Commit { label, before, .. } if label == "Move 1 key" && *before == a),
            "{:?}",
            r.intents
        );
    }

    /// A box over the markers selects live; Esc puts back the selection
    /// before it; the wheel scrolls only rows that overflow.
    #[test]
    fn a_box_selects_and_esc_puts_it_back() {
        let (a, mut s, track) = setup();
        let c = ctx(&a);
        let k0 = s.marker_at(&c, track, 0.0).unwrap();
        let k10 = s.marker_at(&c, track, 10.0).unwrap();
        let empty = (k0.0 - 6.0, k0.1 - 6.0);
        assert_eq!(s.hit(&c, empty.0, empty.1), Some(Hit::Empty));
        s.handle(&mouse("down", empty), &c);
        s.handle(&mouse("move", (k10.0 + 2.0, k10.1 + 2.0)), &c);
        let frames: Vec<f32> = s.selected.iter().map(|k| k.frame).collect();
        assert_eq!(frames, vec![0.0, 10.0], "both markers in the box");
        let esc = Event::KeyDown {
            key: Key::Escape,
            mods: Mods::NONE,
        };
        s.handle(&esc, &c);
        assert!(s.selected.is_empty() && !s.is_dragging());
        let wheel = Event::Wheel {
            delta: -1.0,
            x: k0.0,
            y: k0.1,
            mods: Mods::NONE,
        };
        // Two rows (summary, translation) fit in three: nothing to scroll.
        assert!(!s.handle(&wheel, &c).consumed);
    }
}
