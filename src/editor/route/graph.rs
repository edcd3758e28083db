//! The editor's side of the graph editor: where it sits (in the key
//! strip's place), the context it sees, routing events to it and applying
//! the intents it returns.

use crate::editor::gesture::Drag;
use crate::editor::graph::{Ctx, GraphEditor};
use crate::editor::Editor;
use crate::input::{Event, Key, Mods};
use crate::ui::{Layout, Painter};

impl Editor {
    /// The graph editor is shown (in the key strip's place).
    pub fn graph_open(&self) -> bool {
        self.graph_shown
    }

    /// The graph editor's state, while it is shown.
    pub fn graph(&self) -> Option<&GraphEditor> {
        self.graph.as_deref().filter(|_| self.graph_shown)
    }

    /// Shows or hides the graph editor (toolbar `Graph`, Shift+F6). Hidden,
    /// it keeps its view and channel switches.
    pub fn toggle_graph(&mut self) {
        self.graph_shown = !self.graph_shown;
        if self.graph.is_none() {
            let mut g = Box::<GraphEditor>::default();
            g.height = self.graph_height;
            self.graph = Some(g);
        }
        self.graph_follow();
    }

    /// What the graph sees: the animation, the selected object, the frame,
    /// its area and the selected keys.
    pub fn graph_ctx(&self) -> Ctx<'_> {
        Ctx {
            keyed: self.keyed(),
            rect: self.layout().key_rows,
            selected: &self.keys.selected,
        }
    }

    /// Frames a newly selected object's curves.
    pub(in crate::internals::editor) fn graph_follow(&mut self) {
        if !self.graph_shown {
            return;
        }
        if let Some(mut g) = self.graph.take() {
            g.follow(&self.graph_ctx());
            self.graph = Some(g);
        }
    }

    /// Offers `ev` to the graph: `Some(redraw)` when it took it.
    pub(in crate::internals::editor) fn graph_event(&mut self, ev: &Event) -> Option<bool> {
        if !self.graph_shown {
            return None;
        }
        let mut g = self.graph.take()?;
        let ctx = self.graph_ctx();
        // Keys go to the graph only while the mouse is over it.
        let over = ctx.rect.contains(self.mouse.0, self.mouse.1);
        let holding = matches!(self.drag, Drag::Graph);
        if matches!(ev, Event::KeyDown { .. }) && !over && !holding {
            self.graph = Some(g);
            return None;
        }
        g.follow(&ctx);
        let r = g.handle(ev, &ctx);
        // A drag the graph runs (inside it) is the editor's one gesture.
        match (g.is_dragging(), holding) {
            (true, false) => self.drag = Drag::Graph,
            (false, true) => self.drag = Drag::None,
            _ => {}
        }
        self.graph_height = g.height;
        self.graph = Some(g);
        self.apply_response(r)
    }

    /// Shift+F6 and the toolbar button.
    pub(in crate::internals::editor) fn graph_shortcut(&mut self, key: Key, m: Mods) -> bool {
        if key == Key::F(6) && m.shift && !m.ctrl {
            self.toggle_graph();
            return true;
        }
        false
    }

    pub(in crate::internals::editor) fn draw_graph(&self, p: &mut Painter, l: &Layout) {
        if l.key_rows.is_empty() {
            return;
        }
        if let Some(g) = self.graph() {
            g.draw(p, &self.graph_ctx());
        }
    }
}

impl Editor {
    /// Where a script aims: the pixel of the graph key of `channel`
    /// (`translation.y`, ...) of the selected object at `frame`, or with
    /// `handle` the end of its tangent handle (the key must be selected
    /// and TCB).
    pub fn graph_point(
        &mut self,
        channel: &str,
        frame: f32,
        handle: bool,
    ) -> Result<(f32, f32), String> {
        use crate::editor::graph::{channel::Channel, edit::CurveKey};
        let node = self
            .selection
            .ok_or("nothing selected: the graph shows the selection's curves")?;
        let ch = Channel::parse(node, channel).ok_or_else(|| {
            format!(
                "unknown channel '{channel}' (translation.x, rotation.z, color.g, intensity, ...)"
            )
        })?;
        self.graph_follow();
        let g = self
            .graph
            .as_deref()
            .ok_or("the graph editor is not open (Shift+F6)")?;
        let ctx = self.graph_ctx();
        let k = CurveKey { ch, frame };
        let p = if handle {
            g.handle_of(&ctx, k).map(|h| h.end).ok_or_else(|| {
                format!("no tangent handle on {channel} at frame {frame} (select a TCB key first)")
            })?
        } else {
            g.key_point(&ctx, k)
                .ok_or_else(|| format!("no key of {channel} at frame {frame} in the graph"))?
        };
        if !ctx.rect.contains(p.0, p.1) {
            return Err(format!(
                "{channel} at frame {frame} is outside the graph's view (Home frames all)"
            ));
        }
        Ok(p)
    }
}
