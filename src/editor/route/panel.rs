//! The editor's side of `panel`: the main window's widgets (toolbar, the
//! scene section, the properties' faces the side panel places, the bottom
//! bar) and finding the widget under the mouse.

use crate::editor::browser::Browser;
use crate::editor::fields::FieldId;
use crate::editor::ops;
#[allow(unused_imports)]
use crate::editor::panel::*;
use crate::editor::{Editor, Mode};
use crate::scene::{LightKind, NodeKind};
use crate::ui::layout::{CONTROLS_H, ROW};
use crate::ui::text::{self, CHAR_W};
use crate::ui::Rect;

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

impl Editor {
    /// Property rows the selection needs (for the side panel split).
    pub(in crate::internals::editor) fn prop_rows(&self) -> i32 {
        match self.selection.map(|s| &self.scene.node(s).kind) {
            // As many lines of how to start as show (they never scroll).
            None => (NOTHING_SELECTED.len() as i32).min(self.side_panel().prop_rows_shown().max(1)),
            Some(NodeKind::Light(l)) => match l.kind {
                LightKind::Directional => 5,
                LightKind::Point => 5,
                LightKind::Spot { .. } => 7,
            },
            Some(_) => 5 + self.morph_rows() as i32,
        }
    }

    /// All widgets of the main window (not the modal ones).
    pub fn widgets(&self) -> Vec<Widget> {
        let l = self.layout();
        let mut out = Vec::new();
        self.toolbar_widgets(l.toolbar, &mut out);
        self.scene_widgets(self.side_panel().scene, &mut out);
        self.side_widgets(&mut out);
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
        let mut row = if r.h >= 2 * ROW {
            let (h, rest) = r.take_top(ROW);
            out.push(w(h, WidgetKind::Header("Scene".into())));
            self.clip_widgets(h, out);
            Rect::new(rest.x + 2, rest.y + 1, rest.w - 4, ROW)
        } else {
            // A short panel (the graph editor open): one row, no title,
            // the clips behind their menu button.
            Rect::new(r.x + 2, r.y + 1, r.w - 4, ROW)
        };
        if r.h < 2 * ROW && !self.scene.clips.is_empty() {
            let bw = text::width("Clips") + 4;
            let menu = Rect::new(row.right() - bw, row.y + 1, bw, ROW - 2);
            let clips = crate::editor::rig::clip_action::ClipAction::Menu;
            out.push(button(menu, "Clips", Action::Clip(clips), false));
            row.w -= bw + 2;
        }
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
            let lines = NOTHING_SELECTED.iter().take(self.prop_rows() as usize);
            for (i, line) in lines.enumerate() {
                let y = body.y + i as i32 * ROW;
                out.push(label(Rect::new(body.x + 2, y, body.w, ROW), line, true));
            }
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
