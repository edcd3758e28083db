//! The editor's widgets for the current state and window size: what is
//! where, what it shows and what clicking it does. Built fresh for each
//! draw and each click, so drawing and hit testing always agree.

use super::fields::FieldId;
use super::ops::NewLight;
use crate::scene::{NodeId, RenderStyle};
use crate::ui::Rect;

/// What pressing a button does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    New,
    Open,
    Import,
    Save,
    SaveAs,
    Record,
    Play,
    Grid,
    ViewStyle,
    Mode,
    /// Pick the handles' tool (W / E / T).
    Tool(super::manip::Tool),
    /// Onion skin on or off (O).
    Onion,
    /// The graph editor in the key strip's place (Shift+F6).
    ToggleGraph,
    Undo,
    Redo,
    AddLight(NewLight),
    /// Add a new object (the Add menu's items).
    Add(super::create::NewThing),
    /// Open the Add menu (toolbar `Add`, Shift+A).
    AddMenu,
    /// Copy the selection with its tracks (Shift+D).
    Duplicate,
    /// The Add menu at the mouse (the viewport's context menu).
    AddMenuHere,
    /// The View menu at the mouse.
    ViewMenu,
    /// A view command (numpad keys, the View menu).
    View(super::views::ViewCmd),
    /// Key the selection (K).
    KeySelection,
    /// Remove every key of the selection (Alt+I, as in Blender).
    ClearKeys,
    ToggleLight(NodeId),
    ObjectStyle,
    Delete,
    /// Start typing the selection's name (the lists' context menu).
    Rename,
    DialogSave,
    DialogDiscard,
    DialogCancel,
    BrowserAccept,
    BrowserCancel,
    BrowserUp,
    /// Key panel buttons (`keyprops.rs`).
    Key(super::keyprops::KeyAction),
    /// Clip buttons and menu items (`rig/clips.rs`).
    Clip(super::rig::clip_action::ClipAction),
    /// Type the preview range's frames (F3; `route/timeline.rs`).
    TypePreview,
    /// Material panel buttons (`material/`).
    Material(super::material::MatAction),
}

/// Which list a row belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum List {
    Objects,
    Lights,
}

#[derive(Clone, Debug, PartialEq)]
pub enum WidgetKind {
    Button {
        label: String,
        action: Action,
        on: bool,
    },
    Check {
        action: Action,
        on: bool,
    },
    Field(FieldId),
    Label {
        text: String,
        dim: bool,
    },
    Header(String),
    Row {
        node: NodeId,
        depth: usize,
        list: List,
    },
    /// A file browser entry (index into its listing).
    Entry(usize),
    /// The file browser's typed path.
    PathInput,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Widget {
    pub rect: Rect,
    pub kind: WidgetKind,
}

pub(super) fn w(rect: Rect, kind: WidgetKind) -> Widget {
    Widget { rect, kind }
}

pub(super) fn button(rect: Rect, label: &str, action: Action, on: bool) -> Widget {
    w(
        rect,
        WidgetKind::Button {
            label: label.into(),
            action,
            on,
        },
    )
}

pub(super) fn label(rect: Rect, text: &str, dim: bool) -> Widget {
    w(
        rect,
        WidgetKind::Label {
            text: text.into(),
            dim,
        },
    )
}

/// Lays out `n` equal fields after a label of `label_w` pixels.
pub(super) fn field_row(out: &mut Vec<Widget>, r: Rect, name: &str, label_w: i32, ids: &[FieldId]) {
    let (l, rest) = r.take_left(label_w);
    out.push(label(l.inset(0), name, true));
    let n = ids.len() as i32;
    let fw = (rest.w - (n - 1)) / n;
    for (i, id) in ids.iter().enumerate() {
        let x = rest.x + i as i32 * (fw + 1);
        out.push(w(
            Rect::new(x, r.y + 1, fw, r.h - 2),
            WidgetKind::Field(*id),
        ));
    }
}

pub(super) fn style_name(s: RenderStyle) -> &'static str {
    match s {
        RenderStyle::Filled => "Full",
        RenderStyle::Lines => "Lines",
        RenderStyle::Points => "Points",
        RenderStyle::Hidden => "Hidden",
    }
}
