//! One transparent triangle blended into a multisampled tile, after the
//! shading pass: one walk over the triangle's pixels for all samples (a
//! sample's edge values are the first sample's plus a constant per
//! triangle: edge functions are linear and exact integers), the fragment
//! shaded once per pixel at the first sample it covers in front, and
//! blended into each such sample. A pixel of a `flat` block covered at
//! every sample blends into the first plane only (every sample held the
//! same colour and gets the same blend), so the block stays flat and the
//! resolve keeps its one-plane sum; any other pixel spreads its block
//! first. The weights, depth tests and blends are those of one sample at
//! a time, in the same order per sample, so no bit changes.

use super::fragment::{PLANE, TILE};
use super::prepare::{Tri, SUBPIXEL};
use super::samples::SamplePlanes;
use glam::Vec3;

/// The tile's rectangle `[x0, y0, x1, y1)` (as `raster::Rect`).
type Rect = [i32; 4];

/// Blends `t` into the tile `rect` at the samples `offs` (SUBPIXEL units
/// from the pixel centre, at most 8) where it is in front of `depth`
/// (which transparent triangles test but do not write). `color_at(b1, b2)`
/// gives the fragment's colour and opacity at the first covered sample's
/// weights; `masks`: an opacity of 0 is alpha-tested away (glTF MASK).
pub fn blend_triangle(
    t: &Tri,
    rect: Rect,
    offs: &[(i64, i64)],
    depth: &[f32],
    planes: &mut SamplePlanes,
    (id, masks): (u32, bool),
    color_at: impl Fn(f32, f32) -> (Vec3, f32),
) {
    let x0 = t.bbox[0].max(rect[0]);
    let y0 = t.bbox[1].max(rect[1]);
    let x1 = t.bbox[2].min(rect[2]);
    let y1 = t.bbox[3].min(rect[3]);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let ns = offs.len().min(8);
    let full = (1u32 << ns) - 1;
    let px = x0 as i64 * SUBPIXEL + SUBPIXEL / 2;
    let py = y0 as i64 * SUBPIXEL + SUBPIXEL / 2;
    // Edges at the first sample of (x0, y0), their steps, and each
    // sample's edges minus the first's.
    let mut row = [0i64; 3];
    let mut step_x = [0i64; 3];
    let mut step_y = [0i64; 3];
    for k in 0..3 {
        (row[k], step_x[k], step_y[k]) = t.edge(k, px + offs[0].0, py + offs[0].1);
    }
    let mut d = [[0i64; 3]; 8];
    for (d, &off) in d.iter_mut().zip(&offs[..ns]) {
        for (k, d) in d.iter_mut().enumerate() {
            *d = t.edge(k, px + off.0, py + off.1).0 - row[k];
        }
    }
    // Per edge, the least and greatest of the samples' offsets: a pixel
    // is outside at every sample when an edge is negative even where it
    // is greatest, inside at every sample when every edge is non-negative
    // where it is least (only the other pixels test each sample).
    let dmin: [i64; 3] = std::array::from_fn(|k| d[..ns].iter().map(|d| d[k]).min().unwrap_or(0));
    let dmax: [i64; 3] = std::array::from_fn(|k| d[..ns].iter().map(|d| d[k]).max().unwrap_or(0));
    let inv_area = 1.0 / t.area() as f32;
    for y in y0..y1 {
        let mut e = row;
        let line = (y - rect[1]) as usize * TILE as usize;
        for x in x0..x1 {
            let i = line + (x - rect[0]) as usize;
            let here = e;
            for (e, s) in e.iter_mut().zip(step_x) {
                *e += s;
            }
            if (0..3).any(|k| here[k] + dmax[k] < 0) {
                continue;
            }
            let all_in = (0..3).all(|k| here[k] + dmin[k] >= 0);
            let mut mask = 0u32;
            let mut w = (0.0, 0.0);
            for (s, d) in d[..ns].iter().enumerate() {
                let es = [here[0] + d[0], here[1] + d[1], here[2] + d[2]];
                if !all_in && (es[0] | es[1] | es[2]) < 0 {
                    continue;
                }
                let (w1, w2) = (es[1] as f32 * inv_area, es[2] as f32 * inv_area);
                let z = t.depth_at(w1, w2);
                if z < depth[s * PLANE + i] && z >= 0.0 {
                    if mask == 0 {
                        w = (w1, w2);
                    }
                    mask |= 1 << s;
                }
            }
            if mask == 0 {
                continue;
            }
            let (c, alpha) = color_at(w.0, w.1);
            if masks && alpha == 0.0 {
                continue;
            }
            if mask == full && planes.is_flat(i) {
                planes.blend(i, c, alpha, id);
                continue;
            }
            planes.unflat(i);
            for s in 0..ns {
                if mask >> s & 1 == 1 {
                    planes.blend(s * PLANE + i, c, alpha, id);
                }
            }
        }
        for (r, s) in row.iter_mut().zip(step_y) {
            *r += s;
        }
    }
}
