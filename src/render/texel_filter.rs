//! Fixed-point bilinear filtering: the blend of a lookup's four RGBA8
//! texels with 8-bit sub-texel weights, shared by the one-pixel sampler
//! and the eight-lane one.
//!
//! The formula is OpenGL 4.6 §8.14.2's LINEAR filter (equation 8.9),
//! τ = (1−α)(1−β)·τ₀₀ + α(1−β)·τ₁₀ + (1−α)β·τ₀₁ + αβ·τ₁₁, taken as two
//! horizontal lerps and one vertical one. α and β are quantised to
//! 1/256 of a texel, as GPUs do (Direct3D 11 asks for 8 bits of sub-texel
//! precision; llvmpipe filters 8-bit texels the same way). Why fixed
//! point: every step is then a small integer product, two channels of
//! eight pixels share one 32-bit lane (R and B, G and A, 16 bits each),
//! and the lane sampler does the same integer steps as the one-pixel one,
//! so both give the same bits by construction, with no float rounding to
//! keep in step.
//!
//! The horizontal lerps give 8.8 fixed-point values, rounded to 8 bits
//! (the rounding GPUs do between the two passes); the vertical lerp gives
//! 0..=255·256 without a second rounding. [`UNIT`] turns that into 0..1.

/// A weight of one whole texel.
const ONE: u32 = 256;

/// The low byte of each 16-bit half of a word.
const LOW: u32 = 0x00FF_00FF;

/// Scale from a filtered channel (0..=255·256) to 0..1.
pub const UNIT: f32 = 1.0 / (255.0 * 256.0);

/// A sub-texel fraction `f` (0 ≤ f ≤ 1) as a weight in 0..=256: f·256
/// rounded to nearest (f32 arithmetic, then truncation of a positive
/// value, as the lanes' `trunc_i32` does).
#[inline(always)]
pub fn weight(f: f32) -> u32 {
    (f * 256.0 + 0.5) as i32 as u32
}

/// The bilinear blend of the four RGBA8 words `c` (top left, top right,
/// bottom left, bottom right; R in the low byte) with horizontal weight
/// `wx` and vertical weight `wy` (0..=256, towards the right and the bottom
/// texels): `[R | B << 16, G | A << 16]`, each channel in 0..=255·256.
///
/// Each 16-bit half holds one channel all the way through: a channel times
/// a weight is at most 255·256 < 2¹⁶, so no half carries into the other.
#[inline(always)]
pub fn bilerp(c: [u32; 4], wx: u32, wy: u32) -> [u32; 2] {
    let (ix, iy) = (ONE - wx, ONE - wy);
    let rb = |w: u32| w & LOW;
    let ga = |w: u32| (w >> 8) & LOW;
    // Horizontal: 8.8 fixed point per channel, rounded to 8 bits.
    let row = |a: u32, b: u32| ((a * ix + b * wx + 0x0080_0080) >> 8) & LOW;
    let (top_rb, top_ga) = (row(rb(c[0]), rb(c[1])), row(ga(c[0]), ga(c[1])));
    let (bot_rb, bot_ga) = (row(rb(c[2]), rb(c[3])), row(ga(c[2]), ga(c[3])));
    // Vertical: 8 bits times a weight, up to 255·256 per channel.
    [top_rb * iy + bot_rb * wy, top_ga * iy + bot_ga * wy]
}

/// A blended pair's low channel (R or G) and high one (B or A), 0..1.
#[inline(always)]
pub fn channels(pair: u32) -> (f32, f32) {
    ((pair & 0xFFFF) as f32 * UNIT, (pair >> 16) as f32 * UNIT)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One channel worked out by hand from the formula, per channel.
    fn by_hand(c: [[u8; 4]; 4], wx: u32, wy: u32, ch: usize) -> u32 {
        let row = |a: u8, b: u8| (a as u32 * (256 - wx) + b as u32 * wx + 128) >> 8;
        let top = row(c[0][ch], c[1][ch]);
        let bottom = row(c[2][ch], c[3][ch]);
        top * (256 - wy) + bottom * wy
    }

    /// The packed halves equal the per-channel arithmetic for extreme and
    /// random texels and every weight from 0 to 256.
    #[test]
    fn packed_channels_equal_the_formula_per_channel() {
        let mut seed = 99u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed
        };
        for round in 0..3000 {
            let c: [[u8; 4]; 4] = match round {
                0 => [[255; 4]; 4],
                1 => [[0; 4]; 4],
                2 => [[255, 0, 255, 0], [0, 255, 0, 255], [255; 4], [0; 4]],
                _ => std::array::from_fn(|_| next().to_le_bytes()),
            };
            let (wx, wy) = (next() % 257, (round as u32 * 7) % 257);
            let [rb, ga] = bilerp(c.map(u32::from_le_bytes), wx, wy);
            let got = [rb & 0xFFFF, ga & 0xFFFF, rb >> 16, ga >> 16];
            for (ch, &g) in got.iter().enumerate() {
                assert_eq!(g, by_hand(c, wx, wy, ch), "{c:?} {wx} {wy} ch {ch}");
            }
        }
    }

    /// Whole weights pick texels exactly, white stays exactly 1, and the
    /// weights round to nearest 1/256.
    #[test]
    fn corners_white_and_weights() {
        let c = [0x0403_0201, 0x0807_0605, 0x0c0b_0a09, 0x100f_0e0d];
        assert_eq!(bilerp(c, 0, 0), [(1 | 3 << 16) * 256, (2 | 4 << 16) * 256]);
        assert_eq!(
            bilerp(c, 256, 256),
            [(13 | 15 << 16) * 256, (14 | 16 << 16) * 256]
        );
        let [rb, ga] = bilerp([u32::MAX; 4], 100, 200);
        assert_eq!((channels(rb), channels(ga)), ((1.0, 1.0), (1.0, 1.0)));
        assert_eq!([weight(0.0), weight(0.5), weight(1.0)], [0, 128, 256]);
        assert_eq!([weight(0.4 / 256.0), weight(0.6 / 256.0)], [0, 1]);
    }
}
