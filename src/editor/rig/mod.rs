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
pub mod ik;
pub mod morph;
mod view;

/// The rig tools' own state, one field of the `Editor`.
#[derive(Clone, Debug, Default)]
pub struct RigState {
    /// A morph slider change shown but not recorded (`morph.rs`).
    pub morph_pending: Option<morph::MorphPending>,
    /// The end joint whose IK handle is on (I).
    pub ik: Option<crate::scene::NodeId>,
    /// An IK drag in progress.
    pub ik_drag: Option<ik::IkDrag>,
    /// An IK pose shown but not recorded.
    pub ik_pending: Option<ik::IkPending>,
}

impl crate::editor::Editor {
    /// The scene as shown while a morph or IK change is pending (their
    /// tracks set aside, the shown values in place); `None` when nothing
    /// pends (`route/record.rs::evaluate_shown`).
    pub(in crate::internals::editor) fn rig_shown_scene(&self) -> Option<crate::scene::Scene> {
        let mut s = match self.morph_shown_scene() {
            Some(s) => s,
            None => {
                self.ik_pending()?;
                self.scene.clone()
            }
        };
        self.ik_shown(&mut s);
        Some(s)
    }
}
