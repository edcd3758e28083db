//! The depth pass of a triangle narrower than a block (most small
//! triangles: a 100k-triangle mesh at 1280×720 has them 4 or 5 pixels
//! wide): one row at a time, the row's pixels as the lanes of one
//! window of eight pixels that holds them all.
//!
//! Why a file of its own: tested pixel by pixel, such a triangle cost a
//! test for every pixel of its box (two thirds of them outside) and a
//! scalar depth for every pixel inside; the block walk of wider
//! triangles takes aligned blocks, so a narrow triangle straddles two of
//! them in most rows. Here a row is one lane test, one depth compare, and
//! stores only in the lanes that pass. Each lane does exactly the
//! arithmetic of the pixel walk (`raster::for_each_pixel_at` and
//! `Tri::depth_at`): the same exact integer edge values, converted to f32
//! with the same rounding, the same products and sums in the same order,
//! so no bit changes.

use super::fragment::{PLANE, TILE};
use super::prepare::{Tri, SUBPIXEL};
use super::simd::V8;

/// What a narrow triangle writes into: depth and winner planes (all
/// samples) and the first sample's weights, `TILE` pixels per row.
pub struct NarrowBufs<'a> {
    pub depth: &'a mut [f32],
    pub winner: &'a mut [u32],
    pub b1: &'a mut [f32],
    pub b2: &'a mut [f32],
}

/// Keeps triangle `ti` (`t`) at each sample `offs` of the pixels
/// `[x0, x1) × [y0, y1)` of the tile `rect` where it covers the sample and
/// is nearer than what is there (and not behind the eye's near limit, z ≥
/// 0), as the pixel walk does: depth and winner at that sample's plane,
/// the weights at the first sample. `x1 − x0` is at most 8.
#[inline(always)]
pub fn narrow_depth<V: V8, const NS: usize>(
    t: &Tri,
    ti: u32,
    rect: [i32; 4],
    [x0, y0, x1, y1]: [i32; 4],
    offs: &[(i64, i64); NS],
    bufs: &mut NarrowBufs,
) {
    debug_assert!(x1 - x0 <= 8 && x0 < x1 && y0 < y1);
    // The window: eight pixels of a tile row from column `col`, holding
    // x0..x1 and inside the row (tile rows are TILE long whatever the
    // tile's width, so the buffers hold it).
    let col = ((x0 - rect[0]) as usize).min(TILE as usize - 8);
    let xw = rect[0] + col as i32;
    let (lo, hi) = (x0 - xw, x1 - xw);
    let in_box = (0xFFu32 << lo) & (0xFF >> (8 - hi));
    let inv_area = V::splat(1.0 / t.area() as f32);
    let (z0, dz1, dz2) = (
        V::splat(t.z[0]),
        V::splat(t.z[1] - t.z[0]),
        V::splat(t.z[2] - t.z[0]),
    );
    let zero = V::splat(0.0);
    for (si, &off) in offs.iter().enumerate() {
        let px = xw as i64 * SUBPIXEL + SUBPIXEL / 2 + off.0;
        let py = y0 as i64 * SUBPIXEL + SUBPIXEL / 2 + off.1;
        let ed: [(i64, i64, i64); 3] = std::array::from_fn(|k| t.edge(k, px, py));
        // Lanes go through exact f64 (`V8::from_edge`, the bits of
        // `i64 as f32`) while every value they take stays below 2⁵²:
        // with |e| < 2⁵¹ and steps below 2⁴⁴ it does over 8 lanes and 32
        // rows. Always, near the screen; else this sample is walked
        // pixel by pixel.
        let exact = ed.iter().all(|&(e, sx, sy)| {
            e.unsigned_abs() < 1 << 51 && sx.unsigned_abs() < 1 << 44 && sy.unsigned_abs() < 1 << 44
        });
        if !exact {
            walk_sample(t, ti, rect, [x0, y0, x1, y1], (si, off), bufs);
            continue;
        }
        let mut e = ed.map(|(e, _, _)| e);
        let plane = si * PLANE;
        let mut i0 = plane + (y0 - rect[1]) as usize * TILE as usize + col;
        for _ in y0..y1 {
            let e0 = V::from_edge(e[0], ed[0].1);
            let e1 = V::from_edge(e[1], ed[1].1);
            let e2 = V::from_edge(e[2], ed[2].1);
            // A lane is outside when an edge is negative there; an
            // integer's conversion keeps its sign (0 gives +0).
            let inside = in_box & !e0.or(e1).or(e2).bits();
            if inside != 0 {
                let w1 = e1 * inv_area;
                let w2 = e2 * inv_area;
                let z = z0 + w1 * dz1 + w2 * dz2;
                let depth: &mut [f32; 8] =
                    (&mut bufs.depth[i0..i0 + 8]).try_into().expect("8 lanes");
                let mut pass = V::load(depth).gt(z).and(zero.le(z)).bits() & inside;
                if pass != 0 {
                    let mut zs = [0.0; 8];
                    z.store(&mut zs);
                    let winner: &mut [u32; 8] =
                        (&mut bufs.winner[i0..i0 + 8]).try_into().expect("8 lanes");
                    if si == 0 {
                        let (mut w1s, mut w2s) = ([0.0; 8], [0.0; 8]);
                        w1.store(&mut w1s);
                        w2.store(&mut w2s);
                        let b1: &mut [f32; 8] =
                            (&mut bufs.b1[i0..i0 + 8]).try_into().expect("8 lanes");
                        let b2: &mut [f32; 8] =
                            (&mut bufs.b2[i0..i0 + 8]).try_into().expect("8 lanes");
                        while pass != 0 {
                            let l = pass.trailing_zeros() as usize;
                            depth[l] = zs[l];
                            winner[l] = ti;
                            b1[l] = w1s[l];
                            b2[l] = w2s[l];
                            pass &= pass - 1;
                        }
                    } else {
                        while pass != 0 {
                            let l = pass.trailing_zeros() as usize;
                            depth[l] = zs[l];
                            winner[l] = ti;
                            pass &= pass - 1;
                        }
                    }
                }
            }
            for (e, s) in e.iter_mut().zip(&ed) {
                *e += s.2;
            }
            i0 += TILE as usize;
        }
    }
}

/// One sample plane of [`narrow_depth`] pixel by pixel, with scalar
/// arithmetic: for edge values too large for exact lanes (a triangle
/// reaching far outside the screen), never in practice.
#[cold]
#[inline(never)]
fn walk_sample(
    t: &Tri,
    ti: u32,
    rect: [i32; 4],
    [x0, y0, x1, y1]: [i32; 4],
    (si, off): (usize, (i64, i64)),
    bufs: &mut NarrowBufs,
) {
    let inv_area = 1.0 / t.area() as f32;
    let plane = si * PLANE;
    for y in y0..y1 {
        for x in x0..x1 {
            let px = x as i64 * SUBPIXEL + SUBPIXEL / 2 + off.0;
            let py = y as i64 * SUBPIXEL + SUBPIXEL / 2 + off.1;
            let e: [i64; 3] = std::array::from_fn(|k| t.edge(k, px, py).0);
            if (e[0] | e[1] | e[2]) < 0 {
                continue;
            }
            let (w1, w2) = (e[1] as f32 * inv_area, e[2] as f32 * inv_area);
            let z = t.depth_at(w1, w2);
            let i = (y - rect[1]) as usize * TILE as usize + (x - rect[0]) as usize;
            if z < bufs.depth[plane + i] && z >= 0.0 {
                bufs.depth[plane + i] = z;
                bufs.winner[plane + i] = ti;
                if si == 0 {
                    bufs.b1[i] = w1;
                    bufs.b2[i] = w2;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::internals::render::test_rng::XorShift;
    use crate::render::fragment::NONE;
    use crate::render::prepare::test_tri;
    use crate::render::raster::{for_each_pixel_at, sample_offsets};
    use crate::render::simd::Sse8;

    /// One way of drawing a triangle's narrow box into buffers.
    type Lanes<'a> = dyn Fn(&Tri, u32, [i32; 4], &mut NarrowBufs) + 'a;

    /// Seeded triangles 1 to 8 pixels wide anywhere over a tile (at its
    /// right edge too, where the window stops at the row's end), over
    /// one another with random and tied depths, some reaching behind
    /// the near limit, at 1, 4 and 8 samples: depth, winner and weights
    /// are bit for bit those of the pixel walk, on SSE2 lanes and (where
    /// the CPU has it) AVX.
    #[test]
    fn rows_of_lanes_keep_the_pixel_walks_bits() {
        let mut rng = XorShift::new(0x9E37_79B9_7F4A_7C15);
        let mut next = || rng.unit();
        let rect = [128, 64, 192, 96];
        let (mut kept, mut tris, mut walked) = (0, 0, 0);
        for scene in 0..300 {
            let mut list = Vec::new();
            for k in 0..1 + scene % 9 {
                let x = 126.0 + next() * 70.0;
                let y = 62.0 + next() * 36.0;
                let mut pts = [0, 1, 2].map(|_| (x + next() * 7.0, y + next() * 14.0));
                if scene % 10 == 3 && k == 0 {
                    // Reaching two million pixels to the right (past any
                    // guard band), narrow where the tile's right edge
                    // cuts it: its edge values are too large for exact
                    // lanes, so it is walked pixel by pixel.
                    let y = 64.0 + next() * 30.0;
                    pts = [(187.3, y), (187.3 + 2e6, y - 2e6), (187.3 + 2e6, y + 2e6)];
                }
                let z = match scene % 4 {
                    0 => [0.5; 3],
                    1 => [-0.2, 0.3, 0.6],
                    _ => [0, 1, 2].map(|_| next() as f32),
                };
                let t = test_tri(pts, z);
                let far = (0..3)
                    .any(|k| t.edge(k, 188 * SUBPIXEL, 80 * SUBPIXEL).0.unsigned_abs() >= 1 << 51);
                walked += far as usize;
                if t.area() != 0 {
                    list.push(t);
                }
            }
            for ns in [1usize, 4, 8] {
                let offs = sample_offsets(ns);
                let mut want = (vec![1.0f32; ns * PLANE], vec![NONE; ns * PLANE]);
                let mut want_b = (vec![0.0f32; PLANE], vec![0.0f32; PLANE]);
                for (ti, t) in list.iter().enumerate() {
                    for (s, &off) in offs.iter().enumerate() {
                        for_each_pixel_at(t, rect, off, |x, y, w1, w2| {
                            let z = t.depth_at(w1, w2);
                            let i = (y - rect[1]) as usize * TILE as usize + (x - rect[0]) as usize;
                            if z < want.0[s * PLANE + i] && z >= 0.0 {
                                want.0[s * PLANE + i] = z;
                                want.1[s * PLANE + i] = ti as u32;
                                if s == 0 {
                                    (want_b.0[i], want_b.1[i]) = (w1, w2);
                                }
                            }
                        });
                    }
                }
                let run = |lanes: &Lanes<'_>| {
                    let (mut depth, mut winner) =
                        (vec![1.0f32; ns * PLANE], vec![NONE; ns * PLANE]);
                    let (mut b1, mut b2) = (vec![0.0f32; PLANE], vec![0.0f32; PLANE]);
                    for (ti, t) in list.iter().enumerate() {
                        let x0 = t.bbox[0].max(rect[0]);
                        let y0 = t.bbox[1].max(rect[1]);
                        let x1 = t.bbox[2].min(rect[2]);
                        let y1 = t.bbox[3].min(rect[3]);
                        if x0 < x1 && y0 < y1 {
                            let bufs = &mut NarrowBufs {
                                depth: &mut depth,
                                winner: &mut winner,
                                b1: &mut b1,
                                b2: &mut b2,
                            };
                            lanes(t, ti as u32, [x0, y0, x1, y1], bufs);
                        }
                    }
                    (depth, winner, b1, b2)
                };
                let mut got = vec![run(&|t, ti, r, bufs| match ns {
                    1 => narrow_depth::<Sse8, 1>(t, ti, rect, r, offs.try_into().unwrap(), bufs),
                    4 => narrow_depth::<Sse8, 4>(t, ti, rect, r, offs.try_into().unwrap(), bufs),
                    _ => narrow_depth::<Sse8, 8>(t, ti, rect, r, offs.try_into().unwrap(), bufs),
                })];
                #[cfg(target_arch = "x86_64")]
                if crate::render::simd::avx() {
                    use crate::render::simd::Avx8;
                    // SAFETY: the CPU has AVX (checked above).
                    got.push(run(&|t, ti, r, bufs| unsafe {
                        avx_lanes(t, ti, rect, r, offs, bufs)
                    }));
                    #[target_feature(enable = "avx")]
                    unsafe fn avx_lanes(
                        t: &Tri,
                        ti: u32,
                        rect: [i32; 4],
                        r: [i32; 4],
                        offs: &[(i64, i64)],
                        bufs: &mut NarrowBufs,
                    ) {
                        match offs.len() {
                            1 => narrow_depth::<Avx8, 1>(
                                t,
                                ti,
                                rect,
                                r,
                                offs.try_into().unwrap(),
                                bufs,
                            ),
                            4 => narrow_depth::<Avx8, 4>(
                                t,
                                ti,
                                rect,
                                r,
                                offs.try_into().unwrap(),
                                bufs,
                            ),
                            _ => narrow_depth::<Avx8, 8>(
                                t,
                                ti,
                                rect,
                                r,
                                offs.try_into().unwrap(),
                                bufs,
                            ),
                        }
                    }
                }
                for (depth, winner, b1, b2) in got {
                    for j in 0..ns * PLANE {
                        assert_eq!(
                            depth[j].to_bits(),
                            want.0[j].to_bits(),
                            "scene {scene} ns {ns}"
                        );
                        assert_eq!(winner[j], want.1[j], "scene {scene} ns {ns} at {j}");
                    }
                    for i in 0..PLANE {
                        assert_eq!(b1[i].to_bits(), want_b.0[i].to_bits());
                        assert_eq!(b2[i].to_bits(), want_b.1[i].to_bits());
                    }
                }
                kept += want.1.iter().filter(|&&w| w != NONE).count();
                tris += list.len();
            }
        }
        assert!(
            kept > 20_000 && tris > 2000,
            "{kept} samples kept, {tris} triangles"
        );
        assert!(walked >= 30, "{walked} triangles too large for exact lanes");
    }
}
