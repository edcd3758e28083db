//! The editor's colours, as `0x00RRGGBB` (the frame's pixel format).

pub const PANEL: u32 = 0x2b2d31;
pub const PANEL_DARK: u32 = 0x222327;
pub const TOOLBAR: u32 = 0x35373c;
pub const BORDER: u32 = 0x151618;
pub const HEADER: u32 = 0x3c3f46;
pub const TEXT: u32 = 0xdcdde0;
pub const TEXT_DIM: u32 = 0x8e9197;
pub const BUTTON: u32 = 0x45484f;
pub const BUTTON_HOT: u32 = 0x575b64;
pub const BUTTON_ON: u32 = 0x3d6fb0;
pub const FIELD: u32 = 0x1b1c1f;
pub const FIELD_EDIT: u32 = 0x101a2a;
pub const ACCENT: u32 = 0x4c8fe8;
pub const SELECTED: u32 = 0xff9a1f;
pub const SELECTED_ROW: u32 = 0x5a4626;
pub const RECORD: u32 = 0xd63c3c;
pub const CURSOR: u32 = 0x4cc2ff;
pub const GRID: u32 = 0x4a4c52;
pub const GRID_AXIS_X: u32 = 0x9a3b3b;
pub const GRID_AXIS_Z: u32 = 0x3b5c9a;
pub const LIGHT_OFF: u32 = 0x6b6d72;
pub const ERROR: u32 = 0xff6b6b;
pub const DIALOG: u32 = 0x30333a;

/// A linear 0..1 colour as `0x00RRGGBB` (for swatches and gizmos).
pub fn rgb(c: glam::Vec3) -> u32 {
    let q = |x: f32| ((x.clamp(0.0, 1.0) * 255.0 + 0.5) as u32).min(255);
    (q(c.x) << 16) | (q(c.y) << 8) | q(c.z)
}

/// `c` moved `num/den` of the way to `t`, per channel (integer, so the
/// same bytes everywhere).
pub fn blend(c: u32, t: u32, num: u32, den: u32) -> u32 {
    let ch = |s: u32| {
        let (a, b) = ((c >> s) & 255, (t >> s) & 255);
        ((a * (den - num) + b * num) / den.max(1)) << s
    };
    ch(16) | ch(8) | ch(0)
}
