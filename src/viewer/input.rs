//! Events → viewer state. Mouse bindings follow the editor's View mode:
//! left drag orbits (Shift+left pans), middle orbits (Shift+middle pans),
//! right pans, the wheel zooms.

use super::draw::{bar_rect, time_at_x, viewport_rect};
use super::{Drag, Eye, Viewer};
use crate::input::{Event, Key, Mods, MouseButton};

impl Viewer {
    /// Feeds one event; returns true when the picture needs redrawing.
    pub fn handle(&mut self, ev: Event) -> bool {
        match ev {
            Event::Resize { width, height } => {
                let size = (width.max(16), height.max(16));
                let changed = size != (self.width, self.height);
                (self.width, self.height) = size;
                changed
            }
            Event::Tick { time } => {
                self.now = Some(time);
                let frame_changed = self.clock.tick(time);
                frame_changed || self.show_stats
            }
            Event::KeyDown { key, mods } => self.key(key, mods),
            Event::KeyUp { .. } | Event::Text(_) => false,
            Event::MouseDown { button, x, y, mods } => {
                self.mouse = (x, y);
                self.mouse_down(button, x, y, mods)
            }
            Event::MouseMove { x, y, .. } => self.mouse_move(x, y),
            Event::MouseUp { .. } => {
                if let Drag::Scrub { resume: true } = self.drag {
                    self.clock.toggle_pause();
                }
                self.drag = Drag::None;
                true
            }
            Event::Wheel { delta, x, y, .. } => {
                if bar_rect(self.width, self.height).contains(x, y) {
                    self.clock.step(if delta > 0.0 { 1 } else { -1 });
                } else {
                    self.orbit_camera().zoom(delta);
                }
                true
            }
        }
    }

    fn key(&mut self, key: Key, mods: Mods) -> bool {
        match key {
            Key::Space => self.clock.toggle_pause(),
            Key::Left => self.clock.step(-1),
            Key::Right => self.clock.step(1),
            Key::PageDown => self.cycle_viewpoint(1),
            Key::PageUp => self.cycle_viewpoint(-1),
            Key::Home => self.eye = self.fixed_eye(),
            Key::Char('h') => self.headlight = !self.headlight,
            Key::Char('c') if !mods.ctrl => {
                return self.cycle_clip(if mods.shift { -1 } else { 1 })
            }
            Key::Char('s') if !mods.ctrl => self.show_stats = !self.show_stats,
            Key::Escape | Key::Char('q') => self.quit = true,
            _ => return false,
        }
        true
    }

    /// The viewpoint the view returns to (Home) and cycles from.
    fn fixed_eye(&self) -> Eye {
        if self.cameras.is_empty() {
            Eye::ViewAll
        } else {
            Eye::Viewpoint(self.vp_index.min(self.cameras.len() - 1))
        }
    }

    fn cycle_viewpoint(&mut self, step: i64) {
        let n = self.cameras.len() as i64;
        if n == 0 {
            self.eye = Eye::ViewAll;
            return;
        }
        // From a free view, PageDown/PageUp first return to the viewpoint
        // the view came from, as a viewer's "jump to viewpoint" does.
        if matches!(self.eye, Eye::Viewpoint(_)) {
            self.vp_index = (self.vp_index as i64 + step).rem_euclid(n) as usize;
        }
        self.eye = Eye::Viewpoint(self.vp_index);
    }

    /// The orbit camera, turning the current view into one first.
    fn orbit_camera(&mut self) -> &mut crate::input::camera::OrbitCamera {
        if !matches!(self.eye, Eye::Orbit(_)) {
            self.eye = Eye::Orbit(self.orbit_from_current());
        }
        match &mut self.eye {
            Eye::Orbit(c) => c,
            // Set just above.
            _ => unreachable!("the eye was made an orbit camera"),
        }
    }

    fn mouse_down(&mut self, button: MouseButton, x: f32, y: f32, mods: Mods) -> bool {
        if bar_rect(self.width, self.height).contains(x, y) {
            if button != MouseButton::Left {
                return false;
            }
            let resume = self.clock.is_playing();
            if resume {
                self.clock.toggle_pause();
            }
            self.drag = Drag::Scrub { resume };
            self.scrub_to(x);
            return true;
        }
        if !viewport_rect(self.width, self.height).contains(x, y) {
            return false;
        }
        self.drag = match (button, mods.shift) {
            (MouseButton::Left, false) | (MouseButton::Middle, false) => {
                Drag::Orbit { last: (x, y) }
            }
            _ => Drag::Pan { last: (x, y) },
        };
        false
    }

    fn mouse_move(&mut self, x: f32, y: f32) -> bool {
        self.mouse = (x, y);
        match self.drag {
            Drag::None => false,
            Drag::Scrub { .. } => {
                self.scrub_to(x);
                true
            }
            Drag::Orbit { last } => {
                self.orbit_camera().orbit(x - last.0, y - last.1);
                self.drag = Drag::Orbit { last: (x, y) };
                true
            }
            Drag::Pan { last } => {
                let h = viewport_rect(self.width, self.height).h as f32;
                self.orbit_camera().pan(x - last.0, y - last.1, h);
                self.drag = Drag::Pan { last: (x, y) };
                true
            }
        }
    }

    fn scrub_to(&mut self, x: f32) {
        let t = time_at_x(self.width, self.height, x, self.clock.loop_seconds());
        self.clock.seek(t);
    }
}
