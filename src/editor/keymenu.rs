//! The keys' context menu, one list for the key strip and the graph
//! editor so both offer the same edits: interpolation, ease in / out /
//! both / none, delete, copy, paste at the current frame, and selecting
//! every key of the row (strip) or channel (graph) under the mouse.

pub use super::keyedit::Ease;
use super::keyprops::KeyAction as K;
use super::menu::MenuItem;
use super::panel::Action;
use crate::anim::Interp;

/// What the menu is opened over.
pub struct Over {
    /// Keys are selected (the edits apply to them).
    pub keys: bool,
    /// The first selected key is a rotation (slerp/squad names).
    pub rotation: bool,
    /// Keys were copied: "Paste at frame N".
    pub paste_at: Option<f32>,
    /// The "select every key of …" item, when a row or channel is under
    /// the mouse: its label and action.
    pub select_all: Option<(&'static str, Action)>,
}

/// The menu's items (empty: nothing to offer, no menu).
pub fn items(o: &Over) -> Vec<MenuItem> {
    let mut items = Vec::new();
    if o.keys {
        for i in [Interp::Step, Interp::Linear, Interp::Tcb] {
            let label = format!("Interpolation: {}", i.name(o.rotation));
            items.push(MenuItem::new(&label, "", Action::Key(K::Interp(i))));
        }
        for e in [Ease::In, Ease::Out, Ease::Both, Ease::None] {
            items.push(MenuItem::new(e.label(), "", Action::Key(K::Ease(e))));
        }
        items.push(MenuItem::new(
            "Delete keys",
            "Delete",
            Action::Key(K::Delete),
        ));
        items.push(MenuItem::new("Copy keys", "Ctrl+C", Action::Key(K::Copy)));
    }
    if let Some(f) = o.paste_at {
        let label = format!("Paste at frame {f}");
        items.push(MenuItem::new(&label, "Ctrl+V", Action::Key(K::Paste)));
    }
    if let Some((label, a)) = o.select_all {
        items.push(MenuItem::new(label, "", a));
    }
    items
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_follow_what_is_under_the_mouse() {
        let none = Over {
            keys: false,
            rotation: false,
            paste_at: None,
            select_all: None,
        };
        assert!(items(&none).is_empty());
        let all = Over {
            keys: true,
            rotation: true,
            paste_at: Some(12.0),
            select_all: Some(("Select all on channel", Action::Key(K::SelectChannel))),
        };
        let labels: Vec<String> = items(&all).into_iter().map(|i| i.label).collect();
        assert_eq!(
            labels,
            [
                "Interpolation: step",
                "Interpolation: slerp",
                "Interpolation: squad",
                "Ease in",
                "Ease out",
                "Ease in and out",
                "No ease",
                "Delete keys",
                "Copy keys",
                "Paste at frame 12",
                "Select all on channel",
            ]
        );
    }
}
