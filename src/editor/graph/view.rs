//! The graph's visible window onto (frame, value) space and the pixel
//! mapping, zoom, pan and framing. Pure arithmetic: drawing, hit tests and
//! scripts all go through it, so they agree.

use crate::ui::Rect;

/// Visible frames `f0..f1` and values `v0..v1` (normalised view: -1..1
/// spans each curve's own range).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub f0: f32,
    pub f1: f32,
    pub v0: f32,
    pub v1: f32,
}

impl Default for View {
    fn default() -> Self {
        View {
            f0: 0.0,
            f1: 100.0,
            v0: -1.0,
            v1: 1.0,
        }
    }
}

/// Smallest spans zoom may reach (frames, values).
const MIN_FRAMES: f32 = 2.0;
const MIN_VALUES: f32 = 1e-3;

impl View {
    pub fn frame_to_x(&self, r: Rect, f: f32) -> f32 {
        r.x as f32 + (f - self.f0) / (self.f1 - self.f0) * r.w as f32
    }
    pub fn x_to_frame(&self, r: Rect, x: f32) -> f32 {
        self.f0 + (x - r.x as f32) / r.w.max(1) as f32 * (self.f1 - self.f0)
    }
    pub fn value_to_y(&self, r: Rect, v: f32) -> f32 {
        r.bottom() as f32 - (v - self.v0) / (self.v1 - self.v0) * r.h as f32
    }
    pub fn y_to_value(&self, r: Rect, y: f32) -> f32 {
        self.v0 + (r.bottom() as f32 - y) / r.h.max(1) as f32 * (self.v1 - self.v0)
    }
    /// Pixels per frame and per value unit.
    pub fn scale(&self, r: Rect) -> (f32, f32) {
        (
            r.w.max(1) as f32 / (self.f1 - self.f0),
            r.h.max(1) as f32 / (self.v1 - self.v0),
        )
    }

    /// Zooms the frame axis (or with `values` the value axis) by wheel
    /// `notches` about the pixel (x, y), which stays put.
    pub fn zoom(&mut self, r: Rect, notches: f32, x: f32, y: f32, values: bool) {
        let k = 0.8f32.powf(notches.clamp(-10.0, 10.0));
        if values {
            let c = self.y_to_value(r, y);
            let span = ((self.v1 - self.v0) * k).max(MIN_VALUES);
            let t = (c - self.v0) / (self.v1 - self.v0);
            self.v0 = c - t * span;
            self.v1 = self.v0 + span;
        } else {
            let c = self.x_to_frame(r, x);
            let span = ((self.f1 - self.f0) * k).max(MIN_FRAMES);
            let t = (c - self.f0) / (self.f1 - self.f0);
            self.f0 = c - t * span;
            self.f1 = self.f0 + span;
        }
    }

    /// Moves the view so the content follows the mouse by (dx, dy) pixels.
    pub fn pan(&mut self, r: Rect, dx: f32, dy: f32) {
        let (sx, sy) = self.scale(r);
        let (df, dv) = (dx / sx, dy / sy);
        self.f0 -= df;
        self.f1 -= df;
        self.v0 += dv;
        self.v1 += dv;
    }

    /// Shows frames `f` and values `v` with a margin (empty spans widen).
    pub fn fit(&mut self, f: (f32, f32), v: (f32, f32)) {
        let (fs, vs) = ((f.1 - f.0).max(MIN_FRAMES), (v.1 - v.0).max(0.0));
        let vs = if vs < 1e-4 { v.0.abs().max(1.0) } else { vs };
        let (fc, vc) = ((f.0 + f.1) / 2.0, (v.0 + v.1) / 2.0);
        self.f0 = fc - fs * 0.55;
        self.f1 = fc + fs * 0.55;
        self.v0 = vc - vs * 0.6;
        self.v1 = vc + vs * 0.6;
    }
}

/// Evenly spaced "nice" grid values (1, 2, 5 × 10ⁿ) between `a` and `b`,
/// at least `min_px` pixels apart when `a..b` spans `px` pixels.
pub fn ticks(a: f32, b: f32, px: f32, min_px: f32) -> Vec<f32> {
    let span = (b - a).abs().max(1e-6);
    let raw = span * min_px / px.max(1.0);
    let p = 10f32.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p);
    let first = (a.min(b) / step).ceil() as i64;
    let last = (a.max(b) / step).floor() as i64;
    (first..=last.min(first + 200))
        .map(|i| i as f32 * step)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixels_and_values_map_both_ways() {
        let r = Rect::new(100, 50, 200, 100);
        let v = View {
            f0: 10.0,
            f1: 30.0,
            v0: -2.0,
            v1: 2.0,
        };
        assert_eq!(v.frame_to_x(r, 20.0), 200.0);
        assert_eq!(v.value_to_y(r, 2.0), 50.0);
        assert!((v.x_to_frame(r, v.frame_to_x(r, 17.5)) - 17.5).abs() < 1e-4);
        assert!((v.y_to_value(r, v.value_to_y(r, -0.3)) + 0.3).abs() < 1e-4);
    }

    #[test]
    fn zoom_keeps_the_point_under_the_mouse() {
        let r = Rect::new(0, 0, 400, 200);
        let mut v = View::default();
        let f = v.x_to_frame(r, 123.0);
        v.zoom(r, 2.0, 123.0, 0.0, false);
        assert!((v.x_to_frame(r, 123.0) - f).abs() < 1e-3);
        assert!(v.f1 - v.f0 < 100.0);
        let val = v.y_to_value(r, 40.0);
        v.zoom(r, -1.0, 0.0, 40.0, true);
        assert!((v.y_to_value(r, 40.0) - val).abs() < 1e-4);
        assert!(v.v1 - v.v0 > 2.0);
    }

    #[test]
    fn ticks_are_nice_and_spaced() {
        assert_eq!(
            ticks(0.0, 100.0, 400.0, 40.0),
            (0..=10).map(|i| i as f32 * 10.0).collect::<Vec<_>>()
        );
        let t = ticks(-1.0, 1.0, 100.0, 20.0);
        assert!(t.contains(&0.0) && t.len() >= 3 && t.len() <= 6, "{t:?}");
    }
}
