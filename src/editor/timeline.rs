//! The timeline's own state: which frames the ruler and key strip show
//! (wheel zoom, middle-drag pan) and the preview range playback loops
//! over. Plain numbers only; the editor routes events here and asks for
//! the span it draws with.
//!
//! Without zoom the strip shows frame 0 to the scene's last frame, or to
//! the last key when keys lie beyond it (a shortened scene keeps its late
//! keys visible, greyed, instead of hiding them).

/// Fewest frames the strip can be zoomed in to.
pub const MIN_SPAN: f32 = 4.0;

/// The strip's zoom/pan and the preview range.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Timeline {
    /// Frames at the strip's left and right ends once zoomed or panned
    /// (`None`: the whole scene, see [`full_span`]).
    view: Option<(f32, f32)>,
    /// Preview range: playback loops over these frames (inclusive).
    pub preview: Option<(f32, f32)>,
}

/// The span shown without zoom: 0 to the last frame, or to the last key
/// when one lies beyond the scene's end.
pub fn full_span(duration: f32, last_key: Option<f32>) -> (f32, f32) {
    let end = duration.max(1.0).max(last_key.unwrap_or(0.0));
    (0.0, end)
}

impl Timeline {
    /// Frames at the strip's ends.
    pub fn span(&self, duration: f32, last_key: Option<f32>) -> (f32, f32) {
        self.view.unwrap_or_else(|| full_span(duration, last_key))
    }

    /// Whether the user zoomed or panned.
    pub fn is_zoomed(&self) -> bool {
        self.view.is_some()
    }

    /// The zoomed or panned span (`None`: the whole scene), as the
    /// per-file view memory keeps it.
    pub fn zoomed_span(&self) -> Option<(f32, f32)> {
        self.view
    }

    /// A remembered zoom back in place: kept only when finite and at
    /// least [`MIN_SPAN`] wide (the memory file is text anyone can edit).
    pub fn restore_zoom(&mut self, span: Option<(f32, f32)>) {
        self.view = span.filter(|&(a, b)| a.is_finite() && b.is_finite() && b - a >= MIN_SPAN);
    }

    /// Zooms `notches` wheel steps (positive: in) keeping frame `about`
    /// under the mouse. Never narrower than [`MIN_SPAN`] nor wider than
    /// ten times the full span; zooming back out to the full span or
    /// wider returns to the unzoomed view.
    pub fn zoom(&mut self, span: (f32, f32), full: (f32, f32), about: f32, notches: f32) {
        let w = span.1 - span.0;
        let full_w = full.1 - full.0;
        let nw = (w * 0.85f32.powf(notches)).clamp(MIN_SPAN, full_w.max(MIN_SPAN) * 10.0);
        if nw >= full_w && notches < 0.0 {
            self.view = None;
            return;
        }
        let t = if w > 0.0 { (about - span.0) / w } else { 0.5 };
        let a = about - t * nw;
        self.view = Some((a, a + nw));
    }

    /// Pans by `frames` (positive: later frames come into view).
    pub fn pan(&mut self, span: (f32, f32), frames: f32) {
        if frames.is_finite() {
            self.view = Some((span.0 + frames, span.1 + frames));
        }
    }

    /// Back to the whole scene.
    pub fn reset_view(&mut self) {
        self.view = None;
    }

    /// Sets the preview range from two frames in either order, held to
    /// `0..=duration` and rounded; `None` when it would be a single frame.
    pub fn set_preview(&mut self, a: f32, b: f32, duration: f32) -> Option<(f32, f32)> {
        let c = |f: f32| f.round().clamp(0.0, duration.max(0.0));
        let (lo, hi) = (c(a.min(b)), c(a.max(b)));
        self.preview = (hi > lo).then_some((lo, hi));
        self.preview
    }
}

/// The frame playback shows after `elapsed` frames of real time from
/// `start`: looping over the preview range `lo..=hi` (starting at `lo`
/// when `start` lies outside it), else over the whole scene `0..=duration`.
pub fn play_frame(start: f32, elapsed: f64, duration: f32, preview: Option<(f32, f32)>) -> f32 {
    let (lo, hi) = preview.unwrap_or((0.0, duration.max(1.0)));
    let from = if start >= lo && start <= hi {
        start
    } else {
        lo
    };
    let len = (hi - lo) as f64 + 1.0;
    let f = (from - lo) as f64 + elapsed;
    lo + (f + 1e-6).rem_euclid(len).floor() as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_full_span_reaches_keys_beyond_the_end() {
        assert_eq!(full_span(96.0, Some(40.0)), (0.0, 96.0));
        assert_eq!(full_span(48.0, Some(72.0)), (0.0, 72.0));
        assert_eq!(full_span(0.0, None), (0.0, 1.0));
    }

    #[test]
    fn zoom_keeps_the_frame_under_the_mouse_and_pans() {
        let mut t = Timeline::default();
        let full = (0.0, 100.0);
        t.zoom(full, full, 25.0, 2.0);
        let s = t.span(100.0, None);
        // 100 × 0.85² = 72.25 frames wide; frame 25 stays a quarter in.
        assert!((s.1 - s.0 - 72.25).abs() < 1e-3, "{s:?}");
        assert!(((25.0 - s.0) / (s.1 - s.0) - 0.25).abs() < 1e-5);
        t.pan(s, 10.0);
        let p = t.span(100.0, None);
        assert!((p.0 - s.0 - 10.0).abs() < 1e-4 && (p.1 - s.1 - 10.0).abs() < 1e-4);
        // Far in: never narrower than MIN_SPAN.
        t.zoom(p, full, 50.0, 100.0);
        let z = t.span(100.0, None);
        assert!((z.1 - z.0 - MIN_SPAN).abs() < 1e-4);
        // Out past the full span: back to the whole scene.
        t.zoom(z, full, 50.0, -100.0);
        assert!(!t.is_zoomed());
        assert_eq!(t.span(100.0, None), full);
    }

    #[test]
    fn playback_loops_over_the_preview_range() {
        // Whole scene 0..=96: 97 frames.
        assert_eq!(play_frame(90.0, 10.0, 96.0, None), 3.0);
        // Preview 10..=20 (11 frames), started inside at 15.
        assert_eq!(play_frame(15.0, 3.0, 96.0, Some((10.0, 20.0))), 18.0);
        assert_eq!(play_frame(15.0, 6.0, 96.0, Some((10.0, 20.0))), 10.0);
        // Started outside (frame 50): from the range's start.
        assert_eq!(play_frame(50.0, 0.0, 96.0, Some((10.0, 20.0))), 10.0);
        assert_eq!(play_frame(50.0, 12.0, 96.0, Some((10.0, 20.0))), 11.0);
        let mut t = Timeline::default();
        assert_eq!(t.set_preview(40.4, 9.6, 30.0), Some((10.0, 30.0)));
        assert_eq!(t.set_preview(5.0, 5.2, 30.0), None);
    }
}
