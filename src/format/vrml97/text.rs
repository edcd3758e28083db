//! VRML97 `Text` + `FontStyle` (ISO/IEC 14772-1 §6.47, §6.20) → a
//! [`TextSpec`] and its mesh (built by `format::text`).

use crate::format::lexer::Pos;
use crate::format::syntax::AstNode;
use crate::format::text;
use crate::scene::{Justify, Mesh, TextSpec};

type Msgs = Vec<(Pos, String)>;

/// The mesh of a Text node, with its spec kept on it.
pub fn mesh(g: &AstNode, textured: bool, msgs: &mut Msgs) -> Option<Mesh> {
    let spec = spec(g, msgs);
    text::mesh_of_spec(spec, textured, g.pos, msgs)
}

/// Reads the Text node's fields and its FontStyle (defaults of §6.20 when
/// there is none).
pub fn spec(g: &AstNode, msgs: &mut Msgs) -> TextSpec {
    let mut s = TextSpec {
        strings: g.strings("string"),
        length: g
            .nums("length")
            .unwrap_or_default()
            .iter()
            .map(|&v| v as f32)
            .collect(),
        max_extent: g.f32("maxExtent", 0.0),
        ..TextSpec::default()
    };
    if let Some(fs) = g.node("fontStyle") {
        let fs = fs.effective();
        font_style(&fs, &mut s, msgs);
    }
    let mut m = Vec::new();
    text::sanitize(&mut s, 1.0, &mut m);
    msgs.extend(m.into_iter().map(|t| (g.pos, t)));
    s
}

/// FontStyle's fields onto `s` (§6.20).
fn font_style(fs: &AstNode, s: &mut TextSpec, msgs: &mut Msgs) {
    if fs.kind != "FontStyle" {
        msgs.push((
            fs.pos,
            format!("fontStyle holds a {}, not a FontStyle; ignored", fs.kind),
        ));
        return;
    }
    s.size = fs.f32("size", 1.0);
    s.spacing = fs.f32("spacing", 1.0);
    s.horizontal = fs.bool("horizontal", true);
    s.left_to_right = fs.bool("leftToRight", true);
    s.top_to_bottom = fs.bool("topToBottom", true);
    // The first family the browser knows wins (§6.20.2).
    let families = fs.strings("family");
    if let Some(f) = families.iter().find_map(|f| text::family(f)) {
        s.family = f;
    } else if !families.is_empty() {
        msgs.push((
            fs.pos,
            format!("font family {families:?} unknown; SERIF used"),
        ));
    }
    let style = fs.strings("style");
    match style.first().map(String::as_str).unwrap_or("PLAIN") {
        "PLAIN" | "" => {}
        "BOLD" => s.bold = true,
        "ITALIC" => s.italic = true,
        "BOLDITALIC" => (s.bold, s.italic) = (true, true),
        other => msgs.push((fs.pos, format!("font style '{other}' unknown; PLAIN used"))),
    }
    // justify: major, then minor (FIRST when missing), §6.20.3.
    let words = fs.strings("justify");
    let mut j = [Justify::Begin, Justify::First];
    for (slot, w) in j.iter_mut().zip(&words) {
        match text::justify(w) {
            Some(v) if !matches!(w.as_str(), "LEFT" | "CENTER" | "RIGHT") => *slot = v,
            _ => msgs.push((fs.pos, format!("justify '{w}' unknown; ignored"))),
        }
    }
    s.justify = j;
}

#[cfg(test)]
mod tests {
    use crate::format::export::options::WriteOptions;
    use crate::format::vrml97::{read, write::write};
    use crate::scene::{FontFamily, Justify, Mesh, NodeKind, Scene, TextKind};
    use std::path::Path;

    fn load(src: &str) -> crate::format::Loaded {
        read(src.as_bytes(), Path::new("t.wrl")).unwrap()
    }

    fn text_meshes(s: &Scene) -> Vec<&Mesh> {
        s.nodes
            .iter()
            .filter_map(|n| match &n.kind {
                NodeKind::Shape(sh) => Some(&s.meshes[sh.mesh.0 as usize]),
                _ => None,
            })
            .filter(|m| m.text.is_some())
            .collect()
    }

    const LABEL: &str = r#"#VRML V2.0 utf8
Shape {
  appearance Appearance { material Material { diffuseColor 1 0 0 } }
  geometry DEF Label Text {
    string [ "Hello", "World" ]
    length [ 3 ]
    fontStyle FontStyle {
      family [ "FANCY", "SANS" ] style "BOLDITALIC" size 0.5 spacing 1.5
      justify [ "MIDDLE", "BEGIN" ]
    }
  }
}
"#;

    #[test]
    fn text_and_font_style_are_read() {
        let l = load(LABEL);
        assert!(l.warnings.is_empty(), "{:?}", l.warnings);
        let m = text_meshes(&l.scene);
        assert_eq!(m.len(), 1);
        let t = m[0].text.as_deref().unwrap();
        assert_eq!(t.kind, TextKind::Text);
        assert_eq!(t.strings, ["Hello", "World"]);
        assert_eq!(t.family, FontFamily::Sans);
        assert!(t.bold && t.italic);
        assert_eq!((t.size, t.spacing), (0.5, 1.5));
        assert_eq!(t.justify, [Justify::Middle, Justify::Begin]);
        assert_eq!(t.length, [3.0]);
        assert_eq!(m[0].name, "Label");
        // Real geometry: MIDDLE centres each line on x = 0; "Hello" is
        // stretched to length 3; BEGIN puts the top of the text at y = 0.
        let (lo, hi) = m[0].bounds().unwrap();
        assert!(
            lo.x > -1.6 && lo.x < -1.4 && hi.x > 1.4 && hi.x < 1.6,
            "{lo} {hi}"
        );
        assert!(hi.y <= 1e-6 && hi.y > -0.2, "{hi}");
        assert!(lo.y < -0.75 - 0.3, "{lo}");
        assert!(!m[0].solid);
    }

    #[test]
    fn bad_font_style_values_warn_with_a_location() {
        let l = load(
            r#"#VRML V2.0 utf8
Shape { geometry Text { string "x" fontStyle FontStyle {
  family "NOPE" style "HEAVY" size -2 justify [ "LEFT" ] } } }
"#,
        );
        let w = l.warnings.join("\n");
        for want in ["family", "HEAVY", "size -2", "justify 'LEFT'"] {
            assert!(w.contains(want), "{want} not in {w}");
        }
        assert!(w.contains("t.wrl:2:"), "{w}");
        let m = text_meshes(&l.scene);
        assert_eq!(m[0].text.as_ref().unwrap().size, 1.0);
    }

    #[test]
    fn empty_strings_make_no_shape() {
        let l = load("#VRML V2.0 utf8\nShape { geometry Text { string [ \"\", \" \" ] } }\n");
        assert!(text_meshes(&l.scene).is_empty());
        assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    }

    #[test]
    fn the_writer_writes_a_text_node_that_reads_back_the_same() {
        let l = load(LABEL);
        let (out, _) = write(&l.scene, &WriteOptions::default());
        assert!(out.contains("Text {"), "{out}");
        assert!(!out.contains("IndexedFaceSet"), "{out}");
        let again = load(&out);
        let a = text_meshes(&l.scene);
        let b = text_meshes(&again.scene);
        assert_eq!(a[0].text, b[0].text);
        assert_eq!(a[0].positions, b[0].positions);
    }

    #[test]
    fn a_text_past_the_geometry_budget_fails_the_load_before_it_is_built() {
        use crate::format::limits::{scope_with, Limits};
        let src = format!(
            "#VRML V2.0 utf8\nShape {{ geometry Text {{ string \"{}\" }} }}\n",
            "@".repeat(5000)
        );
        let small = Limits {
            max_geometry: 100_000,
            ..Limits::default()
        };
        let e = scope_with(small, || read(src.as_bytes(), Path::new("t.wrl"))).unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.contains("input budget exceeded") && msg.contains("t.wrl:2:"),
            "{msg}"
        );
    }
}
