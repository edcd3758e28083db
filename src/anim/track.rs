use super::{Key, Target, Value, ValueKind};
use glam::{Quat, Vec3};

/// What a track does outside its first and last key.
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
}

impl Keys {
    pub fn len(&self) -> usize {
        match self {
            Keys::Scalar(k) => k.len(),
            Keys::Vec3(k) => k.len(),
            Keys::Rotation(k) => k.len(),
            Keys::Bool(k) => k.len(),
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
        }
    }

    pub fn value_kind(&self) -> ValueKind {
        match self {
            Keys::Scalar(_) => ValueKind::Scalar,
            Keys::Vec3(_) => ValueKind::Vec3,
            Keys::Rotation(_) => ValueKind::Rotation,
            Keys::Bool(_) => ValueKind::Bool,
        }
    }
}

/// Why a track could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackError {
    Empty,
    NotSorted { index: usize },
    DuplicateTime { index: usize },
    NotFinite { index: usize },
    OutOfRange { index: usize, what: &'static str },
    WrongValueKind,
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
        }
    }
}

impl std::error::Error for TrackError {}

/// One property of one target driven by keys.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    pub target: Target,
    pub repeat: Repeat,
    pub keys: Keys,
}

impl Track {
    /// Sample the track at `frame`.
    ///
    /// Placeholder until the full curve maths lands: holds the last key at or
    /// before `frame`.
    pub fn sample(&self, frame: f32) -> Value {
        fn hold<V: Copy>(k: &[Key<V>], f: f32) -> V {
            let i = k.partition_point(|k| k.frame <= f).saturating_sub(1);
            k[i].value
        }
        match &self.keys {
            Keys::Scalar(k) => Value::Scalar(hold(k, frame)),
            Keys::Vec3(k) => Value::Vec3(hold(k, frame)),
            Keys::Rotation(k) => Value::Rotation(hold(k, frame)),
            Keys::Bool(k) => Value::Bool(hold(k, frame)),
        }
    }
}
