//! The side panel's faces, each a component of its own — the node rows,
//! the key panel, the material rows, the morph sliders (inside the node
//! rows), the scene section and its clip name field — as one part of
//! [`Side`]: a field event goes to the face whose field
//! it names (a press, a typed value) or to the face holding the press
//! (the mouse moved or released, Esc), and the face that shows in the
//! properties' place paints itself. The editor hands field events to the
//! side panel only; [`FacesCtx`] is the snapshot the faces see.

use super::component::Response;
use super::field_press::FieldEvent;
use super::fields::{FieldId, FieldValue};
use super::keypanel::{KeyEvent, KeyPanelCtx};
use super::material::rows_ui::MatCtx;
use super::node_props::{NodeCtx, NodeProps};
use super::props_view::{Look, PropsView};
use super::rig::clip_ui::ClipCtx;
use super::rig::morph_ui::MorphCtx;
use super::scene_section::{SceneCtx, SceneSection};
use super::side_ui::Side;
use crate::ui::Painter;

/// What the faces see of the editor.
pub struct FacesCtx<'a> {
    pub keys: KeyPanelCtx<'a>,
    /// `None` unless the material panel is open on a shape.
    pub material: Option<MatCtx<'a>>,
    pub morph: MorphCtx,
    pub clip: ClipCtx,
    /// The node face (`node_props.rs`) and the scene section
    /// (`scene_section.rs`).
    pub node: NodeCtx,
    pub scene: SceneCtx,
}

/// Whether field `id` belongs to one of the faces here.
pub fn is_face_field(id: FieldId) -> bool {
    matches!(
        id,
        FieldId::Key(_) | FieldId::Material(_) | FieldId::Morph(_) | FieldId::ClipName
    ) || NodeProps::owns(id)
        || SceneSection::owns(id)
}

impl Side {
    /// Whether a face holds a press on one of its fields.
    pub fn face_pressed(&self) -> bool {
        self.keys.pressed()
            || self.material.pressed()
            || self.morph.pressed()
            || self.clip.pressed()
            || self.node.pressed()
            || self.scene.pressed()
    }

    /// Hands `ev` to the face it is for and returns its answer.
    pub fn face_event(&mut self, ev: &FieldEvent, ctx: &FacesCtx) -> Response {
        let field = match ev {
            FieldEvent::Press { field, .. } | FieldEvent::Typed { field, .. } => Some(*field),
            _ => None,
        };
        let to_keys = field.map_or(self.keys.pressed(), |f| matches!(f, FieldId::Key(_)));
        if to_keys {
            let kev = match *ev {
                FieldEvent::Press {
                    field: FieldId::Key(field),
                    x,
                } => KeyEvent::Press { field, x },
                FieldEvent::Typed {
                    field: FieldId::Key(field),
                    value: FieldValue::Number(value),
                } => KeyEvent::Typed { field, value },
                FieldEvent::Move { x } => KeyEvent::Move { x },
                FieldEvent::Release => KeyEvent::Release,
                FieldEvent::Cancel => KeyEvent::Cancel,
                _ => return Response::ignored(),
            };
            return self.keys.handle(kev, &ctx.keys);
        }
        let to = |pressed: bool, of: fn(FieldId) -> bool| field.map_or(pressed, of);
        if to(self.material.pressed(), |f| {
            matches!(f, FieldId::Material(_))
        }) {
            return self.material.handle(ev, ctx.material.as_ref());
        }
        if to(self.morph.pressed(), |f| matches!(f, FieldId::Morph(_))) {
            return self.morph.handle(ev, &ctx.morph);
        }
        if to(self.clip.pressed(), |f| f == FieldId::ClipName) {
            return self.clip.handle(ev, &ctx.clip);
        }
        if to(self.node.pressed(), NodeProps::owns) {
            return self.node.handle(ev.clone(), &ctx.node);
        }
        if to(self.scene.pressed(), SceneSection::owns) {
            return self.scene.handle(ev.clone(), &ctx.scene);
        }
        Response::ignored()
    }

    /// Paints the face that shows in the properties' place (the material
    /// rows, else the key panel), where `view` shows its rows; `false`
    /// when the node's rows show.
    pub fn draw_face(
        &self,
        p: &mut Painter,
        ctx: &FacesCtx,
        view: &PropsView,
        look: &Look,
    ) -> bool {
        if let Some(m) = &ctx.material {
            self.material.draw(p, m, view, look);
            return true;
        }
        if self.keys.shown(&ctx.keys) {
            self.keys.draw(p, &ctx.keys, view, look);
            return true;
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Animation, Weights};
    use crate::editor::component::Intent;
    use crate::editor::rig::state::MorphBase;
    use crate::scene::NodeId;

    fn ctx(anim: &Animation) -> FacesCtx<'_> {
        let base = MorphBase {
            target: NodeId(1),
            shape: NodeId(2),
            start: Weights::from_slice(&[0.25, 0.5]).unwrap(),
        };
        FacesCtx {
            keys: KeyPanelCtx {
                anim,
                keys: Vec::new(),
            },
            material: None,
            morph: MorphCtx {
                names: vec!["smile".into(), "frown".into()],
                base: Some(base),
            },
            clip: ClipCtx {
                name: "Walk".into(),
                named: true,
            },
            node: NodeCtx::default(),
            scene: SceneCtx::default(),
        }
    }

    #[test]
    fn a_slider_press_is_held_by_the_morph_face_until_the_release() {
        let anim = Animation::default();
        let c = ctx(&anim);
        let mut side = Side::default();
        let press = FieldEvent::Press {
            field: FieldId::Morph(1),
            x: 100.0,
        };
        assert!(side.face_event(&press, &c).consumed);
        assert!(side.face_pressed() && side.morph.pressed());
        // Within the slop: still a click, nothing shown.
        let r = side.face_event(&FieldEvent::Move { x: 102.0 }, &c);
        assert!(r.consumed && r.intents.is_empty());
        // 40 px right: weight 1 shown at 0.5 + 40 × 0.005.
        let r = side.face_event(&FieldEvent::Move { x: 140.0 }, &c);
        let shown = r.intents.iter().find_map(|i| match i {
            Intent::ShowWeight { index, value, .. } => Some((*index, *value)),
            _ => None,
        });
        assert!(matches!(shown, Some((1, v)) if (v - 0.7).abs() < 1e-6));
        // The release asks for that weight once, by the record rules.
        let r = side.face_event(&FieldEvent::Release, &c);
        assert!(matches!(
            r.intents.as_slice(),
            [Intent::SetWeight { index: 1, value, .. }] if (*value - 0.7).abs() < 1e-6
        ));
        assert!(!side.face_pressed());
        // Nothing pressed: the mouse is someone else's.
        assert!(!side.face_event(&FieldEvent::Release, &c).consumed);
    }

    #[test]
    fn a_click_types_esc_drops_a_drag_and_the_clip_name_is_never_dragged() {
        let anim = Animation::default();
        let c = ctx(&anim);
        let mut side = Side::default();
        let press = |field| FieldEvent::Press { field, x: 10.0 };
        side.face_event(&press(FieldId::Morph(0)), &c);
        let r = side.face_event(&FieldEvent::Release, &c);
        assert_eq!(
            r.intents,
            vec![Intent::Type {
                field: FieldId::Morph(0),
                text: "0.25".into()
            }]
        );
        side.face_event(&press(FieldId::Morph(0)), &c);
        side.face_event(&FieldEvent::Move { x: 60.0 }, &c);
        let r = side.face_event(&FieldEvent::Cancel, &c);
        assert_eq!(r.intents, vec![Intent::DropWeights]);
        // The clip name: a drag does nothing, a click types its name,
        // Enter renames.
        side.face_event(&press(FieldId::ClipName), &c);
        side.face_event(&FieldEvent::Move { x: 80.0 }, &c);
        assert!(side.face_event(&FieldEvent::Release, &c).intents.is_empty());
        side.face_event(&press(FieldId::ClipName), &c);
        let r = side.face_event(&FieldEvent::Release, &c);
        assert_eq!(
            r.intents,
            vec![Intent::Type {
                field: FieldId::ClipName,
                text: "Walk".into()
            }]
        );
        let typed = FieldEvent::Typed {
            field: FieldId::ClipName,
            value: FieldValue::Text("Run".into()),
        };
        let r = side.face_event(&typed, &c);
        assert_eq!(r.intents, vec![Intent::RenameClip("Run".into())]);
        // No material panel: its fields are not taken.
        let r = side.face_event(
            &press(FieldId::Material(
                crate::editor::material::MatField::Shininess,
            )),
            &c,
        );
        assert!(!r.consumed && !side.face_pressed());
    }
}
