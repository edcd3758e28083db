//! Drawing one screen tile: fixed-point edge functions with the top-left
//! fill rule, a depth pass that keeps the nearest triangle per pixel, then
//! the shading pass (`fragment`: each visible pixel shaded once, eight at a
//! time); lines and points; transparent triangles blended back to front. A
//! tile owns its pixels, so tiles can run on any thread in any order and the
//! picture stays the same.

use super::blend_samples;
use super::clip::ATTRS;
use super::depth_blocks::{
    edge_lanes, make_planes, may_own, DepthBufs, BLOCKS_PER_ROW, EMPTY, PLANES,
};
use super::fragment::{store_masked, Leftover, Pass, Shaded, Visible, NONE};
use super::narrow_depth::{narrow_depth, NarrowBufs};
use super::prepare::{Item, Line, Point, Prepared, Tri, SUBPIXEL};
use super::samples::SamplePlanes;
use super::shade::shade;
use super::shading;
use super::simd::{self, Sse8, V8};
use glam::Vec3;

pub use super::fragment::{PLANE, TILE, TILE_H};

/// A rectangle of pixels: `[x0, y0, x1, y1)`.
pub type Rect = [i32; 4];

/// Indices (into [`Prepared`]) of the primitives touching one tile, in order.
#[derive(Clone, Debug, Default)]
pub struct Bin {
    pub opaque: Vec<u32>,
    pub transparent: Vec<u32>,
    pub lines: Vec<u32>,
    pub points: Vec<u32>,
    /// Whether an opaque triangle of a textured item is in `opaque`: the
    /// tile's shading loop then needs the texture steps.
    pub textured: bool,
}

impl Bin {
    /// Empties the lists, keeping their memory.
    pub fn clear(&mut self) {
        self.textured = false;
        self.opaque.clear();
        self.transparent.clear();
        self.lines.clear();
        self.points.clear();
    }
}

/// Sample positions of multisampling, in SUBPIXEL units from the pixel
/// centre (y down): the standard rotated-grid 4× and 8× patterns of
/// Direct3D 10.1 (given there in 1/16 pixel), so no two samples share a
/// row or a column.
pub fn sample_offsets(samples: usize) -> &'static [(i64, i64)] {
    const S: i64 = SUBPIXEL / 16;
    const ONE: [(i64, i64); 1] = [(0, 0)];
    const FOUR: [(i64, i64); 4] = [
        (-2 * S, -6 * S),
        (6 * S, -2 * S),
        (-6 * S, 2 * S),
        (2 * S, 6 * S),
    ];
    const EIGHT: [(i64, i64); 8] = [
        (S, -3 * S),
        (-S, 3 * S),
        (5 * S, S),
        (-3 * S, -5 * S),
        (-5 * S, 5 * S),
        (-7 * S, -S),
        (3 * S, 7 * S),
        (7 * S, -7 * S),
    ];
    match samples {
        1 => &ONE,
        4 => &FOUR,
        _ => &EIGHT,
    }
}

/// Per-thread working buffers for one tile: every per-sample buffer holds
/// `samples` planes of `TILE`×`TILE_H` (sample-major), reused from tile to
/// tile; the barycentrics one plane (the first sample's). Block states
/// and the first plane's winners are reset for every tile, and a block's
/// other depth and winner planes before the depth pass first uses them
/// (`depth_blocks`); the shading pass writes every colour and id (of a
/// `flat` block, the first plane's) and every `flat` mark; barycentrics
/// are read only where the depth pass wrote them. So reuse never changes
/// a picture.
pub struct Scratch {
    samples: usize,
    r: Vec<f32>,
    g: Vec<f32>,
    b: Vec<f32>,
    depth: Vec<f32>,
    ids: Vec<u32>,
    winner: Vec<u32>,
    b1: Vec<f32>,
    b2: Vec<f32>,
    /// Per block of eight pixels: what the depth pass wrote of it
    /// (`depth_blocks`).
    blocks: Vec<u32>,
    /// Per block of eight pixels under multisampling: kept in the first
    /// sample plane only (see `samples`).
    flat: Vec<bool>,
    /// The shading pass's queue of triangles showing only at later samples.
    queue: Vec<Leftover>,
}

/// Depth, winner, first-sample weights and block states of a tile.
#[cfg(test)]
pub type DepthResults<'a> = (&'a [f32], &'a [u32], &'a [f32], &'a [f32], &'a [u32]);

impl Scratch {
    /// Samples per pixel these buffers hold.
    pub fn samples(&self) -> usize {
        self.samples
    }

    /// The shading pass's `flat` marks of the tile's blocks (see
    /// `samples`), which the resolve reads: the per-stage benchmarks keep
    /// each tile's between the shading and the resolve stages.
    pub fn flat_mut(&mut self) -> &mut [bool] {
        &mut self.flat
    }

    /// The depth pass's results: depth and winner planes, first-sample
    /// weights, block states (for tests comparing it with a reference).
    #[cfg(test)]
    pub fn depth_results(&self) -> DepthResults<'_> {
        (&self.depth, &self.winner, &self.b1, &self.b2, &self.blocks)
    }

    pub fn new(samples: usize) -> Scratch {
        let n = samples * PLANE;
        Scratch {
            samples,
            r: vec![0.0; n],
            g: vec![0.0; n],
            b: vec![0.0; n],
            depth: vec![1.0; n],
            ids: vec![0; n],
            winner: vec![NONE; n],
            b1: vec![0.0; PLANE],
            b2: vec![0.0; PLANE],
            blocks: vec![EMPTY; PLANE / 8],
            flat: vec![false; PLANE / 8],
            queue: Vec::new(),
        }
    }
}

/// Where a tile's finished pixels go: rows of the frame starting at row
/// `y0`, `stride` pixels apart.
pub struct Target<'a> {
    pub color: &'a mut [u32],
    pub depth: &'a mut [f32],
    pub ids: &'a mut [u32],
    pub stride: usize,
    pub y0: i32,
}

/// Edge functions of a triangle stepped across a rectangle. `e[k]` is the
/// (biased) edge function opposite vertex k at the current pixel centre;
/// a pixel is inside when all three are ≥ 0.
struct Edges {
    row: [i64; 3],
    step_x: [i64; 3],
    step_y: [i64; 3],
    inv_area: f32,
}

impl Edges {
    /// Edges at the sample `off` (SUBPIXEL units from the centre) of pixel
    /// (x0, y0).
    fn at(t: &Tri, x0: i32, y0: i32, off: (i64, i64)) -> Edges {
        let (px, py) = (
            x0 as i64 * SUBPIXEL + SUBPIXEL / 2 + off.0,
            y0 as i64 * SUBPIXEL + SUBPIXEL / 2 + off.1,
        );
        let mut row = [0; 3];
        let mut step_x = [0; 3];
        let mut step_y = [0; 3];
        for k in 0..3 {
            (row[k], step_x[k], step_y[k]) = t.edge(k, px, py);
        }
        Edges {
            row,
            step_x,
            step_y,
            inv_area: 1.0 / t.area() as f32,
        }
    }
}

/// Calls `f(x, y, b1, b2)` for every pixel of `rect` that the triangle
/// covers; `b1`, `b2` are the screen-space barycentric weights of vertices 1
/// and 2 (the tests' reference walk; drawing steps the same edges in
/// lanes: the depth pass, `narrow_depth`, `blend_samples`).
#[cfg(test)]
pub fn for_each_pixel(t: &Tri, rect: Rect, f: impl FnMut(i32, i32, f32, f32)) {
    for_each_pixel_at(t, rect, (0, 0), f)
}

/// Calls `f(x, y, b1, b2)` for every pixel of `rect` whose sample at `off`
/// (SUBPIXEL units from its centre) the triangle covers; `b1`, `b2` are
/// the screen-space barycentric weights of vertices 1 and 2 there (the
/// tests' reference walk, one pixel at a time).
#[cfg(test)]
#[inline]
pub fn for_each_pixel_at(
    t: &Tri,
    rect: Rect,
    off: (i64, i64),
    mut f: impl FnMut(i32, i32, f32, f32),
) {
    let x0 = t.bbox[0].max(rect[0]);
    let y0 = t.bbox[1].max(rect[1]);
    let x1 = t.bbox[2].min(rect[2]);
    let y1 = t.bbox[3].min(rect[3]);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let mut ed = Edges::at(t, x0, y0, off);
    for y in y0..y1 {
        let mut e = ed.row;
        for x in x0..x1 {
            if (e[0] | e[1] | e[2]) >= 0 {
                f(x, y, e[1] as f32 * ed.inv_area, e[2] as f32 * ed.inv_area);
            }
            for (e, s) in e.iter_mut().zip(ed.step_x) {
                *e += s;
            }
        }
        for (r, s) in ed.row.iter_mut().zip(ed.step_y) {
            *r += s;
        }
    }
}

/// Keeps, per sample of the tile, the nearest opaque triangle of `bin`
/// (the first one on ties) with its depth, and the first sample's
/// barycentric weights. `NS` samples per pixel at `offs` (SUBPIXEL units
/// from the pixel centre), every triangle once for all of them. With
/// `BLOCKS`, blocks stay empty or owned by one triangle where they can
/// (`depth_blocks`); without, every block has its planes from the start
/// and the pass never looks at the block states (their checks and the
/// buffers' reloads around them cost a one-sample frame about a quarter
/// of its depth pass).
fn depth_pass<const NS: usize, const BLOCKS: bool>(
    p: &Prepared,
    bin: &Bin,
    rect: Rect,
    offs: &[(i64, i64); NS],
    bufs: &mut DepthBufs,
) {
    #[cfg(target_arch = "x86_64")]
    if simd::avx() {
        // SAFETY: `simd::avx()` checked that the CPU has AVX.
        unsafe { depth_pass_avx::<NS, BLOCKS>(p, bin, rect, offs, bufs) };
        return;
    }
    for (k, &ti) in bin.opaque.iter().enumerate() {
        prefetch_ahead(&p.opaque, &bin.opaque, k);
        depth_triangle::<Sse8, NS, BLOCKS>(&p.opaque, ti, rect, offs, bufs);
    }
}

/// Triangles of a bin ahead of the one drawn whose memory is asked for
/// early: set-up wrote them megabytes ago, so the depth pass found each
/// one's first line cold (10 % of its time at the first load of a
/// 100k-triangle frame), and the shading pass, reading the planes, the
/// others.
const AHEAD: usize = 4;

/// Asks the CPU to bring every cache line of the triangle `AHEAD` places
/// after the `k`-th of `list` into the cache (a hint: it changes no value).
#[inline(always)]
fn prefetch_ahead(tris: &[Tri], list: &[u32], k: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(t) = list.get(k + AHEAD).and_then(|&i| tris.get(i as usize)) {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let at = (t as *const Tri).cast::<i8>();
        const SIZE: usize = std::mem::size_of::<Tri>();
        const _: () = assert!(SIZE > 192 && SIZE <= 256, "the offsets below");
        // Every 64-byte line from the first byte, and the last byte's
        // (unrolled: no loop to count).
        for off in [0, 64, 128, 192, SIZE - 1] {
            // SAFETY: `off` is inside the triangle, so the address is
            // too; a prefetch reads nothing the program sees.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(at.wrapping_add(off)) };
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn depth_pass_avx<const NS: usize, const BLOCKS: bool>(
    p: &Prepared,
    bin: &Bin,
    rect: Rect,
    offs: &[(i64, i64); NS],
    bufs: &mut DepthBufs,
) {
    for (k, &ti) in bin.opaque.iter().enumerate() {
        prefetch_ahead(&p.opaque, &bin.opaque, k);
        depth_triangle::<simd::Avx8, NS, BLOCKS>(&p.opaque, ti, rect, offs, bufs);
    }
}

/// One triangle's depth pass over blocks of eight pixels of a row (aligned
/// to the tile), all `NS` samples of a block in turn. A block is skipped
/// when one edge is negative at both of its ends at every sample, and taken
/// whole at a sample when every edge is non-negative at both ends there
/// (edge functions are linear, so a sample's edges are the first sample's
/// plus a constant per triangle); only blocks on an edge test each pixel.
/// Weights and depth are computed exactly as [`for_each_pixel_at`] does, per
/// pixel and sample, and each sample plane sees the triangles in bin
/// order, so the blocks change no bit. The first triangle to cover an
/// empty block at every sample, safely in front, owns it
/// (`depth_blocks`): only its first sample is computed; every other block
/// it touches gets its sample planes first.
#[inline(always)]
fn depth_triangle<V: V8, const NS: usize, const BLOCKS: bool>(
    tris: &[Tri],
    ti: u32,
    rect: Rect,
    offs: &[(i64, i64); NS],
    bufs: &mut DepthBufs,
) {
    // The buffers as locals: kept in registers (or loaded once) across
    // the stores into them, where fields reached through `bufs` were
    // loaded again at every block.
    let DepthBufs {
        depth,
        winner,
        b1,
        b2,
        blocks,
    } = bufs;
    let t = &tris[ti as usize];
    let x0 = t.bbox[0].max(rect[0]);
    let y0 = t.bbox[1].max(rect[1]);
    let x1 = t.bbox[2].min(rect[2]);
    let y1 = t.bbox[3].min(rect[3]);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    if x1 - x0 < 8 {
        // Narrow triangles (most small ones): a row at a time in one
        // window of eight lanes (`narrow_depth`), cheaper than the aligned
        // blocks it would straddle, with the very same arithmetic.
        if BLOCKS {
            let (bc0, bc1) = ((x0 - rect[0]) as usize / 8, (x1 - 1 - rect[0]) as usize / 8);
            for row in (y0 - rect[1]) as usize..(y1 - rect[1]) as usize {
                for bc in bc0..=bc1 {
                    let blk = row * BLOCKS_PER_ROW + bc;
                    let bufs = &mut DepthBufs {
                        depth,
                        winner,
                        b1,
                        b2,
                        blocks,
                    };
                    make_planes::<NS>(tris, rect, offs, blk, bufs);
                }
            }
        }
        let bufs = &mut NarrowBufs {
            depth,
            winner,
            b1,
            b2,
        };
        narrow_depth::<V, NS>(t, ti, rect, [x0, y0, x1, y1], offs, bufs);
        return;
    }
    // First block column (relative to the tile) and its screen x.
    let c0 = ((x0 - rect[0]) & !7) as usize;
    let xb0 = rect[0] + c0 as i32;
    let mut ed = Edges::at(t, xb0, y0, offs[0]);
    let s = ed.step_x;
    // Each sample's edges minus the first sample's (0 for one sample), and
    // per edge their least and greatest.
    let mut d = [[0i64; 3]; NS];
    if NS > 1 {
        let px = xb0 as i64 * SUBPIXEL + SUBPIXEL / 2;
        let py = y0 as i64 * SUBPIXEL + SUBPIXEL / 2;
        for (d, &off) in d.iter_mut().zip(offs) {
            for (k, d) in d.iter_mut().enumerate() {
                *d = t.edge(k, px + off.0, py + off.1).0 - ed.row[k];
            }
        }
    }
    let (mut dmin, mut dmax) = ([0i64; 3], [0i64; 3]);
    if NS > 1 {
        dmin = std::array::from_fn(|k| d.iter().map(|d| d[k]).min().unwrap_or(0));
        dmax = std::array::from_fn(|k| d.iter().map(|d| d[k]).max().unwrap_or(0));
    }
    let (z0, dz1, dz2) = (
        V::splat(t.z[0]),
        V::splat(t.z[1] - t.z[0]),
        V::splat(t.z[2] - t.z[0]),
    );
    let inv_area = V::splat(ed.inv_area);
    let zero = V::splat(0.0);
    // Whether the triangle may own blocks here: asked at the first block
    // it covers whole (small triangles never do).
    let mut own = None;
    // Edge values over the blocks stay below 2⁵² in magnitude (always, for
    // triangles near the screen): lanes are then converted through exact
    // f64 (`V8::from_edge`), giving the bits of `i64 as f32` (either way
    // the same bits; one choice for all samples).
    let span_x = (x1 - rect[0] - c0 as i32 + 8) as i64;
    let span_y = (y1 - y0) as i64;
    let exact = (0..3).all(|k| {
        (ed.row[k].saturating_add(dmin[k]).saturating_abs())
            .max(ed.row[k].saturating_add(dmax[k]).saturating_abs())
            .saturating_add(s[k].saturating_abs().saturating_mul(span_x))
            .saturating_add(ed.step_y[k].saturating_abs().saturating_mul(span_y))
            < 1 << 52
    });
    for y in y0..y1 {
        let mut e = ed.row;
        let row = (y - rect[1]) as usize * TILE as usize;
        let mut c = c0;
        while rect[0] + (c as i32) < x1 {
            let xb = rect[0] + c as i32;
            // Lanes inside the triangle's box.
            let lo = (x0 - xb).max(0);
            let hi = (x1 - xb).min(8);
            let in_box = (0xFFu32 << lo) & (0xFF >> (8 - hi));
            // Outside at every sample: an edge negative at both ends even
            // at the sample where it is greatest; inside at every sample:
            // every edge non-negative at both ends where it is least.
            let mut outside = false;
            let mut all_in = true;
            for k in 0..3 {
                let (a, b) = (e[k], e[k] + 7 * s[k]);
                outside |= a + dmax[k] < 0 && b + dmax[k] < 0;
                all_in &= a + dmin[k] >= 0 && b + dmin[k] >= 0;
            }
            if !outside {
                let blk = (row + c) / 8;
                if BLOCKS
                    && all_in
                    && in_box == 0xFF
                    && blocks[blk] == EMPTY
                    && *own.get_or_insert_with(|| may_own(t, [x0, y0, x1, y1]))
                {
                    // Covered at every sample and in front of the cleared
                    // depth: owned, with the first sample's weights (as
                    // below) and the winner in the first plane only.
                    let i0 = row + c;
                    let b1: &mut [f32; 8] = (&mut b1[i0..i0 + 8]).try_into().expect("8 lanes");
                    (edge_lanes::<V>(exact, e[1], s[1]) * inv_area).store(b1);
                    let b2: &mut [f32; 8] = (&mut b2[i0..i0 + 8]).try_into().expect("8 lanes");
                    (edge_lanes::<V>(exact, e[2], s[2]) * inv_area).store(b2);
                    winner[i0..i0 + 8].fill(ti);
                    blocks[blk] = ti;
                } else {
                    if BLOCKS {
                        let bufs = &mut DepthBufs {
                            depth,
                            winner,
                            b1,
                            b2,
                            blocks,
                        };
                        make_planes::<NS>(tris, rect, offs, blk, bufs);
                    }
                    for (si, d) in d.iter().enumerate() {
                        let es: [i64; 3] = std::array::from_fn(|k| e[k] + d[k]);
                        // This sample's block: outside, or inside whole.
                        let (mut out_s, mut in_s) = (false, all_in);
                        if NS > 1 && !all_in {
                            in_s = true;
                            for k in 0..3 {
                                let (a, b) = (es[k], es[k] + 7 * s[k]);
                                out_s |= a < 0 && b < 0;
                                in_s &= a >= 0 && b >= 0;
                            }
                        }
                        if out_s {
                            continue;
                        }
                        let e1 = edge_lanes::<V>(exact, es[1], s[1]);
                        let e2 = edge_lanes::<V>(exact, es[2], s[2]);
                        let mut mask = in_box;
                        if !in_s {
                            // A lane is outside when an edge is negative there;
                            // an integer's conversion keeps its sign (0 gives
                            // +0), so the sign bits of the converted lanes tell.
                            let e0 = edge_lanes::<V>(exact, es[0], s[0]);
                            mask &= !e0.or(e1).or(e2).bits();
                        }
                        if mask == 0 {
                            continue;
                        }
                        let w1 = e1 * inv_area;
                        let w2 = e2 * inv_area;
                        let z = z0 + w1 * dz1 + w2 * dz2;
                        let i0 = si * PLANE + row + c;
                        let depth: &mut [f32; 8] =
                            (&mut depth[i0..i0 + 8]).try_into().expect("8 lanes");
                        let old = V::load(depth);
                        let m = old.gt(z).and(zero.le(z)).bits() & mask;
                        if m == 0 {
                            continue;
                        }
                        store_masked(depth, z, m);
                        if si == 0 {
                            let b1: &mut [f32; 8] =
                                (&mut b1[i0..i0 + 8]).try_into().expect("8 lanes");
                            store_masked(b1, w1, m);
                            let b2: &mut [f32; 8] =
                                (&mut b2[i0..i0 + 8]).try_into().expect("8 lanes");
                            store_masked(b2, w2, m);
                        }
                        let winner: &mut [u32; 8] =
                            (&mut winner[i0..i0 + 8]).try_into().expect("8 lanes");
                        if m == 0xFF {
                            // Covered and nearer in all eight (inside a
                            // triangle): one store, not eight tests.
                            *winner = [ti; 8];
                        } else {
                            for (l, w) in winner.iter_mut().enumerate() {
                                if m >> l & 1 == 1 {
                                    *w = ti;
                                }
                            }
                        }
                    }
                }
            }
            for (e, s) in e.iter_mut().zip(s) {
                *e += 8 * s;
            }
            c += 8;
        }
        for (r, s) in ed.row.iter_mut().zip(ed.step_y) {
            *r += s;
        }
    }
}

/// Writes the first `dst.len()` (at most 8) of `px`: a whole block as one
/// fixed-size copy (a variable-length one becomes a `memmove` call).
#[inline(always)]
fn put8<T: Copy>(dst: &mut [T], px: &[T; 8]) {
    let n = dst.len().min(8);
    if let Ok(d) = <&mut [T; 8]>::try_from(&mut dst[..n]) {
        *d = *px;
    } else {
        dst[..n].copy_from_slice(&px[..n]);
    }
}

/// Colour of a fragment with attributes `a` of `item`.
#[inline]
fn shade_attrs(item: &Item, a: &[f32; ATTRS], eye: Vec3) -> Vec3 {
    let color = Vec3::new(a[6], a[7], a[8]);
    if item.unlit {
        return color;
    }
    let p = Vec3::new(a[0], a[1], a[2]);
    let n = Vec3::new(a[3], a[4], a[5]);
    shade(&item.material, color, &item.lights, p, n, eye)
}

/// Stage 1 of a tile: per sample, the nearest opaque triangle of `bin`
/// (the first on ties) with its depth and barycentric weights.
/// With `need_planes` every sample plane of depth and winner is written
/// out (a later pass reads depth at any sample); else blocks may stay
/// empty or owned (`depth_blocks`), and the shading pass knows them flat.
pub fn depth_tile(p: &Prepared, bin: &Bin, rect: Rect, scratch: &mut Scratch, need_planes: bool) {
    let ns = scratch.samples;
    let Scratch {
        depth,
        winner,
        b1,
        b2,
        blocks,
        ..
    } = scratch;
    if ns == 1 || need_planes {
        // One sample: a block left in one plane saves only its depth, and
        // writing the owner's depth out when another triangle comes costs
        // more; a later pass reading depth at any sample would need every
        // block written out. Every block has its planes from the start.
        depth.fill(1.0);
        winner.fill(NONE);
        blocks.fill(PLANES);
    } else {
        blocks.fill(EMPTY);
        // The shading pass reads the first plane's winners of every block.
        winner[..PLANE].fill(NONE);
    }
    let mut bufs = DepthBufs {
        depth,
        winner,
        b1,
        b2,
        blocks,
    };
    let offs = sample_offsets(ns);
    let b = &mut bufs;
    match (ns, need_planes) {
        (1, _) => depth_pass::<1, false>(p, bin, rect, offs.try_into().expect("1"), b),
        (4, true) => depth_pass::<4, false>(p, bin, rect, offs.try_into().expect("4"), b),
        (4, false) => depth_pass::<4, true>(p, bin, rect, offs.try_into().expect("4"), b),
        (_, true) => depth_pass::<8, false>(p, bin, rect, offs.try_into().expect("8"), b),
        (_, false) => depth_pass::<8, true>(p, bin, rect, offs.try_into().expect("8"), b),
    }
}

/// Stage 2 of a tile: shade each visible sample once per triangle it
/// shows (after [`depth_tile`]), then the sky behind what was drawn.
pub fn shade_tile(
    p: &Prepared,
    bin: &Bin,
    rect: Rect,
    background: Vec3,
    eye: Vec3,
    scratch: &mut Scratch,
) {
    let tw = (rect[2] - rect[0]) as usize;
    let th = (rect[3] - rect[1]) as usize;
    let ns = scratch.samples;
    let Scratch {
        r,
        g,
        b,
        ids,
        winner,
        b1,
        b2,
        blocks,
        flat,
        queue,
        ..
    } = scratch;
    // Blocks the depth pass left empty or owned by one triangle show the
    // same at every sample: flat before the shading pass looks (it
    // compares the planes of the others, `samples::shade_others`).
    if ns > 1 {
        for (f, &state) in flat.iter_mut().zip(blocks.iter()) {
            *f = state != PLANES;
        }
    }
    let pass = Pass {
        p,
        eye,
        background,
        size: (tw, th, ns),
        origin: (rect[0], rect[1]),
        offsets: sample_offsets(ns),
    };
    shading::shade_visible(
        &pass,
        &Visible {
            winner,
            b1,
            b2,
            textured: bin.textured,
        },
        &mut Shaded {
            r,
            g,
            b,
            ids,
            flat,
            queue,
        },
    );
    if let Some(sky) = &p.sky {
        for s in 0..ns {
            let pl = s * PLANE..(s + 1) * PLANE;
            let rgb = [&mut r[pl.clone()], &mut g[pl.clone()], &mut b[pl.clone()]];
            sky.fill_tile((rect[0], rect[1]), (tw, th), TILE as usize, &ids[pl], rgb);
        }
    }
}

/// Draws every primitive of `bin` into the tile `rect`: depth pass,
/// shading pass, lines and points, transparent triangles, resolve.
pub fn draw_tile(
    p: &Prepared,
    bin: &Bin,
    rect: Rect,
    background: Vec3,
    eye: Vec3,
    scratch: &mut Scratch,
    target: &mut Target,
) {
    // Lines, points, transparent triangles and a frame's depth read depth
    // at any sample.
    let need_planes = !(bin.lines.is_empty()
        && bin.points.is_empty()
        && bin.transparent.is_empty()
        && target.depth.is_empty());
    depth_tile(p, bin, rect, scratch, need_planes);
    shade_tile(p, bin, rect, background, eye, scratch);
    let ns = scratch.samples;
    let offsets = sample_offsets(ns);
    let at = |x: i32, y: i32| (y - rect[1]) as usize * TILE as usize + (x - rect[0]) as usize;
    let Scratch {
        r,
        g,
        b,
        depth,
        ids,
        flat,
        ..
    } = scratch;
    // Flat blocks (see `samples`) stay in one plane until a pass below
    // writes some of their samples.
    let mut planes = SamplePlanes {
        rgb: [r, g, b],
        ids,
        flat,
        ns,
    };
    // 3. Lines and points, depth-tested and shaded as they come; under
    // multisampling they cover samples (a band of the line's width, a square).
    let sample_px: Vec<(f32, f32)> = offsets
        .iter()
        .map(|&(x, y)| (x as f32 / SUBPIXEL as f32, y as f32 / SUBPIXEL as f32))
        .collect();
    for &li in &bin.lines {
        let l = &p.lines[li as usize];
        let item = &p.items[l.item as usize];
        if ns == 1 {
            for_each_line_pixel(l, rect, |x, y, z, a| {
                let i = at(x, y);
                if z < depth[i] && z >= 0.0 {
                    depth[i] = z;
                    planes.put(i, shade_attrs(item, &facing(item, a, eye), eye), item.id);
                }
            });
            continue;
        }
        for_each_line_pixel_aa(l, rect, &sample_px, |x, y, mask, z, a| {
            let i = at(x, y);
            let mut color = None;
            for s in 0..ns {
                let j = s * PLANE + i;
                if mask >> s & 1 == 1 && z < depth[j] && z >= 0.0 {
                    let c =
                        *color.get_or_insert_with(|| shade_attrs(item, &facing(item, a, eye), eye));
                    depth[j] = z;
                    planes.unflat(i);
                    planes.put(j, c, item.id);
                }
            }
        });
    }
    for &pi in &bin.points {
        let pt: &Point = &p.points[pi as usize];
        let item = &p.items[pt.item as usize];
        let c = shade_attrs(item, &facing(item, pt.attr, eye), eye);
        let half = pt.size as f32 * 0.5;
        for y in pt.bbox[1].max(rect[1])..pt.bbox[3].min(rect[3]) {
            for x in pt.bbox[0].max(rect[0])..pt.bbox[2].min(rect[2]) {
                let i = at(x, y);
                for (s, &(ox, oy)) in sample_px.iter().enumerate() {
                    if ns > 1 {
                        // The sample inside the square [c − half, c + half)².
                        let (sx, sy) = (x as f32 + 0.5 + ox, y as f32 + 0.5 + oy);
                        let inside = sx >= pt.c[0] - half
                            && sx < pt.c[0] + half
                            && sy >= pt.c[1] - half
                            && sy < pt.c[1] + half;
                        if !inside {
                            continue;
                        }
                    }
                    let j = s * PLANE + i;
                    if pt.z < depth[j] && pt.z >= 0.0 {
                        depth[j] = pt.z;
                        planes.unflat(i);
                        planes.put(j, c, item.id);
                    }
                }
            }
        }
    }
    // 4. Transparent triangles, already sorted back to front; they test but
    // do not write depth.
    for &ti in &bin.transparent {
        let t = &p.transparent[ti as usize];
        let item = &p.items[t.item as usize];
        let tr = blend_samples::Transparent {
            t,
            item,
            eye,
            // Alpha-tested (glTF MASK) pixels below the cutoff are not drawn.
            masks: item.texture.as_ref().is_some_and(|s| s.masks()),
        };
        blend_samples::blend_triangle(&tr, rect, offsets, depth, &mut planes);
    }
    resolve_tile(rect, scratch, target);
}

/// Stage 5 of a tile: resolve its samples into the frame — the mean of
/// the samples (a box filter), the nearest sample's depth, the id of the
/// first sample showing one. On AVX lanes where the CPU has them (the same
/// lane operations, so the same bits).
pub fn resolve_tile(rect: Rect, scratch: &Scratch, target: &mut Target) {
    #[cfg(target_arch = "x86_64")]
    if simd::avx() {
        // SAFETY: `simd::avx()` checked that the CPU has AVX.
        unsafe { resolve_tile_avx(rect, scratch, target) };
        return;
    }
    resolve_tile_in::<Sse8>(rect, scratch, target);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn resolve_tile_avx(rect: Rect, scratch: &Scratch, target: &mut Target) {
    resolve_tile_in::<simd::Avx8>(rect, scratch, target);
}

#[inline(always)]
fn resolve_tile_in<V: V8>(rect: Rect, scratch: &Scratch, target: &mut Target) {
    let tw = (rect[2] - rect[0]) as usize;
    let ns = scratch.samples;
    let Scratch {
        r,
        g,
        b,
        depth,
        ids,
        flat,
        ..
    } = scratch;
    // A colour-only frame (`render_color_into`) has no depth or ids.
    let depth_and_ids = !target.depth.is_empty();
    for (row, y) in (rect[1]..rect[3]).enumerate() {
        let dst = (y - target.y0) as usize * target.stride + rect[0] as usize;
        let src = row * TILE as usize;
        if ns == 1 {
            // Eight at a time (tile rows are TILE long, so the last block
            // may read past `tw` but only `tw` pixels are written).
            for k in (0..tw).step_by(8) {
                let px = super::frame::pack_rgb8(
                    ld::<V>(r, src + k),
                    ld::<V>(g, src + k),
                    ld::<V>(b, src + k),
                );
                put8(&mut target.color[dst + k..dst + tw], &px);
                if !depth_and_ids {
                    continue;
                }
                let at = src + k..src + k + 8;
                put8(
                    &mut target.depth[dst + k..dst + tw],
                    depth[at.clone()].try_into().expect("8"),
                );
                put8(
                    &mut target.ids[dst + k..dst + tw],
                    ids[at].try_into().expect("8"),
                );
            }
            continue;
        }
        // Eight pixels at a time, all their samples at once (no row-long
        // sums kept in memory); the sum runs in sample order from 0, so it
        // is the same on every machine and as it always was.
        let inv = V::splat(1.0 / ns as f32);
        for k in (0..tw).step_by(8) {
            let i0 = src + k;
            let mut acc = [V::splat(0.0); 3];
            let mut id = [0u32; 8];
            if flat[i0 / 8] {
                // Kept in the first plane only (see `samples`): the same
                // sum, of the first plane `ns` times, and its ids.
                let c = [ld::<V>(r, i0), ld::<V>(g, i0), ld::<V>(b, i0)];
                for _ in 0..ns {
                    for (a, c) in acc.iter_mut().zip(c) {
                        *a = *a + c;
                    }
                }
                id.copy_from_slice(&ids[i0..i0 + 8]);
            } else {
                for s in 0..ns {
                    let j = s * PLANE + i0;
                    for (a, c) in acc.iter_mut().zip([r, g, b]) {
                        *a = *a + ld::<V>(c, j);
                    }
                    if depth_and_ids {
                        for (i, d) in id.iter_mut().zip(&ids[j..j + 8]) {
                            *i = if *i == 0 { *d } else { *i };
                        }
                    }
                }
            }
            let px = super::frame::pack_rgb8(acc[0] * inv, acc[1] * inv, acc[2] * inv);
            put8(&mut target.color[dst + k..dst + tw], &px);
            if depth_and_ids {
                let mut zmin = [f32::INFINITY; 8];
                for s in 0..ns {
                    let j = s * PLANE + i0;
                    for (z, d) in zmin.iter_mut().zip(&depth[j..j + 8]) {
                        *z = z.min(*d);
                    }
                }
                put8(&mut target.depth[dst + k..dst + tw], &zmin);
                put8(&mut target.ids[dst + k..dst + tw], &id);
            }
        }
    }
}

/// The eight lanes of `c` from `i` (a function, not a closure: see
/// [`edge_lanes`]).
#[inline(always)]
fn ld<V: V8>(c: &[f32], i: usize) -> V {
    V::load(c[i..i + 8].try_into().expect("8"))
}

/// The attributes a line or point is lit with. A line or point set is
/// lit by its normal as given: it has no back side to light instead
/// (OpenGL, so Coin: a normal facing away from the light gets ambient
/// only; glTF 2.0 §3.9.7: lines and points with NORMAL are lit as any
/// geometry). A surface that is not solid, drawn in the Lines or Points
/// style, is lit on the side that faces the eye, as its filled triangles
/// are: the normal is turned towards the eye. (A solid one draws only its
/// front faces' strokes, lit as given: `stroke_faces`.)
fn facing(item: &Item, mut a: [f32; ATTRS], eye: Vec3) -> [f32; ATTRS] {
    if !item.surface_strokes {
        return a;
    }
    let p = Vec3::new(a[0], a[1], a[2]);
    let n = Vec3::new(a[3], a[4], a[5]);
    if n.dot(eye - p) < 0.0 {
        for v in &mut a[3..6] {
            *v = -*v;
        }
    }
    a
}

/// Calls `f(x, y, depth, attrs)` for the pixels of a line in `rect`: per
/// column (x-major) or row (y-major) whose centre lies in the half-open
/// span of the segment, the pixel the line crosses, or for a line `width`
/// pixels wide a run of that many centred on it (OpenGL 2.1 §3.4.2: the
/// segment moved by −(w−1)/2 across, then w pixels from there). Each pixel
/// is a function of the segment alone, so tiles agree at their borders.
pub fn for_each_line_pixel(l: &Line, rect: Rect, mut f: impl FnMut(i32, i32, f32, [f32; ATTRS])) {
    let (dx, dy) = (l.x[1] - l.x[0], l.y[1] - l.y[0]);
    let x_major = dx.abs() >= dy.abs();
    // Major axis coordinates of the ends, the other axis, and the span.
    let (m0, m1, o0, od) = if x_major {
        (l.x[0], l.x[1], l.y[0], dy)
    } else {
        (l.y[0], l.y[1], l.x[0], dx)
    };
    let dm = m1 - m0;
    let (lo, hi) = if dm >= 0.0 { (m0, m1) } else { (m1, m0) };
    let (r_lo, r_hi) = if x_major {
        (rect[0], rect[2])
    } else {
        (rect[1], rect[3])
    };
    // OpenGL's diamond-exit rule (2.1 §3.4.1): a pixel is drawn when the
    // segment leaves its diamond |x − xc| + |y − yc| < ½, so the pixel whose
    // diamond holds the start is drawn and the one whose diamond holds the
    // end is not, whichever way the segment runs (centres map to centres
    // between our y-down rows and OpenGL's y-up window, so the rule reads
    // the same here). Between the ends, the pixel of each column (row) is
    // the one whose centre line the segment crosses from the start up to,
    // not at, the end. A polyline's shared vertex is so drawn once, by the
    // segment leaving it. Wide lines keep the centre rule at their ends.
    let centre = |k: i32| {
        let c = k as f32 + 0.5;
        if dm >= 0.0 {
            lo <= c && c < hi
        } else {
            lo < c && c <= hi
        }
    };
    let in_diamond =
        |m: f32, o: f32| (m - (m.floor() + 0.5)).abs() + (o - (o.floor() + 0.5)).abs() < 0.5;
    let thin = l.width == 1;
    let (ks, ke) = (m0.floor() as i32, m1.floor() as i32);
    let start_in = thin && in_diamond(m0, o0);
    let end_in = thin && in_diamond(m1, o0 + od);
    let drawn = |k: i32| {
        if end_in && k == ke {
            false
        } else if start_in && k == ks {
            true
        } else {
            centre(k)
        }
    };
    let first = ((lo.floor() as i32) - 1).max(r_lo);
    let last = ((hi.floor() as i32) + 2).min(r_hi);
    if dm == 0.0 {
        // A degenerate segment: one pixel.
        let (x, y) = (l.x[0].floor() as i32, l.y[0].floor() as i32);
        if x >= rect[0] && x < rect[2] && y >= rect[1] && y < rect[3] {
            f(x, y, l.z[0], l.attr[0]);
        }
        return;
    }
    let shift = (l.width - 1) as f32 * 0.5;
    for k in (first..last).filter(|&k| drawn(k)) {
        // A start pixel drawn for its diamond may lie before the centre
        // line's crossing: its attributes are the start's.
        let t = ((k as f32 + 0.5 - m0) / dm).clamp(0.0, 1.0);
        let o = (o0 + t * od - shift).floor() as i32;
        let (o_lo, o_hi) = if x_major {
            (rect[1], rect[3])
        } else {
            (rect[0], rect[2])
        };
        let run = o.max(o_lo)..(o + l.width).min(o_hi);
        if run.is_empty() {
            continue;
        }
        let z = l.z[0] + t * (l.z[1] - l.z[0]);
        // Perspective-correct weight of the second end.
        let w1 = t * l.inv_w[1];
        let w0 = (1.0 - t) * l.inv_w[0];
        let s = w1 / (w0 + w1);
        let mut a = [0.0; ATTRS];
        for (j, v) in a.iter_mut().enumerate() {
            *v = l.attr[0][j] + s * (l.attr[1][j] - l.attr[0][j]);
        }
        for o in run {
            let (x, y) = if x_major { (k, o) } else { (o, k) };
            f(x, y, z, a);
        }
    }
}

/// Multisampled lines: calls `f(x, y, sample mask, depth, attrs)` for the
/// pixels of `rect` some of whose samples (`samples`, in pixels from the
/// centre) lie in the `width`-pixel-wide band around the segment, within its
/// half-open length. Depth and attributes are taken once per pixel, where
/// the pixel's centre projects onto the segment.
pub fn for_each_line_pixel_aa(
    l: &Line,
    rect: Rect,
    samples: &[(f32, f32)],
    mut f: impl FnMut(i32, i32, u32, f32, [f32; ATTRS]),
) {
    let (dx, dy) = (l.x[1] - l.x[0], l.y[1] - l.y[0]);
    let len2 = dx * dx + dy * dy;
    if len2 == 0.0 {
        // A degenerate segment: as without multisampling, one pixel.
        let (x, y) = (l.x[0].floor() as i32, l.y[0].floor() as i32);
        if x >= rect[0] && x < rect[2] && y >= rect[1] && y < rect[3] {
            f(x, y, (1 << samples.len()) - 1, l.z[0], l.attr[0]);
        }
        return;
    }
    let inv_len = 1.0 / len2.sqrt();
    // Half the band's width, and how far past the ends it reaches.
    let half = l.width as f32 * 0.5;
    let reach = 1 + l.width / 2;
    let x0 = (l.x[0].min(l.x[1]).floor() as i32 - reach)
        .max(rect[0])
        .max(l.bbox[0]);
    let x1 = (l.x[0].max(l.x[1]).ceil() as i32 + reach)
        .min(rect[2])
        .min(l.bbox[2]);
    let y0 = (l.y[0].min(l.y[1]).floor() as i32 - reach)
        .max(rect[1])
        .max(l.bbox[1]);
    let y1 = (l.y[0].max(l.y[1]).ceil() as i32 + reach)
        .min(rect[3])
        .min(l.bbox[3]);
    for y in y0..y1 {
        for x in x0..x1 {
            let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
            // Cheap reject: no sample of this pixel can be in the band.
            if ((cx - l.x[0]) * dy - (cy - l.y[0]) * dx).abs() * inv_len > half + 1.0 {
                continue;
            }
            let mut mask = 0u32;
            for (s, &(ox, oy)) in samples.iter().enumerate() {
                let (px, py) = (cx + ox - l.x[0], cy + oy - l.y[0]);
                let dist = (px * dy - py * dx).abs() * inv_len;
                let t = (px * dx + py * dy) / len2;
                if dist <= half && (0.0..1.0).contains(&t) {
                    mask |= 1 << s;
                }
            }
            if mask == 0 {
                continue;
            }
            let t = (((cx - l.x[0]) * dx + (cy - l.y[0]) * dy) / len2).clamp(0.0, 1.0);
            let z = l.z[0] + t * (l.z[1] - l.z[0]);
            let w1 = t * l.inv_w[1];
            let w0 = (1.0 - t) * l.inv_w[0];
            let s = w1 / (w0 + w1);
            let mut a = [0.0; ATTRS];
            for (j, v) in a.iter_mut().enumerate() {
                *v = l.attr[0][j] + s * (l.attr[1][j] - l.attr[0][j]);
            }
            f(x, y, mask, z, a);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(pts: [(f32, f32); 3]) -> Tri {
        let fx = |v: f32| (v * SUBPIXEL as f32).round() as i64;
        let (base, d1, d2) = super::super::prepare::planes(&[[0.0; ATTRS]; 3], &[1.0; 3]);
        let mut t = Tri {
            x: pts.map(|p| fx(p.0)),
            y: pts.map(|p| fx(p.1)),
            z: [0.5; 3],
            base,
            d1,
            d2,
            item: 0,
            bbox: [0, 0, 64, 64],
            grad: Default::default(),
        };
        let area = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
        if area < 0 {
            t.x.swap(1, 2);
            t.y.swap(1, 2);
        }
        t
    }

    fn coverage(tris: &[Tri]) -> Vec<u32> {
        let mut hits = vec![0u32; 64 * 64];
        for t in tris {
            for_each_pixel(t, [0, 0, 64, 64], |x, y, _, _| {
                hits[(y * 64 + x) as usize] += 1
            });
        }
        hits
    }

    #[test]
    fn shared_edges_cover_every_pixel_exactly_once() {
        // A square split along its diagonal, with edges through pixel centres.
        let a = tri([(4.5, 4.5), (20.5, 4.5), (20.5, 20.5)]);
        let b = tri([(4.5, 4.5), (20.5, 20.5), (4.5, 20.5)]);
        let hits = coverage(&[a, b]);
        assert!(hits.iter().all(|&h| h <= 1), "overlap on a shared edge");
        // Top and left edges are in, bottom and right out: 16×16 pixels.
        assert_eq!(hits.iter().sum::<u32>(), 16 * 16);
        assert_eq!(hits[4 * 64 + 4], 1);
        assert_eq!(hits[20 * 64 + 20], 0);
    }

    #[test]
    fn fan_around_a_point_covers_each_pixel_once() {
        // Eight triangles around an off-grid centre, vertices at sub-pixel
        // positions: the square they tile is covered without gaps or overlaps.
        let c = (31.3, 29.7);
        let ring = [
            (10.25, 10.5),
            (31.3, 10.5),
            (52.75, 10.5),
            (52.75, 29.7),
            (52.75, 50.125),
            (31.3, 50.125),
            (10.25, 50.125),
            (10.25, 29.7),
        ];
        let tris: Vec<Tri> = (0..8)
            .map(|k| tri([c, ring[k], ring[(k + 1) % 8]]))
            .collect();
        let hits = coverage(&tris);
        assert!(hits.iter().all(|&h| h <= 1));
        // Pixel centres x+0.5 in [10.25, 52.75) → x = 10..=52 (43 columns);
        // y+0.5 in [10.5, 50.125) → y = 10..=49 (40 rows).
        assert_eq!(hits.iter().sum::<u32>(), 43 * 40);
    }

    fn covered(tris: &[Tri]) -> Vec<u32> {
        coverage(tris)
    }

    proptest::proptest! {
        /// A convex quad split along either diagonal covers the same pixels,
        /// each exactly once: the shared diagonal is never doubled or
        /// dropped, whatever the sub-pixel positions.
        #[test]
        fn quad_split_either_way_covers_the_same_pixels(
            cx in 20.0f32..44.0, cy in 20.0f32..44.0,
            r in proptest::array::uniform4(6.0f32..18.0),
            a0 in 0.0f32..1.4,
            // Snapped to 1/16 px sometimes, so exact hits on edges happen.
            snap in proptest::bool::ANY,
        ) {
            let q = |v: f32| if snap { (v * 16.0).round() / 16.0 } else { v };
            let pts: Vec<(f32, f32)> = (0..4)
                .map(|k| {
                    let a = a0 + k as f32 * std::f32::consts::FRAC_PI_2;
                    (q(cx + r[k] * a.cos()), q(cy + r[k] * a.sin()))
                })
                .collect();
            let one = covered(&[tri([pts[0], pts[1], pts[2]]), tri([pts[0], pts[2], pts[3]])]);
            let other = covered(&[tri([pts[0], pts[1], pts[3]]), tri([pts[1], pts[2], pts[3]])]);
            proptest::prop_assert!(one.iter().all(|&h| h <= 1));
            proptest::prop_assert!(other.iter().all(|&h| h <= 1));
            proptest::prop_assert_eq!(one, other);
        }
    }

    /// The shading pass recomputes the weights of samples the depth pass
    /// keeps none for: they must be its very bits, at every sample.
    #[test]
    fn weights_at_a_sample_are_the_stepped_edges_bits() {
        let t = tri([(2.3, 1.7), (61.1, 9.45), (11.6, 30.9)]);
        let mut checked = 0;
        for &off in sample_offsets(4).iter().chain(sample_offsets(8)) {
            for_each_pixel_at(&t, [0, 0, 64, 32], off, |x, y, w1, w2| {
                let (v1, v2) = t.weights_at(x, y, off);
                assert_eq!((v1.to_bits(), v2.to_bits()), (w1.to_bits(), w2.to_bits()));
                checked += 1;
            });
        }
        assert!(checked > 12 * 500);
    }

    #[test]
    fn barycentrics_reproduce_vertex_positions() {
        let t = tri([(2.5, 2.5), (40.5, 6.5), (10.5, 50.5)]);
        let mut checked = 0;
        for_each_pixel(&t, [0, 0, 64, 64], |x, y, b1, b2| {
            let b0 = 1.0 - b1 - b2;
            let px = b0 * 2.5 + b1 * t.x[1] as f32 / 256.0 + b2 * t.x[2] as f32 / 256.0;
            let py = b0 * 2.5 + b1 * t.y[1] as f32 / 256.0 + b2 * t.y[2] as f32 / 256.0;
            assert!((px - (x as f32 + 0.5)).abs() < 1e-3);
            assert!((py - (y as f32 + 0.5)).abs() < 1e-3);
            checked += 1;
        });
        assert!(checked > 500);
    }

    #[test]
    fn line_has_one_pixel_per_column() {
        let l = Line {
            x: [2.0, 30.0],
            y: [3.0, 10.0],
            z: [0.5, 0.5],
            inv_w: [1.0, 1.0],
            attr: [[0.0; ATTRS]; 2],
            item: 0,
            width: 1,
            bbox: [0, 0, 64, 64],
        };
        let mut cols = Vec::new();
        for_each_line_pixel(&l, [0, 0, 64, 64], |x, _, _, _| cols.push(x));
        assert_eq!(cols, (2..30).collect::<Vec<_>>());
        // Split across two tiles: the same pixels.
        let mut split = Vec::new();
        for r in [[0, 0, 16, 64], [16, 0, 64, 64]] {
            for_each_line_pixel(&l, r, |x, y, _, _| split.push((x, y)));
        }
        let mut whole = Vec::new();
        for_each_line_pixel(&l, [0, 0, 64, 64], |x, y, _, _| whole.push((x, y)));
        assert_eq!(split, whole);
    }

    /// OpenGL's diamond-exit rule: a segment draws the pixel whose diamond
    /// holds its start and not the one whose diamond holds its end,
    /// whichever way it runs; in between, the centre-line crossings.
    #[test]
    fn lines_draw_their_start_pixel_not_their_end_pixel() {
        let line = |x: f32, y: [f32; 2]| Line {
            x: [x, x],
            y,
            z: [0.5, 0.5],
            inv_w: [1.0, 1.0],
            attr: [[0.0; ATTRS]; 2],
            item: 0,
            width: 1,
            bbox: [0, 0, 64, 64],
        };
        let rows = |x, y| {
            let mut rows = Vec::new();
            for_each_line_pixel(&line(x, y), [0, 0, 64, 64], |_, y, _, _| rows.push(y));
            rows
        };
        let span = |r: std::ops::Range<i32>| r.collect::<Vec<_>>();
        // Ends on centres 2.5 and 9.5: down stops before row 9, up before 2.
        assert_eq!(rows(5.5, [2.5, 9.5]), span(2..9));
        assert_eq!(rows(5.5, [9.5, 2.5]), span(3..10));
        // Ends inside their diamonds but off the centres: the same rows.
        assert_eq!(rows(5.5, [2.2, 9.7]), span(2..9));
        assert_eq!(rows(5.5, [9.7, 2.2]), span(3..10));
        // A start past its row's centre still draws its row when the
        // diamond holds it (0.2 + 0 < ½), not when it lies near the pixel's
        // corner (0.2 + 0.4 > ½): then the centre lines decide.
        assert_eq!(rows(5.5, [2.7, 9.5]), span(2..9));
        assert_eq!(rows(5.9, [2.7, 9.5]), span(3..9));
        // Down then back up: the ends once each, the 6 rows between twice.
        let mut both = rows(5.5, [2.5, 9.5]);
        both.extend(rows(5.5, [9.5, 2.5]));
        both.sort();
        let mut once = both.clone();
        once.dedup();
        assert_eq!((both.len(), once.len()), (14, 8));
    }

    /// A line 2 pixels wide covers, in each column, the pixel it crosses
    /// and the nearer neighbour (the two centres within 1 of the line); a
    /// 3-pixel one is centred on the 1-pixel line's pixel.
    #[test]
    fn wide_lines_cover_width_pixels_per_column() {
        let line = |width| Line {
            x: [2.0, 30.0],
            y: [10.3, 10.3],
            z: [0.5, 0.5],
            inv_w: [1.0, 1.0],
            attr: [[0.0; ATTRS]; 2],
            item: 0,
            width,
            bbox: [0, 0, 64, 64],
        };
        let rows = |width| {
            let mut rows = Vec::new();
            for_each_line_pixel(&line(width), [0, 0, 64, 64], |x, y, _, _| {
                if x == 5 {
                    rows.push(y)
                }
            });
            rows
        };
        assert_eq!(rows(1), [10]);
        assert_eq!(rows(2), [9, 10]);
        assert_eq!(rows(3), [9, 10, 11]);
        // Clipped to the tile across the line, too.
        let mut clipped = Vec::new();
        for_each_line_pixel(&line(3), [0, 10, 64, 64], |_, y, _, _| clipped.push(y));
        assert!(clipped.iter().all(|&y| y >= 10) && clipped.len() == 28 * 2);
    }
}
