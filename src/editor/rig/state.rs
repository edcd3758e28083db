//! The rig tools' state (pure data, no `Editor`): the editor holds a
//! `RigState`, the viewport component (`viewport_ui.rs`) an `IkDrag`
//! and a field drag (`gesture::Base`) a `MorphBase` while a slider is
//! dragged.
//! It lives apart from the tools' `Editor` methods (`morph.rs`, `ik.rs`,
//! `mod.rs`), which would otherwise close import circles through the
//! editor (editor → rig → editor).

use crate::anim::ik::Chain;
use crate::anim::Weights;
use crate::scene::{Node, NodeId};
use glam::{Quat, Vec3};

/// The rig tools' own state, one field of the `Editor`.
#[derive(Clone, Debug, Default)]
pub struct RigState {
    /// A morph slider change shown but not recorded (`morph.rs`).
    pub morph_pending: Option<MorphPending>,
    /// The end joint whose IK handle is on (I).
    pub ik: Option<crate::scene::NodeId>,
    /// An IK pose shown but not recorded.
    pub ik_pending: Option<IkPending>,
}

/// The weights a slider change shows before it is recorded (or while it
/// waits for K on an animated track).
#[derive(Clone, Debug, PartialEq)]
pub struct MorphPending {
    /// The node the weights track drives (the selection).
    pub target: NodeId,
    /// The morphed shape shown (the target or its first morphed child).
    pub shape: NodeId,
    pub frame: f32,
    pub weights: Weights,
    /// History revision when it was made: undo or any edit drops it.
    pub revision: u64,
}

/// What a slider drag started from.
#[derive(Clone, Debug, PartialEq)]
pub struct MorphBase {
    pub target: NodeId,
    pub shape: NodeId,
    pub start: Weights,
}

/// A running IK drag: the chain as it was at the press.
#[derive(Clone, Debug)]
pub struct IkDrag {
    pub(super) root: NodeId,
    pub(super) mid: NodeId,
    pub(super) chain: Chain,
    /// Bend direction at the press (the chain keeps bending that way).
    pub(super) pole: Vec3,
    /// The drag plane: through the end joint, facing the eye.
    pub(super) plane: (Vec3, Vec3),
    /// Root and middle joint as shown at the press.
    pub(super) posed: [Node; 2],
    /// World rotation of the root's parent, and of the root, at the press.
    pub(super) parent_rot: Quat,
    pub(super) root_rot: Quat,
    /// Where the mouse put the target last (drawn).
    pub(super) target: Vec3,
}

/// Two joints shown with new rotations over their tracks (a drag in
/// progress, or its result waiting for K on animated joints).
#[derive(Clone, Debug, PartialEq)]
pub struct IkPending {
    pub joints: [(NodeId, Node); 2],
    pub frame: f32,
    /// History revision when made: undo or any edit drops it.
    pub revision: u64,
}
