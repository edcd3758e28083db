//! The editor's side of the file browser component (`browser_ui.rs`):
//! routes events to it while it is open and turns its answer into file
//! requests for the shell.

use crate::editor::browser::{Ask, Found, Purpose};
use crate::editor::browser_ui::Reply;
use crate::editor::gesture::is_writable_type;
use crate::editor::request::Request;
use crate::editor::Editor;
use crate::input::Event;

impl Editor {
    /// Offers `ev` to the open browser (a question on top of it goes
    /// first): `Some(redraw)` when it took it.
    pub(in crate::internals::editor) fn browser_event(&mut self, ev: &Event) -> Option<bool> {
        if self.dialog.is_some() {
            return None;
        }
        let r = self.browser_rect();
        let reply = self.browser.as_mut()?.handle(ev, r);
        self.browser_reply(reply)
    }

    /// The shell's answer to what the browser asked to have read (a
    /// listing, or what a typed path is); a settled choice is used.
    pub fn browser_found(&mut self, ask: Ask, found: Found) {
        let Some(b) = &mut self.browser else { return };
        if let Some(path) = b.found(ask, found) {
            self.browser_reply(Reply::Use(path));
        }
    }

    /// Applies the browser's answer: a chosen file is asked of the shell
    /// (its answer, `route/files.rs`, closes the browser or shows why not).
    pub(in crate::internals::editor) fn browser_reply(&mut self, reply: Reply) -> Option<bool> {
        match reply {
            Reply::Ignored => None,
            Reply::Taken(redraw) => Some(redraw),
            Reply::Cancel => {
                self.browser = None;
                self.browser_then = None;
                Some(true)
            }
            Reply::Use(path) => {
                let purpose = self.browser.as_ref().map(|b| b.purpose)?;
                match purpose {
                    Purpose::Open => self.requests.push(Request::Open(path)),
                    Purpose::Import => self.requests.push(Request::Import(path)),
                    Purpose::Texture => self.ask_texture(path),
                    Purpose::SaveAs => {
                        let path = if is_writable_type(&path) {
                            path
                        } else {
                            let mut s = path.into_os_string();
                            s.push(".wrl");
                            s.into()
                        };
                        self.request_save(path, None);
                    }
                }
                Some(true)
            }
        }
    }
}
