//! The editor's side of `panel`: the main window's widgets (toolbar, the
//! scene section, the properties' faces the side panel places, the bottom
//! bar), the snapshots the scene section and node face see, and finding
//! the widget under the mouse.

use crate::editor::browser::Browser;
use crate::editor::fields::FieldId;
use crate::editor::node_props::{NodeCtx, NodeProps};
#[allow(unused_imports)]
use crate::editor::panel::*;
use crate::editor::scene_section::{SceneCtx, SceneSection};
use crate::editor::{Editor, Mode};
use crate::ui::layout::CONTROLS_H;
use crate::ui::text::{self, CHAR_W};
use crate::ui::Rect;

impl Editor {
    /// Property rows the selection needs (for the side panel split).
    pub(in crate::internals::editor) fn prop_rows(&self) -> i32 {
        NodeProps::rows(&self.node_ctx())
    }

    /// What the properties' node face sees: the selection as posed now,
    /// its morph sliders and key frames.
    pub(in crate::internals::editor) fn node_ctx(&self) -> NodeCtx {
        NodeCtx {
            node: self.selection.map(|s| (s, self.posed_node(s))),
            morph_rows: self.morph_rows(),
            key_lines: self.key_list_lines(),
            rows_shown: self.side_panel().prop_rows_shown(),
        }
    }

    /// What the scene section sees: its place, the settings, the clips'
    /// row under its title.
    pub(in crate::internals::editor) fn scene_ctx(&self) -> SceneCtx {
        let area = self.side_panel().scene;
        let mut clip_row = Vec::new();
        if let Some(title) = SceneSection::title_row(area) {
            self.clip_widgets(title, &mut clip_row);
        }
        SceneCtx {
            area,
            settings: self.scene.settings.clone(),
            has_clips: !self.scene.clips.is_empty(),
            clip_row,
        }
    }

    /// All widgets of the main window (not the modal ones).
    pub fn widgets(&self) -> Vec<Widget> {
        let l = self.layout();
        let mut out = Vec::new();
        self.toolbar_widgets(l.toolbar, &mut out);
        self.scene_widgets(&mut out);
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

    /// The scene section's widgets (it lays them out, `scene_section.rs`).
    pub(in crate::internals::editor) fn scene_widgets(&self, out: &mut Vec<Widget>) {
        self.side.scene.widgets(&self.scene_ctx(), out);
    }

    /// The properties' widgets in `r`: the material or key panel, or the
    /// node face (`node_props.rs`) with the morph sliders in the room it
    /// leaves and the switches to the other faces on its header.
    pub(in crate::internals::editor) fn prop_widgets(&self, r: Rect, out: &mut Vec<Widget>) {
        if self.material_panel().is_some() {
            self.material_widgets(r, out);
            return;
        }
        if self.key_panel_shown() {
            self.key_panel_widgets(r, out);
            return;
        }
        let Some(room) = self.side.node.widgets(r, &self.node_ctx(), out) else {
            return;
        };
        for (i, row) in room.morph.into_iter().enumerate() {
            self.morph_row(i as u8, row, out);
        }
        self.key_panel_switch(room.header, out);
        self.material_switch(room.header, out);
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
