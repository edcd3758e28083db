//! The editor's side of file work: asks for open/import/save (queued as
//! [`Request`]s for the shell) and applies what the shell reports back.
//! Nothing here reads or writes a file.

use crate::editor::command::Command;
use crate::editor::request::{Read, Request};
use crate::editor::views::Memo;
use crate::editor::{fields, ops, After, Editor};
use crate::format::export::atomic::Stamp;
use crate::scene::Scene;
use std::path::{Path, PathBuf};

impl Editor {
    /// Asks the shell to save to `path`, then to continue with `then`.
    pub(in crate::internals::editor) fn request_save(
        &mut self,
        path: PathBuf,
        then: Option<After>,
    ) {
        let expect = self.disk_stamp_for(&path);
        self.requests.push(Request::Save { path, expect, then });
    }

    /// The stamp a save onto `path` must find there: the one read or last
    /// written, when `path` is the open scene's file.
    pub(in crate::internals::editor) fn disk_stamp_for(&self, path: &Path) -> Option<Stamp> {
        match self.path.as_deref() {
            Some(p) if p == path => self.disk_stamp.clone(),
            _ => None,
        }
    }

    /// A file the browser chose was used (`Ok`) or not: the browser
    /// closes and what waited on it continues, or it shows why.
    fn browser_done(&mut self, r: &Result<(), String>, then: Option<After>) {
        match r {
            Ok(()) => {
                let waiting = self.browser.take().and(self.browser_then.take());
                if let Some(then) = waiting.or(then) {
                    self.continue_with(then);
                }
            }
            Err(e) => {
                if let Some(b) = &mut self.browser {
                    b.message = Some(e.clone());
                }
                self.set_status(e, true);
            }
        }
    }

    /// Says on the status line which file is open and how many warnings
    /// reading it gave (`animed edit FILE` says it too).
    pub fn say_opened(&mut self, path: &Path, warnings: usize) {
        let msg = match warnings {
            0 => format!("Opened {}", path.display()),
            n => format!("Opened {} ({n} warnings)", path.display()),
        };
        self.set_status(&msg, false);
    }

    /// The shell read `path` for opening: show it in place of the scene.
    pub fn open_done(&mut self, path: &Path, read: Read) -> Result<(), String> {
        let r = read.map(|(scene, n, stamp)| {
            self.replace_scene(scene, Some(path.to_path_buf()));
            self.disk_stamp = stamp;
            self.through = None;
            self.recall_view();
            self.say_opened(path, n);
            self.requests.push(Request::FindRecovery {
                scene: path.to_path_buf(),
            });
        });
        self.browser_done(&r, None);
        r
    }

    /// The shell read `path` for importing: its content becomes a new
    /// object (undoable).
    pub fn import_done(&mut self, path: &Path, read: Result<Scene, String>) -> Result<(), String> {
        let r = read.map(|scene| {
            let before = Box::new(self.scene.clone());
            let mut after = self.scene.clone();
            let stem = path
                .file_name()
                .map(|s| s.to_string_lossy().to_string())
                .unwrap_or_default();
            let stem = fields::sanitize_name(stem.split('.').next().unwrap_or("Import"));
            let g = ops::graft(&mut after, &scene, &stem);
            let name = after.node(g).name.clone();
            self.execute(
                &format!("Import {name}"),
                Command::ReplaceScene {
                    before,
                    after: Box::new(after),
                },
            );
            self.selection = Some(g);
            self.set_status(&format!("Imported {} as {name}", path.display()), false);
        });
        self.browser_done(&r, None);
        r
    }

    /// The shell wrote the scene as it was at history revision `rev` to
    /// `path` (or could not: nothing is marked saved then, and the status
    /// says why). On success the recovery copies go and `then` follows.
    pub fn save_done(
        &mut self,
        path: &Path,
        written: Result<Option<Stamp>, String>,
        rev: u64,
        then: Option<After>,
    ) {
        let r = written.map(|stamp| {
            self.disk_stamp = stamp;
            let old = self.path.replace(path.to_path_buf());
            self.saved_revision = rev;
            self.saved_recovery(old.as_deref());
            self.remember_view();
            self.set_status(&format!("Saved {}", path.display()), false);
        });
        self.browser_done(&r, then);
    }

    /// The shell found the remembered view of the open file.
    pub fn view_recalled(&mut self, memo: Memo) {
        self.camera = memo.camera;
        self.recall_timeline(memo.zoom, memo.preview);
    }

    /// File work that failed where nothing else reports it.
    pub fn file_error(&mut self, message: &str) {
        self.set_status(message, true);
    }
}
