//! Painting the key strip (the component's `draw`): row names, a marker
//! per key (diamond for spline keys, square for stepped ones), selected
//! keys highlighted, the fold triangle on the summary row and the
//! selection box.

use super::keystrip::{row_name, KeyRef, KeyStrip, Row, MARKER_R};
use super::keystrip_ui::StripCtx;
use crate::anim::Interp;
use crate::ui::text;
use crate::ui::{theme, Painter, Rect};

const MARKER: u32 = 0xc9cbd0;
const SUMMARY_MARKER: u32 = 0x9a9ca3;
const ROW_A: u32 = 0x26272b;
const ROW_B: u32 = 0x2d2f34;
const SUMMARY_BG: u32 = 0x33363c;
/// Keys after the scene's last frame.
const LATE_MARKER: u32 = 0x5e6066;
const KEY_ROW_H_PX: i32 = crate::ui::layout::KEY_ROW_H;

impl KeyStrip {
    /// Draws the strip's rows under the ruler; `hint` is what an empty
    /// strip says (the editor knows why it is empty).
    pub fn draw(&self, p: &mut Painter, ctx: &StripCtx, hint: Option<&str>) {
        let l = &ctx.layout;
        if l.key_rows.is_empty() {
            return;
        }
        let dur = ctx.duration;
        let names_w = l.key_names_w();
        p.set_clip(Some(l.key_rows));
        for (i, (row, r)) in self.rows(ctx).into_iter().enumerate() {
            let bg = match row {
                Row::Summary => SUMMARY_BG,
                _ if i % 2 == 0 => ROW_A,
                _ => ROW_B,
            };
            p.fill_rect(r, bg);
            let (name_r, _) = r.take_left(names_w);
            p.fill_rect(name_r, theme::PANEL);
            p.fill_rect(Rect::new(name_r.right() - 1, r.y, 1, r.h), theme::BORDER);
            let ty = r.y + (r.h - text::LINE_H) / 2;
            match row {
                Row::Summary => {
                    let (cx, cy) = (r.x as f32 + 7.0, r.y as f32 + r.h as f32 / 2.0);
                    let tri = if self.collapsed {
                        [(cx - 2.0, cy - 4.0), (cx + 3.0, cy), (cx - 2.0, cy + 4.0)]
                    } else {
                        [(cx - 4.0, cy - 2.0), (cx + 4.0, cy - 2.0), (cx, cy + 3.0)]
                    };
                    p.fill_polygon(&tri, theme::TEXT, 255);
                    p.text_clipped(r.x + 14, ty, &ctx.node_name, theme::TEXT, names_w - 16);
                }
                Row::Track(prop) => {
                    p.text_clipped(r.x + 10, ty, row_name(prop), theme::TEXT_DIM, names_w - 12);
                }
                Row::More(n) => {
                    let s = format!("+{n} more");
                    p.text_clipped(r.x + 10, ty, &s, theme::TEXT_DIM, names_w - 12);
                }
            }
            let keys_r = Rect::new(r.x + names_w, r.y, r.w - names_w, r.h);
            p.set_clip(Some(keys_r));
            let cy = r.y as f32 + r.h as f32 / 2.0;
            for (f, ks) in self.markers(ctx, row) {
                let x = l.frame_to_x_in(f, ctx.span);
                let sel = ks.iter().filter(|k| self.is_selected(k)).count();
                let step = ks.iter().all(|k| interp(ctx, k) == Some(Interp::Step));
                let color = match (sel, row) {
                    // After the scene's end: greyed (they do not play).
                    (0, _) if f > dur => LATE_MARKER,
                    (0, Row::Summary) => SUMMARY_MARKER,
                    (0, _) => MARKER,
                    _ => theme::SELECTED,
                };
                let rr = if row == Row::Summary {
                    MARKER_R + 0.5
                } else {
                    MARKER_R
                };
                marker(p, (x, cy), rr, step, color);
                if sel > 0 && sel < ks.len() {
                    // Part of a summary marker selected: a dark centre.
                    marker(p, (x, cy), rr - 2.5, step, SUMMARY_BG);
                }
            }
            p.set_clip(Some(l.key_rows));
        }
        if let Some(h) = hint {
            let x = l.key_rows.x + names_w + 8;
            let y = l.key_rows.y + (KEY_ROW_H_PX - text::LINE_H) / 2;
            p.text_clipped(x, y, h, theme::TEXT_DIM, l.key_rows.right() - x - 4);
        }
        let (first, all, cap) = self.scroll_state(ctx);
        if all > cap && cap > 0 {
            // A scroll bar: rows scroll (wheel) inside the fixed strip.
            let r = l.key_rows;
            let track = Rect::new(r.right() - 4, r.y, 3, r.h);
            p.fill_rect(track, theme::PANEL);
            let th = (r.h * cap as i32 / all as i32).max(6);
            let ty = r.y + (r.h - th) * first as i32 / (all - cap) as i32;
            p.fill_rect(Rect::new(track.x, ty, 3, th), theme::TEXT_DIM);
        }
        if let Some(b) = self.key_box() {
            p.fill_rect_alpha(b, theme::ACCENT, 50);
            p.stroke_rect(b, theme::ACCENT);
        }
        p.set_clip(None);
    }

    /// Whether the key is selected.
    pub fn is_selected(&self, k: &KeyRef) -> bool {
        self.selected.iter().any(|s| s.same(k))
    }
}

fn interp(ctx: &StripCtx, k: &KeyRef) -> Option<Interp> {
    k.get(ctx.anim).map(|k| k.interp)
}

/// A diamond (or a square for stepped keys) centred at `c`.
fn marker(p: &mut Painter, c: (f32, f32), r: f32, square: bool, color: u32) {
    let pts = if square {
        let s = r * 0.8;
        [
            (c.0 - s, c.1 - s),
            (c.0 + s, c.1 - s),
            (c.0 + s, c.1 + s),
            (c.0 - s, c.1 + s),
        ]
    } else {
        [
            (c.0, c.1 - r),
            (c.0 + r, c.1),
            (c.0, c.1 + r),
            (c.0 - r, c.1),
        ]
    };
    p.fill_polygon(&pts, color, 255);
}
