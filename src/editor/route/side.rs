//! The editor's side of the side panel component (`side_ui.rs`): the
//! context it sees, routing the wheel to it, and the lists' reveal of the
//! selection. Its widgets join the editor's (`route/panel.rs` builds the
//! scene section and the properties' faces the panel places).

use crate::editor::ops;
use crate::editor::panel::Widget;
use crate::editor::side_ui::{Section, SectionKind, SideCtx};
use crate::editor::Editor;
use crate::input::Event;
use crate::ui::{Painter, Rect, SidePanel};

impl Editor {
    /// What the side panel sees: its area, the two lists' rows, what the
    /// properties show and how many rows that needs.
    pub(in crate::internals::editor) fn side_ctx(&self) -> SideCtx {
        let lights = ops::lights(&self.scene)
            .into_iter()
            .map(|id| (id, self.scene.node(id).light().is_some_and(|l| l.on)))
            .collect();
        SideCtx {
            area: self.layout().side,
            objects: ops::objects(&self.scene),
            lights,
            section: self.prop_section(),
            section_rows: self.section_rows(),
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
        self.side.props_view(&self.side_ctx())
    }

    /// The wheel over the side panel: `Some(redraw)` when it was the
    /// panel's.
    pub(in crate::internals::editor) fn side_event(&mut self, ev: &Event) -> Option<bool> {
        let ctx = self.side_ctx();
        let r = self.side.handle(ev, &ctx);
        r.consumed.then_some(r.redraw)
    }

    /// The side panel's lists and the properties' widgets that show.
    pub(in crate::internals::editor) fn side_widgets(&self, out: &mut Vec<Widget>) {
        let ctx = self.side_ctx();
        self.side.list_widgets(&ctx, out);
        let (_, tall) = self.side.props_view(&ctx);
        let mut all = Vec::new();
        self.prop_widgets(tall, &mut all);
        self.side.place_props(&ctx, all, out);
    }

    /// The side panel's scroll bars, over the widgets.
    pub(in crate::internals::editor) fn draw_side(&self, p: &mut Painter) {
        self.side.draw(p, &self.side_ctx());
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
