//! Issue 17, the editor for newcomers: no lost or hidden work, stable
//! layout, creating objects, standard views. Driven through events as the
//! window and scripts drive it.

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::editor::{After, Editor, Event, Key, Mods, MouseButton};
use animed::scene::{NodeId, Scene};
use ui_input::*;

/// Mouse to (x, y) without a button.
fn hover(ed: &mut Editor, (x, y): (f32, f32)) {
    ed.handle(Event::MouseMove {
        x,
        y,
        mods: Mods::NONE,
    });
}

/// A point inside the key strip rows (or the timeline when it has none).
fn over_strip(ed: &Editor) -> (f32, f32) {
    let l = ed.layout();
    let r = if l.key_rows.h > 0 {
        l.key_rows
    } else {
        l.ruler
    };
    ((r.x + r.w / 2) as f32, (r.y + r.h / 2) as f32)
}

#[test]
fn delete_over_the_key_strip_without_selected_keys_asks_first() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let n = ed.scene().nodes.len();
    let at = over_strip(&ed);
    hover(&mut ed, at);
    key(&mut ed, Key::Delete, Mods::NONE);
    let d = ed.dialog().expect("asks before deleting the object");
    assert_eq!(d.then, After::DeleteObject);
    assert!(d.message.contains("Ball"), "{}", d.message);
    assert_eq!(ed.scene().nodes.len(), n, "nothing deleted yet");
    // Esc: nothing deleted, and the status line says so.
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(ed.dialog().is_none());
    assert_eq!(ed.scene().nodes.len(), n);
    assert_eq!(ed.status().text, "Nothing deleted");
    // Asked again, Enter deletes it (one undo step).
    key(&mut ed, Key::Delete, Mods::NONE);
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(ed.scene().find_node("Ball").is_none());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.scene().find_node("Ball").is_some());
    // Over the viewport Delete acts on the selected object directly.
    ed.select(Some(node(&ed, "Ball")));
    let vp = ed.layout().viewport;
    hover(&mut ed, ((vp.x + 10) as f32, (vp.y + 10) as f32));
    key(&mut ed, Key::Delete, Mods::NONE);
    assert!(ed.dialog().is_none());
    assert!(ed.scene().find_node("Ball").is_none());
}

#[test]
fn the_status_line_follows_the_selection() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    // A stale message from earlier.
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.status().text, "Nothing to undo");
    let row = find(&ed, &format!("node: NodeId({})", ball.0));
    click(&mut ed, row);
    assert_eq!(ed.selection(), Some(ball));
    assert_eq!(ed.status().text, "Selected Ball");
    // Clicking empty viewport space clears the selection and the line.
    let vp = ed.layout().viewport;
    click(&mut ed, ((vp.x + 3) as f32, (vp.bottom() - 3) as f32));
    assert_eq!(ed.selection(), None);
    assert_eq!(ed.status().text, "");
}

#[test]
fn clamped_and_refused_typed_values_are_said() {
    let mut ed = stage();
    type_into(&mut ed, "Field(Fps)", "500");
    assert_eq!(ed.scene().settings.fps, 240.0);
    let t = &ed.status().text;
    assert!(t.contains("Fps: 500") && t.contains("set to 240"), "{t}");
    type_into(&mut ed, "Field(Frame)", "99999");
    let t = &ed.status().text;
    assert!(
        t.starts_with("Frame: 99999") && t.contains("frames 0 to"),
        "{t}"
    );
    type_into(&mut ed, "Field(Duration)", "abc");
    assert!(ed.status().error && ed.status().text.contains("'abc' is not a number"));
    // A value taken as typed says nothing about clamping.
    type_into(&mut ed, "Field(Fps)", "25");
    assert_eq!(ed.scene().settings.fps, 25.0);
    assert!(!ed.status().text.contains("set to"), "{:?}", ed.status());
}

/// Whether some viewport pixel picks `id`.
fn visible(ed: &mut Editor, id: NodeId) -> bool {
    let vp = ed.layout().viewport;
    (vp.y..vp.bottom()).step_by(2).any(|y| {
        (vp.x..vp.right())
            .step_by(2)
            .any(|x| ed.pick_at(x as f32, y as f32) == Some(id))
    })
}

#[test]
fn new_lights_are_placed_in_view() {
    // One light per editor: two new lights share the spot, and picking
    // finds the first.
    let cases = [0.0, 250.0, -400.0].map(|t| [(t, "AddLight(Point)"), (t, "AddLight(Spot)")]);
    for (turn, which) in cases.into_iter().flatten() {
        let mut ed = stage();
        // Look from elsewhere first (orbit with the middle button).
        let vp = ed.layout().viewport;
        let c = ((vp.x + vp.w / 2) as f32, (vp.y + vp.h / 2) as f32);
        let mods = Mods::NONE;
        let button = MouseButton::Middle;
        ed.handle(Event::MouseDown {
            button,
            x: c.0,
            y: c.1,
            mods,
        });
        ed.handle(Event::MouseMove {
            x: c.0 + turn,
            y: c.1 + turn / 5.0,
            mods,
        });
        ed.handle(Event::MouseUp {
            button,
            x: c.0 + turn,
            y: c.1 + turn / 5.0,
            mods,
        });
        let at = find(&ed, which);
        click(&mut ed, at);
        let id = ed.selection().expect("the new light is selected");
        assert!(
            visible(&mut ed, id),
            "{which} after turning {turn}: off-screen"
        );
    }
}

#[test]
fn a_typed_absolute_path_replaces_the_browsers_folder() {
    let mut ed = Editor::new(Scene::new(), None, 480, 320);
    let dir = std::env::temp_dir();
    ed.set_start_dir(&dir);
    key(&mut ed, Key::Char('o'), Mods::ctrl());
    let b = ed.browser().expect("the browser opens");
    assert!(b.input.ends_with('/'));
    ed.handle(Event::Text("/no/such/place.wrl".into()));
    assert_eq!(ed.browser().unwrap().input, "/no/such/place.wrl");
    key(&mut ed, Key::Enter, Mods::NONE);
    let m = ed.browser().unwrap().message.clone().unwrap_or_default();
    assert!(m.contains("no file /no/such/place.wrl"), "{m}");
    assert!(!m.contains("//"), "{m}");
}
