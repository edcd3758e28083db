//! Headless sessions: a line-based script of input events fed to the same
//! [`Editor`] the window uses (`animed edit --script FILE`).
//!
//! ```text
//! # comment (also after a command)
//! key ctrl+n                 key press (+ release); mods: ctrl, shift, alt
//! type 2.5                   text typed (the rest of the line, verbatim)
//! click X Y [BUTTON]         press + release at window pixel X Y
//! drag X1 Y1 X2 Y2 [BUTTON]  press at 1, move in steps, release at 2
//! move X Y                   mouse move
//! wheel N [X Y]              N wheel notches (positive zooms in)
//! wait-frames N              N ticks of 1/fps seconds (playback advances)
//! sleep-ms N                 N real milliseconds, a tick every 100 ms
//!                            (session time advances by the real time slept:
//!                            autosave fires; another process can watch)
//! resize W H                 window resized
//! screenshot OUT.png         the window as it looks now, written as a PNG
//! click-key ROW F [MODS]     click the key strip marker at frame F of ROW
//!                            (`summary` or a property: `translation`, ...)
//! drag-key ROW F TO [MODS]   drag that marker to frame TO (`alt` scales)
//! click-field NAME           click the panel field NAME (`Translation(0)`,
//!                            `Key(Tension)`, `Key(Frame)`, ...)
//! select NAME                click the object's or light's list row (DEF
//!                            name; selected directly when scrolled away)
//! drag-handle H DX DY [MODS] drag handle H of the current tool (W/E/T) by
//!                            DX DY pixels: `x` `y` `z`, `xy` `xz` `yz`,
//!                            `view`, `uniform`, `body`
//! click-curve-key CH F [MODS]           click the graph editor's key of
//!                            channel CH (`translation.y`, `rotation.z`,
//!                            `color.g`, `intensity`, `weights.2`: morph
//!                            target 2) of the selection at F
//! drag-curve-key CH F DX DY [MODS]      drag that key by DX DY pixels
//!                            (`ctrl` snaps to whole frames)
//! drag-curve-handle CH F DX DY [MODS]   drag the tangent handle of that
//!                            (selected) key by DX DY (`alt`: continuity)
//! ```
//! BUTTON is `left` (default), `middle` or `right`, optionally with
//! modifiers: `alt+left`, `shift+middle`.

use super::Editor;
use crate::input::{Event, Key, Mods, MouseButton};
use std::fmt;
use std::path::{Path, PathBuf};

/// A script error at `path:line:column`.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptError {
    pub path: PathBuf,
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl fmt::Display for ScriptError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}",
            self.path.display(),
            self.line,
            self.column,
            self.message
        )
    }
}

impl std::error::Error for ScriptError {}

/// Steps of a drag between its end points.
const DRAG_STEPS: usize = 8;
/// Largest window a script may ask for.
const MAX_SIDE: u32 = 4096;
/// Largest wait (frames or milliseconds), so a typo cannot hang a session.
const MAX_WAIT: u64 = 100_000;
/// The latest `clock` a script may set (seconds since 1970: year 5138).
const MAX_CLOCK: u64 = 100_000_000_000;
/// How often `sleep-ms` ticks.
const SLEEP_SLICE: std::time::Duration = std::time::Duration::from_millis(100);

/// One parsed line.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    Key(Key, Mods),
    Type(String),
    Click(f32, f32, MouseButton, Mods),
    Drag(f32, f32, f32, f32, MouseButton, Mods),
    Move(f32, f32),
    Wheel(f32, Option<(f32, f32)>),
    WaitFrames(u64),
    SleepMs(u64),
    /// Sets the wall clock to these seconds since 1970 (UTC).
    Clock(u64),
    Resize(u32, u32),
    /// Saves the current window picture (relative paths: the working
    /// directory, as `--screenshot`).
    Screenshot(PathBuf),
    /// A key strip marker: row, frame, drag destination frame, modifiers.
    KeyMarker(super::keystrip::Row, f32, Option<f32>, Mods),
    /// A side panel field by its `FieldId` debug name.
    ClickField(String),
    /// Fails unless the status line holds this text (scripted checks).
    ExpectStatus(String),
    /// A node by name, through its list row.
    Select(String),
    /// A handle of the current tool by name, dragged by (dx, dy) pixels.
    DragHandle(String, f32, f32, Mods),
    /// A graph editor key (or with `handle` its tangent handle): channel,
    /// frame, drag by (dx, dy) pixels or a click, modifiers.
    CurveKey {
        channel: String,
        frame: f32,
        by: Option<(f32, f32)>,
        handle: bool,
        mods: Mods,
    },
}

/// Parses a whole script; `path` names it in errors.
pub fn parse(text: &str, path: &Path) -> Result<Vec<(usize, Step)>, ScriptError> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let err = |col: usize, msg: String| ScriptError {
            path: path.to_path_buf(),
            line,
            column: col,
            message: msg,
        };
        let indent = raw.len() - raw.trim_start().len();
        let body = raw.trim_start();
        let (cmd, rest) = body.split_once(char::is_whitespace).unwrap_or((body, ""));
        if cmd.is_empty() || cmd.starts_with('#') {
            continue;
        }
        // `type` keeps its text verbatim (a '#' in it is text).
        if cmd == "type" {
            out.push((line, Step::Type(rest.to_string())));
            continue;
        }
        if cmd == "expect-status" {
            let text = rest.trim();
            if text.is_empty() {
                return Err(err(
                    indent + cmd.len() + 2,
                    "'expect-status' needs the text the status line should hold".into(),
                ));
            }
            out.push((line, Step::ExpectStatus(text.to_string())));
            continue;
        }
        let rest = rest.split('#').next().unwrap_or("");
        let args_col = indent + cmd.len() + 2;
        let args: Vec<&str> = rest.split_whitespace().collect();
        let col_of = |k: usize| -> usize {
            // Column of the k-th argument (1-based columns).
            let mut pos = 0;
            for (j, a) in rest.split_whitespace().enumerate() {
                let off = rest[pos..].find(a).unwrap_or(0) + pos;
                if j == k {
                    return indent + cmd.len() + 1 + off + 1;
                }
                pos = off + a.len();
            }
            args_col
        };
        let num = |k: usize| -> Result<f32, ScriptError> {
            let a = args
                .get(k)
                .ok_or_else(|| err(col_of(k), format!("'{cmd}' needs more arguments")))?;
            a.parse::<f32>()
                .ok()
                .filter(|x| x.is_finite() && x.abs() < 1e6)
                .ok_or_else(|| err(col_of(k), format!("'{a}' is not a number")))
        };
        let count = |k: usize, max: u64| -> Result<u64, ScriptError> {
            let a = args
                .get(k)
                .ok_or_else(|| err(col_of(k), format!("'{cmd}' needs more arguments")))?;
            a.parse::<u64>()
                .ok()
                .filter(|&n| n <= max)
                .ok_or_else(|| err(col_of(k), format!("'{a}' is not a count up to {max}")))
        };
        let want = |n: std::ops::RangeInclusive<usize>| -> Result<(), ScriptError> {
            if n.contains(&args.len()) {
                Ok(())
            } else {
                Err(err(
                    args_col,
                    format!(
                        "'{cmd}' takes {} to {} arguments, got {}",
                        n.start(),
                        n.end(),
                        args.len()
                    ),
                ))
            }
        };
        let button = |k: usize| -> Result<(MouseButton, Mods), ScriptError> {
            match args.get(k) {
                None => Ok((MouseButton::Left, Mods::NONE)),
                Some(a) => parse_button(a).ok_or_else(|| {
                    err(
                        col_of(k),
                        format!(
                            "unknown button '{a}' (left, middle, right, with alt+/shift+/ctrl+)"
                        ),
                    )
                }),
            }
        };
        let step = match cmd {
            "key" => {
                want(1..=1)?;
                let (k, m) = parse_key(args[0])
                    .ok_or_else(|| err(col_of(0), format!("unknown key '{}'", args[0])))?;
                Step::Key(k, m)
            }
            "click" => {
                want(2..=3)?;
                let (b, m) = button(2)?;
                Step::Click(num(0)?, num(1)?, b, m)
            }
            "drag" => {
                want(4..=5)?;
                let (b, m) = button(4)?;
                Step::Drag(num(0)?, num(1)?, num(2)?, num(3)?, b, m)
            }
            "move" => {
                want(2..=2)?;
                Step::Move(num(0)?, num(1)?)
            }
            "wheel" => {
                if args.len() != 1 && args.len() != 3 {
                    return Err(err(args_col, "'wheel' takes N or N X Y".into()));
                }
                let at = if args.len() == 3 {
                    Some((num(1)?, num(2)?))
                } else {
                    None
                };
                Step::Wheel(num(0)?, at)
            }
            "wait-frames" => {
                want(1..=1)?;
                Step::WaitFrames(count(0, MAX_WAIT)?)
            }
            "sleep-ms" => {
                want(1..=1)?;
                Step::SleepMs(count(0, MAX_WAIT)?)
            }
            "clock" => {
                want(1..=1)?;
                Step::Clock(count(0, MAX_CLOCK)?)
            }
            "resize" => {
                want(2..=2)?;
                let w = count(0, MAX_SIDE as u64)? as u32;
                let h = count(1, MAX_SIDE as u64)? as u32;
                if w < 16 || h < 16 {
                    return Err(err(args_col, "window must be at least 16x16".into()));
                }
                Step::Resize(w, h)
            }
            "screenshot" => {
                want(1..=1)?;
                Step::Screenshot(PathBuf::from(args[0]))
            }
            "click-key" | "drag-key" => {
                let n = if cmd == "drag-key" { 3 } else { 2 };
                want(n..=n + 1)?;
                let row = parse_row(args[0]).ok_or_else(|| {
                    err(
                        col_of(0),
                        format!("unknown key strip row '{}' (summary or a property)", args[0]),
                    )
                })?;
                let to = if n == 3 { Some(num(2)?) } else { None };
                let mods = match args.get(n) {
                    None => Mods::NONE,
                    Some(a) => parse_mods(&a.split('+').collect::<Vec<_>>()).ok_or_else(|| {
                        err(col_of(n), format!("unknown modifiers '{a}' (shift, alt, ctrl)"))
                    })?,
                };
                Step::KeyMarker(row, num(1)?, to, mods)
            }
            "click-field" => {
                want(1..=1)?;
                Step::ClickField(args[0].to_string())
            }
            "select" => {
                want(1..=1)?;
                Step::Select(args[0].to_string())
            }
            "drag-handle" => {
                want(3..=4)?;
                let mods = match args.get(3) {
                    None => Mods::NONE,
                    Some(a) => parse_mods(&a.split('+').collect::<Vec<_>>()).ok_or_else(|| {
                        err(col_of(3), format!("unknown modifiers '{a}' (shift, alt, ctrl)"))
                    })?,
                };
                Step::DragHandle(args[0].to_string(), num(1)?, num(2)?, mods)
            }
            "click-curve-key" | "drag-curve-key" | "drag-curve-handle" => {
                let n = if cmd == "click-curve-key" { 2 } else { 4 };
                want(n..=n + 1)?;
                let mods = match args.get(n) {
                    None => Mods::NONE,
                    Some(a) => parse_mods(&a.split('+').collect::<Vec<_>>()).ok_or_else(|| {
                        err(col_of(n), format!("unknown modifiers '{a}' (shift, alt, ctrl)"))
                    })?,
                };
                Step::CurveKey {
                    channel: args[0].to_string(),
                    frame: num(1)?,
                    by: if n == 4 { Some((num(2)?, num(3)?)) } else { None },
                    handle: cmd == "drag-curve-handle",
                    mods,
                }
            }
            _ => {
                return Err(err(
                    indent + 1,
                    format!(
                        "unknown command '{cmd}' (key, type, click, drag, move, wheel, wait-frames, sleep-ms, resize, screenshot, click-key, drag-key, click-field, select, drag-handle, click-curve-key, drag-curve-key, drag-curve-handle, expect-status)"
                    ),
                ))
            }
        };
        out.push((line, step));
    }
    Ok(out)
}

/// A key strip row: `summary` or a property name.
fn parse_row(s: &str) -> Option<super::keystrip::Row> {
    use super::keystrip::Row;
    if s.eq_ignore_ascii_case("summary") {
        return Some(Row::Summary);
    }
    crate::anim::Property::parse(s).map(Row::Track)
}

/// `ctrl+shift+s` → (Char('s'), ctrl+shift).
pub fn parse_key(s: &str) -> Option<(Key, Mods)> {
    let parts: Vec<&str> = s.split('+').collect();
    // A lone "+" key, or "ctrl++".
    let (mods, key) = if s.ends_with("++") || s == "+" {
        (&parts[..parts.len().saturating_sub(2)], "+")
    } else {
        (&parts[..parts.len() - 1], *parts.last()?)
    };
    let m = parse_mods(mods)?;
    Some((Key::parse(key)?, m))
}

fn parse_mods(parts: &[&str]) -> Option<Mods> {
    let mut m = Mods::NONE;
    for p in parts {
        match p.to_ascii_lowercase().as_str() {
            "ctrl" | "control" => m.ctrl = true,
            "shift" => m.shift = true,
            "alt" => m.alt = true,
            _ => return None,
        }
    }
    Some(m)
}

fn parse_button(s: &str) -> Option<(MouseButton, Mods)> {
    let parts: Vec<&str> = s.split('+').collect();
    let m = parse_mods(&parts[..parts.len() - 1])?;
    let b = match parts.last()?.to_ascii_lowercase().as_str() {
        "left" => MouseButton::Left,
        "middle" => MouseButton::Middle,
        "right" => MouseButton::Right,
        _ => return None,
    };
    Some((b, m))
}

/// Feeds parsed steps to an editor; `clock` is the session time in seconds.
pub struct Runner {
    pub clock: f64,
    mouse: (f32, f32),
}

impl Default for Runner {
    fn default() -> Self {
        Runner {
            clock: 0.0,
            mouse: (0.0, 0.0),
        }
    }
}

impl Runner {
    /// Runs `steps`; a step that cannot be carried out (a screenshot that
    /// cannot be written) stops the session with its line. `path` names
    /// the script in errors.
    pub fn run(
        &mut self,
        ed: &mut Editor,
        steps: &[(usize, Step)],
        path: &Path,
    ) -> Result<(), ScriptError> {
        for (line, s) in steps {
            self.step(ed, s).map_err(|message| ScriptError {
                path: path.to_path_buf(),
                line: *line,
                column: 1,
                message,
            })?;
        }
        Ok(())
    }

    pub fn step(&mut self, ed: &mut Editor, s: &Step) -> Result<(), String> {
        match s {
            Step::Key(key, mods) => {
                feed(
                    ed,
                    Event::KeyDown {
                        key: *key,
                        mods: *mods,
                    },
                );
                feed(
                    ed,
                    Event::KeyUp {
                        key: *key,
                        mods: *mods,
                    },
                );
            }
            Step::Type(t) => {
                feed(ed, Event::Text(t.clone()));
            }
            Step::ExpectStatus(t) => {
                let now = &ed.status().text;
                if !now.contains(t.as_str()) {
                    return Err(format!("the status line says '{now}', not '{t}'"));
                }
            }
            Step::Move(x, y) => self.move_to(ed, *x, *y, Mods::NONE),
            Step::Click(x, y, button, mods) => {
                self.move_to(ed, *x, *y, *mods);
                feed(
                    ed,
                    Event::MouseDown {
                        button: *button,
                        x: *x,
                        y: *y,
                        mods: *mods,
                    },
                );
                feed(
                    ed,
                    Event::MouseUp {
                        button: *button,
                        x: *x,
                        y: *y,
                        mods: *mods,
                    },
                );
            }
            Step::Drag(x1, y1, x2, y2, button, mods) => {
                self.move_to(ed, *x1, *y1, *mods);
                feed(
                    ed,
                    Event::MouseDown {
                        button: *button,
                        x: *x1,
                        y: *y1,
                        mods: *mods,
                    },
                );
                for k in 1..=DRAG_STEPS {
                    let t = k as f32 / DRAG_STEPS as f32;
                    self.move_to(ed, x1 + (x2 - x1) * t, y1 + (y2 - y1) * t, *mods);
                }
                feed(
                    ed,
                    Event::MouseUp {
                        button: *button,
                        x: *x2,
                        y: *y2,
                        mods: *mods,
                    },
                );
            }
            Step::Wheel(n, at) => {
                let (x, y) = at.unwrap_or(self.mouse);
                if at.is_some() {
                    self.move_to(ed, x, y, Mods::NONE);
                }
                feed(
                    ed,
                    Event::Wheel {
                        delta: *n,
                        x,
                        y,
                        mods: Mods::NONE,
                    },
                );
            }
            Step::WaitFrames(n) => {
                let dt = 1.0 / ed.scene().settings.fps.max(1.0) as f64;
                for _ in 0..*n {
                    self.clock += dt;
                    feed(ed, Event::Tick { time: self.clock });
                }
            }
            Step::Clock(secs) => {
                let t = std::time::UNIX_EPOCH + std::time::Duration::from_secs(*secs);
                ed.set_wall_clock(t);
            }
            Step::SleepMs(ms) => {
                // Real time, in slices, each followed by a tick.
                let end = std::time::Instant::now() + std::time::Duration::from_millis(*ms);
                loop {
                    let now = std::time::Instant::now();
                    let left = end.saturating_duration_since(now);
                    std::thread::sleep(left.min(SLEEP_SLICE));
                    self.clock += now.elapsed().as_secs_f64();
                    feed(ed, Event::Tick { time: self.clock });
                    if left <= SLEEP_SLICE {
                        break;
                    }
                }
            }
            Step::Resize(w, h) => {
                feed(
                    ed,
                    Event::Resize {
                        width: *w,
                        height: *h,
                    },
                );
            }
            Step::Screenshot(out) => {
                let frame = ed.render_frame();
                frame
                    .save_png(out)
                    .map_err(|e| format!("screenshot {}: {e}", out.display()))?;
            }
            Step::KeyMarker(row, frame, to, mods) => {
                let has = ed
                    .row_markers(*row)
                    .iter()
                    .any(|(f, _)| (f - frame).abs() <= 1e-3);
                let at = ed
                    .key_marker_at(*row, *frame)
                    .filter(|_| has)
                    .ok_or_else(|| {
                        format!("no key at frame {frame} in the key strip's {row:?} row")
                    })?;
                let b = MouseButton::Left;
                let step = match to {
                    None => Step::Click(at.0, at.1, b, *mods),
                    Some(t) => {
                        let x = ed.layout().frame_to_x_in(*t, ed.time_span());
                        Step::Drag(at.0, at.1, x, at.1, b, *mods)
                    }
                };
                self.step(ed, &step)?;
            }
            Step::ClickField(name) => {
                // A field scrolled out of the properties is scrolled in
                // first, as a user would with the wheel.
                let w = ed
                    .reveal_widget(|w| match &w.kind {
                        super::panel::WidgetKind::Field(id) => {
                            format!("{id:?}").eq_ignore_ascii_case(name)
                        }
                        _ => false,
                    })
                    .ok_or_else(|| format!("no field {name} in the panel now"))?;
                let (x, y) = (
                    w.rect.x as f32 + w.rect.w as f32 / 2.0,
                    w.rect.y as f32 + w.rect.h as f32 / 2.0,
                );
                self.step(ed, &Step::Click(x, y, MouseButton::Left, Mods::NONE))?;
            }
            Step::Select(name) => {
                let id = ed
                    .scene()
                    .find_node(name)
                    .ok_or_else(|| format!("no node named {name}"))?;
                let row = ed.widgets().into_iter().find(
                    |w| matches!(w.kind, super::panel::WidgetKind::Row { node, .. } if node == id),
                );
                match row {
                    Some(w) => {
                        let (x, y) = (
                            w.rect.x as f32 + 8.0,
                            w.rect.y as f32 + w.rect.h as f32 / 2.0,
                        );
                        self.step(ed, &Step::Click(x, y, MouseButton::Left, Mods::NONE))?;
                    }
                    None => ed.select(Some(id)),
                }
                if ed.selection() != Some(id) {
                    return Err(format!("{name} could not be selected"));
                }
            }
            Step::DragHandle(name, dx, dy, mods) => {
                let (x, y) = ed.handle_pixel(name).ok_or_else(|| {
                    format!(
                        "no handle '{name}' of the {} tool on the selection in view",
                        ed.tool().name()
                    )
                })?;
                let b = MouseButton::Left;
                self.step(ed, &Step::Drag(x, y, x + dx, y + dy, b, *mods))?;
            }
            Step::CurveKey {
                channel,
                frame,
                by,
                handle,
                mods,
            } => {
                let (x, y) = ed.graph_point(channel, *frame, *handle)?;
                let b = MouseButton::Left;
                let step = match by {
                    None => Step::Click(x, y, b, *mods),
                    Some((dx, dy)) => Step::Drag(x, y, x + dx, y + dy, b, *mods),
                };
                self.step(ed, &step)?;
            }
        }
        Ok(())
    }

    fn move_to(&mut self, ed: &mut Editor, x: f32, y: f32, mods: Mods) {
        self.mouse = (x, y);
        feed(ed, Event::MouseMove { x, y, mods });
    }
}

/// One event, then the file work it asked for (the runner is a shell).
fn feed(ed: &mut Editor, ev: Event) {
    super::shell::handle(ed, ev);
}

/// Parses and runs a script on `ed`.
pub fn run(ed: &mut Editor, text: &str, path: &Path) -> Result<(), ScriptError> {
    let steps = parse(text, path)?;
    Runner::default().run(ed, &steps, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_every_command() {
        let s = "# header\nkey ctrl+shift+s\ntype a #b\nclick 1 2\ndrag 1 2 3 4 alt+left # orbit\nmove 5 6\nwheel -2\nwheel 1 10 20\nwait-frames 3\nresize 320 240\nscreenshot out/a.png\nsleep-ms 5\nexpect-status  Opened a b.wrl \n";
        let steps = parse(s, Path::new("t.txt")).unwrap();
        let kinds: Vec<Step> = steps.into_iter().map(|(_, s)| s).collect();
        assert_eq!(
            kinds[0],
            Step::Key(
                Key::Char('s'),
                Mods {
                    ctrl: true,
                    shift: true,
                    alt: false
                }
            )
        );
        assert_eq!(kinds[1], Step::Type("a #b".into()));
        assert_eq!(
            kinds[2],
            Step::Click(1.0, 2.0, MouseButton::Left, Mods::NONE)
        );
        assert_eq!(
            kinds[3],
            Step::Drag(1.0, 2.0, 3.0, 4.0, MouseButton::Left, Mods::alt())
        );
        assert_eq!(kinds[5], Step::Wheel(-2.0, None));
        assert_eq!(kinds[6], Step::Wheel(1.0, Some((10.0, 20.0))));
        assert_eq!(kinds[7], Step::WaitFrames(3));
        assert_eq!(kinds[8], Step::Resize(320, 240));
        assert_eq!(kinds[9], Step::Screenshot(PathBuf::from("out/a.png")));
        assert_eq!(kinds[10], Step::SleepMs(5));
        assert_eq!(kinds[11], Step::ExpectStatus("Opened a b.wrl".into()));
        let e = parse("key a\n  expect-status\n", Path::new("t.txt")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 17), "{e}");
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = parse("key a\n  click 10 x\n", Path::new("s.txt")).unwrap_err();
        assert_eq!(e.to_string(), "s.txt:2:12: 'x' is not a number");
        let e = parse("jump 1\n", Path::new("s.txt")).unwrap_err();
        assert_eq!((e.line, e.column), (1, 1));
        assert!(e.message.contains("unknown command"));
        let e = parse("key hyper+a\n", Path::new("s.txt")).unwrap_err();
        assert!(e.message.contains("unknown key"));
        let e = parse("wait-frames 99999999999\n", Path::new("s.txt")).unwrap_err();
        assert!(e.message.contains("count up to"));
        let e = parse("resize 100000 10\n", Path::new("s.txt")).unwrap_err();
        assert_eq!(e.line, 1);
    }

    #[test]
    fn screenshots_mid_session_and_report_unwritable_paths() {
        let dir = std::env::temp_dir().join(format!("animed-script-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let shot = dir.join("mid.png");
        let mut ed = Editor::new(crate::scene::Scene::new(), None, 64, 48);
        let text = format!("key g\nscreenshot {}\n", shot.display());
        run(&mut ed, &text, Path::new("s.txt")).unwrap();
        let img = image::open(&shot).unwrap();
        assert_eq!((img.width(), img.height()), (64, 48));
        let bad = format!(
            "key g\nscreenshot {}\n",
            dir.join("no/such/dir/x.png").display()
        );
        let e = run(&mut ed, &bad, Path::new("s.txt")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 1));
        assert!(e.message.contains("screenshot"), "{}", e.message);
        std::fs::remove_dir_all(&dir).ok();
    }
}
