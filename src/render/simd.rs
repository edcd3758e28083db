//! Lanes of f32 for the shader. Only IEEE-exact operations (+ − × ÷ √,
//! compares, selects) are offered and never a fused multiply-add, so every
//! implementation gives the same bits as scalar code doing the same steps.
//!
//! * [`F4`]: four lanes in an SSE2 register (part of the x86-64 baseline, so
//!   no run-time detection); plain arrays elsewhere.
//! * [`V8`]: the eight-lane interface the shading pass is written against,
//!   with [`Sse8`] (two `F4`s, always available) and, on x86-64, [`Avx8`]
//!   (one 256-bit AVX register, used only after run-time detection; see
//!   [`avx`]). AVX without FMA does lane for lane exactly what SSE2 does, so
//!   the picture does not depend on which one runs.

use std::ops::{Add, Div, Mul, Sub};

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
        /// `self > o ? self : o` (what MAXPS computes, NaN → `o`).
        #[inline(always)]
        pub fn max(self, o: F4) -> F4 {
            unsafe { F4(_mm_max_ps(self.0, o.0)) }
        }
        /// `self < o ? self : o` (what MINPS computes, NaN → `o`).
        #[inline(always)]
        pub fn min(self, o: F4) -> F4 {
            unsafe { F4(_mm_min_ps(self.0, o.0)) }
        }
        /// Truncated towards zero to i32, as `as i32` for values in range.
        #[inline(always)]
        pub fn trunc_i32(self) -> [i32; 4] {
            let mut out = [0i32; 4];
            unsafe { _mm_storeu_si128(out.as_mut_ptr().cast(), _mm_cvttps_epi32(self.0)) };
            out
        }
        /// Bitwise OR (of masks).
        #[inline(always)]
        pub fn or(self, o: F4) -> F4 {
            unsafe { F4(_mm_or_ps(self.0, o.0)) }
        }
        /// `(e + (first + k)·step) as f32` for k = 0..4 through exact f64
        /// (see `V8::from_edge`).
        #[inline(always)]
        pub fn from_edge(e: i64, step: i64, first: i64) -> F4 {
            unsafe {
                let base = _mm_set1_pd(e as f64);
                let st = _mm_set1_pd(step as f64);
                let k = first as f64;
                let lo = _mm_add_pd(base, _mm_mul_pd(_mm_set_pd(k + 1.0, k), st));
                let hi = _mm_add_pd(base, _mm_mul_pd(_mm_set_pd(k + 3.0, k + 2.0), st));
                F4(_mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi)))
            }
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
        /// One bit per lane (the lane's sign bit).
        #[inline(always)]
        pub fn bits(self) -> u32 {
            unsafe { _mm_movemask_ps(self.0) as u32 }
        }
        /// The mask as lanes of all-ones / all-zero bits.
        #[inline(always)]
        pub fn as_f4(self) -> F4 {
            F4(self.0)
        }
    }

    impl F4 {
        /// Reads lanes of all-ones / all-zero bits as a mask.
        #[inline(always)]
        pub fn as_mask(self) -> M4 {
            M4(self.0)
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
        pub fn max(self, o: F4) -> F4 {
            map(self, o, |a, b| if a > b { a } else { b })
        }
        pub fn min(self, o: F4) -> F4 {
            map(self, o, |a, b| if a < b { a } else { b })
        }
        pub fn trunc_i32(self) -> [i32; 4] {
            self.0.map(|v| v as i32)
        }
        pub fn or(self, o: F4) -> F4 {
            map(self, o, |a, b| f32::from_bits(a.to_bits() | b.to_bits()))
        }
        pub fn from_edge(e: i64, step: i64, first: i64) -> F4 {
            F4(std::array::from_fn(|k| {
                (e + (first + k as i64) * step) as f32
            }))
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
        pub fn bits(self) -> u32 {
            (0..4).map(|k| (self.0[k] as u32) << k).sum()
        }
        pub fn as_f4(self) -> F4 {
            F4(self.0.map(|b| f32::from_bits(if b { !0 } else { 0 })))
        }
    }

    impl F4 {
        pub fn as_mask(self) -> M4 {
            M4(self.0.map(|f| f.to_bits() >> 31 == 1))
        }
    }
}

pub use imp::F4;

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

/// The lane arithmetic the lighting is written against, over any lane
/// count: what [`V8`] offers minus loads and stores, so that
/// `lanes::Pair` (sixteen lanes as two independent eight-lane values) can
/// run it too. A mask is a value whose lanes are all-ones or all-zero bits
/// (what the comparisons return), as in SSE/AVX.
pub trait Lanes:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    fn splat(v: f32) -> Self;
    fn sqrt(self) -> Self;
    fn gt(self, o: Self) -> Self;
    fn le(self, o: Self) -> Self;
    /// Lane-wise `mask ? a : b`.
    fn select(mask: Self, a: Self, b: Self) -> Self;
    fn and(self, o: Self) -> Self;
    /// One bit per lane: the lane's sign bit (set for true mask lanes; at
    /// most 32 lanes).
    fn bits(self) -> u32;
    /// Lane-wise `self > o ? self : o` (so a NaN in either gives `o`):
    /// exactly MAXPS.
    fn max(self, o: Self) -> Self;
    /// Lane-wise `self < o ? self : o`: exactly MINPS.
    fn min(self, o: Self) -> Self;
    /// Lane-wise `mask ? self : 0` — one AND, cheaper than a select.
    fn keep(self, mask: Self) -> Self;
    /// `f(self, o)` lane by lane in scalar code (for the rare steps with no
    /// lane form, e.g. `powf`).
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self;
}

/// Eight f32 lanes: [`Lanes`] plus loads, stores and conversions.
pub trait V8: Lanes {
    fn load(a: &[f32; 8]) -> Self;
    fn store(self, a: &mut [f32; 8]);

    /// A mask with lane k true where bit k of `bits` is set.
    #[inline(always)]
    fn from_bits(bits: u32) -> Self {
        let a = std::array::from_fn(|k| f32::from_bits(if bits >> k & 1 == 1 { !0 } else { 0 }));
        Self::load(&a)
    }
    /// Each lane truncated towards zero to an i32 (lanes must lie within
    /// i32; exactly what `as i32` gives there).
    fn trunc_i32(self) -> [i32; 8];

    /// Lane-wise `f32::floor` for finite lanes, bit for bit (−0 stays −0;
    /// |x| ≥ 2²³ is already whole). Built from truncation, so it needs no
    /// SSE4.1 `ROUNDPS` and no `floorf` call.
    #[inline(always)]
    fn floor(self) -> Self {
        let whole = Lanes::le(Self::splat(8_388_608.0), self)
            .or(self.le(Self::splat(-8_388_608.0)))
            .or(self.eq(Self::splat(0.0)));
        let t = Self::from_i32(self.trunc_i32().map(|i| i as f32));
        let t = Self::select(t.gt(self), t - Self::splat(1.0), t);
        Self::select(whole, self, t)
    }
    /// Lane-wise `a == b` as a mask.
    #[inline(always)]
    fn eq(self, o: Self) -> Self {
        self.le(o).and(o.le(self))
    }
    /// Lane-wise mask OR.
    fn or(self, o: Self) -> Self;
    /// Lanes `(e + k·step) as f32` for k = 0..8, for integer edge values
    /// whose magnitudes stay below 2⁵³: computed exactly in f64 and rounded
    /// once to f32, which is what `i64 as f32` gives, without eight scalar
    /// conversions.
    fn from_edge(e: i64, step: i64) -> Self;
    /// Lanes from an array (an alias of `load` taking it by value).
    #[inline(always)]
    fn from_i32(a: [f32; 8]) -> Self {
        Self::load(&a)
    }
    /// The lanes as one AVX register, for code that checked the CPU
    /// (the texture sampler's AVX-512 pass): a register move for
    /// [`Avx8`], a trip through memory for other lanes.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn to_m256(self) -> std::arch::x86_64::__m256 {
        let mut a = [0.0f32; 8];
        self.store(&mut a);
        // SAFETY: 32 bytes either way, and every bit pattern is valid.
        unsafe { std::mem::transmute::<[f32; 8], std::arch::x86_64::__m256>(a) }
    }
    /// Lanes from one AVX register (the inverse of [`V8::to_m256`]).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn from_m256(v: std::arch::x86_64::__m256) -> Self {
        // SAFETY: 32 bytes either way, and every bit pattern is valid.
        Self::load(&unsafe { std::mem::transmute::<std::arch::x86_64::__m256, [f32; 8]>(v) })
    }
}

/// [`Lanes::map2`] for eight lanes: through arrays, lane by lane.
#[inline(always)]
fn map2_8<V: V8>(a: V, b: V, f: impl Fn(f32, f32) -> f32) -> V {
    let (mut x, mut y) = ([0.0; 8], [0.0; 8]);
    a.store(&mut x);
    b.store(&mut y);
    V::load(&std::array::from_fn(|k| f(x[k], y[k])))
}

/// Eight lanes as two SSE2 registers (or arrays off x86-64): the baseline.
#[derive(Clone, Copy, Debug)]
pub struct Sse8(F4, F4);

impl Lanes for Sse8 {
    #[inline(always)]
    fn splat(v: f32) -> Self {
        Sse8(F4::splat(v), F4::splat(v))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Sse8(self.0.sqrt(), self.1.sqrt())
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Self {
        Sse8(self.0.gt(o.0).as_f4(), self.1.gt(o.1).as_f4())
    }
    #[inline(always)]
    fn le(self, o: Self) -> Self {
        Sse8(self.0.le(o.0).as_f4(), self.1.le(o.1).as_f4())
    }
    #[inline(always)]
    fn select(mask: Self, a: Self, b: Self) -> Self {
        Sse8(
            mask.0.as_mask().select(a.0, b.0),
            mask.1.as_mask().select(a.1, b.1),
        )
    }
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        Sse8(
            self.0.as_mask().and(o.0.as_mask()).as_f4(),
            self.1.as_mask().and(o.1.as_mask()).as_f4(),
        )
    }
    #[inline(always)]
    fn bits(self) -> u32 {
        self.0.as_mask().bits() | self.1.as_mask().bits() << 4
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Sse8(self.0.max(o.0), self.1.max(o.1))
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Sse8(self.0.min(o.0), self.1.min(o.1))
    }
    #[inline(always)]
    fn keep(self, mask: Self) -> Self {
        Sse8::and(mask, self)
    }
    #[inline(always)]
    fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
        map2_8(self, o, f)
    }
}

impl V8 for Sse8 {
    #[inline(always)]
    fn load(a: &[f32; 8]) -> Self {
        Sse8(F4::load(&a[..4]), F4::load(&a[4..]))
    }
    #[inline(always)]
    fn store(self, a: &mut [f32; 8]) {
        a[..4].copy_from_slice(&self.0.to_array());
        a[4..].copy_from_slice(&self.1.to_array());
    }
    #[inline(always)]
    fn trunc_i32(self) -> [i32; 8] {
        let (a, b) = (self.0.trunc_i32(), self.1.trunc_i32());
        [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]
    }
    #[inline(always)]
    fn or(self, o: Self) -> Self {
        Sse8(F4::or(self.0, o.0), F4::or(self.1, o.1))
    }
    #[inline(always)]
    fn from_edge(e: i64, step: i64) -> Self {
        Sse8(F4::from_edge(e, step, 0), F4::from_edge(e, step, 4))
    }
}

macro_rules! ops8 {
    ($t:ty, $add:expr, $sub:expr, $mul:expr, $div:expr) => {
        impl Add for $t {
            type Output = $t;
            #[inline(always)]
            fn add(self, o: $t) -> $t {
                $add(self, o)
            }
        }
        impl Sub for $t {
            type Output = $t;
            #[inline(always)]
            fn sub(self, o: $t) -> $t {
                $sub(self, o)
            }
        }
        impl Mul for $t {
            type Output = $t;
            #[inline(always)]
            fn mul(self, o: $t) -> $t {
                $mul(self, o)
            }
        }
        impl Div for $t {
            type Output = $t;
            #[inline(always)]
            fn div(self, o: $t) -> $t {
                $div(self, o)
            }
        }
    };
}

ops8!(
    Sse8,
    |a: Sse8, b: Sse8| Sse8(a.0 + b.0, a.1 + b.1),
    |a: Sse8, b: Sse8| Sse8(a.0 - b.0, a.1 - b.1),
    |a: Sse8, b: Sse8| Sse8(a.0 * b.0, a.1 * b.1),
    |a: Sse8, b: Sse8| Sse8(a.0.div(b.0), a.1.div(b.1))
);

#[cfg(target_arch = "x86_64")]
pub use avx_lanes::Avx8;

#[cfg(target_arch = "x86_64")]
mod avx_lanes {
    use super::*;
    use std::arch::x86_64::*;

    /// Eight lanes in one AVX register. Only use inside a function compiled
    /// with `#[target_feature(enable = "avx")]` after [`super::avx`] said yes.
    #[derive(Clone, Copy, Debug)]
    pub struct Avx8(__m256);

    // SAFETY (every `unsafe` block below): these run only inside functions
    // compiled for AVX and called after run-time detection (see `avx`).
    impl Lanes for Avx8 {
        #[inline(always)]
        fn splat(v: f32) -> Self {
            unsafe { Avx8(_mm256_set1_ps(v)) }
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            unsafe { Avx8(_mm256_sqrt_ps(self.0)) }
        }
        #[inline(always)]
        fn gt(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_cmp_ps::<_CMP_GT_OQ>(self.0, o.0)) }
        }
        #[inline(always)]
        fn le(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_cmp_ps::<_CMP_LE_OQ>(self.0, o.0)) }
        }
        #[inline(always)]
        fn select(mask: Self, a: Self, b: Self) -> Self {
            // AND/ANDNOT/OR rather than BLENDVPS: LLVM rewrites BLENDVPS
            // into a sign test, which AVX without AVX2 does by converting
            // the mask to floats and comparing (three extra instructions).
            unsafe {
                Avx8(_mm256_or_ps(
                    _mm256_and_ps(mask.0, a.0),
                    _mm256_andnot_ps(mask.0, b.0),
                ))
            }
        }
        #[inline(always)]
        fn max(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_max_ps(self.0, o.0)) }
        }
        #[inline(always)]
        fn min(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_min_ps(self.0, o.0)) }
        }
        #[inline(always)]
        fn keep(self, mask: Self) -> Self {
            unsafe { Avx8(_mm256_and_ps(mask.0, self.0)) }
        }
        #[inline(always)]
        fn and(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_and_ps(self.0, o.0)) }
        }
        #[inline(always)]
        fn bits(self) -> u32 {
            unsafe { _mm256_movemask_ps(self.0) as u32 }
        }
        #[inline(always)]
        fn map2(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
            map2_8(self, o, f)
        }
    }

    impl V8 for Avx8 {
        #[inline(always)]
        fn load(a: &[f32; 8]) -> Self {
            unsafe { Avx8(_mm256_loadu_ps(a.as_ptr())) }
        }
        #[inline(always)]
        fn store(self, a: &mut [f32; 8]) {
            unsafe { _mm256_storeu_ps(a.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn trunc_i32(self) -> [i32; 8] {
            let mut out = [0i32; 8];
            unsafe { _mm256_storeu_si256(out.as_mut_ptr().cast(), _mm256_cvttps_epi32(self.0)) };
            out
        }
        #[inline(always)]
        fn or(self, o: Self) -> Self {
            unsafe { Avx8(_mm256_or_ps(self.0, o.0)) }
        }
        #[inline(always)]
        fn from_edge(e: i64, step: i64) -> Self {
            unsafe {
                let base = _mm256_set1_pd(e as f64);
                let st = _mm256_set1_pd(step as f64);
                let lo = _mm256_add_pd(base, _mm256_mul_pd(_mm256_set_pd(3.0, 2.0, 1.0, 0.0), st));
                let hi = _mm256_add_pd(base, _mm256_mul_pd(_mm256_set_pd(7.0, 6.0, 5.0, 4.0), st));
                Avx8(_mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo)))
            }
        }
        #[inline(always)]
        fn to_m256(self) -> __m256 {
            self.0
        }
        #[inline(always)]
        fn from_m256(v: __m256) -> Self {
            Avx8(v)
        }
        /// `f32::floor` by ROUNDPS (AVX has it; SSE2 does not): the same
        /// bits as the default's truncation steps, in one instruction (the
        /// texture sampler floors six lanes' worth per block).
        #[inline(always)]
        fn floor(self) -> Self {
            const DOWN: i32 = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
            unsafe { Avx8(_mm256_round_ps::<DOWN>(self.0)) }
        }
    }

    ops8!(
        Avx8,
        |a: Avx8, b: Avx8| unsafe { Avx8(_mm256_add_ps(a.0, b.0)) },
        |a: Avx8, b: Avx8| unsafe { Avx8(_mm256_sub_ps(a.0, b.0)) },
        |a: Avx8, b: Avx8| unsafe { Avx8(_mm256_mul_ps(a.0, b.0)) },
        |a: Avx8, b: Avx8| unsafe { Avx8(_mm256_div_ps(a.0, b.0)) }
    );
}

/// Whether the AVX-512 register file may serve the AVX path: the CPU has
/// AVX-512F, VL, BW and DQ (every CPU with VL has all four; the texture
/// sampler's 16-lane pass, `trilinear16`, uses BW's 16-bit lanes), and `ANIMED_SIMD` is neither `sse2` nor `avx`. The
/// same eight-lane AVX instructions then get 32 registers instead of 16
/// (the lighting of a [`crate::render::lanes::Pair`] no longer spills);
/// nothing fused is ever emitted (Rust never contracts a multiply and an
/// add on its own), so the bytes stay the same.
pub fn avx512() -> bool {
    use std::sync::OnceLock;
    static AVX512: OnceLock<bool> = OnceLock::new();
    *AVX512.get_or_init(|| {
        let forced_off = std::env::var("ANIMED_SIMD").is_ok_and(|v| v == "sse2" || v == "avx");
        #[cfg(target_arch = "x86_64")]
        {
            !forced_off
                && std::arch::is_x86_feature_detected!("avx512f")
                && std::arch::is_x86_feature_detected!("avx512vl")
                && std::arch::is_x86_feature_detected!("avx512bw")
                && std::arch::is_x86_feature_detected!("avx512dq")
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = forced_off;
            false
        }
    })
}

/// Whether the AVX path may run: the CPU has AVX and `ANIMED_SIMD` is not
/// `sse2` (set it to compare the two paths; they give the same bytes).
pub fn avx() -> bool {
    use std::sync::OnceLock;
    static AVX: OnceLock<bool> = OnceLock::new();
    *AVX.get_or_init(|| {
        let forced_off = std::env::var("ANIMED_SIMD").is_ok_and(|v| v == "sse2");
        #[cfg(target_arch = "x86_64")]
        {
            !forced_off && std::arch::is_x86_feature_detected!("avx")
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = forced_off;
            false
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lanes around the ends of the range where floor needs no work.
    const BIG: [f32; 8] = [
        -1e9, 1e9, -8388607.5, 8388607.5, -0.5, 0.5, -1.0, 16777215.0,
    ];

    fn eight_lane_ops<V: V8>() -> Vec<[f32; 8]> {
        let a = V::load(&[1.5, -2.25, 3.0e-3, 7.0, 0.1, 1e-30, -0.0, 3.0]);
        let b = V::load(&[0.3, 4.0, -1.0e5, 7.0, 0.7, 3.0, 2.0, 9.0]);
        let mut out = Vec::new();
        for v in [
            a + b,
            a - b,
            a * b,
            a / b,
            b.sqrt(),
            a.max(b),
            a.min(b),
            V::select(a.gt(b), a, b * b),
            V::select(a.le(b).and(V::from_bits(0b1010_1010)), a, b),
            a.keep(a.gt(b)),
            V::load(&a.trunc_i32().map(|i| i as f32)),
            a.floor(),
            (b * V::splat(1e-3)).floor(),
            V::load(&BIG).floor(),
        ] {
            let mut o = [0.0; 8];
            v.store(&mut o);
            out.push(o);
        }
        assert_eq!(a.gt(b).bits(), 0b0000_0101);
        out
    }

    #[test]
    fn eight_lanes_match_scalar_and_each_other() {
        let sse = eight_lane_ops::<Sse8>();
        assert_eq!(sse[0][0], 1.5f32 + 0.3);
        assert_eq!(sse[3][1], -2.25f32 / 4.0);
        assert_eq!(sse[4][1], 2.0);
        assert_eq!(sse[9], [1.5, 0.0, 3.0e-3, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert_eq!(sse[10], [1.0, -2.0, 0.0, 7.0, 0.0, 0.0, 0.0, 3.0]);
        let floors = |v: [f32; 8]| v.map(|x: f32| x.floor().to_bits());
        let a = [1.5f32, -2.25, 3.0e-3, 7.0, 0.1, 1e-30, -0.0, 3.0];
        assert_eq!(sse[11].map(f32::to_bits), floors(a));
        let b = [0.3f32, 4.0, -1.0e5, 7.0, 0.7, 3.0, 2.0, 9.0].map(|x| x * 1e-3);
        assert_eq!(sse[12].map(f32::to_bits), floors(b));
        assert_eq!(sse[13].map(f32::to_bits), floors(BIG));
        let mut o = [0.0; 8];
        for (e, st) in [
            (0i64, 1i64),
            (-5, 3),
            (1 << 40, -(1 << 30) - 7),
            ((1 << 52) - 9, 1),
            (123_456_789_012, -987_654_321),
        ] {
            Sse8::from_edge(e, st).store(&mut o);
            assert_eq!(o, std::array::from_fn(|k| (e + k as i64 * st) as f32));
        }
        // MAXPS/MINPS semantics: the second operand on NaN.
        let nan = Lanes::max(Sse8::splat(f32::NAN), Sse8::splat(2.0));
        let mut o = [0.0; 8];
        nan.store(&mut o);
        assert_eq!(o, [2.0; 8]);
        Lanes::min(Sse8::splat(f32::NAN), Sse8::splat(-1.0)).store(&mut o);
        assert_eq!(o, [-1.0; 8]);
        assert_eq!(
            sse[7],
            [1.5, 16.0, 3.0e-3, 49.0, 0.7f32 * 0.7, 9.0, 4.0, 81.0]
        );
        #[cfg(target_arch = "x86_64")]
        if avx() {
            // SAFETY: avx() checked the CPU.
            let avx = unsafe { avx_ops() };
            for (s, a) in sse.iter().zip(&avx) {
                assert_eq!(s.map(f32::to_bits), a.map(f32::to_bits));
            }
        }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn avx_ops() -> Vec<[f32; 8]> {
        eight_lane_ops::<Avx8>()
    }

    #[test]
    fn lanes_match_scalar_arithmetic() {
        let a = [1.5f32, -2.25, 3.0e-3, 7.0];
        let b = [0.3f32, 4.0, -1.0e5, 7.0];
        let (va, vb) = (F4::load(&a), F4::load(&b));
        for k in 0..4 {
            assert_eq!((va + vb).to_array()[k], a[k] + b[k]);
            assert_eq!((va * vb).to_array()[k], a[k] * b[k]);
            assert_eq!(va.div(vb).to_array()[k], a[k] / b[k]);
        }
        assert_eq!(
            F4::load(&[4.0, 9.0, 2.0, 0.0]).sqrt().to_array(),
            [2.0, 3.0, 2f32.sqrt(), 0.0]
        );
        assert_eq!(va.gt(vb).bits(), 0b0101);
        assert_eq!(va.gt(F4::splat(100.0)).bits(), 0);
    }
}
