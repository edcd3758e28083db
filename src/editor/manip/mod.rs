//! Handles on the selected object or light, one file per kind: translate
//! arrows and plane squares (`translate`), rotate rings (`rotate`), scale
//! boxes (`scale`), and dragging the object's body in the view plane
//! (`body`). With the rotate tool a drag inside the rings (not on a ring
//! or the body) turns freely (trackball). This file holds the tool choice,
//! hover and drag state; `handles.rs` is the component that hit-tests,
//! drags and draws them; `aim.rs` names handles for scripts.
//!
//! Tools: W move, E rotate, T scale (R is record mode), or the toolbar's
//! Mov / Rot / Scl buttons. Ctrl snaps: grid step, 15°, 0.1. Esc cancels.
//!
//! During a drag the node is previewed as a [`super::record::Pending`]
//! change (shown over its tracks); the release records one command, with a
//! key in record mode on the changed property.

pub mod aim;
pub(super) mod body;
pub mod geom;
pub mod handles;
pub mod rotate;
pub mod scale;
pub mod translate;

pub use geom::{axis, closest_on_line, grid_step, pixel_ray, ray_plane, snap};

use crate::anim::Property;
use crate::scene::{Node, NodeId};
use glam::{Mat4, Vec3};

/// Arrow length on screen, in pixels.
pub const ARROW_PX: f32 = 70.0;
/// How close (pixels) the mouse must be to a handle to grab it.
pub(super) const GRAB_PX: f32 = 6.0;

pub(super) const AXIS_COLORS: [u32; 3] = [0xe04848, 0x5cc040, 0x4c8fe8];
pub(super) const HOT: u32 = 0xffe040;

/// Which handles the selection shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tool {
    #[default]
    Translate,
    Rotate,
    Scale,
}

impl Tool {
    /// Every tool, in the order `HandlesCtx::targets` holds them.
    pub const ALL: [Tool; 3] = [Tool::Translate, Tool::Rotate, Tool::Scale];

    /// Name shown in the viewport label.
    pub fn name(self) -> &'static str {
        match self {
            Tool::Translate => "Move",
            Tool::Rotate => "Rotate",
            Tool::Scale => "Scale",
        }
    }

    /// The key that picks the tool.
    pub fn key(self) -> char {
        match self {
            Tool::Translate => 'w',
            Tool::Rotate => 'e',
            Tool::Scale => 't',
        }
    }
}

/// One grabbable part of the handles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Handle {
    /// Arrow along world axis 0/1/2.
    Axis(u8),
    /// Square in the plane whose normal is world axis 0/1/2.
    Plane(u8),
    /// Ring about world axis 0/1/2.
    Ring(u8),
    /// The outer ring about the view direction.
    ViewRing,
    /// Box on the node's own scale axis 0/1/2.
    ScaleAxis(u8),
    /// The centre box of the scale handles.
    Uniform,
    /// Inside the rotate rings (not on a ring or the body): free rotation
    /// on the sphere the rings outline.
    Trackball,
    /// The selected object's own pixels (moves in the view plane).
    Body,
}

impl Handle {
    /// The undo label's verb.
    pub(super) fn verb(self) -> &'static str {
        match self {
            Handle::Ring(_) | Handle::ViewRing | Handle::Trackball => "Rotate",
            Handle::ScaleAxis(_) | Handle::Uniform => "Scale",
            _ => "Move",
        }
    }
}

/// The handles' state: tool, hover, and the drag they run (the viewport
/// component's gesture is then `Handle`, `viewport_ui.rs`), or a press on
/// the selection armed to become one (`handles.rs`).
#[derive(Clone, Debug, Default)]
pub struct Manip {
    pub tool: Tool,
    pub hover: Option<Handle>,
    pub(super) drag: Option<HandleDrag>,
    /// Where the press was and the handle it becomes past the slop.
    pub(super) armed: Option<((f32, f32), Handle)>,
}

/// What the handles of a tool act on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target {
    pub(super) id: NodeId,
    pub(super) property: Property,
    /// The fixed point of the change, in world space.
    pub(super) pivot: Vec3,
    /// World → the space the changed value lives in (parent space for an
    /// object's transform, the light's node space for its fields).
    pub(super) to_local: Mat4,
    /// World directions of the node's scale axes (scale handles).
    pub(super) frame: [Vec3; 3],
}

#[derive(Clone, Debug)]
pub(super) struct HandleDrag {
    pub(super) handle: Handle,
    pub(super) t: Target,
    /// The node as stored at press (restored before recording).
    pub(super) stored: Box<Node>,
    /// The node as shown at press (what the drag changes).
    pub(super) shown: Box<Node>,
    /// World point grabbed at press (translate, rotate, body).
    pub(super) grab: Vec3,
    /// Window pixel of the press (uniform scale).
    pub(super) press: (f32, f32),
    /// Scale axis: distance along the axis at press.
    pub(super) along: f32,
    /// Rotate: axis of the ring and the angle turned so far (kept
    /// continuous across half turns).
    pub(super) ring_axis: Vec3,
    pub(super) angle: f32,
    /// Rotate, ring seen edge-on: screen direction and pixel radius the
    /// mouse motion is measured along (see [`rotate::edge_on_drag`]).
    pub(super) edge_on: Option<((f32, f32), f32)>,
}
