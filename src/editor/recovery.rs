//! Never lose work: while there are unsaved changes the editor writes a
//! recovery copy of the scene every [`DEFAULT_INTERVAL`] seconds (counted
//! from the first unsaved change, then from the last autosave), and opening
//! a scene that has a newer recovery copy beside it offers to recover it.
//!
//! * Where: `dir/name.wrl` → `dir/.name.wrl.animed-recovery.wrl` (hidden,
//!   beside the scene, so it moves with it); an untitled scene →
//!   `$XDG_STATE_HOME/animed/untitled-PID.animed-recovery.wrl` (default
//!   `~/.local/state/animed/`).
//! * What: always VRML97 through the normal writer (atomic: written beside,
//!   then renamed), whose `animed-keys 1` note keeps every key exactly.
//! * When it goes: a successful save deletes it (and the copy of the new
//!   name), and so do discarding the changes, undoing back to the saved
//!   state and a clean quit. A copy this session did not write (a crash's)
//!   is only deleted by "Discard copy" or by saving over its scene.
//! * Time comes from `Event::Tick`s: the window loop sends one at least
//!   every second, scripts with `wait-frames` / `sleep-ms`.
//! * Who touches the disk: only the shell (`shell.rs`) and `animed
//!   recover` call the reading and writing helpers here (`newer_copy`,
//!   `untitled_sessions`, `write`); the editor asks for them with
//!   `request::Request`s.

use crate::input::{Event, MouseButton};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// Seconds between autosaves unless told otherwise.
pub const DEFAULT_INTERVAL: f64 = 30.0;

/// What the recovery file name adds to the scene's file name.
pub const SUFFIX: &str = ".animed-recovery.wrl";

/// The recovery copy of the scene at `scene`: `.NAME.animed-recovery.wrl`
/// in the same folder.
pub fn recovery_path(scene: &Path) -> PathBuf {
    let name = scene
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_else(|| "scene".into());
    let file = format!(".{name}{SUFFIX}");
    match scene.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.join(file),
        _ => PathBuf::from(file),
    }
}

/// Folder for copies of untitled scenes: `$XDG_STATE_HOME/animed`, else
/// `~/.local/state/animed`, else the system's temporary folder.
pub fn state_dir() -> PathBuf {
    let abs = |v: Option<std::ffi::OsString>| v.map(PathBuf::from).filter(|p| p.is_absolute());
    if let Some(d) = abs(std::env::var_os("XDG_STATE_HOME")) {
        return d.join("animed");
    }
    if let Some(h) = abs(std::env::var_os("HOME")) {
        return h.join(".local/state/animed");
    }
    std::env::temp_dir().join("animed")
}

/// The recovery copy of this process's untitled scene.
pub fn untitled_path() -> PathBuf {
    untitled_in(&state_dir())
}

/// This process's untitled copy in `dir`.
pub fn untitled_in(dir: &Path) -> PathBuf {
    dir.join(format!("untitled-{}{SUFFIX}", std::process::id()))
}

/// The recovery copy beside `scene` and when it was written, if it exists
/// and is newer than the scene file (or the scene file is gone).
pub fn newer_copy(scene: &Path) -> Option<(PathBuf, SystemTime)> {
    let r = recovery_path(scene);
    let copy = std::fs::metadata(&r).and_then(|m| m.modified()).ok()?;
    match std::fs::metadata(scene).and_then(|m| m.modified()) {
        Ok(saved) if saved >= copy => None,
        _ => Some((r, copy)),
    }
}

/// One untitled session's recovery copy left by an editor that is gone
/// (crashed, killed, or closed without saving).
#[derive(Clone, Debug, PartialEq)]
pub struct Session {
    pub path: PathBuf,
    pub written: SystemTime,
    /// Objects in the copy (the object list's rows); `None` when the copy
    /// does not load.
    pub objects: Option<usize>,
}

impl Session {
    /// "2026-11-30 02:41 UTC, 3 min ago, 4 objects" as seen at `now`.
    pub fn describe(&self, now: SystemTime) -> String {
        let what = match self.objects {
            Some(1) => "1 object".to_string(),
            Some(n) => format!("{n} objects"),
            None => "unreadable".to_string(),
        };
        format!("{}, {what}", describe_time(self.written, now))
    }
}

/// The process id in an untitled copy's name (`untitled-PID` + SUFFIX).
pub fn untitled_pid(path: &Path) -> Option<u32> {
    let name = path.file_name()?.to_str()?;
    name.strip_prefix("untitled-")?
        .strip_suffix(SUFFIX)?
        .parse()
        .ok()
}

/// Whether the editor that writes copies under `pid` still runs: this
/// process, or a live process named animed (Linux `/proc`; elsewhere
/// every other copy counts as left behind). A killed editor nobody has
/// reaped yet (a zombie, state `Z`) is gone.
pub fn session_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    let named = std::fs::read_to_string(format!("/proc/{pid}/comm"))
        .is_ok_and(|c| c.trim_end().starts_with("animed"));
    named && !is_zombie(&std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default())
}

/// `/proc/PID/stat` text of a zombie: the state after the name's `)` is Z.
fn is_zombie(stat: &str) -> bool {
    stat.rfind(')')
        .and_then(|i| stat[i + 1..].split_whitespace().next())
        .is_some_and(|s| s == "Z")
}

/// Every untitled recovery copy in `dir` whose editor is gone, newest
/// first. Each copy is loaded once to count its objects.
pub fn untitled_sessions(dir: &Path) -> Vec<Session> {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut out: Vec<Session> = rd
        .flatten()
        .map(|e| e.path())
        .filter(|p| untitled_pid(p).is_some_and(|pid| !session_alive(pid)))
        .filter_map(|path| {
            let written = std::fs::metadata(&path).and_then(|m| m.modified()).ok()?;
            let objects = crate::format::load(&path)
                .ok()
                .map(|l| super::ops::objects(&l.scene).len());
            Some(Session {
                path,
                written,
                objects,
            })
        })
        .collect();
    out.sort_by(|a, b| b.written.cmp(&a.written).then(a.path.cmp(&b.path)));
    out
}

/// The lines `animed recover --list` prints and the start-up dialog shows:
/// `N  time, objects` (N counts from 1, newest first).
pub fn session_lines(sessions: &[Session], now: SystemTime) -> Vec<String> {
    sessions
        .iter()
        .enumerate()
        .map(|(i, s)| format!("{}  {}", i + 1, s.describe(now)))
        .collect()
}

/// Writes `scene` as a recovery copy (VRML97 with the key note, atomically).
pub fn write(scene: &crate::scene::Scene, path: &Path) -> Result<(), String> {
    if let Some(d) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(d).map_err(|e| format!("{}: {e}", d.display()))?;
    }
    crate::format::save(scene, path, &crate::format::WriteOptions::default())
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// "2026-11-22 02:31 UTC, 3 min ago" for `t` seen at `now`.
pub fn describe_time(t: SystemTime, now: SystemTime) -> String {
    let secs = t
        .duration_since(SystemTime::UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let (y, m, d) = civil_from_days((secs / 86_400) as i64);
    let (hh, mm) = ((secs % 86_400) / 3600, (secs % 3600) / 60);
    let ago = now.duration_since(t).map(|d| d.as_secs()).unwrap_or(0);
    let ago = match ago {
        0..=59 => format!("{ago} s ago"),
        60..=5999 => format!("{} min ago", ago / 60),
        _ => format!("{} h ago", ago / 3600),
    };
    format!("{y:04}-{m:02}-{d:02} {hh:02}:{mm:02} UTC, {ago}")
}

/// "02:41:07 UTC": the time of day of `t`.
pub fn clock_utc(t: SystemTime) -> String {
    let secs = t
        .duration_since(SystemTime::UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let (h, m, s) = ((secs % 86_400) / 3600, (secs % 3600) / 60, secs % 60);
    format!("{h:02}:{m:02}:{s:02} UTC")
}

/// Days since 1970-01-01 → (year, month, day) in the proleptic Gregorian
/// calendar. The algorithm is Howard Hinnant's `civil_from_days`
/// ("chrono-Compatible Low-Level Date Algorithms").
pub(super) fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + if m <= 2 { 1 } else { 0 };
    (y, m, d)
}

/// The editor's autosave state.
#[derive(Clone, Debug)]
pub struct Autosave {
    /// Seconds between autosaves; `None` turns autosave off.
    pub(super) interval: Option<f64>,
    /// Tick time the current wait started (first unsaved change seen, or
    /// the last autosave).
    pub(super) since: Option<f64>,
    /// History revision held by the recovery copy.
    pub(super) copied: Option<u64>,
    /// The recovery file this session wrote (or took over by recovering).
    pub(super) written: Option<PathBuf>,
    /// A crash's copy offered by the open dialog.
    pub(super) offer: Option<PathBuf>,
    /// Untitled sessions offered at start (newest first) and the one the
    /// dialog points at.
    pub(super) untitled: Vec<Session>,
    pub(super) chosen: usize,
    /// Folder of untitled copies when not `state_dir()` (the one offered
    /// from at start).
    pub(super) dir: Option<PathBuf>,
    /// How long the last autosave took, in milliseconds.
    pub(super) last_ms: Option<f64>,
    /// Mouse buttons held: a drag may be previewing into the scene.
    buttons: u8,
    /// Tick time the buttons were first seen held.
    held_since: Option<f64>,
}

impl Default for Autosave {
    fn default() -> Self {
        Autosave {
            interval: Some(DEFAULT_INTERVAL),
            since: None,
            copied: None,
            written: None,
            offer: None,
            untitled: Vec::new(),
            chosen: 0,
            dir: None,
            last_ms: None,
            buttons: 0,
            held_since: None,
        }
    }
}

impl Autosave {
    /// Follows the mouse buttons (every event passes here).
    pub(super) fn note_input(&mut self, ev: &Event) {
        let bit = |b: &MouseButton| match b {
            MouseButton::Left => 1,
            MouseButton::Middle => 2,
            MouseButton::Right => 4,
        };
        match ev {
            Event::MouseDown { button, .. } => self.buttons |= bit(button),
            Event::MouseUp { button, .. } => self.buttons &= !bit(button),
            _ => {}
        }
        if self.buttons == 0 {
            self.held_since = None;
        }
    }

    /// Whether a drag (any kind: handles, fields, keys) may hold a live
    /// preview: a button is down, for less than an interval (a release
    /// the window never reported must not stop autosave for good).
    pub(super) fn dragging(&mut self, now: f64, interval: f64) -> bool {
        if self.buttons == 0 {
            return false;
        }
        now - *self.held_since.get_or_insert(now) < interval
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zombies_are_not_running_editors() {
        assert!(is_zombie("833 (animed) Z 1 833 833 0 -1"));
        assert!(!is_zombie("833 (animed) S 1 833 833 0 -1"));
        assert!(!is_zombie("833 (a) b) R 1"));
        assert!(!is_zombie(""));
        assert!(session_alive(std::process::id()));
    }
}
