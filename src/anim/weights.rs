//! Morph-target weights as one animatable value: a vector of N numbers
//! (N = the mesh's target count) interpolated per component by the same
//! step / linear / Kochanek-Bartels maths as any vector (M3G
//! `MorphingMesh.setWeights`, glTF `weights` channels).
//!
//! The vector lives inline (fixed capacity [`MAX_MORPH_TARGETS`]) so that
//! [`Value`](super::Value) stays `Copy` and the curve code in `hermite.rs`
//! serves it unchanged. Components past `len` are always zero.

use std::ops::{Add, Mul, Sub};

/// Most morph targets a mesh may carry (readers keep the first ones and warn).
pub const MAX_MORPH_TARGETS: usize = 64;

/// N weights, one per morph target; weights may leave [0, 1] (extrapolation).
#[derive(Clone, Copy, PartialEq)]
pub struct Weights {
    len: u8,
    w: [f32; MAX_MORPH_TARGETS],
}

impl Weights {
    /// Zero weights for `n` targets (`n` clamped to [`MAX_MORPH_TARGETS`]).
    pub fn zeros(n: usize) -> Weights {
        Weights {
            len: n.min(MAX_MORPH_TARGETS) as u8,
            w: [0.0; MAX_MORPH_TARGETS],
        }
    }

    /// The weights in `s`; `None` when there are more than
    /// [`MAX_MORPH_TARGETS`].
    pub fn from_slice(s: &[f32]) -> Option<Weights> {
        if s.len() > MAX_MORPH_TARGETS {
            return None;
        }
        let mut out = Weights::zeros(s.len());
        out.w[..s.len()].copy_from_slice(s);
        Some(out)
    }

    /// The first `MAX_MORPH_TARGETS` weights of `s`.
    pub fn from_slice_truncated(s: &[f32]) -> Weights {
        Weights::from_slice(&s[..s.len().min(MAX_MORPH_TARGETS)]).unwrap_or(Weights::zeros(0))
    }

    pub fn len(&self) -> usize {
        self.len as usize
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    pub fn as_slice(&self) -> &[f32] {
        &self.w[..self.len()]
    }

    pub fn as_mut_slice(&mut self) -> &mut [f32] {
        let n = self.len();
        &mut self.w[..n]
    }

    pub fn is_finite(&self) -> bool {
        self.as_slice().iter().all(|x| x.is_finite())
    }
}

impl Default for Weights {
    fn default() -> Self {
        Weights::zeros(0)
    }
}

impl std::fmt::Debug for Weights {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.as_slice()).finish()
    }
}

// Arithmetic runs over the whole fixed array (unused lanes stay zero), which
// keeps it branch-free; the result takes the longer length so a key with
// fewer weights reads as zeros for the missing targets.
impl Add for Weights {
    type Output = Weights;
    #[inline]
    fn add(mut self, o: Weights) -> Weights {
        for (a, b) in self.w.iter_mut().zip(o.w.iter()) {
            *a += *b;
        }
        self.len = self.len.max(o.len);
        self
    }
}

impl Sub for Weights {
    type Output = Weights;
    #[inline]
    fn sub(mut self, o: Weights) -> Weights {
        for (a, b) in self.w.iter_mut().zip(o.w.iter()) {
            *a -= *b;
        }
        self.len = self.len.max(o.len);
        self
    }
}

impl Mul<f32> for Weights {
    type Output = Weights;
    #[inline]
    fn mul(mut self, k: f32) -> Weights {
        for a in self.w.iter_mut() {
            *a *= k;
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_per_component_and_keeps_the_longer_length() {
        let a = Weights::from_slice(&[1.0, 2.0]).unwrap();
        let b = Weights::from_slice(&[0.5, 0.5, 3.0]).unwrap();
        assert_eq!((a + b).as_slice(), &[1.5, 2.5, 3.0]);
        assert_eq!((b - a).as_slice(), &[-0.5, -1.5, 3.0]);
        assert_eq!((a * 2.0).as_slice(), &[2.0, 4.0]);
        assert!(Weights::from_slice(&[0.0; MAX_MORPH_TARGETS + 1]).is_none());
        assert_eq!(
            Weights::from_slice_truncated(&[1.0; MAX_MORPH_TARGETS + 5]).len(),
            MAX_MORPH_TARGETS
        );
    }
}
