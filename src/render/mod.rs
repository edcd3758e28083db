//! The CPU rasteriser: clipping, fixed-point edge functions, per-pixel
//! VRML97 lighting, deterministic tiled threading.
//!
//! API contract used by the CLI, the editor and the viewer:
//! `render(scene, pose, view, opts) -> Frame`. (Bodies are placeholders until
//! the rasteriser lands.)

mod frame;
mod view;

pub use frame::Frame;
pub use view::View;

use crate::anim::Pose;
use crate::scene::{RenderStyle, Scene};
use glam::Vec3;

/// Everything about a render that is not the scene or the camera.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    /// Worker threads (0 = all cores). The output never depends on it.
    pub threads: usize,
    /// Draw every object in this style instead of its own.
    pub style_override: Option<RenderStyle>,
    /// A directional light at the camera looking along the view direction.
    pub headlight: bool,
    pub background: Vec3,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 320,
            height: 240,
            threads: 0,
            style_override: None,
            headlight: true,
            background: Vec3::ZERO,
        }
    }
}

/// Draws `pose` of `scene` seen through `view`.
pub fn render(_scene: &Scene, _pose: &Pose, _view: &View, opts: &RenderOptions) -> Frame {
    Frame::new(opts.width, opts.height, opts.background)
}
