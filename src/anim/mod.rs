//! Keyframe animation: keys, tracks, the properties they drive, and
//! evaluation of a whole scene at a time into a [`Pose`].
//!
//! Key times are in frames (fractional allowed); `evaluate` takes seconds and
//! converts with the scene's fps.

mod key;
mod pose;
mod target;
mod track;

pub use key::{Interp, Key};
pub use pose::{evaluate, Pose};
pub use target::{Property, Target, TargetRef, Value, ValueKind};
pub use track::{Keys, Repeat, Track, TrackError};

/// All tracks of a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    pub tracks: Vec<Track>,
}
