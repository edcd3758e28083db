//! Text from an embedded, pre-rasterised monospace font (Noto Sans Mono,
//! 16 px raster): integer-only and identical on every machine, crisp at 1×.

use noto_sans_mono_bitmap::{get_raster, get_raster_width, FontWeight, RasterHeight};

const WEIGHT: FontWeight = FontWeight::Regular;
const HEIGHT: RasterHeight = RasterHeight::Size16;

/// Advance of every glyph in pixels.
pub const CHAR_W: i32 = get_raster_width(WEIGHT, HEIGHT) as i32;
/// Height of a line of text in pixels.
pub const LINE_H: i32 = 16;

/// Width of `s` in pixels.
pub fn width(s: &str) -> i32 {
    s.chars().count() as i32 * CHAR_W
}

/// How many characters of `s` fit in `w` pixels.
pub fn fit_chars(w: i32) -> usize {
    (w.max(0) / CHAR_W) as usize
}

/// Coverage (0..255) rows of `c`, `CHAR_W` bytes each; unknown characters
/// fall back to '?'.
pub fn glyph(c: char) -> &'static [u8] {
    get_raster(c, WEIGHT, HEIGHT)
        .or_else(|| get_raster('?', WEIGHT, HEIGHT))
        .map(|r| r.pixels())
        .unwrap_or(&[])
}
