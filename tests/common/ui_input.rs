//! Input the editor tests send, as a user would: key presses, clicks,
//! drags in eight steps, widgets found by their debug name. Every event
//! goes through `shell::handle`, as the window loop sends it: the editor,
//! then the file work it asked for.
#![allow(dead_code)] // each test file uses only some of these

use animed::internals::editor::{shell, Editor, Event, Key, Mods, MouseButton};

pub fn key(ed: &mut Editor, k: Key, mods: Mods) {
    shell::handle(ed, Event::KeyDown { key: k, mods });
    shell::handle(ed, Event::KeyUp { key: k, mods });
}

pub fn click_with(ed: &mut Editor, (x, y): (f32, f32), mods: Mods) {
    let button = MouseButton::Left;
    shell::handle(ed, Event::MouseMove { x, y, mods });
    shell::handle(ed, Event::MouseDown { button, x, y, mods });
    shell::handle(ed, Event::MouseUp { button, x, y, mods });
}

pub fn click(ed: &mut Editor, at: (f32, f32)) {
    click_with(ed, at, Mods::NONE);
}

/// Mouse to (x, y), left button down (a drag's start).
pub fn down(ed: &mut Editor, (x, y): (f32, f32), mods: Mods) {
    shell::handle(ed, Event::MouseMove { x, y, mods });
    shell::handle(
        ed,
        Event::MouseDown {
            button: MouseButton::Left,
            x,
            y,
            mods,
        },
    );
}

/// Left button up at (x, y).
pub fn up(ed: &mut Editor, (x, y): (f32, f32), mods: Mods) {
    shell::handle(
        ed,
        Event::MouseUp {
            button: MouseButton::Left,
            x,
            y,
            mods,
        },
    );
}

/// Mouse moved to (x, y) with the button state unchanged.
pub fn move_to(ed: &mut Editor, (x, y): (f32, f32), mods: Mods) {
    shell::handle(ed, Event::MouseMove { x, y, mods });
}

/// Press at `path[0]`, move through the rest (8 steps between points),
/// release at the last, holding `mods`.
pub fn drag_via(ed: &mut Editor, path: &[(f32, f32)], mods: Mods) {
    down(ed, path[0], mods);
    for w in path.windows(2) {
        for i in 1..=8 {
            let t = i as f32 / 8.0;
            let p = (
                w[0].0 + (w[1].0 - w[0].0) * t,
                w[0].1 + (w[1].1 - w[0].1) * t,
            );
            move_to(ed, p, mods);
        }
    }
    up(ed, *path.last().expect("a path"), mods);
}

/// Press at `a`, move in 8 steps, release at `b`, holding `mods`.
pub fn drag(ed: &mut Editor, a: (f32, f32), b: (f32, f32), mods: Mods) {
    drag_via(ed, &[a, b], mods);
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

/// Centre of the widget whose debug text contains `needle`, scrolling the
/// side panel's properties with the wheel (as a user would) until it shows.
pub fn find_scrolled(ed: &mut Editor, needle: &str) -> (f32, f32) {
    let props = ed.side_panel().props;
    let (x, y) = ((props.x + props.w / 2) as f32, (props.bottom() - 4) as f32);
    let mods = Mods::NONE;
    if !ed
        .widgets()
        .iter()
        .any(|w| format!("{:?}", w.kind).contains(needle))
    {
        // From the first row down.
        for _ in 0..3 {
            let delta = 10.0;
            shell::handle(ed, Event::Wheel { delta, x, y, mods });
        }
    }
    for _ in 0..32 {
        if ed
            .widgets()
            .iter()
            .any(|w| format!("{:?}", w.kind).contains(needle))
        {
            return find(ed, needle);
        }
        let delta = -1.0;
        shell::handle(ed, Event::Wheel { delta, x, y, mods });
    }
    panic!("no widget {needle}, even scrolled")
}

/// Types `text` into the field whose debug name contains `field`.
pub fn type_into(ed: &mut Editor, field: &str, text: &str) {
    let at = find_scrolled(ed, field);
    click(ed, at);
    assert!(ed.text_edit().is_some(), "{field} starts typing");
    shell::handle(ed, Event::Text(text.into()));
    key(ed, Key::Enter, Mods::NONE);
}

/// The editor (480×320) on the frozen copy of the demo stage.
pub fn stage() -> Editor {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    Editor::new(
        loaded.scene,
        Some(std::path::PathBuf::from("stage.wrl")),
        480,
        320,
    )
}

pub fn node(ed: &Editor, name: &str) -> animed::internals::scene::NodeId {
    ed.scene().find_node(name).expect("node in the stage")
}
