//! Writes a text mesh back as an Inventor 2.1 `Font` + `Text2` / `Text3`
//! instead of its triangles (VRML97 `Text` and VRML 1.0 `AsciiText`
//! become a flat `Text3 { parts FRONT }`, which Inventor draws the same).
//!
//! Inventor text has LEFT/CENTER/RIGHT along the line only, its first
//! baseline at y = 0 and lines running down: a text whose minor
//! justification, direction, `length` or `maxExtent` say more stays
//! triangles (the caller's IndexedFaceSet), as does everything in an
//! Inventor 1.0 file.

use super::text::TEXT3_DEPTH;
use crate::format::export::text::{num, quoted, Out};
use crate::scene::{FontFamily, Justify, Mesh, TextKind, TextSpec};

/// The spec to write as Inventor text, when Inventor can say what it means.
pub fn writable(mesh: &Mesh) -> Option<&TextSpec> {
    let t = mesh.text.as_deref()?;
    let plain = matches!(t.justify[1], Justify::First)
        && t.horizontal
        && t.left_to_right
        && t.top_to_bottom
        && t.max_extent == 0.0
        && t.length.iter().all(|&l| l == 0.0);
    plain.then_some(t)
}

/// A PostScript-style font name Inventor and Coin know.
fn font_name(t: &TextSpec) -> String {
    let (base, bold, italic, plain) = match t.family {
        FontFamily::Serif => ("Times", "Bold", "Italic", "Roman"),
        FontFamily::Sans => ("Helvetica", "Bold", "Oblique", ""),
        FontFamily::Typewriter => ("Courier", "Bold", "Oblique", ""),
    };
    let style = match (t.bold, t.italic) {
        (false, false) => plain.to_string(),
        (true, false) => bold.to_string(),
        (false, true) => italic.to_string(),
        (true, true) => format!("{bold}{italic}"),
    };
    if style.is_empty() {
        base.to_string()
    } else {
        format!("{base}-{style}")
    }
}

/// `Font { … }` then `[DEF name] Text2 / Text3 { … }`.
pub fn write(out: &mut Out, def: &str, t: &TextSpec) {
    out.line(&format!(
        "Font {{ name {} size {} }}",
        quoted(&font_name(t)),
        num(t.size)
    ));
    let (node, parts) = match t.kind {
        TextKind::Text2 => ("Text2", None),
        TextKind::Text3 {
            front,
            sides,
            back,
            depth,
        } => {
            if sides && depth != TEXT3_DEPTH {
                // The profile's x is the depth.
                out.line(&format!(
                    "ProfileCoordinate2 {{ point [ 0 0, {} 0 ] }}",
                    num(depth)
                ));
                out.line("LinearProfile { index [ 0, 1 ] }");
            }
            let mut p: Vec<&str> = Vec::new();
            for (on, w) in [(front, "FRONT"), (sides, "SIDES"), (back, "BACK")] {
                if on {
                    p.push(w);
                }
            }
            (
                "Text3",
                Some(if p.is_empty() {
                    "FRONT".to_string()
                } else {
                    p.join(" | ")
                }),
            )
        }
        _ => ("Text3", Some("FRONT".to_string())),
    };
    out.open(&format!("{def}{node}"));
    let strings: Vec<String> = t.strings.iter().map(|s| quoted(s)).collect();
    out.line(&format!("string [ {} ]", strings.join(", ")));
    if t.spacing != 1.0 {
        out.line(&format!("spacing {}", num(t.spacing)));
    }
    let j = match t.justify[0] {
        Justify::First | Justify::Begin => "LEFT",
        Justify::Middle => "CENTER",
        Justify::End => "RIGHT",
    };
    out.line(&format!("justification {j}"));
    if let Some(p) = parts {
        let p = if p.contains('|') { format!("({p})") } else { p };
        out.line(&format!("parts {p}"));
    }
    out.close("}");
}
