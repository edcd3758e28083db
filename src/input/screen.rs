//! What the window loop drives. The editor and the viewer (`animed view`)
//! both implement it, so there is one window loop for both.

use super::Event;
use crate::render::Frame;

/// A pure state machine the window shows: events in, frames out.
pub trait Screen {
    /// Size the window opens at.
    fn size(&self) -> (u32, u32);
    /// Feeds one event; returns true when the picture needs redrawing.
    fn handle(&mut self, ev: Event) -> bool;
    /// Performs the side effects the handled events asked for (the
    /// editor's file work: open, save, autosave, recover); the loop calls
    /// it after every batch of events. Returns true when the picture
    /// changed.
    fn perform(&mut self) -> bool {
        false
    }
    /// The wall clock, told by the window loop before each pass's events
    /// (the editor's "Autosaved at …"): a screen never reads the clock
    /// itself, so tests and scripts can fix it.
    fn set_wall_clock(&mut self, _now: std::time::SystemTime) {}
    /// Draws into `frame` (resizing it to [`Screen::size`]).
    fn draw(&mut self, frame: &mut Frame);
    fn wants_quit(&self) -> bool;
    /// True while something moves on its own (playback): the loop then
    /// sends `Event::Tick`s and polls fast.
    fn wants_ticks(&self) -> bool;
    /// Unsaved changes (reported when the window is closed).
    fn is_dirty(&self) -> bool {
        false
    }
    /// Window title (checked every frame; the window follows changes).
    fn window_title(&self) -> String {
        "animed".to_string()
    }
    /// True when it needs a `Tick` at least every second even while idle
    /// (the editor's autosave clock).
    fn wants_clock(&self) -> bool {
        false
    }
    /// The window's close button was used: true keeps the program running
    /// (the screen asks about unsaved work first; the loop reopens the
    /// window to show the question).
    fn close_requested(&mut self) -> bool {
        false
    }
    /// The loop ended (quit or closed): last chance to keep unsaved work.
    /// Returns a line to print.
    fn window_closed(&mut self) -> Option<String> {
        None
    }
}
