//! Rotate and scale handles, body drags and the onion skin, driven by
//! mouse and key events on the demo stage as a user would: each drag turns
//! or scales by what the mouse did, Ctrl snaps, Esc cancels, a drag is one
//! undo step, record mode keys the changed property.

#[path = "common/golden.rs"]
mod golden;

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::anim::{Property, Target, TargetRef, Value};
use animed::internals::editor::manip::{Handle, Tool, ARROW_PX};
use animed::internals::editor::{Editor, Event, Key, Mods};
use animed::internals::scene::{NodeId, NodeKind};
use glam::{Quat, Vec3};
use std::f32::consts::PI;
use std::path::Path;
use ui_input::*;

/// Drags along ring `h` from angle `t0` to `t1` through points on the ring
/// (the mouse follows the arc as a user's would).
fn ring_drag(ed: &mut Editor, h: Handle, t0: f32, t1: f32, mods: Mods) {
    let pts: Vec<(f32, f32)> = (0..=6)
        .map(|k| {
            let t = t0 + (t1 - t0) * k as f32 / 6.0;
            ed.ring_pixel(h, t).expect("ring point on screen")
        })
        .collect();
    drag_via(ed, &pts, mods);
}

/// An angle where ring `h` can be grabbed (the handle there is `h`) and
/// the ring point `span` further on is on screen too.
fn grabbable(ed: &mut Editor, h: Handle, span: f32) -> f32 {
    (0..63)
        .map(|k| k as f32 * 0.1)
        .find(|&t| {
            let p = ed.ring_pixel(h, t).unwrap();
            let q = ed.ring_pixel(h, t + span * 0.5).unwrap();
            ed.handle_at(p.0, p.1) == Some(h) && ed.handle_at(q.0, q.1) == Some(h)
        })
        .unwrap_or_else(|| panic!("no grabbable point on {h:?}"))
}

fn rotation(ed: &Editor, id: NodeId) -> Quat {
    ed.scene().node(id).transform.rotation
}

fn labels(ed: &Editor) -> Vec<String> {
    ed.history().labels().map(str::to_string).collect()
}

#[test]
fn keys_and_toolbar_pick_the_tool() {
    let mut ed = stage();
    assert_eq!(ed.tool(), Tool::Translate);
    key(&mut ed, Key::Char('e'), Mods::NONE);
    assert_eq!(ed.tool(), Tool::Rotate);
    key(&mut ed, Key::Char('t'), Mods::NONE);
    assert_eq!(ed.tool(), Tool::Scale);
    key(&mut ed, Key::Char('w'), Mods::NONE);
    assert_eq!(ed.tool(), Tool::Translate);
    // The toolbar button does the same.
    let b = ed
        .widgets()
        .into_iter()
        .find(|w| format!("{:?}", w.kind).contains("Tool(Rotate)"))
        .expect("a Rot button");
    let at = (
        b.rect.x as f32 + b.rect.w as f32 / 2.0,
        b.rect.y as f32 + b.rect.h as f32 / 2.0,
    );
    down(&mut ed, at, Mods::NONE);
    up(&mut ed, at, Mods::NONE);
    assert_eq!(ed.tool(), Tool::Rotate);
}

#[test]
fn ring_drag_turns_about_its_axis_by_the_arc_as_one_step() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    for (i, want_axis) in [(0u8, Vec3::X), (1, Vec3::Y), (2, Vec3::Z)] {
        let before = rotation(&ed, pyr);
        let h = Handle::Ring(i);
        let t0 = grabbable(&mut ed, h, 0.5);
        ring_drag(&mut ed, h, t0, t0 + 0.5, Mods::NONE);
        let after = rotation(&ed, pyr);
        let want = Quat::from_axis_angle(want_axis, 0.5) * before;
        assert!(
            after.angle_between(want) < 0.01,
            "ring {i}: {after} want {want} (off by {})",
            after.angle_between(want)
        );
    }
    assert_eq!(
        labels(&ed),
        vec!["Rotate Pyramid", "Rotate Pyramid", "Rotate Pyramid"]
    );
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(rotation(&ed, pyr), Quat::IDENTITY);
}

#[test]
fn ring_drag_on_a_parented_node_turns_it_about_the_world_axis() {
    use animed::internals::scene::{Node, Transform};
    use glam::Mat4;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let mut scene = animed::internals::format::load(&path)
        .expect("the stage loads")
        .scene;
    // A parent turned and scaled, a child with a raw matrix
    // (Inventor MatrixTransform) before its own transform.
    let parent = scene.add_node(
        None,
        Node::group("P").with_transform(Transform {
            translation: Vec3::new(1.0, 1.0, 0.0),
            rotation: Quat::from_rotation_x(0.7),
            scale: Vec3::splat(1.5),
            ..Transform::default()
        }),
    );
    let child = scene.add_node(
        Some(parent),
        Node::group("C").with_transform(Transform {
            translation: Vec3::new(0.5, 0.0, 0.3),
            rotation: Quat::from_rotation_y(0.3),
            extra: Some(Mat4::from_rotation_z(0.9)),
            ..Transform::default()
        }),
    );
    let mut ed = Editor::new(scene, None, 480, 320);
    ed.select(Some(child));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let world =
        |ed: &Editor| animed::internals::anim::evaluate(ed.scene(), 0.0).world[child.0 as usize];
    let w0 = world(&ed);
    let t0 = grabbable(&mut ed, Handle::Ring(1), 0.5);
    ring_drag(&mut ed, Handle::Ring(1), t0, t0 + 0.5, Mods::NONE);
    let w1 = world(&ed);
    // Turned about the world y axis through its own origin.
    let p = w0.w_axis.truncate();
    let want =
        Mat4::from_translation(p) * Mat4::from_rotation_y(0.5) * Mat4::from_translation(-p) * w0;
    assert!(w1.abs_diff_eq(want, 0.01), "{w1} want {want}");
}

#[test]
fn an_edge_on_ring_turns_by_the_mouse_motion_along_it() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    // Alt-drag orbits: yaw 0.6 → 0 and pitch 0.45 → 0 (0.01 rad per pixel):
    // the camera looks along −z and the y ring is seen edge-on.
    drag_via(&mut ed, &[(150.0, 150.0), (210.0, 105.0)], Mods::alt());
    let back = ed.camera().back();
    assert!((back - Vec3::Z).length() < 1e-4, "looking along -z: {back}");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let t0 = grabbable(&mut ed, Handle::Ring(1), 0.2);
    let a = ed.ring_pixel(Handle::Ring(1), t0).unwrap();
    // The front of the ring moves towards +x (screen right) as y turns; a
    // few pixels off the ring's line (where ray–plane hits run away) do
    // not matter.
    // The edge-on ring is a line on screen as long as its diameter (its
    // size depends on the pyramid's: handles shrink on small objects).
    let c = ed.handle_points().unwrap()[0];
    let e = ed.ring_pixel(Handle::Ring(1), PI / 2.0).unwrap();
    let radius = ((e.0 - c.0).powi(2) + (e.1 - c.1).powi(2)).sqrt();
    drag_via(&mut ed, &[a, (a.0 + 30.0, a.1 + 4.0)], Mods::NONE);
    let (axis, angle) = rotation(&ed, pyr).to_axis_angle();
    assert!((axis - Vec3::Y).length() < 1e-3, "about +y: {axis}");
    // 30 px along a ring of that radius: about 30 / radius radians.
    let want = 30.0 / radius;
    assert!(
        angle > want * 0.6 && angle < want * 1.4,
        "angle {angle}, ring radius {radius} px"
    );
}

#[test]
fn ctrl_snaps_the_angle_to_15_degrees() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let t0 = grabbable(&mut ed, Handle::Ring(1), 0.6);
    // 0.6 rad is 34.4°: snapped to 30°.
    ring_drag(&mut ed, Handle::Ring(1), t0, t0 + 0.6, Mods::ctrl());
    let q = rotation(&ed, pyr);
    let want = Quat::from_rotation_y(PI / 6.0);
    assert!(q.angle_between(want) < 1e-4, "{q} is not 30° about y");
    // The status line read the angle out during the drag.
    assert_eq!(ed.status().text, "Rotate Pyramid: 30 deg about y");
}

#[test]
fn view_ring_turns_about_the_view_direction() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let t0 = grabbable(&mut ed, Handle::ViewRing, 0.4);
    ring_drag(&mut ed, Handle::ViewRing, t0, t0 + 0.4, Mods::NONE);
    let back = ed.camera().back();
    let want = Quat::from_axis_angle(back, 0.4);
    let q = rotation(&ed, pyr);
    assert!(q.angle_between(want) < 0.01, "{q} want {want}");
}

/// A pixel inside the rotate rings that is neither a ring nor `id`'s body.
fn trackball_pixel(ed: &mut Editor, id: NodeId) -> (f32, f32) {
    let c = ed.handle_points().unwrap()[0];
    // The view ring is a circle on screen; the axis rings lie inside it.
    let v = ed.ring_pixel(Handle::ViewRing, 0.0).unwrap();
    let view_r = ((v.0 - c.0).powi(2) + (v.1 - c.1).powi(2)).sqrt();
    for f in [0.39, 0.47, 0.31, 0.55, 0.25] {
        let r = view_r * f;
        for k in 0..16 {
            let a = k as f32 / 16.0 * std::f32::consts::TAU;
            let p = (c.0 + a.cos() * r, c.1 + a.sin() * r);
            if ed.pick_at(p.0, p.1) != Some(id) && ed.handle_at(p.0, p.1).is_none() {
                return p;
            }
        }
    }
    panic!("no free pixel inside the rings")
}

#[test]
fn dragging_inside_the_rings_turns_freely_and_a_click_there_picks() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let a = trackball_pixel(&mut ed, pyr);
    let picked = ed.pick_at(a.0, a.1);
    // A click without motion picks what is there, as always.
    down(&mut ed, a, Mods::NONE);
    up(&mut ed, a, Mods::NONE);
    assert_eq!(ed.selection(), picked);
    assert!(labels(&ed).is_empty());
    // A drag turns the selection about an axis in the view plane (the
    // mouse moved sideways: the turn axis is about screen-vertical).
    ed.select(Some(pyr));
    drag_via(&mut ed, &[a, (a.0 + 25.0, a.1)], Mods::NONE);
    let q = rotation(&ed, pyr);
    assert!(q.angle_between(Quat::IDENTITY) > 0.2, "turned: {q}");
    let (axis, _) = q.to_axis_angle();
    let back = ed.camera().back();
    assert!(
        axis.dot(back).abs() < 0.5,
        "axis {axis} mostly in the view plane"
    );
    assert_eq!(ed.selection(), Some(pyr));
    assert_eq!(labels(&ed), vec!["Rotate Pyramid"]);
    // Ctrl: a multiple of 15°.
    drag_via(&mut ed, &[a, (a.0 - 10.0, a.1 + 25.0)], Mods::ctrl());
    let (_, turned) = (rotation(&ed, pyr) * q.inverse()).to_axis_angle();
    let steps = turned / (PI / 12.0);
    assert!(
        (steps - steps.round()).abs() < 1e-3 && steps.round() >= 1.0,
        "{turned}"
    );
}

#[test]
fn rotating_an_animated_object_without_record_is_pending() {
    let mut ed = stage();
    let spin = node(&ed, "Spinner");
    ed.select(Some(spin));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let stored = ed.scene().animation.clone();
    let shown0 = ed.posed_node(spin).transform.rotation;
    let t0 = grabbable(&mut ed, Handle::Ring(0), 0.4);
    ring_drag(&mut ed, Handle::Ring(0), t0, t0 + 0.4, Mods::NONE);
    let shown1 = ed.posed_node(spin).transform.rotation;
    assert!(shown1.angle_between(shown0) > 0.3, "shows the turn");
    assert!(ed.pending().is_some());
    assert_eq!(ed.scene().animation, stored, "no key without record");
    // Record on: the same drag keys the rotation at the current frame.
    key(&mut ed, Key::Char('r'), Mods::NONE);
    key(&mut ed, Key::Right, Mods::NONE);
    let t0 = grabbable(&mut ed, Handle::Ring(0), 0.4);
    ring_drag(&mut ed, Handle::Ring(0), t0, t0 + 0.4, Mods::NONE);
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(spin),
            property: Property::Rotation,
        })
        .expect("rotation track");
    let k = t
        .key(t.key_index_at(1.0).expect("a key at frame 1"))
        .unwrap();
    let Value::Rotation(q) = k.value else {
        panic!("rotation key")
    };
    assert!(q.angle_between(ed.posed_node(spin).transform.rotation) < 1e-5);
}

/// World distance along `dir` from `pivot` whose pixel lies three
/// quarters of the way from the pivot's pixel to scale box `box_i` (found
/// by bisection; handle sizes depend on the object's size on screen).
fn along_handle(ed: &mut Editor, pivot: Vec3, dir: Vec3, box_i: usize) -> f32 {
    let p = ed.scale_points().unwrap();
    let dist = |q: (f32, f32)| ((q.0 - p[0].0).powi(2) + (q.1 - p[0].1).powi(2)).sqrt();
    let want = dist(p[box_i]) * 0.75;
    let (mut lo, mut hi) = (0.0f32, 50.0f32);
    for _ in 0..60 {
        let mid = (lo + hi) * 0.5;
        if dist(ed.pixel_of(pivot + dir * mid).unwrap()) < want {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[test]
fn scale_axis_drag_doubles_at_twice_the_distance() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('t'), Mods::NONE);
    let pivot = ed.scene().node(pyr).transform.translation;
    let s = along_handle(&mut ed, pivot, Vec3::X, 1);
    let a = ed.pixel_of(pivot + Vec3::X * s).unwrap();
    let b = ed.pixel_of(pivot + Vec3::X * s * 2.0).unwrap();
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::ScaleAxis(0)));
    drag_via(&mut ed, &[a, b], Mods::NONE);
    let s = ed.scene().node(pyr).transform.scale;
    assert!((s.x - 2.0).abs() < 1e-3, "x scale {s}");
    assert_eq!((s.y, s.z), (1.0, 1.0));
    assert_eq!(ed.status().text, "Scale Pyramid: scale 2 1 1");
    assert_eq!(labels(&ed), vec!["Scale Pyramid"]);
    // Ctrl: steps of 0.1 (z: 1 × 2.26 = 2.26 → 2.3).
    let s = along_handle(&mut ed, pivot, Vec3::Z, 3);
    let a = ed.pixel_of(pivot + Vec3::Z * s).unwrap();
    let b = ed.pixel_of(pivot + Vec3::Z * s * 2.26).unwrap();
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::ScaleAxis(2)));
    drag_via(&mut ed, &[a, b], Mods::ctrl());
    let z = ed.scene().node(pyr).transform.scale.z;
    assert!((z - 2.3).abs() < 1e-5, "z {z}");
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ed.scene().node(pyr).transform.scale, Vec3::ONE);
}

#[test]
fn uniform_box_scales_all_three() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('t'), Mods::NONE);
    // The pyramid is small on screen: the box sits beside its pivot.
    let c = ed.handle_pixel("uniform").unwrap();
    assert_ne!(c, ed.scale_points().unwrap()[0]);
    assert_eq!(ed.handle_at(c.0, c.1), Some(Handle::Uniform));
    drag_via(&mut ed, &[c, (c.0 + ARROW_PX, c.1)], Mods::NONE);
    let s = ed.scene().node(pyr).transform.scale;
    assert!((s - Vec3::splat(2.0)).length() < 1e-4, "{s}");
    // Down by half an arrow: halves (the box may have moved with the
    // pyramid's size on screen).
    let c = ed.handle_pixel("uniform").unwrap();
    drag_via(&mut ed, &[c, (c.0, c.1 + ARROW_PX * 0.5)], Mods::NONE);
    let s = ed.scene().node(pyr).transform.scale;
    assert!((s - Vec3::splat(1.0)).length() < 1e-4, "{s}");
    assert_eq!(labels(&ed).len(), 2);
}

/// A pixel of `id`'s body that is not on a handle of the current tool.
fn body_pixel(ed: &mut Editor, id: NodeId) -> (f32, f32) {
    let c = ed
        .pixel_of(ed.scene().node(id).transform.translation)
        .unwrap();
    for r in 4..60 {
        for k in 0..32 {
            let a = k as f32 / 32.0 * std::f32::consts::TAU;
            let p = (c.0 + a.cos() * r as f32, c.1 + a.sin() * r as f32);
            if ed.pick_at(p.0, p.1) == Some(id) && ed.handle_at(p.0, p.1).is_none() {
                return p;
            }
        }
    }
    panic!("no free body pixel")
}

#[test]
fn body_drag_moves_in_the_view_plane_and_a_click_still_selects() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let t0 = ed.scene().node(pyr).transform.translation;
    let p0 = ed.handle_points().unwrap()[0];
    let a = body_pixel(&mut ed, pyr);
    // A click without motion on the selection: still just selects.
    down(&mut ed, a, Mods::NONE);
    up(&mut ed, a, Mods::NONE);
    assert_eq!(ed.selection(), Some(pyr));
    assert!(labels(&ed).is_empty());
    // A drag moves it with the mouse, at the same depth.
    key(&mut ed, Key::Space, Mods::NONE);
    assert!(ed.is_playing());
    drag_via(&mut ed, &[a, (a.0 + 30.0, a.1 - 20.0)], Mods::NONE);
    assert!(!ed.is_playing(), "a drag stops playback");
    let t1 = ed.scene().node(pyr).transform.translation;
    assert!((t1 - t0).length() > 0.2, "moved {t0} -> {t1}");
    let back = ed.camera().back();
    assert!((t1 - t0).dot(back).abs() < 1e-4, "depth kept");
    let p1 = ed.handle_points().unwrap()[0];
    assert!(
        (p1.0 - p0.0 - 30.0).abs() < 0.1 && (p1.1 - p0.1 + 20.0).abs() < 0.1,
        "pivot moved with the mouse: {p0:?} -> {p1:?}"
    );
    assert_eq!(ed.selection(), Some(pyr));
    assert_eq!(labels(&ed), vec!["Move Pyramid"]);
    // With the rotate tool the body still drags.
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let a = body_pixel(&mut ed, pyr);
    drag_via(&mut ed, &[a, (a.0 - 15.0, a.1)], Mods::NONE);
    assert_eq!(labels(&ed).len(), 2);
    // A click on another object selects it.
    let glass = node(&ed, "Glass");
    let g = ed
        .pixel_of(ed.scene().node(glass).transform.translation)
        .unwrap();
    down(&mut ed, g, Mods::NONE);
    up(&mut ed, g, Mods::NONE);
    assert_eq!(ed.selection(), Some(glass));
}

#[test]
fn body_drag_in_record_mode_keys_the_translation() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('r'), Mods::NONE);
    for _ in 0..10 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    let a = body_pixel(&mut ed, pyr);
    drag_via(&mut ed, &[a, (a.0 + 12.0, a.1 + 9.0)], Mods::NONE);
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(pyr),
            property: Property::Translation,
        })
        .expect("a translation track");
    assert_eq!(t.keys.frames(), vec![10.0]);
    let k = t.key(0).unwrap();
    assert_eq!(
        k.value,
        Value::Vec3(ed.scene().node(pyr).transform.translation)
    );
    assert_eq!(labels(&ed), vec!["Move Pyramid"]);
}

#[test]
fn ctrl_body_drag_snaps_the_pivot_to_the_grid() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let t0 = ed.scene().node(pyr).transform.translation;
    let a = body_pixel(&mut ed, pyr);
    drag_via(&mut ed, &[a, (a.0 + 23.0, a.1 - 17.0)], Mods::ctrl());
    let t1 = ed.scene().node(pyr).transform.translation;
    assert!((t1 - t0).length() > 0.1, "moved {t0} -> {t1}");
    // The stage's grid step (scene radius ~5) is 1: every coordinate of
    // the (top-level) pyramid lands on a whole number.
    for c in t1.to_array() {
        assert!((c - c.round()).abs() < 1e-4, "{t1} on the grid");
    }
    assert_eq!(labels(&ed), vec!["Move Pyramid"]);
}

#[test]
fn spot_rings_turn_its_direction_and_record_a_key() {
    let mut ed = stage();
    let spot = node(&ed, "SpotLamp");
    ed.select(Some(spot));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    key(&mut ed, Key::Char('r'), Mods::NONE);
    let dir0 = match &ed.scene().node(spot).kind {
        NodeKind::Light(l) => l.direction,
        _ => panic!("a light"),
    };
    let t0 = grabbable(&mut ed, Handle::Ring(1), 0.5);
    ring_drag(&mut ed, Handle::Ring(1), t0, t0 + 0.5, Mods::NONE);
    let dir1 = match &ed.scene().node(spot).kind {
        NodeKind::Light(l) => l.direction,
        _ => panic!("a light"),
    };
    let want = Quat::from_rotation_y(0.5) * dir0;
    assert!(
        (dir1 - want).length() < 0.01 * dir0.length(),
        "{dir1} want {want}"
    );
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(spot),
            property: Property::LightDirection,
        })
        .expect("a LightDirection track");
    assert_eq!(t.keys.frames(), vec![0.0]);
    assert_eq!(labels(&ed), vec!["Rotate SpotLamp"]);
    // A point light has nothing to turn; a light has nothing to scale.
    let lamp = node(&ed, "Lamp");
    ed.select(Some(lamp));
    assert!(ed.ring_pixel(Handle::Ring(0), 0.0).is_none());
    key(&mut ed, Key::Char('t'), Mods::NONE);
    ed.select(Some(spot));
    assert!(ed.scale_points().is_none());
}

/// Starts a drag from `a` to `b`, presses Esc mid-way, releases.
fn cancelled(ed: &mut Editor, a: (f32, f32), b: (f32, f32)) {
    down(ed, a, Mods::NONE);
    for i in 1..=4 {
        let t = i as f32 / 4.0;
        ed.handle(Event::MouseMove {
            x: a.0 + (b.0 - a.0) * t,
            y: a.1 + (b.1 - a.1) * t,
            mods: Mods::NONE,
        });
    }
    assert!(ed.handle_dragging(), "a drag runs");
    key(ed, Key::Escape, Mods::NONE);
    assert!(!ed.handle_dragging());
    up(ed, b, Mods::NONE);
}

#[test]
fn esc_cancels_every_kind_of_drag() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    let n0 = ed.scene().node(pyr).clone();
    // Rotate ring, view ring.
    key(&mut ed, Key::Char('e'), Mods::NONE);
    for h in [Handle::Ring(2), Handle::ViewRing] {
        let t0 = grabbable(&mut ed, h, 0.5);
        let a = ed.ring_pixel(h, t0).unwrap();
        let b = ed.ring_pixel(h, t0 + 0.5).unwrap();
        cancelled(&mut ed, a, b);
        assert_eq!(*ed.scene().node(pyr), n0, "{h:?}");
    }
    // Trackball.
    let a = trackball_pixel(&mut ed, pyr);
    cancelled(&mut ed, a, (a.0 + 20.0, a.1 + 10.0));
    assert_eq!(*ed.scene().node(pyr), n0);
    assert_eq!(ed.selection(), Some(pyr), "a cancelled drag does not pick");
    // Scale axis, uniform.
    key(&mut ed, Key::Char('t'), Mods::NONE);
    let p = ed.scale_points().unwrap();
    let a = (
        p[0].0 + (p[1].0 - p[0].0) * 0.7,
        p[0].1 + (p[1].1 - p[0].1) * 0.7,
    );
    assert_eq!(ed.handle_at(a.0, a.1), Some(Handle::ScaleAxis(0)));
    cancelled(&mut ed, a, (a.0 + 20.0, a.1 + 5.0));
    assert_eq!(*ed.scene().node(pyr), n0);
    cancelled(&mut ed, p[0], (p[0].0 + 30.0, p[0].1));
    assert_eq!(*ed.scene().node(pyr), n0);
    // Body.
    key(&mut ed, Key::Char('w'), Mods::NONE);
    let a = body_pixel(&mut ed, pyr);
    cancelled(&mut ed, a, (a.0 + 25.0, a.1));
    assert_eq!(*ed.scene().node(pyr), n0);
    assert_eq!(ed.selection(), Some(pyr));
    assert!(
        labels(&ed).is_empty(),
        "nothing recorded: {:?}",
        labels(&ed)
    );
}

/// Frame 36 (between the ball's keys at 24 and 48), four wheel notches
/// closer so the copies are large enough to see.
fn zoom_to_frame_36(ed: &mut Editor) {
    for _ in 0..36 {
        key(ed, Key::Right, Mods::NONE);
    }
    for _ in 0..4 {
        ed.handle(Event::Wheel {
            delta: 1.0,
            x: 150.0,
            y: 150.0,
            mods: Mods::NONE,
        });
    }
}

#[test]
fn onion_skin_shows_copies_at_the_neighbouring_keys() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    zoom_to_frame_36(&mut ed);
    let off = ed.render_frame();
    key(&mut ed, Key::Char('o'), Mods::NONE);
    assert!(ed.onion_shown());
    assert_eq!(ed.onion_frames(), (Some(24.0), Some(48.0)));
    let on = ed.render_frame();
    // The copies sit where the ball is at frames 24 and 48: pixels change
    // around those points and not in the far corner of the viewport.
    let changed = |p: (f32, f32)| {
        let mut n = 0;
        for dy in -6..=6 {
            for dx in -6..=6 {
                let i = (p.1 as i32 + dy) as usize * 480 + (p.0 as i32 + dx) as usize;
                n += (on.color[i] != off.color[i]) as u32;
            }
        }
        n
    };
    let fps = ed.scene().settings.fps;
    for f in [24.0, 48.0] {
        let pose = animed::internals::anim::evaluate(ed.scene(), f / fps);
        let w = pose.world[ball.0 as usize].w_axis.truncate();
        let p = ed.pixel_of(w).unwrap();
        assert!(
            changed(p) > 80,
            "a copy at frame {f} ({p:?}): {}",
            changed(p)
        );
    }
    // Only the viewport's pixels (the copies) change, beside the label,
    // the toolbar button and the status line.
    let vp = ed.layout().viewport;
    let in_vp = |i: usize| {
        let (x, y) = ((i % 480) as f32, (i / 480) as f32);
        vp.contains(x, y) && y > vp.y as f32 + 20.0
    };
    let differ = |a: &[u32], b: &[u32]| (0..a.len()).filter(|&i| in_vp(i) && a[i] != b[i]).count();
    let total = differ(&on.color, &off.color);
    assert!(
        total < 480 * 320 / 10,
        "only the copies change ({total} px)"
    );
    key(&mut ed, Key::Char('o'), Mods::NONE);
    let again = ed.render_frame();
    assert_eq!(differ(&again.color, &off.color), 0, "off again");
}

#[test]
fn rotate_handles_golden_with_a_hovered_ring() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    ed.select(Some(pyr));
    key(&mut ed, Key::Char('e'), Mods::NONE);
    let t = grabbable(&mut ed, Handle::Ring(0), 0.0);
    let p = ed.ring_pixel(Handle::Ring(0), t).unwrap();
    ed.handle(Event::MouseMove {
        x: p.0,
        y: p.1,
        mods: Mods::NONE,
    });
    golden::check("editor_rotate_handles", &ed.render_frame());
}

#[test]
fn scale_handles_golden() {
    let mut ed = stage();
    let spin = node(&ed, "Spinner");
    ed.select(Some(spin));
    key(&mut ed, Key::Char('t'), Mods::NONE);
    // At frame 12 the spinner is turned 45° about y: the boxes follow its axes.
    for _ in 0..12 {
        key(&mut ed, Key::Right, Mods::NONE);
    }
    let c = ed.scale_points().unwrap()[0];
    ed.handle(Event::MouseMove {
        x: c.0,
        y: c.1,
        mods: Mods::NONE,
    });
    golden::check("editor_scale_handles", &ed.render_frame());
}

#[test]
fn onion_skin_golden() {
    let mut ed = stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    zoom_to_frame_36(&mut ed);
    key(&mut ed, Key::Char('o'), Mods::NONE);
    golden::check("editor_onion_skin", &ed.render_frame());
}

#[test]
fn scripts_drag_handles_by_name() {
    let mut ed = stage();
    let pyr = node(&ed, "Pyramid");
    let script = "select Pyramid\nkey e\ndrag-handle y 30 0\nkey t\ndrag-handle uniform 70 0\nkey w\ndrag-handle body 10 5\n";
    animed::internals::editor::script::run(&mut ed, script, Path::new("s.txt"))
        .expect("the script runs");
    let n = ed.scene().node(pyr);
    let (axis, angle) = n.transform.rotation.to_axis_angle();
    assert!(
        angle > 0.1 && axis.y.abs() > 0.999,
        "turned about y: {axis} {angle}"
    );
    assert!((n.transform.scale - Vec3::splat(2.0)).length() < 1e-4);
    assert_ne!(n.transform.translation, Vec3::new(1.1, 0.0, 2.1));
    assert_eq!(
        labels(&ed),
        vec!["Rotate Pyramid", "Scale Pyramid", "Move Pyramid"]
    );
    // A handle the tool does not have stops the session at its line.
    let e = animed::internals::editor::script::run(
        &mut ed,
        "key e\n\ndrag-handle uniform 5 5\n",
        Path::new("s.txt"),
    )
    .unwrap_err();
    assert_eq!((e.line, e.column), (3, 1));
    assert!(
        e.to_string()
            .contains("no handle 'uniform' of the Rotate tool"),
        "{e}"
    );
}
