//! The properties' node face as a part of the side panel: the selected
//! object's or light's rows (name, transform or light values, draw style,
//! delete), the selection's key frames, and how to start when nothing is
//! selected. [`NodeProps`] lays the rows out from a snapshot of what
//! they show ([`NodeCtx`]: the node as posed at the current frame),
//! paints them itself ([`NodeProps::draw`]) and owns the press, drag and
//! click-to-type of its fields ([`NodeProps::handle`], the shared
//! `field_press.rs` gesture), answering with a [`Response`] whose intents
//! (show the node over its tracks as a handle drag does, put the stored
//! node back and record the change by the record rules, type) the editor
//! applies. It never names the `Editor`; the morph sliders below its
//! rows and the buttons on its header that switch to other faces belong
//! to their own parts (it leaves them room).

use super::component::{Intent, Response};
use super::field_press::{drag_of, FieldEvent, FieldPress};
use super::fields::{clamp_note, format_fit, FieldId, FieldValue};
use super::ops;
use super::panel::{button, field_row, label, style_name, w, Action, Widget, WidgetKind};
use super::props_view::{Look, PropsView};
use super::record::field_property;
use crate::scene::{LightKind, Node, NodeId, NodeKind};
use crate::ui::layout::ROW;
use crate::ui::text::{self, CHAR_W};
use crate::ui::{Painter, Rect};

/// What the properties say with nothing selected: how to start (a
/// newcomer's first questions), as many lines as the section shows.
const NOTHING_SELECTED: [&str; 6] = [
    "Nothing selected",
    "Click an object",
    "Shift+A: add object",
    "F3: find a command",
    "F1: every shortcut",
    "Ctrl+O: open a file",
];

/// What the node face sees of the editor.
#[derive(Clone, Debug, Default)]
pub struct NodeCtx {
    /// The selection as shown: animated values at the current frame (a
    /// change not yet keyed included).
    pub node: Option<(NodeId, Node)>,
    /// The selection as stored (the values under its tracks): what a
    /// drag puts back before it records, so undo returns to it.
    pub stored: Option<Node>,
    /// Morph slider rows under the node's own (`rig/morph.rs` fills them).
    pub morph_rows: usize,
    /// The selection's key frames, as lines that fit after "Keys".
    pub key_lines: Vec<String>,
    /// Body rows the properties section shows.
    pub rows_shown: i32,
}

/// Where the node face left room for other parts: its header (the
/// switches to the key panel and material go at its right) and the morph
/// slider rows.
pub struct Room {
    pub header: Rect,
    pub morph: Vec<Rect>,
}

/// What a field drag started from (the node as shown and as stored)
/// and what it shows now.
#[derive(Clone, Debug)]
pub struct NodeBase {
    id: NodeId,
    node: Box<Node>,
    stored: Box<Node>,
    shown: Option<Box<Node>>,
}

/// The node face's state: the press on one of its fields, until the
/// mouse is released.
#[derive(Clone, Debug, Default)]
pub struct NodeProps {
    press: Option<FieldPress<FieldId, NodeBase>>,
}

impl NodeProps {
    /// Whether `f` is one of the node face's fields.
    pub fn owns(f: FieldId) -> bool {
        field_property(f).is_some() || f == FieldId::Name
    }

    /// Body rows the node's own rows need (for the side panel split; the
    /// key frame lines come on top).
    pub fn rows(ctx: &NodeCtx) -> i32 {
        match ctx.node.as_ref().map(|(_, n)| &n.kind) {
            // As many lines of how to start as show (they never scroll).
            None => (NOTHING_SELECTED.len() as i32).min(ctx.rows_shown.max(1)),
            Some(NodeKind::Light(l)) => match l.kind {
                LightKind::Directional | LightKind::Point => 5,
                LightKind::Spot { .. } => 7,
            },
            Some(_) => 5 + ctx.morph_rows as i32,
        }
    }

    /// The text field `id` shows, at most `max_chars` long.
    pub fn text(id: FieldId, max_chars: usize, ctx: &NodeCtx) -> String {
        match ctx.node.as_ref().and_then(|(_, n)| id.read_node(n)) {
            Some(FieldValue::Number(x)) => format_fit(x, max_chars),
            Some(v) => v.display(),
            None => String::new(),
        }
    }

    /// The text typing into `id` starts from: its value now.
    pub fn start_text(id: FieldId, ctx: &NodeCtx) -> Option<String> {
        let (_, n) = ctx.node.as_ref()?;
        id.read_node(n).map(|v| v.display())
    }

    /// Whether a press on one of its fields holds the mouse.
    pub fn pressed(&self) -> bool {
        self.press.is_some()
    }

    /// The face's widgets in the properties section `r`; where it left
    /// room for others (`None` with nothing selected: no room).
    pub fn widgets(&self, r: Rect, ctx: &NodeCtx, out: &mut Vec<Widget>) -> Option<Room> {
        let (h, body) = r.take_top(ROW);
        let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
        let Some((sel, node)) = &ctx.node else {
            out.push(w(h, WidgetKind::Header("Properties".into())));
            let lines = NOTHING_SELECTED.iter().take(Self::rows(ctx) as usize);
            for (i, line) in lines.enumerate() {
                let y = body.y + i as i32 * ROW;
                out.push(label(Rect::new(body.x + 2, y, body.w, ROW), line, true));
            }
            return None;
        };
        let kind = match &node.kind {
            NodeKind::Light(l) => ops::light_kind_name(l),
            NodeKind::Shape(_) => "Shape",
            NodeKind::Camera(_) => "Camera",
            NodeKind::Group => "Object",
        };
        out.push(w(h, WidgetKind::Header(kind.to_string())));
        let lw = 5 * CHAR_W;
        let mut y = body.y;
        // The next body row, if it fits the section.
        let mut next = || {
            let r = (y + ROW <= body.bottom() + 1).then(|| Rect::new(body.x, y, body.w, ROW));
            y += ROW;
            r
        };
        let axes = |f: fn(u8) -> FieldId| [0, 1, 2].map(f);
        if let Some(r) = next() {
            field_row(out, r, "Name", lw, &[FieldId::Name]);
        }
        match &node.kind {
            NodeKind::Light(l) => {
                if let Some(r) = next() {
                    let (a, b) = r.take_left(lw);
                    out.push(label(a, "On", true));
                    let check = WidgetKind::Check {
                        action: Action::ToggleLight(*sel),
                        on: l.on,
                    };
                    out.push(w(Rect::new(b.x, b.y, ROW, b.h), check));
                    let rest = Rect::new(b.x + ROW + 4, b.y, b.w - ROW - 4, b.h);
                    field_row(out, rest, "Int", lw, &[FieldId::LightIntensity]);
                }
                if let Some(r) = next() {
                    field_row(out, r, "Col", lw, &axes(FieldId::LightColor));
                }
                if !matches!(l.kind, LightKind::Directional) {
                    if let Some(r) = next() {
                        field_row(out, r, "Loc", lw, &axes(FieldId::LightLocation));
                    }
                }
                if !matches!(l.kind, LightKind::Point) {
                    if let Some(r) = next() {
                        field_row(out, r, "Dir", lw, &axes(FieldId::LightDirection));
                    }
                }
                if matches!(l.kind, LightKind::Spot { .. }) {
                    if let Some(r) = next() {
                        let (a, _) = r.take_left(r.w / 2);
                        field_row(out, a, "Cut", lw, &[FieldId::LightCutOff]);
                    }
                }
                if let Some(r) = next() {
                    delete_button(r, out);
                }
            }
            _ => {
                for (name, f) in [
                    ("T", FieldId::Translation as fn(u8) -> FieldId),
                    ("R", FieldId::Rotation),
                    ("S", FieldId::Scale),
                ] {
                    if let Some(r) = next() {
                        field_row(out, r, name, lw, &axes(f));
                    }
                }
                if let Some(r) = next() {
                    let (a, b) = r.take_left(lw);
                    out.push(label(a, "Draw", true));
                    let bw = text::width("Hidden") + 8;
                    let at = Rect::new(b.x, b.y + 1, bw, b.h - 2);
                    out.push(button(
                        at,
                        style_name(node.style),
                        Action::ObjectStyle,
                        false,
                    ));
                    delete_button(r, out);
                }
            }
        }
        let morph = (0..ctx.morph_rows).filter_map(|_| next()).collect();
        for (i, line) in ctx.key_lines.iter().enumerate() {
            let Some(r) = next() else { continue };
            let (a, b) = r.take_left(5 * CHAR_W);
            if i == 0 {
                out.push(label(a, "Keys", true));
            }
            out.push(label(b, line, false));
        }
        Some(Room { header: h, morph })
    }

    /// Its widgets that show where `view` places the properties' rows.
    pub fn shown(&self, ctx: &NodeCtx, view: &PropsView) -> Vec<Widget> {
        let mut all = Vec::new();
        self.widgets(view.tall, ctx, &mut all);
        let mut shown = Vec::new();
        view.place(all, &mut shown);
        shown
    }

    /// Paints its rows where `view` shows the properties (scrolled and
    /// clipped as the side panel places them), looking as `look` says.
    pub fn draw(&self, p: &mut Painter, ctx: &NodeCtx, view: &PropsView, look: &Look) {
        for wd in &self.shown(ctx, view) {
            look.paint(p, wd, |id, max_chars| Self::text(id, max_chars, ctx));
        }
    }

    /// Answers a press, drag, release, Esc or typed value on one of its
    /// fields: a drag shows the node changed from the press (one undo
    /// step at the release, record rules applied), a click types, Esc
    /// puts the node back, a typed value is recorded.
    pub fn handle(&mut self, ev: FieldEvent, ctx: &NodeCtx) -> Response {
        match ev {
            FieldEvent::Press { field, x } => {
                let (Some((id, node)), Some(stored)) = (&ctx.node, &ctx.stored) else {
                    return Response::ignored();
                };
                let base = NodeBase {
                    id: *id,
                    node: Box::new(node.clone()),
                    stored: Box::new(stored.clone()),
                    shown: None,
                };
                self.press = Some(FieldPress::new(field, x, base));
                Response::taken()
            }
            FieldEvent::Move { x } => {
                let (p, dx) = match drag_of(&mut self.press, x) {
                    Ok(held) => held,
                    Err(r) => return r,
                };
                let r = Response::redraw().with(Intent::StopPlayback);
                let (f, b) = (p.field, &mut p.base);
                let Some(FieldValue::Number(v0)) = f.read_node(&b.node) else {
                    return r;
                };
                let v = FieldValue::Number(f.clamp(v0 + dx * f.drag_step()));
                let mut node = b.node.clone();
                let Some(property) = field_property(f) else {
                    return r;
                };
                if !f.write_node(&mut node, &v) {
                    return r;
                }
                b.shown = Some(node.clone());
                // Shown over the property's tracks (as a handle drag is),
                // so an animated value follows the mouse too.
                r.with(Intent::ShowNode {
                    id: b.id,
                    property,
                    node,
                })
            }
            FieldEvent::Release => match self.press.take() {
                None => Response::ignored(),
                Some(p) if p.moved() => {
                    let (f, b) = (p.field, p.base);
                    let Some(after) = b.shown else {
                        return Response::redraw();
                    };
                    // The stored node back, then the change recorded from
                    // it by the record rules.
                    let put_back = Intent::PutBack {
                        id: b.id,
                        node: b.stored,
                    };
                    Response::redraw().with(put_back).with(Intent::SetNode {
                        label: format!("Drag {f:?}"),
                        id: b.id,
                        after,
                        props: field_property(f).into_iter().collect(),
                    })
                }
                // A click: type into the field, starting from its value.
                Some(p) => match p.field.read_node(&p.base.node) {
                    Some(v) => Response::redraw().with(Intent::Type {
                        field: p.field,
                        text: v.display(),
                    }),
                    None => Response::taken(),
                },
            },
            FieldEvent::Cancel => match self.press.take() {
                Some(p) if p.moved() => Response::redraw().with(Intent::PutBack {
                    id: p.base.id,
                    node: p.base.stored,
                }),
                Some(_) => Response::taken(),
                None => Response::ignored(),
            },
            FieldEvent::Typed { field, value } => {
                let Some((id, node)) = &ctx.node else {
                    return Response::ignored();
                };
                let mut after = Box::new(node.clone());
                if !field.write_node(&mut after, &value) {
                    let why = format!("{}: cannot set '{}' here", field.label(), value.display());
                    return Response::redraw().with(Intent::Status(why, true));
                }
                // What Enter did, said before the record rules speak
                // (a pending change says so after it) and before a
                // clamped value's note.
                let said = format!("{}: {} = {}", node.name, field.label(), value.display());
                let mut r = Response::redraw()
                    .with(Intent::StopPlayback)
                    .with(Intent::Status(said, false))
                    .with(Intent::SetNode {
                        label: format!("Set {field:?}"),
                        id: *id,
                        after,
                        props: field_property(field).into_iter().collect(),
                    });
                if let FieldValue::Number(x) = value {
                    if let Some(n) = clamp_note(&field.label(), x, field.clamp(x)) {
                        r = r.with(Intent::Status(n, false));
                    }
                }
                r
            }
        }
    }
}

/// "Delete" at the right end of row `r`.
fn delete_button(r: Rect, out: &mut Vec<Widget>) {
    let bw = text::width("Delete") + 8;
    let at = Rect::new(r.right() - bw, r.y + 1, bw, r.h - 2);
    out.push(button(at, "Delete", Action::Delete, false));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::Property;
    use crate::scene::Light;

    /// Box at x 1 as shown; stored at x 0 (a track moves it).
    fn ctx() -> NodeCtx {
        let mut n = Node::group("Box");
        n.transform.translation.x = 1.0;
        NodeCtx {
            node: Some((NodeId(3), n)),
            stored: Some(Node::group("Box")),
            rows_shown: 4,
            key_lines: vec!["0 10".into()],
            ..NodeCtx::default()
        }
    }

    #[test]
    fn a_drag_shows_the_node_and_the_release_records_it_once_with_its_property() {
        let (mut p, c) = (NodeProps::default(), ctx());
        let tx = FieldId::Translation(0);
        let r = p.handle(FieldEvent::Press { field: tx, x: 50.0 }, &c);
        assert!(r.consumed && r.intents.is_empty() && p.pressed());
        let r = p.handle(FieldEvent::Move { x: 52.0 }, &c);
        assert!(r.intents.is_empty(), "inside the slop nothing changes");
        let r = p.handle(FieldEvent::Move { x: 60.0 }, &c);
        let Some(Intent::ShowNode { id, node, property }) = r.intents.last() else {
            panic!("a drag shows the node over its tracks: {r:?}")
        };
        assert_eq!((*id, *property), (NodeId(3), Property::Translation));
        assert!(
            (node.transform.translation.x - 1.2).abs() < 1e-6,
            "10 px x 0.02"
        );
        let r = p.handle(FieldEvent::Release, &c);
        let [Intent::PutBack { node: stored, .. }, Intent::SetNode { after, props, .. }] =
            r.intents.as_slice()
        else {
            panic!("the stored node back, then one record: {r:?}")
        };
        assert_eq!(stored.transform.translation.x, 0.0);
        assert!((after.transform.translation.x - 1.2).abs() < 1e-6);
        assert_eq!(props, &[Property::Translation]);
        assert!(!p.pressed());
        assert_eq!(p.handle(FieldEvent::Release, &c), Response::ignored());
    }

    #[test]
    fn a_click_types_esc_puts_back_and_a_typed_value_is_recorded_clamped() {
        let (mut p, c) = (NodeProps::default(), ctx());
        p.handle(
            FieldEvent::Press {
                field: FieldId::Name,
                x: 5.0,
            },
            &c,
        );
        let r = p.handle(FieldEvent::Release, &c);
        let typing = Intent::Type {
            field: FieldId::Name,
            text: "Box".into(),
        };
        assert_eq!(r.intents, vec![typing]);
        let tx = FieldId::Translation(0);
        p.handle(FieldEvent::Press { field: tx, x: 5.0 }, &c);
        p.handle(FieldEvent::Move { x: 25.0 }, &c);
        let r = p.handle(FieldEvent::Cancel, &c);
        let Some(Intent::PutBack { node, .. }) = r.intents.last() else {
            panic!("Esc puts the stored node back: {r:?}")
        };
        assert_eq!(node.transform.translation.x, 0.0);
        // A light's intensity typed above 1 is kept at 1 and said so.
        let mut lc = ctx();
        lc.node = Some((NodeId(1), Node::new("L", NodeKind::Light(Light::spot()))));
        let typed = FieldEvent::Typed {
            field: FieldId::LightIntensity,
            value: FieldValue::Number(3.0),
        };
        let r = p.handle(typed, &lc);
        let set = r.intents.iter().find_map(|i| match i {
            Intent::SetNode { after, .. } => Some(after),
            _ => None,
        });
        assert_eq!(set.expect("recorded").light().unwrap().intensity, 1.0);
        assert!(
            matches!(r.intents.last(), Some(Intent::Status(s, false)) if s.contains("set to 1"))
        );
        // Nothing selected: no field is the face's to press.
        let none = NodeCtx::default();
        let r = p.handle(FieldEvent::Press { field: tx, x: 0.0 }, &none);
        assert_eq!(r, Response::ignored());
    }

    #[test]
    fn enter_on_a_node_field_says_what_it_set_before_the_record_rules_do() {
        let (mut p, c) = (NodeProps::default(), ctx());
        let tx = FieldId::Translation(0);
        let typed = FieldEvent::Typed {
            field: tx,
            value: FieldValue::Number(2.5),
        };
        let r = p.handle(typed, &c);
        let said = r.intents.iter().position(|i| {
            matches!(i, Intent::Status(s, false)
                if s == &format!("Box: {} = 2.5", tx.label()))
        });
        let set = r
            .intents
            .iter()
            .position(|i| matches!(i, Intent::SetNode { .. }));
        // The record rules' "Pending" (an animated property) comes later.
        assert!(
            said.expect("a status line") < set.expect("recorded"),
            "{r:?}"
        );
    }

    #[test]
    fn rows_leave_room_for_morph_sliders_before_the_key_lines() {
        let p = NodeProps::default();
        let mut c = ctx();
        c.morph_rows = 2;
        let mut out = Vec::new();
        let r = Rect::new(0, 0, 160, 20 * ROW);
        let room = p.widgets(r, &c, &mut out).expect("a selection");
        assert_eq!(room.morph.len(), 2);
        let keys = out.iter().find(|w| {
            w.kind
                == WidgetKind::Label {
                    text: "Keys".into(),
                    dim: true,
                }
        });
        assert!(keys.unwrap().rect.y >= room.morph[1].bottom());
        assert_eq!(NodeProps::rows(&c), 7);
        // Nothing selected: the hint lines, as many as show.
        let none = NodeCtx {
            rows_shown: 3,
            ..NodeCtx::default()
        };
        let mut out = Vec::new();
        assert!(p.widgets(r, &none, &mut out).is_none());
        assert_eq!(out.len(), 1 + 3);
    }
}
