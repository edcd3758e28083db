//! The editor's side of `panel`: routes events to it and applies what it returns.

use crate::editor::browser::Browser;
use crate::editor::fields::FieldId;
use crate::editor::ops::{self, NewLight};
#[allow(unused_imports)]
use crate::editor::panel::*;
use crate::editor::side_ui::{Section, SectionKind};
use crate::editor::{Editor, Mode};
use crate::scene::{LightKind, NodeId, NodeKind};
use crate::ui::layout::{CONTROLS_H, ROW};
use crate::ui::text::{self, CHAR_W};
use crate::ui::{Rect, SidePanel};

impl Editor {
    /// Property rows the selection needs (for the side panel split).
    pub(in crate::internals::editor) fn prop_rows(&self) -> i32 {
        match self.selection.map(|s| &self.scene.node(s).kind) {
            None => 1,
            Some(NodeKind::Light(l)) => match l.kind {
                LightKind::Directional => 5,
                LightKind::Point => 5,
                LightKind::Spot { .. } => 7,
            },
            Some(_) => 5 + self.morph_rows() as i32,
        }
    }

    /// The side panel's sections: fixed by the window's height alone.
    pub fn side_panel(&self) -> SidePanel {
        SidePanel::new(self.layout().side)
    }

    /// Scrolls the objects and lights lists so the selection's row shows.
    pub(in crate::internals::editor) fn reveal_selection(&mut self) {
        let Some(sel) = self.selection else { return };
        let now = Some((sel, self.layout().side));
        if self.side.revealed == now {
            return;
        }
        self.side.revealed = now;
        let sp = self.side_panel();
        let lists: [(Vec<NodeId>, Rect); 2] = [
            (
                ops::objects(&self.scene)
                    .into_iter()
                    .map(|(id, _)| id)
                    .collect(),
                sp.objects,
            ),
            (ops::lights(&self.scene), sp.lights),
        ];
        for (i, (ids, r)) in lists.iter().enumerate() {
            if let Some(pos) = ids.iter().position(|&id| id == sel) {
                self.side.reveal_row(i, pos, Self::list_capacity(*r).max(1));
            }
        }
    }

    /// What the properties section shows now (its scroll belongs to it).
    pub(in crate::internals::editor) fn prop_section(&self) -> Section {
        let kind = if self.material_panel().is_some() {
            SectionKind::Material
        } else if self.key_panel_shown() {
            SectionKind::Keys
        } else {
            SectionKind::Node
        };
        Section {
            node: self.selection,
            kind,
        }
    }

    /// Body rows of the properties that do not fit their section.
    pub(in crate::internals::editor) fn props_hidden(&self) -> usize {
        (self.section_rows() - self.side_panel().prop_rows_shown()).max(0) as usize
    }

    /// The properties section (`shown`) and the taller rect its rows are
    /// laid out in, moved up by the rows scrolled away (`tall`): laying
    /// out every row and keeping those inside `shown` scrolls the three
    /// faces (node, key panel, material) alike.
    pub(in crate::internals::editor) fn props_view(&self) -> (Rect, Rect) {
        let shown = self.side_panel().props;
        let first = self
            .side
            .props_first(self.prop_section(), self.props_hidden()) as i32;
        let need = (self.section_rows() + 1) * ROW + 2;
        let tall = Rect::new(
            shown.x,
            shown.y - first * ROW,
            shown.w,
            need.max(shown.h + first * ROW),
        );
        (shown, tall)
    }

    /// Moves the properties section by `by` rows (negative: up).
    pub(in crate::internals::editor) fn scroll_props(&mut self, by: i32) {
        let (now, hidden) = (self.prop_section(), self.props_hidden());
        self.side.scroll_props(now, hidden, by);
    }

    /// Scrolls the properties until a widget `wanted` shows (as a user
    /// would with the wheel) and returns it; `None` if no scroll shows one.
    pub fn reveal_widget(&mut self, wanted: impl Fn(&Widget) -> bool) -> Option<Widget> {
        if let Some(w) = self.widgets().into_iter().find(&wanted) {
            return Some(w);
        }
        let now = self.prop_section();
        let before = self.side.props_first(now, self.props_hidden());
        for first in 0..=self.props_hidden() {
            self.side.set_props_first(now, first);
            if let Some(w) = self.widgets().into_iter().find(&wanted) {
                return Some(w);
            }
        }
        self.side.set_props_first(now, before);
        None
    }

    /// The side panel's scrolling sections as (body, first row shown,
    /// rows shown, rows in all), for their scroll bars.
    pub(in crate::internals::editor) fn side_scrolls(&self) -> [(Rect, usize, usize, usize); 3] {
        let sp = self.side_panel();
        let counts = [
            ops::objects(&self.scene).len(),
            ops::lights(&self.scene).len(),
        ];
        let list = |i: usize, r: Rect| {
            let cap = Self::list_capacity(r);
            let first = self.side.lists[i].min(counts[i].saturating_sub(cap));
            let (_, body) = r.take_top(ROW);
            (body, first, cap, counts[i])
        };
        let (props, _) = self.props_view();
        let (_, body) = props.take_top(ROW);
        let hidden = self.props_hidden();
        let first = self.side.props_first(self.prop_section(), hidden);
        let shown = sp.prop_rows_shown() as usize;
        [
            list(0, sp.objects),
            list(1, sp.lights),
            (body, first, shown, shown + hidden),
        ]
    }

    /// Visible rows of a list section.
    pub(in crate::internals::editor) fn list_capacity(r: Rect) -> usize {
        ((r.h - ROW).max(0) / ROW) as usize
    }

    /// All widgets of the main window (not the modal ones).
    pub fn widgets(&self) -> Vec<Widget> {
        let l = self.layout();
        let mut out = Vec::new();
        self.toolbar_widgets(l.toolbar, &mut out);
        let sp = self.side_panel();
        self.scene_widgets(sp.scene, &mut out);
        self.list_widgets(sp.objects, List::Objects, &mut out);
        self.list_widgets(sp.lights, List::Lights, &mut out);
        self.props_widgets(&mut out);
        self.controls_widgets(l.controls, &mut out);
        out
    }

    pub(in crate::internals::editor) fn toolbar_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        let style = match self.view_style {
            None => "Own",
            Some(s) => style_name(s),
        };
        let style_label = format!("Style:{style}");
        use crate::editor::manip::Tool;
        let tool = self.tool();
        let items: [(&str, Action, bool); 14] = [
            ("New", Action::New, false),
            ("Open", Action::Open, false),
            ("Imp", Action::Import, false),
            ("Save", Action::Save, false),
            ("Add", Action::AddMenu, self.add_menu_open()),
            (
                "Mov",
                Action::Tool(Tool::Translate),
                tool == Tool::Translate,
            ),
            ("Rot", Action::Tool(Tool::Rotate), tool == Tool::Rotate),
            ("Scl", Action::Tool(Tool::Scale), tool == Tool::Scale),
            ("Rec", Action::Record, self.record),
            (
                if self.playback.is_some() {
                    "Stop"
                } else {
                    "Play"
                },
                Action::Play,
                self.playback.is_some(),
            ),
            ("Grid", Action::Grid, self.show_grid),
            ("Onion", Action::Onion, self.onion_shown()),
            ("Graph", Action::ToggleGraph, self.graph_open()),
            (&style_label, Action::ViewStyle, false),
        ];
        let mut x = r.x + 2;
        for (label, action, on) in items {
            let bw = text::width(label) + 4;
            if x + bw > r.right() - 2 {
                break;
            }
            out.push(button(
                Rect::new(x, r.y + 2, bw, r.h - 4),
                label,
                action,
                on,
            ));
            x += bw + 1;
        }
    }

    pub(in crate::internals::editor) fn scene_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        let (h, rest) = r.take_top(ROW);
        out.push(w(h, WidgetKind::Header("Scene".into())));
        self.clip_widgets(h, out);
        let row = Rect::new(rest.x + 2, rest.y + 1, rest.w - 4, ROW);
        let half = row.w / 2;
        let (a, b) = row.take_left(half);
        field_row(out, a, "fps", 4 * CHAR_W, &[FieldId::Fps]);
        field_row(
            out,
            Rect::new(b.x + 2, b.y, b.w - 2, b.h),
            "len",
            4 * CHAR_W,
            &[FieldId::Duration],
        );
    }

    pub(in crate::internals::editor) fn list_widgets(
        &self,
        r: Rect,
        list: List,
        out: &mut Vec<Widget>,
    ) {
        let (h, body) = r.take_top(ROW);
        let rows: Vec<(NodeId, usize)> = match list {
            List::Objects => ops::objects(&self.scene),
            List::Lights => ops::lights(&self.scene)
                .into_iter()
                .map(|id| (id, 0))
                .collect(),
        };
        let title = match list {
            List::Objects => format!("Objects ({})", rows.len()),
            List::Lights => "Lights".to_string(),
        };
        out.push(w(h, WidgetKind::Header(title)));
        if list == List::Lights {
            // Add-light buttons at the right of the header; one-letter
            // labels when the panel is narrow.
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
            for (label, which) in items {
                let bw = text::width(label) + 4;
                x -= bw;
                out.push(button(
                    Rect::new(x, h.y + 1, bw, h.h - 2),
                    label,
                    Action::AddLight(which),
                    false,
                ));
                x -= 1;
            }
        }
        let cap = Self::list_capacity(r);
        let idx = if list == List::Objects { 0 } else { 1 };
        let first = self.side.lists[idx].min(rows.len().saturating_sub(cap));
        for (i, (id, depth)) in rows.iter().skip(first).take(cap).enumerate() {
            let rr = Rect::new(body.x, body.y + i as i32 * ROW, body.w, ROW);
            if list == List::Lights {
                let (main, chk) = rr.take_left(rr.w - ROW - 2);
                out.push(w(
                    main,
                    WidgetKind::Row {
                        node: *id,
                        depth: *depth,
                        list,
                    },
                ));
                let on = self.scene.node(*id).light().is_some_and(|l| l.on);
                out.push(w(
                    chk,
                    WidgetKind::Check {
                        action: Action::ToggleLight(*id),
                        on,
                    },
                ));
            } else {
                out.push(w(
                    rr,
                    WidgetKind::Row {
                        node: *id,
                        depth: *depth,
                        list,
                    },
                ));
            }
        }
        if rows.is_empty() && body.h >= ROW {
            out.push(label(
                Rect::new(body.x + 4, body.y, body.w - 4, ROW),
                "(none)",
                true,
            ));
        }
    }

    /// The properties section's widgets that show: its header row stays,
    /// its body rows scroll.
    fn props_widgets(&self, out: &mut Vec<Widget>) {
        let (shown, tall) = self.props_view();
        let mut all = Vec::new();
        self.prop_widgets(tall, &mut all);
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

    pub(in crate::internals::editor) fn prop_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        if self.material_panel().is_some() {
            self.material_widgets(r, out);
            return;
        }
        if self.key_panel_shown() {
            self.key_panel_widgets(r, out);
            return;
        }
        let (h, body) = r.take_top(ROW);
        let body = Rect::new(body.x + 2, body.y + 1, body.w - 4, body.h - 1);
        let Some(sel) = self.selection else {
            out.push(w(h, WidgetKind::Header("Properties".into())));
            out.push(label(
                Rect::new(body.x + 2, body.y, body.w, ROW),
                "Nothing selected",
                true,
            ));
            return;
        };
        let node = self.scene.node(sel);
        let kind = match &node.kind {
            NodeKind::Light(l) => ops::light_kind_name(l),
            NodeKind::Shape(_) => "Shape",
            NodeKind::Camera(_) => "Camera",
            NodeKind::Group => "Object",
        };
        out.push(w(h, WidgetKind::Header(kind.to_string())));
        let lw = 5 * CHAR_W;
        let mut y = body.y;
        let mut row = |out: &mut Vec<Widget>, f: &dyn Fn(&mut Vec<Widget>, Rect)| {
            if y + ROW <= body.bottom() + 1 {
                f(out, Rect::new(body.x, y, body.w, ROW));
            }
            y += ROW;
        };
        row(out, &|o, r| field_row(o, r, "Name", lw, &[FieldId::Name]));
        match &node.kind {
            NodeKind::Light(l) => {
                let on = l.on;
                row(out, &|o, r| {
                    let (a, b) = r.take_left(lw);
                    o.push(label(a, "On", true));
                    o.push(w(
                        Rect::new(b.x, b.y, ROW, b.h),
                        WidgetKind::Check {
                            action: Action::ToggleLight(sel),
                            on,
                        },
                    ));
                    let rest = Rect::new(b.x + ROW + 4, b.y, b.w - ROW - 4, b.h);
                    field_row(o, rest, "Int", lw, &[FieldId::LightIntensity]);
                });
                row(out, &|o, r| {
                    field_row(o, r, "Col", lw, &[0, 1, 2].map(FieldId::LightColor))
                });
                if !matches!(l.kind, LightKind::Directional) {
                    row(out, &|o, r| {
                        field_row(o, r, "Loc", lw, &[0, 1, 2].map(FieldId::LightLocation))
                    });
                }
                if !matches!(l.kind, LightKind::Point) {
                    row(out, &|o, r| {
                        field_row(o, r, "Dir", lw, &[0, 1, 2].map(FieldId::LightDirection))
                    });
                }
                if matches!(l.kind, LightKind::Spot { .. }) {
                    row(out, &|o, r| {
                        let (a, _) = r.take_left(r.w / 2);
                        field_row(o, a, "Cut", lw, &[FieldId::LightCutOff])
                    });
                }
                row(out, &|o, r| {
                    let bw = text::width("Delete") + 8;
                    o.push(button(
                        Rect::new(r.right() - bw, r.y + 1, bw, r.h - 2),
                        "Delete",
                        Action::Delete,
                        false,
                    ));
                });
            }
            _ => {
                row(out, &|o, r| {
                    field_row(o, r, "T", lw, &[0, 1, 2].map(FieldId::Translation))
                });
                row(out, &|o, r| {
                    field_row(o, r, "R", lw, &[0, 1, 2].map(FieldId::Rotation))
                });
                row(out, &|o, r| {
                    field_row(o, r, "S", lw, &[0, 1, 2].map(FieldId::Scale))
                });
                let style = style_name(node.style);
                row(out, &|o, r| {
                    let (a, b) = r.take_left(lw);
                    o.push(label(a, "Draw", true));
                    let bw = text::width("Hidden") + 8;
                    o.push(button(
                        Rect::new(b.x, b.y + 1, bw, b.h - 2),
                        style,
                        Action::ObjectStyle,
                        false,
                    ));
                    let dw = text::width("Delete") + 8;
                    o.push(button(
                        Rect::new(r.right() - dw, r.y + 1, dw, r.h - 2),
                        "Delete",
                        Action::Delete,
                        false,
                    ));
                });
            }
        }
        for i in 0..self.morph_rows() {
            row(out, &|o, r| self.morph_row(i as u8, r, o));
        }
        for i in 0..self.key_list_lines().len() {
            row(out, &|o, r| self.key_list_row(i, r, o));
        }
        self.key_panel_switch(h, out);
        self.material_switch(h, out);
    }

    pub(in crate::internals::editor) fn controls_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        let y = r.y + 1;
        let h = CONTROLS_H - 2;
        let mut x = r.x + 4;
        out.push(label(Rect::new(x, y, 6 * CHAR_W, h), "Frame", true));
        x += 6 * CHAR_W;
        let fw = 6 * CHAR_W;
        out.push(w(Rect::new(x, y, fw, h), WidgetKind::Field(FieldId::Frame)));
        x += fw + 4;
        let total = format!("/{}", self.scene.settings.duration);
        let tw = text::width(&total);
        out.push(label(Rect::new(x, y, tw, h), &total, true));
        x += tw + 8;
        x = self.preview_widgets(x, y, h, out);
        let mode = match self.mode {
            Mode::Select => "Select",
            Mode::View => "View",
        };
        let mw = text::width("Select") + 8;
        if x + mw < r.right() {
            out.push(button(Rect::new(x, y, mw, h), mode, Action::Mode, false));
            x += mw + 8;
        }
        if x < r.right() - 4 {
            out.push(label(
                Rect::new(x, y, r.right() - 4 - x, h),
                &self.status.text,
                false,
            ));
        }
    }

    /// Where a menu opened by the button for `action` goes: under the
    /// button (its bottom-left corner), if the button is shown.
    pub(in crate::internals::editor) fn under_button(&self, action: Action) -> Option<(i32, i32)> {
        self.widgets().into_iter().find_map(|w| match w.kind {
            WidgetKind::Button { action: a, .. } if a == action => {
                Some((w.rect.x, w.rect.bottom()))
            }
            _ => None,
        })
    }

    /// The file browser's box.
    pub fn browser_rect(&self) -> Rect {
        let win = self.layout().window;
        let bw = (win.w - 40).clamp(100, 560);
        let bh = (win.h - 40).clamp(80, 420);
        Rect::new((win.w - bw) / 2, (win.h - bh) / 2, bw, bh)
    }

    /// Widgets of the file browser (it lays them out, `browser_ui.rs`).
    pub fn browser_widgets(&self, b: &Browser) -> Vec<Widget> {
        b.widgets(self.browser_rect())
    }

    /// The topmost widget under (x, y), considering modal boxes first.
    pub fn widget_at(&self, x: f32, y: f32) -> Option<Widget> {
        let list = if let Some(d) = &self.dialog {
            d.widgets(self.layout().window)
        } else if let Some(b) = &self.browser {
            self.browser_widgets(b)
        } else {
            self.widgets()
        };
        list.into_iter().rev().find(|w| {
            w.rect.contains(x, y)
                && !matches!(w.kind, WidgetKind::Label { .. } | WidgetKind::Header(_))
        })
    }
}
