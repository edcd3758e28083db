//! Keyframe animation: keys, tracks, the properties they drive, and
//! evaluation of a whole scene at a time into a [`Pose`].
//!
//! Key times are in frames (fractional allowed); `evaluate` takes seconds and
//! converts with the scene's fps.
//!
//! One file per job: `hermite.rs` (Kochanek-Bartels vectors), `quat_curve.rs`
//! (slerp, squad-TCB), `ease.rs` (ease to/from), `repeat.rs` (hold/loop and
//! neighbours), `sample.rs` (sampling typed keys), `track.rs` (validated
//! tracks), `edit.rs` (key editing), `numbers.rs` (values ⇄ numbers),
//! `pose.rs` (scene evaluation), `synthetic.rs` (benchmark scenes).

mod animation;
pub mod ease;
mod edit;
pub mod hermite;
mod key;
mod numbers;
mod pose;
pub mod quat_curve;
pub mod repeat;
mod sample;
pub mod synthetic;
mod target;
mod track;

pub use edit::KEY_EPS;
pub use key::{Interp, Key, KeyParams};
pub use numbers::ValueError;
pub use pose::{evaluate, evaluate_into, Pose};
pub use target::{Property, Target, TargetRef, Value, ValueKind};
pub use track::{Keys, Repeat, Track, TrackError};

/// All tracks of a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    pub tracks: Vec<Track>,
}
