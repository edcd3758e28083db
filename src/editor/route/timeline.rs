//! Routing for the timeline's zoom, pan and preview range
//! ([`crate::editor::timeline`]): the wheel over the ruler or key strip
//! zooms about the mouse, a middle drag pans, Shift+drag on the ruler or
//! `[` / `]` set the preview range, Alt+P clears it; and the note when a
//! shorter scene leaves keys after its end.

use crate::editor::timeline::{full_span, play_frame};
use crate::editor::Editor;

impl Editor {
    /// The last key frame of every track in the scene.
    pub(in crate::internals::editor) fn last_key_frame(&self) -> Option<f32> {
        self.scene
            .animation
            .tracks
            .iter()
            .filter_map(|t| t.frame_range().map(|r| r.1))
            .reduce(f32::max)
    }

    /// Frames at the ruler's ends (what every strip drawing and hit test
    /// maps with).
    pub fn time_span(&self) -> (f32, f32) {
        self.timeline
            .span(self.scene.settings.duration, self.last_key_frame())
    }

    /// The preview range playback loops over, if set.
    pub fn preview_range(&self) -> Option<(f32, f32)> {
        self.timeline.preview
    }

    /// Sets (or with `None` clears) the preview range, saying so.
    pub fn set_preview_range(&mut self, range: Option<(f32, f32)>) {
        let dur = self.scene.settings.duration;
        match range.and_then(|(a, b)| self.timeline.set_preview(a, b, dur)) {
            Some((a, b)) => self.set_status(
                &format!("Preview frames {a} to {b}: playback loops over them (Alt+P clears)"),
                false,
            ),
            None => {
                self.timeline.preview = None;
                self.set_status(
                    "Preview range cleared: playback loops over the whole scene",
                    false,
                );
            }
        }
    }

    /// Play or stop: the status line says which (and over which frames),
    /// so an older message such as the preview range's hint does not
    /// stay after playback stops.
    pub(in crate::internals::editor) fn say_playback(&mut self) {
        let msg = match (self.playback.is_some(), self.timeline.preview) {
            (true, Some((a, b))) => {
                format!("Playing frames {a} to {b} (preview range; Space stops)")
            }
            (true, None) => "Playing (Space stops)".to_string(),
            (false, _) => format!("Stopped at frame {}", self.frame.round()),
        };
        self.set_status(&msg, false);
    }

    /// `[` / `]`: the preview range starts / ends at the current frame
    /// (the other end is kept, or is the scene's end / start).
    pub(in crate::internals::editor) fn preview_end_here(&mut self, start: bool) {
        let dur = self.scene.settings.duration;
        let (a, b) = self.timeline.preview.unwrap_or((0.0, dur));
        let f = self.frame;
        let r = if start {
            (f, b.max(f + 1.0))
        } else {
            (a.min(f - 1.0), f)
        };
        self.set_preview_range(Some(r));
    }

    /// Wheel over the ruler or key strip: zooms about the frame under the
    /// mouse (positive `delta` zooms in).
    pub(in crate::internals::editor) fn zoom_timeline(&mut self, x: f32, delta: f32) {
        let l = self.layout();
        let span = self.time_span();
        let full = full_span(self.scene.settings.duration, self.last_key_frame());
        let about = l.x_to_frame_in(x, span);
        self.timeline.zoom(span, full, about, delta);
        self.say_timeline_span();
    }

    /// The status line names the frames the strip shows.
    pub(in crate::internals::editor) fn say_timeline_span(&mut self) {
        let s = self.time_span();
        let msg = if self.timeline.is_zoomed() {
            format!(
                "Timeline shows frames {} to {} (wheel zooms, middle-drag pans, Home in the strip resets)",
                s.0.round(),
                s.1.round()
            )
        } else {
            "Timeline shows the whole scene".to_string()
        };
        self.set_status(&msg, false);
    }

    /// Middle drag over the strip: the frames follow the mouse by `dx`
    /// pixels.
    pub(in crate::internals::editor) fn pan_timeline(&mut self, dx: f32) {
        let l = self.layout();
        let span = self.time_span();
        let per_px = l.x_to_frame_in(1.0, span) - l.x_to_frame_in(0.0, span);
        self.timeline.pan(span, -dx * per_px);
    }

    /// Back to the whole scene in the strip.
    pub(in crate::internals::editor) fn reset_timeline_view(&mut self) {
        self.timeline.reset_view();
        self.set_status("Timeline shows the whole scene", false);
    }

    /// The frame playback shows at `elapsed` seconds after it started
    /// from `start`.
    pub(in crate::internals::editor) fn playback_frame(&self, start: f32, elapsed: f64) -> f32 {
        let fps = self.scene.settings.fps.max(1e-6) as f64;
        play_frame(
            start,
            elapsed * fps,
            self.scene.settings.duration,
            self.timeline.preview,
        )
    }

    /// After the scene's length changed: keys after the new end are still
    /// shown (greyed) and the status line says how many; a preview range
    /// past the end is cut to it.
    pub(in crate::internals::editor) fn note_keys_after_end(&mut self) {
        let dur = self.scene.settings.duration;
        if let Some((a, b)) = self.timeline.preview {
            self.timeline.preview = (a < dur).then_some((a, b.min(dur)));
        }
        let late: usize = self
            .scene
            .animation
            .tracks
            .iter()
            .map(|t| t.keys.frames().iter().filter(|&&f| f > dur).count())
            .sum();
        if late > 0 {
            // Short enough for a 480-pixel-wide window's status line.
            let s = if late == 1 { "key" } else { "keys" };
            self.set_status(
                &format!("{late} {s} after frame {dur} kept (greyed)"),
                false,
            );
        }
    }
}
