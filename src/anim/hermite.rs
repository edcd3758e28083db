//! Kochanek-Bartels cubic Hermite curves for scalars, vectors and colours,
//! and the KB tangent rule that the quaternion curve (`quat_curve.rs`) reuses
//! on quaternion logarithms.
//!
//! Tangents follow Kochanek & Bartels, "Interpolating Splines with Local
//! Tension, Continuity, and Bias Control", SIGGRAPH 1984, eqs. (9)/(10).
//! With the chords `A = P_i − P_{i−1}` and `B = P_{i+1} − P_i`:
//!
//! * incoming (source, used at the *end* of the segment that arrives at `P_i`)
//!   `DS_i = (1−t)(1+b)(1−c)/2 · A + (1−t)(1−b)(1+c)/2 · B`
//! * outgoing (destination, used at the *start* of the segment that leaves `P_i`)
//!   `DD_i = (1−t)(1+b)(1+c)/2 · A + (1−t)(1−b)(1−c)/2 · B`
//!
//! Tangents are in "per segment" units (each segment is parametrised by
//! `s ∈ [0, 1]`), so for uneven key spacing they are rescaled as in the same
//! paper: `DS_i × 2·Δt_prev/(Δt_prev+Δt_next)` and
//! `DD_i × 2·Δt_next/(Δt_prev+Δt_next)`. With c = 0 both sides then have the
//! same derivative per frame, so the curve is C¹ in time. With t = c = b = 0
//! and even spacing the tangent is `(P_{i+1} − P_{i−1})/2`: Catmull-Rom.
//!
//! **End keys of an open track** (no neighbour on one side) use the one-sided
//! difference scaled by tension: the tangent is `(1−t)·chord` of the one
//! segment they touch. Continuity and bias have no second side to act on
//! there. A two-key TCB segment with t = 0 is therefore a straight line at
//! constant speed. Looping tracks have neighbours on both sides (see
//! `repeat.rs`).

use std::ops::{Add, Mul, Sub};

/// What a KB curve needs of its values: a vector space over f32.
pub trait VectorLike:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f32, Output = Self>
{
}
impl<T> VectorLike for T where T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f32, Output = T> {}

/// Tension, continuity, bias of one key.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Tcb {
    pub tension: f32,
    pub continuity: f32,
    pub bias: f32,
}

/// The outgoing KB tangent `DD_i` of a key, in per-segment units of the
/// segment that leaves it.
///
/// `after` is the chord of that segment and its length in frames; `before`
/// the chord arriving at the key (`None` where an open track starts).
#[inline]
pub fn kb_out<V: VectorLike>(before: Option<(V, f32)>, after: (V, f32), tcb: Tcb) -> V {
    let one_t = 1.0 - tcb.tension;
    let (b, dn) = after;
    match before {
        Some((a, dp)) => {
            let (c, bias) = (tcb.continuity, tcb.bias);
            let wa = (1.0 + bias) * (1.0 + c);
            let wb = (1.0 - bias) * (1.0 - c);
            (a * wa + b * wb) * (0.5 * one_t * spacing(dn, dp + dn))
        }
        None => b * one_t,
    }
}

/// The incoming KB tangent `DS_i` of a key, in per-segment units of the
/// segment that arrives at it.
///
/// `before` is the chord of that segment and its length in frames; `after`
/// the chord leaving the key (`None` where an open track ends).
#[inline]
pub fn kb_in<V: VectorLike>(before: (V, f32), after: Option<(V, f32)>, tcb: Tcb) -> V {
    let one_t = 1.0 - tcb.tension;
    let (a, dp) = before;
    match after {
        Some((b, dn)) => {
            let (c, bias) = (tcb.continuity, tcb.bias);
            let wa = (1.0 + bias) * (1.0 - c);
            let wb = (1.0 - bias) * (1.0 + c);
            (a * wa + b * wb) * (0.5 * one_t * spacing(dp, dp + dn))
        }
        None => a * one_t,
    }
}

/// The uneven-spacing factor `2·Δ_own/(Δ_prev+Δ_next)`; degenerate spacing
/// (validated tracks never have it) falls back to 1.
#[inline]
fn spacing(own: f32, sum: f32) -> f32 {
    if sum > 0.0 && own.is_finite() && sum.is_finite() {
        2.0 * own / sum
    } else {
        1.0
    }
}

/// Cubic Hermite between `p0` (tangent `m0`) and `p1` (tangent `m1`) at
/// `s ∈ [0, 1]`, tangents in per-segment units.
#[inline]
pub fn hermite<V: VectorLike>(p0: V, m0: V, p1: V, m1: V, s: f32) -> V {
    let s2 = s * s;
    let s3 = s2 * s;
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    p0 * h00 + m0 * h10 + p1 * h01 + m1 * h11
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_ends_and_end_derivatives() {
        let (p0, m0, p1, m1) = (1.0f32, -2.0, 4.0, 3.0);
        assert_eq!(hermite(p0, m0, p1, m1, 0.0), p0);
        assert_eq!(hermite(p0, m0, p1, m1, 1.0), p1);
        let h = 1e-3;
        let d0 = (hermite(p0, m0, p1, m1, h) - p0) / h;
        let d1 = (p1 - hermite(p0, m0, p1, m1, 1.0 - h)) / h;
        // First-order differences: error ≈ h·|p″|/2 ≤ 0.01 here.
        assert!(
            (d0 - m0).abs() < 3e-2 && (d1 - m1).abs() < 3e-2,
            "{d0} {d1}"
        );
    }

    #[test]
    fn tangents_by_hand() {
        let tcb = Tcb::default();
        // Even spacing, TCB 0: Catmull-Rom, (A + B)/2 on both sides.
        assert_eq!(kb_out(Some((2.0f32, 5.0)), (4.0, 5.0), tcb), 3.0);
        assert_eq!(kb_in((2.0f32, 5.0), Some((4.0, 5.0)), tcb), 3.0);
        // Uneven (Δp = 1, Δn = 3): in × 2·1/4, out × 2·3/4.
        assert_eq!(kb_in((2.0f32, 1.0), Some((4.0, 3.0)), tcb), 1.5);
        assert_eq!(kb_out(Some((2.0f32, 1.0)), (4.0, 3.0), tcb), 4.5);
        // c = 1: in = B, out = A (even spacing); open ends: (1 − t)·chord.
        let c1 = Tcb {
            continuity: 1.0,
            ..tcb
        };
        assert_eq!(kb_in((2.0f32, 5.0), Some((4.0, 5.0)), c1), 4.0);
        assert_eq!(kb_out(Some((2.0f32, 5.0)), (4.0, 5.0), c1), 2.0);
        let t = Tcb {
            tension: 0.5,
            ..tcb
        };
        assert_eq!(kb_out(None, (4.0f32, 5.0), t), 2.0);
        assert_eq!(kb_in((2.0f32, 5.0), None, t), 1.0);
    }
}
