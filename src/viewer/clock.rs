//! The viewer's playback clock: real time at the scene's fps, looping,
//! pausable and steppable.
//!
//! The shown frame is worked out from the wall clock at every tick, never
//! by adding one frame per tick, so a slow render drops frames instead of
//! slowing the animation down.

/// Which frame of the animation is shown, and whether it moves.
#[derive(Clone, Debug, PartialEq)]
pub struct Clock {
    fps: f64,
    /// Playback loops over frames `0..length` (the last frame of a looping
    /// VRML TimeSensor equals its first, so it is not shown twice).
    length: u64,
    frame: u64,
    playing: bool,
    /// Wall time and frame at which playback (re)started; set at the first
    /// tick after play or seek.
    anchor: Option<(f64, u64)>,
}

impl Clock {
    /// A clock for an animation of `duration` frames at `fps`, playing.
    pub fn new(fps: f32, duration: f32) -> Clock {
        let fps = if fps.is_finite() && fps > 0.0 {
            fps as f64
        } else {
            24.0
        };
        let length = if duration.is_finite() && duration >= 1.0 {
            (duration as f64).round().min(1e9) as u64
        } else {
            1
        };
        Clock {
            fps,
            length,
            frame: 0,
            playing: true,
            anchor: None,
        }
    }

    pub fn fps(&self) -> f64 {
        self.fps
    }

    pub fn frame(&self) -> u64 {
        self.frame
    }

    /// Frames in one loop.
    pub fn length(&self) -> u64 {
        self.length
    }

    pub fn is_playing(&self) -> bool {
        self.playing
    }

    /// Animation time of the shown frame, in seconds.
    pub fn time(&self) -> f32 {
        (self.frame as f64 / self.fps) as f32
    }

    /// Advances to the frame due at wall time `now` (seconds); returns
    /// whether the shown frame changed.
    pub fn tick(&mut self, now: f64) -> bool {
        if !self.playing {
            return false;
        }
        let (t0, f0) = *self.anchor.get_or_insert((now, self.frame));
        let elapsed = (now - t0).max(0.0);
        // +1e-6: a tick landing exactly on a frame boundary shows that frame.
        let ahead = (elapsed * self.fps + 1e-6).floor() as u64;
        let f = (f0 + ahead) % self.length;
        let changed = f != self.frame;
        self.frame = f;
        changed
    }

    pub fn toggle_pause(&mut self) {
        self.playing = !self.playing;
        self.anchor = None;
    }

    /// Pauses and moves `delta` frames, wrapping around the loop.
    pub fn step(&mut self, delta: i64) {
        self.playing = false;
        self.anchor = None;
        let n = self.length as i64;
        self.frame = (self.frame as i64 + delta).rem_euclid(n) as u64;
    }

    /// Shows the frame nearest `seconds` (clamped into the loop).
    pub fn seek(&mut self, seconds: f64) {
        let f = (seconds * self.fps).round();
        self.frame = if f.is_finite() {
            (f.max(0.0) as u64).min(self.length - 1)
        } else {
            0
        };
        self.anchor = None;
    }

    /// Length of one loop in seconds.
    pub fn loop_seconds(&self) -> f64 {
        self.length as f64 / self.fps
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plays_in_real_time_and_loops() {
        let mut c = Clock::new(10.0, 20.0);
        assert!(!c.tick(100.0)); // anchors at frame 0
        assert!(c.tick(100.35));
        assert_eq!(c.frame(), 3);
        // A slow frame: 1.2 s later we are 12 frames on, not 1.
        c.tick(101.55);
        assert_eq!(c.frame(), 15);
        // Wraps after 20 frames (2 s).
        c.tick(102.05);
        assert_eq!(c.frame(), 0);
        assert!((c.time() - 0.0).abs() < 1e-9);
    }

    #[test]
    fn pause_holds_and_resumes_from_the_held_frame() {
        let mut c = Clock::new(10.0, 100.0);
        c.tick(0.0);
        c.tick(0.5);
        assert_eq!(c.frame(), 5);
        c.toggle_pause();
        assert!(!c.tick(3.0));
        assert_eq!(c.frame(), 5);
        c.toggle_pause();
        c.tick(10.0); // re-anchors here
        c.tick(10.2);
        assert_eq!(c.frame(), 7);
    }

    #[test]
    fn steps_wrap_and_pause() {
        let mut c = Clock::new(24.0, 96.0);
        c.step(-1);
        assert!(!c.is_playing());
        assert_eq!(c.frame(), 95);
        c.step(2);
        assert_eq!(c.frame(), 1);
        assert!((c.time() - 1.0 / 24.0).abs() < 1e-7);
    }

    #[test]
    fn seek_clamps_into_the_loop() {
        let mut c = Clock::new(24.0, 96.0);
        c.seek(1.0);
        assert_eq!(c.frame(), 24);
        c.seek(100.0);
        assert_eq!(c.frame(), 95);
        c.seek(-3.0);
        assert_eq!(c.frame(), 0);
        c.seek(f64::NAN);
        assert_eq!(c.frame(), 0);
        assert!((c.loop_seconds() - 4.0).abs() < 1e-12);
    }

    #[test]
    fn odd_settings_do_not_break_it() {
        let mut c = Clock::new(0.0, 0.0);
        assert_eq!(c.length(), 1);
        assert_eq!(c.fps(), 24.0);
        c.tick(0.0);
        c.tick(5.0);
        assert_eq!(c.frame(), 0);
        c.step(3);
        assert_eq!(c.frame(), 0);
    }
}
