//! How the side panel's parts look right now: where the properties'
//! rows go when they are scrolled ([`PropsView`]) and what a part needs
//! to paint its own widgets alike ([`Look`]: hover, the field being
//! typed into). The side panel (`side_ui.rs`) and its faces (the key
//! panel, `keypanel.rs`) share it, so each draws itself and all of them
//! scroll, light up and show typing the same way.

use super::fields::FieldId;
use super::panel::{Widget, WidgetKind};
use super::widget_paint;
use crate::ui::layout::ROW;
use crate::ui::{widgets, Painter, Rect};

/// The properties section as shown (`shown`) and the taller rect its
/// rows are laid out in, moved up by the rows scrolled away (`tall`):
/// laying out every row and keeping those inside `shown` scrolls the
/// three faces (node, key panel, material) alike.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PropsView {
    pub shown: Rect,
    pub tall: Rect,
}

impl PropsView {
    /// The widgets of `all` (laid out in `tall`) that show: the header
    /// row stays, body rows scroll and those outside `shown` go.
    pub fn place(&self, all: Vec<Widget>, out: &mut Vec<Widget>) {
        let (shown, tall) = (self.shown, self.tall);
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

    /// Paints the widgets of `all` that show (see [`PropsView::place`])
    /// as `look` says, fields with the text `text` gives: how a face of
    /// the properties draws its rows.
    pub fn paint(
        &self,
        p: &mut Painter,
        look: &Look,
        all: Vec<Widget>,
        text: impl Fn(FieldId, usize) -> String,
    ) {
        let mut shown = Vec::new();
        self.place(all, &mut shown);
        for w in &shown {
            look.paint(p, w, &text);
        }
    }
}

/// What a part of the side panel needs to paint its widgets as the
/// editor would: the mouse (`None` while a gesture runs, so nothing
/// lights up under a drag) and the field being typed into with its text.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Look {
    pub mouse: Option<(f32, f32)>,
    pub editing: Option<(FieldId, String)>,
}

impl Look {
    /// Whether the mouse is over `r`.
    pub fn hot(&self, r: Rect) -> bool {
        self.mouse.is_some_and(|(x, y)| r.contains(x, y))
    }

    /// Paints `w`: plain kinds by `widget_paint`, a field with the typed
    /// text or the one `text` gives for `max_chars` characters. Other
    /// kinds are the caller's (`false`).
    pub fn paint(
        &self,
        p: &mut Painter,
        w: &Widget,
        text: impl Fn(FieldId, usize) -> String,
    ) -> bool {
        if widget_paint::plain(p, w, self.mouse).is_some() {
            return true;
        }
        let WidgetKind::Field(id) = w.kind else {
            return false;
        };
        let typed = self.editing.as_ref().filter(|(f, _)| *f == id);
        let shown = match typed {
            Some((_, t)) => t.clone(),
            None => text(id, crate::ui::text::fit_chars(w.rect.w - 5)),
        };
        widgets::field(p, w.rect, &shown, self.hot(w.rect), typed.is_some());
        true
    }
}
