//! Screen-space gradients of a textured triangle's texture planes and of
//! 1/w, from which the sampler's level of detail comes.
//!
//! Why a file of its own: `prepare` works them out once per textured
//! triangle (they are constant over it) and stores them in the `Tri`;
//! the shading pass and the transparent pass only read them. Computed per
//! eight-pixel block instead, they cost a division and about thirty
//! operations for every triangle of every block. It holds only plain
//! numbers, so `prepare` depends on it and not the other way round.

use super::clip::A_UV;
use super::prepare::{INV_W, PLANES, SUBPIXEL};

/// Screen-space gradients of a triangle's planes, per pixel step.
#[derive(Clone, Copy, Debug, Default)]
pub struct Gradients {
    /// ∂(u/w)/∂x, ∂(u/w)/∂y; then the same for v/w.
    pub uv: [[f32; 2]; 2],
    /// ∂(1/w)/∂x, ∂(1/w)/∂y.
    pub q: [f32; 2],
}

impl Gradients {
    /// The gradients of a triangle with fixed-point corners `x`, `y` (as
    /// oriented in `Tri`) and planes `d1`, `d2`: the barycentric weight
    /// of vertex k is its edge function over twice the area, so its step
    /// per pixel is the edge's (fixed-point) delta over the area.
    pub fn of(x: &[i64; 3], y: &[i64; 3], d1: &[f32; PLANES], d2: &[f32; PLANES]) -> Gradients {
        let area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
        let inv = SUBPIXEL as f32 / area as f32;
        // b1: edge from vertex 2 to 0; b2: edge from vertex 0 to 1.
        let db1 = [-((y[0] - y[2]) as f32) * inv, (x[0] - x[2]) as f32 * inv];
        let db2 = [-((y[1] - y[0]) as f32) * inv, (x[1] - x[0]) as f32 * inv];
        let grad = |j: usize, axis: usize| d1[j] * db1[axis] + d2[j] * db2[axis];
        Gradients {
            uv: [
                [grad(A_UV, 0), grad(A_UV, 1)],
                [grad(A_UV + 1, 0), grad(A_UV + 1, 1)],
            ],
            q: [grad(INV_W, 0), grad(INV_W, 1)],
        }
    }
}
