//! The morph sliders as a component: one row per morph target weight of
//! the selection (`rig/morph.rs` has the rules). It lays out a row
//! ([`MorphRows::row`]), paints a slider (the number and a bar of its
//! share of 0..1, [`MorphRows::paint`]) and holds its own press: a drag
//! shows the weights changed, a click types, Esc drops the drag
//! ([`MorphRows::handle`] → [`Response`]); the editor applies the intents
//! by the record rules. It never names the `Editor`: [`MorphCtx`] is the
//! snapshot it sees.

use super::state::MorphBase;
use crate::editor::component::{Intent, Response};
use crate::editor::field_press::{FieldEvent, FieldPress};
use crate::editor::fields::{format_fit, FieldId, FieldValue};
use crate::editor::panel::{field_row, Widget, WidgetKind};
use crate::editor::props_view::Look;
use crate::ui::text::CHAR_W;
use crate::ui::{theme, Painter, Rect};

/// What the sliders see of the editor.
#[derive(Clone, Debug, Default)]
pub struct MorphCtx {
    /// The targets' names ("target 2" when unnamed), one slider each.
    pub names: Vec<String>,
    /// The node keyed, the morphed shape and its shown weights (a
    /// pending change included); `None` without morph targets.
    pub base: Option<MorphBase>,
}

impl MorphCtx {
    /// Weight `i` as shown.
    fn weight(&self, i: u8) -> Option<f32> {
        let b = self.base.as_ref()?;
        b.start.as_slice().get(i as usize).copied()
    }
}

/// The sliders' state: the press in progress and the weight its drag
/// shows now.
#[derive(Clone, Debug, Default)]
pub struct MorphRows {
    press: Option<FieldPress<u8, MorphBase>>,
    dragged: Option<f32>,
}

impl MorphRows {
    /// Whether a press on a slider holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// Slider row `i` in `r`: the target's name, then its weight field.
    pub fn row(i: u8, r: Rect, ctx: &MorphCtx, out: &mut Vec<Widget>) {
        if ctx.base.is_none() {
            return;
        }
        let name = ctx.names.get(i as usize).map_or("", |s| s.as_str());
        let lw = (r.w * 2 / 5).max(5 * CHAR_W);
        field_row(out, r, name, lw, &[FieldId::Morph(i)]);
    }

    /// Paints slider `w` (false when it is not a slider): the field, then
    /// the fill, a bar along its bottom edge, the weight's share of 0..1
    /// (clamped; the number shows values outside).
    pub fn paint(p: &mut Painter, w: &Widget, ctx: &MorphCtx, look: &Look) -> bool {
        let WidgetKind::Field(FieldId::Morph(i)) = w.kind else {
            return false;
        };
        look.paint(p, w, |_, max| {
            ctx.weight(i).map_or(String::new(), |x| format_fit(x, max))
        });
        let Some(v) = ctx.weight(i) else {
            return true;
        };
        let r = w.rect;
        let inner = r.w - 2;
        let fill = ((v.clamp(0.0, 1.0) * inner as f32).round() as i32).clamp(0, inner);
        p.fill_rect(Rect::new(r.x + 1, r.bottom() - 3, inner, 2), theme::BUTTON);
        if fill > 0 {
            p.fill_rect(Rect::new(r.x + 1, r.bottom() - 3, fill, 2), theme::ACCENT);
        }
        true
    }

    /// Answers one event on a slider.
    pub fn handle(&mut self, ev: &FieldEvent, ctx: &MorphCtx) -> Response {
        match ev {
            FieldEvent::Press {
                field: FieldId::Morph(i),
                x,
            } => {
                let Some(base) = ctx.base.clone() else {
                    return Response::ignored();
                };
                self.press = Some(FieldPress::new(*i, *x, base));
                self.dragged = None;
                Response::taken()
            }
            FieldEvent::Move { x } => {
                let Some(p) = &mut self.press else {
                    return Response::ignored();
                };
                let Some(dx) = p.drag_dx(*x) else {
                    return Response::taken();
                };
                let r = Response::redraw().with(Intent::StopPlayback);
                let Some(&v0) = p.base.start.as_slice().get(p.field as usize) else {
                    return r;
                };
                let v = v0 + dx * FieldId::Morph(p.field).drag_step();
                self.dragged = Some(v);
                r.with(Intent::ShowWeight {
                    base: Box::new(p.base.clone()),
                    index: p.field,
                    value: v,
                })
            }
            FieldEvent::Release => match (self.press.take(), self.dragged.take()) {
                (None, _) => Response::ignored(),
                (Some(p), Some(v)) if p.moved() => Response::redraw().with(Intent::SetWeight {
                    base: Box::new(p.base),
                    index: p.field,
                    value: v,
                }),
                (Some(p), _) if p.moved() => Response::taken(),
                // A click: type into the slider, starting from its weight.
                (Some(p), _) => match p.base.start.as_slice().get(p.field as usize) {
                    Some(&v) => Response::redraw().with(Intent::Type {
                        field: FieldId::Morph(p.field),
                        text: FieldValue::Number(v).display(),
                    }),
                    None => Response::taken(),
                },
            },
            FieldEvent::Cancel => match (self.press.take(), self.dragged.take()) {
                (Some(p), _) if p.moved() => Response::redraw().with(Intent::DropWeights),
                (Some(_), _) => Response::taken(),
                (None, _) => Response::ignored(),
            },
            FieldEvent::Typed {
                field: FieldId::Morph(i),
                value: FieldValue::Number(v),
            } => match &ctx.base {
                Some(b) => Response::redraw().with(Intent::SetWeight {
                    base: Box::new(b.clone()),
                    index: *i,
                    value: *v,
                }),
                None => Response::ignored(),
            },
            _ => Response::ignored(),
        }
    }
}
