//! Four f32 lanes for the shader. On x86-64 these are SSE2 registers (part
//! of the baseline, so no run-time detection and the same instructions on
//! every x86-64 machine); elsewhere plain arrays. Only IEEE-exact operations
//! (+ − × ÷ √, compares, selects) are offered, so both versions give the
//! same bits as scalar code doing the same steps.

use std::ops::{Add, Mul, Sub};

#[cfg(target_arch = "x86_64")]
mod imp {
    use std::arch::x86_64::*;

    #[derive(Clone, Copy, Debug)]
    pub struct F4(pub __m128);
    #[derive(Clone, Copy, Debug)]
    pub struct M4(pub __m128);

    // SAFETY (for every `unsafe` block in this module): SSE2 is part of the
    // x86-64 baseline, so these intrinsics are always available.
    impl F4 {
        #[inline(always)]
        pub fn splat(v: f32) -> F4 {
            unsafe { F4(_mm_set1_ps(v)) }
        }
        #[inline(always)]
        pub fn load(a: &[f32]) -> F4 {
            assert!(a.len() >= 4);
            unsafe { F4(_mm_loadu_ps(a.as_ptr())) }
        }
        #[inline(always)]
        pub fn to_array(self) -> [f32; 4] {
            let mut out = [0.0; 4];
            unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
            out
        }
        #[inline(always)]
        pub fn add(self, o: F4) -> F4 {
            unsafe { F4(_mm_add_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn sub(self, o: F4) -> F4 {
            unsafe { F4(_mm_sub_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn mul(self, o: F4) -> F4 {
            unsafe { F4(_mm_mul_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn div(self, o: F4) -> F4 {
            unsafe { F4(_mm_div_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn sqrt(self) -> F4 {
            unsafe { F4(_mm_sqrt_ps(self.0)) }
        }
        #[inline(always)]
        pub fn gt(self, o: F4) -> M4 {
            unsafe { M4(_mm_cmpgt_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn le(self, o: F4) -> M4 {
            unsafe { M4(_mm_cmple_ps(self.0, o.0)) }
        }
    }

    impl M4 {
        /// Lane-wise `self ? a : b`.
        #[inline(always)]
        pub fn select(self, a: F4, b: F4) -> F4 {
            unsafe {
                F4(_mm_or_ps(
                    _mm_and_ps(self.0, a.0),
                    _mm_andnot_ps(self.0, b.0),
                ))
            }
        }
        #[inline(always)]
        pub fn and(self, o: M4) -> M4 {
            unsafe { M4(_mm_and_ps(self.0, o.0)) }
        }
        #[inline(always)]
        pub fn any(self) -> bool {
            unsafe { _mm_movemask_ps(self.0) != 0 }
        }
    }
}

#[cfg(not(target_arch = "x86_64"))]
mod imp {
    #[derive(Clone, Copy, Debug)]
    pub struct F4(pub [f32; 4]);
    #[derive(Clone, Copy, Debug)]
    pub struct M4(pub [bool; 4]);

    fn map(a: F4, b: F4, f: impl Fn(f32, f32) -> f32) -> F4 {
        F4([
            f(a.0[0], b.0[0]),
            f(a.0[1], b.0[1]),
            f(a.0[2], b.0[2]),
            f(a.0[3], b.0[3]),
        ])
    }

    impl F4 {
        pub fn splat(v: f32) -> F4 {
            F4([v; 4])
        }
        pub fn load(a: &[f32]) -> F4 {
            F4([a[0], a[1], a[2], a[3]])
        }
        pub fn to_array(self) -> [f32; 4] {
            self.0
        }
        pub fn add(self, o: F4) -> F4 {
            map(self, o, |a, b| a + b)
        }
        pub fn sub(self, o: F4) -> F4 {
            map(self, o, |a, b| a - b)
        }
        pub fn mul(self, o: F4) -> F4 {
            map(self, o, |a, b| a * b)
        }
        pub fn div(self, o: F4) -> F4 {
            map(self, o, |a, b| a / b)
        }
        pub fn sqrt(self) -> F4 {
            F4(self.0.map(f32::sqrt))
        }
        pub fn gt(self, o: F4) -> M4 {
            M4(std::array::from_fn(|k| self.0[k] > o.0[k]))
        }
        pub fn le(self, o: F4) -> M4 {
            M4(std::array::from_fn(|k| self.0[k] <= o.0[k]))
        }
    }

    impl M4 {
        pub fn select(self, a: F4, b: F4) -> F4 {
            F4(std::array::from_fn(
                |k| if self.0[k] { a.0[k] } else { b.0[k] },
            ))
        }
        pub fn and(self, o: M4) -> M4 {
            M4(std::array::from_fn(|k| self.0[k] && o.0[k]))
        }
        pub fn any(self) -> bool {
            self.0.iter().any(|&b| b)
        }
    }
}

pub use imp::F4;

impl F4 {
    /// Lane-wise `a > b ? a : b`.
    #[inline(always)]
    pub fn max(self, o: F4) -> F4 {
        self.gt(o).select(self, o)
    }
}

impl Add for F4 {
    type Output = F4;
    #[inline(always)]
    fn add(self, o: F4) -> F4 {
        F4::add(self, o)
    }
}
impl Sub for F4 {
    type Output = F4;
    #[inline(always)]
    fn sub(self, o: F4) -> F4 {
        F4::sub(self, o)
    }
}
impl Mul for F4 {
    type Output = F4;
    #[inline(always)]
    fn mul(self, o: F4) -> F4 {
        F4::mul(self, o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_match_scalar_arithmetic() {
        let a = [1.5f32, -2.25, 3.0e-3, 7.0];
        let b = [0.3f32, 4.0, -1.0e5, 7.0];
        let (va, vb) = (F4::load(&a), F4::load(&b));
        for k in 0..4 {
            assert_eq!((va + vb).to_array()[k], a[k] + b[k]);
            assert_eq!((va * vb).to_array()[k], a[k] * b[k]);
            assert_eq!(va.div(vb).to_array()[k], a[k] / b[k]);
            assert_eq!(
                va.max(vb).to_array()[k],
                if a[k] > b[k] { a[k] } else { b[k] }
            );
        }
        assert_eq!(
            F4::load(&[4.0, 9.0, 2.0, 0.0]).sqrt().to_array(),
            [2.0, 3.0, 2f32.sqrt(), 0.0]
        );
        assert!(va.gt(vb).any());
        assert!(!va.gt(F4::splat(100.0)).any());
    }
}
