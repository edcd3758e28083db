//! Editing deforming meshes and clips (issue 13 items 3 and 7), driven by
//! events as a user would: joints picked by their bones, the two-bone IK
//! handle baked to keys as one undo step (rotations checked against the
//! law-of-cosines solution worked out by hand), morph sliders keyed, and
//! the clip list.

#[path = "common/golden.rs"]
mod golden;

#[path = "common/skinned_tube.rs"]
mod skinned_tube;
#[path = "common/ui_input.rs"]
mod ui_input;

use animed::internals::anim::{Property, Target, TargetRef, Value};
use animed::internals::editor::{Editor, Key, Mods};
use animed::internals::scene::{Material, Node, NodeId, NodeKind, Scene, Shape, Skin, Transform};
use glam::{Mat4, Quat, Vec3};
use std::path::Path;
use ui_input::*;

/// The editor's window in these tests: room for the lists and the morph
/// rows (goldens are 320×240 crops of it).
const W: u32 = 640;
const H: u32 = 400;

/// The `w`×`h` part of `f` whose top-left is (x, y).
fn crop(
    f: &animed::internals::render::Frame,
    x: u32,
    y: u32,
    w: u32,
    h: u32,
) -> animed::internals::render::Frame {
    let mut out = animed::internals::render::Frame::new(w, h, Vec3::ZERO);
    for row in 0..h {
        let src = ((y + row) * f.width + x) as usize;
        out.color[(row * w) as usize..((row + 1) * w) as usize]
            .copy_from_slice(&f.color[src..src + w as usize]);
    }
    out
}

/// An arm: a tube from y = 0 to 2 skinned to Upper (at the origin) and
/// Lower (at y = 1, child of Upper); Hand at y = 2 (child of Lower). All
/// under a group "Arm"; the joints are unkeyed.
fn arm() -> (Scene, [NodeId; 4]) {
    let mut s = Scene::new();
    s.settings.fps = 24.0;
    s.settings.duration = 48.0;
    let m = skinned_tube::tube((9, 8), 0.15, (0.0, 2.0), |y| {
        (y - 0.75).clamp(0.0, 0.5) * 2.0
    });
    let root = s.add_node(None, Node::group("Arm"));
    let upper = s.add_node(Some(root), Node::group("Upper"));
    let lower = s.add_node(
        Some(upper),
        Node::group("Lower").with_transform(Transform::from_translation(Vec3::Y)),
    );
    let hand = s.add_node(
        Some(lower),
        Node::group("Hand").with_transform(Transform::from_translation(Vec3::Y)),
    );
    let mesh = s.add_mesh(m);
    let material = s.add_material(Material {
        diffuse: Vec3::new(0.85, 0.6, 0.3),
        ..Material::default()
    });
    let tube = s.add_node(
        Some(root),
        Node::new("Tube", NodeKind::Shape(Shape { mesh, material })),
    );
    let ibm = vec![
        Mat4::IDENTITY,
        Mat4::from_translation(-Vec3::Y),
        Mat4::from_translation(-2.0 * Vec3::Y),
    ];
    let skin = Skin::new("ArmSkin", vec![upper, lower, hand], ibm).unwrap();
    let k = s.add_skin(skin).unwrap();
    s.nodes[tube.0 as usize].skin = Some(k);
    (s, [tube, upper, lower, hand])
}

fn rotation_of(ed: &Editor, id: NodeId) -> Quat {
    ed.scene().node(id).transform.rotation
}

fn rotation_keys(ed: &Editor, id: NodeId) -> Vec<(f32, Quat)> {
    let t = Target {
        of: TargetRef::Node(id),
        property: Property::Rotation,
    };
    let Some(track) = ed.scene().animation.track(t) else {
        return Vec::new();
    };
    (0..track.key_count())
        .map(|i| {
            let k = track.key(i).unwrap();
            match k.value {
                Value::Rotation(q) => (k.frame, q),
                v => panic!("{v:?}"),
            }
        })
        .collect()
}

fn near(a: Quat, b: Quat) -> bool {
    a.angle_between(b) < 2e-3
}

#[test]
fn joints_are_listed_under_their_skeleton_and_picked_by_their_bones() {
    let (s, [tube, upper, lower, hand]) = arm();
    // Tall enough for the objects list to show the whole arm (it scrolls
    // in a smaller window).
    let mut ed = Editor::new(s, None, W, 600);
    // The object list: joints as a tree (each one deeper than its parent).
    let depth = |ed: &Editor, id: NodeId| {
        ed.widgets()
            .into_iter()
            .find_map(|w| match w.kind {
                animed::internals::editor::panel::WidgetKind::Row { node, depth, .. }
                    if node == id =>
                {
                    Some(depth)
                }
                _ => None,
            })
            .unwrap_or_else(|| panic!("no row for {id:?}"))
    };
    assert!(depth(&ed, upper) < depth(&ed, lower) && depth(&ed, lower) < depth(&ed, hand));
    // Nothing selected: no bones, a click at the elbow picks the mesh.
    assert_eq!(ed.joint_on_screen(lower), None, "bones hidden");
    ed.select(Some(tube));
    let elbow = ed
        .joint_on_screen(lower)
        .expect("bones show with the mesh selected");
    ed.select(None);
    click(&mut ed, elbow);
    assert_eq!(ed.selection(), Some(tube), "the mesh is picked first");
    // Now the skeleton shows: the elbow's ball picks Lower…
    click(&mut ed, elbow);
    assert_eq!(ed.selection(), Some(lower));
    // …and a point on the upper bone (between shoulder and elbow) Upper.
    let shoulder = ed.joint_on_screen(upper).unwrap();
    let mid = ((shoulder.0 + elbow.0) / 2.0, (shoulder.1 + elbow.1) / 2.0);
    click(&mut ed, mid);
    assert_eq!(ed.selection(), Some(upper));
}

/// Selects Hand, turns IK on, and drags its target from the hand to the
/// world point (1, 1, 0) in the front view.
fn ik_drag_to_side(ed: &mut Editor, hand: NodeId) {
    key(ed, Key::Num(1), Mods::NONE);
    ed.select(Some(hand));
    key(ed, Key::Char('i'), Mods::NONE);
    assert!(ed.status().text.contains("IK"), "{}", ed.status().text);
    let from = ed.joint_on_screen(hand).expect("hand on screen");
    let to = ed.world_on_screen(Vec3::new(1.0, 1.0, 0.0)).unwrap();
    drag(ed, from, to, Mods::NONE);
}

/// The hand-worked solution (as in `anim::ik`'s unit test): a = b = 1,
/// target (1, 1, 0), d = √2, cos α = (a² + d² − b²)/(2ad) = 1/√2, α = 45°;
/// with the chain straight the bend follows the view's up (+y), so the
/// elbow stays at (0, 1, 0): Upper does not turn, Lower turns −90° about z.
fn want() -> (Quat, Quat) {
    (
        Quat::IDENTITY,
        Quat::from_rotation_z(-std::f32::consts::FRAC_PI_2),
    )
}

#[test]
fn ik_in_record_mode_bakes_both_joints_to_keys_as_one_undo_step() {
    let (s, [_, upper, lower, hand]) = arm();
    let mut ed = Editor::new(s, None, W, H);
    key(&mut ed, Key::Char('r'), Mods::NONE);
    assert!(ed.is_recording());
    let steps = ed.history().labels().count();
    ik_drag_to_side(&mut ed, hand);
    let (wu, wl) = want();
    assert!(
        near(rotation_of(&ed, upper), wu),
        "{:?}",
        rotation_of(&ed, upper)
    );
    assert!(
        near(rotation_of(&ed, lower), wl),
        "{:?}",
        rotation_of(&ed, lower)
    );
    let ku = rotation_keys(&ed, upper);
    let kl = rotation_keys(&ed, lower);
    assert_eq!((ku.len(), kl.len()), (1, 1), "one key each");
    assert_eq!((ku[0].0, kl[0].0), (0.0, 0.0), "at the current frame");
    assert!(near(ku[0].1, wu) && near(kl[0].1, wl));
    assert_eq!(ed.history().labels().count(), steps + 1, "one undo step");
    // The hand reached the target (the pose's world matrix).
    let pose = ed.pose().clone();
    let h = pose.world[hand.0 as usize].transform_point3(Vec3::ZERO);
    assert!((h - Vec3::new(1.0, 1.0, 0.0)).length() < 1e-2, "{h}");
    ed.undo();
    assert!(rotation_keys(&ed, upper).is_empty() && rotation_keys(&ed, lower).is_empty());
    assert!(near(rotation_of(&ed, lower), Quat::IDENTITY));
}

#[test]
fn ik_without_record_sets_unanimated_joints_and_pends_on_animated_ones() {
    let (s, [_, upper, lower, hand]) = arm();
    let mut ed = Editor::new(s, None, W, H);
    let steps = ed.history().labels().count();
    ik_drag_to_side(&mut ed, hand);
    let (wu, wl) = want();
    assert!(near(rotation_of(&ed, upper), wu) && near(rotation_of(&ed, lower), wl));
    assert!(
        rotation_keys(&ed, lower).is_empty(),
        "no keys without record"
    );
    assert_eq!(ed.history().labels().count(), steps + 1);
    ed.undo();
    assert!(near(rotation_of(&ed, lower), Quat::IDENTITY));
    // Animated joints: key both at frame 0 (select each, K), go to frame
    // 5, drag: the pose pends; K keys both at frame 5 in one step.
    for j in [upper, lower] {
        ed.select(Some(j));
        key(&mut ed, Key::Char('k'), Mods::NONE);
    }
    for _ in 0..5 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    key(&mut ed, Key::Char('i'), Mods::NONE); // IK was on: off, then on again
    ik_drag_to_side(&mut ed, hand);
    assert!(ed.ik_pending().is_some(), "{}", ed.status().text);
    assert_eq!(rotation_keys(&ed, lower).len(), 1, "not keyed yet");
    let steps = ed.history().labels().count();
    key(&mut ed, Key::Char('k'), Mods::NONE);
    assert_eq!(ed.history().labels().count(), steps + 1);
    let kl = rotation_keys(&ed, lower);
    assert_eq!(kl.len(), 2);
    assert_eq!(kl[1].0, 5.0);
    assert!(near(kl[1].1, wl), "{:?}", kl[1].1);
    assert!(near(rotation_keys(&ed, upper)[1].1, wu));
}

fn monkey() -> Editor {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/gltf/corpus/monkey_morph.glb");
    let loaded = animed::internals::format::load(&path).expect("monkey loads");
    Editor::new(loaded.scene, None, W, H)
}

fn run(ed: &mut Editor, script: &str) {
    animed::internals::editor::script::run(ed, script, Path::new("test.script"))
        .unwrap_or_else(|e| panic!("{e}"));
}

fn weights_at(ed: &Editor, node: NodeId, frame: f32) -> Vec<f32> {
    let t = Target {
        of: TargetRef::Node(node),
        property: Property::MorphWeights,
    };
    match ed
        .scene()
        .animation
        .track(t)
        .expect("weights track")
        .sample(frame)
    {
        Value::Weights(w) => w.as_slice().to_vec(),
        v => panic!("{v:?}"),
    }
}

#[test]
fn morph_sliders_key_the_weights_in_record_mode_and_pend_without() {
    let mut ed = monkey();
    let suzanne = ed.scene().find_node("Suzanne").unwrap();
    let before = weights_at(&ed, suzanne, 10.0);
    run(
        &mut ed,
        "select Suzanne\nclick-field Frame\ntype 10\nkey enter\nkey r\n",
    );
    let steps = ed.history().labels().count();
    run(&mut ed, "click-field Morph(1)\ntype 1.5\nkey enter\n");
    assert_eq!(
        ed.history().labels().count(),
        steps + 1,
        "{}",
        ed.status().text
    );
    let after = weights_at(&ed, suzanne, 10.0);
    assert_eq!(after, [before[0], 1.5], "ears keyed at 1.5, the nose kept");
    ed.undo();
    assert_eq!(weights_at(&ed, suzanne, 10.0), before);
    // Record off: the change shows but is not keyed until K.
    run(
        &mut ed,
        "key r\nclick-field Morph(0)\ntype 0.75\nkey enter\n",
    );
    assert!(ed.morph_pending().is_some(), "{}", ed.status().text);
    assert_eq!(ed.shown_weights().unwrap().2.as_slice(), [0.75, before[1]]);
    assert_eq!(weights_at(&ed, suzanne, 10.0), before, "not keyed yet");
    key(&mut ed, Key::Char('k'), Mods::NONE);
    assert_eq!(weights_at(&ed, suzanne, 10.0), [0.75, before[1]]);
    assert!(ed.morph_pending().is_none());
}

#[test]
fn clips_switch_add_rename_and_undo() {
    let mut ed = monkey();
    let names = |ed: &Editor| {
        ed.scene()
            .clips
            .names()
            .map(String::from)
            .collect::<Vec<_>>()
    };
    assert_eq!(names(&ed), ["ears_and_nose", "ears_enlarge", "nose_longer"]);
    // C: the menu; Down + Enter plays the second clip, one undo step.
    key(&mut ed, Key::Char('c'), Mods::NONE);
    key(&mut ed, Key::Down, Mods::NONE);
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.clip_name(), "ears_enlarge");
    let len = ed.scene().settings.duration;
    ed.undo();
    assert_eq!(ed.clip_name(), "ears_and_nose");
    // The header's `>` button steps too.
    let next = find(&ed, "Step(1)");
    click(&mut ed, next);
    assert_eq!(ed.clip_name(), "ears_enlarge");
    assert_eq!(ed.scene().settings.duration, len);
    // New (letter n in the menu): an empty clip of the same length, playing.
    key(&mut ed, Key::Char('c'), Mods::NONE);
    key(&mut ed, Key::Char('n'), Mods::NONE);
    assert_eq!(ed.clip_name(), "Clip4");
    assert!(ed.scene().animation.tracks.is_empty());
    // Rename through the header field.
    run(&mut ed, "click-field ClipName\ntype Blink\nkey enter\n");
    assert_eq!(ed.clip_name(), "Blink");
    run(
        &mut ed,
        "click-field ClipName\ntype nose_longer\nkey enter\n",
    );
    assert!(ed.status().error && ed.status().text.contains("already"));
    assert_eq!(names(&ed).len(), 4);
    ed.undo();
    ed.undo();
    assert_eq!(names(&ed).len(), 3);
    assert_eq!(ed.clip_name(), "ears_enlarge");
}

#[test]
fn editor_with_bones_and_the_morph_panel_matches_goldens() {
    let (s, [_, _, lower, _]) = arm();
    let mut ed = Editor::new(s, None, W, H);
    key(&mut ed, Key::Num(1), Mods::NONE);
    ed.select(Some(lower));
    let frame = ed.render_frame();
    frame_png(&frame, "bones_full");
    golden::check("editor_rig_bones", &crop(&frame, 60, 40, 320, 240));
    let mut ed = monkey();
    run(
        &mut ed,
        "select Suzanne\nclick-field Frame\ntype 40\nkey enter\n",
    );
    let frame = ed.render_frame();
    frame_png(&frame, "morph_full");
    golden::check("editor_rig_morph_panel", &crop(&frame, 320, 80, 320, 240));
}

/// Writes the whole window to target/ for a look (not compared).
fn frame_png(f: &animed::internals::render::Frame, name: &str) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/golden-diff");
    let _ = std::fs::create_dir_all(&dir);
    let _ = f.save_png(&dir.join(format!("editor_rig_{name}.png")));
}

#[test]
fn the_rotate_handle_keys_a_joint_in_record_mode() {
    use animed::internals::editor::manip::Handle;
    let (s, [_, _, lower, _]) = arm();
    let mut ed = Editor::new(s, None, W, H);
    key(&mut ed, Key::Num(1), Mods::NONE);
    ed.select(Some(lower));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    key(&mut ed, Key::Char('r'), Mods::NONE);
    // The ring about z (facing the eye in the front view) from a grabbable
    // point half a radian on, through points on the ring as a mouse goes.
    let h = Handle::Ring(2);
    let t0 = (0..63)
        .map(|k| k as f32 * 0.1)
        .find(|&t| {
            let p = ed.ring_pixel(h, t).unwrap();
            ed.handle_at(p.0, p.1) == Some(h)
        })
        .expect("a grabbable point on the view ring");
    let pts: Vec<(f32, f32)> = (0..=6)
        .map(|k| ed.ring_pixel(h, t0 + 0.5 * k as f32 / 6.0).unwrap())
        .collect();
    let steps = ed.history().labels().count();
    drag_via(&mut ed, &pts, Mods::NONE);
    assert_eq!(
        ed.history().labels().count(),
        steps + 1,
        "{}",
        ed.status().text
    );
    let turned = rotation_of(&ed, lower);
    assert!(turned.angle_between(Quat::IDENTITY) > 0.2, "{turned:?}");
    let keys = rotation_keys(&ed, lower);
    assert_eq!(keys.len(), 1, "keyed in record mode");
    assert!(near(keys[0].1, turned));
}
