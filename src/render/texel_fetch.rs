//! Fetching the four bilinear corners of eight lanes from one mip level:
//! one AVX2 gather per corner (or per row of texel pairs) where the CPU
//! has it, one load per lane otherwise.
//!
//! Why a file of its own: the gather needs AVX2, which the rest of the
//! shading pass does not assume (its AVX path runs on AVX-only CPUs too),
//! so it is a separate function compiled for AVX2 and chosen at run time.
//! Both ways read the same words, so the picture does not depend on which
//! one runs (`ANIMED_SIMD=sse2` forces the loads).

use std::sync::OnceLock;

/// The RGBA8 words at `idx[c][k]` (texel indices into `px`) for the four
/// corners `c` of eight lanes `k`.
#[inline(always)]
pub fn fetch4(px: &[[u8; 4]], idx: &[[i32; 8]; 4]) -> [[u32; 8]; 4] {
    #[cfg(target_arch = "x86_64")]
    if gathers() {
        // SAFETY: `gathers()` checked that the CPU has AVX2.
        return unsafe { gather4(px, idx) };
    }
    load4(px, idx)
}

/// [`fetch4`] for blocks whose right texels follow their left ones in
/// memory (every lane's right column is its left column + 1: no wrap seam
/// and no clamped edge in the block): `a[k]` and `b[k]` are lane k's top
/// and bottom left texel indices. With AVX2 a row whose pairs all lie in
/// sixteen consecutive texels is two loads and a permute (one two-table
/// `vpermt2d` per corner row with AVX-512); any other row is two 64-bit
/// gathers (a texel and its right neighbour in one element) instead of
/// two 32-bit gathers of eight. The same words either way.
#[inline(always)]
pub fn fetch_pairs(px: &[[u8; 4]], a: &[i32; 8], b: &[i32; 8]) -> [[u32; 8]; 4] {
    #[cfg(target_arch = "x86_64")]
    if gathers() && px.len() >= 2 {
        if super::simd::avx512() {
            // SAFETY: `avx512()` checked AVX-512F/VL, `gathers()` AVX2.
            return unsafe { gather_pairs_avx512(px, a, b) };
        }
        // SAFETY: `gathers()` checked that the CPU has AVX2.
        return unsafe { gather_pairs(px, a, b) };
    }
    load4(px, &[*a, a.map(|i| i + 1), *b, b.map(|i| i + 1)])
}

/// Whether gathers may run: the CPU has AVX2 and `ANIMED_SIMD` does not
/// force SSE2 (see `simd::avx`).
fn gathers() -> bool {
    static GATHERS: OnceLock<bool> = OnceLock::new();
    *GATHERS.get_or_init(|| {
        #[cfg(target_arch = "x86_64")]
        {
            super::simd::avx() && std::arch::is_x86_feature_detected!("avx2")
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            false
        }
    })
}

/// One load per lane and corner (indices are in range by construction; an
/// index outside `px` would panic, never read out of bounds).
#[inline(always)]
fn load4(px: &[[u8; 4]], idx: &[[i32; 8]; 4]) -> [[u32; 8]; 4] {
    let mut out = [[0u32; 8]; 4];
    for (o, i) in out.iter_mut().zip(idx) {
        for (o, &i) in o.iter_mut().zip(i) {
            *o = u32::from_le_bytes(px[i as usize]);
        }
    }
    out
}

/// One `vpgatherdd` per corner. Every index is first clamped (as unsigned)
/// to the last texel, so no lane can read outside `px` whatever it holds.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn gather4(px: &[[u8; 4]], idx: &[[i32; 8]; 4]) -> [[u32; 8]; 4] {
    use std::arch::x86_64::*;
    // Levels hold at most 2²⁶ texels (`scene::image`), so the last index
    // fits an i32; a level is never empty.
    let last = _mm256_set1_epi32(px.len().saturating_sub(1) as i32);
    let base = px.as_ptr().cast::<i32>();
    let mut out = [[0u32; 8]; 4];
    for (o, i) in out.iter_mut().zip(idx) {
        // SAFETY: `i` and `o` are 8 × 4 bytes; every gathered index is
        // ≤ px.len() − 1 after the unsigned min, and each texel is 4 bytes
        // (scale 4), so every read lies inside `px`.
        unsafe {
            let i = _mm256_min_epu32(_mm256_loadu_si256(i.as_ptr().cast()), last);
            let g = _mm256_i32gather_epi32::<4>(base, i);
            _mm256_storeu_si256(o.as_mut_ptr().cast(), g);
        }
    }
    out
}

/// Two `vpgatherdq` per row, each fetching four lanes' texel pairs; then
/// the pairs are split into left and right texels in lane order. Every
/// index is first clamped (as unsigned) to the last but one texel, so no
/// 8-byte read can leave `px` (callers guarantee `px.len() ≥ 2`). A row
/// within sixteen texels is loaded and permuted instead (`$pick` picks
/// lane k's word of the sixteen). One body for AVX2 and AVX-512, which
/// differ only in `$pick`.
macro_rules! pairs_fn {
    ($(#[$doc:meta])* $name:ident, $features:literal, $pick:ident) => {
        $(#[$doc])*
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        fn $name(px: &[[u8; 4]], a: &[i32; 8], b: &[i32; 8]) -> [[u32; 8]; 4] {
            use std::arch::x86_64::*;
            let last = _mm_set1_epi32(px.len().saturating_sub(2) as i32);
            let base = px.as_ptr().cast::<i64>();
            let mut out = [[0u32; 8]; 4];
            for (row, i) in [a, b].into_iter().enumerate() {
                // SAFETY: `i` is 8 × 4 bytes and each `out` row 8 × 4
                // bytes; every gathered index is ≤ px.len() − 2 after the
                // unsigned min, with scale 4 (bytes per texel) each 8-byte
                // read lies inside `px`.
                unsafe {
                    // All eight pairs within sixteen texels from the first
                    // or last lane's (a row of eight pixels crossing few
                    // texels, the common case in magnified and mildly
                    // minified blocks): two loads and a permute, no gather.
                    let v = _mm256_loadu_si256(i.as_ptr().cast());
                    let first = i[0].min(i[7]);
                    let rel = _mm256_sub_epi32(v, _mm256_set1_epi32(first));
                    if first >= 0 && first as usize + 16 <= px.len() && within14(rel) {
                        // SAFETY: texels first..first + 16 lie inside `px`.
                        let t = px.as_ptr().add(first as usize).cast::<__m256i>();
                        let (t0, t1) = (_mm256_loadu_si256(t), _mm256_loadu_si256(t.add(1)));
                        let right = _mm256_add_epi32(rel, _mm256_set1_epi32(1));
                        _mm256_storeu_si256(out[2 * row].as_mut_ptr().cast(), $pick(t0, t1, rel));
                        _mm256_storeu_si256(
                            out[2 * row + 1].as_mut_ptr().cast(),
                            $pick(t0, t1, right),
                        );
                        continue;
                    }
                    let lo = _mm_min_epu32(_mm_loadu_si128(i.as_ptr().cast()), last);
                    let hi = _mm_min_epu32(_mm_loadu_si128(i.as_ptr().add(4).cast()), last);
                    // Dwords: g0 = L0 R0 L1 R1 | L2 R2 L3 R3, g1 the same for 4..8.
                    let g0 = _mm256_castsi256_ps(_mm256_i32gather_epi64::<4>(base, lo));
                    let g1 = _mm256_castsi256_ps(_mm256_i32gather_epi64::<4>(base, hi));
                    // Evens (left) and odds (right): L0 L1 L4 L5 | L2 L3 L6 L7,
                    // then the middle quadwords swapped into lane order.
                    let left = _mm256_shuffle_ps::<0b10_00_10_00>(g0, g1);
                    let right = _mm256_shuffle_ps::<0b11_01_11_01>(g0, g1);
                    let left =
                        _mm256_permute4x64_epi64::<0b11_01_10_00>(_mm256_castps_si256(left));
                    let right =
                        _mm256_permute4x64_epi64::<0b11_01_10_00>(_mm256_castps_si256(right));
                    _mm256_storeu_si256(out[2 * row].as_mut_ptr().cast(), left);
                    _mm256_storeu_si256(out[2 * row + 1].as_mut_ptr().cast(), right);
                }
            }
            out
        }
    };
}

pairs_fn!(
    /// Texel pairs with AVX2 (`pick16`: two `vpermd` and a blend).
    gather_pairs,
    "avx2",
    pick16
);
pairs_fn!(
    /// Texel pairs with AVX-512 (`pick16_avx512`: one `vpermt2d`).
    gather_pairs_avx512,
    "avx2,avx512f,avx512vl",
    pick16_avx512
);

/// Whether every lane of `rel` lies in 0..=14 (as unsigned, so negative
/// lanes fail): then lane k's pair is words rel[k] and rel[k] + 1 of
/// sixteen.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn within14(rel: std::arch::x86_64::__m256i) -> bool {
    use std::arch::x86_64::*;
    let fourteen = _mm256_set1_epi32(14);
    let ok = _mm256_cmpeq_epi32(_mm256_max_epu32(rel, fourteen), fourteen);
    _mm256_movemask_epi8(ok) == -1
}

/// Lane k of the sixteen words `t0`, `t1` at index `i[k]` (0..16).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn pick16(
    t0: std::arch::x86_64::__m256i,
    t1: std::arch::x86_64::__m256i,
    i: std::arch::x86_64::__m256i,
) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    let upper = _mm256_cmpgt_epi32(i, _mm256_set1_epi32(7));
    let (a, b) = (
        _mm256_permutevar8x32_epi32(t0, i),
        _mm256_permutevar8x32_epi32(t1, i),
    );
    _mm256_blendv_epi8(a, b, upper)
}

/// [`pick16`] in one AVX-512 instruction (`vpermt2d`: bit 3 of each index
/// picks the table).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f,avx512vl")]
#[inline]
fn pick16_avx512(
    t0: std::arch::x86_64::__m256i,
    t1: std::arch::x86_64::__m256i,
    i: std::arch::x86_64::__m256i,
) -> std::arch::x86_64::__m256i {
    std::arch::x86_64::_mm256_permutex2var_epi32(t0, i, t1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gathers and loads read the same words, for every corner and lane,
    /// by corners and by pairs.
    #[test]
    fn gathers_read_what_loads_read() {
        let px: Vec<[u8; 4]> = (0..300u32)
            .map(|i| i.wrapping_mul(2_654_435_761).to_le_bytes())
            .collect();
        let idx: [[i32; 8]; 4] =
            std::array::from_fn(|c| std::array::from_fn(|k| ((c * 97 + k * 41) % 300) as i32));
        let want = load4(&px, &idx);
        assert_eq!(fetch4(&px, &idx), want);
        assert_eq!(want[1][2], u32::from_le_bytes(px[97 + 82]));
        // Pairs: right corners one texel after the left ones, including
        // the last pair of the level.
        let (a, b): ([i32; 8], [i32; 8]) = (
            std::array::from_fn(|k| ((k * 37) % 299) as i32),
            std::array::from_fn(|k| [298, 0, 5, 150, 297, 1, 2, 3][k]),
        );
        let pairs = load4(&px, &[a, a.map(|i| i + 1), b, b.map(|i| i + 1)]);
        assert_eq!(fetch_pairs(&px, &a, &b), pairs);
        assert_eq!(pairs[3][0], u32::from_le_bytes(px[299]));
        // Rows within sixteen texels (loaded and permuted): one that ends
        // at the level's last texel, one that would end past it (gathered),
        // one that spans fifteen texels (gathered).
        let near: [[i32; 8]; 3] = [
            [290, 284, 298, 291, 284, 295, 287, 284],
            [285, 286, 298, 291, 285, 295, 287, 290],
            [10, 24, 11, 12, 14, 15, 17, 25],
        ];
        for (a, b) in [(near[0], near[2]), (near[1], near[0]), (near[2], near[1])] {
            let want = load4(&px, &[a, a.map(|i| i + 1), b, b.map(|i| i + 1)]);
            assert_eq!(fetch_pairs(&px, &a, &b), want);
        }
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: checked just above.
            assert_eq!(unsafe { gather4(&px, &idx) }, want);
            assert_eq!(unsafe { gather_pairs(&px, &a, &b) }, pairs);
            for (a, b) in [(near[0], near[2]), (near[1], near[0])] {
                let want = load4(&px, &[a, a.map(|i| i + 1), b, b.map(|i| i + 1)]);
                // SAFETY: checked above.
                assert_eq!(unsafe { gather_pairs(&px, &a, &b) }, want);
                if std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                {
                    // SAFETY: checked just above.
                    assert_eq!(unsafe { gather_pairs_avx512(&px, &a, &b) }, want);
                } else {
                    eprintln!("gathers_read_what_loads_read: no AVX-512 here, vpermt2d NOT tested");
                }
            }
            // SAFETY: checked above.
            let rel = |v: [i32; 8]| unsafe {
                within14(std::arch::x86_64::_mm256_loadu_si256(v.as_ptr().cast()))
            };
            assert!(rel([0, 14, 3, 7, 8, 9, 1, 2]));
            assert!(!rel([0, 15, 3, 7, 8, 9, 1, 2]));
            assert!(!rel([0, 4, 3, -1, 8, 9, 1, 2]));
        } else {
            eprintln!("gathers_read_what_loads_read: no AVX2 here, gather path NOT tested");
        }
    }
}
