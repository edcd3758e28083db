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
//!   every second, scripts with `wait-frames` / `sleep-ms`. The wall clock
//!   ("Autosaved at …", "… ago") and the process id (the untitled copy's
//!   name) are the shell's too: it passes them in (`Editor::set_wall_clock`,
//!   `Editor::set_pid`), so a test or script can fix them.
//! * Who touches the disk: nobody here. These are the rules (names, which
//!   copy is worth offering, the order of sessions, how times read, the
//!   autosave clock); the shell's `disk.rs` reads folders, file times,
//!   `/proc` and the environment with them, for the shell (`shell.rs`) and
//!   `animed recover`. The editor asks for that work with
//!   `request::Request`s, and the shell tells it the state folder.

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

/// Folder for copies of untitled scenes, from the environment's values
/// (the shell reads them, `disk::state_dir`): `$XDG_STATE_HOME/animed`,
/// else `$HOME/.local/state/animed`, else `animed` in the temporary
/// folder `tmp`. Relative values are ignored, as the XDG spec says.
pub fn state_dir_from(xdg_state_home: Option<&Path>, home: Option<&Path>, tmp: &Path) -> PathBuf {
    if let Some(d) = xdg_state_home.filter(|p| p.is_absolute()) {
        return d.join("animed");
    }
    if let Some(h) = home.filter(|p| p.is_absolute()) {
        return h.join(".local/state/animed");
    }
    tmp.join("animed")
}

/// The untitled copy in `dir` of the session whose process id is `pid`.
pub fn untitled_in(dir: &Path, pid: u32) -> PathBuf {
    dir.join(format!("untitled-{pid}{SUFFIX}"))
}

/// Whether a recovery copy written at `copy` is worth offering over its
/// scene last modified at `scene` (`None`: the scene file is gone).
pub fn copy_is_newer(copy: SystemTime, scene: Option<SystemTime>) -> bool {
    scene.is_none_or(|saved| saved < copy)
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

/// `/proc/PID/stat` text of a zombie: the state after the name's `)` is Z.
pub fn is_zombie(stat: &str) -> bool {
    stat.rfind(')')
        .and_then(|i| stat[i + 1..].split_whitespace().next())
        .is_some_and(|s| s == "Z")
}

/// Sorts sessions newest first (ties by path, so the order is stable).
pub fn newest_first(sessions: &mut [Session]) {
    sessions.sort_by(|a, b| b.written.cmp(&a.written).then(a.path.cmp(&b.path)));
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
    /// Folder of untitled copies: the shell's state folder
    /// (`Editor::set_state_dir`) or the one sessions were offered from;
    /// `None`: untitled work gets no copy.
    pub(super) dir: Option<PathBuf>,
    /// How long the last autosave took, in milliseconds.
    pub(super) last_ms: Option<f64>,
    /// This session's process id, as the shell gave it (names the
    /// untitled copy; `None`: untitled work gets no copy, like a missing
    /// state folder).
    pub(super) pid: Option<u32>,
    /// The wall clock as the shell last read it (the status line's
    /// "Autosaved at …", the recovery dialog's "… ago"); the Unix epoch
    /// until told.
    pub(super) wall: SystemTime,
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
            pid: None,
            wall: SystemTime::UNIX_EPOCH,
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
    }

    #[test]
    fn the_state_folder_follows_xdg_then_home_then_tmp() {
        let (x, h, t) = (Path::new("/x"), Path::new("/h"), Path::new("/t"));
        assert_eq!(state_dir_from(Some(x), Some(h), t), x.join("animed"));
        assert_eq!(
            state_dir_from(Some(Path::new("rel")), Some(h), t),
            h.join(".local/state/animed"),
            "a relative XDG_STATE_HOME is ignored"
        );
        assert_eq!(state_dir_from(None, None, t), t.join("animed"));
        assert_eq!(
            untitled_pid(&untitled_in(x, 4242)),
            Some(4242),
            "the name carries the pid"
        );
    }

    #[test]
    fn only_a_copy_newer_than_its_scene_is_worth_offering() {
        let t = SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1000);
        let later = t + std::time::Duration::from_secs(1);
        assert!(copy_is_newer(later, Some(t)));
        assert!(!copy_is_newer(t, Some(t)), "saved at the copy's time");
        assert!(!copy_is_newer(t, Some(later)));
        assert!(copy_is_newer(t, None), "the scene file is gone");
        let s = |p: &str, secs| Session {
            path: PathBuf::from(p),
            written: SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(secs),
            objects: None,
        };
        let mut v = vec![s("b", 5), s("a", 9), s("a", 5)];
        newest_first(&mut v);
        assert_eq!(v, vec![s("a", 9), s("a", 5), s("b", 5)]);
    }
}
