//! The editor's one gesture in progress: whatever a mouse press started
//! (camera, field drag, seek, pick, a handle, keys in the strip, the IK
//! target, the graph editor) is ONE value of [`Drag`], so a mouse move or
//! release goes to exactly the part that holds the gesture instead of
//! every part being asked in turn. Also what a field drag started from.
//! Routing lives in `route/input.rs`.

use super::fields::FieldId;
use super::rig::state::IkDrag;
use crate::scene::{Node, NodeId, Settings};

/// State kept between mouse down and up.
#[derive(Clone, Debug, Default)]
pub(super) enum Drag {
    #[default]
    None,
    /// A handle of the current tool took the press; the handles
    /// (`manip/handles.rs`) keep their own drag state.
    Handle,
    /// The key strip took the press (keys moved or a selection box); it
    /// keeps its own drag state.
    Keys,
    /// The IK target (`rig/ik.rs`).
    Ik(Box<IkDrag>),
    /// The graph editor took the press; it keeps its own drag state.
    Graph,
    /// The key panel took a press on one of its fields; it keeps its own
    /// drag state (`keypanel.rs`).
    KeyPanel,
    /// The side panel took a press on an object row (a drag re-parents
    /// it); it keeps its own drag state (`side_ui.rs`).
    Side,
    Orbit {
        last: (f32, f32),
    },
    Pan {
        last: (f32, f32),
    },
    /// Pressed on a field: a click starts typing, a drag changes the value.
    Field {
        id: FieldId,
        start_x: f32,
        moved: bool,
        base: Base,
    },
    /// Dragging the current-frame cursor on the ruler.
    Seek,
    /// Pressed in the viewport in select mode; selects on release. On the
    /// selection (`armed`: its body, or inside the rotate rings; the
    /// handles hold which) a move past the slop turns it into that
    /// handle's drag instead.
    Pick {
        at: (f32, f32),
        armed: bool,
    },
    /// Right button in the viewport: a drag pans, a click opens the
    /// viewport's context menu.
    Context {
        at: (f32, f32),
        last: (f32, f32),
        moved: bool,
    },
    /// Middle button over the ruler or key strip: pans the frames shown.
    StripPan {
        last_x: f32,
    },
    /// Shift+drag on the ruler: the preview range from the press's frame.
    Preview {
        from: f32,
    },
    /// Dragging the timeline's top edge: the key strip's height.
    StripResize {
        y0: f32,
        h0: i32,
    },
}

impl Drag {
    /// Ends the gesture and returns what `part` finds in it, when it is
    /// that part's; any other gesture stays.
    fn take_if<T>(&mut self, part: impl FnOnce(Drag) -> Result<T, Drag>) -> Option<T> {
        match part(std::mem::take(self)) {
            Ok(t) => Some(t),
            Err(other) => {
                *self = other;
                None
            }
        }
    }

    /// The IK drag, if it is the gesture (which then ends).
    pub(super) fn take_ik(&mut self) -> Option<Box<IkDrag>> {
        self.take_if(|d| if let Drag::Ik(i) = d { Ok(i) } else { Err(d) })
    }
}

/// What a field drag started from (to compute values and the command).
#[derive(Clone, Debug)]
pub(super) enum Base {
    Node(NodeId, Box<Node>),
    Settings(Settings),
    Frame(f32),
    /// A morph slider (`rig/morph.rs`).
    Morph(Box<super::rig::state::MorphBase>),
    /// The clip name field (`rig/clips.rs`): typed, never dragged.
    Clip,
    /// A material field (`material/`).
    Material(Box<super::material::MatBase>),
    /// A preview range field (`route/timeline.rs`): typed, never dragged.
    Preview,
}

/// Pixels the mouse may move before a press counts as a drag.
pub(super) const DRAG_SLOP: f32 = 3.0;

/// Files the writers can produce.
pub(super) fn is_writable_type(p: &std::path::Path) -> bool {
    let s = p.to_string_lossy().to_ascii_lowercase();
    [".wrl", ".iv", ".wrl.gz", ".wrz"]
        .iter()
        .any(|e| s.ends_with(e))
}
