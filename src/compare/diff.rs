//! The diff picture a person reads at a glance: the golden as a dim grey
//! copy, pixels beyond the tolerance in red (brighter = larger difference),
//! pixels that differ but within tolerance in dark amber, and a cyan frame
//! around all the red pixels so a single changed pixel is still found.
//! Where the two sizes differ, the part only one picture has is magenta.

use crate::picture::Image;

const RED_MIN: u8 = 150;
const AMBER: [u8; 3] = [150, 105, 0];
const FRAME: [u8; 3] = [0, 220, 255];
const OUTSIDE: [u8; 3] = [200, 0, 200];
/// Grey level of black in the dimmed copy and its range: dim enough that
/// red stands out everywhere, bright enough to recognise the picture.
const DIM_BASE: f32 = 24.0;
const DIM_RANGE: f32 = 0.33;

fn dim(p: [u8; 3]) -> [u8; 3] {
    let y = 0.299 * p[0] as f32 + 0.587 * p[1] as f32 + 0.114 * p[2] as f32;
    let g = (DIM_BASE + DIM_RANGE * y) as u8;
    [g, g, g]
}

/// The largest per-channel difference of two pixels.
pub fn channel_diff(a: [u8; 3], b: [u8; 3]) -> u8 {
    a[0].abs_diff(b[0])
        .max(a[1].abs_diff(b[1]))
        .max(a[2].abs_diff(b[2]))
}

/// Builds the diff picture (as large as both pictures together) for a
/// per-pixel tolerance of `channel`.
pub fn diff_image(actual: &Image, golden: &Image, channel: u8) -> Image {
    let w = actual.width().max(golden.width());
    let h = actual.height().max(golden.height());
    let mut out = Image::new(w, h, OUTSIDE);
    let (ow, oh) = (
        actual.width().min(golden.width()),
        actual.height().min(golden.height()),
    );
    let mut bbox: Option<[u32; 4]> = None;
    for y in 0..oh {
        for x in 0..ow {
            let (a, g) = (actual.pixel(x, y), golden.pixel(x, y));
            let d = channel_diff(a, g);
            let p = if d > channel {
                let b = bbox.get_or_insert([x, y, x, y]);
                *b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
                let r = RED_MIN as u16 + (d as u16 * (255 - RED_MIN as u16)) / 255;
                [r as u8, 0, 0]
            } else if d > 0 {
                AMBER
            } else {
                dim(g)
            };
            out.set_pixel(x, y, p);
        }
    }
    if let Some([x0, y0, x1, y1]) = bbox {
        // Two pixels of margin so the frame does not cover what it marks.
        let (x0, y0) = (x0.saturating_sub(2), y0.saturating_sub(2));
        let (x1, y1) = ((x1 + 2).min(w - 1), (y1 + 2).min(h - 1));
        let is_red = |p: [u8; 3]| p[0] >= RED_MIN && p[1] == 0 && p[2] == 0;
        let mut mark = |x: u32, y: u32| {
            if !is_red(out.pixel(x, y)) {
                out.set_pixel(x, y, FRAME);
            }
        };
        for x in x0..=x1 {
            mark(x, y0);
            mark(x, y1);
        }
        for y in y0..=y1 {
            mark(x0, y);
            mark(x1, y);
        }
    }
    out
}
