//! The editor's one gesture in progress: whatever a mouse press started
//! (the viewport's, the key strip's, the graph editor's, the side
//! panel's, a controls bar field, seek, the ruler's and the strip's own)
//! is ONE value of [`Drag`], so a mouse move or release goes to exactly
//! the part that holds the gesture instead of every part being asked in
//! turn. A component that keeps its own drag state (viewport, key strip,
//! graph, side panel with its faces — every field of the side panel is
//! a face's) is named by a marker here. Routing lives in `route/input.rs`.

use super::field_press::FieldPress;
use super::fields::FieldId;

/// State kept between mouse down and up.
#[derive(Clone, Debug, Default)]
pub(super) enum Drag {
    #[default]
    None,
    /// The viewport took the press (orbit, pan, pick, its menu, a
    /// handle, the IK target): it keeps its own gesture
    /// (`viewport_ui.rs`).
    Viewport,
    /// The key strip took the press (keys moved or a selection box); it
    /// keeps its own drag state.
    Keys,
    /// The graph editor took the press; it keeps its own drag state.
    Graph,
    /// The side panel took a press on an object row (a drag re-parents
    /// it) or on a field of one of its faces (key panel, material rows,
    /// morph sliders, the clip name, the node's rows, the scene section);
    /// it keeps its own drag state (`side_ui.rs`, `side_faces.rs`).
    Side,
    /// Pressed on the controls bar's Frame field (a drag scrubs) or a
    /// preview range field (typed only); a click types
    /// (`route/time_field.rs`).
    TimeField(FieldPress<FieldId, f32>),
    /// Dragging the current-frame cursor on the ruler.
    Seek,
    /// Middle button over the ruler or key strip: pans the frames shown.
    StripPan { last_x: f32 },
    /// Shift+drag on the ruler: the preview range from the press's frame.
    Preview { from: f32 },
    /// Dragging the timeline's top edge: the key strip's height.
    StripResize { y0: f32, h0: i32 },
}

/// Pixels the mouse may move before a press counts as a drag (kept with
/// the field gesture, the lower file).
pub(super) use super::field_press::DRAG_SLOP;

/// Files the writers can produce.
pub(super) fn is_writable_type(p: &std::path::Path) -> bool {
    let s = p.to_string_lossy().to_ascii_lowercase();
    [".wrl", ".iv", ".wrl.gz", ".wrz"]
        .iter()
        .any(|e| s.ends_with(e))
}
