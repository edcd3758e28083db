//! Key editing on tracks, in terms of the untyped [`Value`], for the editor
//! and `animed key`. Every edit keeps the track's invariants (sorted, unique,
//! finite times; at least one key) or fails and leaves the track unchanged.
//!
//! Two key times closer than [`KEY_EPS`] frames name the same key.

use super::{Key, KeyParams, Keys, Track, TrackError, Value, ValueKind, Weights};
use glam::{Quat, Vec3};

/// Frames within which an edit's frame matches an existing key.
pub const KEY_EPS: f32 = 1e-4;

/// A type that key values are stored as.
trait Stored: Copy {
    fn from_value(v: Value) -> Option<Self>;
    fn to_value(self) -> Value;
    /// Checks (and normalises) a value about to be stored.
    fn check(self) -> Result<Self, &'static str>;
}

impl Stored for f32 {
    fn from_value(v: Value) -> Option<Self> {
        match v {
            Value::Scalar(x) => Some(x),
            _ => None,
        }
    }
    fn to_value(self) -> Value {
        Value::Scalar(self)
    }
    fn check(self) -> Result<Self, &'static str> {
        if self.is_finite() {
            Ok(self)
        } else {
            Err("value")
        }
    }
}

impl Stored for Vec3 {
    fn from_value(v: Value) -> Option<Self> {
        match v {
            Value::Vec3(x) => Some(x),
            _ => None,
        }
    }
    fn to_value(self) -> Value {
        Value::Vec3(self)
    }
    fn check(self) -> Result<Self, &'static str> {
        if self.is_finite() {
            Ok(self)
        } else {
            Err("value")
        }
    }
}

impl Stored for Quat {
    fn from_value(v: Value) -> Option<Self> {
        match v {
            Value::Rotation(x) => Some(x),
            _ => None,
        }
    }
    fn to_value(self) -> Value {
        Value::Rotation(self)
    }
    fn check(self) -> Result<Self, &'static str> {
        let l = self.length();
        if !l.is_finite() {
            Err("value")
        } else if l < 1e-6 {
            Err("rotation (zero quaternion)")
        } else {
            Ok(self / l)
        }
    }
}

impl Stored for Weights {
    fn from_value(v: Value) -> Option<Self> {
        match v {
            Value::Weights(x) => Some(x),
            _ => None,
        }
    }
    fn to_value(self) -> Value {
        Value::Weights(self)
    }
    fn check(self) -> Result<Self, &'static str> {
        if self.is_finite() {
            Ok(self)
        } else {
            Err("value")
        }
    }
}

impl Stored for bool {
    fn from_value(v: Value) -> Option<Self> {
        match v {
            Value::Bool(x) => Some(x),
            _ => None,
        }
    }
    fn to_value(self) -> Value {
        Value::Bool(self)
    }
    fn check(self) -> Result<Self, &'static str> {
        Ok(self)
    }
}

/// Runs `$body` with `$k` bound to the typed key vector.
macro_rules! with_keys {
    ($keys:expr, $k:ident => $body:expr) => {
        match $keys {
            Keys::Scalar($k) => $body,
            Keys::Vec3($k) => $body,
            Keys::Rotation($k) => $body,
            Keys::Bool($k) => $body,
            Keys::Weights($k) => $body,
        }
    };
}

fn index_at<V>(keys: &[Key<V>], frame: f32) -> Option<usize> {
    let i = keys.partition_point(|k| k.frame < frame - KEY_EPS);
    (i < keys.len() && (keys[i].frame - frame).abs() <= KEY_EPS).then_some(i)
}

fn params_ok(p: &KeyParams) -> Result<(), &'static str> {
    for (x, what, lo) in [
        (p.tension, "tension", -1.0),
        (p.continuity, "continuity", -1.0),
        (p.bias, "bias", -1.0),
        (p.ease_in, "ease in", 0.0),
        (p.ease_out, "ease out", 0.0),
    ] {
        if !(lo..=1.0).contains(&x) {
            return Err(what);
        }
    }
    Ok(())
}

fn insert<V: Stored>(keys: &mut Vec<Key<V>>, key: Key<Value>) -> Result<usize, TrackError> {
    let v = V::from_value(key.value).ok_or(TrackError::WrongValueKind)?;
    let pos = keys.partition_point(|k| k.frame < key.frame - KEY_EPS);
    let bad = |what| TrackError::OutOfRange { index: pos, what };
    if !key.frame.is_finite() {
        return Err(TrackError::NotFinite { index: pos });
    }
    let v = v.check().map_err(|w| match w {
        "value" => TrackError::NotFinite { index: pos },
        w => bad(w),
    })?;
    params_ok(&key.params()).map_err(bad)?;
    let typed = key.map(|_| v);
    match index_at(keys, key.frame) {
        Some(i) => {
            keys[i] = Key {
                frame: keys[i].frame,
                ..typed
            }
        }
        None => keys.insert(pos, typed),
    }
    Ok(pos)
}

fn set<V: Stored>(keys: &mut Vec<Key<V>>, frame: f32, value: Value) -> Result<usize, TrackError> {
    let params = match index_at(keys, frame) {
        Some(i) => keys[i].params(),
        None => {
            // A new key takes the settings of the key before it (or after it,
            // at the start), so a stepped or linear track stays so.
            let pos = keys.partition_point(|k| k.frame < frame);
            pos.checked_sub(1)
                .or((pos < keys.len()).then_some(pos))
                .map(|i| keys[i].params())
                .unwrap_or_default()
        }
    };
    insert(keys, Key::new(frame, value).with_params(params))
}

fn remove<V>(keys: &mut Vec<Key<V>>, frame: f32) -> Result<(), TrackError> {
    let i = index_at(keys, frame).ok_or(TrackError::NoKeyAt { frame })?;
    if keys.len() == 1 {
        return Err(TrackError::Empty);
    }
    keys.remove(i);
    Ok(())
}

fn shift<V: Copy>(keys: &mut Vec<Key<V>>, frames: &[f32], delta: f32) -> Result<(), TrackError> {
    let mut picked = Vec::with_capacity(frames.len());
    for &f in frames {
        let i = index_at(keys, f).ok_or(TrackError::NoKeyAt { frame: f })?;
        if !picked.contains(&i) {
            picked.push(i);
        }
    }
    let mut moved = keys.clone();
    for &i in &picked {
        moved[i].frame += delta;
        if !moved[i].frame.is_finite() {
            return Err(TrackError::NotFinite { index: i });
        }
    }
    moved.sort_by(|a, b| a.frame.total_cmp(&b.frame));
    if let Some(index) = (1..moved.len()).find(|&i| moved[i].frame - moved[i - 1].frame <= KEY_EPS)
    {
        return Err(TrackError::DuplicateTime { index });
    }
    *keys = moved;
    Ok(())
}

impl Keys {
    /// An empty key list holding values of `kind` (colours are `Vec3`).
    pub fn empty(kind: ValueKind) -> Keys {
        match kind {
            ValueKind::Scalar => Keys::Scalar(Vec::new()),
            ValueKind::Vec3 | ValueKind::Color => Keys::Vec3(Vec::new()),
            ValueKind::Rotation => Keys::Rotation(Vec::new()),
            ValueKind::Bool => Keys::Bool(Vec::new()),
            ValueKind::Weights => Keys::Weights(Vec::new()),
        }
    }

    /// Builds typed keys from untyped ones, sorting them by time. Fails on a
    /// value of the wrong kind or anything [`Track::new`] would reject.
    pub fn from_values(kind: ValueKind, keys: &[Key<Value>]) -> Result<Keys, TrackError> {
        let mut out = Keys::empty(kind);
        for k in keys {
            if with_keys!(&out, v => index_at(v, k.frame)).is_some() {
                return Err(TrackError::DuplicateTime {
                    index: with_keys!(&out, v => v.len()),
                });
            }
            with_keys!(&mut out, v => insert(v, *k))?;
        }
        if out.is_empty() {
            return Err(TrackError::Empty);
        }
        Ok(out)
    }

    /// Key `i` with its value as a [`Value`].
    pub fn key(&self, i: usize) -> Option<Key<Value>> {
        with_keys!(self, k => k.get(i).map(|k| k.map(Stored::to_value)))
    }

    /// Index of the key at `frame` (within [`KEY_EPS`]).
    pub fn index_at(&self, frame: f32) -> Option<usize> {
        with_keys!(self, k => index_at(k, frame))
    }
}

impl Track {
    /// Number of keys.
    pub fn key_count(&self) -> usize {
        self.keys.len()
    }

    /// Key `i` as an untyped key.
    pub fn key(&self, i: usize) -> Option<Key<Value>> {
        self.keys.key(i)
    }

    /// Index of the key at `frame` (within [`KEY_EPS`]).
    pub fn key_index_at(&self, frame: f32) -> Option<usize> {
        self.keys.index_at(frame)
    }

    /// Sets the value at `frame`: replaces the value of the key there
    /// (keeping its interpolation, TCB and ease), or inserts a new key in
    /// order whose settings are copied from the key before it. Returns the
    /// key's index.
    pub fn set_key(&mut self, frame: f32, value: Value) -> Result<usize, TrackError> {
        with_keys!(&mut self.keys, k => set(k, frame, value))
    }

    /// Inserts `key` (value and settings), replacing a key at the same frame.
    pub fn insert_key(&mut self, key: Key<Value>) -> Result<usize, TrackError> {
        with_keys!(&mut self.keys, k => insert(k, key))
    }

    /// Removes the key at `frame`. A track keeps at least one key: removing
    /// the last one fails with [`TrackError::Empty`] (remove the track instead).
    pub fn remove_key(&mut self, frame: f32) -> Result<(), TrackError> {
        with_keys!(&mut self.keys, k => remove(k, frame))
    }

    /// Moves the keys at `frames` by `delta` frames. Keys may pass others
    /// (the list is re-sorted), but two keys must not land on one frame.
    pub fn move_keys(&mut self, frames: &[f32], delta: f32) -> Result<(), TrackError> {
        with_keys!(&mut self.keys, k => shift(k, frames, delta))
    }

    /// Moves the key at `from` to frame `to`; returns its new index.
    pub fn move_key(&mut self, from: f32, to: f32) -> Result<usize, TrackError> {
        let delta = to - from;
        self.move_keys(&[from], delta)?;
        self.key_index_at(to)
            .ok_or(TrackError::NoKeyAt { frame: to })
    }

    /// Interpolation, TCB and ease of key `i`.
    pub fn key_params(&self, i: usize) -> Option<KeyParams> {
        self.keys.key(i).map(|k| k.params())
    }

    /// Sets interpolation, TCB and ease of key `i` (ranges checked).
    pub fn set_key_params(&mut self, i: usize, p: KeyParams) -> Result<(), TrackError> {
        if i >= self.keys.len() {
            return Err(TrackError::OutOfRange {
                index: i,
                what: "key index",
            });
        }
        params_ok(&p).map_err(|what| TrackError::OutOfRange { index: i, what })?;
        with_keys!(&mut self.keys, k => k[i] = k[i].with_params(p));
        Ok(())
    }
}
