//! How each kind of widget looks. Stateless: the caller says whether a
//! widget is hot (under the mouse), on, selected or being edited.

use super::layout::ROW;
use super::text::{self, CHAR_W};
use super::theme;
use super::{Painter, Rect};

/// A push button with a centred label; `on` shows a latched toggle.
pub fn button(p: &mut Painter, r: Rect, label: &str, hot: bool, on: bool, color_on: u32) {
    let bg = if on {
        color_on
    } else if hot {
        theme::BUTTON_HOT
    } else {
        theme::BUTTON
    };
    p.fill_rect(r, bg);
    p.stroke_rect(r, theme::BORDER);
    let tw = text::width(label).min(r.w - 4);
    let x = r.x + (r.w - tw) / 2;
    let y = r.y + (r.h - text::LINE_H) / 2;
    p.text_clipped(x, y, label, theme::TEXT, r.w - 4);
}

/// A section header bar.
pub fn header(p: &mut Painter, r: Rect, title: &str) {
    p.fill_rect(r, theme::HEADER);
    p.text_clipped(
        r.x + 4,
        r.y + (r.h - text::LINE_H) / 2,
        title,
        theme::TEXT,
        r.w - 8,
    );
}

/// A value box. While `editing`, shows the typed text and a caret.
pub fn field(p: &mut Painter, r: Rect, value: &str, hot: bool, editing: bool) {
    let bg = if editing {
        theme::FIELD_EDIT
    } else {
        theme::FIELD
    };
    p.fill_rect(r, bg);
    p.stroke_rect(
        r,
        if editing {
            theme::ACCENT
        } else if hot {
            theme::BUTTON_HOT
        } else {
            theme::BORDER
        },
    );
    let y = r.y + (r.h - text::LINE_H) / 2;
    let avail = r.w - 5;
    // While editing keep the end (the caret) visible.
    let n = value.chars().count();
    let fit = text::fit_chars(avail - if editing { 2 } else { 0 });
    let shown: String = if editing && n > fit {
        value.chars().skip(n - fit).collect()
    } else {
        value.to_string()
    };
    let w = p.text_clipped(r.x + 3, y, &shown, theme::TEXT, avail);
    if editing {
        let cx = r.x + 3 + w.min(avail - 1);
        p.fill_rect(Rect::new(cx, r.y + 2, 1, r.h - 4), theme::TEXT);
    }
}

/// A row of a list, indented by `depth`, highlighted when selected.
pub fn list_row(p: &mut Painter, r: Rect, label: &str, depth: usize, selected: bool, hot: bool) {
    if selected {
        p.fill_rect(r, theme::SELECTED_ROW);
        p.fill_rect(Rect::new(r.x, r.y, 2, r.h), theme::SELECTED);
    } else if hot {
        p.fill_rect(r, theme::PANEL_DARK);
    }
    let indent = 4 + depth as i32 * CHAR_W;
    let color = if selected {
        theme::SELECTED
    } else {
        theme::TEXT
    };
    p.text_clipped(
        r.x + indent,
        r.y + (r.h - text::LINE_H) / 2,
        label,
        color,
        r.w - indent - 2,
    );
}

/// A small on/off box.
pub fn checkbox(p: &mut Painter, r: Rect, on: bool, hot: bool) {
    let s = (r.h - 4).clamp(6, ROW - 4);
    let b = Rect::new(r.x + (r.w - s) / 2, r.y + (r.h - s) / 2, s, s);
    p.fill_rect(b, theme::FIELD);
    p.stroke_rect(b, if hot { theme::TEXT } else { theme::TEXT_DIM });
    if on {
        p.fill_rect(b.inset(3), theme::ACCENT);
    }
}

/// Plain text, vertically centred in `r`.
pub fn label(p: &mut Painter, r: Rect, s: &str, color: u32) {
    p.text_clipped(r.x, r.y + (r.h - text::LINE_H) / 2, s, color, r.w);
}

/// A filled diamond of half-size `r` centred at `c` (a key marker: the key
/// strip, the motion path and the graph editor draw keys with it).
pub fn diamond(p: &mut Painter, c: (f32, f32), r: f32, color: u32) {
    let pts = [
        (c.0, c.1 - r),
        (c.0 + r, c.1),
        (c.0, c.1 + r),
        (c.0 - r, c.1),
    ];
    p.fill_polygon(&pts, color, 255);
}

/// A thin scroll bar at the right edge of `track` when `total` rows do not
/// fit: its thumb shows which `shown` rows from `first` are in view, so a
/// section that scrolls says so.
pub fn scroll_bar(p: &mut Painter, track: Rect, first: usize, shown: usize, total: usize) {
    if total <= shown || shown == 0 || track.h < 4 {
        return;
    }
    let x = track.right() - 2;
    p.fill_rect(Rect::new(x, track.y, 2, track.h), theme::PANEL_DARK);
    let h = ((track.h as usize * shown) / total).max(3) as i32;
    let room = track.h - h;
    let y = track.y + (room as usize * first / (total - shown)) as i32;
    p.fill_rect(Rect::new(x, y, 2, h), theme::TEXT_DIM);
}
