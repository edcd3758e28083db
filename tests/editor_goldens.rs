//! Screenshots of editor states, driven by headless scripts exactly as
//! `animed edit --script` runs them, compared with goldens/editor_*.png.
//! `UPDATE_GOLDENS=1` rewrites them (look at every one).

#[path = "common/golden.rs"]
mod golden;

mod editor_material;

use animed::internals::editor::panel::WidgetKind;
use animed::internals::editor::{script, Editor};
use animed::internals::scene::{NodeId, Scene};
use std::path::{Path, PathBuf};

// 480×320: the smallest size at which every panel row fits (the side panel
// needs ~16 rows); `resized_window` shows the 320×240 layout.
const W: u32 = 480;
const H: u32 = 320;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// The editor on the frozen copy of the demo stage.
fn stage(w: u32, h: u32) -> Editor {
    let path = data("editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    Editor::new(loaded.scene, Some(PathBuf::from("stage.wrl")), w, h)
}

fn run(ed: &mut Editor, s: &str) {
    script::run(ed, s, Path::new("golden-session.txt")).expect("script parses");
}

/// Centre of the first widget whose debug text contains `needle`.
fn at(ed: &Editor, needle: &str) -> (i32, i32) {
    let w = ed
        .widgets()
        .into_iter()
        .find(|w| format!("{:?}", w.kind).contains(needle))
        .unwrap_or_else(|| panic!("no widget {needle}"));
    (w.rect.x + w.rect.w / 2, w.rect.y + w.rect.h / 2)
}

/// A viewport pixel where clicking picks `id`.
fn pixel_of(ed: &mut Editor, id: NodeId) -> (i32, i32) {
    let vp = ed.layout().viewport;
    for y in (vp.y..vp.bottom()).step_by(3) {
        for x in (vp.x..vp.right()).step_by(3) {
            if ed.pick_at(x as f32, y as f32) == Some(id) {
                return (x, y);
            }
        }
    }
    panic!("node {id:?} is not visible");
}

fn node(ed: &Editor, name: &str) -> NodeId {
    ed.scene().find_node(name).expect("node in the stage")
}

fn check(name: &str, ed: &mut Editor) {
    let frame = ed.render_frame();
    golden::check(name, &frame);
}

#[test]
fn empty_scene() {
    let mut ed = Editor::new(Scene::new(), None, W, H);
    check("editor_empty", &mut ed);
}

#[test]
fn demo_scene() {
    let mut ed = stage(W, H);
    check("editor_demo", &mut ed);
}

#[test]
fn selection_by_clicking_in_the_viewport() {
    let mut ed = stage(W, H);
    let ball = node(&ed, "Ball");
    let (x, y) = pixel_of(&mut ed, ball);
    run(&mut ed, &format!("click {x} {y}"));
    assert_eq!(ed.selection(), Some(ball));
    check("editor_selection", &mut ed);
}

#[test]
fn lists_select_a_light() {
    let mut ed = stage(W, H);
    let spot = node(&ed, "SpotLamp");
    // Wheel over the list (it scrolls only when the rows do not fit).
    let lights = ed.side_panel().lights;
    run(
        &mut ed,
        &format!("wheel -1 {} {}", lights.x + 20, lights.y + 20),
    );
    // Switch the lamp off with its checkbox: its gizmo turns grey.
    let lamp = node(&ed, "Lamp");
    let (x, y) = at(&ed, &format!("ToggleLight({lamp:?})"));
    run(&mut ed, &format!("click {x} {y}"));
    assert!(!ed.scene().node(lamp).light().unwrap().on);
    let (x, y) = at(&ed, &format!("Row {{ node: {spot:?}"));
    run(&mut ed, &format!("click {x} {y}"));
    assert_eq!(ed.selection(), Some(spot));
    check("editor_lists", &mut ed);
}

#[test]
fn grid_off() {
    let mut ed = stage(W, H);
    run(&mut ed, "key g");
    check("editor_grid_off", &mut ed);
}

#[test]
fn lines_style() {
    let mut ed = stage(W, H);
    let (x, y) = at(&ed, "ViewStyle");
    run(&mut ed, &format!("click {x} {y}\nclick {x} {y}"));
    assert_eq!(
        ed.view_style(),
        Some(animed::internals::scene::RenderStyle::Lines)
    );
    check("editor_lines_style", &mut ed);
}

#[test]
fn file_browser() {
    let mut ed = stage(W, H);
    // A relative folder keeps the shown path the same on every checkout
    // (cargo runs tests in the package root).
    ed.set_start_dir(Path::new("tests/data/editor_browser"));
    // The editor's file has no folder, so the start folder is used.
    run(&mut ed, "key ctrl+o\ntype m\nkey tab");
    let b = ed.browser().expect("browser open");
    assert!(
        b.dir.ends_with("models"),
        "tab entered the only 'm…' folder"
    );
    // Back up with the Up button, then walk the listing with the keys.
    let r = ed.browser_widgets(ed.browser().unwrap());
    let up = r
        .iter()
        .find(|w| format!("{:?}", w.kind).contains("BrowserUp"))
        .expect("Up button")
        .rect;
    run(
        &mut ed,
        &format!(
            "click {} {}\nkey down\nkey down\nkey down",
            up.x + 4,
            up.y + 4
        ),
    );
    assert!(ed.browser().unwrap().input.ends_with("box.iv"));
    check("editor_file_browser", &mut ed);
}

#[test]
fn light_gizmos() {
    let mut ed = Editor::new(Scene::new(), None, W, H);
    for which in ["AddLight(Point)", "AddLight(Spot)", "AddLight(Directional)"] {
        let (x, y) = at(&ed, which);
        run(&mut ed, &format!("click {x} {y}"));
    }
    assert_eq!(animed::internals::editor::ops::lights(ed.scene()).len(), 3);
    run(&mut ed, "key home\nwheel -1 150 150");
    check("editor_light_gizmos", &mut ed);
}

#[test]
fn typed_field_edit() {
    let mut ed = stage(W, H);
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let (x, y) = at(&ed, "Field(Translation(1))");
    run(&mut ed, &format!("click {x} {y}\ntype 2.5\nkey enter"));
    assert_eq!(ed.scene().node(ball).transform.translation.y, 2.5);
    // Start a second edit and leave it open: the field shows text and caret.
    let (x, y) = at(&ed, "Field(Translation(0))");
    run(&mut ed, &format!("click {x} {y}\ntype 1+"));
    check("editor_field_edit", &mut ed);
}

#[test]
fn resized_window() {
    let mut ed = stage(480, 320);
    let spinner = node(&ed, "Spinner");
    ed.select(Some(spinner));
    run(&mut ed, "resize 320 240\nkey f");
    assert_eq!(ed.size(), (320, 240));
    check("editor_resized", &mut ed);
}

#[test]
fn quit_question_after_a_change() {
    let mut ed = stage(W, H);
    ed.select(Some(node(&ed, "Glass")));
    run(&mut ed, "key delete\nkey ctrl+q");
    assert!(ed.dialog().is_some() && !ed.wants_quit());
    check("editor_quit_dialog", &mut ed);
}

#[test]
fn view_mode_orbit_and_playback_frame() {
    let mut ed = stage(W, H);
    let vp = ed.layout().viewport;
    let (x, y) = (vp.x + vp.w / 2, vp.y + vp.h / 2);
    run(
        &mut ed,
        &format!(
            "key esc\ndrag {x} {y} {} {} left\nkey space\nwait-frames 30\nkey space",
            x + 60,
            y + 20
        ),
    );
    assert_eq!(
        ed.current_frame(),
        29.0,
        "frame 0 at the first tick, then 29 more"
    );
    check("editor_view_orbit_frame29", &mut ed);
}

/// Keeps the widget API used above honest (a rename fails here first).
#[test]
fn widget_kinds_are_found() {
    let ed = stage(W, H);
    assert!(ed
        .widgets()
        .iter()
        .any(|w| matches!(w.kind, WidgetKind::Row { .. })));
}
