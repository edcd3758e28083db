//! The editor as the window loop's [`Screen`].

use super::Editor;
use crate::input::{Event, Screen};
use crate::render::Frame;

impl Screen for Editor {
    fn size(&self) -> (u32, u32) {
        Editor::size(self)
    }
    fn handle(&mut self, ev: Event) -> bool {
        Editor::handle(self, ev)
    }
    fn perform(&mut self) -> bool {
        super::shell::perform(self)
    }
    fn set_wall_clock(&mut self, now: std::time::SystemTime) {
        Editor::set_wall_clock(self, now)
    }
    fn draw(&mut self, frame: &mut Frame) {
        Editor::draw(self, frame)
    }
    fn wants_quit(&self) -> bool {
        Editor::wants_quit(self)
    }
    fn wants_ticks(&self) -> bool {
        Editor::wants_ticks(self)
    }
    fn is_dirty(&self) -> bool {
        Editor::is_dirty(self)
    }
    fn window_title(&self) -> String {
        Editor::window_title(self)
    }
    fn wants_clock(&self) -> bool {
        Editor::wants_clock(self)
    }
    fn window_closed(&mut self) -> Option<String> {
        Editor::window_closed(self)
    }
    fn close_requested(&mut self) -> bool {
        Editor::close_requested(self)
    }
}
