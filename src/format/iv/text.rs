//! VRML 1.0 `AsciiText` + `FontStyle` and Inventor `Text2` / `Text3` +
//! `Font` → a [`TextSpec`] and its mesh (built by `format::text`).
//!
//! Both formats put the first line's baseline at y = 0 and run lines
//! downwards, `spacing × size` apart; LEFT/CENTER/RIGHT justification
//! is VRML97's BEGIN/MIDDLE/END along the line (VRML 1.0 spec,
//! "AsciiText"; The Inventor Mentor, ch. 7). Default size: 10.
//!
//! `Text2` is screen-aligned at a constant pixel size in Inventor; here it
//! is flat geometry in the local x-y plane, `size` pixels of a view the
//! rest of the scene fills ([`size_text2`]; an approximation, see the
//! README). `Text3`'s sides are extruded to the depth of the current
//! profile (`ProfileCoordinate2` + `LinearProfile`: its largest x; no
//! bevel), or to 1 unit without one.

use super::state::State;
use crate::format::lexer::Pos;
use crate::format::syntax::AstNode;
use crate::format::text::{self, text_mesh};
use crate::scene::{FontFamily, Justify, Mesh, NodeKind, Scene, TextKind, TextSpec};
use glam::{Mat4, Vec3};

type Msgs = Vec<(Pos, String)>;

/// Builds the text mesh of an AsciiText/Text2/Text3 node with the state's
/// font and profile. Texture coordinates are always made (a texture in the
/// state may use them). Text2 is built at `size` local units; the reader
/// rescales it to pixels once the scene's extent is known.
pub fn mesh(n: &AstNode, st: &State, msgs: &mut Msgs) -> Option<Mesh> {
    let depth =
        profile_depth(st.profile.0.as_deref(), st.profile.1.as_deref()).unwrap_or(TEXT3_DEPTH);
    let spec = spec(n, st.font.as_deref(), depth, msgs);
    text::mesh_of_spec(spec, true, n.pos, msgs)
}

/// Text3's depth without a profile: 1 unit whatever the font size (what
/// Coin 4.0's bounding box of `Text3 { parts ALL }` measures: z from −1
/// to 0 at font sizes 1 and 10).
pub const TEXT3_DEPTH: f32 = 1.0;

/// The node's strings and style.
pub fn spec(n: &AstNode, font: Option<&AstNode>, depth: f32, msgs: &mut Msgs) -> TextSpec {
    let kind = match n.kind.as_str() {
        "AsciiText" => TextKind::AsciiText,
        "Text2" => TextKind::Text2,
        _ => {
            let parts = n.words("parts");
            let has = |w: &str| parts.iter().any(|p| p == w || p == "ALL");
            let (front, sides, back) = if parts.is_empty() {
                (true, false, false)
            } else {
                (has("FRONT"), has("SIDES"), has("BACK"))
            };
            TextKind::Text3 {
                front,
                sides,
                back,
                depth,
            }
        }
    };
    let justify = match n.words("justification").first().map(String::as_str) {
        None => Justify::Begin,
        Some(w) => text::justify(w)
            .filter(|_| matches!(w, "LEFT" | "CENTER" | "RIGHT"))
            .unwrap_or_else(|| {
                msgs.push((n.pos, format!("justification '{w}' unknown; LEFT used")));
                Justify::Begin
            }),
    };
    let mut s = TextSpec {
        kind,
        strings: n.strings("string"),
        family: FontFamily::Serif,
        size: 10.0,
        spacing: n.f32("spacing", 1.0),
        justify: [justify, Justify::First],
        // AsciiText's per-string `width` (0 = natural) is VRML97's length.
        length: n
            .nums("width")
            .unwrap_or_default()
            .iter()
            .map(|&w| w as f32)
            .collect(),
        ..TextSpec::default()
    };
    if let Some(f) = font {
        match f.kind.as_str() {
            "FontStyle" => {
                // VRML 1.0: family SERIF | SANS | TYPEWRITER, style bit mask.
                s.size = f.f32("size", 10.0);
                if let Some(w) = f.words("family").first() {
                    match text::family(w) {
                        Some(fam) => s.family = fam,
                        None => {
                            msgs.push((f.pos, format!("font family '{w}' unknown; SERIF used")))
                        }
                    }
                }
                for w in f.words("style") {
                    match w.as_str() {
                        "BOLD" => s.bold = true,
                        "ITALIC" => s.italic = true,
                        "NONE" => {}
                        other => msgs.push((f.pos, format!("font style '{other}' unknown"))),
                    }
                }
            }
            _ => {
                // Inventor Font: name + size.
                s.size = f.f32("size", 10.0);
                let name = f.strings("name");
                let (fam, bold, italic) =
                    text::inventor_font(name.first().map_or("defaultFont", String::as_str));
                (s.family, s.bold, s.italic) = (fam, bold, italic);
            }
        }
    }
    let mut m = Vec::new();
    text::sanitize(&mut s, 10.0, &mut m);
    msgs.extend(m.into_iter().map(|t| (n.pos, t)));
    s
}

/// Text3's extrusion depth from a profile: the largest x of the
/// ProfileCoordinate2 points a LinearProfile indexes (all when the index is
/// empty). `None` when there is no usable profile.
pub fn profile_depth(coords: Option<&AstNode>, profile: Option<&AstNode>) -> Option<f32> {
    let pts: Vec<f32> = coords?
        .nums("point")?
        .chunks_exact(2)
        .map(|c| c[0] as f32)
        .collect();
    let idx: Vec<usize> = profile
        .and_then(|p| p.nums("index"))
        .unwrap_or_default()
        .iter()
        .filter(|&&i| i >= 0.0)
        .map(|&i| i as usize)
        .collect();
    let xs: Vec<f32> = if idx.is_empty() {
        pts
    } else {
        idx.iter().filter_map(|&i| pts.get(i).copied()).collect()
    };
    xs.into_iter()
        .filter(|x| x.is_finite())
        .reduce(f32::max)
        .map(|d| d.abs())
}

/// The view height, in pixels, that Text2's pixel size is measured
/// against: the scene's bounding-box diagonal is taken to fill it (about
/// what a view-all camera does in a 320×240 picture).
pub const TEXT2_VIEW_PIXELS: f32 = 240.0;

/// Gives every Text2 its size in scene units: `size` pixels of a view in
/// which the rest of the scene's bounding box (diagonal) spans
/// [`TEXT2_VIEW_PIXELS`] — the size writers and the editor see. The
/// renderer draws it at a constant pixel size facing the viewer, as
/// Inventor does, through the `units_per_pixel` kept on its spec.
pub fn size_text2(scene: &mut Scene) {
    let text2 = |m: &Mesh| matches!(m.text.as_deref(), Some(t) if t.kind == TextKind::Text2);
    if !scene.meshes.iter().any(text2) {
        return;
    }
    let mut world = vec![Mat4::IDENTITY; scene.nodes.len()];
    for id in scene.walk() {
        let n = scene.node(id);
        let parent = n.parent.map_or(Mat4::IDENTITY, |p| world[p.0 as usize]);
        world[id.0 as usize] = parent * n.transform.matrix();
    }
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    let mut targets = Vec::new();
    for (i, n) in scene.nodes.iter().enumerate() {
        let NodeKind::Shape(s) = &n.kind else {
            continue;
        };
        let Some(m) = scene.meshes.get(s.mesh.0 as usize) else {
            continue;
        };
        if text2(m) {
            targets.push((s.mesh, world[i]));
            continue;
        }
        for p in &m.positions {
            let w = world[i].transform_point3(*p);
            if w.is_finite() {
                lo = lo.min(w);
                hi = hi.max(w);
            }
        }
    }
    let diagonal = if lo.x <= hi.x {
        (hi - lo).length()
    } else {
        0.0
    };
    let per_pixel = if diagonal > 0.0 && diagonal.is_finite() {
        diagonal / TEXT2_VIEW_PIXELS
    } else {
        2.0 / TEXT2_VIEW_PIXELS
    };
    for (mesh, w) in targets {
        let scale = w
            .x_axis
            .truncate()
            .length()
            .max(w.y_axis.truncate().length());
        let m = &mut scene.meshes[mesh.0 as usize];
        let Some(spec) = m.text.take() else { continue };
        let mut spec = spec;
        let mut drawn = (*spec).clone();
        if scale > 0.0 && scale.is_finite() {
            drawn.size = spec.size * per_pixel / scale;
            spec.units_per_pixel = per_pixel / scale;
        }
        // A label is drawn from its bitmap (`text::bitmap`), `size`
        // pixels high; one too large for a bitmap keeps its outlines. The
        // budget was asked for the same glyphs at the first build.
        let bitmap = (spec.units_per_pixel > 0.0)
            .then(|| crate::format::text::bitmap::label_mesh(&spec, spec.units_per_pixel, true))
            .flatten();
        if let Ok(mut built) = bitmap.map_or_else(|| text_mesh(&drawn, true), Ok) {
            built.name = std::mem::take(&mut m.name);
            *m = built;
        }
        m.text = Some(spec);
    }
}

#[cfg(test)]
mod tests {
    use crate::format::export::options::{InventorVersion, WriteOptions};
    use crate::format::iv::{read_nested, write::write};
    use crate::scene::{FontFamily, Justify, Mesh, NodeKind, Scene, TextKind};
    use std::path::Path;

    fn load(src: &str, vrml1: bool) -> crate::format::Loaded {
        read_nested(src.as_bytes(), Path::new("t.iv"), 0, vrml1).unwrap()
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

    #[test]
    fn ascii_text_with_vrml1_font_style() {
        let l = load(
            "#VRML V1.0 ascii\nSeparator { FontStyle { size 2 family SANS style (BOLD | ITALIC) }\n\
             AsciiText { string [\"ab\", \"c\"] justification RIGHT spacing 2 width [0, 5] } }\n",
            true,
        );
        assert!(l.warnings.is_empty(), "{:?}", l.warnings);
        let m = text_meshes(&l.scene);
        let t = m[0].text.as_deref().unwrap();
        assert_eq!(t.kind, TextKind::AsciiText);
        assert_eq!(
            (t.family, t.bold, t.italic, t.size),
            (FontFamily::Sans, true, true, 2.0)
        );
        assert_eq!(t.justify, [Justify::End, Justify::First]);
        assert_eq!(t.length, [0.0, 5.0]);
        // RIGHT: right edges at x = 0 ("c" stretched to 5 units); the
        // second line 2 × 2 units below the first.
        let (lo, hi) = m[0].bounds().unwrap();
        assert!(hi.x <= 0.0 && hi.x > -0.3, "{hi}");
        assert!(lo.x < -4.5, "{lo}");
        assert!(lo.y < -4.0 && lo.y > -5.0, "{lo}");
    }

    #[test]
    fn text3_parts_and_font_and_default_depth() {
        let l = load(
            "#Inventor V2.1 ascii\nFont { name \"Courier-Bold\" size 1 }\n\
             Text3 { string \"Hi\" parts (FRONT | SIDES | BACK) justification CENTER }\n",
            false,
        );
        let m = text_meshes(&l.scene);
        let t = m[0].text.as_deref().unwrap();
        assert_eq!((t.family, t.bold), (FontFamily::Typewriter, true));
        assert_eq!(
            t.kind,
            TextKind::Text3 {
                front: true,
                sides: true,
                back: true,
                depth: 1.0
            }
        );
        let (lo, hi) = m[0].bounds().unwrap();
        assert_eq!((lo.z, hi.z), (-1.0, 0.0));
        assert!((lo.x + hi.x).abs() < 0.05, "{lo} {hi}");
        // A profile sets the depth.
        let l = load(
            "#Inventor V2.1 ascii\nProfileCoordinate2 { point [0 0, 0.25 0] } LinearProfile { index [0, 1] }\n\
             Text3 { string \"Hi\" parts ALL }\n",
            false,
        );
        let (lo, _) = text_meshes(&l.scene)[0].bounds().unwrap();
        assert_eq!(lo.z, -0.25);
    }

    #[test]
    fn text2_is_sized_in_pixels_of_the_scene() {
        let l = load(
            "#Inventor V2.1 ascii\nSeparator { Cube { width 24 height 24 depth 0 } }\n\
             Text2 { string \"M\" }\n",
            false,
        );
        let m = text_meshes(&l.scene);
        // The cube's diagonal (24·√2 ≈ 33.9) spans 240 pixels, so one
        // pixel is about 0.141 units; 10-pixel text is drawn from its
        // bitmap (`text::bitmap`), where an 'M' (0.655 em) takes 7 whole
        // pixel rows.
        let spec = m[0].text.as_ref().unwrap();
        assert_eq!(spec.size, 10.0);
        // The renderer draws it 10 pixels high through this scale.
        assert!((spec.units_per_pixel - 33.94 / 240.0).abs() < 1e-3);
        let (lo, hi) = m[0].bounds().unwrap();
        let rows = (hi.y - lo.y) / spec.units_per_pixel;
        assert!((rows - 7.0).abs() < 1e-4, "{rows}");
    }

    #[test]
    fn inventor_writer_writes_font_and_text3() {
        let src = "#Inventor V2.1 ascii\nSeparator { Font { name \"Helvetica-Bold\" size 2 }\n\
                   Text3 { string [\"a\", \"b\\\"c\"] justification RIGHT parts (FRONT | BACK) } }\n";
        let l = load(src, false);
        let (out, _) = write(&l.scene, &WriteOptions::default());
        assert!(
            out.contains("Font { name \"Helvetica-Bold\" size 2 }"),
            "{out}"
        );
        assert!(
            out.contains("Text3 {") && out.contains("parts (FRONT | BACK)"),
            "{out}"
        );
        let again = load(&out, false);
        assert_eq!(
            text_meshes(&l.scene)[0].text,
            text_meshes(&again.scene)[0].text
        );
        // Inventor 1.0 output keeps the triangles.
        let v1 = WriteOptions {
            inventor_version: InventorVersion::V1_0,
            ..WriteOptions::default()
        };
        let (out, _) = write(&l.scene, &v1);
        assert!(
            !out.contains("Text3") && out.contains("IndexedFaceSet"),
            "{out}"
        );
    }
}
