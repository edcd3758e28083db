//! The editor window's split into areas: its size, whether the graph
//! editor takes the key strip's place, and the heights the user dragged
//! (the graph's split with the viewport, the key strip's top edge). The
//! window's [`Layout`] is derived from it. It is the editor's, not any one
//! component's: a component taken out of the editor while it handles an
//! event is still laid out from it.

use crate::ui::layout::default_strip_h;
use crate::ui::Layout;

/// How the window is split.
#[derive(Clone, Debug)]
pub struct Split {
    pub width: u32,
    pub height: u32,
    /// The graph editor is shown, in the key strip's place.
    pub graph: bool,
    /// The graph editor's height (the split with the viewport).
    pub graph_h: i32,
    /// The key strip's height once the user dragged the timeline's top
    /// edge (`None`: `ui::layout::default_strip_h`). Never follows the
    /// selection, so selecting does not move the panels.
    pub strip_h: Option<i32>,
}

impl Split {
    /// A `width` × `height` window (at least 1 × 1) with the key strip.
    pub fn new(width: u32, height: u32) -> Split {
        Split {
            width: width.max(1),
            height: height.max(1),
            graph: false,
            graph_h: 140,
            strip_h: None,
        }
    }

    /// The window's layout.
    pub fn layout(&self) -> Layout {
        let (w, h) = (self.width as i32, self.height as i32);
        match self.graph {
            true => Layout::with_graph(w, h, self.graph_h),
            false => Layout::with_strip(w, h, self.strip_h.unwrap_or(default_strip_h(h))),
        }
    }

    /// The window was resized (at least 1 × 1): whether its size changed.
    pub fn resize(&mut self, width: u32, height: u32) -> bool {
        let new = (width.max(1), height.max(1));
        let changed = new != (self.width, self.height);
        (self.width, self.height) = new;
        changed
    }

    /// The timeline's top edge dragged to make the key strip `want` pixels
    /// high, kept to what the layout allows (so the edge follows the mouse).
    pub fn drag_strip(&mut self, want: i32) {
        let (w, h) = (self.width as i32, self.height as i32);
        self.strip_h = Some(Layout::with_strip(w, h, want).key_rows.h);
    }
}
