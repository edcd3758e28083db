//! Translate handles driven by mouse events on the demo stage: the object
//! follows the arrow, Ctrl snaps to the grid, a drag is one undo step, and
//! in record mode the release keys the translation.

#[path = "common/golden.rs"]
mod golden;

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::anim::{Property, Target, TargetRef};
use animed::internals::editor::manip::Handle;
use animed::internals::editor::{Editor, Event, Key, Mods, MouseButton};
use ui_input::*;

/// A point `at` of the way along arrow `axis` (1..=3) and the screen
/// direction of that arrow (unit).
fn on_arrow(ed: &mut Editor, axis: usize, at: f32) -> ((f32, f32), (f32, f32)) {
    let p = ed.handle_points().expect("handles are shown");
    let (c, tip) = (p[0], p[axis]);
    let (dx, dy) = (tip.0 - c.0, tip.1 - c.1);
    let l = (dx * dx + dy * dy).sqrt();
    ((c.0 + dx * at, c.1 + dy * at), (dx / l, dy / l))
}

#[test]
fn dragging_the_x_arrow_moves_along_x_only_as_one_step() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let t0 = ed.scene().node(pyr).transform.translation;
    let (a, dir) = on_arrow(&mut ed, 1, 0.6);
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::Axis(0)));
    let b = (a.0 + dir.0 * 40.0, a.1 + dir.1 * 40.0);
    drag(&mut ed, a, b, Mods::NONE);
    let t1 = ed.scene().node(pyr).transform.translation;
    assert!(t1.x > t0.x + 0.1, "moved along +x: {t0} -> {t1}");
    assert!((t1.y - t0.y).abs() < 1e-5 && (t1.z - t0.z).abs() < 1e-5);
    assert_eq!(ed.selection(), Some(pyr), "a handle drag does not pick");
    // The mouse is still on the x axis line through the moved pivot
    // (exact following along the line is unit-tested in manip.rs; the
    // arrow's world length changes with depth, so compare with the line).
    let p = ed.handle_points().unwrap();
    let (c, tip) = (p[0], p[1]);
    let (dx, dy) = (tip.0 - c.0, tip.1 - c.1);
    let off = ((b.0 - c.0) * dy - (b.1 - c.1) * dx).abs() / (dx * dx + dy * dy).sqrt();
    assert!(off < 0.5, "mouse {off} px off the moved axis");
    assert_eq!(
        ed.history().labels().collect::<Vec<_>>(),
        vec!["Move Pyramid"]
    );
    assert!(ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(pyr),
            property: Property::Translation
        })
        .is_none());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().node(pyr).transform.translation, t0);
}

#[test]
fn ctrl_snaps_to_the_grid_and_esc_cancels() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let t0 = ed.scene().node(pyr).transform.translation;
    let (a, dir) = on_arrow(&mut ed, 3, 0.7);
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::Axis(2)));
    drag(
        &mut ed,
        a,
        (a.0 + dir.0 * 33.0, a.1 + dir.1 * 33.0),
        Mods::ctrl(),
    );
    let z = ed.scene().node(pyr).transform.translation.z;
    assert_ne!(z, t0.z);
    // The stage's grid step is 1 (radius between 2 and 20).
    assert!((z - z.round()).abs() < 1e-5, "z {z} snapped to the grid");
    // Esc during a drag puts the object back.
    let t1 = ed.scene().node(pyr).transform.translation;
    let (a, dir) = on_arrow(&mut ed, 1, 0.6);
    let button = MouseButton::Left;
    ed.handle(Event::MouseDown {
        button,
        x: a.0,
        y: a.1,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseMove {
        x: a.0 + dir.0 * 30.0,
        y: a.1 + dir.1 * 30.0,
        mods: Mods::NONE,
    });
    assert!(ed.handle_dragging());
    assert_ne!(ed.posed_node(pyr).transform.translation, t1);
    key(&mut ed, Key::Escape, Mods::NONE);
    ed.handle(Event::MouseUp {
        button,
        x: a.0,
        y: a.1,
        mods: Mods::NONE,
    });
    assert_eq!(ed.scene().node(pyr).transform.translation, t1);
    assert_eq!(ed.history().labels().count(), 1);
}

#[test]
fn record_mode_drags_make_keys_at_three_frames() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('r'), Mods::NONE);
    for (frame, axis) in [(0, 1), (20, 2), (40, 1)] {
        while ed.current_frame() < frame as f32 {
            key(&mut ed, Key::Right, Mods::NONE);
        }
        let (a, dir) = on_arrow(&mut ed, axis, 0.6);
        drag(
            &mut ed,
            a,
            (a.0 + dir.0 * 25.0, a.1 + dir.1 * 25.0),
            Mods::NONE,
        );
    }
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(pyr),
            property: Property::Translation,
        })
        .expect("translation track");
    assert_eq!(t.keys.frames(), vec![0.0, 20.0, 40.0]);
    // Each drag is one step: undo the last removes its key only.
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(pyr),
            property: Property::Translation,
        })
        .unwrap();
    assert_eq!(t.keys.frames(), vec![0.0, 20.0]);
}

#[test]
fn dragging_an_animated_object_without_record_is_pending_until_k() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let shown0 = ed.posed_node(ball).transform.translation;
    let (a, dir) = on_arrow(&mut ed, 2, 0.6);
    drag(
        &mut ed,
        a,
        (a.0 + dir.0 * 30.0, a.1 + dir.1 * 30.0),
        Mods::NONE,
    );
    let shown1 = ed.posed_node(ball).transform.translation;
    assert!(
        shown1.y > shown0.y + 0.1,
        "the ball shows the drag: {shown0} -> {shown1}"
    );
    assert!(ed.pending().is_some());
    key(&mut ed, Key::Char('k'), Mods::NONE);
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(ball),
            property: Property::Translation,
        })
        .unwrap();
    let k = t.key(t.key_index_at(0.0).expect("key at frame 0")).unwrap();
    assert_eq!(k.value, animed::internals::anim::Value::Vec3(shown1));
}

#[test]
fn handles_golden_with_hover() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let (a, _) = on_arrow(&mut ed, 2, 0.6);
    ed.handle(Event::MouseMove {
        x: a.0,
        y: a.1,
        mods: Mods::NONE,
    });
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::Axis(1)));
    let frame = ed.render_frame();
    golden::check("editor_handles", &frame);
}

#[test]
fn motion_path_golden() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    // Frame of the ball's second key: its marker is highlighted.
    key(&mut ed, Key::Up, Mods::NONE);
    assert!(ed.current_frame() > 0.0, "the ball has a key after frame 0");
    let frame = ed.render_frame();
    golden::check("editor_motion_path", &frame);
}
