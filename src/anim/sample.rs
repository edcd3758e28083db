//! Sampling typed key lists: find the segment (binary search), apply the
//! repeat mode, ease and the segment's interpolation. No allocation.
//!
//! The interpolation of a segment is the `interp` of the key at its start;
//! `Step` holds that key's value up to (not including) the next key. Ease-from
//! of the start key and ease-to of the end key remap time inside the segment
//! (`ease.rs`). Booleans always step.

use super::ease::ease;
use super::hermite::{hermite, kb_in, kb_out, Tcb, VectorLike};
use super::quat_curve::{slerp, squad_tcb, unit};
use super::repeat::{after, before, local_frame, locate, Locate};
use super::{Interp, Key, Repeat};
use glam::Quat;

#[inline]
fn tcb_of<V>(k: &Key<V>) -> Tcb {
    Tcb {
        tension: k.tension,
        continuity: k.continuity,
        bias: k.bias,
    }
}

/// Where `frame` lands after the repeat mode; `None` for no keys.
#[inline]
fn find<V>(keys: &[Key<V>], repeat: Repeat, frame: f32) -> Option<Locate> {
    let first = keys.first()?.frame;
    let last = keys[keys.len() - 1].frame;
    Some(locate(keys, local_frame(first, last, repeat, frame)))
}

/// Samples scalar / vector / colour keys. `None` only when `keys` is empty.
#[inline]
pub fn sample_vector<V: VectorLike>(keys: &[Key<V>], repeat: Repeat, frame: f32) -> Option<V> {
    let (i, s) = match find(keys, repeat, frame)? {
        Locate::Hold(i) => return Some(keys[i].value),
        Locate::Segment(i, s) => (i, s),
    };
    let (k0, k1) = (&keys[i], &keys[i + 1]);
    let chord = k1.value - k0.value;
    Some(match k0.interp {
        Interp::Step => k0.value,
        Interp::Linear => k0.value + chord * ease(s, k0.ease_out, k1.ease_in),
        Interp::Tcb => {
            let len = k1.frame - k0.frame;
            let prev =
                before(keys, i, repeat).map(|(j, f)| (k0.value - keys[j].value, k0.frame - f));
            let next =
                after(keys, i + 1, repeat).map(|(j, f)| (keys[j].value - k1.value, f - k1.frame));
            let m0 = kb_out(prev, (chord, len), tcb_of(k0));
            let m1 = kb_in((chord, len), next, tcb_of(k1));
            hermite(k0.value, m0, k1.value, m1, ease(s, k0.ease_out, k1.ease_in))
        }
    })
}

/// Samples rotation keys (step / slerp / squad-TCB); always unit length.
/// `None` only when `keys` is empty.
#[inline]
pub fn sample_rotation(keys: &[Key<Quat>], repeat: Repeat, frame: f32) -> Option<Quat> {
    let (i, s) = match find(keys, repeat, frame)? {
        Locate::Hold(i) => return Some(unit(keys[i].value)),
        Locate::Segment(i, s) => (i, s),
    };
    let (k0, k1) = (&keys[i], &keys[i + 1]);
    Some(match k0.interp {
        Interp::Step => unit(k0.value),
        Interp::Linear => slerp(k0.value, k1.value, ease(s, k0.ease_out, k1.ease_in)),
        Interp::Tcb => {
            let prev = before(keys, i, repeat).map(|(j, f)| (keys[j].value, k0.frame - f));
            let next = after(keys, i + 1, repeat).map(|(j, f)| (keys[j].value, f - k1.frame));
            squad_tcb(
                prev,
                k0.value,
                tcb_of(k0),
                k1.value,
                tcb_of(k1),
                next,
                k1.frame - k0.frame,
                ease(s, k0.ease_out, k1.ease_in),
            )
        }
    })
}

/// Samples boolean keys: always a step. `None` only when `keys` is empty.
#[inline]
pub fn sample_bool(keys: &[Key<bool>], repeat: Repeat, frame: f32) -> Option<bool> {
    match find(keys, repeat, frame)? {
        Locate::Hold(i) | Locate::Segment(i, _) => Some(keys[i].value),
    }
}
