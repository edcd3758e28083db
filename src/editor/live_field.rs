//! A number field whose drag shows its change live (kept pending over
//! the tracks) and records it once at the release, as the material rows
//! and the morph sliders do: [`LiveField`] answers their mouse alike (a
//! click types, a drag shows, the release sets, Esc drops), and each
//! says through [`LiveRules`] what differs — which value a field reads
//! and the intents that show, set and drop a change.

use super::component::{Intent, Response};
use super::field_press::{cancel_of, drag_of, FieldEvent, FieldPress};
use super::fields::{FieldId, FieldValue};

/// What a face's live fields read and ask for.
pub trait LiveRules {
    type Field: Copy;
    /// What a press starts from (the shown values).
    type Base: Clone;
    /// The field's id in the panel (typing, drag speed, clamping).
    fn id(f: Self::Field) -> FieldId;
    /// Field `f`'s value in `base` (`None`: nothing to drag).
    fn read(f: Self::Field, base: &Self::Base) -> Option<f32>;
    /// Show `base` with field `f` at `v` (a drag in progress).
    fn show(base: &Self::Base, f: Self::Field, v: f32) -> Intent;
    /// Set field `f` to `v` from `base` by the record rules.
    fn set(base: Self::Base, f: Self::Field, v: f32) -> Intent;
    /// Drop what a drag showed.
    fn drop() -> Intent;
}

/// The press on one of a face's live fields and the value its drag shows
/// now.
#[derive(Clone, Debug)]
pub struct LiveField<R: LiveRules> {
    press: Option<FieldPress<R::Field, R::Base>>,
    dragged: Option<f32>,
}

impl<R: LiveRules> Default for LiveField<R> {
    fn default() -> Self {
        LiveField {
            press: None,
            dragged: None,
        }
    }
}

impl<R: LiveRules> LiveField<R> {
    /// Whether a press holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// The mouse went down on field `f` at `x`, the values being `base`.
    pub fn press(&mut self, f: R::Field, x: f32, base: R::Base) -> Response {
        self.press = Some(FieldPress::new(f, x, base));
        self.dragged = None;
        Response::taken()
    }

    /// The mouse moved or came up, or Esc, while pressed; other events
    /// are not the press's.
    pub fn handle(&mut self, ev: &FieldEvent) -> Response {
        match ev {
            FieldEvent::Move { x } => {
                let (p, dx) = match drag_of(&mut self.press, *x) {
                    Ok(drag) => drag,
                    Err(r) => return r,
                };
                let r = Response::redraw().with(Intent::StopPlayback);
                let Some(v0) = R::read(p.field, &p.base) else {
                    return r;
                };
                let id = R::id(p.field);
                let v = id.clamp(v0 + dx * id.drag_step());
                self.dragged = Some(v);
                r.with(R::show(&p.base, p.field, v))
            }
            FieldEvent::Release => match (self.press.take(), self.dragged.take()) {
                (None, _) => Response::ignored(),
                (Some(p), Some(v)) if p.moved() => {
                    Response::redraw().with(R::set(p.base, p.field, v))
                }
                (Some(p), _) if p.moved() => Response::taken(),
                // A click: type into the field, starting from its value.
                (Some(p), _) => match R::read(p.field, &p.base) {
                    Some(v) => Response::redraw().with(Intent::Type {
                        field: R::id(p.field),
                        text: FieldValue::Number(v).display(),
                    }),
                    None => Response::taken(),
                },
            },
            FieldEvent::Cancel => {
                self.dragged = None;
                cancel_of(&mut self.press, |_| Response::redraw().with(R::drop()))
            }
            _ => Response::ignored(),
        }
    }
}
