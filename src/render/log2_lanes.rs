//! `libm::log2f` for eight lanes at once, with its exact bits.
//!
//! Why: the texture sampler picks each pixel's mip level from
//! `log2(ρ²)`, and calling libm once per pixel cost as much as the rest of
//! the level arithmetic. libm's `log2f` (FreeBSD's `e_log2f.c`, as the
//! `libm` crate ports it) is plain f32 arithmetic after splitting the
//! exponent off: reduce x to [√2/2, √2), evaluate a fixed polynomial in
//! s = f/(2+f), and add the exponent with a split constant 1/ln 2. The same
//! IEEE operations in the same order on lanes (no fused multiply-add)
//! give the same bits; only the bit fiddling runs lane by lane.

use super::simd::V8;

// libm's constants, written as libm writes them (so they parse to the same
// f32 bits).
#[allow(clippy::excessive_precision)]
const IVLN2HI: f32 = 1.4428710938e+00; // 0x3fb8b000
#[allow(clippy::excessive_precision)]
const IVLN2LO: f32 = -1.7605285393e-04; // 0xb9389ad4
#[allow(clippy::excessive_precision)]
const LG1: f32 = 0.66666662693; // 0xaaaaaa.0p-24
#[allow(clippy::excessive_precision)]
const LG2: f32 = 0.40000972152; // 0xccce13.0p-25
#[allow(clippy::excessive_precision)]
const LG3: f32 = 0.28498786688; // 0x91e9ee.0p-25
#[allow(clippy::excessive_precision)]
const LG4: f32 = 0.24279078841; // 0xf89e26.0p-26

/// `libm::log2f` of each lane, bit for bit, for lanes holding positive
/// normal finite numbers other than 1 (libm answers 1, zeros, subnormals,
/// negatives, infinities and NaN by special cases; lanes holding those get
/// unspecified values here, so callers select them away).
#[inline(always)]
pub fn log2f8<V: V8>(x: V) -> V {
    // The exponent k and the mantissa scaled into [√2/2, √2), per lane
    // (integer work AVX without AVX2 cannot do on eight lanes).
    let mut xs = [0.0f32; 8];
    x.store(&mut xs);
    let mut reduced = [0.0f32; 8];
    let mut k = [0.0f32; 8];
    for l in 0..8 {
        let ix = xs[l].to_bits().wrapping_add(0x3f80_0000 - 0x3f35_04f3);
        k[l] = ((ix >> 23) as i32 - 0x7f) as f32;
        reduced[l] = f32::from_bits((ix & 0x007f_ffff) + 0x3f35_04f3);
    }
    let one = V::splat(1.0);
    let f = V::load(&reduced) - one;
    let s = f / (V::splat(2.0) + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (V::splat(LG2) + w * V::splat(LG4));
    let t2 = z * (V::splat(LG1) + w * V::splat(LG3));
    let r = t2 + t1;
    let hfsq = V::splat(0.5) * f * f;
    // hi = f − hfsq with its low 12 mantissa bits cleared.
    let hi = (f - hfsq).and(V::splat(f32::from_bits(0xffff_f000)));
    let lo = f - hi - hfsq + s * (hfsq + r);
    (lo + hi) * V::splat(IVLN2LO) + lo * V::splat(IVLN2HI) + hi * V::splat(IVLN2HI) + V::load(&k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::simd::Sse8;

    /// Every lane equals libm's bits: random positive normal numbers over
    /// the whole exponent range, the reduction's boundary near √2, and the
    /// ends of the range.
    #[test]
    fn eight_lanes_match_libm_bit_for_bit() {
        let mut seed = 0x2545_f491u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        let mut values: Vec<f32> = vec![
            1.000_000_1,
            0.999_999_94,
            2.0,
            1.5,
            f32::from_bits(0x3fb5_04f3),
            f32::from_bits(0x3fb5_04f2),
            f32::from_bits(0x3f35_04f3),
            f32::from_bits(0x3f35_04f2),
            f32::MAX,
            f32::MIN_POSITIVE,
            1e-30,
            3.0e7,
        ];
        while values.len() < 80_000 {
            // A positive normal finite number: exponent field 1..=254.
            let bits = next() & 0x7fff_ffff;
            let e = bits >> 23;
            if (1..=254).contains(&e) && bits != 0x3f80_0000 {
                values.push(f32::from_bits(bits));
            }
        }
        for chunk in values.chunks_exact(8) {
            let got = log2f8(Sse8::load(chunk.try_into().expect("8")));
            let mut out = [0.0f32; 8];
            got.store(&mut out);
            for (x, y) in chunk.iter().zip(out) {
                assert_eq!(y.to_bits(), libm::log2f(*x).to_bits(), "log2({x:e})");
            }
        }
    }
}
