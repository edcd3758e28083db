//! Editor frame timing for `animed bench`: a full redraw (scene render +
//! overlay) and an overlay-only redraw (what hovering or typing costs, the
//! scene picture being cached) on the demo scene.

use super::Editor;
use crate::render::Frame;
use std::time::Instant;

/// Median times in milliseconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTimes {
    pub width: u32,
    pub height: u32,
    /// Frames measured of each kind.
    pub frames: usize,
    /// Scene render + grid + overlay + panels.
    pub full_ms: f64,
    /// Overlay + panels over the cached scene picture.
    pub overlay_ms: f64,
}

/// The benchmark's editor: the demo scene with its first object selected
/// (so the outline pass runs too).
pub fn setup(width: u32, height: u32) -> Editor {
    let mut ed = Editor::with_demo(width, height);
    let first = super::ops::objects(ed.scene()).first().map(|(id, _)| *id);
    ed.select(first);
    ed
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(0.0)
}

/// Draws full and overlay-only frames of the demo scene (with its first
/// object selected) at `width`×`height` for at least `min_seconds` (and at
/// least 5 of each).
pub fn bench_frame(width: u32, height: u32, min_seconds: f64) -> FrameTimes {
    let mut ed = setup(width, height);
    let mut frame = Frame::new(width, height, glam::Vec3::ZERO);
    ed.draw(&mut frame); // warm-up: allocations, caches
    let mut full = Vec::new();
    let mut overlay = Vec::new();
    let start = Instant::now();
    while full.len() < 5 || start.elapsed().as_secs_f64() < min_seconds {
        ed.invalidate();
        let t = Instant::now();
        ed.draw(&mut frame);
        full.push(t.elapsed().as_secs_f64() * 1e3);
        let t = Instant::now();
        ed.draw(&mut frame);
        overlay.push(t.elapsed().as_secs_f64() * 1e3);
    }
    FrameTimes {
        width,
        height,
        frames: full.len(),
        full_ms: median(full),
        overlay_ms: median(overlay),
    }
}
