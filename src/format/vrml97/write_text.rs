//! Writes a text mesh back as a VRML97 `Text` node with its `FontStyle`
//! (ISO/IEC 14772-1 §6.47, §6.20) instead of its triangles.
//!
//! VRML97 has no screen-aligned text and no extruded text: Inventor's
//! `Text2` and a `Text3` with sides or back stay triangles (the caller's
//! IndexedFaceSet).

use crate::format::export::text::{num, quoted, Out};
use crate::scene::{FontFamily, Justify, Mesh, TextKind, TextSpec};

/// The spec to write as a Text node, when VRML97 can say what it means.
pub fn writable(mesh: &Mesh) -> Option<&TextSpec> {
    let t = mesh.text.as_deref()?;
    match t.kind {
        TextKind::Text | TextKind::AsciiText => Some(t),
        TextKind::Text3 { sides, back, .. } if !sides && !back => Some(t),
        _ => None,
    }
}

fn justify_word(j: Justify) -> &'static str {
    match j {
        Justify::First => "FIRST",
        Justify::Begin => "BEGIN",
        Justify::Middle => "MIDDLE",
        Justify::End => "END",
    }
}

/// `geometry [DEF name] Text { … }`; fields at their defaults are left out.
pub fn write(out: &mut Out, def: &str, t: &TextSpec) {
    out.open(&format!("geometry {def}Text"));
    let strings: Vec<String> = t.strings.iter().map(|s| quoted(s)).collect();
    out.line(&format!("string [ {} ]", strings.join(", ")));
    if t.length.iter().any(|&l| l != 0.0) {
        let l: Vec<String> = t.length.iter().map(|&l| num(l)).collect();
        out.line(&format!("length [ {} ]", l.join(", ")));
    }
    if t.max_extent != 0.0 {
        out.line(&format!("maxExtent {}", num(t.max_extent)));
    }
    out.open("fontStyle FontStyle");
    let family = match t.family {
        FontFamily::Serif => "SERIF",
        FontFamily::Sans => "SANS",
        FontFamily::Typewriter => "TYPEWRITER",
    };
    out.line(&format!("family \"{family}\""));
    let style = match (t.bold, t.italic) {
        (false, false) => "PLAIN",
        (true, false) => "BOLD",
        (false, true) => "ITALIC",
        (true, true) => "BOLDITALIC",
    };
    out.line(&format!("style \"{style}\""));
    out.line(&format!("size {}", num(t.size)));
    if t.spacing != 1.0 {
        out.line(&format!("spacing {}", num(t.spacing)));
    }
    out.line(&format!(
        "justify [ \"{}\", \"{}\" ]",
        justify_word(t.justify[0]),
        justify_word(t.justify[1])
    ));
    for (name, v) in [
        ("horizontal", t.horizontal),
        ("leftToRight", t.left_to_right),
        ("topToBottom", t.top_to_bottom),
    ] {
        if !v {
            out.line(&format!("{name} FALSE"));
        }
    }
    out.close("}");
    out.close("}");
}
