//! Trilinear sampling for eight pixels at once, with exactly the bits of
//! the one-pixel [`Sampler::texel`].
//!
//! Why a second path: sampling one lane at a time (two bilinear lookups,
//! each a function call with its own `floorf` calls and integer
//! conversions) cost more than three times the whole lighting of a pixel.
//! Here the coordinate arithmetic and the four lerps per level run on
//! [`V8`] lanes, the level of detail's `log2` too (`log2_lanes`, the same
//! bits as the one-pixel sampler's); only what is per lane by nature stays scalar: choosing the mip
//! level and fetching the texels. Every lane
//! does the same operations (IEEE f32, then `texel_filter`'s integer
//! filter) in the same order as `texel` →
//! `sample` → `bilinear`, so the picture does not change.
//!
//! Lanes the fast path does not cover fall back to `texel` lane by lane: a
//! texture transform other than the identity, mirrored wraps, glTF's
//! NEAREST/non-trilinear filters, and NaN footprints (where `f32::max` and
//! `MAXPS` disagree).

use super::log2_lanes::log2_fast8;
use super::simd::V8;
use super::texel_block::filter;
use super::texture::Sampler;
use crate::scene::{MipLevel, TextureModel};
use glam::{Vec2, Vec4};

/// Texture coordinates of eight lanes and their screen derivatives.
pub struct UvIn<V> {
    pub u: V,
    pub v: V,
    pub du_dx: V,
    pub dv_dx: V,
    pub du_dy: V,
    pub dv_dy: V,
    /// Set where every lane has the same derivatives, as on a triangle
    /// without perspective, and finite `u` and `v` (`BlockPlanes::uv_in`).
    /// The lanes above hold the derivatives too.
    pub flat: Option<Flat>,
    /// The level of detail of every lane in the item's texture, when the
    /// caller knows it ([`FlatLod`]): [`Sampler::texel8_lod`] reads it.
    pub tex_lod: Option<f32>,
}

/// Derivatives shared by every lane of a block: `g` / `q`.
#[derive(Clone, Copy, Debug)]
pub struct Flat {
    /// ∂(u/w)/∂x, ∂(v/w)/∂x, ∂(u/w)/∂y, ∂(v/w)/∂y (`Tri::grad`).
    pub g: [f32; 4],
    /// 1/w, the same over the triangle.
    pub q: f32,
    /// The triangle (index into `Prepared::opaque`) they belong to.
    pub tri: u32,
}

/// The level of detail of the last flat triangle (`UvIn::flat`) a tile's
/// shading pass met, in its item's texture.
///
/// Why: with the derivatives constant over the triangle, so is λ; worked
/// out per block (even as one scalar) it sits on the path to the mip
/// level that every texel fetch waits for, and per lane it is a dozen
/// vector steps. Kept from the triangle's first block, the blocks after it
/// (a tile row shows one or two triangles of a large one) read a number.
#[derive(Clone, Copy, Debug)]
pub struct FlatLod {
    tri: u32,
    lod: f32,
}

impl Default for FlatLod {
    fn default() -> Self {
        FlatLod {
            tri: u32::MAX,
            lod: 0.0,
        }
    }
}

impl FlatLod {
    /// λ of `flat`'s lanes in `s` (the texture of the triangle's item, the
    /// only sampler asked through one `FlatLod`): `Sampler::lod` on the
    /// shared derivatives, which is each lane's λ bit for bit (the lanes'
    /// ρ², `log2_fast8` and range test are the same IEEE steps).
    #[inline(always)]
    pub fn of(&mut self, flat: &Flat, s: &Sampler) -> f32 {
        if flat.tri != self.tri {
            // The lanes' derivatives: ∂U/∂x · s with s = 1/q.
            let inv_q = 1.0 / flat.q;
            let d = flat.g.map(|g| g * inv_q);
            self.lod = s.lod(Vec2::new(d[0], d[1]), Vec2::new(d[2], d[3]));
            self.tri = flat.tri;
        }
        self.lod
    }
}

impl Sampler {
    /// [`Sampler::texel`] for eight lanes, as R, G, B, A lanes in 0..1.
    /// Inlined into the shading loop: called once per block as a function
    /// (inputs and outputs through memory), the sampler measured 8 % slower.
    #[inline(always)]
    pub fn texel8<V: V8>(&self, uv: &UvIn<V>) -> [V; 4] {
        self.texel8_in(uv, super::simd::avx512())
    }

    /// [`Sampler::texel8`]'s work; `wide`: blend two levels in one 16-lane
    /// pass (`trilinear16`, only after `simd::avx512()` said yes; a test
    /// compares both ways).
    #[inline(always)]
    pub(super) fn texel8_in<V: V8>(&self, uv: &UvIn<V>, wide: bool) -> [V; 4] {
        // No closures over lanes here: a closure lacks the caller's AVX
        // target feature, and lane operations inside it become calls.
        let base = self.image().base();
        let (bw, bh) = (
            V::splat(base.width() as f32),
            V::splat(base.height() as f32),
        );
        // Level of detail as `Sampler::lod`: ρ² = max(|ddx·size|², |ddy·size|²).
        let (xx, xy) = (uv.du_dx * bw, uv.dv_dx * bh);
        let (yx, yy) = (uv.du_dy * bw, uv.dv_dy * bh);
        let lx = xx * xx + xy * xy;
        let ly = yx * yx + yy * yy;
        let no_nan = lx.eq(lx).and(ly.eq(ly)).bits() == 0xFF;
        if !self.lanes_cover() || !no_nan {
            return self.texel8_by_lane(uv);
        }
        // λ = ½·log2(ρ²) where ρ² > 1 (`log2_fast`'s bits, on lanes); 0 where
        // ρ² ≤ 1, and where ρ² = ∞ (λ would not be finite).
        let rho2 = lx.max(ly);
        let in_range = rho2.gt(V::splat(1.0)).and(rho2.le(V::splat(f32::MAX)));
        let safe = V::select(in_range, rho2, V::splat(2.0));
        // All magnified (the common close-up): λ = 0 without the log.
        let lod = if in_range.bits() == 0 {
            V::splat(0.0)
        } else {
            (V::splat(0.5) * log2_fast8(safe)).keep(in_range)
        };
        if let Some(out) = self.texel8_at_level(level_guess(safe), lod, uv.u, uv.v, wide) {
            return out;
        }
        let lods = to_arr(lod);
        let levels = self.image().levels();
        let last = levels.len() - 1;
        // Per lane: the two levels and the blend fraction (`Sampler::sample`).
        let mut lv = [[0usize; 8]; 2];
        let mut frac = [0.0f32; 8];
        for k in 0..8 {
            let lod = lods[k].max(0.0);
            if lod >= last as f32 {
                // One level: blending it with itself by 0 gives it exactly.
                lv[0][k] = last;
                lv[1][k] = last;
            } else {
                let i = lod as usize;
                lv[0][k] = i;
                lv[1][k] = i + 1;
                frac[k] = lod - i as f32;
            }
        }
        let a = self.bilinear8(levels, &lv[0], uv.u, uv.v);
        let b = self.bilinear8(levels, &lv[1], uv.u, uv.v);
        let f = V::load(&frac);
        let mut out = a;
        for c in 0..4 {
            out[c] = a[c] + (b[c] - a[c]) * f;
        }
        out
    }

    /// [`Sampler::texel8`] where every lane's level of detail is known to
    /// be `uv.tex_lod` (see [`FlatLod`]): the mip level pair is then known
    /// before anything else, and the level arithmetic is skipped.
    #[inline(always)]
    pub fn texel8_lod<V: V8>(&self, uv: &UvIn<V>) -> [V; 4] {
        self.texel8_lod_in(uv, super::simd::avx512())
    }

    /// [`Sampler::texel8_lod`]'s work (`wide` as in [`Sampler::texel8_in`]).
    #[inline(always)]
    pub(super) fn texel8_lod_in<V: V8>(&self, uv: &UvIn<V>, wide: bool) -> [V; 4] {
        if let (Some(lod), true) = (uv.tex_lod, self.lanes_cover()) {
            // `texel8_at_level`'s level (λ is finite and ≥ 0).
            let last = (self.image().levels().len() - 1) as f32;
            let i = lod.min(last) as usize;
            // Flat lanes were checked finite (`BlockPlanes::uv_in`).
            let finite = uv.flat.is_some();
            if let Some(out) = self.texel8_levels((i, V::splat(lod)), (uv.u, uv.v), finite, wide) {
                return out;
            }
        }
        self.texel8_in(uv, wide)
    }

    /// The slow path: `texel` per lane.
    fn texel8_by_lane<V: V8>(&self, uv: &UvIn<V>) -> [V; 4] {
        let (u, v) = (to_arr(uv.u), to_arr(uv.v));
        let (dudx, dvdx) = (to_arr(uv.du_dx), to_arr(uv.dv_dx));
        let (dudy, dvdy) = (to_arr(uv.du_dy), to_arr(uv.dv_dy));
        let mut out = [[0.0f32; 8]; 4];
        for k in 0..8 {
            let t = self.texel(
                Vec2::new(u[k], v[k]),
                Vec2::new(dudx[k], dvdx[k]),
                Vec2::new(dudy[k], dvdy[k]),
            );
            for (c, o) in out.iter_mut().enumerate() {
                o[k] = t[c];
            }
        }
        [
            V::load(&out[0]),
            V::load(&out[1]),
            V::load(&out[2]),
            V::load(&out[3]),
        ]
    }

    /// `Sampler::bilinear` for eight lanes, lane k in level `lv[k]`.
    #[inline(always)]
    fn bilinear8<V: V8>(&self, levels: &[MipLevel], lv: &[usize; 8], s: V, t: V) -> [V; 4] {
        let (ws, hs): ([f32; 8], [f32; 8]) = (
            std::array::from_fn(|k| levels[lv[k]].width() as f32),
            std::array::from_fn(|k| levels[lv[k]].height() as f32),
        );
        let (w, h) = (V::load(&ws), V::load(&hs));
        let (s, t) = self.reduce8(s, t);
        let f = self.footprint8(s, t, w, h);
        let (xa, xb) = (f.xa.trunc_i32(), f.xb.trunc_i32());
        let (ya, yb) = (f.ya.trunc_i32(), f.yb.trunc_i32());
        let mut corner = [[0u32; 8]; 4];
        for k in 0..8 {
            let level = &levels[lv[k]];
            let lw = level.width() as usize;
            let px = level.pixels();
            let (ra, rb) = (ya[k] as usize * lw, yb[k] as usize * lw);
            let (ca, cb) = (xa[k] as usize, xb[k] as usize);
            corner[0][k] = u32::from_le_bytes(px[ra + ca]);
            corner[1][k] = u32::from_le_bytes(px[ra + cb]);
            corner[2][k] = u32::from_le_bytes(px[rb + ca]);
            corner[3][k] = u32::from_le_bytes(px[rb + cb]);
        }
        filter(&corner, f.fx, f.fy, true)
    }
}

impl Sampler {
    /// [`Sampler::before_lighting`]'s diffuse colour for eight lanes (the
    /// opaque pass has no alpha to carry).
    #[inline(always)]
    pub fn before_lighting8<V: V8>(&self, t: &[V; 4], diffuse: [V; 3]) -> [V; 3] {
        match self.model {
            TextureModel::Vrml97 => match self.components {
                1 | 2 => [diffuse[0] * t[0], diffuse[1] * t[0], diffuse[2] * t[0]],
                _ => [t[0], t[1], t[2]],
            },
            TextureModel::MultiplyDiffuse => {
                [diffuse[0] * t[0], diffuse[1] * t[1], diffuse[2] * t[2]]
            }
            _ => diffuse,
        }
    }

    /// [`Sampler::after_lighting`]'s colour for eight lanes: MODULATE on
    /// lanes (`clamp` is max-then-min, and MAXPS sends NaN to 0 as
    /// `f32::max` does), the rarer models lane by lane.
    // Lane k of three channel arrays at once: an index loop reads best.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    pub fn after_lighting8<V: V8>(&self, t: &[V; 4], lit: [V; 3]) -> [V; 3] {
        if !self.acts_after_lighting() {
            return lit;
        }
        if self.model == TextureModel::Modulate {
            let (zero, one) = (V::splat(0.0), V::splat(1.0));
            return [
                lit[0].max(zero).min(one) * t[0],
                lit[1].max(zero).min(one) * t[1],
                lit[2].max(zero).min(one) * t[2],
            ];
        }
        let mut c = [to_arr(lit[0]), to_arr(lit[1]), to_arr(lit[2])];
        for k in 0..8 {
            let l = glam::Vec3::new(c[0][k], c[1][k], c[2][k]);
            let (o, _) = self.after_lighting(lane(t, k), l, 1.0);
            c[0][k] = o.x;
            c[1][k] = o.y;
            c[2][k] = o.z;
        }
        [V::load(&c[0]), V::load(&c[1]), V::load(&c[2])]
    }
}

/// The texel of `texel8`'s lanes as one pixel's RGBA (for the per-lane
/// texture models).
#[inline(always)]
pub fn lane<V: V8>(t: &[V; 4], k: usize) -> Vec4 {
    Vec4::new(
        to_arr(t[0])[k],
        to_arr(t[1])[k],
        to_arr(t[2])[k],
        to_arr(t[3])[k],
    )
}

/// The mip level a block's λ most likely starts at: ⌊e/2⌋ for lane 0's
/// ρ² (`safe`, in (1, f32::MAX]) = 2ᵉ·m, m in [1, 2). λ = ½·(e + log2 m)
/// and log2 m lies in [0, 1), so ⌊λ⌋ = ⌊e/2⌋ but for the polynomial's
/// rounding next to m = 2; the caller checks every lane's exact level
/// against it (a block whose lanes need other levels fails that check).
/// Only the exponent's bits: a few steps, where λ itself is a chain of a
/// dozen.
#[inline(always)]
fn level_guess<V: V8>(safe: V) -> usize {
    let x = to_arr(safe)[0];
    (((x.to_bits() >> 23).wrapping_sub(127)) >> 1) as usize
}

/// The lanes as an array.
#[inline(always)]
fn to_arr<V: V8>(v: V) -> [f32; 8] {
    let mut a = [0.0; 8];
    v.store(&mut a);
    a
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::render::simd::Sse8;
    use crate::scene::{Image, ImageId, ImageSource, Texture, Wrap};

    /// A `w`×`h` RGBA test image with different values in every channel
    /// (`mix` varies the pattern; `mix[2]` = 0 makes it opaque).
    pub fn image(w: u32, h: u32, mix: [u32; 3]) -> Image {
        let px = (0..h).flat_map(|y| (0..w).map(move |x| (x, y)));
        let f = |(x, y): (u32, u32)| {
            let v = (x * mix[0] + y * mix[1]) as u8;
            [v, v.wrapping_mul(3), 255 - v, 255 - (x * mix[2]) as u8]
        };
        Image::new("t", ImageSource::Inline, w, h, 4, px.map(f).collect()).unwrap()
    }

    /// Asserts that `texel8` gives every lane `texel`'s exact bits for the
    /// six coordinate lanes (u, v, du/dx, dv/dx, du/dy, dv/dy).
    #[allow(clippy::needless_range_loop)]
    pub fn assert_lanes_match(s: &Sampler, lanes: &[[f32; 8]; 6], what: &str) {
        let l = |i: usize| Sse8::load(&lanes[i]);
        let uv = UvIn {
            u: l(0),
            v: l(1),
            du_dx: l(2),
            dv_dx: l(3),
            du_dy: l(4),
            dv_dy: l(5),
            flat: None,
            tex_lod: None,
        };
        let got = s.texel8(&uv);
        for k in 0..8 {
            let want = s.texel(
                Vec2::new(lanes[0][k], lanes[1][k]),
                Vec2::new(lanes[2][k], lanes[3][k]),
                Vec2::new(lanes[4][k], lanes[5][k]),
            );
            let have = lane(&got, k);
            assert_eq!(
                have.to_array().map(f32::to_bits),
                want.to_array().map(f32::to_bits),
                "{what} lane {k}: {have} vs {want}"
            );
        }
    }

    /// Eight lanes give `texel`'s exact bits for magnified, minified,
    /// far-minified, repeated, clamped, negative and non-finite coordinates.
    #[test]
    #[allow(clippy::needless_range_loop)]
    fn eight_lanes_match_one_pixel_bit_for_bit() {
        let img = image(64, 32, [37, 91, 7]);
        let mut seed = 12345u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32
        };
        for wrap in [(Wrap::Repeat, Wrap::Repeat), (Wrap::Clamp, Wrap::Repeat)] {
            let mut tex = Texture::new(ImageId(0));
            (tex.wrap_s, tex.wrap_t) = wrap;
            let s = Sampler::new(&tex, &img);
            for round in 0..400 {
                let scale = [0.001, 0.02, 0.1, 1.0, 30.0][round % 5];
                let mut lanes = [[0.0f32; 8]; 6];
                for k in 0..8 {
                    lanes[0][k] = (rnd() - 0.3) * 6.0;
                    lanes[1][k] = (rnd() - 0.5) * 4.0;
                    for d in 2..6 {
                        lanes[d][k] = (rnd() - 0.5) * scale;
                    }
                }
                if round == 7 {
                    lanes[0][3] = f32::INFINITY;
                    lanes[1][5] = f32::NAN;
                    lanes[2][6] = f32::NAN;
                }
                assert_lanes_match(&s, &lanes, &format!("round {round}"));
            }
        }
    }
}
