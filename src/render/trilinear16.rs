//! Trilinear sampling of eight pixels that share a mip level pair with
//! both levels in ONE 16-lane AVX-512 pass: lanes 0..8 are the pixels in
//! the finer level, lanes 8..16 the same pixels in the coarser one.
//!
//! Why: after the level of detail, a trilinear lookup is two bilinear
//! lookups doing identical work on different level sizes. Eight-lane code
//! (`texel_block`) runs that work twice and passes corners and channels
//! through memory; here the footprint, the wraps, the texel addresses and
//! the fetch (one `vpermt2d` per corner row reads both levels' windows)
//! run once on zmm registers, and the fixed-point filter runs on 16-bit
//! lanes (`vpmullw`: two channels of sixteen texels per register) instead
//! of the 32-bit multiplies of `texel_filter::bilerp`.
//!
//! Same bits as `texel_block`'s eight-lane path and the one-pixel
//! `Sampler::bilinear`: the float steps are the same IEEE operations in
//! the same order (no fused multiply-add), the wraps give the same whole
//! numbers, and the filter is `bilerp`'s arithmetic, whose every product
//! and sum fits a 16-bit half (see `texel_filter`), so splitting the
//! 32-bit words into 16-bit lanes changes no result. Only callers that
//! checked [`super::simd::avx512`] (AVX-512 F, VL, BW and DQ) may call in.

#[cfg(target_arch = "x86_64")]
pub use imp::sample;

use crate::scene::MipLevel;

/// The sizes of a level pair as [`sample`] reads them, worked out once per
/// sampler (`Sampler::new`): per lane the width and height (lanes 0..8 the
/// finer level's, 8..16 the coarser one's), and both less two (the last
/// floored coordinate whose footprint stays inside the level).
///
/// Why stored: built per block they were a dozen steps (two loads, two
/// conversions, two broadcasts and an insert per size) on the path from
/// the level to the footprint; stored, they are four 64-byte loads.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub struct PairSizes {
    pub w: [f32; 16],
    pub h: [f32; 16],
    pub w2: [f32; 16],
    pub h2: [f32; 16],
}

impl PairSizes {
    /// The sizes of `a` and the next level `b`.
    pub fn of(a: &MipLevel, b: &MipLevel) -> PairSizes {
        let halves = |x: u32, y: u32| std::array::from_fn(|k| if k < 8 { x } else { y } as f32);
        let (w, h): ([f32; 16], [f32; 16]) =
            (halves(a.width(), b.width()), halves(a.height(), b.height()));
        PairSizes {
            w,
            h,
            w2: w.map(|v| v - 2.0),
            h2: h.map(|v| v - 2.0),
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod imp {
    use super::PairSizes;
    use crate::render::texel_block::OPAQUE;
    use crate::render::texel_fetch::{fetch4, fetch_pairs};
    use crate::render::texel_filter::UNIT;
    use crate::scene::{MipLevel, Wrap};
    use std::arch::x86_64::*;

    /// The trilinear RGBA (R, G, B, A lanes in 0..1) of eight pixels at
    /// reduced coordinates `s`, `t` (`Sampler::reduce8`) between `levels[0]`
    /// and `levels[1]` (the next level), blended by `f` (λ minus the finer
    /// level's index). `alpha`: filter the alpha channel (else it is
    /// `OPAQUE`). The finer level must hold at most 2²⁴ texels (addresses
    /// are exact f32 whole numbers).
    ///
    /// Not a `#[target_feature]` function, so that it can be
    /// `#[inline(always)]`: LLVM would not inline it into the shading loop
    /// (a call per block, its inputs and outputs through memory); inlined
    /// there, its intrinsics take the loop's AVX-512 features.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F, VL, BW and DQ (`simd::avx512()`).
    #[inline(always)]
    pub unsafe fn sample(
        levels: [&MipLevel; 2],
        sizes: &PairSizes,
        s: __m256,
        t: __m256,
        f: __m256,
        wrap: [Wrap; 2],
        alpha: bool,
    ) -> [__m256; 4] {
        // `Sampler::footprint8`, operation for operation (1 − t on the
        // eight lanes, before they are doubled).
        let flipped = _mm256_sub_ps(_mm256_set1_ps(1.0), t);
        let (s, t) = (twice(s), twice(flipped));
        let (w, h) = (lanes16(&sizes.w), lanes16(&sizes.h));
        let half = _mm512_set1_ps(0.5);
        let x = _mm512_sub_ps(_mm512_mul_ps(s, w), half);
        let y = _mm512_sub_ps(_mm512_mul_ps(t, h), half);
        const DOWN: i32 = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
        let (x0, y0) = (
            _mm512_roundscale_ps::<DOWN>(x),
            _mm512_roundscale_ps::<DOWN>(y),
        );
        let (fx, fy) = (_mm512_sub_ps(x, x0), _mm512_sub_ps(y, y0));
        // Every footprint inside its level (0 ≤ x0 ≤ w − 2, the same for
        // y; false for NaN and ±∞): clamping and wrapping leave x0, x0 + 1,
        // y0 and y0 + 1 as they are, and the bottom row's texels are the
        // top row's plus one row, so one set of window indices serves both
        // rows. Blocks on a seam or an edge take `corners`.
        let zero = _mm512_setzero_ps();
        let inside = _mm512_cmp_ps_mask::<_CMP_LE_OQ>(zero, x0)
            & _mm512_cmp_ps_mask::<_CMP_LE_OQ>(x0, lanes16(&sizes.w2))
            & _mm512_cmp_ps_mask::<_CMP_LE_OQ>(zero, y0)
            & _mm512_cmp_ps_mask::<_CMP_LE_OQ>(y0, lanes16(&sizes.h2));
        let windows = if inside == 0xFFFF {
            // Texel addresses (exact: whole numbers below 2²⁴), as
            // `corners` computes them for these lanes.
            let top = _mm512_cvttps_epi32(_mm512_add_ps(_mm512_mul_ps(y0, w), x0));
            rows(levels, top)
        } else {
            None
        };
        let corners = match windows {
            Some(c) => c,
            None => corners(levels, x0, y0, w, h, wrap),
        };
        let [rb, ga] = bilerp16(corners, weights(fx), weights(fy));
        // Channels to 0..1, then the level blend a + (b − a)·f per channel.
        let mut out = [_mm256_set1_ps(OPAQUE); 4];
        let low = _mm512_set1_epi32(0xFFFF);
        let chans = [
            _mm512_and_si512(rb, low),
            _mm512_and_si512(ga, low),
            _mm512_srli_epi32::<16>(rb),
            _mm512_srli_epi32::<16>(ga),
        ];
        for (o, &c) in out.iter_mut().zip(&chans).take(if alpha { 4 } else { 3 }) {
            let v = _mm512_mul_ps(_mm512_cvtepi32_ps(c), _mm512_set1_ps(UNIT));
            let (a, b) = (_mm512_castps512_ps256(v), _mm512_extractf32x8_ps::<1>(v));
            *o = _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(b, a), f));
        }
        out
    }

    /// The four corners (top left, top right, bottom left, bottom right)
    /// of every lane at floored texel coordinates `x0`, `y0` in levels of
    /// `w`×`h` texels: clamped and wrapped (`texel_block`'s footprint, on
    /// sixteen lanes), then fetched by two windows per row or gathered.
    /// Out of line: [`sample`] takes it only for blocks on a seam or an
    /// edge of the texture.
    #[target_feature(enable = "avx,avx2,avx512f,avx512vl,avx512bw,avx512dq")]
    #[inline(never)]
    fn corners(
        levels: [&MipLevel; 2],
        x0: __m512,
        y0: __m512,
        w: __m512,
        h: __m512,
        wrap: [Wrap; 2],
    ) -> [__m512i; 4] {
        let two = _mm512_set1_ps(-2.0);
        let x0 = _mm512_min_ps(_mm512_max_ps(x0, two), w);
        let y0 = _mm512_min_ps(_mm512_max_ps(y0, two), h);
        let (xa, xb) = wrap2(x0, w, wrap[0]);
        let (ya, yb) = wrap2(y0, h, wrap[1]);
        // Texel addresses (exact: whole numbers below 2²⁴).
        let (ra, rb) = (_mm512_mul_ps(ya, w), _mm512_mul_ps(yb, w));
        let top = _mm512_cvttps_epi32(_mm512_add_ps(ra, xa));
        let bottom = _mm512_cvttps_epi32(_mm512_add_ps(rb, xa));
        let pairs = _mm512_cmp_ps_mask::<_CMP_EQ_OQ>(_mm512_sub_ps(xb, xa), _mm512_set1_ps(1.0));
        let windows = if pairs == 0xFFFF {
            match (window(levels, top), window(levels, bottom)) {
                (Some((tl, tr)), Some((bl, br))) => Some([tl, tr, bl, br]),
                _ => None,
            }
        } else {
            None
        };
        match windows {
            Some(c) => c,
            None => {
                let tr = _mm512_cvttps_epi32(_mm512_add_ps(ra, xb));
                let br = _mm512_cvttps_epi32(_mm512_add_ps(rb, xb));
                gather(levels, pairs == 0xFFFF, [top, tr, bottom, br])
            }
        }
    }

    /// The four corners by per-level fetches (`texel_fetch`): for blocks
    /// whose rows span more than sixteen texels or cross a wrap seam
    /// (`pairs`: no lane does; then the right corners are read beside the
    /// left ones). Out of line, so that [`sample`] stays small enough to
    /// inline into the shading loop.
    #[target_feature(enable = "avx,avx2,avx512f,avx512vl")]
    #[inline(never)]
    #[cold]
    fn gather(levels: [&MipLevel; 2], pairs: bool, idx: [__m512i; 4]) -> [__m512i; 4] {
        let idx = [
            lanes8(idx[0]),
            lanes8(idx[1]),
            lanes8(idx[2]),
            lanes8(idx[3]),
        ];
        let level = |l: usize| {
            let px = levels[l].pixels();
            if pairs {
                fetch_pairs(px, &idx[0][l], &idx[2][l])
            } else {
                fetch4(px, &[idx[0][l], idx[1][l], idx[2][l], idx[3][l]])
            }
        };
        join(&level(0), &level(1))
    }

    /// Eight lanes in both halves.
    #[target_feature(enable = "avx512f,avx512dq")]
    #[inline]
    fn twice(v: __m256) -> __m512 {
        _mm512_insertf32x8::<1>(_mm512_castps256_ps512(v), v)
    }

    /// `texel_block::wrap2` on sixteen lanes of whole numbers in −2..=n:
    /// the texel indices i and i + 1 wrapped into 0..n. Repeat takes one
    /// period up or down, then (for n = 1, where that is not enough) the
    /// clamp to 0..=n − 1; i + 1 is then the wrapped i plus one, or 0 at
    /// n — the same whole numbers as wrapping i + 1 itself.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn wrap2(i: __m512, n: __m512, mode: Wrap) -> (__m512, __m512) {
        let (zero, one) = (_mm512_setzero_ps(), _mm512_set1_ps(1.0));
        let last = _mm512_sub_ps(n, one);
        match mode {
            Wrap::Clamp => {
                let j = _mm512_add_ps(i, one);
                (
                    _mm512_min_ps(_mm512_max_ps(i, zero), last),
                    _mm512_min_ps(_mm512_max_ps(j, zero), last),
                )
            }
            _ => {
                let below = _mm512_cmp_ps_mask::<_CMP_LT_OQ>(i, zero);
                let above = _mm512_cmp_ps_mask::<_CMP_LE_OQ>(n, i);
                let once = _mm512_mask_add_ps(i, below, i, n);
                let once = _mm512_mask_sub_ps(once, above, once, n);
                let a = _mm512_min_ps(_mm512_max_ps(once, zero), last);
                let j = _mm512_add_ps(a, one);
                let seam = _mm512_cmp_ps_mask::<_CMP_EQ_OQ>(j, n);
                (a, _mm512_mask_mov_ps(j, seam, zero))
            }
        }
    }

    /// Sub-texel fractions as 8-bit weights (`texel_filter::weight`:
    /// f·256 + ½, truncated) in both 16-bit halves of each lane.
    /// Both halves come from one byte shuffle of the low one (weights
    /// are 0..=256; a NaN fraction truncates to 0x8000_0000, whose low
    /// half is 0, the one-pixel weight of NaN).
    #[target_feature(enable = "avx512f,avx512bw")]
    #[inline]
    fn weights(f: __m512) -> __m512i {
        let w = _mm512_cvttps_epi32(_mm512_add_ps(
            _mm512_mul_ps(f, _mm512_set1_ps(256.0)),
            _mm512_set1_ps(0.5),
        ));
        // Bytes 0, 1, 0, 1 of every 32-bit lane.
        let low_twice = _mm512_set4_epi32(0x0D0C_0D0C, 0x0908_0908, 0x0504_0504, 0x0100_0100);
        _mm512_shuffle_epi8(w, low_twice)
    }

    /// `texel_filter::bilerp` on sixteen lanes of RGBA8 corners (top left,
    /// top right, bottom left, bottom right) with weights from
    /// [`weights`]: `[R | B << 16, G | A << 16]` per lane, each channel in
    /// 0..=255·256. Every product and sum fits its 16-bit half, so the
    /// 16-bit multiplies give `bilerp`'s words exactly.
    ///
    /// The horizontal step `(a·(256 − w) + b·w + 128) >> 8` is computed as
    /// `a + ((b − a)·w + 128) >> 8` (the same whole number: `256·a` is a
    /// multiple of 256), and that last term as `vpmulhrsw` of 2·(b − a)
    /// and 64·w, which rounds `(x·y + 2¹⁴) >> 15`: with x·y = 128·(b − a)·w
    /// that is exactly `((b − a)·w + 128) >> 8`, in three steps fewer per
    /// row (both factors fit 16 signed bits: |2·(b − a)| ≤ 510, 64·w ≤
    /// 2¹⁴). Where a fraction was NaN (`weights` gives weight 0, as the
    /// one-pixel `texel_filter::weight` does) both texels of that axis are
    /// the same edge texel anyway, so any weight gives the same words.
    #[target_feature(enable = "avx512f,avx512bw")]
    #[inline]
    fn bilerp16(c: [__m512i; 4], wx: __m512i, wy: __m512i) -> [__m512i; 2] {
        let unit = _mm512_set1_epi16(256);
        let iy = _mm512_sub_epi16(unit, wy);
        let wx64 = _mm512_slli_epi16::<6>(wx);
        let lowbytes = _mm512_set1_epi32(0x00FF_00FF);
        let rb = |w: __m512i| _mm512_and_si512(w, lowbytes);
        let ga = |w: __m512i| _mm512_srli_epi16::<8>(w);
        // Horizontal: 8.8 fixed point per channel, rounded to 8 bits.
        let row = |a: __m512i, b: __m512i| {
            let d = _mm512_slli_epi16::<1>(_mm512_sub_epi16(b, a));
            _mm512_add_epi16(a, _mm512_mulhrs_epi16(d, wx64))
        };
        let (top_rb, top_ga) = (row(rb(c[0]), rb(c[1])), row(ga(c[0]), ga(c[1])));
        let (bot_rb, bot_ga) = (row(rb(c[2]), rb(c[3])), row(ga(c[2]), ga(c[3])));
        // Vertical: 8 bits times a weight, up to 255·256 per channel.
        let col = |a: __m512i, b: __m512i| {
            _mm512_add_epi16(_mm512_mullo_epi16(a, iy), _mm512_mullo_epi16(b, wy))
        };
        [col(top_rb, bot_rb), col(top_ga, bot_ga)]
    }

    /// [`bilerp16`] on one set of corners with sixteen lanes of weights
    /// `wx` and one `wy`, as `texel_filter::bilerp` words per lane.
    #[cfg(test)]
    pub fn bilerp16_for_tests(c: [u32; 4], wx: [u32; 16], wy: u32) -> [[u32; 2]; 16] {
        let half = |w: u32| (w | w << 16) as i32;
        // SAFETY: the test calls in only where `simd::avx512()` said yes.
        let out = unsafe {
            let c = c.map(|w| _mm512_set1_epi32(w as i32));
            let wx = _mm512_loadu_si512(wx.map(half).as_ptr().cast());
            bilerp16(c, wx, _mm512_set1_epi32(half(wy)))
        };
        let mut words = [[0u32; 16]; 2];
        for (w, o) in words.iter_mut().zip(out) {
            // SAFETY: a 64-byte store into sixteen u32.
            unsafe { _mm512_storeu_si512(w.as_mut_ptr().cast(), o) };
        }
        std::array::from_fn(|k| [words[0][k], words[1][k]])
    }

    /// Both levels' texel pairs of one corner row (`i`: left texel indices,
    /// lanes 0..8 in the finer level, 8..16 in the coarser) when each
    /// level's eight pairs lie within sixteen texels of the smaller of its
    /// first and last lane's: two 64-byte loads and one two-table
    /// `vpermt2d` per side; `None` otherwise (the caller gathers).
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn window(levels: [&MipLevel; 2], i: __m512i) -> Option<(__m512i, __m512i)> {
        let l = lanes8(i);
        let first = [l[0][0].min(l[0][7]), l[1][0].min(l[1][7])];
        let fits = |k: usize| first[k] >= 0 && first[k] as usize + 16 <= levels[k].pixels().len();
        if !fits(0) || !fits(1) {
            return None;
        }
        let start =
            _mm512_inserti64x4::<1>(_mm512_set1_epi32(first[0]), _mm256_set1_epi32(first[1]));
        let rel = _mm512_sub_epi32(i, start);
        // Every lane in 0..=14 (unsigned: negative lanes fail), so lane
        // k's pair is words rel[k] and rel[k] + 1 of its level's sixteen.
        if _mm512_cmple_epu32_mask(rel, _mm512_set1_epi32(14)) != 0xFFFF {
            return None;
        }
        // SAFETY: texels first[k]..first[k] + 16 lie inside level k
        // (checked above); each load reads exactly those 64 bytes.
        let (ta, tb) = unsafe {
            (
                _mm512_loadu_si512(levels[0].pixels().as_ptr().add(first[0] as usize).cast()),
                _mm512_loadu_si512(levels[1].pixels().as_ptr().add(first[1] as usize).cast()),
            )
        };
        // Indices 16..32 pick from the second table (the coarser level).
        let idx = _mm512_add_epi32(
            rel,
            _mm512_inserti64x4::<1>(_mm512_setzero_si512(), _mm256_set1_epi32(16)),
        );
        let right = _mm512_add_epi32(idx, _mm512_set1_epi32(1));
        Some((
            _mm512_permutex2var_epi32(ta, idx, tb),
            _mm512_permutex2var_epi32(ta, right, tb),
        ))
    }

    /// Both rows' corners (top left, top right, bottom left, bottom right)
    /// when every lane's footprint lies inside its level (`top`: the top
    /// left texel indices; the bottom row is one level row further): the
    /// top row's windows as in [`window`], and the bottom row's from the
    /// same indices one row on. `None` where [`window`] gives none or the
    /// bottom windows would leave a level (the caller gathers).
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn rows(levels: [&MipLevel; 2], top: __m512i) -> Option<[__m512i; 4]> {
        // Each half's start, the smaller of its first and last lane's,
        // in every lane of the half (on lanes: no trip through memory).
        let first_lanes = _mm512_set_epi32(8, 8, 8, 8, 8, 8, 8, 8, 0, 0, 0, 0, 0, 0, 0, 0);
        let last_lanes = _mm512_set_epi32(15, 15, 15, 15, 15, 15, 15, 15, 7, 7, 7, 7, 7, 7, 7, 7);
        let start = _mm512_min_epi32(
            _mm512_permutexvar_epi32(first_lanes, top),
            _mm512_permutexvar_epi32(last_lanes, top),
        );
        let first = [
            _mm_cvtsi128_si32(_mm512_castsi512_si128(start)),
            _mm_cvtsi128_si32(_mm512_extracti32x4_epi32::<2>(start)),
        ];
        let fits = |k: usize| {
            first[k] >= 0
                && first[k] as usize + levels[k].width() as usize + 16 <= levels[k].pixels().len()
        };
        if !fits(0) || !fits(1) {
            return None;
        }
        let rel = _mm512_sub_epi32(top, start);
        // Every lane in 0..=14 (unsigned: negative lanes fail), so lane
        // k's pair is words rel[k] and rel[k] + 1 of its level's sixteen.
        if _mm512_cmple_epu32_mask(rel, _mm512_set1_epi32(14)) != 0xFFFF {
            return None;
        }
        let (pa, pb) = (
            levels[0].pixels()[first[0] as usize..].as_ptr(),
            levels[1].pixels()[first[1] as usize..].as_ptr(),
        );
        let (wa, wb) = (levels[0].width() as usize, levels[1].width() as usize);
        // SAFETY: texels first[k]..first[k] + 16 and the sixteen one row
        // further lie inside level k (checked above); each load reads
        // exactly one such run of 64 bytes.
        let (ta, tb, ba, bb) = unsafe {
            (
                _mm512_loadu_si512(pa.cast()),
                _mm512_loadu_si512(pb.cast()),
                _mm512_loadu_si512(pa.add(wa).cast()),
                _mm512_loadu_si512(pb.add(wb).cast()),
            )
        };
        // Indices 16..32 pick from the second table (the coarser level).
        let idx = _mm512_add_epi32(
            rel,
            _mm512_inserti64x4::<1>(_mm512_setzero_si512(), _mm256_set1_epi32(16)),
        );
        let right = _mm512_add_epi32(idx, _mm512_set1_epi32(1));
        Some([
            _mm512_permutex2var_epi32(ta, idx, tb),
            _mm512_permutex2var_epi32(ta, right, tb),
            _mm512_permutex2var_epi32(ba, idx, bb),
            _mm512_permutex2var_epi32(ba, right, bb),
        ])
    }

    /// Sixteen lanes of a [`PairSizes`] row.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn lanes16(a: &[f32; 16]) -> __m512 {
        // SAFETY: a 64-byte load of sixteen f32.
        unsafe { _mm512_loadu_ps(a.as_ptr()) }
    }

    /// The two halves of sixteen i32 lanes as arrays.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn lanes8(v: __m512i) -> [[i32; 8]; 2] {
        let mut out = [[0i32; 8]; 2];
        // SAFETY: a 64-byte store into 2 × 8 i32.
        unsafe { _mm512_storeu_si512(out.as_mut_ptr().cast(), v) };
        out
    }

    /// Corners fetched per level (`fetch_pairs`/`fetch4`) as sixteen lanes.
    #[target_feature(enable = "avx512f")]
    #[inline]
    fn join(a: &[[u32; 8]; 4], b: &[[u32; 8]; 4]) -> [__m512i; 4] {
        std::array::from_fn(|c| {
            // SAFETY: 32-byte loads from arrays of 8 u32.
            unsafe {
                _mm512_inserti64x4::<1>(
                    _mm512_castsi256_si512(_mm256_loadu_si256(a[c].as_ptr().cast())),
                    _mm256_loadu_si256(b[c].as_ptr().cast()),
                )
            }
        })
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::imp::bilerp16_for_tests as bilerp16;
    use crate::render::texel_filter::bilerp;

    /// The 16-lane filter gives `bilerp`'s words for every pair of weights
    /// (0..=256 each) on corners with every channel difference sign and
    /// size, the extremes (0 and 255 next to each other) included. Runs
    /// where the CPU has AVX-512 (the only place the filter runs); this
    /// machine's CI has it, and the test says so when it cannot run.
    #[test]
    fn filter_matches_bilerp_for_every_weight() {
        if !crate::render::simd::avx512() {
            eprintln!("filter_matches_bilerp_for_every_weight: no AVX-512 here, not run");
            return;
        }
        let mut seed = 7u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed
        };
        let mut corners: Vec<[u32; 4]> = vec![
            [0, 0xFFFF_FFFF, 0xFFFF_FFFF, 0],
            [0xFFFF_FFFF, 0, 0, 0xFFFF_FFFF],
            [0x00FF_00FF, 0xFF00_FF00, 0xFF00_FF00, 0x00FF_00FF],
        ];
        corners.extend((0..13).map(|_| [rnd(), rnd(), rnd(), rnd()]));
        let mut checked = 0;
        for c in &corners {
            for wy in 0..=256u32 {
                for wx0 in (0..=256u32).step_by(16) {
                    // Sixteen lanes: weights wx0.. (past 256 wraps to 0).
                    let wx: [u32; 16] = std::array::from_fn(|k| (wx0 + k as u32) % 257);
                    let got = bilerp16(*c, wx, wy);
                    for k in 0..16 {
                        assert_eq!(got[k], bilerp(*c, wx[k], wy), "{c:x?} wx {} wy {wy}", wx[k]);
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 16 * 257 * 257);
    }
}
