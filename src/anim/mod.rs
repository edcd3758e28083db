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
//! `pose.rs` (scene evaluation), `weights.rs` (morph weights as a value),
//! `deform.rs` (per-pose morph + skin into the pose's buffers),
//! `skinning.rs` (the parallel, deterministic kernels), `synthetic.rs`
//! (benchmark scenes).

mod animation;
mod deform;
pub mod ease;
mod edit;
pub mod hermite;
pub mod ik;
mod key;
mod numbers;
mod pose;
pub mod quat_curve;
pub mod repeat;
mod sample;
pub mod skinning;
pub mod synthetic;
pub mod synthetic_deform;
mod target;
mod track;
mod weights;

pub use deform::Deformed;
pub use edit::KEY_EPS;
pub use key::{Interp, Key, KeyParams};
pub use numbers::ValueError;
pub use pose::{evaluate, evaluate_into, Pose};
pub use target::{Property, Target, TargetRef, Value, ValueKind};
pub use track::{Keys, Repeat, Track, TrackError};
pub use weights::{Weights, MAX_MORPH_TARGETS};

/// All tracks of a scene.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Animation {
    pub tracks: Vec<Track>,
}
