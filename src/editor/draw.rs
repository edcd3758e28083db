//! Painting the whole window: viewport layer, overlay, panels, timeline,
//! and the modal browser or dialog on top.

use super::gesture::Drag;
use super::panel::{Widget, WidgetKind};
use super::{Editor, Mode};
use crate::render::Frame;
use crate::ui::text;
use crate::ui::{theme, widgets, Layout, Painter, Rect};
use glam::Vec3;

impl Editor {
    /// Draws the editor into `frame`, resizing it to the editor's size.
    pub fn draw(&mut self, frame: &mut Frame) {
        self.graph_follow();
        if frame.width != self.split.width || frame.height != self.split.height {
            *frame = Frame::new(self.split.width, self.split.height, Vec3::ZERO);
        }
        let l = self.layout();
        self.update_layer();
        // The painter is moved out so `self` can be borrowed while drawing.
        let mut p = std::mem::take(&mut self.painter);
        if self.onion_shown() {
            // The copies blend over the layer in the frame.
            self.blit_viewport(frame, l.viewport);
            self.blit_onion(frame, l.viewport);
            p.begin(frame);
        } else {
            // Straight from the layer into the painter's pixmap: a copy
            // of the viewport into the frame was a pass over most of the
            // window in every redraw. (Onion off: this drops its copies.)
            self.blit_onion(frame, l.viewport);
            let (r, rows) = self.viewport_rows(l.viewport);
            p.begin_with(frame, r, rows);
        }
        self.draw_viewport_overlay(&mut p);
        self.draw_motion_path(&mut p);
        self.draw_bones(&mut p);
        self.draw_viewport_ui(&mut p);
        self.draw_viewport_labels(&mut p, &l);
        self.draw_timeline(&mut p, &l);
        self.draw_panels(&mut p, &l);
        self.draw_modal(&mut p);
        self.draw_tooltip(&mut p);
        self.draw_help(&mut p);
        p.end(frame);
        self.painter = p;
    }

    /// Draws into a new frame of the editor's size.
    pub fn render_frame(&mut self) -> Frame {
        let mut f = Frame::new(self.split.width, self.split.height, Vec3::ZERO);
        self.draw(&mut f);
        f
    }

    fn draw_viewport_labels(&self, p: &mut Painter, l: &Layout) {
        let vp = l.viewport;
        let mode = match self.mode {
            Mode::Select => format!("Select: {}", self.tool().name()),
            Mode::View => "View (Esc: select)".into(),
        };
        let onion = if self.onion_shown() { "  Onion" } else { "" };
        p.set_clip(Some(vp));
        p.text(
            vp.x + 4,
            vp.y + 2,
            &format!("{mode}{onion}"),
            theme::TEXT_DIM,
        );
        if self.record {
            let x = vp.right() - text::width("REC") - 6;
            p.fill_circle((x as f32 - 6.0, vp.y as f32 + 10.0), 4.0, theme::RECORD);
            p.text(x, vp.y + 2, "REC", theme::RECORD);
            p.stroke_rect(vp, theme::RECORD);
        }
        p.set_clip(None);
    }

    fn hot(&self, w: &Widget) -> bool {
        matches!(self.drag, Drag::None) && w.rect.contains(self.mouse.0, self.mouse.1)
    }

    fn draw_panels(&self, p: &mut Painter, l: &Layout) {
        p.fill_rect(l.toolbar, theme::TOOLBAR);
        p.fill_rect(
            Rect::new(l.toolbar.x, l.toolbar.bottom() - 1, l.toolbar.w, 1),
            theme::BORDER,
        );
        p.fill_rect(l.side, theme::PANEL);
        p.fill_rect(Rect::new(l.side.x, l.side.y, 1, l.side.h), theme::BORDER);
        // File name and unsaved mark at the toolbar's right end.
        let name = match &self.path {
            Some(p) => p
                .file_name()
                .map(|s| s.to_string_lossy().to_string())
                .unwrap_or_default(),
            None => "untitled".into(),
        };
        let title = format!("{name}{}", if self.is_dirty() { " *" } else { "" });
        let widgets = self.widgets();
        let tb_end = widgets
            .iter()
            .filter(|w| l.toolbar.contains(w.rect.x as f32, w.rect.y as f32))
            .map(|w| w.rect.right())
            .max()
            .unwrap_or(0);
        let tw = text::width(&title);
        let x = (l.toolbar.right() - tw - 6).max(tb_end + 8);
        p.text_clipped(
            x,
            l.toolbar.y + 3,
            &title,
            theme::TEXT_DIM,
            l.toolbar.right() - x - 2,
        );
        // The side panel paints itself (its sections, faces and lists);
        // the toolbar's and the controls bar's widgets are the editor's.
        let (placed, rest): (Vec<Widget>, Vec<Widget>) = widgets
            .into_iter()
            .partition(|w| l.side.contains(w.rect.x as f32, w.rect.y as f32));
        for w in &rest {
            self.draw_widget(p, w);
        }
        self.draw_side_panel(p, &placed);
    }

    fn draw_widget(&self, p: &mut Painter, w: &Widget) {
        let hot = self.hot(w);
        match &w.kind {
            WidgetKind::Button { label, on, action } => {
                let color = if *action == super::panel::Action::Record {
                    theme::RECORD
                } else {
                    theme::BUTTON_ON
                };
                widgets::button(p, w.rect, label, hot, *on, color)
            }
            WidgetKind::Check { on, .. } => widgets::checkbox(p, w.rect, *on, hot),
            WidgetKind::Header(t) => widgets::header(p, w.rect, t),
            WidgetKind::Label { text, dim } => widgets::label(
                p,
                w.rect,
                text,
                if *dim {
                    theme::TEXT_DIM
                } else if self.status.error && text == &self.status.text {
                    theme::ERROR
                } else {
                    theme::TEXT
                },
            ),
            WidgetKind::Field(id) => {
                let editing = self.edit.as_ref().filter(|e| e.field == *id);
                let text = match editing {
                    Some(e) => e.text.clone(),
                    None => self.field_text(*id, text::fit_chars(w.rect.w - 5)),
                };
                widgets::field(p, w.rect, &text, hot, editing.is_some());
            }
            // The side panel paints its rows (`side_ui.rs`).
            WidgetKind::Row { .. } | WidgetKind::Entry(_) | WidgetKind::PathInput => {}
        }
    }

    /// The text of a field of the controls bar (the side panel's faces
    /// paint their own fields).
    fn field_text(&self, id: super::fields::FieldId, max_chars: usize) -> String {
        use super::fields::{format_fit, FieldId};
        match id {
            FieldId::Preview(_) => self
                .preview_field(id)
                .map_or(String::new(), |x| format_fit(x, max_chars)),
            FieldId::Frame => format_fit(self.frame, max_chars),
            _ => String::new(),
        }
    }

    fn draw_timeline(&self, p: &mut Painter, l: &Layout) {
        p.fill_rect(l.timeline, theme::PANEL_DARK);
        p.fill_rect(
            Rect::new(l.timeline.x, l.timeline.y, l.timeline.w, 1),
            theme::BORDER,
        );
        let r = l.ruler;
        let dur = self.scene.settings.duration.max(1.0);
        let span = self.time_span();
        let px_per_frame = l.frame_to_x_in(1.0, span) - l.frame_to_x_in(0.0, span);
        // Minor ticks at least 4 px apart, labels at least 40 px apart.
        let nice = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000];
        let minor = nice
            .iter()
            .copied()
            .find(|&s| s as f32 * px_per_frame >= 4.0)
            .unwrap_or(10000);
        let major = nice
            .iter()
            .copied()
            .find(|&s| s as f32 * px_per_frame >= 40.0 && s % minor == 0)
            .unwrap_or(10000);
        let base = r.bottom() - 2;
        let ruler_r = l.ruler_span();
        let mut f = ((span.0.max(0.0) / minor as f32).ceil() as i64 * minor as i64) as i32;
        while f as f32 <= span.1 {
            let x = l.frame_to_x_in(f as f32, span) as i32;
            if (x as f32) < ruler_r.0 - 0.5 || (x as f32) > ruler_r.1 + 0.5 {
                f += minor;
                continue;
            }
            let is_major = f % major == 0;
            let th = if is_major { 7 } else { 3 };
            p.fill_rect(Rect::new(x, base - th, 1, th), theme::TEXT_DIM);
            if is_major {
                let s = f.to_string();
                let tx = (x - text::width(&s) / 2).clamp(r.x, r.right() - text::width(&s));
                p.text(tx, r.y - 1, &s, theme::TEXT_DIM);
            }
            f += minor;
        }
        p.fill_rect(Rect::new(r.x, base, r.w, 1), theme::BORDER);
        match self.split.graph {
            true => self.draw_graph(p, l),
            false => self.draw_key_strip(p),
        }
        self.draw_time_shading(p, l, span);
        // Current frame cursor with its number (not when zoomed or panned
        // away from it: it would land on the names column).
        let cxf = l.frame_to_x_in(self.frame.clamp(0.0, dur), span);
        let (x0, x1) = l.ruler_span();
        if cxf < x0 - 0.5 || cxf > x1 + 0.5 {
            return;
        }
        let cx = cxf as i32;
        p.fill_rect(
            // Through the key strip; the graph draws its own frame line.
            Rect::new(
                cx,
                r.y,
                1,
                l.ruler.h + if self.split.graph { 0 } else { l.key_rows.h },
            ),
            theme::CURSOR,
        );
        p.fill_polygon(
            &[
                (cx as f32 - 4.0, r.y as f32),
                (cx as f32 + 5.0, r.y as f32),
                (cx as f32 + 0.5, r.y as f32 + 5.0),
            ],
            theme::CURSOR,
            255,
        );
    }

    /// Darkens the frames after the scene's end (keys there are greyed
    /// and do not play) and outside the preview range, and marks the
    /// preview range's ends on the ruler.
    fn draw_time_shading(&self, p: &mut Painter, l: &Layout, span: (f32, f32)) {
        let (x0, x1) = l.ruler_span();
        let rows_h = if self.split.graph { 0 } else { l.key_rows.h };
        let (y, h) = (l.ruler.y, l.ruler.h + rows_h);
        let x_of = |f: f32| l.frame_to_x_in(f, span).clamp(x0, x1);
        let shade = |p: &mut Painter, a: f32, b: f32, alpha: u8| {
            let (a, b) = (a.round() as i32, b.round() as i32);
            if b > a {
                p.fill_rect_alpha(Rect::new(a, y, b - a, h), 0x000000, alpha);
            }
        };
        let dur = self.scene.settings.duration.max(0.0);
        shade(p, x_of(dur) + 1.0, x1 + 1.0, 110);
        if let Some((a, b)) = self.timeline.preview {
            shade(p, x0, x_of(a), 70);
            shade(p, x_of(b) + 1.0, x_of(dur) + 1.0, 70);
            for f in [a, b] {
                let x = l.frame_to_x_in(f, span);
                if x >= x0 - 0.5 && x <= x1 + 0.5 {
                    p.fill_rect(Rect::new(x as i32, y, 1, l.ruler.h), theme::ACCENT);
                }
            }
            let (xa, xb) = (x_of(a) as i32, x_of(b) as i32);
            p.fill_rect(Rect::new(xa, y, (xb - xa).max(1), 2), theme::ACCENT);
        }
    }

    /// The tooltip below and right of the mouse, kept inside the window.
    fn draw_tooltip(&self, p: &mut Painter) {
        let Some(t) = self.hover.text() else { return };
        let win = self.layout().window;
        let w = (text::width(&t) + 10).min(win.w);
        let h = text::LINE_H + 6;
        let (mx, my) = (self.mouse.0 as i32, self.mouse.1 as i32);
        let x = (mx + 10).clamp(win.x, (win.right() - w).max(win.x));
        let y = if my + 20 + h <= win.bottom() {
            my + 20
        } else {
            my - 8 - h
        };
        let r = Rect::new(x, y.max(win.y), w, h);
        p.fill_rect(r, theme::DIALOG);
        p.stroke_rect(r, theme::ACCENT);
        p.text_clipped(r.x + 5, r.y + 3, &t, theme::TEXT, r.w - 8);
    }

    fn draw_modal(&self, p: &mut Painter) {
        let win = self.layout().window;
        if let Some(b) = &self.browser {
            b.draw(p, self.browser_rect(), win, self.modal_mouse());
        }
        if let Some(m) = &self.menu {
            m.draw(p, win);
        }
        if let Some(s) = &self.search {
            s.menu.draw(p, win);
        }
        if let Some(d) = &self.dialog {
            d.draw(p, win, self.modal_mouse());
        }
    }
}
