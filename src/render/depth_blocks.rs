//! What the depth pass knows of each block of eight pixels of a tile, so
//! that it writes sample planes only where something needs them.
//!
//! A block is in one of three states:
//! - **empty**: no triangle touched it; every sample holds depth 1 and no
//!   winner, but only the first plane's winners are written (the shading
//!   pass reads them);
//! - **owned** by one triangle: the first triangle to touch an empty
//!   block covered all its samples and passed the depth test at each (its
//!   depths lie safely inside (0, 1)); only the first plane's winners and
//!   the first sample's weights are written, as the full pass writes them;
//! - **planes**: depth and winner are written in every sample plane.
//!
//! Under multisampling most of a picture is empty or owned by one large
//! triangle (the sky, a floor), so most blocks never have their other
//! planes cleared, tested or written; the shading pass knows them flat
//! without comparing planes. A block becomes `planes` before anything else
//! touches it ([`make_planes`]): the owner's depths are then computed with
//! the very arithmetic the full pass uses (the same integer edge values
//! and float operations), so nothing downstream sees a different bit.

use super::fragment::{NONE, PLANE, TILE};
use super::prepare::{Tri, SUBPIXEL};
use super::simd::{Lanes, Sse8, V8};

/// Block state: no triangle touched it.
pub const EMPTY: u32 = NONE;
/// Block state: depth and winner are written in every sample plane (any
/// other value is the index of the triangle owning the block).
pub const PLANES: u32 = NONE - 1;

/// Blocks of eight pixels per tile row.
pub const BLOCKS_PER_ROW: usize = TILE as usize / 8;

/// How far inside (0, 1) a triangle's window depth must stay over a
/// rectangle for it to own blocks there: its depth at a covered sample is
/// a convex combination of its corners' computed with a few f32 roundings
/// (below 1e-6 for depths within 0..1), so it then passes the test
/// against a cleared depth (`z < 1 && z ≥ 0`) without being computed.
const Z_MARGIN: f64 = 1e-5;

/// Whether triangle `t` may own blocks of the pixels `[x0, x1) × [y0, y1)`:
/// its depth plane (affine in screen space, so extreme at the corners of
/// the rectangle, which holds every sample of those pixels) stays within
/// [`Z_MARGIN`] of the inside of (0, 1) there. Worked out in f64 from the
/// exact edge values; the margin dwarfs its error.
pub fn may_own(t: &Tri, [x0, y0, x1, y1]: [i32; 4]) -> bool {
    let area = t.area() as f64;
    let (dz1, dz2) = (t.z[1] as f64 - t.z[0] as f64, t.z[2] as f64 - t.z[0] as f64);
    [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]
        .into_iter()
        .all(|(x, y)| {
            let (px, py) = (x as i64 * SUBPIXEL, y as i64 * SUBPIXEL);
            let b1 = t.edge(1, px, py).0 as f64 / area;
            let b2 = t.edge(2, px, py).0 as f64 / area;
            let z = t.z[0] as f64 + b1 * dz1 + b2 * dz2;
            (Z_MARGIN..=1.0 - Z_MARGIN).contains(&z)
        })
}

/// The depth pass's buffers, `TILE` pixels per row: depth and winner for
/// every sample plane, the weights only for the first sample (the shading
/// pass recomputes the few it needs at other samples, `Tri::weights_at`),
/// and the state of each block (see the module's notes).
pub struct DepthBufs<'a> {
    pub depth: &'a mut [f32],
    pub winner: &'a mut [u32],
    pub b1: &'a mut [f32],
    pub b2: &'a mut [f32],
    pub blocks: &'a mut [u32],
}

/// Lanes `(e + l·s) as f32`, through exact f64 when `exact` (a function,
/// not a closure: closures lose the caller's AVX target feature and their
/// lane operations stop being inlined). Either way the same bits.
#[inline(always)]
pub fn edge_lanes<V: V8>(exact: bool, e: i64, s: i64) -> V {
    if exact {
        V::from_edge(e, s)
    } else {
        let mut a = [0.0; 8];
        for (l, a) in a.iter_mut().enumerate() {
            *a = (e + l as i64 * s) as f32;
        }
        V::load(&a)
    }
}

/// Writes depth and winner of every sample plane of block `blk` from its
/// state and marks it `planes`: 1 and no winner for an empty block; for
/// an owned one, the owner at every sample with its depth there, computed
/// as the full pass computes it (edge values exact integers at the
/// sample, the same conversion and float operations). `tris` are the
/// tile's opaque triangles by index, `rect` the tile, `offs` the samples.
#[inline(always)]
pub fn make_planes<const NS: usize>(
    tris: &[Tri],
    rect: [i32; 4],
    offs: &[(i64, i64); NS],
    blk: usize,
    bufs: &mut DepthBufs,
) {
    if bufs.blocks[blk] != PLANES {
        write_planes(tris, rect, offs, blk, bufs);
    }
}

/// [`make_planes`] for a block not yet in planes: out of the depth pass's
/// loops (it runs once per block at most), on SSE2 lanes, which give the
/// bits of every other lane width.
#[cold]
#[inline(never)]
fn write_planes<const NS: usize>(
    tris: &[Tri],
    rect: [i32; 4],
    offs: &[(i64, i64); NS],
    blk: usize,
    bufs: &mut DepthBufs,
) {
    let state = bufs.blocks[blk];
    bufs.blocks[blk] = PLANES;
    let i0 = blk * 8;
    if state == EMPTY {
        for s in 0..NS {
            let j = s * PLANE + i0;
            bufs.depth[j..j + 8].fill(1.0);
            bufs.winner[j..j + 8].fill(NONE);
        }
        return;
    }
    let t = &tris[state as usize];
    let x = rect[0] as i64 + (i0 % TILE as usize) as i64;
    let y = rect[1] as i64 + (i0 / TILE as usize) as i64;
    let inv_area = Sse8::splat(1.0 / t.area() as f32);
    let (z0, dz1, dz2) = (
        Sse8::splat(t.z[0]),
        Sse8::splat(t.z[1] - t.z[0]),
        Sse8::splat(t.z[2] - t.z[0]),
    );
    for (s, &off) in offs.iter().enumerate() {
        let px = x * SUBPIXEL + SUBPIXEL / 2 + off.0;
        let py = y * SUBPIXEL + SUBPIXEL / 2 + off.1;
        let (e1, s1, _) = t.edge(1, px, py);
        let (e2, s2, _) = t.edge(2, px, py);
        let small = |e: i64, s: i64| {
            e.saturating_abs()
                .saturating_add(s.saturating_abs().saturating_mul(8))
                < 1 << 52
        };
        let exact = small(e1, s1) && small(e2, s2);
        let w1 = edge_lanes::<Sse8>(exact, e1, s1) * inv_area;
        let w2 = edge_lanes::<Sse8>(exact, e2, s2) * inv_area;
        let z = z0 + w1 * dz1 + w2 * dz2;
        let j = s * PLANE + i0;
        let depth: &mut [f32; 8] = (&mut bufs.depth[j..j + 8]).try_into().expect("8 lanes");
        z.store(depth);
        bufs.winner[j..j + 8].fill(state);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::prepare::{test_tri, Prepared};
    use crate::render::raster::{depth_tile, for_each_pixel_at, sample_offsets, Bin, Scratch};
    use crate::render::test_rng::XorShift;

    /// [`test_tri`] with its box clamped to the 200×100 picture.
    fn tri(pts: [(f64, f64); 3], z: [f32; 3]) -> Tri {
        let mut t = test_tri(pts, z);
        t.bbox = [
            t.bbox[0].max(0),
            t.bbox[1].max(0),
            t.bbox[2].min(200),
            t.bbox[3].min(100),
        ];
        t
    }

    /// Scenes of large triangles (which own blocks), small ones, ones
    /// reaching the near or far plane (which may not) and exact depth ties,
    /// drawn over a tile at 1, 4 and 8 samples: with every plane written out,
    /// depth, winner and the first sample's weights are bit for bit those
    /// of the plain per-pixel walk; left as they are, the first plane's
    /// winners and weights are the same and an owned or empty block shows
    /// one triangle (or none) at every sample of the reference.
    #[test]
    fn blocks_keep_the_per_pixel_walks_bits() {
        let mut rng = XorShift::new(0x9E37_79B9_7F4A_7C15);
        let rect = [64, 32, 128, 64];
        let mut owned_seen = 0;
        for scene in 0..60 {
            let mut p = Prepared::default();
            for k in 0..1 + scene % 7 {
                let big = k % 3 == 0;
                let (cx, cy) = (64.0 + rng.unit() * 64.0, 32.0 + rng.unit() * 32.0);
                let r = if big {
                    40.0 + rng.unit() * 80.0
                } else {
                    1.0 + rng.unit() * 12.0
                };
                let pts = [0, 1, 2].map(|_| {
                    (
                        cx + (rng.unit() - 0.5) * 2.0 * r,
                        cy + (rng.unit() - 0.5) * 2.0 * r,
                    )
                });
                let z = match scene % 5 {
                    0 => [0.5; 3],
                    1 => [0.0, 0.3, 0.6],
                    2 => [0.9, 1.0, 1.2],
                    _ => [0, 1, 2].map(|_| 0.05 + 0.9 * rng.unit() as f32),
                };
                let t = tri(pts, z);
                if t.area() != 0 {
                    p.opaque.push(t);
                }
            }
            let bin = Bin {
                opaque: (0..p.opaque.len() as u32).collect(),
                ..Bin::default()
            };
            for ns in [1usize, 4, 8] {
                let offs = sample_offsets(ns);
                // The reference: every triangle, pixel and sample in turn.
                let mut depth = vec![1.0f32; ns * PLANE];
                let mut winner = vec![NONE; ns * PLANE];
                let (mut b1, mut b2) = (vec![0.0f32; PLANE], vec![0.0f32; PLANE]);
                for (ti, t) in p.opaque.iter().enumerate() {
                    for (s, &off) in offs.iter().enumerate() {
                        for_each_pixel_at(t, rect, off, |x, y, w1, w2| {
                            let z = t.depth_at(w1, w2);
                            let i = (y - rect[1]) as usize * TILE as usize + (x - rect[0]) as usize;
                            if z < depth[s * PLANE + i] && z >= 0.0 {
                                depth[s * PLANE + i] = z;
                                winner[s * PLANE + i] = ti as u32;
                                if s == 0 {
                                    (b1[i], b2[i]) = (w1, w2);
                                }
                            }
                        });
                    }
                }
                for need_planes in [true, false] {
                    let mut scratch = Scratch::new(ns);
                    depth_tile(&p, &bin, rect, &mut scratch, need_planes);
                    let (d, w, c1, c2, blocks) = scratch.depth_results();
                    for i in 0..PLANE {
                        assert_eq!(w[i], winner[i], "scene {scene} ns {ns} pixel {i}");
                        if winner[i] != NONE {
                            assert_eq!(c1[i].to_bits(), b1[i].to_bits());
                            assert_eq!(c2[i].to_bits(), b2[i].to_bits());
                        }
                    }
                    if need_planes {
                        assert!(blocks.iter().all(|&b| b == PLANES));
                        for j in 0..ns * PLANE {
                            assert_eq!(d[j].to_bits(), depth[j].to_bits(), "scene {scene} ns {ns}");
                            assert_eq!(w[j], winner[j], "scene {scene} ns {ns} sample {j}");
                        }
                        continue;
                    }
                    for (blk, &state) in blocks.iter().enumerate() {
                        if state == PLANES {
                            continue;
                        }
                        owned_seen += (state != EMPTY) as usize;
                        for s in 0..ns {
                            let j = s * PLANE + blk * 8;
                            assert!(winner[j..j + 8].iter().all(|&t| t == state));
                        }
                    }
                }
            }
        }
        assert!(
            owned_seen > 1000,
            "large triangles own blocks: {owned_seen}"
        );
    }
}
