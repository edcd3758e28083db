use super::pixels::{convert, Direction};
use super::text;
use super::Rect;
use crate::render::Frame;
use tiny_skia::{
    FillRule, LineCap, Mask, Paint, PathBuilder, Pixmap, Stroke, Transform as SkTransform,
};

/// Draws the overlay onto a frame: `begin` copies the frame into an opaque
/// pixmap, drawing calls go to the pixmap, `end` copies it back. The pixmap
/// (and the clip mask) are kept between frames to avoid reallocating.
pub struct Painter {
    pixmap: Pixmap,
    clip: Option<Rect>,
    mask: Option<(Rect, Mask)>,
    /// A caller's mask that replaces the clip for paths (e.g. "background
    /// pixels only" for the ground grid).
    custom: Option<Mask>,
}

impl Default for Painter {
    fn default() -> Self {
        Painter::new()
    }
}

fn paint(color: u32, alpha: u8) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8((color >> 16) as u8, (color >> 8) as u8, color as u8, alpha);
    p.anti_alias = true;
    p
}

impl Painter {
    pub fn new() -> Painter {
        Painter {
            // A 1×1 pixmap always exists (non-zero size).
            pixmap: Pixmap::new(1, 1).expect("1x1 pixmap"),
            clip: None,
            mask: None,
            custom: None,
        }
    }

    /// Starts drawing over `frame`.
    pub fn begin(&mut self, frame: &mut Frame) {
        let (w, h) = (frame.width.max(1), frame.height.max(1));
        if self.pixmap.width() != w || self.pixmap.height() != h {
            if let Some(p) = Pixmap::new(w, h) {
                self.pixmap = p;
            }
            self.mask = None;
        }
        self.clip = None;
        if frame.color.len() * 4 == self.pixmap.data().len() {
            convert(&mut frame.color, &mut self.pixmap, Direction::FrameToPixmap);
        }
    }

    /// Writes what was drawn back into `frame`.
    pub fn end(&mut self, frame: &mut Frame) {
        if frame.color.len() * 4 == self.pixmap.data().len() {
            convert(&mut frame.color, &mut self.pixmap, Direction::PixmapToFrame);
        }
    }

    pub fn width(&self) -> i32 {
        self.pixmap.width() as i32
    }

    pub fn height(&self) -> i32 {
        self.pixmap.height() as i32
    }

    /// Restricts later drawing to `r` (or lifts the restriction).
    pub fn set_clip(&mut self, r: Option<Rect>) {
        self.clip = r;
    }

    /// Paths (lines, polygons, circles) are drawn only where `mask` is
    /// non-zero until it is lifted with `None`. Must match the frame size.
    pub fn set_path_mask(&mut self, mask: Option<Mask>) {
        self.custom = mask;
    }

    fn bounds(&self) -> Rect {
        let full = Rect::new(0, 0, self.width(), self.height());
        match self.clip {
            Some(c) => full.intersect(&c),
            None => full,
        }
    }

    /// Makes sure `self.mask` matches the clip; returns whether to use it.
    fn ensure_mask(&mut self) -> bool {
        let Some(clip) = self.clip else { return false };
        let stale = !matches!(&self.mask, Some((r, _)) if *r == clip);
        if stale {
            let Some(mut m) = Mask::new(self.pixmap.width(), self.pixmap.height()) else {
                return false;
            };
            let Some(rect) = tiny_skia::Rect::from_xywh(
                clip.x as f32,
                clip.y as f32,
                clip.w.max(1) as f32,
                clip.h.max(1) as f32,
            ) else {
                return false;
            };
            let path = PathBuilder::from_rect(rect);
            m.fill_path(&path, FillRule::Winding, false, SkTransform::identity());
            self.mask = Some((clip, m));
        }
        true
    }

    /// Fills `r` with an opaque colour (integer-aligned, no anti-aliasing).
    pub fn fill_rect(&mut self, r: Rect, color: u32) {
        self.fill_rect_alpha(r, color, 255);
    }

    /// Fills `r` blending `color` at `alpha`.
    pub fn fill_rect_alpha(&mut self, r: Rect, color: u32, alpha: u8) {
        let r = r.intersect(&self.bounds());
        if r.is_empty() {
            return;
        }
        let w = self.pixmap.width() as usize;
        let data = self.pixmap.data_mut();
        let src = [(color >> 16) as u8, (color >> 8) as u8, color as u8];
        if alpha == 255 {
            let px = [src[0], src[1], src[2], 255];
            for y in r.y..r.bottom() {
                let row = (y as usize * w + r.x as usize) * 4;
                for d in data[row..row + r.w as usize * 4].chunks_exact_mut(4) {
                    d.copy_from_slice(&px);
                }
            }
            return;
        }
        let a = alpha as u32;
        for y in r.y..r.bottom() {
            let row = y as usize * w;
            for x in r.x..r.right() {
                let i = (row + x as usize) * 4;
                for k in 0..3 {
                    let d = data[i + k] as u32;
                    data[i + k] = ((src[k] as u32 * a + d * (255 - a) + 127) / 255) as u8;
                }
            }
        }
    }

    /// A one-pixel rectangle outline just inside `r`.
    pub fn stroke_rect(&mut self, r: Rect, color: u32) {
        self.fill_rect(Rect::new(r.x, r.y, r.w, 1), color);
        self.fill_rect(Rect::new(r.x, r.bottom() - 1, r.w, 1), color);
        self.fill_rect(Rect::new(r.x, r.y, 1, r.h), color);
        self.fill_rect(Rect::new(r.right() - 1, r.y, 1, r.h), color);
    }

    /// An anti-aliased polyline through `pts`.
    pub fn polyline(&mut self, pts: &[(f32, f32)], color: u32, width: f32, closed: bool) {
        if pts.len() < 2 {
            return;
        }
        let mut pb = PathBuilder::new();
        pb.move_to(pts[0].0, pts[0].1);
        for p in &pts[1..] {
            pb.line_to(p.0, p.1);
        }
        if closed {
            pb.close();
        }
        let Some(path) = pb.finish() else { return };
        let stroke = Stroke {
            width,
            line_cap: LineCap::Round,
            ..Stroke::default()
        };
        let p = paint(color, 255);
        let use_mask = self.ensure_mask();
        let mask = match &self.custom {
            Some(m) => Some(m),
            None => self.mask.as_ref().filter(|_| use_mask).map(|(_, m)| m),
        };
        self.pixmap
            .stroke_path(&path, &p, &stroke, SkTransform::identity(), mask);
    }

    pub fn line(&mut self, a: (f32, f32), b: (f32, f32), color: u32, width: f32) {
        self.polyline(&[a, b], color, width, false);
    }

    /// A filled anti-aliased polygon.
    pub fn fill_polygon(&mut self, pts: &[(f32, f32)], color: u32, alpha: u8) {
        if pts.len() < 3 {
            return;
        }
        let mut pb = PathBuilder::new();
        pb.move_to(pts[0].0, pts[0].1);
        for p in &pts[1..] {
            pb.line_to(p.0, p.1);
        }
        pb.close();
        let Some(path) = pb.finish() else { return };
        let p = paint(color, alpha);
        let use_mask = self.ensure_mask();
        let mask = match &self.custom {
            Some(m) => Some(m),
            None => self.mask.as_ref().filter(|_| use_mask).map(|(_, m)| m),
        };
        self.pixmap
            .fill_path(&path, &p, FillRule::Winding, SkTransform::identity(), mask);
    }

    /// A circle outline.
    pub fn circle(&mut self, c: (f32, f32), r: f32, color: u32, width: f32) {
        let Some(path) = PathBuilder::from_circle(c.0, c.1, r.max(0.5)) else {
            return;
        };
        let stroke = Stroke {
            width,
            ..Stroke::default()
        };
        let p = paint(color, 255);
        let use_mask = self.ensure_mask();
        let mask = match &self.custom {
            Some(m) => Some(m),
            None => self.mask.as_ref().filter(|_| use_mask).map(|(_, m)| m),
        };
        self.pixmap
            .stroke_path(&path, &p, &stroke, SkTransform::identity(), mask);
    }

    /// A filled circle.
    pub fn fill_circle(&mut self, c: (f32, f32), r: f32, color: u32) {
        let Some(path) = PathBuilder::from_circle(c.0, c.1, r.max(0.5)) else {
            return;
        };
        let p = paint(color, 255);
        let use_mask = self.ensure_mask();
        let mask = match &self.custom {
            Some(m) => Some(m),
            None => self.mask.as_ref().filter(|_| use_mask).map(|(_, m)| m),
        };
        self.pixmap
            .fill_path(&path, &p, FillRule::Winding, SkTransform::identity(), mask);
    }

    /// Draws `s` with its top-left at (x, y), cut at `max_w` pixels (an
    /// ellipsis-free hard cut keeps columns aligned). Returns the width drawn.
    pub fn text_clipped(&mut self, x: i32, y: i32, s: &str, color: u32, max_w: i32) -> i32 {
        let bounds = self.bounds();
        let w = self.pixmap.width() as i32;
        let src = [(color >> 16) as u8, (color >> 8) as u8, color as u8];
        let n = text::fit_chars(max_w);
        let data = self.pixmap.data_mut();
        let mut cx = x;
        for ch in s.chars().take(n) {
            if ch != ' ' {
                let g = text::glyph(ch);
                for (gy, row) in g.chunks_exact(text::CHAR_W as usize).enumerate() {
                    let py = y + gy as i32;
                    if py < bounds.y || py >= bounds.bottom() {
                        continue;
                    }
                    for (gx, &cov) in row.iter().enumerate() {
                        let px = cx + gx as i32;
                        if cov == 0 || px < bounds.x || px >= bounds.right() {
                            continue;
                        }
                        let i = ((py * w + px) * 4) as usize;
                        let a = cov as u32;
                        for k in 0..3 {
                            let d = data[i + k] as u32;
                            data[i + k] = ((src[k] as u32 * a + d * (255 - a) + 127) / 255) as u8;
                        }
                    }
                }
            }
            cx += text::CHAR_W;
        }
        cx - x
    }

    /// Draws `s` with its top-left at (x, y).
    pub fn text(&mut self, x: i32, y: i32, s: &str, color: u32) -> i32 {
        self.text_clipped(x, y, s, color, i32::MAX / 2)
    }
}
