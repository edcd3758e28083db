//! Never lose work (issue 7 item 8): a headless `animed edit` session makes
//! keyed edits, autosaves, and is killed with SIGKILL; the scene file is
//! untouched, and a second session recovers the copy and saves the edits.
//! Also the recovery dialog's other answers, driven in-process.

use animed::internals::anim::{Property, Target, TargetRef, Value};
use animed::internals::editor::panel::WidgetKind;
use animed::internals::editor::recovery::recovery_path;
use animed::internals::editor::{shell, After, Editor, Event, Key, Mods};
use animed::internals::scene::{NodeId, Scene};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const SIZE: (u32, u32) = (640, 400);

/// A fresh folder for one test.
fn dir(tag: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("editor-recovery-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The demo scene saved as `dir/scene.wrl`.
fn demo_file(d: &Path) -> PathBuf {
    let p = d.join("scene.wrl");
    let demo = animed::internals::format::demo().expect("the bundled demo loads");
    animed::internals::format::save(&demo.scene, &p, &Default::default()).unwrap();
    p
}

fn centre(ed: &Editor, pred: impl Fn(&WidgetKind) -> bool) -> (i32, i32) {
    let w = ed
        .widgets()
        .into_iter()
        .find(|w| pred(&w.kind))
        .expect("widget shown");
    (w.rect.x + w.rect.w / 2, w.rect.y + w.rect.h / 2)
}

/// Script that selects the first object, turns record on, types x = 2.5
/// at frame 0 and x = -4 at frame 10 (two translation keys), then idles in
/// real time so autosave fires. Returns it and the object.
fn editing_script(scene: &Path) -> (String, NodeId) {
    let loaded = animed::internals::format::load(scene).unwrap();
    let mut ed = Editor::new(loaded.scene, Some(scene.to_path_buf()), SIZE.0, SIZE.1);
    let (row, node) = ed
        .widgets()
        .into_iter()
        .find_map(|w| match w.kind {
            WidgetKind::Row { node, .. } => Some(((w.rect.x + 20, w.rect.y + w.rect.h / 2), node)),
            _ => None,
        })
        .expect("the demo lists objects");
    ed.select(Some(node));
    let tx = centre(&ed, |k| format!("{k:?}") == "Field(Translation(0))");
    let mut s = format!("click {} {}\nkey r\n", row.0, row.1);
    s += &format!("click {} {}\ntype 2.5\nkey enter\n", tx.0, tx.1);
    s += &"key right\n".repeat(10);
    // The first key adds key strip rows, which moves the panel: find the
    // field again in an editor that ran the steps so far.
    animed::internals::editor::script::run(&mut ed, &s, Path::new("s1.txt")).expect("script runs");
    let tx = centre(&ed, |k| format!("{k:?}") == "Field(Translation(0))");
    s += &format!("click {} {}\ntype -4\nkey enter\n", tx.0, tx.1);
    s += "sleep-ms 60000\n";
    (s, node)
}

fn translation_keys(scene: &animed::internals::scene::Scene, id: NodeId) -> Vec<(f32, Value)> {
    let t = scene.animation.track(Target {
        of: TargetRef::Node(id),
        property: Property::Translation,
    });
    t.map(|t| {
        (0..t.key_count())
            .map(|i| {
                let k = t.key(i).expect("index in range");
                (k.frame, k.value)
            })
            .collect()
    })
    .unwrap_or_default()
}

fn key_x(keys: &[(f32, Value)], frame: f32) -> Option<f32> {
    keys.iter().find(|k| k.0 == frame).and_then(|k| match k.1 {
        Value::Vec3(v) => Some(v.x),
        _ => None,
    })
}

#[test]
fn a_killed_session_is_recovered_and_saved() {
    let d = dir("kill");
    let scene = demo_file(&d);
    let original = std::fs::read(&scene).unwrap();
    let copy = recovery_path(&scene);
    let (script, node) = editing_script(&scene);
    let s1 = d.join("s1.txt");
    std::fs::write(&s1, script).unwrap();

    let mut child = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(["edit"])
        .arg(&scene)
        .arg("--script")
        .arg(&s1)
        .args(["--size", &format!("{}x{}", SIZE.0, SIZE.1)])
        .env("ANIMED_AUTOSAVE_SECS", "1")
        .spawn()
        .expect("animed starts");
    let t0 = Instant::now();
    while !copy.exists() {
        if let Some(st) = child.try_wait().unwrap() {
            panic!("the session ended ({st}) before autosaving");
        }
        assert!(
            t0.elapsed() < Duration::from_secs(40),
            "no recovery copy after 40 s"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    let appeared = t0.elapsed();
    // SIGKILL: no chance to clean up or save.
    child.kill().unwrap();
    let st = child.wait().unwrap();
    assert!(!st.success(), "killed, not finished");
    eprintln!("recovery copy appeared after {appeared:?}");

    assert_eq!(
        std::fs::read(&scene).unwrap(),
        original,
        "the scene file is untouched"
    );
    let autosaved = animed::internals::format::load(&copy).expect("the copy loads");
    let k = translation_keys(&autosaved.scene, node);
    assert_eq!(key_x(&k, 0.0), Some(2.5), "{k:?}");
    assert_eq!(key_x(&k, 10.0), Some(-4.0), "{k:?}");

    // Second session: Recover (Enter), save (Ctrl+S).
    let s2 = d.join("s2.txt");
    std::fs::write(&s2, "key enter\nkey ctrl+s\n").unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(["edit"])
        .arg(&scene)
        .arg("--script")
        .arg(&s2)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!copy.exists(), "saving deletes the recovery copy");
    let saved = animed::internals::format::load(&scene).expect("the saved scene loads");
    let k = translation_keys(&saved.scene, node);
    assert_eq!(key_x(&k, 0.0), Some(2.5), "{k:?}");
    assert_eq!(key_x(&k, 10.0), Some(-4.0), "{k:?}");
    assert_eq!(
        saved.scene.node(node).name,
        autosaved.scene.node(node).name,
        "same object"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

fn key(ed: &mut Editor, k: Key) {
    key_with(ed, k, Mods::NONE);
}

fn key_with(ed: &mut Editor, key: Key, mods: Mods) {
    shell::handle(ed, Event::KeyDown { key, mods });
    shell::handle(ed, Event::KeyUp { key, mods });
}

/// `dir/scene.wrl` plus a newer recovery copy in which the first node
/// moved to x = 7; an editor that opened the scene.
fn crashed(d: &Path) -> (PathBuf, Editor) {
    let scene = demo_file(d);
    let mut moved = animed::internals::format::load(&scene).unwrap().scene;
    moved.nodes[0].transform.translation.x = 7.0;
    let copy = recovery_path(&scene);
    animed::internals::format::save(&moved, &copy, &Default::default()).unwrap();
    // Newer than the scene, whatever the file system's time resolution.
    let f = std::fs::OpenOptions::new()
        .write(true)
        .open(&scene)
        .unwrap();
    f.set_modified(std::time::SystemTime::now() - Duration::from_secs(120))
        .unwrap();
    let mut ed = Editor::with_demo(SIZE.0, SIZE.1);
    ed.open_file(&scene).unwrap();
    (copy, ed)
}

#[test]
fn opening_offers_the_copy_recover_keeps_the_name_and_undo_shows_the_saved_file() {
    let d = dir("recover");
    let (copy, mut ed) = crashed(&d);
    let dlg = ed.dialog().expect("the recovery question").clone();
    assert_eq!(dlg.then, After::Recover);
    assert!(dlg.message.contains("scene.wrl"), "{}", dlg.message);
    assert!(dlg.message.contains("UTC"), "{}", dlg.message);
    assert_eq!(ed.recovery_offer(), Some(copy.as_path()));
    // The dialog's buttons say what they do.
    let labels: Vec<String> = dlg
        .widgets(ed.layout().window)
        .into_iter()
        .filter_map(|w| match w.kind {
            WidgetKind::Button { label, .. } => Some(label),
            _ => None,
        })
        .collect();
    assert_eq!(labels, ["Open saved", "Discard copy", "Recover"]);
    key(&mut ed, Key::Char('r'));
    assert!(ed.dialog().is_none());
    assert_eq!(ed.scene().nodes[0].transform.translation.x, 7.0);
    assert!(ed.is_dirty(), "recovered work is unsaved");
    assert_eq!(ed.path(), Some(d.join("scene.wrl").as_path()));
    ed.undo();
    assert_ne!(ed.scene().nodes[0].transform.translation.x, 7.0);
    assert!(!ed.is_dirty(), "undo shows the saved file");
    ed.redo();
    assert_eq!(ed.scene().nodes[0].transform.translation.x, 7.0);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn open_saved_keeps_the_copy_and_discard_deletes_it() {
    let d = dir("answers");
    let (copy, mut ed) = crashed(&d);
    key(&mut ed, Key::Char('o'));
    assert!(ed.dialog().is_none());
    assert_ne!(ed.scene().nodes[0].transform.translation.x, 7.0);
    assert!(!ed.is_dirty());
    assert!(copy.exists(), "Open saved keeps the copy");

    let (copy, mut ed) = crashed(&d);
    assert!(ed.dialog().is_some(), "asked again");
    // Keys of the unsaved-changes dialog do nothing unexpected here.
    key(&mut ed, Key::Char('s'));
    assert!(ed.dialog().is_some());
    key(&mut ed, Key::Char('d'));
    assert!(ed.dialog().is_none());
    assert!(!copy.exists(), "Discard copy deletes it");
    assert!(!ed.is_dirty());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn discarding_unsaved_changes_deletes_this_sessions_copy() {
    let d = dir("discard");
    let scene = demo_file(&d);
    let loaded = animed::internals::format::load(&scene).unwrap();
    let mut ed = Editor::new(loaded.scene, Some(scene.clone()), SIZE.0, SIZE.1);
    ed.set_autosave_interval(Some(1.0));
    let x = centre(&ed, |k| matches!(k, WidgetKind::Row { .. }));
    shell::handle(
        &mut ed,
        Event::MouseDown {
            button: animed::internals::editor::MouseButton::Left,
            x: x.0 as f32,
            y: x.1 as f32,
            mods: Mods::NONE,
        },
    );
    shell::handle(
        &mut ed,
        Event::MouseUp {
            button: animed::internals::editor::MouseButton::Left,
            x: x.0 as f32,
            y: x.1 as f32,
            mods: Mods::NONE,
        },
    );
    key(&mut ed, Key::Delete);
    assert!(ed.is_dirty());
    shell::handle(&mut ed, Event::Tick { time: 10.0 });
    shell::handle(&mut ed, Event::Tick { time: 11.5 });
    let copy = recovery_path(&scene);
    assert!(copy.exists(), "autosaved");
    assert!(ed.last_autosave_ms().is_some());
    shell::handle(
        &mut ed,
        Event::KeyDown {
            key: Key::Char('q'),
            mods: Mods::ctrl(),
        },
    );
    assert!(ed.dialog().is_some(), "asks about the unsaved changes");
    key(&mut ed, Key::Char('d'));
    assert!(ed.wants_quit());
    assert!(!copy.exists(), "discarding drops the copy");
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn closing_the_window_asks_once_then_keeps_the_work_in_the_copy() {
    let d = dir("close");
    let scene = demo_file(&d);
    let loaded = animed::internals::format::load(&scene).unwrap();
    let mut ed = Editor::new(loaded.scene, Some(scene.clone()), SIZE.0, SIZE.1);
    // Nothing unsaved: the window just closes.
    assert!(!ed.close_requested());
    assert_eq!(ed.window_closed(), None);
    let node = NodeId(0);
    ed.select(Some(node));
    key(&mut ed, Key::Char('k'));
    assert!(ed.is_dirty());
    // Unsaved work: the first close asks (the app reopens the window).
    assert!(ed.close_requested());
    assert_eq!(ed.dialog().map(|d| d.then), Some(After::Quit));
    // Closing again while asked: the work goes to the recovery copy.
    assert!(!ed.close_requested());
    let msg = ed.window_closed().expect("says where the work went");
    let copy = recovery_path(&scene);
    assert!(msg.contains(&copy.display().to_string()), "{msg}");
    let kept = animed::internals::format::load(&copy).expect("the copy loads");
    // Node ids may differ after a round trip; compare by name.
    let named = |sc: &animed::internals::scene::Scene| {
        let mut v: Vec<String> = sc
            .animation
            .tracks
            .iter()
            .map(|t| match t.target.of {
                TargetRef::Node(n) => format!("{} {:?}", sc.node(n).name, t.target.property),
                TargetRef::Material(m) => format!("material {} {:?}", m.0, t.target.property),
            })
            .collect();
        v.sort();
        v
    };
    let name = &ed.scene().node(node).name;
    assert!(!name.is_empty());
    let ours = named(ed.scene());
    assert!(
        ours.contains(&format!("{name} Translation")),
        "K keyed the object: {ours:?}"
    );
    assert_eq!(named(&kept.scene), ours, "every track kept");
    std::fs::remove_dir_all(&d).unwrap();
}

/// Object rows of a scene (what the recovery list counts).
fn object_count(s: &animed::internals::scene::Scene) -> usize {
    animed::internals::editor::ops::objects(s).len()
}

/// Issue 17 item 5: an untitled session (the demo, never saved) is killed
/// after autosaving; `animed recover --list` and the next start list it
/// (newest first, with time and object count) beside an older one, and
/// Recover brings the work back as unsaved untitled work.
#[test]
fn a_killed_untitled_session_is_listed_and_recovered() {
    let d = dir("untitled");
    let state = d.join("state");
    let copies = state.join("animed");
    // Select the first listed object and delete it: unsaved untitled work.
    let probe = Editor::with_demo(SIZE.0, SIZE.1);
    let row = centre(&probe, |k| matches!(k, WidgetKind::Row { .. }));
    let demo_objects = object_count(probe.scene());
    let script = format!("click {} {}\nkey delete\nsleep-ms 60000\n", row.0, row.1);
    let s1 = d.join("s1.txt");
    std::fs::write(&s1, script).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(["edit", "--script"])
        .arg(&s1)
        .args(["--size", &format!("{}x{}", SIZE.0, SIZE.1)])
        .env("ANIMED_AUTOSAVE_SECS", "1")
        .env("XDG_STATE_HOME", &state)
        .spawn()
        .expect("animed starts");
    let copy = copies.join(format!("untitled-{}.animed-recovery.wrl", child.id()));
    let t0 = Instant::now();
    while !copy.exists() {
        if let Some(st) = child.try_wait().unwrap() {
            panic!("the session ended ({st}) before autosaving");
        }
        assert!(t0.elapsed() < Duration::from_secs(40), "no copy after 40 s");
        std::thread::sleep(Duration::from_millis(50));
    }
    // Let the rename land, then SIGKILL (and reap, so the pid is gone).
    std::thread::sleep(Duration::from_millis(200));
    child.kill().unwrap();
    child.wait().unwrap();
    // An older session left behind by a process that no longer runs.
    let older = copies.join("untitled-999999999.animed-recovery.wrl");
    let mut two = Scene::new();
    two.add_node(None, animed::internals::scene::Node::group("One"));
    two.add_node(None, animed::internals::scene::Node::group("Two"));
    animed::internals::format::save(&two, &older, &Default::default()).unwrap();
    let f = std::fs::OpenOptions::new()
        .write(true)
        .open(&older)
        .unwrap();
    f.set_modified(std::time::SystemTime::now() - Duration::from_secs(3600))
        .unwrap();

    // `animed recover --list`: newest first, time and object count.
    let o = Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(["recover", "--list"])
        .env("XDG_STATE_HOME", &state)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2, "{out}");
    let n = demo_objects - 1;
    assert!(lines[0].starts_with("1  "), "{out}");
    assert!(lines[0].contains(&format!("{n} objects")), "{out}");
    assert!(lines[0].contains(&copy.display().to_string()), "{out}");
    assert!(lines[0].contains("s ago"), "{out}");
    assert!(
        lines[1].starts_with("2  ") && lines[1].contains("2 objects"),
        "{out}"
    );
    assert!(lines[1].contains("60 min ago"), "{out}");

    // The next start offers both, the newest marked.
    let mut ed = Editor::with_demo(SIZE.0, SIZE.1);
    // What the shell tells every session (`cli/edit.rs::tell_places`).
    ed.set_pid(std::process::id());
    ed.set_wall_clock(std::time::SystemTime::now());
    assert_eq!(ed.offer_untitled(&copies), 2);
    let dlg = ed.dialog().expect("the recovery list").clone();
    assert_eq!(dlg.then, After::Recover);
    let shown: Vec<&str> = dlg.message.lines().collect();
    assert!(shown[1].starts_with("> 1  ") && shown[1].contains(&format!("{n} objects")));
    assert!(shown[2].starts_with("  2  ") && shown[2].contains("2 objects"));
    let labels: Vec<String> = dlg
        .widgets(ed.layout().window)
        .into_iter()
        .filter_map(|w| match w.kind {
            WidgetKind::Button { label, .. } => Some(label),
            _ => None,
        })
        .collect();
    assert_eq!(labels, ["Not now", "Discard copy", "Recover"]);
    // Down marks the older one, Up the newer again.
    key(&mut ed, Key::Down);
    assert!(ed.dialog().unwrap().message.contains("> 2  "));
    key(&mut ed, Key::Up);
    assert!(ed.dialog().unwrap().message.contains("> 1  "));
    key(&mut ed, Key::Enter);
    assert!(ed.dialog().is_none());
    assert_eq!(object_count(ed.scene()), n, "the killed session's work");
    assert_eq!(ed.path(), None, "still untitled");
    assert!(ed.is_dirty(), "recovered work is unsaved");
    assert!(ed.status().text.contains("Recovered"), "{:?}", ed.status());
    assert!(!copy.exists(), "taken over by this session");
    let mine = copies.join(format!(
        "untitled-{}.animed-recovery.wrl",
        std::process::id()
    ));
    assert!(mine.exists());
    assert!(older.exists(), "the other session is kept");
    // Saving under a name deletes this session's copy.
    ed.save_to(&d.join("saved.wrl")).unwrap();
    assert!(!mine.exists());

    // Not now keeps the rest; Discard copy deletes the marked one.
    let mut ed = Editor::with_demo(SIZE.0, SIZE.1);
    assert_eq!(ed.offer_untitled(&copies), 1);
    key(&mut ed, Key::Escape);
    assert!(ed.dialog().is_none() && older.exists());
    assert!(
        ed.status().text.contains("recover --list"),
        "{:?}",
        ed.status()
    );
    let mut ed = Editor::with_demo(SIZE.0, SIZE.1);
    ed.offer_untitled(&copies);
    key(&mut ed, Key::Char('d'));
    assert!(!older.exists() && ed.dialog().is_none());
    let mut ed = Editor::with_demo(SIZE.0, SIZE.1);
    assert_eq!(ed.offer_untitled(&copies), 0);
    assert!(ed.dialog().is_none(), "nothing left to offer");
    std::fs::remove_dir_all(&d).unwrap();
}

/// Recovered untitled work comes back with the view it was autosaved
/// with (it came back framed tightly on its objects before), not a fresh
/// view-all.
#[test]
fn recovered_untitled_work_comes_back_with_its_view() {
    let d = dir("untitled-view");
    let copies = d.join("animed");
    let views = d.join("views");
    let mut ed = Editor::new(Scene::new(), None, SIZE.0, SIZE.1);
    ed.set_view_memory(Some(views.clone()));
    ed.set_pid(std::process::id());
    assert_eq!(ed.offer_untitled(&copies), 0, "nothing to offer yet");
    // A box, then the top view zoomed out: work and a view of its own.
    key_with(&mut ed, Key::Char('a'), Mods::shift());
    key(&mut ed, Key::Enter);
    assert_eq!(object_count(ed.scene()), 1);
    key(&mut ed, Key::Num(7));
    for _ in 0..3 {
        shell::handle(
            &mut ed,
            Event::Wheel {
                delta: -1.0,
                x: 100.0,
                y: 100.0,
                mods: Mods::NONE,
            },
        );
    }
    let seen = *ed.camera();
    let copy = ed.autosave_now().expect("the copy is written");
    // The next session recovers the copy.
    let mut again = Editor::new(Scene::new(), None, SIZE.0, SIZE.1);
    again.set_view_memory(Some(views.clone()));
    again.offer_untitled(&copies);
    assert_ne!(*again.camera(), seen);
    again.recover_untitled(&copy);
    assert_eq!(object_count(again.scene()), 1, "the work is back");
    assert_eq!(*again.camera(), seen, "and the view it was seen with");
    // Without a remembered view it is framed as before.
    let mut plain = Editor::new(Scene::new(), None, SIZE.0, SIZE.1);
    plain.offer_untitled(&copies);
    plain.recover_untitled(&copy);
    assert_ne!(*plain.camera(), seen);
    std::fs::remove_dir_all(&d).unwrap();
}

/// The status line says when an autosave happened.
#[test]
fn the_status_line_shows_autosaves() {
    let d = dir("status");
    let scene = demo_file(&d);
    let loaded = animed::internals::format::load(&scene).unwrap();
    let mut ed = Editor::new(loaded.scene, Some(scene.clone()), SIZE.0, SIZE.1);
    ed.set_autosave_interval(Some(1.0));
    ed.select(Some(NodeId(0)));
    key(&mut ed, Key::Char('k'));
    shell::handle(&mut ed, Event::Tick { time: 1.0 });
    assert!(
        shell::handle(&mut ed, Event::Tick { time: 2.5 }),
        "redraws the status"
    );
    let t = &ed.status().text;
    assert!(t.starts_with("Autosaved unsaved changes at "), "{t}");
    assert!(
        t.contains("UTC") && t.contains(".scene.wrl.animed-recovery.wrl"),
        "{t}"
    );
    std::fs::remove_dir_all(&d).unwrap();
}
