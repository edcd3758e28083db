//! Input the editor tests send, as a user would: key presses, clicks,
//! drags in eight steps, widgets found by their debug name.
#![allow(dead_code)] // each test file uses only some of these

use animed::editor::{Editor, Event, Key, Mods, MouseButton};

pub fn key(ed: &mut Editor, k: Key, mods: Mods) {
    ed.handle(Event::KeyDown { key: k, mods });
    ed.handle(Event::KeyUp { key: k, mods });
}

pub fn click_with(ed: &mut Editor, (x, y): (f32, f32), mods: Mods) {
    let button = MouseButton::Left;
    ed.handle(Event::MouseMove { x, y, mods });
    ed.handle(Event::MouseDown { button, x, y, mods });
    ed.handle(Event::MouseUp { button, x, y, mods });
}

pub fn click(ed: &mut Editor, at: (f32, f32)) {
    click_with(ed, at, Mods::NONE);
}

/// Press at `a`, move in 8 steps, release at `b`, holding `mods`.
pub fn drag(ed: &mut Editor, a: (f32, f32), b: (f32, f32), mods: Mods) {
    let button = MouseButton::Left;
    ed.handle(Event::MouseMove {
        x: a.0,
        y: a.1,
        mods,
    });
    ed.handle(Event::MouseDown {
        button,
        x: a.0,
        y: a.1,
        mods,
    });
    for i in 1..=8 {
        let t = i as f32 / 8.0;
        let (x, y) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
        ed.handle(Event::MouseMove { x, y, mods });
    }
    ed.handle(Event::MouseUp {
        button,
        x: b.0,
        y: b.1,
        mods,
    });
}

/// Centre of the widget whose debug text contains `needle`.
pub fn find(ed: &Editor, needle: &str) -> (f32, f32) {
    let w = ed
        .widgets()
        .into_iter()
        .find(|w| format!("{:?}", w.kind).contains(needle))
        .unwrap_or_else(|| panic!("no widget {needle}"));
    (
        w.rect.x as f32 + w.rect.w as f32 / 2.0,
        w.rect.y as f32 + w.rect.h as f32 / 2.0,
    )
}

/// Types `text` into the field whose debug name contains `field`.
pub fn type_into(ed: &mut Editor, field: &str, text: &str) {
    let at = find(ed, field);
    click(ed, at);
    assert!(ed.text_edit().is_some(), "{field} starts typing");
    ed.handle(Event::Text(text.into()));
    key(ed, Key::Enter, Mods::NONE);
}

/// The editor (480×320) on the frozen copy of the demo stage.
pub fn stage() -> Editor {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::format::load(&path).expect("the stage loads");
    Editor::new(
        loaded.scene,
        Some(std::path::PathBuf::from("stage.wrl")),
        480,
        320,
    )
}

pub fn node(ed: &Editor, name: &str) -> animed::scene::NodeId {
    ed.scene().find_node(name).expect("node in the stage")
}
