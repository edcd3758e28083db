//! One transparent triangle blended into a tile, after the shading pass:
//! one walk over the triangle's pixels for all samples (a sample's edge
//! values are the first sample's plus a constant per triangle: edge
//! functions are linear and exact integers), each fragment shaded once per
//! pixel at the first sample it covers in front, eight fragments lit
//! together (the lighting's lanes do a lone pixel's arithmetic, so the
//! same bits as one at a time), and blended into each covered sample.
//! Under multisampling a pixel of a `flat` block covered at every sample
//! blends into the first plane only (every sample held the same colour and
//! gets the same blend), so the block stays flat and the resolve keeps its
//! one-plane sum; any other pixel spreads its block first. Weights, depth
//! tests and blends are those of one sample at a time, so no bit changes.

use super::clip::{A_COLOR, A_NORMAL, A_POS};
use super::fragment::{PLANE, TILE};
use super::prepare::{Item, Tri, INV_W, SUBPIXEL};
use super::samples::SamplePlanes;
use super::shade::shade8;
use super::simd::{Lanes, Sse8, V8};
use super::surface;
use glam::Vec3;

/// The tile's rectangle `[x0, y0, x1, y1)` (as `raster::Rect`).
type Rect = [i32; 4];

/// A transparent triangle and what its fragments need: its item, the eye,
/// and whether an opacity of 0 is alpha-tested away (glTF MASK).
pub struct Transparent<'a> {
    pub t: &'a Tri,
    pub item: &'a Item,
    pub eye: Vec3,
    pub masks: bool,
}

/// Up to eight fragments waiting to be shaded together: the pixel, the
/// samples covered in front, the weights at the first of them.
#[derive(Default)]
struct Pending {
    n: usize,
    i: [usize; 8],
    mask: [u32; 8],
    b1: [f32; 8],
    b2: [f32; 8],
}

/// Blends `tr` into the tile `rect` at the samples `offs` (SUBPIXEL units
/// from the pixel centre, 1 to 8 of them) where it is in front of `depth`
/// (which transparent triangles test but do not write).
pub fn blend_triangle(
    tr: &Transparent,
    rect: Rect,
    offs: &[(i64, i64)],
    depth: &[f32],
    planes: &mut SamplePlanes,
) {
    let t = tr.t;
    let x0 = t.bbox[0].max(rect[0]);
    let y0 = t.bbox[1].max(rect[1]);
    let x1 = t.bbox[2].min(rect[2]);
    let y1 = t.bbox[3].min(rect[3]);
    if x0 >= x1 || y0 >= y1 || offs.is_empty() {
        return;
    }
    let ns = offs.len().min(8);
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
    let mut pending = Pending::default();
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
            let k = pending.n;
            pending.i[k] = i;
            pending.mask[k] = mask;
            (pending.b1[k], pending.b2[k]) = w;
            pending.n += 1;
            if pending.n == 8 {
                flush(tr, &mut pending, ns, planes);
            }
        }
        for (r, s) in row.iter_mut().zip(step_y) {
            *r += s;
        }
    }
    flush(tr, &mut pending, ns, planes);
}

/// Shades the pending fragments and blends each into its samples (each
/// pixel is touched once per triangle, so their order does not matter).
fn flush(tr: &Transparent, pending: &mut Pending, ns: usize, planes: &mut SamplePlanes) {
    let n = std::mem::take(&mut pending.n);
    if n == 0 {
        return;
    }
    let colors = colors(tr, pending, n);
    let full = (1u32 << ns) - 1;
    let id = tr.item.id;
    for (k, &(c, alpha)) in colors.iter().enumerate().take(n) {
        if tr.masks && alpha == 0.0 {
            continue;
        }
        let (i, mask) = (pending.i[k], pending.mask[k]);
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
}

/// Colour and opacity of the first `n` pending fragments. Untextured
/// items: the attribute planes and the lighting on eight lanes, each lane
/// the arithmetic of `Tri::attrs_at` and `shade::shade` for its pixel;
/// textured ones through the one-pixel `surface::shade_textured`.
fn colors(tr: &Transparent, p: &Pending, n: usize) -> [(Vec3, f32); 8] {
    let (t, item, eye) = (tr.t, tr.item, tr.eye);
    let mut out = [(Vec3::ZERO, item.material.alpha); 8];
    if item.textured {
        for (k, o) in out.iter_mut().enumerate().take(n) {
            *o = surface::shade_textured(item, t, p.b1[k], p.b2[k], eye);
        }
        return out;
    }
    let (b1, b2) = (Sse8::load(&p.b1), Sse8::load(&p.b2));
    let plane =
        |j: usize| Sse8::splat(t.base[j]) + b1 * Sse8::splat(t.d1[j]) + b2 * Sse8::splat(t.d2[j]);
    let s = Sse8::splat(1.0) / plane(INV_W);
    let attr = |j: usize| plane(j) * s;
    let three = |j: usize| [attr(j), attr(j + 1), attr(j + 2)];
    let color = three(A_COLOR);
    let rgb = if item.unlit {
        color
    } else {
        shade8(
            &item.material,
            &item.lights,
            eye,
            three(A_POS),
            three(A_NORMAL),
            color,
        )
    };
    let mut lanes = [[0.0f32; 8]; 3];
    for (l, v) in lanes.iter_mut().zip(rgb) {
        v.store(l);
    }
    for (k, o) in out.iter_mut().enumerate().take(n) {
        o.0 = Vec3::new(lanes[0][k], lanes[1][k], lanes[2][k]);
    }
    out
}
