//! The editor's side of the side panel component (`side_ui.rs`): the
//! snapshot it sees, routing the wheel and presses on its rows to it
//! (`Drag::Side` while it holds a row drag), applying what it returns,
//! the lists' reveal of the selection, Tab between its fields, and
//! painting its scene section and node face. Its widgets join the
//! editor's for hit testing (`route/panel.rs` gathers the scene section
//! and the properties' faces the panel places).

use crate::editor::fields::FieldId;
use crate::editor::gesture::Drag;
use crate::editor::ops;
use crate::editor::panel::{Widget, WidgetKind};
use crate::editor::props_view::{Look, PropsView};
use crate::editor::side_ui::{LightRow, ObjectRow, Section, SectionKind, SideCtx};
use crate::editor::{Editor, TextEdit};
use crate::input::Event;
use crate::ui::{theme, Painter, Rect, SidePanel};

impl Editor {
    /// What the side panel sees: its area, the two lists' rows, what the
    /// properties show and how many rows that needs.
    pub(in crate::internals::editor) fn side_ctx(&self) -> SideCtx {
        let name = |id| ops::display_name(&self.scene, id);
        let lights = ops::lights(&self.scene).into_iter().map(|id| {
            let l = self.scene.node(id).light();
            LightRow {
                node: id,
                on: l.is_some_and(|l| l.on),
                name: name(id),
                color: l.map_or(0, |l| theme::rgb(l.color)),
            }
        });
        let objects = ops::objects(&self.scene).into_iter();
        let objects = objects.map(|(node, depth)| ObjectRow {
            node,
            depth,
            name: name(node),
        });
        SideCtx {
            area: self.layout().side,
            objects: objects.collect(),
            lights: lights.collect(),
            selection: self.selection,
            section: self.prop_section(),
            section_rows: self.section_rows(),
        }
    }

    /// How the side panel's parts look now: hover (none during a
    /// gesture) and the field being typed into.
    pub(in crate::internals::editor) fn side_look(&self) -> Look {
        Look {
            mouse: matches!(self.drag, Drag::None).then_some(self.mouse),
            editing: self.edit.as_ref().map(|e| (e.field, e.text.clone())),
        }
    }

    /// The side panel's sections: fixed by the window's height alone.
    pub fn side_panel(&self) -> SidePanel {
        SidePanel::new(self.layout().side)
    }

    /// Scrolls the objects and lights lists so the selection's row shows.
    pub(in crate::internals::editor) fn reveal_selection(&mut self) {
        let Some(sel) = self.selection else { return };
        let ctx = self.side_ctx();
        self.side.reveal(&ctx, sel);
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

    /// The properties section shown and the taller rect its rows are laid
    /// out in (see `Side::props_view`).
    pub(in crate::internals::editor) fn props_view(&self) -> (Rect, Rect) {
        let v = self.side.props_view(&self.side_ctx());
        (v.shown, v.tall)
    }

    /// Hands `ev` to the side panel (the wheel, a press on a list row,
    /// the mouse and Esc while it holds a row drag) and applies its
    /// answer: `Some(redraw)` when it was the panel's.
    pub(in crate::internals::editor) fn side_event(&mut self, ev: &Event) -> Option<bool> {
        let ctx = self.side_ctx();
        let r = self.side.handle(ev, &ctx);
        let held = self.side.pressed();
        match (&self.drag, held) {
            (Drag::None, true) => self.drag = Drag::Side,
            (Drag::Side, false) => self.drag = Drag::None,
            _ => {}
        }
        self.apply_response(r)
    }

    /// The side panel's lists and the properties' widgets that show.
    pub(in crate::internals::editor) fn side_widgets(&self, out: &mut Vec<Widget>) {
        let ctx = self.side_ctx();
        self.side.list_widgets(&ctx, out);
        let tall = self.side.props_view(&ctx).tall;
        let mut all = Vec::new();
        self.prop_widgets(tall, &mut all);
        self.side.place_props(&ctx, all, out);
    }

    /// The scene section and, when the properties show it, the node face
    /// paint themselves; the widgets they painted, for the editor to
    /// leave out.
    pub(in crate::internals::editor) fn draw_side_sections(&self, p: &mut Painter) -> Vec<Widget> {
        let node_shown = self.prop_section().kind == SectionKind::Node;
        let (shown, tall) = self.props_view();
        let view = PropsView { shown, tall };
        let ctxs = (&self.scene_ctx(), &self.node_ctx());
        let look = self.side_look();
        self.side
            .draw_sections(p, ctxs, node_shown.then_some(&view), &look)
    }

    /// The side panel paints its lists, scroll bars and row drag.
    pub(in crate::internals::editor) fn draw_side(&self, p: &mut Painter) {
        self.side.draw(p, &self.side_ctx(), &self.side_look());
    }

    /// Tab while typing: records the field (if anything was typed) and
    /// types into the next field of the side panel (Shift: the one before), scrolling the
    /// properties so it shows. A field outside the side panel (the frame,
    /// the preview range) only records, as Enter does.
    pub(in crate::internals::editor) fn tab_field(&mut self, back: bool) {
        let Some((from, fresh)) = self.edit.as_ref().map(|e| (e.field, e.fresh)) else {
            return;
        };
        if fresh {
            // Nothing typed: nothing to record (no undo step, no change
            // left pending on an animated property).
            self.edit = None;
        } else {
            self.commit_edit();
        }
        let order = self.side_fields();
        let Some(i) = order.iter().position(|&f| f == from) else {
            return;
        };
        let n = order.len();
        let next = order[if back { (i + n - 1) % n } else { (i + 1) % n }];
        let shown = self.reveal_widget(|w| w.kind == WidgetKind::Field(next));
        if let (Some(_), Some(text)) = (shown, self.field_start_text(next)) {
            self.edit = Some(TextEdit {
                field: next,
                text,
                fresh: true,
            });
        }
    }

    /// The side panel's fields in Tab order: the scene section's, then
    /// every row of the properties, shown or scrolled away.
    fn side_fields(&self) -> Vec<FieldId> {
        let ctx = self.side_ctx();
        let mut all = Vec::new();
        self.scene_widgets(&mut all);
        self.prop_widgets(self.side.props_view(&ctx).tall, &mut all);
        let field = |w: Widget| match w.kind {
            WidgetKind::Field(id) => Some(id),
            _ => None,
        };
        all.into_iter().filter_map(field).collect()
    }

    /// The text typing into field `id` starts from: its value now.
    fn field_start_text(&self, id: FieldId) -> Option<String> {
        // Every field of the side panel is a face's (`side_faces.rs`).
        self.face_start_text(id)
    }

    /// Scrolls the properties until a widget `wanted` shows (as a user
    /// would with the wheel) and returns it; `None` if no scroll shows one.
    pub fn reveal_widget(&mut self, wanted: impl Fn(&Widget) -> bool) -> Option<Widget> {
        if let Some(w) = self.widgets().into_iter().find(&wanted) {
            return Some(w);
        }
        let ctx = self.side_ctx();
        let (now, hidden) = (ctx.section, ctx.props_hidden());
        let before = self.side.props_first(now, hidden);
        for first in 0..=hidden {
            self.side.set_props_first(now, first);
            if let Some(w) = self.widgets().into_iter().find(&wanted) {
                return Some(w);
            }
        }
        self.side.set_props_first(now, before);
        None
    }
}
