//! Sixteen lanes for the lighting: [`Pair`], two independent eight-lane
//! values, implementing the lane arithmetic [`Lanes`] (defined beside
//! [`V8`] in `simd`, which every `V8` implements too).
//!
//! Why pairs: the per-pixel lighting is a long chain of dependent steps
//! (square roots, divisions, the specular power's squarings), and one
//! eight-lane block at a time leaves the CPU waiting on latencies; two
//! independent blocks interleaved instruction by instruction keep it busy.
//! Each lane still does exactly the scalar arithmetic, so the picture is
//! the same bits for any lane count.

use super::simd::{Lanes, V8};
use std::ops::{Add, Div, Mul, Sub};

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
        Pair(V::splat(v), V::splat(v))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Pair(Lanes::sqrt(self.0), Lanes::sqrt(self.1))
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Self {
        Pair(Lanes::gt(self.0, o.0), Lanes::gt(self.1, o.1))
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        Pair(Lanes::le(self.0, o.0), Lanes::le(self.1, o.1))
    }
    #[inline(always)]
    fn select(mask: Self, a: Self, b: Self) -> Self {
        Pair(
            Lanes::select(mask.0, a.0, b.0),
            Lanes::select(mask.1, a.1, b.1),
        )
    }
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        Pair(Lanes::and(self.0, o.0), Lanes::and(self.1, o.1))
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        Lanes::bits(self.0) | Lanes::bits(self.1) << 8
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Pair(Lanes::max(self.0, o.0), Lanes::max(self.1, o.1))
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Pair(Lanes::min(self.0, o.0), Lanes::min(self.1, o.1))
    }
    #[inline(always)]
    fn keep(self, mask: Self) -> Self {
        Pair(Lanes::keep(self.0, mask.0), Lanes::keep(self.1, mask.1))
    }
    #[inline(always)]
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        Pair(self.0.map2(o.0, &f), self.1.map2(o.1, &f))
    }
}

/// Lanes made of `N` eight-lane blocks (one block, or a [`Pair`]): what the
/// per-block steps of shading (texture sampling, which works on eight
/// lanes) need to take a value apart and put it back, so one shading
/// sequence serves a block and a pair alike.
pub trait Blocks<V: V8>: Lanes {
    /// Blocks per value (1 or 2).
    const N: usize;
    /// Block `k` (< `N`).
    fn block(self, k: usize) -> V;
    /// Replaces block `k` (< `N`).
    fn set_block(&mut self, k: usize, v: V);
}

impl<V: V8> Blocks<V> for V {
    const N: usize = 1;
    #[inline(always)]
    fn block(self, _: usize) -> V {
        self
    }
    #[inline(always)]
    fn set_block(&mut self, _: usize, v: V) {
        *self = v;
    }
}

impl<V: V8> Blocks<V> for Pair<V> {
    const N: usize = 2;
    #[inline(always)]
    fn block(self, k: usize) -> V {
        if k == 0 {
            self.0
        } else {
            self.1
        }
    }
    #[inline(always)]
    fn set_block(&mut self, k: usize, v: V) {
        if k == 0 {
            self.0 = v;
        } else {
            self.1 = v;
        }
    }
}
