//! Fetching the four bilinear corners of eight lanes from one mip level:
//! one AVX2 gather per corner where the CPU has it, one load per lane
//! otherwise.
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Gathers and loads read the same words, for every corner and lane.
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
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: checked just above.
            assert_eq!(unsafe { gather4(&px, &idx) }, want);
        } else {
            eprintln!("gathers_read_what_loads_read: no AVX2 here, gather path NOT tested");
        }
    }
}
