//! The shell's disk and process helpers around the editor: recovery copies
//! (write one, find a newer one beside a scene, list untitled sessions left
//! by editors that are gone), the per-file view memory, and where the state
//! folder is. Only the shell (`shell.rs`) and the command line (`animed
//! edit`, `animed recover`) call them; the rules they apply are pure and
//! live in `recovery.rs` and `views.rs`, so the state machine never reads
//! a file, a folder, `/proc` or the environment.

use super::recovery::{copy_is_newer, is_zombie, newest_first, recovery_path, untitled_pid};
use super::recovery::{state_dir_from, Session};
use super::views::{recall_in, remember_in, Memo};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// The state folder (`recovery::state_dir_from` with this process's
/// `$XDG_STATE_HOME`, `$HOME` and temporary folder).
pub fn state_dir() -> PathBuf {
    let xdg = std::env::var_os("XDG_STATE_HOME").map(PathBuf::from);
    state_dir_from(xdg.as_deref(), home().as_deref(), &std::env::temp_dir())
}

/// `$HOME`, which the file browser's `~/` stands for.
pub fn home() -> Option<PathBuf> {
    std::env::var_os("HOME").map(PathBuf::from)
}

/// The recovery copy beside `scene` and when it was written, if it exists
/// and is newer than the scene file (or the scene file is gone).
pub fn newer_copy(scene: &Path) -> Option<(PathBuf, SystemTime)> {
    let r = recovery_path(scene);
    let copy = std::fs::metadata(&r).and_then(|m| m.modified()).ok()?;
    let saved = std::fs::metadata(scene).and_then(|m| m.modified()).ok();
    copy_is_newer(copy, saved).then_some((r, copy))
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
    newest_first(&mut out);
    out
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

/// The remembered view of `scene` (an absolute path) in the file `memory`.
pub fn recall(memory: &Path, scene: &Path) -> Option<Memo> {
    recall_in(&std::fs::read_to_string(memory).ok()?, scene)
}

/// Remembers `memo` for `scene` in the file `memory`, replacing its older
/// line (written beside, then renamed).
pub fn remember(memory: &Path, scene: &Path, memo: &Memo) -> Result<(), String> {
    let old = std::fs::read_to_string(memory).unwrap_or_default();
    let text = remember_in(&old, scene, memo);
    if let Some(d) = memory.parent() {
        std::fs::create_dir_all(d).map_err(|e| format!("{}: {e}", d.display()))?;
    }
    let tmp: PathBuf = memory.with_extension("tmp");
    std::fs::write(&tmp, text).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, memory).map_err(|e| format!("{}: {e}", memory.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::OrbitCamera;

    #[test]
    fn this_editor_is_alive() {
        assert!(session_alive(std::process::id()));
        assert!(state_dir().is_absolute());
    }

    #[test]
    fn views_are_remembered_in_their_file() {
        let d = std::env::temp_dir().join(format!("animed-views-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        let mem = d.join("views");
        let a = Path::new("/x/a.wrl");
        assert_eq!(recall(&mem, a), None, "no file yet");
        let memo = Memo {
            camera: OrbitCamera {
                yaw: 1.25,
                ..OrbitCamera::default()
            },
            zoom: Some((12.5, 40.0)),
            preview: None,
        };
        remember(&mem, a, &memo).unwrap();
        remember(&mem, a, &memo).unwrap();
        assert_eq!(recall(&mem, a), Some(memo));
        let text = std::fs::read_to_string(&mem).unwrap();
        assert_eq!(text.lines().count(), 1, "{text}");
        std::fs::remove_dir_all(&d).unwrap();
    }
}
