//! Painting the graph editor: grid with frame and value labels, one
//! coloured polyline per visible channel (its samples), a dot at every
//! whole frame along each curve (ease shows as dots bunching near a key),
//! keys, the tangent handle of selected TCB keys, the current frame line,
//! the selection box and the channel list with its visibility and lock
//! switches.

use super::view::ticks;
use super::{Areas, Ctx, GraphEditor, CHANNEL_ROW};
use crate::anim::Interp;
use crate::editor::fields::format_fit;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{theme, widgets, Painter, Rect};

/// Plot background and its zero line (grid lines use `theme::BORDER`).
const PLOT_BG: u32 = 0x1f2024;
const ZERO_LINE: u32 = 0x484b53;

impl GraphEditor {
    pub fn draw(&self, p: &mut Painter, ctx: &Ctx) {
        let a = Areas::new(ctx.rect);
        p.set_clip(Some(ctx.rect));
        p.fill_rect(a.split, theme::TOOLBAR);
        let mid = a.split.x + a.split.w / 2;
        p.fill_rect(Rect::new(mid - 12, a.split.y + 2, 24, 1), theme::TEXT_DIM);
        p.fill_rect(a.list, theme::PANEL);
        p.fill_rect(a.band, theme::PANEL_DARK);
        p.fill_rect(a.plot, PLOT_BG);
        self.draw_grid(p, &a);
        self.draw_list(p, ctx, &a);
        let shown = self.shown(ctx);
        let sel = self.selected(ctx);
        p.set_clip(Some(a.plot));
        let v = &self.view;
        let (sx, _) = v.scale(a.plot);
        for s in &shown {
            let color = if self.is_locked(&s.ch) {
                theme::LIGHT_OFF
            } else {
                s.ch.color()
            };
            let pts: Vec<(f32, f32)> = s
                .curve
                .samples
                .iter()
                .map(|&(f, val)| {
                    (
                        v.frame_to_x(a.plot, f),
                        v.value_to_y(a.plot, s.to_plot(val)),
                    )
                })
                .collect();
            p.polyline(&pts, color, 1.5, false);
            // Timing: a dot per whole frame where they are far enough apart.
            if sx >= 5.0 {
                let mut f = v.f0.ceil();
                while f <= v.f1 {
                    if let Some(val) = value_near(&s.curve.samples, f) {
                        let c = (
                            v.frame_to_x(a.plot, f),
                            v.value_to_y(a.plot, s.to_plot(val)),
                        );
                        p.fill_circle(c, 1.3, color);
                    }
                    f += 1.0;
                }
            }
        }
        for s in &shown {
            for &(f, val) in &s.curve.keys {
                let c = (
                    v.frame_to_x(a.plot, f),
                    v.value_to_y(a.plot, s.to_plot(val)),
                );
                let on = sel
                    .iter()
                    .any(|k| k.ch == s.ch && (k.frame - f).abs() < 1e-3);
                let (r, color) = if on {
                    (4.0, theme::SELECTED)
                } else {
                    (3.0, theme::TEXT)
                };
                widgets::diamond(p, c, r, color);
            }
        }
        for k in &sel {
            if let Some(h) = self.handle_of(ctx, *k) {
                let (c, end) = (h.key, h.end);
                let tcb = k.key_ref().get(ctx.anim).map(|k| k.interp) == Some(Interp::Tcb);
                let color = if tcb {
                    theme::SELECTED
                } else {
                    theme::TEXT_DIM
                };
                let back = (2.0 * c.0 - end.0, 2.0 * c.1 - end.1);
                p.line(back, end, color, 1.0);
                p.fill_circle(end, 3.0, color);
                p.circle(back, 2.5, color, 1.0);
            }
        }
        // Current frame line, its number in the band.
        p.set_clip(Some(ctx.rect));
        let x = v.frame_to_x(a.plot, ctx.frame);
        if x >= a.plot.x as f32 && x <= a.plot.right() as f32 {
            p.line(
                (x, a.band.y as f32),
                (x, a.plot.bottom() as f32),
                theme::CURSOR,
                1.0,
            );
            let label = format_fit(ctx.frame, 5);
            let w = text::width(&label) + 4;
            let r = Rect::new(x as i32 - w / 2, a.band.y, w, a.band.h);
            p.fill_rect(r, theme::CURSOR);
            p.text(
                r.x + 2,
                r.y + (r.h - text::LINE_H) / 2,
                &label,
                theme::PANEL_DARK,
            );
        }
        if let Some(b) = self.box_rect() {
            p.fill_rect_alpha(b, theme::ACCENT, 50);
            p.stroke_rect(b, theme::ACCENT);
        }
        if ctx.node.is_none() || shown.is_empty() && self.channels(ctx).is_empty() {
            let msg = if ctx.node.is_none() {
                "Select an object to see its curves"
            } else {
                "No animated channels (record keys with K)"
            };
            p.text(a.plot.x + 8, a.plot.y + 6, msg, theme::TEXT_DIM);
        }
        p.set_clip(None);
    }

    fn draw_grid(&self, p: &mut Painter, a: &Areas) {
        let v = &self.view;
        p.set_clip(Some(Rect::new(
            a.band.x,
            a.band.y,
            a.band.w,
            a.band.h + a.plot.h,
        )));
        for f in ticks(v.f0, v.f1, a.plot.w as f32, 50.0) {
            let x = v.frame_to_x(a.plot, f).round();
            p.fill_rect(Rect::new(x as i32, a.plot.y, 1, a.plot.h), theme::BORDER);
            let s = format_fit(f, 6);
            p.text(
                x as i32 + 2,
                a.band.y + (a.band.h - text::LINE_H) / 2,
                &s,
                theme::TEXT_DIM,
            );
        }
        p.set_clip(Some(a.plot));
        for val in ticks(v.v0, v.v1, a.plot.h as f32, 28.0) {
            let y = v.value_to_y(a.plot, val).round() as i32;
            let c = if val == 0.0 { ZERO_LINE } else { theme::BORDER };
            p.fill_rect(Rect::new(a.plot.x, y, a.plot.w, 1), c);
            p.text(
                a.plot.x + 2,
                y - text::LINE_H,
                &format_fit(val, 7),
                theme::TEXT_DIM,
            );
        }
    }

    fn draw_list(&self, p: &mut Painter, ctx: &Ctx, a: &Areas) {
        p.set_clip(Some(a.list));
        let head = Rect::new(a.list.x, a.list.y, a.list.w, CHANNEL_ROW);
        p.fill_rect(head, theme::HEADER);
        let title = if self.normalised {
            "Graph (norm)"
        } else {
            "Graph"
        };
        let title = match ctx.node {
            Some(_) => format!("{title}: {}", ctx.node_name),
            None => title.to_string(),
        };
        p.text_clipped(head.x + 3, head.y, &title, theme::TEXT, head.w - 4);
        for (i, ch) in self.channels(ctx).into_iter().enumerate() {
            let y = a.list.y + (i as i32 + 1) * CHANNEL_ROW;
            if y >= a.list.bottom() {
                break;
            }
            let hidden = self.is_hidden(&ch);
            let eye = Rect::new(a.list.x + 3, y + 3, 10, 10);
            p.stroke_rect(eye, theme::TEXT_DIM);
            if !hidden {
                p.fill_rect(eye.inset(2), ch.color());
            }
            let lock = Rect::new(a.list.x + 17, y + 3, 10, 10);
            p.stroke_rect(lock, theme::TEXT_DIM);
            if self.is_locked(&ch) {
                p.fill_rect(lock.inset(2), theme::TEXT);
            }
            let color = if hidden { theme::TEXT_DIM } else { ch.color() };
            let max = a.list.w - 33;
            p.text_clipped(
                a.list.x + 31,
                y,
                &ch.label(ctx.morph_targets),
                color,
                max.max(CHAR_W),
            );
        }
        p.fill_rect(
            Rect::new(a.list.right() - 1, a.list.y, 1, a.list.h),
            theme::BORDER,
        );
    }
}

/// The sample at whole frame `f` (the curve samples every whole frame
/// when zoomed in this far).
fn value_near(samples: &[(f32, f32)], f: f32) -> Option<f32> {
    let i = samples.partition_point(|s| s.0 < f - 1e-3);
    samples
        .get(i)
        .filter(|s| (s.0 - f).abs() < 1e-3)
        .map(|s| s.1)
}
