//! Text nodes drawn as geometry: goldens of hand-written scenes
//! (`tests/data/text/`: VRML97 Text + FontStyle families, styles,
//! justification and directions; Inventor Text3 with sides) and one corpus
//! file (VRML 1.0 AsciiText, compared side by side with Coin 4 before it
//! was kept), plus what text must do for framing and picking.

#[path = "common/golden.rs"]
mod golden;

use animed::internals::render::job::{render_at, FrameSpec, Headlight};
use animed::internals::render::Frame;
use animed::internals::scene::{NodeKind, Scene};
use std::path::Path;

fn load(file: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/text")
        .join(file);
    animed::internals::format::load(&path)
        .expect("test file loads")
        .scene
}

fn draw(scene: &Scene, w: u32, h: u32) -> Frame {
    let spec = FrameSpec {
        width: w,
        height: h,
        viewpoint: None,
        style: None,
        background: Some(glam::Vec3::new(0.3, 0.1, 0.3)),
        headlight: Headlight::Auto,
        threads: 0,
        aa: 1,
    };
    render_at(scene, &spec, 0.0).expect("renders")
}

/// Object ids (node index + 1) of the scene's shapes, in node order.
fn shape_ids(scene: &Scene) -> Vec<u32> {
    scene
        .nodes
        .iter()
        .enumerate()
        .filter(|(_, n)| matches!(n.kind, NodeKind::Shape(_)))
        .map(|(i, _)| i as u32 + 1)
        .collect()
}

/// Inventor source read and drawn at 160×120, with its shapes' ids.
fn draw_iv(src: &str) -> (Frame, Vec<u32>) {
    let l = animed::internals::format::load_bytes(src.as_bytes(), Path::new("t.iv")).unwrap();
    (draw(&l.scene, 160, 120), shape_ids(&l.scene))
}

/// SERIF / SANS / TYPEWRITER in PLAIN, BOLD, ITALIC, BOLDITALIC, each line
/// centred on x = 0 (justify MIDDLE); '8', 'O', '&', '@' show the holes.
#[test]
fn golden_text_families_and_styles() {
    golden::check("text_vrml97_styles", &draw(&load("styles.wrl"), 320, 240));
}

/// END/END against the axes, a vertical column, right-to-left, `length`
/// and `maxExtent`.
#[test]
fn golden_text_justify_and_directions() {
    golden::check("text_vrml97_layout", &draw(&load("layout.wrl"), 320, 240));
}

/// Inventor Text3 extruded (parts ALL, lit sides) and a flat two-line Text3.
#[test]
fn golden_text3_extruded() {
    golden::check("text_iv_text3", &draw(&load("text3.iv"), 240, 180));
}

/// castle-engine demo-models `text/vrml_1/text_textured.wrl`: two
/// AsciiTexts, the second one rotated back (its textures are missing, so
/// both are plain, as in Coin's picture of it).
#[test]
fn golden_ascii_text_corpus_file() {
    golden::check(
        "text_vrml1_text_textured",
        &draw(&load("text_textured.wrl"), 320, 240),
    );
}

/// A file holding only text is framed on the text (view-all counts it),
/// and every text pixel picks its Shape node.
#[test]
fn text_is_framed_and_picked() {
    let s = load("styles.wrl");
    let f = draw(&s, 160, 120);
    let shapes = shape_ids(&s);
    assert_eq!(shapes.len(), 4);
    for id in &shapes {
        let n = f.ids.iter().filter(|i| *i == id).count();
        assert!(n > 50, "text shape {id} covers {n} pixels");
    }
    // Without its Viewpoint the view-all camera frames the text: ink
    // reaches near both sides of the picture.
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/text/styles.wrl"),
    )
    .unwrap()
    .replace("Viewpoint { position 0 0 9 }", "");
    let dir = std::env::temp_dir().join(format!("animed-text-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("noview.wrl");
    std::fs::write(&p, src).unwrap();
    let s = animed::internals::format::load(&p).unwrap().scene;
    let f = draw(&s, 160, 120);
    let cols: Vec<u32> = (0..f.width)
        .filter(|&x| (0..f.height).any(|y| f.ids[(y * f.width + x) as usize] != 0))
        .collect();
    let (lo, hi) = (cols[0], *cols.last().unwrap());
    assert!(lo < 40 && hi > 120, "text spans columns {lo}..{hi} of 160");
    std::fs::remove_dir_all(&dir).ok();
}

/// Inventor Text2 is a label of a pixel size: view-all frames the rest of
/// the scene (and the label's anchor), as Coin does, so a long label does
/// not shrink the model.
#[test]
fn text2_labels_do_not_change_the_framing() {
    let with = "#Inventor V2.1 ascii\nSeparator { Cube {} }\n\
                Separator { Translation { translation 1 1 1 }\n\
                Text2 { string \"a long label that reaches far to the right\" } }\n";
    let without = "#Inventor V2.1 ascii\nSeparator { Cube {} }\n";
    let cube_pixels = |src: &str| {
        let (f, shapes) = draw_iv(src);
        f.ids.iter().filter(|&&i| i == shapes[0]).count()
    };
    let (a, b) = (cube_pixels(with), cube_pixels(without));
    assert!(a > 1000);
    assert_eq!(a, b);
}

/// Inventor Text2 is drawn `Font.size` pixels high facing the viewer
/// whatever the distance and the rotation above it (as Coin's SoText2
/// bitmaps are): an 'H' 20 pixels in size is about 13 pixels high (cap
/// height 0.655 em) with the camera 10 or 40 units away, and a 90° turn
/// of its group leaves it upright.
#[test]
fn text2_labels_keep_their_pixel_size_and_face_the_viewer() {
    let ink = |distance: f32, turn: &str| {
        let src = format!(
            "#Inventor V2.1 ascii\nSeparator {{ PerspectiveCamera {{ position 0 0 {distance} }}\n\
             Cube {{ width 0.1 height 0.1 depth 0.1 }}\n\
             Separator {{ Translation {{ translation 0.5 0 0 }} {turn}\n\
             Font {{ size 20 }} Text2 {{ string \"HHHH\" }} }} }}\n"
        );
        let (f, shapes) = draw_iv(&src);
        let label = *shapes.last().unwrap();
        let px: Vec<(u32, u32)> = (0..f.height)
            .flat_map(|y| (0..f.width).map(move |x| (x, y)))
            .filter(|&(x, y)| f.ids[(y * f.width + x) as usize] == label)
            .collect();
        assert!(!px.is_empty(), "label drawn at distance {distance}");
        let w = px.iter().map(|p| p.0).max().unwrap() - px.iter().map(|p| p.0).min().unwrap() + 1;
        let h = px.iter().map(|p| p.1).max().unwrap() - px.iter().map(|p| p.1).min().unwrap() + 1;
        (w, h)
    };
    let near = ink(10.0, "");
    let far = ink(40.0, "");
    let turned = ink(
        10.0,
        "RotationXYZ { axis Z angle 1.5708 } Scale { scaleFactor 3 3 3 }",
    );
    assert!((12..=14).contains(&near.1), "{near:?}");
    assert!(near.0 > 2 * near.1, "{near:?}");
    for other in [far, turned] {
        assert!(
            near.0.abs_diff(other.0) <= 1 && near.1.abs_diff(other.1) <= 1,
            "{near:?} vs {other:?}"
        );
    }
}

/// View-all frames Inventor `Text2` labels by their pixel rectangles as
/// Coin's camera before view-all sees them (`render/coin_bounds.rs`): for
/// the Inventor sample `text.iv` (data/models/simple) at 160×120, Coin 4
/// (pivy) put its camera at (−0.0828, −0.0247, 5.4395) — its box x
/// −1.8225..1.6569, y −1.0493..1 holds the cube and the two labels whose
/// rectangles reach the view from 2 units away ("brown", "lazy"); the
/// labels at the camera's own depth and those above the view count
/// nothing. Counting the anchors alone put it at z 4.18.
#[test]
fn text2_files_are_framed_as_coin_frames_them() {
    let scene = text_iv();
    let pose = animed::internals::anim::evaluate(&scene, 0.0);
    let v = animed::internals::render::View::view_all_for_picture(&scene, &pose, &pose, 160, 120);
    let coin = glam::Vec3::new(-0.0828, -0.0247, 5.4395);
    assert!((v.eye - coin).length() < 0.05, "{} vs Coin's {coin}", v.eye);
}

/// The viewer's view-all and the editor's frame-all count Text2 labels as
/// `animed render` does for a picture of their size: the viewer's camera
/// is Coin's for text.iv, and the editor frames the box that holds the
/// labels' pixel rectangles, which reaches past their anchors.
#[test]
fn viewer_and_editor_frame_text2_labels_as_render_does() {
    use animed::internals::render::{scene_bounds, scene_bounds_for_picture};
    let scene = text_iv();
    let pose = animed::internals::anim::evaluate(&scene, 0.0);
    let eye = animed::internals::viewer::Eye::ViewAll;
    let v = eye.view(&scene, &pose, &[], 160, 120);
    let coin = glam::Vec3::new(-0.0828, -0.0247, 5.4395);
    assert!(
        (v.eye - coin).length() < 0.05,
        "viewer {} vs Coin's {coin}",
        v.eye
    );

    // A label inside the view Coin's box is taken with (text.iv's labels
    // at y = ±1 are outside it at the editor's viewport size and count
    // nothing there, as in `render`), reaching right of its anchor.
    let src = "#Inventor V2.1 ascii\nSeparator { Font { size 20 } Cube { }\n\
               Separator { Transform { translation 1 0 -2 } Text2 { string \"a long label\" } } }";
    let scene = animed::internals::format::load_bytes(src.as_bytes(), Path::new("label.iv"))
        .unwrap()
        .scene;
    let pose = animed::internals::anim::evaluate(&scene, 0.0);
    let e = animed::internals::editor::Editor::new(scene.clone(), None, 640, 480);
    let vp = e.layout().viewport;
    let (w, h) = (vp.w.max(1) as u32, vp.h.max(1) as u32);
    let (lo, hi) = scene_bounds_for_picture(&scene, &pose, w, h).unwrap();
    let (alo, ahi) = scene_bounds(&scene, &pose).unwrap();
    assert!(
        hi.x > ahi.x + 0.1 && lo.x <= alo.x,
        "{lo} {hi} vs anchors {alo} {ahi}"
    );
    let centre = (lo + hi) * 0.5;
    let cam = e.camera();
    assert!(
        (cam.target - centre).length() < 1e-4,
        "{} vs {centre}",
        cam.target
    );
    let r = (hi - lo).length() * 0.5;
    let want = r / (cam.fov_y * 0.5).sin() * 1.1;
    assert!(
        (cam.distance - want).abs() < 1e-3,
        "{} vs {want}",
        cam.distance
    );
}

/// Coin's text.iv: eight Text2 labels at a cube's corners.
fn text_iv() -> Scene {
    let mut src =
        String::from("#Inventor V2.1 ascii\nSeparator { Font { name \"Courier-Bold\" size 20 }\n");
    for (at, text, right) in [
        ("-1 1 1", "The", true),
        ("-1 1 -1", "quick", true),
        ("-1 -1 -1", "brown", true),
        ("-1 -1 1", "fox", true),
        ("1 1 1", "jumped", false),
        ("1 1 -1", "over the", false),
        ("1 -1 -1", "lazy", false),
        ("1 -1 1", "dog", false),
    ] {
        let j = if right { "justification RIGHT" } else { "" };
        src += &format!(
            " Separator {{ Transform {{ translation {at} }} Text2 {{ string \"{text}\" {j} }} }}\n"
        );
    }
    src += " Cube { }\n}\n";
    animed::internals::format::load_bytes(src.as_bytes(), Path::new("text.iv"))
        .unwrap()
        .scene
}
