//! Trilinear sampling of eight lanes that all read the same mip level
//! pair: the common case (a plane, a model's face, anything whose texture
//! scale changes slowly across eight pixels), and the fast path of
//! [`Sampler::texel8`](super::texture::Sampler).
//!
//! Why a path of its own: with one level per block the level's size is a
//! constant, so the texel addresses are computed on lanes (row · width +
//! column, whole numbers below 2²⁴ and so exact in f32), the coordinates
//! are reduced to one period once for both levels, and the four corners of
//! each lane come from one gather per corner where the CPU has AVX2
//! (`texel_fetch`) instead of per-lane level lookups and index arithmetic.
//! The filtering arithmetic is `Sampler::bilinear`'s, operation for
//! operation, so the bits do not change.

use super::simd::{Lanes, V8};
use super::texel_fetch::{fetch4, fetch_pairs};
use super::texel_filter::{bilerp, UNIT};
use super::texture::Sampler;
#[cfg(target_arch = "x86_64")]
use super::trilinear16;
use crate::scene::{MipLevel, Wrap};

/// The filtered alpha of four texels of alpha 255: `bilerp` gives
/// 255·256 for any weights, then × [`UNIT`] (const arithmetic is IEEE
/// f32, the same as at run time). Blending two levels of it gives it again.
pub(super) const OPAQUE: f32 = (255.0 * 256.0) * UNIT;

/// Largest level (in texels) whose addresses stay exact in f32 lanes.
const EXACT_TEXELS: u64 = 1 << 24;

impl Sampler {
    /// The trilinear texel of eight lanes when they share their level pair,
    /// `None` otherwise (or for levels too large to address in f32). `lod`
    /// is each lane's level of detail (finite, ≥ 0); `u`, `v` the
    /// untransformed coordinates. With `wide` (which the caller checked
    /// with `simd::avx512()`) two levels blend in one 16-lane AVX-512 pass
    /// (`trilinear16`), else in two eight-lane passes: the same bits
    /// either way.
    #[cfg(test)]
    pub(super) fn texel8_one_level<V: V8>(&self, lod: V, u: V, v: V, wide: bool) -> Option<[V; 4]> {
        let last = self.image().levels().len() - 1;
        // `Sampler::sample`'s choice: level `lod as usize` and the next,
        // or the last level alone from `lod ≥ last` on. Truncating
        // min(lod, last) names both cases by one number per lane.
        let i = lod.min(V::splat(last as f32)).trunc_i32();
        if i.iter().any(|&k| k != i[0]) {
            return None;
        }
        self.texel8_at_level(i[0] as usize, lod, u, v, wide)
    }

    /// [`Sampler::texel8_one_level`] for lanes whose level pair was
    /// guessed to start at level `i` (`None` where any lane's level is
    /// another). Why a guess: the level's size starts the long chain of
    /// the footprint, fetch and filter; named before the level of detail
    /// is known (from the exponent of ρ², `texture_lanes`), that chain
    /// does not wait for λ's polynomial, which only the blend fraction at
    /// the end needs. The check below is a branch, which the CPU predicts,
    /// not a wait.
    #[inline(always)]
    pub(super) fn texel8_at_level<V: V8>(
        &self,
        i: usize,
        lod: V,
        u: V,
        v: V,
        wide: bool,
    ) -> Option<[V; 4]> {
        let last = self.image().levels().len() - 1;
        if i > last {
            return None;
        }
        let exact = lod.min(V::splat(last as f32)).trunc_i32();
        if exact.iter().any(|&k| k != i as i32) {
            return None;
        }
        self.texel8_levels((i, lod), (u, v), false, wide)
    }

    /// [`Sampler::texel8_at_level`] once the level pair is known to start
    /// at level `i` in every lane (`lod` truncates to `i`, or `i` is the
    /// last level and no lane's `lod` is below it): `None` only for a
    /// level too large to address in f32 lanes. `finite`: every lane of
    /// `u` and `v` is known to be finite (the test for it is skipped).
    #[inline(always)]
    pub(super) fn texel8_levels<V: V8>(
        &self,
        (i, lod): (usize, V),
        (u, v): (V, V),
        finite: bool,
        wide: bool,
    ) -> Option<[V; 4]> {
        let levels = self.image().levels();
        let last = levels.len() - 1;
        let level = &levels[i];
        if level.width() as u64 * level.height() as u64 > EXACT_TEXELS {
            return None;
        }
        let (s, t) = if finite {
            self.wrap8(u, v)
        } else {
            self.reduce8(u, v)
        };
        // `lod − i as f32`; a block that needs no blending (all magnified,
        // or exactly on a level) reads one level, as `sample` does.
        let f = lod - V::splat(i as f32);
        let blend = i != last && f.eq(V::splat(0.0)).bits() != 0xFF;
        #[cfg(not(target_arch = "x86_64"))]
        let _ = wide;
        #[cfg(target_arch = "x86_64")]
        if let (true, Some(sizes)) = (blend && wide, self.pair_sizes(i)) {
            let levels = [level, &levels[i + 1]];
            let wrap = [self.wrap_s(), self.wrap_t()];
            // SAFETY: the caller checked `simd::avx512()` (AVX-512 F, VL,
            // BW, DQ); the finer level holds at most 2²⁴ texels (above).
            let out = unsafe {
                trilinear16::sample(
                    levels,
                    sizes,
                    s.to_m256(),
                    t.to_m256(),
                    f.to_m256(),
                    wrap,
                    !self.opaque(),
                )
            };
            // (Not `out.map(..)`: a closure lacks the caller's target
            // features, and lane operations inside it become calls.)
            return Some([
                V::from_m256(out[0]),
                V::from_m256(out[1]),
                V::from_m256(out[2]),
                V::from_m256(out[3]),
            ]);
        }
        let a = self.bilinear_level8(level, s, t);
        if !blend {
            return Some(a);
        }
        let b = self.bilinear_level8(&levels[i + 1], s, t);
        let mut out = a;
        for c in 0..4 {
            out[c] = a[c] + (b[c] - a[c]) * f;
        }
        Some(out)
    }

    /// `Sampler::bilinear`'s first steps, shared by both levels:
    /// non-finite coordinates read as 0, repeating ones are reduced to one
    /// period.
    #[inline(always)]
    pub(super) fn reduce8<V: V8>(&self, s: V, t: V) -> (V, V) {
        self.wrap8(s.keep(finite(s)), t.keep(finite(t)))
    }

    /// [`Sampler::reduce8`] of finite coordinates: repeating ones reduced
    /// to one period.
    #[inline(always)]
    fn wrap8<V: V8>(&self, s: V, t: V) -> (V, V) {
        let s = if self.wrap_s() == Wrap::Repeat {
            s - s.floor()
        } else {
            s
        };
        let t = if self.wrap_t() == Wrap::Repeat {
            t - t.floor()
        } else {
            t
        };
        (s, t)
    }

    /// `Sampler::bilinear` in one level for eight lanes of reduced
    /// coordinates (see [`Sampler::reduce8`]), as R, G, B, A in 0..1.
    #[inline(always)]
    fn bilinear_level8<V: V8>(&self, level: &MipLevel, s: V, t: V) -> [V; 4] {
        let (w, h) = (
            V::splat(level.width() as f32),
            V::splat(level.height() as f32),
        );
        let f = self.footprint8(s, t, w, h);
        // Texel addresses: whole numbers below 2²⁴ (the caller checked the
        // level's size), so every product and sum here is exact.
        let (ra, rb) = (f.ya * w, f.yb * w);
        let (a, b) = ((ra + f.xa).trunc_i32(), (rb + f.xa).trunc_i32());
        // Right texels next to the left ones in every lane (the block
        // crosses no wrap seam or clamped edge): fetched as pairs.
        let corners = if (f.xb - f.xa).eq(V::splat(1.0)).bits() == 0xFF {
            fetch_pairs(level.pixels(), &a, &b)
        } else {
            let idx = [a, (ra + f.xb).trunc_i32(), b, (rb + f.xb).trunc_i32()];
            fetch4(level.pixels(), &idx)
        };
        filter(&corners, f.fx, f.fy, !self.opaque())
    }
}

/// Where a bilinear lookup reads in a level: the wrapped texel columns
/// `xa`, `xb` and rows `ya`, `yb` (whole numbers) and the blend fractions.
pub(super) struct Footprint<V> {
    pub xa: V,
    pub xb: V,
    pub ya: V,
    pub yb: V,
    pub fx: V,
    pub fy: V,
}

impl Sampler {
    /// The [`Footprint`] of reduced coordinates `s`, `t` (see
    /// [`Sampler::reduce8`]) in a level of `w`×`h` texels (per lane).
    #[inline(always)]
    pub(super) fn footprint8<V: V8>(&self, s: V, t: V, w: V, h: V) -> Footprint<V> {
        let x = s * w - V::splat(0.5);
        // Rows are stored top first; t = 0 is the bottom row.
        let y = (V::splat(1.0) - t) * h - V::splat(0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        // `clamp(-2, w)` as in the scalar path (x0 is finite here), then the
        // two wrapped indices per axis on lanes (small whole numbers, exact).
        let x0 = x0.max(V::splat(-2.0)).min(w);
        let y0 = y0.max(V::splat(-2.0)).min(h);
        let (xa, xb) = wrap2(x0, w, self.wrap_s());
        let (ya, yb) = wrap2(y0, h, self.wrap_t());
        Footprint {
            xa,
            xb,
            ya,
            yb,
            fx,
            fy,
        }
    }
}

/// The bilinear blend of the four corners' RGBA8 words (top left, top
/// right, bottom left, bottom right) by the fractions `fx`, `fy`, as R, G,
/// B, A in 0..1: `Sampler::bilinear`'s fixed-point filter
/// (`texel_filter`), its weights rounded by the same f32 steps as
/// `texel_filter::weight`. Without `alpha` (an image whose texels are all
/// opaque) the alpha lanes are that filter's result for four 255s,
/// [`OPAQUE`], without converting it.
// Lane k of four corner arrays at once: an index loop reads best.
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub(super) fn filter<V: V8>(corner: &[[u32; 8]; 4], fx: V, fy: V, alpha: bool) -> [V; 4] {
    let (scale, half) = (V::splat(256.0), V::splat(0.5));
    // Weights in 0..=256 (`weight`'s range; `trunc_i32` gives i32::MIN
    // where a clamped coordinate overflowed to ±∞ and the fraction is NaN:
    // there both texels of that axis are the same edge texel, so any
    // weight gives the one-pixel result, and `bilerp` must not overflow).
    let wx = (fx * scale + half).trunc_i32().map(|w| w.clamp(0, 256));
    let wy = (fy * scale + half).trunc_i32().map(|w| w.clamp(0, 256));
    // Integer lanes (LLVM vectorises these loops with the caller's
    // instruction set).
    let mut ch = [[0.0f32; 8]; 4];
    for k in 0..8 {
        let c = [corner[0][k], corner[1][k], corner[2][k], corner[3][k]];
        let [rb, ga] = bilerp(c, wx[k] as u32, wy[k] as u32);
        ch[0][k] = (rb & 0xFFFF) as f32;
        ch[1][k] = (ga & 0xFFFF) as f32;
        ch[2][k] = (rb >> 16) as f32;
        ch[3][k] = (ga >> 16) as f32;
    }
    let unit = V::splat(UNIT);
    [
        V::load(&ch[0]) * unit,
        V::load(&ch[1]) * unit,
        V::load(&ch[2]) * unit,
        if alpha {
            V::load(&ch[3]) * unit
        } else {
            V::splat(OPAQUE)
        },
    ]
}

/// The lanes as an array.
#[cfg(test)]
#[inline(always)]
fn to_arr<V: V8>(v: V) -> [f32; 8] {
    let mut a = [0.0; 8];
    v.store(&mut a);
    a
}

/// A mask of the finite lanes.
#[inline(always)]
pub(super) fn finite<V: V8>(x: V) -> V {
    Lanes::le(V::splat(-f32::MAX), x).and(x.le(V::splat(f32::MAX)))
}

/// `texture::wrap` of the texel indices `i` and `i + 1` for lanes of whole
/// numbers in −2..=n (`n` per lane, the level's size): repeat is
/// `rem_euclid` (by one period's addition or subtraction, see
/// [`repeat_once`]), clamp is `clamp(i, 0, n − 1)`. Mirror never comes
/// here (see `Sampler::lanes_cover`).
#[inline(always)]
fn wrap2<V: V8>(i: V, n: V, mode: Wrap) -> (V, V) {
    let one = V::splat(1.0);
    let j = i + one;
    match mode {
        Wrap::Clamp => {
            let (lo, hi) = (V::splat(0.0), n - one);
            (i.max(lo).min(hi), j.max(lo).min(hi))
        }
        // Repeat: i lies in −2..=n (the clamp before), j = i + 1, so one
        // period up or down wraps them (small whole numbers: exact, the
        // same as `rem_euclid`, with no division).
        _ => (repeat_once(i, n), repeat_once(j, n)),
    }
}

/// `i` wrapped into 0..n for whole-number lanes in −2..=n + 1: one period
/// up or down, then a clamp that only acts for n = 1 (where two periods
/// may be needed and the answer is 0).
#[inline(always)]
fn repeat_once<V: V8>(i: V, n: V) -> V {
    let zero = V::splat(0.0);
    let once = i + n.keep(zero.gt(i)) - n.keep(n.le(i));
    once.max(zero).min(n - V::splat(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::simd::Sse8;
    use crate::render::texture_lanes::tests::{assert_lanes_match, image};
    use crate::scene::{ImageId, Texture};
    use glam::Vec2;

    /// Blocks whose lanes share a level pair take the one-level path, and
    /// every lane gets `texel`'s exact bits: magnified (no blending),
    /// blended between two levels, beyond the last level, repeat and clamp,
    /// power-of-two and odd sizes, coordinates far outside 0..1, images
    /// with alpha and opaque ones (whose alpha lanes are not filtered).
    #[test]
    #[allow(clippy::needless_range_loop)]
    fn shared_level_blocks_match_one_pixel_bit_for_bit() {
        let mut seed = 777u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32
        };
        let mut taken = [0usize; 3];
        let wide = crate::render::simd::avx512();
        if !wide {
            eprintln!("shared_level_blocks_match_one_pixel_bit_for_bit: no AVX-512 here, trilinear16 NOT tested");
        }
        for (w, h, a) in [(64, 32, 11), (50, 30, 11), (7, 1, 11), (40, 24, 0)] {
            let img = image(w, h, [53, 29, a]);
            assert_eq!(img.has_alpha(), a != 0);
            for wrap in [
                (Wrap::Repeat, Wrap::Repeat),
                (Wrap::Clamp, Wrap::Repeat),
                (Wrap::Repeat, Wrap::Clamp),
            ] {
                let mut tex = Texture::new(ImageId(0));
                (tex.wrap_s, tex.wrap_t) = wrap;
                let s = Sampler::new(&tex, &img);
                for round in 0..300 {
                    // Texels per pixel: magnified, between levels 1 and 2,
                    // beyond the last level.
                    let scale = [0.2, 5.0, 300.0][round % 3] / w as f32;
                    let mut lanes = [[0.0f32; 8]; 6];
                    for k in 0..8 {
                        lanes[0][k] = (rnd() - 0.3) * 9.0;
                        lanes[1][k] = (rnd() - 0.5) * 5.0;
                        // One footprint per block, nudged per lane so the
                        // lanes' fractions differ within their level pair.
                        lanes[2][k] = scale * (1.0 + 0.01 * rnd());
                        lanes[5][k] = scale * 0.5;
                    }
                    assert_lanes_match(&s, &lanes, &format!("{w}x{h} {wrap:?} round {round}"));
                    // The same levels of detail straight into the one-level path.
                    let lods: [f32; 8] = std::array::from_fn(|k| {
                        s.lod(Vec2::new(lanes[2][k], 0.0), Vec2::new(0.0, lanes[5][k]))
                    });
                    let (u, v) = (Sse8::load(&lanes[0]), Sse8::load(&lanes[1]));
                    let lod = Sse8::load(&lods);
                    // Two eight-lane passes and the 16-lane AVX-512 pass
                    // give the same bits (`assert_lanes_match` above took
                    // the path this CPU runs).
                    if wide {
                        let bits = |o: Option<[Sse8; 4]>| {
                            o.map(|c| c.map(|v| to_arr(v).map(f32::to_bits)))
                        };
                        assert_eq!(
                            bits(s.texel8_one_level(lod, u, v, false)),
                            bits(s.texel8_one_level(lod, u, v, true)),
                            "{w}x{h} {wrap:?} round {round}: 8 vs 16 lanes"
                        );
                    }
                    if s.texel8_one_level(lod, u, v, wide).is_some() {
                        taken[round % 3] += 1;
                    } else {
                        assert!(
                            lods.iter().any(|&x| x as usize != lods[0] as usize),
                            "{lods:?}"
                        );
                    }
                }
            }
        }
        // Each kind of block went through the one-level path most times.
        assert!(taken.iter().all(|&n| n > 250), "{taken:?}");
    }

    /// Blocks as the shading pass sees them — eight neighbouring pixels,
    /// coordinates a fixed step apart, one to three texels per pixel so
    /// the lanes blend two levels — give every lane `texel`'s exact bits,
    /// inside the texture (one pair of 16-texel windows per row for both
    /// rows) and across its seams and edges (the general corners).
    #[test]
    #[allow(clippy::needless_range_loop)]
    fn neighbouring_lanes_match_one_pixel_bit_for_bit() {
        let mut seed = 4242u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32
        };
        for (w, h) in [(64, 32), (50, 30), (256, 256)] {
            let img = image(w, h, [53, 29, 11]);
            for wrap in [(Wrap::Repeat, Wrap::Repeat), (Wrap::Clamp, Wrap::Clamp)] {
                let mut tex = Texture::new(ImageId(0));
                (tex.wrap_s, tex.wrap_t) = wrap;
                let s = Sampler::new(&tex, &img);
                for round in 0..400 {
                    // Texels per pixel in the base level: 1 to 3.
                    let step = (1.0 + 2.0 * rnd()) / w as f32;
                    let (u0, v0) = ((rnd() - 0.2) * 1.4, (rnd() - 0.2) * 1.4);
                    let dv = (rnd() - 0.5) * 0.2 / h as f32;
                    let mut lanes = [[0.0f32; 8]; 6];
                    for k in 0..8 {
                        lanes[0][k] = u0 + step * k as f32;
                        lanes[1][k] = v0 + dv * k as f32;
                        lanes[2][k] = step;
                        lanes[3][k] = dv;
                        lanes[4][k] = 0.0;
                        lanes[5][k] = step * 0.7;
                    }
                    assert_lanes_match(&s, &lanes, &format!("{w}x{h} {wrap:?} round {round}"));
                }
            }
        }
    }

    /// Clamped coordinates so large that s·w overflows to ±∞ (a NaN
    /// fraction) read the edge texel in every path, without overflowing
    /// the filter's integer arithmetic (`256 − 0x8000_0000` in u32, a
    /// panic wherever overflow checks are on).
    #[test]
    fn huge_clamped_coordinates_read_the_edge() {
        let img = image(64, 32, [53, 29, 11]);
        let mut tex = Texture::new(ImageId(0));
        (tex.wrap_s, tex.wrap_t) = (Wrap::Clamp, Wrap::Clamp);
        let s = Sampler::new(&tex, &img);
        let big = 3.0e38f32;
        let mut lanes = [[0.0f32; 8]; 6];
        lanes[0] = [big, -big, 0.5, big, -big, 0.25, 0.75, big];
        lanes[1] = [0.5, 0.5, big, -big, big, -big, 0.5, big];
        // Magnified (one level) and blended between levels 1 and 2.
        for scale in [0.2 / 64.0, 5.0 / 64.0] {
            lanes[2] = [scale; 8];
            lanes[5] = [scale * 0.5; 8];
            assert_lanes_match(&s, &lanes, &format!("scale {scale}"));
            let lods: [f32; 8] = std::array::from_fn(|k| {
                s.lod(Vec2::new(lanes[2][k], 0.0), Vec2::new(0.0, lanes[5][k]))
            });
            let (u, v) = (Sse8::load(&lanes[0]), Sse8::load(&lanes[1]));
            let one = s.texel8_one_level(Sse8::load(&lods), u, v, false);
            let one = one
                .expect("one level pair")
                .map(|c| to_arr(c).map(f32::to_bits));
            for k in 0..8 {
                let want = s.texel(
                    Vec2::new(lanes[0][k], lanes[1][k]),
                    Vec2::new(lanes[2][k], 0.0),
                    Vec2::new(0.0, lanes[5][k]),
                );
                assert_eq!(
                    [one[0][k], one[1][k], one[2][k], one[3][k]],
                    want.to_array().map(f32::to_bits),
                    "lane {k}"
                );
            }
        }
    }

    /// Lanes on different levels are left to the per-lane path.
    #[test]
    fn lanes_on_different_levels_are_not_taken() {
        let img = image(64, 64, [53, 29, 11]);
        let s = Sampler::new(&Texture::new(ImageId(0)), &img);
        let lod = Sse8::load(&[0.5, 0.5, 0.5, 1.5, 0.5, 0.5, 0.5, 0.5]);
        let z = Sse8::splat(0.3);
        assert!(s.texel8_one_level(lod, z, z, false).is_none());
        let lod = Sse8::load(&[0.5, 0.0, 0.25, 0.75, 0.5, 0.5, 0.5, 0.999]);
        assert!(s.texel8_one_level(lod, z, z, false).is_some());
        // A wrong guess of the level is refused, a right one taken, and
        // it gives the one-level path's bits.
        assert!(s.texel8_at_level(1, lod, z, z, false).is_none());
        assert!(s.texel8_at_level(9, lod, z, z, false).is_none());
        let bits = |o: Option<[Sse8; 4]>| o.map(|c| c.map(|v| to_arr(v).map(f32::to_bits)));
        assert_eq!(
            bits(s.texel8_at_level(0, lod, z, z, false)),
            bits(s.texel8_one_level(lod, z, z, false))
        );
    }
}
