//! Text as geometry: the embedded fonts (`font`), glyph outlines to
//! triangles with holes (`tessellate`), lines and justification
//! (`layout`), the mesh (`mesh`), and Inventor `Text2` labels as bitmaps
//! (`bitmap`). The readers turn their Text nodes
//! into a [`TextSpec`](crate::scene::TextSpec) and call [`text_mesh`];
//! the spec stays on the mesh so writers can write the node again.

pub mod bitmap;
pub mod font;
pub mod layout;
pub mod mesh;
pub mod tessellate;

pub use mesh::{text_mesh, MAX_GLYPHS};

/// A text node's mesh with its spec kept on it (both readers end here):
/// `None` when every string is blank (nothing to draw, not an error) or
/// the mesh cannot be built (the reason goes to `msgs` at `pos`); a text
/// longer than [`MAX_GLYPHS`] is cut and says so.
pub fn mesh_of_spec(
    spec: TextSpec,
    textured: bool,
    pos: crate::format::lexer::Pos,
    msgs: &mut Vec<(crate::format::lexer::Pos, String)>,
) -> Option<crate::scene::Mesh> {
    if spec.strings.iter().all(|s| s.trim().is_empty()) {
        return None;
    }
    let mut m = match text_mesh(&spec, textured) {
        Ok(m) => m,
        Err(e) => {
            msgs.push((pos, e.to_string()));
            return None;
        }
    };
    let glyphs: usize = spec.strings.iter().map(|s| s.chars().count()).sum();
    if glyphs > MAX_GLYPHS {
        msgs.push((
            pos,
            format!("text longer than {MAX_GLYPHS} characters is cut"),
        ));
    }
    m.text = Some(Box::new(spec));
    Some(m)
}

use crate::scene::{FontFamily, Justify, TextSpec};

/// The x span of a horizontal text's line advances in its local units
/// (`layout::Layout::advance_x`), for bounds that count a line's box as
/// its advances, as Coin's do; `None` for vertical text or no glyph.
pub fn advance_span(spec: &TextSpec) -> Option<[f32; 2]> {
    let font = font::Font::new(spec.family, spec.bold, spec.italic);
    layout::layout(spec, &font).advance_x
}

/// Replaces values no text can be drawn with (non-finite or non-positive
/// size, non-finite or negative spacing) by the defaults, saying so.
pub fn sanitize(spec: &mut TextSpec, default_size: f32, msgs: &mut Vec<String>) {
    if !(spec.size.is_finite() && spec.size > 0.0) {
        msgs.push(format!(
            "font size {} is not positive; {default_size} used",
            spec.size
        ));
        spec.size = default_size;
    }
    if !(spec.spacing.is_finite() && spec.spacing >= 0.0) {
        msgs.push(format!(
            "spacing {} is not a non-negative number; 1 used",
            spec.spacing
        ));
        spec.spacing = 1.0;
    }
    if !spec.max_extent.is_finite() || spec.max_extent < 0.0 {
        msgs.push(format!("maxExtent {} ignored", spec.max_extent));
        spec.max_extent = 0.0;
    }
}

/// A VRML97 family name (§6.20.2: "SERIF", "SANS", "TYPEWRITER"); other
/// names are browser-dependent, so `None`.
pub fn family(name: &str) -> Option<FontFamily> {
    match name {
        "SERIF" => Some(FontFamily::Serif),
        "SANS" => Some(FontFamily::Sans),
        "TYPEWRITER" => Some(FontFamily::Typewriter),
        _ => None,
    }
}

/// A justification word of VRML97 (FIRST/BEGIN/MIDDLE/END) or of VRML 1.0
/// and Inventor (LEFT/CENTER/RIGHT).
pub fn justify(word: &str) -> Option<Justify> {
    match word {
        "FIRST" => Some(Justify::First),
        "BEGIN" | "LEFT" => Some(Justify::Begin),
        "MIDDLE" | "CENTER" => Some(Justify::Middle),
        "END" | "RIGHT" => Some(Justify::End),
        _ => None,
    }
}

/// Inventor's `Font.name` ("Times-Roman", "Helvetica-Bold", "Courier",
/// "defaultFont", fontconfig-like "Sans:Bold Italic") → family, bold,
/// italic. Unknown names are the default serif face, as Coin's default
/// font is a serif one.
pub fn inventor_font(name: &str) -> (FontFamily, bool, bool) {
    let l = name.to_ascii_lowercase();
    let family = if ["courier", "mono", "typewriter", "fixed"]
        .iter()
        .any(|k| l.contains(k))
    {
        FontFamily::Typewriter
    } else if ["helvetica", "arial", "sans", "verdana", "utopia"]
        .iter()
        .any(|k| l.contains(k))
    {
        FontFamily::Sans
    } else {
        FontFamily::Serif
    };
    let bold = l.contains("bold");
    let italic = l.contains("italic") || l.contains("oblique");
    (family, bold, italic)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inventor_font_names() {
        assert_eq!(
            inventor_font("Times-Roman"),
            (FontFamily::Serif, false, false)
        );
        assert_eq!(
            inventor_font("Helvetica-BoldOblique"),
            (FontFamily::Sans, true, true)
        );
        assert_eq!(
            inventor_font("Courier-Bold"),
            (FontFamily::Typewriter, true, false)
        );
        assert_eq!(
            inventor_font("defaultFont"),
            (FontFamily::Serif, false, false)
        );
        assert_eq!(
            inventor_font("DejaVu Sans:Italic"),
            (FontFamily::Sans, false, true)
        );
    }

    #[test]
    fn bad_sizes_fall_back() {
        let mut s = TextSpec {
            size: f32::NAN,
            spacing: -1.0,
            ..TextSpec::default()
        };
        let mut m = Vec::new();
        sanitize(&mut s, 1.0, &mut m);
        assert_eq!((s.size, s.spacing), (1.0, 1.0));
        assert_eq!(m.len(), 2);
    }
}
