//! The key panel's rules: which number each field shows of a key, and how
//! an edit changes the selected keys (frame, value, interpolation,
//! tension, continuity, bias, ease, the track's repeat mode, on/off). The
//! panel itself (its state, widgets and answers) is `keypanel.rs`.
//!
//! Editing T, C or B of a step or linear key switches it to TCB (they
//! shape nothing else). Values show the *primary* key (the first selected); an edit sets the
//! parameter on every selected key (a value only on keys of the primary's
//! property, a frame moves them all by the same offset). Typing records at
//! Enter, dragging previews live and records one step at release, so the
//! motion path follows at once.

pub use super::fields::KeyField;
use super::fields::{euler_degrees, from_euler_degrees};
use super::keyedit::retime;
use super::keystrip::KeyRef;
use crate::anim::{Animation, Interp, Key, Repeat, Value};

/// Buttons of the key panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyAction {
    Interp(Interp),
    /// Flip the value of boolean keys (light on, visible).
    ToggleBool,
    /// The selected keys' tracks hold their end values / loop their key
    /// range outside it (the track's repeat mode).
    Repeat(crate::anim::Repeat),
    /// Show the node's properties / the key panel.
    ShowNode,
    ShowKeys,
    /// The keys' context menu (`keymenu.rs`): ease in, out, both or
    /// none, delete, copy, paste at the current frame, and select every
    /// key of a strip row or of the graph channel under the mouse.
    Ease(super::keyedit::Ease),
    Delete,
    Copy,
    Paste,
    SelectRow(super::keystrip::Row),
    SelectChannel,
}

/// The number a field shows for `key`.
pub(super) fn read(field: KeyField, key: &Key<Value>) -> Option<f32> {
    Some(match field {
        KeyField::Frame => key.frame,
        KeyField::Value(i) => match key.value {
            Value::Vec3(v) => v[i as usize],
            Value::Rotation(q) => euler_degrees(q)[i as usize],
            Value::Scalar(x) if i == 0 => x,
            _ => return None,
        },
        KeyField::Tension => key.tension,
        KeyField::Continuity => key.continuity,
        KeyField::Bias => key.bias,
        KeyField::EaseIn => key.ease_in,
        KeyField::EaseOut => key.ease_out,
    })
}

/// `key` with the field set to `v` (already clamped).
pub(super) fn write(field: KeyField, key: Key<Value>, v: f32) -> Key<Value> {
    let mut k = key;
    match field {
        KeyField::Frame => k.frame = v,
        KeyField::Value(i) => {
            k.value = match k.value {
                Value::Vec3(mut x) => {
                    x[i as usize] = v;
                    Value::Vec3(x)
                }
                Value::Rotation(q) => {
                    let mut e = euler_degrees(q);
                    e[i as usize] = v;
                    Value::Rotation(from_euler_degrees(e))
                }
                Value::Scalar(_) if i == 0 => Value::Scalar(v),
                other => other,
            }
        }
        KeyField::Tension => k.tension = v,
        KeyField::Continuity => k.continuity = v,
        KeyField::Bias => k.bias = v,
        KeyField::EaseIn => k.ease_in = v,
        KeyField::EaseOut => k.ease_out = v,
    }
    k
}

/// `anim` with `field` = `v` on the selected `keys` (`keys[0]` is the
/// primary). Returns the new animation and the keys' refs after it.
pub fn set_field(
    anim: &Animation,
    keys: &[KeyRef],
    field: KeyField,
    v: f32,
) -> Result<(Animation, Vec<KeyRef>), String> {
    let Some(primary) = keys.first() else {
        return Err("no keys selected".into());
    };
    let v = field.clamp(primary.property, v);
    if !v.is_finite() {
        return Err("not a number".into());
    }
    if field == KeyField::Frame {
        let first = keys.iter().map(|k| k.frame).fold(f32::INFINITY, f32::min);
        let delta = (v - primary.frame).max(-first.max(0.0));
        return retime(anim, keys, |f| f + delta);
    }
    let mut out = anim.clone();
    for k in keys {
        if matches!(field, KeyField::Value(_)) && k.property != primary.property {
            continue;
        }
        let Some(key) = k.get(&out) else { continue };
        let Some(track) = out.track_mut(k.target()) else {
            continue;
        };
        let mut new = write(field, key, v);
        // T, C and B shape TCB segments only: editing them on a step or
        // linear key makes it a TCB key, so the change shows.
        let tcb = matches!(
            field,
            KeyField::Tension | KeyField::Continuity | KeyField::Bias
        );
        if tcb && !matches!(new.value, Value::Bool(_)) {
            new.interp = Interp::Tcb;
        }
        track.insert_key(new).map_err(|e| e.to_string())?;
    }
    Ok((out, keys.to_vec()))
}

/// `anim` with every selected key's parameters changed by `f` (ranges
/// stay in bounds, so setting them cannot fail).
fn with_params(
    anim: &Animation,
    keys: &[KeyRef],
    f: impl Fn(&mut crate::anim::KeyParams),
) -> Animation {
    let mut out = anim.clone();
    for k in keys {
        if let Some(t) = out.track_mut(k.target()) {
            if let Some(idx) = t.key_index_at(k.frame) {
                if let Some(mut p) = t.key_params(idx) {
                    f(&mut p);
                    let _ = t.set_key_params(idx, p);
                }
            }
        }
    }
    out
}

/// The selected keys' segments with interpolation `i`.
pub fn with_interp(anim: &Animation, keys: &[KeyRef], i: Interp) -> Animation {
    with_params(anim, keys, |p| p.interp = i)
}

/// The selected keys with ease `e` (in, out, both or none).
pub fn with_ease(anim: &Animation, keys: &[KeyRef], e: super::keyedit::Ease) -> Animation {
    with_params(anim, keys, |p| e.apply(p))
}

/// The selected keys' tracks with repeat mode `r`, and the line saying so.
pub fn with_repeat(anim: &Animation, keys: &[KeyRef], r: Repeat) -> (Animation, &'static str) {
    let mut out = anim.clone();
    for k in keys {
        if let Some(t) = out.track_mut(k.target()) {
            t.repeat = r;
        }
    }
    let label = match r {
        Repeat::Constant => "Track holds its end values",
        Repeat::Loop => "Track loops its keys",
    };
    (out, label)
}

/// The primary key's property's selected on/off keys flipped (from the
/// primary's value), and whether they were on; `None` unless the primary
/// is an on/off key.
pub fn toggled(anim: &Animation, keys: &[KeyRef]) -> Option<(Animation, bool)> {
    let p = keys.first()?;
    let Value::Bool(b) = p.get(anim)?.value else {
        return None;
    };
    let mut out = anim.clone();
    for k in keys.iter().filter(|k| k.property == p.property) {
        let Some(key) = k.get(&out) else { continue };
        if let Some(t) = out.track_mut(k.target()) {
            let _ = t.insert_key(Key {
                value: Value::Bool(!b),
                ..key
            });
        }
    }
    Some((out, b))
}
