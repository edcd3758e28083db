//! The material rows as a component: the face of the side panel's
//! properties that shows the selection's material (name, three colours,
//! shininess and transparency, the texture with its thumbnail and wrap
//! toggles, the emissive map). It lays out its widgets
//! ([`MatRows::widgets`]), paints them with the colour swatches and the
//! thumbnail ([`MatRows::draw`]) and holds its own field press: a drag
//! shows the material changed, a click types, Esc drops the drag
//! ([`MatRows::handle`] → [`Response`]). What a value does to the scene
//! (the record rules, undo steps) the editor applies from the intents
//! (`material/route.rs`). It never names the `Editor`: [`MatCtx`] is the
//! snapshot it sees. Its buttons go through their widgets' actions.

use super::{thumb, MatAction, MatBase, MatField, Shown};
use crate::editor::component::{Intent, Response};
use crate::editor::field_press::{FieldEvent, FieldPress};
use crate::editor::fields::{format_fit, FieldId, FieldValue};
use crate::editor::panel::{button, field_row, label, w, Action, Widget, WidgetKind};
use crate::editor::props_view::{Look, PropsView};
use crate::scene::{Image, Material, Wrap};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{theme, Painter, Rect};

/// Rows under the panel's header: name, three colours, shininess and
/// transparency, texture name, wrap, and the emissive map's name (only
/// shown when the material has one).
pub const ROWS: i32 = 8;

/// What the material rows see of the editor.
pub struct MatCtx<'a> {
    /// Which material the selection shows.
    pub shown: Shown,
    /// Its name for the name row (its own, else the shape's).
    pub name: String,
    /// The material as shown at the current frame (a pending change
    /// included): the fields' numbers and the swatches.
    pub value: Material,
    /// The stored material (its texture and emissive map).
    pub stored: Option<&'a Material>,
    /// The texture's and the emissive map's names.
    pub texture_name: Option<String>,
    pub glow_name: Option<String>,
    /// The shown material's texture image (the thumbnail).
    pub image: Option<&'a Image>,
}

impl MatCtx<'_> {
    /// Rows the panel needs (for the side panel split).
    pub fn rows(&self) -> i32 {
        let glow = self.stored.is_some_and(|m| m.emissive_texture.is_some());
        if glow {
            ROWS
        } else {
            ROWS - 1
        }
    }
}

/// The material rows' state: the field press in progress and the value
/// its drag shows now.
#[derive(Clone, Debug, Default)]
pub struct MatRows {
    press: Option<FieldPress<MatField, MatBase>>,
    dragged: Option<f32>,
}

/// The panel's rows inside the properties rect `r`.
struct Rows {
    header: Rect,
    rows: [Rect; ROWS as usize],
    /// The texture thumbnail's box (left of the two texture rows).
    thumb: Rect,
}

fn rows(r: Rect) -> Rows {
    let (header, body) = r.take_top(ROW);
    let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
    let rows = std::array::from_fn(|i| Rect::new(body.x, body.y + i as i32 * ROW, body.w, ROW));
    let side = 2 * ROW - 2;
    let thumb = Rect::new(body.x, body.y + 5 * ROW + 1, side, side);
    Rows {
        header,
        rows,
        thumb,
    }
}

/// Short wrap names for the toggles ("S:Rep").
fn wrap_short(w: Wrap) -> &'static str {
    match w {
        Wrap::Repeat => "Rep",
        Wrap::Clamp => "Clamp",
        Wrap::Mirror => "Mir",
    }
}

/// The "Mat" button at the right of the object properties' `header`
/// (left of the buttons already there) that opens the panel.
pub fn switch(header: Rect, out: &mut Vec<Widget>) {
    let right = out
        .iter()
        .filter(|w| w.rect.y == header.y + 1 && header.contains(w.rect.x as f32, w.rect.y as f32))
        .map(|w| w.rect.x)
        .min()
        .unwrap_or(header.right());
    let bw = text::width("Mat") + 6;
    out.push(button(
        Rect::new(right - bw - 2, header.y + 1, bw, header.h - 2),
        "Mat",
        Action::Material(MatAction::Open),
        false,
    ));
}

impl MatRows {
    /// Whether a press on one of its fields holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// Answers one event on its fields (`None`: the panel is not shown;
    /// a press in progress still ends).
    pub fn handle(&mut self, ev: &FieldEvent, ctx: Option<&MatCtx>) -> Response {
        let base = |c: &MatCtx| MatBase {
            material: c.shown.material,
            start: c.value.clone(),
        };
        match ev {
            FieldEvent::Press {
                field: FieldId::Material(f),
                x,
            } => {
                let Some(c) = ctx else {
                    return Response::ignored();
                };
                self.press = Some(FieldPress::new(*f, *x, base(c)));
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
                let f = p.field;
                let v0 = f.read(&p.base.start);
                let v = f.clamp(v0 + dx * FieldId::Material(f).drag_step());
                let mut m = p.base.start.clone();
                f.write(&mut m, v);
                self.dragged = Some(v);
                Response::redraw()
                    .with(Intent::StopPlayback)
                    .with(Intent::ShowMaterial {
                        id: p.base.material,
                        props: vec![f.property()],
                        value: Box::new(m),
                    })
            }
            FieldEvent::Release => match (self.press.take(), self.dragged.take()) {
                (None, _) => Response::ignored(),
                (Some(p), Some(v)) if p.moved() => Response::redraw().with(Intent::SetMaterial {
                    field: p.field,
                    base: Box::new(p.base),
                    value: v,
                }),
                (Some(p), _) if p.moved() => Response::taken(),
                // A click: type into the field, starting from its number.
                (Some(p), _) => Response::redraw().with(Intent::Type {
                    field: FieldId::Material(p.field),
                    text: FieldValue::Number(p.field.read(&p.base.start)).display(),
                }),
            },
            FieldEvent::Cancel => match (self.press.take(), self.dragged.take()) {
                (Some(p), _) if p.moved() => Response::redraw().with(Intent::DropMaterial),
                (Some(_), _) => Response::taken(),
                (None, _) => Response::ignored(),
            },
            FieldEvent::Typed {
                field: FieldId::Material(f),
                value: FieldValue::Number(v),
            } => match ctx {
                Some(c) => Response::redraw().with(Intent::SetMaterial {
                    field: *f,
                    base: Box::new(base(c)),
                    value: *v,
                }),
                None => Response::ignored(),
            },
            _ => Response::ignored(),
        }
    }

    /// A field's text: the shown value in at most `max` characters.
    pub fn field_text(f: MatField, max: usize, ctx: &MatCtx) -> String {
        format_fit(f.read(&ctx.value), max)
    }

    /// The panel's widgets in the properties rect `r`.
    pub fn widgets(&self, r: Rect, ctx: &MatCtx, out: &mut Vec<Widget>) {
        let l = rows(r);
        out.push(w(l.header, WidgetKind::Header("Material".into())));
        let bw = text::width("Obj") + 6;
        out.push(button(
            Rect::new(
                l.header.right() - bw - 2,
                l.header.y + 1,
                bw,
                l.header.h - 2,
            ),
            "Obj",
            Action::Material(MatAction::Close),
            false,
        ));
        let bottom = r.bottom() + 1;
        let ok = |r: &Rect| r.bottom() <= bottom;
        let [name_r, dif, spe, emi, se, tex_r, wrap, glow] = l.rows;
        let lw = 5 * CHAR_W;
        if ok(&name_r) {
            let sh = ctx.shown;
            let text = match sh.differ {
                true => format!("{} (first of {} shapes)", ctx.name, sh.shapes),
                false => ctx.name.clone(),
            };
            out.push(label(name_r, &text, false));
        }
        for (row, (name, fields)) in [dif, spe, emi]
            .iter()
            .zip(["Dif", "Spe", "Emi"].iter().zip(MatField::ROWS))
        {
            if ok(row) {
                let ids: Vec<FieldId> = fields.iter().map(|&f| FieldId::Material(f)).collect();
                field_row(out, *row, name, lw, &ids);
            }
        }
        if ok(&se) {
            let (a, b) = se.take_left(se.w / 2);
            field_row(
                out,
                a,
                "Shin",
                lw,
                &[FieldId::Material(MatField::Shininess)],
            );
            let b = Rect::new(b.x + 2, b.y, b.w - 2, b.h);
            field_row(
                out,
                b,
                "Tra",
                4 * CHAR_W,
                &[FieldId::Material(MatField::Transparency)],
            );
        }
        let texture = ctx.stored.and_then(|m| m.texture.as_ref());
        let x0 = l.thumb.right() + 4;
        if ok(&tex_r) {
            // Right to left: [x] (with a texture), [Load].
            let mut right = tex_r.right() + 2;
            let buttons = [
                ("x", MatAction::RemoveTexture, texture.is_some()),
                ("Load", MatAction::LoadTexture, true),
            ];
            for (name, a, _) in buttons.into_iter().filter(|b| b.2) {
                let bw = text::width(name) + 6;
                right -= bw + 2;
                let r = Rect::new(right, tex_r.y + 1, bw, ROW - 2);
                out.push(button(r, name, Action::Material(a), false));
            }
            match (&ctx.texture_name, texture) {
                (Some(name), Some(_)) => {
                    let nr = Rect::new(x0, tex_r.y, right - x0 - 2, ROW);
                    out.push(label(nr, name, false));
                }
                _ => {
                    let nr = Rect::new(tex_r.x, tex_r.y, right - tex_r.x - 2, ROW);
                    out.push(label(nr, "Texture: none", true));
                }
            }
        }
        // The emissive map (glTF emissiveTexture): named, not edited here.
        let glow_map = ctx.stored.and_then(|m| m.emissive_texture.as_ref());
        if let (true, Some(_)) = (ok(&glow), glow_map) {
            let name = ctx.glow_name.clone().unwrap_or_default();
            out.push(label(glow, &format!("Emissive map: {name}"), false));
        }
        if let (true, Some(t)) = (ok(&wrap), texture) {
            let mut x = x0;
            for (axis, wr, a) in [
                ("S", t.wrap_s, MatAction::WrapS),
                ("T", t.wrap_t, MatAction::WrapT),
            ] {
                let s = format!("{axis}:{}", wrap_short(wr));
                let bw = text::width(&s) + 4;
                if x + bw > wrap.right() {
                    break;
                }
                out.push(button(
                    Rect::new(x, wrap.y + 1, bw, ROW - 2),
                    &s,
                    Action::Material(a),
                    false,
                ));
                x += bw + 2;
            }
        }
    }

    /// Paints the panel where `view` shows the properties' rows, looking
    /// as `look` says, then the colour swatches beside the colour rows'
    /// labels and the texture thumbnail.
    pub fn draw(&self, p: &mut Painter, ctx: &MatCtx, view: &PropsView, look: &Look) {
        let mut all = Vec::new();
        self.widgets(view.tall, ctx, &mut all);
        let mut shown = Vec::new();
        view.place(all, &mut shown);
        for w in &shown {
            look.paint(p, w, |id, max| match id {
                FieldId::Material(f) => Self::field_text(f, max, ctx),
                _ => String::new(),
            });
        }
        // Laid out like the widgets: in the scrolled rows, drawn where
        // they show.
        let (props, l) = (view.shown, rows(view.tall));
        let m = &ctx.value;
        let bottom = props.bottom() + 1;
        let top = props.y + ROW;
        for (i, c) in [m.diffuse, m.specular, m.emissive].into_iter().enumerate() {
            let r = l.rows[1 + i];
            if r.y >= top && r.bottom() <= bottom {
                let s = Rect::new(r.x + 3 * CHAR_W + 3, r.y + 4, 8, 8);
                p.fill_rect(s, super::swatch(c));
                p.stroke_rect(s.inset(-1), theme::BORDER);
            }
        }
        let t = l.thumb;
        if t.y < top || t.bottom() > bottom {
            return;
        }
        let Some(img) = ctx.image else {
            return;
        };
        p.fill_rect(t, theme::FIELD);
        let inner = t.inset(1);
        let (tw, th) = thumb::fit(img, inner.w as u32);
        let px = thumb::pixels(img, tw, th);
        let x0 = inner.x + (inner.w - tw as i32) / 2;
        let y0 = inner.y + (inner.h - th as i32) / 2;
        for (i, &c) in px.iter().enumerate() {
            let (x, y) = ((i as u32 % tw) as i32, (i as u32 / tw) as i32);
            p.fill_rect(Rect::new(x0 + x, y0 + y, 1, 1), c);
        }
        p.stroke_rect(t, theme::BORDER);
    }
}
