//! What a clip button or menu item does (pure data, no `Editor`): panel
//! widgets carry it (`panel.rs`), so it lives apart from the clip list's
//! `Editor` methods in `clips.rs`, which would otherwise close an import
//! circle editor → menu → panel → clips → editor.

/// What a clip button or menu item does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClipAction {
    /// Play clip i (0-based).
    Play(usize),
    /// The next (+1) or previous (-1) clip.
    Step(i32),
    New,
    Duplicate,
    /// Start typing the playing clip's new name.
    Rename,
    Delete,
    /// Open the clip menu under the Scene header's button.
    Menu,
}
