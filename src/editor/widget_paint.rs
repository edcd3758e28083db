//! Paints the widgets that need nothing from the editor to look right —
//! buttons, headers, labels, checkboxes — so components (the dialog, the
//! file browser) draw themselves without naming the `Editor`. `draw.rs`
//! keeps the ones that show editor state (fields, list rows, the status
//! line's error colour, the record button).

use super::panel::{Widget, WidgetKind};
use crate::ui::{theme, widgets, Painter};

/// Draws `w` lit when `mouse` is over it; `None` for the kinds this does
/// not know (the caller draws those).
pub fn plain(p: &mut Painter, w: &Widget, mouse: Option<(f32, f32)>) -> Option<()> {
    let hot = mouse.is_some_and(|(x, y)| w.rect.contains(x, y));
    match &w.kind {
        WidgetKind::Button { label, on, .. } => {
            widgets::button(p, w.rect, label, hot, *on, theme::BUTTON_ON)
        }
        WidgetKind::Check { on, .. } => widgets::checkbox(p, w.rect, *on, hot),
        WidgetKind::Header(t) => widgets::header(p, w.rect, t),
        WidgetKind::Label { text, dim } => {
            let color = if *dim { theme::TEXT_DIM } else { theme::TEXT };
            widgets::label(p, w.rect, text, color)
        }
        _ => return None,
    }
    Some(())
}
