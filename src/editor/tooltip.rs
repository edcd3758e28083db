//! Tooltips: after the mouse rests on a toolbar button or a field for
//! [`DELAY_S`], a line saying what it does and its shortcut, so labels
//! like `Imp`, `Scl` or `Style:Own` explain themselves. The timer runs on
//! the editor's ticks (no clock of its own), so tests drive it with
//! `Tick` events.

use super::fields::FieldId;
use super::keyprops::KeyAction;
use super::manip::Tool;
use super::material::MatAction;
use super::panel::{Action, List, WidgetKind};

/// Seconds the mouse rests before the tooltip shows.
pub const DELAY_S: f64 = 0.5;

/// The hover timer.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Hover {
    /// The widget under the mouse and the tick time it was first seen at
    /// (`None` until the next tick after a move).
    widget: Option<WidgetKind>,
    since: Option<f64>,
    /// Whether the tooltip shows.
    pub shown: bool,
}

impl Hover {
    /// The mouse is now over `widget`: restarts the timer when it changed.
    /// `true` when a shown tooltip went away (redraw).
    pub fn moved(&mut self, widget: Option<WidgetKind>) -> bool {
        if widget == self.widget {
            return false;
        }
        let was = self.shown;
        *self = Hover {
            widget,
            since: None,
            shown: false,
        };
        was
    }

    /// A tick at `now` seconds: `true` when the tooltip just appeared.
    pub fn tick(&mut self, now: f64) -> bool {
        let Some(w) = &self.widget else { return false };
        let since = *self.since.get_or_insert(now);
        if !self.shown && now - since >= DELAY_S && text_for(w).is_some() {
            self.shown = true;
            return true;
        }
        false
    }

    /// Waiting to show a tooltip (the window loop keeps ticking).
    pub fn pending(&self) -> bool {
        !self.shown && self.widget.as_ref().and_then(text_for).is_some()
    }

    /// The shown tooltip's text.
    pub fn text(&self) -> Option<String> {
        self.widget
            .as_ref()
            .filter(|_| self.shown)
            .and_then(text_for)
    }
}

/// What a widget's tooltip says (`None`: no tooltip, e.g. headers).
pub fn text_for(kind: &WidgetKind) -> Option<String> {
    match kind {
        WidgetKind::Button { action, .. } | WidgetKind::Check { action, .. } => {
            action_text(action).map(str::to_string)
        }
        WidgetKind::Field(id) => Some(field_text(*id)),
        WidgetKind::Row { list, .. } => Some(
            match list {
                List::Objects => "Click selects; drag onto a row parents it; right-click: menu",
                List::Lights => "Click selects the light; right-click: rename, duplicate, delete",
            }
            .to_string(),
        ),
        // The key strip's tips (`strip_tips.rs`): labels are never hovered
        // widgets, so a label here is a tip's text.
        WidgetKind::Label { text, .. } => Some(text.clone()),
        _ => None,
    }
}

fn action_text(a: &Action) -> Option<&'static str> {
    Some(match a {
        Action::New => "New scene (Ctrl+N)",
        Action::Open => "Open a scene file (Ctrl+O)",
        Action::Import => "Import a model as a new object (Ctrl+I)",
        Action::Save => "Save (Ctrl+S; Ctrl+Shift+S saves as)",
        Action::AddMenu => "Add a shape, empty, camera or light (Shift+A)",
        Action::Tool(Tool::Translate) => "Move handles (W)",
        Action::Tool(Tool::Rotate) => "Rotate handles (E)",
        Action::Tool(Tool::Scale) => "Scale handles (T)",
        Action::Record => "Record mode: drags and typed values key the frame (R)",
        Action::Play => "Play / stop (Space)",
        Action::Grid => "Ground grid on/off (G)",
        Action::Onion => "Onion skin: the selection at its previous/next key (O)",
        Action::ToggleGraph => "Graph editor in the key strip's place (Shift+F6)",
        Action::ViewStyle => "Viewport style: Own = each object's; click cycles",
        Action::AddLight(_) => "Add a light of this kind, placed in view",
        Action::ToggleLight(_) => "Light on/off (L)",
        Action::ObjectStyle => "How this object is drawn (click cycles)",
        Action::Delete => "Delete the object (Delete)",
        Action::Key(KeyAction::Interp(_)) => "How the segment after the selected keys moves",
        Action::Key(KeyAction::Repeat(_)) => "After its keys the track holds or loops",
        Action::Key(KeyAction::ToggleBool) => "Flip the selected keys' on/off value",
        Action::Key(KeyAction::ShowNode) => "Show the object's properties",
        Action::Key(KeyAction::ShowKeys) => "Show the selected keys",
        Action::Material(MatAction::Open) => "Material: colours, shininess, texture (M)",
        Action::Material(MatAction::Close) => "Back to the object's properties (M)",
        Action::Material(MatAction::WrapS) => "Texture wrap across (S): repeat or clamp",
        Action::Material(MatAction::WrapT) => "Texture wrap up (T): repeat or clamp",
        Action::Material(MatAction::RemoveTexture) => "Take the texture off (Ctrl+Z undoes)",
        Action::Material(MatAction::LoadTexture) => {
            "Load an image file as the texture (replaces it; Ctrl+Z undoes)"
        }
        _ => return None,
    })
}

fn field_text(id: FieldId) -> String {
    match id {
        FieldId::Fps => "Frames per second (drag or type)".into(),
        FieldId::Duration => "Scene length in frames (2*24 works)".into(),
        FieldId::Frame => "Current frame: type one (Left/Right step)".into(),
        FieldId::Name => "Object name: click to type".into(),
        FieldId::Preview(_) => format!(
            "{}: type a frame; playback loops over the range",
            id.label()
        ),
        FieldId::Material(m) => format!("{}: 0..1, drag or type; K keys it", m.label()),
        other => format!("{}: drag to change, click to type", other.label()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn button(action: Action) -> Option<WidgetKind> {
        Some(WidgetKind::Button {
            label: String::new(),
            action,
            on: false,
        })
    }

    #[test]
    fn shows_after_the_delay_and_hides_on_a_move() {
        let mut h = Hover::default();
        h.moved(button(Action::Import));
        assert!(!h.tick(10.0));
        assert!(!h.tick(10.4));
        assert!(h.tick(10.5));
        assert!(h.text().unwrap().contains("Ctrl+I"));
        // Same widget: nothing changes.
        assert!(!h.moved(button(Action::Import)));
        assert!(h.shown);
        // Another widget: hidden (redraw), timer restarts.
        assert!(h.moved(button(Action::Grid)));
        assert_eq!(h.text(), None);
        assert!(!h.tick(11.0));
        assert!(h.tick(11.6));
        assert_eq!(h.text().unwrap(), "Ground grid on/off (G)");
        // Nothing under the mouse: nothing shows.
        h.moved(None);
        assert!(!h.tick(20.0) && !h.tick(30.0));
    }

    #[test]
    fn every_toolbar_action_and_field_has_a_line() {
        for a in [
            Action::New,
            Action::Open,
            Action::Import,
            Action::Save,
            Action::AddMenu,
            Action::Tool(Tool::Translate),
            Action::Tool(Tool::Rotate),
            Action::Tool(Tool::Scale),
            Action::Record,
            Action::Play,
            Action::Grid,
            Action::Onion,
            Action::ToggleGraph,
            Action::ViewStyle,
            Action::Material(MatAction::Open),
            Action::Material(MatAction::WrapS),
            Action::Material(MatAction::RemoveTexture),
        ] {
            let t = text_for(&button(a).unwrap()).unwrap_or_default();
            // Short enough for the smallest window (480 px, 7 px glyphs).
            assert!(!t.is_empty() && t.len() <= 60, "{a:?}: {t}");
        }
        assert!(text_for(&WidgetKind::Field(FieldId::Translation(1)))
            .unwrap()
            .starts_with("Translation y"));
    }
}
