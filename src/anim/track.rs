//! A track: one property of one target, its keys and its repeat mode.
//! Construction validates; sampling is a binary search plus one segment's
//! maths (see `sample.rs`), with no allocation.

use super::sample::{sample_bool, sample_rotation, sample_vector};
use super::Weights;
use super::{Key, Target, Value, ValueKind};
use glam::{Quat, Vec3};

/// What a track does outside its first and last key (rules in `repeat.rs`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Repeat {
    /// Hold the end values.
    #[default]
    Constant,
    /// Repeat the key range forever.
    Loop,
}

/// The keys of a track, typed by value kind.
#[derive(Clone, Debug, PartialEq)]
pub enum Keys {
    Scalar(Vec<Key<f32>>),
    Vec3(Vec<Key<Vec3>>),
    Rotation(Vec<Key<Quat>>),
    Bool(Vec<Key<bool>>),
    /// Morph weights (all keys should hold the same count; a shorter key
    /// reads as zeros for the missing targets).
    Weights(Vec<Key<Weights>>),
}

impl Keys {
    pub fn len(&self) -> usize {
        match self {
            Keys::Scalar(k) => k.len(),
            Keys::Vec3(k) => k.len(),
            Keys::Rotation(k) => k.len(),
            Keys::Bool(k) => k.len(),
            Keys::Weights(k) => k.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Frame times of all keys.
    pub fn frames(&self) -> Vec<f32> {
        match self {
            Keys::Scalar(k) => k.iter().map(|k| k.frame).collect(),
            Keys::Vec3(k) => k.iter().map(|k| k.frame).collect(),
            Keys::Rotation(k) => k.iter().map(|k| k.frame).collect(),
            Keys::Bool(k) => k.iter().map(|k| k.frame).collect(),
            Keys::Weights(k) => k.iter().map(|k| k.frame).collect(),
        }
    }

    pub fn value_kind(&self) -> ValueKind {
        match self {
            Keys::Scalar(_) => ValueKind::Scalar,
            Keys::Vec3(_) => ValueKind::Vec3,
            Keys::Rotation(_) => ValueKind::Rotation,
            Keys::Bool(_) => ValueKind::Bool,
            Keys::Weights(_) => ValueKind::Weights,
        }
    }
}

/// Why a track could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackError {
    Empty,
    NotSorted {
        index: usize,
    },
    DuplicateTime {
        index: usize,
    },
    NotFinite {
        index: usize,
    },
    OutOfRange {
        index: usize,
        what: &'static str,
    },
    WrongValueKind,
    /// An edit named a frame where the track has no key.
    NoKeyAt {
        frame: f32,
    },
}

impl std::fmt::Display for TrackError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TrackError::Empty => write!(f, "a track needs at least one key"),
            TrackError::NotSorted { index } => {
                write!(f, "key {index} is earlier than the key before it")
            }
            TrackError::DuplicateTime { index } => {
                write!(f, "key {index} has the same time as the key before it")
            }
            TrackError::NotFinite { index } => write!(
                f,
                "key {index} has a time or value that is not a finite number"
            ),
            TrackError::OutOfRange { index, what } => {
                write!(f, "key {index}: {what} is out of range")
            }
            TrackError::WrongValueKind => {
                write!(f, "the keys' value type does not match the property")
            }
            TrackError::NoKeyAt { frame } => write!(f, "there is no key at frame {frame}"),
        }
    }
}

impl std::error::Error for TrackError {}

/// One property of one target driven by keys.
///
/// Invariants (checked by [`Track::new`] / [`Track::validate`]): at least one
/// key; key times finite, strictly increasing; values finite (rotations
/// non-zero, stored unit length); tension/continuity/bias in [-1, 1]; ease in
/// [0, 1]; the key list's value type fits `target.property.kind()` (colours
/// use `Keys::Vec3`). Sampling an unvalidated track never panics.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    pub target: Target,
    pub repeat: Repeat,
    pub keys: Keys,
}

impl Track {
    /// Builds a track, checking the invariants above. Rotation keys are
    /// normalised to unit length.
    pub fn new(target: Target, repeat: Repeat, keys: Keys) -> Result<Track, TrackError> {
        let mut track = Track {
            target,
            repeat,
            keys,
        };
        if let Keys::Rotation(k) = &mut track.keys {
            for (i, key) in k.iter_mut().enumerate() {
                let l = key.value.length();
                if !l.is_finite() {
                    return Err(TrackError::NotFinite { index: i });
                }
                if l < 1e-6 {
                    return Err(TrackError::OutOfRange {
                        index: i,
                        what: "rotation (zero quaternion)",
                    });
                }
                key.value /= l;
            }
        }
        track.validate()?;
        Ok(track)
    }

    /// Checks the invariants of a track that may have been built or edited
    /// field by field.
    pub fn validate(&self) -> Result<(), TrackError> {
        if !kind_fits(self.target.property.kind(), self.keys.value_kind()) {
            return Err(TrackError::WrongValueKind);
        }
        match &self.keys {
            Keys::Scalar(k) => check_keys(k, |v| v.is_finite()),
            Keys::Vec3(k) => check_keys(k, |v| v.is_finite()),
            Keys::Rotation(k) => {
                check_keys(k, |q| q.is_finite())?;
                match k
                    .iter()
                    .position(|k| (k.value.length_squared() - 1.0).abs() > 1e-3)
                {
                    Some(index) => Err(TrackError::OutOfRange {
                        index,
                        what: "rotation (not unit length)",
                    }),
                    None => Ok(()),
                }
            }
            Keys::Bool(k) => check_keys(k, |_| true),
            Keys::Weights(k) => check_keys(k, |w| w.is_finite()),
        }
    }

    /// Samples the track at `frame` (fractional frames allowed), applying
    /// the repeat mode outside the keys.
    #[inline]
    pub fn sample(&self, frame: f32) -> Value {
        let r = self.repeat;
        match &self.keys {
            Keys::Scalar(k) => Value::Scalar(sample_vector(k, r, frame).unwrap_or(0.0)),
            Keys::Vec3(k) => Value::Vec3(sample_vector(k, r, frame).unwrap_or(Vec3::ZERO)),
            Keys::Rotation(k) => {
                Value::Rotation(sample_rotation(k, r, frame).unwrap_or(Quat::IDENTITY))
            }
            Keys::Bool(k) => Value::Bool(sample_bool(k, r, frame).unwrap_or(true)),
            Keys::Weights(k) => Value::Weights(sample_vector(k, r, frame).unwrap_or_default()),
        }
    }

    /// First and last key frame, or `None` for a track without keys.
    pub fn frame_range(&self) -> Option<(f32, f32)> {
        match &self.keys {
            Keys::Scalar(k) => range(k),
            Keys::Vec3(k) => range(k),
            Keys::Rotation(k) => range(k),
            Keys::Bool(k) => range(k),
            Keys::Weights(k) => range(k),
        }
    }
}

fn range<V>(k: &[Key<V>]) -> Option<(f32, f32)> {
    Some((k.first()?.frame, k.last()?.frame))
}

/// Whether keys of value type `keys` can drive a property of kind `want`.
pub(crate) fn kind_fits(want: ValueKind, keys: ValueKind) -> bool {
    match want {
        ValueKind::Color => keys == ValueKind::Vec3,
        w => w == keys,
    }
}

/// Order, finiteness and parameter ranges of a key list.
fn check_keys<V>(keys: &[Key<V>], value_ok: impl Fn(&V) -> bool) -> Result<(), TrackError> {
    if keys.is_empty() {
        return Err(TrackError::Empty);
    }
    for (index, k) in keys.iter().enumerate() {
        if !k.frame.is_finite() || !value_ok(&k.value) {
            return Err(TrackError::NotFinite { index });
        }
        for (x, what, lo) in [
            (k.tension, "tension", -1.0),
            (k.continuity, "continuity", -1.0),
            (k.bias, "bias", -1.0),
            (k.ease_in, "ease in", 0.0),
            (k.ease_out, "ease out", 0.0),
        ] {
            if !(lo..=1.0).contains(&x) {
                return Err(TrackError::OutOfRange { index, what });
            }
        }
        if index > 0 {
            let prev = keys[index - 1].frame;
            if k.frame == prev {
                return Err(TrackError::DuplicateTime { index });
            }
            if k.frame < prev {
                return Err(TrackError::NotSorted { index });
            }
        }
    }
    Ok(())
}
