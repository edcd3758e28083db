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
//! for the mip level, `block_planes`) are computed only for textured items, and
//! the loop of a tile without textured triangles is compiled without any
//! texture code (`TEX = false`).

use super::block_planes::BlockPlanes;
use super::lanes::Pair;
use super::prepare::{Item, Prepared};
use super::simd::V8;
use super::surface::shade_lanes;
use super::texture_lanes::{FlatLod, UvIn};
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
    let mut lods = FlatLod::default();
    for row in 0..h {
        let mut next = 0;
        for bx in (0..w).step_by(8) {
            if bx < next {
                continue;
            }
            let i0 = row * TILE as usize + bx;
            if bx + 8 < w {
                if let Some(item) = pair_item(p, vis.winner, i0) {
                    shade_pair::<V, TEX>(p, item, eye, vis, out, i0, &mut lods);
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
            let (rgb, lane_id) = shade_mixed_in::<V, TEX>(p, eye, &win, lanes, (b1, b2), &mut lods);
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
    shade_mixed_in::<V, TEX>(p, eye, win, lanes, (b1, b2), &mut FlatLod::default())
}

/// [`shade_mixed`] with the pass's [`FlatLod`].
#[inline(always)]
fn shade_mixed_in<V: V8, const TEX: bool>(
    p: &Prepared,
    eye: Vec3,
    win: &[u32; 8],
    lanes: u32,
    (b1, b2): (V, V),
    lods: &mut FlatLod,
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
        let c = shade_group::<V, TEX>(p, item, eye, (win, group), (b1, b2), lods);
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

/// Interpolates and lights the lanes of `group` (all of one item).
#[inline(always)]
fn shade_group<V: V8, const TEX: bool>(
    p: &Prepared,
    item: &Item,
    eye: Vec3,
    (win, group): (&[u32; 8], u32),
    (b1, b2): (V, V),
    lods: &mut FlatLod,
) -> [V; 3] {
    // No closures over lanes in this file: a closure is a function of its
    // own without the caller's AVX target feature, and lane operations
    // inside it stop being inlined (a call per instruction).
    let planes = BlockPlanes::new(p, win, group, b1, b2);
    let (a, s) = planes.attributes(reads_colour::<TEX>(item));
    let mut v = [s; 9];
    for (v, a) in v.iter_mut().zip(a) {
        *v = a * s;
    }
    let uv_store;
    let uv: &[UvIn<V>] = if TEX && item.textured {
        uv_store = [with_lod(item, planes.uv_in(s), lods)];
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

/// `uv` with its level of detail in `item`'s texture where its lanes are
/// flat (`UvIn::flat`; kept per triangle in `lods`).
#[inline(always)]
fn with_lod<V: V8>(item: &Item, mut uv: UvIn<V>, lods: &mut FlatLod) -> UvIn<V> {
    if let (Some(f), Some(s)) = (&uv.flat, &item.texture) {
        uv.tex_lod = Some(lods.of(f, s));
    }
    uv
}

/// Whether the shading of `item` reads the interpolated colour: not when
/// its texture replaces it (then the colour planes are not evaluated).
#[inline(always)]
fn reads_colour<const TEX: bool>(item: &Item) -> bool {
    !(TEX && item.textured && item.texture.as_ref().is_some_and(|s| s.replaces_diffuse()))
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
    // A triangle's item is looked up where the winner changes, not per
    // pixel (blocks of small triangles show several).
    let mut last = first;
    for &t in &win[1..] {
        if t != last {
            if t == NONE || p.opaque[t as usize].item != item {
                return None;
            }
            last = t;
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
    lods: &mut FlatLod,
) {
    let it = &p.items[item as usize];
    let (wa, wb) = (*lanes8(vis.winner, i0), *lanes8(vis.winner, i0 + 8));
    let (b1a, b2a) = (V::load(lanes8(vis.b1, i0)), V::load(lanes8(vis.b2, i0)));
    let (b1b, b2b) = (
        V::load(lanes8(vis.b1, i0 + 8)),
        V::load(lanes8(vis.b2, i0 + 8)),
    );
    let (pa, pb) = (
        BlockPlanes::new(p, &wa, 0xFF, b1a, b2a),
        BlockPlanes::new(p, &wb, 0xFF, b1b, b2b),
    );
    let colour = reads_colour::<TEX>(it);
    let (a, sa) = pa.attributes(colour);
    let (b, sb) = pb.attributes(colour);
    let mut v = [Pair(sa, sb); 9];
    for (j, v) in v.iter_mut().enumerate() {
        *v = Pair(a[j] * sa, b[j] * sb);
    }
    let uv_store;
    let uv: &[UvIn<V>] = if TEX && it.textured {
        uv_store = [
            with_lod(it, pa.uv_in(sa), lods),
            with_lod(it, pb.uv_in(sb), lods),
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
