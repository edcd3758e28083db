//! Tooltips over the key strip, which has no widgets: what a key marker,
//! a row name or empty strip space does with the mouse. The hover timer
//! (`tooltip.rs`) takes them as a dim label kind, which is never a
//! hovered widget otherwise (labels are not hit), so its text is shown.

use crate::editor::keystrip::{row_name, Hit, Row};
use crate::editor::panel::WidgetKind;
use crate::editor::Editor;

impl Editor {
    /// The key strip's tooltip under (x, y), if the strip is there.
    pub(in crate::internals::editor) fn strip_tip(&self, x: f32, y: f32) -> Option<WidgetKind> {
        if self.graph_open() {
            return None;
        }
        let text = match self.key_strip_hit(x, y)? {
            Hit::Keys(ks) => {
                let k = ks.first()?;
                let f = crate::editor::fields::format_number(k.frame);
                match ks.len() {
                    1 => format!(
                        "{} key, frame {f}: drag moves; right-click: menu",
                        row_name(k.property)
                    ),
                    n => format!("{n} keys, frame {f}: drag moves all; right-click: menu"),
                }
            }
            Hit::Name(Row::Summary) => {
                "Click selects every key; the triangle folds the rows".into()
            }
            Hit::Name(Row::Track(p)) => format!("Click selects every {} key", row_name(p)),
            Hit::Name(Row::More(n)) => format!("{n} more rows: the wheel scrolls"),
            Hit::Empty => "Drag: box select; wheel zooms; right-click: menu".into(),
        };
        Some(WidgetKind::Label { text, dim: true })
    }
}
