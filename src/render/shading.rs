//! The shading pass's entry: picks the loop compiled with or without the
//! texture steps (`TEX`: a tile with no textured triangle runs no texture
//! code at all) on the widest lanes the CPU has, then shades each pixel's
//! first sample (`fragment`) and, under multisampling, the triangles that
//! show only at its other samples (`samples`).

use super::fragment::{self, Pass, Shaded, Visible};
use super::samples;
use super::simd::{self, Sse8, V8};

/// Shades the visible samples of a tile; samples with no triangle get the
/// background and id 0.
pub fn shade_visible(pass: &Pass, vis: &Visible, out: &mut Shaded) {
    if vis.textured {
        shade_visible_isa::<true>(pass, vis, out);
    } else {
        shade_visible_isa::<false>(pass, vis, out);
    }
}

/// The shading loop (with or without the texture steps, `TEX`) on the
/// widest lanes the CPU has.
#[inline(always)]
fn shade_visible_isa<const TEX: bool>(pass: &Pass, vis: &Visible, out: &mut Shaded) {
    #[cfg(target_arch = "x86_64")]
    if simd::avx512() {
        // SAFETY: `simd::avx512()` checked that the CPU has AVX-512
        // F/VL/BW/DQ (and so AVX).
        unsafe { shade_visible_avx512::<TEX>(pass, vis, out) };
        return;
    }
    #[cfg(target_arch = "x86_64")]
    if simd::avx() {
        // SAFETY: `simd::avx()` checked that the CPU has AVX.
        unsafe { shade_visible_avx::<TEX>(pass, vis, out) };
        return;
    }
    shade_visible_in::<Sse8, TEX>(pass, vis, out);
}

#[inline(always)]
fn shade_visible_in<V: V8, const TEX: bool>(pass: &Pass, vis: &Visible, out: &mut Shaded) {
    fragment::shade_first::<V, TEX>(pass, vis, out);
    if pass.size.2 > 1 {
        samples::shade_others::<V, TEX>(pass, vis, out);
    }
}

/// `shade_visible_in` on AVX lanes compiled with the target features
/// `$features`: the same generic code, so the same bits; only the
/// registers and encodings the compiler may use differ.
macro_rules! avx_entry {
    ($(#[$doc:meta])* $name:ident, $features:literal) => {
        $(#[$doc])*
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = $features)]
        unsafe fn $name<const TEX: bool>(pass: &Pass, vis: &Visible, out: &mut Shaded) {
            shade_visible_in::<simd::Avx8, TEX>(pass, vis, out);
        }
    };
}

avx_entry!(
    /// The AVX path compiled with AVX-512's 32 registers (see `simd::avx512`).
    shade_visible_avx512,
    "avx,avx2,avx512f,avx512vl,avx512bw,avx512dq"
);
avx_entry!(shade_visible_avx, "avx");
