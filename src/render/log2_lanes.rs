//! A division-free `log2` for the texture sampler's level of detail, one
//! pixel at a time or eight lanes at once, with the same bits either way.
//!
//! Why not libm's `log2f`: the level of detail needs λ to a small fraction
//! of a level (it only sets which two mip levels blend and by how much),
//! and libm's correctly-rounded reduction (a division, a split constant)
//! cost as much per block as the rest of the level arithmetic. Here
//! x = 2ᵉ·m with m in [1, 2) is split by its bits (IEEE 754 binary32: the
//! exponent field minus 127, the mantissa field under exponent 0), and
//! log2(m) is a degree-4 polynomial in t = m − 1 with no constant term, so
//! log2 of a power of two is exact. The coefficients were fitted here to
//! log2(1 + t) on [0, 1] by iteratively reweighted least squares towards
//! the minimax fit; the error stays below 1.1·10⁻⁴ (the test checks it),
//! far below the 1/256 the level blend can show. Both forms do the same
//! IEEE f32 operations in the same order (Horner, no fused multiply-add),
//! so the one-pixel sampler and the lanes agree bit for bit.

use super::simd::V8;

// p(t) = t·(C1 + t·(C2 + t·(C3 + t·C4))) ≈ log2(1 + t) on [0, 1].
const C1: f32 = 1.439_013_8;
const C2: f32 = -0.679_939_15;
const C3: f32 = 0.325_587_2;
const C4: f32 = -0.084_764_24;

/// The mantissa in [1, 2) and the unbiased exponent of a positive normal
/// finite `x` (as f32; other inputs give unspecified values).
#[inline(always)]
fn split(x: f32) -> (f32, f32) {
    let b = x.to_bits();
    let m = f32::from_bits((b & 0x007f_ffff) | 0x3f80_0000);
    (m, ((b >> 23) as i32 - 127) as f32)
}

/// log2 of a positive normal finite `x` within 1.1·10⁻⁴ (see the module
/// doc); other inputs give unspecified values, so callers exclude them.
#[inline(always)]
pub fn log2_fast(x: f32) -> f32 {
    let (m, e) = split(x);
    let t = m - 1.0;
    t * (C1 + t * (C2 + t * (C3 + t * C4))) + e
}

/// [`log2_fast`] of each lane, bit for bit.
#[inline(always)]
pub fn log2_fast8<V: V8>(x: V) -> V {
    // The bit split on integer lanes (LLVM vectorises this loop with the
    // caller's instruction set).
    let mut xs = [0.0f32; 8];
    x.store(&mut xs);
    let (mut m, mut e) = ([0.0f32; 8], [0.0f32; 8]);
    for l in 0..8 {
        (m[l], e[l]) = split(xs[l]);
    }
    // No closure for the constants: it would lack the caller's AVX
    // target feature and turn lane operations into calls.
    let t = V::load(&m) - V::splat(1.0);
    let (c1, c2, c3, c4) = (V::splat(C1), V::splat(C2), V::splat(C3), V::splat(C4));
    t * (c1 + t * (c2 + t * (c3 + t * c4))) + V::load(&e)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::simd::Sse8;

    /// Lanes equal the one-pixel function bit for bit, and both stay within
    /// 1.1·10⁻⁴ of log2 (f64) over the whole exponent range; powers of
    /// two are exact.
    #[test]
    fn lanes_match_scalar_and_log2_within_bound() {
        let mut seed = 0x2545_f491u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let mut values: Vec<f32> = vec![1.0, 2.0, 1.5, 1.999_999_9, 1.000_000_1, f32::MAX, 3.0e7];
        values.extend((1..=254u32).map(|e| f32::from_bits(e << 23)));
        while !values.len().is_multiple_of(8) || values.len() < 80_000 {
            // A positive normal finite number: exponent field 1..=254.
            let bits = next() & 0x7fff_ffff;
            if (1..=254).contains(&(bits >> 23)) {
                values.push(f32::from_bits(bits));
            }
        }
        let mut worst = 0.0f64;
        for chunk in values.chunks_exact(8) {
            let got = log2_fast8(Sse8::load(chunk.try_into().expect("8")));
            let mut out = [0.0f32; 8];
            got.store(&mut out);
            for (&x, y) in chunk.iter().zip(out) {
                assert_eq!(y.to_bits(), log2_fast(x).to_bits(), "log2({x:e})");
                worst = worst.max((y as f64 - (x as f64).log2()).abs());
                if x.to_bits() & 0x007f_ffff == 0 {
                    assert_eq!(y as f64, (x as f64).log2(), "{x:e} is a power of two");
                }
            }
        }
        assert!(worst < 1.1e-4, "worst error {worst:e}");
        assert!(
            worst > 1e-6,
            "the test saw the polynomial's error: {worst:e}"
        );
    }
}
