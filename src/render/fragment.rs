//! The shading pass of a tile: after the depth pass has chosen one
//! triangle per pixel, shade every visible pixel once, eight pixels of a
//! row at a time in structure-of-arrays lanes ([`V8`]). Under
//! multisampling this shades each pixel's first sample (the lanes'
//! machinery here serves `samples` for the triangles showing only at
//! other samples, near edges; `shading` runs both).
//!
//! A block of eight pixels may show several triangles. Their attributes are
//! planes over the screen-space barycentrics the depth pass stored
//! (`value/w = base + b1·d1 + b2·d2`, set up once per triangle in
//! `prepare`), so each triangle present is evaluated for all eight lanes and
//! merged by lane mask; then the block is lit once per material it shows
//! (normally once). Each lane does exactly the arithmetic a lone pixel would,
//! so neither the grouping nor the lane width (SSE2 or AVX) changes a bit.
//!
//! What a pixel's colour is made of (texture, lighting, emissive map) is
//! `surface::shade_lanes`; this file gathers the lanes. Texture
//! coordinates (perspective-correct, with their screen-space derivatives
//! for the mip level, [`uv_in`]) are computed only for textured items, and
//! the loop of a tile without textured triangles is compiled without any
//! texture code (`TEX = false`).

use super::clip::{A_COLOR, A_NORMAL, A_POS, A_UV};
use super::lanes::Pair;
use super::prepare::{Item, Prepared, Tri, INV_W};
use super::simd::V8;
use super::surface::shade_lanes;
use super::texture_lanes::UvIn;
use glam::Vec3;

/// Tile width in pixels (the row stride of every tile buffer).
pub const TILE: i32 = 64;
/// Tile height in pixels: half the width, so a 720-row frame splits into
/// 23 bands of work instead of 12 (two threads finish closer together) and
/// a tile's buffers stay in the L2 cache under multisampling.
pub const TILE_H: i32 = 32;
/// Pixels of one sample plane of a tile buffer.
pub const PLANE: usize = (TILE * TILE_H) as usize;
/// Marks a pixel no opaque triangle covers.
pub const NONE: u32 = u32::MAX;

/// What the depth pass left for the shading pass: per sample a plane of
/// `TILE`×`TILE_H` pixels (sample-major).
pub struct Visible<'a> {
    /// Index into `Prepared::opaque` of the nearest triangle, or [`NONE`].
    pub winner: &'a [u32],
    /// Screen-space barycentric weights of vertices 1 and 2 at the first
    /// sample of the pixel (one plane).
    pub b1: &'a [f32],
    pub b2: &'a [f32],
    /// Whether a triangle of a textured item may show in the tile: picks
    /// the shading loop compiled with the texture steps.
    pub textured: bool,
}

/// The tile's linear colour channels and object ids, per sample like
/// [`Visible`].
pub struct Shaded<'a> {
    pub r: &'a mut [f32],
    pub g: &'a mut [f32],
    pub b: &'a mut [f32],
    pub ids: &'a mut [u32],
    /// Under multisampling, per block of eight pixels: whether every sample
    /// of its pixels shows the triangle of the first sample. Such a block's
    /// colours and ids are kept in the first plane only (the resolve and
    /// `samples::SamplePlanes` know; the passes after this one keep a
    /// block flat while they write all samples of a pixel alike).
    pub flat: &'a mut [bool],
    /// Working memory of `samples::shade_others`.
    pub queue: &'a mut Vec<Leftover>,
}

/// A triangle showing at sample `s` of pixel `i` (tile index) and at no
/// earlier sample of it: it is shaded there once, for all its samples.
#[derive(Clone, Copy, Debug)]
pub struct Leftover {
    pub i: u16,
    pub s: u8,
    pub t: u32,
}

/// What the shading pass of a tile works with besides its buffers.
#[derive(Clone, Copy)]
pub struct Pass<'a> {
    pub p: &'a Prepared,
    pub eye: Vec3,
    /// The colour of samples no triangle covers.
    pub background: Vec3,
    /// Tile width and height in pixels, samples per pixel.
    pub size: (usize, usize, usize),
    /// The tile's top-left pixel, and the sample positions (SUBPIXEL units
    /// from the pixel centre), for weights recomputed at other samples.
    pub origin: (i32, i32),
    pub offsets: &'a [(i64, i64)],
}

#[inline(always)]
pub fn lanes8<T>(s: &[T], i: usize) -> &[T; 8] {
    s[i..i + 8]
        .try_into()
        .expect("tile rows are multiples of 8")
}

#[inline(always)]
pub fn lanes8_mut<T>(s: &mut [T], i: usize) -> &mut [T; 8] {
    (&mut s[i..i + 8])
        .try_into()
        .expect("tile rows are multiples of 8")
}

/// Stores `v` into the lanes of `dst` selected by `mask` (bit per lane).
/// Partial stores go lane by lane: a select of the loaded old value would
/// compile to a masked store, which is very slow on some CPUs.
#[inline(always)]
pub fn store_masked<V: V8>(dst: &mut [f32; 8], v: V, mask: u32) {
    if mask == 0xFF {
        v.store(dst);
    } else {
        let mut a = [0.0; 8];
        v.store(&mut a);
        for (k, (d, a)) in dst.iter_mut().zip(a).enumerate() {
            if mask >> k & 1 == 1 {
                *d = a;
            }
        }
    }
}

/// Shades the first sample of every pixel of a tile (all of them without
/// multisampling; `samples::shade_others` does the rest): two neighbouring
/// blocks of one lit item as a pair, other blocks lit once per item they
/// show. Samples with no triangle get the background and id 0.
#[inline(always)]
pub fn shade_first<V: V8, const TEX: bool>(pass: &Pass, vis: &Visible, out: &mut Shaded) {
    let (p, eye) = (pass.p, pass.eye);
    let (w, h, _) = pass.size;
    for row in 0..h {
        let mut next = 0;
        for bx in (0..w).step_by(8) {
            if bx < next {
                continue;
            }
            let i0 = row * TILE as usize + bx;
            if bx + 8 < w {
                if let Some(item) = pair_item(p, vis.winner, i0) {
                    shade_pair::<V, TEX>(p, item, eye, vis, out, i0);
                    next = bx + 16;
                    continue;
                }
            }
            let win = *lanes8(vis.winner, i0);
            let mut lanes = 0u32;
            for (k, &t) in win.iter().enumerate() {
                lanes |= ((t != NONE) as u32) << k;
            }
            if lanes != 0xFF {
                let bg = pass.background;
                for (dst, c) in [&mut *out.r, &mut *out.g, &mut *out.b]
                    .into_iter()
                    .zip([bg.x, bg.y, bg.z])
                {
                    V::splat(c).store(lanes8_mut(dst, i0));
                }
                let ids = lanes8_mut(out.ids, i0);
                for (k, id) in ids.iter_mut().enumerate() {
                    if lanes >> k & 1 == 0 {
                        *id = 0;
                    }
                }
            }
            if lanes == 0 {
                continue;
            }
            let (b1, b2) = (V::load(lanes8(vis.b1, i0)), V::load(lanes8(vis.b2, i0)));
            let (rgb, lane_id) = shade_mixed::<V, TEX>(p, eye, &win, lanes, b1, b2);
            for (dst, src) in [&mut *out.r, &mut *out.g, &mut *out.b]
                .into_iter()
                .zip(&rgb)
            {
                store_masked(lanes8_mut(dst, i0), V::load(src), lanes);
            }
            let ids = lanes8_mut(out.ids, i0);
            for (k, id) in ids.iter_mut().enumerate() {
                if lanes >> k & 1 == 1 {
                    *id = lane_id[k];
                }
            }
        }
    }
}

/// Colours and ids of the lanes of `lanes`, each showing triangle `win[k]`
/// at weights (`b1`, `b2`): lit once per item (material + lights) among
/// them. Lanes outside `lanes` are left zero.
#[inline(always)]
pub fn shade_mixed<V: V8, const TEX: bool>(
    p: &Prepared,
    eye: Vec3,
    win: &[u32; 8],
    lanes: u32,
    b1: V,
    b2: V,
) -> ([[f32; 8]; 3], [u32; 8]) {
    let mut rgb = [[0.0f32; 8]; 3];
    let mut lane_id = [0u32; 8];
    let mut todo = lanes;
    while todo != 0 {
        let item_ix = p.opaque[win[todo.trailing_zeros() as usize] as usize].item;
        let mut group = 0u32;
        for (k, &t) in win.iter().enumerate() {
            if todo >> k & 1 == 1 && p.opaque[t as usize].item == item_ix {
                group |= 1 << k;
            }
        }
        todo &= !group;
        let item = &p.items[item_ix as usize];
        let c = shade_group::<V, TEX>(p, item, eye, win, group, b1, b2);
        for (dst, v) in rgb.iter_mut().zip(c) {
            store_masked(dst, v, group);
        }
        for (k, id) in lane_id.iter_mut().enumerate() {
            if group >> k & 1 == 1 {
                *id = item.id;
            }
        }
    }
    (rgb, lane_id)
}

/// The next distinct triangle among the lanes of `rest` and the mask of
/// the lanes showing it (removed from `rest`).
#[inline(always)]
fn next_tri<'p>(p: &'p Prepared, win: &[u32; 8], rest: &mut u32) -> (&'p Tri, u32) {
    let t = win[rest.trailing_zeros() as usize];
    let mut mask = 0u32;
    for (k, &wk) in win.iter().enumerate() {
        mask |= ((*rest >> k & 1 == 1 && wk == t) as u32) << k;
    }
    *rest &= !mask;
    (&p.opaque[t as usize], mask)
}

/// `base + b1·d1 + b2·d2` of plane `j` of `t`, per lane.
#[inline(always)]
fn plane<V: V8>(t: &Tri, j: usize, b1: V, b2: V) -> V {
    V::splat(t.base[j]) + b1 * V::splat(t.d1[j]) + b2 * V::splat(t.d2[j])
}

/// Interpolates and lights the lanes of `group` (all of one item).
#[inline(always)]
fn shade_group<V: V8, const TEX: bool>(
    p: &Prepared,
    item: &Item,
    eye: Vec3,
    win: &[u32; 8],
    group: u32,
    b1: V,
    b2: V,
) -> [V; 3] {
    // No closures over lanes in this file: a closure is a function of its
    // own without the caller's AVX target feature, and lane operations
    // inside it stop being inlined (a call per instruction).
    let (a, s) = attributes(p, win, group, b1, b2);
    let mut v = [s; 9];
    for (v, a) in v.iter_mut().zip(a) {
        *v = a * s;
    }
    let uv_store;
    let uv: &[UvIn<V>] = if TEX && item.textured {
        uv_store = [uv_in(p, win, group, b1, b2, s)];
        &uv_store
    } else {
        &[]
    };
    shade_lanes::<V, V, TEX>(
        item,
        eye,
        [v[0], v[1], v[2]],
        [v[3], v[4], v[5]],
        [v[6], v[7], v[8]],
        uv,
    )
}

/// Plane indices [`attributes`] evaluates: position, normal, colour, 1/w.
const USED: [usize; 10] = [
    A_POS,
    A_POS + 1,
    A_POS + 2,
    A_NORMAL,
    A_NORMAL + 1,
    A_NORMAL + 2,
    A_COLOR,
    A_COLOR + 1,
    A_COLOR + 2,
    INV_W,
];

/// The [`USED`] planes (value/w, then 1/w) of the lanes of `group`, each
/// from its own triangle, and `s` = w (1 over the last plane): attribute j
/// is `a[j] · s`, perspective-correct. Lanes outside `group` carry harmless
/// values of the first triangle's planes.
#[inline(always)]
fn attributes<V: V8>(p: &Prepared, win: &[u32; 8], group: u32, b1: V, b2: V) -> ([V; 10], V) {
    let mut a = [V::splat(0.0); 10];
    let mut rest = group;
    let mut first = true;
    while rest != 0 {
        let (t, mask) = next_tri(p, win, &mut rest);
        if first {
            for (v, &j) in a.iter_mut().zip(&USED) {
                *v = plane(t, j, b1, b2);
            }
            first = false;
        } else {
            let m = V::from_bits(mask);
            for (v, &j) in a.iter_mut().zip(&USED) {
                *v = V::select(m, plane(t, j, b1, b2), *v);
            }
        }
    }
    let s = V::splat(1.0) / a[9];
    (a, s)
}

/// The item that two neighbouring blocks of a row (`i0`, `i0 + 8`) show
/// in every one of their sixteen pixels, when it is one lit item: those
/// blocks are lit together as a [`Pair`].
#[inline(always)]
fn pair_item(p: &Prepared, winner: &[u32], i0: usize) -> Option<u32> {
    let win = &winner[i0..i0 + 16];
    let first = win[0];
    if first == NONE {
        return None;
    }
    let item = p.opaque[first as usize].item;
    for &t in &win[1..] {
        if t != first && (t == NONE || p.opaque[t as usize].item != item) {
            return None;
        }
    }
    (!p.items[item as usize].unlit).then_some(item)
}

/// Shades the sixteen pixels at `i0` (one row, two blocks) that all show
/// the lit `item` (see [`pair_item`]): attributes and texture coordinates
/// per block, then the shading sequence once over both as a [`Pair`] —
/// the same per-lane arithmetic as [`shade_group`], so the same bits.
#[inline(always)]
fn shade_pair<V: V8, const TEX: bool>(
    p: &Prepared,
    item: u32,
    eye: Vec3,
    vis: &Visible,
    out: &mut Shaded,
    i0: usize,
) {
    let it = &p.items[item as usize];
    let (wa, wb) = (*lanes8(vis.winner, i0), *lanes8(vis.winner, i0 + 8));
    let (b1a, b2a) = (V::load(lanes8(vis.b1, i0)), V::load(lanes8(vis.b2, i0)));
    let (b1b, b2b) = (
        V::load(lanes8(vis.b1, i0 + 8)),
        V::load(lanes8(vis.b2, i0 + 8)),
    );
    let (a, sa) = attributes(p, &wa, 0xFF, b1a, b2a);
    let (b, sb) = attributes(p, &wb, 0xFF, b1b, b2b);
    let mut v = [Pair(sa, sb); 9];
    for (j, v) in v.iter_mut().enumerate() {
        *v = Pair(a[j] * sa, b[j] * sb);
    }
    let uv_store;
    let uv: &[UvIn<V>] = if TEX && it.textured {
        uv_store = [
            uv_in(p, &wa, 0xFF, b1a, b2a, sa),
            uv_in(p, &wb, 0xFF, b1b, b2b, sb),
        ];
        &uv_store
    } else {
        &[]
    };
    let lit = shade_lanes::<V, Pair<V>, TEX>(
        it,
        eye,
        [v[0], v[1], v[2]],
        [v[3], v[4], v[5]],
        [v[6], v[7], v[8]],
        uv,
    );
    for (dst, c) in [&mut *out.r, &mut *out.g, &mut *out.b].into_iter().zip(lit) {
        c.0.store(lanes8_mut(dst, i0));
        c.1.store(lanes8_mut(dst, i0 + 8));
    }
    out.ids[i0..i0 + 16].fill(it.id);
}

/// Perspective-correct texture coordinates of the lanes of `group` and
/// their screen-space derivatives (per pixel step in x and in y), from
/// which the sampler picks the mip level (e.g. ρ = max(|∂uv/∂x|, |∂uv/∂y|)
/// in texels, OpenGL 4.6 §8.14.1). `s` is 1/q, the reciprocal of the
/// interpolated 1/w, per lane.
///
/// With `q = 1/w` and `U = u/w` both affine in screen space,
/// `u = U/q` and `∂u/∂x = (∂U/∂x − u·∂q/∂x)/q`.
#[inline(always)]
fn uv_in<V: V8>(p: &Prepared, win: &[u32; 8], group: u32, b1: V, b2: V, s: V) -> UvIn<V> {
    // Per lane: U, V planes and the constant gradients of U, V and q.
    let mut m = [V::splat(0.0); 8];
    let mut rest = group;
    let mut first = true;
    while rest != 0 {
        let (t, mask) = next_tri(p, win, &mut rest);
        let g = t.grad;
        let vals = [
            plane(t, A_UV, b1, b2),
            plane(t, A_UV + 1, b1, b2),
            V::splat(g.uv[0][0]),
            V::splat(g.uv[1][0]),
            V::splat(g.q[0]),
            V::splat(g.uv[0][1]),
            V::splat(g.uv[1][1]),
            V::splat(g.q[1]),
        ];
        if first {
            m = vals;
            first = false;
        } else {
            let mk = V::from_bits(mask);
            for (o, v) in m.iter_mut().zip(vals) {
                *o = V::select(mk, v, *o);
            }
        }
    }
    let (u, v) = (m[0] * s, m[1] * s);
    UvIn {
        u,
        v,
        du_dx: (m[2] - u * m[4]) * s,
        dv_dx: (m[3] - v * m[4]) * s,
        du_dy: (m[5] - u * m[7]) * s,
        dv_dy: (m[6] - v * m[7]) * s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::clip::ATTRS;
    use crate::render::prepare::{planes, SUBPIXEL};
    use crate::render::simd::{Lanes, Sse8};
    use crate::render::tri_gradients::Gradients;

    /// Screen positions, 1/w and texture coordinates of three vertices.
    type Corners = ([(f32, f32); 3], [f32; 3], [[f32; 2]; 3]);

    /// A triangle with texture coordinates and very different depths at
    /// its corners, in a one-triangle `Prepared`.
    fn textured() -> (Prepared, Corners) {
        let xy = [(2.0, 3.0), (60.0, 10.0), (12.0, 50.0)];
        let inv_w = [1.0, 0.25, 0.5];
        let uv = [[0.0, 0.0], [4.0, 1.0], [1.0, 3.0]];
        let mut attr = [[0.0; ATTRS]; 3];
        for k in 0..3 {
            attr[k][A_UV] = uv[k][0];
            attr[k][A_UV + 1] = uv[k][1];
        }
        let (base, d1, d2) = planes(&attr, &inv_w);
        let fx = |v: f32| (v * SUBPIXEL as f32) as i64;
        let mut tri = Tri {
            x: xy.map(|p| fx(p.0)),
            y: xy.map(|p| fx(p.1)),
            z: [0.5; 3],
            base,
            d1,
            d2,
            item: 0,
            bbox: [0, 0, 64, 64],
            grad: Gradients::default(),
        };
        tri.grad = Gradients::of(&tri.x, &tri.y, &tri.d1, &tri.d2);
        let mut p = Prepared::default();
        p.opaque.push(tri);
        (p, (xy, inv_w, uv))
    }

    /// Perspective-correct uv at a screen point, from the vertices.
    fn exact_uv(
        xy: &[(f32, f32); 3],
        inv_w: &[f32; 3],
        uv: &[[f32; 2]; 3],
        x: f64,
        y: f64,
    ) -> [f64; 2] {
        let p = xy.map(|(a, b)| (a as f64, b as f64));
        let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0);
        let b1 = ((x - p[0].0) * (p[2].1 - p[0].1) - (y - p[0].1) * (p[2].0 - p[0].0)) / area;
        let b2 = ((p[1].0 - p[0].0) * (y - p[0].1) - (p[1].1 - p[0].1) * (x - p[0].0)) / area;
        let w = [1.0 - b1 - b2, b1, b2];
        let q: f64 = (0..3).map(|k| w[k] * inv_w[k] as f64).sum();
        let f = |c: usize| {
            (0..3)
                .map(|k| w[k] * inv_w[k] as f64 * uv[k][c] as f64)
                .sum::<f64>()
                / q
        };
        [f(0), f(1)]
    }

    #[test]
    fn texture_coordinates_and_derivatives_are_perspective_correct() {
        let (p, (xy, inv_w, uv)) = textured();
        let t = &p.opaque[0];
        let mut checked = 0;
        crate::render::raster::for_each_pixel(t, [0, 0, 64, 64], |x, y, b1, b2| {
            let q = t.base[INV_W] + b1 * t.d1[INV_W] + b2 * t.d2[INV_W];
            let lanes = uv_in(
                &p,
                &[0; 8],
                0xFF,
                Sse8::splat(b1),
                Sse8::splat(b2),
                Sse8::splat(1.0) / Sse8::splat(q),
            );
            let get = |v: Sse8| {
                let mut a = [0.0; 8];
                v.store(&mut a);
                a[0] as f64
            };
            let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
            let want = exact_uv(&xy, &inv_w, &uv, cx, cy);
            assert!((get(lanes.u) - want[0]).abs() < 1e-4, "u at {x},{y}");
            assert!((get(lanes.v) - want[1]).abs() < 1e-4, "v at {x},{y}");
            // Central differences of the exact mapping.
            let h = 1e-3;
            let dx = exact_uv(&xy, &inv_w, &uv, cx + h, cy);
            let dx0 = exact_uv(&xy, &inv_w, &uv, cx - h, cy);
            let dy = exact_uv(&xy, &inv_w, &uv, cx, cy + h);
            let dy0 = exact_uv(&xy, &inv_w, &uv, cx, cy - h);
            let close = |a: f64, b: f64| (a - b).abs() < 1e-3 * (1.0 + b.abs());
            assert!(close(get(lanes.du_dx), (dx[0] - dx0[0]) / (2.0 * h)));
            assert!(close(get(lanes.dv_dx), (dx[1] - dx0[1]) / (2.0 * h)));
            assert!(close(get(lanes.du_dy), (dy[0] - dy0[0]) / (2.0 * h)));
            assert!(close(get(lanes.dv_dy), (dy[1] - dy0[1]) / (2.0 * h)));
            checked += 1;
        });
        assert!(checked > 500);
    }
}
