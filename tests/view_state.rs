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

/// The clip key (issue 13 item 3): C / Shift+C cycle the file's clips,
/// the clock takes the clip's length and the corner names the clip.
mod clips {
    use super::*;
    use animed::internals::anim::{Animation, Key as AKey, Keys, Property, Repeat};
    use animed::internals::anim::{Target, TargetRef, Track};
    use animed::internals::scene::{Clip, Node, Scene};
    use glam::Vec3;

    fn three_clips() -> Viewer {
        let mut s = Scene::new();
        let n = s.add_node(None, Node::group("Ball"));
        let clips = ["Walk", "Run", "Idle"]
            .iter()
            .enumerate()
            .map(|(i, name)| {
                let keys = Keys::Vec3(vec![
                    AKey::new(0.0, Vec3::ZERO),
                    AKey::new(5.0 * (i + 1) as f32, Vec3::X),
                ]);
                let target = Target {
                    of: TargetRef::Node(n),
                    property: Property::Translation,
                };
                Clip {
                    name: name.to_string(),
                    animation: Animation {
                        tracks: vec![Track::new(target, Repeat::Constant, keys).unwrap()],
                    },
                    duration: 10.0 * (i + 1) as f32,
                }
            })
            .collect();
        s.set_clips(clips, 0);
        s.settings.fps = 10.0;
        let opts = ViewerOptions {
            width: 320,
            height: 240,
            ..ViewerOptions::default()
        };
        Viewer::new(s, &opts).expect("viewer")
    }

    fn shift_c(v: &mut Viewer) -> bool {
        v.handle(Event::KeyDown {
            key: Key::Char('c'),
            mods: Mods {
                shift: true,
                ..Mods::NONE
            },
        })
    }

    #[test]
    fn c_cycles_clips_and_the_clock_follows() {
        let mut v = three_clips();
        assert_eq!(v.clip_label().as_deref(), Some("Walk (1/3)"));
        assert_eq!(v.clock().length(), 10);
        assert_eq!(v.key_times(), &[0.0, 0.5]);
        assert!(key(&mut v, Key::Char('c')));
        assert_eq!(v.clip_label().as_deref(), Some("Run (2/3)"));
        assert_eq!(
            v.clock().length(),
            20,
            "the clock plays the new clip's length"
        );
        assert_eq!(v.key_times(), &[0.0, 1.0], "key marks of the new clip");
        assert_eq!(v.clock().frame(), 0);
        key(&mut v, Key::Char('c'));
        key(&mut v, Key::Char('c'));
        assert_eq!(v.clip_label().as_deref(), Some("Walk (1/3)"), "wraps");
        assert!(shift_c(&mut v));
        assert_eq!(v.clip_label().as_deref(), Some("Idle (3/3)"));
        // Paused stays paused.
        key(&mut v, Key::Space);
        key(&mut v, Key::Char('c'));
        assert!(!v.clock().is_playing());
        // The name is drawn in the corner (text pixels in the top rows).
        let mut frame = Frame::new(1, 1, glam::Vec3::ZERO);
        v.draw(&mut frame);
        // The scene is one empty group on black: bright pixels are text.
        let lit = frame.color[..20 * 320]
            .iter()
            .filter(|&&c| (c >> 16) & 0xff > 0x80)
            .count();
        assert!(lit > 100, "{lit} text pixels at the top");
    }

    #[test]
    fn a_scene_without_named_clips_ignores_c() {
        let mut v = demo();
        assert_eq!(v.clip_label(), None);
        assert!(!key(&mut v, Key::Char('c')));
        let mut frame = Frame::new(1, 1, glam::Vec3::ZERO);
        v.draw(&mut frame);
    }
}
