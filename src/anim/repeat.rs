//! What a track does outside its keys, and which keys are a key's neighbours.
//!
//! * [`Repeat::Constant`]: before the first key the first value holds, after
//!   the last key the last value holds. The end keys have a neighbour on one
//!   side only (see the end-key rule in `hermite.rs`).
//! * [`Repeat::Loop`]: the key range `[first, last]` repeats with period
//!   `last − first`; the first and last keys are the *same instant* of the
//!   loop (author them with the same value for a seamless loop; if they
//!   differ, the motion jumps at the wrap, as authored). For tangents the
//!   neighbours wrap: the key before the first key is the second-to-last key
//!   shifted back by one period, the key after the last key is the second key
//!   shifted forward by one period. With equal end values and equal
//!   tension/bias on the two end keys (continuity 0) the loop is C¹ across the
//!   wrap. A loop of one key (period 0) is constant.

use super::{Key, Repeat};

/// Maps `frame` into the track's key range according to `repeat`.
///
/// Constant tracks return `frame` unchanged (sampling clamps to the ends);
/// looping tracks return a frame in `[first, last)`.
#[inline]
pub fn local_frame(first: f32, last: f32, repeat: Repeat, frame: f32) -> f32 {
    match repeat {
        Repeat::Constant => frame,
        Repeat::Loop => {
            let period = last - first;
            if period.is_nan() || period <= 0.0 || !period.is_finite() || !frame.is_finite() {
                return first;
            }
            if frame >= first && frame < last {
                // Inside the key range: unchanged, so keys are hit exactly.
                return frame;
            }
            // floor-based remainder: much cheaper than `%` (a libm fmod call)
            // and exact enough for frame numbers.
            let d = frame - first;
            let mut x = d - (d / period).floor() * period;
            if x < 0.0 {
                x += period;
            }
            // Rounding can land on exactly `period` (or just past it).
            if x >= period {
                first
            } else {
                first + x
            }
        }
    }
}

/// The key before key `i` for tangent purposes: `(index, frame)`, the frame
/// shifted by one period when it wraps. `None` at the start of an open track.
#[inline]
pub fn before<V>(keys: &[Key<V>], i: usize, repeat: Repeat) -> Option<(usize, f32)> {
    if i > 0 {
        return Some((i - 1, keys[i - 1].frame));
    }
    let n = keys.len();
    if repeat == Repeat::Loop && n >= 2 {
        let period = keys[n - 1].frame - keys[0].frame;
        return Some((n - 2, keys[n - 2].frame - period));
    }
    None
}

/// The key after key `i` for tangent purposes: `(index, frame)`, the frame
/// shifted by one period when it wraps. `None` at the end of an open track.
#[inline]
pub fn after<V>(keys: &[Key<V>], i: usize, repeat: Repeat) -> Option<(usize, f32)> {
    let n = keys.len();
    if i + 1 < n {
        return Some((i + 1, keys[i + 1].frame));
    }
    if repeat == Repeat::Loop && n >= 2 {
        let period = keys[n - 1].frame - keys[0].frame;
        return Some((1, keys[1].frame + period));
    }
    None
}

/// Where a (local) frame falls among the keys.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Locate {
    /// Exactly a key's value: before the first key, after the last, on a
    /// key, or a degenerate segment.
    Hold(usize),
    /// Inside the segment from key `i` to key `i + 1` at `s ∈ (0, 1)`.
    Segment(usize, f32),
}

/// Finds the segment holding `frame` by binary search. `keys` must not be
/// empty; unsorted keys give some key, never a panic.
#[inline]
pub fn locate<V>(keys: &[Key<V>], frame: f32) -> Locate {
    let n = keys.len();
    if n < 2 || frame.is_nan() || frame <= keys[0].frame {
        return Locate::Hold(0);
    }
    if frame >= keys[n - 1].frame {
        return Locate::Hold(n - 1);
    }
    let i = keys
        .partition_point(|k| k.frame <= frame)
        .saturating_sub(1)
        .min(n - 2);
    let (f0, f1) = (keys[i].frame, keys[i + 1].frame);
    let d = f1 - f0;
    if d.is_nan() || d <= 0.0 {
        return Locate::Hold(i);
    }
    let s = (frame - f0) / d;
    if s <= 0.0 {
        Locate::Hold(i)
    } else if s >= 1.0 {
        Locate::Hold(i + 1)
    } else {
        Locate::Segment(i, s)
    }
}
