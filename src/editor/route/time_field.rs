//! The controls bar's Frame field and preview range fields: a press is
//! the editor's small gesture `Drag::TimeField` (the shared field gesture
//! of `field_press.rs`). Dragging the Frame field scrubs from the frame
//! at the press; a click types into either (the preview range's are
//! typed only, `route/timeline.rs` sets them); Esc puts the frame back.

use crate::editor::field_press::FieldPress;
use crate::editor::fields::{FieldId, FieldValue};
use crate::editor::gesture::Drag;
use crate::editor::{Editor, TextEdit};

impl Editor {
    /// A press on the Frame or a preview range field: the gesture until
    /// release. Whether `id` was one of them.
    pub(in crate::internals::editor) fn time_field_press(&mut self, id: FieldId, x: f32) -> bool {
        if !matches!(id, FieldId::Frame | FieldId::Preview(_)) {
            return false;
        }
        self.drag = Drag::TimeField(FieldPress::new(id, x, self.frame));
        true
    }

    /// The mouse moved while the gesture holds: the Frame field scrubs
    /// once past the slop. Whether the picture changed.
    pub(in crate::internals::editor) fn time_field_move(&mut self, x: f32) -> bool {
        let Drag::TimeField(p) = &mut self.drag else {
            return false;
        };
        let Some(dx) = p.drag_dx(x) else {
            return false;
        };
        let (id, from) = (p.field, p.base);
        self.stop_playback();
        if id == FieldId::Frame {
            let v = id.clamp(from + dx * id.drag_step());
            self.frame = v.round().min(self.scene.settings.duration);
        }
        true
    }

    /// The release: a click types into the field, from its value.
    pub(in crate::internals::editor) fn time_field_release(&mut self, p: FieldPress<FieldId, f32>) {
        if p.moved() {
            return;
        }
        let v = match p.field {
            FieldId::Frame => Some(p.base),
            id => self.preview_field(id),
        };
        if let Some(v) = v {
            self.edit = Some(TextEdit {
                field: p.field,
                text: FieldValue::Number(v).display(),
                fresh: true,
            });
        }
    }

    /// Esc during the press: the frame it started from.
    pub(in crate::internals::editor) fn time_field_cancel(&mut self, p: FieldPress<FieldId, f32>) {
        if p.field == FieldId::Frame {
            self.frame = p.base;
        }
    }
}
