//! Animation output: frame ranges rendered to PNG sequences or animated
//! GIFs, on all cores, deterministic, optionally split into shards for
//! several machines.
//!
//! - [`range`]: `--range START:STEP:COUNT` (seconds), `--frames A:B`, `--shard K/N`
//! - [`pattern`]: `frames/f_####.png` → `frames/f_0007.png`
//! - [`sequence`]: the driver (draw frames in parallel, write in order)
//! - [`palette`], [`dither`], [`gif`]: one median-cut palette for the whole
//!   animation, ordered two-colour dithering, GIF encoding
//! - [`pool`], [`progress`], [`png`]: threads, progress lines, atomic PNGs

pub mod dither;
pub mod gif;
pub mod palette;
pub mod pattern;
pub mod png;
pub mod pool;
pub mod progress;
pub mod range;
pub mod sequence;

pub use pattern::Pattern;
pub use progress::Mode as ProgressMode;
pub use range::{FrameRange, Shard};
pub use sequence::{OutputKind, SequenceJob};
