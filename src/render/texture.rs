//! Texture sampling and how a texel combines with lighting.
//!
//! Sampling is trilinear: bilinear within the two mip levels around the
//! level of detail, blended by its fraction (the level of detail is log2 of
//! the larger of the two screen-axis footprints in texels, as in the OpenGL
//! 1.x specification §3.8.5). Texture coordinates follow VRML: (0, 0) is
//! the image's lower-left corner, s to the right, t up. Repeat wraps the
//! texel index, clamp clamps it (OpenGL `CLAMP_TO_EDGE`). Within a level
//! the four texels blend in fixed point with 8-bit sub-texel weights
//! (`texel_filter`, as GPUs do); the level blend is f32.
//!
//! Combining follows [`TextureModel`]: the VRML97 rules of ISO/IEC 14772-1
//! §4.14.3 (table 4.5) and the OpenGL texture environment functions that
//! Inventor's MODULATE/DECAL/BLEND name (OpenGL 1.1 table 3.18).
//! Everything else is plain f32 arithmetic with no fused operations, so
//! results are the same on every machine and for any thread count.

use super::log2_lanes::log2_fast;
use super::texel_filter::{bilerp, channels, weight};
use super::trilinear16::PairSizes;
use crate::scene::{Filter, Image, MipLevel, MipMode, Texture, TextureModel, Wrap};
use glam::{Affine2, Vec2, Vec3, Vec4};

/// A texture ready to sample: the image (a cheap shared clone), wraps and
/// matrix.
#[derive(Clone, Debug)]
pub struct Sampler {
    image: Image,
    wrap_s: Wrap,
    wrap_t: Wrap,
    matrix: Affine2,
    identity: bool,
    pub model: TextureModel,
    /// Components of the source image (1..=4).
    pub components: u8,
    blend_color: Vec3,
    translucent: bool,
    /// Every texel's alpha is 255 (then sampled alpha is exactly
    /// 255 · (1/255) everywhere, and the lanes need not filter it).
    opaque: bool,
    filter: Filter,
    alpha_cutoff: Option<f32>,
    /// See [`Sampler::lanes_cover`].
    lanes: bool,
    /// Per mip level pair (level i and i + 1), its sizes for the 16-lane
    /// pass; empty where that pass does not run (no AVX-512, or a
    /// sampler the lanes do not cover).
    pairs: Vec<PairSizes>,
}

impl Sampler {
    pub fn new(t: &Texture, image: &Image) -> Sampler {
        let uses_alpha = matches!(image.components(), 2 | 4) && t.model != TextureModel::Decal;
        let lanes = t.transform.is_identity()
            && t.filter == Filter::default()
            && t.wrap_s != Wrap::Mirror
            && t.wrap_t != Wrap::Mirror;
        let pairs = if lanes && super::simd::avx512() {
            let levels = image.levels();
            levels
                .windows(2)
                .map(|l| PairSizes::of(&l[0], &l[1]))
                .collect()
        } else {
            Vec::new()
        };
        Sampler {
            image: image.clone(),
            wrap_s: t.wrap_s,
            wrap_t: t.wrap_t,
            matrix: t.transform.matrix(),
            identity: t.transform.is_identity(),
            model: t.model,
            components: image.components(),
            blend_color: t.blend_color,
            translucent: uses_alpha && image.has_alpha(),
            opaque: !image.has_alpha(),
            filter: t.filter,
            alpha_cutoff: t.alpha_cutoff,
            lanes,
            pairs,
        }
    }

    /// The image sampled.
    pub(super) fn image(&self) -> &Image {
        &self.image
    }
    pub(super) fn wrap_s(&self) -> Wrap {
        self.wrap_s
    }
    pub(super) fn wrap_t(&self) -> Wrap {
        self.wrap_t
    }
    /// Whether every texel is fully opaque.
    pub(super) fn opaque(&self) -> bool {
        self.opaque
    }
    /// Whether the eight-lane path (`texture_lanes`) covers this sampler:
    /// repeat/clamp wraps, trilinear filtering, no transform (worked out
    /// once in `new`: it is asked for every block).
    pub(super) fn lanes_cover(&self) -> bool {
        self.lanes
    }
    /// The sizes of level pair `i` for the 16-lane pass, if it runs.
    pub(super) fn pair_sizes(&self, i: usize) -> Option<&PairSizes> {
        self.pairs.get(i)
    }

    /// Whether pixels are alpha-tested (glTF MASK): then a pixel of alpha
    /// 0 from [`Sampler::masked`] is not drawn at all.
    pub fn masks(&self) -> bool {
        self.alpha_cutoff.is_some()
    }

    /// The alpha after the alpha test: 1 at or above the cutoff, 0 below
    /// (unchanged without one).
    pub fn masked(&self, alpha: f32) -> f32 {
        match self.alpha_cutoff {
            Some(c) if alpha >= c => 1.0,
            Some(_) => 0.0,
            None => alpha,
        }
    }

    /// Whether the texture can make pixels partly transparent (then its
    /// shape is drawn with the transparent ones, sorted back to front).
    pub fn translucent(&self) -> bool {
        self.translucent
    }

    /// The mesh texture coordinate after the texture transform.
    #[inline]
    pub fn transform(&self, uv: Vec2) -> Vec2 {
        if self.identity {
            uv
        } else {
            self.matrix.transform_point2(uv)
        }
    }

    /// A derivative of (s, t) after the texture transform.
    #[inline]
    pub fn transform_vector(&self, d: Vec2) -> Vec2 {
        if self.identity {
            d
        } else {
            self.matrix.transform_vector2(d)
        }
    }

    /// Level of detail from the screen-space derivatives of the
    /// (transformed) coordinates: log2 of the longer footprint axis in
    /// base-level texels. ≤ 0 means magnified.
    pub fn lod(&self, ddx: Vec2, ddy: Vec2) -> f32 {
        let base = self.image.base();
        let size = Vec2::new(base.width() as f32, base.height() as f32);
        let (x, y) = (ddx * size, ddy * size);
        let rho2 = x.length_squared().max(y.length_squared());
        // Also catches NaN footprints; an infinite one reads as magnified.
        if !(rho2 > 1.0 && rho2 <= f32::MAX) {
            return 0.0;
        }
        // log2(rho) = log2(rho²) / 2, division-free (`log2_lanes`).
        0.5 * log2_fast(rho2)
    }

    /// The filtered RGBA (0..1) at transformed coordinates `st`.
    pub fn sample(&self, st: Vec2, lod: f32) -> Vec4 {
        if self.filter != Filter::default() {
            return self.sample_filtered(st, lod);
        }
        let levels = self.image.levels();
        let last = levels.len() - 1;
        let lod = if lod.is_finite() { lod.max(0.0) } else { 0.0 };
        if lod >= last as f32 {
            return self.bilinear(&levels[last], st);
        }
        let i = lod as usize;
        let f = lod - i as f32;
        let a = self.bilinear(&levels[i], st);
        if f == 0.0 {
            return a;
        }
        let b = self.bilinear(&levels[i + 1], st);
        a + (b - a) * f
    }

    /// [`Sampler::sample`] with glTF's other filters (OpenGL 4.6 §8.14,
    /// §8.15): λ ≤ 0 is magnification (the mag filter on the base level);
    /// minified, MIPMAP_NEAREST takes level ⌈λ + ½⌉ − 1 (0 for λ ≤ ½),
    /// MIPMAP_LINEAR blends the two levels around λ, no mipmap stays on the
    /// base level; within a level NEAREST takes the texel under the point.
    fn sample_filtered(&self, st: Vec2, lod: f32) -> Vec4 {
        let levels = self.image.levels();
        let last = levels.len() - 1;
        let lod = if lod.is_finite() { lod } else { 0.0 };
        let in_level = |level: &MipLevel, nearest: bool| {
            if nearest {
                self.nearest(level, st)
            } else {
                self.bilinear(level, st)
            }
        };
        if lod <= 0.0 {
            return in_level(&levels[0], self.filter.mag_nearest);
        }
        let nearest = self.filter.min_nearest;
        match self.filter.mip {
            MipMode::None => in_level(&levels[0], nearest),
            MipMode::Nearest => {
                let d = if lod <= 0.5 {
                    0
                } else {
                    ((lod + 0.5).ceil() as usize).saturating_sub(1)
                };
                in_level(&levels[d.min(last)], nearest)
            }
            MipMode::Linear => {
                if lod >= last as f32 {
                    return in_level(&levels[last], nearest);
                }
                let i = lod as usize;
                let f = lod - i as f32;
                let a = in_level(&levels[i], nearest);
                let b = in_level(&levels[i + 1], nearest);
                a + (b - a) * f
            }
        }
    }

    /// A coordinate reduced to one period of its wrap (two for mirror), so
    /// huge values keep their fraction; non-finite ones read as 0.
    fn reduce(c: f32, wrap: Wrap) -> f32 {
        let c = if c.is_finite() { c } else { 0.0 };
        match wrap {
            Wrap::Repeat => c - c.floor(),
            Wrap::Mirror => c - 2.0 * (c * 0.5).floor(),
            Wrap::Clamp => c,
        }
    }

    /// The texel under `st` in one level (OpenGL NEAREST: ⌊s·w⌋).
    fn nearest(&self, level: &MipLevel, st: Vec2) -> Vec4 {
        let (w, h) = (level.width() as i64, level.height() as i64);
        let s = Self::reduce(st.x, self.wrap_s);
        let t = Self::reduce(st.y, self.wrap_t);
        let x = (s * w as f32).floor().clamp(-2.0, 2.0 * w as f32) as i64;
        let y = ((1.0 - t) * h as f32).floor().clamp(-2.0, 2.0 * h as f32) as i64;
        let p = level.pixels()[wrap(y, h, self.wrap_t) * w as usize + wrap(x, w, self.wrap_s)];
        Vec4::new(p[0] as f32, p[1] as f32, p[2] as f32, p[3] as f32) * (1.0 / 255.0)
    }

    /// Bilinear filtering in one level (texel centres at half-integers),
    /// in fixed point (see `texel_filter`).
    fn bilinear(&self, level: &MipLevel, st: Vec2) -> Vec4 {
        let (w, h) = (level.width() as i64, level.height() as i64);
        let s = if st.x.is_finite() { st.x } else { 0.0 };
        let t = if st.y.is_finite() { st.y } else { 0.0 };
        // Reduce repeating coordinates to one period first so huge values
        // keep their fraction.
        let s = if self.wrap_s == Wrap::Repeat {
            s - s.floor()
        } else {
            s
        };
        let t = if self.wrap_t == Wrap::Repeat {
            t - t.floor()
        } else {
            t
        };
        // Mirrored: two periods (the scalar forms above stay as they were,
        // so repeat and clamp keep their bits).
        let s = if self.wrap_s == Wrap::Mirror {
            Self::reduce(s, Wrap::Mirror)
        } else {
            s
        };
        let t = if self.wrap_t == Wrap::Mirror {
            Self::reduce(t, Wrap::Mirror)
        } else {
            t
        };
        let x = s * w as f32 - 0.5;
        // Rows are stored top first; t = 0 is the bottom row.
        let y = (1.0 - t) * h as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        // Within two texels of the period (mirrored: two periods, and
        // their flips 1 − t), so the indices stay small.
        let keep = |c: f32, n: i64, wrap: Wrap| {
            let n = n as f32;
            match wrap {
                Wrap::Mirror => c.clamp(-2.0 * n - 2.0, 2.0 * n),
                _ => c.clamp(-2.0, n),
            }
        };
        let (x0, y0) = (
            keep(x0, w, self.wrap_s) as i64,
            keep(y0, h, self.wrap_t) as i64,
        );
        let xs = [wrap(x0, w, self.wrap_s), wrap(x0 + 1, w, self.wrap_s)];
        let ys = [wrap(y0, h, self.wrap_t), wrap(y0 + 1, h, self.wrap_t)];
        let px = level.pixels();
        let at = |x: usize, y: usize| u32::from_le_bytes(px[y * w as usize + x]);
        let corners = [
            at(xs[0], ys[0]),
            at(xs[1], ys[0]),
            at(xs[0], ys[1]),
            at(xs[1], ys[1]),
        ];
        let [rb, ga] = bilerp(corners, weight(fx), weight(fy));
        let ((r, b), (g, a)) = (channels(rb), channels(ga));
        Vec4::new(r, g, b, a)
    }

    /// The diffuse colour and alpha lighting starts from, given a texel and
    /// the material's (or colour node's) diffuse colour and alpha. Models
    /// that act after lighting leave them unchanged.
    #[inline]
    pub fn before_lighting(&self, texel: Vec4, diffuse: Vec3, alpha: f32) -> (Vec3, f32) {
        let rgb = texel.truncate();
        match self.model {
            TextureModel::Vrml97 => match self.components {
                1 => (diffuse * rgb.x, alpha),
                2 => (diffuse * rgb.x, texel.w),
                3 => (rgb, alpha),
                _ => (rgb, texel.w),
            },
            TextureModel::Modulate => (diffuse, alpha * texel.w),
            TextureModel::MultiplyDiffuse => (diffuse * rgb, alpha * texel.w),
            _ => (diffuse, alpha),
        }
    }

    /// Whether the texel replaces the diffuse colour outright (VRML97's
    /// RGB and RGBA textures, §4.14.3 table 4.5): the interpolated colour
    /// is then never read.
    #[inline]
    pub fn replaces_diffuse(&self) -> bool {
        self.model == TextureModel::Vrml97 && self.components >= 3
    }

    /// Whether [`Sampler::after_lighting`] changes anything.
    #[inline]
    pub fn acts_after_lighting(&self) -> bool {
        matches!(
            self.model,
            TextureModel::Replace
                | TextureModel::Modulate
                | TextureModel::Decal
                | TextureModel::Blend
        )
    }

    /// The final colour and alpha from a texel and the lit colour, for the
    /// models that act after lighting (others return `lit`, clamped to 0..1).
    #[inline]
    pub fn after_lighting(&self, texel: Vec4, lit: Vec3, alpha: f32) -> (Vec3, f32) {
        let rgb = texel.truncate();
        let has_alpha = matches!(self.components, 2 | 4);
        // OpenGL clamps the lit colour to 0..1 before the texture function.
        let lit = lit.clamp(Vec3::ZERO, Vec3::ONE);
        match self.model {
            TextureModel::Replace => (rgb, if has_alpha { texel.w } else { alpha }),
            // The alpha was multiplied before lighting.
            TextureModel::Modulate => (lit * rgb, alpha),
            TextureModel::Decal => {
                let a = if has_alpha { texel.w } else { 1.0 };
                (lit + (rgb - lit) * a, alpha)
            }
            TextureModel::Blend => (
                lit * (Vec3::ONE - rgb) + self.blend_color * rgb,
                if has_alpha { alpha * texel.w } else { alpha },
            ),
            _ => (lit, alpha),
        }
    }
}

impl Sampler {
    /// Everything for one pixel: the texel at mesh coordinates `uv` with
    /// screen derivatives `ddx`, `ddy` (before the texture transform).
    #[inline]
    pub fn texel(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
        let st = self.transform(uv);
        let lod = self.lod(self.transform_vector(ddx), self.transform_vector(ddy));
        self.sample(st, lod)
    }
}

/// A texel index wrapped (repeat) or clamped into `0..n`. Indices come
/// within a period or two of the image (the bilinear footprint of a
/// coordinate already reduced to one period), so repeat wraps by one
/// addition or subtraction and divides only in the rare rest (same result
/// as `rem_euclid`, without an integer division per texel).
#[inline]
pub(super) fn wrap(i: i64, n: i64, mode: Wrap) -> usize {
    match mode {
        Wrap::Repeat => {
            let j = if i < 0 {
                i + n
            } else if i >= n {
                i - n
            } else {
                i
            };
            if (0..n).contains(&j) {
                j as usize
            } else {
                i.rem_euclid(n) as usize
            }
        }
        Wrap::Clamp => i.clamp(0, n - 1) as usize,
        // OpenGL 4.6 §8.14.2: period 2n, the second half flipped.
        Wrap::Mirror => {
            let j = i.rem_euclid(2 * n);
            (if j < n { j } else { 2 * n - 1 - j }) as usize
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{ImageId, ImageSource};

    fn image(w: u32, h: u32, comps: u8, f: impl Fn(u32, u32) -> [u8; 4]) -> Image {
        let px = (0..h).flat_map(|y| (0..w).map(move |x| (x, y)));
        Image::new(
            "t",
            ImageSource::Inline,
            w,
            h,
            comps,
            px.map(|(x, y)| f(x, y)).collect(),
        )
        .unwrap()
    }

    fn tex() -> Texture {
        Texture::new(ImageId(0))
    }

    #[test]
    fn texel_centres_and_orientation() {
        // 2x2: top row red, green; bottom row blue, white.
        let img = image(2, 2, 3, |x, y| {
            [
                [[255, 0, 0, 255], [0, 255, 0, 255]],
                [[0, 0, 255, 255], [255; 4]],
            ][y as usize][x as usize]
        });
        let s = Sampler::new(&tex(), &img);
        let red = s.sample(Vec2::new(0.25, 0.75), 0.0);
        assert_eq!(red, Vec4::new(1.0, 0.0, 0.0, 1.0));
        let blue = s.sample(Vec2::new(0.25, 0.25), 0.0);
        assert_eq!(blue, Vec4::new(0.0, 0.0, 1.0, 1.0));
        // Half-way between red and green texel centres: weight 128/256,
        // and 127.5 rounds to 128 in the 8-bit horizontal pass.
        let mid = s.sample(Vec2::new(0.5, 0.75), 0.0);
        let half = 128.0 / 255.0;
        assert!((mid - Vec4::new(half, half, 0.0, 1.0)).abs().max_element() < 1e-6);
    }

    #[test]
    fn repeat_wraps_and_clamp_holds_the_edge() {
        let img = image(
            2,
            1,
            3,
            |x, _| if x == 0 { [0, 0, 0, 255] } else { [255; 4] },
        );
        let mut t = tex();
        let rep = Sampler::new(&t, &img);
        // s = 0 lies between the last and first texel when repeating.
        assert!((rep.sample(Vec2::new(0.0, 0.5), 0.0).x - 128.0 / 255.0).abs() < 1e-6);
        assert_eq!(rep.sample(Vec2::new(3.25, 0.5), 0.0).x, 0.0);
        t.wrap_s = Wrap::Clamp;
        let cl = Sampler::new(&t, &img);
        assert_eq!(cl.sample(Vec2::new(0.0, 0.5), 0.0).x, 0.0);
        assert_eq!(cl.sample(Vec2::new(-5.0, 0.5), 0.0).x, 0.0);
        assert_eq!(cl.sample(Vec2::new(7.0, 0.5), 0.0).x, 1.0);
        // Non-finite coordinates do not panic.
        let _ = rep.sample(Vec2::new(f32::NAN, f32::INFINITY), f32::NAN);
    }

    #[test]
    fn mirrored_repeat_flips_every_other_period() {
        // 4 texels: 0, 85, 170, 255 left to right.
        let img = image(4, 1, 3, |x, _| [(x * 85) as u8; 4]);
        let mut t = tex();
        t.wrap_s = Wrap::Mirror;
        t.filter.mag_nearest = true;
        let s = Sampler::new(&t, &img);
        let at = |u: f32| (s.sample(Vec2::new(u, 0.5), 0.0).x * 255.0).round() as u32;
        // First period as is, second flipped, third as is; negative side
        // mirrored about 0.
        assert_eq!([at(0.1), at(0.4), at(0.9)], [0, 85, 255]);
        assert_eq!([at(1.1), at(1.4), at(1.9)], [255, 170, 0]);
        assert_eq!([at(2.1), at(-0.1), at(-0.9)], [0, 0, 255]);
        assert_eq!(wrap(-1, 4, Wrap::Mirror), 0);
        assert_eq!(wrap(4, 4, Wrap::Mirror), 3);
        assert_eq!(wrap(9, 4, Wrap::Mirror), 1);
        // Bilinear across the mirror seam at s = 1 blends texel 3 with itself.
        t.filter.mag_nearest = false;
        let s = Sampler::new(&t, &img);
        assert_eq!(s.sample(Vec2::new(1.0, 0.5), 0.0).x, 1.0);
        // Bilinear in the flipped period reads as its mirror image (it
        // once read the last texels there).
        for (u, m) in [(1.5, 0.5), (1.75, 0.25), (-0.25, 0.25)] {
            let (a, b) = (
                s.sample(Vec2::new(u, 0.5), 0.0),
                s.sample(Vec2::new(m, 0.5), 0.0),
            );
            assert_eq!(a, b, "{u} mirrors {m}");
        }
    }

    #[test]
    fn nearest_filters_and_mip_modes() {
        // 4x4 checker of single texels: magnified nearest keeps hard edges.
        let img = image(4, 4, 3, |x, y| {
            if (x + y) % 2 == 0 {
                [255; 4]
            } else {
                [0, 0, 0, 255]
            }
        });
        let mut t = tex();
        t.filter.mag_nearest = true;
        let s = Sampler::new(&t, &img);
        assert_eq!(s.sample(Vec2::new(0.26, 0.99), 0.0).x, 0.0);
        assert_eq!(s.sample(Vec2::new(0.24, 0.99), 0.0).x, 1.0);
        // Minified with NEAREST and no mipmap: still a texel of the base level.
        t.filter.min_nearest = true;
        t.filter.mip = MipMode::None;
        let s = Sampler::new(&t, &img);
        assert!([0.0, 1.0].contains(&s.sample(Vec2::new(0.3, 0.3), 2.0).x));
        // MIPMAP_NEAREST at λ = 1.6 takes level 2 (the 1x1 grey mean).
        t.filter.mip = MipMode::Nearest;
        let s = Sampler::new(&t, &img);
        let c = s.sample(Vec2::new(0.3, 0.3), 1.6).x;
        assert!((c - 0.5).abs() < 0.01, "{c}");
        // λ = 0.4: level 0.
        assert!([0.0, 1.0].contains(&s.sample(Vec2::new(0.3, 0.3), 0.4).x));
    }

    #[test]
    fn alpha_cutoff_is_a_test() {
        let img = image(1, 1, 4, |_, _| [9; 4]);
        let mut t = tex();
        let s = Sampler::new(&t, &img);
        assert!(!s.masks());
        assert_eq!(s.masked(0.3), 0.3);
        t.alpha_cutoff = Some(0.5);
        let s = Sampler::new(&t, &img);
        assert!(s.masks());
        assert_eq!(
            (s.masked(0.49), s.masked(0.5), s.masked(0.9)),
            (0.0, 1.0, 1.0)
        );
    }

    #[test]
    fn minified_checker_goes_grey() {
        let img = image(64, 64, 3, |x, y| {
            if (x + y) % 2 == 0 {
                [255; 4]
            } else {
                [0, 0, 0, 255]
            }
        });
        let s = Sampler::new(&tex(), &img);
        // One screen pixel covers 8 texels: lod 3.
        let lod = s.lod(Vec2::new(8.0 / 64.0, 0.0), Vec2::new(0.0, 8.0 / 64.0));
        assert!((lod - 3.0).abs() < 1e-6, "{lod}");
        let c = s.sample(Vec2::new(0.3, 0.7), lod);
        assert!((c.x - 0.5).abs() < 0.01, "{c}");
        // Magnified: lod 0.
        assert_eq!(s.lod(Vec2::new(0.001, 0.0), Vec2::ZERO), 0.0);
    }

    #[test]
    fn vrml97_component_rules() {
        let t = tex();
        let diffuse = Vec3::new(1.0, 0.5, 0.0);
        let texel = Vec4::new(0.5, 0.25, 1.0, 0.5);
        let check = |comps: u8| {
            let img = image(1, 1, comps, |_, _| [0; 4]);
            Sampler::new(&t, &img).before_lighting(texel, diffuse, 0.8)
        };
        assert_eq!(check(1), (diffuse * 0.5, 0.8));
        assert_eq!(check(2), (diffuse * 0.5, 0.5));
        assert_eq!(check(3), (texel.truncate(), 0.8));
        assert_eq!(check(4), (texel.truncate(), 0.5));
    }

    #[test]
    fn inventor_models() {
        let img = image(1, 1, 4, |_, _| [0; 4]);
        let texel = Vec4::new(1.0, 0.0, 0.0, 0.25);
        let lit = Vec3::new(0.0, 0.0, 1.0);
        let mut t = tex();
        t.model = TextureModel::Decal;
        let (c, a) = Sampler::new(&t, &img).after_lighting(texel, lit, 0.9);
        assert_eq!((c, a), (Vec3::new(0.25, 0.0, 0.75), 0.9));
        t.model = TextureModel::Blend;
        t.blend_color = Vec3::new(0.0, 1.0, 0.0);
        let (c, a) = Sampler::new(&t, &img).after_lighting(texel, lit, 0.8);
        assert_eq!((c, a), (Vec3::new(0.0, 0.0, 1.0), 0.2));
        t.model = TextureModel::Modulate;
        let s = Sampler::new(&t, &img);
        // The lit colour (specular included) times the texture, as GL_MODULATE.
        assert_eq!(
            s.before_lighting(texel, Vec3::splat(0.5), 0.8),
            (Vec3::splat(0.5), 0.2)
        );
        let lit = Vec3::new(0.5, 0.25, 1.0);
        assert_eq!(
            s.after_lighting(texel, lit, 0.3),
            (Vec3::new(0.5, 0.0, 0.0), 0.3)
        );
        t.model = TextureModel::MultiplyDiffuse;
        let s = Sampler::new(&t, &img);
        assert_eq!(
            s.before_lighting(texel, Vec3::splat(0.5), 0.8),
            (Vec3::new(0.5, 0.0, 0.0), 0.2)
        );
        assert!(!s.acts_after_lighting());
        t.model = TextureModel::Replace;
        let (c, a) = Sampler::new(&t, &img).after_lighting(texel, lit, 1.0);
        assert_eq!((c, a), (Vec3::new(1.0, 0.0, 0.0), 0.25));
    }
}
