//! The only module that touches the window system (minifb): it turns window
//! input into editor [`Event`]s, shows the frames the editor draws, and
//! sleeps between polls when nothing happens so an idle editor costs close
//! to no CPU.

mod keymap;

pub use crate::input::Screen;

use crate::input::{Event, Mods, MouseButton};
use crate::render::Frame;
use minifb::{MouseMode, Window, WindowOptions};
use std::cell::RefCell;
use std::rc::Rc;
use std::time::{Duration, Instant, SystemTime};

/// Poll interval while something moves (playback, drags) and when idle.
const ACTIVE_POLL: Duration = Duration::from_millis(8);
const IDLE_POLL: Duration = Duration::from_millis(20);
/// Poll interval while a frame is being drawn (a quick click lasts
/// 30-100 ms).
const POLL_WHILE_DRAWING: Duration = Duration::from_millis(4);
/// How long after the last input the loop stays in the fast poll.
const ACTIVE_FOR: Duration = Duration::from_millis(500);
/// Longest gap between `Tick`s for a screen that wants a clock (autosave).
const CLOCK_EVERY: Duration = Duration::from_secs(1);

/// What minifb's input callback saw since the last poll, in order. Key
/// edges come from here rather than from `get_keys_pressed`, which misses a
/// press and release that both happen between two polls (xdotool does that).
/// Characters and keys share one queue: text typed just before Enter in
/// the same poll must reach the field before the Enter does (a fast
/// `2*24⏎` otherwise set `2*2`).
#[derive(Default)]
struct Typed {
    inputs: Vec<Input>,
}

/// One item of [`Typed`].
enum Input {
    Char(char),
    Key(minifb::Key, bool),
}

struct Sink(Rc<RefCell<Typed>>);

impl minifb::InputCallback for Sink {
    fn add_char(&mut self, c: u32) {
        if let Some(ch) = char::from_u32(c) {
            if !ch.is_control() {
                self.0.borrow_mut().inputs.push(Input::Char(ch));
            }
        }
    }

    fn set_key_state(&mut self, key: minifb::Key, down: bool) {
        self.0.borrow_mut().inputs.push(Input::Key(key, down));
    }
}

/// Opens the window and runs the editor (or the viewer) until it quits or
/// the window closes.
pub fn run<S: Screen + Send>(mut ed: S) -> Result<(), String> {
    if std::env::var_os("DISPLAY").is_none() && std::env::var_os("WAYLAND_DISPLAY").is_none() {
        return Err(no_display("DISPLAY is not set"));
    }
    let (w, h) = ed.size();
    let typed = Rc::new(RefCell::new(Typed::default()));
    let mut window =
        open_window("animed", (w as usize, h as usize), &typed).map_err(|e| no_display(&e))?;

    let start = Instant::now();
    let mut frame = Frame::new(w, h, glam::Vec3::ZERO);
    let mut input = Polled {
        size: (w as usize, h as usize),
        mouse: (-1.0, -1.0),
        buttons: [false; 3],
        mods: Mods::NONE,
    };
    let mut last_input = Instant::now();
    let mut last_tick = Instant::now();
    let mut dirty = true;
    let mut title = String::from("animed");
    // Input seen while a frame was drawn, handled before the next poll's.
    let mut pending: Vec<Event> = Vec::new();

    while !ed.wants_quit() {
        if !window.is_open() {
            // minifb cannot refuse a close. With unsaved changes the screen
            // asks first: a fresh window shows the question (a second close
            // while it is shown really closes; see `window_closed`).
            if !ed.close_requested() {
                break;
            }
            match open_window(&title, input.size, &typed) {
                Ok(win) => window = win,
                Err(_) => break,
            }
            (input.mods, input.buttons, dirty) = (Mods::NONE, [false; 3], true);
            continue;
        }
        let mut events = std::mem::take(&mut pending);
        input.poll(&window, &typed, &mut events);
        // The screen reads no clock: the loop tells it the time.
        ed.set_wall_clock(SystemTime::now());
        if !events.is_empty() {
            last_input = Instant::now();
        }
        for ev in events {
            // Each event's file work before the next event sees the state.
            dirty |= ed.handle(ev);
            dirty |= ed.perform();
        }
        // Playback ticks every pass; the autosave clock at least once a second.
        if ed.wants_ticks() || (ed.wants_clock() && last_tick.elapsed() >= CLOCK_EVERY) {
            last_tick = Instant::now();
            dirty |= ed.handle(Event::Tick {
                time: start.elapsed().as_secs_f64(),
            });
        }
        // The file work the events asked for (the screen only asks), then
        // whatever was asked before the first event (the view memory).
        dirty |= ed.perform();
        let t = ed.window_title();
        if t != title {
            window.set_title(&t);
            title = t;
        }
        if dirty {
            // The window is polled while the frame is drawn: minifb keeps
            // only the buttons' state, so a click pressed and released
            // within one slow frame would otherwise be lost.
            std::thread::scope(|s| {
                let drawing = s.spawn(|| ed.draw(&mut frame));
                while !drawing.is_finished() {
                    std::thread::sleep(POLL_WHILE_DRAWING);
                    window.update();
                    input.poll(&window, &typed, &mut pending);
                }
                drawing.join()
            })
            .map_err(|_| "drawing the frame failed".to_string())?;
            window
                .update_with_buffer(&frame.color, frame.width as usize, frame.height as usize)
                .map_err(|e| format!("cannot show the frame: {e}"))?;
            dirty = false;
        } else {
            // Pump window events only.
            window.update();
        }
        let busy = ed.wants_ticks() || last_input.elapsed() < ACTIVE_FOR;
        std::thread::sleep(if busy { ACTIVE_POLL } else { IDLE_POLL });
    }
    // minifb cannot refuse a close: unsaved work goes to the recovery copy.
    if let Some(msg) = ed.window_closed() {
        eprintln!("animed: {msg}");
    }
    Ok(())
}

/// The window input as of the last poll, so each poll turns changes into
/// events.
struct Polled {
    size: (usize, usize),
    mouse: (f32, f32),
    buttons: [bool; 3],
    /// Modifier keys held, from the key callback's edges.
    mods: Mods,
}

impl Polled {
    /// Appends the events since the last poll: a resize, a mouse move,
    /// button edges, the wheel, then the keys and text typed, in order.
    fn poll(&mut self, window: &Window, typed: &Rc<RefCell<Typed>>, events: &mut Vec<Event>) {
        let Typed { inputs } = std::mem::take(&mut *typed.borrow_mut());
        // Modifier level as of the start of this batch, for mouse events.
        let mods = self.mods;
        let now_size = window.get_size();
        if now_size != self.size && now_size.0 > 0 && now_size.1 > 0 {
            self.size = now_size;
            events.push(Event::Resize {
                width: now_size.0 as u32,
                height: now_size.1 as u32,
            });
        }
        if let Some((x, y)) = window.get_mouse_pos(MouseMode::Pass) {
            if (x, y) != self.mouse {
                self.mouse = (x, y);
                events.push(Event::MouseMove { x, y, mods });
            }
        }
        for (i, (mb, button)) in [
            (minifb::MouseButton::Left, MouseButton::Left),
            (minifb::MouseButton::Middle, MouseButton::Middle),
            (minifb::MouseButton::Right, MouseButton::Right),
        ]
        .into_iter()
        .enumerate()
        {
            let down = window.get_mouse_down(mb);
            if down != self.buttons[i] {
                self.buttons[i] = down;
                let (x, y) = self.mouse;
                events.push(if down {
                    Event::MouseDown { button, x, y, mods }
                } else {
                    Event::MouseUp { button, x, y, mods }
                });
            }
        }
        if let Some((_, dy)) = window.get_scroll_wheel() {
            if dy != 0.0 {
                events.push(Event::Wheel {
                    delta: dy.signum() * (dy.abs() / 3.0).clamp(1.0, 5.0),
                    x: self.mouse.0,
                    y: self.mouse.1,
                    mods,
                });
            }
        }
        typed_events(inputs, &mut self.mods, events);
    }
}

/// The key and text events of one poll's `inputs`, in the order they were
/// typed: characters gather into one `Text` until the next key edge (so
/// text typed before Enter reaches the field first). Text typed while
/// Ctrl or Alt is held is a shortcut's, not text, and is dropped.
fn typed_events(inputs: Vec<Input>, mods: &mut Mods, events: &mut Vec<Event>) {
    let mut text = String::new();
    let flush = |text: &mut String, events: &mut Vec<Event>| {
        if !text.is_empty() {
            events.push(Event::Text(std::mem::take(text)));
        }
    };
    for input in inputs {
        let (k, down) = match input {
            Input::Char(c) => {
                if !mods.ctrl && !mods.alt {
                    text.push(c);
                }
                continue;
            }
            Input::Key(k, down) => (k, down),
        };
        use minifb::Key as K;
        match k {
            K::LeftCtrl | K::RightCtrl => mods.ctrl = down,
            K::LeftShift | K::RightShift => mods.shift = down,
            K::LeftAlt | K::RightAlt => mods.alt = down,
            _ => {}
        }
        if let Some(key) = keymap::key(k) {
            flush(&mut text, events);
            events.push(if down {
                Event::KeyDown { key, mods: *mods }
            } else {
                Event::KeyUp { key, mods: *mods }
            });
        }
    }
    flush(&mut text, events);
}

/// A resizable window whose input goes to `typed`, paced by the caller.
fn open_window(
    title: &str,
    (w, h): (usize, usize),
    typed: &Rc<RefCell<Typed>>,
) -> Result<Window, String> {
    let opts = WindowOptions {
        resize: true,
        ..WindowOptions::default()
    };
    // minifb reports a missing X server or libraries as an error; guard
    // against a panic in its C glue as well.
    let window = std::panic::catch_unwind(|| Window::new(title, w, h, opts));
    let mut window = match window {
        Ok(Ok(win)) => win,
        Ok(Err(e)) => return Err(e.to_string()),
        Err(_) => return Err("the window system failed".into()),
    };
    // We pace the loop ourselves.
    window.set_target_fps(0);
    window.set_input_callback(Box::new(Sink(typed.clone())));
    Ok(window)
}

fn no_display(why: &str) -> String {
    format!(
        "cannot open a window ({why}). The editor needs an X display; \
         without one use `animed render` to draw a scene to PNG, or \
         `animed edit --script FILE --screenshot OUT.png` for a headless session"
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Key;

    #[test]
    fn text_typed_before_enter_in_one_poll_comes_first() {
        let mut mods = Mods::NONE;
        let mut ev = Vec::new();
        let inputs = vec![
            Input::Char('2'),
            Input::Char('*'),
            Input::Char('2'),
            Input::Char('4'),
            Input::Key(minifb::Key::Enter, true),
            Input::Key(minifb::Key::Enter, false),
            Input::Char('x'),
        ];
        typed_events(inputs, &mut mods, &mut ev);
        let m = Mods::NONE;
        assert_eq!(
            ev,
            vec![
                Event::Text("2*24".into()),
                Event::KeyDown {
                    key: Key::Enter,
                    mods: m
                },
                Event::KeyUp {
                    key: Key::Enter,
                    mods: m
                },
                Event::Text("x".into()),
            ]
        );
        // Characters typed with Ctrl held are a shortcut's, not text.
        let mut ev = Vec::new();
        let inputs = vec![
            Input::Char('a'),
            Input::Key(minifb::Key::LeftCtrl, true),
            Input::Char('s'),
            Input::Key(minifb::Key::S, true),
        ];
        typed_events(inputs, &mut mods, &mut ev);
        assert_eq!(ev[0], Event::Text("a".into()));
        assert!(!ev.iter().any(|e| *e == Event::Text("s".into())), "{ev:?}");
        assert!(mods.ctrl);
    }
}
