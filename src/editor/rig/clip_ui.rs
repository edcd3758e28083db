//! The clip name field as a component: `< name > Clips` at the right of
//! the Scene header when the scene has named clips (`rig/clips.rs` has
//! the edits). It lays out its widgets ([`ClipField::widgets`]), paints
//! them ([`ClipField::paint`]) and holds its own press: the name is typed,
//! never dragged, so a click types and a drag does nothing; Enter asks
//! for the rename ([`ClipField::handle`] → [`Response`]). It never names
//! the `Editor`: [`ClipCtx`] is the snapshot it sees. Its buttons go
//! through their widgets' actions.

use super::clip_action::ClipAction;
use crate::editor::component::{Intent, Response};
use crate::editor::field_press::{FieldEvent, FieldPress};
use crate::editor::fields::{FieldId, FieldValue};
use crate::editor::panel::{button, w, Action, Widget, WidgetKind};
use crate::editor::props_view::Look;
use crate::ui::text;
use crate::ui::{Painter, Rect};

/// What the clip field sees of the editor.
#[derive(Clone, Debug, Default)]
pub struct ClipCtx {
    /// The playing clip's name ("" without named clips).
    pub name: String,
    /// The scene has named clips (else the field is not shown).
    pub named: bool,
}

/// The clip field's state: a press on it, until the mouse is released.
#[derive(Clone, Debug, Default)]
pub struct ClipField {
    press: Option<FieldPress<(), ()>>,
}

impl ClipField {
    /// Whether a press on the field holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// `< name > Clips` at the right of the Scene header `h`.
    pub fn widgets(h: Rect, ctx: &ClipCtx, out: &mut Vec<Widget>) {
        if !ctx.named {
            return;
        }
        let title = text::width("Scene") + 8;
        let bw = |s: &str| text::width(s) + 4;
        let (y, bh) = (h.y + 1, h.h - 2);
        let mut x = h.right() - 2;
        let menu_w = bw("Clips");
        x -= menu_w;
        let menu = Rect::new(x, y, menu_w, bh);
        x -= bw(">") + 1;
        let next = Rect::new(x, y, bw(">"), bh);
        let field_w = (x - 1 - (h.x + title) - bw("<") - 1).min(16 * text::CHAR_W);
        let menu_button = button(menu, "Clips", Action::Clip(ClipAction::Menu), false);
        if field_w < 3 * text::CHAR_W {
            // Too narrow: only the menu.
            out.push(menu_button);
            return;
        }
        x -= field_w + 1;
        let field = Rect::new(x, y, field_w, bh);
        x -= bw("<") + 1;
        let prev = Rect::new(x, y, bw("<"), bh);
        out.push(button(prev, "<", Action::Clip(ClipAction::Step(-1)), false));
        out.push(w(field, WidgetKind::Field(FieldId::ClipName)));
        out.push(button(next, ">", Action::Clip(ClipAction::Step(1)), false));
        out.push(menu_button);
    }

    /// Paints `w` if it is one of the clip widgets (false otherwise).
    pub fn paint(p: &mut Painter, w: &Widget, ctx: &ClipCtx, look: &Look) -> bool {
        let ours = match &w.kind {
            WidgetKind::Field(id) => *id == FieldId::ClipName,
            WidgetKind::Button { action, .. } => matches!(action, Action::Clip(_)),
            _ => false,
        };
        ours && look.paint(p, w, |_, _| ctx.name.clone())
    }

    /// Answers one event on the field.
    pub fn handle(&mut self, ev: &FieldEvent, ctx: &ClipCtx) -> Response {
        match ev {
            FieldEvent::Press {
                field: FieldId::ClipName,
                x,
            } => {
                self.press = Some(FieldPress::new((), *x, ()));
                Response::taken()
            }
            FieldEvent::Move { x } => match &mut self.press {
                // Typed, never dragged: a drag only stops being a click.
                Some(p) => match p.drag_dx(*x) {
                    Some(_) => Response::redraw(),
                    None => Response::taken(),
                },
                None => Response::ignored(),
            },
            FieldEvent::Release => match self.press.take() {
                None => Response::ignored(),
                Some(p) if p.moved() => Response::taken(),
                Some(_) => Response::redraw().with(Intent::Type {
                    field: FieldId::ClipName,
                    text: ctx.name.clone(),
                }),
            },
            FieldEvent::Cancel => match self.press.take() {
                Some(_) => Response::taken(),
                None => Response::ignored(),
            },
            FieldEvent::Typed {
                field: FieldId::ClipName,
                value: FieldValue::Text(t),
            } => Response::redraw().with(Intent::RenameClip(t.clone())),
            _ => Response::ignored(),
        }
    }
}
