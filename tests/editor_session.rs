//! Drives the editor through events (as the window and scripts do) and
//! checks its state: selection, commands and undo, fields, modal boxes.

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::editor::{script, shell, Editor, Event, Key, Mode, Mods, MouseButton};
use animed::internals::scene::{
    Light, LightKind, Material, Mesh, Node, NodeId, NodeKind, Scene, Shape,
};
use glam::Vec3;
use std::path::Path;
use ui_input::*;

/// Two named boxes and a point light, built by hand so these tests do not
/// depend on the readers.
fn scene() -> Scene {
    let mut s = Scene::new();
    let mut cube = Mesh::default();
    for i in 0..8 {
        cube.positions.push(Vec3::new(
            if i & 1 == 0 { -1.0 } else { 1.0 },
            if i & 2 == 0 { -1.0 } else { 1.0 },
            if i & 4 == 0 { -1.0 } else { 1.0 },
        ));
    }
    cube.triangles = vec![[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5]];
    let mesh = s.add_mesh(cube);
    let mat = s.add_material(Material::default());
    for (name, x) in [("Left", -2.0), ("Right", 2.0)] {
        let g = s.add_node(
            None,
            Node::group(name).with_transform(
                animed::internals::scene::Transform::from_translation(Vec3::new(x, 1.0, 0.0)),
            ),
        );
        s.add_node(
            Some(g),
            Node::new(
                "",
                NodeKind::Shape(Shape {
                    mesh,
                    material: mat,
                }),
            ),
        );
    }
    let mut l = Light::new(LightKind::Point);
    l.location = Vec3::new(0.0, 3.0, 0.0);
    s.add_node(None, Node::new("Lamp", NodeKind::Light(l)));
    s
}

fn editor() -> Editor {
    Editor::new(scene(), None, 480, 320)
}

fn click(ed: &mut Editor, x: f32, y: f32) {
    shell::handle(
        ed,
        Event::MouseMove {
            x,
            y,
            mods: Mods::NONE,
        },
    );
    for down in [true, false] {
        let (button, mods) = (MouseButton::Left, Mods::NONE);
        shell::handle(
            ed,
            if down {
                Event::MouseDown { button, x, y, mods }
            } else {
                Event::MouseUp { button, x, y, mods }
            },
        );
    }
}

fn run(ed: &mut Editor, s: &str) {
    script::run(ed, s, Path::new("test.txt")).expect("script parses");
}

#[test]
fn list_click_selects_and_properties_follow() {
    let mut ed = editor();
    assert_eq!(ed.selection(), None);
    let (x, y) = find(&ed, "node: NodeId(2)");
    click(&mut ed, x, y);
    assert_eq!(ed.selection(), Some(NodeId(2)), "Right is node 2");
    // The name field shows the selection's name.
    assert!(ed
        .widgets()
        .iter()
        .any(|w| format!("{:?}", w.kind) == "Field(Name)"));
}

#[test]
fn typed_field_edit_is_one_undoable_step() {
    let mut ed = editor();
    ed.select(Some(NodeId(0)));
    let (x, y) = find(&ed, "Field(Translation(0))");
    click(&mut ed, x, y);
    assert!(ed.text_edit().is_some(), "a click starts typing");
    ed.handle(Event::Text("4.5".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().node(NodeId(0)).transform.translation.x, 4.5);
    assert!(ed.is_dirty());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().node(NodeId(0)).transform.translation.x, -2.0);
    assert!(!ed.is_dirty());
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(ed.scene().node(NodeId(0)).transform.translation.x, 4.5);
}

#[test]
fn escape_cancels_typing_and_bad_numbers_change_nothing() {
    let mut ed = editor();
    ed.select(Some(NodeId(0)));
    let (x, y) = find(&ed, "Field(Scale(1))");
    click(&mut ed, x, y);
    ed.handle(Event::Text("7".into()));
    key(&mut ed, Key::Escape, Mods::NONE);
    assert_eq!(ed.scene().node(NodeId(0)).transform.scale.y, 1.0);
    assert_eq!(ed.mode(), Mode::Select, "Esc only cancelled the edit");
    click(&mut ed, x, y);
    ed.handle(Event::Text("seven".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().node(NodeId(0)).transform.scale.y, 1.0);
    assert!(ed.status().error);
    assert!(!ed.is_dirty());
}

#[test]
fn dragging_a_field_changes_it_and_undoes_in_one_step() {
    let mut ed = editor();
    ed.select(Some(NodeId(0)));
    let (x, y) = find(&ed, "Field(Translation(1))");
    run(&mut ed, &format!("drag {x} {y} {} {y}", x + 50.0));
    let ty = ed.scene().node(NodeId(0)).transform.translation.y;
    assert!((ty - 2.0).abs() < 1e-4, "50 px × 0.02 = +1, got {ty}");
    assert_eq!(ed.history().labels().count(), 1, "one step for the drag");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().node(NodeId(0)).transform.translation.y, 1.0);
}

#[test]
fn scene_settings_fields() {
    let mut ed = editor();
    let (x, y) = find(&ed, "Field(Fps)");
    click(&mut ed, x, y);
    ed.handle(Event::Text("30".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().settings.fps, 30.0);
    let (x, y) = find(&ed, "Field(Duration)");
    click(&mut ed, x, y);
    ed.handle(Event::Text("48".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().settings.duration, 48.0);
}

#[test]
fn add_toggle_and_delete_lights() {
    let mut ed = editor();
    let (x, y) = find(&ed, "AddLight(Spot)");
    click(&mut ed, x, y);
    let spot = ed.selection().expect("the new light is selected");
    assert!(matches!(
        ed.scene().node(spot).light().map(|l| &l.kind),
        Some(LightKind::Spot { .. })
    ));
    assert!(ed.scene().node(spot).light().unwrap().on);
    key(&mut ed, Key::Char('l'), Mods::NONE);
    assert!(
        !ed.scene().node(spot).light().unwrap().on,
        "L switches it off"
    );
    // The list's checkbox switches the lamp off too (scrolled into view:
    // the list shows the new light first).
    let lights = ed.side_panel().lights;
    ed.handle(Event::Wheel {
        delta: 1.0,
        x: (lights.x + 20) as f32,
        y: (lights.y + 20) as f32,
        mods: Mods::NONE,
    });
    let (x, y) = find(&ed, "ToggleLight(NodeId(4))");
    click(&mut ed, x, y);
    assert!(!ed.scene().node(NodeId(4)).light().unwrap().on);
    let n = ed.scene().nodes.len();
    ed.select(Some(NodeId(0)));
    key(&mut ed, Key::Delete, Mods::NONE);
    assert_eq!(ed.scene().nodes.len(), n - 2, "object and its shape");
    assert_eq!(ed.selection(), None);
    assert!(ed.scene().find_node("Left").is_none());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.scene().find_node("Left").is_some());
}

#[test]
fn clicking_a_light_gizmo_selects_the_light() {
    let mut ed = editor();
    // Project the lamp the way the overlay does, via a script-free path:
    // scan the viewport for the pixel that picks it.
    let vp = ed.layout().viewport;
    let mut hit = None;
    'scan: for y in (vp.y..vp.bottom()).step_by(2) {
        for x in (vp.x..vp.right()).step_by(2) {
            if ed.pick_at(x as f32, y as f32) == Some(NodeId(4)) {
                hit = Some((x as f32, y as f32));
                break 'scan;
            }
        }
    }
    let (x, y) = hit.expect("the lamp's gizmo is in view after framing all");
    click(&mut ed, x, y);
    assert_eq!(ed.selection(), Some(NodeId(4)));
    // Clicking empty space (top-left corner of the viewport) deselects.
    click(&mut ed, vp.x as f32 + 3.0, vp.y as f32 + 20.0);
    assert_eq!(ed.selection(), None);
}

#[test]
fn view_mode_orbits_with_left_drag_and_wheel_zooms() {
    let mut ed = editor();
    let vp = ed.layout().viewport;
    let (cx, cy) = (vp.x as f32 + 100.0, vp.y as f32 + 100.0);
    let cam0 = *ed.camera();
    key(&mut ed, Key::Escape, Mods::NONE);
    assert_eq!(ed.mode(), Mode::View);
    run(&mut ed, &format!("drag {cx} {cy} {} {cy}", cx + 40.0));
    assert!((ed.camera().yaw - cam0.yaw).abs() > 0.1);
    assert_eq!(ed.selection(), None, "view mode does not select");
    let d = ed.camera().distance;
    run(&mut ed, &format!("wheel 2 {cx} {cy}"));
    assert!(ed.camera().distance < d);
    // Shift+middle pans: the target moves, the angles stay.
    let before = *ed.camera();
    run(
        &mut ed,
        &format!("drag {cx} {cy} {} {} shift+middle", cx + 30.0, cy + 10.0),
    );
    assert_ne!(ed.camera().target, before.target);
    assert_eq!(ed.camera().yaw, before.yaw);
    // Alt+left orbits in select mode too.
    key(&mut ed, Key::Escape, Mods::NONE);
    let yaw = ed.camera().yaw;
    run(
        &mut ed,
        &format!("drag {cx} {cy} {} {cy} alt+left", cx - 40.0),
    );
    assert!(ed.camera().yaw > yaw);
}

#[test]
fn frame_selection_and_home() {
    let mut ed = editor();
    ed.select(Some(NodeId(2)));
    key(&mut ed, Key::Char('f'), Mods::NONE);
    assert!((ed.camera().target - Vec3::new(2.0, 1.0, 0.0)).length() < 1e-4);
    key(&mut ed, Key::Home, Mods::NONE);
    let t = ed.camera().target;
    assert!(t.x.abs() < 1e-4, "all: centred between the boxes, {t}");
}

#[test]
fn grid_style_and_playback_toggles() {
    let mut ed = editor();
    assert!(ed.grid_shown());
    key(&mut ed, Key::Char('g'), Mods::NONE);
    assert!(!ed.grid_shown());
    let (x, y) = find(&ed, "ViewStyle");
    click(&mut ed, x, y);
    assert_eq!(
        ed.view_style(),
        Some(animed::internals::scene::RenderStyle::Filled)
    );
    click(&mut ed, x, y);
    assert_eq!(
        ed.view_style(),
        Some(animed::internals::scene::RenderStyle::Lines)
    );
    // Object style applies to the object's whole subtree.
    ed.select(Some(NodeId(0)));
    let (x, y) = find(&ed, "ObjectStyle");
    click(&mut ed, x, y);
    assert_eq!(
        ed.scene().node(NodeId(1)).style,
        animed::internals::scene::RenderStyle::Lines
    );
    // Playback advances in real time and loops.
    key(&mut ed, Key::Space, Mods::NONE);
    assert!(ed.is_playing());
    let steps = script::parse("wait-frames 1\nwait-frames 10", Path::new("t")).unwrap();
    let mut runner = script::Runner::default();
    runner.run(&mut ed, &steps, Path::new("t")).unwrap();
    assert_eq!(ed.current_frame(), 10.0);
    let steps = script::parse("wait-frames 90", Path::new("t")).unwrap();
    runner.run(&mut ed, &steps, Path::new("t")).unwrap();
    assert_eq!(ed.current_frame(), 3.0, "96 frames + frame 0 = 97 per loop");
    key(&mut ed, Key::Char('p'), Mods::ctrl());
    assert!(!ed.is_playing());
}

#[test]
fn timeline_click_seeks() {
    let mut ed = editor();
    let l = ed.layout();
    let x = l.frame_to_x(48.0, 96.0);
    click(&mut ed, x, l.ruler.y as f32 + 8.0);
    assert_eq!(ed.current_frame(), 48.0);
    key(&mut ed, Key::Right, Mods::NONE);
    assert_eq!(ed.current_frame(), 49.0);
}

#[test]
fn quit_asks_when_unsaved() {
    let mut ed = editor();
    assert_eq!(ed.window_title(), "animed — untitled");
    key(&mut ed, Key::Char('q'), Mods::ctrl());
    assert!(ed.wants_quit(), "nothing to save: quits at once");
    let mut ed = editor();
    key(&mut ed, Key::Char('g'), Mods::NONE);
    ed.select(Some(NodeId(0)));
    key(&mut ed, Key::Delete, Mods::NONE);
    assert_eq!(ed.window_title(), "animed — untitled *");
    key(&mut ed, Key::Char('q'), Mods::ctrl());
    assert!(!ed.wants_quit());
    assert!(ed.dialog().is_some());
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(ed.dialog().is_none() && !ed.wants_quit());
    key(&mut ed, Key::Char('q'), Mods::ctrl());
    key(&mut ed, Key::Char('d'), Mods::NONE);
    assert!(ed.wants_quit(), "discard quits");
}

#[test]
fn new_scene_asks_then_clears() {
    let mut ed = editor();
    ed.select(Some(NodeId(0)));
    key(&mut ed, Key::Delete, Mods::NONE);
    key(&mut ed, Key::Char('n'), Mods::ctrl());
    assert!(ed.dialog().is_some());
    key(&mut ed, Key::Char('d'), Mods::NONE);
    assert!(ed.scene().nodes.is_empty());
    assert!(!ed.is_dirty());
}

#[test]
fn file_browser_lists_completes_and_cancels() {
    let dir = std::env::temp_dir().join(format!("animed-editor-browser-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("scene.wrl"), "#VRML V2.0 utf8\n").unwrap();
    std::fs::write(dir.join("readme.txt"), "x").unwrap();
    let mut ed = editor();
    ed.set_start_dir(&dir);
    key(&mut ed, Key::Char('o'), Mods::ctrl());
    let b = ed.browser().expect("Ctrl+O opens the browser");
    let names: Vec<_> = b.entries.iter().map(|e| e.name.clone()).collect();
    assert_eq!(names, vec!["..", "sub", "scene.wrl"]);
    // Typing goes to the path, Tab completes.
    ed.handle(Event::Text("sc".into()));
    key(&mut ed, Key::Tab, Mods::NONE);
    assert!(ed.browser().unwrap().input.ends_with("/scene.wrl"));
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(ed.browser().is_none());
    assert_eq!(ed.scene().nodes.len(), 5, "nothing opened");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn resize_relayouts() {
    let mut ed = editor();
    assert!(ed.handle(Event::Resize {
        width: 320,
        height: 240
    }));
    assert_eq!(ed.layout().window.w, 320);
    let f = ed.render_frame();
    assert_eq!((f.width, f.height), (320, 240));
    assert!(!ed.handle(Event::Resize {
        width: 320,
        height: 240
    }));
}

#[test]
fn idle_events_do_not_ask_for_redraws() {
    let mut ed = editor();
    assert!(!ed.handle(Event::Tick { time: 1.0 }), "not playing");
    assert!(!ed.handle(Event::KeyUp {
        key: Key::Char('a'),
        mods: Mods::NONE
    }));
    // Moving within the viewport (no widget there) needs no redraw.
    let vp = ed.layout().viewport;
    ed.handle(Event::MouseMove {
        x: vp.x as f32 + 50.0,
        y: vp.y as f32 + 50.0,
        mods: Mods::NONE,
    });
    assert!(!ed.handle(Event::MouseMove {
        x: vp.x as f32 + 52.0,
        y: vp.y as f32 + 50.0,
        mods: Mods::NONE
    }));
}

fn temp_dir(tag: &str) -> std::path::PathBuf {
    let d = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("editor-session-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn save_as_open_and_import_through_the_browser() {
    let dir = temp_dir("files");
    let mut ed = editor();
    ed.set_start_dir(&dir);
    ed.select(Some(NodeId(0)));
    key(&mut ed, Key::Delete, Mods::NONE);
    assert!(ed.is_dirty());
    // Ctrl+S without a file asks for a name; the browser's path starts as
    // the folder, typing appends the file name.
    key(&mut ed, Key::Char('s'), Mods::ctrl());
    assert!(ed.browser().is_some());
    ed.handle(Event::Text("saved".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    let saved = dir.join("saved.wrl");
    assert!(ed.browser().is_none(), "status: {:?}", ed.status());
    assert!(
        saved.is_file(),
        ".wrl is added when no known extension is typed"
    );
    assert!(!ed.is_dirty());
    assert_eq!(ed.path(), Some(saved.as_path()));
    // Open it again into a fresh editor.
    let mut other = Editor::new(Scene::new(), None, 480, 320);
    other.set_start_dir(&dir);
    key(&mut other, Key::Char('o'), Mods::ctrl());
    other.handle(Event::Text("saved.wrl".into()));
    key(&mut other, Key::Enter, Mods::NONE);
    assert!(other.browser().is_none(), "status: {:?}", other.status());
    assert!(other.scene().find_node("Right").is_some());
    assert!(
        other.scene().find_node("Left").is_none(),
        "deleted before saving"
    );
    assert!(other.scene().find_node("Lamp").is_some());
    // Import it into the first editor as a new object (undoable).
    let before = ed.scene().nodes.len();
    key(&mut ed, Key::Char('i'), Mods::ctrl());
    ed.handle(Event::Text("saved.wrl".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    let group = ed.selection().expect("the import is selected");
    assert_eq!(ed.scene().node(group).name, "saved");
    assert!(ed.scene().nodes.len() > before);
    assert!(ed.is_dirty());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().nodes.len(), before);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn ctrl_s_saves_in_place_and_quit_can_save_first() {
    let dir = temp_dir("inplace");
    let path = dir.join("scene.wrl");
    let mut ed = Editor::new(scene(), Some(path.clone()), 480, 320);
    ed.select(Some(NodeId(2)));
    key(&mut ed, Key::Delete, Mods::NONE);
    key(&mut ed, Key::Char('q'), Mods::ctrl());
    assert!(ed.dialog().is_some());
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(path.is_file(), "Save in the dialog wrote the file");
    assert!(ed.wants_quit());
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.starts_with("#VRML V2.0"),
        "{}",
        &text[..40.min(text.len())]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The editor itself never touches the disk: Ctrl+S and the autosave clock
/// only queue requests; the shell (here `shell::perform`, in the window
/// `app`) writes, and a failed write marks nothing saved.
#[test]
fn the_editor_asks_for_file_work_and_the_shell_does_it() {
    use animed::internals::editor::request::{AutosaveWhy, Request};
    let dir = temp_dir("requests");
    let path = dir.join("scene.wrl");
    let mut ed = Editor::new(scene(), Some(path.clone()), 480, 320);
    ed.set_autosave_interval(Some(1.0));
    ed.select(Some(NodeId(2)));
    ed.handle(Event::KeyDown {
        key: Key::Delete,
        mods: Mods::NONE,
    });
    assert!(ed.is_dirty());
    ed.handle(Event::KeyDown {
        key: Key::Char('s'),
        mods: Mods::ctrl(),
    });
    let asked = ed.requests().to_vec();
    assert_eq!(
        asked,
        [Request::Save {
            path: path.clone(),
            expect: None,
            then: None
        }]
    );
    assert!(!path.exists(), "the state machine wrote nothing");
    assert!(ed.is_dirty(), "not saved before the write");
    assert!(shell::perform(&mut ed));
    assert!(path.is_file() && !ed.is_dirty(), "{:?}", ed.status());
    assert!(ed.requests().is_empty());
    // Unsaved again; the clock asks for a recovery copy, the shell writes it.
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.is_dirty());
    ed.handle(Event::Tick { time: 10.0 });
    ed.handle(Event::Tick { time: 11.5 });
    let copy = ed
        .recovery_file()
        .expect("a saved scene has a copy beside it");
    assert!(ed.requests().contains(&Request::Autosave {
        path: copy.clone(),
        why: AutosaveWhy::Clock
    }));
    assert!(!copy.exists());
    shell::perform(&mut ed);
    assert!(copy.is_file(), "{:?}", ed.status());
    assert!(
        ed.status().text.starts_with("Autosaved"),
        "{:?}",
        ed.status()
    );
    // A save that cannot be written leaves the work unsaved, and says why.
    let blocked = dir.join("scene.wrl").join("inside-a-file.wrl");
    assert!(ed.save_to(&blocked).is_err());
    assert!(ed.is_dirty(), "a failed save marks nothing saved");
    assert!(ed.status().error, "{:?}", ed.status());
    assert_eq!(ed.path(), Some(path.as_path()), "still the old file");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn opening_a_bad_file_reports_it_and_keeps_the_scene() {
    let dir = temp_dir("bad");
    std::fs::write(
        dir.join("broken.wrl"),
        "#VRML V2.0 utf8\nShape { geometry Box { size 1 2 } \n",
    )
    .unwrap();
    let mut ed = editor();
    ed.set_start_dir(&dir);
    key(&mut ed, Key::Char('o'), Mods::ctrl());
    ed.handle(Event::Text("broken.wrl".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(ed.status().error);
    assert!(
        ed.status().text.contains("broken.wrl:"),
        "{}",
        ed.status().text
    );
    assert!(
        ed.browser().is_some(),
        "the browser stays open to pick another"
    );
    assert_eq!(ed.scene().nodes.len(), 5);
    let _ = std::fs::remove_dir_all(&dir);
}
