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
pub mod clip_action;
pub mod clip_ui;
pub mod clips;
pub mod ik;
pub mod ik_drag;
pub mod morph;
pub mod morph_ui;
pub mod state;
pub mod targets;
mod view;

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
