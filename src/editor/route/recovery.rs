//! The editor's side of `recovery`: routes events to it and applies what it returns.

use crate::editor::command::Command;
#[allow(unused_imports)]
use crate::editor::recovery::*;
use crate::editor::request::{AutosaveWhy, Read, Request};
use crate::editor::{After, Dialog, Editor};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

impl Editor {
    /// Seconds between autosaves (`None` or 0: off).
    pub fn set_autosave_interval(&mut self, secs: Option<f64>) {
        self.autosave.interval = secs.filter(|s| *s > 0.0 && s.is_finite());
    }

    /// Whether the app must send a `Tick` at least every second: there is
    /// unsaved work to autosave, or a copy to delete.
    pub fn wants_clock(&self) -> bool {
        self.is_dirty() || self.autosave.written.is_some()
    }

    /// The folder where untitled work is autosaved (the shell's state
    /// folder, `disk::state_dir`): the editor never reads the environment.
    /// Without one, untitled work gets no recovery copy.
    pub fn set_state_dir(&mut self, dir: &Path) {
        self.autosave.dir = Some(dir.to_path_buf());
    }

    /// This session's process id, from the shell (names the untitled
    /// copy): the editor never asks the process.
    pub fn set_pid(&mut self, pid: u32) {
        self.autosave.pid = Some(pid);
    }

    /// The wall clock, from the shell before each event (the window loop)
    /// or once (scripts, `clock` in a script): what "Autosaved at …" and
    /// the recovery dialog's "… ago" read. The editor never reads it.
    pub fn set_wall_clock(&mut self, now: SystemTime) {
        self.autosave.wall = now;
    }

    /// The wall clock as the shell last gave it.
    pub fn wall_clock(&self) -> SystemTime {
        self.autosave.wall
    }

    /// Where this session's recovery copy goes (`None`: untitled work and
    /// no state folder given).
    pub fn recovery_file(&self) -> Option<PathBuf> {
        match &self.path {
            Some(p) => Some(recovery_path(p)),
            None => self.untitled_file(),
        }
    }

    /// Where this session's untitled work is autosaved (`None` until the
    /// shell gave a state folder and the process id).
    pub(in crate::internals::editor) fn untitled_file(&self) -> Option<PathBuf> {
        let (dir, pid) = (self.autosave.dir.as_deref()?, self.autosave.pid?);
        Some(untitled_in(dir, pid))
    }

    /// The recovery copy this session wrote, if it still stands.
    pub fn autosaved_to(&self) -> Option<&Path> {
        self.autosave.written.as_deref()
    }

    /// Milliseconds the last autosave took.
    pub fn last_autosave_ms(&self) -> Option<f64> {
        self.autosave.last_ms
    }

    /// Called on every tick (`now` in seconds): writes the recovery copy
    /// when unsaved changes have waited long enough. Returns true when the
    /// status line changed.
    pub(in crate::internals::editor) fn autosave_tick(&mut self, now: f64) -> bool {
        if !self.is_dirty() {
            self.autosave.since = None;
            if let Some(p) = self.autosave.written.take() {
                // Back at the saved state (undo): the copy is stale.
                self.requests.push(Request::Remove(p));
            }
            return false;
        }
        let Some(interval) = self.autosave.interval else {
            return false;
        };
        let rev = self.history.revision();
        if self.autosave.copied == Some(rev) {
            return false;
        }
        let since = *self.autosave.since.get_or_insert(now);
        // Not in the middle of a drag (the scene may hold a preview) or
        // while the recovery question is open.
        let busy = self.autosave.dragging(now, interval) || self.autosave.offer.is_some();
        if now - since < interval || busy {
            return false;
        }
        if self
            .requests
            .iter()
            .any(|r| matches!(r, Request::Autosave { .. }))
        {
            return false;
        }
        // Waits another interval if the write fails (on success the wait
        // starts at the next change).
        self.autosave.since = Some(now);
        let Some(path) = self.recovery_file() else {
            return false;
        };
        if self.path.is_none() {
            // Untitled work has no file to remember its view by: its copy
            // is the key, so recovered work comes back as it was seen.
            self.remember_view_as(path.clone());
        }
        self.requests.push(Request::Autosave {
            path,
            why: AutosaveWhy::Clock,
        });
        false
    }

    /// The shell wrote (or failed to write) the recovery copy at `path`,
    /// holding history revision `rev`, in `ms` milliseconds.
    pub fn autosave_done(
        &mut self,
        path: PathBuf,
        why: AutosaveWhy,
        written: Result<f64, String>,
        rev: u64,
    ) {
        match written {
            Ok(ms) => {
                self.autosave.last_ms = Some(ms);
                self.autosave.copied = Some(rev);
                self.autosave.since = None;
                let name = path.file_name().map(|n| n.to_string_lossy().to_string());
                self.autosave.written = Some(path);
                if why == AutosaveWhy::Clock {
                    // Say so: the user should see their work is safe.
                    let when = clock_utc(self.autosave.wall);
                    let what = match &self.path {
                        Some(_) => "unsaved changes",
                        None => "untitled work",
                    };
                    self.set_status(
                        &format!("Autosaved {what} at {when} ({})", name.unwrap_or_default()),
                        false,
                    );
                }
            }
            Err(e) if why == AutosaveWhy::Clock => {
                self.set_status(&format!("Autosave failed: {e}"), true)
            }
            Err(_) => {}
        }
    }

    /// Deletes this session's recovery copy (changes saved or discarded).
    pub(in crate::internals::editor) fn forget_recovery(&mut self) {
        if let Some(p) = self.autosave.written.take() {
            self.requests.push(Request::Remove(p));
        }
        self.autosave.since = None;
        self.autosave.copied = None;
    }

    /// After a successful save (the scene was at `old` before): the copies
    /// of both names are out of date.
    pub(in crate::internals::editor) fn saved_recovery(&mut self, old: Option<&Path>) {
        self.forget_recovery();
        if let Some(p) = self.untitled_file().filter(|_| old.is_none()) {
            self.requests.push(Request::Remove(p));
        }
        if let Some(p) = &self.path {
            self.requests.push(Request::Remove(recovery_path(p)));
        }
    }

    /// A new scene replaced the old one (its changes were saved or
    /// discarded before).
    pub(in crate::internals::editor) fn reset_recovery(&mut self) {
        self.forget_recovery();
        self.autosave.offer = None;
    }

    /// The shell found a recovery copy newer than the open scene's file
    /// (written `when`; "… ago" from the wall clock the shell gave): asks
    /// whether to recover it (the dialog's Recover / Discard copy / Open
    /// saved).
    pub fn recovery_found(&mut self, scene: &Path, copy: PathBuf, when: SystemTime) {
        if self.path.as_deref() != Some(scene) {
            return;
        }
        let name = scene
            .file_name()
            .map(|n| n.to_string_lossy().to_string())
            .unwrap_or_default();
        let when = describe_time(when, self.autosave.wall);
        self.autosave.offer = Some(copy);
        self.dialog = Some(Dialog::new(
            format!("Unsaved work on {name} was autosaved\n{when}. Recover it?"),
            After::Recover,
        ));
    }

    /// The recovery copy the open dialog offers.
    pub fn recovery_offer(&self) -> Option<&Path> {
        self.autosave.offer.as_deref()
    }

    /// The untitled sessions the shell found in `dir` (newest first):
    /// lists them in the recovery dialog unless another question is open.
    /// Returns how many were offered.
    pub fn offer_sessions(&mut self, dir: &Path, list: Vec<Session>) -> usize {
        if self.dialog.is_some() {
            return 0;
        }
        self.autosave.dir = Some(dir.to_path_buf());
        self.autosave.untitled = list;
        self.autosave.chosen = 0;
        self.show_untitled_offer();
        self.autosave.untitled.len()
    }

    /// The untitled sessions the recovery dialog lists, newest first.
    pub fn untitled_offers(&self) -> &[Session] {
        &self.autosave.untitled
    }

    /// (Re)builds the dialog listing `autosave.untitled`; closes it when
    /// none are left.
    pub(in crate::internals::editor) fn show_untitled_offer(&mut self) {
        let list = &self.autosave.untitled;
        if list.is_empty() {
            self.autosave.offer = None;
            if self
                .dialog
                .as_ref()
                .is_some_and(|d| d.then == After::Recover)
            {
                self.dialog = None;
            }
            return;
        }
        let chosen = self.autosave.chosen.min(list.len() - 1);
        self.autosave.chosen = chosen;
        self.autosave.offer = Some(list[chosen].path.clone());
        let mut message = String::from("Untitled work was autosaved and not saved:");
        let lines = session_lines(list, self.autosave.wall);
        // At most 9 rows (keys 1-9 pick one); the rest wait their turn.
        for (i, l) in lines.iter().enumerate().take(9) {
            let mark = if i == chosen { ">" } else { " " };
            message += &format!("\n{mark} {l}");
        }
        if lines.len() > 9 {
            message += &format!("\n  ... and {} more", lines.len() - 9);
        }
        message += "\nRecover the marked one? (Up/Down or 1-9 choose)";
        self.dialog = Some(Dialog {
            message,
            then: After::Recover,
            list: true,
        });
    }

    /// The shell read an untitled session's copy: it becomes new untitled
    /// work — an empty scene, then one undoable "Recover" step (so the
    /// work counts as unsaved and keeps being autosaved) — and the copy
    /// this session's own (`TakeOver`), so a save or a clean quit deletes
    /// it.
    pub fn recover_untitled_done(&mut self, read: Read, copy: PathBuf, mine: PathBuf) {
        let scene = match read {
            Ok((scene, _, _)) => scene,
            Err(e) => {
                self.set_status(&format!("cannot recover: {e}"), true);
                return;
            }
        };
        self.replace_scene(crate::scene::Scene::new(), None);
        let before = Box::new(self.scene.clone());
        self.execute(
            "Recover autosaved work",
            Command::ReplaceScene {
                before,
                after: Box::new(scene),
            },
        );
        self.frame_all();
        // The view the work was last autosaved with, if remembered.
        self.recall_view_of(copy.clone());
        // After `replace_scene`'s removal of this session's old copy.
        self.requests.push(Request::TakeOver { copy, mine });
        self.set_status(
            "Recovered untitled work: Ctrl+S saves it under a name",
            false,
        );
    }

    /// The shell moved the recovered copy to `path`: this session's copy.
    pub fn took_over(&mut self, path: PathBuf) {
        self.autosave.written = Some(path);
    }

    /// The shell read the recovery copy: it comes into the editor as one
    /// undoable change (undo shows the saved file again); the file name
    /// stays the scene's, so Ctrl+S writes the original.
    pub fn recover_done(&mut self, copy: &Path, read: Read) {
        match read {
            Ok((scene, _, _)) => {
                let before = Box::new(self.scene.clone());
                self.execute(
                    "Recover autosaved work",
                    Command::ReplaceScene {
                        before,
                        after: Box::new(scene),
                    },
                );
                self.frame = self.frame.min(self.scene.settings.duration);
                // The copy now holds this session's work.
                self.autosave.written = Some(copy.to_path_buf());
                self.set_status("Recovered the autosaved work: Ctrl+S saves it", false);
            }
            Err(e) => self.set_status(&format!("cannot recover: {e}"), true),
        }
    }

    /// The window's close button: with unsaved changes, ask "Save changes
    /// first?" (as Ctrl+Q does) and keep running — true. Closing again
    /// while that question is shown, or with nothing unsaved, closes.
    pub fn close_requested(&mut self) -> bool {
        let asked = self.dialog.as_ref().is_some_and(|d| d.then == After::Quit);
        if !self.is_dirty() || self.quit || asked {
            return false;
        }
        self.dialog = Some(Dialog::new("Save changes before closing?", After::Quit));
        true
    }
}

#[cfg(test)]
mod tests {
    use crate::editor::command::Command;
    use crate::editor::recovery::*;
    use crate::editor::Editor;
    use crate::input::{Event, MouseButton};
    use crate::scene::{Node, Scene, Transform};
    use std::path::{Path, PathBuf};
    use std::time::Duration;
    use std::time::SystemTime;

    fn tmp_dir(tag: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("animed-recovery-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn boxes() -> Scene {
        let mut s = Scene::new();
        s.add_node(
            None,
            Node::group("Box").with_transform(Transform::from_translation(glam::Vec3::X)),
        );
        s
    }

    #[test]
    fn recovery_names() {
        assert_eq!(
            recovery_path(Path::new("dir/sub/walk.wrl")),
            PathBuf::from("dir/sub/.walk.wrl.animed-recovery.wrl")
        );
        assert_eq!(
            recovery_path(Path::new("a.iv")),
            PathBuf::from(".a.iv.animed-recovery.wrl")
        );
        // Untitled work goes to the state folder the shell gives, and
        // nowhere without one (the editor reads no environment).
        let mut ed = Editor::new(boxes(), None, 320, 240);
        assert_eq!(ed.recovery_file(), None);
        ed.set_state_dir(Path::new("/state/animed"));
        assert_eq!(ed.recovery_file(), None, "no pid given");
        // The pid is the shell's to give, not the process's to ask.
        ed.set_pid(4242);
        let u = ed.recovery_file().unwrap();
        assert_eq!(
            u,
            Path::new("/state/animed").join("untitled-4242.animed-recovery.wrl")
        );
    }

    #[test]
    fn only_a_newer_copy_is_offered() {
        let d = tmp_dir("newer");
        let scene = d.join("s.wrl");
        std::fs::write(&scene, "#VRML V2.0 utf8\n").unwrap();
        assert_eq!(crate::editor::disk::newer_copy(&scene), None, "no copy");
        let copy = recovery_path(&scene);
        std::fs::write(&copy, "#VRML V2.0 utf8\n").unwrap();
        let now = SystemTime::now();
        let set = |p: &Path, t: SystemTime| {
            let f = std::fs::OpenOptions::new().write(true).open(p).unwrap();
            f.set_modified(t).unwrap();
        };
        set(&scene, now - Duration::from_secs(60));
        set(&copy, now);
        assert_eq!(
            crate::editor::disk::newer_copy(&scene).map(|c| c.0),
            Some(copy.clone())
        );
        // Saved after the copy: the copy is stale.
        set(&scene, now + Duration::from_secs(1));
        assert_eq!(crate::editor::disk::newer_copy(&scene), None);
        // The scene file is gone: the copy is all there is.
        std::fs::remove_file(&scene).unwrap();
        assert!(crate::editor::disk::newer_copy(&scene).is_some());
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn dates_are_utc_calendar_dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(civil_from_days(20_779), (2026, 11, 22));
        let t = SystemTime::UNIX_EPOCH + Duration::from_secs(20_779 * 86_400 + 2 * 3600 + 31 * 60);
        assert_eq!(
            describe_time(t, t + Duration::from_secs(200)),
            "2026-11-22 02:31 UTC, 3 min ago"
        );
    }

    /// The clock ticks the editor, then the shell writes what it asked.
    fn tick(ed: &mut Editor, now: f64) {
        ed.autosave_tick(now);
        crate::editor::shell::perform(ed);
    }

    #[test]
    fn autosave_waits_for_the_interval_and_a_save_deletes_the_copy() {
        let d = tmp_dir("save");
        let scene = d.join("s.wrl");
        let mut ed = Editor::new(boxes(), None, 320, 240);
        ed.save_to(&scene).unwrap();
        ed.set_autosave_interval(Some(30.0));
        let copy = recovery_path(&scene);
        let id = crate::scene::NodeId(0);
        let mut after = Box::new(ed.scene().node(id).clone());
        after.transform.translation.x = 5.0;
        let before = Box::new(ed.scene().node(id).clone());
        ed.execute("move", Command::SetNode { id, before, after });
        tick(&mut ed, 100.0);
        tick(&mut ed, 129.0);
        assert!(!copy.exists(), "29 s after the first change: not yet");
        tick(&mut ed, 130.5);
        assert!(copy.exists(), "30 s after the first change");
        assert_eq!(ed.autosaved_to(), Some(copy.as_path()));
        let back = crate::format::load(&copy).unwrap().scene;
        assert_eq!(back.node(id).transform.translation.x, 5.0);
        // Nothing new: the copy is not rewritten.
        std::fs::remove_file(&copy).unwrap();
        tick(&mut ed, 200.0);
        assert!(!copy.exists());
        ed.autosave_now().unwrap();
        assert!(copy.exists());
        ed.save_to(&scene).unwrap();
        assert!(!copy.exists(), "a save deletes the copy");
        assert_eq!(ed.autosaved_to(), None);
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn no_autosave_while_a_button_is_held_unless_it_is_stuck() {
        let d = tmp_dir("held");
        let scene = d.join("s.wrl");
        let mut ed = Editor::new(boxes(), None, 320, 240);
        ed.save_to(&scene).unwrap();
        ed.set_autosave_interval(Some(10.0));
        let id = crate::scene::NodeId(0);
        let mut after = Box::new(ed.scene().node(id).clone());
        after.transform.translation.z = 3.0;
        let before = Box::new(ed.scene().node(id).clone());
        ed.execute("move", Command::SetNode { id, before, after });
        let (x, y, mods) = (-5.0, -5.0, crate::editor::Mods::NONE);
        tick(&mut ed, 0.0);
        ed.handle(Event::MouseDown {
            button: MouseButton::Middle,
            x,
            y,
            mods,
        });
        tick(&mut ed, 5.0);
        tick(&mut ed, 12.0);
        assert!(!recovery_path(&scene).exists(), "held: wait");
        // Held for a whole interval: a lost release; save anyway.
        tick(&mut ed, 15.5);
        assert!(recovery_path(&scene).exists());
        std::fs::remove_file(recovery_path(&scene)).unwrap();
        ed.handle(Event::MouseUp {
            button: MouseButton::Middle,
            x,
            y,
            mods,
        });
        let before = Box::new(ed.scene().node(id).clone());
        let mut after = before.clone();
        after.transform.translation.z = 4.0;
        ed.execute("move", Command::SetNode { id, before, after });
        tick(&mut ed, 30.0);
        tick(&mut ed, 40.0);
        assert!(recovery_path(&scene).exists(), "released: saved");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_clock_and_pid_the_shell_gives_make_a_fixed_status_line() {
        // Nothing here depends on when or as which process the test runs:
        // the script sets the wall clock, the test the pid.
        let d = tmp_dir("clock");
        let mut ed = Editor::new(boxes(), None, 320, 240);
        ed.set_state_dir(&d);
        ed.set_pid(4242);
        let id = crate::scene::NodeId(0);
        let before = Box::new(ed.scene().node(id).clone());
        let mut after = before.clone();
        after.transform.translation.y = 2.0;
        ed.execute("move", Command::SetNode { id, before, after });
        let script = "clock 1795833077\nwait-frames 1000\n";
        crate::editor::script::run(&mut ed, script, Path::new("clock.txt")).unwrap();
        let copy = "untitled-4242.animed-recovery.wrl";
        assert_eq!(
            ed.status().text,
            format!("Autosaved untitled work at 02:31:17 UTC ({copy})")
        );
        assert!(d.join(copy).exists());
        assert_eq!(
            ed.wall_clock(),
            SystemTime::UNIX_EPOCH + Duration::from_secs(1_795_833_077)
        );
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn undoing_back_to_the_saved_state_drops_the_copy() {
        let d = tmp_dir("undo");
        let scene = d.join("s.wrl");
        let mut ed = Editor::new(boxes(), None, 320, 240);
        ed.save_to(&scene).unwrap();
        ed.set_autosave_interval(Some(1.0));
        let id = crate::scene::NodeId(0);
        let mut after = Box::new(ed.scene().node(id).clone());
        after.transform.translation.y = 2.0;
        let before = Box::new(ed.scene().node(id).clone());
        ed.execute("move", Command::SetNode { id, before, after });
        tick(&mut ed, 0.0);
        tick(&mut ed, 1.0);
        assert!(recovery_path(&scene).exists());
        ed.undo();
        tick(&mut ed, 1.5);
        assert!(!recovery_path(&scene).exists());
        std::fs::remove_dir_all(&d).unwrap();
    }
}
