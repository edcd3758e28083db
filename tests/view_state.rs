//! `animed view` without a window: the viewer state machine driven by
//! events, as the window loop drives it.

use animed::internals::editor::{Event, Key, Mods, MouseButton};
use animed::internals::render::job::Headlight;
use animed::internals::render::Frame;
use animed::internals::viewer::{Eye, Viewer, ViewerOptions};

fn demo() -> Viewer {
    let scene = animed::internals::format::demo().expect("demo loads").scene;
    let opts = ViewerOptions {
        width: 320,
        height: 240,
        headlight: Headlight::Auto,
        ..ViewerOptions::default()
    };
    Viewer::new(scene, &opts).expect("viewer")
}

fn key(v: &mut Viewer, k: Key) -> bool {
    v.handle(Event::KeyDown {
        key: k,
        mods: Mods::NONE,
    })
}

#[test]
fn plays_in_real_time_pauses_and_steps() {
    let mut v = demo();
    let fps = v.scene().settings.fps as f64;
    assert!(v.clock().is_playing());
    v.handle(Event::Tick { time: 10.0 });
    // Half a second later: half a second of frames, however few ticks came.
    assert!(v.handle(Event::Tick { time: 10.5 }));
    assert_eq!(v.clock().frame(), (0.5 * fps).floor() as u64);
    key(&mut v, Key::Space);
    assert!(!v.clock().is_playing());
    let held = v.clock().frame();
    v.handle(Event::Tick { time: 20.0 });
    assert_eq!(v.clock().frame(), held);
    key(&mut v, Key::Right);
    key(&mut v, Key::Right);
    key(&mut v, Key::Left);
    assert_eq!(v.clock().frame(), held + 1);
    // Loops: a full loop later the same frame shows again.
    key(&mut v, Key::Space);
    v.handle(Event::Tick { time: 30.0 });
    let f0 = v.clock().frame();
    v.handle(Event::Tick {
        time: 30.0 + v.clock().loop_seconds(),
    });
    assert_eq!(v.clock().frame(), f0);
}

#[test]
fn key_times_of_every_track_are_collected() {
    let v = demo();
    let s = v.scene();
    assert!(!s.animation.tracks.is_empty());
    let fps = s.settings.fps;
    for t in &s.animation.tracks {
        for f in t.keys.frames() {
            let secs = f / fps;
            assert!(v.key_times().iter().any(|&k| (k - secs).abs() < 1e-6));
        }
    }
    assert!(v.key_times().windows(2).all(|w| w[0] < w[1]));
}

#[test]
fn headlight_and_viewpoints_cycle() {
    let mut v = demo();
    let h = v.headlight();
    key(&mut v, Key::Char('h'));
    assert_eq!(v.headlight(), !h);
    let cams = v
        .scene()
        .nodes
        .iter()
        .filter(|n| n.camera().is_some())
        .count();
    if cams == 0 {
        assert_eq!(*v.eye(), Eye::ViewAll);
        key(&mut v, Key::PageDown);
        assert_eq!(*v.eye(), Eye::ViewAll);
    } else {
        assert_eq!(*v.eye(), Eye::Viewpoint(0));
        key(&mut v, Key::PageDown);
        assert_eq!(*v.eye(), Eye::Viewpoint(1 % cams));
        key(&mut v, Key::PageUp);
        assert_eq!(*v.eye(), Eye::Viewpoint(0));
    }
    // A drag turns the view into a free orbit camera; Home goes back.
    let fixed = v.eye().clone();
    v.handle(Event::MouseDown {
        button: MouseButton::Left,
        x: 100.0,
        y: 100.0,
        mods: Mods::NONE,
    });
    assert!(v.handle(Event::MouseMove {
        x: 140.0,
        y: 110.0,
        mods: Mods::NONE
    }));
    assert!(matches!(v.eye(), Eye::Orbit(_)));
    key(&mut v, Key::Home);
    assert_eq!(*v.eye(), fixed);
}

#[test]
fn an_unknown_viewpoint_is_an_error_naming_the_choices() {
    let scene = animed::internals::format::demo().unwrap().scene;
    let opts = ViewerOptions {
        viewpoint: Some("nowhere".into()),
        ..ViewerOptions::default()
    };
    let e = Viewer::new(scene, &opts).err().expect("an error");
    assert!(e.contains("nowhere"), "{e}");
}

#[test]
fn scrubbing_the_bar_seeks_and_draw_shows_scene_and_bar() {
    let mut v = demo();
    let (w, h) = v.size();
    // Click three quarters along the bar (it sits at the bottom).
    let x = 10.0 + 0.75 * (w as f32 - 20.0);
    v.handle(Event::MouseDown {
        button: MouseButton::Left,
        x,
        y: h as f32 - 10.0,
        mods: Mods::NONE,
    });
    let want = (0.75 * v.clock().loop_seconds() * v.clock().fps()).round() as u64;
    assert_eq!(v.clock().frame(), want);
    assert!(!v.clock().is_playing(), "paused while scrubbing");
    v.handle(Event::MouseUp {
        button: MouseButton::Left,
        x,
        y: h as f32 - 10.0,
        mods: Mods::NONE,
    });
    assert!(v.clock().is_playing(), "plays again after the scrub");
    let mut frame = Frame::new(1, 1, glam::Vec3::ZERO);
    v.draw(&mut frame);
    assert_eq!((frame.width, frame.height), (w, h));
    // The scene area is the render of that time through the same camera:
    // compare its top rows with render_at at the clock's time.
    let spec = animed::internals::render::job::FrameSpec {
        width: w,
        height: h - 40,
        ..Default::default()
    };
    let alone =
        animed::internals::render::job::render_at(v.scene(), &spec, v.clock().time()).unwrap();
    let rows = 60 * w as usize;
    assert_eq!(&frame.color[..rows], &alone.color[..rows]);
    // The bar fills the bottom rows (its panel colour, text aside).
    let bar_row = (h as usize - 2) * w as usize;
    let panel = frame.color[bar_row..bar_row + w as usize]
        .iter()
        .filter(|&&c| c == animed::internals::ui::theme::PANEL_DARK)
        .count();
    assert!(panel > w as usize / 2, "{panel} of {w} bar pixels");
}

#[test]
fn quit_keys() {
    let mut v = demo();
    assert!(!v.wants_quit());
    key(&mut v, Key::Escape);
    assert!(v.wants_quit());
}

#[test]
fn without_a_display_view_says_so_and_fails() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_animed"))
        .arg("view")
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("run animed");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("no display"), "{err}");
    assert!(err.contains("animed render"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
