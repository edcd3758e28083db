//! The material panel (issue 12's editor part), driven by headless
//! scripts: what it shows for a textured box, a group of two shapes and
//! an animated material; typed values and drags as one undo step each;
//! record mode and K keying material tracks; the wrap toggles and
//! taking the texture off; a golden of the panel on the textured box.

use super::golden;
use animed::internals::anim::{Property, Target, TargetRef, Value};
use animed::internals::editor::{material, script, Editor};
use animed::internals::render::Frame;
use animed::internals::scene::{MaterialId, Wrap};
use glam::Vec3;
use std::path::{Path, PathBuf};

const W: u32 = 480;
const H: u32 = 360;

fn scene() -> Editor {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_material.wrl");
    let loaded = animed::internals::format::load(&path).expect("the material scene loads");
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    Editor::new(loaded.scene, Some(PathBuf::from("material.wrl")), W, H)
}

fn run(ed: &mut Editor, s: &str) {
    script::run(ed, s, Path::new("material-session.txt")).expect("script runs");
}

/// Debug texts of the widgets shown now.
fn shown(ed: &Editor) -> Vec<String> {
    ed.widgets()
        .iter()
        .map(|w| format!("{:?}", w.kind))
        .collect()
}

fn has(ed: &Editor, needle: &str) -> bool {
    shown(ed).iter().any(|s| s.contains(needle))
}

/// Centre of the first widget whose debug text contains `needle`.
fn at(ed: &Editor, needle: &str) -> String {
    let w = ed
        .widgets()
        .into_iter()
        .find(|w| format!("{:?}", w.kind).contains(needle))
        .unwrap_or_else(|| panic!("no widget {needle} in {:?}", shown(ed)));
    format!("{} {}", w.rect.x + w.rect.w / 2, w.rect.y + w.rect.h / 2)
}

fn click_on(ed: &mut Editor, needle: &str) {
    let c = at(ed, needle);
    run(ed, &format!("click {c}"));
}

/// Selects `name`; its (first shape's) material.
fn material_of(ed: &mut Editor, name: &str) -> MaterialId {
    let n = ed.scene().find_node(name).expect("node");
    ed.select(Some(n));
    let sh = material::shown(ed.scene(), n).expect("a shape under it");
    sh.material
}

fn diffuse_track(ed: &Editor, m: MaterialId) -> Option<Vec<(f32, Value)>> {
    let t = ed.scene().animation.track(Target {
        of: TargetRef::Material(m),
        property: Property::Diffuse,
    })?;
    Some(
        (0..t.key_count())
            .filter_map(|i| t.key(i))
            .map(|k| (k.frame, k.value))
            .collect(),
    )
}

#[test]
fn the_panel_shows_the_textured_boxs_material() {
    let mut ed = scene();
    run(&mut ed, "select Crate");
    assert!(has(&ed, "label: \"Mat\""), "the Mat button in the header");
    assert!(ed.material_panel().is_none(), "closed until asked for");
    click_on(&mut ed, "label: \"Mat\"");
    let sh = ed.material_panel().expect("open on the box");
    assert_eq!((sh.shapes, sh.differ), (1, false));
    assert!(has(&ed, "Header(\"Material\")"));
    assert!(
        has(&ed, "text: \"Brick\""),
        "its DEF name: {:?}",
        shown(&ed)
    );
    assert!(has(&ed, "text: \"brick_imagemagick.png\""));
    assert!(has(&ed, "label: \"S:Clamp\"") && has(&ed, "label: \"T:Rep\""));
    for f in [
        "Diffuse(0)",
        "Specular(2)",
        "Emissive(1)",
        "Shininess",
        "Transparency",
    ] {
        assert!(has(&ed, &format!("Field(Material({f}))")), "{f}");
    }
    // M closes it; the object's fields are back.
    run(&mut ed, "key m");
    assert!(has(&ed, "Field(Translation(0))") && !has(&ed, "Material(Diffuse(0))"));
    run(&mut ed, "key m");
    assert!(ed.material_panel().is_some());
    // It stays open for the next shape selected.
    run(&mut ed, "select Glow");
    assert!(ed.material_panel().is_some(), "still open on another shape");
}

#[test]
fn a_group_shows_its_first_shape_and_says_how_many_differ() {
    let mut ed = scene();
    run(&mut ed, "select Pair\nkey m");
    let sh = ed.material_panel().unwrap();
    assert_eq!((sh.shapes, sh.differ), (2, true));
    assert!(has(&ed, "(first of 2 shapes)"), "{:?}", shown(&ed));
    let m = ed.scene().materials[sh.material.0 as usize].diffuse;
    assert_eq!(m, Vec3::new(0.2, 0.4, 1.0), "the sphere, first in the list");
    assert!(has(&ed, "Texture: none"));
    assert!(!has(&ed, "S:"), "no wrap toggles without a texture");
}

#[test]
fn typed_values_and_expressions_are_one_undo_step_each_and_clamps_are_said() {
    let mut ed = scene();
    let m = material_of(&mut ed, "Crate");
    run(
        &mut ed,
        "key m\nclick-field Material(Diffuse(1))\ntype 0.25*2\nkey enter",
    );
    let mat = |ed: &Editor| ed.scene().materials[m.0 as usize].clone();
    assert_eq!(mat(&ed).diffuse, Vec3::new(0.9, 0.5, 0.7));
    assert_eq!(ed.history().labels().count(), 1);
    assert!(
        ed.status().text.contains("Diffuse g = 0.5"),
        "{:?}",
        ed.status()
    );
    run(
        &mut ed,
        "click-field Material(Shininess)\ntype 3\nkey enter",
    );
    assert_eq!(mat(&ed).shininess, 1.0);
    let t = &ed.status().text;
    assert!(t.contains("Shininess: 3") && t.contains("set to 1"), "{t}");
    run(
        &mut ed,
        "click-field Material(Transparency)\ntype half\nkey enter",
    );
    assert!(ed.status().error && ed.status().text.contains("'half' is not a number"));
    assert_eq!(ed.history().labels().count(), 2);
    run(&mut ed, "key ctrl+z");
    assert_eq!(mat(&ed).shininess, 0.4);
    run(&mut ed, "key ctrl+z");
    assert_eq!(mat(&ed).diffuse, Vec3::new(0.9, 0.8, 0.7));
    // A drag previews live and records once at release.
    let f = at(&ed, "Material(Emissive(0))");
    let (x, y) = f.split_once(' ').unwrap();
    let x: i32 = x.parse().unwrap();
    run(&mut ed, &format!("drag {x} {y} {} {y}", x + 40));
    let e = mat(&ed).emissive.x;
    assert!((e - 0.2).abs() < 0.02, "40 px × 0.005 = 0.2, got {e}");
    assert_eq!(ed.history().labels().count(), 1);
}

#[test]
fn an_animated_material_keeps_a_change_pending_until_k_and_record_mode_keys() {
    let mut ed = scene();
    let m = material_of(&mut ed, "Glow");
    let before = diffuse_track(&ed, m).expect("the ColorInterpolator's track");
    // The strip has no rows for material tracks: its line says where they are.
    let hint = ed
        .material_keys_hint()
        .expect("a hint for an animated material");
    assert!(hint.starts_with("Material keys at 0 12 24"), "{hint}");
    assert!(before.iter().all(|(f, _)| *f != 54.0), "{before:?}");
    run(&mut ed, "key m\nclick-field Frame\ntype 54\nkey enter");
    run(
        &mut ed,
        "click-field Material(Diffuse(2))\ntype 0.9\nkey enter",
    );
    // Pending: shown, not stored, no undo step.
    assert_eq!(diffuse_track(&ed, m).unwrap(), before);
    assert_eq!(ed.history().labels().count(), 0);
    assert!(ed.material_pending().is_some());
    assert!((ed.shown_material(m).unwrap().diffuse.z - 0.9).abs() < 1e-6);
    assert!(ed.status().text.contains("K keys"), "{:?}", ed.status());
    run(&mut ed, "key k");
    let after = diffuse_track(&ed, m).unwrap();
    assert_eq!(after.len(), before.len() + 1, "{after:?}");
    let k = after.iter().find(|(f, _)| *f == 54.0).expect("a key at 54");
    let Value::Vec3(c) = k.1 else {
        panic!("colour")
    };
    assert!((c.z - 0.9).abs() < 1e-6, "{c}");
    assert_eq!(ed.history().labels().count(), 1);
    // A new frame drops a pending change.
    run(
        &mut ed,
        "click-field Material(Diffuse(0))\ntype 0.1\nkey enter\nkey right",
    );
    assert!(ed.material_pending().is_none());
    // Record mode keys an unanimated property at once, one undo step.
    run(&mut ed, "key r\nclick-field Frame\ntype 24\nkey enter");
    run(
        &mut ed,
        "click-field Material(Shininess)\ntype 0.7\nkey enter",
    );
    let shin = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Material(m),
            property: Property::Shininess,
        })
        .expect("a shininess track");
    assert_eq!(shin.key_count(), 1);
    assert_eq!(shin.key(0).unwrap().frame, 24.0);
    assert_eq!(ed.scene().materials[m.0 as usize].shininess, 0.7);
    assert_eq!(ed.history().labels().count(), 2);
    run(&mut ed, "key ctrl+z");
    let gone = ed.scene().animation.track(Target {
        of: TargetRef::Material(m),
        property: Property::Shininess,
    });
    assert!(gone.is_none());
    assert_eq!(ed.scene().materials[m.0 as usize].shininess, 0.2);
    // K over a field of an unanimated property keys it.
    run(&mut ed, "key r");
    let spec = at(&ed, "Material(Specular(0))");
    run(&mut ed, &format!("move {spec}\nkey k"));
    assert!(ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Material(m),
            property: Property::Specular,
        })
        .is_some());
}

#[test]
fn wrap_toggles_and_removing_the_texture_are_undoable() {
    let mut ed = scene();
    let m = material_of(&mut ed, "Crate");
    let tex = |ed: &Editor| ed.scene().materials[m.0 as usize].texture.clone();
    run(&mut ed, "key m");
    click_on(&mut ed, "label: \"S:Clamp\"");
    assert_eq!(tex(&ed).unwrap().wrap_s, Wrap::Repeat);
    assert!(has(&ed, "label: \"S:Rep\""));
    click_on(&mut ed, "label: \"T:Rep\"");
    assert_eq!(tex(&ed).unwrap().wrap_t, Wrap::Clamp);
    run(&mut ed, "key ctrl+z\nkey ctrl+z");
    let t = tex(&ed).unwrap();
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Clamp, Wrap::Repeat));
    click_on(&mut ed, "label: \"x\"");
    assert!(tex(&ed).is_none());
    assert!(has(&ed, "Texture: none"));
    assert!(ed.status().text.contains("brick_imagemagick.png removed"));
    run(&mut ed, "key ctrl+z");
    assert!(tex(&ed).is_some());
}

#[test]
fn load_replaces_the_texture_through_the_browser_and_says_why_a_file_is_refused() {
    let mut ed = scene();
    let m = material_of(&mut ed, "Crate");
    let tex = |ed: &Editor| ed.scene().materials[m.0 as usize].texture.clone();
    let image_of = |ed: &Editor| {
        let t = tex(ed).unwrap();
        let i = ed.scene().image(t.image).unwrap();
        (i.name.clone(), i.width(), i.height())
    };
    let brick = image_of(&ed);
    run(&mut ed, "key m");
    click_on(&mut ed, "label: \"Load\"");
    let b = ed.browser().expect("Load opens the file browser");
    assert_eq!(b.purpose.title(), "Texture image");
    let gltf = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf");
    // A typed folder lists its images only (not the .gltf files).
    run(&mut ed, &format!("type {}/\nkey enter", gltf.display()));
    let names: Vec<String> = ed
        .browser()
        .unwrap()
        .entries
        .iter()
        .map(|e| e.name.clone())
        .collect();
    assert!(names.contains(&"tex_2x2.png".to_string()), "{names:?}");
    assert!(!names.iter().any(|n| n.ends_with(".gltf")), "{names:?}");
    // A file that is not an image: the browser stays and says why.
    let d = std::env::temp_dir().join(format!("animed-mat-load-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let bad = d.join("broken.png");
    std::fs::write(&bad, b"not a png at all").unwrap();
    run(&mut ed, &format!("type {}\nkey enter", bad.display()));
    let msg = ed.browser().expect("still open").message.clone().unwrap();
    assert!(msg.starts_with("cannot read texture 'broken.png'"), "{msg}");
    assert!(ed.status().error);
    assert_eq!(image_of(&ed), brick, "nothing changed");
    // A real image replaces the brick and keeps the wrap (S clamped).
    let png = gltf.join("tex_2x2.png");
    // The refused path stays typed; a '/' typed after it starts afresh.
    run(&mut ed, &format!("type /{}\nkey enter", png.display()));
    assert!(ed.browser().is_none(), "closed once used");
    assert_eq!(image_of(&ed), ("tex_2x2.png".to_string(), 2, 2));
    assert_eq!(tex(&ed).unwrap().wrap_s, Wrap::Clamp, "the wrap is kept");
    assert!(
        ed.status().text.contains("texture tex_2x2.png (2x2)"),
        "{}",
        ed.status().text
    );
    assert!(has(&ed, "\"tex_2x2.png\""), "the row names the new file");
    // One undo step brings the brick back, redo the new image.
    run(&mut ed, "key ctrl+z");
    assert_eq!(image_of(&ed), brick);
    run(&mut ed, "key ctrl+shift+z");
    assert_eq!(image_of(&ed).0, "tex_2x2.png");
    // A material without a texture gets a plain repeating one.
    click_on(&mut ed, "label: \"x\"");
    assert!(tex(&ed).is_none());
    click_on(&mut ed, "label: \"Load\"");
    run(&mut ed, &format!("type {}\nkey enter", png.display()));
    let t = tex(&ed).expect("textured again");
    assert_eq!((t.wrap_s, t.wrap_t), (Wrap::Repeat, Wrap::Repeat));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn an_emissive_map_is_named_in_the_panel() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf/emissive.gltf");
    let loaded = animed::internals::format::load(&path).expect("emissive.gltf loads");
    let mut ed = Editor::new(loaded.scene, Some(path.clone()), W, H);
    let glowing: Vec<usize> = (0..ed.scene().materials.len())
        .filter(|&i| ed.scene().materials[i].emissive_texture.is_some())
        .collect();
    assert!(!glowing.is_empty(), "the file has an emissive map");
    let shape = (0..ed.scene().nodes.len() as u32)
        .map(animed::internals::scene::NodeId)
        .find(|&n| {
            material::shown(ed.scene(), n)
                .is_some_and(|s| glowing.contains(&(s.material.0 as usize)))
        })
        .expect("a shape with the emissive map");
    ed.select(Some(shape));
    run(&mut ed, "key m");
    // The panel's last row: the wheel over the properties brings it in.
    let props = ed.side_panel().props;
    let over = (props.x + props.w / 2, props.bottom() - 4);
    run(&mut ed, &format!("wheel -4 {} {}", over.0, over.1));
    assert!(has(&ed, "Emissive map: "), "{:?}", shown(&ed));
    // A material without one has no such row.
    let plain = (0..ed.scene().nodes.len() as u32)
        .map(animed::internals::scene::NodeId)
        .find(|&n| {
            material::shown(ed.scene(), n)
                .is_some_and(|s| !glowing.contains(&(s.material.0 as usize)))
        });
    if let Some(p) = plain {
        ed.select(Some(p));
        run(&mut ed, &format!("wheel -4 {} {}", over.0, over.1));
        assert!(has(&ed, "Texture"), "scrolled to the panel's end");
        assert!(!has(&ed, "Emissive map: "));
    }
}

/// The right part of the window: the textured box and the panel.
fn crop(f: &Frame, x0: u32, y0: u32, w: u32, h: u32) -> Frame {
    let mut out = Frame::new(w, h, Vec3::ZERO);
    for y in 0..h {
        for x in 0..w {
            out.color[(y * w + x) as usize] = f.color[((y0 + y) * f.width + x0 + x) as usize];
        }
    }
    out
}

#[test]
fn golden_material_panel_on_a_textured_box() {
    let mut ed = scene();
    run(&mut ed, "select Crate\nkey f\nkey m");
    let side = ed.layout().side;
    let f = ed.render_frame();
    let (w, h) = (320u32, 240u32);
    let x0 = (side.x + side.w) as u32 - w;
    let y0 = (side.y + side.h) as u32 - h;
    let c = crop(&f, x0, y0, w, h);
    // The thumbnail shows the brick's colours, not a flat box.
    let mut colours: Vec<u32> = c.color.clone();
    colours.sort_unstable();
    colours.dedup();
    assert!(colours.len() > 50);
    golden::check("editor_material_panel", &c);
}
