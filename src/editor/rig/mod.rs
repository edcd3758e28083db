//! Editing deforming meshes and clips (issue 13 items 3 and 7): the
//! skeleton's bones in the viewport and picking joints by them (`bones`,
//! `view`), two-bone IK on a joint chain (`ik`), one slider per morph
//! target weight (`morph`), and the clip list (`clips`).
//!
//! Joints are ordinary nodes, so the object list already shows them as a
//! tree under their skeleton and the rotate handle and K already key
//! them; this folder adds what only skins, morphs and clips need. The
//! pure parts (`bones`) never name the `Editor`; the others are its
//! methods, like `route/`.

pub mod bones;
pub mod clips;
pub mod morph;
mod view;

/// The rig tools' own state, one field of the `Editor`.
#[derive(Clone, Debug, Default)]
pub struct RigState {
    /// A morph slider change shown but not recorded (`morph.rs`).
    pub morph_pending: Option<morph::MorphPending>,
}
