//! Drawing the viewer: the scene (re-rendered only when the frame, view,
//! size or headlight changed), the scrub bar with the current time and
//! every key time, and the optional stats box.

use super::{LayerKey, Viewer};
use crate::render::job::{options_for, FrameSpec, Headlight};
use crate::render::{render, Frame};
use crate::ui::text;
use crate::ui::{theme, Painter, Rect};
use std::time::Instant;

/// Height of the scrub bar: a track row and a text row.
pub const BAR_H: i32 = 40;
/// Margin left and right of the track, so the ends can be grabbed.
const TRACK_MARGIN: i32 = 10;

fn bar_h(h: u32) -> i32 {
    BAR_H.min(h as i32 / 2)
}

/// The part of the window that shows the scene.
pub fn viewport_rect(w: u32, h: u32) -> Rect {
    Rect::new(0, 0, w as i32, h as i32 - bar_h(h))
}

/// The scrub bar along the bottom.
pub fn bar_rect(w: u32, h: u32) -> Rect {
    let bh = bar_h(h);
    Rect::new(0, h as i32 - bh, w as i32, bh)
}

fn track(w: u32) -> (f32, f32) {
    let x0 = TRACK_MARGIN as f32;
    let x1 = (w as i32 - TRACK_MARGIN) as f32;
    (x0, x1.max(x0 + 1.0))
}

/// The time (seconds) under pixel column `x` of the track, clamped to the loop.
pub fn time_at_x(w: u32, _h: u32, x: f32, loop_seconds: f64) -> f64 {
    let (x0, x1) = track(w);
    (((x - x0) / (x1 - x0)).clamp(0.0, 1.0) as f64) * loop_seconds
}

fn x_at_time(w: u32, t: f64, loop_seconds: f64) -> f32 {
    let (x0, x1) = track(w);
    let f = if loop_seconds > 0.0 {
        (t / loop_seconds).clamp(0.0, 1.0) as f32
    } else {
        0.0
    };
    x0 + f * (x1 - x0)
}

impl Viewer {
    /// Draws the viewer into `frame`, resizing it to the viewer's size.
    pub fn draw(&mut self, frame: &mut Frame) {
        let (w, h) = (self.width, self.height);
        if frame.width != w || frame.height != h {
            *frame = Frame::new(w, h, self.scene.settings.background);
        }
        self.update_layer();
        if let Some((_, layer)) = &self.layer {
            let lw = layer.width as usize;
            for (y, row) in layer.color.chunks_exact(lw.max(1)).enumerate() {
                let dst = y * w as usize;
                frame.color[dst..dst + lw].copy_from_slice(row);
            }
        }
        let mut p = std::mem::take(&mut self.painter);
        p.begin(frame);
        self.draw_bar(&mut p);
        if self.show_stats {
            self.draw_stats(&mut p);
        }
        self.draw_clip_name(&mut p);
        p.end(frame);
        self.painter = p;
    }

    /// Size of the scene picture.
    pub(super) fn viewport_size(&self) -> (u32, u32) {
        let r = viewport_rect(self.width, self.height);
        (r.w.max(1) as u32, r.h.max(1) as u32)
    }

    fn update_layer(&mut self) {
        let (w, h) = self.viewport_size();
        let key = LayerKey {
            frame: self.clock.frame(),
            eye: self.eye.clone(),
            w,
            h,
            headlight: self.headlight,
        };
        if self.layer.as_ref().is_some_and(|(k, _)| *k == key) {
            return;
        }
        let started = Instant::now();
        let pose = crate::anim::evaluate(&self.scene, self.clock.time());
        let view = self.eye.view(&self.scene, &pose, &self.cameras, w, h);
        let spec = FrameSpec {
            width: w,
            height: h,
            headlight: if self.headlight {
                Headlight::On
            } else {
                Headlight::Off
            },
            aa: self.aa,
            ..FrameSpec::default()
        };
        let frame = render(&self.scene, &pose, &view, &options_for(&self.scene, &spec));
        self.stats.last_render = started.elapsed();
        self.layer = Some((key, frame));
        self.count_shown();
    }

    fn count_shown(&mut self) {
        let Some(now) = self.now else { return };
        let second = now.floor();
        if self.stats.second == Some(second) {
            self.stats.count += 1;
        } else {
            if self.stats.second == Some(second - 1.0) {
                self.stats.shown_fps = self.stats.count;
            }
            self.stats.second = Some(second);
            self.stats.count = 1;
        }
    }

    fn draw_bar(&self, p: &mut Painter) {
        let (w, h) = (self.width, self.height);
        let bar = bar_rect(w, h);
        p.fill_rect(bar, theme::PANEL_DARK);
        p.fill_rect(Rect::new(bar.x, bar.y, bar.w, 1), theme::BORDER);
        let loop_s = self.clock.loop_seconds();
        let (x0, x1) = track(w);
        let ty = bar.y + 12;
        p.fill_rect(
            Rect::new(x0 as i32, ty - 1, (x1 - x0) as i32 + 1, 3),
            theme::BUTTON,
        );
        let cx = x_at_time(w, self.clock.time() as f64, loop_s);
        p.fill_rect(
            Rect::new(x0 as i32, ty - 1, (cx - x0) as i32, 3),
            theme::ACCENT,
        );
        // Key times: small diamonds on the track.
        for &t in &self.key_times {
            if (t as f64) < 0.0 || t as f64 > loop_s + 1e-6 {
                continue;
            }
            let x = x_at_time(w, t as f64, loop_s).round() + 0.5;
            let y = ty as f32 + 0.5;
            p.fill_polygon(
                &[(x, y - 4.0), (x + 3.0, y), (x, y + 4.0), (x - 3.0, y)],
                theme::SELECTED,
                255,
            );
        }
        // Cursor.
        p.fill_rect(Rect::new(cx as i32, bar.y + 2, 1, 20), theme::CURSOR);
        p.fill_polygon(
            &[
                (cx - 4.0, bar.y as f32 + 2.0),
                (cx + 5.0, bar.y as f32 + 2.0),
                (cx + 0.5, bar.y as f32 + 7.0),
            ],
            theme::CURSOR,
            255,
        );
        let state = if self.clock.is_playing() {
            "playing"
        } else {
            "paused "
        };
        let info = format!(
            "{state} {:7.3} / {:.3} s  frame {}/{} at {} fps  {}  headlight {}",
            self.clock.time(),
            loop_s,
            self.clock.frame(),
            self.clock.length(),
            trim_number(self.clock.fps()),
            self.viewpoint_name(),
            if self.headlight { "on" } else { "off" }
        );
        let ty = bar.y + 22;
        let used = p.text_clipped(6, ty, &info, theme::TEXT, bar.w - 12);
        let help = "Space pause  <- -> step  PgUp/PgDn view  H light";
        let hw = text::width(help);
        if used + hw + 24 <= bar.w {
            p.text(bar.right() - hw - 6, ty, help, theme::TEXT_DIM);
        }
    }

    fn draw_stats(&self, p: &mut Painter) {
        let (w, h) = self.viewport_size();
        let ms = self.stats.last_render.as_secs_f64() * 1000.0;
        let lines = [
            format!("render {ms:.1} ms ({w}x{h})"),
            format!("shown  {} new pictures/s", self.stats.shown_fps),
        ];
        let bw = lines.iter().map(|l| text::width(l)).max().unwrap_or(0) + 8;
        p.fill_rect_alpha(
            Rect::new(4, 4, bw, text::LINE_H * 2 + 6),
            theme::PANEL_DARK,
            200,
        );
        for (i, l) in lines.iter().enumerate() {
            p.text(8, 7 + i as i32 * text::LINE_H, l, theme::TEXT);
        }
    }
}

/// `24` rather than `24.000`, `29.97` as is.
fn trim_number(x: f64) -> String {
    let s = format!("{x:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bar_and_viewport_tile_the_window() {
        let v = viewport_rect(640, 480);
        let b = bar_rect(640, 480);
        assert_eq!(v.h + b.h, 480);
        assert_eq!(b.y, v.h);
        // A tiny window still has both.
        assert!(viewport_rect(16, 16).h >= 8);
    }

    #[test]
    fn track_maps_time_both_ways() {
        let loop_s = 4.0;
        for t in [0.0, 1.0, 2.5, 4.0] {
            let x = x_at_time(640, t, loop_s);
            assert!((time_at_x(640, 480, x, loop_s) - t).abs() < 1e-5);
        }
        assert_eq!(time_at_x(640, 480, -50.0, loop_s), 0.0);
        assert_eq!(time_at_x(640, 480, 5000.0, loop_s), 4.0);
        assert_eq!(trim_number(24.0), "24");
        assert_eq!(trim_number(29.97), "29.97");
    }
}
