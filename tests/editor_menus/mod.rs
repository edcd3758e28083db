//! Issue 17's leftovers from session 5: the graph editor's context menu,
//! ease in and out set separately, the toolbar's `Add` lit by its own menu
//! only, and no stale status line after playback stops.

use super::{big_stage, hover, pick, right_click};
use crate::ui_input::*;
use animed::internals::anim::{Keys, Property, Target, TargetRef};
use animed::internals::editor::graph::channel::Channel;
use animed::internals::editor::graph::edit::CurveKey;
use animed::internals::editor::panel::{Action, WidgetKind};
use animed::internals::editor::{Editor, Event, Key, Mods, MouseButton};

fn labels(ed: &Editor) -> Vec<String> {
    let m = ed.menu().expect("a menu is open");
    m.items.iter().map(|i| i.label.clone()).collect()
}

/// (ease in, ease out) of Ball's translation key at `frame`.
fn ease_at(ed: &Editor, frame: f32) -> (f32, f32) {
    let ball = node(ed, "Ball");
    let t = Target {
        of: TargetRef::Node(ball),
        property: Property::Translation,
    };
    let Keys::Vec3(k) = &ed.scene().animation.track(t).unwrap().keys else {
        panic!("vector keys")
    };
    let k = k.iter().find(|k| k.frame == frame).expect("a key there");
    (k.ease_in, k.ease_out)
}

#[test]
fn the_graph_editors_context_menu_edits_keys_and_selects_a_channel() {
    let mut ed = big_stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    key(&mut ed, Key::F(6), Mods::shift());
    assert!(ed.graph_open());
    let ch = Channel::parse(ball, "translation.y").unwrap();
    let at = {
        let g = ed.graph().unwrap();
        g.key_point(&ed.graph_ctx(), CurveKey { ch, frame: 24.0 })
            .expect("the key is shown")
    };
    right_click(&mut ed, at);
    assert_eq!(ed.menu().unwrap().title, "Keys: translation.y");
    assert_eq!(
        labels(&ed),
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
            "Select all on channel",
        ]
    );
    assert_eq!(ed.selected_keys().len(), 1, "the clicked key is selected");
    pick(&mut ed, "Ease out");
    assert_eq!(ease_at(&ed, 24.0), (0.0, 1.0));
    right_click(&mut ed, at);
    pick(&mut ed, "Ease in");
    assert_eq!(ease_at(&ed, 24.0), (1.0, 1.0), "ease out kept");
    right_click(&mut ed, at);
    pick(&mut ed, "No ease");
    assert_eq!(ease_at(&ed, 24.0), (0.0, 0.0));
    right_click(&mut ed, at);
    pick(&mut ed, "Select all on channel");
    assert_eq!(ed.selected_keys().len(), 5);
    assert_eq!(ed.status().text, "Selected 5 keys on the channel");
    let steps = ed.history().labels().count();
    right_click(&mut ed, at);
    pick(&mut ed, "Interpolation: step");
    assert_eq!(ed.history().labels().count(), steps + 1, "one undo step");
    // A right drag pans and opens no menu.
    let before = ed.graph().unwrap().view;
    let plot = ed.layout().key_rows;
    let c = (
        (plot.x + plot.w * 2 / 3) as f32,
        (plot.y + plot.h / 2) as f32,
    );
    let b = MouseButton::Right;
    let m = Mods::NONE;
    ed.handle(Event::MouseDown {
        button: b,
        x: c.0,
        y: c.1,
        mods: m,
    });
    ed.handle(Event::MouseMove {
        x: c.0 + 30.0,
        y: c.1,
        mods: m,
    });
    ed.handle(Event::MouseUp {
        button: b,
        x: c.0 + 30.0,
        y: c.1,
        mods: m,
    });
    assert!(ed.menu().is_none());
    assert_ne!(ed.graph().unwrap().view, before, "panned");
}

#[test]
fn the_key_strips_menu_sets_ease_in_and_out_separately() {
    use animed::internals::editor::keystrip::Row;
    let mut ed = big_stage();
    ed.select(Some(node(&ed, "Ball")));
    let at = ed
        .key_marker_at(Row::Track(Property::Translation), 48.0)
        .unwrap();
    right_click(&mut ed, at);
    pick(&mut ed, "Ease in");
    assert_eq!(ease_at(&ed, 48.0), (1.0, 0.0));
    right_click(&mut ed, at);
    pick(&mut ed, "Ease out");
    assert_eq!(ease_at(&ed, 48.0), (1.0, 1.0));
    key(&mut ed, Key::Char('z'), Mods::ctrl());
    assert_eq!(ease_at(&ed, 48.0), (1.0, 0.0), "one undo step each");
}

/// Whether the toolbar's Add button is drawn lit.
fn add_lit(ed: &Editor) -> bool {
    ed.widgets().iter().any(|w| {
        matches!(
            &w.kind,
            WidgetKind::Button {
                action: Action::AddMenu,
                on: true,
                ..
            }
        )
    })
}

#[test]
fn add_is_lit_by_its_own_menu_only() {
    let mut ed = big_stage();
    ed.select(Some(node(&ed, "Ball")));
    assert!(!add_lit(&ed));
    let strip = ed.layout().key_rows;
    right_click(
        &mut ed,
        ((strip.x + strip.w / 2) as f32, (strip.y + 5) as f32),
    );
    assert!(ed.menu().is_some(), "the strip's menu");
    assert!(!add_lit(&ed));
    key(&mut ed, Key::Escape, Mods::NONE);
    key(&mut ed, Key::F(3), Mods::NONE);
    assert!(!add_lit(&ed), "not by the search");
    key(&mut ed, Key::Escape, Mods::NONE);
    let vp = ed.layout().viewport;
    hover(&mut ed, ((vp.x + 40) as f32, (vp.y + 40) as f32));
    key(&mut ed, Key::Char('a'), Mods::shift());
    assert!(add_lit(&ed), "Shift+A");
    key(&mut ed, Key::Escape, Mods::NONE);
    assert!(!add_lit(&ed));
}

#[test]
fn stopping_playback_replaces_the_preview_hint() {
    let mut ed = big_stage();
    key(&mut ed, Key::Char(']'), Mods::NONE);
    let f = find(&ed, "Field(Frame)");
    click(&mut ed, f);
    ed.handle(Event::Text("40".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    key(&mut ed, Key::Char(']'), Mods::NONE);
    assert!(
        ed.status().text.starts_with("Preview frames 0 to 40"),
        "{:?}",
        ed.status()
    );
    key(&mut ed, Key::Space, Mods::NONE);
    assert!(
        ed.status().text.starts_with("Playing frames 0 to 40"),
        "{:?}",
        ed.status()
    );
    for i in 0..10 {
        ed.handle(Event::Tick {
            time: 50.0 + i as f64 * 0.1,
        });
    }
    key(&mut ed, Key::Space, Mods::NONE);
    let t = &ed.status().text;
    let shown = ed.current_frame();
    assert_eq!(t, &format!("Stopped at frame {shown}"));
    assert!(!t.contains("Preview"));
}

#[test]
fn the_preview_range_is_typed_into_its_fields() {
    let mut ed = big_stage();
    assert!(
        !format!("{:?}", ed.widgets()).contains("Preview(0)"),
        "no range, no fields"
    );
    // F3 → "Preview range": a range over the scene, typing its start.
    key(&mut ed, Key::F(3), Mods::NONE);
    ed.handle(Event::Text("preview".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.preview_range(), Some((0.0, 96.0)));
    assert!(ed.text_edit().is_some(), "typing the start");
    ed.handle(Event::Text("10+10".into()));
    key(&mut ed, Key::Enter, Mods::NONE);
    assert_eq!(ed.preview_range(), Some((20.0, 96.0)));
    type_into(&mut ed, "Field(Preview(1))", "40");
    assert_eq!(ed.preview_range(), Some((20.0, 40.0)));
    // A start after the end is refused and said.
    type_into(&mut ed, "Field(Preview(0))", "50");
    assert_eq!(ed.preview_range(), Some((20.0, 40.0)));
    assert!(ed.status().error, "{:?}", ed.status());
    assert!(
        ed.status().text.contains("must be before"),
        "{:?}",
        ed.status()
    );
    // Past the scene's end: clamped, and the line says so.
    type_into(&mut ed, "Field(Preview(1))", "500");
    assert_eq!(ed.preview_range(), Some((20.0, 96.0)));
    let t = &ed.status().text;
    assert!(
        t.contains("Preview end: 500") && t.contains("set to 96"),
        "{t}"
    );
}

#[test]
fn list_rows_and_the_key_strip_have_tooltips() {
    use animed::internals::editor::keystrip::Row;
    let mut ed = big_stage();
    let ball = node(&ed, "Ball");
    ed.select(Some(ball));
    let rest = |ed: &mut Editor, at: (f32, f32)| {
        hover(ed, at);
        for i in 0..8 {
            ed.handle(Event::Tick {
                time: 10.0 + i as f64 * 0.1,
            });
        }
        ed.tooltip().unwrap_or_default()
    };
    let at = ed
        .key_marker_at(Row::Track(Property::Translation), 24.0)
        .unwrap();
    let t = rest(&mut ed, at);
    assert_eq!(
        t,
        "Translation key, frame 24: drag moves; right-click: menu"
    );
    let strip = ed.layout().key_rows;
    let empty = ((strip.right() - 6) as f32, (strip.bottom() - 4) as f32);
    assert!(rest(&mut ed, empty).starts_with("Drag: box select"));
    let row = find(&ed, &format!("node: NodeId({})", ball.0));
    assert!(rest(&mut ed, row).contains("drag onto a row parents it"));
}
