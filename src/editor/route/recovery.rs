//! The editor's side of `recovery`: routes events to it and applies what it returns.

use crate::editor::command::Command;
use crate::editor::panel::Action;
#[allow(unused_imports)]
use crate::editor::recovery::*;
use crate::editor::{After, Dialog, Editor};
use crate::input::Key;
use std::path::{Path, PathBuf};
use std::time::{Instant, SystemTime};

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

    /// Where this session's recovery copy goes.
    pub fn recovery_file(&self) -> PathBuf {
        match &self.path {
            Some(p) => recovery_path(p),
            None => self.untitled_file(),
        }
    }

    /// Where this session's untitled work is autosaved.
    fn untitled_file(&self) -> PathBuf {
        match &self.autosave.dir {
            Some(d) => untitled_in(d),
            None => untitled_path(),
        }
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
    pub(in crate::editor) fn autosave_tick(&mut self, now: f64) -> bool {
        if !self.is_dirty() {
            self.autosave.since = None;
            if let Some(p) = self.autosave.written.take() {
                // Back at the saved state (undo): the copy is stale.
                remove(&p);
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
        match self.autosave_now() {
            Ok(p) => {
                // Say so: the user should see their work is safe.
                let name = p.file_name().map(|n| n.to_string_lossy().to_string());
                let when = clock_utc(SystemTime::now());
                let what = match &self.path {
                    Some(_) => "unsaved changes",
                    None => "untitled work",
                };
                self.set_status(
                    &format!("Autosaved {what} at {when} ({})", name.unwrap_or_default()),
                    false,
                );
                true
            }
            Err(e) => {
                // Try again after another interval.
                self.autosave.since = Some(now);
                self.set_status(&format!("Autosave failed: {e}"), true);
                true
            }
        }
    }

    /// Writes the recovery copy now; returns where.
    pub fn autosave_now(&mut self) -> Result<PathBuf, String> {
        let path = self.recovery_file();
        let t0 = Instant::now();
        write(&self.scene, &path)?;
        self.autosave.last_ms = Some(t0.elapsed().as_secs_f64() * 1e3);
        self.autosave.copied = Some(self.history.revision());
        self.autosave.since = None;
        self.autosave.written = Some(path.clone());
        Ok(path)
    }

    /// Deletes this session's recovery copy (changes saved or discarded).
    pub(in crate::editor) fn forget_recovery(&mut self) {
        if let Some(p) = self.autosave.written.take() {
            remove(&p);
        }
        self.autosave.since = None;
        self.autosave.copied = None;
    }

    /// After a successful save (the scene was at `old` before): the copies
    /// of both names are out of date.
    pub(in crate::editor) fn saved_recovery(&mut self, old: Option<&Path>) {
        self.forget_recovery();
        if old.is_none() {
            remove(&self.untitled_file());
        }
        if let Some(p) = &self.path {
            remove(&recovery_path(p));
        }
    }

    /// A new scene replaced the old one (its changes were saved or
    /// discarded before).
    pub(in crate::editor) fn reset_recovery(&mut self) {
        self.forget_recovery();
        self.autosave.offer = None;
    }

    /// When the open scene has a newer recovery copy beside it, asks
    /// whether to recover it (the dialog's Recover / Discard copy / Open
    /// saved). Call after opening a file.
    pub fn check_recovery(&mut self) {
        let Some(scene) = self.path.clone() else {
            return;
        };
        let Some((copy, when)) = newer_copy(&scene) else {
            return;
        };
        let name = scene
            .file_name()
            .map(|n| n.to_string_lossy().to_string())
            .unwrap_or_default();
        let when = describe_time(when, SystemTime::now());
        self.autosave.offer = Some(copy);
        self.dialog = Some(Dialog {
            message: format!("Unsaved work on {name} was autosaved\n{when}. Recover it?"),
            then: After::Recover,
        });
    }

    /// The recovery copy the open dialog offers.
    pub fn recovery_offer(&self) -> Option<&Path> {
        self.autosave.offer.as_deref()
    }

    /// At start: when untitled sessions left recovery copies in `dir` (the
    /// state folder, see `state_dir`), lists them newest first in the
    /// recovery dialog (unless another question is open). Returns how
    /// many were offered.
    pub fn offer_untitled(&mut self, dir: &Path) -> usize {
        if self.dialog.is_some() {
            return 0;
        }
        self.autosave.dir = Some(dir.to_path_buf());
        self.autosave.untitled = untitled_sessions(dir);
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
    fn show_untitled_offer(&mut self) {
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
        let lines = session_lines(list, SystemTime::now());
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
        });
    }

    /// Keys of the recovery dialog: Enter or R recovers, D discards the
    /// copy, O or Esc opens the saved file. True when the key was taken.
    pub(in crate::editor) fn recovery_key(&mut self, key: Key) -> bool {
        if !self
            .dialog
            .as_ref()
            .is_some_and(|d| d.then == After::Recover)
        {
            return false;
        }
        let untitled = !self.autosave.untitled.is_empty();
        let n = self.autosave.untitled.len().min(9);
        let a = match key {
            Key::Up | Key::Down if untitled => {
                let c = self.autosave.chosen;
                self.autosave.chosen = match key {
                    Key::Up => c.saturating_sub(1),
                    _ => (c + 1).min(n.saturating_sub(1)),
                };
                self.show_untitled_offer();
                return true;
            }
            Key::Char(d @ '1'..='9') if untitled => {
                let i = d as usize - '1' as usize;
                if i >= n {
                    return true;
                }
                self.autosave.chosen = i;
                self.show_untitled_offer();
                Action::DialogSave
            }
            Key::Enter | Key::Char('r') => Action::DialogSave,
            Key::Char('d') => Action::DialogDiscard,
            Key::Escape | Key::Char('o') => Action::DialogCancel,
            _ => return true,
        };
        self.run_action(a);
        true
    }

    /// Dialog buttons while the recovery question is open (Save = Recover,
    /// Discard = Discard copy, Cancel = Open saved); also drops this
    /// session's copy when unsaved changes are discarded. True when the
    /// action was handled here.
    pub(in crate::editor) fn recovery_action(&mut self, a: Action) -> bool {
        let recovering = self
            .dialog
            .as_ref()
            .is_some_and(|d| d.then == After::Recover);
        if !recovering {
            if a == Action::DialogDiscard && self.dialog.is_some() {
                self.forget_recovery();
            }
            return false;
        }
        if !self.autosave.untitled.is_empty() {
            return self.untitled_action(a);
        }
        let copy = self.autosave.offer.take();
        match a {
            Action::DialogSave => {
                self.dialog = None;
                if let Some(copy) = copy {
                    self.recover_from(&copy);
                }
            }
            Action::DialogDiscard => {
                self.dialog = None;
                if let Some(copy) = copy {
                    remove(&copy);
                    self.set_status("Recovery copy deleted", false);
                }
            }
            Action::DialogCancel => {
                // Kept: asked again next time, replaced by the next autosave.
                self.dialog = None;
                self.set_status("Opened the saved file; the recovery copy is kept", false);
            }
            _ => {
                self.autosave.offer = copy;
                return false;
            }
        }
        true
    }

    /// The recovery dialog's buttons for untitled sessions: Recover loads
    /// the marked one as new untitled work, Discard copy deletes it and
    /// lists the rest, Not now keeps them all for the next start.
    fn untitled_action(&mut self, a: Action) -> bool {
        let i = self.autosave.chosen;
        match a {
            Action::DialogSave => {
                let s = self.autosave.untitled.remove(i);
                self.autosave.untitled.clear();
                self.autosave.offer = None;
                self.dialog = None;
                self.recover_untitled(&s.path);
            }
            Action::DialogDiscard => {
                let s = self.autosave.untitled.remove(i);
                remove(&s.path);
                self.set_status(
                    &format!("Deleted the recovery copy {}", s.path.display()),
                    false,
                );
                self.show_untitled_offer();
            }
            Action::DialogCancel => {
                let n = self.autosave.untitled.len();
                self.autosave.untitled.clear();
                self.autosave.offer = None;
                self.dialog = None;
                self.set_status(
                    &format!(
                        "Kept {n} recovery cop{} for later (`animed recover --list`)",
                        if n == 1 { "y" } else { "ies" }
                    ),
                    false,
                );
            }
            _ => return false,
        }
        true
    }

    /// Opens an untitled session's copy as new untitled work: an empty
    /// scene, then one undoable "Recover" step (so the work counts as
    /// unsaved and keeps being autosaved). The copy becomes this session's
    /// own, so a save or a clean quit deletes it.
    pub fn recover_untitled(&mut self, copy: &Path) {
        let loaded = match crate::format::load(copy) {
            Ok(l) => l,
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
                after: Box::new(loaded.scene),
            },
        );
        self.frame_all();
        let mine = self.untitled_file();
        let taken = if copy == mine || std::fs::rename(copy, &mine).is_ok() {
            mine
        } else {
            copy.to_path_buf()
        };
        self.autosave.written = Some(taken);
        self.set_status(
            "Recovered untitled work: Ctrl+S saves it under a name",
            false,
        );
    }

    /// Loads the recovery copy into the editor as one undoable change (undo
    /// shows the saved file again); the file name stays the scene's, so
    /// Ctrl+S writes the original.
    pub(in crate::editor) fn recover_from(&mut self, copy: &Path) {
        match crate::format::load(copy) {
            Ok(l) => {
                let before = Box::new(self.scene.clone());
                self.execute(
                    "Recover autosaved work",
                    Command::ReplaceScene {
                        before,
                        after: Box::new(l.scene),
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
        self.dialog = Some(Dialog {
            message: "Save changes before closing?".into(),
            then: After::Quit,
        });
        true
    }

    /// The window loop ended: after a clean quit this session's copy goes;
    /// closed with unsaved changes (closed twice, or the window system
    /// went away), they are written to the recovery copy right away.
    /// Returns a line to print.
    pub fn window_closed(&mut self) -> Option<String> {
        if !self.is_dirty() || self.quit {
            self.forget_recovery();
            return None;
        }
        Some(match self.autosave_now() {
            Ok(p) => {
                let how = match &self.path {
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
        let u = untitled_path();
        assert!(u.is_absolute(), "{}", u.display());
        assert!(u.to_string_lossy().ends_with(&format!(
            "untitled-{}.animed-recovery.wrl",
            std::process::id()
        )));
    }

    #[test]
    fn only_a_newer_copy_is_offered() {
        let d = tmp_dir("newer");
        let scene = d.join("s.wrl");
        std::fs::write(&scene, "#VRML V2.0 utf8\n").unwrap();
        assert_eq!(newer_copy(&scene), None, "no copy");
        let copy = recovery_path(&scene);
        std::fs::write(&copy, "#VRML V2.0 utf8\n").unwrap();
        let now = SystemTime::now();
        let set = |p: &Path, t: SystemTime| {
            let f = std::fs::OpenOptions::new().write(true).open(p).unwrap();
            f.set_modified(t).unwrap();
        };
        set(&scene, now - Duration::from_secs(60));
        set(&copy, now);
        assert_eq!(newer_copy(&scene).map(|c| c.0), Some(copy.clone()));
        // Saved after the copy: the copy is stale.
        set(&scene, now + Duration::from_secs(1));
        assert_eq!(newer_copy(&scene), None);
        // The scene file is gone: the copy is all there is.
        std::fs::remove_file(&scene).unwrap();
        assert!(newer_copy(&scene).is_some());
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
        ed.autosave_tick(100.0);
        ed.autosave_tick(129.0);
        assert!(!copy.exists(), "29 s after the first change: not yet");
        ed.autosave_tick(130.5);
        assert!(copy.exists(), "30 s after the first change");
        assert_eq!(ed.autosaved_to(), Some(copy.as_path()));
        let back = crate::format::load(&copy).unwrap().scene;
        assert_eq!(back.node(id).transform.translation.x, 5.0);
        // Nothing new: the copy is not rewritten.
        std::fs::remove_file(&copy).unwrap();
        ed.autosave_tick(200.0);
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
        ed.autosave_tick(0.0);
        ed.handle(Event::MouseDown {
            button: MouseButton::Middle,
            x,
            y,
            mods,
        });
        ed.autosave_tick(5.0);
        ed.autosave_tick(12.0);
        assert!(!recovery_path(&scene).exists(), "held: wait");
        // Held for a whole interval: a lost release; save anyway.
        ed.autosave_tick(15.5);
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
        ed.autosave_tick(30.0);
        ed.autosave_tick(40.0);
        assert!(recovery_path(&scene).exists(), "released: saved");
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
        ed.autosave_tick(0.0);
        ed.autosave_tick(1.0);
        assert!(recovery_path(&scene).exists());
        ed.undo();
        ed.autosave_tick(1.5);
        assert!(!recovery_path(&scene).exists());
        std::fs::remove_dir_all(&d).unwrap();
    }
}
