//! Record mode, K, key jumps and undo driven through editor events, with
//! the resulting keys checked in `scene.animation` and a golden of the
//! recording editor.

#[path = "common/golden.rs"]
mod golden;

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::anim::{Property, Target, TargetRef, Value};
use animed::internals::editor::{Editor, Key, Mods};
use animed::internals::scene::{Light, LightKind, Node, NodeId, NodeKind, Scene, Transform};
use glam::Vec3;
use std::path::{Path, PathBuf};
use ui_input::*;

/// A group "Box" at (1, 0, 0) and a point light "Lamp".
fn scene() -> Scene {
    let mut s = Scene::new();
    s.add_node(
        None,
        Node::group("Box").with_transform(Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))),
    );
    let mut l = Light::new(LightKind::Point);
    l.location = Vec3::new(0.0, 3.0, 0.0);
    s.add_node(None, Node::new("Lamp", NodeKind::Light(l)));
    s
}

fn target(id: NodeId, p: Property) -> Target {
    Target {
        of: TargetRef::Node(id),
        property: p,
    }
}

/// (frame, value) of every key on a track.
fn keys(ed: &Editor, id: NodeId, p: Property) -> Vec<(f32, Value)> {
    match ed.scene().animation.track(target(id, p)) {
        None => Vec::new(),
        Some(t) => (0..t.key_count())
            .map(|i| {
                let k = t.key(i).expect("index in range");
                (k.frame, k.value)
            })
            .collect(),
    }
}

fn goto(ed: &mut Editor, frame: u32) {
    while ed.current_frame() > 0.0 {
        key(ed, Key::Left, Mods::NONE);
    }
    for _ in 0..frame {
        key(ed, Key::Right, Mods::NONE);
    }
    assert_eq!(ed.current_frame(), frame as f32);
}

#[test]
fn record_mode_turns_typed_values_into_keys_and_undo_takes_both_back() {
    let mut ed = Editor::new(scene(), None, 480, 320);
    let bx = NodeId(0);
    ed.select(Some(bx));
    key(&mut ed, Key::Char('r'), Mods::NONE);
    assert!(ed.is_recording());

    type_into(&mut ed, "Field(Translation(0))", "2");
    goto(&mut ed, 10);
    type_into(&mut ed, "Field(Translation(0))", "6");
    goto(&mut ed, 20);
    type_into(&mut ed, "Field(Translation(1))", "3");
    let k = keys(&ed, bx, Property::Translation);
    assert_eq!(
        k,
        vec![
            (0.0, Value::Vec3(Vec3::new(2.0, 0.0, 0.0))),
            (10.0, Value::Vec3(Vec3::new(6.0, 0.0, 0.0))),
            // At frame 20 the field started from the shown (animated) x = 6.
            (20.0, Value::Vec3(Vec3::new(6.0, 3.0, 0.0))),
        ]
    );
    // Only the edited property was keyed.
    assert!(keys(&ed, bx, Property::Scale).is_empty());
    // Typing again at frame 10 replaces that key.
    goto(&mut ed, 10);
    type_into(&mut ed, "Field(Translation(2))", "-1");
    let k = keys(&ed, bx, Property::Translation);
    assert_eq!(k.len(), 3);
    assert_eq!(k[1], (10.0, Value::Vec3(Vec3::new(6.0, 0.0, -1.0))));
    // The panel shows the animated value between keys (frame 5 of a
    // straight two-key stretch from x=2 to x=6 is not 2).
    goto(&mut ed, 5);
    let shown = ed.posed_node(bx).transform.translation.x;
    assert!(shown > 2.5 && shown < 6.0, "x at frame 5 is {shown}");

    // Each recorded edit is one undo step: value and key together.
    let steps = ed.history().labels().count();
    assert_eq!(steps, 4);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(
        keys(&ed, bx, Property::Translation)[1],
        (10.0, Value::Vec3(Vec3::new(6.0, 0.0, 0.0)))
    );
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(keys(&ed, bx, Property::Translation).len(), 2);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(ed.scene().animation.tracks.is_empty());
    assert_eq!(ed.scene().node(bx).transform.translation.x, 1.0);
    assert!(!ed.is_dirty());
    let ctrl_shift = Mods {
        ctrl: true,
        shift: true,
        alt: false,
    };
    key(&mut ed, Key::Char('z'), ctrl_shift);
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(keys(&ed, bx, Property::Translation).len(), 2);
}

#[test]
fn without_record_edits_change_values_but_make_no_keys() {
    let mut ed = Editor::new(scene(), None, 480, 320);
    ed.select(Some(NodeId(0)));
    type_into(&mut ed, "Field(Translation(0))", "4");
    assert_eq!(ed.scene().node(NodeId(0)).transform.translation.x, 4.0);
    assert!(ed.scene().animation.tracks.is_empty());
}

#[test]
fn k_keys_the_transform_and_arrows_jump_between_keys() {
    let mut ed = Editor::new(scene(), None, 480, 320);
    let bx = NodeId(0);
    ed.select(Some(bx));
    goto(&mut ed, 4);
    key(&mut ed, Key::Char('k'), Mods::NONE);
    goto(&mut ed, 12);
    type_into(&mut ed, "Field(Scale(0))", "2");
    key(&mut ed, Key::Char('k'), Mods::NONE);
    // The scale was animated (keyed at 4), so typing it made a pending
    // change and K keys only what changed.
    for p in [Property::Translation, Property::Rotation] {
        let k = keys(&ed, bx, p);
        assert_eq!(k.len(), 1, "{p:?} untouched at 12");
    }
    let k = keys(&ed, bx, Property::Scale);
    assert_eq!((k.len(), k[0].0, k[1].0), (2, 4.0, 12.0));
    // With nothing pending K keys the whole transform.
    key(&mut ed, Key::Char('k'), Mods::NONE);
    for p in [Property::Translation, Property::Rotation, Property::Scale] {
        let k = keys(&ed, bx, p);
        assert_eq!(k.len(), 2, "{p:?}");
        assert_eq!((k[0].0, k[1].0), (4.0, 12.0));
    }
    assert_eq!(
        keys(&ed, bx, Property::Scale)[1].1,
        Value::Vec3(Vec3::new(2.0, 1.0, 1.0))
    );
    // A change on an animated property without K is shown until the frame
    // changes, then dropped (Blender's pending change).
    goto(&mut ed, 8);
    type_into(&mut ed, "Field(Scale(1))", "3");
    assert_eq!(ed.posed_node(bx).transform.scale.y, 3.0);
    assert!(ed.pending().is_some());
    key(&mut ed, Key::Right, Mods::NONE);
    assert!(ed.pending().is_none());
    assert!((ed.posed_node(bx).transform.scale.y - 1.0).abs() < 1e-5);
    assert_eq!(keys(&ed, bx, Property::Scale).len(), 2);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    // The second K (whole transform) is one undo step; the first one's
    // scale key stays.
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(keys(&ed, bx, Property::Translation).len(), 1);
    assert_eq!(keys(&ed, bx, Property::Rotation).len(), 1);
    assert_eq!(keys(&ed, bx, Property::Scale).len(), 2);
    key(&mut ed, Key::Char('y'), Mods::ctrl());
    assert_eq!(keys(&ed, bx, Property::Translation).len(), 2);
    goto(&mut ed, 0);
    key(&mut ed, Key::Up, Mods::NONE);
    assert_eq!(ed.current_frame(), 4.0);
    key(&mut ed, Key::Up, Mods::NONE);
    assert_eq!(ed.current_frame(), 12.0);
    key(&mut ed, Key::Up, Mods::NONE);
    assert_eq!(ed.current_frame(), 12.0, "no key after the last");
    key(&mut ed, Key::Down, Mods::NONE);
    assert_eq!(ed.current_frame(), 4.0);
}

#[test]
fn light_fields_and_switch_record_light_keys() {
    let mut ed = Editor::new(scene(), None, 480, 320);
    let lamp = NodeId(1);
    ed.select(Some(lamp));
    key(&mut ed, Key::Char('r'), Mods::NONE);
    type_into(&mut ed, "Field(LightIntensity)", "0.25");
    type_into(&mut ed, "Field(LightLocation(1))", "5");
    goto(&mut ed, 8);
    key(&mut ed, Key::Char('l'), Mods::NONE);
    assert_eq!(
        keys(&ed, lamp, Property::LightIntensity),
        vec![(0.0, Value::Scalar(0.25))]
    );
    assert_eq!(
        keys(&ed, lamp, Property::LightLocation),
        vec![(0.0, Value::Vec3(Vec3::new(0.0, 5.0, 0.0)))]
    );
    assert_eq!(
        keys(&ed, lamp, Property::LightOn),
        vec![(8.0, Value::Bool(false))]
    );
    // K on a light keys its light fields, not a transform.
    key(&mut ed, Key::Char('k'), Mods::NONE);
    assert!(keys(&ed, lamp, Property::Translation).is_empty());
    assert_eq!(keys(&ed, lamp, Property::LightColor).len(), 1);
}

#[test]
fn recording_editor_golden() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    let mut ed = Editor::new(loaded.scene, Some(PathBuf::from("stage.wrl")), 480, 320);
    let ball = ed
        .scene()
        .find_node("Pyramid")
        .expect("Pyramid in the stage");
    ed.select(Some(ball));
    key(&mut ed, Key::Char('r'), Mods::NONE);
    type_into(&mut ed, "Field(Translation(1))", "1.5");
    goto(&mut ed, 30);
    type_into(&mut ed, "Field(Translation(1))", "0.5");
    assert_eq!(keys(&ed, ball, Property::Translation).len(), 2);
    let frame = ed.render_frame();
    golden::check("editor_record", &frame);
}
