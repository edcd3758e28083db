//! The side panel's own state: how far its lists and its properties
//! section are scrolled. The panel's sections have fixed places (see
//! `ui::layout::SidePanel`), so whatever does not fit scrolls inside its
//! section instead of pushing the next one down.

use crate::scene::NodeId;
use crate::ui::Rect;

/// What the properties section shows: a scroll made for one thing does
/// not carry over to another (a key panel opened after scrolling an
/// object's rows starts at its top).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Section {
    pub node: Option<NodeId>,
    pub kind: SectionKind,
}

/// Which of its faces the properties section shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SectionKind {
    #[default]
    Node,
    Keys,
    Material,
}

/// The side panel's scroll state.
#[derive(Clone, Debug, Default)]
pub struct Side {
    /// First visible row of the objects and lights lists.
    pub lists: [usize; 2],
    /// First visible body row of the properties, and what it was for.
    props: (Section, usize),
    /// The selection the lists were last scrolled to show, and the side
    /// panel's rect then (a panel made smaller shows it again).
    pub revealed: Option<(NodeId, Rect)>,
}

impl Side {
    /// First visible body row of the properties showing `now`, when
    /// `hidden` of its rows do not fit.
    pub fn props_first(&self, now: Section, hidden: usize) -> usize {
        if self.props.0 == now {
            self.props.1.min(hidden)
        } else {
            0
        }
    }

    /// Moves the properties showing `now` by `by` rows (negative: towards
    /// the first row), within the `hidden` rows that do not fit.
    pub fn scroll_props(&mut self, now: Section, hidden: usize, by: i32) {
        let first = self.props_first(now, hidden);
        self.props = (now, step(first, by, hidden));
    }

    /// Shows the properties of `now` from body row `first`.
    pub fn set_props_first(&mut self, now: Section, first: usize) {
        self.props = (now, first);
    }

    /// Moves list `i` of `n` rows, `cap` of them shown, by `by` rows.
    pub fn scroll_list(&mut self, i: usize, n: usize, cap: usize, by: i32) {
        self.lists[i] = step(self.lists[i], by, n.saturating_sub(cap));
    }

    /// Scrolls list `i` so its row `pos` is among the `cap` shown.
    pub fn reveal_row(&mut self, i: usize, pos: usize, cap: usize) {
        let s = &mut self.lists[i];
        if pos < *s {
            *s = pos;
        } else if pos >= *s + cap {
            *s = pos + 1 - cap;
        }
    }
}

/// Rows a wheel turn of `delta` moves (negative: towards the first row):
/// a turn up (positive delta) shows earlier rows, one row per notch.
pub fn wheel_rows(delta: f32) -> i32 {
    let n = delta.abs().round().clamp(1.0, 10.0) as i32;
    if delta > 0.0 {
        -n
    } else {
        n
    }
}

/// `first` moved by `by` and kept within `0..=max`.
fn step(first: usize, by: i32, max: usize) -> usize {
    (first as i64 + by as i64).clamp(0, max as i64) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scroll_belongs_to_what_it_was_made_for_and_stays_in_range() {
        let mut s = Side::default();
        let ball = Section {
            node: Some(NodeId(1)),
            kind: SectionKind::Node,
        };
        let keys = Section {
            kind: SectionKind::Keys,
            ..ball
        };
        s.scroll_props(ball, 3, wheel_rows(-5.0));
        assert_eq!(s.props_first(ball, 3), 3);
        assert_eq!(s.props_first(ball, 1), 1, "fewer hidden rows clamp it");
        assert_eq!(s.props_first(keys, 6), 0, "the key panel starts at its top");
        s.scroll_props(ball, 3, wheel_rows(1.0));
        assert_eq!(s.props_first(ball, 3), 2);
        s.scroll_list(1, 5, 2, 2);
        s.scroll_list(1, 5, 2, 2);
        assert_eq!(s.lists[1], 3);
        s.scroll_list(1, 5, 2, -1);
        assert_eq!(s.lists[1], 2);
        s.reveal_row(1, 0, 2);
        assert_eq!(s.lists[1], 0);
    }
}
