//! The side panel as a component: its sections have fixed places (see
//! `ui::layout::SidePanel`), so whatever does not fit scrolls inside its
//! section instead of pushing the next one down. [`Side`] owns the
//! scroll state and the drag of an object row (drop it on another row to
//! parent it there, on the list's empty space for the top level), lays
//! out and paints the two lists, places the properties' rows (scrolled
//! and clipped, `props_view.rs`), answers the wheel and presses on its
//! rows ([`Side::handle`] → [`Response`]) and draws its scroll bars. It
//! holds the faces with fields of their own (`side_faces.rs` routes their
//! field gesture), the scene section and node face among them. It
//! never names the `Editor`: [`SideCtx`] is the snapshot it sees, and
//! `route/side.rs` routes to it and applies what it returns. Clicks on
//! its buttons and on/off boxes go through their widgets' actions like
//! every other widget's.

use super::component::{Intent, Response};
use super::field_press::DRAG_SLOP;
use super::keypanel::KeyPanel;
use super::material::rows_ui::MatRows;
use super::node_props::{NodeCtx, NodeProps};
use super::ops::NewLight;
use super::panel::{button, label, w, Action, List, Widget, WidgetKind};
use super::props_view::{Look, PropsView};
use super::rig::clip_ui::ClipField;
use super::rig::morph_ui::MorphRows;
use super::scene_section::{SceneCtx, SceneSection};
use crate::input::{Event, Key, MouseButton};
use crate::scene::NodeId;
use crate::ui::layout::ROW;
use crate::ui::{text, theme, widgets, Painter, Rect, SidePanel};

/// What the properties section shows: a scroll made for one thing does
/// not carry over to another (a key panel opened after scrolling an
/// object's rows starts at its top).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Section {
    pub node: Option<NodeId>,
    pub kind: SectionKind,
}

/// Which of its faces the properties section shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SectionKind {
    #[default]
    Node,
    Keys,
    Material,
}

/// The side panel's scroll state.
#[derive(Clone, Debug, Default)]
pub struct Side {
    /// First visible row of the objects and lights lists.
    pub lists: [usize; 2],
    /// First visible body row of the properties, and what it was for.
    props: (Section, usize),
    /// The selection the lists were last scrolled to show, and the side
    /// panel's rect then (a panel made smaller shows it again).
    pub revealed: Option<(NodeId, Rect)>,
    /// An object row pressed and maybe being dragged.
    row_drag: Option<RowDrag>,
    /// The faces that are components of their own (`side_faces.rs`
    /// routes to them): the key panel, the material rows, the morph
    /// sliders, the clip name field.
    pub keys: KeyPanel,
    pub material: MatRows,
    pub morph: MorphRows,
    pub clip: ClipField,
    /// The properties' node face and the scene section (`node_props.rs`,
    /// `scene_section.rs`), faces too.
    pub node: NodeProps,
    pub scene: SceneSection,
}

/// A press on an object row: past the slop it drags the object, to drop
/// it onto another row or the list's empty space.
#[derive(Clone, Debug)]
struct RowDrag {
    node: NodeId,
    at: (f32, f32),
    /// Where the mouse is now (the drop mark follows it).
    to: (f32, f32),
    moved: bool,
}

impl Side {
    /// First visible body row of the properties showing `now`, when
    /// `hidden` of its rows do not fit.
    pub fn props_first(&self, now: Section, hidden: usize) -> usize {
        if self.props.0 == now {
            self.props.1.min(hidden)
        } else {
            0
        }
    }

    /// Moves the properties showing `now` by `by` rows (negative: towards
    /// the first row), within the `hidden` rows that do not fit.
    pub fn scroll_props(&mut self, now: Section, hidden: usize, by: i32) {
        let first = self.props_first(now, hidden);
        self.props = (now, step(first, by, hidden));
    }

    /// Shows the properties of `now` from body row `first`.
    pub fn set_props_first(&mut self, now: Section, first: usize) {
        self.props = (now, first);
    }

    /// Moves list `i` of `n` rows, `cap` of them shown, by `by` rows.
    pub fn scroll_list(&mut self, i: usize, n: usize, cap: usize, by: i32) {
        self.lists[i] = step(self.lists[i], by, n.saturating_sub(cap));
    }

    /// Scrolls list `i` so its row `pos` is among the `cap` shown.
    pub fn reveal_row(&mut self, i: usize, pos: usize, cap: usize) {
        let s = &mut self.lists[i];
        if pos < *s {
            *s = pos;
        } else if pos >= *s + cap {
            *s = pos + 1 - cap;
        }
    }
}

/// A row of the objects list.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectRow {
    pub node: NodeId,
    /// Depth in the scene tree (the row's indent).
    pub depth: usize,
    pub name: String,
}

/// A row of the lights list.
#[derive(Clone, Debug, PartialEq)]
pub struct LightRow {
    pub node: NodeId,
    pub on: bool,
    pub name: String,
    /// The light's colour (0xRRGGBB), shown as a swatch.
    pub color: u32,
}

/// What the side panel sees of the editor.
pub struct SideCtx {
    /// The panel's place in the window (the layout's `side`).
    pub area: Rect,
    /// The objects list, in tree order.
    pub objects: Vec<ObjectRow>,
    /// The lights list.
    pub lights: Vec<LightRow>,
    /// The selected node (its row is highlighted).
    pub selection: Option<NodeId>,
    /// What the properties section shows, and the body rows it needs.
    pub section: Section,
    pub section_rows: i32,
}

impl SideCtx {
    /// The panel's sections (fixed by its height alone).
    pub fn sections(&self) -> SidePanel {
        SidePanel::new(self.area)
    }

    /// Body rows of the properties that do not fit their section.
    pub fn props_hidden(&self) -> usize {
        (self.section_rows - self.sections().prop_rows_shown()).max(0) as usize
    }

    fn list(&self, i: usize) -> (Rect, usize) {
        let sp = self.sections();
        match i {
            0 => (sp.objects, self.objects.len()),
            _ => (sp.lights, self.lights.len()),
        }
    }
}

/// Visible rows of a list section `r` (below its header).
pub fn list_capacity(r: Rect) -> usize {
    ((r.h - ROW).max(0) / ROW) as usize
}

impl Side {
    /// Where the properties' rows go, scrolled as far as the section's
    /// scroll says (see `PropsView`).
    pub fn props_view(&self, ctx: &SideCtx) -> PropsView {
        let shown = ctx.sections().props;
        let first = self.props_first(ctx.section, ctx.props_hidden()) as i32;
        let need = (ctx.section_rows + 1) * ROW + 2;
        let tall = Rect::new(
            shown.x,
            shown.y - first * ROW,
            shown.w,
            need.max(shown.h + first * ROW),
        );
        PropsView { shown, tall }
    }

    /// The properties' widgets `all` (laid out in `props_view`'s `tall`)
    /// that show: the header row stays, body rows scroll.
    pub fn place_props(&self, ctx: &SideCtx, all: Vec<Widget>, out: &mut Vec<Widget>) {
        self.props_view(ctx).place(all, out);
    }

    /// The two lists' widgets: headers (the lights' with its add buttons),
    /// the rows that show, each light's on/off box, `(none)`.
    pub fn list_widgets(&self, ctx: &SideCtx, out: &mut Vec<Widget>) {
        for (i, list) in [List::Objects, List::Lights].into_iter().enumerate() {
            let (r, n) = ctx.list(i);
            let (h, body) = r.take_top(ROW);
            let title = match list {
                List::Objects => format!("Objects ({n})"),
                List::Lights => "Lights".to_string(),
            };
            out.push(w(h, WidgetKind::Header(title)));
            if list == List::Lights {
                add_light_buttons(h, out);
            }
            let cap = list_capacity(r);
            let first = self.lists[i].min(n.saturating_sub(cap));
            for k in first..n.min(first + cap) {
                let rr = Rect::new(body.x, body.y + (k - first) as i32 * ROW, body.w, ROW);
                match list {
                    List::Objects => {
                        let (node, depth) = (ctx.objects[k].node, ctx.objects[k].depth);
                        out.push(w(rr, WidgetKind::Row { node, depth, list }));
                    }
                    List::Lights => {
                        let (node, on) = (ctx.lights[k].node, ctx.lights[k].on);
                        let (main, chk) = rr.take_left(rr.w - ROW - 2);
                        out.push(w(
                            main,
                            WidgetKind::Row {
                                node,
                                depth: 0,
                                list,
                            },
                        ));
                        let action = Action::ToggleLight(node);
                        out.push(w(chk, WidgetKind::Check { action, on }));
                    }
                }
            }
            if n == 0 && body.h >= ROW {
                let r = Rect::new(body.x + 4, body.y, body.w - 4, ROW);
                out.push(label(r, "(none)", true));
            }
        }
    }

    /// Scrolls the lists so `sel`'s row shows, once per selection and
    /// panel size (a list the user scrolled away stays so).
    pub fn reveal(&mut self, ctx: &SideCtx, sel: NodeId) {
        let now = Some((sel, ctx.area));
        if self.revealed == now {
            return;
        }
        self.revealed = now;
        let objects = ctx.objects.iter().position(|r| r.node == sel);
        let lights = ctx.lights.iter().position(|r| r.node == sel);
        for (i, pos) in [objects, lights].into_iter().enumerate() {
            if let Some(pos) = pos {
                let cap = list_capacity(ctx.list(i).0).max(1);
                self.reveal_row(i, pos, cap);
            }
        }
    }

    /// The list row under (x, y) and its list.
    fn row_at(&self, ctx: &SideCtx, x: f32, y: f32) -> Option<(Widget, NodeId, List)> {
        let mut out = Vec::new();
        self.list_widgets(ctx, &mut out);
        out.into_iter().find_map(|wd| match wd.kind {
            WidgetKind::Row { node, list, .. } if wd.rect.contains(x, y) => Some((wd, node, list)),
            _ => None,
        })
    }

    /// The wheel over a list or the properties scrolls it; a press on a
    /// list row selects its node, and on an object row starts the row
    /// drag (move, release, Esc); every other event is someone else's.
    pub fn handle(&mut self, ev: &Event, ctx: &SideCtx) -> Response {
        match *ev {
            Event::Wheel { delta, x, y, .. } => self.wheel(wheel_rows(delta), x, y, ctx),
            Event::MouseDown {
                button: MouseButton::Left,
                x,
                y,
                ..
            } => {
                let Some((_, node, list)) = self.row_at(ctx, x, y) else {
                    return Response::ignored();
                };
                if list == List::Objects {
                    self.row_drag = Some(RowDrag {
                        node,
                        at: (x, y),
                        to: (x, y),
                        moved: false,
                    });
                }
                Response::redraw().with(Intent::Select(node))
            }
            Event::MouseMove { x, y, .. } => {
                let Some(d) = &mut self.row_drag else {
                    return Response::ignored();
                };
                d.to = (x, y);
                if !d.moved && (x - d.at.0).abs().max((y - d.at.1).abs()) < DRAG_SLOP {
                    return Response::taken();
                }
                d.moved = true;
                Response::redraw()
            }
            Event::MouseUp { x, y, .. } => match self.row_drag.take() {
                None => Response::ignored(),
                Some(d) if !d.moved => Response::redraw(),
                Some(d) => self.drop_row(d.node, x, y, ctx),
            },
            Event::KeyDown {
                key: Key::Escape, ..
            } if self.row_drag.is_some() => {
                self.row_drag = None;
                Response::redraw()
            }
            _ => Response::ignored(),
        }
    }

    /// Whether a press on one of its rows holds the mouse.
    pub fn pressed(&self) -> bool {
        self.row_drag.is_some()
    }

    fn wheel(&mut self, by: i32, x: f32, y: f32, ctx: &SideCtx) -> Response {
        for i in 0..2 {
            let (r, n) = ctx.list(i);
            if r.contains(x, y) {
                self.scroll_list(i, n, list_capacity(r), by);
                return Response::redraw();
            }
        }
        if ctx.sections().props.contains(x, y) {
            self.scroll_props(ctx.section, ctx.props_hidden(), by);
            return Response::redraw();
        }
        Response::ignored()
    }

    /// `node` dropped at (x, y): onto another object's row it goes under
    /// that object, onto the list's empty space to the top level.
    fn drop_row(&self, node: NodeId, x: f32, y: f32, ctx: &SideCtx) -> Response {
        let onto = self
            .row_at(ctx, x, y)
            .filter(|(_, _, list)| *list == List::Objects);
        let r = Response::redraw();
        match onto {
            Some((_, t, _)) if t == node => r,
            Some((_, t, _)) => r.with(Intent::Reparent {
                node,
                parent: Some(t),
            }),
            None if ctx.sections().objects.contains(x, y) => {
                r.with(Intent::Reparent { node, parent: None })
            }
            None => r.with(Intent::Status(
                "Drop on an object's row to parent it there, on the list's empty space to unparent"
                    .into(),
                false,
            )),
        }
    }

    /// Paints the scene section and, when the properties show it
    /// (`node_shown`), the node face where `view` places its rows; first,
    /// as other parts' widgets sit on their title rows. Returns the
    /// widgets they painted, for the editor to leave out.
    pub fn draw_sections(
        &self,
        p: &mut Painter,
        (scene, node): (&SceneCtx, &NodeCtx),
        node_view: Option<&PropsView>,
        look: &Look,
    ) -> Vec<Widget> {
        self.scene.draw(p, scene, look);
        let mut own = self.scene.own_widgets(scene);
        if let Some(view) = node_view {
            self.node.draw(p, node, view, look);
            own.extend(self.node.shown(node, view));
        }
        own
    }

    /// Paints the two lists (headers, add buttons, rows, on/off boxes),
    /// the scroll bars of the sections that overflow, and where a dragged
    /// object row would go.
    pub fn draw(&self, p: &mut Painter, ctx: &SideCtx, look: &Look) {
        let mut out = Vec::new();
        self.list_widgets(ctx, &mut out);
        for wd in &out {
            if look.paint(p, wd, |_, _| String::new()) {
                continue;
            }
            if let WidgetKind::Row { node, depth, list } = wd.kind {
                let selected = ctx.selection == Some(node);
                let hot = look.hot(wd.rect);
                match list {
                    List::Objects => {
                        let name = ctx.objects.iter().find(|r| r.node == node);
                        let name = name.map_or("", |r| r.name.as_str());
                        widgets::list_row(p, wd.rect, name, depth, selected, hot);
                    }
                    List::Lights => {
                        let Some(l) = ctx.lights.iter().find(|r| r.node == node) else {
                            continue;
                        };
                        widgets::list_row(p, wd.rect, &l.name, depth, selected, hot);
                        // A colour swatch before the on/off box.
                        let s = Rect::new(wd.rect.right() - 10, wd.rect.y + 4, 8, 8);
                        p.fill_rect(s, l.color);
                    }
                }
            }
        }
        for i in 0..2 {
            let (r, n) = ctx.list(i);
            let cap = list_capacity(r);
            let first = self.lists[i].min(n.saturating_sub(cap));
            widgets::scroll_bar(p, r.take_top(ROW).1, first, cap, n);
        }
        let hidden = ctx.props_hidden();
        let shown = ctx.sections().prop_rows_shown() as usize;
        let body = ctx.sections().props.take_top(ROW).1;
        let first = self.props_first(ctx.section, hidden);
        widgets::scroll_bar(p, body, first, shown, shown + hidden);
        if let Some(d) = self.row_drag.as_ref().filter(|d| d.moved) {
            let (mx, my) = d.to;
            if let Some((wd, _, List::Objects)) = self.row_at(ctx, mx, my) {
                p.stroke_rect(wd.rect, theme::ACCENT);
            }
            let name = ctx.objects.iter().find(|r| r.node == d.node);
            let name = format!("move {}", name.map_or("", |r| r.name.as_str()));
            p.text(mx as i32 + 10, my as i32 + 4, &name, theme::ACCENT);
        }
    }
}

/// `+Spot +Pt +Dir` at the right of the lights header `h`; one-letter
/// labels when the panel is narrow.
fn add_light_buttons(h: Rect, out: &mut Vec<Widget>) {
    let long = [
        ("+Spot", NewLight::Spot),
        ("+Pt", NewLight::Point),
        ("+Dir", NewLight::Directional),
    ];
    let short = [
        ("+S", NewLight::Spot),
        ("+P", NewLight::Point),
        ("+D", NewLight::Directional),
    ];
    let need: i32 = long.iter().map(|(l, _)| text::width(l) + 5).sum();
    let items = if h.w - text::width("Lights") - 8 >= need {
        long
    } else {
        short
    };
    let mut x = h.right() - 2;
    for (name, which) in items {
        let bw = text::width(name) + 4;
        x -= bw;
        let r = Rect::new(x, h.y + 1, bw, h.h - 2);
        out.push(button(r, name, Action::AddLight(which), false));
        x -= 1;
    }
}

/// Rows a wheel turn of `delta` moves (negative: towards the first row):
/// a turn up (positive delta) shows earlier rows, one row per notch.
pub fn wheel_rows(delta: f32) -> i32 {
    let n = delta.abs().round().clamp(1.0, 10.0) as i32;
    if delta > 0.0 {
        -n
    } else {
        n
    }
}

/// `first` moved by `by` and kept within `0..=max`.
fn step(first: usize, by: i32, max: usize) -> usize {
    (first as i64 + by as i64).clamp(0, max as i64) as usize
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Mods;

    /// The side panel of a 480x320 window with six objects (the fourth
    /// under the third) and three lights: four property rows show.
    fn ctx() -> SideCtx {
        let objects = (0..6).map(|i| ObjectRow {
            node: NodeId(i),
            depth: usize::from(i == 3),
            name: format!("o{i}"),
        });
        let lights = (6..9).map(|i| LightRow {
            node: NodeId(i),
            on: true,
            name: format!("l{i}"),
            color: 0xffffff,
        });
        SideCtx {
            area: Rect::new(327, 22, 153, 220),
            objects: objects.collect(),
            lights: lights.collect(),
            selection: None,
            section: Section::default(),
            section_rows: 7,
        }
    }

    fn node_section(kind: SectionKind) -> Section {
        Section {
            node: Some(NodeId(1)),
            kind,
        }
    }

    #[test]
    fn a_scroll_belongs_to_what_it_was_made_for_and_stays_in_range() {
        let (ball, keys) = (
            node_section(SectionKind::Node),
            node_section(SectionKind::Keys),
        );
        let mut s = Side::default();
        s.scroll_props(ball, 3, wheel_rows(-5.0));
        assert_eq!(s.props_first(ball, 3), 3);
        assert_eq!(s.props_first(ball, 1), 1, "fewer hidden rows clamp it");
        assert_eq!(s.props_first(keys, 6), 0, "the key panel starts at its top");
        s.scroll_props(ball, 3, wheel_rows(1.0));
        assert_eq!(s.props_first(ball, 3), 2);
        s.scroll_list(1, 5, 2, 2);
        s.scroll_list(1, 5, 2, 2);
        assert_eq!(s.lists[1], 3);
        s.scroll_list(1, 5, 2, -1);
        assert_eq!(s.lists[1], 2);
        s.reveal_row(1, 0, 2);
        assert_eq!(s.lists[1], 0);
    }

    #[test]
    fn the_wheel_scrolls_the_section_under_it_and_nothing_else() {
        let ctx = ctx();
        let sp = ctx.sections();
        let wheel = |r: Rect| Event::Wheel {
            delta: -1.0,
            x: (r.x + 4) as f32,
            y: (r.bottom() - 2) as f32,
            mods: Mods::NONE,
        };
        let mut s = Side::default();
        assert!(s.handle(&wheel(sp.objects), &ctx).consumed);
        assert_eq!(s.lists, [1, 0]);
        assert!(s.handle(&wheel(sp.lights), &ctx).consumed);
        assert_eq!(s.lists, [1, 1]);
        assert!(s.handle(&wheel(sp.props), &ctx).consumed);
        assert_eq!(s.props_first(ctx.section, ctx.props_hidden()), 1);
        assert!(!s.handle(&wheel(sp.scene), &ctx).consumed);
        assert!(!s.handle(&Event::Tick { time: 0.0 }, &ctx).consumed);
        // The objects list shows its rows from the second, as many as fit.
        let mut out = Vec::new();
        s.list_widgets(&ctx, &mut out);
        let rows: Vec<NodeId> = out
            .iter()
            .filter_map(|w| match w.kind {
                WidgetKind::Row {
                    node,
                    list: List::Objects,
                    ..
                } => Some(node),
                _ => None,
            })
            .collect();
        assert_eq!(rows.first(), Some(&NodeId(1)));
        assert_eq!(rows.len(), list_capacity(sp.objects));
        // Revealing a light scrolled away brings its row back.
        s.reveal(&ctx, NodeId(6));
        assert_eq!(s.lists[1], 0);
    }

    #[test]
    fn an_object_row_dragged_onto_another_row_or_the_empty_list_is_reparented() {
        // A taller panel: two objects leave the list's empty space below
        // their rows.
        let mut c = ctx();
        c.objects.truncate(2);
        c.area.h = 400;
        let sp = c.sections();
        let row = |i: i32| {
            (
                sp.objects.x as f32 + 20.0,
                (sp.objects.y + ROW * (1 + i) + 8) as f32,
            )
        };
        let ev = |kind: fn(f32, f32) -> Event, (x, y): (f32, f32)| kind(x, y);
        let down = |x, y| Event::MouseDown {
            button: MouseButton::Left,
            x,
            y,
            mods: Mods::NONE,
        };
        let up = |x, y| Event::MouseUp {
            button: MouseButton::Left,
            x,
            y,
            mods: Mods::NONE,
        };
        let mv = |x, y| Event::MouseMove {
            x,
            y,
            mods: Mods::NONE,
        };
        let mut s = Side::default();
        // A press selects the row and holds the mouse; a release where it
        // was pressed only selects.
        let r = s.handle(&ev(down, row(1)), &c);
        assert_eq!(r.intents, vec![Intent::Select(NodeId(1))]);
        assert!(s.pressed());
        let r = s.handle(&ev(up, row(1)), &c);
        assert!(r.consumed && r.intents.is_empty() && !s.pressed());
        // Dragged onto row 0: under node 0.
        s.handle(&ev(down, row(1)), &c);
        assert!(s.handle(&ev(mv, row(0)), &c).redraw);
        let r = s.handle(&ev(up, row(0)), &c);
        let under = |parent| Intent::Reparent {
            node: NodeId(1),
            parent,
        };
        assert_eq!(r.intents, vec![under(Some(NodeId(0)))]);
        // Onto the list's empty space: the top level.
        let empty = (row(0).0, (sp.objects.bottom() - 2) as f32);
        assert!(c.objects.len() < list_capacity(sp.objects));
        s.handle(&ev(down, row(1)), &c);
        s.handle(&ev(mv, empty), &c);
        assert_eq!(s.handle(&ev(up, empty), &c).intents, vec![under(None)]);
        // Outside the list: nothing moves, the status line says how.
        let lights = (row(0).0, (sp.lights.y + ROW + 4) as f32);
        s.handle(&ev(down, row(1)), &c);
        s.handle(&ev(mv, lights), &c);
        let r = s.handle(&ev(up, lights), &c);
        assert!(matches!(&r.intents[..], [Intent::Status(t, false)] if t.contains("Drop on")));
        // Esc ends the drag: the release is someone else's.
        s.handle(&ev(down, row(1)), &c);
        s.handle(&ev(mv, row(0)), &c);
        let esc = Event::KeyDown {
            key: Key::Escape,
            mods: Mods::NONE,
        };
        assert!(s.handle(&esc, &c).consumed);
        assert!(!s.handle(&ev(up, row(0)), &c).consumed);
        // A light's row selects it but never drags.
        let light = (row(0).0, (sp.lights.y + ROW + 8) as f32);
        let r = s.handle(&ev(down, light), &c);
        assert_eq!(r.intents, vec![Intent::Select(NodeId(6))]);
        assert!(!s.pressed());
    }
}
