//! The key panel as a component: while keys are selected the side panel's
//! properties section shows it (frame, value, interpolation, T/C/B, ease,
//! the track's repeat mode, the selected keys). It lays out its own
//! widgets ([`KeyPanel::widgets`]) and paints them ([`KeyPanel::draw`],
//! scrolled where the side panel's properties section shows them), and
//! answers its buttons, its fields' drags and typed numbers itself
//! ([`KeyPanel::handle`]) with a [`Response`] whose intents (preview or
//! commit an animation, select keys, type into a field, a status line)
//! the editor applies. Its own state is whether the "Object" button put
//! the node's properties back and the field drag in progress (the
//! editor's gesture only says the key panel holds the mouse). It never
//! names the `Editor`; the rules it applies are in `keyprops.rs`, its
//! routing in `route/keyprops.rs`.

use super::component::{Intent, Response};
use super::field_press::FieldPress;
use super::fields::{clamp_note, format_fit, format_number, FieldId, FieldValue};
use super::keyprops::*;
use super::keystrip::{row_name, KeyRef};
use super::panel::{button, label, w as widget, Action, Widget, WidgetKind};
use super::props_view::{Look, PropsView};
use crate::anim::{Animation, Interp, Repeat, Value, ValueKind};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{Painter, Rect};

/// What the key panel sees of the editor.
pub struct KeyPanelCtx<'a> {
    pub anim: &'a Animation,
    /// The selected keys that exist (the first is the primary).
    pub keys: Vec<KeyRef>,
}

/// The key panel's state.
#[derive(Clone, Debug, Default)]
pub struct KeyPanel {
    /// The "Object" button: show the node's properties instead while keys
    /// are selected ("Keys" comes back; selecting keys comes back too).
    pub node_shown: bool,
    /// A press on one of its fields, until the mouse is released.
    press: Option<FieldPress<KeyField, PressBase>>,
}

/// What a key field's drag starts from: the animation and the selected
/// keys at the press.
type PressBase = (Animation, Vec<KeyRef>);

/// What happens to the key panel: a click on one of its buttons, the
/// mouse pressed on one of its fields (the editor found which), moved
/// and released, Esc during that drag, or a number typed into a field.
#[derive(Clone, Copy, Debug)]
pub enum KeyEvent {
    Button(KeyAction),
    /// The mouse went down on `field` at `x`.
    Press {
        field: KeyField,
        x: f32,
    },
    /// The mouse moved to `x` while pressed.
    Move {
        x: f32,
    },
    /// The mouse came up: a drag is one undo step, a click types.
    Release,
    /// Esc during the drag: back to the press.
    Cancel,
    /// A number typed into the field and Enter.
    Typed {
        field: KeyField,
        value: f32,
    },
}

impl KeyPanel {
    /// Whether the properties section shows the key panel.
    pub fn shown(&self, ctx: &KeyPanelCtx) -> bool {
        !self.node_shown && !ctx.keys.is_empty()
    }

    /// Rows the key panel needs (for the side panel split).
    pub fn rows(&self, ctx: &KeyPanelCtx) -> i32 {
        7 + ctx.keys.len().min(4) as i32
    }

    /// The number a field shows of the primary key of `keys` in `anim`.
    pub fn number(f: KeyField, anim: &Animation, keys: &[KeyRef]) -> Option<f32> {
        read(f, &keys.first()?.get(anim)?)
    }

    /// Text of a field, at most `max_chars` long.
    pub fn field_text(&self, f: KeyField, max_chars: usize, ctx: &KeyPanelCtx) -> String {
        Self::number(f, ctx.anim, &ctx.keys)
            .map(|x| format_fit(x, max_chars))
            .unwrap_or_default()
    }

    /// Whether a press on one of its fields holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// Answers one event. Buttons of the keys' menu that are not the
    /// panel's own (delete, copy, paste, select a row or channel) are
    /// ignored: the editor sends them to the key strip and graph editor.
    pub fn handle(&mut self, ev: KeyEvent, ctx: &KeyPanelCtx) -> Response {
        let keys = &ctx.keys;
        let commit = |label: &str, after: Animation| {
            Response::redraw()
                .with(Intent::Commit {
                    label: label.to_string(),
                    before: ctx.anim.clone(),
                    after,
                })
                .with(Intent::Status(label.to_string(), false))
        };
        match ev {
            KeyEvent::Button(a) => match a {
                KeyAction::ShowNode => {
                    self.node_shown = true;
                    Response::redraw()
                }
                KeyAction::ShowKeys => {
                    self.node_shown = false;
                    Response::redraw()
                }
                KeyAction::Ease(e) => commit(e.label(), with_ease(ctx.anim, keys, e)),
                KeyAction::Interp(i) => {
                    let rot = keys
                        .first()
                        .is_some_and(|k| k.property.kind() == ValueKind::Rotation);
                    let label = format!("Interpolation {}", i.name(rot));
                    commit(&label, with_interp(ctx.anim, keys, i))
                }
                KeyAction::Repeat(r) => {
                    let (after, label) = with_repeat(ctx.anim, keys, r);
                    commit(label, after).with(Intent::Status(label.into(), false))
                }
                KeyAction::ToggleBool => match toggled(ctx.anim, keys) {
                    Some((after, on)) => commit(if on { "Key off" } else { "Key on" }, after),
                    None => Response::taken(),
                },
                KeyAction::Delete
                | KeyAction::Copy
                | KeyAction::Paste
                | KeyAction::SelectRow(_)
                | KeyAction::SelectChannel => Response::ignored(),
            },
            KeyEvent::Press { field, x } => {
                if keys.is_empty() {
                    return Response::ignored();
                }
                let base = (ctx.anim.clone(), keys.clone());
                self.press = Some(FieldPress::new(field, x, base));
                Response::taken()
            }
            KeyEvent::Move { x } => {
                let Some(p) = &mut self.press else {
                    return Response::ignored();
                };
                let Some(dx) = p.drag_dx(x) else {
                    return Response::taken();
                };
                let r = Response::redraw().with(Intent::StopPlayback);
                let (base, keys) = &p.base;
                let Some(v0) = Self::number(p.field, base, keys) else {
                    return r;
                };
                let v = v0 + dx * p.field.drag_step(keys[0].property);
                match set_field(base, keys, p.field, v) {
                    Ok((anim, refs)) => r.with(Intent::Preview(anim)).with(Intent::ShowKeys(refs)),
                    Err(_) => r,
                }
            }
            KeyEvent::Release => match self.press.take() {
                None => Response::ignored(),
                Some(p) if p.moved() => Response::redraw().with(Intent::Commit {
                    label: format!("Drag key {:?}", FieldId::Key(p.field)),
                    before: p.base.0,
                    after: ctx.anim.clone(),
                }),
                // A click: type into the field, starting from its number.
                Some(p) => match Self::number(p.field, &p.base.0, &p.base.1) {
                    Some(v) => Response::redraw().with(Intent::Type {
                        field: FieldId::Key(p.field),
                        text: FieldValue::Number(v).display(),
                    }),
                    None => Response::taken(),
                },
            },
            KeyEvent::Cancel => match self.press.take() {
                Some(p) if p.moved() => Response::redraw()
                    .with(Intent::Preview(p.base.0))
                    .with(Intent::ShowKeys(p.base.1)),
                Some(_) => Response::taken(),
                None => Response::ignored(),
            },
            KeyEvent::Typed { field, value } => match set_field(ctx.anim, keys, field, value) {
                Ok((after, refs)) => {
                    let mut r =
                        commit(&format!("Set key {field:?}"), after).with(Intent::SelectKeys(refs));
                    let kept = keys.first().map(|k| field.clamp(k.property, value));
                    let name = FieldId::Key(field).label();
                    if let Some(n) = kept.and_then(|k| clamp_note(&name, value, k)) {
                        r = r.with(Intent::Status(n, false));
                    }
                    r
                }
                Err(e) => Response::redraw().with(Intent::Status(e, true)),
            },
        }
    }

    /// Paints the panel where `view` shows the properties' rows (scrolled
    /// and clipped as the side panel places them), looking as `look` says.
    pub fn draw(&self, p: &mut Painter, ctx: &KeyPanelCtx, view: &PropsView, look: &Look) {
        let mut all = Vec::new();
        self.widgets(view.tall, ctx, &mut all);
        let mut shown = Vec::new();
        view.place(all, &mut shown);
        for w in &shown {
            look.paint(p, w, |id, max_chars| match id {
                FieldId::Key(f) => self.field_text(f, max_chars, ctx),
                _ => String::new(),
            });
        }
    }

    /// "Keys" at the right of the node properties' `header` while keys are
    /// selected but the node is shown.
    pub fn switch(&self, header: Rect, ctx: &KeyPanelCtx, out: &mut Vec<Widget>) {
        if self.node_shown && !ctx.keys.is_empty() {
            let bw = text::width("Keys") + 6;
            out.push(button(
                Rect::new(header.right() - bw - 2, header.y + 1, bw, header.h - 2),
                "Keys",
                Action::Key(KeyAction::ShowKeys),
                false,
            ));
        }
    }

    /// The panel's widgets in the properties section `r`.
    pub fn widgets(&self, r: Rect, ctx: &KeyPanelCtx, out: &mut Vec<Widget>) {
        let keys = &ctx.keys;
        let Some(primary) = keys.first().copied() else {
            return;
        };
        let Some(pkey) = primary.get(ctx.anim) else {
            return;
        };
        let (h, body) = r.take_top(ROW);
        let bw = text::width("Object") + 6;
        let name = row_name(primary.property);
        let title = match keys.len() {
            1 if text::width(name) + text::width("Key: ") + bw + 12 <= h.w => {
                format!("Key: {name}")
            }
            1 => name.to_string(),
            n => format!("{n} keys"),
        };
        out.push(widget(h, WidgetKind::Header(title)));
        out.push(button(
            Rect::new(h.right() - bw - 2, h.y + 1, bw, h.h - 2),
            "Object",
            Action::Key(KeyAction::ShowNode),
            false,
        ));
        let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
        // The longest label ("Value", "Euler", "Frame") plus a gap, so a
        // label never runs into its value.
        let lw = 6 * CHAR_W;
        let mut y = body.y;
        let mut next = || {
            let r = (y + ROW <= body.bottom() + 1).then(|| Rect::new(body.x, y, body.w, ROW));
            y += ROW;
            r
        };
        if let Some(r) = next() {
            let (a, _) = r.take_left(r.w / 2 + lw / 2);
            field_row(out, a, "Frame", lw + CHAR_W, &[KeyField::Frame]);
        }
        let rotation = primary.property.kind() == ValueKind::Rotation;
        if let Some(r) = next() {
            match pkey.value {
                Value::Vec3(_) | Value::Rotation(_) => {
                    let name = match primary.property.kind() {
                        ValueKind::Color => "RGB",
                        ValueKind::Rotation => "Euler",
                        _ => "Value",
                    };
                    field_row(out, r, name, lw, &[0, 1, 2].map(KeyField::Value));
                }
                Value::Scalar(_) => field_row(out, r, "Value", lw, &[KeyField::Value(0)]),
                Value::Weights(w) => out.push(label(r, &format!("{} weights", w.len()), true)),
                Value::Bool(b) => {
                    let (a, rest) = r.take_left(lw);
                    out.push(label(a, "Value", true));
                    let bw = text::width("Off") + 10;
                    out.push(button(
                        Rect::new(rest.x, rest.y + 1, bw, rest.h - 2),
                        if b { "On" } else { "Off" },
                        Action::Key(KeyAction::ToggleBool),
                        b,
                    ));
                }
            }
        }
        if let Some(r) = next() {
            // Interpolation buttons use the whole row (no label).
            let rest = r;
            if matches!(pkey.value, Value::Bool(_)) {
                out.push(label(rest, "Steps (on/off)", true));
            } else {
                let n = 3;
                let bw = (rest.w - (n - 1) * 2) / n;
                for (i, it) in [Interp::Step, Interp::Linear, Interp::Tcb]
                    .into_iter()
                    .enumerate()
                {
                    out.push(button(
                        Rect::new(rest.x + i as i32 * (bw + 2), rest.y + 1, bw, rest.h - 2),
                        it.name(rotation),
                        Action::Key(KeyAction::Interp(it)),
                        pkey.interp == it,
                    ));
                }
            }
        }
        if let Some(r) = next() {
            field_row(
                out,
                r,
                "TCB",
                lw,
                &[KeyField::Tension, KeyField::Continuity, KeyField::Bias],
            );
        }
        if let Some(r) = next() {
            field_row(out, r, "Ease", lw, &[KeyField::EaseIn, KeyField::EaseOut]);
        }
        if let Some(r) = next() {
            // The track's repeat mode outside its keys (per track).
            let now = ctx.anim.track(primary.target()).map(|t| t.repeat);
            let (a, rest) = r.take_left(lw);
            out.push(label(a, "After", true));
            let bw = (rest.w - 2) / 2;
            for (i, (name, rep)) in [("hold", Repeat::Constant), ("loop", Repeat::Loop)]
                .into_iter()
                .enumerate()
            {
                out.push(button(
                    Rect::new(rest.x + i as i32 * (bw + 2), rest.y + 1, bw, rest.h - 2),
                    name,
                    Action::Key(KeyAction::Repeat(rep)),
                    now == Some(rep),
                ));
            }
        }
        // The selected keys, one per row (frame and property).
        let shown = keys.len().min(4);
        for (i, k) in keys.iter().take(shown).enumerate() {
            let Some(r) = next() else { break };
            let more = keys.len() - shown;
            let s = if i + 1 == shown && more > 0 {
                format!("+{} more", more + 1)
            } else {
                format!("{:>5} {}", format_number(k.frame), row_name(k.property))
            };
            out.push(label(r, &s, i > 0));
        }
    }
}

/// A label then equal fields for `ids` (the panel's row of key fields).
fn field_row(out: &mut Vec<Widget>, r: Rect, name: &str, label_w: i32, ids: &[KeyField]) {
    let ids: Vec<FieldId> = ids.iter().map(|k| FieldId::Key(*k)).collect();
    super::panel::field_row(out, r, name, label_w, &ids);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Property, Target, TargetRef, Track};
    use crate::scene::NodeId;
    use glam::Vec3;

    /// One node with two translation keys (linear) at 0 and 10.
    fn anim() -> Animation {
        let keys = vec![
            Key::new(0.0, Vec3::ZERO).with_interp(Interp::Linear),
            Key::new(10.0, Vec3::new(1.0, 2.0, 3.0)).with_interp(Interp::Linear),
        ];
        let target = Target {
            of: TargetRef::Node(NodeId(0)),
            property: Property::Translation,
        };
        let t = Track::new(target, Repeat::Constant, Keys::Vec3(keys)).unwrap();
        Animation { tracks: vec![t] }
    }

    fn key(frame: f32) -> KeyRef {
        KeyRef {
            node: NodeId(0),
            property: Property::Translation,
            frame,
        }
    }

    fn committed(r: &Response) -> Option<(&str, &Animation)> {
        r.intents.iter().find_map(|i| match i {
            Intent::Commit { label, after, .. } => Some((label.as_str(), after)),
            _ => None,
        })
    }

    #[test]
    fn the_panel_answers_its_buttons_and_typed_numbers_by_itself() {
        let a = anim();
        let ctx = KeyPanelCtx {
            anim: &a,
            keys: vec![key(10.0)],
        };
        let mut p = KeyPanel::default();
        assert!(p.shown(&ctx));
        assert_eq!(p.field_text(KeyField::Value(1), 8, &ctx), "2");
        let r = p.handle(KeyEvent::Button(KeyAction::Interp(Interp::Tcb)), &ctx);
        let (label, after) = committed(&r).expect("one undo step");
        assert_eq!(label, "Interpolation tcb");
        assert_eq!(key(10.0).get(after).unwrap().interp, Interp::Tcb);
        // Typing bias on a linear key makes it TCB; out of range is kept
        // in range and said so.
        let r = p.handle(
            KeyEvent::Typed {
                field: KeyField::Bias,
                value: 3.0,
            },
            &ctx,
        );
        let (_, after) = committed(&r).unwrap();
        let k = key(10.0).get(after).unwrap();
        assert_eq!((k.bias, k.interp), (1.0, Interp::Tcb));
        assert!(r.intents.contains(&Intent::SelectKeys(vec![key(10.0)])));
        assert!(r
            .intents
            .iter()
            .any(|i| matches!(i, Intent::Status(s, false) if s.contains("Bias"))));
        // "Object" shows the node instead; "Keys" comes back.
        assert_eq!(
            p.handle(KeyEvent::Button(KeyAction::ShowNode), &ctx),
            Response::redraw()
        );
        assert!(!p.shown(&ctx));
        let mut w = Vec::new();
        p.switch(Rect::new(0, 0, 200, ROW), &ctx, &mut w);
        assert_eq!(w.len(), 1, "the Keys button");
        p.handle(KeyEvent::Button(KeyAction::ShowKeys), &ctx);
        assert!(p.shown(&ctx));
        // The keys' menu commands are not the panel's.
        assert!(!p.handle(KeyEvent::Button(KeyAction::Delete), &ctx).consumed);
    }

    #[test]
    fn a_frame_drag_previews_moved_keys_and_release_commits_once() {
        let a = anim();
        let keys = vec![key(10.0)];
        let mut p = KeyPanel::default();
        let ctx = KeyPanelCtx {
            anim: &a,
            keys: keys.clone(),
        };
        let press = KeyEvent::Press {
            field: KeyField::Frame,
            x: 100.0,
        };
        assert_eq!(p.handle(press, &ctx), Response::taken());
        assert!(p.pressed(), "the panel holds the press");
        // Within the slop nothing changes yet.
        let r = p.handle(KeyEvent::Move { x: 102.0 }, &ctx);
        assert!(r.intents.is_empty() && !r.redraw);
        let r = p.handle(KeyEvent::Move { x: 140.0 }, &ctx);
        let moved = r.intents.iter().find_map(|i| match i {
            Intent::Preview(m) => Some(m.clone()),
            _ => None,
        });
        let Some(moved) = moved else {
            panic!("a preview: {r:?}");
        };
        assert!(committed(&r).is_none(), "nothing recorded while dragging");
        let Some(Intent::ShowKeys(refs)) = r.intents.last() else {
            panic!("the moved keys shown selected: {r:?}");
        };
        assert!(refs[0].frame > 10.0 && refs[0].get(&moved).is_some());
        // Release: one step from the press to what is shown.
        let shown = KeyPanelCtx {
            anim: &moved,
            keys: refs.clone(),
        };
        let r = p.handle(KeyEvent::Release, &shown);
        assert_eq!(
            r.intents,
            vec![Intent::Commit {
                label: "Drag key Key(Frame)".into(),
                before: a.clone(),
                after: moved.clone(),
            }]
        );
        assert!(!p.pressed());
        // Esc during a drag puts back the press's animation and keys.
        p.handle(press, &ctx);
        p.handle(KeyEvent::Move { x: 60.0 }, &ctx);
        let r = p.handle(KeyEvent::Cancel, &shown);
        assert_eq!(
            r.intents,
            vec![Intent::Preview(a.clone()), Intent::ShowKeys(keys.clone())]
        );
        // A click without a drag types into the field from its number.
        p.handle(press, &ctx);
        let r = p.handle(KeyEvent::Release, &ctx);
        assert_eq!(
            r.intents,
            vec![Intent::Type {
                field: FieldId::Key(KeyField::Frame),
                text: "10".into(),
            }]
        );
        // Nothing pressed: the mouse is someone else's.
        assert!(!p.handle(KeyEvent::Move { x: 0.0 }, &ctx).consumed);
        assert!(!p.handle(KeyEvent::Release, &ctx).consumed);
    }
}
