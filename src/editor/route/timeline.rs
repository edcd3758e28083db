//! Routing for the timeline's zoom, pan and preview range
//! ([`crate::editor::timeline`]): the wheel over the ruler or key strip
//! zooms about the mouse, a middle drag pans, Shift+drag on the ruler or
//! `[` / `]` set the preview range, Alt+P clears it; and the note when a
//! shorter scene leaves keys after its end.

use crate::editor::fields::FieldId;
use crate::editor::panel::{label, Widget, WidgetKind};
use crate::editor::timeline::{full_span, play_frame};
use crate::editor::Editor;
use crate::ui::text::{self, CHAR_W};
use crate::ui::Rect;

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

    /// A preview range field's frame (`None` without a range).
    pub(in crate::internals::editor) fn preview_field(&self, id: FieldId) -> Option<f32> {
        let (a, b) = self.timeline.preview?;
        match id {
            FieldId::Preview(0) => Some(a),
            FieldId::Preview(_) => Some(b),
            _ => None,
        }
    }

    /// A typed preview start (`end` 0) or end (1): the other end is kept;
    /// a start not before the end (or the reverse) is refused, a frame
    /// outside the scene is clamped, both said in the status line.
    pub(in crate::internals::editor) fn set_preview_field(&mut self, end: u8, x: f32) {
        let dur = self.scene.settings.duration;
        let (a, b) = self.timeline.preview.unwrap_or((0.0, dur));
        let f = x.round().clamp(0.0, dur);
        let name = FieldId::Preview(end).label();
        let ok = match end {
            0 => f < b,
            _ => f > a,
        };
        if !ok {
            let other = if end == 0 { b } else { a };
            let side = if end == 0 { "before" } else { "after" };
            let msg = format!("{name} {x} must be {side} the other end ({other})");
            self.set_status(&msg, true);
            return;
        }
        let r = if end == 0 { (f, b) } else { (a, f) };
        self.set_preview_range(Some(r));
        if let Some(n) = crate::editor::fields::clamp_note(&name, x, f) {
            self.set_status(&format!("{n} (the scene has frames 0 to {dur})"), false);
        }
    }

    /// The controls bar's `Preview [a]-[b]` fields while a range is set;
    /// returns the next free x.
    pub(in crate::internals::editor) fn preview_widgets(
        &self,
        x: i32,
        y: i32,
        h: i32,
        out: &mut Vec<Widget>,
    ) -> i32 {
        if self.timeline.preview.is_none() {
            return x;
        }
        let lw = text::width("Preview");
        let fw = 5 * CHAR_W;
        if x + lw + 2 * fw + 24 > self.layout().controls.right() - 60 {
            return x;
        }
        out.push(label(Rect::new(x, y, lw, h), "Preview", true));
        let mut x = x + lw + 4;
        for i in 0..2u8 {
            let r = Rect::new(x, y, fw, h);
            out.push(Widget {
                rect: r,
                kind: WidgetKind::Field(FieldId::Preview(i)),
            });
            x += fw + 2;
            if i == 0 {
                out.push(label(Rect::new(x, y, CHAR_W, h), "-", true));
                x += CHAR_W + 2;
            }
        }
        x + 6
    }

    /// F3's "Preview range": sets one over the whole scene when there is
    /// none and starts typing its first frame.
    pub(in crate::internals::editor) fn type_preview_range(&mut self) {
        if self.timeline.preview.is_none() {
            self.set_preview_range(Some((0.0, self.scene.settings.duration)));
        }
        if let Some(a) = self.preview_field(FieldId::Preview(0)) {
            self.edit = Some(crate::editor::TextEdit {
                field: FieldId::Preview(0),
                text: crate::editor::fields::format_number(a),
                fresh: true,
            });
            self.set_status("Type the preview's first frame, Enter sets it", false);
        }
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

    /// The remembered zoom and preview range of the opened file (the
    /// preview is held to the scene's frames like a typed one).
    pub(in crate::internals::editor) fn recall_timeline(
        &mut self,
        zoom: Option<(f32, f32)>,
        preview: Option<(f32, f32)>,
    ) {
        self.timeline.restore_zoom(zoom);
        let dur = self.scene.settings.duration;
        self.timeline.preview = None;
        if let Some((a, b)) = preview {
            self.timeline.set_preview(a, b, dur);
        }
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
