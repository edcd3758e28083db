//! Lane arithmetic for the lighting, over any lane count: [`Lanes`] is
//! what [`V8`] offers minus loads and stores, implemented for every `V8`
//! and for [`Pair`], sixteen lanes as two independent eight-lane values.
//!
//! Why pairs: the per-pixel lighting is a long chain of dependent steps
//! (square roots, divisions, the specular power's squarings), and one
//! eight-lane block at a time leaves the CPU waiting on latencies; two
//! independent blocks interleaved instruction by instruction keep it busy.
//! Each lane still does exactly the scalar arithmetic, so the picture is
//! the same bits for any lane count.

use super::simd::V8;
use std::ops::{Add, Div, Mul, Sub};

/// The lane arithmetic the lighting is written against: what [`V8`] offers
/// minus loads and stores, so that [`Pair`] (sixteen lanes as two
/// independent eight-lane values) can run it too.
pub trait Lanes:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    fn splat(v: f32) -> Self;
    fn sqrt(self) -> Self;
    fn gt(self, o: Self) -> Self;
    fn le(self, o: Self) -> Self;
    fn select(mask: Self, a: Self, b: Self) -> Self;
    fn and(self, o: Self) -> Self;
    /// One bit per lane (at most 32 lanes).
    fn bits(self) -> u32;
    fn max(self, o: Self) -> Self;
    fn min(self, o: Self) -> Self;
    fn keep(self, mask: Self) -> Self;
    /// `f(self, o)` lane by lane in scalar code (for the rare steps with no
    /// lane form, e.g. `powf`).
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self;
}

impl<T: V8> Lanes for T {
    #[inline(always)]
    fn splat(v: f32) -> Self {
        V8::splat(v)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        V8::sqrt(self)
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Self {
        V8::gt(self, o)
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        V8::le(self, o)
    }
    #[inline(always)]
    fn select(mask: Self, a: Self, b: Self) -> Self {
        V8::select(mask, a, b)
    }
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        V8::and(self, o)
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        V8::bits(self)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        V8::max(self, o)
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        V8::min(self, o)
    }
    #[inline(always)]
    fn keep(self, mask: Self) -> Self {
        V8::keep(self, mask)
    }
    #[inline(always)]
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        let (mut a, mut b) = ([0.0; 8], [0.0; 8]);
        self.store(&mut a);
        o.store(&mut b);
        V8::load(&std::array::from_fn(|k| f(a[k], b[k])))
    }
}

/// Sixteen lanes as two independent eight-lane values: every operation is
/// two instructions with no dependency between them, so a lighting chain
/// that is bound by latency (square roots, divisions, the specular power's
/// squarings) keeps the CPU twice as busy. Lane k of the pair is lane k of
/// `.0` for k < 8, lane k − 8 of `.1` otherwise.
#[derive(Clone, Copy, Debug)]
pub struct Pair<V>(pub V, pub V);

impl<V: V8> Add for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Pair(self.0 + o.0, self.1 + o.1)
    }
}
impl<V: V8> Sub for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Pair(self.0 - o.0, self.1 - o.1)
    }
}
impl<V: V8> Mul for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Pair(self.0 * o.0, self.1 * o.1)
    }
}
impl<V: V8> Div for Pair<V> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        Pair(self.0 / o.0, self.1 / o.1)
    }
}

impl<V: V8> Lanes for Pair<V> {
    #[inline(always)]
    fn splat(v: f32) -> Self {
        Pair(V8::splat(v), V8::splat(v))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Pair(V8::sqrt(self.0), V8::sqrt(self.1))
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Self {
        Pair(V8::gt(self.0, o.0), V8::gt(self.1, o.1))
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        Pair(V8::le(self.0, o.0), V8::le(self.1, o.1))
    }
    #[inline(always)]
    fn select(mask: Self, a: Self, b: Self) -> Self {
        Pair(V8::select(mask.0, a.0, b.0), V8::select(mask.1, a.1, b.1))
    }
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        Pair(V8::and(self.0, o.0), V8::and(self.1, o.1))
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        V8::bits(self.0) | V8::bits(self.1) << 8
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Pair(V8::max(self.0, o.0), V8::max(self.1, o.1))
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Pair(V8::min(self.0, o.0), V8::min(self.1, o.1))
    }
    #[inline(always)]
    fn keep(self, mask: Self) -> Self {
        Pair(V8::keep(self.0, mask.0), V8::keep(self.1, mask.1))
    }
    #[inline(always)]
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        Pair(self.0.map2(o.0, &f), self.1.map2(o.1, &f))
    }
}
