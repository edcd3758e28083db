//! The embedded fonts: Liberation Serif, Sans and Mono 2.1.5 in four styles
//! each, renamed "Animed Metric …" (`assets/fonts/`, SIL OFL 1.1, subset to
//! Latin, Greek and Cyrillic without hinting — see `assets/fonts/README.md`),
//! read with ttf-parser. Why these: their advance widths equal Times, Arial
//! and Courier's, the metrics of the Nimbus faces Coin gets from fontconfig
//! for SERIF/SANS/TYPEWRITER and Inventor's Times/Helvetica/Courier, so text
//! lines are as long as Coin's and view-all frames text-heavy files alike.
//!
//! Only what layout needs leaves this file: advances, kerning, the ascent
//! and descent, and a glyph's outline in em units (1 = the font size).

use crate::scene::FontFamily;
use ttf_parser::{Face, GlyphId, OutlineBuilder};

macro_rules! font {
    ($name:literal) => {
        include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/", $name))
    };
}

/// [regular, bold, italic, bold italic] per family.
static SERIF: [&[u8]; 4] = [
    font!("AnimedMetricSerif-Regular.ttf"),
    font!("AnimedMetricSerif-Bold.ttf"),
    font!("AnimedMetricSerif-Italic.ttf"),
    font!("AnimedMetricSerif-BoldItalic.ttf"),
];
static SANS: [&[u8]; 4] = [
    font!("AnimedMetricSans-Regular.ttf"),
    font!("AnimedMetricSans-Bold.ttf"),
    font!("AnimedMetricSans-Italic.ttf"),
    font!("AnimedMetricSans-BoldItalic.ttf"),
];
static MONO: [&[u8]; 4] = [
    font!("AnimedMetricMono-Regular.ttf"),
    font!("AnimedMetricMono-Bold.ttf"),
    font!("AnimedMetricMono-Italic.ttf"),
    font!("AnimedMetricMono-BoldItalic.ttf"),
];

/// The face's file name, for messages and tests.
pub fn face_name(family: FontFamily, bold: bool, italic: bool) -> &'static str {
    let names = match family {
        FontFamily::Serif => [
            "Animed Metric Serif",
            "Animed Metric Serif Bold",
            "Animed Metric Serif Italic",
            "Animed Metric Serif Bold Italic",
        ],
        FontFamily::Sans => [
            "Animed Metric Sans",
            "Animed Metric Sans Bold",
            "Animed Metric Sans Italic",
            "Animed Metric Sans Bold Italic",
        ],
        FontFamily::Typewriter => [
            "Animed Metric Mono",
            "Animed Metric Mono Bold",
            "Animed Metric Mono Italic",
            "Animed Metric Mono Bold Italic",
        ],
    };
    names[style_index(bold, italic)]
}

fn style_index(bold: bool, italic: bool) -> usize {
    usize::from(bold) + 2 * usize::from(italic)
}

/// One parsed face with its scale to em units.
pub struct Font {
    face: Face<'static>,
    /// 1 / units per em.
    scale: f32,
}

/// A glyph's outline: closed contours of points in em units (y up), as the
/// font draws them (TrueType: outer contours clockwise, holes
/// counter-clockwise; the tessellator does not rely on it).
pub type Contours = Vec<Vec<[f32; 2]>>;

/// Line segments per quadratic Bézier piece. Fixed, so the same text
/// always gives the same triangles.
pub const QUAD_STEPS: u32 = 6;
/// Line segments per cubic Bézier piece (none in TrueType fonts; kept for
/// completeness of the outline interface).
pub const CUBIC_STEPS: u32 = 8;

impl Font {
    /// The embedded face for a family and style. The embedded data is
    /// known to parse (a unit test checks all twelve faces).
    pub fn new(family: FontFamily, bold: bool, italic: bool) -> Font {
        let set = match family {
            FontFamily::Serif => &SERIF,
            FontFamily::Sans => &SANS,
            FontFamily::Typewriter => &MONO,
        };
        let face = Face::parse(set[style_index(bold, italic)], 0)
            .or_else(|_| Face::parse(SANS[0], 0))
            .expect("the embedded sans face parses");
        let scale = 1.0 / f32::from(face.units_per_em().max(1));
        Font { face, scale }
    }

    /// The glyph for a character; missing characters map to the font's
    /// `.notdef` box (glyph 0), as font renderers do.
    pub fn glyph(&self, c: char) -> GlyphId {
        self.face.glyph_index(c).unwrap_or(GlyphId(0))
    }

    /// Whether the font has a glyph for `c`.
    pub fn has(&self, c: char) -> bool {
        self.face.glyph_index(c).is_some()
    }

    /// Horizontal advance in em.
    pub fn advance(&self, g: GlyphId) -> f32 {
        f32::from(self.face.glyph_hor_advance(g).unwrap_or(0)) * self.scale
    }

    /// Pair kerning in em from the `kern` table (0 when none).
    pub fn kerning(&self, left: GlyphId, right: GlyphId) -> f32 {
        let Some(kern) = self.face.tables().kern else {
            return 0.0;
        };
        kern.subtables
            .into_iter()
            .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
            .find_map(|s| s.glyphs_kerning(left, right))
            .map_or(0.0, |k| f32::from(k) * self.scale)
    }

    /// Ascent above the baseline, em (positive).
    pub fn ascent(&self) -> f32 {
        f32::from(self.face.ascender()) * self.scale
    }

    /// Descent below the baseline, em (positive).
    pub fn descent(&self) -> f32 {
        -f32::from(self.face.descender()) * self.scale
    }

    /// The glyph's contours in em units, curves flattened with a fixed
    /// number of steps.
    pub fn outline(&self, g: GlyphId) -> Contours {
        let mut b = Flatten {
            scale: self.scale,
            contours: Vec::new(),
            cur: Vec::new(),
            pen: [0.0, 0.0],
        };
        self.face.outline_glyph(g, &mut b);
        b.finish_contour();
        b.contours
    }
}

/// Collects outline segments as polylines.
struct Flatten {
    scale: f32,
    contours: Contours,
    cur: Vec<[f32; 2]>,
    /// The pen position in font units (curves start there).
    pen: [f32; 2],
}

impl Flatten {
    fn push(&mut self, x: f32, y: f32) {
        self.pen = [x, y];
        let p = [x * self.scale, y * self.scale];
        if self.cur.last() != Some(&p) {
            self.cur.push(p);
        }
    }

    fn finish_contour(&mut self) {
        let mut c = std::mem::take(&mut self.cur);
        while c.len() > 1 && c.first() == c.last() {
            c.pop();
        }
        if c.len() >= 3 {
            self.contours.push(c);
        }
    }
}

impl OutlineBuilder for Flatten {
    fn move_to(&mut self, x: f32, y: f32) {
        self.finish_contour();
        self.push(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.push(x, y);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let [x0, y0] = self.pen;
        for i in 1..=QUAD_STEPS {
            let t = i as f32 / QUAD_STEPS as f32;
            let u = 1.0 - t;
            let px = u * u * x0 + 2.0 * u * t * x1 + t * t * x;
            let py = u * u * y0 + 2.0 * u * t * y1 + t * t * y;
            self.push(px, py);
        }
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let [x0, y0] = self.pen;
        for i in 1..=CUBIC_STEPS {
            let t = i as f32 / CUBIC_STEPS as f32;
            let u = 1.0 - t;
            let (a, b, c, d) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
            self.push(
                a * x0 + b * x1 + c * x2 + d * x,
                a * y0 + b * y1 + c * y2 + d * y,
            );
        }
    }

    fn close(&mut self) {
        self.finish_contour();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_twelve_faces_parse_and_have_ascii() {
        for fam in [FontFamily::Serif, FontFamily::Sans, FontFamily::Typewriter] {
            for (bold, italic) in [(false, false), (true, false), (false, true), (true, true)] {
                let set = match fam {
                    FontFamily::Serif => &SERIF,
                    FontFamily::Sans => &SANS,
                    FontFamily::Typewriter => &MONO,
                };
                let face = Face::parse(set[style_index(bold, italic)], 0);
                assert!(face.is_ok(), "{}", face_name(fam, bold, italic));
                let f = Font::new(fam, bold, italic);
                for c in ' '..='~' {
                    assert!(f.has(c), "{} lacks {c:?}", face_name(fam, bold, italic));
                }
                assert!(f.has('é') && f.has('Ж') && f.has('λ'));
            }
        }
    }

    #[test]
    fn metrics_are_in_em() {
        let f = Font::new(FontFamily::Sans, false, false);
        // Liberation Sans: 2048 units per em, ascender 1854, descender -434.
        assert!((f.ascent() - 1854.0 / 2048.0).abs() < 1e-6);
        assert!((f.descent() - 434.0 / 2048.0).abs() < 1e-6);
        let m = Font::new(FontFamily::Typewriter, false, false);
        // A monospace font: every ASCII glyph advances the same.
        let w = m.advance(m.glyph('i'));
        assert!(w > 0.5 && w < 0.7, "{w}");
        assert_eq!(w, m.advance(m.glyph('W')));
        // Courier's advance: 0.6 em (1229 of 2048 units).
        assert_eq!(w, 1229.0 / 2048.0);
        // 'A' 'V' kern together in Liberation Sans.
        assert!(f.kerning(f.glyph('A'), f.glyph('V')) < 0.0);
    }

    /// The reason these faces are embedded: Coin draws SERIF/SANS/TYPEWRITER
    /// (and Inventor's Times/Helvetica/Courier) with fontconfig's Nimbus
    /// faces, whose widths are the Adobe core fonts' (Times-Roman.afm,
    /// Helvetica.afm, Courier.afm, in 1/1000 em); ours must advance alike.
    #[test]
    fn advances_match_times_helvetica_and_courier() {
        let afm: [(FontFamily, [u16; 6]); 3] = [
            (FontFamily::Serif, [250, 444, 278, 778, 944, 611]),
            (FontFamily::Sans, [278, 556, 222, 833, 944, 611]),
            (FontFamily::Typewriter, [600, 600, 600, 600, 600, 600]),
        ];
        for (fam, widths) in afm {
            let f = Font::new(fam, false, false);
            for (c, w) in " aimWT".chars().zip(widths) {
                let got = f.advance(f.glyph(c)) * 1000.0;
                assert!(
                    (got - f32::from(w)).abs() <= 0.6,
                    "{} {c:?}: {got} vs {w}",
                    face_name(fam, false, false)
                );
            }
        }
    }

    #[test]
    fn o_has_two_closed_contours_within_the_em() {
        let f = Font::new(FontFamily::Sans, false, false);
        let c = f.outline(f.glyph('O'));
        assert_eq!(c.len(), 2);
        for contour in &c {
            assert!(contour.len() > 8);
            for p in contour {
                assert!(
                    p[0] > -0.1 && p[0] < 1.0 && p[1] > -0.1 && p[1] < 0.9,
                    "{p:?}"
                );
            }
        }
        assert!(f.outline(f.glyph(' ')).is_empty());
    }
}
