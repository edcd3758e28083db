//! Rotation curves on unit quaternions: step, slerp, and squad with
//! Kochanek-Bartels intermediate quaternions.
//!
//! Logarithms here are "half-angle" vectors: `log(q) = axis·θ/2` for a
//! rotation by θ, and `exp` is its inverse, so a rotation at constant angular
//! velocity ω (per segment) is `q0·exp(s·ω/2)`.
//!
//! **Squad-TCB.** For the segment `q0 → q1` the KB tangents `T0` (outgoing at
//! q0) and `T1` (incoming at q1) are built with the same rule as vector
//! tangents (`hermite.rs`, K&B 1984 eqs. (9)/(10), uneven-spacing factors
//! included), with the chords `A`, `B` replaced by the relative logarithms
//! `log(q_{i−1}⁻¹ q_i)` and `log(q_i⁻¹ q_{i+1})`. The intermediate
//! quaternions are (DESIGN.md, "Animation model")
//! `s0 = q0·exp((T0 − log(q0⁻¹q1))/2)`, `s1 = q1·exp((log(q0⁻¹q1) − T1)/2)`,
//! and the curve is Shoemake's
//! `squad(q0, q1, s0, s1; h) = slerp(slerp(q0, q1, h), slerp(s0, s1, h), 2h(1−h))`.
//! Its body-frame angular velocity is `2·T0` at h = 0 and `2·T1` at h = 1:
//! differentiating the nested slerps at h = 0, where the blend weight
//! 2h(1−h) is 0 with slope 2, gives squad′(0) = q0·(log(q0⁻¹q1) +
//! 2·log(q0⁻¹s0)) = q0·T0 (likewise at h = 1). So continuity 0 gives C¹
//! angular velocity at keys, and with t = c = b = 0 on even spacing
//! `T_i = (A + B)/2`, which makes s_i exactly Shoemake's
//! `q_i·exp(−(log(q_i⁻¹q_{i+1}) + log(q_i⁻¹q_{i−1}))/4)`.
//!
//! **Hemispheres.** `q` and `−q` are the same rotation. Each segment takes
//! the short way: the end key of a segment is negated if its 4D dot product
//! with the start key is negative, so two keys 170° apart turn 170°, and a
//! turn of 270° authored as three keys (0°, 135°, 270°) turns 270° because
//! each segment is less than 180°. The tangent neighbours are aligned along
//! the chain: `q_{i−1}` is sign-aligned to `q_i`, `q_{i+1}` to `q_i`, and
//! `q_{i+2}` to the (aligned) `q_{i+1}`, so every relative logarithm above is
//! the short way (|angle| ≤ 180°). Consequence: the sign of the output
//! quaternion may flip at a key (the rotation itself is continuous).

use super::hermite::{kb_in, kb_out, Tcb};
use glam::{Quat, Vec3};

/// `log` of a unit quaternion as a half-angle vector (`axis·θ/2`).
#[inline]
pub fn qlog(q: Quat) -> Vec3 {
    let v = Vec3::new(q.x, q.y, q.z);
    let s = v.length();
    if s < 1e-7 {
        return v;
    }
    let half = libm::atan2f(s, q.w);
    v * (half / s)
}

/// `exp` of a half-angle vector: the unit quaternion rotating by `2·|v|`
/// about `v`.
#[inline]
pub fn qexp(v: Vec3) -> Quat {
    let half = v.length();
    if half < 1e-7 {
        return Quat::from_xyzw(v.x, v.y, v.z, 1.0).normalize();
    }
    let (s, c) = libm::sincosf(half);
    let a = v * (s / half);
    Quat::from_xyzw(a.x, a.y, a.z, c)
}

/// `b` or `−b`, whichever is in the same hemisphere as `a` (the short way).
#[inline]
pub fn align(b: Quat, a: Quat) -> Quat {
    if a.dot(b) < 0.0 {
        -b
    } else {
        b
    }
}

/// Unit-length `q`, or the identity for a zero/non-finite quaternion (only
/// unvalidated tracks can hold those).
#[inline]
pub fn unit(q: Quat) -> Quat {
    let l2 = q.length_squared();
    if (l2 - 1.0).abs() < 1e-5 {
        q
    } else if l2 > 1e-20 && l2.is_finite() {
        q * (1.0 / l2.sqrt())
    } else {
        Quat::IDENTITY
    }
}

/// Spherical linear interpolation *without* hemisphere correction (the
/// callers align first; squad's inner slerps must not flip).
#[inline]
pub fn slerp_raw(a: Quat, b: Quat, t: f32) -> Quat {
    let d = a.dot(b).clamp(-1.0, 1.0);
    if d > 0.9995 {
        // Nearly equal: normalised lerp is accurate to f32 precision.
        return unit(a * (1.0 - t) + b * t);
    }
    // sin θ from the dot product, and sin((1−t)θ) from the angle-difference
    // identity, so one acos and one sincos do the whole slerp.
    let sin = (1.0 - d * d).sqrt();
    if sin < 1e-6 {
        // Opposite quaternions (only reachable through extreme squad
        // intermediates): no unique arc; hold the nearer end.
        return if t < 0.5 { a } else { b };
    }
    let theta = libm::acosf(d);
    let (st, ct) = libm::sincosf(t * theta);
    let wb = st / sin;
    let wa = (sin * ct - d * st) / sin;
    a * wa + b * wb
}

/// Short-way slerp between two keys (the `Linear` rotation segment).
#[inline]
pub fn slerp(q0: Quat, q1: Quat, t: f32) -> Quat {
    let a = unit(q0);
    unit(slerp_raw(a, align(unit(q1), a), t))
}

/// Shoemake's squad with given intermediates.
#[inline]
pub fn squad(q0: Quat, q1: Quat, s0: Quat, s1: Quat, h: f32) -> Quat {
    let outer = slerp_raw(q0, q1, h);
    let inner = slerp_raw(s0, s1, h);
    unit(slerp_raw(outer, inner, 2.0 * h * (1.0 - h)))
}

/// A neighbouring key for tangents: its rotation and its distance in frames.
pub type Neighbour = (Quat, f32);

/// One squad-TCB segment from `q0` (outgoing TCB `tcb0`) to `q1` (incoming
/// TCB `tcb1`), `len` frames long, with optional outer neighbours `prev`
/// (before q0) and `next` (after q1), at `h ∈ [0, 1]`.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn squad_tcb(
    prev: Option<Neighbour>,
    q0: Quat,
    tcb0: Tcb,
    q1: Quat,
    tcb1: Tcb,
    next: Option<Neighbour>,
    len: f32,
    h: f32,
) -> Quat {
    let (s0, s1, a, b) = squad_intermediates(prev, q0, tcb0, q1, tcb1, next, len);
    squad(a, b, s0, s1, h)
}

/// The KB intermediates `(s0, s1)` of a segment and its sign-aligned,
/// unit end keys `(q0, q1)`.
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn squad_intermediates(
    prev: Option<Neighbour>,
    q0: Quat,
    tcb0: Tcb,
    q1: Quat,
    tcb1: Tcb,
    next: Option<Neighbour>,
    len: f32,
) -> (Quat, Quat, Quat, Quat) {
    let a = unit(q0);
    let b = align(unit(q1), a);
    let chord = qlog(a.conjugate() * b);
    let before = prev.map(|(p, dp)| {
        let p = align(unit(p), a);
        (qlog(p.conjugate() * a), dp)
    });
    let after = next.map(|(n, dn)| {
        let n = align(unit(n), b);
        (qlog(b.conjugate() * n), dn)
    });
    let t0 = kb_out(before, (chord, len), tcb0);
    let t1 = kb_in((chord, len), after, tcb1);
    let s0 = a * qexp((t0 - chord) * 0.5);
    let s1 = b * qexp((chord - t1) * 0.5);
    (s0, s1, a, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: Quat, b: Quat, tol: f32) -> bool {
        (a - b).length() < tol || (a + b).length() < tol
    }

    #[test]
    fn exp_inverts_log() {
        for (axis, angle) in [
            (Vec3::X, 0.3),
            (Vec3::new(1.0, 2.0, -1.0), 2.9),
            (Vec3::Z, 1e-5),
        ] {
            let q = Quat::from_axis_angle(axis.normalize(), angle);
            assert!(near(qexp(qlog(q)), q, 1e-6), "{axis} {angle}");
            // log is the half-angle vector.
            assert!((qlog(q).length() - angle / 2.0).abs() < 1e-6);
        }
    }

    #[test]
    fn slerp_raw_hits_ends_and_middle() {
        let a = Quat::from_rotation_y(0.2);
        let b = Quat::from_rotation_y(1.4);
        assert!(near(slerp_raw(a, b, 0.0), a, 1e-6));
        assert!(near(slerp_raw(a, b, 1.0), b, 1e-6));
        assert!(near(
            slerp_raw(a, b, 0.25),
            Quat::from_rotation_y(0.5),
            1e-6
        ));
    }

    #[test]
    fn squad_with_end_keys_as_intermediates_is_slerp() {
        let a = Quat::from_rotation_x(-0.4);
        let b = Quat::from_axis_angle(Vec3::new(0.0, 1.0, 1.0).normalize(), 1.1);
        for i in 0..=8 {
            let h = i as f32 / 8.0;
            assert!(near(squad(a, b, a, b, h), slerp(a, b, h), 1e-6));
        }
        // Two keys, no neighbours, tension 0: the intermediates are the keys.
        let (s0, s1, _, _) =
            squad_intermediates(None, a, Tcb::default(), b, Tcb::default(), None, 10.0);
        assert!(near(s0, a, 1e-6) && near(s1, b, 1e-6));
    }
}
