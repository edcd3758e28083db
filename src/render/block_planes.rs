//! The attribute planes of an eight-pixel block whose lanes may show
//! different triangles, found in one pass over the lanes.
//!
//! Why a file of its own: a block of small triangles (a 100k-triangle mesh
//! at 1280×720 puts five or six in most blocks) is evaluated once per
//! triangle run on all eight lanes and merged by mask, and the shading
//! pass used to look for the block's triangles twice per triangle (once
//! for the lit attributes, once for the texture coordinates, eight lane
//! tests each time). Here one pass over the lanes splits them into runs of
//! one triangle and every plane reads them; each lane still computes
//! `base + b1·d1 + b2·d2` with its own triangle's numbers in the same
//! order, so no bit changes.

use super::clip::{A_COLOR, A_NORMAL, A_POS, A_UV};
use super::prepare::{Prepared, Tri, INV_W};
use super::simd::V8;
use super::texel_block::finite;
use super::texture_lanes::{Flat, UvIn};

/// The triangles a block's lanes show, with their screen-space weights.
pub struct BlockPlanes<'p, V> {
    /// The triangle of the first run of lanes (of all lanes, in the
    /// common block that shows one triangle), and its index.
    first: &'p Tri,
    tri: u32,
    /// The other runs, when there are any: kept apart so that a block of
    /// one triangle fills no per-run arrays.
    more: Option<Runs<'p, V>>,
    b1: V,
    b2: V,
}

/// The runs after the first: each a triangle and the mask of the lanes
/// that show it.
struct Runs<'p, V> {
    /// One triangle per run of neighbouring lanes showing it (a triangle
    /// showing in lanes apart gets one run per stretch: the same numbers).
    tris: [&'p Tri; 7],
    masks: [V; 7],
    n: usize,
}

/// Position, normal and colour planes, then 1/w: what every lit pixel
/// needs.
const USED: [usize; 10] = [
    A_POS,
    A_POS + 1,
    A_POS + 2,
    A_NORMAL,
    A_NORMAL + 1,
    A_NORMAL + 2,
    A_COLOR,
    A_COLOR + 1,
    A_COLOR + 2,
    INV_W,
];

impl<'p, V: V8> BlockPlanes<'p, V> {
    /// The triangles `win[k]` of the lanes of `group` (not empty) at
    /// weights (`b1`, `b2`). Lanes outside `group` get the planes of the
    /// first triangle: harmless values the caller does not keep.
    #[inline(always)]
    pub fn new(p: &'p Prepared, win: &[u32; 8], group: u32, b1: V, b2: V) -> Self {
        debug_assert!(group & 0xFF != 0);
        let group = group & 0xFF;
        let first = win[group.trailing_zeros() as usize];
        let more = if *win == [first; 8] {
            None
        } else {
            Some(Runs::new(p, win, group, first))
        };
        BlockPlanes {
            first: &p.opaque[first as usize],
            tri: first,
            more,
            b1,
            b2,
        }
    }

    /// `base + b1·d1 + b2·d2` of plane `j`, each lane with its triangle's
    /// coefficients.
    #[inline(always)]
    pub fn plane(&self, j: usize) -> V {
        let at = |t: &Tri| (t.base[j], t.d1[j], t.d2[j]);
        let (base, d1, d2) = at(self.first);
        let mut v = V::splat(base) + self.b1 * V::splat(d1) + self.b2 * V::splat(d2);
        if let Some(runs) = &self.more {
            for r in 0..runs.n {
                let (base, d1, d2) = at(runs.tris[r]);
                let x = V::splat(base) + self.b1 * V::splat(d1) + self.b2 * V::splat(d2);
                v = V::select(runs.masks[r], x, v);
            }
        }
        v
    }

    /// Lane by lane, `c` of the lane's triangle.
    #[inline(always)]
    fn pick(&self, c: impl Fn(&Tri) -> f32) -> V {
        let mut v = V::splat(c(self.first));
        if let Some(runs) = &self.more {
            for r in 0..runs.n {
                v = V::select(runs.masks[r], V::splat(c(runs.tris[r])), v);
            }
        }
        v
    }

    /// The lit attributes (value/w: position, normal, colour; then 1/w)
    /// and `s` = w (1 over the last): attribute j is `a[j] · s`,
    /// perspective-correct. Without `colour` (a texture replaces it) the
    /// colour planes are left zero.
    #[inline(always)]
    pub fn attributes(&self, colour: bool) -> ([V; 10], V) {
        let mut a = [V::splat(0.0); 10];
        for (v, &j) in a.iter_mut().zip(&USED) {
            if colour || !(A_COLOR..A_COLOR + 3).contains(&j) {
                *v = self.plane(j);
            }
        }
        let s = V::splat(1.0) / a[9];
        (a, s)
    }

    /// Perspective-correct texture coordinates and their screen-space
    /// derivatives (per pixel step in x and in y), from which the sampler
    /// picks the mip level (e.g. ρ = max(|∂uv/∂x|, |∂uv/∂y|) in texels,
    /// OpenGL 4.6 §8.14.1). `s` is 1/q, the reciprocal of the
    /// interpolated 1/w, per lane ([`BlockPlanes::attributes`]).
    ///
    /// With `q = 1/w` and `U = u/w` both affine in screen space,
    /// `u = U/q` and `∂u/∂x = (∂U/∂x − u·∂q/∂x)/q`; the gradients are
    /// constant per triangle (`Tri::grad`).
    ///
    /// A block of one triangle without perspective (its 1/w plane has
    /// deltas of exactly zero: every orthographic view) has q = `base` in
    /// every lane whose weights are finite, so `s` is 1/`base` there,
    /// ∂q/∂x and ∂q/∂y are ±0, and where u and v are finite the
    /// derivatives are `∂U/∂x · s` in every lane (the sign of a zero
    /// aside, which no reader sees: the sampler squares them). They are
    /// then also given once as [`UvIn::flat`], from which the sampler's
    /// level of detail comes once per triangle; other blocks, and lanes
    /// with non-finite coordinates, take the general formula.
    #[inline(always)]
    pub fn uv_in(&self, s: V) -> UvIn<V> {
        let (u, v) = (self.plane(A_UV) * s, self.plane(A_UV + 1) * s);
        let t = self.first;
        if self.more.is_none()
            && t.d1[INV_W] == 0.0
            && t.d2[INV_W] == 0.0
            && finite(u).and(finite(v)).bits() == 0xFF
        {
            let g = t.grad.uv;
            let g = [g[0][0], g[1][0], g[0][1], g[1][1]];
            return UvIn {
                u,
                v,
                du_dx: V::splat(g[0]) * s,
                dv_dx: V::splat(g[1]) * s,
                du_dy: V::splat(g[2]) * s,
                dv_dy: V::splat(g[3]) * s,
                flat: Some(Flat {
                    g,
                    q: t.base[INV_W],
                    tri: self.tri,
                }),
                tex_lod: None,
            };
        }
        self.uv_lanes(u, v, s)
    }

    /// [`BlockPlanes::uv_in`] by the general formula, lane by lane, for
    /// coordinates `u`, `v` (`flat` is `None`).
    #[inline(always)]
    fn uv_lanes(&self, u: V, v: V, s: V) -> UvIn<V> {
        let (gux, gvx, gqx) = (
            self.pick(|t| t.grad.uv[0][0]),
            self.pick(|t| t.grad.uv[1][0]),
            self.pick(|t| t.grad.q[0]),
        );
        let (guy, gvy, gqy) = (
            self.pick(|t| t.grad.uv[0][1]),
            self.pick(|t| t.grad.uv[1][1]),
            self.pick(|t| t.grad.q[1]),
        );
        UvIn {
            u,
            v,
            du_dx: (gux - u * gqx) * s,
            dv_dx: (gvx - v * gqx) * s,
            du_dy: (guy - u * gqy) * s,
            dv_dy: (gvy - v * gqy) * s,
            flat: None,
            tex_lod: None,
        }
    }
}

impl<'p, V: V8> Runs<'p, V> {
    /// The runs after the first of the lanes of `group`, whose first lane
    /// shows `first` (a block showing more than one triangle). Lanes
    /// outside `group` are in no run's mask.
    #[inline(always)]
    fn new(p: &'p Prepared, win: &[u32; 8], group: u32, first: u32) -> Self {
        let mut tris = [&p.opaque[first as usize]; 7];
        let mut bits = [0u32; 7];
        let mut n = 0;
        let mut last = first;
        for (k, &t) in win.iter().enumerate() {
            if group >> k & 1 == 0 {
                continue;
            }
            if t != last {
                tris[n] = &p.opaque[t as usize];
                last = t;
                n += 1;
            }
            if n > 0 {
                bits[n - 1] |= 1 << k;
            }
        }
        let mut masks = [V::splat(0.0); 7];
        for (m, &b) in masks.iter_mut().zip(&bits).take(n) {
            *m = V::from_bits(b);
        }
        Runs { tris, masks, n }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::clip::ATTRS;
    use crate::render::prepare::{planes, SUBPIXEL};
    use crate::render::simd::{Lanes, Sse8};
    use crate::render::tri_gradients::Gradients;

    /// Screen positions, 1/w and texture coordinates of three vertices.
    type Corners = ([(f32, f32); 3], [f32; 3], [[f32; 2]; 3]);

    /// A triangle with texture coordinates and very different depths at
    /// its corners, in a one-triangle `Prepared`.
    fn textured() -> (Prepared, Corners) {
        let xy = [(2.0, 3.0), (60.0, 10.0), (12.0, 50.0)];
        let inv_w = [1.0, 0.25, 0.5];
        let uv = [[0.0, 0.0], [4.0, 1.0], [1.0, 3.0]];
        (one_triangle(xy, inv_w, uv), (xy, inv_w, uv))
    }

    /// A one-triangle `Prepared`: screen corners `xy` (pixels), 1/w and
    /// texture coordinates per corner, its gradients set.
    pub(super) fn one_triangle(
        xy: [(f32, f32); 3],
        inv_w: [f32; 3],
        uv: [[f32; 2]; 3],
    ) -> Prepared {
        let mut attr = [[0.0; ATTRS]; 3];
        for k in 0..3 {
            attr[k][A_UV] = uv[k][0];
            attr[k][A_UV + 1] = uv[k][1];
        }
        let (base, d1, d2) = planes(&attr, &inv_w);
        let fx = |v: f32| (v * SUBPIXEL as f32) as i64;
        let mut tri = Tri {
            x: xy.map(|p| fx(p.0)),
            y: xy.map(|p| fx(p.1)),
            z: [0.5; 3],
            base,
            d1,
            d2,
            item: 0,
            bbox: [0, 0, 64, 64],
            grad: Gradients::default(),
        };
        tri.grad = Gradients::of(&tri.x, &tri.y, &tri.d1, &tri.d2);
        let mut p = Prepared::default();
        p.opaque.push(tri);
        p
    }

    /// Perspective-correct uv at a screen point, from the vertices.
    fn exact_uv(
        xy: &[(f32, f32); 3],
        inv_w: &[f32; 3],
        uv: &[[f32; 2]; 3],
        x: f64,
        y: f64,
    ) -> [f64; 2] {
        let p = xy.map(|(a, b)| (a as f64, b as f64));
        let area = (p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[1].1 - p[0].1) * (p[2].0 - p[0].0);
        let b1 = ((x - p[0].0) * (p[2].1 - p[0].1) - (y - p[0].1) * (p[2].0 - p[0].0)) / area;
        let b2 = ((p[1].0 - p[0].0) * (y - p[0].1) - (p[1].1 - p[0].1) * (x - p[0].0)) / area;
        let w = [1.0 - b1 - b2, b1, b2];
        let q: f64 = (0..3).map(|k| w[k] * inv_w[k] as f64).sum();
        let f = |c: usize| {
            (0..3)
                .map(|k| w[k] * inv_w[k] as f64 * uv[k][c] as f64)
                .sum::<f64>()
                / q
        };
        [f(0), f(1)]
    }

    #[test]
    fn texture_coordinates_and_derivatives_are_perspective_correct() {
        let (p, (xy, inv_w, uv)) = textured();
        let t = &p.opaque[0];
        let mut checked = 0;
        crate::render::raster::for_each_pixel(t, [0, 0, 64, 64], |x, y, b1, b2| {
            let q = t.base[INV_W] + b1 * t.d1[INV_W] + b2 * t.d2[INV_W];
            let planes = BlockPlanes::new(&p, &[0; 8], 0xFF, Sse8::splat(b1), Sse8::splat(b2));
            let lanes = planes.uv_in(Sse8::splat(1.0) / Sse8::splat(q));
            let get = |v: Sse8| {
                let mut a = [0.0; 8];
                v.store(&mut a);
                a[0] as f64
            };
            let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
            let want = exact_uv(&xy, &inv_w, &uv, cx, cy);
            assert!((get(lanes.u) - want[0]).abs() < 1e-4, "u at {x},{y}");
            assert!((get(lanes.v) - want[1]).abs() < 1e-4, "v at {x},{y}");
            // Central differences of the exact mapping.
            let h = 1e-3;
            let dx = exact_uv(&xy, &inv_w, &uv, cx + h, cy);
            let dx0 = exact_uv(&xy, &inv_w, &uv, cx - h, cy);
            let dy = exact_uv(&xy, &inv_w, &uv, cx, cy + h);
            let dy0 = exact_uv(&xy, &inv_w, &uv, cx, cy - h);
            let close = |a: f64, b: f64| (a - b).abs() < 1e-3 * (1.0 + b.abs());
            assert!(close(get(lanes.du_dx), (dx[0] - dx0[0]) / (2.0 * h)));
            assert!(close(get(lanes.dv_dx), (dx[1] - dx0[1]) / (2.0 * h)));
            assert!(close(get(lanes.du_dy), (dy[0] - dy0[0]) / (2.0 * h)));
            assert!(close(get(lanes.dv_dy), (dy[1] - dy0[1]) / (2.0 * h)));
            checked += 1;
        });
        assert!(checked > 500);
    }
}

#[cfg(test)]
mod flat_tests {
    use super::*;
    use crate::render::prepare::SUBPIXEL;
    use crate::render::simd::{Lanes, Sse8};
    use crate::render::texture::Sampler;
    use crate::render::texture_lanes::tests::image;
    use crate::render::texture_lanes::FlatLod;
    use crate::scene::{ImageId, Texture, Wrap};

    /// A one-triangle `Prepared` with 1/w `inv_w` at the corners and
    /// texture coordinates `scale`·(corner uv) + `shift`.
    fn tri(inv_w: [f32; 3], scale: f32, shift: [f32; 2]) -> Prepared {
        let xy = [(0.0, 0.0), (64.0, 4.0), (6.0, 32.0)];
        let uv = [[0.0, 0.0], [1.0, 0.15], [0.2, -0.9]];
        let uv = uv.map(|[u, v]| [u * scale + shift[0], v * scale + shift[1]]);
        super::tests::one_triangle(xy, inv_w, uv)
    }

    fn bits(t: [Sse8; 4]) -> [[u32; 8]; 4] {
        t.map(|c| {
            let mut a = [0.0; 8];
            c.store(&mut a);
            a.map(f32::to_bits)
        })
    }

    /// On a triangle without perspective every block of eight pixels gets
    /// flat derivatives, and sampling at their one level of detail gives
    /// the bits of the lane-by-lane derivatives, from magnified to far minified, repeated
    /// and clamped, in the 16-lane and the 8-lane paths alike.
    #[test]
    fn flat_blocks_sample_the_lane_by_lane_bits() {
        let mut flat = 0;
        for (w, h) in [(64, 32), (50, 30), (256, 256)] {
            let img = image(w, h, [53, 29, 11]);
            for wrap in [Wrap::Repeat, Wrap::Clamp] {
                let mut tex = Texture::new(ImageId(0));
                (tex.wrap_s, tex.wrap_t) = (wrap, wrap);
                let s = Sampler::new(&tex, &img);
                for (scale, shift) in [(0.3, [0.1, 0.9]), (2.5, [-0.4, 0.2]), (40.0, [3.0, 1.5])] {
                    let p = tri([0.5; 3], scale, shift);
                    let mut lods = FlatLod::default();
                    for y in 0..32 {
                        for x0 in (0..64).step_by(8) {
                            // Screen weights at the pixel centres.
                            let t = &p.opaque[0];
                            let area = t.area() as f32;
                            let at = |x: i32| {
                                let (px, py) = (
                                    (x as f32 + 0.5) * SUBPIXEL as f32,
                                    (y as f32 + 0.5) * SUBPIXEL as f32,
                                );
                                let (x, y) = (t.x.map(|v| v as f32), t.y.map(|v| v as f32));
                                let b1 = ((px - x[0]) * (y[2] - y[0])
                                    - (py - y[0]) * (x[2] - x[0]))
                                    / area;
                                let b2 = ((x[1] - x[0]) * (py - y[0])
                                    - (y[1] - y[0]) * (px - x[0]))
                                    / area;
                                (b1, b2)
                            };
                            let b: [(f32, f32); 8] = std::array::from_fn(|k| at(x0 + k as i32));
                            let planes = BlockPlanes::new(
                                &p,
                                &[0; 8],
                                0xFF,
                                Sse8::load(&b.map(|b| b.0)),
                                Sse8::load(&b.map(|b| b.1)),
                            );
                            let (_, sl) = planes.attributes(false);
                            let mut got = planes.uv_in(sl);
                            let f = got.flat.expect("an affine block is flat");
                            got.tex_lod = Some(lods.of(&f, &s));
                            let want = planes.uv_lanes(got.u, got.v, sl);
                            for wide in [false, crate::render::simd::avx512()] {
                                assert_eq!(
                                    bits(s.texel8_lod_in(&got, wide)),
                                    bits(s.texel8_in(&want, wide)),
                                    "{w}x{h} {wrap:?} scale {scale} at {x0},{y}"
                                );
                            }
                            flat += 1;
                        }
                    }
                }
            }
        }
        assert_eq!(flat, 3 * 2 * 3 * 32 * 8);
    }

    /// Perspective, and a lane with a non-finite coordinate, take the
    /// lane-by-lane derivatives.
    #[test]
    fn perspective_and_non_finite_lanes_are_not_flat() {
        let b = Sse8::splat(0.25);
        let p = tri([1.0, 0.5, 0.25], 1.0, [0.0, 0.0]);
        let planes = BlockPlanes::new(&p, &[0; 8], 0xFF, b, b);
        let (_, s) = planes.attributes(false);
        assert!(planes.uv_in(s).flat.is_none());
        let p = tri([0.5; 3], 1.0, [0.0, 0.0]);
        let mut b1 = [0.25f32; 8];
        b1[5] = f32::INFINITY;
        let planes = BlockPlanes::new(&p, &[0; 8], 0xFF, Sse8::load(&b1), b);
        let (_, s) = planes.attributes(false);
        assert!(planes.uv_in(s).flat.is_none());
        let planes = BlockPlanes::new(&p, &[0; 8], 0xFF, b, b);
        let (_, s) = planes.attributes(false);
        assert!(planes.uv_in(s).flat.is_some());
    }
}

#[cfg(test)]
mod mixed_tests {
    use super::*;
    use crate::render::prepare::PLANES;
    use crate::render::simd::{Lanes, Sse8};
    use crate::render::tri_gradients::Gradients;

    fn lanes(v: Sse8) -> [u32; 8] {
        let mut a = [0.0; 8];
        v.store(&mut a);
        a.map(f32::to_bits)
    }

    /// A block showing three triangles in scattered lanes gives every lane
    /// the bits of a block showing only that lane's triangle: the
    /// attributes, 1/w's reciprocal, the texture coordinates and their
    /// derivatives.
    #[test]
    fn mixed_blocks_match_one_triangle_blocks_bit_for_bit() {
        let mut seed = 99u32;
        let mut rnd = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32 - 0.5
        };
        let mut p = Prepared::default();
        for _ in 0..3 {
            let mut row = || -> [f32; PLANES] { std::array::from_fn(|_| rnd() * 8.0) };
            let (mut base, d1, d2) = (row(), row(), row());
            base[INV_W] = 1.0 + base[INV_W].abs();
            let g = [rnd(), rnd(), rnd(), rnd(), rnd(), rnd()];
            p.opaque.push(Tri {
                x: [0; 3],
                y: [0; 3],
                z: [0.5; 3],
                base,
                d1,
                d2,
                item: 0,
                bbox: [0, 0, 64, 64],
                grad: Gradients {
                    uv: [[g[0], g[1]], [g[2], g[3]]],
                    q: [g[4], g[5]],
                },
            });
        }
        for (win, group) in [
            ([0, 1, 1, 2, 0, 2, 2, 1], 0xFF),
            ([2, 2, 0, 0, 1, 1, 1, 1], 0xFF),
            ([1, 0, 2, 0, 1, 2, 0, 1], 0b1011_0110),
        ] {
            let b1: [f32; 8] = std::array::from_fn(|_| rnd() + 0.5);
            let b2: [f32; 8] = std::array::from_fn(|_| rnd() + 0.5);
            let mixed = BlockPlanes::new(&p, &win, group, Sse8::load(&b1), Sse8::load(&b2));
            assert!(mixed.more.as_ref().is_some_and(|r| r.n > 0));
            let (a, s) = mixed.attributes(true);
            let uv = mixed.uv_in(s);
            for k in (0..8).filter(|k| group >> k & 1 == 1) {
                let alone = BlockPlanes::new(
                    &p,
                    &[win[k]; 8],
                    0xFF,
                    Sse8::splat(b1[k]),
                    Sse8::splat(b2[k]),
                );
                assert!(alone.more.is_none());
                let (a1, s1) = alone.attributes(true);
                let uv1 = alone.uv_in(s1);
                for j in 0..10 {
                    assert_eq!(lanes(a[j])[k], lanes(a1[j])[0], "plane {j} lane {k}");
                }
                let pairs = [
                    (uv.u, uv1.u),
                    (uv.v, uv1.v),
                    (uv.du_dx, uv1.du_dx),
                    (uv.dv_dx, uv1.dv_dx),
                    (uv.du_dy, uv1.du_dy),
                    (uv.dv_dy, uv1.dv_dy),
                    (s, s1),
                ];
                for (i, (m, o)) in pairs.into_iter().enumerate() {
                    assert_eq!(lanes(m)[k], lanes(o)[0], "uv value {i} lane {k}");
                }
            }
        }
    }
}
