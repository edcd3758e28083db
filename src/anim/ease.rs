//! Ease to / ease from (3ds Max TCB controllers): a remap of the segment
//! parameter that slows the motion near a key without changing the path.
//!
//! The remap chosen is the constant-acceleration ease of Watt & Watt
//! ("Advanced Animation and Rendering Techniques", 1992, §15.2) that 3D Studio
//! uses: over the first fraction `a` of the segment (ease from the start key)
//! the parameter speeds up with constant acceleration from rest, over the last
//! fraction `b` (ease to the end key) it slows down to rest the same way, and
//! between the two it moves at constant speed. Speed is continuous, so the
//! remap is C¹ inside the segment. Derivation (ours): with middle speed `v`,
//! the area under the speed profile is `v·(a/2 + (1−a−b) + b/2) = 1`, so
//! `v = 2/(2−a−b)`; writing `k = v/2 = 1/(2−a−b)`:
//! `u(s) = k·s²/a` for `s < a`, `k·(2s − a)` in the middle, and
//! `1 − k·(1−s)²/b` for `s > 1−b`.
//! If `a + b > 1` both are scaled down so that they sum to 1 (no middle part).

/// Remaps `s` in [0, 1] (the position inside a segment) for an ease-from
/// value `from` at the segment's start key and an ease-to value `to` at its
/// end key, both in [0, 1]. `ease(s, 0, 0) == s`; the result is monotone,
/// starts at 0 and ends at 1.
#[inline]
pub fn ease(s: f32, from: f32, to: f32) -> f32 {
    // NaN eases fall back to "no ease" (validated tracks never hold them).
    let mut a = if from.is_nan() {
        0.0
    } else {
        from.clamp(0.0, 1.0)
    };
    let mut b = if to.is_nan() { 0.0 } else { to.clamp(0.0, 1.0) };
    if a == 0.0 && b == 0.0 {
        return s;
    }
    let sum = a + b;
    if sum > 1.0 {
        a /= sum;
        b /= sum;
    }
    let k = 1.0 / (2.0 - a - b);
    if s < a {
        k * s * s / a
    } else if s <= 1.0 - b {
        k * (2.0 * s - a)
    } else {
        let r = 1.0 - s;
        1.0 - k * r * r / b
    }
}

#[cfg(test)]
mod tests {
    use super::ease;

    #[test]
    fn identity_without_ease() {
        for i in 0..=10 {
            let s = i as f32 / 10.0;
            assert_eq!(ease(s, 0.0, 0.0), s);
        }
    }

    #[test]
    fn hand_worked_values() {
        // a = 0.5, b = 0: k = 1/1.5. At s = 0.25: k·s²/a = (2/3)·0.0625/0.5 = 1/12.
        assert!((ease(0.25, 0.5, 0.0) - 1.0 / 12.0).abs() < 1e-6);
        // Middle part at s = 0.75: k·(1.5 − 0.5) = 2/3.
        assert!((ease(0.75, 0.5, 0.0) - 2.0 / 3.0).abs() < 1e-6);
        // Symmetric full ease (a = b = 0.5) passes through the middle.
        assert!((ease(0.5, 0.5, 0.5) - 0.5).abs() < 1e-6);
        assert!((ease(0.25, 1.0, 1.0) - 0.125).abs() < 1e-6);
    }

    #[test]
    fn monotone_continuous_and_slow_at_ends() {
        for &(a, b) in &[(0.3, 0.0), (0.0, 0.4), (0.5, 0.5), (0.8, 0.9), (1.0, 0.2)] {
            let mut last = 0.0f32;
            let n = 1000;
            for i in 0..=n {
                let s = i as f32 / n as f32;
                let u = ease(s, a, b);
                assert!(u >= last - 1e-6, "not monotone at {s} for {a},{b}");
                assert!(u - last < 3.0 / n as f32, "jump at {s} for {a},{b}");
                last = u;
            }
            assert!((ease(1.0, a, b) - 1.0).abs() < 1e-6);
            let h = 1e-3;
            if a > 0.0 {
                assert!(ease(h, a, b) / h < 0.05, "no ease at start for {a},{b}");
            }
            if b > 0.0 {
                assert!((1.0 - ease(1.0 - h, a, b)) / h < 0.05, "no ease at end");
            }
        }
    }
}
