//! Issue 17, the editor for newcomers: no lost or hidden work, stable
//! layout, creating objects, standard views. Driven through events as the
//! window and scripts drive it.

#[path = "common/golden.rs"]
mod golden;
#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::editor::{After, Editor, Event, Key, Mods, MouseButton};
use animed::internals::scene::{NodeId, Scene};
use ui_input::*;

mod editor_menus;

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

// ----- item 6: stable layout -----

/// The stage in a window where every list row shows (800×600).
fn big_stage() -> Editor {
    let mut ed = stage();
    ed.handle(Event::Resize {
        width: 800,
        height: 600,
    });
    ed
}

/// Every label's text fits its box, and no label runs into a field on its
/// row.
fn assert_text_fits(ed: &Editor) {
    use animed::internals::editor::panel::WidgetKind;
    use animed::internals::ui::text::width;
    let ws = ed.widgets();
    for w in &ws {
        let WidgetKind::Label { text, .. } = &w.kind else {
            continue;
        };
        assert!(
            width(text) <= w.rect.w,
            "label '{text}' ({} px) cut in a {} px box",
            width(text),
            w.rect.w
        );
        for f in &ws {
            if matches!(f.kind, WidgetKind::Field(_))
                && f.rect.y.abs_diff(w.rect.y) < 4
                && f.rect.x >= w.rect.x
            {
                assert!(
                    w.rect.x + width(text) + 2 <= f.rect.x,
                    "label '{text}' runs into the field at x {}",
                    f.rect.x
                );
            }
        }
    }
}

#[test]
fn selecting_never_moves_the_viewport_or_the_side_panel() {
    let mut ed = big_stage();
    let before = ed.layout();
    for name in ["Ball", "Ground", "Lamp", "SpotLamp"] {
        let id = node(&ed, name);
        let row = find(&ed, &format!("node: NodeId({})", id.0));
        click(&mut ed, row);
        assert_eq!(ed.selection(), Some(id));
        let l = ed.layout();
        assert_eq!(
            (l.viewport, l.side, l.key_rows),
            (before.viewport, before.side, before.key_rows),
            "{name}"
        );
        assert_text_fits(&ed);
    }
}

/// A named thing in the side panel and its rect (x, y, w, h).
type Spot = (String, (i32, i32, i32, i32));

/// How many of `spots` are named `name`.
fn count(spots: &[Spot], name: &str) -> usize {
    spots.iter().filter(|(n, _)| n == name).count()
}

/// Where the side panel's fixed things are: the list headers, the
/// add-light buttons and every visible list row.
fn side_spots(ed: &Editor) -> Vec<Spot> {
    use animed::internals::editor::panel::WidgetKind;
    let side = ed.layout().side;
    ed.widgets()
        .into_iter()
        .filter(|w| side.contains(w.rect.x as f32, w.rect.y as f32))
        .filter_map(|w| {
            let name = match &w.kind {
                WidgetKind::Header(t) if t.starts_with("Objects") => "objects header".into(),
                WidgetKind::Header(t) if t == "Lights" => "lights header".into(),
                WidgetKind::Button { label, .. } if label.starts_with('+') => label.clone(),
                WidgetKind::Row { list, .. } => format!("{list:?} row"),
                _ => return None,
            };
            Some((name, (w.rect.x, w.rect.y, w.rect.w, w.rect.h)))
        })
        .collect()
}

#[test]
fn the_side_panel_never_moves_when_selection_keys_or_lists_change() {
    // Issue 17's first problem: the lights list and its +Pt/+Dir/+Spot
    // buttons moved 16-48 px when the properties grew, so the next click
    // landed on another row. In the tests' 480x320 window and a big one.
    for big in [false, true] {
        let mut ed = if big { big_stage() } else { stage() };
        let start = side_spots(&ed);
        assert!(count(&start, "Objects row") >= 2, "{start:?}");
        assert!(count(&start, "Lights row") >= 2, "{start:?}");
        let same = |ed: &Editor, step: &str| {
            let now = side_spots(ed);
            // Every thing shown at the start is still where it was (a
            // list may show a row more, never one less or one moved).
            for s in &start {
                assert!(now.contains(s), "{step} (big {big}): {s:?} moved: {now:?}");
            }
        };
        // Select the ball from the objects list.
        let ball = node(&ed, "Ball");
        let at = find(&ed, &format!("node: NodeId({})", ball.0));
        click(&mut ed, at);
        assert_eq!(ed.selection(), Some(ball));
        same(&ed, "select the ball");
        // Its first key: the properties gain the `Keys` line.
        key(&mut ed, Key::Char('k'), Mods::NONE);
        same(&ed, "first key");
        // A second key, and the key panel for the first.
        for _ in 0..12 {
            key(&mut ed, Key::Right, Mods::NONE);
        }
        key(&mut ed, Key::Char('k'), Mods::NONE);
        same(&ed, "second key");
        let m = ed
            .key_marker_at(animed::internals::editor::keystrip::Row::Summary, 0.0)
            .expect("a key at frame 0");
        click(&mut ed, m);
        assert!(
            ed.widgets()
                .iter()
                .any(|w| format!("{:?}", w.kind).contains("ShowNode")),
            "the key panel is open"
        );
        same(&ed, "key panel");
        // Two more lights (each selected as it comes), then nothing.
        let at = find(&ed, "Button { label: \"+P");
        click(&mut ed, at);
        same(&ed, "add a point light");
        let at = find(&ed, "Button { label: \"+S");
        click(&mut ed, at);
        same(&ed, "add a spot light");
        key(&mut ed, Key::Escape, Mods::NONE);
        same(&ed, "Esc");
        // Rows that no longer fit scroll: the wheel over the lights list
        // moves its rows, never its header or buttons.
        let before = side_spots(&ed);
        let lights = ed.side_panel().lights;
        let at = ((lights.x + 20) as f32, (lights.bottom() - 4) as f32);
        ed.handle(Event::Wheel {
            delta: -1.0,
            x: at.0,
            y: at.1,
            mods: Mods::NONE,
        });
        let now = side_spots(&ed);
        for s in start.iter().filter(|(n, _)| !n.ends_with("row")) {
            assert!(now.contains(s), "scrolled (big {big}): {s:?} moved");
        }
        let shown = count(&before, "Lights row");
        assert_eq!(count(&now, "Lights row"), shown, "same rows shown");
    }
}

#[test]
fn the_properties_scroll_with_the_wheel_and_keep_their_header() {
    use animed::internals::editor::panel::WidgetKind;
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    let at = find(&ed, &format!("node: NodeId({})", ball.0));
    click(&mut ed, at);
    let has = |ed: &Editor, needle: &str| {
        ed.widgets()
            .iter()
            .any(|w| format!("{:?}", w.kind).contains(needle))
    };
    let header = |ed: &Editor| {
        let top = ed.side_panel().props.y;
        ed.widgets()
            .into_iter()
            .find(|w| matches!(&w.kind, WidgetKind::Header(_)) && w.rect.y == top)
            .map(|w| (w.rect, format!("{:?}", w.kind)))
    };
    // 480x320: four rows show; the draw style row is below them.
    assert!(has(&ed, "Field(Name)") && !has(&ed, "ObjectStyle"));
    let top = header(&ed).expect("the properties header");
    let props = ed.side_panel().props;
    let over = ((props.x + 20) as f32, (props.bottom() - 4) as f32);
    let mods = Mods::NONE;
    ed.handle(Event::Wheel {
        delta: -1.0,
        x: over.0,
        y: over.1,
        mods,
    });
    assert!(has(&ed, "ObjectStyle"), "scrolled one row down");
    assert!(!has(&ed, "Field(Name)"), "the first row scrolled away");
    assert_eq!(header(&ed), Some(top), "the header stays");
    // Scrolling stops at the last row and at the first.
    for _ in 0..5 {
        ed.handle(Event::Wheel {
            delta: -1.0,
            x: over.0,
            y: over.1,
            mods,
        });
    }
    assert!(
        has(&ed, "text: \"Keys\""),
        "the last row (the ball's keys) shows"
    );
    ed.handle(Event::Wheel {
        delta: 9.0,
        x: over.0,
        y: over.1,
        mods,
    });
    assert!(has(&ed, "Field(Name)") && !has(&ed, "ObjectStyle"));
    // Another selection starts at its first row.
    ed.handle(Event::Wheel {
        delta: -1.0,
        x: over.0,
        y: over.1,
        mods,
    });
    let ground = node(&ed, "Ground");
    let at = find(&ed, &format!("node: NodeId({})", ground.0));
    click(&mut ed, at);
    assert!(has(&ed, "Field(Name)"), "Ground's panel starts at the top");
}

#[test]
fn the_key_strip_resizes_by_its_edge_and_scrolls_its_rows() {
    let mut ed = stage();
    ed.select(Some(node(&ed, "Ball")));
    let l = ed.layout();
    let edge = (l.viewport.x as f32 + 40.0, l.timeline.y as f32);
    // Drag the edge up by 30 px: the strip grows, the viewport shrinks.
    drag(&mut ed, edge, (edge.0, edge.1 - 30.0), Mods::NONE);
    let l2 = ed.layout();
    assert_eq!(l2.key_rows.h, l.key_rows.h + 30);
    assert_eq!(l2.viewport.h, l.viewport.h - 30);
    // Down to one row: the rest scroll (wheel over the strip).
    let edge = (edge.0, l2.timeline.y as f32);
    drag(&mut ed, edge, (edge.0, edge.1 + 400.0), Mods::NONE);
    let (first, all, cap) = ed.key_strip_scroll();
    assert!(cap >= 1 && all > cap, "rows {all}, fit {cap}");
    assert_eq!(first, 0);
    let r = ed.layout().key_rows;
    let at = ((r.x + r.w / 2) as f32, (r.y + r.h / 2) as f32);
    ed.handle(Event::Wheel {
        delta: -1.0,
        x: at.0,
        y: at.1,
        mods: Mods::NONE,
    });
    assert_eq!(ed.key_strip_scroll().0, 1, "scrolled one row");
    assert_eq!(
        ed.current_frame(),
        0.0,
        "the wheel scrolled instead of stepping"
    );
}

#[test]
fn the_key_list_wraps_and_key_panel_labels_keep_clear() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    // Many keys: K at every 6th frame.
    for _ in 0..12 {
        key(&mut ed, Key::Char('k'), Mods::NONE);
        for _ in 0..6 {
            key(&mut ed, Key::Right, Mods::NONE);
        }
    }
    assert_text_fits(&ed);
    // The key panel (a key selected): "Value", "Frame" clear of their fields.
    let m = ed
        .key_marker_at(animed::internals::editor::keystrip::Row::Summary, 0.0)
        .expect("a key at frame 0");
    click(&mut ed, m);
    assert_text_fits(&ed);
}

// ----- item 1: create -----

#[test]
fn shift_a_adds_a_unit_box_at_the_orbit_centre_selected_and_named() {
    let mut ed = Editor::new(Scene::new(), None, 480, 320);
    let vp = ed.layout().viewport;
    hover(&mut ed, ((vp.x + 60) as f32, (vp.y + 60) as f32));
    key(&mut ed, Key::Char('a'), Mods::shift());
    let m = ed.menu().expect("Shift+A opens the Add menu");
    let labels: Vec<&str> = m.items.iter().map(|i| i.label.as_str()).collect();
    assert_eq!(
        labels,
        [
            "Box",
            "Sphere",
            "Cone",
            "Cylinder",
            "Plane",
            "Empty",
            "Camera",
            "Point light",
            "Spot light",
            "Directional light"
        ]
    );
    // Click "Box".
    let r = m.item_rect(ed.layout().window, 0);
    click(&mut ed, ((r.x + 10) as f32, (r.y + 5) as f32));
    assert!(ed.menu().is_none());
    let b = ed.selection().expect("the box is selected");
    let s = ed.scene();
    assert_eq!(s.node(b).name, "Box1");
    assert_eq!(s.node(b).transform.translation, ed.camera().target);
    let mesh = s.nodes.iter().find_map(|n| match &n.kind {
        animed::internals::scene::NodeKind::Shape(sh) => Some(&s.meshes[sh.mesh.0 as usize]),
        _ => None,
    });
    let (lo, hi) = mesh.unwrap().bounds().unwrap();
    assert_eq!(hi - lo, glam::Vec3::ONE, "a unit box in an empty scene");
    assert!(ed.status().text.starts_with("Added Box1"));
    // Again (by keyboard): a second, uniquely named box; undo removes it.
    key(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Char('b'), Mods::NONE);
    assert_eq!(ed.scene().node(ed.selection().unwrap()).name, "Box2");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.scene().find_node("Box2").is_none());
    // Esc closes the menu without adding.
    key(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(ed.menu().is_none());
    assert!(ed.scene().find_node("Box2").is_none());
}

#[test]
fn every_add_menu_item_adds_something_selected_and_in_a_sized_scene_bigger() {
    let mut ed = stage();
    let at = find(&ed, "AddMenu");
    let mut names = std::collections::HashSet::new();
    for i in 0..10 {
        click(&mut ed, at);
        let m = ed.menu().expect("the toolbar's Add opens the menu");
        let r = m.item_rect(ed.layout().window, i);
        click(&mut ed, ((r.x + 10) as f32, (r.y + 5) as f32));
        let id = ed.selection().expect("selected");
        assert!(
            names.insert(ed.scene().node(id).name.clone()),
            "unique names"
        );
    }
    assert!(ed.scene().find_node("Camera1").is_some());
    // Sized to the view: the stage is framed from further than 10 units.
    let sphere = ed.scene().find_node("Sphere1").unwrap();
    let shape = ed.scene().node(sphere).children[0];
    let animed::internals::scene::NodeKind::Shape(sh) = &ed.scene().node(shape).kind else {
        panic!("a shape")
    };
    let (lo, hi) = ed.scene().meshes[sh.mesh.0 as usize].bounds().unwrap();
    assert!(hi.x - lo.x >= 2.0, "{}", hi.x - lo.x);
}

#[test]
fn shift_d_duplicates_with_tracks_and_list_drags_parent() {
    use animed::internals::anim::{Property, Target, TargetRef};
    let mut ed = big_stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    key(&mut ed, Key::Char('d'), Mods::shift());
    let copy = ed.selection().expect("the copy is selected");
    assert_ne!(copy, ball);

    let t = |of| Target {
        of: TargetRef::Node(of),
        property: Property::Translation,
    };
    let a = ed.scene().animation.track(t(ball)).expect("ball animated");
    let b = ed.scene().animation.track(t(copy)).expect("copy animated");
    assert_eq!(a.key_count(), b.key_count());
    // Drag the copy's row onto Ground's row: it goes under Ground.
    let ground = node(&ed, "Ground");
    let from = find(&ed, &format!("node: NodeId({})", copy.0));
    let to = find(&ed, &format!("node: NodeId({})", ground.0));
    drag(&mut ed, from, to, Mods::NONE);
    assert_eq!(ed.scene().node(copy).parent, Some(ground));
    // Onto the list's empty space: back to the top level.
    let objects = ed.side_panel().objects;
    let from = find(&ed, &format!("node: NodeId({})", copy.0));
    drag(
        &mut ed,
        from,
        ((objects.x + 20) as f32, (objects.bottom() - 3) as f32),
        Mods::NONE,
    );
    assert_eq!(ed.scene().node(copy).parent, None);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().node(copy).parent, Some(ground), "undo");
}

#[test]
fn newcomer_goldens() {
    // The Add menu open over an empty scene.
    let mut ed = Editor::new(Scene::new(), None, 480, 320);
    let vp = ed.layout().viewport;
    hover(&mut ed, ((vp.x + 80) as f32, (vp.y + 40) as f32));
    key(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Down, Mods::NONE);
    golden::check("editor_add_menu", &ed.render_frame());
    // Box, sphere and cone added (sized and placed), the cone selected.
    key(&mut ed, Key::Escape, Mods::NONE);
    for item in ['b', 's'] {
        key(&mut ed, Key::Char('a'), Mods::shift());
        key(&mut ed, Key::Char(item), Mods::NONE);
        // Move each aside so all three show.
        let id = ed.selection().unwrap();
        let tx = find(&ed, "Field(Translation(0))");
        click(&mut ed, tx);
        ed.handle(Event::Text(if item == 'b' { "-2" } else { "2" }.into()));
        key(&mut ed, Key::Enter, Mods::NONE);
        assert_ne!(ed.scene().node(id).transform.translation.x, 0.0);
    }
    key(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Char('c'), Mods::NONE);
    golden::check("editor_added_shapes", &ed.render_frame());
    // The stage with a short, scrolled key strip.
    let mut ed = stage();
    ed.select(Some(node(&ed, "Ball")));
    let l = ed.layout();
    let edge = (l.viewport.x as f32 + 40.0, l.timeline.y as f32);
    drag(&mut ed, edge, (edge.0, edge.1 + 400.0), Mods::NONE);
    let r = ed.layout().key_rows;
    ed.handle(Event::Wheel {
        delta: -1.0,
        x: (r.x + r.w / 2) as f32,
        y: (r.y + 4) as f32,
        mods: Mods::NONE,
    });
    golden::check("editor_strip_scrolled", &ed.render_frame());
}

// ----- item 4: views -----

#[test]
fn numpad_views_ortho_and_the_scene_camera() {
    use std::f32::consts::{FRAC_PI_2, PI};
    let mut ed = stage();
    let near = |a: f32, b: f32| (a - b).abs() < 1e-5;
    key(&mut ed, Key::Num(1), Mods::NONE);
    assert!(near(ed.camera().yaw, 0.0) && near(ed.camera().pitch, 0.0));
    assert!(
        ed.status().text.starts_with("Front view"),
        "{:?}",
        ed.status()
    );
    key(&mut ed, Key::Num(1), Mods::ctrl());
    assert!(near(ed.camera().yaw, PI), "back");
    key(&mut ed, Key::Num(3), Mods::NONE);
    assert!(near(ed.camera().yaw, FRAC_PI_2), "right");
    key(&mut ed, Key::Num(7), Mods::NONE);
    assert!(near(ed.camera().pitch, FRAC_PI_2), "top");
    // Straight down still draws a picture (no degenerate look-at).
    let f = ed.render_frame();
    let vp = ed.layout().viewport;
    let c = f.color[((vp.y + vp.h / 2) as u32 * f.width + (vp.x + vp.w / 2) as u32) as usize];
    assert_ne!(c, 0, "the top view shows the stage");
    key(&mut ed, Key::Num(5), Mods::NONE);
    assert!(ed.camera().ortho);
    assert_eq!(ed.status().text, "Orthographic view");
    key(&mut ed, Key::Num(5), Mods::NONE);
    assert!(!ed.camera().ortho);
    // Numpad 0 looks through the scene's camera, and again goes back.
    let before = *ed.camera();
    key(&mut ed, Key::Num(0), Mods::NONE);
    let through = *ed.camera();
    if ed.status().text.starts_with("Looking through") {
        assert_ne!(through, before);
        key(&mut ed, Key::Num(0), Mods::NONE);
        assert_eq!(*ed.camera(), before, "back to the view before");
    } else {
        assert!(ed.status().text.contains("no camera"), "{:?}", ed.status());
    }
    // With a camera added at the view, numpad 0 sees what it sees.
    key(&mut ed, Key::Num(1), Mods::NONE);
    let front = *ed.camera();
    key(&mut ed, Key::Char('a'), Mods::shift());
    let m = ed.menu().unwrap();
    let i = m.items.iter().position(|i| i.label == "Camera").unwrap();
    let r = m.item_rect(ed.layout().window, i);
    click(&mut ed, ((r.x + 10) as f32, (r.y + 5) as f32));
    assert!(ed
        .scene()
        .node(ed.selection().unwrap())
        .name
        .starts_with("Camera"));
    key(&mut ed, Key::Num(3), Mods::NONE);
    key(&mut ed, Key::Num(0), Mods::NONE);
    let cam = ed.camera();
    assert!(
        (cam.eye() - front.eye()).length() < 1e-3,
        "{:?} vs {:?}",
        cam.eye(),
        front.eye()
    );
    assert!((cam.back() - front.back()).length() < 1e-3);
}

#[test]
fn the_viewport_context_menu_and_the_view_menu() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let vp = ed.layout().viewport;
    let at = ((vp.x + 30) as f32, (vp.y + 30) as f32);
    ed.handle(Event::MouseMove {
        x: at.0,
        y: at.1,
        mods: Mods::NONE,
    });
    for down in [true, false] {
        let (button, mods) = (MouseButton::Right, Mods::NONE);
        ed.handle(if down {
            Event::MouseDown {
                button,
                x: at.0,
                y: at.1,
                mods,
            }
        } else {
            Event::MouseUp {
                button,
                x: at.0,
                y: at.1,
                mods,
            }
        });
    }
    let m = ed.menu().expect("right-click opens the context menu");
    assert_eq!(m.title, "Viewport");
    let labels: Vec<&str> = m.items.iter().map(|i| i.label.as_str()).collect();
    assert!(
        labels.contains(&"Duplicate") && labels.contains(&"View..."),
        "{labels:?}"
    );
    // View... → Top.
    let i = labels.iter().position(|l| *l == "View...").unwrap();
    let r = m.item_rect(ed.layout().window, i);
    click(&mut ed, ((r.x + 10) as f32, (r.y + 5) as f32));
    let m = ed.menu().expect("the View menu");
    let shortcuts: Vec<&str> = m.items.iter().map(|i| i.shortcut.as_str()).collect();
    assert!(shortcuts.contains(&"Num 7") && shortcuts.contains(&"Ctrl+Num 1"));
    let i = m.items.iter().position(|i| i.label == "Top").unwrap();
    let r = m.item_rect(ed.layout().window, i);
    click(&mut ed, ((r.x + 10) as f32, (r.y + 5) as f32));
    assert!((ed.camera().pitch - std::f32::consts::FRAC_PI_2).abs() < 1e-5);
    // A right drag still pans (no menu).
    let t0 = ed.camera().target;
    let (button, mods) = (MouseButton::Right, Mods::NONE);
    ed.handle(Event::MouseDown {
        button,
        x: at.0,
        y: at.1,
        mods,
    });
    ed.handle(Event::MouseMove {
        x: at.0 + 40.0,
        y: at.1,
        mods,
    });
    ed.handle(Event::MouseUp {
        button,
        x: at.0 + 40.0,
        y: at.1,
        mods,
    });
    assert!(ed.menu().is_none());
    assert_ne!(ed.camera().target, t0);
}

#[test]
fn the_view_is_remembered_per_file_not_in_the_scene() {
    let d = std::env::temp_dir().join(format!("animed-newcomer-views-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    let mem = d.join("views");
    let file = d.join("scene.wrl");
    let mut ed = stage();
    ed.set_view_memory(Some(mem.clone()));
    key(&mut ed, Key::Num(3), Mods::NONE);
    key(&mut ed, Key::Num(5), Mods::NONE);
    // The timeline's zoom and preview range are remembered too.
    let r = ed.layout().ruler;
    let (x, y) = (r.x as f32 + r.w as f32 * 0.6, (r.y + r.h / 2) as f32);
    for _ in 0..3 {
        ed.handle(Event::Wheel {
            delta: 1.0,
            x,
            y,
            mods: Mods::NONE,
        });
    }
    ed.set_preview_range(Some((20.0, 40.0)));
    let zoom = ed.time_span();
    assert!(zoom.1 - zoom.0 < 90.0, "{zoom:?}");
    ed.save_to(&file).unwrap();
    let saved = *ed.camera();
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(!text.contains("ortho"), "the view is not in the scene");
    let loaded = animed::internals::format::load(&file).unwrap();
    let mut again = Editor::new(loaded.scene, Some(file.clone()), 480, 320);
    assert_ne!(
        *again.camera(),
        saved,
        "framed, not remembered, without memory"
    );
    again.set_view_memory(Some(mem.clone()));
    // The editor only asks for the memory; the shell reads it.
    assert_ne!(*again.camera(), saved, "not read by the editor itself");
    animed::internals::editor::shell::perform(&mut again);
    assert_eq!(*again.camera(), saved);
    assert_eq!(again.time_span(), zoom);
    assert_eq!(again.preview_range(), Some((20.0, 40.0)));
    // Opening the file in another editor recalls it too.
    let mut other = Editor::new(Scene::new(), None, 480, 320);
    other.set_view_memory(Some(mem.clone()));
    other.open_file(&file).unwrap();
    assert_eq!(*other.camera(), saved);
    assert_eq!(other.time_span(), zoom);
    assert_eq!(other.preview_range(), Some((20.0, 40.0)));
    // Leaving the file for a new scene remembers what changed meanwhile,
    // and the new scene starts unzoomed without a preview range.
    other.set_preview_range(Some((5.0, 50.0)));
    other.new_scene();
    animed::internals::editor::shell::perform(&mut other);
    assert_eq!(other.preview_range(), None);
    assert_eq!(other.time_span().0, 0.0);
    let memo = animed::internals::editor::disk::recall(&mem, &file).unwrap();
    assert_eq!(memo.preview, Some((5.0, 50.0)));
    assert_eq!(memo.zoom, Some(zoom));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn view_goldens() {
    let mut ed = stage();
    key(&mut ed, Key::Num(1), Mods::NONE);
    key(&mut ed, Key::Num(5), Mods::NONE);
    golden::check("editor_front_ortho", &ed.render_frame());
    key(&mut ed, Key::Num(7), Mods::NONE);
    golden::check("editor_top_ortho", &ed.render_frame());
}

// ----- item 3 (part): per-track repeat in the UI -----

#[test]
fn a_track_loops_from_the_key_panel() {
    use animed::internals::anim::{Property, Repeat, Target, TargetRef};
    let mut ed = big_stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let m = ed
        .key_marker_at(
            animed::internals::editor::keystrip::Row::Track(Property::Translation),
            24.0,
        )
        .expect("a translation key at 24");
    click(&mut ed, m);
    let t = Target {
        of: TargetRef::Node(ball),
        property: Property::Translation,
    };
    // The stage's ball loops; "hold" stops that, "loop" brings it back.
    assert_eq!(ed.scene().animation.track(t).unwrap().repeat, Repeat::Loop);
    let at = find(&ed, "Repeat(Constant)");
    click(&mut ed, at);
    assert_eq!(
        ed.scene().animation.track(t).unwrap().repeat,
        Repeat::Constant
    );
    assert_eq!(ed.status().text, "Track holds its end values");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().animation.track(t).unwrap().repeat, Repeat::Loop);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    let at = find(&ed, "Repeat(Constant)");
    click(&mut ed, at);
    let at = find(&ed, "Repeat(Loop)");
    click(&mut ed, at);
    assert_eq!(ed.scene().animation.track(t).unwrap().repeat, Repeat::Loop);
    assert_eq!(ed.status().text, "Track loops its keys");
}

// ----- item 7: selection display -----

#[test]
fn selection_keeps_the_objects_colour_and_handles_shrink_on_small_objects() {
    let mut ed = Editor::new(Scene::new(), None, 480, 320);
    let vp = ed.layout().viewport;
    hover(&mut ed, ((vp.x + 60) as f32, (vp.y + 60) as f32));
    key(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Char('b'), Mods::NONE);
    let b = ed.selection().expect("Box1 selected");
    key(&mut ed, Key::Num(1), Mods::NONE);
    let c = ed.camera().target;
    let arrow = |ed: &mut Editor| {
        let p = ed.handle_points().expect("move handles");
        ((p[1].0 - p[0].0).powi(2) + (p[1].1 - p[0].1).powi(2)).sqrt()
    };
    // A unit box seen from 10 units is ~33 px wide, so the arrows shrink
    // from their 70 px to 2.5 box radii (never under half).
    let small = arrow(&mut ed);
    assert!((35.0..=50.0).contains(&small), "small object: {small} px");
    // The box's lower-left quadrant (clear of the handles) keeps its own
    // grey: the tint moves each channel by at most an eighth.
    let at = ed.pixel_of(c + glam::Vec3::new(-0.3, -0.3, 0.5)).unwrap();
    let sel = ed.render_frame();
    golden::check("editor_selected_small", &sel);
    ed.select(None);
    let plain = ed.render_frame();
    let i = at.1 as usize * sel.width as usize + at.0 as usize;
    let ch = |c: u32, s: u32| ((c >> s) & 255) as i32;
    for s in [16, 8, 0] {
        let d = (ch(sel.color[i], s) - ch(plain.color[i], s)).abs();
        assert!(
            d <= 33,
            "channel {s}: {:06x} vs {:06x}",
            sel.color[i],
            plain.color[i]
        );
    }
    assert_ne!(plain.color[i], 0, "the probe is on the box");
    // The outline runs outside the box's left edge.
    let edge = ed.pixel_of(c + glam::Vec3::new(-0.5, -0.2, 0.5)).unwrap();
    let row = edge.1 as usize * sel.width as usize;
    let x0 = edge.0 as usize;
    assert!(
        (x0.saturating_sub(3)..x0 + 1)
            .any(|x| sel.color[row + x] == 0xff9a1f && plain.color[row + x] != sel.color[row + x]),
        "an orange outline left of the box"
    );
    // The scale tool's centre box leaves the small box's pivot: it sits
    // beside the box, off every axis, and still scales all three.
    ed.select(Some(b));
    key(&mut ed, Key::Char('t'), Mods::NONE);
    let pivot = ed.pixel_of(c).unwrap();
    let u = ed.handle_pixel("uniform").expect("a uniform box in view");
    let away = ((u.0 - pivot.0).powi(2) + (u.1 - pivot.1).powi(2)).sqrt();
    assert!(away > 20.0, "off the object's disc: {away} px");
    assert_ne!(ed.pick_at(u.0, u.1), Some(b), "not over the box itself");
    assert_ne!(
        ed.handle_at(pivot.0, pivot.1),
        Some(animed::internals::editor::manip::Handle::Uniform),
        "the pivot shows the object"
    );
    golden::check("editor_scale_small", &ed.render_frame());
    drag_via(&mut ed, &[u, (u.0 + 35.0, u.1)], Mods::NONE);
    let s = ed.scene().node(b).transform.scale;
    assert!((s - glam::Vec3::splat(1.5)).length() < 1e-4, "{s}");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('w'), Mods::NONE);
    // Framed, the box is big on screen and the handles are full size.
    ed.select(Some(b));
    key(&mut ed, Key::Char('f'), Mods::NONE);
    let big = arrow(&mut ed);
    assert!((big - 70.0).abs() < 1.0, "big object: {big} px");
}

// ----- item 3: timeline zoom/pan, preview range, keys after the end -----

#[test]
fn the_wheel_zooms_the_timeline_and_a_middle_drag_pans_it() {
    let mut ed = stage();
    ed.select(Some(node(&ed, "Ball")));
    let full = ed.time_span();
    assert_eq!(full, (0.0, 96.0));
    let r = ed.layout().ruler;
    let (x, y) = (r.x as f32 + r.w as f32 * 0.6, (r.y + r.h / 2) as f32);
    // The frame under the mouse stays under it while zooming in.
    let frame_at = |ed: &Editor, x: f32| {
        let s = ed.time_span();
        let l = ed.layout();
        let a = l.frame_to_x_in(s.0, s);
        let b = l.frame_to_x_in(s.1, s);
        s.0 + (x - a) / (b - a) * (s.1 - s.0)
    };
    let before = frame_at(&ed, x);
    let frame0 = ed.current_frame();
    for _ in 0..4 {
        ed.handle(Event::Wheel {
            delta: 1.0,
            x,
            y,
            mods: Mods::NONE,
        });
    }
    let z = ed.time_span();
    assert!(z.1 - z.0 < 60.0, "zoomed in: {z:?}");
    assert!((frame_at(&ed, x) - before).abs() < 0.01);
    assert_eq!(
        ed.current_frame(),
        frame0,
        "the wheel no longer steps frames"
    );
    assert!(ed.status().text.starts_with("Timeline shows frames"));
    // Frame 0 is out of view now: no cursor line anywhere on the ruler
    // (it used to land on the names column).
    assert!(z.0 > 0.0);
    let f = ed.render_frame();
    let tl = ed.layout().timeline;
    let cursor_px = (tl.y..tl.bottom())
        .flat_map(|y| (0..f.width as i32).map(move |x| (x, y)))
        .filter(|&(x, y)| f.color[(y * f.width as i32 + x) as usize] == 0x4cc2ff)
        .count();
    assert_eq!(cursor_px, 0);
    // Keys follow the zoom: the key at 48 is where the span puts it.
    let m = ed
        .key_marker_at(animed::internals::editor::keystrip::Row::Summary, 48.0)
        .unwrap();
    assert!((m.0 - ed.layout().frame_to_x_in(48.0, z)).abs() < 1e-3);
    // A middle drag 40 px to the left shows later frames.
    let mid = animed::internals::editor::MouseButton::Middle;
    ed.handle(Event::MouseDown {
        button: mid,
        x,
        y,
        mods: Mods::NONE,
    });
    move_to(&mut ed, (x - 40.0, y), Mods::NONE);
    ed.handle(Event::MouseUp {
        button: mid,
        x: x - 40.0,
        y,
        mods: Mods::NONE,
    });
    let p = ed.time_span();
    assert!(
        p.0 > z.0 + 1.0 && ((p.1 - p.0) - (z.1 - z.0)).abs() < 1e-3,
        "{p:?}"
    );
    assert_eq!(ed.current_frame(), frame0, "panning does not seek");
    let said = format!("Timeline shows frames {} to", p.0.round());
    assert!(ed.status().text.starts_with(&said), "{}", ed.status().text);
    // Home over the timeline shows the whole scene again.
    hover(&mut ed, (x, y));
    key(&mut ed, Key::Home, Mods::NONE);
    assert_eq!(ed.time_span(), full);
}

#[test]
fn playback_loops_over_a_preview_range_set_on_the_ruler() {
    let mut ed = stage();
    let r = ed.layout().ruler;
    let y = (r.y + r.h / 2) as f32;
    let x_of = |ed: &Editor, f: f32| ed.layout().frame_to_x_in(f, ed.time_span());
    // Shift+drag on the ruler from frame 20 to frame 40.
    let (a, b) = (x_of(&ed, 20.0), x_of(&ed, 40.0));
    drag(&mut ed, (a, y), (b, y), Mods::shift());
    assert_eq!(ed.preview_range(), Some((20.0, 40.0)));
    assert!(
        ed.status().text.starts_with("Preview frames 20 to 40"),
        "{}",
        ed.status().text
    );
    assert_eq!(ed.current_frame(), 0.0, "setting the range does not seek");
    // Play from frame 0 (outside): playback runs inside 20..=40 only and
    // comes round again.
    key(&mut ed, Key::Space, Mods::NONE);
    let mut seen = Vec::new();
    for i in 0..100 {
        ed.handle(Event::Tick {
            time: 100.0 + i as f64 * 0.05,
        });
        seen.push(ed.current_frame());
    }
    assert!(seen.iter().all(|f| (20.0..=40.0).contains(f)), "{seen:?}");
    assert!(
        seen.contains(&40.0) && seen.windows(2).any(|w| w[1] < w[0]),
        "loops"
    );
    key(&mut ed, Key::Space, Mods::NONE);
    ed.select(Some(node(&ed, "Ball")));
    golden::check("editor_timeline_preview", &ed.render_frame());
    // [ and ] set the ends at the current frame; Alt+P clears.
    let f = find(&ed, "Field(Frame)");
    click(&mut ed, f);
    ed.handle(Event::Text("10".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    key(&mut ed, Key::Char('['), Mods::NONE);
    assert_eq!(ed.preview_range(), Some((10.0, 40.0)));
    click(&mut ed, f);
    ed.handle(Event::Text("30".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    key(&mut ed, Key::Char(']'), Mods::NONE);
    assert_eq!(ed.preview_range(), Some((10.0, 30.0)));
    key(&mut ed, Key::Char('p'), Mods::alt());
    assert_eq!(ed.preview_range(), None);
    assert!(ed.status().text.starts_with("Preview range cleared"));
}

#[test]
fn a_shorter_scene_keeps_its_late_keys_visible_greyed_and_says_so() {
    let mut ed = stage();
    ed.select(Some(node(&ed, "Ball")));
    // The len field takes an expression like the other number fields.
    let len = find(&ed, "Field(Duration)");
    click(&mut ed, len);
    ed.handle(Event::Text("2*24".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().settings.duration, 48.0);
    let s = ed.status().text.clone();
    assert_eq!(s, "13 keys after frame 48 kept (greyed)");
    // The strip still reaches the key at 96, past the end.
    assert_eq!(ed.time_span(), (0.0, 96.0));
    let row = animed::internals::editor::keystrip::Row::Summary;
    let late = ed.key_marker_at(row, 96.0).unwrap();
    let early = ed.key_marker_at(row, 24.0).unwrap();
    let frame = ed.render_frame();
    let px =
        |p: (f32, f32)| frame.color[p.1 as usize * frame.width as usize + p.0.round() as usize];
    let lum = |c: u32| ((c >> 16) & 255) + ((c >> 8) & 255) + (c & 255);
    assert!(
        lum(px(late)) * 2 < lum(px(early)),
        "late key {:06x} greyed against {:06x}",
        px(late),
        px(early)
    );
    golden::check("editor_timeline_late_keys", &frame);
    // Undo: the scene is long again and nothing is greyed.
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().settings.duration, 96.0);
}

// ----- item 2: context menus in the strip and lists, tooltips -----

fn right_click(ed: &mut Editor, (x, y): (f32, f32)) {
    let button = MouseButton::Right;
    ed.handle(Event::MouseMove {
        x,
        y,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseDown {
        button,
        x,
        y,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseUp {
        button,
        x,
        y,
        mods: Mods::NONE,
    });
}

/// Picks the open menu's item whose label starts with `label`.
fn pick(ed: &mut Editor, label: &str) {
    let m = ed.menu().expect("a menu is open");
    let i = m
        .items
        .iter()
        .position(|it| it.label.starts_with(label))
        .unwrap_or_else(|| panic!("no {label} in {:?}", m.items));
    let r = m.item_rect(ed.layout().window, i);
    click(ed, ((r.x + 10) as f32, (r.y + 5) as f32));
    assert!(ed.menu().is_none());
}

#[test]
fn clear_keys_from_the_viewport_menu_or_alt_i_is_one_undo_step() {
    use animed::internals::anim::TargetRef;
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let keys = |ed: &Editor| -> usize {
        ed.scene()
            .animation
            .tracks_of(TargetRef::Node(ball))
            .map(|t| t.key_count())
            .sum()
    };
    let n = keys(&ed);
    assert!(n > 0);
    let vp = ed.layout().viewport;
    right_click(&mut ed, ((vp.x + 20) as f32, (vp.y + 20) as f32));
    pick(&mut ed, "Clear keys");
    assert_eq!(keys(&ed), 0);
    assert_eq!(
        ed.status().text,
        format!("Cleared {n} keys of Ball (Ctrl+Z brings them back)")
    );
    // Other objects keep theirs.
    assert!(ed
        .scene()
        .animation
        .tracks
        .iter()
        .any(|t| t.target.of != TargetRef::Node(ball)));
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(keys(&ed), n);
    // Alt+I does the same; again says there is nothing left.
    key(&mut ed, Key::Char('i'), Mods::alt());
    assert_eq!(keys(&ed), 0);
    key(&mut ed, Key::Char('i'), Mods::alt());
    assert_eq!(ed.status().text, "Ball has no keys to clear");
    // The strip draws with the keys gone.
    let _ = ed.render_frame();
}

#[test]
fn the_key_strips_context_menu_edits_the_keys_under_the_mouse() {
    use animed::internals::anim::{Interp, Keys, Property, Target, TargetRef};
    use animed::internals::editor::keystrip::Row;
    let mut ed = big_stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let row = Row::Track(Property::Translation);
    let at = ed.key_marker_at(row, 24.0).unwrap();
    right_click(&mut ed, at);
    let labels: Vec<String> = ed
        .menu()
        .expect("the strip's menu")
        .items
        .iter()
        .map(|i| i.label.clone())
        .collect();
    assert_eq!(
        labels,
        [
            "Interpolation: step",
            "Interpolation: linear",
            "Interpolation: tcb",
            "Ease in",
            "Ease out",
            "Ease in and out",
            "No ease",
            "Delete keys",
            "Copy keys",
            "Select all on row"
        ]
    );
    let keys = |ed: &Editor| {
        let t = Target {
            of: TargetRef::Node(ball),
            property: Property::Translation,
        };
        match &ed.scene().animation.track(t).unwrap().keys {
            Keys::Vec3(k) => k.clone(),
            _ => panic!("vector keys"),
        }
    };
    pick(&mut ed, "Interpolation: step");
    assert_eq!(keys(&ed)[1].interp, Interp::Step, "the key at 24");
    assert_ne!(keys(&ed)[2].interp, Interp::Step, "only that key");
    right_click(&mut ed, at);
    pick(&mut ed, "Ease in and out");
    assert_eq!((keys(&ed)[1].ease_in, keys(&ed)[1].ease_out), (1.0, 1.0));
    // Select all on the row, then delete them; undo brings them back.
    right_click(&mut ed, at);
    pick(&mut ed, "Select all on row");
    assert_eq!(ed.status().text, "Selected 5 keys on the row");
    right_click(&mut ed, at);
    pick(&mut ed, "Copy keys");
    right_click(&mut ed, at);
    pick(&mut ed, "Delete keys");
    assert!(ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(ball),
            property: Property::Translation
        })
        .is_none_or(|t| t.key_count() == 0));
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(keys(&ed).len(), 5);
    // With keys on the clipboard the menu offers pasting them.
    let at48 = ed.key_marker_at(row, 48.0).unwrap();
    right_click(&mut ed, at48);
    assert!(ed
        .menu()
        .unwrap()
        .items
        .iter()
        .any(|i| i.label == "Paste at frame 0"));
    key(&mut ed, Key::Escape, Mods::NONE);
}

#[test]
fn the_lists_context_menu_renames_duplicates_and_deletes() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    let row = find(&ed, &format!("node: NodeId({})", ball.0));
    right_click(&mut ed, row);
    assert_eq!(ed.selection(), Some(ball), "the row is selected");
    pick(&mut ed, "Rename");
    ed.handle(Event::Text("Planet".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().node(ball).name, "Planet");
    let row = find(&ed, &format!("node: NodeId({})", ball.0));
    right_click(&mut ed, row);
    pick(&mut ed, "Duplicate");
    let copy = ed.selection().unwrap();
    assert_ne!(copy, ball);
    assert!(ed.scene().node(copy).name.starts_with("Planet"));
    let row = find(&ed, &format!("node: NodeId({})", copy.0));
    right_click(&mut ed, row);
    pick(&mut ed, "Delete");
    assert!(ed.scene().find_node(&ed.scene().node(ball).name).is_some());
    assert_eq!(ed.selection(), None);
}

#[test]
fn tooltips_explain_toolbar_buttons_and_fields_after_half_a_second() {
    let mut ed = stage();
    let imp = find(&ed, "Import");
    hover(&mut ed, imp);
    assert!(
        ed.wants_ticks(),
        "a pending tooltip keeps the clock running"
    );
    ed.handle(Event::Tick { time: 5.0 });
    ed.handle(Event::Tick { time: 5.3 });
    assert_eq!(ed.tooltip(), None, "not before 0.5 s");
    assert!(ed.handle(Event::Tick { time: 5.55 }), "appearing redraws");
    assert_eq!(
        ed.tooltip().as_deref(),
        Some("Import a model as a new object (Ctrl+I)")
    );
    golden::check("editor_tooltip", &ed.render_frame());
    // Another widget: gone, and back after its own delay.
    let style = find(&ed, "ViewStyle");
    assert!(ed.handle(Event::MouseMove {
        x: style.0,
        y: style.1,
        mods: Mods::NONE
    }));
    assert_eq!(ed.tooltip(), None);
    ed.handle(Event::Tick { time: 6.0 });
    ed.handle(Event::Tick { time: 6.6 });
    assert!(ed.tooltip().unwrap().starts_with("Viewport style"));
    // A click hides it.
    let len = find(&ed, "Field(Duration)");
    click(&mut ed, len);
    assert_eq!(ed.tooltip(), None);
    key(&mut ed, Key::Escape, Mods::NONE);
}

#[test]
fn f3_searches_every_command_by_name() {
    let mut ed = Editor::new(Scene::new(), None, 480, 320);
    key(&mut ed, Key::F(3), Mods::NONE);
    let n = ed.search().expect("F3 opens the search").menu.items.len();
    assert!(n > 10, "the whole list shows first ({n})");
    // Typing filters; the keys typed are text, not shortcuts.
    key(&mut ed, Key::Char('b'), Mods::NONE);
    ed.handle(Event::Text("Box".into()));
    let s = ed.search().unwrap();
    assert_eq!(s.menu.items[0].label, "Add Box");
    assert_eq!(s.menu.items[0].shortcut, "Shift+A");
    golden::check("editor_search", &ed.render_frame());
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(ed.search().is_none());
    assert_eq!(ed.scene().node(ed.selection().unwrap()).name, "Box1");
    // Esc closes without running anything.
    key(&mut ed, Key::F(3), Mods::NONE);
    ed.handle(Event::Text("sphere".into()));
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(ed.search().is_none());
    assert!(ed.scene().find_node("Sphere1").is_none());
    assert_eq!(
        ed.mode(),
        animed::internals::editor::Mode::Select,
        "Esc only closed the search"
    );
}

#[test]
fn with_nothing_selected_the_properties_say_how_to_start() {
    use animed::internals::editor::panel::WidgetKind;
    use animed::internals::ui::text;
    let mut ed = stage();
    assert_eq!(ed.selection(), None);
    let sp = ed.side_panel();
    let body = sp.props.take_top(16).1;
    let lines = |ed: &Editor| -> Vec<(String, animed::internals::ui::Rect)> {
        ed.widgets()
            .into_iter()
            .filter(|w| body.contains(w.rect.x as f32, w.rect.y as f32 + 1.0))
            .filter_map(|w| match w.kind {
                WidgetKind::Label { text, .. } => Some((text, w.rect)),
                _ => None,
            })
            .collect()
    };
    let said = lines(&ed);
    // As many lines as show at 480x320, each whole, none scrolled.
    assert_eq!(said.len(), sp.prop_rows_shown() as usize, "{said:?}");
    assert_eq!(said[0].0, "Nothing selected");
    assert!(said.iter().any(|(t, _)| t.contains("Shift+A")), "{said:?}");
    for (t, r) in &said {
        assert!(r.bottom() <= sp.props.bottom(), "{t} inside");
        assert!(text::width(t) + 4 <= r.w, "{t} fits its row");
    }
    // Selecting and deselecting moves no section of the panel.
    let ball = node(&ed, "Ball");
    let at = find(&ed, &format!("node: NodeId({})", ball.0));
    click(&mut ed, at);
    assert!(lines(&ed).iter().all(|(t, _)| !t.contains("Shift+A")));
    assert_eq!(ed.side_panel(), sp);
    key(&mut ed, Key::Escape, Mods::NONE);
    ed.select(None);
    assert_eq!(lines(&ed), said);
    assert_eq!(ed.side_panel(), sp);
}
