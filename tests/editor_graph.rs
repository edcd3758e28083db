//! The graph editor, driven as a user drives it: Shift+F6 or the toolbar
//! opens it in the key strip's place; keys and tangent handles are aimed
//! at through the headless script steps (`click-curve-key`,
//! `drag-curve-key`, `drag-curve-handle`), and every edit is checked on
//! the scene's keys, on undo, and in goldens/editor_graph_*.png.

#[path = "common/golden.rs"]
mod golden;
#[path = "common/ui_input.rs"]
mod ui_input;

use animed::internals::anim::{Interp, Key, Property, Target, TargetRef, Value};
use animed::internals::editor::{script, Editor, Event, Key as K, Mods, MouseButton};
use animed::internals::scene::NodeId;
use std::path::{Path, PathBuf};

const W: u32 = 480;
const H: u32 = 320;

/// The editor on the frozen copy of the demo stage (Ball keys at 0, 24,
/// 48, 72, 96, linear).
fn stage() -> Editor {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/editor_stage.wrl");
    let loaded = animed::internals::format::load(&path).expect("the stage loads");
    Editor::new(loaded.scene, Some(PathBuf::from("stage.wrl")), W, H)
}

fn run(ed: &mut Editor, s: &str) {
    script::run(ed, s, Path::new("graph-session.txt")).unwrap_or_else(|e| panic!("{e}"));
}

fn ball(ed: &Editor) -> NodeId {
    ed.scene().find_node("Ball").expect("Ball")
}

/// The Ball's translation key at `frame`.
fn key_at(ed: &Editor, frame: f32) -> Option<Key<Value>> {
    let t = ed.scene().animation.track(Target {
        of: TargetRef::Node(ball(ed)),
        property: Property::Translation,
    })?;
    t.key(t.key_index_at(frame)?)
}

fn y_of(k: Key<Value>) -> f32 {
    match k.value {
        Value::Vec3(v) => v.y,
        _ => panic!("translation is a Vec3"),
    }
}

/// Stage with the Ball selected and the graph open.
fn graph_on_ball() -> Editor {
    let mut ed = stage();
    run(&mut ed, "select Ball\nkey shift+f6");
    assert!(ed.graph_open(), "Shift+F6 opens the graph");
    ed
}

#[test]
fn shift_f6_and_the_toolbar_button_toggle_the_graph_in_the_strips_place() {
    let mut ed = stage();
    let strip = ed.layout().key_rows;
    run(&mut ed, "select Ball\nkey shift+f6");
    assert!(ed.graph_open());
    let g = ed.layout().key_rows;
    assert!(
        g.h > strip.h.max(60),
        "the graph is taller than the strip: {g:?}"
    );
    assert_eq!(
        ed.layout().viewport.h + g.h,
        strip.h + ed.layout().viewport.h + (g.h - strip.h)
    );
    run(&mut ed, "key shift+f6");
    assert!(!ed.graph_open());
    let b = ed
        .widgets()
        .into_iter()
        .find(|w| format!("{:?}", w.kind).contains("ToggleGraph"))
        .expect("a Graph button on the toolbar");
    let c = (
        (b.rect.x + b.rect.w / 2) as f32,
        (b.rect.y + b.rect.h / 2) as f32,
    );
    ui_input::click(&mut ed, c);
    assert!(ed.graph_open(), "the toolbar button opens it");
}

#[test]
fn dragging_a_key_up_raises_its_value_and_one_undo_restores_it() {
    let mut ed = graph_on_ball();
    let before = y_of(key_at(&ed, 24.0).unwrap());
    let steps = ed.history().labels().count();
    let world = |ed: &Editor| {
        let s = ed.scene();
        animed::internals::editor::motion_path::world_at(s, &s.animation, ball(ed), 24.0)
            .w_axis
            .y
    };
    let shown = world(&ed);
    run(&mut ed, "drag-curve-key translation.y 24 0 -20");
    let after = y_of(key_at(&ed, 24.0).expect("still at frame 24 (no sideways motion)"));
    assert!(after > before + 0.05, "{before} -> {after}");
    let labels: Vec<&str> = ed.history().labels().collect();
    assert_eq!(labels.len(), steps + 1, "one undo step: {labels:?}");
    // Where the motion path and the viewport put the Ball follows the key.
    assert!((world(&ed) - shown - (after - before)).abs() < 1e-4);
    run(&mut ed, "key ctrl+z");
    assert_eq!(y_of(key_at(&ed, 24.0).unwrap()), before);
}

#[test]
fn a_sideways_drag_moves_the_key_in_time_and_ctrl_snaps_it_to_a_frame() {
    let mut ed = graph_on_ball();
    run(&mut ed, "drag-curve-key translation.y 24 9 0");
    let moved: Vec<f32> = frames(&ed);
    assert!(!moved.contains(&24.0), "left frame 24: {moved:?}");
    let f = moved[1];
    assert!(f > 24.0 && f < 36.0, "{moved:?}");
    run(&mut ed, "key ctrl+z");
    run(&mut ed, "drag-curve-key translation.y 24 9 0 ctrl");
    let snapped = frames(&ed)[1];
    assert!(
        snapped > 24.0 && snapped.fract() == 0.0,
        "Ctrl snaps to whole frames: {snapped}"
    );
}

fn frames(ed: &Editor) -> Vec<f32> {
    ed.scene()
        .animation
        .track(Target {
            of: TargetRef::Node(ball(ed)),
            property: Property::Translation,
        })
        .unwrap()
        .keys
        .frames()
}

#[test]
fn dragging_the_tangent_handle_sets_tension_and_bias_and_the_handle_follows() {
    let mut ed = graph_on_ball();
    run(&mut ed, "click-curve-key translation.y 24");
    let k0 = key_at(&ed, 24.0).unwrap();
    assert_eq!(k0.interp, Interp::Linear);
    let start = ed.graph_point("translation.y", 24.0, true).unwrap();
    run(&mut ed, "drag-curve-handle translation.y 24 25 -12");
    let k = key_at(&ed, 24.0).unwrap();
    assert_eq!(k.interp, Interp::Tcb, "shaping a key makes it TCB");
    assert_eq!(y_of(k), y_of(k0), "the value stays");
    assert!(k.tension < 0.0, "a longer handle loosens: {}", k.tension);
    assert!(k.bias != 0.0, "the direction sets bias: {}", k.bias);
    assert_eq!(k.continuity, 0.0);
    // Tension follows the distance to the release point: the handle is
    // that long now; bias turned it up, the way the mouse went.
    let key = ed.graph_point("translation.y", 24.0, false).unwrap();
    let end = ed.graph_point("translation.y", 24.0, true).unwrap();
    let want = (start.0 + 25.0, start.1 - 12.0);
    let len = |p: (f32, f32)| (p.0 - key.0).hypot(p.1 - key.1);
    assert!(
        (len(end) - len(want)).abs() < 2.0,
        "handle at {end:?}, released at {want:?}"
    );
    let rise = |p: (f32, f32)| (key.1 - p.1) / (p.0 - key.0);
    assert!(rise(end) > rise(start), "turned up: {end:?} from {start:?}");
    run(&mut ed, "key ctrl+z");
    let k = key_at(&ed, 24.0).unwrap();
    assert_eq!((k.interp, k.tension, k.bias), (Interp::Linear, 0.0, 0.0));
}

/// A 40-px pull on a default handle loosens it by about half, not to
/// the limit (the handle's length is a ratio scale: 2x is -0.5, 4x is -1).
/// The ball in the graph with the y key at 24 selected: the key's pixel
/// and its tangent handle's end.
fn y24_selected() -> (Editor, (f32, f32), (f32, f32)) {
    let mut ed = graph_on_ball();
    run(&mut ed, "click-curve-key translation.y 24");
    let key = ed.graph_point("translation.y", 24.0, false).unwrap();
    let end = ed.graph_point("translation.y", 24.0, true).unwrap();
    (ed, key, end)
}

#[test]
fn a_sideways_pull_on_the_handle_loosens_gently() {
    let (mut ed, key, end) = y24_selected();
    let len = |p: (f32, f32)| (p.0 - key.0).hypot(p.1 - key.1);
    let ratio = len((end.0 + 40.0, end.1)) / len(end);
    run(&mut ed, "drag-curve-handle translation.y 24 40 0");
    let t = key_at(&ed, 24.0).unwrap().tension;
    assert!(
        (t + ratio.log(4.0)).abs() < 0.02,
        "tension {t}, ratio {ratio}"
    );
    assert!(t > -0.8 && t < -0.3, "a gentle pull: {t}");
}

/// A 10-px tilt over a 40-px pull turns bias by the angle turned over 45°
/// (about 0.3), not to the limit as solving the bias that points the
/// tangent at the mouse did on this flat curve.
#[test]
fn a_tilt_of_the_handle_biases_gently() {
    let (mut ed, key, end) = y24_selected();
    let to = (end.0 + 40.0, end.1 - 10.0);
    let angle = |p: (f32, f32)| (key.1 - p.1).atan2(p.0 - key.0);
    let turn = angle(to) - angle(end);
    run(&mut ed, "drag-curve-handle translation.y 24 40 -10");
    let b = key_at(&ed, 24.0).unwrap().bias;
    assert!(
        (b.abs() - turn / std::f32::consts::FRAC_PI_4).abs() < 0.02,
        "bias {b}, turned {turn} rad"
    );
    assert!(b.abs() > 0.1 && b.abs() < 0.5, "a gentle tilt: {b}");
}

/// Moving the animated Ball with a handle (record off) leaves a change not
/// yet keyed; editing its keys in the graph drops it, as editing them in
/// the key strip or the key panel does (one rule for every part).
#[test]
fn a_key_drag_in_the_graph_drops_a_change_not_yet_keyed() {
    let mut ed = graph_on_ball();
    run(&mut ed, "drag-handle x 30 0");
    assert!(ed.pending().is_some(), "{}", ed.status().text);
    run(&mut ed, "drag-curve-key translation.y 24 0 -20");
    assert!(ed.pending().is_none());
}

#[test]
fn alt_on_the_handle_sets_continuity() {
    let mut ed = graph_on_ball();
    run(
        &mut ed,
        "click-curve-key translation.y 24\ndrag-curve-handle translation.y 24 30 0 alt",
    );
    let k = key_at(&ed, 24.0).unwrap();
    assert!(k.continuity > 0.3, "{}", k.continuity);
    assert_eq!(k.bias, 0.0);
}

#[test]
fn a_locked_channel_keeps_its_keys_and_a_hidden_one_is_not_drawn() {
    let mut ed = graph_on_ball();
    let list = graph_list(&ed);
    // Channel rows under the list header: translation.x, .y, .z.
    let row_y = (list.y + 2 * 16 + 8) as f32;
    ui_input::click(&mut ed, ((list.x + 22) as f32, row_y));
    let before = y_of(key_at(&ed, 24.0).unwrap());
    run(&mut ed, "drag-curve-key translation.y 24 0 -20");
    assert_eq!(y_of(key_at(&ed, 24.0).unwrap()), before, "locked");
    ui_input::click(&mut ed, ((list.x + 8) as f32, row_y));
    let err = script::run(&mut ed, "click-curve-key translation.y 24", Path::new("s"));
    assert!(err.is_err(), "a hidden curve's keys cannot be aimed at");
}

fn graph_list(ed: &Editor) -> animed::internals::ui::Rect {
    animed::internals::editor::graph::Areas::new(ed.layout().key_rows).list
}

#[test]
fn a_box_selects_keys_and_the_key_panel_follows() {
    let mut ed = graph_on_ball();
    let a = animed::internals::editor::graph::Areas::new(ed.layout().key_rows);
    let p = a.plot;
    ui_input::drag_via(
        &mut ed,
        &[
            ((p.x + 2) as f32, (p.y + 2) as f32),
            ((p.right() - 2) as f32, (p.bottom() - 2) as f32),
        ],
        Mods::NONE,
    );
    let sel = ed.selected_keys();
    assert!(sel.len() >= 3, "keys in view selected: {sel:?}");
    assert!(sel.iter().all(|k| k.property == Property::Translation));
}

#[test]
fn the_frame_band_scrubs_and_the_wheel_zooms() {
    let mut ed = graph_on_ball();
    let a = animed::internals::editor::graph::Areas::new(ed.layout().key_rows);
    let v = ed.graph().unwrap().view;
    let x = v.frame_to_x(a.plot, 30.0);
    ui_input::click(&mut ed, (x, (a.band.y + 5) as f32));
    assert_eq!(ed.current_frame(), 30.0);
    let span = v.f1 - v.f0;
    let (cx, cy) = (
        (a.plot.x + a.plot.w / 2) as f32,
        (a.plot.y + a.plot.h / 2) as f32,
    );
    ed.handle(Event::MouseMove {
        x: cx,
        y: cy,
        mods: Mods::NONE,
    });
    ed.handle(Event::Wheel {
        delta: 2.0,
        x: cx,
        y: cy,
        mods: Mods::NONE,
    });
    let z = ed.graph().unwrap().view;
    assert!(z.f1 - z.f0 < span * 0.8, "zoomed in on frames");
    ed.handle(Event::Wheel {
        delta: -2.0,
        x: cx,
        y: cy,
        mods: Mods::ctrl(),
    });
    let zv = ed.graph().unwrap().view;
    assert!(
        zv.v1 - zv.v0 > (z.v1 - z.v0) * 1.2,
        "Ctrl+wheel zooms values"
    );
    ed.handle(Event::KeyDown {
        key: K::Home,
        mods: Mods::NONE,
    });
    assert_eq!(ed.graph().unwrap().view, v, "Home frames all again");
    // Middle drag pans.
    ed.handle(Event::MouseDown {
        button: MouseButton::Middle,
        x: cx,
        y: cy,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseMove {
        x: cx + 40.0,
        y: cy,
        mods: Mods::NONE,
    });
    ed.handle(Event::MouseUp {
        button: MouseButton::Middle,
        x: cx + 40.0,
        y: cy,
        mods: Mods::NONE,
    });
    assert!(ed.graph().unwrap().view.f0 < v.f0);
}

#[test]
fn graph_goldens() {
    let mut ed = graph_on_ball();
    golden::check("editor_graph_open", &ed.render_frame());
    run(
        &mut ed,
        "drag-curve-key translation.y 24 0 -20\nclick-curve-key translation.y 24\ndrag-curve-handle translation.y 24 25 -12",
    );
    // Home over the graph frames all again, handle and all.
    run(&mut ed, "move 300 250\nkey home");
    golden::check("editor_graph_shaped", &ed.render_frame());
    run(&mut ed, "key n");
    golden::check("editor_graph_normalised", &ed.render_frame());
}

/// Every file of `src/editor/` by module path (`["editor", "route",
/// "input"]`), with its code before the test module and without comments
/// (test modules sit at the ends of files).
fn editor_code() -> std::collections::BTreeMap<Vec<String>, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = std::collections::BTreeMap::new();
    let mut stack = vec![root.join("editor")];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let rel = p.strip_prefix(&root).unwrap().with_extension("");
                let mut m: Vec<String> = rel
                    .iter()
                    .map(|s| s.to_string_lossy().into_owned())
                    .collect();
                if m.last().is_some_and(|l| l == "mod") {
                    m.pop();
                }
                let text = std::fs::read_to_string(&p).unwrap();
                let code = text.split("#[cfg(test)]").next().unwrap_or("");
                let code: String = code
                    .lines()
                    .map(|l| l.split("//").next().unwrap_or(""))
                    .collect::<Vec<_>>()
                    .join("\n");
                files.insert(m, code);
            }
        }
    }
    assert!(files.len() > 40, "found the editor's files");
    files
}

/// File I/O left the state machine (issue 16): only the shell's files read
/// or write, or read the process's environment; every other editor file
/// asks with `request::Request`s and is told the places (start folder,
/// `$HOME`, state folder). The allowed ones: `shell.rs` (performs the
/// requests), `script.rs` (the headless shell: screenshots), `screen.rs`
/// (the window loop's adapter, calls the shell), `disk.rs` (the disk
/// helpers only the shell and the command line call; their rules are in
/// `recovery.rs` and `views.rs`, which touch nothing).
#[test]
fn only_the_shell_touches_files() {
    let allowed = ["shell", "script", "screen", "disk"];
    let io = [
        "std::env",
        "env::var",
        "current_dir",
        "/proc/",
        "std::fs",
        "fs::",
        "File::",
        "format::load",
        "format::save",
        "read_dir",
        "remove_file",
        "Stamp::of",
        "is_dir()",
        "is_file()",
        ".exists()",
        "metadata(",
        "disk::",
        "newer_copy",
        "untitled_sessions",
        "session_alive",
        // the shell's own operations
        ".save_to(",
        ".open_file(",
        ".import_file(",
        ".autosave_now(",
        ".check_recovery(",
        ".offer_untitled(",
        ".recover_untitled(",
        ".window_closed(",
        "shell::",
    ];
    let files = editor_code();
    let mut found = Vec::new();
    for (m, code) in &files {
        if m.len() == 2 && allowed.contains(&m[1].as_str()) {
            continue;
        }
        for w in io {
            if code.contains(w) {
                found.push(format!("{}: {w}", m.join("/")));
            }
        }
    }
    assert!(
        found.is_empty(),
        "file work in the state machine: {found:?}"
    );
}

/// The wall clock and the process id are the shell's to pass in
/// (`Editor::set_wall_clock`, `set_pid`; the window loop and
/// `cli/edit.rs::tell_places` do): no editor file but `disk.rs` (the
/// shell's helpers) asks for them, so a test or a script can fix both.
#[test]
fn the_state_machine_reads_no_clock_or_pid() {
    let process = ["SystemTime::now", "process::id", "UNIX_EPOCH.elapsed"];
    let mut found = Vec::new();
    for (m, code) in &editor_code() {
        if m.len() == 2 && m[1] == "disk" {
            continue;
        }
        for w in process {
            if code.contains(w) {
                found.push(format!("{}: {w}", m.join("/")));
            }
        }
    }
    assert!(found.is_empty(), "process state in the editor: {found:?}");
}

/// No file of `src/editor/` imports another that (through others)
/// imports it back. An edge A → B is any path in A's non-test code that
/// names module B (`use super::b::…`, `crate::editor::b::…`, a child
/// `b::…` in a module file, a `use` group); `mod b;` declarations are not
/// edges. A re-exported item (`crate::editor::After`) counts as an edge to
/// the re-exporting module file, whose `pub use` is an edge on to the
/// defining file: more edges than the truth, so no cycle is missed.
#[test]
fn editor_files_import_no_cycle() {
    use std::collections::{BTreeMap, BTreeSet};
    let files = editor_code();
    let is_mod = |m: &[String]| files.contains_key(m);
    // Expands `a::{b, c::{d}}` into full paths.
    fn expand(tree: &str) -> Vec<String> {
        let tree = tree.trim();
        let Some(i) = tree.find('{') else {
            return vec![tree.split(" as ").next().unwrap_or("").trim().to_string()];
        };
        let (prefix, inner) = (
            &tree[..i],
            &tree[i + 1..tree.rfind('}').unwrap_or(tree.len())],
        );
        let (mut parts, mut depth, mut cur) = (Vec::new(), 0, String::new());
        for c in inner.chars() {
            match c {
                ',' if depth == 0 => parts.push(std::mem::take(&mut cur)),
                _ => {
                    depth += (c == '{') as i32 - (c == '}') as i32;
                    cur.push(c);
                }
            }
        }
        parts.push(cur);
        parts
            .iter()
            .filter(|p| !p.trim().is_empty())
            .flat_map(|p| expand(p))
            .map(|e| format!("{prefix}{e}"))
            .collect()
    }
    let resolve = |here: &[String], path: &str| -> Option<Vec<String>> {
        let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
        let mut cur: Vec<String> = here.to_vec();
        let mut rest = &segs[..];
        match segs.first()? {
            &"crate" => {
                cur.clear();
                rest = &segs[1..];
            }
            &"super" | &"self" => {
                while let Some(s) = rest.first().filter(|s| **s == "super" || **s == "self") {
                    if *s == "super" {
                        cur.pop();
                    }
                    rest = &rest[1..];
                }
            }
            first => {
                let mut child = cur.clone();
                child.push(first.to_string());
                if !is_mod(&child) {
                    return None;
                }
            }
        }
        for s in rest {
            let mut next = cur.clone();
            next.push(s.to_string());
            if is_mod(&next) {
                cur = next;
            } else {
                break;
            }
        }
        Some(cur)
    };
    let mut edges: BTreeMap<Vec<String>, BTreeSet<Vec<String>>> = BTreeMap::new();
    for (m, code) in &files {
        let mut paths = Vec::new();
        // `use` statements (at a line's start, maybe `pub`), to their `;`.
        let mut at = 0;
        for line in code.split_inclusive('\n') {
            let t = line.trim_start();
            let t = t
                .strip_prefix("pub(crate) ")
                .or(t.strip_prefix("pub(super) "))
                .unwrap_or(t);
            let t = t.strip_prefix("pub ").unwrap_or(t);
            if let Some(rest) = t.strip_prefix("use ") {
                let start = at + (line.len() - rest.len());
                if let Some(tree) = code[start..].split(';').next() {
                    paths.extend(expand(tree));
                }
            }
            at += line.len();
        }
        for w in code.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':')) {
            if w.contains("::") {
                paths.push(w.to_string());
            }
        }
        for p in paths {
            if let Some(t) = resolve(m, &p) {
                if &t != m && t.first().is_some_and(|f| f == "editor") && files.contains_key(&t) {
                    edges.entry(m.clone()).or_default().insert(t);
                }
            }
        }
    }
    // A cycle shows as a path back to its start (depth-first search).
    fn cycle_from(
        n: &Vec<String>,
        edges: &BTreeMap<Vec<String>, BTreeSet<Vec<String>>>,
        path: &mut Vec<Vec<String>>,
        done: &mut BTreeSet<Vec<String>>,
    ) -> Option<Vec<Vec<String>>> {
        if let Some(i) = path.iter().position(|p| p == n) {
            return Some(path[i..].to_vec());
        }
        if !done.insert(n.clone()) {
            return None;
        }
        path.push(n.clone());
        for t in edges.get(n).into_iter().flatten() {
            if let Some(c) = cycle_from(t, edges, path, done) {
                return Some(c);
            }
        }
        path.pop();
        None
    }
    let total: usize = edges.values().map(BTreeSet::len).sum();
    assert!(
        total > 50,
        "the scan found the editor's imports ({total} edges)"
    );
    let mut done = BTreeSet::new();
    for n in files.keys() {
        let mut path = Vec::new();
        if let Some(c) = cycle_from(n, &edges, &mut path, &mut done) {
            let names: Vec<String> = c.iter().map(|m| m.join("/")).collect();
            panic!("import cycle in src/editor: {}", names.join(" -> "));
        }
    }
}

#[test]
fn with_the_graph_open_each_list_and_the_properties_keep_a_row() {
    use animed::internals::editor::panel::{List, WidgetKind};
    let ed = graph_on_ball();
    let w = ed.widgets();
    let rows = |which: List| {
        w.iter()
            .filter(|w| matches!(w.kind, WidgetKind::Row { list, .. } if list == which))
            .count()
    };
    assert!(rows(List::Objects) >= 1, "an object row shows");
    assert!(
        rows(List::Lights) >= 1,
        "a light row shows, not only the header"
    );
    let has = |s: &str| w.iter().any(|w| format!("{:?}", w.kind) == s);
    // The scene's fields share one row; the ball's name field shows.
    assert!(has("Field(Fps)") && has("Field(Duration)") && has("Field(Name)"));
    assert!(!w
        .iter()
        .any(|w| w.kind == WidgetKind::Header("Scene".into())));
}

/// The weights of shape `m`'s morph key at `frame`.
fn weights_at(ed: &Editor, frame: f32) -> Vec<f32> {
    let m = ed.scene().find_node("m").expect("the morphed shape");
    let t = ed
        .scene()
        .animation
        .track(Target {
            of: TargetRef::Node(m),
            property: Property::MorphWeights,
        })
        .expect("keyed weights");
    match t.key(t.key_index_at(frame).expect("a key")).unwrap().value {
        Value::Weights(w) => w.as_slice().to_vec(),
        _ => panic!("weights keys hold weights"),
    }
}

#[test]
fn morph_weights_are_one_curve_per_target_and_drag_like_any_curve() {
    // Four targets, keys at 0 and 24 (weights x, x/2, 0.3, 1-x).
    let scene = animed::internals::anim::synthetic_deform::morphed_scene(64);
    let mut ed = Editor::new(scene, None, W, H);
    run(&mut ed, "select m\nkey shift+f6");
    let before = weights_at(&ed, 24.0);
    assert_eq!(before.len(), 4);
    run(&mut ed, "drag-curve-key weights.2 24 0 -20");
    let after = weights_at(&ed, 24.0);
    assert!(after[2] > before[2] + 0.01, "{before:?} -> {after:?}");
    for i in [0, 1, 3] {
        assert_eq!(after[i], before[i], "only target 2 moves: {after:?}");
    }
    run(&mut ed, "key ctrl+z");
    assert_eq!(weights_at(&ed, 24.0), before);
    // Each target is its own curve, and there are only four.
    for ch in ["weights.0", "weights.3"] {
        run(&mut ed, &format!("click-curve-key {ch} 24"));
    }
    let err = script::run(&mut ed, "click-curve-key weights.4", Path::new("s"));
    assert!(err.is_err(), "no fifth target");
    let err = script::run(&mut ed, "click-curve-key weights.4 24", Path::new("s"));
    assert!(err.is_err(), "no fifth target");
}
