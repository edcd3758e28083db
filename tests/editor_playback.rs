//! Playback stops on any edit (issue 7 item 6): typed values, K, handle
//! and field drags, delete and undo all stop it; looking around does not.

#[path = "common/ui_input.rs"]
mod ui_input;
use animed::internals::editor::panel::WidgetKind;
use animed::internals::editor::{Editor, Event, Key, Mods, MouseButton};
use animed::internals::scene::NodeId;
use std::path::{Path, PathBuf};
use ui_input::*;

fn stage() -> (Editor, NodeId) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    let mut ed = Editor::new(loaded.scene, Some(PathBuf::from("stage.wrl")), 480, 320);
    let pyr = ed.scene().find_node("Pyramid").expect("node in the stage");
    ed.select(Some(pyr));
    (ed, pyr)
}

/// Starts playback and lets it run a few ticks.
fn play(ed: &mut Editor, t: &mut f64) {
    assert!(!ed.is_playing());
    key(ed, Key::Space, Mods::NONE);
    for _ in 0..5 {
        *t += 0.1;
        ed.handle(Event::Tick { time: *t });
    }
    assert!(ed.is_playing());
    assert!(ed.current_frame() > 0.0, "playback advanced");
}

fn field(ed: &Editor, name: &str) -> (f32, f32) {
    let w = ed
        .widgets()
        .into_iter()
        .find(|w| matches!(&w.kind, WidgetKind::Field(_)) && format!("{:?}", w.kind) == name)
        .unwrap_or_else(|| panic!("no {name}"));
    (
        w.rect.x as f32 + w.rect.w as f32 / 2.0,
        w.rect.y as f32 + w.rect.h as f32 / 2.0,
    )
}

#[test]
fn a_typed_value_stops_playback() {
    let (mut ed, pyr) = stage();
    let mut t = 0.0;
    play(&mut ed, &mut t);
    let (x, y) = field(&ed, "Field(Translation(1))");
    ed.handle(Event::MouseDown {
        button: MouseButton::Left,
        x,
        y,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseUp {
        button: MouseButton::Left,
        x,
        y,
        mods: Mods::NONE,
    });
    assert!(ed.text_edit().is_some());
    ed.handle(Event::Text("1.25".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert!(!ed.is_playing(), "typing a value stopped playback");
    assert_eq!(ed.scene().node(pyr).transform.translation.y, 1.25);
}

#[test]
fn k_stops_playback() {
    let (mut ed, _) = stage();
    let mut t = 0.0;
    play(&mut ed, &mut t);
    let steps = ed.history().labels().count();
    key(&mut ed, Key::Char('k'), Mods::NONE);
    assert!(ed.history().labels().count() > steps, "K keyed something");
    assert!(!ed.is_playing(), "K stopped playback");
}

#[test]
fn a_handle_drag_stops_playback() {
    let (mut ed, pyr) = stage();
    let mut t = 0.0;
    play(&mut ed, &mut t);
    let p = ed.handle_points().expect("handles are shown");
    let (c, tip) = (p[0], p[1]);
    let a = (c.0 + (tip.0 - c.0) * 0.6, c.1 + (tip.1 - c.1) * 0.6);
    let b = (a.0 + (tip.0 - c.0) * 0.5, a.1 + (tip.1 - c.1) * 0.5);
    let before = ed.scene().node(pyr).transform.translation;
    drag(&mut ed, a, b, Mods::NONE);
    assert!(!ed.is_playing(), "a handle drag stopped playback");
    assert_ne!(ed.scene().node(pyr).transform.translation, before);
}

#[test]
fn a_field_drag_stops_playback_at_its_first_preview() {
    let (mut ed, _) = stage();
    let mut t = 0.0;
    play(&mut ed, &mut t);
    let (x, y) = field(&ed, "Field(Translation(0))");
    ed.handle(Event::MouseDown {
        button: MouseButton::Left,
        x,
        y,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseMove {
        x: x + 20.0,
        y,
        mods: Mods::NONE,
    });
    assert!(!ed.is_playing(), "the live preview stopped playback");
}

#[test]
fn delete_and_undo_stop_playback_but_looking_around_does_not() {
    let (mut ed, _) = stage();
    let mut t = 0.0;
    play(&mut ed, &mut t);
    let vp = ed.layout().viewport;
    let (cx, cy) = (vp.x as f32 + vp.w as f32 / 2.0, vp.y as f32 + 10.0);
    ed.handle(Event::Wheel {
        delta: 1.0,
        x: cx,
        y: cy,
        mods: Mods::NONE,
    });
    drag(&mut ed, (cx, cy), (cx + 30.0, cy + 10.0), Mods::NONE);
    key(&mut ed, Key::Char('g'), Mods::NONE);
    assert!(
        ed.is_playing(),
        "zoom, an empty viewport drag and the grid are not edits"
    );
    key(&mut ed, Key::Delete, Mods::NONE);
    assert!(!ed.is_playing(), "delete stopped playback");
    play(&mut ed, &mut t);
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert!(!ed.is_playing(), "undo stopped playback");
}
