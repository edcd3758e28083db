//! Onion skin (O, toolbar): faint tinted copies of the selected object at
//! its previous and next key frames, so the user sees where it comes from
//! and goes to.
//!
//! Each copy is the selected subtree alone (every other shape hidden in
//! the pose, lights kept so it is shaded as usual) rendered by the normal
//! renderer with the viewport's camera, then blended at [`ALPHA`] with a
//! tint (outline firmer) over the viewport where it is not behind what the viewport shows.
//! The copies are cached until the scene, the neighbouring keys, camera,
//! size, style or selection change, and only made while the onion skin is on.

use super::record::key_frames;
use crate::anim::KEY_EPS;
use crate::render::Frame;
use crate::scene::{NodeId, RenderStyle};
use crate::ui::Rect;

/// How much of a copy shows over the viewport, inside and on its outline.
pub const ALPHA: f32 = 0.4;
pub const EDGE_ALPHA: f32 = 0.8;
/// Tints of the copy at the previous key (blue) and at the next (magenta:
/// distinct from the green y handle and green objects).
pub const BEFORE: u32 = 0x4c8fe8;
pub const AFTER: u32 = 0xe060d0;

/// Onion skin switch and its cached copies.
#[derive(Default)]
pub(super) struct Onion {
    pub on: bool,
    pub(super) key: Option<OnionKey>,
    /// The covered pixels of the rendered copies, ready to blend.
    pub(super) ghosts: Vec<GhostPixel>,
}

/// One pixel a copy covers: index in the viewport layer, the colour to
/// blend in (tinted) with its strength, and its depth.
#[derive(Clone, Copy, Debug)]
pub(super) struct GhostPixel {
    index: u32,
    color: u32,
    alpha: f32,
    depth: f32,
}

impl Onion {
    /// Blends the copies over the viewport part `vp` of `frame`, hidden
    /// where `layer` (the viewport's own render) is nearer.
    pub(super) fn blend(&self, layer: &Frame, frame: &mut Frame, vp: Rect) {
        let (w, h) = (layer.width, layer.height);
        let depth = &layer.depth;
        let fw = frame.width as usize;
        let rows = (vp.h.max(0) as usize).min(h as usize);
        let cols = (vp.w.max(0) as usize).min(w as usize);
        for g in &self.ghosts {
            let i = g.index as usize;
            let (x, y) = (i % w as usize, i / w as usize);
            // Hidden where the viewport shows something nearer.
            if x >= cols || y >= rows || g.depth > depth[i] + 1e-6 {
                continue;
            }
            let o = (vp.y as usize + y) * fw + vp.x as usize + x;
            frame.color[o] = mix(frame.color[o], g.color, g.alpha);
        }
    }
}

/// The pixels `g` covers, tinted; its silhouette firmer so the shape reads.
pub(super) fn covered(g: &Frame, tint: u32, out: &mut Vec<GhostPixel>) {
    let (w, h) = (g.width as usize, g.height as usize);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if g.ids[i] == 0 {
                continue;
            }
            let edge = x == 0
                || y == 0
                || x + 1 == w
                || y + 1 == h
                || g.ids[i - 1] == 0
                || g.ids[i + 1] == 0
                || g.ids[i - w] == 0
                || g.ids[i + w] == 0;
            let (color, alpha) = if edge {
                (tint, EDGE_ALPHA)
            } else {
                (mix(g.color[i], tint, 0.5), ALPHA)
            };
            out.push(GhostPixel {
                index: i as u32,
                color,
                alpha,
                depth: g.depth[i],
            });
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct OnionKey {
    pub(super) rev: u64,
    /// The key frames shown (not the current frame: the copies stay
    /// while the frame moves between the same two keys).
    pub(super) keys: (Option<f32>, Option<f32>),
    pub(super) camera: crate::input::OrbitCamera,
    pub(super) w: u32,
    pub(super) h: u32,
    pub(super) sel: NodeId,
    pub(super) style: Option<RenderStyle>,
}

/// The key frames of `id` just before and just after `frame`.
pub fn neighbour_keys(
    anim: &crate::anim::Animation,
    id: NodeId,
    frame: f32,
) -> (Option<f32>, Option<f32>) {
    let keys = key_frames(anim, Some(id));
    let before = keys.iter().rev().copied().find(|&k| k < frame - KEY_EPS);
    let after = keys.iter().copied().find(|&k| k > frame + KEY_EPS);
    (before, after)
}

/// Mixes `a` towards `b` by `t` (packed 0xRRGGBB).
pub(super) fn mix(a: u32, b: u32, t: f32) -> u32 {
    let ch = |s: u32| {
        let (x, y) = (((a >> s) & 255) as f32, ((b >> s) & 255) as f32);
        ((x + (y - x) * t).round() as u32).min(255) << s
    };
    ch(16) | ch(8) | ch(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Animation, Property, Target, TargetRef, Value};
    use glam::Vec3;

    #[test]
    fn neighbours_skip_the_key_under_the_frame() {
        let mut a = Animation::default();
        let t = Target {
            of: TargetRef::Node(NodeId(0)),
            property: Property::Translation,
        };
        for f in [0.0, 10.0, 20.0] {
            a.set_key(t, f, Value::Vec3(Vec3::ZERO)).unwrap();
        }
        assert_eq!(neighbour_keys(&a, NodeId(0), 10.0), (Some(0.0), Some(20.0)));
        assert_eq!(neighbour_keys(&a, NodeId(0), 5.0), (Some(0.0), Some(10.0)));
        assert_eq!(neighbour_keys(&a, NodeId(0), 0.0), (None, Some(10.0)));
        assert_eq!(neighbour_keys(&a, NodeId(1), 5.0), (None, None));
    }

    #[test]
    fn mixing_by_hand() {
        assert_eq!(mix(0x000000, 0xffffff, 0.5), 0x808080);
        assert_eq!(mix(0x102030, 0x102030, 0.35), 0x102030);
        assert_eq!(mix(0xff0000, 0x0000ff, 0.0), 0xff0000);
    }
}
