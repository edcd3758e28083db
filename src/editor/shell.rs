//! The shell's file work: performs the [`Request`]s the editor queued and
//! hands each outcome back (`Editor::*_done`). The window loop (`app`, via
//! `Screen::perform`) and the headless script runner (`script.rs`) call
//! [`perform`] after every event; nothing the editor routes events to
//! imports this file, so the state machine itself never touches the disk.
//!
//! The `impl Editor` block below holds the shell-side operations the
//! command line and tests call directly (open, save, autosave, recover):
//! each reads or writes here and applies the outcome through the same
//! `*_done` method an event's request would.

use super::browser::{Ask, Entry, Found, Purpose};
use super::disk;
use super::recovery::Session;
use super::request::{AutosaveWhy, Read, Request};
use super::Editor;
use crate::format::export::atomic::{EditLock, Stamp};
use crate::scene::Scene;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Rounds of requests answered in one [`perform`]: an answer may queue
/// more (an open asks for the view memory and the recovery check), never
/// an endless chain.
const MAX_ROUNDS: usize = 8;

/// Performs every queued request (and those their answers queue); true
/// when any was performed (the picture may have changed).
pub fn perform(ed: &mut Editor) -> bool {
    let mut any = false;
    for _ in 0..MAX_ROUNDS {
        let queue = ed.take_requests();
        if queue.is_empty() {
            break;
        }
        any = true;
        for r in queue {
            perform_one(ed, r);
        }
    }
    any
}

/// One event through the editor and then its file work, as the window
/// loop and the script runner feed it; true when the picture changed.
pub fn handle(ed: &mut Editor, ev: crate::input::Event) -> bool {
    ed.handle(ev) | perform(ed)
}

fn perform_one(ed: &mut Editor, r: Request) {
    match r {
        Request::Open(path) => {
            let r = read(&path);
            let _ = ed.open_done(&path, r);
        }
        Request::Import(path) => {
            let r = read(&path).map(|(s, _, _)| s);
            let _ = ed.import_done(&path, r);
        }
        Request::Save { path, expect, then } => {
            let rev = ed.history().revision();
            let r = save_scene_checked(ed.scene(), &path, expect.as_ref());
            ed.save_done(&path, r, rev, then);
        }
        Request::Autosave { path, why } => {
            let _ = autosave(ed, path, why);
        }
        Request::Remove(p) => remove(&p),
        Request::FindRecovery { scene } => {
            if let Some((copy, when)) = disk::newer_copy(&scene) {
                ed.recovery_found(&scene, copy, when);
            }
        }
        Request::Recover { copy } => {
            let r = read(&copy);
            ed.recover_done(&copy, r);
        }
        Request::RecoverUntitled { copy, mine } => {
            let r = read(&copy);
            ed.recover_untitled_done(r, copy, mine);
        }
        Request::TakeOver { copy, mine } => {
            // The recovered copy becomes this session's own, so a save or
            // a clean quit deletes it.
            let taken = if copy == mine || std::fs::rename(&copy, &mine).is_ok() {
                mine
            } else {
                copy
            };
            ed.took_over(taken);
        }
        Request::ReadTexture { path, material } => {
            let r = read_image(&path);
            ed.texture_read(&path, material, r);
        }
        Request::RecallView { memory, key } => {
            if let Some(m) = disk::recall(&memory, &key) {
                ed.view_recalled(m);
            }
        }
        Request::Look { ask, purpose } => {
            let found = look(&ask, purpose);
            ed.browser_found(ask, found);
        }
        Request::RememberView { memory, key, memo } => {
            if let Err(e) = disk::remember(&memory, &key, &memo) {
                ed.file_error(&format!("cannot remember the view: {e}"));
            }
        }
    }
}

/// An image file decoded for a texture (the readers' decoder, so the same
/// formats and size limits as a texture named in a scene file).
fn read_image(path: &Path) -> super::request::ReadImage {
    use crate::format::textures::decode;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let abs = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let source = crate::scene::ImageSource::File {
        url: abs.display().to_string(),
        path: abs,
    };
    decode::read_file(path).and_then(|bytes| decode::decode(&bytes, &name, source))
}

/// What the file browser asked to have read: a folder's listing, or
/// whether a typed path is a folder, a file or nothing.
pub fn look(ask: &Ask, purpose: Purpose) -> Found {
    match ask {
        Ask::Enter(dir) | Ask::Complete(dir) => Found::Listing(list(dir, purpose)),
        Ask::Probe(p) if p.is_dir() => Found::Listing(list(p, purpose)),
        Ask::Probe(p) if p.is_file() => Found::File,
        Ask::Probe(_) => Found::Missing,
    }
}

/// Lists `dir`: ".." first, then folders, then the files `purpose` shows,
/// each sorted case-insensitively; hidden entries are skipped.
fn list(dir: &Path, purpose: Purpose) -> Result<Vec<Entry>, String> {
    let mut dirs = Vec::new();
    let mut files = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| e.to_string())? {
        let Ok(e) = e else { continue };
        let name = e.file_name().to_string_lossy().to_string();
        if name.starts_with('.') {
            continue;
        }
        let is_dir = e.path().is_dir();
        if is_dir {
            dirs.push(Entry { name, is_dir });
        } else if purpose.shows(&name) {
            files.push(Entry { name, is_dir });
        }
    }
    let key = |e: &Entry| e.name.to_lowercase();
    dirs.sort_by_key(key);
    files.sort_by_key(key);
    let mut out = Vec::with_capacity(dirs.len() + files.len() + 1);
    if dir.parent().is_some() {
        out.push(Entry {
            name: "..".into(),
            is_dir: true,
        });
    }
    out.extend(dirs);
    out.extend(files);
    Ok(out)
}

/// Writes the recovery copy and tells the editor; returns where.
fn autosave(ed: &mut Editor, path: PathBuf, why: AutosaveWhy) -> Result<PathBuf, String> {
    let rev = ed.history().revision();
    let t0 = Instant::now();
    let r = disk::write(ed.scene(), &path).map(|()| t0.elapsed().as_secs_f64() * 1e3);
    let out = r.clone().map(|_| path.clone());
    ed.autosave_done(path, why, r, rev);
    out
}

fn read(path: &Path) -> Read {
    let stamp = Stamp::of(path);
    let loaded = crate::format::load(path).map_err(|e| e.to_string())?;
    Ok((loaded.scene, loaded.warnings.len(), stamp))
}

fn remove(path: &Path) {
    // Already gone is fine; anything else only leaves a stale copy behind.
    let _ = std::fs::remove_file(path);
}

/// Writes the scene to `path` (format from the extension: .wrl, .wrl.gz,
/// .iv) through the writers, which save atomically (written beside, then
/// renamed: a failed save leaves the old file whole).
pub fn save_scene(scene: &Scene, path: &Path) -> Result<(), String> {
    crate::format::save(scene, path, &crate::format::WriteOptions::default())
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// [`save_scene`] under the folder's edit lock, after checking that `path`
/// is still what `expect` saw when it was read or last saved (so another
/// program's or animed command's save is never silently overwritten);
/// returns the stamp of the file written.
pub fn save_scene_checked(
    scene: &Scene,
    path: &Path,
    expect: Option<&Stamp>,
) -> Result<Option<Stamp>, String> {
    let _lock = EditLock::acquire(path)
        .map_err(|e| format!("{}: cannot lock for editing: {e}", path.display()))?;
    if let Some(s) = expect {
        s.check(path).map_err(|e| e.to_string())?;
    }
    save_scene(scene, path)?;
    Ok(Stamp::of(path))
}

/// Shell-side operations for the command line and tests: each does its
/// file work here and applies the outcome as the request's answer would.
impl Editor {
    /// Opens a scene file, replacing the current scene.
    pub fn open_file(&mut self, path: &Path) -> Result<(), String> {
        let r = read(path);
        let out = self.open_done(path, r);
        perform(self);
        out
    }

    /// Adds a model file's content as a new object (undoable).
    pub fn import_file(&mut self, path: &Path) -> Result<(), String> {
        let r = read(path).map(|(s, _, _)| s);
        let out = self.import_done(path, r);
        perform(self);
        out
    }

    /// Saves to `path` through the writers (format from the extension).
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        let expect = self.disk_stamp_for(path);
        let rev = self.history().revision();
        let r = save_scene_checked(self.scene(), path, expect.as_ref());
        let out = r.as_ref().map(|_| ()).map_err(|e| e.clone());
        self.save_done(path, r, rev, None);
        perform(self);
        out
    }

    /// Writes the recovery copy now; returns where.
    pub fn autosave_now(&mut self) -> Result<PathBuf, String> {
        let path = self
            .recovery_file()
            .ok_or("no state folder for a copy of untitled work")?;
        if self.path().is_none() {
            // Untitled work's view, remembered by its copy (as the clock's).
            self.remember_view_as(path.clone());
        }
        let out = autosave(self, path, AutosaveWhy::Now);
        perform(self);
        out
    }

    /// When the open scene has a newer recovery copy beside it, asks
    /// whether to recover it (the dialog's Recover / Discard copy / Open
    /// saved). Call after opening a file.
    pub fn check_recovery(&mut self) {
        if let Some(scene) = self.path().map(Path::to_path_buf) {
            perform_one(self, Request::FindRecovery { scene });
        }
        perform(self);
    }

    /// At start: when untitled sessions left recovery copies in `dir` (the
    /// state folder, see `disk::state_dir`), lists them newest first
    /// in the recovery dialog (unless another question is open). Returns
    /// how many were offered.
    pub fn offer_untitled(&mut self, dir: &Path) -> usize {
        if self.dialog().is_some() {
            return 0;
        }
        let list: Vec<Session> = disk::untitled_sessions(dir);
        let n = self.offer_sessions(dir, list);
        perform(self);
        n
    }

    /// Opens an untitled session's copy as new untitled work: an empty
    /// scene, then one undoable "Recover" step (so the work counts as
    /// unsaved and keeps being autosaved). The copy becomes this session's
    /// own, so a save or a clean quit deletes it.
    pub fn recover_untitled(&mut self, copy: &Path) {
        // Without a state folder the copy is taken over where it is.
        let mine = self.untitled_file().unwrap_or_else(|| copy.to_path_buf());
        perform_one(
            self,
            Request::RecoverUntitled {
                copy: copy.to_path_buf(),
                mine,
            },
        );
        perform(self);
    }

    /// The window loop ended: after a clean quit this session's copy goes;
    /// closed with unsaved changes (closed twice, or the window system
    /// went away), they are written to the recovery copy right away.
    /// Returns a line to print.
    pub fn window_closed(&mut self) -> Option<String> {
        self.remember_view();
        if !self.is_dirty() || self.wants_quit() {
            self.forget_recovery();
            perform(self);
            return None;
        }
        perform(self);
        Some(match self.autosave_now() {
            Ok(p) => {
                let how = match self.path() {
                    Some(_) => "open the scene again to recover them",
                    None => "animed offers it at the next start; `animed recover --list` shows it",
                };
                format!(
                    "window closed with unsaved changes; they are in the recovery copy {} ({how})",
                    p.display()
                )
            }
            Err(e) => format!("window closed with unsaved changes; autosave failed: {e}"),
        })
    }
}
