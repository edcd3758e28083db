//! The editor's side of the side panel's faces (`side_faces.rs`): the
//! snapshot they see, a press on one of their fields (the side panel
//! holds the gesture, `Drag::Side`, until the release), the mouse and Esc
//! while it holds it, a typed value, and painting the face that shows.

use crate::editor::component::Response;
use crate::editor::field_press::FieldEvent;
use crate::editor::fields::{FieldId, FieldValue};
use crate::editor::gesture::Drag;
use crate::editor::keypanel::KeyPanel;
use crate::editor::node_props::NodeProps;
use crate::editor::props_view::PropsView;
use crate::editor::side_faces::FacesCtx;
use crate::editor::Editor;
use crate::input::Event;
use crate::ui::Painter;

impl Editor {
    /// What the faces see.
    pub(in crate::internals::editor) fn faces_ctx(&self) -> FacesCtx<'_> {
        FacesCtx {
            keys: self.key_panel_ctx(),
            material: self.material_ctx(),
            morph: self.morph_ctx(),
            clip: self.clip_ctx(),
            node: self.node_ctx(),
            scene: self.scene_ctx(),
        }
    }

    /// Hands `ev` to the side panel's faces and applies the answer;
    /// `Drag::Side` while a face holds a press. `Some(redraw)` when it
    /// was theirs.
    pub(in crate::internals::editor) fn face_event(&mut self, ev: FieldEvent) -> Option<bool> {
        let mut side = std::mem::take(&mut self.side);
        let r: Response = side.face_event(&ev, &self.faces_ctx());
        self.side = side;
        match (&self.drag, self.side.face_pressed()) {
            (Drag::None, true) => self.drag = Drag::Side,
            (Drag::Side, false) => self.drag = Drag::None,
            _ => {}
        }
        self.apply_response(r)
    }

    /// The mouse or Esc while the side panel holds the gesture: to the
    /// face holding a field press, else to the panel (its row drag).
    pub(in crate::internals::editor) fn side_mouse(&mut self, ev: &Event) -> Option<bool> {
        if !self.side.face_pressed() {
            return self.side_event(ev);
        }
        let fev = match *ev {
            Event::MouseMove { x, .. } => FieldEvent::Move { x },
            Event::MouseUp { .. } => FieldEvent::Release,
            _ => FieldEvent::Cancel,
        };
        self.face_event(fev)
    }

    /// A value typed into a face's field and Enter.
    pub(in crate::internals::editor) fn face_typed(&mut self, field: FieldId, value: FieldValue) {
        self.face_event(FieldEvent::Typed { field, value });
    }

    /// The text typing into face field `id` starts from (Tab): its value
    /// now.
    pub(in crate::internals::editor) fn face_start_text(&self, id: FieldId) -> Option<String> {
        let ctx = self.faces_ctx();
        let v = match id {
            FieldId::Key(f) => KeyPanel::number(f, ctx.keys.anim, &ctx.keys.keys)?,
            FieldId::Material(f) => f.read(&ctx.material?.value),
            FieldId::Morph(i) => *ctx.morph.base?.start.as_slice().get(i as usize)?,
            FieldId::ClipName => return Some(ctx.clip.name),
            FieldId::Fps | FieldId::Duration => {
                return id.read_settings(&ctx.scene.settings).map(|v| v.display())
            }
            _ if NodeProps::owns(id) => return NodeProps::start_text(id, &ctx.node),
            _ => return None,
        };
        Some(FieldValue::Number(v).display())
    }

    /// Paints the face that shows in the properties' place; false when
    /// the node's rows show.
    pub(in crate::internals::editor) fn draw_face(&self, p: &mut Painter) -> bool {
        let (shown, tall) = self.props_view();
        let view = PropsView { shown, tall };
        self.side
            .draw_face(p, &self.faces_ctx(), &view, &self.side_look())
    }
}
