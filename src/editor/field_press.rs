//! A press on a panel field, the gesture every face of the side panel
//! shares (key panel, material rows, morph sliders, the clip name, node
//! rows): a click without a drag starts typing into the field, a drag
//! past the slop changes its value from what it was at the press. The
//! face that took the press keeps it (and what the value started from);
//! the editor's one gesture only says the side panel holds the mouse.

use super::component::Response;
use super::fields::{FieldId, FieldValue};

/// Pixels the mouse may move before a press counts as a drag (every
/// press the editor knows: fields, handles, rows).
pub const DRAG_SLOP: f32 = 3.0;

/// A press on field `field` at `start_x`, with what its value started
/// from (`base`).
#[derive(Clone, Debug)]
pub struct FieldPress<F, B> {
    pub field: F,
    pub base: B,
    start_x: f32,
    moved: bool,
}

impl<F, B> FieldPress<F, B> {
    pub fn new(field: F, x: f32, base: B) -> Self {
        FieldPress {
            field,
            base,
            start_x: x,
            moved: false,
        }
    }

    /// The mouse is at `x`: how far it is from the press once it has
    /// moved past the slop (from then on every move is a drag); `None`
    /// while the press is still a click.
    pub fn drag_dx(&mut self, x: f32) -> Option<f32> {
        let dx = x - self.start_x;
        if !self.moved && dx.abs() < DRAG_SLOP {
            return None;
        }
        self.moved = true;
        Some(dx)
    }

    /// Whether the press became a drag.
    pub fn moved(&self) -> bool {
        self.moved
    }
}

/// The press held in `slot` moved to `x`: the press and how far it moved
/// once it is a drag; otherwise the answer to give (`ignored` without a
/// press, `taken` while it may still be a click).
pub fn drag_of<F, B>(
    slot: &mut Option<FieldPress<F, B>>,
    x: f32,
) -> Result<(&mut FieldPress<F, B>, f32), Response> {
    let Some(p) = slot else {
        return Err(Response::ignored());
    };
    match p.drag_dx(x) {
        Some(dx) => Ok((p, dx)),
        None => Err(Response::taken()),
    }
}

/// What happens to a face's fields: the mouse pressed on one of them (the
/// editor found which), moved and released, Esc during that press, or a
/// value typed into a field and Enter.
#[derive(Clone, Debug, PartialEq)]
pub enum FieldEvent {
    Press { field: FieldId, x: f32 },
    Move { x: f32 },
    Release,
    Cancel,
    Typed { field: FieldId, value: FieldValue },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_press_is_a_click_until_it_moves_past_the_slop_then_a_drag() {
        let mut p = FieldPress::new(FieldId::Fps, 100.0, ());
        assert_eq!(p.drag_dx(102.0), None);
        assert!(!p.moved());
        assert_eq!(p.drag_dx(110.0), Some(10.0));
        // Once a drag, back within the slop is still a drag.
        assert_eq!(p.drag_dx(101.0), Some(1.0));
        assert!(p.moved());
    }
}
