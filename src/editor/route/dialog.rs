//! The editor's side of the dialog component (`dialog.rs`): routes events
//! to the open question and applies its answer — save, discard, delete,
//! or the recovery choices, which become file requests for the shell.

use crate::editor::browser::Purpose;
use crate::editor::dialog::Answer;
use crate::editor::gesture::{is_writable_type, Drag};
use crate::editor::request::Request;
use crate::editor::{After, Editor};
use crate::input::Event;

impl Editor {
    /// Offers `ev` to the open question: `Some(redraw)` when it took it.
    pub(in crate::internals::editor) fn dialog_event(&mut self, ev: &Event) -> Option<bool> {
        self.dialog.as_ref()?;
        if let Event::MouseDown { .. } | Event::KeyDown { .. } = ev {
            if self.help_shown() {
                // Any key or click closes the help first.
                return None;
            }
            if let Event::MouseDown { x, y, .. } = ev {
                self.hover.moved(None);
                self.mouse = (*x, *y);
            }
        }
        let win = self.layout().window;
        match self.dialog.as_ref()?.handle(ev, win) {
            Answer::Ignored => None,
            Answer::Taken(redraw) => Some(redraw),
            a => {
                self.dialog_answer(a);
                Some(true)
            }
        }
    }

    /// Where the mouse lights a modal box's buttons and rows (not during
    /// a drag).
    pub(in crate::internals::editor) fn modal_mouse(&self) -> Option<(f32, f32)> {
        matches!(self.drag, Drag::None).then_some(self.mouse)
    }

    /// Applies the open question's answer.
    pub(in crate::internals::editor) fn dialog_answer(&mut self, a: Answer) {
        let Some(d) = self.dialog.as_ref() else {
            return;
        };
        match (d.then, d.list) {
            (After::Recover, true) => self.untitled_answer(a),
            (After::Recover, false) => self.recovery_answer(a),
            (After::DeleteObject, _) => {
                self.dialog = None;
                match a {
                    Answer::Yes => self.delete_selection(),
                    _ => self.set_status("Nothing deleted", false),
                }
            }
            (then, _) => match a {
                Answer::Yes => {
                    self.dialog = None;
                    match self.path.clone() {
                        Some(p) if is_writable_type(&p) => self.request_save(p, Some(then)),
                        _ => self.browse(Purpose::SaveAs, Some(then)),
                    }
                }
                Answer::Discard => {
                    self.dialog = None;
                    // Discarding: forget the changes (and their recovery
                    // copy) before continuing.
                    self.forget_recovery();
                    self.saved_revision = self.history.revision();
                    self.continue_with(then);
                }
                _ => self.dialog = None,
            },
        }
    }

    /// The recovery question about the open file's copy: Recover loads it,
    /// Discard copy deletes it, Open saved keeps it for next time.
    fn recovery_answer(&mut self, a: Answer) {
        self.dialog = None;
        let copy = self.autosave.offer.take();
        match a {
            Answer::Yes => {
                if let Some(copy) = copy {
                    self.requests.push(Request::Recover { copy });
                }
            }
            Answer::Discard => {
                if let Some(copy) = copy {
                    self.requests.push(Request::Remove(copy));
                    self.set_status("Recovery copy deleted", false);
                }
            }
            _ => {
                // Kept: asked again next time, replaced by the next autosave.
                self.set_status("Opened the saved file; the recovery copy is kept", false);
            }
        }
    }

    /// The recovery question listing untitled sessions: the arrows and
    /// 1-9 move the mark, Recover loads the marked one as new untitled
    /// work, Discard copy deletes it and lists the rest, Not now keeps
    /// them all for the next start.
    fn untitled_answer(&mut self, a: Answer) {
        let n = self.autosave.untitled.len().min(9);
        let i = self.autosave.chosen;
        match a {
            Answer::Step(d) => {
                self.autosave.chosen = i.saturating_add_signed(d as isize).min(n.saturating_sub(1));
                self.show_untitled_offer();
            }
            Answer::Pick(p) if p >= n => {}
            Answer::Pick(p) => {
                self.autosave.chosen = p;
                self.show_untitled_offer();
                self.untitled_answer(Answer::Yes);
            }
            Answer::Yes => {
                let s = self.autosave.untitled.remove(i);
                self.autosave.untitled.clear();
                self.autosave.offer = None;
                self.dialog = None;
                // Offered sessions came from the state folder: it is set.
                if let Some(mine) = self.untitled_file() {
                    self.requests
                        .push(Request::RecoverUntitled { copy: s.path, mine });
                }
            }
            Answer::Discard => {
                let s = self.autosave.untitled.remove(i);
                self.set_status(
                    &format!("Deleted the recovery copy {}", s.path.display()),
                    false,
                );
                self.requests.push(Request::Remove(s.path));
                self.show_untitled_offer();
            }
            _ => {
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
        }
    }
}
