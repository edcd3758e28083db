//! The editor's 2D overlay: panels, text, lines and widgets drawn over the
//! rendered scene with tiny-skia and an embedded bitmap font.
//!
//! Nothing here knows about the editor's state: `editor/` decides *what* to
//! draw, this module knows *how*. All drawing goes through a [`Painter`],
//! which owns the only conversion between the renderer's `0x00RRGGBB` frame
//! and tiny-skia's premultiplied RGBA pixmap (see `pixels.rs`).

pub mod layout;
pub mod line;
mod painter;
mod pixels;
mod rect;
pub mod text;
pub mod theme;
pub mod widgets;

pub use layout::{Layout, SidePanel};
pub use painter::Painter;
pub use rect::Rect;
