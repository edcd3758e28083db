use super::pixels::{convert, convert_with, Direction};
use super::text;
use super::Rect;
use crate::render::Frame;
use tiny_skia::{
    FillRule, LineCap, Mask, Paint, PathBuilder, Pixmap, Stroke, Transform as SkTransform,
};

/// Draws the overlay onto a frame: `begin` copies the frame into an opaque
/// pixmap, drawing calls go to the pixmap, `end` copies it back. The pixmap
/// (and the clip masks) are kept between frames to avoid reallocating.
pub struct Painter {
    pixmap: Pixmap,
    clip: Option<Rect>,
    /// Masks of the clips drawn with lately, newest last: a frame uses a
    /// few clips in turn (the viewport, then none, then the panels), and
    /// a window-sized mask built afresh on each change cost more than the
    /// lines it clipped.
    masks: Vec<(Rect, Mask)>,
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
            masks: Vec::new(),
            custom: None,
        }
    }

    /// Starts drawing over `frame`.
    pub fn begin(&mut self, frame: &mut Frame) {
        self.fit(frame);
        if frame.color.len() * 4 == self.pixmap.data().len() {
            convert(&mut frame.color, &mut self.pixmap, Direction::FrameToPixmap);
        }
    }

    /// A pixmap of `frame`'s size, no clip.
    fn fit(&mut self, frame: &Frame) {
        let (w, h) = (frame.width.max(1), frame.height.max(1));
        if self.pixmap.width() != w || self.pixmap.height() != h {
            if let Some(p) = Pixmap::new(w, h) {
                self.pixmap = p;
            }
            self.masks.clear();
        }
        self.clip = None;
    }

    /// [`Painter::begin`] over `frame` with rectangle `r` showing other
    /// pixels: `row(y, out)` writes row `y` of `r` as `0x00RRGGBB`. The
    /// frame gets them at [`Painter::end`] (or now, when there is no
    /// pixmap to draw on). A rectangle not inside the frame shows none.
    pub fn begin_with(
        &mut self,
        frame: &mut Frame,
        r: Rect,
        row: impl Fn(usize, &mut [u32]) + Sync,
    ) {
        self.fit(frame);
        let (w, h) = (frame.width as i32, frame.height as i32);
        let inside = r.x >= 0 && r.y >= 0 && r.w >= 0 && r.h >= 0;
        let fits = inside && r.x + r.w <= w && r.y + r.h <= h;
        let rect = match fits {
            true => (r.x as usize, r.y as usize, r.w as usize, r.h as usize),
            false => (0, 0, 0, 0),
        };
        let fw = frame.width as usize;
        if frame.color.len() * 4 == self.pixmap.data().len() {
            convert_with(&frame.color, fw, &mut self.pixmap, rect, row);
            return;
        }
        let (x0, y0, rw, rh) = rect;
        for y in 0..rh {
            let at = (y0 + y) * fw + x0;
            row(y, &mut frame.color[at..at + rw]);
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
            // Whole pixels as words (the panels' backgrounds are a good
            // part of the window); bytes if the pixmap is not word-aligned.
            match bytemuck::try_cast_slice_mut::<u8, u32>(data) {
                Ok(words) => {
                    let word = u32::from_ne_bytes(px);
                    for y in r.y..r.bottom() {
                        let row = y as usize * w + r.x as usize;
                        words[row..row + r.w as usize].fill(word);
                    }
                }
                Err(_) => {
                    for y in r.y..r.bottom() {
                        let row = (y as usize * w + r.x as usize) * 4;
                        for d in data[row..row + r.w as usize * 4].chunks_exact_mut(4) {
                            d.copy_from_slice(&px);
                        }
                    }
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
        let size = (self.pixmap.width(), self.pixmap.height());
        let mask = path_mask(&mut self.masks, &self.custom, self.clip, size);
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
        let size = (self.pixmap.width(), self.pixmap.height());
        let mask = path_mask(&mut self.masks, &self.custom, self.clip, size);
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
        let size = (self.pixmap.width(), self.pixmap.height());
        let mask = path_mask(&mut self.masks, &self.custom, self.clip, size);
        self.pixmap
            .stroke_path(&path, &p, &stroke, SkTransform::identity(), mask);
    }

    /// A filled circle.
    pub fn fill_circle(&mut self, c: (f32, f32), r: f32, color: u32) {
        let Some(path) = PathBuilder::from_circle(c.0, c.1, r.max(0.5)) else {
            return;
        };
        let p = paint(color, 255);
        let size = (self.pixmap.width(), self.pixmap.height());
        let mask = path_mask(&mut self.masks, &self.custom, self.clip, size);
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

/// How many clip masks a painter keeps.
const KEPT_MASKS: usize = 4;

/// The mask paths are drawn through: the caller's (`custom`), else the
/// clip's, made (and kept, newest last) when no kept mask has the clip's
/// rectangle; none without a clip.
fn path_mask<'a>(
    masks: &'a mut Vec<(Rect, Mask)>,
    custom: &'a Option<Mask>,
    clip: Option<Rect>,
    (w, h): (u32, u32),
) -> Option<&'a Mask> {
    if custom.is_some() {
        return custom.as_ref();
    }
    let clip = clip?;
    match masks.iter().position(|(r, _)| *r == clip) {
        Some(i) => {
            let kept = masks.remove(i);
            masks.push(kept);
        }
        None => {
            let m = clip_mask(clip, w, h)?;
            if masks.len() == KEPT_MASKS {
                masks.remove(0);
            }
            masks.push((clip, m));
        }
    }
    masks.last().map(|(_, m)| m)
}

/// A `w`×`h` mask open inside `clip` only.
fn clip_mask(clip: Rect, w: u32, h: u32) -> Option<Mask> {
    let mut m = Mask::new(w, h)?;
    let rect = tiny_skia::Rect::from_xywh(
        clip.x as f32,
        clip.y as f32,
        clip.w.max(1) as f32,
        clip.h.max(1) as f32,
    )?;
    let path = PathBuilder::from_rect(rect);
    m.fill_path(&path, FillRule::Winding, false, SkTransform::identity());
    Some(m)
}

#[cfg(test)]
mod tests {
    use super::Painter;
    use crate::render::Frame;
    use crate::ui::Rect;

    fn frame(w: u32, h: u32) -> Frame {
        let mut f = Frame::new(w, h, glam::Vec3::ZERO);
        for (i, c) in f.color.iter_mut().enumerate() {
            *c = (i as u32).wrapping_mul(0x9e37_79b9) & 0xff_ffff;
        }
        f
    }

    #[test]
    fn an_opaque_fill_covers_its_rectangle_only() {
        let mut f = frame(13, 9);
        let before = f.color.clone();
        let mut p = Painter::new();
        p.begin(&mut f);
        p.fill_rect(Rect::new(2, 3, 5, 4), 0x12_34_56);
        p.set_clip(Some(Rect::new(0, 0, 4, 9)));
        p.fill_rect(Rect::new(-3, 8, 50, 5), 0xab_cd_ef);
        p.end(&mut f);
        for y in 0..9 {
            for x in 0..13 {
                let want = if (2..7).contains(&x) && (3..7).contains(&y) {
                    0x12_34_56
                } else if x < 4 && y == 8 {
                    0xab_cd_ef
                } else {
                    before[(y * 13 + x) as usize]
                };
                assert_eq!(f.color[(y * 13 + x) as usize], want, "({x}, {y})");
            }
        }
    }

    /// Lines under clips used in turn, more clips than are kept, drawn by
    /// one painter over several frames.
    fn clipped_lines(p: &mut Painter, f: &mut Frame, clips: &[Option<Rect>]) {
        p.begin(f);
        for (i, &clip) in clips.iter().enumerate() {
            p.set_clip(clip);
            let o = i as f32 * 3.0;
            p.line((1.0 + o, 2.0), (60.0, 37.0 - o), 0xff_80_20, 1.5);
            p.circle((30.0, 20.0), 5.0 + o, 0x20_80_ff, 1.0);
        }
        p.end(f);
    }

    #[test]
    fn kept_clip_masks_clip_as_new_ones_do() {
        let clips = [
            Some(Rect::new(0, 0, 40, 30)),
            None,
            Some(Rect::new(10, 5, 30, 30)),
            Some(Rect::new(0, 0, 40, 30)),
            Some(Rect::new(20, 0, 44, 12)),
            Some(Rect::new(5, 5, 5, 5)),
            Some(Rect::new(1, 1, 60, 38)),
            Some(Rect::new(10, 5, 30, 30)),
        ];
        let mut kept = Painter::new();
        for _ in 0..3 {
            let mut f = frame(64, 40);
            clipped_lines(&mut kept, &mut f, &clips);
            // A fresh painter per clip builds every mask anew.
            let mut want = frame(64, 40);
            for (i, &clip) in clips.iter().enumerate() {
                let mut fresh = Painter::new();
                // The same line and circle as `clipped_lines` draws at i.
                fresh.begin(&mut want);
                fresh.set_clip(clip);
                let o = i as f32 * 3.0;
                fresh.line((1.0 + o, 2.0), (60.0, 37.0 - o), 0xff_80_20, 1.5);
                fresh.circle((30.0, 20.0), 5.0 + o, 0x20_80_ff, 1.0);
                fresh.end(&mut want);
            }
            assert!(f.color == want.color);
            assert!(f.color != frame(64, 40).color, "something was drawn");
        }
    }
}
