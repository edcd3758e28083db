//! The side panel as a component: its sections have fixed places (see
//! `ui::layout::SidePanel`), so whatever does not fit scrolls inside its
//! section instead of pushing the next one down. [`Side`] owns the
//! scroll state, lays out the two lists, places the properties' rows the
//! editor builds (scrolled and clipped), answers the wheel
//! ([`Side::handle`] → [`Response`]) and draws its scroll bars. It never
//! names the `Editor`: [`SideCtx`] is what it sees, and
//! `route/side.rs` routes to it. Clicks on its rows and buttons go
//! through their widgets' actions like every other widget's.

use super::component::Response;
use super::ops::NewLight;
use super::panel::{button, label, w, Action, List, Widget, WidgetKind};
use crate::input::Event;
use crate::scene::NodeId;
use crate::ui::layout::ROW;
use crate::ui::{text, widgets, Painter, Rect, SidePanel};

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

/// What the side panel sees of the editor.
pub struct SideCtx {
    /// The panel's place in the window (the layout's `side`).
    pub area: Rect,
    /// The objects list: each node with its depth in the tree.
    pub objects: Vec<(NodeId, usize)>,
    /// The lights list: each light and whether it is on.
    pub lights: Vec<(NodeId, bool)>,
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
    /// The properties section (`shown`) and the taller rect its rows are
    /// laid out in, moved up by the rows scrolled away (`tall`): laying
    /// out every row and keeping those inside `shown` scrolls the three
    /// faces (node, key panel, material) alike.
    pub fn props_view(&self, ctx: &SideCtx) -> (Rect, Rect) {
        let shown = ctx.sections().props;
        let first = self.props_first(ctx.section, ctx.props_hidden()) as i32;
        let need = (ctx.section_rows + 1) * ROW + 2;
        let tall = Rect::new(
            shown.x,
            shown.y - first * ROW,
            shown.w,
            need.max(shown.h + first * ROW),
        );
        (shown, tall)
    }

    /// The properties' widgets `all` (laid out in `props_view`'s `tall`)
    /// that show: the header row stays, body rows scroll.
    pub fn place_props(&self, ctx: &SideCtx, all: Vec<Widget>, out: &mut Vec<Widget>) {
        let (shown, tall) = self.props_view(ctx);
        let scrolled = shown.y - tall.y;
        for mut w in all {
            if w.rect.y < tall.y + ROW {
                w.rect.y += scrolled;
                out.push(w);
            } else if w.rect.y >= shown.y + ROW && w.rect.bottom() <= shown.bottom() + 1 {
                out.push(w);
            }
        }
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
                        let (node, depth) = ctx.objects[k];
                        out.push(w(rr, WidgetKind::Row { node, depth, list }));
                    }
                    List::Lights => {
                        let (node, on) = ctx.lights[k];
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
        let objects = ctx.objects.iter().position(|&(id, _)| id == sel);
        let lights = ctx.lights.iter().position(|&(id, _)| id == sel);
        for (i, pos) in [objects, lights].into_iter().enumerate() {
            if let Some(pos) = pos {
                let cap = list_capacity(ctx.list(i).0).max(1);
                self.reveal_row(i, pos, cap);
            }
        }
    }

    /// The wheel over a list or the properties scrolls it; every other
    /// event is someone else's.
    pub fn handle(&mut self, ev: &Event, ctx: &SideCtx) -> Response {
        let Event::Wheel { delta, x, y, .. } = *ev else {
            return Response::ignored();
        };
        let by = wheel_rows(delta);
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

    /// The scroll bars of the sections that overflow, over the widgets
    /// (the editor draws those: rows and fields show its state).
    pub fn draw(&self, p: &mut Painter, ctx: &SideCtx) {
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

    #[test]
    fn a_scroll_belongs_to_what_it_was_made_for_and_stays_in_range() {
        let mut s = Side::default();
        let ball = Section {
            node: Some(NodeId(1)),
            kind: SectionKind::Node,
        };
        let keys = Section {
            kind: SectionKind::Keys,
            ..ball
        };
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
        use crate::input::Mods;
        // The side panel of a 480x320 window: four property rows show.
        let ctx = SideCtx {
            area: Rect::new(327, 22, 153, 220),
            objects: (0..6).map(|i| (NodeId(i), 0)).collect(),
            lights: (6..9).map(|i| (NodeId(i), true)).collect(),
            section: Section::default(),
            section_rows: 7,
        };
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
}
