//! The other samples of a multisampled tile, after `fragment` has shaded
//! every pixel's first sample: a sample showing the first sample's
//! triangle takes its colour (each triangle is shaded once per pixel, at
//! the first sample it shows in); the triangles that show only at later
//! samples — near edges, a few pixels of a tile — are queued and shaded
//! eight at a time from across the tile, with their weights recomputed
//! exactly at their sample (`Tri::weights_at`: the depth pass keeps
//! weights for the first sample only).
//!
//! Blocks of eight pixels whose every sample shows what the first sample
//! shows (inside surfaces and the background: most of a picture) are
//! marked `flat` and written in the first plane only; the resolve sums the
//! first plane `samples` times for them (the same sum, so the same bits;
//! the sky, drawn after this per plane and the same in every plane of a
//! pixel, may paint the unused planes of a flat block, which nothing
//! reads); [`SamplePlanes`] writes a block out only when something draws
//! into some of its samples (lines, points, transparent triangles).

use super::fragment::{
    lanes8, lanes8_mut, shade_mixed, Leftover, Pass, Shaded, Visible, NONE, PLANE, TILE,
};
use super::simd::V8;
use glam::Vec3;

/// Colours and ids of every sample but the first of each pixel of the
/// tile, and the `flat` marks of its blocks.
#[inline(always)]
pub fn shade_others<V: V8, const TEX: bool>(pass: &Pass, vis: &Visible, out: &mut Shaded) {
    let (w, h, _) = pass.size;
    let mut queue = std::mem::take(&mut *out.queue);
    queue.clear();
    for row in 0..h {
        for bx in (0..w).step_by(8) {
            let i0 = row * TILE as usize + bx;
            // Marked flat on entry: the depth pass left the block empty or
            // owned by one triangle (`depth_blocks`), so every sample shows
            // what the first shows and the other planes were not written.
            if !out.flat[i0 / 8] {
                out.flat[i0 / 8] = spread_block::<V>(pass, vis, out, i0, &mut queue);
            }
        }
    }
    let p = pass.p;
    let ns = pass.size.2;
    for chunk in queue.chunks(8) {
        let mut win = [chunk[0].t; 8];
        let (mut b1, mut b2) = ([0.0f32; 8], [0.0f32; 8]);
        for (k, e) in chunk.iter().enumerate() {
            win[k] = e.t;
            let i = e.i as usize;
            let x = pass.origin.0 + (i % TILE as usize) as i32;
            let y = pass.origin.1 + (i / TILE as usize) as i32;
            (b1[k], b2[k]) = p.opaque[e.t as usize].weights_at(x, y, pass.offsets[e.s as usize]);
        }
        let lanes = (1u32 << chunk.len()) - 1;
        let (rgb, ids) =
            shade_mixed::<V, TEX>(p, pass.eye, &win, lanes, V::load(&b1), V::load(&b2));
        for (k, e) in chunk.iter().enumerate() {
            for s in e.s as usize..ns {
                let j = s * PLANE + e.i as usize;
                if vis.winner[j] == e.t {
                    out.r[j] = rgb[0][k];
                    out.g[j] = rgb[1][k];
                    out.b[j] = rgb[2][k];
                    out.ids[j] = ids[k];
                }
            }
        }
    }
    *out.queue = queue;
}

/// The other samples of the eight pixels at `i0`: the first sample's
/// colour and id where they show its triangle, the background where they
/// show none, and the rest queued (each triangle at the first sample it
/// shows in). Returns whether the block is flat — every sample shows what
/// the first shows, a triangle or none — and then writes nothing.
#[inline(always)]
fn spread_block<V: V8>(
    pass: &Pass,
    vis: &Visible,
    out: &mut Shaded,
    i0: usize,
    queue: &mut Vec<Leftover>,
) -> bool {
    let ns = pass.size.2;
    let first = *lanes8(vis.winner, i0);
    let mut flat = true;
    for s in 1..ns {
        flat &= *lanes8(vis.winner, s * PLANE + i0) == first;
    }
    if flat {
        return true;
    }
    let bg = pass.background;
    let bg = [V::splat(bg.x), V::splat(bg.y), V::splat(bg.z)];
    let c0 = [
        V::load(lanes8(out.r, i0)),
        V::load(lanes8(out.g, i0)),
        V::load(lanes8(out.b, i0)),
    ];
    let id0 = *lanes8(out.ids, i0);
    for s in 1..ns {
        let j0 = s * PLANE + i0;
        let ws = *lanes8(vis.winner, j0);
        let (mut none, mut other) = (0u32, 0u32);
        let mut ids = [0u32; 8];
        for k in 0..8 {
            let t = ws[k];
            none |= ((t == NONE) as u32) << k;
            other |= ((t != NONE && t != first[k]) as u32) << k;
            if t == first[k] {
                ids[k] = id0[k];
            }
        }
        // Queued lanes get these placeholders until they are shaded.
        let m = V::from_bits(none);
        for (dst, (b, c)) in [&mut *out.r, &mut *out.g, &mut *out.b]
            .into_iter()
            .zip(bg.into_iter().zip(c0))
        {
            V::select(m, b, c).store(lanes8_mut(dst, j0));
        }
        *lanes8_mut(out.ids, j0) = ids;
        while other != 0 {
            let k = other.trailing_zeros() as usize;
            other &= other - 1;
            let t = ws[k];
            if (1..s).all(|e| vis.winner[e * PLANE + i0 + k] != t) {
                queue.push(Leftover {
                    i: (i0 + k) as u16,
                    s: s as u8,
                    t,
                });
            }
        }
    }
    false
}

/// A tile's colour and id planes with the `flat` marks of its blocks, for
/// the passes that draw into single samples after the shading pass (lines,
/// points, transparent triangles). A flat block stays flat (one plane)
/// until a pass writes a pixel of it in some samples only; then
/// [`SamplePlanes::unflat`] writes its first plane into the others, so
/// the resolve keeps its one-plane sum for every block left untouched.
pub struct SamplePlanes<'a> {
    pub rgb: [&'a mut [f32]; 3],
    pub ids: &'a mut [u32],
    pub flat: &'a mut [bool],
    pub ns: usize,
}

impl SamplePlanes<'_> {
    /// Whether pixel `i`'s block is kept in the first plane only.
    #[inline]
    pub fn is_flat(&self, i: usize) -> bool {
        self.ns > 1 && self.flat[i / 8]
    }

    /// Gives pixel `i`'s block its colours and ids in every plane (writes
    /// the first plane into the other `ns − 1` and clears its mark), before
    /// a pass writes some of its samples.
    #[inline]
    pub fn unflat(&mut self, i: usize) {
        if !self.is_flat(i) {
            return;
        }
        let blk = i / 8;
        self.flat[blk] = false;
        let i0 = blk * 8;
        let [r, g, b] = &mut self.rgb;
        for c in [&mut **r, &mut **g, &mut **b] {
            let v = *lanes8(c, i0);
            for s in 1..self.ns {
                *lanes8_mut(c, s * PLANE + i0) = v;
            }
        }
        let v = *lanes8(self.ids, i0);
        for s in 1..self.ns {
            *lanes8_mut(self.ids, s * PLANE + i0) = v;
        }
    }

    /// Writes colour `c` and `id` into sample `j` (plane-major index).
    #[inline]
    pub fn put(&mut self, j: usize, c: Vec3, id: u32) {
        self.rgb[0][j] = c.x;
        self.rgb[1][j] = c.y;
        self.rgb[2][j] = c.z;
        self.ids[j] = id;
    }

    /// Blends colour `c` with opacity `alpha` over sample `j`.
    #[inline]
    pub fn blend(&mut self, j: usize, c: Vec3, alpha: f32, id: u32) {
        let under = Vec3::new(self.rgb[0][j], self.rgb[1][j], self.rgb[2][j]);
        self.put(j, c * alpha + under * (1.0 - alpha), id);
    }
}
