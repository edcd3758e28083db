//! What a text shape says, kept beside the triangles built from it so that
//! writers can write a Text node again (not the triangles) and the editor
//! can show the string.
//!
//! The fields follow VRML97's Text + FontStyle (ISO/IEC 14772-1 §6.47,
//! §6.20); VRML 1.0 `AsciiText` and Inventor's `Text2`/`Text3` map onto the
//! same record (their LEFT/CENTER/RIGHT justification is BEGIN/MIDDLE/END,
//! their `width` is `length`).

/// The font family (§6.20: SERIF, SANS, TYPEWRITER).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FontFamily {
    #[default]
    Serif,
    Sans,
    Typewriter,
}

/// Alignment along one direction (§6.20.3: FIRST, BEGIN, MIDDLE, END).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Justify {
    First,
    #[default]
    Begin,
    Middle,
    End,
}

/// Which node the text came from (decides how it is written back).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum TextKind {
    /// VRML97 `Text` (also what other formats are converted to).
    #[default]
    Text,
    /// VRML 1.0 `AsciiText`.
    AsciiText,
    /// Inventor `Text2`: screen-aligned at a constant pixel size (see
    /// `TextSpec::units_per_pixel`).
    Text2,
    /// Inventor `Text3` with its parts (front, sides, back) and the depth
    /// its sides are extruded to.
    Text3 {
        front: bool,
        sides: bool,
        back: bool,
        depth: f32,
    },
}

/// A text shape's strings and font style.
#[derive(Clone, Debug, PartialEq)]
pub struct TextSpec {
    pub kind: TextKind,
    /// One entry per line (or column when `horizontal` is false).
    pub strings: Vec<String>,
    pub family: FontFamily,
    pub bold: bool,
    pub italic: bool,
    /// Nominal glyph height (the em size) in local units.
    pub size: f32,
    /// Line distance as a multiple of `size`.
    pub spacing: f32,
    /// Major (along a line) and minor (across lines) alignment.
    pub justify: [Justify; 2],
    pub horizontal: bool,
    pub left_to_right: bool,
    pub top_to_bottom: bool,
    /// Wanted length of each line along the major direction; 0 or missing =
    /// its natural length.
    pub length: Vec<f32>,
    /// When > 0, lines longer than this are compressed to it.
    pub max_extent: f32,
    /// For an Inventor `Text2` (`size` in pixels): local units of the built
    /// mesh per pixel, so the renderer can draw the label `size` pixels
    /// high facing the viewer (`render/label.rs`). 0 for every other text.
    pub units_per_pixel: f32,
}

impl Default for TextSpec {
    /// VRML97's defaults: SERIF PLAIN, size 1, spacing 1, justify
    /// BEGIN/FIRST, horizontal, left to right, top to bottom.
    fn default() -> Self {
        TextSpec {
            kind: TextKind::Text,
            strings: Vec::new(),
            family: FontFamily::Serif,
            bold: false,
            italic: false,
            size: 1.0,
            spacing: 1.0,
            justify: [Justify::Begin, Justify::First],
            horizontal: true,
            left_to_right: true,
            top_to_bottom: true,
            length: Vec::new(),
            max_extent: 0.0,
            units_per_pixel: 0.0,
        }
    }
}
