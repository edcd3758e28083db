//! The key strip and the key properties panel driven through editor events
//! like a user: selecting keys (click, Shift, box), moving and scaling them
//! in time, Delete, Ctrl+C / Ctrl+V, editing key parameters by typing and
//! dragging, each checked in `scene.animation` and through undo/redo.

#[path = "common/golden.rs"]
mod golden;

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::anim::{Interp, Property, Target, TargetRef, Value};
use animed::internals::editor::keystrip::{KeyRef, Row};
use animed::internals::editor::{Editor, Event, Key, Mods};
use animed::internals::scene::{Node, NodeId, Scene, Transform};
use glam::Vec3;
use std::path::{Path, PathBuf};
use ui_input::*;

/// Two groups: "Box" with translation keys at 0, 10, 20 (x = 0, 4, 0) and
/// scale keys at 10 and 30; "Other" without keys. 60 frames.
fn scene() -> Scene {
    let mut s = Scene::new();
    let bx = s.add_node(None, Node::group("Box"));
    s.add_node(
        None,
        Node::group("Other").with_transform(Transform::from_translation(Vec3::new(0.0, 2.0, 0.0))),
    );
    s.settings.duration = 60.0;
    let t = target(bx, Property::Translation);
    for (f, x) in [(0.0, 0.0), (10.0, 4.0), (20.0, 0.0)] {
        s.animation
            .set_key(t, f, Value::Vec3(Vec3::new(x, 0.0, 0.0)))
            .unwrap();
    }
    let sc = target(bx, Property::Scale);
    for (f, k) in [(10.0, 1.0), (30.0, 2.0)] {
        s.animation
            .set_key(sc, f, Value::Vec3(Vec3::splat(k)))
            .unwrap();
    }
    s
}

fn editor() -> (Editor, NodeId) {
    let mut ed = Editor::new(scene(), None, 480, 320);
    let bx = NodeId(0);
    ed.select(Some(bx));
    (ed, bx)
}

fn target(id: NodeId, p: Property) -> Target {
    Target {
        of: TargetRef::Node(id),
        property: p,
    }
}

fn sample_x(ed: &Editor, id: NodeId, frame: f32) -> f32 {
    match ed
        .scene()
        .animation
        .track(target(id, T))
        .unwrap()
        .sample(frame)
    {
        Value::Vec3(v) => v.x,
        v => panic!("translation is a vector, got {v:?}"),
    }
}

fn marker(ed: &Editor, row: Row, frame: f32) -> (f32, f32) {
    ed.key_marker_at(row, frame)
        .unwrap_or_else(|| panic!("no marker row {row:?} frame {frame}"))
}

fn click_marker(ed: &mut Editor, row: Row, frame: f32, mods: Mods) {
    let at = marker(ed, row, frame);
    click_with(ed, at, mods);
}

/// Window x of `frame` on the ruler.
fn frame_x(ed: &Editor, frame: f32) -> f32 {
    ed.layout().frame_to_x(frame, ed.scene().settings.duration)
}

fn frames(ed: &Editor, id: NodeId, p: Property) -> Vec<f32> {
    ed.scene()
        .animation
        .track(target(id, p))
        .map(|t| t.keys.frames())
        .unwrap_or_default()
}

fn selected(ed: &Editor) -> Vec<(Property, f32)> {
    let mut v: Vec<(Property, f32)> = ed
        .selected_keys()
        .into_iter()
        .map(|k| (k.property, k.frame))
        .collect();
    v.sort_by(|a, b| {
        a.1.total_cmp(&b.1)
            .then(format!("{:?}", a.0).cmp(&format!("{:?}", b.0)))
    });
    v
}

const T: Property = Property::Translation;
const S: Property = Property::Scale;

#[test]
fn strip_has_a_summary_row_and_a_row_per_property_and_folds() {
    let (mut ed, _) = editor();
    let rows: Vec<Row> = ed.key_strip_layout().into_iter().map(|(r, _)| r).collect();
    assert_eq!(rows, vec![Row::Summary, Row::Track(T), Row::Track(S)]);
    // The strip's height never follows the rows (issue 17: stable layout).
    let l = ed.layout();
    let h = l.key_rows.h;
    assert!(h >= animed::internals::ui::layout::KEY_ROW_H, "{h}");
    // The fold triangle sits in the summary row's name cell.
    let (_, r) = ed.key_strip_layout()[0];
    click(&mut ed, (r.x as f32 + 6.0, r.y as f32 + 7.0));
    let rows: Vec<Row> = ed.key_strip_layout().into_iter().map(|(r, _)| r).collect();
    assert_eq!(rows, vec![Row::Summary]);
    assert_eq!(ed.layout().key_rows.h, h);
    // Nothing animated selected: the strip stays, with its summary row only.
    ed.select(Some(NodeId(1)));
    assert_eq!(ed.layout().key_rows.h, h);
    assert_eq!(ed.key_strip_layout().len(), 1);
}

#[test]
fn click_selects_shift_adds_and_toggles_summary_selects_a_frame() {
    let (mut ed, _) = editor();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    assert_eq!(selected(&ed), vec![(T, 10.0)]);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::NONE);
    assert_eq!(selected(&ed), vec![(T, 20.0)], "a plain click replaces");
    click_marker(&mut ed, Row::Track(S), 30.0, Mods::shift());
    assert_eq!(selected(&ed), vec![(T, 20.0), (S, 30.0)]);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::shift());
    assert_eq!(selected(&ed), vec![(S, 30.0)], "shift toggles off");
    // A summary marker stands for every key at its frame.
    click_marker(&mut ed, Row::Summary, 10.0, Mods::NONE);
    assert_eq!(selected(&ed), vec![(S, 10.0), (T, 10.0)]);
    // A click on empty strip space clears; so does Esc.
    let (x, y) = marker(&ed, Row::Track(T), 10.0);
    let at = (frame_x(&ed, 45.0), y);
    click(&mut ed, at);
    assert!(selected(&ed).is_empty());
    click(&mut ed, (x, y));
    assert_eq!(selected(&ed).len(), 1);
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(selected(&ed).is_empty());
    assert_eq!(
        ed.mode(),
        animed::internals::editor::Mode::Select,
        "Esc cleared keys only"
    );
}

#[test]
fn box_select_takes_keys_inside() {
    let (mut ed, _) = editor();
    let (_, yt) = marker(&ed, Row::Track(T), 0.0);
    let (_, ys) = marker(&ed, Row::Track(S), 0.0);
    // From above the translation row at frame 5 to below the scale row at 25.
    let a = (frame_x(&ed, 5.0), yt - 5.0);
    let b = (frame_x(&ed, 25.0), ys + 5.0);
    drag(&mut ed, a, b, Mods::NONE);
    assert_eq!(selected(&ed), vec![(S, 10.0), (T, 10.0), (T, 20.0)]);
    // Shift+box adds.
    let a = (frame_x(&ed, 28.0), ys - 3.0);
    let b = (frame_x(&ed, 40.0), ys + 3.0);
    drag(&mut ed, a, b, Mods::shift());
    assert_eq!(selected(&ed).len(), 4);
    assert!(ed.scene().animation.tracks.len() == 2 && !ed.is_dirty());
}

#[test]
fn dragging_keys_moves_them_by_whole_frames_as_one_undo_step() {
    let (mut ed, bx) = editor();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::shift());
    let before = ed.history().labels().count();
    // Drag the 10 marker by 5.4 frames' worth of pixels: snaps to +5.
    let a = marker(&ed, Row::Track(T), 10.0);
    let b = (frame_x(&ed, 15.4), a.1);
    drag(&mut ed, a, b, Mods::NONE);
    assert_eq!(frames(&ed, bx, T), vec![0.0, 15.0, 25.0]);
    assert_eq!(
        frames(&ed, bx, S),
        vec![10.0, 30.0],
        "unselected track untouched"
    );
    assert_eq!(
        selected(&ed),
        vec![(T, 15.0), (T, 25.0)],
        "selection follows"
    );
    assert_eq!(ed.history().labels().count(), before + 1, "one step");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, T), vec![0.0, 10.0, 20.0]);
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, T), vec![0.0, 15.0, 25.0]);
    // The moved key keeps its value.
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(
        t.key(1).unwrap().value,
        Value::Vec3(Vec3::new(4.0, 0.0, 0.0))
    );
}

#[test]
fn moving_a_key_onto_another_replaces_it_and_esc_cancels_a_drag() {
    let (mut ed, bx) = editor();
    let a = marker(&ed, Row::Track(T), 10.0);
    let b = (frame_x(&ed, 20.0), a.1);
    drag(&mut ed, a, b, Mods::NONE);
    assert_eq!(frames(&ed, bx, T), vec![0.0, 20.0]);
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(
        t.key(1).unwrap().value,
        Value::Vec3(Vec3::new(4.0, 0.0, 0.0))
    );
    // Esc in the middle of a drag puts the keys back.
    let a = marker(&ed, Row::Track(S), 30.0);
    down(&mut ed, a, Mods::NONE);
    let x = frame_x(&ed, 40.0);
    move_to(&mut ed, (x, a.1), Mods::NONE);
    assert_eq!(frames(&ed, bx, S), vec![10.0, 40.0], "previewed live");
    key(&mut ed, Key::Escape, Mods::NONE);
    up(&mut ed, (x, a.1), Mods::NONE);
    assert_eq!(frames(&ed, bx, S), vec![10.0, 30.0]);
}

#[test]
fn alt_drag_scales_timing_about_the_current_frame() {
    let (mut ed, bx) = editor();
    // Select all translation keys (click the row name), cursor at frame 0.
    let (_, r) = ed.key_strip_layout()[1];
    click(&mut ed, (r.x as f32 + 20.0, r.y as f32 + 7.0));
    assert_eq!(selected(&ed).len(), 3);
    // Drag the key at 20 to 40 with Alt: factor 2 about frame 0.
    let a = marker(&ed, Row::Track(T), 20.0);
    let b = (frame_x(&ed, 40.0), a.1);
    drag(&mut ed, a, b, Mods::alt());
    assert_eq!(frames(&ed, bx, T), vec![0.0, 20.0, 40.0]);
    assert_eq!(ed.history().labels().count(), 1);
    assert_eq!(ed.current_frame(), 0.0, "the drag did not seek");
}

#[test]
fn delete_removes_selected_keys_not_the_object() {
    let (mut ed, bx) = editor();
    click_marker(&mut ed, Row::Summary, 10.0, Mods::NONE);
    key(&mut ed, Key::Delete, Mods::NONE);
    assert_eq!(ed.scene().nodes.len(), 2, "the object stays");
    assert_eq!(ed.selection(), Some(bx));
    assert_eq!(frames(&ed, bx, T), vec![0.0, 20.0]);
    assert_eq!(frames(&ed, bx, S), vec![30.0]);
    // Deleting the last key of a track removes the track; the property
    // keeps the value shown at the current frame.
    click_marker(&mut ed, Row::Track(S), 30.0, Mods::NONE);
    key(&mut ed, Key::Delete, Mods::NONE);
    assert!(ed.scene().animation.track(target(bx, S)).is_none());
    assert_eq!(ed.scene().node(bx).transform.scale, Vec3::splat(2.0));
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, S), vec![30.0]);
    assert_eq!(ed.scene().node(bx).transform.scale, Vec3::ONE);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, S), vec![10.0, 30.0]);
    // With no keys selected, Delete over the strip asks before deleting
    // the object (issue 17: never delete what has no focus unasked).
    key(&mut ed, Key::Escape, Mods::NONE);
    key(&mut ed, Key::Delete, Mods::NONE);
    assert_eq!(ed.scene().nodes.len(), 2, "asked first");
    assert!(ed.dialog().is_some());
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.scene().nodes.len(), 1);
}

#[test]
fn copy_paste_at_the_current_frame_and_onto_another_object() {
    let (mut ed, bx) = editor();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::shift());
    key(&mut ed, Key::Char('c'), Mods::ctrl());
    for _ in 0..40 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    key(&mut ed, Key::Char('v'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, T), vec![0.0, 10.0, 20.0, 40.0, 50.0]);
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(
        t.key(3).unwrap().value,
        Value::Vec3(Vec3::new(4.0, 0.0, 0.0))
    );
    assert_eq!(t.key(4).unwrap().value, Value::Vec3(Vec3::ZERO));
    assert_eq!(
        selected(&ed),
        vec![(T, 40.0), (T, 50.0)],
        "pasted keys selected"
    );
    // Onto another object: its translation gets the two keys.
    let other = NodeId(1);
    ed.select(Some(other));
    key(&mut ed, Key::Char('v'), Mods::ctrl());
    assert_eq!(frames(&ed, other, T), vec![40.0, 50.0]);
    assert_eq!(ed.history().labels().count(), 2);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.scene().animation.track(target(other, T)).is_none());
}

/// Translation keys x = 0, 4, 0, 10 at 0, 10, 20, 30: the spline's
/// tangent at 20 is not flat, so tension there changes the curve.
fn zigzag() -> (Editor, NodeId) {
    let (mut ed, bx) = editor();
    // Add a key at 30 through the UI: record mode, frame 30, type x.
    key(&mut ed, Key::Char('r'), Mods::NONE);
    for _ in 0..30 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    type_into(&mut ed, "Field(Translation(0))", "10");
    key(&mut ed, Key::Char('r'), Mods::NONE);
    assert_eq!(frames(&ed, bx, T), vec![0.0, 10.0, 20.0, 30.0]);
    (ed, bx)
}

#[test]
fn typing_tension_in_the_key_panel_changes_the_curve_and_the_motion_path() {
    let (mut ed, bx) = zigzag();
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::NONE);
    assert!(ed.key_panel_shown());
    let steps = ed.history().labels().count();
    let before = sample_x(&ed, bx, 24.0);
    let path0 = animed::internals::editor::motion_path::path(ed.scene(), bx, &[24.0])[0];
    type_into(&mut ed, "Field(Key(Tension))", "1");
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(2).unwrap().tension, 1.0);
    assert_eq!(t.key(1).unwrap().tension, 0.0, "only the selected key");
    let after = sample_x(&ed, bx, 24.0);
    assert!(
        (after - before).abs() > 0.05,
        "curve at 24: {before} -> {after}"
    );
    let path1 = animed::internals::editor::motion_path::path(ed.scene(), bx, &[24.0])[0];
    assert!(
        (path1 - path0).length() > 0.05,
        "motion path moved: {path0} -> {path1}"
    );
    assert_eq!(ed.history().labels().count(), steps + 1);
    // Out-of-range values are clamped, not refused.
    type_into(&mut ed, "Field(Key(Bias))", "7");
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(2).unwrap().bias, 1.0);
    type_into(&mut ed, "Field(Key(EaseIn))", "-3");
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(2).unwrap().ease_in, 0.0);
    assert_eq!(
        ed.history().labels().count(),
        steps + 2,
        "ease in stayed 0: nothing to undo"
    );
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(
        (sample_x(&ed, bx, 24.0) - before).abs() < 1e-6,
        "undo restores"
    );
}

#[test]
fn several_keys_get_the_edited_param_and_value_and_frame_edits_work() {
    let (mut ed, bx) = zigzag();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::shift());
    type_into(&mut ed, "Field(Key(Continuity))", "-0.5");
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(1).unwrap().continuity, -0.5);
    assert_eq!(t.key(2).unwrap().continuity, -0.5);
    assert_eq!(t.key(0).unwrap().continuity, 0.0);
    // A value component on all selected keys of that property.
    type_into(&mut ed, "Field(Key(Value(1)))", "2.5");
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(
        t.key(1).unwrap().value,
        Value::Vec3(Vec3::new(4.0, 2.5, 0.0))
    );
    assert_eq!(
        t.key(2).unwrap().value,
        Value::Vec3(Vec3::new(0.0, 2.5, 0.0))
    );
    // The frame field moves the keys together (primary 10 -> 12).
    type_into(&mut ed, "Field(Key(Frame))", "12");
    assert_eq!(frames(&ed, bx, T), vec![0.0, 12.0, 22.0, 30.0]);
    assert_eq!(selected(&ed), vec![(T, 12.0), (T, 22.0)]);
}

#[test]
fn dragging_a_key_param_previews_live_and_is_one_undo_step() {
    let (mut ed, bx) = zigzag();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    let steps = ed.history().labels().count();
    let a = find(&ed, "Field(Key(Tension))");
    down(&mut ed, a, Mods::NONE);
    let mut last = 0.0;
    for i in 1..=6 {
        let x = a.0 + i as f32 * 10.0;
        move_to(&mut ed, (x, a.1), Mods::NONE);
        let t = ed.scene().animation.track(target(bx, T)).unwrap();
        let now = t.key(1).unwrap().tension;
        assert!(now > last, "previewed live at step {i}: {now}");
        last = now;
    }
    up(&mut ed, (a.0 + 60.0, a.1), Mods::NONE);
    assert!((last - 0.6).abs() < 1e-4, "60 px at 0.01 per px: {last}");
    assert_eq!(ed.history().labels().count(), steps + 1);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(1).unwrap().tension, 0.0);
    // Dragging far clamps at 1.
    let a = find(&ed, "Field(Key(Tension))");
    drag(&mut ed, a, (a.0 + 400.0, a.1), Mods::NONE);
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(1).unwrap().tension, 1.0);
}

#[test]
fn interpolation_step_holds_values_and_the_node_panel_stays_reachable() {
    let (mut ed, bx) = zigzag();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    assert!(
        (sample_x(&ed, bx, 15.0) - 4.0).abs() > 0.1,
        "a spline moves"
    );
    let at = find(&ed, "Key(Interp(Step))");
    click(&mut ed, at);
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(1).unwrap().interp, Interp::Step);
    assert_eq!(sample_x(&ed, bx, 15.0), 4.0, "holds the key's value");
    assert_eq!(sample_x(&ed, bx, 19.9), 4.0);
    // The node's fields are one click away and come back.
    assert!(ed
        .widgets()
        .iter()
        .all(|w| !format!("{:?}", w.kind).contains("Field(Translation(0))")));
    let at = find(&ed, "ShowNode");
    click(&mut ed, at);
    assert!(!ed.key_panel_shown());
    find(&ed, "Field(Translation(0))");
    let at = find(&ed, "ShowKeys");
    click(&mut ed, at);
    assert!(ed.key_panel_shown());
}

fn stage() -> Editor {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    Editor::new(loaded.scene, Some(PathBuf::from("stage.wrl")), 480, 320)
}

#[test]
fn rotation_keys_offer_slerp_and_squad_and_euler_values() {
    let mut ed = stage();
    let sp = ed
        .scene()
        .find_node("Spinner")
        .expect("Spinner in the stage");
    ed.select(Some(sp));
    let r = Property::Rotation;
    let f = ed.row_markers(Row::Track(r))[1].0;
    click_marker(&mut ed, Row::Track(r), f, Mods::NONE);
    assert_eq!(
        ed.selected_keys(),
        vec![KeyRef {
            node: sp,
            property: r,
            frame: f
        }]
    );
    let at = find(&ed, "label: \"squad\"");
    click(&mut ed, at);
    let t = ed.scene().animation.track(target(sp, r)).unwrap();
    assert_eq!(t.key(1).unwrap().interp, Interp::Tcb);
    find(&ed, "label: \"slerp\"");
    // Euler degrees in, a rotation out (all three typed: the key sits at
    // 90 degrees about y, where Euler angles are not unique).
    type_into(&mut ed, "Field(Key(Value(0)))", "0");
    type_into(&mut ed, "Field(Key(Value(1)))", "45");
    type_into(&mut ed, "Field(Key(Value(2)))", "0");
    let Value::Rotation(q) = ed
        .scene()
        .animation
        .track(target(sp, r))
        .unwrap()
        .key(1)
        .unwrap()
        .value
    else {
        panic!("rotation keys hold quaternions")
    };
    let want = glam::Quat::from_rotation_y(45f32.to_radians());
    assert!(q.dot(want).abs() > 0.9999, "{q} vs {want}");
}

#[test]
fn undo_and_redo_bring_back_the_key_selection_or_drop_missing_keys() {
    let (mut ed, bx) = editor();
    click_marker(&mut ed, Row::Track(S), 30.0, Mods::NONE);
    let a = marker(&ed, Row::Track(S), 30.0);
    let b = (frame_x(&ed, 40.0), a.1);
    drag(&mut ed, a, b, Mods::NONE);
    assert_eq!(selected(&ed), vec![(S, 40.0)]);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, S), vec![10.0, 30.0]);
    assert_eq!(selected(&ed), vec![(S, 30.0)], "the key where it was");
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(selected(&ed), vec![(S, 40.0)], "and where it went");
    // The frame field: same.
    type_into(&mut ed, "Field(Key(Frame))", "45");
    assert_eq!(selected(&ed), vec![(S, 45.0)]);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(selected(&ed), vec![(S, 40.0)]);
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(selected(&ed), vec![(S, 45.0)]);
    // A key made outside the strip, selected, then undone: dropped (no
    // selection went with the animation before it).
    let (mut ed, bx) = editor();
    key(&mut ed, Key::Char('r'), Mods::NONE);
    for _ in 0..5 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    type_into(&mut ed, "Field(Scale(0))", "3");
    assert_eq!(frames(&ed, bx, S), vec![5.0, 10.0, 30.0]);
    click_marker(&mut ed, Row::Track(S), 5.0, Mods::NONE);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(frames(&ed, bx, S), vec![10.0, 30.0]);
    assert!(selected(&ed).is_empty(), "the key at 5 is gone");
    assert!(!ed.key_panel_shown());
    // Selecting another object hides the keys of the first.
    click_marker(&mut ed, Row::Track(S), 30.0, Mods::NONE);
    ed.select(Some(NodeId(1)));
    assert!(ed.selected_keys().is_empty());
}

#[test]
fn key_strip_golden() {
    let mut ed = stage();
    let ball = ed.scene().find_node("Ball").expect("Ball in the stage");
    ed.select(Some(ball));
    let rows = ed.key_strip_layout();
    assert_eq!(rows.len(), 2, "summary + translation");
    let second = ed.row_markers(Row::Track(T))[1].0;
    click_marker(&mut ed, Row::Track(T), second, Mods::NONE);
    assert!(ed.key_panel_shown());
    let frame = ed.render_frame();
    golden::check("editor_key_strip", &frame);
}

#[test]
fn scripts_aim_at_keys_and_key_fields_by_name() {
    let (mut ed, bx) = editor();
    let script = "click-key translation 10\n\
                  drag-key translation 10 14\n\
                  click-field Key(Tension)\n\
                  type 0.5\n\
                  key enter\n\
                  click-key summary 30 shift\n";
    animed::internals::editor::script::run(&mut ed, script, Path::new("keys.txt"))
        .expect("script runs");
    assert_eq!(frames(&ed, bx, T), vec![0.0, 14.0, 20.0]);
    let t = ed.scene().animation.track(target(bx, T)).unwrap();
    assert_eq!(t.key(1).unwrap().tension, 0.5);
    assert_eq!(selected(&ed), vec![(T, 14.0), (S, 30.0)]);
    // No key there: the line is named.
    let e = animed::internals::editor::script::run(
        &mut ed,
        "key esc\nclick-key scale 11\n",
        Path::new("k.txt"),
    )
    .unwrap_err();
    assert_eq!((e.line, e.column), (2, 1));
    assert!(e.message.contains("no key at frame 11"), "{}", e.message);
    let e =
        animed::internals::editor::script::run(&mut ed, "click-key wobble 1\n", Path::new("k.txt"))
            .unwrap_err();
    assert_eq!((e.line, e.column), (1, 11));
    assert!(e.message.contains("unknown key strip row"), "{}", e.message);
    let e = animed::internals::editor::script::run(
        &mut ed,
        "click-field Key(Nope)\n",
        Path::new("k.txt"),
    )
    .unwrap_err();
    assert!(e.message.contains("no field"), "{}", e.message);
}

/// A spot light with keys on eight properties, two keys each.
fn busy_light() -> (Editor, NodeId) {
    let mut s = Scene::new();
    let id = s.add_node(
        None,
        Node::new(
            "Spot",
            animed::internals::scene::NodeKind::Light(animed::internals::scene::Light::spot()),
        ),
    );
    let vals: [(Property, Value); 8] = [
        (Property::LightOn, Value::Bool(true)),
        (Property::LightIntensity, Value::Scalar(0.5)),
        (Property::LightColor, Value::Vec3(Vec3::ONE)),
        (Property::LightLocation, Value::Vec3(Vec3::ZERO)),
        (Property::LightDirection, Value::Vec3(Vec3::NEG_Y)),
        (Property::LightCutOff, Value::Scalar(0.5)),
        (Property::LightBeamWidth, Value::Scalar(0.4)),
        (Property::LightDropOff, Value::Scalar(0.0)),
    ];
    for (p, v) in vals {
        for f in [0.0, 10.0] {
            s.animation.set_key(target(id, p), f, v).unwrap();
        }
    }
    let mut ed = Editor::new(s, None, 320, 240);
    ed.select(Some(id));
    (ed, id)
}

#[test]
fn too_many_rows_scroll_and_bool_keys_toggle() {
    let (mut ed, id) = busy_light();
    let rows: Vec<Row> = ed.key_strip_layout().into_iter().map(|(r, _)| r).collect();
    let cap = (ed.layout().key_rows.h / animed::internals::ui::layout::KEY_ROW_H) as usize;
    assert!(cap < 9, "the strip is capped ({cap} rows)");
    assert_eq!(rows.len(), cap);
    assert_eq!(rows[0], Row::Summary);
    assert_eq!(ed.key_strip_scroll(), (0, 9, cap));
    // The wheel over the strip scrolls the rows (to the last ones).
    let r = ed.layout().key_rows;
    for _ in 0..20 {
        ed.handle(Event::Wheel {
            delta: -1.0,
            x: (r.x + r.w / 2) as f32,
            y: (r.y + 3) as f32,
            mods: Mods::NONE,
        });
    }
    let rows: Vec<Row> = ed.key_strip_layout().into_iter().map(|(r, _)| r).collect();
    assert_eq!(*rows.last().unwrap(), Row::Track(Property::LightDropOff));
    assert_eq!(ed.key_strip_scroll().0, 9 - cap);
    // Back to the top; then a taller strip (drag its edge) fits every row.
    for _ in 0..20 {
        ed.handle(Event::Wheel {
            delta: 1.0,
            x: (r.x + r.w / 2) as f32,
            y: (r.y + 3) as f32,
            mods: Mods::NONE,
        });
    }
    ed.handle(Event::Resize {
        width: 640,
        height: 480,
    });
    let top = ed.layout().timeline.y as f32;
    drag(&mut ed, (20.0, top), (20.0, top - 200.0), Mods::NONE);
    assert_eq!(ed.key_strip_layout().len(), 9);
    // A boolean key: the panel's On/Off button flips it.
    click_marker(&mut ed, Row::Track(Property::LightOn), 10.0, Mods::NONE);
    let at = find(&ed, "Key(ToggleBool)");
    click(&mut ed, at);
    let t = ed
        .scene()
        .animation
        .track(target(id, Property::LightOn))
        .unwrap();
    assert_eq!(t.key(1).unwrap().value, Value::Bool(false));
    assert_eq!(t.key(0).unwrap().value, Value::Bool(true));
    // Folding leaves the summary row only.
    let (_, r) = ed.key_strip_layout()[0];
    click(&mut ed, (r.x as f32 + 6.0, r.y as f32 + 7.0));
    assert_eq!(ed.key_strip_layout().len(), 1);
}

#[test]
fn key_edits_stop_playback() {
    let (mut ed, bx) = editor();
    click_marker(&mut ed, Row::Track(T), 10.0, Mods::NONE);
    key(&mut ed, Key::Space, Mods::NONE);
    assert!(ed.is_playing());
    key(&mut ed, Key::Delete, Mods::NONE);
    assert!(!ed.is_playing(), "Delete stopped playback");
    assert_eq!(frames(&ed, bx, T), vec![0.0, 20.0]);
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::NONE);
    key(&mut ed, Key::Space, Mods::NONE);
    let a = marker(&ed, Row::Track(T), 20.0);
    let b = (frame_x(&ed, 25.0), a.1);
    drag(&mut ed, a, b, Mods::NONE);
    assert!(!ed.is_playing(), "a key drag stopped playback");
}

#[test]
fn the_frame_line_in_the_strip_scrubs() {
    let (mut ed, _) = editor();
    for _ in 0..5 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    let (_, y) = marker(&ed, Row::Track(S), 10.0);
    let a = (frame_x(&ed, 5.0).floor() + 0.5, y);
    let b = (frame_x(&ed, 40.0), y);
    drag(&mut ed, a, b, Mods::NONE);
    assert_eq!(ed.current_frame(), 40.0);
    assert!(selected(&ed).is_empty(), "no box select");
    assert!(!ed.is_dirty());
}

#[test]
fn tcb_on_a_linear_key_makes_it_a_spline_key() {
    let mut ed = stage();
    let ball = ed.scene().find_node("Ball").expect("Ball in the stage");
    ed.select(Some(ball));
    let f = ed.row_markers(Row::Track(T))[1].0;
    let t0 = ed.scene().animation.track(target(ball, T)).unwrap().clone();
    assert_eq!(
        t0.key(1).unwrap().interp,
        Interp::Linear,
        "VRML keys are linear"
    );
    click_marker(&mut ed, Row::Track(T), f, Mods::NONE);
    type_into(&mut ed, "Field(Key(Continuity))", "0.5");
    let t = ed.scene().animation.track(target(ball, T)).unwrap();
    assert_eq!(t.key(1).unwrap().interp, Interp::Tcb);
    assert_eq!(t.key(1).unwrap().continuity, 0.5);
    let mid = f + 6.0;
    assert_ne!(
        t.sample(mid),
        t0.sample(mid),
        "the path bends after the key"
    );
    // Ease does not change the interpolation.
    type_into(&mut ed, "Field(Key(EaseOut))", "0.5");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    click_marker(&mut ed, Row::Track(T), f, Mods::NONE);
    type_into(&mut ed, "Field(Key(EaseOut))", "0.5");
    let t = ed.scene().animation.track(target(ball, T)).unwrap();
    assert_eq!(t.key(1).unwrap().interp, Interp::Linear);
    assert_eq!(t.key(1).unwrap().ease_out, 0.5);
}

#[test]
fn script_select_step_uses_the_list() {
    let mut ed = stage();
    animed::internals::editor::script::run(
        &mut ed,
        "select Spinner\nclick-key rotation 24\n",
        Path::new("s.txt"),
    )
    .expect("script runs");
    let sp = ed.scene().find_node("Spinner").unwrap();
    assert_eq!(ed.selection(), Some(sp));
    assert_eq!(selected(&ed), vec![(Property::Rotation, 24.0)]);
    let e = animed::internals::editor::script::run(&mut ed, "select Nobody\n", Path::new("s.txt"))
        .unwrap_err();
    assert!(e.message.contains("no node named Nobody"), "{}", e.message);
}

/// Whether field `id` shows in the window (not scrolled away).
fn field_shown(ed: &Editor, id: animed::internals::editor::fields::FieldId) -> bool {
    use animed::internals::editor::panel::WidgetKind;
    ed.widgets().iter().any(|w| w.kind == WidgetKind::Field(id))
}

#[test]
fn tab_types_into_the_next_field_and_scrolls_it_into_view() {
    use animed::internals::editor::fields::{FieldId, KeyField};
    let (mut ed, bx) = zigzag();
    let typing = |ed: &Editor| ed.text_edit().map(|e| (e.field, e.text.clone()));
    // The box's own rows (four show at 480x320); one notch down hides
    // the name.
    let props = ed.side_panel().props;
    let (x, y) = ((props.x + 20) as f32, (props.bottom() - 4) as f32);
    let mods = Mods::NONE;
    ed.handle(Event::Wheel {
        delta: -1.0,
        x,
        y,
        mods,
    });
    assert!(!field_shown(&ed, FieldId::Name));
    let at = find(&ed, "Field(Translation(0))");
    click(&mut ed, at);
    let steps = ed.history().labels().count();
    key(&mut ed, Key::Tab, Mods::shift());
    assert_eq!(typing(&ed), Some((FieldId::Name, "Box".into())));
    assert_eq!(
        ed.history().labels().count(),
        steps,
        "nothing typed: nothing recorded"
    );
    assert!(field_shown(&ed, FieldId::Name), "scrolled back into view");
    ed.handle(Event::Text("Crate".into()));
    key(&mut ed, Key::Tab, Mods::NONE);
    assert_eq!(ed.scene().node(bx).name, "Crate", "Tab records the field");
    assert_eq!(typing(&ed).map(|t| t.0), Some(FieldId::Translation(0)));
    key(&mut ed, Key::Escape, Mods::NONE);
    // The key panel: T, C and B show, the ease row is below them.
    click_marker(&mut ed, Row::Track(T), 20.0, Mods::NONE);
    assert!(ed.key_panel_shown());
    let (bias, ease) = (FieldId::Key(KeyField::Bias), FieldId::Key(KeyField::EaseIn));
    assert!(field_shown(&ed, bias) && !field_shown(&ed, ease));
    let at = find(&ed, "Field(Key(Bias))");
    click(&mut ed, at);
    ed.handle(Event::Text("0.5".into()));
    key(&mut ed, Key::Tab, Mods::NONE);
    let k20 = |ed: &Editor| {
        let t = ed.scene().animation.track(target(bx, T)).unwrap();
        t.key(2).unwrap()
    };
    assert_eq!(k20(&ed).bias, 0.5);
    assert_eq!(typing(&ed), Some((ease, "0".into())));
    assert!(field_shown(&ed, ease), "the ease row scrolled into view");
    ed.handle(Event::Text("0.25".into()));
    key(&mut ed, Key::Tab, Mods::shift());
    assert_eq!(k20(&ed).ease_in, 0.25);
    assert_eq!(typing(&ed), Some((bias, "0.5".into())));
    assert!(field_shown(&ed, bias));
    // Tab from the frame field (not the side panel's) only records.
    key(&mut ed, Key::Escape, Mods::NONE);
    let at = find(&ed, "Field(Frame)");
    click(&mut ed, at);
    ed.handle(Event::Text("12".into()));
    key(&mut ed, Key::Tab, Mods::NONE);
    assert_eq!((ed.current_frame(), typing(&ed)), (12.0, None));
}

/// Enter, or a click on another field, with nothing typed leaves the
/// value as it was: no undo step, and on an animated property nothing
/// left pending for K (it used to record the unchanged value).
#[test]
fn enter_or_clicking_away_with_nothing_typed_records_nothing() {
    use animed::internals::editor::fields::FieldId;
    let (mut ed, _) = zigzag();
    let steps = ed.history().labels().count();
    let untouched = |ed: &Editor| {
        ed.text_edit().is_none()
            && ed.history().labels().count() == steps
            && ed.pending().is_none()
            && !ed.status().text.contains("Pending")
    };
    let tx = find(&ed, "Field(Translation(0))");
    click(&mut ed, tx);
    assert_eq!(
        ed.text_edit().map(|e| e.field),
        Some(FieldId::Translation(0))
    );
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(untouched(&ed), "Enter with nothing typed records nothing");
    // A click on another field ends the first one the same way.
    click(&mut ed, tx);
    let ty = find(&ed, "Field(Translation(1))");
    click(&mut ed, ty);
    let typing = ed.text_edit().map(|e| e.field);
    assert_eq!(typing, Some(FieldId::Translation(1)));
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(
        untouched(&ed),
        "clicking away with nothing typed records nothing"
    );
    // Something typed still records (the track is animated: pending).
    click(&mut ed, tx);
    ed.handle(Event::Text("2".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.history().labels().count(), steps + 1);
    assert!(ed.pending().is_some() && ed.status().text.contains("Pending"));
}
