//! Where each glyph of a text goes: lines (or columns), spacing, `length`
//! and `maxExtent`, and justification, per ISO/IEC 14772-1 §6.20.2
//! (direction: horizontal, leftToRight, topToBottom), §6.20.3
//! (justification: Tables 6.2 and 6.3, major and minor, FIRST / BEGIN /
//! MIDDLE / END) and §6.47 (Text: `length` stretches or compresses a
//! string, `maxExtent` compresses all strings when the longest is longer).
//!
//! Units are the text's local units: a glyph is `size` high (one em).
//! The "edges" of a line that BEGIN/MIDDLE/END align are its font's ascent
//! above and descent below the baseline (Liberation Sans, our "Animed Metric Sans": 0.91 and 0.21 em).
//! Vertical text stacks glyphs in cells `size` high, each centred on its
//! column, columns `spacing × size` apart.

use super::font::Font;
use crate::scene::{Justify, TextSpec};
use ttf_parser::GlyphId;

/// One glyph put in place: its outline is scaled by `scale` (x, y) and
/// moved to `origin` (its baseline start).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    pub glyph: GlyphId,
    pub origin: [f32; 2],
    pub scale: [f32; 2],
}

/// The laid-out text.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layout {
    pub glyphs: Vec<Placed>,
    /// Start of the first string's baseline, the texture origin (§6.47:
    /// "the origin of the first string, as determined by the justification").
    pub origin: [f32; 2],
    /// Horizontal text: the x span of its non-empty lines' advances (pen
    /// start to pen end), the width a line box has whatever its glyphs'
    /// ink; `None` for vertical text or no glyph.
    pub advance_x: Option<[f32; 2]>,
}

/// Lays out `spec` with `font`. Non-finite or non-positive sizes and
/// spacings are the caller's to replace (see `sanitize`).
pub fn layout(spec: &TextSpec, font: &Font) -> Layout {
    if spec.horizontal {
        horizontal(spec, font)
    } else {
        vertical(spec, font)
    }
}

/// Glyphs of one line with their pen positions along the line (em, from
/// 0, in reading order) and the line's natural length (em).
fn shape_line(s: &str, font: &Font) -> (Vec<(GlyphId, f32)>, f32) {
    let mut out = Vec::new();
    let mut pen = 0.0f32;
    let mut prev: Option<GlyphId> = None;
    for c in s.chars().filter(|c| !c.is_control()) {
        let g = font.glyph(c);
        if let Some(p) = prev {
            pen += font.kerning(p, g);
        }
        out.push((g, pen));
        pen += font.advance(g);
        prev = Some(g);
    }
    (out, pen.max(0.0))
}

/// Per-line stretch along the major direction from `length` and
/// `maxExtent` (§6.47), given each line's natural length in local units.
fn stretches(spec: &TextSpec, natural: &[f32]) -> Vec<f32> {
    let mut k: Vec<f32> = natural
        .iter()
        .enumerate()
        .map(|(i, &w)| match spec.length.get(i) {
            Some(&l) if l > 0.0 && l.is_finite() && w > 0.0 => l / w,
            _ => 1.0,
        })
        .collect();
    if spec.max_extent > 0.0 && spec.max_extent.is_finite() {
        let longest = natural
            .iter()
            .zip(&k)
            .map(|(w, s)| w * s)
            .fold(0.0f32, f32::max);
        if longest > spec.max_extent {
            let f = spec.max_extent / longest;
            k.iter_mut().for_each(|s| *s *= f);
        }
    }
    k
}

/// Offset of an extent of length `len` that runs from 0 towards `dir`
/// (+1 or −1), so that BEGIN puts its start at 0, MIDDLE its centre and
/// END its end.
fn major_offset(j: Justify, len: f32, dir: f32) -> f32 {
    match j {
        Justify::First | Justify::Begin => 0.0,
        Justify::Middle => -dir * len / 2.0,
        Justify::End => -dir * len,
    }
}

fn horizontal(spec: &TextSpec, font: &Font) -> Layout {
    let size = spec.size;
    let lines: Vec<_> = spec.strings.iter().map(|s| shape_line(s, font)).collect();
    let natural: Vec<f32> = lines.iter().map(|(_, w)| w * size).collect();
    let k = stretches(spec, &natural);
    let dir = if spec.left_to_right { 1.0 } else { -1.0 };
    let line_step = spec.spacing * size;
    let down = if spec.top_to_bottom { -1.0 } else { 1.0 };
    let n = lines.len().max(1) as f32;
    let (asc, desc) = (font.ascent() * size, font.descent() * size);
    // Minor direction (Table 6.2): where the block sits across the lines.
    let last = (n - 1.0) * line_step;
    let (top, bottom) = if spec.top_to_bottom {
        (asc, -last - desc)
    } else {
        (last + asc, -desc)
    };
    let shift = match spec.justify[1] {
        Justify::First => 0.0,
        Justify::Begin if spec.top_to_bottom => -top,
        Justify::Begin => -bottom,
        Justify::End if spec.top_to_bottom => -bottom,
        Justify::End => -top,
        Justify::Middle => -(top + bottom) / 2.0,
    };
    let mut out = Layout::default();
    for (i, ((glyphs, _), (&len, &s))) in lines.iter().zip(natural.iter().zip(&k)).enumerate() {
        let y = down * i as f32 * line_step + shift;
        let len = len * s;
        // The line starts at `start` and runs towards `dir`.
        let start = major_offset(spec.justify[0], len, dir);
        if i == 0 {
            out.origin = [start.min(start + dir * len), y];
        }
        if !glyphs.is_empty() {
            let (a, b) = (start.min(start + dir * len), start.max(start + dir * len));
            out.advance_x = Some(match out.advance_x {
                Some([lo, hi]) => [lo.min(a), hi.max(b)],
                None => [a, b],
            });
        }
        for &(g, pen) in glyphs {
            let adv = font.advance(g) * size * s;
            let along = pen * size * s;
            // Right to left: each glyph's box is mirrored in place, not
            // the glyph (its outline still reads left to right).
            let x = if dir > 0.0 {
                start + along
            } else {
                start - along - adv
            };
            out.glyphs.push(Placed {
                glyph: g,
                origin: [x, y],
                scale: [size * s, size],
            });
        }
    }
    out
}

fn vertical(spec: &TextSpec, font: &Font) -> Layout {
    let size = spec.size;
    let columns: Vec<Vec<GlyphId>> = spec
        .strings
        .iter()
        .map(|s| {
            s.chars()
                .filter(|c| !c.is_control())
                .map(|c| font.glyph(c))
                .collect()
        })
        .collect();
    let natural: Vec<f32> = columns.iter().map(|c| c.len() as f32 * size).collect();
    let k = stretches(spec, &natural);
    let down = if spec.top_to_bottom { -1.0 } else { 1.0 };
    let across = if spec.left_to_right { 1.0 } else { -1.0 };
    let step = spec.spacing * size;
    let n = columns.len().max(1) as f32;
    // Minor direction (Table 6.3): columns side by side, each `size` wide.
    let extent = (n - 1.0) * step + size;
    let shift = match spec.justify[1] {
        Justify::First | Justify::Begin => 0.0,
        Justify::Middle => -across * extent / 2.0,
        Justify::End => -across * extent,
    };
    let desc = font.descent() * size;
    let mut out = Layout::default();
    for (j, (glyphs, (&len, &s))) in columns.iter().zip(natural.iter().zip(&k)).enumerate() {
        // Left edge of the column.
        let near = across * j as f32 * step + shift;
        let left = if across > 0.0 { near } else { near - size };
        let len = len * s;
        let start = major_offset(spec.justify[0], len, down);
        let cell = size * s;
        if j == 0 {
            out.origin = [left, start.min(start + down * len)];
        }
        for (i, &g) in glyphs.iter().enumerate() {
            // The cell's lower edge.
            let lower = if down < 0.0 {
                start - (i + 1) as f32 * cell
            } else {
                start + i as f32 * cell
            };
            let adv = font.advance(g) * size;
            out.glyphs.push(Placed {
                glyph: g,
                origin: [left + (size - adv) / 2.0, lower + desc * s],
                scale: [size, size * s],
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::FontFamily;

    fn mono() -> Font {
        Font::new(FontFamily::Typewriter, false, false)
    }

    fn spec(strings: &[&str], major: Justify, minor: Justify) -> TextSpec {
        TextSpec {
            strings: strings.iter().map(|s| s.to_string()).collect(),
            family: FontFamily::Typewriter,
            justify: [major, minor],
            ..TextSpec::default()
        }
    }

    fn x_range(l: &Layout, f: &Font, size: f32) -> (f32, f32) {
        l.glyphs.iter().fold((f32::MAX, f32::MIN), |(lo, hi), p| {
            let w = f.advance(p.glyph) * p.scale[0];
            let _ = size;
            (lo.min(p.origin[0]), hi.max(p.origin[0] + w))
        })
    }

    #[test]
    fn major_justification_begin_middle_end() {
        let f = mono();
        let w = f.advance(f.glyph('a')); // every glyph the same advance
        for (j, want_lo) in [
            (Justify::Begin, 0.0),
            (Justify::First, 0.0),
            (Justify::Middle, -2.0 * w),
            (Justify::End, -4.0 * w),
        ] {
            let l = layout(&spec(&["abcd"], j, Justify::First), &f);
            let (lo, hi) = x_range(&l, &f, 1.0);
            assert!((lo - want_lo).abs() < 1e-5, "{j:?}: {lo}");
            assert!((hi - (want_lo + 4.0 * w)).abs() < 1e-5, "{j:?}: {hi}");
        }
        // Each line is justified on its own: END puts both right edges at 0.
        let l = layout(&spec(&["ab", "abcd"], Justify::End, Justify::First), &f);
        assert!((l.glyphs[1].origin[0] + w).abs() < 1e-5);
        assert!((l.glyphs[5].origin[0] + w).abs() < 1e-5);
    }

    #[test]
    fn minor_justification_and_line_spacing() {
        let f = mono();
        let (asc, desc) = (f.ascent(), f.descent());
        let mut s = spec(&["a", "b", "c"], Justify::Begin, Justify::First);
        s.spacing = 2.0;
        s.size = 0.5;
        let l = layout(&s, &f);
        // FIRST: first baseline at 0, lines spacing × size apart downwards.
        let ys: Vec<f32> = l.glyphs.iter().map(|p| p.origin[1]).collect();
        assert_eq!(ys, vec![0.0, -1.0, -2.0]);
        s.justify[1] = Justify::Begin; // top of the first line at 0
        assert!((layout(&s, &f).glyphs[0].origin[1] + asc * 0.5).abs() < 1e-6);
        s.justify[1] = Justify::End; // bottom of the last line at 0
        assert!((layout(&s, &f).glyphs[2].origin[1] - desc * 0.5).abs() < 1e-6);
        s.justify[1] = Justify::Middle;
        let l = layout(&s, &f);
        let top = l.glyphs[0].origin[1] + asc * 0.5;
        let bottom = l.glyphs[2].origin[1] - desc * 0.5;
        assert!((top + bottom).abs() < 1e-6, "{top} {bottom}");
        // Bottom to top: lines go up.
        s.justify[1] = Justify::First;
        s.top_to_bottom = false;
        let ys: Vec<f32> = layout(&s, &f).glyphs.iter().map(|p| p.origin[1]).collect();
        assert_eq!(ys, vec![0.0, 1.0, 2.0]);
    }

    #[test]
    fn right_to_left_runs_towards_minus_x() {
        let f = mono();
        let w = f.advance(f.glyph('a'));
        let mut s = spec(&["ab"], Justify::Begin, Justify::First);
        s.left_to_right = false;
        let l = layout(&s, &f);
        assert!((l.glyphs[0].origin[0] + w).abs() < 1e-6);
        assert!((l.glyphs[1].origin[0] + 2.0 * w).abs() < 1e-6);
    }

    #[test]
    fn length_and_max_extent_scale_the_major_direction() {
        let f = mono();
        let w = f.advance(f.glyph('a'));
        let mut s = spec(&["ab", "abcd"], Justify::Begin, Justify::First);
        s.length = vec![8.0 * w];
        let l = layout(&s, &f);
        let (_, hi) = x_range(
            &Layout {
                glyphs: l.glyphs[..2].to_vec(),
                ..Layout::default()
            },
            &f,
            1.0,
        );
        assert!((hi - 8.0 * w).abs() < 1e-5, "{hi}");
        // The advance span covers the stretched line.
        let [a0, a1] = l.advance_x.unwrap();
        assert!(a0 == 0.0 && (a1 - 8.0 * w).abs() < 1e-5, "{a0} {a1}");
        assert_eq!(l.glyphs[0].scale, [4.0, 1.0]);
        assert_eq!(l.glyphs[2].scale, [1.0, 1.0]);
        // maxExtent 2w: the longest (the 8w line) is compressed to 2w, and
        // the others by the same factor.
        s.max_extent = 2.0 * w;
        let l = layout(&s, &f);
        assert!((l.glyphs[0].scale[0] - 1.0).abs() < 1e-5);
        assert!((l.glyphs[2].scale[0] - 0.25).abs() < 1e-5);
        // maxExtent longer than every line changes nothing.
        s.length.clear();
        s.max_extent = 100.0;
        assert!(layout(&s, &f).glyphs.iter().all(|p| p.scale == [1.0, 1.0]));
    }

    #[test]
    fn vertical_text_stacks_glyphs_downwards_in_columns() {
        let f = mono();
        let mut s = spec(&["ab", "c"], Justify::Begin, Justify::First);
        s.horizontal = false;
        let l = layout(&s, &f);
        let d = f.descent();
        assert!((l.glyphs[0].origin[1] - (-1.0 + d)).abs() < 1e-6);
        assert!((l.glyphs[1].origin[1] - (-2.0 + d)).abs() < 1e-6);
        // Second column one spacing × size to the right.
        assert!((l.glyphs[2].origin[0] - l.glyphs[0].origin[0] - 1.0).abs() < 1e-6);
    }
}
