//! Where the panels go for a given window size. Pure arithmetic, so the
//! editor (hit testing) and the drawing code always agree.

use super::Rect;

/// Height of one panel row (a text line plus nothing: the font's raster is
/// exactly this tall).
pub const ROW: i32 = 16;
pub const TOOLBAR_H: i32 = 22;
/// Height of the timeline's frame ruler.
pub const RULER_H: i32 = 18;
/// Height of a key strip row (issue: record mode / key strip).
pub const KEY_ROW_H: i32 = 14;
/// Characters of a key strip row name that fit the name column.
pub const KEY_NAMES_CHARS: i32 = 12;
/// Height of the timeline's control row (frame field, status).
pub const CONTROLS_H: i32 = 18;
/// The key strip's height until the user drags its top edge: a seventh of
/// the window in whole rows, one to three (small windows keep their room
/// for the viewport and the side panel).
pub fn default_strip_h(window_h: i32) -> i32 {
    (window_h / 7 / KEY_ROW_H).clamp(1, 3) * KEY_ROW_H
}

/// The big regions of the editor window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    pub window: Rect,
    pub toolbar: Rect,
    pub viewport: Rect,
    pub side: Rect,
    /// Whole timeline strip: ruler, key rows, controls.
    pub timeline: Rect,
    pub ruler: Rect,
    /// Key strip rows below the ruler (empty when there are none).
    pub key_rows: Rect,
    pub controls: Rect,
}

impl Layout {
    /// Lays out a `w`×`h` window with `key_rows` key strip rows.
    pub fn new(w: i32, h: i32, key_rows: usize) -> Layout {
        Layout::split(w, h, |rest_h| {
            (key_rows as i32 * KEY_ROW_H).min((rest_h / 3).max(0))
        })
    }

    /// Lays out a `w`×`h` window with a key strip `strip_h` pixels tall,
    /// whatever the selection: rows scroll inside it, so selecting
    /// something never moves the viewport or the side panel. The viewport
    /// keeps at least a quarter of the height.
    pub fn with_strip(w: i32, h: i32, strip_h: i32) -> Layout {
        Layout::split(w, h, |rest_h| {
            let most = (rest_h - RULER_H - CONTROLS_H - rest_h / 4).max(0);
            strip_h.clamp(KEY_ROW_H.min(most), most)
        })
    }

    /// Lays out a `w`×`h` window with the graph editor, `graph_h` pixels
    /// tall, in the key strip's place (`key_rows`); the viewport keeps at
    /// least a quarter of the height.
    pub fn with_graph(w: i32, h: i32, graph_h: i32) -> Layout {
        Layout::split(w, h, |rest_h| {
            let most = (rest_h - RULER_H - CONTROLS_H - rest_h / 4).max(0);
            graph_h.clamp(60.min(most), most)
        })
    }

    /// The layout with `rows_h(height below the toolbar)` pixels of key
    /// rows (or graph).
    fn split(w: i32, h: i32, rows_h: impl Fn(i32) -> i32) -> Layout {
        let window = Rect::new(0, 0, w.max(1), h.max(1));
        let (toolbar, rest) = window.take_top(TOOLBAR_H);
        let rows_h = rows_h(rest.h);
        let tl_h = RULER_H + rows_h + CONTROLS_H;
        let (middle, timeline) = rest.take_top(rest.h - tl_h);
        let side_w = (w * 32 / 100).clamp(140.min(w / 2), 280);
        let (viewport, side) = middle.take_left(middle.w - side_w);
        let (ruler, r) = timeline.take_top(RULER_H);
        let (key_rows, controls) = r.take_top(rows_h);
        Layout {
            window,
            toolbar,
            viewport,
            side,
            timeline,
            ruler,
            key_rows,
            controls,
        }
    }

    /// X pixel of `frame` on the ruler for a timeline of `duration` frames.
    pub fn frame_to_x(&self, frame: f32, duration: f32) -> f32 {
        self.frame_to_x_in(frame, (0.0, duration.max(1.0)))
    }

    /// X pixel of `frame` on the ruler when it shows frames `span.0` to
    /// `span.1` (zoomed or panned).
    pub fn frame_to_x_in(&self, frame: f32, span: (f32, f32)) -> f32 {
        let r = self.ruler_span();
        let w = (span.1 - span.0).max(1e-3);
        r.0 + ((frame - span.0) / w) * (r.1 - r.0)
    }

    /// Frame under ruler pixel `x` when it shows `span` (not clamped).
    pub fn x_to_frame_in(&self, x: f32, span: (f32, f32)) -> f32 {
        let r = self.ruler_span();
        span.0 + (x - r.0) / (r.1 - r.0).max(1.0) * (span.1 - span.0)
    }

    /// Frame under the ruler pixel `x` (clamped to 0..=duration).
    pub fn x_to_frame(&self, x: f32, duration: f32) -> f32 {
        let r = self.ruler_span();
        ((x - r.0) / (r.1 - r.0).max(1.0) * duration.max(1.0)).clamp(0.0, duration.max(0.0))
    }

    /// Width of the key strip's name column at the left of the timeline
    /// (0 without key rows): the ruler starts after it so keys and ruler
    /// ticks line up.
    pub fn key_names_w(&self) -> i32 {
        if self.key_rows.h > 0 {
            (KEY_NAMES_CHARS * super::text::CHAR_W + 12).min(self.ruler.w / 4)
        } else {
            0
        }
    }

    /// Left and right x of the ruler's usable span (a margin for labels).
    /// Left and right x of the frames on the ruler.
    pub fn ruler_span(&self) -> (f32, f32) {
        let x0 = (self.ruler.x + 8 + self.key_names_w()) as f32;
        let x1 = (self.ruler.right() - 8) as f32;
        (x0, x1.max(x0 + 1.0))
    }
}

/// The side panel's sections.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SidePanel {
    pub scene: Rect,
    pub objects: Rect,
    pub lights: Rect,
    pub props: Rect,
}

impl SidePanel {
    /// Body rows the properties section keeps at most: the key panel with
    /// four selected keys (its tallest state) fits whole.
    pub const PROP_ROWS: i32 = 11;
    /// Rows each list keeps below its header while the panel has room.
    pub const LIST_ROWS: i32 = 2;

    /// Splits `side` by its height alone, so no section ever moves or
    /// resizes when the selection, its keys or a list's length change
    /// (issue 17: a click must land where the user aimed). Each list keeps
    /// its header and `LIST_ROWS` rows, the properties get the rest up to
    /// half the rows and at most `PROP_ROWS` body rows, and what the
    /// properties leave goes to the lists, objects 3 : lights 2. Every
    /// section scrolls what overflows. A short panel keeps a header and
    /// one row for each list and the properties.
    pub fn new(side: Rect) -> SidePanel {
        // A panel too short for the scene section's title row, a header
        // and a row per list and the properties (the graph editor open in
        // a small window) puts the scene's fields on one row.
        let lists_props = 3 * (ROW + ROW) + 2;
        let scene_h = if side.h >= 2 * ROW + 2 + lists_props {
            2 * ROW + 2
        } else {
            ROW + 2
        };
        let (scene, rest) = side.take_top(scene_h);
        let rows = rest.h / ROW;
        let lists_min = 2 * (1 + Self::LIST_ROWS);
        let prop_rows = (rows - lists_min - 1)
            .min(rows / 2)
            .clamp(1, Self::PROP_ROWS);
        // Header, rows, and the body's two pixels of inset.
        let props_h = ((prop_rows + 1) * ROW + 2).min(rest.h);
        let (lists, props) = rest.take_top(rest.h - props_h);
        let free_rows = (lists.h / ROW - 2).max(2);
        let obj_rows = ((free_rows * 3 + 2) / 5).clamp(1, (free_rows - 1).max(1));
        let obj_h = ((obj_rows + 1) * ROW).min(lists.h);
        let (objects, lights) = lists.take_top(obj_h);
        SidePanel {
            scene,
            objects,
            lights,
            props,
        }
    }

    /// Body rows of the properties section that show.
    pub fn prop_rows_shown(&self) -> i32 {
        ((self.props.h - ROW) / ROW).max(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_tile_the_window() {
        for (w, h) in [(320, 240), (480, 320), (1280, 720)] {
            let l = Layout::new(w, h, 0);
            assert_eq!(l.toolbar.h + l.viewport.h + l.timeline.h, h);
            assert_eq!(l.viewport.w + l.side.w, w);
            assert_eq!(l.viewport.h, l.side.h);
            assert!(
                l.viewport.w > l.side.w,
                "{w}x{h}: viewport is the main area"
            );
            let s = SidePanel::new(l.side);
            assert!(s.objects.h >= 2 * ROW && s.lights.h >= 2 * ROW);
            assert_eq!(s.scene.h + s.objects.h + s.lights.h + s.props.h, l.side.h);
        }
    }

    #[test]
    fn lists_keep_two_rows_and_properties_their_share_from_the_height_alone() {
        // The tests' window: both lists keep a header and two rows.
        let s = SidePanel::new(Layout::with_strip(480, 320, default_strip_h(320)).side);
        assert!(s.objects.h >= 3 * ROW, "objects {:?}", s.objects);
        assert!(s.lights.h >= 3 * ROW, "lights {:?}", s.lights);
        assert_eq!(s.prop_rows_shown(), 4);
        // A tall window: the properties keep their most, the lists share
        // the rest 3 : 2.
        let s = SidePanel::new(Layout::with_strip(1024, 640, default_strip_h(640)).side);
        assert_eq!(s.prop_rows_shown(), SidePanel::PROP_ROWS);
        assert!(s.objects.h > s.lights.h && s.lights.h >= 6 * ROW);
        // The graph editor open in the tests' window: each list and the
        // properties keep a header and a row (the scene's fields share one).
        let short = Layout::with_graph(480, 320, 140).side;
        let s = SidePanel::new(short);
        assert!(
            short.h < 2 * ROW + 2 + 6 * ROW + 2,
            "a short panel: {short:?}"
        );
        assert_eq!(s.scene.h, ROW + 2);
        assert!(s.objects.h >= 2 * ROW && s.lights.h >= 2 * ROW, "{s:?}");
        assert!(s.prop_rows_shown() >= 1);
        // Sections follow each other with no gap, whatever the height.
        for h in (0..600).step_by(7) {
            let s = SidePanel::new(Rect::new(300, 22, 160, h));
            assert_eq!(s.objects.y, s.scene.bottom());
            assert_eq!(s.lights.y, s.objects.bottom());
            assert_eq!(s.props.y, s.lights.bottom());
            assert_eq!(s.props.bottom(), 22 + h);
        }
    }

    #[test]
    fn ruler_maps_frames_both_ways() {
        let l = Layout::new(480, 320, 0);
        let x = l.frame_to_x(30.0, 96.0);
        assert!((l.x_to_frame(x, 96.0) - 30.0).abs() < 1e-3);
        assert_eq!(l.x_to_frame(-100.0, 96.0), 0.0);
        assert_eq!(l.x_to_frame(10_000.0, 96.0), 96.0);
    }
}
